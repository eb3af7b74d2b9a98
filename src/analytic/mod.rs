//! The analytic core: exact kinematics at constant crank speed, the
//! textbook's approximations with their errors, statics after Ng, and the
//! calibration fit of Ng's Table 1.

pub mod approx;
pub mod calibration;
pub mod harmonics;
pub mod kinematics;
pub mod statics;
