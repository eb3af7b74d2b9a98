//! The curve engine: [`trace`] and what it needs. The method is described in
//! the module docs of [`crate::diagram`].

use super::{Segment, Subpath, TracedPath};
use crate::error::{Error, Field, Result, finite, positive};
use crate::figure::PageFromWorld;
use crate::geom::{Frame, Point, Vector, cross};
use std::ops::RangeInclusive;

/// The default tolerance of every traced curve: the largest distance, 0.01
/// page units (px), allowed between a drawn curve and the exact one. Scenes,
/// the named figures and [`TraceOptions::DEFAULT`] ask it of their curves
/// unless told otherwise (docs/design.md §6); the crate's one such
/// constant.
pub const DEFAULT_TOLERANCE: f64 = 0.01;

/// The tolerance to trace a curve to so that its path, once written with
/// every point rounded to the writer's grid ([`crate::number::GRID`], up to
/// `GRID/√2` away), is still within `tolerance` of the curve, with room for
/// the rounding of the map in the file: `tolerance − 0.8 GRID`. Below
/// `GRID` the written path cannot keep the promise whatever the trace
/// does; the curve is then traced to a fifth of `tolerance` (the two rules
/// meet at `GRID`).
pub fn trace_tolerance(tolerance: f64) -> f64 {
    let grid = crate::number::GRID;
    (tolerance - 0.8 * grid).max(0.2 * tolerance)
}

/// The largest turn of the curve's tangent between neighbouring samples
/// (an eighth of a piece) for which the geometric bound is used: 15°.
const MAX_TURN: f64 = std::f64::consts::PI / 12.0;

/// A plane curve given by its point and its exact derivative with respect to
/// the parameter, in world coordinates.
///
/// The parameter and its unit are the curve's to choose (the mechanism's
/// curves in [`super::Locus`] use the crank angle in degrees, with
/// derivatives per degree); the range given to [`trace`] is in the same
/// unit. `None` (or a non-finite value) means undefined there, for example
/// at a pole; the point should run off to infinity as a pole is approached,
/// as a centrode's does.
///
/// Any `Fn(f64) -> Option<(Point, Vector)>` is a curve.
pub trait Curve {
    /// The point and the derivative d(point)/dt at `t`, or `None`.
    fn eval(&self, t: f64) -> Option<(Point, Vector)>;
}

impl<F> Curve for F
where
    F: Fn(f64) -> Option<(Point, Vector)>,
{
    fn eval(&self, t: f64) -> Option<(Point, Vector)> {
        self(t)
    }
}

/// How a curve becomes segments.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Method {
    /// Cubic Béziers from the exact derivatives, halved until each is within
    /// the tolerance. The method for figures.
    Cubic,
    /// Line segments, halved until each chord is within the tolerance.
    Polyline,
    /// Line segments between this many equal steps of the parameter, with no
    /// error control (for comparison); still clipped to the frame. Zero steps
    /// is an error.
    Uniform(usize),
}

/// The tolerance and the limits of a trace. Limits may be added in later
/// versions: start from [`TraceOptions::DEFAULT`] (or
/// [`TraceOptions::with_tolerance`]) and set the fields wanted.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct TraceOptions {
    /// The largest distance, in page units, allowed between the path and the
    /// exact curve ([`DEFAULT_TOLERANCE`]). Must be finite and positive.
    pub tolerance: f64,
    /// Equal pieces the range is cut into before any fitting (default 4; at
    /// least 1). Ignored by [`Method::Uniform`], which uses its own count.
    pub initial_pieces: usize,
    /// How many times a first piece may be halved (default 50; values above
    /// 60 are taken as 60). A piece of the curve that is still not within the
    /// tolerance then is an error; a crossing of the frame is then taken as
    /// found.
    pub max_depth: u32,
    /// The most segments a trace may emit (default 1 000 000); more is an
    /// error.
    pub max_segments: usize,
    /// The most evaluations of the curve one trace may make (default
    /// 1 000 000, well under a second); more is an error
    /// ([`crate::error::Error::Limit`]), so that no curve takes unbounded time.
    pub max_evaluations: usize,
}

