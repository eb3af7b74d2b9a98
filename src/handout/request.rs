//! The request of a handout as a front end gives it: every option of
//! `handout` that shapes the page, the same for the command line (its
//! flags) and the Python package (its keywords), made into the
//! [`Handout`] once here. Which pages are written and where (an exercise,
//! a class, the file) is the front end's.

use super::{DynamicsAsk, Handout, Paper};
use crate::analytic::kinematics::crank_speed;
use crate::angle::Angle;
use crate::error::{Error, Field, Input, Result, Wording};
use crate::files::{MAX_DATA_BYTES, read_text};
use crate::mechanism::SliderCrank;
use crate::sources::ENGINE_35;
use crate::units::{Unit, Units};
use std::path::PathBuf;

/// The crank angle a handout works when none is given, degrees.
pub const DEFAULT_HANDOUT_ANGLE: f64 = 45.0;

/// What a user asks of a handout; `None` leaves the handout's own value
/// (the §35 engine, in line, at 45° and 250 rpm, in feet and pounds, on
/// A4, no torque, no dynamics: [`crate::sources`]). Each field is the
/// option of its name on every front end ([`Field::key`]).
///
/// Fields may be added in later versions: start from
/// [`HandoutRequest::default`] and set the fields wanted.
#[derive(Debug, Clone, PartialEq, Default)]
#[non_exhaustive]
pub struct HandoutRequest {
    /// The crank radius r.
    pub crank: Option<f64>,
    /// The rod length l.
    pub rod: Option<f64>,
    /// The offset e of the line of stroke.
    pub offset: Option<f64>,
    /// The crank angle worked, degrees.
    pub angle: Option<f64>,
    /// The crank speed in revolutions per minute (not with `omega`).
    pub rpm: Option<f64>,
    /// The crank speed ω in rad/s (not with `rpm`).
    pub omega: Option<f64>,
    /// The name of the length unit.
    pub unit: Option<Unit>,
    /// The name of the force unit (following `unit` when only that is
    /// given, [`Units::asked`]).
    pub force_unit: Option<Unit>,
    /// A crank torque: adds the OM line and the forces.
    pub torque: Option<f64>,
    /// The slider's coefficient of friction (with `torque`; 0 when not
    /// given).
    pub friction: Option<f64>,
    /// The reciprocating mass: adds the dynamics ([`DynamicsAsk`]).
    pub mass: Option<f64>,
    /// The coefficient of fluctuation of speed of the dynamics' flywheel
    /// (with `mass`).
    pub fluctuation: Option<f64>,
    /// A constant gas force of the dynamics (with `mass`).
    pub gas_force: Option<f64>,
    /// The file of an indicator diagram of the dynamics (with `mass` and
    /// `bore`).
    pub indicator: Option<PathBuf>,
    /// The bore of the indicator diagram's cylinder.
    pub bore: Option<f64>,
    /// The paper the page is printed on (A4 when not given).
    pub paper: Option<Paper>,
}

impl HandoutRequest {
    /// Whether any length of the engine is given (a class then varies
    /// that engine rather than drawing its own, [`super::Class::around`]).
    pub fn engine_given(&self) -> bool {
        self.crank.is_some() || self.rod.is_some() || self.offset.is_some()
    }

    /// The handout this request asks for, its options checked (the
    /// indicator diagram read) in the order the page states them: the
    /// engine, the angle, the speed, the load, the dynamics.
    ///
    /// Errors: a mechanism, angle, speed or load the library refuses;
    /// `rpm` with `omega`, `friction` without `torque`; the indicator
    /// file unreadable or larger than [`MAX_DATA_BYTES`]; what
    /// [`Handout::with_dynamics_asked`] refuses.
    pub fn handout(&self) -> Result<Handout> {
        if self.friction.is_some() && self.torque.is_none() {
            return Err(Error::refused(
                Input::Options,
                Wording::default()
                    .option(Field::Friction)
                    .then(" applies with a torque: give ")
                    .option(Field::Torque)
                    .then(" too"),
            ));
        }
        let mechanism = SliderCrank::new(
            self.crank.unwrap_or(ENGINE_35.0),
            self.rod.unwrap_or(ENGINE_35.1),
            self.offset.unwrap_or(0.0),
        )?;
        let angle = Angle::from_degrees(self.angle.unwrap_or(DEFAULT_HANDOUT_ANGLE))?;
        let mut h = Handout::new(mechanism, angle);
        if let Some(omega) = crank_speed(self.rpm, self.omega)? {
            h = h.with_omega(omega)?;
        }
        let units = Units::FOOT_POUND.asked(self.unit.as_ref(), self.force_unit.as_ref());
        h = h
            .with_units(units)
            .with_paper(self.paper.unwrap_or_default());
        if let Some(torque) = self.torque {
            h = h.with_torque(torque, self.friction.unwrap_or(0.0))?;
        }
        let indicator = match &self.indicator {
            Some(path) => Some((
                read_text(path, MAX_DATA_BYTES, Input::Indicator)?,
                path.display().to_string(),
            )),
            None => None,
        };
        h.with_dynamics_asked(&DynamicsAsk {
            mass: self.mass,
            fluctuation: self.fluctuation,
            gas_force: self.gas_force,
            indicator,
            bore: self.bore,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_request_of_no_option_is_the_section_35_engine_at_45_degrees() {
        let h = HandoutRequest::default().handout().unwrap();
        let m = h.mechanism();
        assert_eq!((m.crank(), m.rod(), m.offset()), (0.5, 3.0, 0.0));
        assert_eq!(h.angle().degrees(), 45.0);
        // 250 rpm, the §35 engine's.
        assert!((h.rpm() - 250.0).abs() < 1e-9, "{}", h.rpm());
        assert_eq!(h.paper(), Paper::A4);
    }

    #[test]
    fn fields_are_refused_by_their_keys() {
        let r = HandoutRequest {
            friction: Some(0.1),
            ..Default::default()
        };
        let e = r.handout().unwrap_err().to_string();
        assert_eq!(e, "`friction` applies with a torque: give `torque` too");
        let r = HandoutRequest {
            rpm: Some(10.0),
            omega: Some(1.0),
            ..Default::default()
        };
        let e = r.handout().unwrap_err().to_string();
        assert!(e.contains("`rpm`") && e.contains("`omega`"), "{e}");
    }
}
