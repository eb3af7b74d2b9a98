//! Diagrams in page space: curves traced to a tolerance, clipped to a plot
//! area, and measured against the exact curve.
//!
//! A curve comes from the analytic core as a point and its exact derivative
//! against a parameter ([`Curve`]; the mechanism's own are [`Locus`], in
//! degrees of crank angle). [`trace`] maps it to the page with a panel's
//! page-from-world map ([`crate::figure::PageFromWorld`], the same map the figure panels use) and draws it as cubic Béziers (or, for
//! comparison, line segments) within a tolerance in page units
//! ([`DEFAULT_TOLERANCE`] = 0.01), clipped to a [`Frame`](crate::geom::Frame).
//! The result is a [`TracedPath`] in page coordinates, which maps to world
//! coordinates and back exactly through the map's inverse
//! ([`TracedPath::transform`]). [`measure()`] checks a path against the exact curve
//! independently of how it was made.
//!
//! # How a piece is fitted
//!
//! The curve's point and derivative are mapped to the page (the derivative
//! by the linear part of the map). A piece `[t0, t1]` of the parameter, of
//! length `h`, is sampled with exact derivatives at nine parameters
//! `u = k/8`. The first candidate is the cubic Hermite Bézier
//! `P0 = p(t0)`, `P1 = P0 + p′(t0) h/3`, `P2 = P3 − p′(t1) h/3`,
//! `P3 = p(t1)`. Its error `e(u) = B(u) − p(t0 + u h)` against the curve at
//! the same parameter bounds the geometric distance from above; at the
//! samples `e` and its exact derivative `e′` are known, and on each eighth
//! the cubic Hermite interpolant of `e` lies in the convex hull of its four
//! Bézier points, whose largest norm is the bound. It is exact up to the
//! fourth-order remainder of an eighth of the piece: only a bump narrower
//! than an eighth that also escapes the samples could go unseen.
//!
//! When that parametric bound exceeds the tolerance, two geometric bounds
//! are tried, of the same form but with the cubic reparameterised by φ, the
//! Hermite interpolant of each sample's nearest parameter on the cubic (so
//! that the tangential drift between two parameterisations does not count):
//! one for the Hermite cubic, one for a second candidate with the same end
//! tangents whose lengths make it pass through the middle sample. Since
//! B∘φ covers the whole cubic, its distance from the curve bounds the
//! Hausdorff distance both ways. They are used only where φ is as smooth as
//! the curve (the tangent turns by less than 15° per eighth, φ increases
//! with slopes near its secants and stays in [0, 1]); the candidate with the
//! least bound is kept if it is within the tolerance, and the piece is
//! halved otherwise (its even samples become the halves' samples, so a
//! halving costs eight evaluations). The polyline methods bound the chord's
//! deviation by the largest distance from the chord to the curve's Hermite
//! hull points (distance to a segment is convex, so the hull's vertices
//! bound it).
//!
//! # Clipping, poles and cusps
//!
//! A piece is fitted only between two points inside the frame. Where the
//! curve crosses the frame's edge, or stops being defined (at a pole the
//! curve returns `None`, and its points run off the page before it), the
//! crossing is found by bisection on the exact curve to within an eighth of
//! the tolerance; the subpath ends there and a new one starts where the
//! curve comes back. Parts with both ends outside are skipped when the hull
//! of their Hermite cubic, grown by twice its measured error at the
//! midpoint, misses the frame, and halved otherwise, so a brief pass through
//! a corner is found. So no segment ever spans a pole and nothing is drawn
//! across the page. At a cusp (zero derivative) the Hermite fit still
//! converges: its error falls with the fourth power of the piece's length.
//! Every halving is bounded by [`TraceOptions::max_depth`] and the output by
//! [`TraceOptions::max_segments`]; when they are not enough the trace
//! reports an error instead of looping.
//!
//! ```
//! use slider_crank::SliderCrank;
//! use slider_crank::diagram::{Locus, LocusKind, Method, TraceOptions, measure, trace};
//! use slider_crank::figure::PageFromWorld;
//! use slider_crank::geom::{Frame, Point};
//!
//! let engine = SliderCrank::in_line(0.5, 3.0)?;
//! let curve = Locus::new(engine, LocusKind::PolarVelocity);
//! // 300 px per ft, y down, C at (200, 200) on a 400 × 400 page.
//! let map = PageFromWorld::scale_translate(300.0, -300.0, 200.0, 200.0).unwrap();
//! let frame = Frame::new(Point::new(0.0, 0.0), Point::new(400.0, 400.0));
//! let options = TraceOptions::default();
//! let path = trace(&curve, 0.0..=360.0, &map, &frame, Method::Cubic, &options)?;
//! let deviation = measure(&path, &curve, 0.0..=360.0, &map, &frame);
//! assert!(deviation.max() <= options.tolerance);
//! # Ok::<(), slider_crank::Error>(())
//! ```

mod axis;
mod curve;
mod locus;
mod measure;
mod path;
mod plot;

pub use crate::number::format_number;
pub use axis::{Axis, Scale, Tick};
pub(crate) use curve::evaluations_on_this_thread;
pub use curve::{Curve, DEFAULT_TOLERANCE, Method, TraceOptions, trace, trace_tolerance};
pub use locus::{Locus, LocusKind};
pub use measure::{Deviation, measure};
pub use path::{Segment, Subpath, TracedPath};
pub use plot::Plot;
pub(crate) use plot::{CAPTION, LEGEND_GAP};
