//! Exact kinematics of the slider and the rod at constant crank speed.

use crate::error::{Error, Field, Input, Result, Wording, finite};
use crate::mechanism::Pose;

/// Largest crank speed |ω| accepted, in rad/s (any unit of time: choose one
/// that brings the speed in range). With lengths up to
/// [`crate::mechanism::MAX_LENGTH`], ω² times a length stays far from overflow; what
/// is left near the limit of assembly [`Kinematics::new`] checks.
pub const MAX_OMEGA: f64 = 1e100;

/// Smallest non-zero crank speed |ω| accepted, in rad/s: one turn then
/// takes 2π/ω ≤ 6.3e100 time units, which a time axis can show.
pub const MIN_OMEGA: f64 = 1e-100;

/// Checks a crank speed: finite, and 0 or [`MIN_OMEGA`] ≤ |ω| ≤
/// [`MAX_OMEGA`].
#[inline]
pub fn check_omega(omega: f64) -> Result<f64> {
    let omega = finite(Field::Omega, omega)?;
    if omega.abs() > MAX_OMEGA {
        return Err(Error::OutOfRange {
            name: Field::Omega,
            value: omega,
            reason: format!(
                "a crank speed is at most {MAX_OMEGA:e} rad/s (give it per a shorter unit of time)"
            ),
        });
    }
    if omega != 0.0 && omega.abs() < MIN_OMEGA {
        return Err(Error::OutOfRange {
            name: Field::Omega,
            value: omega,
            reason: format!(
                "a crank speed is 0 or at least {MIN_OMEGA:e} rad/s (give it per a longer unit of time)"
            ),
        });
    }
    Ok(omega)
}

/// Converts revolutions per minute to radians per second (exact π).
pub fn rpm_to_omega(rpm: f64) -> f64 {
    rpm * (2.0 * std::f64::consts::PI / 60.0)
}

/// Largest |rpm| [`omega_from_rpm`] takes: the speed whose ω is
/// [`MAX_OMEGA`], rounded down to a round number.
pub const MAX_RPM: f64 = 9e100;

/// A crank speed given in revolutions per minute as ω in rad/s, checked as
/// every front end's rpm is: finite, |rpm| ≤ [`MAX_RPM`], and the ω it gives within
/// [`check_omega`]'s range (a tiny non-zero speed is refused, also where
/// its ω would underflow to 0).
pub fn omega_from_rpm(rpm: f64) -> Result<f64> {
    let rpm = finite(Field::Rpm, rpm)?;
    if rpm.abs() > MAX_RPM {
        return Err(Error::OutOfRange {
            name: Field::Rpm,
            value: rpm,
            reason: format!("a crank speed is at most {MAX_RPM:e} rpm"),
        });
    }
    let omega = rpm_to_omega(rpm);
    if rpm != 0.0 && omega == 0.0 {
        // A speed so small that ω underflows (5e-324 rpm) is as tiny as
        // one check_omega refuses, not a crank at rest.
        return Err(Error::OutOfRange {
            name: Field::Rpm,
            value: rpm,
            reason: format!(
                "a crank speed is 0 or at least {MIN_OMEGA:e} rad/s (give it per a longer unit of time)"
            ),
        });
    }
    check_omega(omega)
}

/// Slider and rod motion at one pose for a constant crank speed ω (rad/s,
/// positive counter-clockwise).
///
/// Velocities and accelerations are signed in the world frame: the slider's
/// are d x_A/dt and d²x_A/dt²; the rod's are dφ/dt and d²φ/dt² (the seeds'
/// sign; the rod's counter-clockwise angular velocity is −dφ/dt). At the dead
/// centres the slider velocity is exactly zero for an in-line mechanism.
///
/// It serialises (serde) as a map of its field names to numbers, in the
/// user's units and radians: the values as computed, which the analysis's
/// JSON ([`crate::table::ReadingJson`]) writes in its own schema (the rod angle there in degrees).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Kinematics {
    /// Crank speed ω in rad/s.
    pub omega: f64,
    /// Slider position x_A.
    pub position: f64,
    /// Slider velocity d x_A/dt.
    pub velocity: f64,
    /// Slider acceleration d² x_A/dt².
    pub acceleration: f64,
    /// Rod obliquity φ in radians.
    pub rod_angle: f64,
    /// dφ/dt in rad/s.
    pub rod_angular_velocity: f64,
    /// d²φ/dt² in rad/s².
    pub rod_angular_acceleration: f64,
}

