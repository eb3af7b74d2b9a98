//! # slider-crank
//!
//! Exact kinematics, statics and the classical graphical constructions of the
//! slider-crank mechanism (textbook §34–37: the velocity line CE, Klein's and
//! Kisch's acceleration constructions, centrodes; Ng: the OM torque line).
//!
//! ## Conventions
//!
//! World frame: the crank centre C at the origin, the line of stroke
//! `y = e` (offset `e`, 0 for an in-line engine), the slider on the `+x`
//! side. The crank angle θ is counter-clockwise from `+x`; θ = 0 puts the
//! slider at its outer dead centre. ω > 0 turns the crank counter-clockwise.
//!
//! | point | textbook | Ng |
//! |---|---|---|
//! | crank centre | C | O |
//! | crank pin | B | C |
//! | cross-head | A | P |
//! | instantaneous centre of the rod | D | I |
//! | rod produced meets the vertical through C | E | M |
//!
//! Velocities and accelerations are signed: d x_A/dt, d² x_A/dt², dφ/dt,
//! d²φ/dt² with sin φ = (r sin θ − e)/l. Points at infinity are values
//! ([`geom::Intersection::AtInfinity`]), never NaN or 1e16. Lengths and
//! forces are in the user's units, which figures, tables and JSON name
//! ([`Units`]: names only, no number is converted).
//!
//! ```
//! use slider_crank::{Angle, Kinematics, SliderCrank};
//! let engine = SliderCrank::in_line(0.5, 3.0)?;          // §35: r = 0.5 ft, l = 3 ft
//! let pose = engine.pose(Angle::from_degrees(45.0)?);
//! let k = Kinematics::new(&pose, 26.16)?;               // the book's V_c / r
//! assert!((k.velocity + 10.3466).abs() < 1e-4);         // ft/s, towards C
//! # Ok::<(), slider_crank::Error>(())
//! ```
//!
//! ## Figures
//!
//! A [`Scene`] says what one figure shows; its layers ask for only the
//! constructions they draw. It builds an immutable [`Figure`] in world
//! coordinates, which [`render::to_svg`] writes with one world-to-page map
//! per panel (and [`render::to_png`] rasterises, [`render::to_pdf`] sets as
//! a vector page). The seeds' own figures
//! are named by [`FigureName`], and so are the diagrams (velocity and
//! acceleration against θ, time or position, polar diagrams, centrodes,
//! Ng's graphs), built by [`FigureName::figure`] from plot panels
//! ([`diagram::Plot`]) whose curves the curve engine traces to a tolerance
//! in page units.
//!
//! ```
//! use slider_crank::{FigureName, Layer, render::to_svg};
//! let scene = FigureName::Fig66Kisch.scene().unwrap(); // §35 engine at 60°
//! let (figure, computed) = scene.build()?;
//! assert_eq!(computed.instant_centre, 0);              // Kisch needs no D
//! let svg = to_svg(&figure);
//! // G is lettered in the enlarged detail of the construction.
//! assert!(svg.contains(r#"id="detail-point-G""#) && scene.has(Layer::Kisch));
//! # Ok::<(), slider_crank::Error>(())
//! ```
//!
//! A scene is fitted to its own pose; [`Scene::with_held_view`] holds its page
//! map over a range of poses and [`Scene::frames`] draws a series in one
//! such view (the whole revolution by default); [`animate::Animation`]
//! plays one revolution of such a series as a self-playing SVG or an HTML
//! page with a slider. [`SceneFile::from_toml`]
//! reads scene files, whose keys `docs/scene-format.md` lists
//! ([`SceneFile::keys`]); [`FigureName::scene_toml`] writes the file of a
//! named figure.
//!
//! ## The shape of the API
//!
//! - Builders cannot fail: [`Scene`]'s `with_*` methods take any value,
//!   and the settings that can be out of range are checked once, when the
//!   figure is built ([`Scene::build`], [`Scene::figure`],
//!   [`Scene::frames`]), with one `Result`. Values with rules of their own
//!   are checked where they are made ([`SliderCrank::new`],
//!   [`Angle::from_degrees`], [`Page::new`], [`construct::CouplerPoint::new`]).
//! - Angles: [`Angle::from_degrees`] for input (an error for NaN or
//!   infinity), [`Angle::deg`] for literals (`Angle::deg(30.0)`).
//! - Every value named on the command line and in scene files
//!   ([`FigureName`], [`Layer`], [`Style`], [`Notation`], [`Font`],
//!   [`catalogue::Fit`], [`Assembly`], [`table::Format`]) parses with
//!   `str::parse` and writes its name with `Display`, and the two
//!   round-trip; a wrong name is an [`Error::Invalid`] listing the names.
//!   A [`Unit`] (any name within its rules) parses and writes the same way.
//! - The results worth storing ([`Kinematics`],
//!   [`analytic::approx::Approximation`], [`analytic::calibration::LineFit`],
//!   [`analytic::statics::Friction`], [`construct::CheckRow`],
//!   [`construct::SweepReport`], [`LinkRates`], [`LinkMotion`],
//!   [`ConvergenceRow`], the chain's check rows) implement serde's
//!   `Serialize`.
//! - Enums and option structs that are expected to grow are
//!   `#[non_exhaustive]`: match them with a `_` arm, and build
//!   [`catalogue::FigureOptions`] and [`diagram::TraceOptions`] from their
//!   defaults by setting fields.
//! - [`Error::Io`] keeps the file and the operating system's error as its
//!   `source`.
//!
//! ## Features
//!
//! - `cli` (default): the `slider-crank` program (clap).
//! - `png` (default): PNG output through resvg ([`render::to_png`]; without
//!   the feature it returns [`Error::Unsupported`]).
//! - `pdf` (default): vector PDF output with the bundled faces embedded
//!   ([`render::to_pdf`]; without the feature it returns
//!   [`Error::Unsupported`]).
//! - `html` (default): the HTML pages and the faces they carry (maud,
//!   subsetter, base64): [`gallery`], [`handout`], an animation's page
//!   and an SVG with its faces embedded.
//! - `explore` (default; needs `cli` and `html`): the explorer's server,
//!   request reading and page ([`explore`]), served by `slider-crank
//!   explore` (httparse).
//! - `fonts` (default; `png`, `pdf` and `html` need it): the bundled
//!   faces' files ([`Font::data`]); without it text is measured from the
//!   glyph table alone.
//! - `bench` (not default): criterion, which the benchmarks in `benches/`
//!   need; the library does not use it.
//!
//! [`gallery`] makes every named figure in each format, the tables and an
//! `index.html` captioning each figure with the seed section it
//! reproduces. [`handout`] writes printable pages that work one engine
//! through §35–37 and Ng step by step, and exercise sheets with their
//! answer keys for a whole class.
//!
//! With `default-features = false` the crate computes every number and
//! writes SVG, with neither clap nor resvg nor the PDF writer among its
//! dependencies. The
//! design, the command-line contract and the JSON schema are in
//! `docs/design.md` in the repository.
#![deny(missing_docs)]
// No panic on a path from input: an `unwrap`, `expect`, index or slice
// outside the tests is allowed only where a comment proves it cannot fail
// (`tests/library/panic_free.rs` holds every allowance to one).
#![deny(clippy::unwrap_used, clippy::expect_used, clippy::indexing_slicing)]

