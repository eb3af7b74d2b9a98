//! The graphical constructions of textbook §36–37 and Ng's paper, built as
//! geometry and read off as lengths.
//!
//! One construction per file. Each computes only what it needs (Kisch never
//! builds D) and reports its derived quantity as a rate with respect to the
//! crank angle θ; multiply by ω or ω² for time rates. [`cross_check`] sets
//! every value read off a construction beside the analytic core's;
//! [`Reading`] holds everything read at one pose (what `analyze` prints).

mod acceleration;
mod acceleration_polygon;
mod bennett;
mod centrode;
mod check;
mod coupler;
mod instant_centre;
mod kisch;
mod klein;
mod reading;
mod ritterhaus;
mod torque;
mod velocity_line;
mod velocity_polygon;
mod virtual_centres;

pub use acceleration::AccelerationPoints;
pub use acceleration_polygon::AccelerationPolygon;
pub use bennett::Bennett;
pub use centrode::{Centrode, CentrodeKind};
pub use check::{CheckRow, Quantity, SweepReport, condition, cross_check, sweep};
pub use coupler::CouplerPoint;
pub use instant_centre::InstantCentre;
pub use kisch::Kisch;
pub use klein::Klein;
#[cfg(feature = "html")]
pub(crate) use reading::check_load;
pub use reading::{Graphical, Reading, Statics};
pub use ritterhaus::Ritterhaus;
pub use torque::TorqueLine;
pub use velocity_line::VelocityLine;
pub use velocity_polygon::VelocityPolygon;
pub use virtual_centres::{Link, VirtualCentres, kennedy_residual};
