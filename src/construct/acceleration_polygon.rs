//! The acceleration polygon of the relative-velocity method: o′, b′, the
//! rod's normal and tangential components, a′ and the image q′ of a point
//! of the rod.

use super::{CouplerPoint, VelocityPolygon};
use crate::geom::{Vector, cross, perp};
use crate::mechanism::Pose;

/// The acceleration polygon (acceleration diagram) of the slider-crank at
/// constant crank speed, drawn from a pole o′: o′b′ the crank pin's
/// centripetal acceleration ω²r, from B towards C; from b′ the rod's normal
/// component v_AB²/AB, parallel to AB from A towards B, to x; from x a line
/// perpendicular to AB (the tangential component α · AB, of unknown
/// length); from o′ a line parallel to the stroke; they meet at a′. The
/// image q′ of a point Q of the rod divides a′b′ as Q divides AB (the
/// acceleration image), and the rod's angular acceleration is the
/// tangential component xa′ over AB.
///
/// The vectors are accelerations per ω², lengths (o′b′ = CB: the polygon is
/// drawn to the scale in which CB represents ω²r); multiply by ω² for the
/// time rates. a′ always exists (the rod is never vertical). At θ = 90°
/// (e = 0) the normal component vanishes (the rod translates) and x = b′;
/// at the dead centres the tangential component vanishes and a′ = x.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AccelerationPolygon {
    b: Vector,
    x: Vector,
    a: Vector,
    q: Option<Vector>,
    /// B − A on the mechanism.
    rod: Vector,
}

impl AccelerationPolygon {
    /// Draws the polygon of `pose` from its velocity polygon (which gives
    /// the normal component), with the image of `coupler` if given.
    #[inline]
    pub fn construct(
        pose: &Pose,
        velocity: &VelocityPolygon,
        coupler: Option<CouplerPoint>,
    ) -> Self {
        let crank = pose.b() - pose.c();
        let rod = velocity.rod();
        // o′b′: towards C, of length r (ω²r at the scale ω²).
        let b = -crank;
        // b′x: |ab|² / AB along AB from A towards B.
        let x = b + rod * (velocity.ab().norm_squared() / rod.norm_squared());
        // From x along the perpendicular to AB to the level of o′.
        let across = perp(&rod);
        let t = -x.y / across.y;
        let a = Vector::new(x.x + t * across.x, 0.0);
        let q = coupler.map(|p| p.image(a, b));
        Self { b, x, a, q, rod }
    }

    /// o′b′, the crank pin's acceleration per ω² (−CB: centripetal).
    pub fn b(&self) -> Vector {
        self.b
    }

    /// x, the end of the rod's normal component b′x (parallel to AB).
    pub fn x(&self) -> Vector {
        self.x
    }

    /// o′a′, the slider's acceleration per ω², along the stroke.
    pub fn a(&self) -> Vector {
        self.a
    }

    /// o′q′, the coupler point's acceleration per ω², when one was given.
    pub fn q(&self) -> Option<Vector> {
        self.q
    }

    /// d²s/dθ² read off the polygon: the signed length o′a′ along +x (the
    /// slider's acceleration per ω²).
    #[inline]
    pub fn slider_acceleration_ratio(&self) -> f64 {
        self.a.x
    }

    /// The tangential component xa′ (perpendicular to AB), per ω².
    pub fn tangential(&self) -> Vector {
        self.a - self.x
    }

    /// d²φ/dθ² read off the polygon: the tangential component xa′ over AB,
    /// signed as the seeds' φ. xa′ = α (A − B) turned a quarter turn, α
    /// the rod's counter-clockwise angular acceleration per ω², and
    /// d²φ/dθ² = −α.
    #[inline]
    pub fn rod_angular_acceleration_ratio(&self) -> f64 {
        cross(&self.rod, &self.tangential()) / self.rod.norm_squared()
    }
}
