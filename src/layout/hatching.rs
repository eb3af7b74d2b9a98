//! Hatching opened for letters and lines: as a draughtsman interrupts
//! hatching where an inscription cannot be set outside it, a hatch stroke
//! that a placed letter's box meets is left out; and so is one that a
//! construction line crosses or passes within [`ROOM`] of, so that a thin
//! line run across a guide (Fig. 67's HA, at a slant) reads as a line and
//! not as one more stroke. The label search still treats the hatching as
//! heavily as a link, so a letter lands on it only where every place near
//! its point is crowded.

use super::Ink;
use super::labels::span;
use super::mark::Mark;
use super::mark::{PathCommand, PathData};
use super::markup::path;
use crate::figure::{Part, Pen, Role};
use crate::geom::Frame;
use crate::geom::{Point, Vector};

/// Room kept between a letter's box and the strokes left, page units.
const ROOM: f64 = 1.0;
/// A line within this angle of the hatched edge (radians, 5°) runs along
/// it and leaves its strokes standing.
const ALONG: f64 = 0.087;

/// A hatching waiting for the labels: where its node sits in the panel's
/// drawing order, what it is written with, and its strokes (page points).
pub(super) struct Hatching {
    pub node: usize,
    pub id: String,
    pub role: Role,
    pub pen: Pen,
    pub strokes: Vec<(Point, Point)>,
}

impl Hatching {
    /// The strokes that meet none of the `boxes` (each grown by [`ROOM`])
    /// and keep [`ROOM`] from every one of the `crossing` lines (page
    /// segments), as one path; `None` when every stroke is covered.
    pub fn written(&self, boxes: &[Frame], crossing: &[(Point, Point)]) -> Option<Mark> {
        let ink = Ink {
            id: &self.id,
            role: self.role,
            pen: self.pen,
            part: Part::Plain,
        };
        // Only the lines that come near the hatching's strokes at all.
        let ends: Vec<Point> = self.strokes.iter().flat_map(|(p, q)| [*p, *q]).collect();
        let reach = Frame::enclosing(&ends)?.inflate(ROOM);
        let near: Vec<&(Point, Point)> = (crossing.iter())
            .filter(|(p, q)| Frame::enclosing(&[*p, *q]).is_some_and(|b| b.meets(&reach)))
            .filter(|line| !self.on_edge(line))
            .collect();
        let clear = |s: &&(Point, Point)| near.iter().all(|c| apart(**s, **c, ROOM));
        let mut d = PathData::new();
        for (p, q) in kept(&self.strokes, boxes).filter(clear) {
            d.push(PathCommand::Move(*p));
            d.push(PathCommand::Line(*q));
        }
        (!d.is_empty()).then(|| ink.tag(path(d, self.pen)))
    }
}

impl Hatching {
    /// Whether the line `(a, b)` runs along the hatched edge (the line of
    /// the strokes' feet): within [`ROOM`] of it at both ends (a line
    /// drawn on the fixed link itself, a centre at infinity along it,
    /// meets every stroke at its foot and crosses none of the band), or
    /// within [`ALONG`] of its direction (a line of Kennedy's theorem
    /// through the fixed rod's pins at a pose near a dead centre runs
    /// through the band at a slant of a degree or two: it crosses the
    /// strokes as a line crosses hatching, and leaving out every stroke
    /// it meets left the fixed link with none).
    fn on_edge(&self, &(a, b): &(Point, Point)) -> bool {
        let (Some(first), Some(last)) = (self.strokes.first(), self.strokes.last()) else {
            return false;
        };
        let (f, l) = (first.0, last.0);
        let along = l - f;
        let n = along.norm();
        if n == 0.0 {
            return false;
        }
        let off = |p: Point| ((p - f).x * along.y - (p - f).y * along.x).abs() / n;
        let line = b - a;
        let parallel = line.norm() > 0.0 && line.dot(&along).abs() > ALONG.cos() * line.norm() * n;
        parallel || (off(a) <= ROOM && off(b) <= ROOM)
    }
}

