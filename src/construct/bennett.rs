//! Bennett's construction of the piston's acceleration.

use super::AccelerationPoints;
use crate::geom::{Point, Vector};
use crate::mechanism::Pose;

/// Bennett, for the in-line engine: with the crank at right angles to the
/// stroke, the perpendicular from C to the rod cuts off C₁L₁ = r²/l from
/// the crank pin; set off BL = r²/l on the rod from B towards A; from L a
/// line perpendicular to the rod meets the line of stroke at K; from K a
/// line perpendicular to the stroke meets the rod at F (his Q); from F a
/// line perpendicular to the rod meets the line of stroke at G (his N).
/// CFG is Klein's construction again: the piston's acceleration is
/// ω² · CG, from G towards C (docs/polygons.md).
///
/// Why: with u the unit vector from B to A, F = B + s u where
/// s cos²φ = BL − r sin θ · sin φ (K on the line of stroke, F straight
/// above it), which for BL = r²/l is r² cos²θ / l, so BF = BE²/BA,
/// Kisch's mean proportional. The lines always meet (the rod is never
/// perpendicular to the stroke). `None` for an offset engine, where the
/// fixed length C₁L₁ no longer gives Kisch's BF at every angle (the
/// construction is the in-line engine's).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bennett {
    l: Point,
    k: Point,
    points: AccelerationPoints,
}

impl Bennett {
    /// Constructs L, K, F and G; `None` when the line of stroke does not
    /// pass through the crank centre.
    pub fn construct(pose: &Pose) -> Option<Self> {
        let m = pose.mechanism();
        if m.offset() != 0.0 {
            return None;
        }
        let (r, rod) = (m.crank(), m.rod());
        let (a, b) = (pose.a(), pose.b());
        let u: Vector = (a - b) / rod;
        let l = b + u * (r * r / rod);
        // K on the line of stroke (y = 0) with (K − B) · u = BL.
        let k = Point::new(b.x + (r * r / rod + b.y * u.y) / u.x, 0.0);
        // F on the rod straight above (or below) K.
        let f = b + u * ((k.x - b.x) / u.x);
        Some(Self {
            l,
            k,
            points: AccelerationPoints::from_f(pose, f),
        })
    }

    /// L, on the rod at r²/l from the crank pin.
    pub fn l(&self) -> Point {
        self.l
    }

    /// K, on the line of stroke.
    pub fn k(&self) -> Point {
        self.k
    }

    /// F (his Q) and G (his N), and what they give.
    pub fn points(&self) -> &AccelerationPoints {
        &self.points
    }
}
