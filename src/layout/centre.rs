//! Lines broken at letters: as a draughtsman interrupts a centre line or
//! a dimension line where a letter must sit on it, the line of stroke,
//! the arcs of angle marks and a detail's frame are written after the
//! labels are placed, with a gap at each label box they cross. (A detail's
//! frame on the main view is avoided by letters as any line is; only a
//! pin's letter with no other place, among the crowded points it frames,
//! breaks it.)

use super::Ink;
use super::labels::span;
use super::mark::Mark;
use super::mark::{PathCommand, PathData};
use super::markup::{arc_beziers, bezier_d, path, polyline_d};
use crate::figure::{Part, Pen, Role};
use crate::geom::{Frame, Point, Vector};

/// The dash pattern of a centre line: long dash, gap, dot, gap.
pub(super) const DASH: &str = "14 3 2 3";

/// Room kept between a letter's box and the ends of the gap, page units.
const GAP_ROOM: f64 = 1.5;

/// Shortest piece of line worth writing, page units.
const SHORTEST: f64 = 0.5;

/// The weight of a line that opens for letters (a centre line, an angle
/// mark's arc) in the label search: a letter on it costs little, since
/// the line opens for it, but a clean place still wins.
pub(super) const WEIGHT: f64 = 0.25;

/// Whether the item is a centre line that opens for letters: the line of
/// stroke ([`Part::CentreLine`]), in the main view or a detail.
pub(super) fn is_centre_line(part: Part) -> bool {
    part == Part::CentreLine
}

/// The course of a line that opens for letters, in page coordinates.
#[derive(Debug, Clone, Copy)]
pub(super) enum Course {
    /// A centre line from one point to another, written dash-dotted.
    Centre { from: Point, to: Point },
    /// A detail's frame or border (a closed rectangle, written plain): its
    /// corners in order.
    Frame { corners: [Point; 4] },
    /// An angle mark's arc: its centre, radius, and the page angles it
    /// starts at and turns through (radians).
    Arc {
        centre: Point,
        radius: f64,
        start: f64,
        sweep: f64,
    },
}

/// A line waiting for the labels: where its node sits in the panel's
/// drawing order, and what it is written with.
pub(super) struct OpenLine {
    pub node: usize,
    pub id: String,
    pub role: Role,
    pub pen: Pen,
    pub course: Course,
}

impl OpenLine {
    /// The line as a path, one sub-path per piece left between the
    /// `boxes` it crosses; `None` where the boxes leave nothing of it (an
    /// angle's mark a degree wide under its letter).
    pub fn written(&self, boxes: &[Frame]) -> Option<Mark> {
        let ink = Ink {
            id: &self.id,
            role: self.role,
            pen: self.pen,
            part: Part::Plain,
        };
        let d = match self.course {
            Course::Centre { from, to } => {
                let mut d = PathData::new();
                for (s, t) in without_stubs(from, to, pieces(from, to, boxes)) {
                    d.push(PathCommand::Move(s));
                    d.push(PathCommand::Line(t));
                }
                d
            }
            Course::Frame { corners } => frame_d(&corners, boxes),
            Course::Arc {
                centre,
                radius,
                start,
                sweep,
            } => {
                let mut d = PathData::new();
                for (t0, t1) in arc_pieces(centre, radius, (start, sweep), boxes) {
                    let piece = arc_beziers(centre, radius, start + t0 * sweep, (t1 - t0) * sweep);
                    d.extend(bezier_d(&piece));
                }
                d
            }
        };
        if d.is_empty() {
            return None;
        }
        let mark = ink.tag(path(d, self.pen));
        Some(match self.course {
            Course::Centre { .. } => mark.dashed(DASH),
            _ => mark,
        })
    }
}

/// The path of a closed frame through `corners`, open at the `boxes` it
/// crosses: one closed sub-path where it crosses none, else each side's
/// pieces.
fn frame_d(corners: &[Point; 4], boxes: &[Frame]) -> PathData {
    let sides: Vec<(Point, Point)> = (0..4)
        .filter_map(|k| Some((*corners.get(k)?, *corners.get((k + 1) % 4)?)))
        .collect();
    let cut: Vec<Vec<(Point, Point)>> = sides.iter().map(|&(a, b)| pieces(a, b, boxes)).collect();
    if cut.iter().zip(&sides).all(|(p, s)| p.as_slice() == [*s]) {
        return polyline_d(corners, true);
    }
    let mut d = PathData::new();
    for (s, t) in cut.into_iter().flatten() {
        d.push(PathCommand::Move(s));
        d.push(PathCommand::Line(t));
    }
    d
}

/// Length of the steps along an arc at which [`arc_pieces`] looks for
/// letters, page units.
const ARC_STEP: f64 = 0.25;

