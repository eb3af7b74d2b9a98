//! The renderer: a [`crate::figure::Figure`] to SVG text (the `svg`
//! crate), and SVG to PNG (resvg, with the `png` feature); files are
//! written whole or not at all.

mod labels;
mod number;
mod output;
#[cfg(feature = "png")]
mod png;
mod sizes;
mod svg;

pub use number::{GRID, fmt, plain};
pub use output::write_atomic;
#[cfg(feature = "png")]
pub use png::{font_database, to_png};
pub use svg::to_svg;

/// Renders SVG text to PNG bytes: built without the `png` feature, this
/// returns [`Error::Unsupported`](crate::Error::Unsupported) whatever the
/// input (build with `features = ["png"]` for PNG output).
#[cfg(not(feature = "png"))]
pub fn to_png(svg: &str, scale: f32) -> crate::Result<Vec<u8>> {
    let _ = (svg, scale);
    Err(crate::Error::Unsupported(
        "PNG output needs the `png` feature of slider-crank, which this build leaves out: write SVG instead".into(),
    ))
}

pub(crate) use sizes::NOTE_LINE;

#[cfg(all(test, not(feature = "png")))]
mod tests {
    #[test]
    fn png_without_the_feature_is_an_error_that_names_it() {
        let err = super::to_png("<svg/>", 1.0).unwrap_err();
        assert!(matches!(err, crate::Error::Unsupported(_)));
        assert!(err.to_string().contains("`png` feature"), "{err}");
    }
}
