//! The polygons of a Coriolis figure's pose as drawn: each point from
//! the pole with its letter, the vectors between them, the side each
//! polygon is about, and the values read off them.

use crate::chain::{CoriolisPolygon, Inversion};
use crate::figure::Role;
use crate::geom::Vector;

/// The share of a polygon's size below which a value read off it is its
/// rounding and is written 0.
pub(super) const ROUNDING: f64 = 1e-10;

/// The polygons of a pose, as drawn: each point from the pole, and how
/// each is lettered.
pub(super) struct Polygons {
    pub(super) inversion: Inversion,
    pub(super) p: CoriolisPolygon,
    /// The length CA, from the crank centre to the block's pin.
    pub(super) ca: f64,
}

/// A point of a polygon: its id (ASCII), its letter as markup, where.
pub(super) type Lettered = (&'static str, &'static str, Vector);

/// A vector of a polygon: its id, its role, from, to.
pub(super) type Arrow = (&'static str, Role, Vector, Vector);

/// The side of a polygon the figure is about: from, to.
pub(super) type Subject = (Vector, Vector);

impl Polygons {
    /// The velocity polygon's points: o, the driven point's image, a_d.
    pub(super) fn velocity_points(&self) -> Vec<Lettered> {
        let p = &self.p;
        let driven = match self.inversion {
            Inversion::Rod => ("c", "*c*"),
            _ => ("a", "*a*"),
        };
        vec![
            ("o", "*o*", Vector::zeros()),
            (driven.0, driven.1, p.driven()),
            ("ad", "*a*_{d}", p.a_d()),
        ]
    }

    /// The velocity polygon's vectors: the driven point's velocity, the
    /// meet of the line ⟂ CA and the slot's line, the sliding velocity
    /// heavier.
    pub(super) fn velocity_arrows(&self) -> Vec<Arrow> {
        let p = &self.p;
        let o = Vector::zeros();
        match self.inversion {
            Inversion::Rod => vec![
                ("velocity-oc", Role::Construction, o, p.driven()),
                ("velocity-cad", Role::Construction, p.driven(), p.a_d()),
                ("velocity-oad", Role::Result, o, p.a_d()),
            ],
            _ => vec![
                ("velocity-oa", Role::Construction, o, p.driven()),
                ("velocity-oad", Role::Construction, o, p.a_d()),
                ("velocity-ada", Role::Result, p.a_d(), p.driven()),
            ],
        }
    }

    /// The end k of the Coriolis component: from o′ in inversion 3, back
    /// from a′ in inversion 2.
    pub(super) fn k(&self) -> Vector {
        let p = &self.p;
        match self.inversion {
            Inversion::Rod => p.coriolis(),
            _ => p.driven_acceleration() - p.coriolis(),
        }
    }

    /// The acceleration polygon's points: o′, the driven point's image,
    /// n, k, a′_d.
    pub(super) fn acceleration_points(&self) -> Vec<Lettered> {
        let p = &self.p;
        let driven = match self.inversion {
            Inversion::Rod => ("c2", "*c*′"),
            _ => ("a2", "*a*′"),
        };
        vec![
            ("o2", "*o*′", Vector::zeros()),
            (driven.0, driven.1, p.driven_acceleration()),
            ("n", "*n*", p.n()),
            ("k", "*k*", self.k()),
            ("ad2", "*a*′_{d}", p.a_d_acceleration()),
        ]
    }

    /// The acceleration polygon's vectors: the driven point's
    /// centripetal acceleration, d's normal and tangential components,
    /// the Coriolis component and the sliding acceleration, and the
    /// acceleration of d's point at A heavier.
    pub(super) fn acceleration_arrows(&self) -> Vec<Arrow> {
        let p = &self.p;
        let o = Vector::zeros();
        let (n, k, ad) = (p.n(), self.k(), p.a_d_acceleration());
        match self.inversion {
            Inversion::Rod => vec![
                (
                    "acceleration-oc",
                    Role::Construction,
                    o,
                    p.driven_acceleration(),
                ),
                (
                    "acceleration-cn",
                    Role::Construction,
                    p.driven_acceleration(),
                    n,
                ),
                ("acceleration-nad", Role::Construction, n, ad),
                ("acceleration-coriolis", Role::Construction, o, k),
                ("acceleration-kad", Role::Construction, k, ad),
                ("acceleration-oad", Role::Result, o, ad),
            ],
            _ => vec![
                (
                    "acceleration-oa",
                    Role::Construction,
                    o,
                    p.driven_acceleration(),
                ),
                ("acceleration-on", Role::Construction, o, n),
                ("acceleration-nad", Role::Construction, n, ad),
                ("acceleration-adk", Role::Construction, ad, k),
                (
                    "acceleration-coriolis",
                    Role::Construction,
                    k,
                    p.driven_acceleration(),
                ),
                ("acceleration-oad", Role::Result, o, ad),
            ],
        }
    }

    /// The normal component's foot: c′ in inversion 3 (c′n from the
    /// crank pin's image), o′ in inversion 2.
    pub(super) fn normal_from(&self) -> Vector {
        match self.inversion {
            Inversion::Rod => self.p.driven_acceleration(),
            _ => Vector::zeros(),
        }
    }

    /// The largest vector of the velocity polygon (`false`) or of the
    /// acceleration polygon (`true`): the scale below which a value read
    /// off it is the construction's rounding.
    pub(super) fn size(&self, acceleration: bool) -> f64 {
        let points = if acceleration {
            self.acceleration_points()
        } else {
            self.velocity_points()
        };
        points.iter().map(|p| p.2.norm()).fold(0.0, f64::max)
    }

    /// `x`, a value read off the velocity (`acceleration` false) or the
    /// acceleration polygon times `length`, or 0 where it is below
    /// [`ROUNDING`] of the polygon's size (ω_d at the lever's extremes
    /// comes out 3e-15 rad/s, not 0).
    pub(super) fn clean(&self, x: f64, length: f64, acceleration: bool) -> f64 {
        if (x * length).abs() <= ROUNDING * self.size(acceleration) {
            0.0
        } else {
            x
        }
    }

    /// The velocity polygon's subject, the sliding velocity: o a_d in
    /// inversion 3, a_d a in inversion 2; `None` where it is nil.
    pub(super) fn velocity_subject(&self) -> Option<Subject> {
        let p = &self.p;
        let side = match self.inversion {
            Inversion::Rod => (Vector::zeros(), p.a_d()),
            _ => (p.a_d(), p.driven()),
        };
        (self.clean((side.1 - side.0).norm(), 1.0, false) > 0.0).then_some(side)
    }

    /// The acceleration polygon's subject, the Coriolis component: o′k in
    /// inversion 3, ka′ in inversion 2; `None` where it is nil.
    pub(super) fn acceleration_subject(&self) -> Option<Subject> {
        let p = &self.p;
        let side = match self.inversion {
            Inversion::Rod => (Vector::zeros(), self.k()),
            _ => (self.k(), p.driven_acceleration()),
        };
        (self.clean(p.coriolis().norm(), 1.0, true) > 0.0).then_some(side)
    }

    /// The sliding velocity v whose turn gives the Coriolis component: d's
    /// point relative to the block in inversion 3, the block relative to
    /// d in inversion 2, as a vector along the slot.
    pub(super) fn v(&self) -> Vector {
        match self.inversion {
            Inversion::Rod => -self.p.slot() * self.p.sliding_velocity(),
            _ => self.p.slot() * self.p.sliding_velocity(),
        }
    }
}
