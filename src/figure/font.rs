//! The bundled type: the faces a figure is set in, their files (from the
//! `typst-assets` crate, so nothing depends on the fonts of the machine)
//! and text measured with their own glyph metrics.
//!
//! The default is New Computer Modern, the face of LaTeX books: most
//! readers of these figures are textbook authors writing in LaTeX, whose
//! body text and formulas are set in Computer Modern, so the letters on a
//! figure match the θ, φ and *AB* of the page around it. Libertinus Serif
//! is the alternative for books set in Linux Libertine or similar faces.

use super::metrics::VerticalMetrics;
use crate::error::{Error, Input, Result};
use serde::Deserialize;
#[cfg(feature = "fonts")]
use skrifa::instance::{LocationRef, Size};
#[cfg(feature = "fonts")]
use skrifa::metrics::GlyphMetrics;
#[cfg(feature = "fonts")]
use skrifa::string::StringId;
#[cfg(feature = "fonts")]
use skrifa::{FontRef, GlyphId, MetadataProvider};
use std::collections::HashMap;
use std::fmt;
use std::str::FromStr;
use std::sync::{Mutex, OnceLock};

/// A bundled face, chosen by the field [`crate::Field::Font`] (a scene
/// file's `font` key).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default, Deserialize)]
#[serde(rename_all = "kebab-case")]
#[non_exhaustive]
pub enum Font {
    /// New Computer Modern (10 pt design size), the look of LaTeX books.
    #[default]
    NewComputerModern,
    /// Libertinus Serif, a Linux Libertine descendant; a little darker
    /// and narrower than Computer Modern.
    LibertinusSerif,
}

/// Upright or italic.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum FontStyle {
    /// Upright (roman).
    #[default]
    Regular,
    /// Italic (point letters, variables).
    Italic,
}

impl FontStyle {
    /// [`FontStyle::Italic`] if `italic`, else [`FontStyle::Regular`].
    pub fn from_italic(italic: bool) -> Self {
        if italic {
            FontStyle::Italic
        } else {
            FontStyle::Regular
        }
    }
}

/// The extent of a set text, in page units, from the start of its
/// baseline.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct TextBox {
    /// The sum of the glyph advances.
    pub width: f64,
    /// The highest ink above the baseline.
    pub above: f64,
    /// The lowest ink below the baseline (positive below).
    pub below: f64,
    /// Where the ink begins, from the start of the baseline (negative
    /// where the first glyph reaches back before it); 0 for a text with
    /// no ink.
    pub left: f64,
    /// Where the ink ends, from the start of the baseline: past
    /// [`TextBox::width`] where the last glyph overhangs its advance, as an
    /// italic capital does; 0 for a text with no ink.
    pub right: f64,
}

impl TextBox {
    /// The box of `self` followed on the same line by `next`.
    pub fn then(self, next: TextBox) -> TextBox {
        let (left, right) = match (self.has_ink(), next.has_ink()) {
            (_, false) => (self.left, self.right),
            (false, true) => (self.width + next.left, self.width + next.right),
            (true, true) => (
                self.left.min(self.width + next.left),
                self.right.max(self.width + next.right),
            ),
        };
        TextBox {
            width: self.width + next.width,
            above: self.above.max(next.above),
            below: self.below.max(next.below),
            left,
            right,
        }
    }

    /// Whether any glyph leaves ink (not only spaces).
    fn has_ink(&self) -> bool {
        self.right > self.left
    }
}

/// One face parsed once: its character map, advances and ink bounds.
#[cfg(feature = "fonts")]
struct Face {
    font: FontRef<'static>,
    glyphs: GlyphMetrics<'static>,
    units_per_em: f64,
}

/// What the text measures need of one character in one style, in ems:
/// its advance, its ink bottom, top, left and right (from its origin), and
/// whether a face has it.
#[derive(Debug, Clone, Copy)]
struct CharMetrics {
    advance: f64,
    bottom: f64,
    top: f64,
    left: f64,
    right: f64,
    present: bool,
}

#[cfg(feature = "fonts")]
impl Face {
    // cannot fail: only the faces compiled in are parsed (`bundled`), and the tests parse every one.
    #[allow(clippy::expect_used)]
    fn parse(data: &'static [u8]) -> Face {
        let font = FontRef::new(data).expect("a bundled font parses");
        let m = font.metrics(Size::unscaled(), LocationRef::default());
        Face {
            glyphs: font.glyph_metrics(Size::unscaled(), LocationRef::default()),
            units_per_em: f64::from(m.units_per_em),
            font,
        }
    }

