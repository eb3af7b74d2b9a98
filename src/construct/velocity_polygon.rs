//! The velocity polygon of the relative-velocity method: o, b, a and the
//! image q of a point of the rod.

use super::CouplerPoint;
use crate::geom::{Vector, cross, perp};
use crate::mechanism::Pose;

/// The velocity polygon (velocity diagram) of the slider-crank, drawn from
/// a pole o: ob the crank pin's velocity, perpendicular to CB and turned
/// from it in the crank's sense; from b a line perpendicular to AB (the
/// velocity of A relative to B, v_AB ⟂ AB), from o a line parallel to the
/// stroke (A's velocity is along the guides); they meet at a. The image q
/// of a point Q of the rod divides ab as Q divides AB (the velocity image).
///
/// The vectors are velocities per unit crank speed, lengths per radian
/// (ob = CB, so the polygon is drawn to the scale in which CB represents
/// V_B = rω): multiply by ω for the time rates. a always exists: the
/// perpendicular to the rod is horizontal only if the rod is vertical, which
/// a fully turning crank never makes it. At the dead centres a = o (the
/// slider at rest) and ab = ob; at θ = 90° and 270° with e = 0, ab
/// vanishes (the rod translates) and a = b.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct VelocityPolygon {
    b: Vector,
    a: Vector,
    q: Option<Vector>,
    /// B − A on the mechanism.
    rod: Vector,
}

impl VelocityPolygon {
    /// Draws the polygon of `pose`, with the image of `coupler` if given.
    #[inline]
    pub fn construct(pose: &Pose, coupler: Option<CouplerPoint>) -> Self {
        let crank = pose.b() - pose.c();
        let rod = pose.b() - pose.a();
        // ob: the crank turned a quarter turn in the sense of ω.
        let b = perp(&crank);
        // From b along the perpendicular to AB down to the level of o:
        // b + t · perp(AB) with b.y + t · (B − A).x = 0. The rod is never
        // vertical, so (B − A).x ≠ 0.
        let across = perp(&rod);
        let t = -b.y / across.y;
        let a = Vector::new(b.x + t * across.x, 0.0);
        let q = coupler.map(|p| p.image(a, b));
        Self { b, a, q, rod }
    }

    /// ob, the crank pin's velocity per ω (perpendicular to CB, |ob| = r).
    pub fn b(&self) -> Vector {
        self.b
    }

    /// oa, the slider's velocity per ω, along the stroke.
    pub fn a(&self) -> Vector {
        self.a
    }

    /// oq, the velocity per ω of the coupler point, when one was given.
    pub fn q(&self) -> Option<Vector> {
        self.q
    }

    /// ab, the velocity per ω of B relative to A (v_BA), perpendicular to
    /// AB; zero where the rod translates (θ = 90°, 270° when e = 0).
    pub fn ab(&self) -> Vector {
        self.b - self.a
    }

    /// ds/dθ read off the polygon: the signed length oa along +x (the
    /// slider's velocity per ω).
    #[inline]
    pub fn slider_velocity_ratio(&self) -> f64 {
        self.a.x
    }

    /// dφ/dθ read off the polygon: |ab| / AB with the sign of the rod's
    /// turning (ab = Ω · AB turned a quarter turn, Ω the rod's
    /// counter-clockwise rate per ω; dφ/dθ = −Ω, the seeds' sign).
    #[inline]
    pub fn rod_angular_velocity_ratio(&self) -> f64 {
        -cross(&self.rod, &self.ab()) / self.rod.norm_squared()
    }

    /// B − A on the mechanism, the direction ab is perpendicular to.
    pub(crate) fn rod(&self) -> Vector {
        self.rod
    }
}
