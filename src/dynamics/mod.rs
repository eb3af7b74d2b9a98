//! Engine dynamics: the inertia of the reciprocating parts and the rod,
//! the crank effort through Ng's OM line, the turning-moment diagram over
//! a turn, the fluctuation of energy and the flywheel, the primary and
//! secondary unbalanced forces, and the balance of in-line, V and radial
//! engines and of a single cylinder in part.
//!
//! The textbook's §37 gives the piston acceleration (Klein's CG) and Ng's
//! paper the torque line (T = F · OM); what follows from them, the rod as
//! an equivalent dynamical system, the turning-moment diagram and the
//! flywheel, is standard engine dynamics beyond both
//! (`docs/dynamics.md` derives every formula).
//!
//! Sign conventions: the piston effort F and the gas force act along the
//! line of stroke, **positive towards the crank centre** (−x), the way the
//! gas pushes in a cylinder beyond the slider; F = −F_p of Ng's statics.
//! The crank effort T is the torque the piston and rod forces deliver to
//! the crank, counter-clockwise positive, so that T ω = −F v (v = dx_A/dt)
//! and T = F · OM. The crank turns at a constant speed ω. Gravity (a
//! vertical engine, [`Gravity`]) and the friction of the slider in its
//! guides ([`Engine::with_friction`]) are out unless given.
//!
//! ```
//! use slider_crank::{Angle, SliderCrank};
//! use slider_crank::dynamics::{Engine, GasForce};
//! let m = SliderCrank::in_line(0.5, 3.0)?;                  // §35's engine
//! let engine = Engine::new(m, 2.0, 26.18)?.with_gas(GasForce::Constant(1000.0))?;
//! let at = engine.at(Angle::deg(90.0))?;
//! // At 90° OM = r, so T = F r.
//! assert!((at.crank_effort - at.piston_effort * 0.5).abs() < 1e-9);
//! # Ok::<(), slider_crank::Error>(())
//! ```

mod balance;
mod engine;
mod flywheel;
mod gas;
mod gravity;
mod guide;
mod inline;
mod loads;
mod partial;
mod parts;
mod planes;
mod pose;
pub(crate) mod quadrature;
mod radial;
mod rod;
pub(crate) mod turning;

pub use balance::{Balance, unbalanced_forces};
pub use engine::{EXAMPLE_MASS, Engine};
pub use flywheel::{
    DEFAULT_FLUCTUATION, Flywheel, FlywheelAsk, MAX_COEFFICIENT, checked_coefficient,
};
pub use gas::{
    EXAMPLE_BORE, EXAMPLE_INDICATOR, GasForce, IndicatorDiagram, MAX_INDICATOR_ROWS,
    example_indicator,
};
pub use gravity::{Gravity, STANDARD_GRAVITY};
pub use guide::{AT_REST, check_friction, largest_tan_obliquity};
pub use inline::{
    BALANCE_TOLERANCE, DEFAULT_CRANKS, InlineEngine, MAX_INLINE_CYLINDERS, Polygon, Resultant,
    default_planes, offset_harmonic,
};
pub use loads::EngineLoads;
pub use partial::{DEFAULT_FRACTIONS, HammerBlow, PartialBalance, Unbalanced};
pub use parts::{EngineParts, IndicatorText};
pub use planes::{Revolving, two_plane_balance};
pub use pose::EnginePose;
pub use radial::{DEFAULT_AXES, MAX_RADIAL_CYLINDERS, RadialEngine};
pub use rod::{DynamicalSystem, RodInertia, RodMass};
pub use turning::{Lobe, MAX_CYLINDERS, RELATIVE_TOLERANCE, TurningMoment};

/// Uniform draws in [0, 1) from a xorshift generator started at `seed`
/// (not zero), for the unit tests' random engines: the same draws on
/// every run.
#[cfg(test)]
fn uniform_draws(mut seed: u64) -> impl FnMut() -> f64 {
    move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 11) as f64 / (1u64 << 53) as f64
    }
}
