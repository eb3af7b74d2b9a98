//! Infinite lines and their intersections.

use super::{Direction, Point, Vector, cross, perp};

/// Default tolerance for [`Line::intersect`]: two lines whose directions make
/// an angle with sine at most this are taken as parallel. It is well below
/// the sine of the smallest angle a pose given in degrees to 1e-6° produces
/// (about 1.7e-8), so at θ = 89.999999° the rod's instantaneous centre is
/// still a finite point.
pub const PARALLEL_TOLERANCE: f64 = 1e-14;

/// An infinite line through `point` along `direction` (never zero).
///
/// The direction is kept as given, not normalised, so that intersection
/// parameters divide once, late.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Line {
    point: Point,
    direction: Vector,
}

/// Where two lines meet.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Intersection {
    /// One finite point.
    Point(Point),
    /// The lines are parallel and distinct: they meet at the point at infinity
    /// in this direction (the first line's, up to sign).
    AtInfinity(Direction),
    /// The lines are the same line: every point of it is common.
    Coincident,
}

impl Intersection {
    /// The finite point, if there is one.
    #[inline]
    pub fn point(&self) -> Option<Point> {
        match self {
            Intersection::Point(p) => Some(*p),
            _ => None,
        }
    }
}

impl Line {
    /// The line through `point` along `direction`; `None` when the direction
    /// is zero or either is not finite.
    pub fn new(point: Point, direction: Vector) -> Option<Self> {
        let ok = point.x.is_finite()
            && point.y.is_finite()
            && direction.x.is_finite()
            && direction.y.is_finite()
            && (direction.x != 0.0 || direction.y != 0.0);
        ok.then_some(Self { point, direction })
    }

    /// A line from parts already known to be finite with a non-zero
    /// direction (the constructions' own lines).
    #[inline]
    pub(crate) fn from_parts(point: Point, direction: Vector) -> Self {
        debug_assert!(Self::new(point, direction).is_some());
        Self { point, direction }
    }

    /// The line through two points; `None` when they coincide.
    pub fn through(p: Point, q: Point) -> Option<Self> {
        Self::new(p, q - p)
    }

    /// A point of the line (the one it was built with).
    #[inline]
    pub fn point(&self) -> Point {
        self.point
    }

    /// The direction it was built with (not normalised).
    pub fn direction(&self) -> Vector {
        self.direction
    }

    /// The unit direction.
    pub fn unit_direction(&self) -> Direction {
        Direction::new_normalize(self.direction)
    }

    /// The point at parameter `t`: `point + t · direction`.
    #[inline]
    pub fn at(&self, t: f64) -> Point {
        self.point + self.direction * t
    }

    /// The parallel to this line through `p`.
    pub fn parallel_through(&self, p: Point) -> Self {
        Self {
            point: p,
            direction: self.direction,
        }
    }

    /// The perpendicular to this line through `p`.
    pub fn perpendicular_through(&self, p: Point) -> Self {
        Self {
            point: p,
            direction: perp(&self.direction),
        }
    }

    /// The direction scaled to unit length without overflow or underflow
    /// (directions of 1e308 or 1e-320 included).
    fn unit(&self) -> Vector {
        let d = self.direction;
        let big = d.x.abs().max(d.y.abs());
        let v = d / big;
        v / v.norm()
    }

    /// The foot of the perpendicular from `p` (finite) to this line.
    ///
    /// Computed on halved coordinates with a unit direction, so that points
    /// and directions anywhere in the range of f64 (1e308 included) give a
    /// finite foot; only a foot that itself lies beyond the largest f64
    /// (about 1.8e308) has an infinite coordinate. A non-finite `p` gives a
    /// non-finite foot.
    pub fn foot(&self, p: Point) -> Point {
        let u = self.unit();
        let half = (p.coords * 0.5 - self.point.coords * 0.5).dot(&u);
        let half_foot = self.point.coords * 0.5 + u * half;
        Point::from(half_foot * 2.0)
    }

    /// Signed distance of `p` (finite) from the line, positive to the left
    /// of the direction; computed without intermediate overflow (points of
    /// 1e308 included), ±infinity only when the distance itself exceeds the
    /// largest f64.
    pub fn signed_distance(&self, p: Point) -> f64 {
        let half = p.coords * 0.5 - self.point.coords * 0.5;
        2.0 * cross(&self.unit(), &half)
    }

    /// Intersection with [`PARALLEL_TOLERANCE`].
    #[inline]
    pub fn intersect(&self, other: &Line) -> Intersection {
        self.intersect_eps(other, PARALLEL_TOLERANCE)
    }