/// The pieces, as fractions 0..1 of the sweep, of the arc about `centre`
/// of `radius` from the page angle `start` turning `sweep` that lie
/// outside every box (each grown by [`GAP_ROOM`]); the whole arc where it
/// crosses none. Found in steps of [`ARC_STEP`] along the arc.
fn arc_pieces(
    centre: Point,
    radius: f64,
    (start, sweep): (f64, f64),
    boxes: &[Frame],
) -> Vec<(f64, f64)> {
    let ring = Frame::around(centre, Vector::new(radius, radius));
    let near: Vec<Frame> = boxes
        .iter()
        .map(|b| b.inflate(GAP_ROOM))
        .filter(|b| b.meets(&ring))
        .collect();
    let length = (sweep * radius).abs();
    if near.is_empty() || length.is_nan() || length <= 0.0 {
        return vec![(0.0, 1.0)];
    }
    let n = ((length / ARC_STEP).ceil() as usize).clamp(1, 100_000);
    let outside = |k: usize| {
        let a = start + sweep * k as f64 / n as f64;
        let p = centre + Vector::new(a.cos(), a.sin()) * radius;
        !near.iter().any(|b| b.contains(p))
    };
    let mut out = Vec::new();
    let mut begin = None;
    for k in 0..=n {
        match (outside(k), begin) {
            (true, None) => begin = Some(k),
            (false, Some(b)) => {
                out.push((b, k - 1));
                begin = None;
            }
            _ => {}
        }
    }
    if let Some(b) = begin {
        out.push((b, n));
    }
    out.into_iter()
        .filter(|(b, e)| (e - b) as f64 / n as f64 * length > SHORTEST)
        .map(|(b, e)| (b as f64 / n as f64, e as f64 / n as f64))
        .collect()
}

/// The length of one period of a centre line's dashes ([`DASH`]): a
/// long dash, a dot and their gaps.
fn dash_period() -> f64 {
    (DASH.split(' '))
        .filter_map(|n| n.parse::<f64>().ok())
        .sum()
}

/// The `pieces` of the centre line `from`–`to` less a piece at either end
/// of it, cut off by a letter, shorter than one period of its dashes
/// ([`dash_period`]) where a longer piece stays: such a stub is one dash
/// alone beside the letter, read with it as a sign. At l = 58.2 r, 180°,
/// the line of stroke opened for A between the guides and left 9 units
/// of it beyond, and A read "−A".
fn without_stubs(from: Point, to: Point, pieces: Vec<(Point, Point)>) -> Vec<(Point, Point)> {
    let period = dash_period();
    let stub = |&(s, t): &(Point, Point)| (s == from || t == to) && (t - s).norm() < period;
    let whole = pieces.as_slice() == [(from, to)];
    if whole || pieces.iter().all(stub) {
        return pieces;
    }
    pieces.into_iter().filter(|p| !stub(p)).collect()
}

