//! Figures: an immutable model of panels and primitives in world
//! coordinates and the [`Style`] they are drawn in, built by a
//! [`crate::scene::Scene`] or a [diagram](crate::catalogue) and written by the
//! [renderer](super::render).
//!
//! Data flows one way: scene → constructions its layers ask for → this
//! model → the renderer, which maps each panel's world to the page with the
//! panel's one [`PageFromWorld`].

mod font;
// Written by a test from the bundled faces (see the file), not by hand.
#[rustfmt::skip]
mod glyphs;
mod metadata;
mod metrics;
mod model;
mod page_length;
mod path;
mod style;
mod text;
mod transform;

pub use crate::error::is_noncharacter;
pub use font::{Font, FontStyle, TextBox};
pub use metadata::{AxisRecord, AxisScale, EngineRecord, Metadata, PlotRecord};
pub use metrics::VerticalMetrics;
pub use model::{
    Align, BEARING_FOOT, Dash, Figure, Foot, Hue, Item, Panel, Part, Role, Shape, Symbol, TextSize,
};
pub use page_length::{PageLength, PageUnit, UNITS_PER_INCH};
pub use path::{Path, PathBuilder, PathSegment};
pub use style::Style;
pub(crate) use style::{
    ANGLE_RADIUS, ANGLE_RADIUS_MOST, ARROW_LENGTH, DOT_RADIUS, HATCH_DEPTH, HATCH_SPACING,
    LETTER_SIZE, NOTE_LINE, NOTE_SIZE, PIN_PEN, PIN_RADIUS, Pen, RIGHT_ANGLE, SMALL_DETAIL_EMS,
    angle_radius,
};
pub use text::{
    MAX_TITLE_CHARS, RichText, Run, SUBSCRIPT_DROP, SUBSCRIPT_SIZE, SUPERSCRIPT_RISE, Title,
};
pub use transform::PageFromWorld;
