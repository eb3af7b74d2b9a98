//! F and G, the end of Klein's and Kisch's constructions, and what they
//! give: CG for the piston acceleration, FG for the rod's.

use crate::geom::{Line, Point, Vector, cross};
use crate::mechanism::Pose;

/// F on the rod and G on the line through C parallel to the stroke, with FG
/// perpendicular to the rod.
///
/// G_x = −d²s/dθ², so the piston acceleration is ω² · CG directed from G
/// towards C; |FG| = l |d²φ/dθ²|. G always exists (the rod is never
/// vertical, so its perpendicular is never horizontal).
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
    pub(crate) fn from_f(pose: &Pose, f: Point) -> Self {
        let (a, b) = (pose.a(), pose.b());
        let rod_dir = b - a;
        let perpendicular = Line::from_parts(f, Vector::new(-rod_dir.y, rod_dir.x));
        let through_c = Line::from_parts(pose.c(), Vector::new(1.0, 0.0));
        let g = perpendicular
            .intersect_eps(&through_c, 0.0)
            .point()
            .expect("the perpendicular to the rod is never horizontal");
        let rod = pose.mechanism().rod();
        Self { f, g, rod_dir, rod }
    }

    /// F, on the rod AB.
    pub fn f(&self) -> Point {
        self.f
    }

    /// G, on the line through C parallel to the stroke.
    pub fn g(&self) -> Point {
        self.g
    }

    /// Signed CG along +x (= −d²s/dθ²).
    pub fn cg(&self) -> f64 {
        self.g.x
    }

    /// d²s/dθ² read off the construction: −CG (acceleration = ω² CG from G
    /// towards C).
    pub fn acceleration_ratio(&self) -> f64 {
        -self.g.x
    }

    /// Signed length FG, positive when G is to the right of the direction
    /// from A to B. Rod angular acceleration = ω² · FG / l.
    pub fn fg(&self) -> f64 {
        cross(&(self.g - self.f), &self.rod_dir) / self.rod
    }

    /// d²φ/dθ² read off the construction, FG / l.
    pub fn rod_angular_acceleration_ratio(&self) -> f64 {
        self.fg() / self.rod
    }
}