    /// Intersection, taking the lines as parallel when the sine of the angle
    /// between them is at most `eps` (0 for exactly parallel only). Parallel
    /// lines closer than `eps` times the larger of their points' distances
    /// from the origin (or than `eps` itself) are coincident.
    #[inline]
    pub fn intersect_eps(&self, other: &Line, eps: f64) -> Intersection {
        let d1 = self.direction;
        let d2 = other.direction;
        let denom = cross(&d1, &d2);
        // Compared squared: no square roots on the common path.
        if denom * denom <= eps * eps * d1.norm_squared() * d2.norm_squared() {
            let scale = self
                .point
                .coords
                .norm()
                .max(other.point.coords.norm())
                .max(1.0);
            return if self.signed_distance(other.point).abs() <= eps * scale {
                Intersection::Coincident
            } else {
                Intersection::AtInfinity(self.unit_direction())
            };
        }
        let t = cross(&(other.point - self.point), &d2) / denom;
        let p = self.at(t);
        if p.x.is_finite() && p.y.is_finite() {
            Intersection::Point(p)
        } else {
            Intersection::AtInfinity(self.unit_direction())
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn crossing_lines_meet_at_a_point() {
        let a = Line::through(Point::new(0.0, 0.0), Point::new(1.0, 1.0)).unwrap();
        let b = Line::new(Point::new(2.0, 0.0), Vector::new(0.0, 1.0)).unwrap();
        assert_eq!(a.intersect(&b), Intersection::Point(Point::new(2.0, 2.0)));
    }

    #[test]
    fn parallel_lines_meet_at_infinity() {
        let a = Line::new(Point::new(0.0, 0.0), Vector::new(0.0, 2.0)).unwrap();
        let b = Line::new(Point::new(3.0, 0.0), Vector::new(0.0, -1.0)).unwrap();
        match a.intersect(&b) {
            Intersection::AtInfinity(d) => assert_eq!(d.into_inner(), Vector::new(0.0, 1.0)),
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn same_line_is_coincident() {
        let a = Line::through(Point::new(0.0, 0.0), Point::new(1.0, 0.0)).unwrap();
        let b = Line::through(Point::new(5.0, 0.0), Point::new(-1.0, 0.0)).unwrap();
        assert_eq!(a.intersect(&b), Intersection::Coincident);
    }

    #[test]
    fn nearly_parallel_lines_still_meet_when_above_tolerance() {
        let a = Line::new(Point::new(0.0, 0.0), Vector::new(1e-8, 1.0)).unwrap();
        let b = Line::new(Point::new(1.0, 0.0), Vector::new(0.0, 1.0)).unwrap();
        let p = a.intersect(&b).point().unwrap();
        assert!((p.y - 1e8).abs() < 1e-7);
        assert!(matches!(
            a.intersect_eps(&b, 1e-6),
            Intersection::AtInfinity(_)
        ));
    }

    #[test]
    fn degenerate_lines_are_refused() {
        assert!(Line::through(Point::new(1.0, 1.0), Point::new(1.0, 1.0)).is_none());
        assert!(Line::new(Point::new(f64::NAN, 0.0), Vector::new(1.0, 0.0)).is_none());
    }

    #[test]
    fn foot_and_distance_of_huge_coordinates_are_finite() {
        // Issue 9 (10): NaN for coordinates of 1e308.
        let l = Line::new(Point::new(-1e308, 0.0), Vector::new(1e308, 0.0)).unwrap();
        let p = Point::new(1e308, 1e308);
        assert_eq!(l.foot(p), Point::new(1e308, 0.0));
        assert_eq!(l.signed_distance(p), 1e308);
        let tiny = Line::new(Point::new(0.0, 0.0), Vector::new(0.0, 5e-324)).unwrap();
        assert_eq!(tiny.foot(Point::new(3.0, 4.0)), Point::new(0.0, 4.0));
        assert_eq!(tiny.signed_distance(Point::new(3.0, 4.0)), -3.0);
    }

    #[test]
    fn foot_and_perpendicular() {
        let l = Line::through(Point::new(0.0, 0.0), Point::new(2.0, 0.0)).unwrap();
        assert_eq!(l.foot(Point::new(1.5, 3.0)), Point::new(1.5, 0.0));
        let p = l.perpendicular_through(Point::new(1.0, 1.0));
        assert_eq!(p.intersect(&l).point(), Some(Point::new(1.0, 0.0)));
        assert_eq!(l.signed_distance(Point::new(0.0, -2.0)), -2.0);
    }
}