impl Kinematics {
    /// The exact kinematics of `pose` at crank speed `omega` (any sign, at
    /// most [`MAX_OMEGA`]; 0 gives a mechanism at rest).
    ///
    /// Errors: ω not finite or beyond [`MAX_OMEGA`], or a velocity or
    /// acceleration beyond the largest f64 (a huge crank near the limit of
    /// assembly, l → r + |e|, spun fast): every field returned is finite.
    #[inline]
    pub fn new(pose: &Pose, omega: f64) -> Result<Self> {
        let omega = check_omega(omega)?;
        let k = Self {
            omega,
            position: pose.position(),
            velocity: omega * pose.position_rate(),
            acceleration: omega * omega * pose.position_acceleration(),
            rod_angle: pose.obliquity(),
            rod_angular_velocity: omega * pose.obliquity_rate(),
            rod_angular_acceleration: omega * omega * pose.obliquity_acceleration(),
        };
        let values = [
            k.velocity,
            k.acceleration,
            k.rod_angular_velocity,
            k.rod_angular_acceleration,
        ];
        if values.iter().all(|v| v.is_finite()) {
            Ok(k)
        } else {
            Err(Error::OutOfRange {
                name: Field::Omega,
                value: omega,
                reason: format!(
                    "the accelerations at θ = {}° exceed the largest number (about 1.8e308): give ω per a longer unit of time or the lengths in a smaller unit",
                    pose.angle().degrees()
                ),
            })
        }
    }
}

