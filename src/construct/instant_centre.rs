//! D, the instantaneous centre of the rod (textbook Fig. 63, Ng's I).

use crate::geom::{Intersection, Line, Vector};
use crate::mechanism::Pose;

/// D: the crank line CB produced meets the perpendicular to the stroke
/// through A.
///
/// At θ = 90° and 270° (CB perpendicular to the stroke) the two lines are
/// parallel and D is the point at infinity along CB: then the rod is in
/// pure translation and its angular velocity is zero. At the dead centres
/// D coincides with A.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InstantCentre {
    d: Intersection,
    /// B − C, the crank.
    crank: Vector,
}

impl InstantCentre {
    /// Constructs D for `pose` (lines meeting within the default
    /// [`crate::geom::PARALLEL_TOLERANCE`]).
    #[inline]
    pub fn construct(pose: &Pose) -> Self {
        let (c, b, a) = (pose.c(), pose.b(), pose.a());
        let crank = Line::from_parts(c, b - c);
        let normal_at_a = Line::from_parts(a, Vector::new(0.0, 1.0));
        let d = match crank.intersect(&normal_at_a) {
            // The lines cannot coincide: A is never on CB's perpendicular...
            // unless CB is vertical and passes through A, impossible as
            // x_A > r |cos θ|. Treat defensively as at infinity.
            Intersection::Coincident => Intersection::AtInfinity(crank.unit_direction()),
            other => other,
        };
        Self { d, crank: b - c }
    }

    /// D, a finite point or a point at infinity.
    pub fn d(&self) -> Intersection {
        self.d
    }

    /// dφ/dθ, the derivative of the rod's obliquity φ against the crank
    /// angle θ (dimensionless), read off the construction: |CB / BD| with
    /// the sign of the rod's turning (rod angular velocity dφ/dt = ω dφ/dθ,
    /// of magnitude ω · CB / BD, textbook §37); 0 when D is at infinity.
    /// The counterpart of
    /// [`Pose::obliquity_rate`](crate::mechanism::Pose::obliquity_rate).
    #[inline]
    pub fn rod_angular_velocity_ratio(&self) -> f64 {
        // The rod turns about D: ω (B − C) = Ω (B − D) with Ω the rod's
        // counter-clockwise rate, and dφ/dt = −Ω. B − D = (B − C) − (D − C).
        match self.d {
            Intersection::Point(d) => {
                let bd = self.crank - d.coords;
                -self.crank.dot(&bd) / bd.norm_squared()
            }
            _ => 0.0,
        }
    }
}
