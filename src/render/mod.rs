//! The renderer: a [`crate::figure::Figure`], placed by
//! [`crate::layout::place`], to SVG text (its own small element writer) and
//! to a TikZ picture; SVG to PNG (resvg, with the `png` feature) and to
//! vector PDF (with the `pdf` feature); files are written whole or not at
//! all.

mod atomic;
mod element;
mod file_format;
#[cfg(any(feature = "png", feature = "pdf"))]
mod font_database;
#[cfg(feature = "pdf")]
mod pdf;
mod pending;
#[cfg(feature = "png")]
mod png;
mod save;
mod svg;
#[cfg(any(feature = "png", feature = "pdf"))]
mod svg_tree;
mod tikz;

pub use crate::number::plain;
pub use crate::number::{GRID, fmt};
pub use atomic::{
    no_link_at_derived, same_file, write_atomic, write_atomic_all, write_atomic_with,
    write_protected,
};
pub(crate) use element::{Element, Node, escape_text};
pub use file_format::FileFormat;
#[cfg(any(feature = "png", feature = "pdf"))]
pub use font_database::font_database;
#[cfg(feature = "pdf")]
pub use pdf::{POINTS_PER_UNIT, to_pdf};
pub use pending::{Pending, make_pending, remove_pending, uninterrupted};
#[cfg(feature = "png")]
pub use png::to_png;
pub use save::save;
pub(crate) use svg::root_size;
#[cfg(feature = "html")]
pub use svg::to_svg_with_fonts;
pub use svg::{SvgOptions, metadata_of, svg_body, to_svg, to_svg_with};
pub use tikz::{TikzOptions, to_tikz};

/// Renders SVG text to PNG bytes: built without the `png` feature, this
/// returns [`Error::Unsupported`](crate::error::Error::Unsupported) whatever the
/// input (build with `features = ["png"]` for PNG output).
#[cfg(not(feature = "png"))]
pub fn to_png(svg: &str, scale: f32) -> crate::error::Result<Vec<u8>> {
    let _ = (svg, scale);
    Err(crate::error::Error::Unsupported(
        "PNG output needs the `png` feature of slider-crank, which this build leaves out: write SVG instead".into(),
    ))
}

/// Renders SVG text to PDF bytes: built without the `pdf` feature, this
/// returns [`Error::Unsupported`](crate::error::Error::Unsupported) whatever the
/// input (build with `features = ["pdf"]` for PDF output).
#[cfg(not(feature = "pdf"))]
pub fn to_pdf(svg: &str) -> crate::error::Result<Vec<u8>> {
    let _ = svg;
    Err(crate::error::Error::Unsupported(
        "PDF output needs the `pdf` feature of slider-crank, which this build leaves out: write SVG instead".into(),
    ))
}

#[cfg(test)]
mod tests {
    #[cfg(not(feature = "png"))]
    #[test]
    fn png_without_the_feature_is_an_error_that_names_it() {
        let err = super::to_png("<svg/>", 1.0).unwrap_err();
        assert!(matches!(err, crate::error::Error::Unsupported(_)));
        assert!(err.to_string().contains("`png` feature"), "{err}");
    }

    #[cfg(not(feature = "pdf"))]
    #[test]
    fn pdf_without_the_feature_is_an_error_that_names_it() {
        let err = super::to_pdf("<svg/>").unwrap_err();
        assert!(matches!(err, crate::error::Error::Unsupported(_)));
        assert!(err.to_string().contains("`pdf` feature"), "{err}");
    }
}
