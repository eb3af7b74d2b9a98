//! Diagrams in page space: curves traced to a tolerance, clipped to a plot
//! area, and measured against the exact curve.
//!
//! A curve comes from the analytic core as a point and its exact derivative
//! against a parameter ([`Curve`]; the mechanism's own are [`Locus`], in
//! degrees of crank angle). [`trace`] maps it to the page with a panel's
//! page-from-world [`Affine`] map and draws it as cubic Béziers (or, for
//! comparison, line segments) within a tolerance in page units
//! ([`DEFAULT_TOLERANCE`] = 0.01), clipped to a [`Frame`](crate::geom::Frame);
//! poles and cusps are handled (see [`curve`](self::trace) docs). The result is
//! a [`Path`] in page coordinates, which maps back to world coordinates
//! exactly through the inverse map. [`measure`] checks a path against the
//! exact curve independently of how it was made.
//!
//! ```
//! use slider_crank::SliderCrank;
//! use slider_crank::diagram::{Affine, Locus, LocusKind, Method, TraceOptions, measure, trace};
//! use slider_crank::geom::{Frame, Point};
//!
//! let engine = SliderCrank::in_line(0.5, 3.0)?;
//! let curve = Locus::new(engine, LocusKind::PolarVelocity);
//! // 300 px per ft, y down, C at (200, 200) on a 400 × 400 page.
//! let map = Affine::scale_translate(300.0, -300.0, 200.0, 200.0).unwrap();
//! let frame = Frame::new(Point::new(0.0, 0.0), Point::new(400.0, 400.0));
//! let options = TraceOptions::default();
//! let path = trace(&curve, 0.0..=360.0, &map, &frame, Method::Cubic, &options)?;
//! let deviation = measure(&path, &curve, 0.0..=360.0, &map, &frame);
//! assert!(deviation.max() <= options.tolerance);
//! # Ok::<(), slider_crank::Error>(())
//! ```

mod affine;
mod curve;
mod locus;
mod measure;
mod path;

pub use affine::Affine;
pub use curve::{Curve, DEFAULT_TOLERANCE, Method, TraceOptions, trace};
pub use locus::{Locus, LocusKind};
pub use measure::{Deviation, measure};
pub use path::{Path, Segment, Subpath};
