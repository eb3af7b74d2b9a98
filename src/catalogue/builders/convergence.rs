//! The curved slot converging on the straight one (textbook Fig. 60 (b) →
//! (c)): the worst difference over a turn between the block's arc
//! position, velocity and acceleration on a slot of radius ρ and the
//! straight slot's, scaled by r, against ρ from 1 to 1e15, log–log. It
//! falls as 1/ρ until it meets the rounding of the inputs.

use super::{Ctx, Sheet, short};
use crate::chain::{ConvergenceRow, slot_convergence};
use crate::diagram::{Axis, Plot};
use crate::error::{Error, Field, Result};
use crate::figure::{Dash, Figure, Symbol};
use crate::geom::{Frame, Point};
use crate::mechanism::SliderCrank;

/// Crank angles per turn at which each radius is compared.
const SAMPLES: usize = 720;
/// Radii per decade.
const PER_DECADE: i32 = 4;

/// The height of the notes below the plot, page units.
const NOTES_HEIGHT: f64 = 44.0;

/// One of the plotted differences of a row.
type Value = fn(&ConvergenceRow) -> f64;

/// The three differences: id, legend, marker and value.
const SERIES: [(&str, &str, Symbol, Value); 3] = [
    (
        "position",
        "arc position σ against *x*_{A}",
        Symbol::Disc,
        |w| w.position,
    ),
    (
        "velocity",
        "velocity dσ/dθ against d*x*_{A}/dθ",
        Symbol::Square,
        |w| w.velocity,
    ),
    (
        "acceleration",
        "acceleration d²σ/dθ² against d²*x*_{A}/dθ²",
        Symbol::Triangle,
        |w| w.acceleration,
    ),
];

pub(in crate::catalogue) fn build(ctx: &Ctx) -> Result<Figure> {
    let page = ctx.page();
    let m = ctx.mechanism;
    let radii = radii(&m)?;
    let rows = slot_convergence(&m, &radii, SAMPLES)?;
    let mut sheet = Sheet::new(ctx);
    sheet.mechanism(ctx, false, false);
    let plot = plot(ctx, &rows, &radii)?;
    sheet.meta(
        "rows",
        serde_json::json!(
            rows.iter()
                .map(|w| [w.radius, w.position, w.velocity, w.acceleration])
                .collect::<Vec<_>>()
        ),
    );
    sheet.plot(plot);
    sheet.notes(Point::new(20.0, page.height() - NOTES_HEIGHT), &notes(&m));
    Ok(sheet.finish())
}

/// The slot radii compared, PER_DECADE a decade from 1 to 1e15, those
/// the crank turns with; refused where fewer than two are left.
fn radii(m: &SliderCrank) -> Result<Vec<f64>> {
    let (r, l, e) = (m.crank(), m.rod(), m.offset());
    // The least radius the crank turns with (CylindricChain::new).
    let bound = 0.5 * (l + r + e);
    let radii: Vec<f64> = (0..=15 * PER_DECADE)
        .map(|k| 10f64.powf(k as f64 / PER_DECADE as f64))
        .filter(|rho| *rho > bound * (1.0 + 1e-9))
        .collect();
    if radii.len() < 2 {
        return Err(Error::OutOfRange {
            name: Field::Rod,
            value: l,
            reason: "the slot radii from 1 to 1e15 need (rod + crank + offset)/2 well below 1e15"
                .into(),
        });
    }
    Ok(radii)
}

/// The rounding of the inputs: one ulp of the largest length, in r.
fn floor(m: &SliderCrank) -> f64 {
    f64::EPSILON * (m.rod() + m.crank() + m.offset().abs()) / m.crank()
}

/// The log–log plot of the three differences of `rows` against the
/// `radii`, with the slope −1 and the rounding of the inputs.
fn plot(ctx: &Ctx, rows: &[ConvergenceRow], radii: &[f64]) -> Result<Plot> {
    let page = ctx.page();
    // `radii` holds two or more ([`radii`]).
    let least = radii.first().copied().unwrap_or(1.0);
    let floor = floor(&ctx.mechanism);
    let positive = |v: f64| v.max(floor * 0.25);
    let top = rows
        .iter()
        .flat_map(|w| SERIES.map(|s| (s.3)(w)))
        .fold(0.0f64, f64::max);
    let x = Axis::log("slot radius ρ", least, 1e15)?;
    let y = Axis::log(
        "worst difference over the turn, in units of *r*",
        floor * 0.1,
        top * 100.0,
    )?;
    let rect = Frame::from_origin_size(
        16.0,
        16.0,
        page.width() - 32.0,
        page.height() - 32.0 - NOTES_HEIGHT,
    );
    let mut plot = Plot::new("convergence", rect, x, y, ctx.tolerance, ctx.font)?
        .with_grid()
        .with_caption("The curved slot against the straight slot");
    // The three series lie within a factor of a few of each other: each
    // sets its markers at every third radius, the three staggered, so
    // that no marker covers another; its line runs through every radius.
    for (i, (id, legend, symbol, value)) in SERIES.into_iter().enumerate() {
        let points: Vec<(f64, f64)> = rows
            .iter()
            .map(|w| (w.radius, positive(value(w))))
            .collect();
        let marked: Vec<(f64, f64)> = points.iter().copied().skip(i).step_by(3).collect();
        plot.line(&format!("series-{id}"), &points, Dash::Solid, None);
        plot.points(&format!("point-{id}"), &marked, symbol, None);
        plot.legend_marker(legend, symbol);
    }
    guides(&mut plot, rows, least, floor);
    Ok(plot)
}

/// The slope −1 a decade above the velocity at the middle radius, so
/// that it runs beside the series instead of under them, and the
/// rounding of the inputs `floor`, from the `least` radius on.
fn guides(plot: &mut Plot, rows: &[ConvergenceRow], least: f64, floor: f64) {
    // (No guide without rows: a NaN passes no filter.)
    let k = rows
        .get(rows.len() / 2)
        .map_or(f64::NAN, |middle| 10.0 * middle.velocity * middle.radius);
    let guide: Vec<(f64, f64)> = [least, 1e15]
        .into_iter()
        .map(|rho| (rho, k / rho))
        .filter(|(_, v)| *v >= floor * 0.1)
        .collect();
    if guide.len() == 2 {
        plot.line("guide-slope", &guide, Dash::Dashed, None);
        plot.legend_line("slope −1: falling as 1/ρ (a decade above)", Dash::Dashed);
    }
    plot.line(
        "guide-rounding",
        &[(least, floor), (1e15, floor)],
        Dash::Dotted,
        None,
    );
    plot.legend_line(
        "ε (*l* + *r* + |*e*|)/*r*: rounding of the inputs",
        Dash::Dotted,
    );
}

/// The notes: the mechanism and what is compared, and why the
/// difference falls as 1/ρ to the rounding.
fn notes(m: &SliderCrank) -> [String; 2] {
    let (r, l, e) = (m.crank(), m.rod(), m.offset());
    [
        format!(
            "*r* = {}, *l* = {}{}; worst over {SAMPLES} crank angles of the difference between the block on a slot of radius ρ (centre below the stroke) and on the straight slot.",
            short(r),
            short(l),
            if e == 0.0 { String::new() } else { format!(", *e* = {}", short(e)) }
        ),
        "Computed from the curvature 1/ρ: no cancellation, so the difference falls as 1/ρ until the rounding of the inputs (zero differences drawn at a quarter of it).".to_string(),
    ]
}
