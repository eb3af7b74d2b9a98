//! The six virtual centres of the chain (Kennedy), and the velocity and
//! acceleration constructions carried over to the curved slot.
//!
//! For all three chains of Fig. 60 the centres are found "exactly as in the
//! case of the quadric crank-chain": the four pins O_ad = C, O_ab = B,
//! O_bc = A and O_cd, then by Kennedy's theorem O_bd on CB and on the lever
//! line O_cd A, and O_ac on the coupler line AB and on the frame line
//! C O_cd. For the straight slot O_cd is at infinity perpendicular to the
//! stroke, so the lever line is the perpendicular at A and the frame line
//! the perpendicular at C: O_bd = D and O_ac = E.
//!
//! Which constructions generalise to the curved slot (centre O_cd on the
//! perpendicular to the stroke through C, [`crate::chain::CylindricChain`]):
//!
//! - **E** carries over unchanged: O_ac is still where the rod produced meets
//!   the perpendicular through C, because O_cd lies on it. CE / CB is now the
//!   speed of the point of the *lever* at E over the crank pin's; the block,
//!   at radius ρ on the same lever, moves ρ / O_cd E times as fast:
//!   dσ/dθ = −CE / (1 + κ (CE − e)), exactly −CE at κ = 0.
//! - **D** (O_bd) carries over with the lever line for the perpendicular at
//!   A: the rod turns about D, and the block's velocity is the rod's angular
//!   velocity times DA, along the slot; the rod's is CB / BD as today.
//! - **Klein** carries over unchanged given the curved slot's D: its
//!   derivation uses only that D lies on CB and that E runs along a fixed
//!   line through C, so CG is again the rate of change of CE,
//!   d(CE)/dθ = G_x; differentiating the velocity above gives the block's
//!   acceleration along the slot, d²σ/dθ² = −(1 − κe) G_x / (1 + κ(CE − e))².
//! - **Kisch** does not carry over as it stands: BA · BF = BE² rests on AD
//!   being parallel to CE, which fails once the lever line at A tilts. The
//!   relation holds with A replaced by A*, where the parallel to CE through
//!   D meets the rod; finding A* needs D, and then Kisch is Klein's
//!   homothety again. So the curved slot has E, D and Klein, not Kisch.
//!
//! Each is cross-checked against the exact core in the tests and by
//! the command line's check of the slot.

use super::cylindric::CylindricPose;
use super::quadric::QuadricPose;
use crate::construct::{Link, kennedy_residual};
use crate::geom::{Intersection, Line, MeetJson, Point, Vector, perp};
use crate::mechanism::Pose;

/// The names of the six centres, in the order [`ChainCentres::all`] keeps.
pub const CENTRE_NAMES: [&str; 6] = ["O_ab", "O_ac", "O_ad", "O_bc", "O_bd", "O_cd"];

/// The six virtual centres O_ab, O_ac, O_ad, O_bc, O_bd, O_cd, each a point
/// or a point at infinity with its direction ([`Intersection::Coincident`]
/// where the two lines that should fix it are one line: O_bd and O_ac when
/// a quadric chain lies flat at a change point).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ChainCentres {
    centres: [Intersection; 6],
}

const PAIRS: [(Link, Link); 6] = [
    (Link::A, Link::B),
    (Link::A, Link::C),
    (Link::A, Link::D),
    (Link::B, Link::C),
    (Link::B, Link::D),
    (Link::C, Link::D),
];

impl ChainCentres {
    /// From the pins and the directions of the lever line at A (A − O_cd, or
    /// the slot's normal) and of the frame line at C (towards O_cd).
    fn from_pins(
        c: Point,
        b: Point,
        a: Point,
        o_cd: Intersection,
        lever: Vector,
        frame: Vector,
    ) -> Self {
        let o_bd = Line::from_parts(c, b - c).intersect(&Line::from_parts(a, lever));
        // Anchored at B, next to E (no cancellation when the offset is large).
        let o_ac = Line::from_parts(b, a - b).intersect(&Line::from_parts(c, frame));
        Self {
            centres: [
                Intersection::Point(b),
                o_ac,
                Intersection::Point(c),
                Intersection::Point(a),
                o_bd,
                o_cd,
            ],
        }
    }

