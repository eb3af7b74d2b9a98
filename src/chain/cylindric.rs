//! The cylindric slider-crank: the block in a circularly curved slot,
//! textbook §34, Fig. 60 (b), and its limit the straight slot, Fig. 60 (c).

use super::quadric::{Assembly, QuadricChain};
use crate::angle::Angle;
use crate::error::{Error, Field, Result, finite};
use crate::geom::{Direction, Intersection, Point, Vector, cross, perp};
use crate::mechanism::SliderCrank;

/// A slider-crank whose block slides in a circular slot of radius ρ
/// (curvature κ = 1/ρ), validated once; κ = 0 is today's straight slot.
///
/// Where the slot lies: it touches the line of stroke y = e at T = (0, e),
/// the foot of the perpendicular from the crank centre C, and its centre
/// O_cd lies on that perpendicular, at (0, e − ρ). So ρ > 0 puts O_cd below
/// the stroke (the slot arches up, as the lever's arc does in Fig. 60 (b):
/// the open quadric chain), ρ < 0 above it (the crossed chain). As |ρ|
/// grows the slot tends to the line y = e and O_cd to the point at infinity
/// on the perpendicular through C, the straight slot's O_cd.
///
/// Everything is computed from κ, never from ρ: the block's place is the
/// root z of a quadratic whose coefficients differ from the straight
/// slot's by terms in κ, so κ = 0 gives today's mechanism and ρ = 1e12
/// differs from it only by the true O(1/ρ) amount, not by cancellation.
///
/// Arc position σ: the distance along the slot from T, signed +x; it tends
/// to today's slider position x_A.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CylindricChain {
    mechanism: SliderCrank,
    curvature: f64,
}

impl CylindricChain {
    /// The curved slot of radius `slot_radius` (finite, non-zero; sign as
    /// above) for `mechanism` (its crank, rod and offset).
    ///
    /// The crank turns fully only when |ρ| > (l + r + e·sign ρ)/2: a shorter
    /// radius is an error that names the bound (the far end of the slot's
    /// circle would come within reach of the rod).
    pub fn new(mechanism: SliderCrank, slot_radius: f64) -> Result<Self> {
        let rho = finite(Field::SlotRadius, slot_radius)?;
        if rho == 0.0 {
            return Err(Error::NotPositive {
                name: Field::SlotRadiusSize,
                value: rho,
            });
        }
        let bound = Self::bound(&mechanism, rho.signum());
        if rho.abs() <= bound {
            return Err(Error::OutOfRange {
                name: Field::SlotRadius,
                value: rho,
                reason: format!(
                    "the crank turns fully only when |slot radius| > (rod + crank {} offset)/2 = {bound}",
                    if rho > 0.0 { "+" } else { "−" }
                ),
            });
        }
        Ok(Self {
            mechanism,
            curvature: 1.0 / rho,
        })
    }

    /// The slot of curvature `curvature` = 1/ρ (0: the straight slot);
    /// errors as [`CylindricChain::new`].
    pub fn with_curvature(mechanism: SliderCrank, curvature: f64) -> Result<Self> {
        let kappa = finite(Field::SlotCurvature, curvature)?;
        if kappa == 0.0 {
            return Ok(Self::straight(mechanism));
        }
        Self::new(mechanism, 1.0 / kappa)
    }

    /// Today's straight slot (κ = 0).
    pub fn straight(mechanism: SliderCrank) -> Self {
        Self {
            mechanism,
            curvature: 0.0,
        }
    }

    fn bound(m: &SliderCrank, sign: f64) -> f64 {
        0.5 * (m.rod() + m.crank() + sign * m.offset())
    }

    /// The crank, rod and offset.
    pub fn mechanism(&self) -> &SliderCrank {
        &self.mechanism
    }

    /// The slot's curvature κ = 1/ρ (0 for the straight slot).
    pub fn curvature(&self) -> f64 {
        self.curvature
    }

    /// The slot's radius ρ; `None` for the straight slot.
    pub fn slot_radius(&self) -> Option<f64> {
        (self.curvature != 0.0).then(|| 1.0 / self.curvature)
    }

