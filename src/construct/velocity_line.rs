//! E and the velocity line CE (textbook Fig. 63, Ng Fig. A1 where E is M).

use crate::geom::{Line, Point, Vector};
use crate::mechanism::Pose;

/// E: the rod AB produced meets the line through C perpendicular to the
/// stroke. CE / CB = V_p / V_c.
///
/// E always exists: the rod is never perpendicular to the stroke for a
/// mechanism whose crank turns fully. At the dead centres E = C and the
/// slider is at rest; at θ = 90° E = B.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct VelocityLine {
    e: Point,
}

impl VelocityLine {
    /// Constructs E for `pose`.
    #[inline]
    pub fn construct(pose: &Pose) -> Self {
        // Anchored at B, near E, so that no digits cancel when the offset is
        // much larger than the crank (E_y = r sin θ + r cos θ h / w).
        let rod = Line::from_parts(pose.b(), pose.a() - pose.b());
        let vertical = Line::from_parts(pose.c(), Vector::new(0.0, 1.0));
        // Exactly-parallel test only: the rod is never vertical.
        // cannot fail: for a crank that turns fully (l > r + |e|) the rod's run w = √((l − h)(l + h)) > 0, so the rod is never parallel to the vertical through C.
        #[allow(clippy::expect_used)]
        let e = rod
            .intersect_eps(&vertical, 0.0)
            .point()
            .expect("the rod of a fully turning crank is never perpendicular to the stroke");
        Self { e }
    }

    /// The point E (Ng's M), on the y-axis.
    #[inline]
    pub fn e(&self) -> Point {
        self.e
    }

    /// The signed length CE, in the mechanism's length unit: positive when
    /// E is above C. Equals −ds/dθ (s = x_A the slider's position, θ the
    /// crank angle), so the slider velocity is ds/dt = −ω · CE and
    /// V_p / V_c = CE / CB in magnitude.
    pub fn ce(&self) -> f64 {
        self.e.y
    }

    /// ds/dθ, the derivative of the slider's position s = x_A against the
    /// crank angle θ (length per rad), read off the construction: −CE. Not a
    /// ratio of two velocities: the slider velocity per ω (ds/dt = ω ds/dθ),
    /// the counterpart of [`Pose::position_rate`](crate::mechanism::Pose::position_rate).
    #[inline]
    pub fn velocity_ratio(&self) -> f64 {
        -self.e.y
    }
}
