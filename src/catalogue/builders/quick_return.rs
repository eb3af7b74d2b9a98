//! The quick return's tool (its ram) against the driver's turn since the
//! cutting stroke began, which is time at the driver's constant speed:
//! (a) its velocity and (b) its acceleration over the cutting stroke
//! (full) and the quicker return (dashed), the strokes' end dotted where
//! the driver has turned through the cutting stroke's angle (θ = 90° or
//! 270°, d square to the crank a), the values at the drawn pose marked,
//! and the time ratio in the notes ([`crate::chain::QuickReturn`],
//! docs/quick-return.md). Against θ the strokes would take half a turn
//! each and the quick return would not show.

use super::{Ctx, Sheet, short, sig};
use crate::angle::Angle;
use crate::chain::{Inversion, QuickReturn, Stroke, ToolMotion};
use crate::diagram::{Axis, Plot};
use crate::error::Result;
use crate::figure::{Dash, Figure, Symbol};
use crate::geom::{Frame, Point, Vector};
use std::f64::consts::TAU;

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
    let beside = q.stroke_angles().1.to_degrees() < RETURN_DETAIL_BELOW;
    for (top, what) in [
        (16.0, Quantity::Velocity),
        (16.0 + height + 24.0, Quantity::Acceleration),
    ] {
        let band = ctx.band(top, height);
        if !beside {
            sheet.plot(panel(ctx, &q, what, band)?);
            continue;
        }
        let (main, detail) = split(band);
        let main = panel(ctx, &q, what, main)?;
        let per_degree = main.area().width() / 360.0;
        sheet.plot(main);
        sheet.plot(return_panel(ctx, &q, what, detail, per_degree)?);
    }
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
fn panel(ctx: &Ctx, q: &QuickReturn, what: Quantity, band: Frame) -> Result<Plot> {
    let w = ctx.omega;
    let value = move |deg: f64| value(q, w, what, deg);
    let (cutting, _) = q.stroke_angles();
    let cut = cutting.to_degrees();
    let curve = move |deg: f64, back: bool| traced(q, w, what, cut, deg, back);
    let cutting_curve = move |deg: f64| curve(deg, false);
    let return_curve = move |deg: f64| curve(deg, true);
    let range = |from: f64, to: f64| {
        (0..=360)
            .filter_map(|k| value(from + (to - from) * f64::from(k) / 360.0))
            .fold((0.0f64, 0.0f64), |(lo, hi), v| (lo.min(v), hi.max(v)))
    };
    // Cutting over θ from 270° to 450° (as the curves are traced), the
    // return over 90° to 270°.
    let (cut_range, back_range) = (range(270.0, 450.0), range(90.0, 270.0));
    let peak = |(lo, hi): (f64, f64)| lo.abs().max(hi);
    let times = enlargement(peak(cut_range), peak(back_range));
    let k = times.unwrap_or(1.0);
    let (lo, hi) = (
        back_range.0.min(k * cut_range.0),
        back_range.1.max(k * cut_range.1),
    );
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
    // (b) has no legend: its enlargement is named in its caption.
    let caption = match (what, times) {
        (Quantity::Acceleration, Some(k)) => {
            format!("{caption}; dash-dot: the cutting stroke ×{}", short(k))
        }
        _ => caption.to_string(),
    };
    // 3 % of the span to spare at each end: the slotted lever's default
    // return touched the −750 frame line.
    let pad = 0.03 * (hi - lo);
    let y = Axis::nice(&format!("{title} ({unit})"), lo - pad, hi + pad)?;
    let x = Axis::linear(TURN_AXIS, 0.0, 360.0)?.with_step(30.0)?;
    let mut plot = Plot::new(name, band, x, y, ctx.tolerance, ctx.font)?.with_caption(&caption);
    let back = TAU - cutting;
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
        &[
            (&cutting_curve, 270.0..=360.0),
            (&cutting_curve, 0.0..=90.0),
        ],
        Dash::Solid,
        first.then_some(cutting_key.as_str()),
    )?;
    plot.curve(
        &format!("curve-{name}-return"),
        &[(&return_curve, 90.0..=270.0)],
        Dash::Dashed,
        first.then_some(return_key.as_str()),
    )?;
    if let Some(k) = times {
        let enlarged = move |deg: f64| {
            let (p, d) = curve(deg, false)?;
            Some((Point::new(p.x, k * p.y), Vector::new(d.x, k * d.y)))
        };
        let key = format!("cutting stroke ×{}", short(k));
        plot.curve(
            &format!("curve-{name}-cutting-enlarged"),
            &[(&enlarged, 270.0..=360.0), (&enlarged, 0.0..=90.0)],
            Dash::DashDot,
            first.then_some(key.as_str()),
        )?;
    }
    end_line(&mut plot, name, cut, (lo, hi));
    let theta = ctx.angle.degrees();
    let pose = q.at(ctx.angle, w);
    if let Some(v) = value(theta) {
        let turn = in_stroke(
            pose.driver_angle.to_degrees(),
            cut,
            pose.stroke == Stroke::Return,
        );
        let key = format!(
            "θ = {}° (turn {}°): {} {unit}",
            short(theta),
            short(turn),
            sig(v)
        );
        plot.points(
            &format!("point-{name}"),
            &[(turn, v)],
            Symbol::Circle,
            first.then_some(key.as_str()),
        );
    }
    Ok(plot)
}

