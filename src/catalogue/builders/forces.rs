//! Ng Fig. 8: the slider force F (theory, eq. 6) and F′ (theory, eq. 8
//! with μ = 1) against the crank angle, with the measured F′ as points, and
//! the transmission angle β (eq. 11) below.
//!
//! The torque is the one Ng's F column implies, T = 264.87 N·mm (1 kg on
//! the 27 mm circular crank; docs/seed-errata.md). F′ uses each angle's own
//! φ (Ng's printed F′ column used the φ of 60° throughout). The measured
//! points are Ng's experiment column (examples/ng-experiment.csv) unless
//! other data are given.

use super::{Ctx, PER_DEGREE, Sheet, Table, short, sig};
use crate::analytic::statics;
use crate::diagram::{Axis, Curve, Plot};
use crate::error::{Error, Input, Result};
use crate::figure::{Dash, Figure, Item, Role, Shape, Symbol};
use crate::geom::{Point, Vector};
use crate::sources::NG_TORQUE;
use crate::{angle::Angle, mechanism::Pose, mechanism::SliderCrank};

/// Ng's measured F′ against θ.
const NG_EXPERIMENT: &str = include_str!("../../../examples/ng-experiment.csv");

/// Ng's coefficient of friction (a 45° tilt, eq. 10).
const MU: f64 = 1.0;

/// |tan φ| and its derivative per radian.
fn tan_phi(p: &Pose) -> (f64, f64) {
    let (h, w) = (p.rise(), p.run());
    let l = p.mechanism().rod();
    let dh = p.mechanism().crank() * p.angle().cos();
    let sign = if h < 0.0 { -1.0 } else { 1.0 };
    (sign * h / w, sign * dh * l * l / (w * w * w))
}

/// F = T / OM and its derivative per radian; `None` at a dead centre.
fn force(p: &Pose) -> Option<(f64, f64)> {
    let f = statics::slider_force(p, NG_TORQUE).ok()??;
    let s1 = p.position_rate();
    Some((f, NG_TORQUE * p.position_acceleration() / (s1 * s1)))
}

/// The root of `f` in (a, b) by bisection, where `f(a)` and `f(b)` differ
/// in sign; `None` otherwise.
fn root(f: impl Fn(f64) -> f64, mut a: f64, mut b: f64) -> Option<f64> {
    let (mut fa, fb) = (f(a), f(b));
    if fa * fb > 0.0 || (fa * fb).is_nan() {
        return None;
    }
    for _ in 0..200 {
        let m = 0.5 * (a + b);
        let fm = f(m);
        if fa * fm <= 0.0 {
            b = m;
        } else {
            a = m;
            fa = fm;
        }
    }
    Some(0.5 * (a + b))
}

/// The height of the transmission angle's band, page units.
const BETA_HEIGHT: f64 = 250.0;

pub(in crate::catalogue) fn build(ctx: &Ctx) -> Result<Figure> {
    let page = ctx.page();
    let mut sheet = Sheet::new(ctx);
    sheet.mechanism(ctx, false, false);
    sheet.meta("torque", serde_json::json!(NG_TORQUE));
    sheet.meta("friction", serde_json::json!(MU));
    let measured = measured(ctx)?;
    let height = page.height() - 16.0 - BETA_HEIGHT - 54.0 - 8.0;
    let m = ctx.mechanism;
    let least_f = least_force_angle(&m);
    let right = right_angle(&m);
    let places = least_f.zip(right).map_or(1, |(a, b)| places_apart(a, b));
    sheet.plot(forces(ctx, &measured, height, least_f, places)?);
    sheet.plot(transmission(ctx, 16.0 + height + 8.0, right, places)?);
    if let (Some(a), Some(b)) = (least_f, right) {
        sheet.meta("least_force_deg", serde_json::json!(a));
        sheet.meta("right_transmission_deg", serde_json::json!(b));
    }
    let notes = notes(ctx, least_f.zip(right), places);
    sheet.notes(Point::new(20.0, page.height() - 42.0), &notes);
    Ok(sheet.finish())
}

/// The crank angle of the least F, degrees: where OM = −ds/dθ is
/// greatest, d²s/dθ² = 0 (none where no root is found in 1° to 179°).
fn least_force_angle(m: &SliderCrank) -> Option<f64> {
    root(|d| at(m, d, Pose::position_acceleration), 1.0, 179.0)
}

