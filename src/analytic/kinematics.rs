//! Exact kinematics of the slider and the rod at constant crank speed.

use crate::error::{Result, finite};
use crate::mechanism::Pose;

/// Converts revolutions per minute to radians per second (exact π).
pub fn rpm_to_omega(rpm: f64) -> f64 {
    rpm * (2.0 * std::f64::consts::PI / 60.0)
}

/// Slider and rod motion at one pose for a constant crank speed ω (rad/s,
/// positive counter-clockwise).
///
/// Velocities and accelerations are signed in the world frame: the slider's
/// are d x_A/dt and d²x_A/dt²; the rod's are dφ/dt and d²φ/dt² (the seeds'
/// sign; the rod's counter-clockwise angular velocity is −dφ/dt). At the dead
/// centres the slider velocity is exactly zero for an in-line mechanism.
#[derive(Debug, Clone, Copy, PartialEq)]
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
    /// The exact kinematics of `pose` at crank speed `omega` (finite, any
    /// sign; 0 gives a mechanism at rest).
    pub fn new(pose: &Pose, omega: f64) -> Result<Self> {
        let omega = finite("omega", omega)?;
        Ok(Self {
            omega,
            position: pose.position(),
            velocity: omega * pose.position_rate(),
            acceleration: omega * omega * pose.position_acceleration(),
            rod_angle: pose.obliquity(),
            rod_angular_velocity: omega * pose.obliquity_rate(),
            rod_angular_acceleration: omega * omega * pose.obliquity_acceleration(),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Angle, SliderCrank};

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
            let a = Angle::from_degrees(d).unwrap();
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
        let p = m.pose(Angle::from_degrees(10.0).unwrap());
        assert!(Kinematics::new(&p, f64::NAN).is_err());
    }
}