pub mod analytic;
mod angle;
pub mod animate;
pub mod catalogue;
pub mod chain;
pub mod construct;
mod csv;
pub mod diagram;
pub mod dynamics;
mod error;
#[cfg(feature = "explore")]
pub mod explore;
pub mod figure;
pub mod files;
#[cfg(feature = "html")]
pub mod gallery;
pub mod geom;
#[cfg(feature = "html")]
pub mod handout;
#[cfg(feature = "html")]
mod html;
pub mod layout;
pub mod lists;

mod mechanism;
pub mod number;
pub mod render;
pub mod scene;
pub mod sources;
pub mod table;
mod units;

pub use analytic::kinematics::{Kinematics, MAX_OMEGA, omega_from_rpm, rpm_to_omega};
pub use angle::Angle;
pub use catalogue::{FigureName, SceneFile};
pub use chain::{
    Assembly, ChainCentres, ConvergenceRow, CrankReach, CylindricChain, CylindricPose,
    GrashofClass, Inversion, InversionPose, InvertedChain, LinkMotion, LinkRates, QuadricChain,
    QuadricPose, SlotConstruction, slot_convergence,
};
pub use error::{Error, Field, Input, Keys, Result, Spelling, Wording};
pub use figure::Style;
pub use figure::{Figure, Font};
pub use mechanism::{MAX_LENGTH, MIN_LENGTH, Pose, SliderCrank};
pub use scene::{Layer, Notation, Page, Scene};
pub use units::{MAX_UNIT_CHARS, Unit, Units};

/// The examples of README.md, compiled and run with the doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
mod readme {}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::catalogue::Fit;
    use crate::table::Format;
    use std::fmt::Display;
    use std::str::FromStr;

    fn round_trips<T>(all: &[T])
    where
        T: FromStr<Err = Error> + Display + PartialEq + std::fmt::Debug,
    {
        for x in all {
            assert_eq!(x.to_string().parse::<T>().as_ref(), Ok(x), "{x}");
        }
        let Err(Error::Invalid { message, .. }) = "no-such-name".parse::<T>() else {
            panic!("a wrong name is refused");
        };
        // The error names every value it would have taken.
        for x in all {
            let message = message.to_string();
            assert!(message.contains(&x.to_string()), "{message} lacks {x}");
        }
    }

    #[test]
    fn value_enums_round_trip_through_their_names() {
        round_trips(&[Style::Textbook, Style::Handout]);
        round_trips(&[Fit::Origin, Fit::Intercept, Fit::Both]);
        round_trips(&[
            crate::dynamics::Gravity::TowardsCrank,
            crate::dynamics::Gravity::AwayFromCrank,
        ]);
        round_trips(&FigureName::ALL);
        round_trips(&Layer::ALL);
        round_trips(&[Notation::Textbook, Notation::Ng]);
        round_trips(&[Assembly::Open, Assembly::Crossed]);
        round_trips(&[Format::Text, Format::Markdown, Format::Csv]);
        round_trips(&Font::ALL);
    }
}
