//! Sides of a polygon that lie on one line, set side by side: a folded
//! polygon's sides run over each other (inversion 2 at 180° on a short
//! rod, where o′n and a′_d k lie on one line and read as one line with a
//! head at either end), and a book draws each beside the other, a few
//! units apart, so that each arrow is its own.

use super::{Point, Vector, cross, point_segment_distance, segment_distance};

/// The sine of the angle under which two sides may run over each other
/// (about 6°).
const PARALLEL: f64 = 0.1;

/// The offset of each of `sides` (from, to; in the order drawn) that
/// sets it clear of the sides before it which it would run over, or
/// which would run over it (a short side under a long one): a side
/// near an earlier one, nearly parallel to it and sharing with it more
/// than a few `apart` of its run ([`runs_over`]), is moved `apart` across
/// (to its left, else its right, else twice that), zero for the others
/// and for sides shorter than `apart` (they are not drawn long enough to
/// run over anything). Degenerate: zero-length sides get no offset, and an empty
/// list gives an empty one.
pub(crate) fn side_by_side(sides: &[(Point, Point)], apart: f64) -> Vec<Vector> {
    set_beside(sides, apart, false)
        .into_iter()
        .map(|(tail, _)| tail)
        .collect()
}

/// As [`side_by_side`], the offsets of each side's tail and head: a side
/// moved `apart` across keeps its head on its point, its tail alone moved
/// to the side it would be moved to, where so turned it runs over none
/// of the sides before it (its head, on a point off the other side's
/// line, stands clear of it); else the whole side is moved. The engine's acceleration polygon with an offset (e =
/// 0.5, 176°) set c′q′ beside c′a′, which it leaves at a narrow angle,
/// and its head ended 7 units off q′, over a′'s letter. Degenerate as
/// [`side_by_side`].
pub(crate) fn side_by_side_ends(sides: &[(Point, Point)], apart: f64) -> Vec<(Vector, Vector)> {
    set_beside(sides, apart, true)
}

/// The offsets of the tail and head of each of `sides` ([`side_by_side`],
/// [`side_by_side_ends`]): with `turn`, a side moved keeps its head where
/// that runs over none before it.
fn set_beside(sides: &[(Point, Point)], apart: f64, turn: bool) -> Vec<(Vector, Vector)> {
    let mut drawn: Vec<(Point, Point)> = Vec::new();
    let mut offsets = Vec::new();
    let zero = Vector::zeros();
    for (i, &(from, to)) in sides.iter().enumerate() {
        let d = to - from;
        let length = d.norm();
        if !(length > apart && apart > 0.0) {
            offsets.push((zero, zero));
            continue;
        }
        let across = Vector::new(-d.y, d.x) / length;
        let clear = |(t, h): (Vector, Vector)| {
            let moved = (from + t, to + h);
            !(drawn.iter()).any(|s| runs_over(moved, *s, apart) || runs_over(*s, moved, apart))
        };
        // The sides a moved one may touch: those drawn where drawn, the
        // rest where they stand.
        let others: Vec<(Point, Point)> = (drawn.iter().copied())
            .chain(sides.iter().skip(i + 1).copied())
            .collect();
        let touched = |(t, h): &(Vector, Vector)| touches((from + t, to + h), &others, apart);
        // In place, else moved whole to the first place clear, once, one
        // and a half times or twice as far to either side, those that
        // touch fewer of the others first (else left before right, nearer
        // before farther: a side not quite on the other's line, moved
        // once away from it, may still run within `apart` of it); with
        // `turn`, moved once, turned about its head instead where that is
        // clear too (it takes the place it would take moved whole, and
        // leaves the others theirs) and the side leaves the one it runs
        // over at an angle (on one line, turned, it would be drawn
        // slanted across it), or turned to either side where it cannot
        // be moved once.
        let mut places: Vec<Vector> = [1.0, 1.5, 2.0]
            .iter()
            .flat_map(|m| [across * (m * apart), across * (-m * apart)])
            .collect();
        places.sort_by_key(|o| touched(&(*o, *o)));
        let once: Vec<Vector> = (places.iter().copied())
            .filter(|o| (o.norm() - apart).abs() <= 1e-9 * apart)
            .collect();
        let slot = once.iter().find(|o| clear((**o, **o)));
        let turnable = turn && !on_a_line((from, to), &drawn, apart);
        let turned: Vec<(Vector, Vector)> = match (turnable, slot) {
            (false, _) => Vec::new(),
            (true, Some(o)) => vec![(*o, zero)],
            (true, None) => once.iter().map(|o| (*o, zero)).collect(),
        };
        let offset = std::iter::once((zero, zero))
            .chain(turned)
            .chain(places.iter().map(|o| (*o, *o)))
            .find(|o| clear(*o))
            .unwrap_or((zero, zero));
        drawn.push((from + offset.0, to + offset.1));
        offsets.push(offset);
    }
    offsets
}

