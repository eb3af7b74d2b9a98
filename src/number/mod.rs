//! Numbers as text, for every layer: in running text ([`plain`]), on the
//! SVG's grid of page coordinates ([`fmt`]), to fixed decimals as tables
//! print them ([`fixed`]), and set on a figure with one rule of
//! significant figures (`sig`, `short`, [`format_number`]).
//!
//! Each writer keeps every double, subnormals and the largest included,
//! to a bounded width: exponent form (or a power of ten on a figure) where
//! fixed notation would run to hundreds of digits, never `inf` or `NaN`.

mod figure;
mod fixed;
mod grid;
mod plain;

pub use figure::format_number;
pub(crate) use figure::{given, power_of_ten, short, sig};
// A page's numbers: the handout's (feature `html`).
#[cfg(feature = "html")]
pub(crate) use figure::{SetOn, short_on, sig_on};
pub use fixed::{angle_cell, fixed, significant};
pub use grid::{GRID, OnGrid, fmt, fmt_coefficient};
pub use plain::{MAX_FIXED_WIDTH, plain, unsigned_zero};