    /// The straight slot: O_bd = D, O_ac = E, O_cd at infinity along (0, 1).
    pub fn of_slider_crank(pose: &Pose) -> Self {
        let up = Vector::new(0.0, 1.0);
        let o_cd = Intersection::AtInfinity(crate::geom::Direction::new_unchecked(up));
        Self::from_pins(pose.c(), pose.b(), pose.a(), o_cd, up, up)
    }

    /// The quadric chain: O_cd is the lever's pivot (d, 0).
    pub fn of_quadric(pose: &QuadricPose) -> Self {
        let chain = pose.chain();
        Self::from_pins(
            pose.c(),
            pose.b(),
            pose.a(),
            Intersection::Point(chain.lever_pivot()),
            pose.lever_vector(),
            Vector::new(1.0, 0.0),
        )
    }

    /// The curved (or straight) slot: O_cd the slot's centre.
    pub fn of_cylindric(pose: &CylindricPose) -> Self {
        Self::from_pins(
            pose.c(),
            pose.b(),
            pose.a(),
            pose.chain().slot_centre(),
            pose.lever_direction(),
            Vector::new(0.0, 1.0),
        )
    }

    /// The centre of links `p` and `q` (either order); `None` when p = q.
    pub fn centre(&self, p: Link, q: Link) -> Option<Intersection> {
        let (p, q) = if p <= q { (p, q) } else { (q, p) };
        PAIRS
            .iter()
            .zip(self.centres)
            .find(|&(&pair, _)| pair == (p, q))
            .map(|(_, centre)| centre)
    }

    /// All six, in the order of [`CENTRE_NAMES`].
    pub fn all(&self) -> &[Intersection; 6] {
        &self.centres
    }

    /// (name, centre) for all six.
    // cannot fail: `from_fn` makes an array of six, so i < 6, and both
    // arrays hold six.
    #[allow(clippy::indexing_slicing)]
    pub fn named(&self) -> [(&'static str, Intersection); 6] {
        std::array::from_fn(|i| (CENTRE_NAMES[i], self.centres[i]))
    }

    /// Kennedy's residuals for the four triples of links abc, abd, acd, bcd
    /// ([`kennedy_residual`]: 0 to rounding when the three centres are in one
    /// line).
    pub fn kennedy_residuals(&self) -> [f64; 4] {
        use Link::*;
        let triples = [(A, B, C), (A, B, D), (A, C, D), (B, C, D)];
        triples.map(|(x, y, z)| {
            // cannot fail: the triples name distinct links, and `centre` is `None` only for a link with itself.
            #[allow(clippy::expect_used)]
            let get = |p, q| self.centre(p, q).expect("distinct links");
            kennedy_residual(&get(x, y), &get(y, z), &get(x, z))
        })
    }

    /// The six as a JSON object keyed `O_ab` … `O_cd`: each `[x, y]`, or
    /// `{"at_infinity": [dx, dy]}`, or `{"indeterminate": true}` where two
    /// coincident lines leave it anywhere on a line (the same form in
    /// the analysis's JSON and in the figures' metadata).
    pub fn to_json(&self) -> serde_json::Value {
        let mut map = serde_json::Map::new();
        for (name, centre) in self.named() {
            let value = MeetJson(&centre, crate::number::unsigned_zero).value();
            map.insert(name.to_string(), value);
        }
        serde_json::Value::Object(map)
    }

    /// The centres seen from another link's frame: points mapped by the rigid
    /// motion `p ↦ rotation · (p − origin)`, directions turned by `rotation`
    /// (a unit complex number as (cos, sin)).
    pub fn moved(&self, origin: Point, rotation: Vector) -> Self {
        let turn = |v: Vector| {
            Vector::new(
                rotation.x * v.x - rotation.y * v.y,
                rotation.y * v.x + rotation.x * v.y,
            )
        };
        Self {
            centres: self.centres.map(|c| match c {
                Intersection::Point(p) => Intersection::Point(Point::from(turn(p - origin))),
                Intersection::AtInfinity(d) => {
                    Intersection::AtInfinity(crate::geom::Direction::new_normalize(turn(*d)))
                }
                Intersection::Coincident => Intersection::Coincident,
            }),
        }
    }
}

/// The velocity line CE, the rod's instantaneous centre D and Klein's
/// construction, drawn for the block in a curved slot (see the module
/// docs), each giving a θ-rate that the exact core also computes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SlotConstruction {
    centres: ChainCentres,
    b: Point,
    a: Point,
    tangent: Vector,
    /// Upward curvature −κ and the offset e.
    k: f64,
    e: f64,
}

