//! The connecting rod's inertia: exactly, as a rigid body, as two masses
//! at the cross-head and the crank pin with the correction couple, and as
//! the true equivalent dynamical system of two masses at the cross-head
//! and the centre of percussion.

use crate::error::{Field, Result, non_negative};
use crate::mechanism::Pose;

/// A connecting rod with mass: its mass m_r, the distance BG of its centre
/// of mass G from the crank pin B along the rod (0 ≤ BG ≤ l, checked by
/// [`super::Engine::with_rod`]) and its radius of gyration k about G
/// (moment of inertia m_r k²). A rod of zero mass is allowed and exerts
/// no force.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct RodMass {
    mass: f64,
    cg: f64,
    gyration: f64,
}

impl RodMass {
    /// Errors: any value negative or not finite.
    pub fn new(mass: f64, cg_from_crank_pin: f64, gyration: f64) -> Result<Self> {
        Ok(Self {
            mass: non_negative(Field::RodMass, mass)?,
            cg: non_negative(Field::RodCg, cg_from_crank_pin)?,
            gyration: non_negative(Field::RodGyration, gyration)?,
        })
    }

    /// The rod's mass m_r.
    pub fn mass(&self) -> f64 {
        self.mass
    }

    /// BG, the distance of the centre of mass from the crank pin.
    pub fn cg(&self) -> f64 {
        self.cg
    }

    /// The radius of gyration k about G.
    pub fn gyration(&self) -> f64 {
        self.gyration
    }

    /// The rod of length `rod_length` as its true equivalent dynamical
    /// system: two masses with its mass, centre of mass and moment of
    /// inertia, one at the cross-head A (AG = l₁ from G) and one at the
    /// centre of percussion P, k²/l₁ beyond G, at
    /// **L = l₁ + k²/l₁** from A. `None` when G is at A (l₁ = 0: no
    /// second point at a finite distance).
    pub fn dynamical_system(&self, rod_length: f64) -> Option<DynamicalSystem> {
        let l1 = rod_length - self.cg;
        if l1 <= 0.0 {
            return None;
        }
        let l2 = self.gyration * self.gyration / l1;
        let distance = l1 + l2;
        Some(DynamicalSystem {
            crosshead_to_cg: l1,
            distance,
            mass_at_crosshead: self.mass * l2 / distance,
            mass_at_percussion: self.mass * l1 / distance,
        })
    }
}

/// The rod as two masses that have its mass, its centre of mass and its
/// moment of inertia about G (no correction couple): m₁ at the cross-head
/// A and m₂ at the centre of percussion P on AB produced, at L = l₁ +
/// k²/l₁ from A, with m₁ = m_r l₂/L, m₂ = m_r l₁/L, l₂ = k²/l₁, so that
/// m₁ l₁ = m₂ l₂ and m₁ l₁² + m₂ l₂² = m_r l₁ l₂ = m_r k². P lies between
/// G and the crank pin B when L < l, beyond B when L > l; the two-mass
/// approximation (m_A at A, m_B at B) is exact only when L = l.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct DynamicalSystem {
    /// l₁ = AG.
    pub crosshead_to_cg: f64,
    /// L = l₁ + k²/l₁, the distance AP.
    pub distance: f64,
    /// m₁ = m_r k²/(l₁ L), at A.
    pub mass_at_crosshead: f64,
    /// m₂ = m_r l₁/L, at P.
    pub mass_at_percussion: f64,
}

