//! `table dynamics`: the forces and torques of an engine against θ, with
//! the turn's mean torque, fluctuation of energy and flywheel as notes.

use super::{Table, sig};
use crate::angle::Angle;
use crate::dynamics::{EXAMPLE_MASS, Engine, Flywheel, FlywheelAsk, TurningMoment};
use crate::error::Result;
use crate::number::fixed;
use crate::number::{angle_cell, plain};
use crate::units::Units;

/// The title, headers and notes of the dynamics table of `engine` with
/// cylinders at `phases_deg` (the notes hold the turn's results).
///
/// Errors: those of [`TurningMoment::new`] and [`Flywheel`].
pub fn dynamics_head(
    engine: &Engine,
    phases_deg: &[f64],
    flywheel: FlywheelAsk,
    units: &Units,
) -> Result<Table> {
    let (u, f, t) = (units.length(), units.force(), units.torque());
    let m = engine.mechanism();
    let turn = TurningMoment::new(engine, phases_deg)?;
    let mut headers = vec![
        "θ (°)".to_string(),
        format!("gas ({f})"),
        format!("inertia ({f})"),
    ];
    let (weighed, rubbing) = guides(engine);
    if weighed {
        headers.push(format!("weight ({f})"));
    }
    if rubbing {
        headers.push(format!("friction ({f})"));
    }
    headers.extend([
        format!("F ({f})"),
        format!("rod ({f})"),
        format!("guides ({f})"),
        format!("OM ({u})"),
        format!("F·OM ({t})"),
        format!("T rod ({t})"),
        format!("T ({t})"),
    ]);
    if turn.phases_deg.len() > 1 {
        headers.push(format!("T all ({t})"));
    }
    let mut notes = vec![
        "Forces along the stroke are positive towards the crank centre; F = gas + inertia; rod: F / cos φ (compression); guides: the slider's thrust along +y, −F tan φ; T = F·OM + the rod's inertia torque, counter-clockwise positive.".to_string(),
        format!(
            "Over the {} ({} cylinder{} at {}°): work {} {t}, mean torque {} {t}, fluctuation of energy ΔE = {} {t} (most energy at θ = {}°, least at {}°; {} areas).{}",
            if turn.cycle_deg > 360.0 { "four-stroke cycle of 720°, rows past 360° in its second turn" } else { "turn" },
            turn.phases_deg.len(),
            if turn.phases_deg.len() == 1 { "" } else { "s" },
            turn.phases_deg.iter().map(|d| plain(*d)).collect::<Vec<_>>().join(", "),
            sig(turn.settled(turn.work)),
            sig(turn.settled(turn.mean * turn.cycle_deg.to_radians()) / turn.cycle_deg.to_radians()),
            sig(turn.settled(turn.fluctuation)),
            fixed(turn.max_energy_deg, 2), fixed(turn.min_energy_deg, 2),
            turn.lobes.len(),
            if turn.work.abs() <= turn.tolerance {
                " A work within the integrals' tolerance of zero is written 0 (the inertia forces alone do no work over a turn)."
            } else {
                ""
            },
        ),
    ];
    if let Some(note) = guides_note(engine, units) {
        notes.insert(1, note);
    }
    let fw = match flywheel {
        FlywheelAsk::None => None,
        FlywheelAsk::Coefficient(c) => Some(Flywheel::for_coefficient(
            turn.fluctuation,
            engine.omega(),
            c,
        )?),
        FlywheelAsk::Inertia(i) => {
            Some(Flywheel::for_inertia(turn.fluctuation, engine.omega(), i)?)
        }
    };
    if let Some(fw) = fw {
        notes.push(format!(
            "Flywheel: I = ΔE / (ω² C_s) = {} {} for C_s = {}.",
            sig(fw.inertia),
            units.moment_of_inertia(),
            sig(fw.coefficient)
        ));
    }
    Ok(Table {
        title: format!(
            "Engine dynamics: r = {} {u}, l = {} {u}, e = {} {u}, m = {} {}, ω = {} rad/s",
            plain(m.crank()),
            plain(m.rod()),
            plain(m.offset()),
            plain(engine.reciprocating_mass()),
            units.mass(),
            plain(engine.omega())
        ),
        headers,
        rows: vec![],
        notes,
    })
}

