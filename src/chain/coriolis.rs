//! The velocity and acceleration polygons of the inversions where the block
//! slides on a turning link, with the Coriolis component (docs/polygons.md).

use super::inversion::{Inversion, InversionPose};
use crate::geom::{Point, Vector, cross, perp};

/// The polygons of inversion 2 (the crank a fixed: the rotating block,
/// Whitworth's quick return) or 3 (the rod b fixed: the oscillating
/// cylinder, the crank and slotted lever) at one pose, for the driver
/// turning at a constant speed, in the fixed link's frame.
///
/// In both the block c slides along the slotted link d, and c and d turn
/// together (ω_c = ω_d), so the motion of c relative to d is a translation
/// along the slot u. For the point of d at A (under the block's pin), the
/// acceleration of one of the two coincident points relative to the other
/// is the sliding acceleration along u plus the **Coriolis component
/// 2 ω_d v**, v the sliding velocity turned a quarter turn in the sense of
/// ω_d.
///
/// - Inversion 3: the crank pin C turns about B (fixed) at ω_a; the block's
///   pin A is fixed. Velocity polygon: o, c = v_C ⟂ BC; from c the line ⟂
///   CA (d turning about C), from o the line ∥ u (d sliding through the
///   block at rest); they meet at a_d. Acceleration polygon: o′c′ = ω_a²
///   BC towards B, c′n = ω_d² CA towards C, then the line ⟂ CA; from o′
///   the Coriolis component 2 ω_d v to k, then the line ∥ u; they meet at
///   a′_d.
/// - Inversion 2: the rod b turns about B (fixed) at ω_b carrying the block
///   at A; d turns about C (fixed). Velocity polygon: o, a = v_A ⟂ BA; from
///   o the line ⟂ CA, from a the line ∥ u; they meet at a_d. Acceleration
///   polygon: o′a′ = ω_b² BA towards B; from a′ back by the Coriolis
///   component to k, then the line ∥ u; from o′ the normal component
///   ω_d² CA towards C to n, then the line ⟂ CA; they meet at a′_d.
///
/// The lines always meet: each pair is ⟂ CA and ∥ u, and CA · u = x_A,
/// the slider's distance from the crank centre along the stroke, never 0
/// for a crank that turns fully.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CoriolisPolygon {
    inversion: Inversion,
    /// The slot's direction (unit), d's +x turned into the fixed frame.
    u: Vector,
    /// The driven point's velocity (C's in 3, A's in 2).
    driven: Vector,
    /// The velocity of d's point at A.
    a_d: Vector,
    /// The driven point's acceleration.
    driven_acceleration: Vector,
    /// The end of the normal component of d's point at A about C.
    n: Vector,
    /// The Coriolis component, 2 ω_d times the sliding velocity turned.
    coriolis: Vector,
    /// The acceleration of d's point at A.
    a_d_acceleration: Vector,
    omega_d: f64,
    alpha_d: f64,
    sliding_velocity: f64,
    sliding_acceleration: f64,
}

impl CoriolisPolygon {
    /// The polygons of `pose` with the driver (the crank a in inversion 3,
    /// the rod b in inversion 2) at `omega` rad/s; `None` for inversions 1
    /// and 4, where no block slides on a turning link.
    pub fn construct(pose: &InversionPose, omega: f64) -> Option<Self> {
        let engine = pose.engine_pose();
        let (c, b, a) = (
            pose.place(engine.c()),
            pose.place(engine.b()),
            pose.place(engine.a()),
        );
        let u = pose.turn(Vector::new(1.0, 0.0));
        let ca = a - c;
        // CA · u = x_A > 0: the denominators of both meets.
        let along = ca.dot(&u);
        match pose.inversion() {
            Inversion::Rod => Some(Self::slotted_lever(c, b, ca, u, along, omega)),
            Inversion::Crank => Some(Self::rotating_block(b, a, ca, u, along, omega)),
            Inversion::Frame | Inversion::Slider => None,
        }
    }

