//! Clipping lines, rays and segments to an axis-aligned frame (parry2d-f64).

use super::{Line, Point, Vector};
use parry2d_f64::bounding_volume::Aabb;
use parry2d_f64::query::Ray;

/// An axis-aligned rectangle: a drawing frame or a plot area.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Frame {
    aabb: Aabb,
}

impl Frame {
    /// The rectangle spanned by two corners (in any order); `None` when a
    /// coordinate is NaN or infinite. Use this for corners from outside.
    pub fn try_new(a: Point, b: Point) -> Option<Self> {
        let ok = [a.x, a.y, b.x, b.y].iter().all(|v| v.is_finite());
        ok.then(|| Self::new(a, b))
    }

    /// The rectangle spanned by two corners (in any order), known to be
    /// finite (the program's own frames; [`Frame::try_new`] checks). A NaN
    /// coordinate gives a frame that contains no point, never a panic.
    pub fn new(a: Point, b: Point) -> Self {
        Self {
            aabb: Aabb::new(a.inf(&b), a.sup(&b)),
        }
    }

    /// Lower-left corner.
    pub fn min(&self) -> Point {
        self.aabb.mins
    }

    /// Upper-right corner.
    pub fn max(&self) -> Point {
        self.aabb.maxs
    }

    /// Whether `p` lies in the frame (boundary included).
    pub fn contains(&self, p: Point) -> bool {
        p.x >= self.aabb.mins.x
            && p.x <= self.aabb.maxs.x
            && p.y >= self.aabb.mins.y
            && p.y <= self.aabb.maxs.y
    }

    /// The part of an infinite line inside the frame, or `None`.
    pub fn clip_line(&self, line: &Line) -> Option<(Point, Point)> {
        let s = self.aabb.clip_line(&line.point(), &line.direction())?;
        Some((s.a, s.b))
    }

    /// The part of the ray from `origin` along `direction` inside the frame.
    pub fn clip_ray(&self, origin: Point, direction: Vector) -> Option<(Point, Point)> {
        let s = self.aabb.clip_ray(&Ray::new(origin, direction))?;
        Some((s.a, s.b))
    }

    /// The part of the segment `a b` inside the frame.
    pub fn clip_segment(&self, a: Point, b: Point) -> Option<(Point, Point)> {
        let s = self.aabb.clip_segment(&a, &b)?;
        Some((s.a, s.b))
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn nan_corners_are_refused_or_contain_nothing() {
        // Issue 9 (10): Frame::new accepted NaN.
        let nan = Point::new(f64::NAN, 0.0);
        let one = Point::new(1.0, 1.0);
        assert!(Frame::try_new(nan, one).is_none());
        assert!(Frame::try_new(Point::new(f64::INFINITY, 0.0), one).is_none());
        assert!(Frame::try_new(Point::origin(), one).is_some());
        let f = Frame::new(nan, one);
        assert!(!f.contains(Point::new(0.5, 0.5)));
    }

    use super::*;

    #[test]
    fn line_is_clipped_to_frame_edges() {
        let f = Frame::new(Point::new(0.0, 0.0), Point::new(10.0, 5.0));
        let l = Line::new(Point::new(-100.0, 2.0), Vector::new(1.0, 0.0)).unwrap();
        let (a, b) = f.clip_line(&l).unwrap();
        assert_eq!((a, b), (Point::new(0.0, 2.0), Point::new(10.0, 2.0)));
        let outside = Line::new(Point::new(0.0, 7.0), Vector::new(1.0, 0.0)).unwrap();
        assert!(f.clip_line(&outside).is_none());
    }

    #[test]
    fn ray_starts_at_its_origin() {
        let f = Frame::new(Point::new(0.0, 0.0), Point::new(10.0, 10.0));
        let (a, b) = f
            .clip_ray(Point::new(5.0, 5.0), Vector::new(0.0, 1.0))
            .unwrap();
        assert_eq!((a, b), (Point::new(5.0, 5.0), Point::new(5.0, 10.0)));
        assert!(f.contains(a) && !f.contains(Point::new(11.0, 0.0)));
    }
}
