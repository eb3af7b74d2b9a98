//! The fixed and moving centrodes of the rod (textbook Fig. 61).

use crate::geom::{Direction, Intersection, Point, Vector};
use crate::mechanism::Pose;

/// Which centrode of the rod b.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CentrodeKind {
    /// The locus of D = O_bd in the frame d (the textbook's full line).
    Fixed,
    /// The locus of D in the rod's own frame (the dotted curve): origin A,
    /// x along A→B, y a quarter turn counter-clockwise from it.
    Moving,
}

/// A centrode as a curve parameterised by the crank angle θ, with exact
/// derivatives.
///
/// Poles: both centrodes run off to infinity as θ → 90° and 270°, where
/// D is at infinity; there the point is [`Intersection::AtInfinity`] and
/// the derivative `None`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Centrode {
    kind: CentrodeKind,
}

impl Centrode {
    /// The centrode of the given kind.
    pub fn new(kind: CentrodeKind) -> Self {
        Self { kind }
    }

    /// Which one.
    pub fn kind(&self) -> CentrodeKind {
        self.kind
    }

    /// The crank angles (degrees) where the centrode has a pole.
    pub fn poles_degrees() -> [f64; 2] {
        [90.0, 270.0]
    }

    /// k = D_y − e = x_A tan θ − e and its θ-derivative; `None` at a pole.
    fn height(pose: &Pose) -> Option<(f64, f64)> {
        let (s, c) = (pose.angle().sin(), pose.angle().cos());
        if c == 0.0 {
            return None;
        }
        let x = pose.position();
        let tan = s / c;
        let k = x * tan - pose.mechanism().offset();
        let dk = pose.position_rate() * tan + x / (c * c);
        (k.is_finite() && dk.is_finite()).then_some((k, dk))
    }

    /// The centrode point at `pose`, at infinity at a pole.
    pub fn point(&self, pose: &Pose) -> Intersection {
        let Some((k, _)) = Self::height(pose) else {
            return Intersection::AtInfinity(self.asymptote(pose));
        };
        match self.kind {
            CentrodeKind::Fixed => {
                Intersection::Point(Point::new(pose.position(), pose.mechanism().offset() + k))
            }
            CentrodeKind::Moving => {
                let l = pose.mechanism().rod();
                Intersection::Point(Point::new(k * pose.rise() / l, -k * pose.run() / l))
            }
        }
    }

    /// The exact derivative with respect to θ; `None` at a pole.
    pub fn derivative(&self, pose: &Pose) -> Option<Vector> {
        let (k, dk) = Self::height(pose)?;
        Some(match self.kind {
            CentrodeKind::Fixed => Vector::new(pose.position_rate(), dk),
            CentrodeKind::Moving => {
                let l = pose.mechanism().rod();
                let r = pose.mechanism().crank();
                let dh = r * pose.angle().cos();
                let dw = -pose.rise() * dh / pose.run();
                Vector::new(
                    (dk * pose.rise() + k * dh) / l,
                    -(dk * pose.run() + k * dw) / l,
                )
            }
        })
    }

    /// The direction in which the point runs off at a pole (the direction of
    /// the crank for the fixed centrode; the rod's normal for the moving).
    fn asymptote(&self, pose: &Pose) -> Direction {
        let s = pose.angle().sin();
        match self.kind {
            CentrodeKind::Fixed => Direction::new_normalize(Vector::new(0.0, s.signum())),
            CentrodeKind::Moving => {
                Direction::new_normalize(Vector::new(pose.rise() * s, -pose.run() * s))
            }
        }
    }
}
