//! Coupler points: points of the rod between A and B, which trace ovals.

use crate::error::{Error, Field, Result};
use crate::geom::{Point, Vector};
use crate::mechanism::Pose;

/// The point A + t (B − A) of the rod, t in [0, 1] (0 at the cross-head, 1
/// at the crank pin). t = 0 traces the line of stroke, t = 1 the crank
/// circle, and every point between an oval (textbook §34).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CouplerPoint {
    t: f64,
}

impl CouplerPoint {
    /// The coupler point at fraction `t` from A to B; an
    /// [`Error::OutOfRange`] unless 0 ≤ t ≤ 1 (NaN included).
    pub fn new(t: f64) -> Result<Self> {
        if (0.0..=1.0).contains(&t) {
            Ok(Self { t })
        } else {
            Err(Error::OutOfRange {
                name: Field::Coupler,
                value: t,
                reason: "the coupler point is a fraction of the rod from A (0) to B (1)".into(),
            })
        }
    }

    /// The fraction t.
    pub fn t(&self) -> f64 {
        self.t
    }

    /// Its position at `pose`.
    pub fn point(&self, pose: &Pose) -> Point {
        let (a, b) = (pose.a(), pose.b());
        a + (b - a) * self.t
    }

    /// Its exact derivative with respect to θ at `pose`.
    pub fn derivative(&self, pose: &Pose) -> Vector {
        let r = pose.mechanism().crank();
        let (s, c) = (pose.angle().sin(), pose.angle().cos());
        let xa = pose.position_rate();
        Vector::new(xa + self.t * (-r * s - xa), self.t * r * c)
    }

    /// Its exact second derivative with respect to θ at `pose` (its
    /// acceleration per ω² at constant ω): A″ + t (B″ − A″), with
    /// A″ = (d²s/dθ², 0) from the analytic core and B″ = −r (cos θ, sin θ).
    pub fn second_derivative(&self, pose: &Pose) -> Vector {
        let r = pose.mechanism().crank();
        let (s, c) = (pose.angle().sin(), pose.angle().cos());
        let xa = pose.position_acceleration();
        Vector::new(xa + self.t * (-r * c - xa), self.t * -r * s)
    }
}
