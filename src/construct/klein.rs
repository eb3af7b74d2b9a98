//! Klein's construction (textbook Fig. 65).

use super::{AccelerationPoints, InstantCentre, VelocityLine};
use crate::geom::{Intersection, Point};
use crate::mechanism::Pose;

/// Klein: through C draw CF parallel to DE, F on AB; FG perpendicular to AB
/// meets the line through C parallel to the stroke at G.
///
/// F is placed by the intercept theorem rather than by intersecting CF with
/// AB: C lies on BD, so the homothety about B that takes D to C takes E to F,
/// F = B + (E − B) · BC/BD (signed). Intersecting the two lines loses all
/// digits near the dead centres, where CF and AB become the same line
/// (`docs/accuracy.md`); the ratio does not.
///
/// Unavailable (`None`) where D is at infinity (θ = 90°, 270°): DE has no
/// finite point D to draw from. Kisch's construction needs no D.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Klein {
    d: Point,
    points: AccelerationPoints,
}

impl Klein {
    /// Constructs F and G from D and E.
    pub fn construct(pose: &Pose, d: &InstantCentre, e: &VelocityLine) -> Option<Self> {
        let Intersection::Point(d) = d.d() else {
            return None;
        };
        let b = pose.b();
        let bd = d - b;
        let ratio = (pose.c() - b).dot(&bd) / bd.norm_squared();
        let f = b + (e.e() - b) * ratio;
        Some(Self {
            d,
            points: AccelerationPoints::from_f(pose, f),
        })
    }

    /// The finite D the construction was drawn from.
    pub fn d(&self) -> Point {
        self.d
    }

    /// F and G and what they give.
    pub fn points(&self) -> &AccelerationPoints {
        &self.points
    }
}
