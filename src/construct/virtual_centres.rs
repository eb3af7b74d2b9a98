//! The six virtual centres of the slider-crank chain and Kennedy's theorem.

use super::{InstantCentre, VelocityLine};
use crate::geom::{Direction, Intersection, Vector};
use crate::mechanism::Pose;

/// The links of the chain (textbook letters).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Link {
    /// The crank.
    A,
    /// The connecting rod.
    B,
    /// The slider (cross-head).
    C,
    /// The frame.
    D,
}

/// The six virtual centres O_ad = C, O_ab = B, O_bc = A, O_cd (at infinity,
/// perpendicular to the stroke), O_bd = D (at infinity at θ = 90°, 270°),
/// O_ac = E. Each is a finite point or a point at infinity.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct VirtualCentres {
    centres: [(Link, Link, Intersection); 6],
}

impl VirtualCentres {
    /// All six centres of `pose`.
    pub fn construct(pose: &Pose, d: &InstantCentre, e: &VelocityLine) -> Self {
        let up = Direction::new_unchecked(Vector::new(0.0, 1.0));
        use Link::*;
        Self {
            centres: [
                (A, D, Intersection::Point(pose.c())),
                (A, B, Intersection::Point(pose.b())),
                (B, C, Intersection::Point(pose.a())),
                (C, D, Intersection::AtInfinity(up)),
                (B, D, d.d()),
                (A, C, Intersection::Point(e.e())),
            ],
        }
    }

    /// The centre of relative motion of links `p` and `q` (`p != q`, in
    /// either order); `None` when `p == q`.
    pub fn centre(&self, p: Link, q: Link) -> Option<Intersection> {
        let (p, q) = if p <= q { (p, q) } else { (q, p) };
        self.centres
            .iter()
            .find(|(x, y, _)| *x == p && *y == q)
            .map(|c| c.2)
    }

    /// All six, as (link, link, centre).
    pub fn all(&self) -> &[(Link, Link, Intersection); 6] {
        &self.centres
    }
}

/// Homogeneous coordinates of a centre, scaled to unit size.
fn homogeneous(c: &Intersection) -> [f64; 3] {
    match c {
        Intersection::Point(p) => {
            let s = 1.0 / (1.0 + p.coords.norm());
            [p.x * s, p.y * s, s]
        }
        Intersection::AtInfinity(d) => [d.x, d.y, 0.0],
        Intersection::Coincident => [0.0, 0.0, 0.0],
    }
}

/// Kennedy's theorem: the three virtual centres of any three links lie on
/// one line. Returns the determinant of their normalised homogeneous
/// coordinates, zero (to rounding) when they are collinear; points at
/// infinity take part as directions.
pub fn kennedy_residual(p: &Intersection, q: &Intersection, r: &Intersection) -> f64 {
    let (a, b, c) = (homogeneous(p), homogeneous(q), homogeneous(r));
    a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
        + a[2] * (b[0] * c[1] - b[1] * c[0])
}
