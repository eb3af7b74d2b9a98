//! The primary and secondary unbalanced forces of the reciprocating parts
//! over a turn: (a) the primary force m r ω² cos θ, the secondary
//! m r ω² cos 2θ / n, their sum and the exact inertia force −m a (along
//! the line of stroke, away from the crank positive: the force on the
//! frame); (b) what the two terms leave out, the exact force less their
//! sum, of the order of m r ω² / n³ in line (`docs/dynamics.md` §6).
//!
//! Each curve is traced from its value and its exact derivative (the
//! slider's jerk for the exact force).

use super::{Ctx, Sheet, against_angle, extent, positive_mass, short, sig};
use crate::diagram::{Axis, Plot};
use crate::error::Result;
use crate::figure::{Dash, Figure};
use crate::geom::{Frame, Point};
use crate::mechanism::Pose;

/// The four forces of panel (a) at a pose, each with its derivative per
/// radian, in units of m r ω²: primary, secondary, their sum, exact.
fn forces(pose: &Pose) -> [(f64, f64); 4] {
    let m = pose.mechanism();
    let (r, n) = (m.crank(), m.ratio());
    let (s, c) = (pose.angle().sin(), pose.angle().cos());
    let primary = (c, -s);
    // cos 2θ = 2cos²θ − 1 and sin 2θ = 2 sin θ cos θ, exact where the
    // angle's sine and cosine are.
    let secondary = ((2.0 * c * c - 1.0) / n, -4.0 * s * c / n);
    let sum = (primary.0 + secondary.0, primary.1 + secondary.1);
    let exact = (-pose.position_acceleration() / r, -pose.position_jerk() / r);
    [primary, secondary, sum, exact]
}

/// The curves of panel (a): id, legend and dash, in the order of
/// [`forces`].
const CURVES: [(&str, &str, Dash); 4] = [
    ("curve-primary", "primary *m\u{a0}r*ω² cos θ", Dash::Dashed),
    (
        "curve-secondary",
        "secondary *m\u{a0}r*ω² cos 2θ / *n*",
        Dash::Dotted,
    ),
    (
        "curve-primary-secondary",
        "primary + secondary",
        Dash::DashDot,
    ),
    (
        "curve-inertia-exact",
        "exact inertia force −*m a*",
        Dash::Solid,
    ),
];

pub(in crate::catalogue) fn build(ctx: &Ctx) -> Result<Figure> {
    let page = ctx.page();
    let mass = positive_mass(ctx)?;
    let m = ctx.mechanism;
    let k = mass * m.crank() * ctx.omega * ctx.omega;
    let mut sheet = Sheet::new(ctx);
    sheet.mechanism(ctx, true, false);
    let tall = page.height() - 16.0 - 24.0 - 72.0;
    let (a_height, b_height) = (0.62 * tall, 0.38 * tall);
    let (forces, per_force) = forces_plot(ctx, k, ctx.band(16.0, a_height))?;
    sheet.plot(forces);
    let (plot, worst) = remainder_plot(ctx, k, ctx.band(16.0 + a_height + 24.0, b_height))?;
    sheet.plot(plot);
    sheet.meta(
        "unbalanced",
        serde_json::json!({"mass": mass, "m_r_omega2": k, "largest_remainder": worst}),
    );
    sheet.notes(
        Point::new(20.0, page.height() - 56.0),
        &notes(ctx, mass, k, worst, worst * per_force < WITHIN_A_LINE),
    );
    Ok(sheet.finish())
}

/// The crank-angle axis.
fn theta() -> Result<Axis> {
    Axis::linear("crank angle θ (°)", 0.0, 360.0)?.with_step(30.0)
}

/// Page distance under which the sum of the two terms is drawn under the
/// exact force in (a): within the width of the lines (the §35 engine's
/// sum differs by at most 8 lbf in 4000, and the legend listed a curve
/// that could not be seen).
const WITHIN_A_LINE: f64 = 1.5;