    /// Ascent, descent and cap height, in ems (what the glyph table
    /// holds).
    #[cfg(test)]
    fn vertical(&self) -> VerticalMetrics {
        let m = self.font.metrics(Size::unscaled(), LocationRef::default());
        let em = |v: f32| f64::from(v) / self.units_per_em;
        VerticalMetrics {
            ascent: em(m.ascent),
            descent: -em(m.descent),
            cap_height: em(m.cap_height.unwrap_or(0.7 * m.units_per_em as f32)),
        }
    }

    fn advance(&self, g: GlyphId) -> f64 {
        let a = self.glyphs.advance_width(g).unwrap_or(0.0);
        f64::from(a) / self.units_per_em
    }

    /// Ink bounds of glyph `g` from its origin, in ems: left, bottom,
    /// right, top (all 0 for a glyph without ink).
    fn ink(&self, g: GlyphId) -> [f64; 4] {
        match self.glyphs.bounds(g) {
            Some(b) if b.y_max > b.y_min && b.x_max > b.x_min => {
                [b.x_min, b.y_min, b.x_max, b.y_max].map(|v| f64::from(v) / self.units_per_em)
            }
            _ => [0.0; 4],
        }
    }
}

/// The typst-assets face of that PostScript name, parsed.
// cannot fail: the names asked for are the two of `Font`, which typst-assets (a pinned version) ships; the tests load both.
#[allow(clippy::expect_used)]
#[cfg(feature = "fonts")]
fn bundled(postscript_name: &str) -> Face {
    let data = typst_assets::fonts()
        .find(|data| {
            FontRef::new(data).is_ok_and(|f| {
                f.localized_strings(StringId::POSTSCRIPT_NAME)
                    .english_or_first()
                    .is_some_and(|n| n.to_string() == postscript_name)
            })
        })
        .expect("typst-assets ships the bundled faces");
    Face::parse(data)
}

impl Font {
    /// Every bundled face, the default first.
    pub const ALL: [Font; 2] = [Font::NewComputerModern, Font::LibertinusSerif];

