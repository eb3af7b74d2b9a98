//! Glyph metrics of the bundled faces (stub, to be written by the test).

use super::font::VerticalMetrics;

/// The metrics of one face's style.
pub(super) struct GlyphTable {
    pub vertical: VerticalMetrics,
    pub chars: &'static [(char, [f64; 5])],
}

const EMPTY: GlyphTable = GlyphTable { vertical: VerticalMetrics { ascent: 0.0, descent: 0.0, cap_height: 0.0 }, chars: &[] };

pub(super) static TABLES: [&GlyphTable; 4] = [&EMPTY, &EMPTY, &EMPTY, &EMPTY];