/// The crank angle where β = 90°, degrees (θ + φ = 90°; none where it is
/// not reached).
fn right_angle(m: &SliderCrank) -> Option<f64> {
    root(
        |d| 90.0 - d - at(m, d, Pose::obliquity).to_degrees(),
        0.0,
        180.0,
    )
}

/// The fewest decimal places, at least 1 and at most 9, at which the
/// angles `a` and `b` print apart by their difference to within a tenth
/// of it, so that the figure never prints one value for two angles it
/// says are apart (at long rods the least F and β = 90° are thousandths
/// of a degree apart), nor a gap the notes contradict (88.725° and
/// 88.724° for 0.00148°); 9 where they agree even there.
fn places_apart(a: f64, b: f64) -> usize {
    let printed = |x: f64, p: usize| format!("{x:.p$}").parse::<f64>().unwrap_or(x);
    (1..=9)
        .find(|&p| {
            let gap = printed(a, p) - printed(b, p);
            gap != 0.0 && (gap - (a - b)).abs() <= 0.1 * (a - b).abs()
        })
        .unwrap_or(9)
}

/// The sentence saying where the least F falls against β = 90°: `a` and
/// `b` their crank angles, printed to `places` decimals.
fn apart(a: f64, b: f64, places: usize) -> String {
    if a == b {
        return format!(" The least *F* is at β = 90°, θ = {a:.places$}°.");
    }
    let way = if a > b { "after" } else { "before" };
    // The gap between the angles as printed, so that the three numbers
    // agree (1.785° between 72.6° and 70.9° read as a slip).
    let printed = |x: f64| format!("{x:.places$}").parse::<f64>().unwrap_or(x);
    let by = (printed(a) - printed(b)).abs();
    format!(
        " The least *F* (θ = {a:.places$}°) comes {by:.places$}° of crank angle {way} β = 90° (θ = {b:.places$}°): *F* = *T* / *OM* is least where *OM* is greatest, not where the rod is square to the crank."
    )
}

/// The crank angles (0° to 180°) where |tan φ| > 1/μ, so that
/// F′ = F(1 − μ |tan φ|) would be negative (the slider locks) and its
/// curve stops at the axis, as a clause for the notes; empty where there
/// are none (at l = 1.09 r the curve stopped between about 50° and 130°
/// with no word).
fn locked(m: &SliderCrank) -> String {
    // Positive where the slider locks; each change of sign between two
    // samples 0.05° apart found by [`root`].
    let excess = |deg: f64| pose_at(m, deg).map_or(f64::NAN, |p| MU * tan_phi(&p).0 - 1.0);
    let step = |k: i32| 0.05 * f64::from(k);
    let mut spans: Vec<(f64, f64)> = Vec::new();
    let mut start = (excess(0.0) > 0.0).then_some(0.0);
    for k in 1..=3600 {
        let (a, b) = (step(k - 1), step(k));
        let Some(edge) = root(excess, a, b).filter(|_| (excess(a) > 0.0) != (excess(b) > 0.0))
        else {
            continue;
        };
        match start.take() {
            None => start = Some(edge),
            Some(from) => spans.push((from, edge)),
        }
    }
    if let Some(a) = start {
        spans.push((a, 180.0));
    }
    if spans.is_empty() {
        return String::new();
    }
    let spans: Vec<String> = spans
        .iter()
        .map(|(a, b)| format!("{a:.1}° to {b:.1}°"))
        .collect();
    format!(
        "; from θ = {} |tan φ| > 1/μ, where *F*′ would be negative (the slider locks) and is not drawn",
        spans.join(" and ")
    )
}

/// Whether the figure draws Ng's own rig (r = 25, l = 72, in line), whose
/// experiment it may show.
fn ngs_rig(ctx: &Ctx) -> bool {
    let m = ctx.mechanism;
    (m.crank(), m.rod()) == crate::sources::NG_RIG && m.offset() == 0.0
}

