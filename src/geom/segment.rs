//! Distances between straight segments of the plane.

use super::{Point, Vector, cross};

/// The unit vector along `v`; `None` for a zero or unbounded vector.
pub(crate) fn unit(v: Vector) -> Option<Vector> {
    let n = v.norm();
    (n > 0.0 && n.is_finite()).then(|| v / n)
}

/// Where the segments `a b` and `c d` cross: the sine of the angle between
/// them; `None` if they do not (or one of them is a point).
pub(crate) fn crossing(a: Point, b: Point, c: Point, d: Point) -> Option<f64> {
    let o = |p: Point, q: Point, r: Point| cross(&(q - p), &(r - p));
    let (d1, d2) = (o(c, d, a), o(c, d, b));
    let (d3, d4) = (o(a, b, c), o(a, b, d));
    if d1 * d2 <= 0.0 && d3 * d4 <= 0.0 && (d1 != 0.0 || d2 != 0.0) {
        let (u, v) = (unit(b - a)?, unit(d - c)?);
        Some(cross(&u, &v).abs())
    } else {
        None
    }
}

/// The distance between the segments `a b` and `c d`: 0 where they cross;
/// a segment may be a point.
pub(crate) fn segment_distance(a: Point, b: Point, c: Point, d: Point) -> f64 {
    if crossing(a, b, c, d).is_some() {
        return 0.0;
    }
    [
        point_segment_distance(a, c, d),
        point_segment_distance(b, c, d),
        point_segment_distance(c, a, b),
        point_segment_distance(d, a, b),
    ]
    .into_iter()
    .fold(f64::INFINITY, f64::min)
}

/// The distance from `p` to the segment `a b` (to `a` where the segment is
/// a point).
pub(crate) fn point_segment_distance(p: Point, a: Point, b: Point) -> f64 {
    let ab = b - a;
    let len2 = ab.norm_squared();
    if len2 == 0.0 {
        return (p - a).norm();
    }
    let t = ((p - a).dot(&ab) / len2).clamp(0.0, 1.0);
    (p - (a + ab * t)).norm()
}

/// The greatest distance from a point of the segment `p q` to the segment
/// `a b`: at one of `p q`'s ends, the distance being convex along it. A
/// line lies beside a link all its length where this is small (0 where
/// `p q` lies on `a b`; `a b` may be a point).
pub(crate) fn farthest_from_segment(p: Point, q: Point, a: Point, b: Point) -> f64 {
    point_segment_distance(p, a, b).max(point_segment_distance(q, a, b))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_segment_is_as_far_from_another_as_its_farther_end() {
        let p = |x: f64, y: f64| Point::new(x, y);
        let (a, b) = (p(0.0, 0.0), p(10.0, 0.0));
        assert_eq!(farthest_from_segment(p(1.0, 1.0), p(9.0, 3.0), a, b), 3.0);
        assert_eq!(farthest_from_segment(p(2.0, 0.0), p(8.0, 0.0), a, b), 0.0);
        // Past the end of a b: measured to b.
        assert_eq!(farthest_from_segment(p(5.0, 0.0), p(14.0, 3.0), a, b), 5.0);
    }

    #[test]
    fn distances_between_segments() {
        let p = |x: f64, y: f64| Point::new(x, y);
        assert_eq!(
            segment_distance(p(0., 0.), p(2., 0.), p(1., -1.), p(1., 1.)),
            0.0
        );
        assert_eq!(
            segment_distance(p(0., 0.), p(2., 0.), p(3., 0.), p(4., 1.)),
            1.0
        );
        assert_eq!(
            segment_distance(p(0., 0.), p(2., 0.), p(1., 2.), p(1., 5.)),
            2.0
        );
        assert!(crossing(p(0., 0.), p(2., 0.), p(1., 1.), p(1., 3.)).is_none());
        let sin = crossing(p(0., 0.), p(2., 0.), p(0., -1.), p(2., 1.)).unwrap();
        assert!((sin - 0.5f64.sqrt()).abs() < 1e-15);
    }
}
