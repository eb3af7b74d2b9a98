//! The renderer: a [`crate::figure::Figure`] to SVG text (the `svg`
//! crate), and SVG to PNG (resvg); files are written whole or not at all.

mod labels;
mod number;
mod output;
mod png;
mod sizes;
mod svg;

pub use number::{GRID, fmt, plain};
pub use output::write_atomic;
pub use png::{font_database, to_png};
pub use svg::to_svg;

pub(crate) use sizes::NOTE_LINE;
