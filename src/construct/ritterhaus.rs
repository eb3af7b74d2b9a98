//! Ritterhaus's construction of the piston's acceleration.

use super::{AccelerationPoints, VelocityLine};
use crate::geom::Point;
use crate::mechanism::Pose;

/// Ritterhaus: the rod AB produced meets the perpendicular to the stroke
/// through C at E (his M; the triangle CBE is his velocity diagram, CE the
/// piston's velocity to the scale ω); from E a line parallel to AC (the
/// line joining the piston to the crank centre, the line of stroke of an
/// in-line engine) meets the crank CB produced at K; from K a line
/// perpendicular to the stroke (parallel to CE) meets the rod at F (his
/// Q); from F a line perpendicular to the rod meets the line through C
/// parallel to the stroke at G (his N). His quadrilateral CQNO is Klein's
/// CFG again: the piston's acceleration is ω² · CG, from G towards C
/// (docs/polygons.md).
///
/// Why: the homothety about B that takes A to E takes the line AC to the
/// parallel through E, so C to K, and the perpendicular to the stroke
/// through C (through E) to the one through K, so E to F: BF/BE = BE/BA,
/// Kisch's BA · BF = BE². Read by that ratio, K and F stay defined at the
/// dead centres, where the line through E parallel to AC is the crank line
/// itself and the drawing gives no point K. Needs no D.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ritterhaus {
    k: Point,
    points: AccelerationPoints,
}

impl Ritterhaus {
    /// Constructs K, F and G from E.
    pub fn construct(pose: &Pose, e: &VelocityLine) -> Self {
        let (a, b, c) = (pose.a(), pose.b(), pose.c());
        let ba = a - b;
        // BE / BA, signed: E is on the rod produced.
        let ratio = (e.e() - b).dot(&ba) / ba.norm_squared();
        let k = b + (c - b) * ratio;
        let f = b + (e.e() - b) * ratio;
        Self {
            k,
            points: AccelerationPoints::from_f(pose, f),
        }
    }

    /// K, on the crank CB produced, level with E as seen along AC.
    pub fn k(&self) -> Point {
        self.k
    }

    /// F (his Q) and G (his N), and what they give.
    pub fn points(&self) -> &AccelerationPoints {
        &self.points
    }
}