/// The measured F′ against θ: the data given, else Ng's experiment on his
/// own rig (none for another engine: his points are not its forces);
/// refused where an angle is outside 0° to 180°.
fn measured(ctx: &Ctx) -> Result<Vec<(f64, f64)>> {
    let text = match ctx.options.data.as_deref() {
        Some(text) => text,
        None if ngs_rig(ctx) => NG_EXPERIMENT,
        None => return Ok(Vec::new()),
    };
    let measured = Table::parse(text, Input::Data, "data")?
        .pairs(&["angle", "theta", "θ"], &["force", "f"])?;
    if let Some((a, _)) = measured.iter().find(|(a, _)| !(0.0..=180.0).contains(a)) {
        return Err(Error::invalid(
            Input::Data,
            format!("data: angle {a}° is outside the figure’s 0° to 180°"),
        ));
    }
    Ok(measured)
}

/// The pose of `m` at `deg` degrees.
fn pose_at(m: &SliderCrank, deg: f64) -> Option<Pose> {
    Angle::from_degrees(deg).ok().map(|a| m.pose(a))
}

/// `g` of the pose of `m` at `deg` degrees; NaN where there is none.
fn at(m: &SliderCrank, deg: f64, g: fn(&Pose) -> f64) -> f64 {
    pose_at(m, deg).map_or(f64::NAN, |p| g(&p))
}

/// The crank angle's axis, 0° to 180°.
fn theta() -> Result<Axis> {
    Axis::linear("crank angle θ (°)", 0.0, 180.0)?.with_step(20.0)
}

/// (a) F and F′ (theory) against θ, `height` page units high, with the
/// `measured` F′ and the least F at `least_f` (its angle printed to
/// `places` decimals).
fn forces(
    ctx: &Ctx,
    measured: &[(f64, f64)],
    height: f64,
    least_f: Option<f64>,
    places: usize,
) -> Result<Plot> {
    let m = ctx.mechanism;
    let f_curve = |deg: f64| -> Option<(Point, Vector)> {
        let (f, df) = force(&pose_at(&m, deg)?)?;
        Some((Point::new(deg, f), Vector::new(1.0, df * PER_DEGREE)))
    };
    let f1_curve = |deg: f64| -> Option<(Point, Vector)> {
        let p = pose_at(&m, deg)?;
        let (f, df) = force(&p)?;
        let (k, dk) = tan_phi(&p);
        Some((
            Point::new(deg, f * (1.0 - MU * k)),
            Vector::new(1.0, (df * (1.0 - MU * k) - f * MU * dk) * PER_DEGREE),
        ))
    };
    let least_force = least_f
        .and_then(|d| pose_at(&m, d).as_ref().and_then(force))
        .map(|(f, _)| (least_f.unwrap_or(90.0), f));
    // The scale holds the measured points and the theory's U to two and a
    // half times its least F (at every engine: a torque on a small crank
    // gives forces far above Ng's); 50 N at Ng's rig, as he plotted it.
    let floor: f64 = if ngs_rig(ctx) { 50.0 } else { 0.0 };
    let theory = least_force.map_or(0.0, |(_, f)| 2.5 * f);
    let most = measured
        .iter()
        .map(|p| p.1)
        .fold(floor.max(theory), f64::max);
    let least = measured.iter().map(|p| p.1).fold(0.0, f64::min);
    let force_unit = ctx.units.force();
    let y = Axis::nice(&format!("force on the slider ({force_unit})"), least, most)?;
    let mut forces = Plot::new(
        "forces",
        ctx.band(16.0, height),
        theta()?,
        y,
        ctx.tolerance,
        ctx.font,
    )?
    .with_caption("(a) Slider force against crank angle");
    let pieces: [(&dyn Curve, _); 1] = [(&f_curve, 0.0..=180.0)];
    forces.curve(
        "curve-force",
        &pieces,
        Dash::Solid,
        Some("*F*, theory: *T* / *OM* (eq. 6)"),
    )?;
    let pieces: [(&dyn Curve, _); 1] = [(&f1_curve, 0.0..=180.0)];
    forces.curve(
        "curve-force-friction",
        &pieces,
        Dash::Dashed,
        Some("*F*′, theory: *F*(1 − μ |tan φ|), μ = 1 (eq. 8)"),
    )?;
    if !measured.is_empty() {
        forces.points(
            "point-measured",
            measured,
            Symbol::Disc,
            Some(if ctx.options.data.is_some() {
                "*F*′, measured (the data given)"
            } else {
                "*F*′, experiment (Ng, Table 2)"
            }),
        );
    }
    if let Some((d, f)) = least_force {
        forces.points(
            "point-least-force",
            &[(d, f)],
            Symbol::Triangle,
            Some(&format!(
                "least *F*: θ = {d:.places$}°, {} {force_unit}",
                sig(f)
            )),
        );
    }
    Ok(forces)
}

