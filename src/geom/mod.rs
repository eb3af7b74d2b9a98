//! Plane geometry in f64 on nalgebra: infinite lines whose intersection may
//! be a point, a point at infinity or the whole line; circles; clipping to an
//! axis-aligned frame.

mod circle;
mod clip;
mod line;
mod meet_json;
mod outline;
mod segment;
mod side_by_side;

pub use circle::{Circle, CircleIntersection};
pub use clip::Frame;
pub use line::{Intersection, Line, PARALLEL_TOLERANCE};
pub use meet_json::{MeetJson, PointJson};
pub(crate) use outline::inside_outline;
pub(crate) use segment::{
    crossing, farthest_from_segment, point_segment_distance, segment_distance, unit,
};
pub(crate) use side_by_side::{side_by_side, side_by_side_ends};

/// A point of the world (or page) plane.
pub type Point = nalgebra::Point2<f64>;
/// A vector of the plane.
pub type Vector = nalgebra::Vector2<f64>;
/// A unit vector: a direction, for example of a point at infinity.
pub type Direction = nalgebra::Unit<Vector>;

/// The z-component of the cross product of two plane vectors.
#[inline]
pub fn cross(a: &Vector, b: &Vector) -> f64 {
    a.x * b.y - a.y * b.x
}

/// `v` turned a quarter turn counter-clockwise.
#[inline]
pub fn perp(v: &Vector) -> Vector {
    Vector::new(-v.y, v.x)
}
