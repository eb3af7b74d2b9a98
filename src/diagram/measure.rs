//! Measuring a path against the exact curve, independently of how the path
//! was made.
//!
//! Both are sampled densely in page space: the path at 17 points per cubic
//! and 9 per line at least, the curve at 2004; both are refined until
//! neighbouring samples are at most 1/1024 of the frame's diagonal apart
//! and the tangent turns by less than 10° from one to the next. For
//! each sample of one, the nearby samples of the other are found through a
//! grid of cells; every interval next to a sample that may neighbour the
//! nearest point (its distance is within the local sample spacing of the
//! least) is searched for the exact nearest point, a root of
//! (p(t) − q)·p′(t), by the Illinois method on the exact point and
//! derivative (curve or segment). Every distance found is the distance to a
//! real point of the other set, so it can only err upwards. The largest
//! distances found are then refined by a golden-section search for the
//! maximum between their neighbouring samples, so the largest deviation is
//! located, not only sampled.

use super::{Curve, Segment, TracedPath};
use crate::figure::PageFromWorld;
use crate::geom::{Frame, Point, Vector};
use std::ops::RangeInclusive;

/// How far a path is from a curve, in page units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Deviation {
    /// The largest distance from a point of the path to the exact curve
    /// (over the whole range, inside or outside the frame). 0 for an empty
    /// path; infinite when the path has points but the curve none near the
    /// frame.
    pub path_to_curve: f64,
    /// The largest distance from a point of the exact curve inside the frame
    /// to the path: how completely the path draws what is visible. 0 when
    /// the curve does not enter the frame; infinite when it does and the path
    /// is empty.
    pub curve_to_path: f64,
}

impl Deviation {
    /// The larger of the two: the Hausdorff distance between the path and
    /// the visible curve.
    pub fn max(&self) -> f64 {
        self.path_to_curve.max(self.curve_to_path)
    }
}

/// Curve samples per range before refinement: a prime, so that they do not
/// fall on the dyadic parameters where a traced path has its vertices (and
/// is exact).
const BASE_SAMPLES: usize = 2003;
/// Sample spacing as a fraction of the frame's diagonal.
const SPACING: f64 = 1.0 / 1024.0;
/// Halvings of a base interval at most.
const MAX_REFINE: u32 = 30;
/// Samples in all at most (the refinement stops there).
const MAX_SAMPLES: usize = 1 << 22;
/// Golden-section steps (the bracket shrinks to 0.618^48 ≈ 1e-10 of itself).
const GOLDEN_STEPS: usize = 48;
/// Illinois steps at most.
const ROOT_STEPS: usize = 60;
/// The largest turn of the tangent between neighbouring samples: 10°.
const MAX_TURN: f64 = std::f64::consts::PI / 18.0;
/// Samples per line segment and per cubic at least.
const LINE_SAMPLES: f64 = 8.0;
const CUBIC_SAMPLES: f64 = 16.0;
/// How many of the largest sampled distances are refined.
const REFINED_MAXIMA: usize = 8;