    /// O_cd, the slot's centre (0, e − ρ); for the straight slot the point at
    /// infinity on the perpendicular to the stroke, direction (0, 1).
    pub fn slot_centre(&self) -> Intersection {
        match self.slot_radius() {
            Some(rho) => Intersection::Point(Point::new(0.0, self.mechanism.offset() - rho)),
            None => Intersection::AtInfinity(Direction::new_unchecked(Vector::new(0.0, 1.0))),
        }
    }

    /// The same chain as a quadric crank chain (lever c = |ρ|, frame
    /// d = |e − ρ|), with its assembly mode and the angle in degrees by which
    /// its frame (O_cd on +x) is turned into this one's: a crank angle θ here
    /// is θ − turn there. `None` for the straight slot.
    pub fn as_quadric(&self) -> Option<(QuadricChain, Assembly, f64)> {
        let rho = self.slot_radius()?;
        let m = &self.mechanism;
        let frame = m.offset() - rho;
        let chain = QuadricChain::new(m.crank(), m.rod(), rho.abs(), frame.abs()).ok()?;
        let (mode, turn) = if rho > 0.0 {
            (Assembly::Open, -90.0)
        } else {
            (Assembly::Crossed, 90.0)
        };
        Some((chain, mode, turn))
    }

    /// The chain at crank angle `angle`.
    pub fn pose(&self, angle: Angle) -> CylindricPose {
        CylindricPose::new(*self, angle)
    }
}

/// The cylindric chain at one crank angle: the block's place on the slot and
/// its exact derivatives with respect to θ (multiply by ω and ω² for time
/// rates at constant crank speed).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CylindricPose {
    chain: CylindricChain,
    angle: Angle,
    /// Upward curvature k = −κ: the slot's centre is at (0, e + 1/k).
    k: f64,
    /// The slot's stereographic parameter: A − T = (z, k z²/2)/(1 + τ²).
    z: f64,
    /// τ = k z / 2 = tan(ψ/2).
    tau: f64,
    /// The block A = (z / (1 + τ²), e + k z² / (2 (1 + τ²))).
    a: Point,
    /// A − B, the rod.
    rod: Vector,
    /// Unit tangent of the slot at A (+x at T).
    tangent: Vector,
    /// dσ/dθ and d²σ/dθ².
    rate: f64,
    accel: f64,
}

impl CylindricPose {
    fn new(chain: CylindricChain, angle: Angle) -> Self {
        let m = &chain.mechanism;
        let (r, l, e) = (m.crank(), m.rod(), m.offset());
        let k = -chain.curvature;
        let px = r * angle.cos();
        let h = r * angle.sin() - e;
        // The block on the slot, |A − B| = l, as A z² − 2 P_x z + C = 0 with
        // A = 1 − k h + k² C/4, C = |B − T|² − l²; at k = 0 the straight
        // slot's z = r cos θ + √(l² − h²).
        let w2 = (l - h) * (l + h);
        let cq = px * px - w2;
        let lead = 1.0 - k * h + 0.25 * k * k * cq;
        let disc = (w2 + k * h * cq - 0.25 * k * k * cq * cq).max(0.0);
        let root = disc.sqrt();
        let z = (px + root) / lead;
        let tau = 0.5 * k * z;
        let den = 1.0 + tau * tau;
        // A − B without cancellation: x = (√Δ + P_x (1 − A(1 + τ²)))/(A(1 + τ²)).
        let shrink = k * h - 0.25 * k * k * cq - lead * tau * tau;
        let rod = Vector::new(
            (root + px * shrink) / (lead * den),
            0.5 * k * z * z / den - h,
        );
        let tangent = Vector::new((1.0 - tau * tau) / den, 2.0 * tau / den);
        let b = Vector::new(px, r * angle.sin());
        let b1 = perp(&b);
        let along = rod.dot(&tangent);
        let rate = rod.dot(&b1) / along;
        let rel = tangent * rate - b1;
        let normal = perp(&tangent);
        let accel =
            -(rel.norm_squared() + k * rate * rate * rod.dot(&normal) + rod.dot(&b)) / along;
        let a = Point::new(z / den, e + 0.5 * k * z * z / den);
        Self {
            chain,
            angle,
            k,
            z,
            tau,
            a,
            rod,
            tangent,
            rate,
            accel,
        }
    }

