//! The primary and secondary unbalanced forces of the reciprocating
//! parts, against the exact inertia force.

use super::engine::Engine;
use crate::angle::Angle;

/// The unbalanced force of the reciprocating mass m along +x (on the
/// frame, through the crank shaft's bearing) at one crank angle.
///
/// x_A = r cos θ + l √(1 − (r sin θ − e)²/l²) expands, for e = 0, as
/// r cos θ + l − (r²/4l)(1 − cos 2θ) − O(r⁴/l³), so the inertia force −m a
/// is m r ω² (cos θ + cos 2θ / n) to within O(m r ω² / n³): the primary
/// force m r ω² cos θ and the secondary m r ω² cos 2θ / n. The series is
/// for an in-line engine; with an offset the exact force still stands
/// beside it.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Balance {
    /// The crank angle in degrees.
    pub angle_deg: f64,
    /// m r ω² cos θ.
    pub primary: f64,
    /// m r ω² cos 2θ / n.
    pub secondary: f64,
    /// −m a along +x, exact.
    pub exact: f64,
    /// exact − (primary + secondary): the higher harmonics.
    pub remainder: f64,
}

/// The forces of [`Balance`] for `engine` at `angle`.
pub fn unbalanced_forces(engine: &Engine, angle: Angle) -> Balance {
    let m = engine.mechanism();
    let scale = engine.reciprocating_mass() * m.crank() * engine.omega() * engine.omega();
    let c = angle.cos();
    let primary = scale * c;
    // cos 2θ = 2cos²θ − 1, exact where cos θ is (multiples of 90°).
    let secondary = scale * (2.0 * c * c - 1.0) / m.ratio();
    let exact = -engine.reciprocating_mass()
        * engine.omega()
        * engine.omega()
        * m.pose(angle).position_acceleration();
    Balance {
        angle_deg: angle.degrees(),
        primary,
        secondary,
        exact,
        remainder: exact - primary - secondary,
    }
}
