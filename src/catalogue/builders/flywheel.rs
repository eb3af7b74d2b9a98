//! The flywheel: (a) the energy stored above its least over the turn,
//! E(θ) − E_min, rising to the fluctuation of energy ΔE; (b) the crank
//! speed over the turn with the flywheel that holds it within the
//! coefficient of fluctuation C_s, I = ΔE / (ω² C_s) (`docs/dynamics.md`
//! §5): ½ I ω(θ)² = ½ I ω_min² + E(θ) − E_min with ω_min = ω (1 − C_s/2),
//! so that the speed runs between ω_min and ω_max = ω (1 + C_s/2).
//!
//! The engine is the turning-moment figure's (its indicator diagram,
//! the data, and the mass); the crank speed is taken as constant in T, as
//! there, which is the flywheel's usual approximation.

use super::turning::{engine, stored};
use super::{Ctx, PER_DEGREE, Sheet, short, sig};
use crate::diagram::{Axis, Plot};
use crate::dynamics::turning::total_torque;
use crate::dynamics::{Flywheel, TurningMoment};
use crate::error::Result;
use crate::figure::{Dash, Figure, Item, Role, Shape, Symbol};
use crate::geom::{Point, Vector};

/// The coefficient asked for, else the default; refused unless
/// 0 < C_s < 2 ([`crate::dynamics::checked_coefficient`]).
fn coefficient(ctx: &Ctx) -> Result<f64> {
    crate::dynamics::checked_coefficient(
        ctx.options
            .fluctuation
            .unwrap_or(crate::dynamics::DEFAULT_FLUCTUATION),
    )
}

pub(in crate::catalogue) fn build(ctx: &Ctx) -> Result<Figure> {
    let page = ctx.page();
    let engine = engine(ctx)?;
    let tm = TurningMoment::new(&engine, &[0.0])?;
    let fly = Flywheel::for_coefficient(tm.fluctuation, ctx.omega, coefficient(ctx)?)?;
    let least = stored(&engine, &tm, tm.min_energy_deg);
    let mut sheet = Sheet::new(ctx);
    sheet.mechanism(ctx, true, false);
    sheet.meta(
        "flywheel",
        serde_json::json!({
            "fluctuation": fly.fluctuation,
            "coefficient": fly.coefficient,
            "inertia": fly.inertia,
            "least_energy_deg": tm.min_energy_deg,
            "most_energy_deg": tm.max_energy_deg,
        }),
    );
    // E(θ) − E_min and its slope per degree, T − T_mean.
    let above = |deg: f64| -> (f64, f64) {
        let slope = total_torque(&engine, &[0.0], deg.to_radians()) - tm.mean;
        (stored(&engine, &tm, deg) - least, slope * PER_DEGREE)
    };
    let height = 0.5 * (page.height() - 32.0 - 24.0 - 56.0);
    sheet.plot(energy_plot(ctx, &tm, &above, height)?);
    let extremes = (tm.min_energy_deg, tm.max_energy_deg);
    let band = (16.0 + height + 24.0, height);
    sheet.plot(speed_plot(ctx, &fly, &above, extremes, band)?);
    let (u, mass_u) = (ctx.unit(), ctx.units.mass());
    let inertia_u = ctx.units.moment_of_inertia();
    let t = ctx.units.torque();
    let w = ctx.omega;
    sheet.notes(
        Point::new(20.0, page.height() - 40.0),
        &[
            format!(
                "The turning-moment figure’s engine: *r* = {} {u}, *l* = {} {u}{}, *m* = {} {mass_u}, {} rpm (ω = {} rad/s){}. Δ*E* = {} {t}, from θ = {}° (least) to {}° (most).",
                short(ctx.mechanism.crank()), short(ctx.mechanism.rod()),
                ctx.offset_clause(),
                short(ctx.options.mass.unwrap_or(crate::dynamics::EXAMPLE_MASS)),
                short(ctx.rpm()), sig(w),
                super::turning::guides_note(ctx),
                sig(fly.fluctuation), short(tm.min_energy_deg), short(tm.max_energy_deg),
            ),
            format!(
                "For *C*_s = {}: *I* = Δ*E*/(ω²*C*_s) = {} {inertia_u}; the speed runs from ω_{{min}} = {} to ω_{{max}} = {} rad/s.",
                short(fly.coefficient), sig(fly.inertia),
                sig(w * (1.0 - 0.5 * fly.coefficient)), sig(w * (1.0 + 0.5 * fly.coefficient)),
            ),
        ],
    );
    Ok(sheet.finish())
}

