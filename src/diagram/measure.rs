//! Measuring a path against the exact curve, independently of how the path
//! was made.
//!
//! Both are sampled densely in page space (the curve adaptively, so that
//! neighbouring samples are at most 1/1024 of the frame's diagonal apart,
//! the path at 17 points per cubic and 9 per line, finer when long). For
//! each sample of one, the nearest samples of the other are found through a
//! grid of cells, and the distance is refined by a golden-section search of
//! the exact point (curve or segment) between the neighbouring samples.
//! Every distance found is the distance to a real point of the other set,
//! so it can only err upwards. The largest distances found are then refined
//! by a golden-section search for the maximum between their neighbouring
//! samples, so the largest deviation is located, not only sampled.

use super::{Affine, Curve, Path, Segment};
use crate::geom::{Frame, Point};
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
/// Golden-section steps (the bracket shrinks to 0.618^32 ≈ 2e-7 of itself).
const GOLDEN_STEPS: usize = 32;
/// Samples per line segment and per cubic at least.
const LINE_SAMPLES: f64 = 8.0;
const CUBIC_SAMPLES: f64 = 16.0;
/// How many of the largest sampled distances are refined.
const REFINED_MAXIMA: usize = 8;

/// Measures `path` (page coordinates) against `curve` over `range` mapped
/// by the page-from-world `map`, with `frame` the plot area it was clipped to.
///
/// Degenerate cases: an empty or reversed range has no curve points; a frame
/// of zero size samples at a spacing of 1e-9 page units.
pub fn measure<C: Curve + ?Sized>(
    path: &Path,
    curve: &C,
    range: RangeInclusive<f64>,
    map: &Affine,
    frame: &Frame,
) -> Deviation {
    let diag = (frame.max() - frame.min()).norm();
    let spacing = (diag * SPACING).max(1e-9);
    let margin = 0.05 * diag + 64.0 * spacing;
    let m = nalgebra::Vector2::new(margin, margin);
    let region = Frame::new(frame.min() - m, frame.max() + m);

    let curve_at = |_: usize, t: f64| -> Option<Point> {
        let (p, _) = curve.eval(t)?;
        let p = map.point(p);
        (p.x.is_finite() && p.y.is_finite()).then_some(p)
    };
    let curve_cloud = Cloud::new(
        sample_curve(&curve_at, range, &region, spacing),
        &region,
        spacing,
    );

    let segments: Vec<_> = path.subpaths().iter().flat_map(|s| s.pieces()).collect();
    let path_at = |k: usize, u: f64| -> Option<Point> {
        let (start, seg) = segments.get(k)?;
        Some(seg.eval(*start, u))
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
        for j in 0..=n {
            let u = j as f64 / n as f64;
            path_samples.push((k, u, Some(seg.eval(*start, u))));
        }
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

/// The largest `distance` over the samples of `cloud` that `keep` accepts,
/// with the few largest refined by a golden-section search for the maximum
/// between their neighbours (`at` gives the exact points).
fn largest(
    cloud: &Cloud,
    at: &impl Fn(usize, f64) -> Option<Point>,
    distance: impl Fn(Point) -> f64,
    keep: impl Fn(Point) -> bool,
) -> f64 {
    let mut scored: Vec<(f64, usize)> = cloud
        .samples
        .iter()
        .enumerate()
        .filter_map(|(i, s)| s.2.filter(|p| keep(*p)).map(|p| (distance(p), i)))
        .collect();
    let mut best = scored.iter().map(|s| s.0).fold(0.0, f64::max);
    if scored.len() > REFINED_MAXIMA {
        scored.select_nth_unstable_by(REFINED_MAXIMA, |a, b| b.0.total_cmp(&a.0));
        scored.truncate(REFINED_MAXIMA);
    }
    for (_, i) in scored {
        let (lo, hi, piece) = cloud.bracket(i);
        let f = |t: f64| {
            at(piece, t)
                .filter(|p| keep(*p))
                .map_or(0.0, |p| -distance(p))
        };
        best = best.max(-golden(f, lo, hi));
    }
    best
}

/// Samples `(piece, parameter, point)` of the curve in parameter order,
/// refined until neighbours are `spacing` apart where it matters.
fn sample_curve(
    at: &impl Fn(usize, f64) -> Option<Point>,
    range: RangeInclusive<f64>,
    region: &Frame,
    spacing: f64,
) -> Vec<(usize, f64, Option<Point>)> {
    let (start, end) = range.into_inner();
    let mut out = Vec::new();
    if !(start.is_finite() && end.is_finite() && end >= start) {
        return out;
    }
    let ts: Vec<f64> = (0..=BASE_SAMPLES)
        .map(|i| {
            if i == BASE_SAMPLES {
                end
            } else {
                start + (end - start) * (i as f64 / BASE_SAMPLES as f64)
            }
        })
        .collect();
    let mut prev = (ts[0], at(0, ts[0]));
    out.push((0, prev.0, prev.1));
    for &t in &ts[1..] {
        let next = (t, at(0, t));
        refine(at, prev, next, 0, region, spacing, &mut out);
        out.push((0, next.0, next.1));
        prev = next;
    }
    out
}

/// Pushes the samples strictly between `a` and `b`.
fn refine(
    at: &impl Fn(usize, f64) -> Option<Point>,
    a: (f64, Option<Point>),
    b: (f64, Option<Point>),
    depth: u32,
    region: &Frame,
    spacing: f64,
    out: &mut Vec<(usize, f64, Option<Point>)>,
) {
    if depth >= MAX_REFINE || out.len() >= MAX_SAMPLES {
        return;
    }
    let split = match (a.1, b.1) {
        (Some(p), Some(q)) => {
            let (lo, hi) = (region.min(), region.max());
            let same_side = (p.x < lo.x && q.x < lo.x)
                || (p.x > hi.x && q.x > hi.x)
                || (p.y < lo.y && q.y < lo.y)
                || (p.y > hi.y && q.y > hi.y);
            !same_side && (p - q).norm() > spacing
        }
        (None, None) => depth < 4,
        _ => true,
    };
    let m = 0.5 * (a.0 + b.0);
    if !(split && a.0 < m && m < b.0) {
        return;
    }
    let mid = (m, at(0, m));
    refine(at, a, mid, depth + 1, region, spacing, out);
    out.push((0, mid.0, mid.1));
    refine(at, mid, b, depth + 1, region, spacing, out);
}

/// Samples of a curve or path, in parameter order, with a grid of cells over
/// the region for nearest-sample queries.
struct Cloud {
    samples: Vec<(usize, f64, Option<Point>)>,
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
    fn new(samples: Vec<(usize, f64, Option<Point>)>, region: &Frame, spacing: f64) -> Self {
        let size = region.max() - region.min();
        let cell = (size.x.max(size.y) / 512.0).max(spacing);
        let nx = ((size.x / cell).ceil() as usize).clamp(1, 1024);
        let ny = ((size.y / cell).ceil() as usize).clamp(1, 1024);
        let origin = region.min();
        let mut keyed: Vec<(usize, usize)> = samples
            .iter()
            .enumerate()
            .filter_map(|(i, &(_, _, p))| {
                let p = p?;
                let (cx, cy) = Self::cell_of(origin, cell, p);
                (cx >= 0 && cy >= 0 && (cx as usize) < nx && (cy as usize) < ny)
                    .then(|| (cy as usize * nx + cx as usize, i))
            })
            .collect();
        keyed.sort_unstable();
        let mut starts = vec![0; nx * ny + 1];
        for &(c, _) in &keyed {
            starts[c + 1] += 1;
        }
        for c in 0..nx * ny {
            starts[c + 1] += starts[c];
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

    fn point(&self, i: usize) -> Point {
        self.samples[i].2.unwrap_or(Point::origin())
    }

    /// The indexed samples within `slack` of the nearest one to `q`, and the
    /// nearest distance (infinite when none is indexed).
    fn near(&self, q: Point, slack: f64) -> (f64, Vec<usize>) {
        let mut seen: Vec<(f64, usize)> = Vec::new();
        if self.members.is_empty() {
            return (f64::INFINITY, seen.into_iter().map(|s| s.1).collect());
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
                            for &i in &self.members[self.starts[c]..self.starts[c + 1]] {
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
        let near = seen
            .into_iter()
            .filter(|s| s.0 <= best + slack)
            .map(|s| s.1)
            .collect();
        (best, near)
    }

    /// The parameters of the neighbours of sample `i` in its piece (its own
    /// at the ends), and the piece.
    fn bracket(&self, i: usize) -> (f64, f64, usize) {
        let (piece, t, _) = self.samples[i];
        let neighbour = |j: Option<usize>| {
            j.and_then(|j| self.samples.get(j))
                .filter(|s| s.0 == piece)
                .map_or(t, |s| s.1)
        };
        (neighbour(i.checked_sub(1)), neighbour(Some(i + 1)), piece)
    }

    /// Distance from `q` to sample `j`, infinite when there is none (or it
    /// is in another piece than `piece`).
    fn sample_distance(&self, j: Option<usize>, piece: usize, q: Point) -> f64 {
        j.and_then(|j| self.samples.get(j))
            .filter(|s| s.0 == piece)
            .and_then(|s| s.2)
            .map_or(f64::INFINITY, |p| (p - q).norm())
    }

    /// The distance from `q` to the set the samples come from, `at` giving
    /// its exact points: the nearest samples that are local minima of the
    /// distance along their piece, each refined between its neighbours.
    fn distance(&self, q: Point, at: &impl Fn(usize, f64) -> Option<Point>) -> f64 {
        let (mut best, near) = self.near(q, self.spacing);
        for i in near {
            let piece = self.samples[i].0;
            let d = self.sample_distance(Some(i), piece, q);
            if d > self.sample_distance(i.checked_sub(1), piece, q)
                || d > self.sample_distance(Some(i + 1), piece, q)
            {
                continue;
            }
            let (lo, hi, _) = self.bracket(i);
            let f = |s: f64| at(piece, s).map_or(f64::INFINITY, |p| (p - q).norm());
            best = best.min(golden(f, lo, hi));
        }
        best
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