    /// The chain.
    pub fn chain(&self) -> &CylindricChain {
        &self.chain
    }

    /// The crank angle.
    pub fn angle(&self) -> Angle {
        self.angle
    }

    /// Crank centre C = O_ad, the origin.
    pub fn c(&self) -> Point {
        Point::origin()
    }

    /// Crank pin B = O_ab.
    pub fn b(&self) -> Point {
        let r = self.chain.mechanism.crank();
        Point::new(r * self.angle.cos(), r * self.angle.sin())
    }

    /// The block A = O_bc on the slot.
    pub fn a(&self) -> Point {
        self.a
    }

    /// The rod A − B (length l).
    pub fn rod_vector(&self) -> Vector {
        self.rod
    }

    /// The slot's unit tangent at A, pointing along +σ.
    pub fn tangent(&self) -> Vector {
        self.tangent
    }

    /// The direction of the lever O_cd A at A (the slot's normal, turned a
    /// quarter turn counter-clockwise from the tangent); for the straight
    /// slot the perpendicular to the stroke.
    pub fn lever_direction(&self) -> Vector {
        perp(&self.tangent)
    }

    /// The block's angle on the slot ψ: the angle the lever O_cd A has
    /// turned counter-clockwise from O_cd T, ψ = −σ/ρ (so negative for
    /// ρ > 0 with the block on the +x side of T); 0 for the straight slot.
    pub fn slot_angle(&self) -> f64 {
        2.0 * self.tau.atan()
    }

    /// Arc position σ of the block along the slot from T (the straight
    /// slot's x_A in the limit): σ = z · atan(τ)/τ.
    pub fn arc_position(&self) -> f64 {
        if self.tau == 0.0 {
            self.z
        } else {
            self.z * (self.tau.atan() / self.tau)
        }
    }

    /// dσ/dθ = (A − B)·B′ / ((A − B)·t): the block's velocity along the slot
    /// per unit crank rate.
    pub fn arc_rate(&self) -> f64 {
        self.rate
    }

    /// d²σ/dθ²: the block's tangential acceleration along the slot at
    /// constant crank speed, per ω² (its normal acceleration is
    /// κ (dσ/dθ)² towards O_cd).
    pub fn arc_acceleration(&self) -> f64 {
        self.accel
    }

    /// dψ/dθ = −κ dσ/dθ: the lever's (and block's) counter-clockwise
    /// angular velocity per unit crank rate; 0 for the straight slot.
    pub fn lever_rate(&self) -> f64 {
        self.k * self.rate
    }

    /// d²ψ/dθ², the lever's angular acceleration per ω².
    pub fn lever_acceleration(&self) -> f64 {
        self.k * self.accel
    }

    /// The rod's obliquity φ with A − B = l (cos φ, −sin φ), the seeds' sign
    /// (sin φ = (r sin θ − e)/l for the straight slot).
    pub fn obliquity(&self) -> f64 {
        (-self.rod.y).atan2(self.rod.x)
    }

    /// dφ/dθ (the rod's counter-clockwise rate is −dφ/dθ).
    pub fn obliquity_rate(&self) -> f64 {
        let l = self.chain.mechanism.rod();
        -cross(&self.rod, &self.rod_rate()) / (l * l)
    }

    /// d²φ/dθ².
    pub fn obliquity_acceleration(&self) -> f64 {
        let l = self.chain.mechanism.rod();
        let b = self.b().coords;
        let accel =
            self.tangent * self.accel + perp(&self.tangent) * (self.k * self.rate * self.rate) + b;
        -cross(&self.rod, &accel) / (l * l)
    }

    /// d(A − B)/dθ.
    fn rod_rate(&self) -> Vector {
        self.tangent * self.rate - perp(&self.b().coords)
    }
}