    /// Inversion 3: C turns about B; A is fixed.
    fn slotted_lever(c: Point, b: Point, ca: Vector, u: Vector, along: f64, w: f64) -> Self {
        let driven = perp(&(c - b)) * w;
        // a_d = c + ω_d J(CA) along u: cross(u, a_d) = 0.
        let omega_d = -cross(&u, &driven) / along;
        let a_d = driven + perp(&ca) * omega_d;
        // d's point at A relative to the block, at rest: a_d itself.
        let v = a_d.dot(&u);
        let driven_acceleration = -(c - b) * (w * w);
        let n = driven_acceleration - ca * (omega_d * omega_d);
        let coriolis = perp(&(u * v)) * (2.0 * omega_d);
        // n + α J(CA) = coriolis + s u.
        let alpha_d = (cross(&u, &coriolis) - cross(&u, &n)) / along;
        let a_d_acceleration = n + perp(&ca) * alpha_d;
        let s = (a_d_acceleration - coriolis).dot(&u);
        Self {
            inversion: Inversion::Rod,
            u,
            driven,
            a_d,
            driven_acceleration,
            n,
            coriolis,
            a_d_acceleration,
            omega_d,
            alpha_d,
            // The block relative to d: the opposite translation.
            sliding_velocity: -v,
            sliding_acceleration: -s,
        }
    }

    /// Inversion 2: A turns about B with the rod; d turns about C.
    fn rotating_block(b: Point, a: Point, ca: Vector, u: Vector, along: f64, w: f64) -> Self {
        let driven = perp(&(a - b)) * w;
        // a_d = ω_d J(CA) with driven − a_d along u.
        let omega_d = cross(&u, &driven) / along;
        let a_d = perp(&ca) * omega_d;
        let v = (driven - a_d).dot(&u);
        let driven_acceleration = -(a - b) * (w * w);
        let coriolis = perp(&(u * v)) * (2.0 * omega_d);
        let n = -ca * (omega_d * omega_d);
        // driven″ − coriolis = n + α J(CA) + s u.
        let k = driven_acceleration - coriolis;
        let alpha_d = cross(&u, &(k - n)) / along;
        let a_d_acceleration = n + perp(&ca) * alpha_d;
        let s = (k - a_d_acceleration).dot(&u);
        Self {
            inversion: Inversion::Crank,
            u,
            driven,
            a_d,
            driven_acceleration,
            n,
            coriolis,
            a_d_acceleration,
            omega_d,
            alpha_d,
            sliding_velocity: v,
            sliding_acceleration: s,
        }
    }

    /// The inversion (2 or 3).
    pub fn inversion(&self) -> Inversion {
        self.inversion
    }

    /// The slot's direction, a unit vector.
    pub fn slot(&self) -> Vector {
        self.u
    }

    /// The driven point's velocity from the pole: C's (inversion 3) or A's
    /// (inversion 2).
    pub fn driven(&self) -> Vector {
        self.driven
    }

    /// The velocity of the point of d at A.
    pub fn a_d(&self) -> Vector {
        self.a_d
    }

    /// The driven point's acceleration (centripetal, the driver at
    /// constant speed).
    pub fn driven_acceleration(&self) -> Vector {
        self.driven_acceleration
    }

    /// The end n of the normal component ω_d² CA of d's point at A.
    pub fn n(&self) -> Vector {
        self.n
    }

    /// The Coriolis component 2 ω_d v: the sliding velocity turned a
    /// quarter turn in the sense of ω_d (of the block on d in inversion 2,
    /// of d's point on the block in 3).
    pub fn coriolis(&self) -> Vector {
        self.coriolis
    }

    /// The acceleration of the point of d at A.
    pub fn a_d_acceleration(&self) -> Vector {
        self.a_d_acceleration
    }

    /// d's angular velocity (rad/s, counter-clockwise), read off the
    /// velocity polygon.
    pub fn omega_d(&self) -> f64 {
        self.omega_d
    }

    /// d's angular acceleration (rad/s²), from the tangential component.
    pub fn alpha_d(&self) -> f64 {
        self.alpha_d
    }

    /// The block's velocity along d (the engine's d x_A/dt).
    pub fn sliding_velocity(&self) -> f64 {
        self.sliding_velocity
    }

    /// The block's acceleration along d (the engine's d² x_A/dt² at this
    /// driver speed).
    pub fn sliding_acceleration(&self) -> f64 {
        self.sliding_acceleration
    }
}