impl TraceOptions {
    /// The defaults: [`DEFAULT_TOLERANCE`], 4 initial pieces, depth 50,
    /// 1 000 000 segments, 1 000 000 evaluations.
    pub const DEFAULT: Self = Self {
        tolerance: DEFAULT_TOLERANCE,
        initial_pieces: 4,
        max_depth: 50,
        max_segments: 1_000_000,
        max_evaluations: 1_000_000,
    };

    /// The defaults with another tolerance (page units).
    pub fn with_tolerance(tolerance: f64) -> Self {
        Self {
            tolerance,
            ..Self::DEFAULT
        }
    }

    /// The defaults for a curve that is written to a file and must be
    /// within `tolerance` (page units) there: traced to
    /// [`trace_tolerance`]`(tolerance)`, which leaves room for the
    /// rounding of the written numbers.
    pub fn written(tolerance: f64) -> Self {
        Self::with_tolerance(trace_tolerance(tolerance))
    }
}

impl Default for TraceOptions {
    fn default() -> Self {
        Self::DEFAULT
    }
}

/// Traces `curve` over the parameter `range` (closed, start < end) through
/// the page-from-world `map`, clipped to `frame` (page coordinates), by
/// `method`. The result is in page coordinates; map it with
/// `map.inverse()` ([`TracedPath::transform`]) to store it in world coordinates.
///
/// Each emitted segment is within `options.tolerance` of the exact curve (a
/// measured bound, see [`crate::diagram`]) except with [`Method::Uniform`];
/// the path stays inside the frame grown by about the tolerance, and its
/// subpaths end within an eighth of the tolerance of the frame's edge where
/// the curve leaves it. A curve that is nowhere defined inside the frame
/// gives an empty path.
///
/// Errors: a tolerance that is not finite and positive, a range that is not
/// finite or not increasing, zero pieces; and [`crate::error::Error::Limit`] for a
/// curve that cannot be fitted within the depth limit (a jump, for
/// example), more segments or more evaluations than allowed.
pub fn trace<C: Curve + ?Sized>(
    curve: &C,
    range: RangeInclusive<f64>,
    map: &PageFromWorld,
    frame: &Frame,
    method: Method,
    options: &TraceOptions,
) -> Result<TracedPath> {
    let tolerance = positive(Field::Tolerance, options.tolerance)?;
    let (start, end) = range.into_inner();
    let start = finite(Field::RangeStart, start)?;
    let end = finite(Field::RangeEnd, end)?;
    let span = end - start;
    if !(span > 0.0 && span.is_finite()) {
        return Err(Error::OutOfRange {
            name: Field::RangeEnd,
            value: end,
            reason: format!("the range must increase from its start {start} by a finite amount"),
        });
    }
    let pieces = match method {
        Method::Uniform(n) => n,
        _ => options.initial_pieces,
    };
    if pieces == 0 || pieces > options.max_segments {
        return Err(Error::OutOfRange {
            name: Field::Pieces,
            value: pieces as f64,
            reason: format!("between 1 and the segment limit {}", options.max_segments),
        });
    }
    let delta = tolerance / 8.0;
    let (lo, hi) = (frame.min(), frame.max());
    let pad = Vector::new(delta, delta);
    let piece = span / pieces as f64;
    let depth = options.max_depth.min(60);
    let mut tracer = Tracer {
        curve,
        map,
        frame: *frame,
        loose: Frame::new(lo - pad, hi + pad),
        inner: (hi.x - lo.x > 2.0 * delta && hi.y - lo.y > 2.0 * delta)
            .then(|| Frame::new(lo + pad, hi - pad)),
        method,
        tolerance,
        delta,
        min_dt: piece * 0.5f64.powi(depth as i32),
        coarse_dt: piece / 64.0,
        depth,
        max_segments: options.max_segments,
        segments: 0,
        evaluations: std::cell::Cell::new(0),
        max_evaluations: options.max_evaluations,
        subpaths: Vec::new(),
        current: None,
    };
    let mut a = tracer.node(start);
    for i in 1..=pieces {
        let t = if i == pieces {
            end
        } else {
            start + span * (i as f64 / pieces as f64)
        };
        let b = tracer.node(t);
        tracer.interval(a, b)?;
        a = b;
    }
    if let Some((sub, _)) = tracer.current.take() {
        tracer.subpaths.push(sub);
    }
    Ok(TracedPath::new(tracer.subpaths))
}

