//! The quick-return mechanisms of inversions 2 and 3 (docs/quick-return.md):
//! the time ratio of the cutting to the return stroke from the geometry,
//! and the tool's (the ram's) position, velocity and acceleration over
//! both strokes.
//!
//! The tool is driven by the slotted link d through its arm of length L
//! (the lever): the arm's end P carries a pin that slides in a slot of
//! the ram square to its stroke, so the ram follows P's component along
//! the stroke exactly. The ram's stroke is square to the fixed link's line
//! of centres (B to A in inversion 3, C to B in inversion 2), and the arm
//! points along d away from the block: P = pivot − L u, u the slot's
//! direction (the engine's +x turned into the fixed link's frame). The
//! tool's position is s = L u · n less its value at mid-stroke, n the
//! line of centres turned a quarter turn counter-clockwise: s = L r sin θ
//! / l in inversion 3, −L sin θ in inversion 2. So measured, the tool
//! moves the + way on its cutting stroke (the driver turning
//! counter-clockwise) and the − way on its return.
//!
//! The strokes end where d stops turning against the fixed link, square
//! to the crank a: at θ = 90° and 270° in both inversions (θ the crank a
//! against the frame d, as everywhere), whatever the offset. In inversion
//! 2 the crank is the fixed link, so d is then square to the line of
//! centres; in inversion 3 d is tangent to the crank pin's circle. The driver (the crank a about B in
//! inversion 3, the rod b about B in inversion 2) turns through
//! π + φ(270°) − φ(90°) between them one way (the return, through
//! θ = 180°) and the rest of its turn the other (the cutting stroke): in
//! line, 180° − β and 180° + β with β = 2 asin(r/l), the arm's swing in
//! inversion 3.

use super::inversion::{Inversion, InversionPose, InvertedChain};
use crate::angle::Angle;
use crate::error::{Error, Field, Result};
use crate::geom::Vector;
use crate::mechanism::SliderCrank;
use std::f64::consts::{PI, TAU};

/// One of the two strokes of the tool.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Stroke {
    /// The slow stroke, the driver turning through the larger angle.
    Cutting,
    /// The quick stroke back.
    Return,
}

impl Stroke {
    /// Its name, `cutting` or `return`.
    pub fn name(self) -> &'static str {
        match self {
            Stroke::Cutting => "cutting",
            Stroke::Return => "return",
        }
    }
}

/// The tool's motion at one pose, for the driver at a constant speed.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct ToolMotion {
    /// The stroke under way (at the strokes' ends, θ = 90° and 270°, the
    /// one that begins there).
    pub stroke: Stroke,
    /// The driver's turn since the cutting stroke began, radians, from 0
    /// to 2π: the time since then times the driver's speed.
    pub driver_angle: f64,
    /// The tool's position from mid-stroke along its stroke, + the way
    /// it cuts (the unit of the lengths).
    pub position: f64,
    /// Its velocity (per second).
    pub velocity: f64,
    /// Its acceleration (per second squared).
    pub acceleration: f64,
}

/// A quick-return mechanism: inversion 2 (Whitworth's) or 3 (the crank and
/// slotted lever) of a slider-crank chain, with the arm L of d that drives
/// the tool.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct QuickReturn {
    chain: InvertedChain,
    lever: f64,
}

impl QuickReturn {
    /// The quick return of `mechanism` (already valid) with `inversion`'s
    /// link fixed and the arm `lever` long. Errors for inversions 1 and 4,
    /// which make no quick return, and for an arm that is not positive and
    /// finite.
    pub fn new(mechanism: SliderCrank, inversion: Inversion, lever: f64) -> Result<Self> {
        if !matches!(inversion, Inversion::Crank | Inversion::Rod) {
            return Err(Error::Unsupported(format!(
                "inversion {} makes no quick return: give inversion 2 (Whitworth’s) or 3 (the crank and slotted lever)",
                inversion.number()
            )));
        }
        let lever = crate::error::positive(Field::Lever, lever)?;
        Ok(Self {
            chain: InvertedChain::new(mechanism, inversion),
            lever,
        })
    }