/// How many of `others` the side `moved` (set beside its place) touches:
/// comes within [`TOUCH`] of `apart` of without running over it (a side
/// it runs over is one it is set beside). Moved towards the side that
/// meets it at its tail, a side starts on that side, not at its point
/// (inversion 2 at l = 1.02 r, 90°: n a′_d, on the Coriolis component's
/// line, moved towards o′ started 7 units down o′n, under the right-angle
/// mark at n); moved across a short side, it cuts it (inversion 3 at
/// l = 1.08 r, 270.65°: o′c′, beside the Coriolis component o′k, ran
/// between k and a′_d in the ×10 detail).
fn touches(moved: (Point, Point), others: &[(Point, Point)], apart: f64) -> usize {
    (others.iter())
        .filter(|s| s.0 != s.1)
        .filter(|s| !(runs_over(moved, **s, apart) || runs_over(**s, moved, apart)))
        .filter(|s| segment_distance(moved.0, moved.1, s.0, s.1) < TOUCH * apart)
        .count()
}

/// The share of `apart` within which a side set beside its place touches
/// another ([`touches`]).
const TOUCH: f64 = 0.5;

/// Whether `side` runs over one of `drawn` whose line holds its head
/// (within [`TOUCH`] of `apart`): the two lie on one line (the engine's
/// velocity polygon at l = 1.09 r, 0°: cq along cb, q its middle), and
/// turned about its head it would be drawn slanted across the other, a
/// direction it does not have.
fn on_a_line(side: (Point, Point), drawn: &[(Point, Point)], apart: f64) -> bool {
    (drawn.iter()).any(|s| {
        let along = s.1 - s.0;
        let n = along.norm();
        let off = if n > 0.0 {
            cross(&along, &(side.1 - s.0)).abs() / n
        } else {
            f64::INFINITY
        };
        (runs_over(side, *s, apart) || runs_over(*s, side, apart)) && off < TOUCH * apart
    })
}

/// Whether the side `a` runs over the side `b`: at less than [`PARALLEL`]
/// to it and within `apart` of it over more than [`SHARED`] times `apart`
/// of its run, or over more than [`HIDDEN`] of it (measured at
/// [`SAMPLES`] points along it): two sides at a narrow angle read as one
/// line where they run that close, as much as two on one line (near 90° at a long rod xa′ runs back over c′b′ at
/// 1.2°, its end 4 units off c′).
fn runs_over(a: (Point, Point), b: (Point, Point), apart: f64) -> bool {
    let (u, v) = (b.1 - b.0, a.1 - a.0);
    if u.norm() <= 0.0 || cross(&u, &v).abs() > PARALLEL * u.norm() * v.norm() {
        return false;
    }
    let near = (0..SAMPLES)
        .map(|i| a.0 + v * ((i as f64 + 0.5) / SAMPLES as f64))
        .filter(|p| point_segment_distance(*p, b.0, b.1) < 0.999 * apart)
        .count();
    let shared = near as f64 / SAMPLES as f64 * v.norm();
    shared > (SHARED * apart).min(HIDDEN * v.norm())
}