/// The pieces of the segment `from`–`to` outside every box (each grown by
/// [`GAP_ROOM`]), in order; the whole segment where it crosses none.
fn pieces(from: Point, to: Point, boxes: &[Frame]) -> Vec<(Point, Point)> {
    let d = to - from;
    let length = d.norm();
    if length == 0.0 {
        return vec![(from, to)];
    }
    let mut cuts: Vec<(f64, f64)> = boxes
        .iter()
        .filter_map(|b| span(from, d, &b.inflate(GAP_ROOM)))
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
    fn an_arc_opens_where_a_letter_sits_and_only_there() {
        let c = Point::new(0.0, 0.0);
        let quarter = std::f64::consts::FRAC_PI_2;
        // A letter over the middle of a quarter arc of radius 20.
        let mid = Point::new(
            20.0 * (0.5f64 * quarter).cos(),
            20.0 * (0.5f64 * quarter).sin(),
        );
        let letter = Frame::around(mid, Vector::new(3.0, 3.0));
        let p = arc_pieces(c, 20.0, (0.0, quarter), &[letter]);
        assert_eq!(p.len(), 2, "{p:?}");
        assert_eq!(p[0].0, 0.0);
        assert_eq!(p[1].1, 1.0);
        // Every point left is outside the grown box, and the gap is about
        // as long as the grown box is wide along the arc (9 units of 31).
        for (t0, t1) in &p {
            for t in [*t0, *t1] {
                let a = t * quarter;
                let q = Point::new(20.0 * a.cos(), 20.0 * a.sin());
                let grown = 3.0 + GAP_ROOM;
                assert!(
                    (q - mid).x.abs() > grown - 0.3 || (q - mid).y.abs() > grown - 0.3,
                    "{q:?}"
                );
            }
        }
        let gap = (p[1].0 - p[0].1) * quarter * 20.0;
        assert!(gap > 9.0 && gap < 13.5, "{gap}");
        // A letter clear of the arc leaves it whole; a clockwise sweep
        // opens the same way.
        let clear = Frame::around(Point::new(0.0, 0.0), Vector::new(3.0, 3.0));
        assert_eq!(
            arc_pieces(c, 20.0, (0.0, quarter), &[clear]),
            vec![(0.0, 1.0)]
        );
        let back = arc_pieces(c, 20.0, (quarter, -quarter), &[letter]);
        assert_eq!(back.len(), 2, "{back:?}");
        assert!((back[0].1 - (1.0 - p[1].0)).abs() < 0.02, "{back:?} {p:?}");
    }

    /// The `<path …>` tag of the element with `id` in `svg`.
    fn tag<'s>(svg: &'s str, id: &str) -> &'s str {
        let at = svg.find(&format!("id=\"{id}\"")).unwrap();
        let start = svg[..at].rfind('<').unwrap();
        &svg[start..at + svg[at..].find('>').unwrap()]
    }

    #[test]
    fn a_centre_line_is_known_by_its_part_never_by_its_id() {
        use crate::figure::{Figure, Item, PageFromWorld, Panel, Shape, Style};
        let line = |id: &str, part: Part| {
            Item::new(
                id,
                Role::Auxiliary,
                Shape::Polyline {
                    points: vec![Point::new(10.0, 50.0), Point::new(190.0, 50.0)],
                    closed: false,
                },
            )
            .as_part(part)
        };
        let items = vec![
            line("axis", Part::CentreLine),
            line("line-stroke", Part::Plain),
        ];
        let rect = Frame::from_origin_size(0.0, 0.0, 200.0, 100.0);
        let panel = Panel::new("panel", rect, PageFromWorld::identity(), items);
        let figure = Figure::new(
            "t",
            200.0,
            100.0,
            Style::Textbook,
            0.01,
            vec![panel],
            Default::default(),
        );
        let svg = crate::render::to_svg(&figure);
        let dashes = format!("stroke-dasharray=\"{DASH}\"");
        assert!(tag(&svg, "axis").contains(&dashes), "{svg}");
        assert!(!tag(&svg, "line-stroke").contains(&dashes), "{svg}");
    }

    #[test]
    fn a_line_opens_where_a_letter_sits_and_only_there() {
        let (a, b) = (Point::new(0.0, 0.0), Point::new(100.0, 0.0));
        let letter = Frame::around(Point::new(50.0, 2.0), Vector::new(5.0, 6.0));
        let p = pieces(a, b, &[letter]);
        assert_eq!(p.len(), 2, "{p:?}");
        assert_eq!(p[0].0, a);
        assert!((p[0].1.x - (45.0 - GAP_ROOM)).abs() < 1e-12);
        assert!((p[1].0.x - (55.0 + GAP_ROOM)).abs() < 1e-12);
        assert_eq!(p[1].1, b);
        // A letter clear of the line leaves it whole.
        let clear = Frame::around(Point::new(50.0, 20.0), Vector::new(5.0, 6.0));
        assert_eq!(pieces(a, b, &[clear]), vec![(a, b)]);
        // Overlapping letters make one gap; a letter over an end trims it.
        let next = Frame::around(Point::new(58.0, 0.0), Vector::new(5.0, 6.0));
        let end = Frame::around(Point::new(100.0, 0.0), Vector::new(5.0, 6.0));
        let p = pieces(a, b, &[next, letter, end]);
        assert_eq!(p.len(), 2, "{p:?}");
        assert!((p[1].0.x - (63.0 + GAP_ROOM)).abs() < 1e-12);
        assert!((p[1].1.x - (95.0 - GAP_ROOM)).abs() < 1e-12);
    }

    #[test]
    fn a_centre_line_leaves_no_stub_beyond_a_letter_at_its_end() {
        let (a, b) = (Point::new(0.0, 0.0), Point::new(100.0, 0.0));
        assert_eq!(dash_period(), 22.0);
        // A letter 10 units from the end: the 3.5 units beyond it go.
        let letter = Frame::around(Point::new(10.0, 0.0), Vector::new(5.0, 6.0));
        let kept = without_stubs(a, b, pieces(a, b, &[letter]));
        assert_eq!(kept.len(), 1, "{kept:?}");
        assert_eq!(kept[0].1, b);
        // 30 units beyond it, a period and more: they stay.
        let letter = Frame::around(Point::new(37.0, 0.0), Vector::new(5.0, 6.0));
        assert_eq!(without_stubs(a, b, pieces(a, b, &[letter])).len(), 2);
        // The line whole, however short, stays whole.
        let short = Point::new(10.0, 0.0);
        assert_eq!(without_stubs(a, short, vec![(a, short)]), vec![(a, short)]);
    }
}
