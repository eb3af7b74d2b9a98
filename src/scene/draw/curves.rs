//! Curves traced by the mechanism: the rod's centrodes (Fig. 61) and the
//! ovals of its points, fitted with cubic Béziers from exact derivatives to
//! the scene's tolerance in page units and clipped to the frame.

use super::Ctx;
use super::velocity::basics_d;
use crate::Angle;
use crate::construct::{Centrode, CentrodeKind};
use crate::figure::{Path, RichText, Role, Shape, TextSize};
use crate::geom::{Frame, Intersection, Point, Vector, perp};
use crate::scene::canvas::{Canvas, Marker};
use crate::scene::notation::Named;
use std::f64::consts::PI;

/// Samples per branch when looking for where a curve is on the page.
const SAMPLES: usize = 240;
/// Deepest subdivision of one fitted piece.
const MAX_DEPTH: u32 = 24;
/// Most pieces one curve may have, whatever the tolerance asked.
const MAX_PIECES: usize = 20_000;

/// A curve p(θ) with its θ-derivative; `None` at a pole.
type Curve<'a> = dyn Fn(f64) -> Option<(Point, Vector)> + 'a;

fn bezier(p0: Point, c1: Point, c2: Point, p1: Point, t: f64) -> Point {
    let s = 1.0 - t;
    Point::from(
        p0.coords * (s * s * s)
            + c1.coords * (3.0 * s * s * t)
            + c2.coords * (3.0 * s * t * t)
            + p1.coords * (t * t * t),
    )
}

/// Appends Hermite cubics for [t0, t1] to `out`, subdividing until each
/// stays within `tol` page units of the curve at its quarter points.
#[allow(clippy::too_many_arguments)]
fn fit(
    f: &Curve,
    t0: f64,
    a: (Point, Vector),
    t1: f64,
    b: (Point, Vector),
    scale: f64,
    tol: f64,
    depth: u32,
    out: &mut Vec<[Point; 3]>,
) {
    let h = t1 - t0;
    let c1 = a.0 + a.1 * (h / 3.0);
    let c2 = b.0 - b.1 * (h / 3.0);
    let mut worst = 0.0f64;
    let mut mid = None;
    for (k, t) in [0.25, 0.5, 0.75].into_iter().enumerate() {
        match f(t0 + t * h) {
            Some(p) => {
                worst = worst.max((bezier(a.0, c1, c2, b.0, t) - p.0).norm() * scale);
                if k == 1 {
                    mid = Some(p);
                }
            }
            None => worst = f64::INFINITY,
        }
    }
    match mid {
        Some(m)
            if (worst > tol || !worst.is_finite())
                && depth < MAX_DEPTH
                && out.len() < MAX_PIECES =>
        {
            let tm = t0 + 0.5 * h;
            fit(f, t0, a, tm, m, scale, tol, depth + 1, out);
            fit(f, tm, m, t1, b, scale, tol, depth + 1, out);
        }
        _ => out.push([c1, c2, b.0]),
    }
}

/// The parameter intervals of (lo, hi) where the curve is inside `frame`,
/// their ends found by bisection to the frame's edge.
fn inside_runs(f: &Curve, lo: f64, hi: f64, frame: &Frame) -> Vec<(f64, f64)> {
    let inside = |t: f64| f(t).is_some_and(|(p, _)| frame.contains(p));
    let ts: Vec<f64> = (0..SAMPLES)
        .map(|i| lo + (hi - lo) * (i as f64 + 0.5) / SAMPLES as f64)
        .collect();
    let flags: Vec<bool> = ts.iter().map(|t| inside(*t)).collect();
    let edge = |mut a: f64, mut b: f64| {
        // a inside, b outside.
        for _ in 0..48 {
            let m = 0.5 * (a + b);
            if inside(m) { a = m } else { b = m }
        }
        a
    };
    let mut runs = Vec::new();
    let mut i = 0;
    while i < SAMPLES {
        if !flags[i] {
            i += 1;
            continue;
        }
        let j0 = i;
        while i + 1 < SAMPLES && flags[i + 1] {
            i += 1;
        }
        let start = if j0 == 0 {
            ts[0]
        } else {
            edge(ts[j0], ts[j0 - 1])
        };
        let end = if i + 1 == SAMPLES {
            ts[i]
        } else {
            edge(ts[i], ts[i + 1])
        };
        if end > start {
            runs.push((start, end));
        }
        i += 1;
    }
    runs
}

