//! The connecting rod's angular velocity and acceleration against the
//! crank angle (textbook §37), with the approximation of eq. (2a), and the
//! values at the drawn pose marked.
//!
//! Signs are the seeds': dφ/dt and d²φ/dt² of the obliquity φ
//! (sin φ = (r sin θ − e)/l); the rod's counter-clockwise angular velocity
//! is −dφ/dt.

use super::{Ctx, Sheet, against_angle, extent, short, sig};
use crate::diagram::{Axis, Plot};
use crate::error::Result;
use crate::figure::{Dash, Figure, Symbol};
use crate::geom::Point;
use crate::mechanism::Pose;

pub(in crate::catalogue) fn build(ctx: &Ctx) -> Result<Figure> {
    let page = ctx.page();
    let mut sheet = Sheet::new(ctx);
    sheet.mechanism(ctx, true, true);
    let height = 0.5 * (page.height() - 32.0 - 56.0);
    sheet.plot(velocity(ctx, height)?);
    let (plot, under) = acceleration(ctx, 16.0 + height + 24.0, height)?;
    sheet.plot(plot);
    sheet.notes(Point::new(20.0, page.height() - 36.0), &[note(ctx, under)]);
    Ok(sheet.finish())
}

/// The least room between a curve's extreme and its axis's end, a share
/// of the values' span: at l = 35.3 r the rod's angular velocity of
/// −0.7416 rad/s lay on the −0.75 frame line.
const ROOM: f64 = 0.03;

/// An axis of round values over `lo` to `hi` with [`ROOM`] on each side.
fn roomy(title: &str, lo: f64, hi: f64) -> Result<Axis> {
    let pad = ROOM * (hi - lo);
    Axis::nice(title, lo - pad, hi + pad)
}

/// Page distance under which eq. (2a) is drawn under the exact curve:
/// within the width of the lines (at long rods the two differ by
/// hundredths of a unit, and the legend listed a curve that could not be
/// seen).
const WITHIN_A_LINE: f64 = 1.5;

/// The crank angle's axis over a turn.
fn theta_axis() -> Result<Axis> {
    Axis::linear("crank angle θ (°)", 0.0, 360.0)?.with_step(30.0)
}

/// (a) The rod's angular velocity against θ, `height` page units high,
/// with its value at the drawn pose.
fn velocity(ctx: &Ctx, height: f64) -> Result<Plot> {
    let (m, omega) = (ctx.mechanism, ctx.omega);
    let pose = ctx.pose();
    let theta = pose.angle().degrees();
    let (lo, hi) = extent(&m, |p| omega * p.obliquity_rate());
    let y = roomy("dφ/d*t* (rad/s)", lo, hi)?;
    let mut velocity = Plot::new(
        "angular-velocity",
        ctx.band(16.0, height),
        theta_axis()?,
        y,
        ctx.tolerance,
        ctx.font,
    )?
    .with_caption("(a) Angular velocity of the rod, ω *r* cos θ / (*l* cos φ)");
    let rate = against_angle(m, |p: &Pose| {
        (
            omega * p.obliquity_rate(),
            omega * p.obliquity_acceleration(),
        )
    });
    velocity.curve(
        "curve-rod-angular-velocity",
        &[(&rate, 0.0..=360.0)],
        Dash::Solid,
        Some("exact"),
    )?;
    let v0 = omega * pose.obliquity_rate();
    velocity.points(
        "point-rod-angular-velocity",
        &[(theta, v0)],
        Symbol::Circle,
        Some(&format!("θ = {}°: {} rad/s", short(theta), sig(v0))),
    );
    Ok(velocity)
}

/// (b) The rod's angular acceleration against θ from `top` down, exact
/// and by eq. (2a), with its value at the drawn pose; also whether eq.
/// (2a) lies within [`WITHIN_A_LINE`] of the exact curve on the page.
fn acceleration(ctx: &Ctx, top: f64, height: f64) -> Result<(Plot, bool)> {
    let m = ctx.mechanism;
    let w2 = ctx.omega * ctx.omega;
    let n = m.ratio();
    let pose = ctx.pose();
    let theta = pose.angle().degrees();
    let eq_2a = |p: &Pose| {
        let s = p.angle().sin();
        -w2 * s / ((n - s) * (n + s)).sqrt()
    };
    // Both curves on the axis: with an offset eq. (2a), written for an
    // in-line engine, passes the exact curve's extremes (at l = 1.63 r,
    // e = 0.478 r it was clipped flat along the axis).
    let (lo, hi) = extent(&m, |p| w2 * p.obliquity_acceleration());
    let (lo_2a, hi_2a) = extent(&m, eq_2a);
    let (gap_lo, gap_hi) = extent(&m, |p| w2 * p.obliquity_acceleration() - eq_2a(p));
    let (lo, hi) = (lo.min(lo_2a).min(-w2 / n), hi.max(hi_2a).max(w2 / n));
    let y = roomy("d²φ/d*t*² (rad/s²)", lo, hi)?;
    let (y0, y1) = y.range();
    let mut acceleration = Plot::new(
        "angular-acceleration",
        ctx.band(top, height),
        theta_axis()?,
        y,
        ctx.tolerance,
        ctx.font,
    )?
    .with_caption("(b) Angular acceleration of the rod");
    let exact = against_angle(m, |p: &Pose| {
        (w2 * p.obliquity_acceleration(), w2 * p.obliquity_jerk())
    });
    acceleration.curve(
        "curve-rod-angular-acceleration",
        &[(&exact, 0.0..=360.0)],
        Dash::Solid,
        Some("exact, eq. (2)"),
    )?;
    let approx = against_angle(m, |p: &Pose| {
        let (s, c) = (p.angle().sin(), p.angle().cos());
        let q = (n - s) * (n + s);
        (eq_2a(p), -w2 * n * n * c / (q * q.sqrt()))
    });
    acceleration.curve(
        "curve-rod-angular-acceleration-eq-2a",
        &[(&approx, 0.0..=360.0)],
        Dash::Dashed,
        Some("eq. (2a), −ω² sin θ / √(*n*² − sin²θ)"),
    )?;
    let per_unit = acceleration.area().height() / (y1 - y0);
    let under = gap_lo.abs().max(gap_hi.abs()) * per_unit < WITHIN_A_LINE;
    let a0 = w2 * pose.obliquity_acceleration();
    acceleration.points(
        "point-rod-angular-acceleration",
        &[(theta, a0)],
        Symbol::Circle,
        Some(&format!("θ = {}°: {} rad/s²", short(theta), sig(a0))),
    );
    Ok((acceleration, under))
}

/// The note: the engine, its speed, and the seeds' signs; where eq. (2a)
/// is drawn `under` the exact curve, that.
fn note(ctx: &Ctx, under: bool) -> String {
    let m = ctx.mechanism;
    format!(
        "*r* = {} {u}, *l* = {} {u} (*n* = {}){}, {} rpm (ω = {} rad/s). Signs as in the textbook and Ng’s paper: the rod turns counter-clockwise at −dφ/d*t*.{}{}",
        short(m.crank()),
        short(m.rod()),
        short(m.ratio()),
        ctx.offset_clause(),
        short(ctx.rpm()),
        sig(ctx.omega),
        if m.offset() == 0.0 {
            ""
        } else {
            " Eq. (2a) is written for an in-line engine."
        },
        if under {
            " In (b) eq. (2a) lies within a line’s width of the exact curve and is drawn under it."
        } else {
            ""
        },
        u = ctx.unit()
    )
}
