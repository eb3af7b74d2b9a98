//! SVG to PNG through resvg, with the system's fonts loaded once.

use crate::error::{Error, Result};
use resvg::{tiny_skia, usvg};
use std::sync::{Arc, OnceLock};

fn fonts() -> Arc<usvg::fontdb::Database> {
    static FONTS: OnceLock<Arc<usvg::fontdb::Database>> = OnceLock::new();
    FONTS
        .get_or_init(|| {
            let mut db = usvg::fontdb::Database::new();
            db.load_system_fonts();
            db.set_serif_family("DejaVu Serif");
            Arc::new(db)
        })
        .clone()
}

/// Most pixels of a PNG (24 megapixels, 96 MB of canvas: a 2400 × 2400
/// page at scale 2). A larger picture is refused with a message, never
/// allocated.
pub const MAX_PNG_PIXELS: u64 = 24_000_000;

/// Renders SVG text to PNG bytes at `scale` pixels per page unit (1 for
/// the page size, 2 for a sharper picture). Letters use the system's
/// serif fonts; without any, lines are still drawn.
pub fn to_png(svg: &str, scale: f32) -> Result<Vec<u8>> {
    if !(scale.is_finite() && scale > 0.0 && scale <= 16.0) {
        return Err(Error::OutOfRange {
            name: "scale",
            value: scale as f64,
            reason: "a PNG scale is between 0 and 16".into(),
        });
    }
    let options = usvg::Options {
        fontdb: fonts(),
        ..usvg::Options::default()
    };
    let tree = usvg::Tree::from_str(svg, &options)
        .map_err(|e| Error::Parse(format!("cannot read the SVG: {e}")))?;
    let size = tree
        .size()
        .to_int_size()
        .scale_by(scale)
        .ok_or_else(|| Error::OutOfRange {
            name: "scale",
            value: scale as f64,
            reason: "the picture would be empty".into(),
        })?;
    let pixels = u64::from(size.width()) * u64::from(size.height());
    if pixels > MAX_PNG_PIXELS {
        return Err(Error::OutOfRange {
            name: "PNG size",
            value: pixels as f64,
            reason: format!(
                "a PNG of {} × {} pixels is more than the {} megapixels this program draws: make the page smaller, or write SVG",
                size.width(),
                size.height(),
                MAX_PNG_PIXELS / 1_000_000
            ),
        });
    }
    let mut pixmap =
        tiny_skia::Pixmap::new(size.width(), size.height()).ok_or_else(|| Error::OutOfRange {
            name: "scale",
            value: scale as f64,
            reason: "the picture would be too large".into(),
        })?;
    resvg::render(
        &tree,
        tiny_skia::Transform::from_scale(scale, scale),
        &mut pixmap.as_mut(),
    );
    pixmap
        .encode_png()
        .map_err(|e| Error::Io(format!("cannot encode PNG: {e}")))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn huge_pages_are_refused_before_drawing() {
        // Issue 9 (8): a 20000 × 20000 page took 12 GB.
        let svg = r#"<svg xmlns="http://www.w3.org/2000/svg" width="20000" height="20000"/>"#;
        let err = to_png(svg, 2.0).unwrap_err().to_string();
        assert!(
            err.contains("a PNG of 40000 × 40000 pixels is more than the 24 megapixels"),
            "{err}"
        );
        let small = r#"<svg xmlns="http://www.w3.org/2000/svg" width="100" height="50"/>"#;
        assert!(to_png(small, 2.0).unwrap().starts_with(b"\x89PNG"));
    }
}