impl SlotConstruction {
    /// Builds E, D (and Klein's F and G when asked) for `pose`.
    pub fn construct(pose: &CylindricPose) -> Self {
        Self {
            centres: ChainCentres::of_cylindric(pose),
            b: pose.b(),
            a: pose.a(),
            tangent: pose.tangent(),
            k: -pose.chain().curvature(),
            e: pose.chain().mechanism().offset(),
        }
    }

    /// The six centres.
    pub fn centres(&self) -> &ChainCentres {
        &self.centres
    }

    /// E = O_ac, when finite (the rod is not parallel to CE).
    pub fn e(&self) -> Option<Point> {
        self.centres.centre(Link::A, Link::C)?.point()
    }

    /// D = O_bd (a point, or at infinity where CB is parallel to the lever).
    // cannot fail: B and D are distinct links.
    #[allow(clippy::expect_used)]
    pub fn d(&self) -> Intersection {
        self.centres.centre(Link::B, Link::D).expect("distinct")
    }

    /// 1 + κ(CE − e) = O_cd E / O_cd A, the lever's radius at E over the
    /// block's.
    fn radius_ratio(&self, ce: f64) -> f64 {
        1.0 - self.k * (ce - self.e)
    }

    /// dσ/dθ from E: −CE / (1 + κ(CE − e)).
    pub fn arc_rate_from_e(&self) -> Option<f64> {
        let ce = self.e()?.y;
        Some(-ce / self.radius_ratio(ce))
    }

    /// The rod's counter-clockwise angular velocity per unit crank rate from
    /// D: CB / BD signed, 0 when D is at infinity.
    fn rod_turn(&self) -> Option<f64> {
        match self.d() {
            Intersection::Point(d) => {
                let bd = self.b - d;
                Some(self.b.coords.dot(&bd) / bd.norm_squared())
            }
            Intersection::AtInfinity(_) => Some(0.0),
            Intersection::Coincident => None,
        }
    }

    /// dφ/dθ from D (the seeds' sign: minus the rod's counter-clockwise
    /// rate CB/BD).
    pub fn obliquity_rate_from_d(&self) -> Option<f64> {
        self.rod_turn().map(|w| -w)
    }

    /// dσ/dθ from D: the rod turns about D, so the block moves at the rod's
    /// rate times DA, along the slot (at the crank pin's velocity when D is
    /// at infinity and the rod translates).
    pub fn arc_rate_from_d(&self) -> Option<f64> {
        let velocity = match self.d() {
            Intersection::Point(d) => perp(&(self.a - d)) * self.rod_turn()?,
            Intersection::AtInfinity(_) => perp(&self.b.coords),
            Intersection::Coincident => return None,
        };
        Some(velocity.dot(&self.tangent))
    }