/// Whether `engine` has gravity, and friction in its guides: each adds
/// its column.
fn guides(engine: &Engine) -> (bool, bool) {
    (engine.gravity() != [0.0, 0.0], engine.friction() > 0.0)
}

/// The note of gravity and the guides' friction, `None` without either.
fn guides_note(engine: &Engine, units: &Units) -> Option<String> {
    let (weighed, rubbing) = guides(engine);
    if !weighed && !rubbing {
        return None;
    }
    let mut parts = vec![];
    if weighed {
        let g = engine.gravity();
        parts.push(format!(
            "gravity g = ({}, {}) {}/s² along and across the line of stroke: weight, that of the reciprocating parts towards the crank, is in F, and the rod's weight at G in the pin loads and in T (m_r g·G′)",
            sig(g[0]),
            sig(g[1]),
            units.length()
        ));
    }
    if rubbing {
        parts.push(format!(
            "the guides' friction μ = {} against the slider's motion, μ |N| with N the guides' reaction of the reciprocating parts (in F; 0 at a dead centre), and in T with the rod's inertia in N",
            plain(engine.friction())
        ));
    }
    let mut note = parts.join("; ");
    note.insert_str(0, "With ");
    note.push_str(": F = gas + inertia");
    if weighed {
        note.push_str(" + weight");
    }
    if rubbing {
        note.push_str(" + friction");
    }
    note.push('.');
    Some(note)
}

/// One row of the dynamics table at `degrees`; past 360° (to 720°) in
/// the second turn of a four-stroke cycle.
pub fn dynamics_row(
    engine: &Engine,
    phases_deg: &[f64],
    degrees: f64,
    decimals: usize,
) -> Result<Vec<String>> {
    let angle = Angle::from_degrees(degrees)?;
    let at = engine.at_turn(angle, engine.turn_at_degrees(degrees))?;
    let mut row = vec![
        angle_cell(degrees, 1),
        fixed(at.gas_force, decimals),
        fixed(at.inertia_force, decimals),
    ];
    if let Some(w) = at.weight {
        row.push(fixed(w, decimals));
    }
    if let Some(f) = at.friction {
        row.push(fixed(f, decimals));
    }
    row.extend([
        fixed(at.piston_effort, decimals),
        fixed(at.rod_force, decimals),
        fixed(at.guide_thrust, decimals),
        fixed(at.om, decimals),
        fixed(at.crank_effort, decimals),
        fixed(at.rod.map_or(0.0, |r| r.torque), decimals),
        fixed(at.torque, decimals),
    ]);
    if phases_deg.len() > 1 {
        // The turn of the cycle of the row's angle carried by the phases
        // (cylinder i at θ + δ_i, θ past 360° on a four-stroke cycle),
        // each phase first reduced exactly modulo the cycle.
        let turns = engine.gas().turns() as f64;
        let turn = degrees.div_euclid(360.0).rem_euclid(turns);
        let shifted: Vec<f64> = phases_deg
            .iter()
            .map(|d| d % (360.0 * turns) + 360.0 * turn)
            .collect();
        row.push(fixed(
            engine.torque_of_cylinders(&shifted, angle)?,
            decimals,
        ));
    }
    Ok(row)
}

/// The dynamics table of the example engine: §35's (r = 0.5 ft, l = 3 ft,
/// 250 rpm) with [`EXAMPLE_MASS`], no gas force, one cylinder, 4 decimals,
/// at `angles` (degrees).
pub fn example_table(angles: &[f64]) -> Result<Table> {
    let (r, l) = crate::sources::ENGINE_35;
    let m = crate::mechanism::SliderCrank::in_line(r, l)?;
    let engine = Engine::new(
        m,
        EXAMPLE_MASS,
        crate::analytic::kinematics::rpm_to_omega(crate::sources::RPM),
    )?;
    let head = dynamics_head(&engine, &[0.0], FlywheelAsk::None, &Units::FOOT_POUND)?;
    let rows = angles
        .iter()
        .map(|&d| dynamics_row(&engine, &[0.0], d, 4))
        .collect::<Result<Vec<_>>>()?;
    Ok(Table { rows, ..head })
}