/// Measures `path` (page coordinates) against `curve` over `range` mapped
/// by the page-from-world `map`, with `frame` the plot area it was clipped to.
///
/// Degenerate cases: an empty or reversed range has no curve points; a frame
/// that is not finite is replaced, for sampling, by the path's bounding box
/// (nothing is then inside it unless it is infinite), and a frame or box of
/// zero size takes its sample spacing from the path's extent (1/1024 of it,
/// or 1/1024 page unit for an empty path).
pub fn measure<C: Curve + ?Sized>(
    path: &TracedPath,
    curve: &C,
    range: RangeInclusive<f64>,
    map: &PageFromWorld,
    frame: &Frame,
) -> Deviation {
    let finite_frame = [frame.min(), frame.max()]
        .iter()
        .all(|p| p.x.is_finite() && p.y.is_finite());
    let path_box = bounds(path);
    let (lo, hi) = if finite_frame {
        (frame.min(), frame.max())
    } else {
        path_box.unwrap_or((Point::origin(), Point::origin()))
    };
    let diag = (hi - lo).norm();
    let extent = if diag > 0.0 {
        diag
    } else {
        path_box.map_or(0.0, |(a, b)| (b - a).norm()).max(1.0)
    };
    let spacing = extent * SPACING;
    let margin = 0.05 * extent + 64.0 * spacing;
    let m = Vector::new(margin, margin);
    let region = Frame::new(lo - m, hi + m);

    let curve_at = |_: usize, t: f64| -> At {
        let (p, d) = curve.eval(t)?;
        let (p, d) = (map.apply(p), map.apply_vector(d));
        finite(p, d).then_some((p, d))
    };
    let curve_cloud = Cloud::new(
        sample_curve(&curve_at, range, &region, spacing),
        &region,
        spacing,
    );

    let segments: Vec<_> = path.subpaths().iter().flat_map(|s| s.pieces()).collect();
    let path_at = |k: usize, u: f64| -> At {
        let (start, seg) = segments.get(k)?;
        Some((seg.eval(*start, u), seg.derivative(*start, u)))
    };
    let mut path_samples = Vec::new();
    for (k, (start, seg)) in segments.iter().enumerate() {
        let (polygon, least) = match *seg {
            Segment::Line(p) => ((p - start).norm(), LINE_SAMPLES),
            Segment::Cubic(a, b, p) => (
                (a - start).norm() + (b - a).norm() + (p - b).norm(),
                CUBIC_SAMPLES,
            ),
        };
        // An even count, so that u = 1/2 is a sample.
        let n = 2 * ((polygon / spacing / 2.0).ceil().clamp(least / 2.0, 32768.0) as usize);
        let ts = (0..=n).map(|j| j as f64 / n as f64);
        sample_piece(k, &path_at, ts, &region, spacing, &mut path_samples);
    }
    let path_cloud = Cloud::new(path_samples, &region, spacing);

    let path_to_curve = largest(
        &path_cloud,
        &path_at,
        |q| curve_cloud.distance(q, &curve_at),
        |_| true,
    );
    let curve_to_path = largest(
        &curve_cloud,
        &curve_at,
        |q| path_cloud.distance(q, &path_at),
        |p| frame.contains(p),
    );
    Deviation {
        path_to_curve,
        curve_to_path,
    }
}

/// The bounding box of the path's points and control points, when finite.
fn bounds(path: &TracedPath) -> Option<(Point, Point)> {
    let mut points = path.subpaths().iter().flat_map(|s| {
        std::iter::once(s.start()).chain(s.segments().iter().flat_map(|g| match *g {
            Segment::Line(p) => [p, p, p],
            Segment::Cubic(a, b, p) => [a, b, p],
        }))
    });
    let first = points.next()?;
    let (lo, hi) = points.fold((first, first), |(lo, hi), p| (lo.inf(&p), hi.sup(&p)));
    let finite = lo.x.is_finite() && lo.y.is_finite() && hi.x.is_finite() && hi.y.is_finite();
    finite.then_some((lo, hi))
}

/// A point and its derivative with respect to the parameter of its piece.
type At = Option<(Point, Vector)>;

fn finite(p: Point, d: Vector) -> bool {
    p.x.is_finite() && p.y.is_finite() && d.x.is_finite() && d.y.is_finite()
}

/// One sample: the piece (segment index, or 0 for the curve), its parameter
/// and what is there.
#[derive(Debug, Clone, Copy)]
struct Sample {
    piece: usize,
    t: f64,
    at: At,
}

impl Sample {
    fn point(&self) -> Option<Point> {
        self.at.map(|(p, _)| p)
    }
}

/// The largest `distance` over the samples of `cloud` that `keep` accepts,
/// with the few largest refined by a golden-section search for the maximum
/// between their neighbours (`at` gives the exact points).
fn largest(
    cloud: &Cloud,
    at: &impl Fn(usize, f64) -> At,
    distance: impl Fn(Point) -> f64,
    keep: impl Fn(Point) -> bool,
) -> f64 {
    let mut scored: Vec<(f64, usize)> = cloud
        .samples
        .iter()
        .enumerate()
        .filter_map(|(i, s)| s.point().filter(|p| keep(*p)).map(|p| (distance(p), i)))
        .collect();
    let mut best = scored.iter().map(|s| s.0).fold(0.0, f64::max);
    if scored.len() > REFINED_MAXIMA {
        scored.select_nth_unstable_by(REFINED_MAXIMA, |a, b| b.0.total_cmp(&a.0));
        scored.truncate(REFINED_MAXIMA);
    }
    for (_, i) in scored {
        let (lo, hi) = (cloud.neighbour(i, -1), cloud.neighbour(i, 1));
        let piece = cloud.sample(i).piece;
        let f = |t: f64| {
            at(piece, t)
                .map(|(p, _)| p)
                .filter(|p| keep(*p))
                .map_or(0.0, |p| -distance(p))
        };
        best = best.max(-golden(f, cloud.sample(lo).t, cloud.sample(hi).t));
    }
    best
}

