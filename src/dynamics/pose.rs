//! The forces and the crank effort of an engine at one pose.

use super::engine::Engine;
use super::guide::motion;
use super::loads::{EngineLoads, Slider};
use super::rod::{RodInertia, cg_rate};
use crate::angle::Angle;
use crate::construct::{InstantCentre, Kisch, Klein, TorqueLine, VelocityLine};
use crate::error::{Error, Field, Result};
use crate::mechanism::Pose;

/// Everything the dynamics gives at one pose. Forces along the line of
/// stroke are positive towards the crank centre; torques on the crank are
/// counter-clockwise positive (see [`crate::dynamics`]).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct EnginePose {
    /// The crank angle θ in degrees.
    pub angle_deg: f64,
    /// The gas force on the piston.
    pub gas_force: f64,
    /// The inertia force of the reciprocating parts, exact: m a towards the
    /// crank (−m a along +x, a = d²x_A/dt²).
    pub inertia_force: f64,
    /// The same from Klein's construction, a = −ω² CG (Kisch's where D is
    /// at infinity, θ = 90° and 270° in line).
    pub inertia_force_graphical: f64,
    /// The weight of the reciprocating parts along the line of stroke,
    /// towards the crank, −m g_x (m g in a vertical engine with its
    /// cylinder above the crank); `None` without gravity.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub weight: Option<f64>,
    /// The guides' friction on the reciprocating parts towards the crank,
    /// μ |N| against the slider's motion with N the guides' reaction of a
    /// massless rod (with the rod's inertia: `loads`); 0 at a dead
    /// centre; `None` for a frictionless engine.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub friction: Option<f64>,
    /// The piston effort F = gas force + inertia force of the
    /// reciprocating parts (+ their weight + the guides' friction, where
    /// given; the rod's inertia is in `rod`, and the equivalent system's
    /// effort with the rod's mass at the cross-head in `loads`).
    pub piston_effort: f64,
    /// The force along the rod, F / cos φ (compression positive), of the
    /// reciprocating parts alone (with the rod's inertia: `loads`).
    pub rod_force: f64,
    /// The thrust of the slider on its guides along +y, −F tan φ (Ng's
    /// F_s = F_p tan φ with F_p = −F; + m g_y with gravity across the
    /// stroke), of the reciprocating parts alone (with the rod's inertia:
    /// `loads`).
    pub guide_thrust: f64,
    /// OM (= CE) read off Ng's torque line.
    pub om: f64,
    /// The crank effort of the piston effort, F · OM, OM from the
    /// construction.
    pub crank_effort: f64,
    /// The same by the exact formula F r sin(θ + φ) / cos φ.
    pub crank_effort_exact: f64,
    /// The rod's inertia, `None` for a massless rod.
    pub rod: Option<RodInertia>,
    /// The whole torque on the crank: the gas and reciprocating parts'
    /// crank effort (their weight and the guides' friction with the rod's
    /// inertia in the guides' reaction, where given), the rod's exact
    /// inertia torque and its weight's torque m_r g · G′.
    pub torque: f64,
    /// The forces of the whole engine with the rod's inertia (pin and
    /// bearing loads, guide thrust, force along the rod, shaking force):
    /// those above are of the reciprocating parts alone.
    pub loads: EngineLoads,
}

impl Engine {
    /// The forces and torques at the crank angle `angle`, in the first
    /// turn of the gas force's cycle as [`Engine::turn_at_degrees`] counts
    /// it: for a four-stroke diagram expansion and exhaust, and, where an
    /// offset puts the outer dead centre past 0°, the end of compression
    /// before it.
    ///
    /// Errors: a force beyond the largest number (very large masses or
    /// pressures near the limit of assembly).
    pub fn at(&self, angle: Angle) -> Result<EnginePose> {
        self.at_turn(angle, self.turn_at_degrees(angle.degrees()))
    }

    /// [`Engine::at`] in turn `turn` of the gas force's cycle (1: the
    /// intake and compression of a four-stroke cycle; for a one-turn
    /// cycle every turn is the same).
    ///
    /// Errors: as [`Engine::at`].
    pub fn at_turn(&self, angle: Angle, turn: usize) -> Result<EnginePose> {
        let pose = self.mechanism().pose(angle);
        let omega = self.omega();
        let w2 = omega * omega;
        let gas = self.gas().at_turn(&pose, omega, turn);
        let m = self.reciprocating_mass();
        let inertia_force = m * w2 * pose.position_acceleration();
        let inertia_force_graphical = -m * w2 * graphical_cg(&pose);
        let rod = self.rod().map(|r| RodInertia::new(&pose, r, omega));
        let weight = -m * self.gravity()[0];
        let slider = self.slider(&pose, gas + inertia_force + weight);
        let (piston_effort, reaction) = slider.alone(&pose);
        let cos_phi = pose.run() / pose.mechanism().rod();
        let line = TorqueLine::construct(&pose, &VelocityLine::construct(&pose));
        let om = line.om();
        let arm = exact_arm(&pose);
        let crank_effort_exact = piston_effort * arm;
        let (loads, whole) = EngineLoads::new(&pose, &slider, self.rod().zip(rod.as_ref()));
        let rod_torque = rod.map_or(0.0, |r| r.torque) + self.rod_weight_torque(&pose);
        let at = EnginePose {
            angle_deg: angle.degrees(),
            gas_force: gas,
            inertia_force,
            inertia_force_graphical,
            weight: (self.gravity() != [0.0, 0.0]).then_some(weight),
            friction: (self.friction() > 0.0).then_some(piston_effort - slider.effort),
            piston_effort,
            rod_force: piston_effort / cos_phi,
            guide_thrust: -reaction,
            om,
            crank_effort: piston_effort * om,
            crank_effort_exact,
            torque: whole * arm + rod_torque,
            rod,
            loads,
        };
        at.check(angle)
    }

