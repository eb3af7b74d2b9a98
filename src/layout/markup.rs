//! The pieces every symbol is made of: finite points and unit vectors,
//! arcs as Béziers, stroked paths and arrowheads.

use super::mark::{Mark, Paint, PathData, Shape};
use super::symbol_sizes::{ARROW_HALF_WIDTH, ARROW_LENGTH};
use crate::figure::Pen;
use crate::geom::{Point, Vector};

pub(super) fn finite(p: &Point) -> bool {
    p.x.is_finite() && p.y.is_finite()
}

/// `v` of unit length; `None` for a zero or non-finite vector.
pub(super) fn unit(v: Vector) -> Option<Vector> {
    let n = v.norm();
    (n > 0.0 && n.is_finite()).then(|| v / n)
}

/// The cubic Béziers of a circular arc, pieces of at most 30°.
pub(super) fn arc_beziers(centre: Point, radius: f64, start: f64, sweep: f64) -> Vec<[Point; 4]> {
    let n = ((sweep.abs() / (std::f64::consts::PI / 6.0)).ceil() as usize).clamp(1, 64);
    let delta = sweep / n as f64;
    let k = 4.0 / 3.0 * (delta / 4.0).tan();
    (0..n)
        .map(|i| {
            let a0 = start + delta * i as f64;
            let a1 = a0 + delta;
            let (s0, c0) = a0.sin_cos();
            let (s1, c1) = a1.sin_cos();
            let p0 = centre + Vector::new(c0, s0) * radius;
            let p3 = centre + Vector::new(c1, s1) * radius;
            let p1 = p0 + Vector::new(-s0, c0) * (k * radius);
            let p2 = p3 - Vector::new(-s1, c1) * (k * radius);
            [p0, p1, p2, p3]
        })
        .collect()
}

pub(super) fn bezier_d(pieces: &[[Point; 4]]) -> PathData {
    PathData::beziers(pieces)
}

pub(super) fn polyline_d(points: &[Point], closed: bool) -> PathData {
    PathData::polyline(points, closed)
}

/// A circle stroked with `pen`, unfilled.
pub(super) fn stroked_circle(centre: Point, radius: f64, pen: Pen) -> Mark {
    Mark::new(Shape::Circle {
        centre,
        radius,
        paint: Paint::stroked(pen, false),
    })
}

/// A stroked path with round caps and joins.
pub(super) fn path(d: PathData, pen: Pen) -> Mark {
    Mark::new(Shape::Path(d, Paint::stroked(pen, true)))
}

/// A filled arrowhead with its tip at `tip`, pointing along the unit `u`.
pub(super) fn arrow_head(tip: Point, u: Vector, colour: &'static str) -> Mark {
    let n = Vector::new(-u.y, u.x);
    let back = tip - u * ARROW_LENGTH;
    let pts = [
        tip,
        back + n * ARROW_HALF_WIDTH,
        back - n * ARROW_HALF_WIDTH,
    ];
    Mark::new(Shape::Path(polyline_d(&pts, true), Paint::filled(colour)))
}
