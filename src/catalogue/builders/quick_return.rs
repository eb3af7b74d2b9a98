//! The quick return's tool (its ram) against θ: (a) its velocity and (b)
//! its acceleration over the cutting stroke (full) and the return stroke
//! (dashed), the strokes' ends at θ = 90° and 270° dotted, the values at
//! the drawn pose marked, and the time ratio in the notes
//! ([`crate::chain::QuickReturn`], docs/quick-return.md).

use super::{Ctx, Sheet, short, sig};
use crate::angle::Angle;
use crate::chain::{Inversion, QuickReturn, ToolMotion};
use crate::diagram::{Axis, Plot};
use crate::error::Result;
use crate::figure::{Dash, Figure, Symbol};
use crate::geom::{Point, Vector};

/// A step of θ (degrees) for the acceleration's derivative, by central
/// differences: its error, about 1e-9 of the value, is far below the
/// curves' tolerance.
const STEP: f64 = 1e-3;

pub(in crate::catalogue) fn build(ctx: &Ctx, inversion: Inversion) -> Result<Figure> {
    let m = ctx.mechanism;
    let q = QuickReturn::new(m, inversion, QuickReturn::default_lever(&m))?;
    let page = ctx.page();
    let mut sheet = Sheet::new(ctx);
    sheet.mechanism(ctx, true, true);
    sheet.meta("inversion", serde_json::json!(inversion.number()));
    sheet.meta("time_ratio", serde_json::json!(q.time_ratio()));
    sheet.meta("lever", serde_json::json!(q.lever()));
    let height = 0.5 * (page.height() - 32.0 - 74.0);
    sheet.plot(panel(ctx, &q, Quantity::Velocity, 16.0, height)?);
    sheet.plot(panel(
        ctx,
        &q,
        Quantity::Acceleration,
        16.0 + height + 24.0,
        height,
    )?);
    sheet.notes(Point::new(20.0, page.height() - 54.0), &notes(ctx, &q));
    Ok(sheet.finish())
}

/// Which of the tool's values a panel draws.
#[derive(Clone, Copy)]
enum Quantity {
    Velocity,
    Acceleration,
}

impl Quantity {
    fn of(self, t: &ToolMotion) -> f64 {
        match self {
            Quantity::Velocity => t.velocity,
            Quantity::Acceleration => t.acceleration,
        }
    }
}

