//! The connecting rod's inertia: exactly, as a rigid body, and as the
//! equivalent dynamical system of two masses with the correction couple.

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
        let g1 = [(1.0 - beta) * -r * s + beta * s1, (1.0 - beta) * r * c];
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
        Self {
            force: [-rod.mass * w2 * g2[0], -rod.mass * w2 * g2[1]],
            couple,
            torque,
            mass_at_crosshead,
            mass_at_crank_pin,
            correction_couple,
            correction_torque,
            equivalent_torque: -w2 * mass_at_crosshead * s2 * s1 + crank_pin + correction_torque,
        }
    }
}
