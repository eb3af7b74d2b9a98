//! The slider-crank chain as a whole (textbook §34, Fig. 60): the quadric
//! crank chain (a), the block in a curved slot (b), the straight slot (c),
//! their six virtual centres, and the four inversions.
//!
//! Links (textbook letters): a crank, b coupler or connecting rod, c lever
//! or slider block, d frame. Pins: C = O_ad, B = O_ab, A = O_bc; O_cd is the
//! lever's pivot, the slot's centre, or the point at infinity on the
//! perpendicular to a straight stroke.
//!
//! One concept per file: [`QuadricChain`] (four lengths, both assembly
//! modes, Grashof class, reach, toggles and change points),
//! [`CylindricChain`] (the curved slot, computed from its curvature so that
//! κ = 0 is today's [`crate::mechanism::SliderCrank`]), [`ChainCentres`] (the six
//! virtual centres of any of them, Kennedy's theorem, and the velocity and
//! acceleration constructions carried over to the curved slot),
//! [`InvertedChain`] (the four inversions), [`CoriolisPolygon`] (the
//! polygons of inversions 2 and 3 with the Coriolis component) and
//! [`QuickReturn`] (their quick returns: the time ratio and the tool's
//! motion over the strokes).

mod centres;
mod check;
mod coriolis;
mod cylindric;
mod inversion;
mod quadric;
mod quick_return;

pub use centres::{CENTRE_NAMES, ChainCentres, SlotConstruction};
pub use check::{
    ChainCheckRow, arc_position_by_iteration, coriolis_sweep, quadric_sweep, slot_sweep,
};
pub use coriolis::CoriolisPolygon;
pub use cylindric::{ConvergenceRow, CylindricChain, CylindricPose, slot_convergence};
pub use inversion::{Inversion, InversionPose, InvertedChain, LinkMotion};
pub use quadric::{
    Assembly, CLOSURE_TOLERANCE, CrankReach, GrashofClass, LinkRates, QuadricChain, QuadricPose,
};
pub use quick_return::{QuickReturn, Stroke, ToolMotion};