thread_local! {
    /// Curve evaluations made on this thread by every trace so far.
    static EVALUATIONS: std::cell::Cell<u64> = const { std::cell::Cell::new(0) };
}

/// The curve evaluations every trace on this thread has made so far: the
/// difference over a piece of work is what its curves cost (an animation
/// bounds its frames' total by it).
pub(crate) fn evaluations_on_this_thread() -> u64 {
    EVALUATIONS.with(std::cell::Cell::get)
}

/// The curve at one parameter, in page coordinates.
#[derive(Debug, Clone, Copy)]
struct Node {
    t: f64,
    /// Page point and page derivative, both finite; `None` where undefined.
    at: Option<(Point, Vector)>,
    /// Defined and inside the frame (edge included).
    inside: bool,
}

impl Node {
    fn point(&self) -> Option<Point> {
        self.at.map(|(p, _)| p)
    }
}

struct Tracer<'a, C: ?Sized> {
    curve: &'a C,
    map: &'a PageFromWorld,
    frame: Frame,
    /// The frame grown by `delta`: a fitted piece's interior samples may
    /// stray this far outside.
    loose: Frame,
    /// The frame shrunk by `delta` (none when too small): what a part with
    /// both ends outside must miss to be skipped.
    inner: Option<Frame>,
    method: Method,
    tolerance: f64,
    /// How close a crossing is located (page units).
    delta: f64,
    /// Pieces this short are not halved.
    min_dt: f64,
    /// Parts undefined at both ends and the middle are given up below this.
    coarse_dt: f64,
    depth: u32,
    max_segments: usize,
    segments: usize,
    /// Evaluations made so far, and the most allowed.
    evaluations: std::cell::Cell<usize>,
    max_evaluations: usize,
    subpaths: Vec<Subpath>,
    /// The subpath being built and the parameter where it ends.
    current: Option<(Subpath, f64)>,
}

fn finite_point(p: &Point) -> bool {
    p.x.is_finite() && p.y.is_finite()
}

