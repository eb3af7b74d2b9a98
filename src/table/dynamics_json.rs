//! The member `dynamics` of the analysis's JSON: the engine's forces and
//! torques at one pose, one copy for the command line and the Python
//! package.

use crate::angle::Angle;
use crate::dynamics::{Engine, EngineLoads, EnginePose, unbalanced_forces};
use crate::units::Units;
use serde_json::{Value, json};

use crate::number::unsigned_zero as num;

/// The unit of mass the forces imply ([`Units::mass`]: `slug` with the
/// textbook's units, `kg` with N and m).
pub fn mass_unit(units: &Units) -> String {
    units.mass()
}

/// The dynamics of `engine` at `angle` (its pose `at`) as the analysis's
/// JSON writes them: forces along the stroke, the crank effort by
/// Ng's OM and exactly, the torque, the unbalanced forces, the rod's
/// inertia (`null` for a massless rod) and the forces of the whole engine
/// with it (`whole_engine`); with gravity `gravity` (g, x and y) and the
/// reciprocating parts' `weight`, with friction `friction_coefficient`
/// and the guides' `friction` (and `whole_engine.friction`).
pub fn dynamics_json(engine: &Engine, at: &EnginePose, angle: Angle, units: &Units) -> Value {
    let b = unbalanced_forces(engine, angle);
    let system = engine
        .rod()
        .and_then(|rod| rod.dynamical_system(engine.mechanism().rod()));
    let rod = at.rod.map_or(Value::Null, |r| {
        let dynamical = match (system, r.dynamical_torque) {
            (Some(d), Some(t)) => json!({
                "percussion_distance": num(d.distance),
                "mass_at_crosshead": num(d.mass_at_crosshead),
                "mass_at_percussion": num(d.mass_at_percussion),
                "torque": num(t),
            }),
            _ => Value::Null,
        };
        json!({
            "inertia_force": [num(r.force[0]), num(r.force[1])],
            "inertia_couple": num(r.couple),
            "torque": num(r.torque),
            "equivalent": {
                "mass_at_crosshead": num(r.mass_at_crosshead),
                "mass_at_crank_pin": num(r.mass_at_crank_pin),
                "correction_couple": num(r.correction_couple),
                "correction_torque": num(r.correction_torque),
                "torque": num(r.equivalent_torque),
            },
            "dynamical": dynamical,
        })
    });
    let mut out = json!({
        "units": {"force": units.force(), "torque": units.torque(), "mass": mass_unit(units)},
        "sign": "forces along the stroke positive towards the crank centre; torques counter-clockwise positive",
        "reciprocating_mass": engine.reciprocating_mass(),
        "gas_force": num(at.gas_force),
        "inertia_force": num(at.inertia_force),
        "inertia_force_klein": num(at.inertia_force_graphical),
        "piston_effort": num(at.piston_effort),
        "rod_force": num(at.rod_force),
        "guide_thrust": num(at.guide_thrust),
        "OM": num(at.om),
        "crank_effort": num(at.crank_effort),
        "crank_effort_exact": num(at.crank_effort_exact),
        "torque": num(at.torque),
        "unbalanced": {
            "primary": num(b.primary), "secondary": num(b.secondary),
            "exact": num(b.exact), "remainder": num(b.remainder),
        },
        "rod": rod,
        "whole_engine": loads_json(&at.loads),
    });
    // Gravity and friction only where given: an engine without either
    // writes what it always did.
    if let Some(w) = at.weight {
        let g = engine.gravity();
        put(&mut out, "gravity", json!([num(g[0]), num(g[1])]));
        put(&mut out, "weight", json!(num(w)));
    }
    if let Some(f) = at.friction {
        put(&mut out, "friction_coefficient", json!(engine.friction()));
        put(&mut out, "friction", json!(num(f)));
    }
    out
}

/// The forces of the whole engine, the rod's inertia included
/// ([`EngineLoads`]): with a massless rod the same as the reciprocating
/// parts' above.
fn loads_json(l: &EngineLoads) -> Value {
    let pair = |v: [f64; 2]| [num(v[0]), num(v[1])];
    let mut out = json!({
        "crosshead_pin_load": pair(l.crosshead_pin),
        "crank_pin_load": pair(l.crank_pin),
        "rod_force": num(l.rod_force),
        "guide_thrust": num(l.guide_thrust),
        "piston_effort_equivalent": num(l.piston_effort_equivalent),
        "shaking_force": pair(l.shaking_force),
    });
    if let Some(f) = l.friction {
        put(&mut out, "friction", json!(num(f)));
    }
    out
}

/// Sets `key` of the object `out` to `value` (nothing where `out` is not
/// an object, which the callers' `json!` never makes).
fn put(out: &mut Value, key: &str, value: Value) {
    if let Value::Object(map) = out {
        map.insert(key.to_string(), value);
    }
}
