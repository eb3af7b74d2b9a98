//! Circles and their intersections with circles and lines.

use super::{Line, Point, Vector, perp};

/// A circle with a centre and a radius ≥ 0.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Circle {
    /// Centre.
    pub centre: Point,
    /// Radius (≥ 0).
    pub radius: f64,
}

/// Where two curves (circle–circle or line–circle) meet.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum CircleIntersection {
    /// They do not meet.
    None,
    /// They touch (within the tangency tolerance) at one point.
    Tangent(Point),
    /// They cross at two points; for a line, in the order of its direction;
    /// for two circles, the first is to the left of the line of centres.
    Two(Point, Point),
    /// The same circle: every point is common.
    Coincident,
}

impl Circle {
    /// The circle with `centre` and `radius`; `None` when the centre is
    /// not finite or the radius is negative, NaN or infinite.
    pub fn new(centre: Point, radius: f64) -> Option<Self> {
        let ok =
            centre.x.is_finite() && centre.y.is_finite() && radius.is_finite() && radius >= 0.0;
        ok.then_some(Self { centre, radius })
    }

    /// The circle on the segment `p q` as diameter.
    pub fn on_diameter(p: Point, q: Point) -> Self {
        Self {
            centre: nalgebra::center(&p, &q),
            radius: 0.5 * (q - p).norm(),
        }
    }

    /// Intersection with another circle. The circles touch when the gap
    /// between them (in length units) is at most `tolerance`.
    pub fn intersect_circle(&self, other: &Circle, tolerance: f64) -> CircleIntersection {
        let d = other.centre - self.centre;
        let dist = d.norm();
        if dist == 0.0 {
            return if (self.radius - other.radius).abs() <= tolerance {
                CircleIntersection::Coincident
            } else {
                CircleIntersection::None
            };
        }
        let (r1, r2) = (self.radius, other.radius);
        let outer_gap = dist - (r1 + r2);
        let inner_gap = (r1 - r2).abs() - dist;
        if outer_gap > tolerance || inner_gap > tolerance {
            return CircleIntersection::None;
        }
        let u = d / dist;
        // Distance along the centre line to the chord: a = (d² + r1² − r2²)/2d.
        let a = (dist * dist + (r1 - r2) * (r1 + r2)) / (2.0 * dist);
        let h2 = (r1 - a) * (r1 + a);
        let foot = self.centre + u * a;
        if outer_gap.abs() <= tolerance || inner_gap.abs() <= tolerance || h2 <= 0.0 {
            return CircleIntersection::Tangent(foot);
        }
        let off = perp(&u) * h2.sqrt();
        CircleIntersection::Two(foot + off, foot - off)
    }

    /// Intersection with a line; it touches when its distance from the centre
    /// is within `tolerance` of the radius.
    pub fn intersect_line(&self, line: &Line, tolerance: f64) -> CircleIntersection {
        let foot = line.foot(self.centre);
        let dist = (foot - self.centre).norm();
        let gap = dist - self.radius;
        if gap > tolerance {
            return CircleIntersection::None;
        }
        if gap.abs() <= tolerance {
            return CircleIntersection::Tangent(foot);
        }
        let half = ((self.radius - dist) * (self.radius + dist)).sqrt();
        let u: Vector = line.unit_direction().into_inner();
        CircleIntersection::Two(foot - u * half, foot + u * half)
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn bad_circles_are_refused() {
        // Issue 9 (10): Circle::new accepted NaN.
        assert!(Circle::new(Point::new(f64::NAN, 0.0), 1.0).is_none());
        assert!(Circle::new(Point::origin(), f64::NAN).is_none());
        assert!(Circle::new(Point::origin(), -1.0).is_none());
        assert!(Circle::new(Point::origin(), f64::INFINITY).is_none());
        assert_eq!(Circle::new(Point::origin(), 0.0).unwrap().radius, 0.0);
    }

    use super::*;

    #[test]
    fn two_circles_cross_symmetrically() {
        let a = Circle::new(Point::new(0.0, 0.0), 5.0).unwrap();
        let b = Circle::new(Point::new(8.0, 0.0), 5.0).unwrap();
        match a.intersect_circle(&b, 1e-12) {
            CircleIntersection::Two(p, q) => {
                assert_eq!(p, Point::new(4.0, 3.0));
                assert_eq!(q, Point::new(4.0, -3.0));
            }
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn tangency_within_tolerance() {
        let a = Circle::new(Point::new(0.0, 0.0), 1.0).unwrap();
        let b = Circle::new(Point::new(2.0 + 1e-13, 0.0), 1.0).unwrap();
        assert!(matches!(
            a.intersect_circle(&b, 1e-12),
            CircleIntersection::Tangent(_)
        ));
        assert_eq!(a.intersect_circle(&b, 0.0), CircleIntersection::None);
        let inner = Circle::new(Point::new(0.5, 0.0), 0.5).unwrap();
        assert_eq!(
            a.intersect_circle(&inner, 1e-12),
            CircleIntersection::Tangent(Point::new(1.0, 0.0))
        );
        assert_eq!(a.intersect_circle(&a, 0.0), CircleIntersection::Coincident);
    }

    #[test]
    fn line_cuts_circle_in_direction_order() {
        let c = Circle::new(Point::new(0.0, 0.0), 2.0).unwrap();
        let l = Line::new(Point::new(-5.0, 0.0), Vector::new(1.0, 0.0)).unwrap();
        assert_eq!(
            c.intersect_line(&l, 1e-12),
            CircleIntersection::Two(Point::new(-2.0, 0.0), Point::new(2.0, 0.0))
        );
        let far = Line::new(Point::new(0.0, 3.0), Vector::new(1.0, 0.0)).unwrap();
        assert_eq!(c.intersect_line(&far, 1e-12), CircleIntersection::None);
    }

    #[test]
    fn diameter_circle() {
        let c = Circle::on_diameter(Point::new(0.0, 0.0), Point::new(4.0, 0.0));
        assert_eq!(c.centre, Point::new(2.0, 0.0));
        assert_eq!(c.radius, 2.0);
    }
}