/// Samples of the curve in parameter order (see [`sample_piece`]).
fn sample_curve(
    at: &impl Fn(usize, f64) -> At,
    range: RangeInclusive<f64>,
    region: &Frame,
    spacing: f64,
) -> Vec<Sample> {
    let (start, end) = range.into_inner();
    let mut out = Vec::new();
    if !(start.is_finite() && end.is_finite() && end >= start) {
        return out;
    }
    let ts = (0..=BASE_SAMPLES).map(|i| {
        if i == BASE_SAMPLES {
            end
        } else {
            start + (end - start) * (i as f64 / BASE_SAMPLES as f64)
        }
    });
    sample_piece(0, at, ts, region, spacing, &mut out);
    out
}

/// Appends samples of `piece` at the parameters `ts` (increasing), refined
/// between them until neighbours are at most `spacing` apart and the
/// tangent turns by less than [`MAX_TURN`] from one to the next (and from
/// either to the chord), wherever the curve is not wholly to one side of
/// `region`. Between such neighbours the distance to any point has at most
/// one minimum, which the nearest-point search relies on.
fn sample_piece(
    piece: usize,
    at: &impl Fn(usize, f64) -> At,
    mut ts: impl Iterator<Item = f64>,
    region: &Frame,
    spacing: f64,
    out: &mut Vec<Sample>,
) {
    let sample = |t: f64| Sample {
        piece,
        t,
        at: at(piece, t),
    };
    let Some(first) = ts.next() else {
        return;
    };
    let mut prev = sample(first);
    out.push(prev);
    for t in ts {
        let next = sample(t);
        refine(&sample, prev, next, 0, region, spacing, out);
        out.push(next);
        prev = next;
    }
}

/// Whether the tangent turns by more than [`MAX_TURN`] between two samples
/// or either tangent is that far from their chord.
fn turns(a: (Point, Vector), b: (Point, Vector)) -> bool {
    let cos = MAX_TURN.cos();
    let chord = b.0 - a.0;
    let bent = |u: Vector, v: Vector| u.dot(&v) < cos * u.norm() * v.norm();
    if chord.norm() == 0.0 {
        return false;
    }
    bent(a.1, b.1) || bent(a.1, chord) || bent(chord, b.1)
}

/// Pushes the samples strictly between `a` and `b`.
fn refine(
    sample: &impl Fn(f64) -> Sample,
    a: Sample,
    b: Sample,
    depth: u32,
    region: &Frame,
    spacing: f64,
    out: &mut Vec<Sample>,
) {
    if depth >= MAX_REFINE || out.len() >= MAX_SAMPLES {
        return;
    }
    let split = match (a.at, b.at) {
        (Some(pa), Some(pb)) => {
            let (p, q) = (pa.0, pb.0);
            let (lo, hi) = (region.min(), region.max());
            let same_side = (p.x < lo.x && q.x < lo.x)
                || (p.x > hi.x && q.x > hi.x)
                || (p.y < lo.y && q.y < lo.y)
                || (p.y > hi.y && q.y > hi.y);
            !same_side && ((p - q).norm() > spacing || turns(pa, pb))
        }
        (None, None) => depth < 4,
        _ => true,
    };
    let m = 0.5 * (a.t + b.t);
    if !(split && a.t < m && m < b.t) {
        return;
    }
    let mid = sample(m);
    refine(sample, a, mid, depth + 1, region, spacing, out);
    out.push(mid);
    refine(sample, mid, b, depth + 1, region, spacing, out);
}

/// Samples of a curve or path, in parameter order, with a grid of cells over
/// the region for nearest-sample queries.
struct Cloud {
    samples: Vec<Sample>,
    origin: Point,
    cell: f64,
    nx: usize,
    ny: usize,
    /// `starts[c]..starts[c + 1]` indexes `members` for cell `c`.
    starts: Vec<usize>,
    members: Vec<usize>,
    spacing: f64,
}