impl<C: Curve + ?Sized> Tracer<'_, C> {
    fn node(&self, t: f64) -> Node {
        self.evaluations.set(self.evaluations.get() + 1);
        EVALUATIONS.with(|n| n.set(n.get() + 1));
        let at = self
            .curve
            .eval(t)
            .map(|(p, d)| (self.map.apply(p), self.map.apply_vector(d)))
            .filter(|(p, d)| finite_point(p) && d.x.is_finite() && d.y.is_finite());
        Node {
            t,
            at,
            inside: at.is_some_and(|(p, _)| self.frame.contains(p)),
        }
    }

    /// The middle of `[a, b]`, when the piece may still be halved.
    fn midpoint(&self, a: &Node, b: &Node) -> Option<f64> {
        let m = a.t + 0.5 * (b.t - a.t);
        (b.t - a.t > self.min_dt && a.t < m && m < b.t).then_some(m)
    }

    /// An error once the curve has been evaluated more often than allowed.
    fn budget(&self, t: f64) -> Result<()> {
        if self.evaluations.get() <= self.max_evaluations {
            return Ok(());
        }
        Err(Error::Limit(format!(
            "the curve needs more than {} evaluations to be drawn within {} page units (it turns or jumps too fast near parameter {t})",
            self.max_evaluations, self.tolerance
        )))
    }

    /// Any part of the curve between two nodes.
    fn interval(&mut self, a: Node, b: Node) -> Result<()> {
        self.budget(a.t)?;
        match (a.inside, b.inside) {
            (true, true) => self.fit(a, b),
            (true, false) => {
                let (last_in, first_out) = self.crossing(a, b);
                self.fit(a, last_in)?;
                self.interval(first_out, b)
            }
            (false, true) => {
                let (last_out, first_in) = self.crossing(a, b);
                self.interval(a, last_out)?;
                self.fit(first_in, b)
            }
            (false, false) => self.outside(a, b),
        }
    }

    /// Bisection on the exact curve between one node inside and one not,
    /// until they are within `delta` of each other on the page (or the piece
    /// cannot be halved). Returns the two final nodes in parameter order.
    fn crossing(&self, a: Node, b: Node) -> (Node, Node) {
        let (mut lo, mut hi) = (a, b);
        loop {
            if let (Some(p), Some(q)) = (lo.point(), hi.point())
                && (p - q).norm() <= self.delta
            {
                break;
            }
            let Some(m) = self.midpoint(&lo, &hi) else {
                break;
            };
            let mid = self.node(m);
            if mid.inside == lo.inside {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        (lo, hi)
    }

    /// A part with neither end inside the frame: skipped when the curve
    /// clearly misses the frame there, halved otherwise.
    fn outside(&mut self, a: Node, b: Node) -> Result<()> {
        let Some(m) = self.midpoint(&a, &b) else {
            return Ok(());
        };
        let mid = self.node(m);
        let halve = mid.inside
            || match (a.at, mid.point(), b.at) {
                (Some(pa), Some(pm), Some(pb)) => !self.misses_frame(pa, pm, pb, b.t - a.t),
                (None, None, None) => b.t - a.t > self.coarse_dt,
                _ => true,
            };
        if halve {
            self.interval(a, mid)?;
            self.interval(mid, b)?;
        }
        Ok(())
    }

    /// Whether the Hermite cubic of a part, its hull grown by twice its error
    /// at the midpoint, misses the frame shrunk by `delta`.
    fn misses_frame(&self, a: (Point, Vector), mid: Point, b: (Point, Vector), h: f64) -> bool {
        let Some(inner) = self.inner else {
            return true;
        };
        let c1 = a.0 + a.1 * (h / 3.0);
        let c2 = b.0 - b.1 * (h / 3.0);
        let hermite_mid = (a.0.coords + (c1.coords + c2.coords) * 3.0 + b.0.coords) / 8.0;
        let slack = 2.0 * (hermite_mid - mid.coords).norm();
        let pts = [a.0, c1, c2, b.0, mid];
        let min_x = pts.iter().map(|p| p.x).fold(f64::INFINITY, f64::min) - slack;
        let max_x = pts.iter().map(|p| p.x).fold(f64::NEG_INFINITY, f64::max) + slack;
        let min_y = pts.iter().map(|p| p.y).fold(f64::INFINITY, f64::min) - slack;
        let max_y = pts.iter().map(|p| p.y).fold(f64::NEG_INFINITY, f64::max) + slack;
        // Written so that a NaN anywhere means "does not miss" (halve again).
        min_x > inner.max().x
            || max_x < inner.min().x
            || min_y > inner.max().y
            || max_y < inner.min().y
    }

    /// A part with both ends inside the frame.
    fn fit(&mut self, a: Node, b: Node) -> Result<()> {
        if a.t >= b.t {
            return Ok(());
        }
        if let Method::Uniform(_) = self.method {
            let (Some(_), Some(pb)) = (a.point(), b.point()) else {
                return Ok(());
            };
            return self.emit(&a, &b, Segment::Line(pb));
        }
        let h = b.t - a.t;
        let even = [
            a,
            self.node(a.t + 0.25 * h),
            self.node(a.t + 0.5 * h),
            self.node(a.t + 0.75 * h),
            b,
        ];
        self.fit_samples(even)
    }

    /// Fits the piece whose samples at u = 0, 1/4, 1/2, 3/4, 1 are `even`.
    fn fit_samples(&mut self, even: [Node; 5]) -> Result<()> {
        let [a, e1, e2, e3, b] = even;
        self.budget(a.t)?;
        let h = b.t - a.t;
        let n = [
            a,
            self.node(a.t + h * (1.0 / 8.0)),
            e1,
            self.node(a.t + h * (3.0 / 8.0)),
            e2,
            self.node(a.t + h * (5.0 / 8.0)),
            e3,
            self.node(a.t + h * (7.0 / 8.0)),
            b,
        ];
        let mut samples = [(Point::origin(), Vector::zeros()); 9];
        for (s, node) in samples.iter_mut().zip(&n) {
            match node.at {
                Some((p, d)) if self.loose.contains(p) => *s = (p, d * h),
                _ => {
                    // The curve leaves the frame (or is undefined) inside this
                    // piece: clip the two halves afresh.
                    if self.midpoint(&a, &b).is_none() {
                        return Ok(());
                    }
                    self.interval(a, n[4])?;
                    return self.interval(n[4], b);
                }
            }
        }
        let (segment, error) = match self.method {
            Method::Cubic => cubic_fit(&samples, self.tolerance),
            Method::Polyline | Method::Uniform(_) => chord_fit(&samples),
        };
        if error <= self.tolerance {
            return self.emit(&a, &b, segment);
        }
        if self.midpoint(&a, &b).is_none() {
            return Err(Error::Limit(format!(
                "the curve cannot be drawn within {} page units near parameter {}: {} halvings were not enough (error {error:.3e})",
                self.tolerance, a.t, self.depth
            )));
        }
        self.fit_samples([n[0], n[1], n[2], n[3], n[4]])?;
        self.fit_samples([n[4], n[5], n[6], n[7], n[8]])
    }

    fn emit(&mut self, a: &Node, b: &Node, segment: Segment) -> Result<()> {
        self.segments += 1;
        if self.segments > self.max_segments {
            return Err(Error::Limit(format!(
                "the curve needs more than {} segments to be drawn within {} page units",
                self.max_segments, self.tolerance
            )));
        }
        match &mut self.current {
            Some((sub, end)) if *end == a.t => {
                sub.push(segment);
                *end = b.t;
            }
            _ => {
                let Some(start) = a.point() else {
                    return Ok(());
                };
                if let Some((done, _)) = self.current.take() {
                    self.subpaths.push(done);
                }
                let mut sub = Subpath::starting_at(start);
                sub.push(segment);
                self.current = Some((sub, b.t));
            }
        }
        Ok(())
    }
}

/// The cubic for nine samples `(point, derivative per unit u)` at u = k/8,
/// and the bound on its error (see [`crate::diagram`]).
///
/// First the Hermite cubic with its parametric bound; when that exceeds
/// `tolerance`, the bound after matching each sample to its nearest point of
/// the cubic, and a second candidate with the same end tangents whose
/// lengths make it pass through the middle sample at u = 1/2, bounded the
/// same way; the candidate with the smaller bound is returned. A segment
/// whose control points are not finite gets an infinite error.
fn cubic_fit(s: &[(Point, Vector); 9], tolerance: f64) -> (Segment, f64) {
    let (p0, d0) = s[0];
    let (p3, d3) = s[8];
    let c1 = p0 + d0 / 3.0;
    let c2 = p3 - d3 / 3.0;
    let segment = Segment::Cubic(c1, c2, p3);
    if !(finite_point(&c1) && finite_point(&c2)) {
        return (segment, f64::INFINITY);
    }
    let bez = Bezier::new(p0, c1, c2, p3);
    // Parametric: e(u) = B(u) − p(u), e'(u) = B'(u) − p'(u).
    let mut parametric = [(Vector::zeros(), Vector::zeros()); 9];
    for (k, (e, (p, d))) in parametric.iter_mut().zip(s).enumerate() {
        let u = k as f64 / 8.0;
        *e = (bez.at(u) - p.coords, bez.slope(u) - d);
    }
    let mut best = (segment, hull_bound(&parametric));
    if best.1 > tolerance {
        if let Some(matched) = reparameterised(&bez, s) {
            best.1 = best.1.min(hull_bound(&matched));
        }
        if let Some((m1, m2)) = through_middle(s) {
            let bez = Bezier::new(p0, m1, m2, p3);
            if let Some(matched) = reparameterised(&bez, s) {
                let error = hull_bound(&matched);
                if error < best.1 {
                    best = (Segment::Cubic(m1, m2, p3), error);
                }
            }
        }
    }
    (
        best.0,
        if best.1.is_nan() {
            f64::INFINITY
        } else {
            best.1
        },
    )
}

/// Control points with the end tangents of the samples and lengths α, β > 0
/// chosen so that the cubic's point at u = 1/2 is the middle sample:
/// (P0 + P3)/2 + 3/8 (α T0 − β T3) = p(1/2). `None` when an end derivative
/// vanishes, the tangents are nearly parallel, or a length is not positive
/// or longer than twice the chord.
fn through_middle(s: &[(Point, Vector); 9]) -> Option<(Point, Point)> {
    let (p0, d0) = s[0];
    let (p3, d3) = s[8];
    let (n0, n3) = (d0.norm(), d3.norm());
    if n0.is_nan() || n3.is_nan() || n0 <= 0.0 || n3 <= 0.0 {
        return None;
    }
    let (t0, t3) = (d0 / n0, -d3 / n3);
    let r = (s[4].0 - nalgebra::center(&p0, &p3)) * (8.0 / 3.0);
    let det = cross(&t0, &t3);
    if det.abs() < 1e-3 {
        return None;
    }
    let alpha = cross(&r, &t3) / det;
    let beta = cross(&t0, &r) / det;
    let chord = (p3 - p0).norm();
    let ok = |x: f64| x > 0.0 && x <= 2.0 * chord;
    (ok(alpha) && ok(beta)).then(|| (p0 + t0 * alpha, p3 + t3 * beta))
}

/// The error of the cubic against the samples with the cubic reparameterised
/// by φ, the Hermite interpolant of each sample's nearest parameter u*_k on
/// the cubic with slopes that make e'(u_k) normal to the cubic:
/// e(u) = B(φ(u)) − p(u). B∘φ covers the whole cubic as φ goes from 0 to 1
/// (continuously, staying in [0, 1]), so its distance bounds the geometric
/// (Hausdorff) distance as the parametric one does, but without the
/// tangential drift of the two parameterisations.
///
/// The hull bound is only as good as the samples resolve e, so φ must be as
/// smooth as the curve: `None` (the parametric bound stands) unless the
/// curve's tangent turns by less than [`MAX_TURN`] between neighbouring
/// samples, every projection settles, φ increases with slopes within a
/// factor 2 of its secants, and φ stays in [0, 1].
fn reparameterised(bez: &Bezier, s: &[(Point, Vector); 9]) -> Option<[(Vector, Vector); 9]> {
    for ((_, a), (_, b)) in s.iter().zip(&s[1..]) {
        let (na, nb) = (a.norm(), b.norm());
        // cos of the turn between the two tangents, compared without division.
        if na.is_nan()
            || nb.is_nan()
            || na <= 0.0
            || nb <= 0.0
            || a.dot(b) < MAX_TURN.cos() * na * nb
        {
            return None;
        }
    }
    // φ and its slope at each sample.
    let mut phi = [(0.0, 1.0); 9];
    for (k, (f, &(p, d))) in phi.iter_mut().zip(s).enumerate() {
        let u = match k {
            0 => 0.0,
            8 => 1.0,
            _ => bez.nearest(p, k as f64 / 8.0)?,
        };
        let b1 = bez.slope(u);
        let speed2 = b1.norm_squared();
        if speed2.is_nan() || speed2 <= 0.0 {
            return None;
        }
        *f = (u, d.dot(&b1) / speed2);
    }
    for (&(f0, m0), &(f1, m1)) in phi.iter().zip(&phi[1..]) {
        let secant = (f1 - f0) * 8.0;
        let smooth = |m: f64| m >= 0.5 * secant && m <= 2.0 * secant;
        if secant.is_nan() || secant <= 0.0 || !smooth(m0) || !smooth(m1) {
            return None;
        }
        // φ on each eighth lies in the hull of its Hermite control values.
        let controls = [f0, f0 + m0 / 24.0, f1 - m1 / 24.0, f1];
        if !controls.iter().all(|c| (0.0..=1.0).contains(c)) {
            return None;
        }
    }
    let mut matched = [(Vector::zeros(), Vector::zeros()); 9];
    for (e, (&(f, m), &(p, d))) in matched.iter_mut().zip(phi.iter().zip(s)) {
        *e = (bez.at(f) - p.coords, bez.slope(f) * m - d);
    }
    Some(matched)
}

/// The largest norm over the Bézier hulls of the cubic Hermite interpolant
/// of an error sampled with its derivative (per unit u) at u = k/8.
fn hull_bound(e: &[(Vector, Vector); 9]) -> f64 {
    let mut worst: f64 = 0.0;
    for (&(e0, s0), &(e1, s1)) in e.iter().zip(&e[1..]) {
        for v in [e0, e0 + s0 / 24.0, e1 - s1 / 24.0, e1] {
            worst = worst.max(v.norm());
        }
    }
    worst
}

/// A cubic Bézier in power form, for points, slopes and nearest points.
struct Bezier {
    p0: Vector,
    /// B(u) = p0 + a u + b u² + c u³.
    a: Vector,
    b: Vector,
    c: Vector,
}

impl Bezier {
    fn new(p0: Point, c1: Point, c2: Point, p3: Point) -> Self {
        let (p0, c1, c2, p3) = (p0.coords, c1.coords, c2.coords, p3.coords);
        Self {
            p0,
            a: (c1 - p0) * 3.0,
            b: (p0 - c1 * 2.0 + c2) * 3.0,
            c: p3 - p0 + (c1 - c2) * 3.0,
        }
    }

    fn at(&self, u: f64) -> Vector {
        self.p0 + (self.a + (self.b + self.c * u) * u) * u
    }

    fn slope(&self, u: f64) -> Vector {
        self.a + (self.b * 2.0 + self.c * (3.0 * u)) * u
    }

    fn curvature_vector(&self, u: f64) -> Vector {
        self.b * 2.0 + self.c * (6.0 * u)
    }

    /// The parameter in [0, 1] of the point nearest to `q`, by Newton's
    /// method from `u`; `None` when it does not settle.
    fn nearest(&self, q: Point, mut u: f64) -> Option<f64> {
        for _ in 0..8 {
            let d = self.at(u) - q.coords;
            let b1 = self.slope(u);
            let f = d.dot(&b1);
            let df = b1.norm_squared() + d.dot(&self.curvature_vector(u));
            if df.is_nan() || df <= 0.0 {
                return None;
            }
            let next = (u - f / df).clamp(0.0, 1.0);
            let step = (next - u).abs();
            u = next;
            if step <= 1e-12 {
                return Some(u);
            }
        }
        Some(u).filter(|u| u.is_finite())
    }
}

/// The chord from the first sample to the last and the bound on the
/// curve's distance from it (see [`crate::diagram`]).
fn chord_fit(s: &[(Point, Vector); 9]) -> (Segment, f64) {
    let (a, b) = (s[0].0, s[8].0);
    let ab = b - a;
    let len2 = ab.norm_squared();
    let distance = |p: Point| {
        let t = if len2 > 0.0 {
            ((p - a).dot(&ab) / len2).clamp(0.0, 1.0)
        } else {
            0.0
        };
        (p - (a + ab * t)).norm()
    };
    let mut worst: f64 = 0.0;
    for (&(p0, d0), &(p1, d1)) in s.iter().zip(&s[1..]) {
        for p in [p0, p0 + d0 / 24.0, p1 - d1 / 24.0, p1] {
            worst = worst.max(distance(p));
        }
    }
    (
        Segment::Line(b),
        if worst.is_nan() { f64::INFINITY } else { worst },
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_written_curve_is_traced_inside_the_rounding_of_the_file() {
        // Written path within 0.01 of the curve: traced to 0.002.
        assert!((trace_tolerance(0.01) - 0.002).abs() < 1e-15);
        assert!((trace_tolerance(0.004) - 0.0008).abs() < 1e-18);
        assert!((trace_tolerance(0.1) - 0.092).abs() < 1e-15);
        let options = TraceOptions::written(DEFAULT_TOLERANCE);
        assert!((options.tolerance - 0.002).abs() < 1e-15);
        assert_eq!(options.max_depth, TraceOptions::DEFAULT.max_depth);
    }

    fn samples(f: impl Fn(f64) -> (Point, Vector)) -> [(Point, Vector); 9] {
        std::array::from_fn(|k| f(k as f64 / 8.0))
    }

    #[test]
    fn a_cubic_is_its_own_fit() {
        // p(u) = (u, u³): the Hermite cubic is exact, control points by hand.
        let s = samples(|u| (Point::new(u, u * u * u), Vector::new(1.0, 3.0 * u * u)));
        let (segment, error) = cubic_fit(&s, 0.0);
        let Segment::Cubic(c1, c2, end) = segment else {
            panic!("{segment:?}")
        };
        assert!((c1 - Point::new(1.0 / 3.0, 0.0)).norm() < 1e-15);
        assert!((c2 - Point::new(2.0 / 3.0, 0.0)).norm() < 1e-15);
        assert_eq!(end, Point::new(1.0, 1.0));
        assert!(error < 1e-15, "{error}");
    }

    #[test]
    fn quartic_error_is_bounded_near_its_true_maximum() {
        // p(u) = (u, u⁴): B(u) − p(u) = −u²(1 − u)² in y, largest 1/16 at
        // u = 1/2, which is a sample.
        let s = samples(|u| (Point::new(u, u.powi(4)), Vector::new(1.0, 4.0 * u.powi(3))));
        let (_, error) = cubic_fit(&s, 0.0);
        assert!((0.0625 - 1e-15..0.0625 * 1.01).contains(&error), "{error}");
    }

    #[test]
    fn the_evaluation_budget_ends_a_trace_with_a_limit() {
        // Issue 9 (1): a curve that wiggles faster than any halving resolves
        // (sin 1/t near 0) was halved for minutes; the budget stops it.
        let wild = |t: f64| {
            let (s, c) = (1.0 / t).sin_cos();
            Some((Point::new(t, s), Vector::new(1.0, -c / (t * t))))
        };
        let map = PageFromWorld::scale_translate(100.0, 100.0, 0.0, 0.0).unwrap();
        let frame = Frame::new(Point::new(-1.0, -200.0), Point::new(200.0, 200.0));
        let options = TraceOptions {
            max_evaluations: 20_000,
            ..TraceOptions::default()
        };
        let err = trace(&wild, 1e-4..=1.0, &map, &frame, Method::Cubic, &options).unwrap_err();
        assert!(matches!(err, Error::Limit(_)), "{err:?}");
        assert!(
            err.to_string().contains("more than 20000 evaluations"),
            "{err}"
        );
    }

    #[test]
    fn chord_error_of_a_parabola() {
        // y = u(1 − u) above the chord y = 0: largest 1/4 at u = 1/2.
        let s = samples(|u| {
            (
                Point::new(u, u * (1.0 - u)),
                Vector::new(1.0, 1.0 - 2.0 * u),
            )
        });
        let (segment, error) = chord_fit(&s);
        assert_eq!(segment, Segment::Line(Point::new(1.0, 0.0)));
        assert!((0.25..0.25 * 1.01).contains(&error), "{error}");
    }
}
