//! The OM torque line (Ng Fig. 1): slider force and side thrust from a crank
//! torque, read off the construction.

use super::VelocityLine;
use crate::analytic::statics;
use crate::angle::Angle;
use crate::error::Result;
use crate::geom::Point;
use crate::mechanism::Pose;

/// Ng's construction: PC (the rod) produced meets the vertical through O at
/// M (the textbook's E), and F_p · OM = T.
///
/// At a dead centre M = O, OM = 0, and no finite slider force balances a
/// torque: [`TorqueLine::slider_force`] is then `Ok(None)`. A force beyond
/// the largest f64 (a huge torque on a tiny mechanism, where OM is small
/// but not zero) is an error, never taken for a dead centre.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TorqueLine {
    m: Point,
    tan_phi: f64,
    angle: Angle,
    crank: f64,
}

impl TorqueLine {
    /// Builds the torque line from the velocity construction (M = E).
    pub fn construct(pose: &Pose, e: &VelocityLine) -> Self {
        let (a, b) = (pose.a(), pose.b());
        let rod = b - a;
        Self {
            m: e.e(),
            // Read off the rod, or per unit crank where its rise is below
            // the normal range (a tiny crank a hair from the stroke).
            tan_phi: if rod.y.abs() >= f64::MIN_POSITIVE {
                rod.y / -rod.x
            } else {
                pose.tan_obliquity()
            },
            angle: pose.angle(),
            crank: pose.mechanism().crank(),
        }
    }

    /// M (= E).
    pub fn m(&self) -> Point {
        self.m
    }

    /// Signed OM, positive above O.
    pub fn om(&self) -> f64 {
        self.m.y
    }

    /// tan φ, read off the rod (positive when the crank pin is above the
    /// line of stroke).
    pub fn tan_phi(&self) -> f64 {
        self.tan_phi
    }

    /// F_p = T / OM along +x (Ng eq. 2, 6). `Ok(None)` at a dead centre
    /// (OM = 0); an error when T is not finite or T / OM exceeds the
    /// largest f64, as [`crate::analytic::statics::slider_force`] (the
    /// same division, with OM read off the construction).
    pub fn slider_force(&self, torque: f64) -> Result<Option<f64>> {
        statics::force_over_arm(torque, self.arm(), self.angle)
    }

    /// F_s = T tan φ / OM, finite wherever the side thrust is, also when
    /// F_p alone is beyond the largest f64 (then |tan φ| < 1 for a finite
    /// F_s, and T tan φ is finite): `Ok(None)` at a dead centre; the error
    /// of [`TorqueLine::slider_force`] or [`TorqueLine::side_thrust`]
    /// when F_s too is beyond it.
    pub(crate) fn side_thrust_from_torque(&self, torque: f64) -> Result<Option<f64>> {
        match self.slider_force(torque) {
            Ok(Some(fp)) => self.side_thrust(fp).map(Some),
            Ok(None) => Ok(None),
            Err(e) => {
                let moment = torque * self.tan_phi;
                if !moment.is_finite() {
                    return Err(e);
                }
                statics::force_over_arm(moment, self.arm(), self.angle).map_err(|_| e)
            }
        }
    }

    fn arm(&self) -> statics::Arm {
        statics::Arm {
            om: self.m.y,
            crank: self.crank,
            per_crank: self.om_per_crank(),
        }
    }

    /// OM / r = sin θ + cos θ tan φ, tan φ read off the rod: zero only at a
    /// dead centre, also where OM itself is below the smallest f64 (a tiny
    /// crank a hair from a dead centre).
    pub fn om_per_crank(&self) -> f64 {
        statics::om_per_crank(self.angle, self.tan_phi)
    }

    /// Side thrust F_s = F_p tan φ (Ng eq. 7), tan φ read off the rod; an
    /// error when the product exceeds the largest f64, as
    /// [`crate::analytic::statics::side_thrust`].
    pub fn side_thrust(&self, slider_force: f64) -> Result<f64> {
        statics::thrust(slider_force, self.tan_phi, self.angle)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mechanism::SliderCrank;

    fn line(m: &SliderCrank, degrees: f64) -> (Pose, TorqueLine) {
        let pose = m.pose(Angle::deg(degrees));
        let tl = TorqueLine::construct(&pose, &VelocityLine::construct(&pose));
        (pose, tl)
    }

    #[test]
    fn dead_centre_is_none() {
        let m = SliderCrank::in_line(25.0, 72.0).unwrap();
        for d in [0.0, 180.0] {
            assert_eq!(line(&m, d).1.slider_force(1.0), Ok(None), "{d}");
        }
    }

    #[test]
    fn overflow_is_an_error_not_a_dead_centre() {
        // Issue 9 (6): T = 1e308 on r = 1e-100, l = 3e-100 at 45°: OM is
        // 8.8e-101, not zero, and T / OM is beyond the largest f64.
        let m = SliderCrank::in_line(1e-100, 3e-100).unwrap();
        let (pose, tl) = line(&m, 45.0);
        assert!(tl.om() > 8e-101);
        let err = tl.slider_force(1e308).unwrap_err();
        assert!(
            err.to_string().contains("exceeds the largest number"),
            "{err}"
        );
        // The same answer as the analytic core's, message and all.
        assert_eq!(Err(err), statics::slider_force(&pose, 1e308));
        // A torque that fits is a finite force.
        let f = tl.slider_force(1.0).unwrap().unwrap();
        assert!(f.is_finite() && (f * tl.om() - 1.0).abs() < 1e-15);
        assert!(tl.slider_force(f64::INFINITY).is_err());
        // OM below the smallest number, a hair from the dead centre: the
        // same error, not a dead centre.
        let (pose, tl) = line(&m, 1e-230);
        assert_eq!(tl.om(), 0.0);
        assert!(tl.om_per_crank() > 0.0);
        let err = tl.slider_force(1.0).unwrap_err();
        assert!(
            err.to_string().contains("below the smallest number"),
            "{err}"
        );
        assert!(statics::slider_force(&pose, 1.0).is_err());
    }

    #[test]
    fn side_thrust_overflow_is_an_error() {
        // One ulp from the limit of assembly at 90°: tan φ = 4.7e7, so a
        // force of 1e308 has a thrust beyond the largest f64.
        let m = SliderCrank::in_line(1.0, 1.0000000000000002).unwrap();
        let (pose, tl) = line(&m, 90.0);
        let f = tl.slider_force(1e308).unwrap().unwrap();
        assert!(f.is_finite());
        let err = tl.side_thrust(f).unwrap_err();
        assert!(err.to_string().contains("the side thrust"), "{err}");
        assert!(statics::side_thrust(&pose, f).is_err());
        assert!(tl.side_thrust(1.0).unwrap().is_finite());
    }
}