impl Cloud {
    fn new(samples: Vec<Sample>, region: &Frame, spacing: f64) -> Self {
        let size = region.max() - region.min();
        let cell = (size.x.max(size.y) / 512.0).max(spacing);
        let nx = ((size.x / cell).ceil() as usize).clamp(1, 1024);
        let ny = ((size.y / cell).ceil() as usize).clamp(1, 1024);
        let origin = region.min();
        let mut keyed: Vec<(usize, usize)> = samples
            .iter()
            .enumerate()
            .filter_map(|(i, s)| {
                let (cx, cy) = Self::cell_of(origin, cell, s.point()?);
                (cx >= 0 && cy >= 0 && (cx as usize) < nx && (cy as usize) < ny)
                    .then(|| (cy as usize * nx + cx as usize, i))
            })
            .collect();
        keyed.sort_unstable();
        let mut starts = vec![0; nx * ny + 1];
        for &(c, _) in &keyed {
            if let Some(count) = starts.get_mut(c + 1) {
                *count += 1;
            }
        }
        let mut total = 0;
        for start in &mut starts {
            total += *start;
            *start = total;
        }
        Self {
            members: keyed.into_iter().map(|(_, i)| i).collect(),
            samples,
            origin,
            cell,
            nx,
            ny,
            starts,
            spacing,
        }
    }

    fn cell_of(origin: Point, cell: f64, p: Point) -> (i64, i64) {
        let c = (p - origin) / cell;
        (c.x.floor() as i64, c.y.floor() as i64)
    }

    /// The sample at `i`.
    // cannot fail: every index a cloud hands around is a position in its
    // `samples` (which never change after `new`): from their enumeration
    // (`members`, the maxima in `largest`), or `neighbour`'s, which is
    // either its argument or checked with `get`.
    #[allow(clippy::indexing_slicing)]
    fn sample(&self, i: usize) -> &Sample {
        &self.samples[i]
    }

    fn point(&self, i: usize) -> Point {
        self.sample(i).point().unwrap_or(Point::origin())
    }

    /// The index of the sample `step` (±1) from `i` in the same piece, or
    /// `i` itself at the end of its piece.
    fn neighbour(&self, i: usize, step: isize) -> usize {
        i.checked_add_signed(step)
            .filter(|&j| {
                self.samples
                    .get(j)
                    .is_some_and(|s| s.piece == self.sample(i).piece)
            })
            .unwrap_or(i)
    }

    /// The indexed samples within `slack` of the nearest one to `q`, with
    /// their distances, and the nearest distance (infinite when none is
    /// indexed).
    fn near(&self, q: Point, slack: f64) -> (f64, Vec<(f64, usize)>) {
        let mut seen: Vec<(f64, usize)> = Vec::new();
        if self.members.is_empty() {
            return (f64::INFINITY, seen);
        }
        let (qx, qy) = Self::cell_of(self.origin, self.cell, q);
        let inside = qx >= 0 && qy >= 0 && (qx as usize) < self.nx && (qy as usize) < self.ny;
        if !inside {
            seen = self
                .members
                .iter()
                .map(|&i| ((self.point(i) - q).norm(), i))
                .collect();
        } else {
            let mut best = f64::INFINITY;
            let reach = self.nx.max(self.ny) as i64;
            for r in 0..=reach {
                for cy in (qy - r).max(0)..=(qy + r).min(self.ny as i64 - 1) {
                    let ring_row = cy == qy - r || cy == qy + r;
                    let step = if ring_row { 1 } else { (2 * r).max(1) };
                    let mut cx = qx - r;
                    while cx <= qx + r {
                        if cx >= 0 && (cx as usize) < self.nx {
                            let c = cy as usize * self.nx + cx as usize;
                            let members = match self.starts.get(c..=c + 1) {
                                Some(&[a, b]) => self.members.get(a..b).unwrap_or_default(),
                                _ => &[],
                            };
                            for &i in members {
                                let d = (self.point(i) - q).norm();
                                best = best.min(d);
                                seen.push((d, i));
                            }
                        }
                        cx += step;
                    }
                }
                // Unvisited samples are at least r cells away.
                if best + slack <= r as f64 * self.cell {
                    break;
                }
            }
        }
        let best = seen.iter().map(|s| s.0).fold(f64::INFINITY, f64::min);
        seen.retain(|s| s.0 <= best + slack);
        (best, seen)
    }

