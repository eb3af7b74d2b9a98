//! Curves traced by the mechanism: the rod's centrodes (Fig. 61) and the
//! ovals of its points, fitted with cubic Béziers from exact derivatives to
//! the scene's tolerance in page units and clipped to the frame.

use super::LayerCtx;
use super::velocity::basics_d;
use crate::angle::Angle;
use crate::construct::{Centrode, CentrodeKind};
use crate::diagram::{self, Curve, Locus, LocusKind, Method, TraceOptions};
use crate::figure::{Part, Path, RichText, Role, Shape, TextSize};
use crate::geom::{Frame, Intersection, Point, Vector, perp};
use crate::scene::canvas::{Canvas, Marker};
use crate::scene::notation::Named;
use std::f64::consts::PI;

/// The curve over (lo, hi), traced by the curve engine to the scene's
/// tolerance in page units (less the rounding of the written file,
/// [`TraceOptions::written`]) and clipped to the canvas frame, as a world path
/// and a point of it for a label; `None` if none of it is on the page (or,
/// which the engine's caps make unlikely for these smooth curves, if it
/// cannot be fitted: then nothing is drawn rather than a wrong curve).
fn trace(
    f: &impl diagram::Curve,
    lo: f64,
    hi: f64,
    canvas: &Canvas,
    tol: f64,
) -> Option<(Path, Point)> {
    let map = canvas.transform();
    let world = canvas.frame();
    let page = Frame::new(map.apply(world.min()), map.apply(world.max()));
    let traced = diagram::trace(
        f,
        lo..=hi,
        map,
        &page,
        Method::Cubic,
        &TraceOptions::written(tol),
    )
    .ok()?;
    // The label goes at the middle of the longest subpath.
    let longest = traced
        .subpaths()
        .iter()
        .max_by_key(|s| s.segments().len())?;
    let anchor = longest.segments().get(longest.segments().len() / 2)?.end();
    Some((traced.to_figure_path(map)?, map.invert(anchor)))
}

fn pose_at(ctx: &LayerCtx, t: f64) -> Option<crate::mechanism::Pose> {
    Angle::from_radians(t)
        .ok()
        .map(|a| ctx.scene.mechanism().pose(a))
}

pub(crate) fn centrodes(ctx: &LayerCtx, canvas: &mut Canvas) {
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
            if let Some(t) = trace(&f, lo, hi, canvas, tol) {
                builder_paths.push(t);
            }
        }
        let part = match kind {
            CentrodeKind::Fixed => Part::FixedCentrode,
            CentrodeKind::Moving => Part::MovingCentrode,
        };
        canvas.with_part(part, |canvas| {
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
        });
    }
}

pub(crate) fn coupler(ctx: &LayerCtx, canvas: &mut Canvas) {
    let q = ctx.scene.coupler();
    ctx.main.note_coupler();
    let f = |t: f64| -> Option<(Point, Vector)> {
        let pose = pose_at(ctx, t)?;
        Some((q.point(&pose), q.derivative(&pose)))
    };
    if let Some((path, _)) = trace(&f, 0.0, 2.0 * PI, canvas, ctx.scene.tolerance()) {
        canvas.push("curve-coupler", Role::Curve, Shape::Path(path));
    }
    let here = ctx.main.pose();
    let p = q.point(here);
    canvas.point(ctx.letter(Named::Coupler), p, Marker::Dot, here.c());
}

/// Fig. 64's polar diagram of piston velocity as far as the crank has
/// turned: E′ on the crank at CE′ = |CE| from C (on the crank itself on
/// the return stroke too, as the textbook sets it off), traced from the
/// outer dead centre to the drawn pose, and E′ lettered there. At the
/// outer dead centre itself nothing is traced yet (E′ = C).
pub(crate) fn polar(ctx: &LayerCtx, canvas: &mut Canvas) {
    let m = *ctx.scene.mechanism();
    let locus = Locus::new(m, LocusKind::PolarVelocity);
    let (outer, inner) = m.dead_centres();
    let (o, i) = (outer.to_degrees(), inner.to_degrees());
    let mut theta = ctx.main.pose().angle().degrees();
    if theta < o {
        theta += 360.0;
    }
    let outward = |d: f64| locus.eval(d);
    let inward = |d: f64| locus.eval(d).map(|(p, v)| (Point::origin() - p.coords, -v));
    let tol = ctx.scene.tolerance();
    let mut k = 0;
    let pieces = [(o, theta.min(i), false), (i, theta, true)];
    for (lo, hi, back) in pieces.into_iter().filter(|(lo, hi, _)| hi > lo) {
        let traced = if back {
            trace(&inward, lo, hi, canvas, tol)
        } else {
            trace(&outward, lo, hi, canvas, tol)
        };
        if let Some((path, _)) = traced {
            k += 1;
            canvas.push(format!("curve-polar-{k}"), Role::Curve, Shape::Path(path));
        }
    }
    let here = if theta > i {
        inward(theta)
    } else {
        outward(theta)
    };
    if let Some((p, _)) = here
        && p != Point::origin()
    {
        canvas.push(
            "point-E-polar",
            Role::Construction,
            Shape::Dot { centre: p },
        );
        canvas.label("label-E-polar", p, RichText::italic("E′"), TextSize::Letter);
    }
}
