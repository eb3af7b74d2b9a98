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
