//! The font database of PNG and PDF output: the bundled faces only, so
//! that no system font is ever loaded and the text is set in the face the
//! SVG names on every machine.

use crate::figure::Font;
use std::sync::{Arc, OnceLock};
use usvg::fontdb::{Database, Source};

/// Loads every bundled face ([`Font::files`] of each [`Font`], in order,
/// which is the order usvg falls back in) into `db`, straight from the
/// bytes in the binary.
pub(crate) fn load_bundled(db: &mut Database) {
    for font in Font::ALL {
        for data in font.files() {
            db.load_font_source(Source::Binary(Arc::new(data)));
        }
    }
    db.set_serif_family(Font::default().family());
}

/// The font database [`to_png`](super::to_png) and
/// [`to_pdf`](super::to_pdf) set text with: the bundled faces only, loaded
/// once (for reading the SVG with usvg or resvg directly).
pub fn font_database() -> Arc<Database> {
    static FONTS: OnceLock<Arc<Database>> = OnceLock::new();
    FONTS
        .get_or_init(|| {
            let mut db = Database::new();
            load_bundled(&mut db);
            Arc::new(db)
        })
        .clone()
}
