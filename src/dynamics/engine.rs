//! An engine: a slider-crank with its masses, its gas force and its crank
//! speed, each checked once where it is given.

use super::gas::GasForce;
use super::rod::RodMass;
use crate::analytic::kinematics::check_omega;
use crate::error::{Error, Field, Result, non_negative};
use crate::mechanism::SliderCrank;
use std::f64::consts::TAU;

/// A slider-crank engine: the mechanism, the reciprocating mass m (piston
/// and cross-head), the rod's mass if it has one, the gas force on the
/// piston and the constant crank speed ω (rad/s).
///
/// Masses are in the unit that makes mass × length / s² the force unit
/// (kg with m and N, slug with ft and lbf, t with mm and N). A massless
/// engine with no gas force is allowed: every force is then zero.
#[derive(Debug, Clone, PartialEq)]
pub struct Engine {
    mechanism: SliderCrank,
    reciprocating: f64,
    rod: Option<RodMass>,
    gas: GasForce,
    omega: f64,
    gravity: [f64; 2],
    friction: f64,
}

impl Engine {
    /// An engine with reciprocating mass `reciprocating` (≥ 0) at crank
    /// speed `omega` (rad/s, as [`crate::analytic::kinematics::Kinematics::new`] takes it), a
    /// massless rod and no gas force.
    ///
    /// Errors: a mass that is negative or not finite, a speed out of
    /// range ([`crate::analytic::kinematics::check_omega`]), or m ω² r
    /// beyond the largest number.
    pub fn new(mechanism: SliderCrank, reciprocating: f64, omega: f64) -> Result<Self> {
        let reciprocating = non_negative(Field::Mass, reciprocating)?;
        let omega = check_omega(omega)?;
        let engine = Self {
            mechanism,
            reciprocating,
            rod: None,
            gas: GasForce::None,
            omega,
            gravity: [0.0, 0.0],
            friction: 0.0,
        };
        engine.check_scale(reciprocating)?;
        Ok(engine)
    }

    /// The same engine with a rod of mass (see [`RodMass`]).
    ///
    /// Errors: the rod's centre of mass beyond its length (BG > l), or its
    /// inertia forces beyond the largest number.
    pub fn with_rod(mut self, rod: RodMass) -> Result<Self> {
        let l = self.mechanism.rod();
        if rod.cg() > l {
            return Err(Error::OutOfRange {
                name: Field::RodCg,
                value: rod.cg(),
                reason: format!(
                    "the rod's centre of mass lies on the rod, 0 ≤ BG ≤ l = {}",
                    crate::number::plain(l)
                ),
            });
        }
        let scale = rod.mass() * (1.0 + rod.gyration() * rod.gyration() / (l * l));
        self.check_scale(scale)?;
        self.rod = Some(rod);
        Ok(self)
    }

    /// The same engine with the gas force `gas` on the piston.
    ///
    /// Errors: a constant force that is not finite (an indicator diagram
    /// was checked when it was read).
    pub fn with_gas(mut self, gas: GasForce) -> Result<Self> {
        if let GasForce::Constant(f) = gas {
            crate::error::finite(Field::GasForce, f)?;
        }
        self.gas = gas;
        Ok(self)
    }

    /// The same engine with gravity's acceleration `g` (x along the line
    /// of stroke from the crank centre, y across it; length units per s²,
    /// [`super::Gravity::in_unit`] for a vertical engine): the weights
    /// m g of the reciprocating parts at the cross-head and m_r g of the
    /// rod at G enter every force and the torque. [0, 0] (the default)
    /// leaves gravity out.
    ///
    /// Errors: a component not finite.
    pub fn with_gravity(mut self, g: [f64; 2]) -> Result<Self> {
        for c in g {
            crate::error::finite(Field::Gravity, c)?;
        }
        self.gravity = g;
        Ok(self)
    }

    /// The same engine with the coefficient of friction μ of the slider
    /// in its guides: a force μ |N| against the slider's motion, N the
    /// guides' reaction (0 at a dead centre, [`super::AT_REST`]). 0 (the
    /// default) is frictionless.
    ///
    /// Errors: μ negative or not finite, or so large that the slider
    /// self-locks somewhere in the turn ([`super::check_friction`]).
    pub fn with_friction(mut self, mu: f64) -> Result<Self> {
        self.friction = super::guide::check_friction(&self.mechanism, mu)?;
        Ok(self)
    }

