//! A link drawn past a pin or a lettered crossing it is not joined at:
//! the line hops over it in a half circle, as a draughtsman draws one
//! part passing another without a joint. Drawn straight through, the
//! inversions' turning bar d with its offset leg read as pivoted at the
//! crank's pin O_ab wherever its leg ran over it, and as pinned to the
//! rod at O_ac, the crossing a centre's letter named.

use crate::geom::{Point, Vector, cross};

/// A point the line must not run through, with the directions (from it)
/// of what meets it there: the hop bulges away from them.
pub(super) struct Over {
    /// The pin or the crossing.
    pub at: Point,
    /// The directions of the links (and a bearing) at it.
    pub away_from: Vec<Vector>,
}

/// Points per hop's half circle.
const STEPS: usize = 12;

/// `points` (a polyline) with a half circle of `radius` about the foot of
/// each point of `over` that lies within `radius` of one of its pieces,
/// not within `radius` of the piece's ends (a joint of the link itself);
/// the half circle bulges to the side whose middle stands farthest in
/// angle from the point's `away_from`. A piece with no such point, or a
/// `radius` that is not positive, is left as it is.
pub(super) fn hopped(points: &[Point], over: &[Over], radius: f64) -> Vec<Point> {
    let Some(&first) = points.first() else {
        return Vec::new();
    };
    let mut out = vec![first];
    for pair in points.windows(2) {
        let (p, q) = (pair[0], pair[1]);
        let length = (q - p).norm();
        if !(radius > 0.0 && length > 2.0 * radius) {
            out.push(q);
            continue;
        }
        let u = (q - p) / length;
        let mut feet: Vec<(f64, &Over)> = (over.iter())
            .filter_map(|o| {
                let s = (o.at - p).dot(&u);
                let h = cross(&u, &(o.at - p)).abs();
                (h < radius && s > radius && s < length - radius).then_some((s, o))
            })
            .collect();
        feet.sort_by(|a, b| a.0.total_cmp(&b.0));
        let mut last = f64::NEG_INFINITY;
        for (s, o) in feet {
            // Two hops that would overlap: the first serves.
            if s - last < 2.0 * radius {
                continue;
            }
            last = s;
            out.extend(half_circle(p + u * s, u, side(u, &o.away_from), radius));
        }
        out.push(q);
    }
    out
}

/// The normal to `u` on the side farther in angle from every direction
/// of `away`.
fn side(u: Vector, away: &[Vector]) -> Vector {
    let n = Vector::new(-u.y, u.x);
    let least = |m: Vector| {
        (away.iter())
            .filter(|d| d.norm() > 0.0)
            .map(|d| m.dot(&d.normalize()).clamp(-1.0, 1.0).acos())
            .fold(f64::INFINITY, f64::min)
    };
    if least(-n) > least(n) { -n } else { n }
}

/// The half circle of `radius` about `m` from `m − u·radius` to
/// `m + u·radius`, bulging towards `n`.
fn half_circle(m: Point, u: Vector, n: Vector, radius: f64) -> impl Iterator<Item = Point> {
    (0..=STEPS).map(move |k| {
        let a = std::f64::consts::PI * (1.0 - k as f64 / STEPS as f64);
        m + u * (radius * a.cos()) + n * (radius * a.sin())
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_line_hops_over_a_pin_on_it_away_from_the_links_there() {
        let line = [Point::new(0.0, 0.0), Point::new(10.0, 0.0)];
        // A pin at (5, 0) with a link leaving it upwards.
        let over = [Over {
            at: Point::new(5.0, 0.2),
            away_from: vec![Vector::new(0.0, 1.0)],
        }];
        let hop = hopped(&line, &over, 1.0);
        assert_eq!(hop.len(), 2 + STEPS + 1);
        // It passes no nearer the pin than the radius less its offset,
        // and bulges downwards, away from the link.
        let nearest = (hop.windows(2))
            .map(|w| crate::geom::point_segment_distance(over[0].at, w[0], w[1]))
            .fold(f64::INFINITY, f64::min);
        assert!(nearest > 0.75, "{nearest}");
        assert!(hop.iter().all(|p| p.y <= 1e-12));
        assert!(hop.iter().any(|p| p.y < -0.99));
    }

    #[test]
    fn a_pin_off_the_line_or_at_its_end_is_not_hopped() {
        let line = [Point::new(0.0, 0.0), Point::new(10.0, 0.0)];
        for at in [
            Point::new(5.0, 1.5),
            Point::new(0.5, 0.0),
            Point::new(9.5, 0.0),
        ] {
            let over = [Over {
                at,
                away_from: vec![],
            }];
            assert_eq!(hopped(&line, &over, 1.0), line.to_vec(), "{at:?}");
        }
    }
}
