//! A text naming a line (a link's length) with no place beside its own
//! line that reads as its own: set clear of everything nearby, a leader
//! drawn from it to the line, as a draughtsman names a part with no room
//! beside it.

use super::labels::{MISREAD, Segment, Steer, place_toward};
use super::{PanelLayout, Pending, ROOM};
use crate::geom::{Frame, Point, Vector, point_segment_distance};

/// How far, in font sizes, a text naming a line looks for a clear place
/// with a leader: out to 2.5, then 4 em from the line's middle.
const LED_REACH: [f64; 2] = [2.5, 4.0];

/// The share of its line (from its first end) a leader may end on: its
/// middle part, away from the joints at its ends.
const LED_ON: (f64, f64) = (0.15, 0.85);

/// The most a led text's place may cost: its box's room may touch a
/// line (the glyphs clear of it), as at a letter's first place.
const LED_CROWDED: f64 = 5.0;

/// A leader shorter than this (page units) is not drawn: the text stands
/// beside its line.
const LED_LEAST: f64 = 3.0;

/// The leader from the box `bx` to the middle part of the line `(a, b)`,
/// from the box's point nearest where it ends; `None` where the box
/// stands within [`LED_LEAST`] of it (beside the line, no leader drawn).
pub(super) fn leader_to_line(bx: &Frame, (a, b): Segment) -> Option<(Point, Point)> {
    let centre = nalgebra::center(&bx.min(), &bx.max());
    let along = b - a;
    let t = ((centre - a).dot(&along) / along.norm_squared()).clamp(LED_ON.0, LED_ON.1);
    let to = a + along * t;
    let from = Point::new(
        to.x.clamp(bx.min().x, bx.max().x),
        to.y.clamp(bx.min().y, bx.max().y),
    );
    ((to - from).norm() >= LED_LEAST).then_some((from, to))
}

impl PanelLayout<'_> {
    /// The place (centre, cost) and the leader of a text naming a line
    /// whose best place beside it, `cost`, reads as another's (another
    /// link's, or a dimension line's value: [`MISREAD`] or more): a
    /// clear place within [`LED_REACH`] of the line's middle whose leader
    /// to the line's middle part crosses no other link, dimension line,
    /// label or part. `None` where the text names no line, its place is
    /// not misread, or no such place is found (the text keeps its place).
    pub(super) fn line_leader(
        &self,
        p: &Pending,
        half: Vector,
        cost: f64,
        room: &Frame,
    ) -> Option<((Point, f64), (Point, Point))> {
        let own = p.line?;
        if cost < MISREAD {
            return None;
        }
        let on_own = |q: Point| point_segment_distance(q, own.0, own.1) < 0.5;
        let links: Vec<Segment> = (self.links.iter())
            .filter(|(p, q)| !(on_own(*p) && on_own(*q)))
            .copied()
            .collect();
        let steer = Steer {
            pair: p.size,
            led: Some((own, &links, &self.dimensions)),
            apart: super::APART_EMS * p.size,
            ..Steer::default()
        };
        let middle = nalgebra::center(&own.0, &own.1);
        LED_REACH.into_iter().find_map(|far| {
            let reach = far * p.size - ROOM;
            let (centre, cost) =
                place_toward(middle, half, p.gap, reach, steer, &self.obstacles, room);
            let leader = leader_to_line(&Frame::around(centre, half), own)?;
            (cost < LED_CROWDED).then_some(((centre, cost), leader))
        })
    }
}
