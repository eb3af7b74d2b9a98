//! Centre lines broken at letters: as a draughtsman interrupts a centre
//! line where a letter or dimension text must sit on it, the line of
//! stroke is written after the labels are placed, with a gap at each
//! label box it crosses.

use super::Ink;
use super::markup::{path, pt};
use crate::figure::{Pen, Role};
use crate::geom::{Point, Vector};
use crate::render::labels::{Bounds, span};
use std::fmt::Write as _;
use svg::node::element::Path as SvgPath;

/// The dash pattern of a centre line: long dash, gap, dot, gap.
pub(super) const DASH: &str = "14 3 2 3";

/// Room kept between a letter's box and the ends of the gap, page units.
const GAP_ROOM: f64 = 1.5;

/// Shortest piece of line worth writing, page units.
const SHORTEST: f64 = 0.5;

/// The weight of a centre line in the label search: a letter on it costs
/// little, since the line opens for it, but a clean place still wins.
pub(super) const WEIGHT: f64 = 0.25;

/// Whether the item is a centre line that opens for letters: the line of
/// stroke (`line-stroke…`, auxiliary).
pub(super) fn is_centre_line(role: Role, id: &str) -> bool {
    role == Role::Auxiliary && id.starts_with("line-stroke")
}

/// A centre line waiting for the labels: where its node sits in the
/// panel's drawing order, and what it is written with.
pub(super) struct CentreLine {
    pub node: usize,
    pub id: String,
    pub role: Role,
    pub pen: Pen,
    pub from: Point,
    pub to: Point,
}

impl CentreLine {
    /// The line as a path, one sub-path per piece left between the
    /// `boxes` it crosses.
    pub fn written(&self, boxes: &[Bounds]) -> SvgPath {
        let ink = Ink {
            id: &self.id,
            role: self.role,
            pen: self.pen,
        };
        let mut d = String::new();
        for (s, t) in pieces(self.from, self.to, boxes) {
            let sep = if d.is_empty() { "" } else { " " };
            let _ = write!(d, "{sep}M{} L{}", pt(s), pt(t));
        }
        ink.tag(path(d, self.pen)).set("stroke-dasharray", DASH)
    }
}

/// The pieces of the segment `from`–`to` outside every box (each grown by
/// [`GAP_ROOM`]), in order; the whole segment where it crosses none.
fn pieces(from: Point, to: Point, boxes: &[Bounds]) -> Vec<(Point, Point)> {
    let d = to - from;
    let length = d.norm();
    if length == 0.0 {
        return vec![(from, to)];
    }
    let room = Vector::new(GAP_ROOM, GAP_ROOM);
    let mut cuts: Vec<(f64, f64)> = boxes
        .iter()
        .filter_map(|b| {
            let grown = Bounds {
                min: b.min - room,
                max: b.max + room,
            };
            span(from, d, &grown)
        })
        .collect();
    cuts.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut out = Vec::new();
    let mut at = 0.0;
    for (t0, t1) in cuts {
        if (t0 - at) * length > SHORTEST {
            out.push((from + d * at, from + d * t0));
        }
        at = at.max(t1);
    }
    if (1.0 - at) * length > SHORTEST {
        out.push((from + d * at, to));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_line_opens_where_a_letter_sits_and_only_there() {
        let (a, b) = (Point::new(0.0, 0.0), Point::new(100.0, 0.0));
        let letter = Bounds::around(Point::new(50.0, 2.0), Vector::new(5.0, 6.0));
        let p = pieces(a, b, &[letter]);
        assert_eq!(p.len(), 2, "{p:?}");
        assert_eq!(p[0].0, a);
        assert!((p[0].1.x - (45.0 - GAP_ROOM)).abs() < 1e-12);
        assert!((p[1].0.x - (55.0 + GAP_ROOM)).abs() < 1e-12);
        assert_eq!(p[1].1, b);
        // A letter clear of the line leaves it whole.
        let clear = Bounds::around(Point::new(50.0, 20.0), Vector::new(5.0, 6.0));
        assert_eq!(pieces(a, b, &[clear]), vec![(a, b)]);
        // Overlapping letters make one gap; a letter over an end trims it.
        let next = Bounds::around(Point::new(58.0, 0.0), Vector::new(5.0, 6.0));
        let end = Bounds::around(Point::new(100.0, 0.0), Vector::new(5.0, 6.0));
        let p = pieces(a, b, &[next, letter, end]);
        assert_eq!(p.len(), 2, "{p:?}");
        assert!((p[1].0.x - (63.0 + GAP_ROOM)).abs() < 1e-12);
        assert!((p[1].1.x - (95.0 - GAP_ROOM)).abs() < 1e-12);
    }
}