    /// Checks that a mass `scale` times ω² times the largest length of the
    /// mechanism times the largest acceleration factor stays finite, so
    /// that no force or torque computed later overflows.
    fn check_scale(&self, mass: f64) -> Result<()> {
        let m = &self.mechanism;
        let length = m.crank() + m.rod() + m.offset().abs();
        // The acceleration factor grows like 1/(1 − (r + |e|)/l)^1.5 near
        // the limit of assembly; 1e6 covers every rod with l > 1.0001 (r + |e|).
        let bound = mass * self.omega * self.omega * length * length * 1e6;
        if bound.is_finite() {
            Ok(())
        } else {
            Err(Error::OutOfRange {
                name: Field::Mass,
                value: mass,
                reason: "the inertia forces m ω² r would exceed the largest number: give the mass, the lengths or ω in larger or smaller units".into(),
            })
        }
    }

    /// The mechanism.
    pub fn mechanism(&self) -> &SliderCrank {
        &self.mechanism
    }

    /// The reciprocating mass m.
    pub fn reciprocating_mass(&self) -> f64 {
        self.reciprocating
    }

    /// The rod's mass, `None` for a massless rod.
    pub fn rod(&self) -> Option<&RodMass> {
        self.rod.as_ref()
    }

    /// The gas force.
    pub fn gas(&self) -> &GasForce {
        &self.gas
    }

    /// The crank speed ω in rad/s.
    pub fn omega(&self) -> f64 {
        self.omega
    }

    /// Gravity's acceleration (x along the line of stroke, y across it),
    /// [0, 0] without gravity.
    pub fn gravity(&self) -> [f64; 2] {
        self.gravity
    }

    /// The slider's coefficient of friction in its guides, 0 without.
    pub fn friction(&self) -> f64 {
        self.friction
    }

    /// The turn of the gas force's cycle (0 or 1 for a four-stroke
    /// diagram; always 0 for a one-turn cycle) that the crank angle
    /// `degrees` falls in. Turns are counted from the outer dead centre,
    /// where expansion begins, not from θ = 0: with an offset the outer
    /// dead centre is at asin(e/(l + r)), and between it and 0° the piston
    /// is still on the stroke that ends there (the previous turn's).
    pub fn turn_at_degrees(&self, degrees: f64) -> usize {
        let odc = self.mechanism.dead_centres().0.to_degrees();
        turn_from(degrees - odc, 360.0, self.gas.turns())
    }

    /// [`Engine::turn_at_degrees`] of an angle in radians.
    pub fn turn_at_radians(&self, radians: f64) -> usize {
        let odc = self.mechanism.dead_centres().0;
        turn_from(radians - odc, TAU, self.gas.turns())
    }
}

/// The whole turns in `since` (an angle past the outer dead centre, in a
/// unit of which a turn is `turn`) modulo `turns`.
fn turn_from(since: f64, turn: f64, turns: usize) -> usize {
    since.div_euclid(turn).rem_euclid(turns as f64) as usize
}

/// The reciprocating mass of the example engine, in slug (about 322 lbf
/// of piston and cross-head): an illustration, the textbook gives none.
pub const EXAMPLE_MASS: f64 = 10.0;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bad_inputs_are_refused_with_their_names() {
        let m = SliderCrank::in_line(0.5, 3.0).unwrap();
        let e = Engine::new(m, -1.0, 10.0).unwrap_err();
        assert_eq!(e.to_string(), "mass must not be negative, got -1");
        assert!(Engine::new(m, f64::NAN, 10.0).is_err());
        assert!(Engine::new(m, 1.0, f64::INFINITY).is_err());
        assert!(Engine::new(m, 1e300, 1e10).is_err());
        let engine = Engine::new(m, 1.0, 10.0).unwrap();
        let rod = RodMass::new(1.0, 3.5, 1.0).unwrap();
        let e = engine.clone().with_rod(rod).unwrap_err();
        assert!(
            e.to_string().starts_with("rod-cg = 3.5 is out of range"),
            "{e}"
        );
        assert!(engine.with_gas(GasForce::Constant(f64::NAN)).is_err());
    }
}