/// The tool's value at θ = `deg` (degrees) and driver speed `w`.
fn value(q: &QuickReturn, w: f64, what: Quantity, deg: f64) -> Option<f64> {
    let a = Angle::from_degrees(deg).ok()?;
    Some(what.of(&q.at(a, w)))
}

/// A stroke's curve traced over θ = `deg` and set at the driver's turn,
/// taken in the stroke's own span (`back`: the return's; at its ends the
/// turn is 0 or 360°, one time; `cut`, the cutting stroke's end), with
/// its derivative per degree of θ: d turn/dθ is the driver's rate per dθ
/// with its sign (in inversion 2 the driver turns forward as θ falls);
/// the velocity's slope from the acceleration (dv/dθ = a / (dθ/dt),
/// dθ/dt = ω / the driver's rate per dθ), the acceleration's by central
/// differences. `None` where θ is not a finite angle.
fn traced(
    q: &QuickReturn,
    w: f64,
    what: Quantity,
    cut: f64,
    deg: f64,
    back: bool,
) -> Option<(Point, Vector)> {
    let a = Angle::from_degrees(deg).ok()?;
    let t = q.at(a, w);
    let rate = q.chain().pose(a).link_rate(q.chain().inversion().driver());
    let slope = match what {
        Quantity::Velocity => t.acceleration * rate / w * super::PER_DEGREE,
        Quantity::Acceleration => {
            (value(q, w, what, deg + STEP)? - value(q, w, what, deg - STEP)?) / (2.0 * STEP)
        }
    };
    let x = in_stroke(t.driver_angle.to_degrees(), cut, back);
    Some((Point::new(x, what.of(&t)), Vector::new(rate, slope)))
}

/// The cutting stroke's end (`cut`, the driver's turn) dotted across the
/// values `(lo, hi)` of the plot `name`.
fn end_line(plot: &mut Plot, name: &str, cut: f64, (lo, hi): (f64, f64)) {
    plot.line(
        &format!("line-{name}-end"),
        &[(cut, lo), (cut, hi)],
        Dash::Dotted,
        None,
    );
}

/// The return's share of the driver's turn (degrees) below which each
/// panel is drawn narrower and the return drawn again beside it over its
/// own span: at l = 1.03 r Whitworth's return of 28° was a hair-thin
/// spike against the whole turn.
const RETURN_DETAIL_BELOW: f64 = 60.0;

/// A panel's band parted into the whole turn's plot (left, 64 %) and the
/// return's (right, 32 %), 4 % between them.
fn split(band: Frame) -> (Frame, Frame) {
    let (x, y, w, h) = (band.min().x, band.min().y, band.width(), band.height());
    (
        Frame::from_origin_size(x, y, 0.64 * w, h),
        Frame::from_origin_size(x + 0.68 * w, y, 0.32 * w, h),
    )
}

/// The return panel's range of the driver's turn: from the multiple of
/// 5° at least 2.5° below the cutting stroke's end to 360°, so that the
/// dotted end stands clear of the axis (at l = 1.1 r, 310.8°, it had run
/// into the axis at 310°).
fn return_axis(q: &QuickReturn) -> (f64, f64) {
    let cut = q.stroke_angles().0.to_degrees();
    (((cut - 2.5) / 5.0).floor() * 5.0, 360.0)
}

/// The return stroke alone (dashed) over its own span of the driver's
/// turn, its time drawn wider than in the whole turn's panel beside it
/// (`per_degree`, that panel's page units per degree; the caption names
/// how many times), with the strokes' end dotted and the pose marked
/// where it falls in the return. Its values to their own scale.
fn return_panel(
    ctx: &Ctx,
    q: &QuickReturn,
    what: Quantity,
    band: Frame,
    per_degree: f64,
) -> Result<Plot> {
    let w = ctx.omega;
    let cut = q.stroke_angles().0.to_degrees();
    let back = move |deg: f64| traced(q, w, what, cut, deg, true);
    let (lo, hi) = (0..=360)
        .filter_map(|k| value(q, w, what, 90.0 + 0.5 * f64::from(k)))
        .fold((0.0f64, 0.0f64), |(lo, hi), v| (lo.min(v), hi.max(v)));
    let pad = 0.03 * (hi - lo);
    let u = ctx.unit();
    let (name, title, caption) = match what {
        Quantity::Velocity => ("return-velocity", "d*s*/d*t* ({u}/s)", "(a′)"),
        Quantity::Acceleration => ("return-acceleration", "d²*s*/d*t*² ({u}/s²)", "(b′)"),
    };
    let y = Axis::nice(&title.replace("{u}", &u.to_string()), lo - pad, hi + pad)?;
    let (from, to) = return_axis(q);
    let x = Axis::linear("the driver’s turn (°)", from, to)?.with_step(10.0)?;
    let plot = Plot::new(name, band, x, y, ctx.tolerance, ctx.font)?;
    let stretch = plot.area().width() / (to - from) / per_degree;
    let caption = format!(
        "{caption} The return, its time ×{}",
        short((10.0 * stretch).round() / 10.0)
    );
    let mut plot = plot.with_caption(&caption);
    plot.curve(
        &format!("curve-{name}"),
        &[(&back, 90.0..=270.0)],
        Dash::Dashed,
        None,
    )?;
    end_line(&mut plot, name, cut, (lo, hi));
    let pose = q.at(ctx.angle, w);
    if pose.stroke == Stroke::Return {
        let turn = in_stroke(pose.driver_angle.to_degrees(), cut, true);
        plot.points(
            &format!("point-{name}"),
            &[(turn, what.of(&pose))],
            Symbol::Circle,
            None,
        );
    }
    Ok(plot)
}

