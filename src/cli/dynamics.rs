//! The engine flags of `analyze` and `table dynamics`: masses, gas force,
//! cylinders and flywheel; and the dynamics section of `analyze`.

use clap::Args;
use slider_crank::dynamics::{Engine, EnginePose, unbalanced_forces};
use slider_crank::render::plain;
use slider_crank::table::{GivenEngine, mass_unit};
use slider_crank::{Angle, Units};
use std::path::PathBuf;

/// The engine's masses and gas force. Any of them adds the dynamics.
#[derive(Debug, Clone, Args)]
pub struct EngineArgs {
    /// Reciprocating mass m (piston and cross-head) in the unit that makes
    /// mass × length/s² the force unit (kg with m and N, slug with ft and
    /// lbf): adds the engine's dynamics (inertia force exact and by
    /// Klein's CG, piston effort, rod force, thrust on the guides, crank
    /// effort T = F·OM) [default: 0 with another dynamics flag]
    #[arg(long, allow_negative_numbers = true, value_name = "M")]
    pub mass: Option<f64>,
    /// The connecting rod's mass (give --rod-cg and --rod-gyration with it)
    #[arg(long, allow_negative_numbers = true, value_name = "M", requires_all = ["rod_cg", "rod_gyration"])]
    pub rod_mass: Option<f64>,
    /// Distance BG of the rod's centre of mass from the crank pin, in the
    /// length unit (0 ≤ BG ≤ l)
    #[arg(
        long,
        allow_negative_numbers = true,
        value_name = "BG",
        requires = "rod_mass"
    )]
    pub rod_cg: Option<f64>,
    /// The rod's radius of gyration k about its centre of mass
    #[arg(
        long,
        allow_negative_numbers = true,
        value_name = "K",
        requires = "rod_mass"
    )]
    pub rod_gyration: Option<f64>,
    /// A constant gas force on the piston, positive towards the crank
    /// centre, in the force unit
    #[arg(
        long,
        allow_negative_numbers = true,
        value_name = "F",
        conflicts_with = "indicator"
    )]
    pub gas_force: Option<f64>,
    /// An indicator diagram: CSV with the columns fraction (of the stroke
    /// from the outer dead centre, 0 to 1), expansion and compression
    /// (gauge pressures, force per length²) for a cycle of one turn; with
    /// exhaust and intake columns too, a four-stroke cycle of 720° (table
    /// dynamics: the results over both turns and rows past 360° in the
    /// second; analyze: the first turn, expansion and exhaust); give
    /// --bore with it
    #[arg(long, value_name = "CSV", requires = "bore")]
    pub indicator: Option<PathBuf>,
    /// The cylinder's bore D (piston area π D²/4), in the length unit
    #[arg(
        long,
        allow_negative_numbers = true,
        value_name = "D",
        requires = "indicator"
    )]
    pub bore: Option<f64>,
    /// A vertical engine: gravity along the line of stroke towards-crank
    /// (the cylinder above the crank) or away-from-crank (below it),
    /// standard gravity 9.80665 m/s² in the length unit; the weights of
    /// the reciprocating mass and the rod (at its centre of mass) enter
    /// the piston effort, the rod force, the guide thrust, the pin and
    /// bearing loads and the torque [default: none, a horizontal engine's
    /// weights left out]
    #[arg(long, value_name = "DIRECTION")]
    pub gravity: Option<slider_crank::dynamics::Gravity>,
}

impl EngineArgs {
    /// The request's engine these flags give, the one place the command
    /// line fills it (`table` and `analyze` alike); its
    /// [`GivenEngine::engine`] is the engine asked for, `None` without a
    /// dynamics flag.
    pub fn given(&self) -> GivenEngine {
        GivenEngine {
            mass: self.mass,
            rod_mass: self.rod_mass,
            rod_cg: self.rod_cg,
            rod_gyration: self.rod_gyration,
            gas_force: self.gas_force,
            indicator: self.indicator.clone(),
            bore: self.bore,
            gravity: self.gravity,
        }
    }
}

/// The turn's flags of `table dynamics`: cylinders and flywheel.
#[derive(Debug, Clone, Args)]
pub struct TurnArgs {
    /// Phase angles of the cylinders' cranks in degrees, ahead of the
    /// first, comma-separated (0,180: two cylinders opposite) [default: 0,
    /// one cylinder]
    #[arg(long, value_name = "LIST", allow_hyphen_values = true)]
    pub phases: Option<String>,
    /// Coefficient of fluctuation of speed C_s = (ω_max − ω_min)/ω: adds
    /// the flywheel I = ΔE / (ω² C_s) to the notes
    #[arg(
        long,
        allow_negative_numbers = true,
        value_name = "CS",
        conflicts_with = "flywheel"
    )]
    pub fluctuation: Option<f64>,
    /// A flywheel's moment of inertia I (FORCE·s²·UNIT): adds its
    /// coefficient of fluctuation of speed to the notes
    #[arg(long, allow_negative_numbers = true, value_name = "I")]
    pub flywheel: Option<f64>,
}

