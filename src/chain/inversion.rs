//! The four inversions of the slider-crank chain, numbered by the fixed
//! link (textbook §34: "its different inversions form ... various types of
//! reciprocating steam-engines").
//!
//! The relative motion of the links is the same in every inversion; only
//! the link at rest and the link driven at constant speed change. So an
//! [`InversionPose`] is the chain at one relative position, given by θ, the
//! angle of the crank a against the frame d (as in the engine), seen from
//! the fixed link: its six virtual centres in that link's frame, and each
//! link's angular velocity and acceleration relative to it.

use super::centres::ChainCentres;
use crate::angle::Angle;
use crate::construct::Link;
use crate::error::{Error, Field, Result};
use crate::geom::{Point, Vector};
use crate::mechanism::{Pose, SliderCrank};
use std::f64::consts::PI;

/// An inversion of the slider-crank chain, by its fixed link.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Inversion {
    /// 1: the frame d fixed, the crank a driven: the direct-acting engine
    /// (today's [`SliderCrank`]). Frame: the world frame.
    Frame,
    /// 2: the crank a fixed, the rod b driven about O_ab; the frame d (the
    /// slotted link or the cylinders) turns fully about O_ad, the block c
    /// sliding on it: Whitworth's quick return, the Gnome rotary engine.
    /// Frame: O_ad at the origin, O_ab on +x.
    Crank,
    /// 3: the rod b fixed, the crank a driven about O_ab; the block c
    /// oscillates about O_bc with d sliding in it: the oscillating cylinder
    /// engine, the crank and slotted lever quick return. Frame: O_ab at the
    /// origin, O_bc on +x.
    Rod,
    /// 4: the slider c fixed, the rod b (the handle) driven about O_bc; d
    /// slides in c: the hand pump. Frame: O_bc at the origin, the stroke
    /// along +x.
    Slider,
}

impl Inversion {
    /// All four, in order.
    pub const ALL: [Inversion; 4] = [
        Inversion::Frame,
        Inversion::Crank,
        Inversion::Rod,
        Inversion::Slider,
    ];

    /// The inversion numbered 1 to 4; other numbers are an error.
    pub fn from_number(n: u32) -> Result<Self> {
        match n {
            1 => Ok(Inversion::Frame),
            2 => Ok(Inversion::Crank),
            3 => Ok(Inversion::Rod),
            4 => Ok(Inversion::Slider),
            _ => Err(Error::OutOfRange {
                name: Field::Inversion,
                value: n as f64,
                reason: "the inversions are numbered 1 (frame d fixed), 2 (crank a), 3 (rod b), 4 (slider c)".into(),
            }),
        }
    }

    /// Its number, 1 to 4.
    // cannot fail: ALL lists every variant.
    #[allow(clippy::expect_used)]
    pub fn number(&self) -> u32 {
        Self::ALL.iter().position(|i| i == self).expect("listed") as u32 + 1
    }

    /// The link at rest.
    pub fn fixed(&self) -> Link {
        match self {
            Inversion::Frame => Link::D,
            Inversion::Crank => Link::A,
            Inversion::Rod => Link::B,
            Inversion::Slider => Link::C,
        }
    }

    /// The link driven at constant angular speed relative to the fixed one.
    pub fn driver(&self) -> Link {
        match self {
            Inversion::Frame | Inversion::Rod => Link::A,
            Inversion::Crank | Inversion::Slider => Link::B,
        }
    }

    /// The mechanisms it makes, for reports.
    pub fn name(&self) -> &'static str {
        match self {
            Inversion::Frame => "direct-acting engine",
            Inversion::Crank => "rotating block: Whitworth quick return, Gnome engine",
            Inversion::Rod => "oscillating cylinder; crank and slotted lever quick return",
            Inversion::Slider => "hand pump",
        }
    }
}

/// The value of `link` in `values`, given for a, b, c, d in order.
fn of(values: &[f64; 4], link: Link) -> f64 {
    let [a, b, c, d] = *values;
    match link {
        Link::A => a,
        Link::B => b,
        Link::C => c,
        Link::D => d,
    }
}

/// A slider-crank chain with one of its links fixed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InvertedChain {
    mechanism: SliderCrank,
    inversion: Inversion,
}

impl InvertedChain {
    /// The chain of `mechanism` (already validated) with `inversion`'s link
    /// fixed.
    pub fn new(mechanism: SliderCrank, inversion: Inversion) -> Self {
        Self {
            mechanism,
            inversion,
        }
    }

    /// The chain's lengths.
    pub fn mechanism(&self) -> &SliderCrank {
        &self.mechanism
    }

    /// Which link is fixed.
    pub fn inversion(&self) -> Inversion {
        self.inversion
    }

    /// The chain at relative position θ (crank a against frame d).
    pub fn pose(&self, angle: Angle) -> InversionPose {
        InversionPose::new(self.inversion, self.mechanism.pose(angle))
    }