/// ω in rad/s from a speed given in rpm or as ω (`None`: neither given,
/// the figure's own), each checked as everywhere ([`omega_from_rpm`],
/// [`check_omega`]); both given are refused.
pub fn crank_speed(rpm: Option<f64>, omega: Option<f64>) -> Result<Option<f64>> {
    match (rpm, omega) {
        (Some(_), Some(_)) => Err(Error::refused(
            Input::Options,
            Wording::from("give the crank speed as ")
                .option(Field::Rpm)
                .then(" or as ")
                .option(Field::Omega)
                .then(", not both"),
        )),
        (_, Some(w)) => check_omega(w).map(Some),
        (Some(n), None) => omega_from_rpm(n).map(Some),
        (None, None) => Ok(None),
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn serialises_with_its_field_names() {
        let m = crate::mechanism::SliderCrank::in_line(0.5, 3.0).unwrap();
        let k = super::Kinematics::new(&m.pose(crate::angle::Angle::deg(45.0)), 26.16).unwrap();
        let json: serde_json::Value = serde_json::to_value(k).unwrap();
        assert_eq!(json["velocity"].as_f64(), Some(k.velocity));
        assert_eq!(json["rod_angle"].as_f64(), Some(k.rod_angle));
        assert_eq!(json.as_object().unwrap().len(), 7);
        let text = serde_json::to_string(&k).unwrap();
        let back: serde_json::Value = serde_json::from_str(&text).unwrap();
        assert_eq!(back["omega"].as_f64(), Some(26.16));
    }

    use super::*;
    use crate::{angle::Angle, mechanism::SliderCrank};

    #[test]
    fn a_speed_is_given_one_way_and_checked() {
        // 60 rpm is one turn a second, 2π rad/s.
        assert_eq!(
            crank_speed(Some(60.0), None).unwrap(),
            Some(std::f64::consts::TAU)
        );
        assert_eq!(crank_speed(None, Some(3.0)).unwrap(), Some(3.0));
        assert_eq!(crank_speed(None, None).unwrap(), None);
        let e = crank_speed(Some(1.0), Some(1.0)).unwrap_err();
        assert_eq!(
            e.to_string(),
            "give the crank speed as `rpm` or as `omega`, not both"
        );
        assert!(crank_speed(Some(f64::NAN), None).is_err());
    }

    #[test]
    fn rpm_conversion() {
        assert!((rpm_to_omega(60.0) - 2.0 * std::f64::consts::PI).abs() < 1e-15);
    }

    #[test]
    fn textbook_closed_forms_for_in_line_engine() {
        // §35 and §37 in closed form, n = 6.
        let (r, n, omega) = (0.5, 6.0, 26.16);
        let m = SliderCrank::in_line(r, n * r).unwrap();
        for d in [0.0, 10.0, 45.0, 90.0, 135.0, 200.0, 300.0] {
            let a = Angle::deg(d);
            let k = Kinematics::new(&m.pose(a), omega).unwrap();
            let (s, c) = (a.sin(), a.cos());
            let q = (n * n - s * s).sqrt();
            let v = -r * omega * (s + 2.0 * s * c / (2.0 * q));
            let rate = omega * c / q;
            let acc = -omega * omega * s / q * (n * n - 1.0) / (n * n - s * s);
            assert!((k.velocity - v).abs() <= 1e-13 * r * omega, "{d}");
            assert!(
                (k.rod_angular_velocity - rate).abs() <= 1e-14 * omega,
                "{d}"
            );
            assert!(
                (k.rod_angular_acceleration - acc).abs() <= 1e-13 * omega * omega,
                "{d}"
            );
        }
    }

    #[test]
    fn omega_must_be_finite() {
        let m = SliderCrank::in_line(1.0, 3.0).unwrap();
        let p = m.pose(Angle::deg(10.0));
        assert!(Kinematics::new(&p, f64::NAN).is_err());
    }

    #[test]
    fn tiny_speeds_are_refused_but_rest_is_not() {
        assert!(check_omega(1e-300).is_err());
        assert_eq!(check_omega(0.0), Ok(0.0));
        assert_eq!(check_omega(-1e-100), Ok(-1e-100));
    }

    #[test]
    fn a_speed_whose_omega_underflows_is_refused_as_tiny() {
        // 5e-324 rpm × 2π/60 rounds to ω = 0: refused as 1e-300 rpm is,
        // never taken for a crank at rest.
        for rpm in [5e-324, -5e-324, 1e-300] {
            let e = omega_from_rpm(rpm).unwrap_err().to_string();
            assert!(
                e.contains("is out of range: a crank speed is 0 or at least"),
                "{e}"
            );
        }
        assert_eq!(omega_from_rpm(0.0).unwrap(), 0.0);
        assert_eq!(omega_from_rpm(-0.0).unwrap(), 0.0);
    }

    #[test]
    fn huge_speeds_are_errors_not_infinities() {
        // Issue 9 (5): ω = 1e200 gave ±inf and NaN.
        let m = SliderCrank::in_line(1.0, 3.0).unwrap();
        let p = m.pose(Angle::deg(0.0));
        let err = Kinematics::new(&p, 1e200).unwrap_err();
        assert!(
            err.to_string().starts_with("omega = 1e200 is out of range"),
            "{err}"
        );
        // Within MAX_OMEGA but overflowing near the limit of assembly.
        let m = SliderCrank::in_line(1e99, 1e99 * (1.0 + 4.0 * f64::EPSILON)).unwrap();
        let p = m.pose(Angle::deg(1e-9));
        match Kinematics::new(&p, 1e100) {
            Ok(k) => assert!(k.acceleration.is_finite() && k.velocity.is_finite()),
            Err(e) => assert!(e.to_string().contains("exceed the largest number"), "{e}"),
        }
        let k = Kinematics::new(&m.pose(Angle::deg(0.0)), 1e100).unwrap();
        assert!(k.acceleration.is_finite());
    }
}