    /// The slider's part in the balances at `pose` for the piston effort
    /// without friction `effort` (gas, inertia and weight).
    fn slider(&self, pose: &Pose, effort: f64) -> Slider {
        let omega = self.omega();
        let g = self.gravity();
        let mass_at_crosshead = self
            .rod()
            .map_or(0.0, |r| r.mass() * r.cg() / pose.mechanism().rod());
        let a = omega * omega * pose.position_acceleration();
        Slider {
            omega,
            mass: self.reciprocating_mass(),
            effort,
            gravity: g,
            friction: self.friction(),
            motion: motion(pose, omega),
            equivalent: mass_at_crosshead * (a - g[0]),
        }
    }

    /// The torque of the rod's weight on the crank, m_r g · G′ (virtual
    /// work: the weight's power m_r g · v_G over ω); 0 without gravity or
    /// a rod.
    fn rod_weight_torque(&self, pose: &Pose) -> f64 {
        let g = self.gravity();
        self.rod().map_or(0.0, |r| {
            let rate = cg_rate(pose, r.cg() / pose.mechanism().rod());
            r.mass() * (g[0] * rate[0] + g[1] * rate[1])
        })
    }
}

impl EnginePose {
    fn check(self, angle: Angle) -> Result<Self> {
        let values = [
            self.inertia_force,
            self.inertia_force_graphical,
            self.piston_effort,
            self.weight.unwrap_or(0.0),
            self.friction.unwrap_or(0.0),
            self.rod_force,
            self.guide_thrust,
            self.crank_effort,
            self.torque,
        ];
        if values
            .iter()
            .chain(&self.loads.values())
            .all(|v| v.is_finite())
        {
            Ok(self)
        } else {
            Err(Error::OutOfRange {
                name: Field::Angle,
                value: angle.degrees(),
                reason: "a force or torque of the engine here exceeds the largest number (about 1.8e308): give the masses or pressures in larger units".into(),
            })
        }
    }
}

/// r sin(θ + φ) / cos φ, the exact moment arm of the piston effort, from
/// θ and φ alone (not from the construction's E).
fn exact_arm(pose: &Pose) -> f64 {
    let phi = pose.obliquity();
    let r = pose.mechanism().crank();
    r * (pose.angle().radians() + phi).sin() / phi.cos()
}

/// CG of Klein's construction, or of Kisch's where D is at infinity.
fn graphical_cg(pose: &Pose) -> f64 {
    let e = VelocityLine::construct(pose);
    match Klein::construct(pose, &InstantCentre::construct(pose), &e) {
        Some(k) => k.points().cg(),
        None => Kisch::construct(pose, &e).points().cg(),
    }
}

impl Engine {
    /// The whole torque on the crank at `pose` by the exact formulas alone
    /// (no construction, no check): what the turning-moment diagram
    /// integrates. Equal to [`EnginePose::torque`].
    pub fn torque(&self, pose: &Pose) -> f64 {
        self.torque_in_turn(pose, self.turn_at_degrees(pose.angle().degrees()))
    }

    /// [`Engine::torque`] in turn `turn` of the gas force's cycle (the
    /// second turn of a four-stroke cycle: intake and compression).
    pub fn torque_in_turn(&self, pose: &Pose, turn: usize) -> f64 {
        let omega = self.omega();
        let m = self.reciprocating_mass();
        let effort = self.gas().at_turn(pose, omega, turn)
            + m * omega * omega * pose.position_acceleration()
            - m * self.gravity()[0];
        let rod = self.rod().map(|r| RodInertia::new(pose, r, omega));
        let effort = if self.friction() > 0.0 {
            let slider = self.slider(pose, effort);
            EngineLoads::new(pose, &slider, self.rod().zip(rod.as_ref())).1
        } else {
            effort
        };
        effort * exact_arm(pose) + rod.map_or(0.0, |r| r.torque) + self.rod_weight_torque(pose)
    }
}