/// The curve over (lo, hi) as a path clipped to the frame, and a point of
/// it for a label; `None` if none of it is on the page.
fn trace(
    f: &Curve,
    lo: f64,
    hi: f64,
    canvas: &Canvas,
    tol: f64,
    closed: bool,
) -> Option<(Path, Point)> {
    let scale = canvas.transform().scale();
    let mut runs = inside_runs(f, lo, hi, canvas.frame());
    let step = (hi - lo) / SAMPLES as f64;
    if closed && runs.len() == 1 && runs[0].0 <= lo + step && runs[0].1 >= hi - step {
        runs[0] = (lo, hi);
    }
    let mut builder = Path::new();
    let mut anchor: Option<(f64, Point)> = None;
    let mut any = false;
    for (t0, t1) in &runs {
        let (Some(a), Some(b)) = (f(*t0), f(*t1)) else {
            continue;
        };
        let mut pieces = Vec::new();
        fit(f, *t0, a, *t1, b, scale, tol, 0, &mut pieces);
        builder = builder.move_to(a.0);
        for [c1, c2, p] in pieces {
            builder = builder.cubic_to(c1, c2, p);
        }
        if closed && runs.len() == 1 && *t0 == lo && *t1 == hi {
            builder = builder.close();
        }
        any = true;
        if let Some((p, _)) = f(0.5 * (t0 + t1))
            && anchor.is_none_or(|(len, _)| t1 - t0 > len)
        {
            anchor = Some((t1 - t0, p));
        }
    }
    if !any {
        return None;
    }
    Some((builder.build()?, anchor?.1))
}

fn pose_at(ctx: &Ctx, t: f64) -> Option<crate::Pose> {
    Angle::from_radians(t)
        .ok()
        .map(|a| ctx.scene.mechanism().pose(a))
}

pub(crate) fn centrodes(ctx: &Ctx, canvas: &mut Canvas) {
    basics_d(ctx, canvas);
    let tol = ctx.scene.tolerance();
    let here = ctx.main.pose();
    let (a0, b0) = (here.a(), here.b());
    let u = (b0 - a0) / here.mechanism().rod();
    let v = perp(&u);
    for (kind, role, name) in [
        (CentrodeKind::Fixed, Role::Curve, "fixed"),
        (CentrodeKind::Moving, Role::Auxiliary, "moving"),
    ] {
        let c = Centrode::new(kind);
        ctx.main.note_centrode();
        let f = |t: f64| -> Option<(Point, Vector)> {
            let pose = pose_at(ctx, t)?;
            let Intersection::Point(p) = c.point(&pose) else {
                return None;
            };
            let d = c.derivative(&pose)?;
            match kind {
                CentrodeKind::Fixed => Some((p, d)),
                // In the rod's frame: carried with the rod at the drawn pose.
                CentrodeKind::Moving => Some((a0 + u * p.x + v * p.y, u * d.x + v * d.y)),
            }
        };
        let eps = 1e-9;
        let mut builder_paths = Vec::new();
        for (lo, hi) in [
            (-0.5 * PI + eps, 0.5 * PI - eps),
            (0.5 * PI + eps, 1.5 * PI - eps),
        ] {
            if let Some(t) = trace(&f, lo, hi, canvas, tol, false) {
                builder_paths.push(t);
            }
        }
        for (k, (path, anchor)) in builder_paths.into_iter().enumerate() {
            canvas.push(
                format!("curve-centrode-{name}-{}", k + 1),
                role,
                Shape::Path(path),
            );
            if k == 0 {
                canvas.label(
                    format!("label-centrode-{name}"),
                    anchor,
                    RichText::parse(&format!("{name} centrode")),
                    TextSize::Small,
                );
            }
        }
    }
}

pub(crate) fn coupler(ctx: &Ctx, canvas: &mut Canvas) {
    let q = ctx.scene.coupler();
    ctx.main.note_coupler();
    let f = |t: f64| -> Option<(Point, Vector)> {
        let pose = pose_at(ctx, t)?;
        Some((q.point(&pose), q.derivative(&pose)))
    };
    if let Some((path, _)) = trace(&f, 0.0, 2.0 * PI, canvas, ctx.scene.tolerance(), true) {
        canvas.push("curve-coupler", Role::Curve, Shape::Path(path));
    }
    let here = ctx.main.pose();
    let p = q.point(here);
    canvas.point(ctx.letter(Named::Coupler), p, Marker::Dot, here.c());
}