/// The rod's inertia at one pose, at constant crank speed ω.
///
/// Exact (rigid body): the inertia force −m_r a_G at G and the inertia
/// couple −m_r k² α (α the rod's counter-clockwise angular acceleration,
/// −d²φ/dt²); by virtual work they deliver to the crank
/// T = −(m_r a_G · v_G + m_r k² α Ω) / ω (Ω = −dφ/dt), which at constant
/// ω is −ω² (m_r G″ · G′ + m_r k² φ″ φ′) with ′ = d/dθ: finite also at
/// rest (ω = 0, every value 0).
///
/// Equivalent dynamical system: m_A = m_r BG / l at the cross-head A (it
/// moves with the piston), m_B = m_r AG / l at the crank pin B (it turns
/// with the crank: its force passes through C and gives no torque at
/// constant ω), and the correction couple
/// −m_r (k² − AG · BG) α that makes up the difference between m_r k² and
/// the two masses' moment of inertia m_r AG · BG. The two give the same
/// torque ([`RodInertia::torque`] and [`RodInertia::equivalent_torque`]).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct RodInertia {
    /// The inertia force −m_r a_G on the rod at G, x and y.
    pub force: [f64; 2],
    /// The inertia couple −m_r k² α, counter-clockwise positive.
    pub couple: f64,
    /// The torque the rod's inertia delivers to the crank, exact.
    pub torque: f64,
    /// m_A = m_r BG / l, the mass at the cross-head.
    pub mass_at_crosshead: f64,
    /// m_B = m_r AG / l, the mass at the crank pin.
    pub mass_at_crank_pin: f64,
    /// The correction couple −m_r (k² − AG · BG) α.
    pub correction_couple: f64,
    /// The torque on the crank of the correction couple alone.
    pub correction_torque: f64,
    /// The torque of the equivalent system: m_A's inertia force through
    /// OM, m_B's (zero) and the correction couple's.
    pub equivalent_torque: f64,
    /// The torque of the true dynamical system ([`DynamicalSystem`]):
    /// m₁'s inertia at A and m₂'s at P, no couple; equal to `torque`.
    /// `None` when there is no such system (G at A).
    pub dynamical_torque: Option<f64>,
}

impl RodInertia {
    /// The rod's inertia at `pose` at crank speed `omega`.
    pub fn new(pose: &Pose, rod: &RodMass, omega: f64) -> Self {
        let m = pose.mechanism();
        let (r, l) = (m.crank(), m.rod());
        let beta = rod.cg / l;
        let (s, c) = (pose.angle().sin(), pose.angle().cos());
        let (s1, s2) = (pose.position_rate(), pose.position_acceleration());
        let (p1, p2) = (pose.obliquity_rate(), pose.obliquity_acceleration());
        // G = B + β (A − B): its derivatives are the same blend of B's and A's.
        let g1 = cg_rate(pose, beta);
        let g2 = [(1.0 - beta) * -r * c + beta * s2, (1.0 - beta) * -r * s];
        let w2 = omega * omega;
        let inertia = rod.mass * rod.gyration * rod.gyration;
        // α = −ω² φ″, Ω = −ω φ′.
        let couple = inertia * w2 * p2;
        let torque = -w2 * (rod.mass * (g2[0] * g1[0] + g2[1] * g1[1]) + inertia * p2 * p1);
        let ag_bg = rod.cg * (l - rod.cg);
        let correction_couple = rod.mass * (rod.gyration * rod.gyration - ag_bg) * w2 * p2;
        let correction_torque = -correction_couple * p1;
        let mass_at_crosshead = rod.mass * beta;
        let mass_at_crank_pin = rod.mass * (1.0 - beta);
        // m_B on the crank pin: −ω² m_B B″ · B′, zero (B″ ⟂ B′ on the circle).
        let (b1, b2) = ([-r * s, r * c], [-r * c, -r * s]);
        let crank_pin = -w2 * mass_at_crank_pin * (b2[0] * b1[0] + b2[1] * b1[1]);
        // P = A + (L/l)(B − A): its derivatives the same blend.
        let dynamical_torque = rod.dynamical_system(l).map(|d| {
            let q = d.distance / l;
            let p1_ = [(1.0 - q) * s1 + q * b1[0], q * b1[1]];
            let p2_ = [(1.0 - q) * s2 + q * b2[0], q * b2[1]];
            -w2 * (d.mass_at_crosshead * s2 * s1
                + d.mass_at_percussion * (p2_[0] * p1_[0] + p2_[1] * p1_[1]))
        });
        Self {
            force: [-rod.mass * w2 * g2[0], -rod.mass * w2 * g2[1]],
            couple,
            torque,
            mass_at_crosshead,
            mass_at_crank_pin,
            correction_couple,
            correction_torque,
            equivalent_torque: -w2 * mass_at_crosshead * s2 * s1 + crank_pin + correction_torque,
            dynamical_torque,
        }
    }
}