    /// The quick return's time ratio of inversions 3 (the crank and
    /// slotted lever) and 2 (Whitworth's): the driver (the crank a about
    /// B in 3, the rod b about B in 2) turns at constant speed relative to
    /// the fixed link; d reaches the ends of its swing (3) or of the tool's
    /// stroke it drives (2) where the crank is perpendicular to the stroke
    /// (θ = 90°, 270°), and the driver turns π + φ(270°) − φ(90°) between
    /// them one way and the rest of the turn the other: the ratio of the
    /// longer to the shorter, (π + 2 asin(r/l)) / (π − 2 asin(r/l)) in
    /// line for both (in Whitworth's, cos(α/2) = CB/BA = r/l for the
    /// return's angle α). `None` for inversions 1 and 4.
    pub fn time_ratio(&self) -> Option<f64> {
        if !matches!(self.inversion, Inversion::Rod | Inversion::Crank) {
            return None;
        }
        let phi = |d: f64| {
            // cannot fail: `d` is one of the finite angles of the sweep below.
            #[allow(clippy::expect_used)]
            let a = Angle::from_degrees(d).expect("finite");
            self.mechanism.pose(a).obliquity()
        };
        let one_way = PI + phi(270.0) - phi(90.0);
        let other = 2.0 * PI - one_way;
        Some(one_way.max(other) / one_way.min(other))
    }
}

/// Angular velocities and accelerations of the four links (a, b, c, d in
/// that order) relative to the fixed link, and the sliding of c on d, for
/// the driver turning at constant speed.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct LinkMotion {
    /// Angular velocities (counter-clockwise, rad/s) of a, b, c, d.
    pub velocity: [f64; 4],
    /// Angular accelerations (rad/s²) of a, b, c, d.
    pub acceleration: [f64; 4],
    /// Velocity of the block c along d (d x_A/dt of the engine).
    pub sliding_velocity: f64,
    /// Acceleration of c along d.
    pub sliding_acceleration: f64,
}

/// The chain at one relative position with one link fixed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InversionPose {
    inversion: Inversion,
    pose: Pose,
    centres: ChainCentres,
    /// Angular velocity of a, b, c, d relative to the fixed link, per unit
    /// dθ/dt.
    rates: [f64; 4],
    /// Their rates of change per unit (dθ/dt)² at constant dθ/dt.
    accels: [f64; 4],
    /// The fixed link's frame: its origin in the engine's frame and the
    /// rotation (cos, sin) from engine directions to its own.
    origin: Point,
    rotation: Vector,
}

impl InversionPose {
    fn new(inversion: Inversion, pose: Pose) -> Self {
        // In the engine's frame (d fixed): a turns at 1, b at −φ′, c and d
        // not at all.
        let engine = [1.0, -pose.obliquity_rate(), 0.0, 0.0];
        let engine_acc = [0.0, -pose.obliquity_acceleration(), 0.0, 0.0];
        let fixed = inversion.fixed();
        let rates = engine.map(|w| w - of(&engine, fixed));
        let accels = engine_acc.map(|w| w - of(&engine_acc, fixed));
        let (origin, turn) = frame_of(inversion, &pose);
        let centres = ChainCentres::of_slider_crank(&pose).moved(origin, turn);
        Self {
            inversion,
            pose,
            centres,
            rates,
            accels,
            origin,
            rotation: turn,
        }
    }

    /// The inversion.
    pub fn inversion(&self) -> Inversion {
        self.inversion
    }

    /// The engine's pose at the same relative position.
    pub fn engine_pose(&self) -> &Pose {
        &self.pose
    }

    /// A point of the engine's frame (d fixed) seen from the fixed link's
    /// frame: the rigid motion that [`InversionPose::centres`] applies.
    pub fn place(&self, p: Point) -> Point {
        Point::from(self.turn(p - self.origin))
    }

    /// A direction of the engine's frame turned into the fixed link's.
    pub fn turn(&self, v: Vector) -> Vector {
        let r = self.rotation;
        Vector::new(r.x * v.x - r.y * v.y, r.y * v.x + r.x * v.y)
    }

    /// The six virtual centres in the fixed link's frame (the same points of
    /// the chain as the engine's, moved rigidly).
    pub fn centres(&self) -> &ChainCentres {
        &self.centres
    }

    /// The angular velocity of `link` relative to the fixed link per unit
    /// dθ/dt (θ: crank a against frame d).
    pub fn link_rate(&self, link: Link) -> f64 {
        of(&self.rates, link)
    }

    /// d/dθ of [`InversionPose::link_rate`].
    pub fn link_acceleration(&self, link: Link) -> f64 {
        of(&self.accels, link)
    }

    /// The angular velocity of `p` relative to `q` per unit dθ/dt: the same
    /// in every inversion.
    pub fn relative_rate(&self, p: Link, q: Link) -> f64 {
        self.link_rate(p) - self.link_rate(q)
    }

