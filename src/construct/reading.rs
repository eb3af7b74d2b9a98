//! Everything read at one pose: the exact values of the analytic core, the
//! lengths of the constructions (CE, BD, CG, FG) and the values they give
//! when scaled, and Ng's statics for a crank torque. What `analyze` prints
//! and the handout works through, computed once.

use super::{InstantCentre, Kisch, VelocityLine};
use crate::analytic::statics::{self, Friction};
use crate::error::{Error, Field, Result};
use crate::geom::{Intersection, Point};
use crate::{analytic::kinematics::Kinematics, mechanism::Pose};

/// The values read off the constructions at a pose, scaled to time rates at
/// the crank speed ω (textbook §36–37): the piston velocity ω · CE, its
/// acceleration ω² · CG, the rod's angular velocity ω · CB / BD and
/// angular acceleration ω² · FG / l, each signed as the analytic core's
/// ([`Kinematics`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Graphical {
    /// Slider velocity d x_A/dt from CE.
    pub velocity: f64,
    /// Slider acceleration d² x_A/dt² from CG.
    pub acceleration: f64,
    /// Rod angular velocity dφ/dt from BD (0 when D is at infinity).
    pub rod_angular_velocity: f64,
    /// Rod angular acceleration d²φ/dt² from FG.
    pub rod_angular_acceleration: f64,
}

impl Graphical {
    /// The values read off the constructions at `pose` and crank speed
    /// `omega` (rad/s): the instantaneous centre D, the velocity line CE
    /// and Kisch's F and G, nothing else (a sweep's per-pose cost; the
    /// same values as [`Reading::new`]'s). Errors where a value exceeds
    /// the largest number (ω in too short a unit of time for the lengths).
    #[inline]
    pub fn new(pose: &Pose, omega: f64) -> Result<Self> {
        let d = InstantCentre::construct(pose);
        let e = VelocityLine::construct(pose);
        let kisch = Kisch::construct(pose, &e);
        Self::read(pose, omega, &d, &e, &kisch)
    }

    /// The values the constructions `d`, `e` and `kisch` of `pose` give at
    /// crank speed `omega`.
    #[inline]
    fn read(
        pose: &Pose,
        omega: f64,
        d: &InstantCentre,
        e: &VelocityLine,
        kisch: &Kisch,
    ) -> Result<Self> {
        let points = kisch.points();
        let graphical = Graphical {
            velocity: omega * e.velocity_ratio(),
            acceleration: omega * omega * points.acceleration_ratio(),
            rod_angular_velocity: omega * d.rod_angular_velocity_ratio(),
            rod_angular_acceleration: omega * omega * points.rod_angular_acceleration_ratio(),
        };
        let values = [
            graphical.velocity,
            graphical.acceleration,
            graphical.rod_angular_velocity,
            graphical.rod_angular_acceleration,
        ];
        if let Some(bad) = values.iter().find(|g| !g.is_finite()) {
            return Err(Error::OutOfRange {
                name: Field::Omega,
                value: omega,
                reason: format!(
                    "the values read off the construction at θ = {}° ({bad}) exceed the largest number: give ω per a longer unit of time or the lengths in a smaller unit",
                    pose.angle().degrees()
                ),
            });
        }
        Ok(graphical)
    }
}

/// Ng's statics at a pose for a crank torque (eq. 2, 6–8, 11).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Statics {
    /// The crank torque T.
    pub torque: f64,
    /// The signed moment arm OM (= CE).
    pub om: f64,
    /// The slider force F_p = T / OM; `None` at a dead centre (OM = 0).
    pub force: Option<f64>,
    /// The side thrust F_s = F_p tan φ.
    pub side_thrust: Option<f64>,
    /// The slider force with friction F_p′ = F_p (1 − μ |tan φ|), or self
    /// locking.
    pub with_friction: Option<Friction>,
    /// The transmission angle β in degrees: the interior angle at the
    /// crank pin.
    pub transmission_deg: f64,
    /// The coefficient of friction μ of the slider in its guides.
    pub mu: f64,
}

/// Everything read at one pose: points, exact values, the lengths of the
/// constructions and the values they give, and the statics when a torque
/// is given. Built by [`Reading::new`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Reading {
    /// The pose.
    pub pose: Pose,
    /// The crank speed ω in rad/s.
    pub omega: f64,
    /// D, the instantaneous centre of the rod (at infinity at θ = 90°,
    /// 270°).
    pub d: Intersection,
    /// E, where the rod produced meets the perpendicular to the stroke
    /// through C.
    pub e: Point,
    /// F of Kisch's (and Klein's) construction, on the rod.
    pub f: Point,
    /// G, on the line through C parallel to the stroke.
    pub g: Point,
    /// H of Kisch's construction (`None` only at the very limit of
    /// assembly).
    pub h: Option<Point>,
    /// The radius BE of Kisch's circle about B.
    pub be: f64,
    /// The signed length CE (E above C positive).
    pub ce: f64,
    /// The signed length CG along +x.
    pub cg: f64,
    /// The signed length FG.
    pub fg: f64,
    /// The exact values of the analytic core.
    pub exact: Kinematics,
    /// The values read off the constructions.
    pub graphical: Graphical,
    /// Ng's statics, when a torque was given.
    pub statics: Option<Statics>,
}