/// (a) The four forces of [`forces`] against θ, `k` = m r ω², in `rect`;
/// also at most how many page units a force unit takes on its axis (the
/// axis spans at least the forces' extent).
fn forces_plot(ctx: &Ctx, k: f64, rect: Frame) -> Result<(Plot, f64)> {
    let m = ctx.mechanism;
    let values = |p: &Pose| forces(p).map(|f| f.0);
    let (_, high) = extent(&m, |p| {
        values(p).into_iter().fold(f64::NEG_INFINITY, f64::max)
    });
    let (low, _) = extent(&m, |p| values(p).into_iter().fold(f64::INFINITY, f64::min));
    let mut plot = Plot::new(
        "unbalanced",
        rect,
        theta()?,
        Axis::nice(
            &format!("force on the frame along the stroke ({})", ctx.units.force()),
            k * low,
            k * high,
        )?,
        ctx.tolerance,
        ctx.font,
    )?
    .with_caption(
        "(a) The unbalanced force of the reciprocating parts: primary, secondary, their sum and the exact force",
    );
    for (i, (id, legend, dash)) in CURVES.into_iter().enumerate() {
        let curve = against_angle(m, move |p: &Pose| {
            let f = forces(p).get(i).copied().unwrap_or((0.0, 0.0));
            (k * f.0, k * f.1)
        });
        plot.curve(id, &[(&curve, 0.0..=360.0)], dash, Some(legend))?;
    }
    let per_force = rect.height() / (k * (high - low)).max(f64::MIN_POSITIVE);
    Ok((plot, per_force))
}

/// (b) The exact force less the two terms against θ, in `rect`, and the
/// largest of it over the turn (721 angles).
fn remainder_plot(ctx: &Ctx, k: f64, rect: Frame) -> Result<(Plot, f64)> {
    let remainder = |p: &Pose| {
        let [_, _, sum, exact] = forces(p);
        (k * (exact.0 - sum.0), k * (exact.1 - sum.1))
    };
    let (rlo, rhi) = extent(&ctx.mechanism, |p| remainder(p).0);
    let mut plot = Plot::new(
        "remainder",
        rect,
        theta()?,
        Axis::nice(
            &format!("exact − (primary + secondary) ({})", ctx.units.force()),
            rlo.min(0.0),
            rhi.max(0.0),
        )?,
        ctx.tolerance,
        ctx.font,
    )?
    .with_caption(if ctx.mechanism.offset() == 0.0 {
        "(b) What the two terms leave out: the higher harmonics, of the order of *m\u{a0}r*ω²/*n*³"
    } else {
        // With an offset x_A = r cos θ + l − (r sin θ − e)²/2l − …
        // carries e r sin θ / l: a primary term in sin θ of the order of
        // m r ω² e/l that the in-line series leaves out.
        "(b) What the two terms leave out: with the offset, a term in sin θ of the order of *m\u{a0}r*ω²*e*/*l*, and the higher harmonics"
    });
    let curve = against_angle(ctx.mechanism, remainder);
    plot.curve(
        "curve-remainder",
        &[(&curve, 0.0..=360.0)],
        Dash::Solid,
        None,
    )?;
    Ok((plot, rlo.abs().max(rhi.abs())))
}

/// The notes: the engine, the amplitudes and the largest remainder, and
/// whether the sum is drawn `under` the exact force in (a).
fn notes(ctx: &Ctx, mass: f64, k: f64, worst: f64, under: bool) -> Vec<String> {
    let m = ctx.mechanism;
    let (u, f) = (ctx.unit(), ctx.units.force());
    let mass_u = ctx.units.mass();
    let n = m.ratio();
    let offset = if m.offset() == 0.0 {
        String::new()
    } else {
        format!(
            " With the offset *e* = {} {u} the series, written for an in-line engine, leaves out terms in *e*/*l* as well.",
            short(m.offset())
        )
    };
    vec![
        format!(
            "*r* = {} {u}, *l* = {} {u} (*n* = {}), {} rpm; reciprocating mass *m* = {} {mass_u}: *m\u{a0}r*ω² = {} {f}, the primary force’s amplitude; the secondary’s is *m\u{a0}r*ω²/*n* = {} {f}.",
            short(m.crank()),
            short(m.rod()),
            short(n),
            short(ctx.rpm()),
            short(mass),
            sig(k),
            sig(k / n),
        ),
        format!(
            "Positive away from the crank: the force on the frame through the crank shaft’s bearing. The largest remainder over the turn is {} {f}, {}\u{a0}× *m\u{a0}r*ω²/*n*³{}.{offset}",
            sig(worst),
            sig(worst * n * n * n / k),
            if under {
                ": in (a) the sum lies within a line’s width of the exact force and is drawn under it, (b) shows the difference"
            } else {
                ""
            },
        ),
    ]
}