    /// The motion for the driver ([`Inversion::driver`]) turning at constant
    /// `omega` relative to the fixed link; `None` where the driver is at
    /// rest relative to the fixed link for every dθ/dt (the hand pump's
    /// handle at the end of its swing, θ = 90°, 270°).
    pub fn motion(&self, omega: f64) -> Option<LinkMotion> {
        let driver = self.inversion.driver();
        let (k, k1) = (of(&self.rates, driver), of(&self.accels, driver));
        if k == 0.0 {
            return None;
        }
        let rate = omega / k;
        let accel = -omega * omega * k1 / (k * k * k);
        let s1 = self.pose.position_rate();
        let s2 = self.pose.position_acceleration();
        let mut acceleration = [0.0; 4];
        for (x, (a, w)) in acceleration
            .iter_mut()
            .zip(self.accels.iter().zip(&self.rates))
        {
            *x = a * rate * rate + w * accel;
        }
        Some(LinkMotion {
            velocity: self.rates.map(|w| w * rate),
            acceleration,
            sliding_velocity: s1 * rate,
            sliding_acceleration: s2 * rate * rate + s1 * accel,
        })
    }
}

/// The fixed link's frame: its origin in the engine's frame and the
/// rotation (cos, sin) that takes engine directions to its own.
fn frame_of(inversion: Inversion, pose: &Pose) -> (Point, Vector) {
    match inversion {
        Inversion::Frame => (pose.c(), Vector::new(1.0, 0.0)),
        Inversion::Crank => {
            let a = pose.angle();
            (pose.c(), Vector::new(a.cos(), -a.sin()))
        }
        Inversion::Rod => {
            // A − B = (w, −h) = l (cos φ, −sin φ).
            let rod = Vector::new(pose.run(), -pose.rise()) / pose.mechanism().rod();
            (pose.b(), Vector::new(rod.x, -rod.y))
        }
        Inversion::Slider => (pose.a(), Vector::new(1.0, 0.0)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_round_trip() {
        for (k, inv) in Inversion::ALL.iter().enumerate() {
            assert_eq!(inv.number(), k as u32 + 1);
            assert_eq!(Inversion::from_number(k as u32 + 1).unwrap(), *inv);
        }
        assert!(Inversion::from_number(0).is_err());
        assert!(Inversion::from_number(5).is_err());
    }

    #[test]
    fn slotted_lever_time_ratio_in_line() {
        let m = SliderCrank::in_line(1.0, 2.0).unwrap();
        let ratio = InvertedChain::new(m, Inversion::Rod).time_ratio().unwrap();
        // sin α = r/l = 1/2: α = 30°, (180 + 60)/(180 − 60) = 2.
        assert!((ratio - 2.0).abs() < 1e-15, "{ratio}");
        assert!(
            InvertedChain::new(m, Inversion::Frame)
                .time_ratio()
                .is_none()
        );
    }

    #[test]
    fn whitworth_time_ratio_in_line_and_with_an_offset() {
        // In line, cos(α/2) = r/l for the return's angle α: r/l = 1/2
        // gives α = 120° and (360 − 120)/120 = 2.
        let m = SliderCrank::in_line(1.0, 2.0).unwrap();
        let ratio = InvertedChain::new(m, Inversion::Crank)
            .time_ratio()
            .unwrap();
        assert!((ratio - 2.0).abs() < 1e-15, "{ratio}");
        // With an offset e the stroke's ends stand at φ = asin((r − e)/l)
        // and asin((−r − e)/l): the return takes π − asin((r − e)/l) −
        // asin((r + e)/l).
        let (r, l, e) = (1.0_f64, 3.0_f64, 0.4_f64);
        let m = SliderCrank::new(r, l, e).unwrap();
        let swing = ((r - e) / l).asin() + ((r + e) / l).asin();
        let expected = (PI + swing) / (PI - swing);
        let ratio = InvertedChain::new(m, Inversion::Crank)
            .time_ratio()
            .unwrap();
        assert!((ratio - expected).abs() < 1e-14, "{ratio} {expected}");
        assert!(
            InvertedChain::new(m, Inversion::Slider)
                .time_ratio()
                .is_none()
        );
    }

    #[test]
    fn fixed_link_is_at_rest_and_pins_on_it_stay_put() {
        let m = SliderCrank::new(1.0, 3.0, 0.2).unwrap();
        for inv in Inversion::ALL {
            let chain = InvertedChain::new(m, inv);
            let first = chain.pose(Angle::deg(10.0));
            let later = chain.pose(Angle::deg(130.0));
            assert_eq!(first.link_rate(inv.fixed()), 0.0);
            // The pins of the fixed link do not move in its frame.
            let pins: &[(Link, Link)] = match inv {
                Inversion::Frame => &[(Link::A, Link::D)],
                Inversion::Crank => &[(Link::A, Link::D), (Link::A, Link::B)],
                Inversion::Rod => &[(Link::A, Link::B), (Link::B, Link::C)],
                Inversion::Slider => &[(Link::B, Link::C)],
            };
            for &(p, q) in pins {
                let x = first.centres().centre(p, q).unwrap().point().unwrap();
                let y = later.centres().centre(p, q).unwrap().point().unwrap();
                assert!((x - y).norm() < 1e-14, "{inv:?} {p:?}{q:?}");
            }
        }
    }
}