    /// The name on the command line and in scene files.
    pub fn name(&self) -> &'static str {
        match self {
            Font::NewComputerModern => "new-computer-modern",
            Font::LibertinusSerif => "libertinus-serif",
        }
    }

    /// The family name in the font files (what a renderer matches).
    /// Characters missing from the text faces of New Computer Modern (the
    /// primes ′ and ″, which figures set as ʹ and ʺ, and ∫) come from its
    /// maths face, NewComputerModern Math.
    pub fn family(&self) -> &'static str {
        match self {
            Font::NewComputerModern => "NewComputerModern",
            Font::LibertinusSerif => "Libertinus Serif",
        }
    }

    /// The CSS `font-family` list the SVG asks for: the family first, then
    /// the names other installations give it and the nearest faces, then
    /// the generic serif.
    pub fn css_family(&self) -> &'static str {
        match self {
            Font::NewComputerModern => {
                "NewComputerModern, 'NewComputerModern Math', 'New Computer Modern', 'Latin Modern Roman', 'CMU Serif', serif"
            }
            Font::LibertinusSerif => {
                "'Libertinus Serif', 'Linux Libertine O', 'Linux Libertine', serif"
            }
        }
    }

    /// The PostScript name of a style's file.
    #[cfg(feature = "fonts")]
    pub(crate) fn postscript_name(&self, style: FontStyle) -> &'static str {
        match (self, style) {
            (Font::NewComputerModern, FontStyle::Regular) => "NewCM10-Regular",
            (Font::NewComputerModern, FontStyle::Italic) => "NewCM10-Italic",
            (Font::LibertinusSerif, FontStyle::Regular) => "LibertinusSerif-Regular",
            (Font::LibertinusSerif, FontStyle::Italic) => "LibertinusSerif-Italic",
        }
    }

    /// The entry for `style` of this font in `slots`, which holds the
    /// regular and italic of each font in the order of [`Font::ALL`].
    fn slot<'a, T>(&self, style: FontStyle, slots: &'a [T; 4]) -> &'a T {
        let [cm, cm_italic, libertinus, libertinus_italic] = slots;
        match (self, style) {
            (Font::NewComputerModern, FontStyle::Regular) => cm,
            (Font::NewComputerModern, FontStyle::Italic) => cm_italic,
            (Font::LibertinusSerif, FontStyle::Regular) => libertinus,
            (Font::LibertinusSerif, FontStyle::Italic) => libertinus_italic,
        }
    }

    /// The font file (OpenType) of a style, bundled in the binary
    /// (feature `fonts`).
    #[cfg(feature = "fonts")]
    pub fn data(&self, style: FontStyle) -> &'static [u8] {
        self.face(style).font.data().as_bytes()
    }

    /// Every font file the face is drawn from: regular, italic, and the
    /// face its missing symbols come from (New Computer Modern's maths
    /// face). A renderer falling back to them in this order draws what
    /// [`Font::width`] measures. Feature `fonts`.
    #[cfg(feature = "fonts")]
    pub fn files(&self) -> Vec<&'static [u8]> {
        let mut v = vec![self.data(FontStyle::Regular), self.data(FontStyle::Italic)];
        v.extend(self.symbols().map(|f| f.font.data().as_bytes()));
        v
    }

    #[cfg(feature = "fonts")]
    fn face(&self, style: FontStyle) -> &'static Face {
        static FACES: [OnceLock<Face>; 4] = [const { OnceLock::new() }; 4];
        self.slot(style, &FACES)
            .get_or_init(|| bundled(self.postscript_name(style)))
    }

    /// The face of the symbols missing from the text faces.
    #[cfg(feature = "fonts")]
    fn symbols(&self) -> Option<&'static Face> {
        static MATH: OnceLock<Face> = OnceLock::new();
        match self {
            Font::NewComputerModern => Some(MATH.get_or_init(|| bundled("NewCMMath-Regular"))),
            Font::LibertinusSerif => None,
        }
    }

    /// The face and glyph `c` is drawn with: the style's own, else the
    /// symbols face's, else the style's `.notdef`.
    #[cfg(feature = "fonts")]
    fn glyph(&self, c: char, style: FontStyle) -> (&'static Face, GlyphId) {
        let face = self.face(style);
        if let Some(g) = face.font.charmap().map(c) {
            return (face, g);
        }
        if let Some(sym) = self.symbols()
            && let Some(g) = sym.font.charmap().map(c)
        {
            return (sym, g);
        }
        (face, GlyphId::NOTDEF)
    }

    /// The metrics of `c` in `style`: from the table made from the faces
    /// ([`glyphs`](super::glyphs)) for the characters figures use, so
    /// that no outline is decoded while a figure is set; any other
    /// character looked up in the faces once per process.
    fn char_metrics(&self, c: char, style: FontStyle) -> CharMetrics {
        let table = self.slot(style, &super::glyphs::TABLES);
        let found = table.chars.binary_search_by_key(&c, |g| g.0).ok();
        if let Some(&(_, [advance, left, bottom, right, top])) =
            found.and_then(|i| table.chars.get(i))
        {
            return CharMetrics {
                advance,
                bottom,
                top,
                left,
                right,
                present: true,
            };
        }
        type Cache = Mutex<HashMap<char, CharMetrics>>;
        static CACHES: [OnceLock<Cache>; 4] = [const { OnceLock::new() }; 4];
        let cache = self.slot(style, &CACHES).get_or_init(Cache::default);
        let mut cache = cache.lock().unwrap_or_else(|e| e.into_inner());
        *cache
            .entry(c)
            .or_insert_with(|| self.measured_metrics(c, style))
    }

    /// The metrics of `c` in `style` without the faces (feature `fonts`
    /// off): those of the table's M, the widest capital but one, and
    /// missing. Only characters outside the glyph table (ASCII,
    /// Latin-1, Greek and the signs figures use) are measured so.
    #[cfg(not(feature = "fonts"))]
    fn measured_metrics(&self, _: char, style: FontStyle) -> CharMetrics {
        let table = self.slot(style, &super::glyphs::TABLES);
        let m = table
            .chars
            .binary_search_by_key(&'M', |g| g.0)
            .ok()
            .and_then(|i| table.chars.get(i))
            .map_or([1.0, 0.0, 0.0, 1.0, 0.7], |g| g.1);
        let [advance, left, bottom, right, top] = m;
        CharMetrics {
            advance,
            bottom,
            top,
            left,
            right,
            present: false,
        }
    }

    /// The metrics of `c` in `style` read from the faces' outlines.
    #[cfg(feature = "fonts")]
    fn measured_metrics(&self, c: char, style: FontStyle) -> CharMetrics {
        let (face, g) = self.glyph(c, style);
        let [left, bottom, right, top] = face.ink(g);
        CharMetrics {
            advance: face.advance(g),
            bottom,
            top,
            left,
            right,
            present: g != GlyphId::NOTDEF,
        }
    }

    /// The width of `text` at `size` (page units): the glyph advances
    /// summed (no kerning).
    pub fn width(&self, text: &str, size: f64, style: FontStyle) -> f64 {
        size * text
            .chars()
            .map(|c| self.char_metrics(c, style).advance)
            .sum::<f64>()
    }

    /// The width and the ink's height, depth and left and right ends of
    /// `text` at `size`.
    pub fn measure(&self, text: &str, size: f64, style: FontStyle) -> TextBox {
        let (mut bottom, mut top, mut width) = (0.0f64, 0.0f64, 0.0);
        let (mut left, mut right) = (f64::INFINITY, f64::NEG_INFINITY);
        for c in text.chars() {
            let m = self.char_metrics(c, style);
            bottom = bottom.min(m.bottom);
            top = top.max(m.top);
            if m.right > m.left {
                left = left.min(width + m.left);
                right = right.max(width + m.right);
            }
            width += m.advance;
        }
        if left > right {
            (left, right) = (0.0, 0.0);
        }
        TextBox {
            width: size * width,
            above: size * top,
            below: -size * bottom,
            left: size * left,
            right: size * right,
        }
    }

    /// Ascent, descent and cap height of a style.
    pub fn metrics(&self, style: FontStyle) -> VerticalMetrics {
        self.slot(style, &super::glyphs::TABLES).vertical
    }

    /// Whether the face (with its symbols face) has a glyph for `c` (else
    /// a renderer falls back to another font).
    pub fn has_glyph(&self, c: char, style: FontStyle) -> bool {
        self.char_metrics(c, style).present
    }

    /// The names of the faces, for help texts and errors.
    pub fn names() -> String {
        Font::ALL.map(|f| f.name()).join(", ")
    }
}

