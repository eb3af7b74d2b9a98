//! The renderer: a [`crate::figure::Figure`] to SVG text (its own small
//! element writer), SVG to PNG (resvg, with the `png` feature) and to vector PDF
//! (with the `pdf` feature); files are written whole or not at all.

mod element;
#[cfg(any(feature = "png", feature = "pdf"))]
mod fonts;
mod format;
mod labels;
mod output;
#[cfg(feature = "pdf")]
mod pdf;
mod pending;
#[cfg(feature = "png")]
mod png;
mod save;
mod sizes;
mod svg;

pub use crate::number::plain;
pub use crate::number::{GRID, fmt};
pub(crate) use element::{Element, Node, escape_text};
#[cfg(any(feature = "png", feature = "pdf"))]
pub use fonts::font_database;
pub use format::FileFormat;
pub use output::{same_file, write_atomic, write_atomic_with, write_protected};
#[cfg(feature = "pdf")]
pub use pdf::{POINTS_PER_UNIT, to_pdf};
pub use pending::{Pending, make_pending, remove_pending, uninterrupted};
#[cfg(feature = "png")]
pub use png::to_png;
pub use save::save;
pub(crate) use svg::root_size;
pub use svg::to_svg;
#[cfg(feature = "html")]
pub use svg::to_svg_with_fonts;

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