/// G′ = dG/dθ of the point G = B + β (A − B) of the rod at `pose`:
/// (1 − β) B′ + β A′, B′ = r (−sin θ, cos θ), A′ = (s′, 0).
pub(crate) fn cg_rate(pose: &Pose, beta: f64) -> [f64; 2] {
    let r = pose.mechanism().crank();
    let (s, c) = (pose.angle().sin(), pose.angle().cos());
    [
        (1.0 - beta) * -r * s + beta * pose.position_rate(),
        (1.0 - beta) * r * c,
    ]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::angle::Angle;
    use crate::mechanism::SliderCrank;

    /// The dynamical system has the rod's mass, centre of mass and moment
    /// of inertia; its torque is the rigid body's; and the correction
    /// couple of the two-mass approximation is the textbooks'
    /// −m_r l₁ (L − l) α (α = −ω² φ″), which vanishes when L = l.
    #[test]
    fn the_dynamical_system_is_the_rod() {
        let mut next = crate::dynamics::uniform_draws(0x0000_ddb1_a5e5_u64);
        for _ in 0..200 {
            let (r, n) = (0.2 + next(), 1.05 + 8.0 * next());
            let l = n * r;
            let e = (next() - 0.5) * (l - r) * 0.9;
            let m = SliderCrank::new(r, l, e).unwrap();
            let (mass, bg, k) = (0.5 + 5.0 * next(), l * 0.95 * next(), l * next());
            let rod = RodMass::new(mass, bg, k).unwrap();
            let d = rod.dynamical_system(l).unwrap();
            let (l1, big_l) = (l - bg, d.distance);
            assert!((d.mass_at_crosshead + d.mass_at_percussion - mass).abs() < 1e-12 * mass);
            // The centre of mass at G: m₁ l₁ = m₂ (L − l₁).
            let moment = d.mass_at_crosshead * l1 - d.mass_at_percussion * (big_l - l1);
            assert!(moment.abs() < 1e-12 * mass * big_l, "{moment}");
            let inertia =
                d.mass_at_crosshead * l1 * l1 + d.mass_at_percussion * (big_l - l1) * (big_l - l1);
            assert!((inertia - mass * k * k).abs() < 1e-12 * mass * big_l * big_l);
            let omega = 20.0 * next() - 10.0;
            let pose = m.pose(Angle::deg(360.0 * next()));
            let at = RodInertia::new(&pose, &rod, omega);
            let t = at.dynamical_torque.unwrap();
            let scale = mass * omega * omega * big_l.max(l) * big_l.max(l) * 10.0;
            assert!((t - at.torque).abs() < 1e-12 * scale, "{t} {}", at.torque);
            let alpha = -omega * omega * pose.obliquity_acceleration();
            let textbook = -mass * l1 * (big_l - l) * alpha;
            assert!(
                (at.correction_couple - textbook).abs() < 1e-12 * scale,
                "{} {textbook}",
                at.correction_couple
            );
        }
        // G at the cross-head: no second point.
        assert!(
            RodMass::new(1.0, 3.0, 0.5)
                .unwrap()
                .dynamical_system(3.0)
                .is_none()
        );
        // k² = AG · BG: the centre of percussion is the crank pin.
        let rod = RodMass::new(2.0, 1.0, 2f64.sqrt()).unwrap();
        let d = rod.dynamical_system(3.0).unwrap();
        assert!((d.distance - 3.0).abs() < 1e-15);
    }
}