impl fmt::Display for Font {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Font {
    type Err = Error;

    fn from_str(s: &str) -> Result<Self> {
        Font::ALL
            .into_iter()
            .find(|f| f.name() == s)
            .ok_or_else(|| {
                Error::invalid(
                    Input::Font,
                    format!("unknown font '{s}': expected one of {}", Font::names()),
                )
            })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    #[cfg(feature = "fonts")]
    use skrifa::raw::TableProvider;

    #[cfg(feature = "fonts")]
    /// The advances of `text` in ems, read from the raw `cmap` and `hmtx`
    /// tables of the file.
    fn raw_advances(data: &[u8], text: &str) -> f64 {
        let font = skrifa::raw::FontRef::new(data).unwrap();
        let cmap = font.cmap().unwrap();
        let hmtx = font.hmtx().unwrap();
        let upem = f64::from(font.head().unwrap().units_per_em());
        text.chars()
            .map(|c| {
                let g = cmap.map_codepoint(c).expect("glyph");
                f64::from(hmtx.advance(g).expect("advance")) / upem
            })
            .sum()
    }

    #[cfg(feature = "fonts")]
    #[test]
    fn width_is_the_sum_of_the_advances_in_the_file() {
        for font in Font::ALL {
            for style in [FontStyle::Regular, FontStyle::Italic] {
                let text = "OM = 1.25 ft, θ";
                let expected = 17.0 * raw_advances(font.data(style), text);
                let got = font.width(text, 17.0, style);
                assert!((got - expected).abs() < 1e-9, "{font} {style:?}");
                assert!(got > 17.0 * 5.0 && got < 17.0 * 12.0, "{got}");
            }
        }
    }

    #[cfg(feature = "fonts")]
    #[test]
    fn faces_and_styles_differ() {
        let s = "Klein's construction FCG";
        let ncm = Font::NewComputerModern.width(s, 13.0, FontStyle::Regular);
        let lib = Font::LibertinusSerif.width(s, 13.0, FontStyle::Regular);
        assert!((ncm - lib).abs() > 0.02 * ncm, "{ncm} {lib}");
        for font in Font::ALL {
            // Italic letters have advances of their own (the sums of a
            // whole line can come out close).
            let differ = ('a'..='z')
                .filter(|c| {
                    let c = c.to_string();
                    let r = font.width(&c, 10.0, FontStyle::Regular);
                    (r - font.width(&c, 10.0, FontStyle::Italic)).abs() > 0.05
                })
                .count();
            assert!(differ >= 9, "{font}: {differ} of 26 letters");
            assert_ne!(font.data(FontStyle::Regular), font.data(FontStyle::Italic));
        }
    }

    #[test]
    fn vertical_metrics_and_ink() {
        for font in Font::ALL {
            for style in [FontStyle::Regular, FontStyle::Italic] {
                let m = font.metrics(style);
                assert!(m.cap_height > 0.6 && m.cap_height < 0.75, "{font} {m:?}");
                assert!(m.ascent > m.cap_height && m.descent > 0.1, "{font} {m:?}");
                // A capital's ink stands on the baseline and reaches the
                // cap height; p's descender goes below it.
                let h = font.measure("H", 10.0, style);
                assert!((h.above - 10.0 * m.cap_height).abs() < 0.3, "{h:?} {m:?}");
                assert!(h.below.abs() < 0.3, "{h:?}");
                assert!(font.measure("p", 10.0, style).below > 1.0);
                assert_eq!(font.measure(" ", 10.0, style).above, 0.0);
            }
        }
    }

    #[test]
    fn ink_ends_are_the_glyph_outlines_not_the_advances() {
        for font in Font::ALL {
            // An italic capital leans past its advance; an upright one
            // keeps its ink within it, side bearings on both sides.
            let p = font.measure("P", 20.0, FontStyle::Italic);
            assert!(p.right > p.width + 0.3, "{font} {p:?}");
            let h = font.measure("H", 20.0, FontStyle::Regular);
            assert!(h.left > 0.0 && h.right < h.width, "{font} {h:?}");
            assert!(h.right - h.left > 0.6 * h.width, "{font} {h:?}");
            // Spaces have no ink: they only move the ink that follows.
            let sp = font.measure(" ", 20.0, FontStyle::Regular);
            assert_eq!((sp.left, sp.right), (0.0, 0.0));
            let both = sp.then(h);
            assert!((both.left - (sp.width + h.left)).abs() < 1e-12, "{both:?}");
            assert!((both.right - (sp.width + h.right)).abs() < 1e-12);
            let joined = font.measure(" H", 20.0, FontStyle::Regular);
            assert!((joined.left - both.left).abs() < 1e-9, "{joined:?}");
            assert!((joined.right - both.right).abs() < 1e-9, "{joined:?}");
            assert_eq!(h.then(sp).right, h.right);
        }
    }

    #[cfg(feature = "fonts")]
    #[test]
    fn primes_of_new_computer_modern_come_from_its_maths_face() {
        let f = Font::NewComputerModern;
        let math = f.files()[2];
        assert_eq!(f.files().len(), 3);
        assert!(f.has_glyph('′', FontStyle::Italic));
        let expected = 12.0 * raw_advances(math, "′″");
        assert!((f.width("′″", 12.0, FontStyle::Regular) - expected).abs() < 1e-9);
        assert_eq!(Font::LibertinusSerif.files().len(), 2);
    }

    #[test]
    fn names_round_trip() {
        for f in Font::ALL {
            assert_eq!(f.to_string().parse::<Font>().unwrap(), f);
            assert!(f.css_family().contains(f.family()));
        }
        assert_eq!(Font::default(), Font::NewComputerModern);
        assert_eq!(
            "libertinus-serif".parse::<Font>().unwrap(),
            Font::LibertinusSerif
        );
        let e = "times".parse::<Font>().unwrap_err().to_string();
        assert!(e.contains("new-computer-modern, libertinus-serif"), "{e}");
    }

    #[cfg(feature = "fonts")]
    /// The characters the glyph table holds, where a face (or its
    /// symbols face) has them: ASCII and Latin-1, the modifier primes
    /// (the primes figures set), Greek, the dashes, quotes and primes,
    /// super- and subscripts, arrows and the
    /// mathematical signs the figures write.
    const TABLE_RANGES: [(char, char); 10] = [
        (' ', '~'),
        ('\u{a0}', 'ÿ'),
        ('ʹ', 'ʺ'),
        ('Α', 'ω'),
        ('ϑ', 'ϖ'),
        ('\u{2010}', '\u{2044}'),
        ('⁰', 'ₜ'),
        ('←', '↓'),
        ('∂', '∞'),
        ('≈', '≥'),
    ];

    #[cfg(feature = "fonts")]
    /// The source of `glyphs.rs`: every character of [`TABLE_RANGES`] the
    /// faces have, measured from their outlines as [`Font::measured_metrics`]
    /// does, written exactly (`{:?}` of an f64 reads back as itself).
    fn glyph_table_source() -> String {
        let mut out = String::from(GLYPHS_HEAD);
        let mut names = Vec::new();
        for font in Font::ALL {
            for style in [FontStyle::Regular, FontStyle::Italic] {
                let name = format!("{}_{style:?}", font.name().replace('-', "_")).to_uppercase();
                let v = font.face(style).vertical();
                out.push_str(&format!(
                    "\n/// {} {style:?}.\nstatic {name}: GlyphTable = GlyphTable {{\n    vertical: VerticalMetrics {{ ascent: {:?}, descent: {:?}, cap_height: {:?} }},\n    chars: &[\n",
                    font.name(), v.ascent, v.descent, v.cap_height
                ));
                for (lo, hi) in TABLE_RANGES {
                    for c in lo..=hi {
                        let m = font.measured_metrics(c, style);
                        if m.present {
                            out.push_str(&format!(
                                "        ({c:?}, [{:?}, {:?}, {:?}, {:?}, {:?}]),\n",
                                m.advance, m.left, m.bottom, m.right, m.top
                            ));
                        }
                    }
                }
                out.push_str("    ],\n};\n");
                names.push(name);
            }
        }
        out.push_str(&format!(
            "\n/// By [`Font::index`](super::font): each face's regular, then italic.\npub(super) static TABLES: [&GlyphTable; 4] = [{}];\n",
            names.iter().map(|n| format!("&{n}")).collect::<Vec<_>>().join(", ")
        ));
        out
    }

    #[cfg(feature = "fonts")]
    const GLYPHS_HEAD: &str =
        "//! Glyph metrics of the bundled faces, in ems: each style's vertical
//! metrics and, for the characters figures write, the advance and the ink
//! bounds (left, bottom, right, top) read from the glyph outlines, so
//! that setting a figure's text decodes no outline (the first figure of a
//! process costs what the hundredth does). Written from the faces by the
//! test `the_glyph_table_is_what_the_faces_measure` in `font.rs` (run it
//! with SLIDER_CRANK_WRITE_GLYPHS=1 after changing the faces or the
//! characters); not edited by hand.

// Measured advances and bounds (0.318 em) that only look like 1/π.
#![allow(clippy::approx_constant)]

use super::metrics::VerticalMetrics;

/// The metrics of one style of a face.
pub(super) struct GlyphTable {
    /// Ascent, descent and cap height.
    pub vertical: VerticalMetrics,
    /// (character, [advance, left, bottom, right, top]), sorted by
    /// character; only characters the face or its symbols face has.
    pub chars: &'static [(char, [f64; 5])],
}
";

    #[cfg(feature = "fonts")]
    #[test]
    fn the_glyph_table_is_what_the_faces_measure() {
        let source = glyph_table_source();
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/src/figure/glyphs.rs");
        if std::env::var_os("SLIDER_CRANK_WRITE_GLYPHS").is_some() {
            std::fs::write(path, &source).unwrap();
        }
        let written = std::fs::read_to_string(path).unwrap();
        assert!(
            written == source,
            "src/figure/glyphs.rs is not what the bundled faces measure: rerun this test with SLIDER_CRANK_WRITE_GLYPHS=1"
        );
        // The table and the outlines agree through the public measures.
        for font in Font::ALL {
            for style in [FontStyle::Regular, FontStyle::Italic] {
                for c in ['A', 'θ', '′', '₂', '−', 'ω', '°', '∞'] {
                    let m = font.measured_metrics(c, style);
                    let t = font.char_metrics(c, style);
                    assert_eq!(
                        (m.advance, m.left, m.bottom, m.right, m.top, m.present),
                        (t.advance, t.left, t.bottom, t.right, t.top, t.present),
                        "{font} {style:?} {c}"
                    );
                }
                assert_eq!(font.metrics(style), font.face(style).vertical());
            }
        }
    }

    /// Without the faces, a character outside the glyph table.
    #[test]
    #[cfg(not(feature = "fonts"))]
    fn a_character_outside_the_table_is_measured_as_an_m_and_missing() {
        for font in Font::ALL {
            let m = font.measure("M", 10.0, FontStyle::Italic);
            assert_eq!(font.measure("\u{4E2D}", 10.0, FontStyle::Italic), m);
            assert!(m.width > 5.0, "{m:?}");
            assert!(!font.has_glyph('\u{4E2D}', FontStyle::Regular));
            assert!(font.has_glyph('θ', FontStyle::Regular));
        }
    }
}