    /// The arm's length when none is given: l + r, the lever of the crank
    /// and slotted lever reaching the crank pin's farthest place.
    pub fn default_lever(mechanism: &SliderCrank) -> f64 {
        mechanism.rod() + mechanism.crank()
    }

    /// The chain.
    pub fn chain(&self) -> &InvertedChain {
        &self.chain
    }

    /// The arm L.
    pub fn lever(&self) -> f64 {
        self.lever
    }

    /// The obliquity φ at `degrees` (a multiple of 90°, exact).
    fn phi(&self, degrees: f64) -> f64 {
        // cannot fail: the angles asked for are finite.
        #[allow(clippy::expect_used)]
        let a = Angle::from_degrees(degrees).expect("finite");
        self.chain.mechanism().pose(a).obliquity()
    }

    /// The driver's turn over the cutting and the return stroke, radians:
    /// π − φ(270°) + φ(90°) and π + φ(270°) − φ(90°).
    pub fn stroke_angles(&self) -> (f64, f64) {
        let back = PI + self.phi(270.0) - self.phi(90.0);
        (TAU - back, back)
    }

    /// The time of the cutting stroke over that of the return, at least 1:
    /// (180° + β)/(180° − β) in line, β = 2 asin(r/l).
    pub fn time_ratio(&self) -> f64 {
        let (cutting, back) = self.stroke_angles();
        cutting / back
    }

    /// The arm's projection L u · n at the strokes' ends, θ = 90° and
    /// 270°.
    fn ends(&self) -> (f64, f64) {
        let at = |d: f64| {
            // cannot fail: the angles asked for are finite.
            #[allow(clippy::expect_used)]
            let a = Angle::from_degrees(d).expect("finite");
            self.projection(&self.chain.pose(a))
        };
        (at(90.0), at(270.0))
    }

    /// The tool's stroke: 2 L r/l in inversion 3 (the arm's swing between
    /// its two tangents to the crank circle, whatever the offset), 2 L in
    /// inversion 2, where d turns fully.
    pub fn stroke_length(&self) -> f64 {
        let (a, b) = self.ends();
        (a - b).abs()
    }

    /// The arm's projection on the tool's stroke at `pose`: L u · n.
    fn projection(&self, pose: &InversionPose) -> f64 {
        let u = pose.turn(Vector::new(1.0, 0.0));
        self.lever * u.y
    }

    /// The tool's motion at relative position `angle` for the driver
    /// turning at `omega` rad/s (counter-clockwise when positive).
    pub fn at(&self, angle: Angle, omega: f64) -> ToolMotion {
        let pose = self.chain.pose(angle);
        let u = pose.turn(Vector::new(1.0, 0.0));
        let (w, alpha) = match pose.motion(omega) {
            Some(m) => (m.velocity[3], m.acceleration[3]),
            // cannot happen for inversions 2 and 3, whose driver turns
            // fully (rate 1 + φ′ > 0); at rest, then.
            None => (0.0, 0.0),
        };
        let l = self.lever;
        let (cutting, _) = self.stroke_angles();
        let driver = self.driver_angle(&pose);
        let (a, b) = self.ends();
        ToolMotion {
            stroke: if driver < cutting {
                Stroke::Cutting
            } else {
                Stroke::Return
            },
            driver_angle: driver,
            position: l * u.y - 0.5 * (a + b),
            velocity: l * w * u.x,
            acceleration: l * (alpha * u.x - w * w * u.y),
        }
    }

    /// The driver's turn since the cutting stroke began: θ turns up from
    /// 270° in inversion 3 (the crank a at θ + φ against the rod b) and
    /// down from 90° in inversion 2 (the rod b at −θ − φ against the crank
    /// a), the driver turning counter-clockwise.
    fn driver_angle(&self, pose: &InversionPose) -> f64 {
        let engine = pose.engine_pose();
        let theta = engine.angle().radians();
        let phi = engine.obliquity();
        let turn = match pose.inversion() {
            Inversion::Rod => (theta - 1.5 * PI).rem_euclid(TAU) + phi - self.phi(270.0),
            _ => (0.5 * PI - theta).rem_euclid(TAU) - phi + self.phi(90.0),
        };
        turn.clamp(0.0, TAU)
    }
}