/// The share of a side that, run over, hides it however short the run:
/// inversion 2's o′a′ at l = 1.06 r, 180°, 14 units along the heavier
/// o′a′_d, was not to be seen.
const HIDDEN: f64 = 0.5;

/// The points along a side at which its distance to another is taken.
const SAMPLES: usize = 32;

/// The run (in `apart`s) two sides share within `apart` of each other
/// before one is set beside the other: longer than where two sides at a
/// polygon's vertex meet at [`PARALLEL`] or more.
const SHARED: f64 = 3.0;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_side_over_another_is_set_beside_it_and_others_stay() {
        let p = |x, y| Point::new(x, y);
        // The second runs back over the first; the third crosses it.
        let sides = [
            (p(0.0, 0.0), p(10.0, 0.0)),
            (p(9.0, 0.0), p(2.0, 0.0)),
            (p(5.0, -3.0), p(5.0, 3.0)),
            (p(20.0, 0.0), p(30.0, 0.0)),
        ];
        let o = side_by_side(&sides, 0.5);
        assert_eq!(o[0], Vector::zeros());
        assert!((o[1].norm() - 0.5).abs() < 1e-12 && o[1].x == 0.0);
        assert_eq!(o[2], Vector::zeros());
        // On the first's line but sharing none of its run.
        assert_eq!(o[3], Vector::zeros());
        // A third side over both goes beyond them.
        let three = [sides[0], sides[1], (p(1.0, 0.0), p(8.0, 0.0))];
        let o = side_by_side(&three, 0.5);
        assert!((o[2].norm() - 0.5).abs() < 1e-12 && o[2] != o[1]);
        assert!(side_by_side(&[], 1.0).is_empty());
    }

    #[test]
    fn a_side_leaving_another_keeps_its_head_on_its_point() {
        let p = |x, y| Point::new(x, y);
        // The second leaves the first's line at its tail at 2°: set
        // beside it, its tail alone moves and its head stays.
        let sides = [(p(0.0, 0.0), p(10.0, 0.0)), (p(0.0, 0.0), p(14.0, 0.5))];
        let o = side_by_side_ends(&sides, 0.5);
        assert_eq!(o[0], (Vector::zeros(), Vector::zeros()));
        assert!((o[1].0.norm() - 0.5).abs() < 1e-12);
        assert_eq!(o[1].1, Vector::zeros());
        // On one line, the head kept would run over the first: the whole
        // side moves.
        let folded = [sides[0], (p(0.0, 0.0), p(14.0, 0.0))];
        let o = side_by_side_ends(&folded, 0.5);
        assert_eq!(o[1].0, o[1].1);
        assert!((o[1].1.norm() - 0.5).abs() < 1e-12);
    }
    #[test]
    fn a_side_is_set_beside_another_away_from_the_side_at_its_tail() {
        let p = |x, y| Point::new(x, y);
        // The second runs back over the first from its middle, where the
        // third arrives from below: set beside it below, it would start on
        // the third; it goes above.
        let sides = [
            (p(0.0, 0.0), p(10.0, 0.0)),
            (p(5.0, -3.0), p(5.0, 0.0)),
            (p(5.0, 0.0), p(0.0, 0.0)),
        ];
        let o = side_by_side(&sides, 0.5);
        assert!(o[2].y > 0.0 && o[2].x.abs() < 1e-12, "{:?}", o[2]);
        // Its left is below: with no side at its tail it goes there.
        let free = [sides[0], sides[2]];
        assert!(side_by_side(&free, 0.5)[1].y < 0.0);
    }

    #[test]
    fn a_side_on_another_s_line_is_moved_whole_not_turned() {
        let p = |x, y| Point::new(x, y);
        // The second lies along the first to its middle: turned about its
        // head it would be drawn slanted; it is moved whole.
        let sides = [(p(0.0, 0.0), p(0.0, 10.0)), (p(0.0, 0.0), p(0.0, 5.0))];
        let o = side_by_side_ends(&sides, 0.5);
        assert_eq!(o[1].0, o[1].1);
        assert!((o[1].0.norm() - 0.5).abs() < 1e-12);
    }
}