/// The difference between the curved and the straight slot at one radius:
/// the worst over the turn of |σ − x_A| / r, |dσ/dθ − dx_A/dθ| / r and
/// |d²σ/dθ² − d²x_A/dθ²| / r.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct ConvergenceRow {
    /// The slot radius ρ.
    pub radius: f64,
    /// Worst scaled difference of the positions.
    pub position: f64,
    /// Worst scaled difference of the velocities.
    pub velocity: f64,
    /// Worst scaled difference of the accelerations.
    pub acceleration: f64,
}

/// The rows of the convergence figure: for each radius, the curved slot
/// against `mechanism`'s straight slot at `samples` crank angles equally
/// spaced in degrees. Errors for a radius the crank cannot turn with.
pub fn slot_convergence(
    mechanism: &SliderCrank,
    radii: &[f64],
    samples: usize,
) -> Result<Vec<ConvergenceRow>> {
    let r = mechanism.crank();
    radii
        .iter()
        .map(|&rho| {
            let chain = CylindricChain::new(*mechanism, rho)?;
            let mut row = ConvergenceRow {
                radius: rho,
                position: 0.0,
                velocity: 0.0,
                acceleration: 0.0,
            };
            for k in 0..samples.max(1) {
                let angle = Angle::from_degrees(360.0 * k as f64 / samples.max(1) as f64)?;
                let (p, q) = (chain.pose(angle), mechanism.pose(angle));
                row.position = row
                    .position
                    .max((p.arc_position() - q.position()).abs() / r);
                row.velocity = row
                    .velocity
                    .max((p.arc_rate() - q.position_rate()).abs() / r);
                row.acceleration = row
                    .acceleration
                    .max((p.arc_acceleration() - q.position_acceleration()).abs() / r);
            }
            Ok(row)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_radius_must_let_the_crank_turn() {
        let m = SliderCrank::new(1.0, 3.0, 0.5).unwrap();
        // Bound (l + r ± e)/2: 2.25 for ρ > 0, 1.75 for ρ < 0.
        assert!(CylindricChain::new(m, 2.25).is_err());
        assert!(CylindricChain::new(m, 2.2500001).is_ok());
        assert!(CylindricChain::new(m, -1.75).is_err());
        assert!(CylindricChain::new(m, -1.7500001).is_ok());
        assert!(CylindricChain::new(m, 0.0).is_err());
        assert!(CylindricChain::new(m, f64::INFINITY).is_err());
        assert_eq!(
            CylindricChain::with_curvature(m, 0.0).unwrap(),
            CylindricChain::straight(m)
        );
    }

    #[test]
    fn zero_curvature_is_todays_mechanism() {
        let m = SliderCrank::new(1.0, 1.05, 0.04).unwrap();
        let slot = CylindricChain::straight(m);
        for d in 0..360 {
            let (p, q) = (
                slot.pose(Angle::deg(d as f64)),
                m.pose(Angle::deg(d as f64)),
            );
            assert_eq!(p.arc_position(), q.position(), "{d}");
            assert_eq!(p.a(), q.a(), "{d}");
            assert_eq!(p.slot_angle(), 0.0);
            let tol = 1e-14 * (1.0 + q.position_acceleration().abs());
            assert!((p.arc_rate() - q.position_rate()).abs() < tol, "{d}");
            assert!(
                (p.arc_acceleration() - q.position_acceleration()).abs() < tol,
                "{d}"
            );
            assert!((p.obliquity() - q.obliquity()).abs() < 1e-15, "{d}");
        }
    }

    #[test]
    fn the_block_stays_on_its_slot_and_the_rod_keeps_its_length() {
        let m = SliderCrank::new(1.0, 3.0, -0.4).unwrap();
        for rho in [2.0, -2.5, 10.0, -1e3] {
            let slot = CylindricChain::new(m, rho).unwrap();
            let Intersection::Point(o) = slot.slot_centre() else {
                panic!()
            };
            for d in (0..360).step_by(7) {
                let p = slot.pose(Angle::deg(d as f64));
                assert!(((p.a() - o).norm() - rho.abs()).abs() < 1e-13 * rho.abs());
                assert!(((p.a() - p.b()).norm() - 3.0).abs() < 1e-14);
            }
        }
    }
}