impl Reading {
    /// Reads `pose` at crank speed `omega` (rad/s); with a torque, also
    /// Ng's statics with the coefficient of friction `mu` (≥ 0).
    ///
    /// Errors: ω out of range, a torque that is not finite, μ negative or
    /// not finite, or a value beyond the largest number.
    pub fn new(pose: &Pose, omega: f64, torque: Option<f64>, mu: f64) -> Result<Self> {
        let exact = Kinematics::new(pose, omega)?;
        let d = InstantCentre::construct(pose);
        let e = VelocityLine::construct(pose);
        let kisch = Kisch::construct(pose, &e);
        let points = kisch.points();
        let graphical = Graphical::read(pose, omega, &d, &e, &kisch)?;
        let statics = match torque {
            None => None,
            Some(t) => Some(Self::statics(pose, t, mu)?),
        };
        Ok(Self {
            pose: *pose,
            omega,
            d: d.d(),
            e: e.e(),
            f: points.f(),
            g: points.g(),
            h: kisch.h(),
            be: kisch.be(),
            ce: e.ce(),
            cg: points.cg(),
            fg: points.fg(),
            exact,
            graphical,
            statics,
        })
    }

    fn statics(pose: &Pose, torque: f64, mu: f64) -> Result<Statics> {
        check_load(torque, mu)?;
        let force = statics::slider_force(pose, torque)?;
        let (side_thrust, with_friction) = match force {
            Some(f) => (
                Some(statics::side_thrust(pose, f)?),
                Some(statics::with_friction(pose, f, mu)?),
            ),
            None => (None, None),
        };
        Ok(Statics {
            torque,
            om: statics::om(pose),
            force,
            side_thrust,
            with_friction,
            transmission_deg: pose.transmission_angle().to_degrees(),
            mu,
        })
    }

    /// The length BD, `None` when D is at infinity.
    pub fn bd(&self) -> Option<f64> {
        self.d.point().map(|d| (d - self.pose.b()).norm())
    }

    /// The length BF of Kisch's construction (BA · BF = BE²).
    pub fn bf(&self) -> f64 {
        (self.f - self.pose.b()).norm()
    }
}

/// Checks a crank torque and a coefficient of friction once: an error for
/// a torque that is not finite or a coefficient that is negative or not
/// finite.
pub(crate) fn check_load(torque: f64, mu: f64) -> Result<()> {
    if !torque.is_finite() {
        return Err(Error::NotFinite {
            name: Field::Torque,
            value: torque,
        });
    }
    if !(mu >= 0.0 && mu.is_finite()) {
        return Err(Error::OutOfRange {
            name: Field::Friction,
            value: mu,
            reason: "the coefficient of friction must be a finite number ≥ 0".into(),
        });
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{angle::Angle, mechanism::SliderCrank};

    #[test]
    fn the_constructions_give_the_exact_values() {
        let m = SliderCrank::new(0.5, 1.6, 0.1).unwrap();
        let r = Reading::new(&m.pose(Angle::deg(40.0)), 26.0, Some(10.0), 0.2).unwrap();
        let close = |a: f64, b: f64| (a - b).abs() <= 1e-9 * b.abs().max(1.0);
        assert!(close(r.graphical.velocity, r.exact.velocity));
        assert!(close(r.graphical.acceleration, r.exact.acceleration));
        assert!(close(
            r.graphical.rod_angular_velocity,
            r.exact.rod_angular_velocity
        ));
        assert!(close(
            r.graphical.rod_angular_acceleration,
            r.exact.rod_angular_acceleration
        ));
        // Kisch: BA · BF = BE².
        assert!(close(m.rod() * r.bf(), r.be * r.be));
        let s = r.statics.unwrap();
        assert!(close(s.om, r.ce));
        assert!(close(s.force.unwrap() * s.om, 10.0));
    }

    #[test]
    fn d_at_infinity_has_no_bd_and_bad_input_is_refused() {
        let m = SliderCrank::in_line(0.5, 3.0).unwrap();
        let r = Reading::new(&m.pose(Angle::deg(90.0)), 1.0, None, 0.0).unwrap();
        assert_eq!(r.bd(), None);
        assert_eq!(r.graphical.rod_angular_velocity, 0.0);
        let pose = m.pose(Angle::deg(30.0));
        assert!(Reading::new(&pose, 1.0, Some(f64::NAN), 0.0).is_err());
        assert!(Reading::new(&pose, 1.0, Some(1.0), -0.5).is_err());
    }
}
