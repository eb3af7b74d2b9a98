//! The OM torque line (Ng Fig. 1): slider force and side thrust from a crank
//! torque, read off the construction.

use super::VelocityLine;
use crate::geom::Point;
use crate::mechanism::Pose;

/// Ng's construction: PC (the rod) produced meets the vertical through O at
/// M (the textbook's E), and F_p · OM = T.
///
/// At a dead centre M = O, OM = 0, and no finite slider force balances a
/// torque: [`TorqueLine::slider_force`] is then `None`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TorqueLine {
    m: Point,
    tan_phi: f64,
}

impl TorqueLine {
    /// Builds the torque line from the velocity construction (M = E).
    pub fn construct(pose: &Pose, e: &VelocityLine) -> Self {
        let (a, b) = (pose.a(), pose.b());
        let rod = b - a;
        Self {
            m: e.e(),
            tan_phi: rod.y / -rod.x,
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

    /// F_p = T / OM along +x (Ng eq. 2, 6); `None` at a dead centre, and
    /// also when T / OM exceeds the largest f64 (a huge torque on a tiny
    /// mechanism): [`crate::analytic::statics::slider_force`] tells the two
    /// apart.
    pub fn slider_force(&self, torque: f64) -> Option<f64> {
        let f = torque / self.m.y;
        (self.m.y != 0.0 && f.is_finite()).then_some(f)
    }

    /// Side thrust F_s = F_p tan φ (Ng eq. 7), tan φ read off the rod.
    pub fn side_thrust(&self, slider_force: f64) -> f64 {
        slider_force * self.tan_phi
    }
}
