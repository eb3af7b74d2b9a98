//! A figure's SVG read once, for every format drawn from it: usvg parses
//! the text and lays its letters out in the bundled faces, which is about
//! a third of making a PNG and most of making a PDF, so a figure written
//! as both is read once ([`crate::gallery::Gallery::build`]).

use super::font_database::font_database;
use crate::error::{Error, Input, Result};
use std::sync::Arc;
use usvg::fontdb::Database;

/// SVG text read into usvg's tree, its letters laid out in the faces of
/// `fontdb` (the bundled ones, [`font_database`], everywhere but in tests
/// that prove no other face is reached). Errors: SVG that cannot be read.
pub(crate) fn read_with(svg: &str, fontdb: Arc<Database>) -> Result<usvg::Tree> {
    let options = usvg::Options {
        fontdb,
        ..usvg::Options::default()
    };
    usvg::Tree::from_str(svg, &options)
        .map_err(|e| Error::invalid(Input::Svg, format!("cannot read the SVG: {e}")))
}

/// SVG text read into usvg's tree, its letters laid out in the bundled
/// faces. Errors: SVG that cannot be read.
pub(crate) fn read(svg: &str) -> Result<usvg::Tree> {
    read_with(svg, font_database())
}
