//! F and G, the end of Klein's and Kisch's constructions, and what they
//! give: CG for the piston acceleration, FG for the rod's.

use crate::geom::{Line, Point, Vector, cross};
use crate::mechanism::Pose;

/// F on the rod and G on the line through C parallel to the stroke, with FG
/// perpendicular to the rod.
///
/// With s = x_A the slider's position and θ the crank angle, G_x =
/// −d²s/dθ² (a second derivative against θ, not against time), so at a
/// constant crank speed ω the piston acceleration d²s/dt² = ω² d²s/dθ² is
/// ω² · CG directed from G towards C; |FG| = l |d²φ/dθ²|. G always exists
/// (the rod is never vertical, so its perpendicular is never horizontal).
/// The `_ratio` methods are these θ-derivatives: a rate per ω, or per ω²,
/// at constant ω.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AccelerationPoints {
    f: Point,
    g: Point,
    /// B − A.
    rod_dir: Vector,
    rod: f64,
}

impl AccelerationPoints {
    /// G from F: the perpendicular to AB at F meets the line through C
    /// parallel to the stroke.
    #[inline]
    pub(crate) fn from_f(pose: &Pose, f: Point) -> Self {
        let (a, b) = (pose.a(), pose.b());
        let rod_dir = b - a;
        let perpendicular = Line::from_parts(f, Vector::new(-rod_dir.y, rod_dir.x));
        let through_c = Line::from_parts(pose.c(), Vector::new(1.0, 0.0));
        // cannot fail: the perpendicular to the rod is horizontal only if the rod is vertical, which w > 0 rules out (see VelocityLine).
        #[allow(clippy::expect_used)]
        let g = perpendicular
            .intersect_eps(&through_c, 0.0)
            .point()
            .expect("the perpendicular to the rod is never horizontal");
        let rod = pose.mechanism().rod();
        Self { f, g, rod_dir, rod }
    }

    /// F, on the rod AB.
    #[inline]
    pub fn f(&self) -> Point {
        self.f
    }

    /// G, on the line through C parallel to the stroke.
    #[inline]
    pub fn g(&self) -> Point {
        self.g
    }

    /// The signed length CG along +x (G_x, C being the origin), in the
    /// mechanism's length unit. It equals −d²s/dθ², minus the second
    /// derivative of the slider's position s = x_A against the crank angle
    /// θ: the piston acceleration at constant ω is d²s/dt² = −ω² · CG.
    /// [`AccelerationPoints::acceleration_ratio`] gives d²s/dθ² itself.
    pub fn cg(&self) -> f64 {
        self.g.x
    }

    /// d²s/dθ², the second derivative of the slider's position s = x_A
    /// against the crank angle θ (length per rad²), read off the
    /// construction: −CG. Not a ratio of two accelerations: it is the
    /// piston acceleration per ω² at constant ω (d²s/dt² = ω² d²s/dθ²), the
    /// construction's counterpart of
    /// [`Pose::position_acceleration`](crate::mechanism::Pose::position_acceleration).
    #[inline]
    pub fn acceleration_ratio(&self) -> f64 {
        -self.g.x
    }

    /// The signed length FG, in the mechanism's length unit, positive when
    /// G is to the right of the direction from A to B. It equals
    /// l · d²φ/dθ² (φ the rod's obliquity): the rod's angular acceleration
    /// at constant ω is d²φ/dt² = ω² · FG / l.
    #[inline]
    pub fn fg(&self) -> f64 {
        cross(&(self.g - self.f), &self.rod_dir) / self.rod
    }

    /// d²φ/dθ², the second derivative of the rod's obliquity φ against the
    /// crank angle θ (dimensionless, per rad²), read off the construction:
    /// FG / l. The rod's angular acceleration per ω² at constant ω, the
    /// counterpart of
    /// [`Pose::obliquity_acceleration`](crate::mechanism::Pose::obliquity_acceleration).
    #[inline]
    pub fn rod_angular_acceleration_ratio(&self) -> f64 {
        self.fg() / self.rod
    }
}
