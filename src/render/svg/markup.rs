//! The pieces every symbol is written with: numbers and points on the
//! grid, path data of polylines and arcs, strokes and arrowheads.

use crate::figure::Pen;
use crate::geom::{Point, Vector};
use crate::number::{OnGrid, fmt};
use crate::render::Element;
use crate::render::symbol_sizes::{ARROW_HALF_WIDTH, ARROW_LENGTH};
use std::fmt as stdfmt;
use std::fmt::Write as _;

/// A page point as path data: `x y` on the grid, written straight into
/// the path's string.
pub(super) fn pt(p: Point) -> impl stdfmt::Display {
    struct Pt(Point);
    impl stdfmt::Display for Pt {
        fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
            write!(f, "{} {}", OnGrid(self.0.x), OnGrid(self.0.y))
        }
    }
    Pt(p)
}

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

pub(super) fn bezier_d(pieces: &[[Point; 4]]) -> String {
    let mut d = String::new();
    if let Some(first) = pieces.first() {
        let _ = write!(d, "M{}", pt(first[0]));
    }
    for [_, c1, c2, p] in pieces {
        let _ = write!(d, " C{} {} {}", pt(*c1), pt(*c2), pt(*p));
    }
    d
}

pub(super) fn polyline_d(points: &[Point], closed: bool) -> String {
    let mut d = String::new();
    for (i, p) in points.iter().enumerate() {
        let _ = write!(d, "{}{}", if i == 0 { "M" } else { " L" }, pt(*p));
    }
    if closed {
        d.push_str(" Z");
    }
    d
}

/// `node` stroked with `pen`, unfilled.
pub(super) fn stroke(mut node: Element, pen: Pen) -> Element {
    node.assign("stroke", pen.colour);
    node.assign("stroke-width", fmt(pen.width));
    node.assign("fill", "none");
    if let Some(d) = pen.dash {
        node.assign("stroke-dasharray", d);
    }
    node
}

/// A stroked path with round caps and joins.
pub(super) fn path(d: String, pen: Pen) -> Element {
    stroke(Element::new("path").set("d", d), pen)
        .set("stroke-linecap", "round")
        .set("stroke-linejoin", "round")
}

/// A filled arrowhead with its tip at `tip`, pointing along the unit `u`.
pub(super) fn arrow_head(tip: Point, u: Vector, colour: &'static str) -> Element {
    let n = Vector::new(-u.y, u.x);
    let back = tip - u * ARROW_LENGTH;
    let pts = [
        tip,
        back + n * ARROW_HALF_WIDTH,
        back - n * ARROW_HALF_WIDTH,
    ];
    Element::new("path")
        .set("d", polyline_d(&pts, true))
        .set("fill", colour)
        .set("stroke", "none")
}