/// One panel: the value against θ, the cutting stroke full and the
/// return dashed, the strokes' ends dotted, the drawn pose's value marked.
fn panel(ctx: &Ctx, q: &QuickReturn, what: Quantity, top: f64, height: f64) -> Result<Plot> {
    let w = ctx.omega;
    let driver = q.chain().inversion().driver();
    let value = move |deg: f64| -> Option<f64> {
        let a = Angle::from_degrees(deg).ok()?;
        Some(what.of(&q.at(a, w)))
    };
    // The derivative per degree: the velocity's from the acceleration
    // (dv/dθ = a / (dθ/dt), dθ/dt = ω / the driver's rate per dθ), the
    // acceleration's by central differences.
    let curve = move |deg: f64| -> Option<(Point, Vector)> {
        let a = Angle::from_degrees(deg).ok()?;
        let t = q.at(a, w);
        let slope = match what {
            Quantity::Velocity => {
                let rate = q.chain().pose(a).link_rate(driver);
                t.acceleration * rate / w * super::PER_DEGREE
            }
            Quantity::Acceleration => (value(deg + STEP)? - value(deg - STEP)?) / (2.0 * STEP),
        };
        Some((Point::new(deg, what.of(&t)), Vector::new(1.0, slope)))
    };
    let (lo, hi) = (0..=720)
        .filter_map(|k| value(0.5 * f64::from(k)))
        .fold((0.0f64, 0.0f64), |(lo, hi), v| (lo.min(v), hi.max(v)));
    let u = ctx.unit();
    let (name, title, caption, unit) = match what {
        Quantity::Velocity => (
            "tool-velocity",
            "d*s*/d*t*",
            "(a) The tool’s velocity",
            format!("{u}/s"),
        ),
        Quantity::Acceleration => (
            "tool-acceleration",
            "d²*s*/d*t*²",
            "(b) The tool’s acceleration, the strokes and the pose as in (a)",
            format!("{u}/s²"),
        ),
    };
    let y = Axis::nice(&format!("{title} ({unit})"), lo, hi)?;
    let x = Axis::linear("crank angle θ (°)", 0.0, 360.0)?.with_step(30.0)?;
    let mut plot = Plot::new(name, ctx.band(top, height), x, y, ctx.tolerance, ctx.font)?
        .with_caption(caption);
    let (cutting, back) = q.stroke_angles();
    // The strokes and the pose are named in (a)'s legend only: a second
    // legend found no free corner in (b) and was set beside its plot.
    let first = matches!(what, Quantity::Velocity);
    let cutting_key = format!(
        "cutting stroke, {}° of the driver’s turn",
        short(cutting.to_degrees())
    );
    let return_key = format!("return stroke, {}°", short(back.to_degrees()));
    plot.curve(
        &format!("curve-{name}-cutting"),
        &[(&curve, 0.0..=90.0), (&curve, 270.0..=360.0)],
        Dash::Solid,
        first.then_some(cutting_key.as_str()),
    )?;
    plot.curve(
        &format!("curve-{name}-return"),
        &[(&curve, 90.0..=270.0)],
        Dash::Dashed,
        first.then_some(return_key.as_str()),
    )?;
    for end in [90.0, 270.0] {
        plot.line(
            &format!("line-{name}-end-{end}"),
            &[(end, lo), (end, hi)],
            Dash::Dotted,
            None,
        );
    }
    let theta = ctx.angle.degrees();
    if let Some(v) = value(theta) {
        let key = format!("θ = {}°: {} {unit}", short(theta), sig(v));
        plot.points(
            &format!("point-{name}"),
            &[(theta, v)],
            Symbol::Circle,
            first.then_some(key.as_str()),
        );
    }
    Ok(plot)
}

/// The notes: the mechanism, the arm and the drive, the time ratio and
/// the stroke.
fn notes(ctx: &Ctx, q: &QuickReturn) -> Vec<String> {
    let m = ctx.mechanism;
    let u = ctx.unit();
    let (cutting, back) = q.stroke_angles();
    let pose = q.at(ctx.angle, ctx.omega);
    let (name, driver) = match q.chain().inversion() {
        Inversion::Rod => (
            "Inversion 3, the crank and slotted lever",
            "the crank *a* turns about *B*",
        ),
        _ => (
            "Inversion 2, Whitworth’s quick return",
            "the rod *b* turns about *B* (θ falling: the strokes run from right to left)",
        ),
    };
    let offset = ctx.offset_clause();
    vec![
        format!(
            "{name}: *r* = {} {u}, *l* = {} {u}{offset}; {driver} at ω = {} rad/s ({} rpm); the tool is driven by the arm *L* = {} {u} of the slotted link *d* through a pin in a slot of the ram, its stroke square to the fixed link’s line of centres.",
            short(m.crank()),
            short(m.rod()),
            sig(ctx.omega),
            short(ctx.rpm()),
            short(q.lever()),
        ),
        format!(
            "The strokes end where *d* is square to the line of centres, θ = 90° and 270° (dotted): time ratio {}° / {}° = {}, stroke {} {u}; *s* is + the way the tool cuts. At θ = {}° ({}): d²*s*/d*t*² = {} {u}/s².",
            short(cutting.to_degrees()),
            short(back.to_degrees()),
            sig(q.time_ratio()),
            sig(q.stroke_length()),
            short(ctx.angle.degrees()),
            pose.stroke.name(),
            sig(pose.acceleration),
        ),
    ]
}