/// The dynamics section of `analyze`'s text.
pub fn to_text(engine: &Engine, at: &EnginePose, angle: Angle, units: &Units) -> String {
    let (f, t, u) = (
        units.force().to_string(),
        units.torque(),
        units.length().to_string(),
    );
    let b = unbalanced_forces(engine, angle);
    let mut out = format!(
        "  dynamics (m = {} {}, forces positive towards the crank centre, torques counter-clockwise)\n",
        plain(engine.reciprocating_mass()),
        mass_unit(units)
    );
    let mut row = |name: &str, x: f64, unit: &str| {
        out.push_str(&format!("    {name:<34}{:>20}  {unit}\n", number(x)));
    };
    row("gas force", at.gas_force, &f);
    row("inertia force m a (exact)", at.inertia_force, &f);
    row(
        "inertia force −m ω² CG (Klein)",
        at.inertia_force_graphical,
        &f,
    );
    if let Some(w) = at.weight {
        row("weight −m g_x", w, &f);
    }
    if let Some(fr) = at.friction {
        row(
            &format!("friction μ|N| (μ = {})", plain(engine.friction())),
            fr,
            &f,
        );
    }
    row("piston effort F", at.piston_effort, &f);
    row("force along the rod F/cos φ", at.rod_force, &f);
    row("thrust on the guides −F tan φ", at.guide_thrust, &f);
    row("OM (Ng's line)", at.om, &u);
    row("crank effort F·OM", at.crank_effort, &t);
    row("crank effort F r sin(θ+φ)/cos φ", at.crank_effort_exact, &t);
    if let Some(r) = at.rod {
        row("rod inertia force x", r.force[0], &f);
        row("rod inertia force y", r.force[1], &f);
        row("rod inertia couple", r.couple, &t);
        row("rod torque on the crank (exact)", r.torque, &t);
        row(
            "rod mass at the cross-head m_A",
            r.mass_at_crosshead,
            &mass_unit(units),
        );
        row(
            "rod mass at the crank pin m_B",
            r.mass_at_crank_pin,
            &mass_unit(units),
        );
        row("correction couple", r.correction_couple, &t);
        row("rod torque (two masses + couple)", r.equivalent_torque, &t);
        let system = engine
            .rod()
            .and_then(|rod| rod.dynamical_system(engine.mechanism().rod()));
        if let (Some(d), Some(torque)) = (system, r.dynamical_torque) {
            row("centre of percussion L from A", d.distance, &u);
            row(
                "dynamical system: mass at A",
                d.mass_at_crosshead,
                &mass_unit(units),
            );
            row(
                "dynamical system: mass at L",
                d.mass_at_percussion,
                &mass_unit(units),
            );
            row("rod torque (dynamical system)", torque, &t);
        }
        let w = &at.loads;
        row(
            "piston effort with m_A (equivalent)",
            w.piston_effort_equivalent,
            &f,
        );
        row("with the rod: force along the rod", w.rod_force, &f);
        row("with the rod: thrust on the guides", w.guide_thrust, &f);
        if let Some(fr) = w.friction {
            row("with the rod: friction μ|N|", fr, &f);
        }
        row("with the rod: crank-pin load x", w.crank_pin[0], &f);
        row("with the rod: crank-pin load y", w.crank_pin[1], &f);
        row("with the rod: shaking force x", w.shaking_force[0], &f);
        row("with the rod: shaking force y", w.shaking_force[1], &f);
    }
    row("torque on the crank T", at.torque, &t);
    row("primary force m r ω² cos θ", b.primary, &f);
    row("secondary force m r ω² cos 2θ / n", b.secondary, &f);
    row("exact unbalanced force −m a", b.exact, &f);
    out
}

/// Ten decimals, exponent form beyond 1e12 or below 1e-6.
fn number(x: f64) -> String {
    let a = x.abs();
    if a != 0.0 && !(1e-6..1e12).contains(&a) {
        format!("{:.10e}", x + 0.0)
    } else {
        format!("{:.10}", x + 0.0)
    }
}