/// Whether the segments `s` and `t` keep more than `room` apart: they do
/// not cross, and no end of one comes within `room` of the other.
fn apart(s: (Point, Point), t: (Point, Point), room: f64) -> bool {
    let cross = |a: Vector, b: Vector| a.x * b.y - a.y * b.x;
    let side = |(p, q): (Point, Point), x: Point| cross(q - p, x - p);
    let crosses = side(s, t.0) * side(s, t.1) < 0.0 && side(t, s.0) * side(t, s.1) < 0.0;
    let near = |(p, q): (Point, Point), x: Point| {
        let d = q - p;
        let len = d.norm_squared();
        let k = if len > 0.0 {
            ((x - p).dot(&d) / len).clamp(0.0, 1.0)
        } else {
            0.0
        };
        (p + d * k - x).norm() <= room
    };
    !crosses && !near(s, t.0) && !near(s, t.1) && !near(t, s.0) && !near(t, s.1)
}

/// The strokes that meet none of the boxes grown by [`ROOM`].
fn kept<'a>(
    strokes: &'a [(Point, Point)],
    boxes: &'a [Frame],
) -> impl Iterator<Item = &'a (Point, Point)> + 'a {
    let room = Vector::new(ROOM, ROOM);
    strokes.iter().filter(move |(p, q)| {
        boxes.iter().all(|b| {
            let grown = Frame::from_corners(b.min() - room, b.max() + room);
            span(*p, q - p, &grown).is_none()
        })
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn strokes_a_line_crosses_are_left_out_and_only_those() {
        let strokes = band();
        let hatching = Hatching {
            node: 0,
            id: "hatch".into(),
            role: Role::Frame,
            pen: Pen {
                colour: "#000000",
                width: 1.0,
                dash: None,
            },
            strokes,
        };
        // A slanting line across the band from (10, -2) to (40, 9).
        let line = (Point::new(10.0, -2.0), Point::new(40.0, 9.0));
        let all = starts(&hatching.written(&[], &[]).unwrap());
        let some = starts(&hatching.written(&[], &[line]).unwrap());
        assert_eq!(all.len(), 10);
        let kept = some.len();
        assert!((4..10).contains(&kept), "{kept} strokes kept: {some:?}");
        // The strokes starting at x = 0 and 54 lie far off the line.
        let at = |x: f64| some.contains(&Point::new(x, 0.0));
        assert!(at(0.0) && at(54.0), "{some:?}");
        assert!(apart(strokes_at(0.0), line, ROOM) && !apart(strokes_at(24.0), line, ROOM));
    }

    /// Where the strokes of a hatching's path start.
    fn starts(mark: &crate::layout::Mark) -> Vec<Point> {
        let crate::layout::MarkShape::Path(d, _) = &mark.shape else {
            panic!("a hatching is a path: {mark:?}");
        };
        (d.commands().iter())
            .filter_map(|c| match c {
                crate::layout::PathCommand::Move(p) => Some(*p),
                _ => None,
            })
            .collect()
    }

    /// A hatch stroke from `x` on the guide's line, at 6 units' spacing.
    fn strokes_at(x: f64) -> (Point, Point) {
        (Point::new(x, 0.0), Point::new(x - 5.2, 6.5))
    }

    /// Ten strokes from x = 0 to 54.
    fn band() -> Vec<(Point, Point)> {
        (0..10).map(|k| strokes_at(6.0 * f64::from(k))).collect()
    }

    #[test]
    fn a_stroke_under_a_letter_is_left_out_and_only_that_one() {
        let strokes = band();
        let letter = Frame::around(Point::new(24.0, 10.0), Vector::new(4.0, 5.0));
        let boxes = [letter];
        let left: Vec<_> = kept(&strokes, &boxes).collect();
        // The strokes from x = 24 and 30 reach into the letter's box.
        assert_eq!(left.len(), 8, "{left:?}");
        assert!(left.iter().all(|(p, _)| p.x != 24.0 && p.x != 30.0));
        let clear = Frame::around(Point::new(24.0, 40.0), Vector::new(4.0, 5.0));
        let boxes = [clear];
        assert_eq!(kept(&strokes, &boxes).count(), 10);
    }
}