/// (b) The transmission angle β against θ from `top` down, with β = 90°
/// marked at `right` where it is reached (printed to `places` decimals).
fn transmission(ctx: &Ctx, top: f64, right: Option<f64>, places: usize) -> Result<Plot> {
    let m = ctx.mechanism;
    // From 0° to 180°, or in steps of 30° as far beyond as β goes: with an
    // offset β passes 180° (φ < 0 at small θ), and an axis ending at 180°
    // cut its curve off near θ = 20° with no word (l = 3.88 r, e = 1.65 r).
    let beta_at = |deg: f64| pose_at(&m, deg).map(|p| 180.0 - deg - p.obliquity().to_degrees());
    let (lo, hi) = (0..=360)
        .filter_map(|k| beta_at(0.5 * f64::from(k)))
        .fold((0.0f64, 180.0f64), |(lo, hi), b| (lo.min(b), hi.max(b)));
    let y = Axis::linear(
        "transmission angle β (°)",
        (lo / 30.0).floor() * 30.0,
        (hi / 30.0).ceil() * 30.0,
    )?
    .with_step(30.0)?;
    let mut beta = Plot::new(
        "transmission",
        ctx.band(top, BETA_HEIGHT),
        theta()?,
        y,
        ctx.tolerance,
        ctx.font,
    )?
    .with_caption("(b) Transmission angle, β = 180° − φ − θ (eq. 11)");
    let b_curve = |deg: f64| -> Option<(Point, Vector)> {
        let p = pose_at(&m, deg)?;
        Some((
            Point::new(deg, 180.0 - deg - p.obliquity().to_degrees()),
            Vector::new(1.0, -1.0 - p.obliquity_rate()),
        ))
    };
    let pieces: [(&dyn Curve, _); 1] = [(&b_curve, 0.0..=180.0)];
    beta.curve("curve-transmission-angle", &pieces, Dash::Solid, Some("β"))?;
    if let Some(d) = right {
        beta.push(
            Item::new(
                "line-beta-90",
                Role::Dimension,
                Shape::Polyline {
                    points: vec![Point::new(0.0, 90.0), Point::new(180.0, 90.0)],
                    closed: false,
                },
            )
            .dashed(Dash::Dotted),
        );
        beta.points(
            "point-beta-90",
            &[(d, 90.0)],
            Symbol::Circle,
            Some(&format!("β = 90° at θ = {d:.places$}°")),
        );
    }
    Ok(beta)
}

/// The notes: Ng's rig and the torque, how F′ is drawn, and how far the
/// least F (the first of `angles`) falls from β = 90° (the second), to
/// `places` decimals.
fn notes(ctx: &Ctx, angles: Option<(f64, f64)>, places: usize) -> [String; 2] {
    let m = ctx.mechanism;
    let rig = if ngs_rig(ctx) {
        "Ng’s rig"
    } else {
        "The engine (Ng’s experiment, on his rig, is not drawn)"
    };
    [
        format!(
            "{rig}: *r* = {} {u}, *l* = {} {u}{}; *T* = {NG_TORQUE:.2} {}, the torque Ng’s *F* column implies{}.",
            short(m.crank()),
            short(m.rod()),
            ctx.offset_clause(),
            ctx.units.torque(),
            if ngs_rig(ctx) && ctx.units == crate::units::Units::MILLIMETRE_NEWTON {
                " (1 kg hung at the 27 mm radius of Ng’s circular crank)"
            } else {
                ""
            },
            u = ctx.unit(),
        ),
        format!(
            "*F*′ is drawn with each angle’s φ (Ng’s printed *F*′ used φ of 60° throughout){}.{}",
            locked(&m),
            angles.map_or(String::new(), |(a, b)| apart(a, b, places))
        ),
    ]
}
