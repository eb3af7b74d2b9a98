//! Coupler points: points of the rod between A and B, which trace ovals,
//! and points of the rod's plane off its line.

use crate::error::{Error, Field, Result};
use crate::geom::{Point, Vector, perp};
use crate::mechanism::Pose;

/// The most a coupler point stands off the rod's line, in rod lengths.
const MOST_ACROSS: f64 = 100.0;

/// The point A + t (B − A) + h J(B − A) of the rod (the connecting rod as
/// a plate), t in [0, 1] along it (0 at the cross-head, 1 at the crank
/// pin) and h across it, both in lengths AB, J the quarter turn
/// counter-clockwise (h > 0 to the left of A → B). With h = 0, t = 0
/// traces the line of stroke, t = 1 the crank circle, and every point
/// between an oval (textbook §34).
///
/// Its image in the velocity or acceleration polygon is the same
/// combination of the images of A and B, a + t (b − a) + h J(b − a)
/// ([`CouplerPoint::image`]): the triangle abq is similar to ABQ, turned
/// the same way (the velocity and acceleration images).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CouplerPoint {
    t: f64,
    h: f64,
}

impl CouplerPoint {
    /// The coupler point at fraction `t` from A to B; an
    /// [`Error::OutOfRange`] unless 0 ≤ t ≤ 1 (NaN included).
    pub fn new(t: f64) -> Result<Self> {
        if (0.0..=1.0).contains(&t) {
            Ok(Self { t, h: 0.0 })
        } else {
            Err(Error::OutOfRange {
                name: Field::Coupler,
                value: t,
                reason: "the coupler point is a fraction of the rod from A (0) to B (1)".into(),
            })
        }
    }

    /// The point at fraction `t` along the rod from A and `across` rod
    /// lengths off its line (to the left of A → B where positive); an
    /// [`Error::OutOfRange`] unless 0 ≤ t ≤ 1 and |across| ≤ 100 (NaN
    /// included). `across` = 0 is [`CouplerPoint::new`].
    pub fn off_rod(t: f64, across: f64) -> Result<Self> {
        let point = Self::new(t)?;
        if across.abs() <= MOST_ACROSS {
            Ok(Self { h: across, ..point })
        } else {
            Err(Error::OutOfRange {
                name: Field::Coupler,
                value: across,
                reason: "a coupler point stands at most 100 rod lengths off the rod's line".into(),
            })
        }
    }

    /// The fraction t along the rod.
    pub fn t(&self) -> f64 {
        self.t
    }

    /// Its distance off the rod's line, in rod lengths (0 on the rod).
    pub fn across(&self) -> f64 {
        self.h
    }

    /// The point of the rod's plane that stands to `a` and `b` as this
    /// point to A and B: a + t (b − a) + h J(b − a). Applied to the
    /// positions, the velocities or the accelerations of A and B (the
    /// rod is rigid, so J turns their differences with it), it gives
    /// this point's.
    pub fn image(&self, a: Vector, b: Vector) -> Vector {
        let ab = b - a;
        a + ab * self.t + perp(&ab) * self.h
    }

    /// Its position at `pose`.
    pub fn point(&self, pose: &Pose) -> Point {
        let (a, b) = (pose.a(), pose.b());
        Point::from(self.image(a.coords, b.coords))
    }

    /// Its exact derivative with respect to θ at `pose`.
    pub fn derivative(&self, pose: &Pose) -> Vector {
        let r = pose.mechanism().crank();
        let (s, c) = (pose.angle().sin(), pose.angle().cos());
        let xa = pose.position_rate();
        self.image(Vector::new(xa, 0.0), Vector::new(-r * s, r * c))
    }

    /// Its exact second derivative with respect to θ at `pose` (its
    /// acceleration per ω² at constant ω): A″ + t (B″ − A″) + h J(B″ − A″), with
    /// A″ = (d²s/dθ², 0) from the analytic core and B″ = −r (cos θ, sin θ).
    pub fn second_derivative(&self, pose: &Pose) -> Vector {
        let r = pose.mechanism().crank();
        let (s, c) = (pose.angle().sin(), pose.angle().cos());
        let xa = pose.position_acceleration();
        self.image(Vector::new(xa, 0.0), Vector::new(-r * c, -r * s))
    }
}