    /// Klein's G: through C draw CF parallel to DE, F on AB (by the
    /// homothety about B taking D to C); FG perpendicular to AB meets the
    /// line through C parallel to the stroke at G. `None` where D or E is
    /// not a finite point.
    pub fn klein_g(&self) -> Option<Point> {
        let d = self.d().point()?;
        let e = self.e()?;
        let bd = d - self.b;
        let f = self.b + (e - self.b) * ((-self.b.coords).dot(&bd) / bd.norm_squared());
        let rod = self.a - self.b;
        let normal = Line::from_parts(f, perp(&rod));
        let stroke = Line::from_parts(Point::origin(), Vector::new(1.0, 0.0));
        normal.intersect_eps(&stroke, 0.0).point()
    }

    /// d²σ/dθ² from Klein's CG: −(1 − κe) G_x / (1 + κ(CE − e))².
    pub fn arc_acceleration_from_klein(&self) -> Option<f64> {
        let g = self.klein_g()?;
        let ratio = self.radius_ratio(self.e()?.y);
        Some(-(1.0 + self.k * self.e) * g.x / (ratio * ratio))
    }
}

/// The sine of the angle between two vectors (for tests of collinearity).
#[cfg(test)]
fn sine(u: Vector, v: Vector) -> f64 {
    crate::geom::cross(&u, &v) / (u.norm() * v.norm())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::chain::{Assembly, CylindricChain, QuadricChain};
    use crate::{angle::Angle, mechanism::SliderCrank};

    #[test]
    fn straight_slot_centres_match_the_existing_constructions() {
        use crate::construct::{InstantCentre, VelocityLine, VirtualCentres};
        let m = SliderCrank::new(1.0, 3.0, 0.3).unwrap();
        for d in [0.0, 30.0, 90.0, 200.0, 270.0] {
            let pose = m.pose(Angle::deg(d));
            let old = VirtualCentres::construct(
                &pose,
                &InstantCentre::construct(&pose),
                &VelocityLine::construct(&pose),
            );
            let new = ChainCentres::of_slider_crank(&pose);
            for (p, q, c) in old.all() {
                let mine = new.centre(*p, *q).unwrap();
                match (c, mine) {
                    (Intersection::Point(x), Intersection::Point(y)) => {
                        assert!((x - y).norm() < 1e-14 * (1.0 + x.coords.norm()), "{d}")
                    }
                    (Intersection::AtInfinity(x), Intersection::AtInfinity(y)) => {
                        assert!(sine(x.into_inner(), y.into_inner()).abs() < 1e-15)
                    }
                    other => panic!("{d}: {other:?}"),
                }
            }
        }
    }

    #[test]
    fn kennedy_holds_for_a_quadric_chain() {
        let m = QuadricChain::new(1.0, 3.0, 2.5, 3.2).unwrap();
        for d in (0..360).step_by(15) {
            for mode in [Assembly::Open, Assembly::Crossed] {
                let c = ChainCentres::of_quadric(&m.pose(Angle::deg(d as f64), mode).unwrap());
                for r in c.kennedy_residuals() {
                    assert!(r.abs() < 1e-14, "{d} {mode:?}: {r}");
                }
            }
        }
    }

    #[test]
    fn slot_constructions_give_the_exact_rates() {
        let m = SliderCrank::new(1.0, 2.5, 0.4).unwrap();
        for rho in [2.0, -2.0, 7.0, 1e6] {
            let slot = CylindricChain::new(m, rho).unwrap();
            for d in (0..360).step_by(10) {
                let p = slot.pose(Angle::deg(d as f64));
                let s = SlotConstruction::construct(&p);
                let tol = 1e-12 * (1.0 + p.arc_acceleration().abs());
                assert!((s.arc_rate_from_e().unwrap() - p.arc_rate()).abs() < tol);
                assert!((s.arc_rate_from_d().unwrap() - p.arc_rate()).abs() < tol);
                assert!((s.obliquity_rate_from_d().unwrap() - p.obliquity_rate()).abs() < tol);
                if let Some(acc) = s.arc_acceleration_from_klein() {
                    assert!((acc - p.arc_acceleration()).abs() < tol, "{rho} {d}");
                }
            }
        }
    }
}
