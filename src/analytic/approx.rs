//! The textbook's approximations (§35 eq. 2, 3; §37 eq. 2a) and their error
//! against the exact values.
//!
//! The approximations assume an in-line engine; for an offset mechanism the
//! reported error includes the offset's effect as well.

use crate::mechanism::Pose;

/// An approximate value beside the exact one it stands for.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Approximation {
    /// The value of the approximate formula.
    pub approx: f64,
    /// The exact value.
    pub exact: f64,
}

impl Approximation {
    /// approx − exact.
    pub fn error(&self) -> f64 {
        self.approx - self.exact
    }

    /// |approx − exact| / |exact|; infinite when the exact value is 0 and the
    /// approximation is not, 0 when both are 0.
    pub fn relative_error(&self) -> f64 {
        let e = self.error();
        if e == 0.0 {
            0.0
        } else {
            (e / self.exact).abs()
        }
    }
}

/// Eq. (2): piston velocity ≈ −V_c (sin θ + sin 2θ / 2n), V_c = rω, signed
/// as d x_A/dt (the book drops the minus sign).
pub fn velocity(pose: &Pose, omega: f64) -> Approximation {
    let m = pose.mechanism();
    let (s, c) = (pose.angle().sin(), pose.angle().cos());
    let vc = m.crank() * omega;
    let approx = -vc * (s + s * c / m.ratio());
    Approximation {
        approx,
        exact: omega * pose.position_rate(),
    }
}

/// Eq. (3): piston acceleration ≈ −(V_c²/r)(cos θ + cos 2θ / n), signed as
/// d² x_A/dt².
pub fn acceleration(pose: &Pose, omega: f64) -> Approximation {
    let m = pose.mechanism();
    let (s, c) = (pose.angle().sin(), pose.angle().cos());
    let cos2 = (c - s) * (c + s);
    let approx = -m.crank() * omega * omega * (c + cos2 / m.ratio());
    Approximation {
        approx,
        exact: omega * omega * pose.position_acceleration(),
    }
}

/// The factor cos θ + cos 2θ / n of eq. (3), the entry of the textbook's
/// table; `n = f64::INFINITY` gives cos θ (simple harmonic motion).
pub fn acceleration_factor(sin: f64, cos: f64, n: f64) -> f64 {
    let cos2 = (cos - sin) * (cos + sin);
    cos + cos2 / n
}

/// Eq. (2a): rod angular acceleration ≈ −ω² sin θ / √(n² − sin²θ)
/// (the exact eq. (2) has the further factor (n² − 1)/(n² − sin²θ)).
pub fn rod_angular_acceleration(pose: &Pose, omega: f64) -> Approximation {
    let n = pose.mechanism().ratio();
    let s = pose.angle().sin();
    let approx = -omega * omega * s / ((n - s) * (n + s)).sqrt();
    Approximation {
        approx,
        exact: omega * omega * pose.obliquity_acceleration(),
    }
}

/// The error due to obliquity, r(√(n² − sin²θ) − n), against simple
/// harmonic motion: `approx` is the SHM position r cos θ + l, `exact` the
/// slider position; the error is minus the obliquity term.
pub fn simple_harmonic_position(pose: &Pose) -> Approximation {
    let m = pose.mechanism();
    Approximation {
        approx: m.crank() * pose.angle().cos() + m.rod(),
        exact: pose.position(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{angle::Angle, mechanism::SliderCrank};

    #[test]
    fn approximations_are_exact_at_dead_centres_where_they_should_be() {
        let m = SliderCrank::in_line(1.0, 4.0).unwrap();
        let p = m.pose(Angle::deg(0.0));
        assert_eq!(velocity(&p, 1.0).error(), 0.0);
        assert_eq!(rod_angular_acceleration(&p, 1.0).error(), 0.0);
        // eq. 3 at θ = 0: −(1 + 1/n) exactly.
        assert!(acceleration(&p, 1.0).error().abs() < 1e-15);
    }

    #[test]
    fn relative_error_of_zero() {
        let a = Approximation {
            approx: 0.0,
            exact: 0.0,
        };
        assert_eq!(a.relative_error(), 0.0);
    }
}
