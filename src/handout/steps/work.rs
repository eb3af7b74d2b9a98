//! What the steps share: the engine, its reading and the names of its
//! units.

use crate::construct::Reading;
use crate::handout::Handout;
use crate::{mechanism::Pose, mechanism::SliderCrank};

/// Units of a page.
pub(super) struct Names {
    pub length: String,
    pub velocity: String,
    pub acceleration: String,
    pub force: String,
    pub torque: String,
}

impl Names {
    /// The names of `h`'s units.
    pub fn of(h: &Handout) -> Self {
        let u = h.units();
        Self {
            length: u.length().as_str().to_string(),
            velocity: u.velocity(),
            acceleration: u.acceleration(),
            force: u.force().as_str().to_string(),
            torque: u.torque(),
        }
    }
}

/// The engine being worked, everything read at its pose and the names of
/// its units: what every step and its rows are made from.
pub(super) struct Work<'a> {
    /// The engine at its angle, with its speed, units and torque.
    pub h: &'a Handout,
    /// Everything read at the pose.
    pub r: &'a Reading,
    /// The names of the units.
    pub n: Names,
}

impl<'a> Work<'a> {
    /// `h` worked from `r`, its reading.
    pub fn new(h: &'a Handout, r: &'a Reading) -> Self {
        Self {
            h,
            r,
            n: Names::of(h),
        }
    }

    /// The mechanism.
    pub fn mechanism(&self) -> &SliderCrank {
        self.h.mechanism()
    }

    /// The pose worked.
    pub fn pose(&self) -> &Pose {
        &self.r.pose
    }

    /// The name of the unit of length (`ft`, `mm`).
    pub fn length(&self) -> &str {
        &self.n.length
    }

    /// The crank speed ω in rad/s.
    pub fn omega(&self) -> f64 {
        self.h.omega()
    }

    /// The speed of the crank pin, *V*_c = *r*ω.
    pub fn vc(&self) -> f64 {
        self.mechanism().crank() * self.omega()
    }

    /// Whether the line of stroke passes through the crank centre: only
    /// then does a step set the textbook's approximations beside the exact
    /// values.
    pub fn in_line(&self) -> bool {
        self.mechanism().offset() == 0.0
    }
}
