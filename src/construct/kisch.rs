//! Kisch's construction (textbook Fig. 66).

use super::{AccelerationPoints, VelocityLine};
use crate::geom::{Circle, Point, Vector, perp};
use crate::mechanism::Pose;

/// Kisch: on AB describe a semicircle AHB; the circle with centre B and
/// radius BE cuts it at H; HFG perpendicular to AB gives F on AB and G on
/// the line through C parallel to the stroke.
///
/// F is placed from BA · BF = BE² (BE a mean proportional), which holds
/// also where H degenerates: at θ = 90° E = B, so H = F = B; at the dead
/// centres H = F lies on AB. H is taken on the side of AB away from C (the
/// upper side when C is on AB), at height √(BF · FA) above F. Never needs D.
///
/// H exists whenever BE ≤ BA, and for a crank that turns fully that always
/// holds: BE / BA = r |cos θ| / (l cos φ) < 1 because l > r + |e|.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Kisch {
    b: Point,
    ba: Vector,
    away: Vector,
    be2: f64,
    ratio: f64,
    points: AccelerationPoints,
}

impl Kisch {
    /// Constructs F and G from E (H and the circle are computed when asked).
    #[inline]
    pub fn construct(pose: &Pose, e: &VelocityLine) -> Self {
        let (a, b, c) = (pose.a(), pose.b(), pose.c());
        let ba = a - b;
        let be2 = (e.e() - b).norm_squared();
        // BF / BA = BE² / BA².
        let ratio = be2 / ba.norm_squared();
        let f = b + ba * ratio;
        Self {
            b,
            ba,
            away: b - c,
            be2,
            ratio,
            points: AccelerationPoints::from_f(pose, f),
        }
    }

    /// H, where the circle about B through E cuts the semicircle on AB;
    /// `None` only if rounding makes BE > BA at the very limit of assembly.
    pub fn h(&self) -> Option<Point> {
        // HF² = BF · FA (altitude of the right triangle AHB).
        let ba = self.ba.norm();
        let bf = ba * self.ratio;
        let fa = ba - bf;
        if fa < 0.0 {
            return None;
        }
        let mut n: Vector = perp(&self.ba) / ba;
        let side = n.dot(&self.away);
        if side < 0.0 || (side == 0.0 && n.y < 0.0) {
            n = -n;
        }
        Some(self.points.f() + n * (bf * fa).sqrt())
    }

    /// The radius BE of the circle about B.
    pub fn be(&self) -> f64 {
        self.be2.sqrt()
    }

    /// The crank pin B, centre of the circle of radius BE.
    pub fn b(&self) -> Point {
        self.b
    }

    /// The circle on AB as diameter (the semicircle AHB is its half away
    /// from C).
    pub fn semicircle(pose: &Pose) -> Circle {
        Circle::on_diameter(pose.a(), pose.b())
    }

    /// F and G and what they give.
    #[inline]
    pub fn points(&self) -> &AccelerationPoints {
        &self.points
    }
}
