//! An angle's letter with no clear place inside its sector near its arc
//! (a narrow angle, or one crowded by the links about it): set on the
//! angle's bisector just beyond the arc, a short leader drawn from it to
//! the arc's middle, as a draughtsman letters an angle too small to hold
//! its letter.

use super::labels::{CLEARANCE, TOO_NEAR, Wedge};
use super::{APART_EMS, PanelLayout, Pending};
use crate::geom::{Frame, Point, Vector};

/// The clear gaps (page units) between the arc and the letter's box
/// tried in turn along the bisector: past a leader worth drawing, out to
/// about an em and a half.
const BEYOND: [f64; 6] = [6.0, 9.0, 12.0, 15.0, 19.0, 23.0];

/// How far (page units) the leader keeps from the arc and from the box
/// at its two ends.
const LEADER_ENDS: f64 = 1.0;

/// The least length (page units) of a leader from a letter set outside
/// its sector to its arc: shorter, the letter reads by its arc without.
const OUTSIDE_LEAST: f64 = 3.0;

/// The least cost of an angle letter's best place in its sector for it
/// to be set beyond the arc instead: its glyphs within half an em of
/// another text's, or worse.
const CROWDED: f64 = TOO_NEAR;

impl PanelLayout<'_> {
    /// The place (centre, cost) and the leader of an angle's letter whose
    /// best place in its sector, `cost`, is crowded ([`CROWDED`] or more):
    /// the first place on the bisector beyond the arc ([`BEYOND`]) whose
    /// box (half-size `half`) meets nothing, stands within `room` and
    /// half an em from every text, and whose leader to the arc crosses
    /// no line, label or part. `None` for any other label, or where no
    /// such place is found.
    pub(super) fn angle_leader(
        &self,
        p: &Pending,
        half: Vector,
        cost: f64,
        room: &Frame,
    ) -> Option<((Point, f64), (Point, Point))> {
        let (vertex, dir, _) = p.wedge?;
        if cost < CROWDED {
            return None;
        }
        // From the box's middle back along the bisector to its edge.
        let exit = (half.x / dir.x.abs()).min(half.y / dir.y.abs());
        BEYOND.into_iter().find_map(|gap| {
            let centre = p.anchor + dir * (gap + exit);
            let b = Frame::around(centre, half);
            let apart = b.inflate(APART_EMS * p.size);
            let clear = room.holds(&b)
                && self.obstacles.cost(&b.inflate(CLEARANCE)) == 0.0
                && !self.obstacles.meets_a_text(&apart)
                && (centre - vertex).norm() > (p.anchor - vertex).norm();
            let leader = (
                p.anchor + dir * LEADER_ENDS,
                p.anchor + dir * (gap - LEADER_ENDS),
            );
            let led = !self.obstacles.crosses_a_line(leader.0, leader.1)
                && !self.obstacles.crosses_a_box(leader.0, leader.1, leader.0);
            (clear && led).then_some(((centre, 0.0), leader))
        })
    }

    /// The leader from an angle's letter set outside its sector (no
    /// place inside it clear: a sector crowded by another angle's arc and
    /// letter) at `centre`, box half-size `half`, to its arc's middle:
    /// from the box's nearest point to the arc, crossing no line, label
    /// or part. `None` for a letter inside its sector or any other label,
    /// or where the leader would be too short or not clear.
    pub(super) fn outside_leader(
        &self,
        p: &Pending,
        centre: Point,
        half: Vector,
    ) -> Option<(Point, Point)> {
        let (vertex, middle, size) = p.wedge?;
        let wedge = Wedge {
            vertex,
            middle,
            half: size,
        };
        if wedge.holds(centre) {
            return None;
        }
        let b = Frame::around(centre, half);
        let from = Point::new(
            p.anchor.x.clamp(b.min().x, b.max().x),
            p.anchor.y.clamp(b.min().y, b.max().y),
        );
        let d = p.anchor - from;
        let length = d.norm();
        if length < OUTSIDE_LEAST + 2.0 * LEADER_ENDS {
            return None;
        }
        let u = d / length;
        let (a, z) = (from + u * LEADER_ENDS, p.anchor - u * LEADER_ENDS);
        let clear = !self.obstacles.crosses_a_line(a, z) && !self.obstacles.crosses_a_box(a, z, a);
        clear.then_some((a, z))
    }
}