/// How much the cutting stroke's curve is drawn enlarged beside itself,
/// where the return's greatest value is more than ten times its own
/// (`cutting` and `back`, each stroke's greatest magnitude): the largest
/// of 5, 10, 20, 50, … that takes it to no more than half the return's,
/// so that the stroke the tool works in is read to its own scale (at
/// l = 1.1 r Whitworth's return of 49° reached 21 times the cutting
/// speed and its acceleration's spike flattened the cutting stroke onto
/// the zero line). `None` where the curves share a scale well (a
/// cutting stroke of no motion included).
fn enlargement(cutting: f64, back: f64) -> Option<f64> {
    let ratio = 0.5 * back / cutting;
    if !(ratio.is_finite() && ratio >= 5.0) {
        return None;
    }
    let decade = 10f64.powf(ratio.log10().floor());
    [5.0, 2.0, 1.0]
        .into_iter()
        .map(|m| m * decade)
        .find(|&k| k <= ratio)
        .filter(|&k| k >= 5.0)
}

/// The title of the panels' axis of abscissae, one at every engine (the
/// notes say where the turn is counted from: a longer title, "… since
/// the cutting stroke began …", did not fit beside the return's panel).
const TURN_AXIS: &str = "the driver’s turn (°), as time";

/// The driver's turn `turn` (degrees, 0 to 360) taken in its stroke's
/// span: the cutting stroke's from 0 to `cut`, the return's from `cut`
/// to 360 (`back`), so that a stroke's end, where the turn is both 0 and
/// 360°, lands at its own stroke's end.
fn in_stroke(turn: f64, cut: f64, back: bool) -> f64 {
    match back {
        true if turn < 0.5 * cut => turn + 360.0,
        false if turn > 0.5 * (cut + 360.0) => turn - 360.0,
        _ => turn,
    }
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
            "the rod *b* turns about *B* (θ falling as it turns)",
        ),
    };
    // The offset named as the chain has it: the line of stroke is the
    // slot in d, set e off the crank's centre C (the figure draws no
    // mechanism; "the line of stroke above the crank centre" read as the
    // ram's).
    let offset = match m.offset() {
        0.0 => String::new(),
        e => format!(
            ", *e* = {} {u} (the slot in *d*, the engine’s line of stroke, set {} {u} off the crank’s centre *C*)",
            short(e),
            short(e.abs())
        ),
    };
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
            "The strokes end where *d* is square to the crank *a*, θ = 90° and 270°; the driver turns {}° over the cutting stroke and {}° over the return (the turn counted from the cutting stroke’s start; dotted: its end), time ratio {}, stroke {} {u}; *s* is + the way the tool cuts. At θ = {}°, the driver’s turn {}° ({} stroke): d²*s*/d*t*² = {} {u}/s².",
            short(cutting.to_degrees()),
            short(back.to_degrees()),
            sig(q.time_ratio()),
            sig(q.stroke_length()),
            short(ctx.angle.degrees()),
            short(pose.driver_angle.to_degrees()),
            pose.stroke.name(),
            sig(pose.acceleration),
        ),
    ]
}

#[cfg(test)]
mod tests {
    use super::enlargement;

    #[test]
    fn the_cutting_stroke_is_enlarged_only_where_the_return_dwarfs_it() {
        assert_eq!(enlargement(1.0, 9.9), None);
        assert_eq!(enlargement(1.0, 10.0), Some(5.0));
        assert_eq!(enlargement(28.8, 600.0), Some(10.0));
        assert_eq!(enlargement(1.0, 39.9), Some(10.0));
        assert_eq!(enlargement(1.0, 40.0), Some(20.0));
        assert_eq!(enlargement(1.0, 150.0), Some(50.0));
        assert_eq!(enlargement(0.0, 1.0), None);
        assert_eq!(enlargement(0.0, 0.0), None);
    }
}