/// The crank-angle axis.
fn theta() -> Result<Axis> {
    Axis::linear("crank angle θ (°)", 0.0, 360.0)?.with_step(30.0)
}

/// (a) E(θ) − E_min with the lines of least and most energy and ΔE
/// between them at the angle of most.
fn energy_plot(
    ctx: &Ctx,
    tm: &TurningMoment,
    above: &dyn Fn(f64) -> (f64, f64),
    height: f64,
) -> Result<Plot> {
    let t_unit = ctx.units.torque();
    let de = tm.fluctuation;
    let mut plot = Plot::new(
        "energy-above-least",
        ctx.band(16.0, height),
        theta()?,
        Axis::nice(&format!("energy above the least, *E* − *E*_{{min}} ({t_unit})"), 0.0, de)?,
        ctx.tolerance,
        ctx.font,
    )?
    .with_caption("(a) The energy stored in the flywheel above its least: it rises by the fluctuation of energy Δ*E*");
    let curve = |deg: f64| -> Option<(Point, Vector)> {
        let (e, slope) = above(deg);
        Some((Point::new(deg, e), Vector::new(1.0, slope)))
    };
    plot.curve(
        "curve-energy-above-least",
        &[(&curve, 0.0..=360.0)],
        Dash::Solid,
        Some("*E* − *E*_{min}"),
    )?;
    plot.line(
        "line-most-energy",
        &[(0.0, de), (360.0, de)],
        Dash::Dashed,
        None,
    );
    plot.points(
        "point-energy-extremes",
        &[(tm.min_energy_deg, 0.0), (tm.max_energy_deg, de)],
        Symbol::Circle,
        Some(&format!("least and most, Δ*E* = {} {t_unit}", sig(de))),
    );
    if let (Some(from), Some(to)) = (
        plot.world_point(tm.max_energy_deg, 0.0),
        plot.world_point(tm.max_energy_deg, de),
    ) {
        plot.push(Item::new(
            "dimension-fluctuation",
            Role::Dimension,
            Shape::Arrow { from, to },
        ));
    }
    Ok(plot)
}

/// (b) The crank speed over the turn with the flywheel, between ω_min and
/// ω_max (marked at the angles of least and most energy, `extremes`),
/// the mean speed dashed, in the band (top, height).
fn speed_plot(
    ctx: &Ctx,
    fly: &Flywheel,
    above: &dyn Fn(f64) -> (f64, f64),
    extremes: (f64, f64),
    (top, height): (f64, f64),
) -> Result<Plot> {
    let w = ctx.omega;
    let (lo, hi) = (
        w * (1.0 - 0.5 * fly.coefficient),
        w * (1.0 + 0.5 * fly.coefficient),
    );
    let inertia = fly.inertia;
    let mut plot = Plot::new(
        "speed",
        ctx.band(top, height),
        theta()?,
        Axis::nice("crank speed ω (rad/s)", lo, hi)?,
        ctx.tolerance,
        ctx.font,
    )?
    .with_caption(&format!(
        "(b) The crank speed with the flywheel *I* = Δ*E*/(ω²*C*_s) for *C*_s = {}",
        short(fly.coefficient)
    ));
    // ½ I ω² = ½ I ω_min² + (E − E_min); dω/dθ = (T − T_mean)/(I ω).
    let curve = |deg: f64| -> Option<(Point, Vector)> {
        let (e, slope) = above(deg);
        let speed = if inertia > 0.0 {
            (lo * lo + 2.0 * e / inertia).sqrt()
        } else {
            w
        };
        let rate = if inertia > 0.0 {
            slope / (inertia * speed)
        } else {
            0.0
        };
        Some((Point::new(deg, speed), Vector::new(1.0, rate)))
    };
    plot.curve(
        "curve-speed",
        &[(&curve, 0.0..=360.0)],
        Dash::Solid,
        Some("ω(θ)"),
    )?;
    plot.points(
        "point-speed-extremes",
        &[(extremes.0, lo), (extremes.1, hi)],
        Symbol::Circle,
        Some("ω_{min} and ω_{max} = ω(1 ± *C*_s/2)"),
    );
    plot.line(
        "line-mean-speed",
        &[(0.0, w), (360.0, w)],
        Dash::Dashed,
        Some(&format!("mean ω = {} rad/s", sig(w))),
    );
    Ok(plot)
}