    /// The distance from `q` to the set the samples come from, `at` giving
    /// its exact points and derivatives.
    ///
    /// The nearest point lies in an interval between two neighbouring
    /// samples, each at most the interval's length farther from `q` than it;
    /// so every interval next to a sample within the local spacing of the
    /// least sampled distance is searched.
    fn distance(&self, q: Point, at: &impl Fn(usize, f64) -> At) -> f64 {
        let (mut best, near) = self.near(q, self.spacing);
        let mut searched: Vec<usize> = Vec::new();
        for (d, i) in near {
            let (lo, hi) = (self.neighbour(i, -1), self.neighbour(i, 1));
            let gap = |j: usize| {
                self.sample(j)
                    .point()
                    .map_or(0.0, |p| (p - self.point(i)).norm())
            };
            if d > best + gap(lo).max(gap(hi)) {
                continue;
            }
            for start in [lo, i] {
                let end = self.neighbour(start, 1);
                if end == start || searched.contains(&start) {
                    continue;
                }
                searched.push(start);
                best = best.min(self.nearest_between(start, end, q, at));
            }
        }
        best
    }

    /// The least distance from `q` to the piece between samples `a` and `b`
    /// (neighbours): at a root of g(t) = (p(t) − q)·p′(t) where g changes
    /// sign from − to +, found by the Illinois method (bisection when the
    /// secant leaves the bracket), else at an end.
    fn nearest_between(&self, a: usize, b: usize, q: Point, at: &impl Fn(usize, f64) -> At) -> f64 {
        let piece = self.sample(a).piece;
        let g = |s: &Sample| s.at.map(|(p, d)| (p - q).dot(&d));
        let end_distance = |s: &Sample| s.point().map_or(f64::INFINITY, |p| (p - q).norm());
        let (sa, sb) = (*self.sample(a), *self.sample(b));
        let best = end_distance(&sa).min(end_distance(&sb));
        let (Some(mut ga), Some(mut gb)) = (g(&sa), g(&sb)) else {
            return best;
        };
        // A minimum inside: g goes from − to +. An end where the derivative
        // vanishes (a cusp) has g = 0 and counts for either sign.
        if !(ga <= 0.0 && gb >= 0.0 && (ga < 0.0 || gb > 0.0)) {
            return best;
        }
        let (mut ta, mut tb) = (sa.t, sb.t);
        let mut found = best;
        let mut side = 0;
        for _ in 0..ROOT_STEPS {
            let t = (ta * gb - tb * ga) / (gb - ga);
            let t = if t > ta && t < tb { t } else { 0.5 * (ta + tb) };
            let Some((p, d)) = at(piece, t) else {
                break;
            };
            found = found.min((p - q).norm());
            let gt = (p - q).dot(&d);
            if gt == 0.0 || !(t > ta && t < tb) {
                break;
            }
            if gt < 0.0 {
                ta = t;
                ga = gt;
                if side == -1 {
                    gb *= 0.5;
                }
                side = -1;
            } else {
                tb = t;
                gb = gt;
                if side == 1 {
                    ga *= 0.5;
                }
                side = 1;
            }
            if tb - ta <= 1e-15 * ta.abs().max(tb.abs()).max(1e-300) {
                break;
            }
        }
        found
    }
}

/// The least value of `f` found by a golden-section search on `[lo, hi]`.
fn golden(f: impl Fn(f64) -> f64, mut lo: f64, mut hi: f64) -> f64 {
    let r = 0.5 * (5f64.sqrt() - 1.0);
    let mut x1 = hi - r * (hi - lo);
    let mut x2 = lo + r * (hi - lo);
    let (mut f1, mut f2) = (f(x1), f(x2));
    let mut best = f(lo).min(f(hi)).min(f1).min(f2);
    for _ in 0..GOLDEN_STEPS {
        if f1 <= f2 {
            hi = x2;
            x2 = x1;
            f2 = f1;
            x1 = hi - r * (hi - lo);
            f1 = f(x1);
            best = best.min(f1);
        } else {
            lo = x1;
            x1 = x2;
            f1 = f2;
            x2 = lo + r * (hi - lo);
            f2 = f(x2);
            best = best.min(f2);
        }
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn golden_section_finds_a_parabola_minimum() {
        let v = golden(|x| (x - 0.3) * (x - 0.3) + 2.0, 0.0, 1.0);
        assert!((v - 2.0).abs() < 1e-15, "{v}");
    }
}
