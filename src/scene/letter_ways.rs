//! The sides links' letters are tried on first where links lie along
//! one another or meet in a narrow wedge: a draughtsman letters two links
//! on one line on its two sides, and each of a narrow wedge's links
//! outside it. (The inversions keep a rule of their own for the crank and
//! the rod beside d's bar, `catalogue::builders::inversions`.)

use crate::geom::{Point, Vector, segment_distance, unit};

/// Two links within this distance (page units) of each other, lying
/// along one another, have their letters on their two sides.
pub(crate) const LINK_LETTER_NEAR: f64 = 12.0;
/// Links within this angle (degrees) of each other lie along one another…
const ALONG: f64 = 10.0;
/// …and within this one meet in a wedge too narrow for a letter of each.
const WEDGE: f64 = 40.0;

/// The side each link's letter is tried on first (a world direction;
/// `None`: wherever the renderer finds room by it). Two links lying along
/// one another within `near` (world units) take their two sides, the
/// shorter the side away from the `pins` off their line ("b a" side by
/// side over one line named neither, l = 1.1 r at 180°); two meeting in a
/// narrow wedge each the side away from the other (b between the rod and
/// the lever c named c, l = 1.06 r at 269.41°).
pub(crate) fn letter_ways<const N: usize>(
    links: [(Point, Point); N],
    pins: &[Point],
    near: f64,
) -> [Option<Vector>; N] {
    let mut ways: [Option<Vector>; N] = [None; N];
    let dir = |(p, q): (Point, Point)| unit(q - p);
    let normal = |u: Vector| Vector::new(-u.y, u.x);
    let mid = |(p, q): (Point, Point)| Point::from((p.coords + q.coords) * 0.5);
    let get = |ways: &[Option<Vector>; N], k: usize| ways.get(k).copied().flatten();
    let set = |ways: &mut [Option<Vector>; N], k: usize, n: Vector| {
        if let Some(w) = ways.get_mut(k) {
            w.get_or_insert(n);
        }
    };
    type Pair = (usize, (Point, Point), Vector);
    let pairs = |limit: f64| {
        let mut found: Vec<(Pair, Pair)> = Vec::new();
        for (i, &li) in links.iter().enumerate() {
            for (j, &lj) in links.iter().enumerate().skip(i + 1) {
                let (Some(u), Some(v)) = (dir(li), dir(lj)) else {
                    continue;
                };
                if u.dot(&v).abs() >= limit.to_radians().cos()
                    && segment_distance(li.0, li.1, lj.0, lj.1) < near
                {
                    found.push(((i, li, u), (j, lj, v)));
                }
            }
        }
        // The narrowest first: a link between two wedges takes its side
        // out of the narrower.
        found.sort_by(|x, y| {
            let cos = |p: &(Pair, Pair)| p.0.2.dot(&p.1.2).abs();
            cos(y).total_cmp(&cos(x))
        });
        found
    };
    for (first, second) in pairs(ALONG) {
        // The shorter link first, its letter away from the pins off the
        // line the two lie along.
        let length = |(_, (p, q), _): Pair| (q - p).norm();
        let ((s, ls, u), (l, _, _)) = if length(first) <= length(second) {
            (first, second)
        } else {
            (second, first)
        };
        let n = normal(u);
        let off: f64 = (pins.iter())
            .map(|&p| (p - ls.0).dot(&n))
            .filter(|d| d.abs() > near)
            .sum();
        let n = match get(&ways, s).or(get(&ways, l).map(|w| -w)) {
            Some(w) => w,
            None if off > 0.0 => -n,
            None => n,
        };
        set(&mut ways, s, n);
        set(&mut ways, l, -n);
    }
    for (first, second) in pairs(WEDGE) {
        for ((k, lk, w), (_, lo, _)) in [(first, second), (second, first)] {
            let n = normal(w);
            let toward = (mid(lo) - mid(lk)).dot(&n);
            set(&mut ways, k, if toward > 0.0 { -n } else { n });
        }
    }
    ways
}
