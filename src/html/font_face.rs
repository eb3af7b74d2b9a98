//! The faces an HTML page is set in, carried by the page: `@font-face`
//! rules whose sources are `data:` URLs of the bundled faces cut down to
//! the characters the page holds, so that a browser without New Computer
//! Modern installed sets (and prints) the page and its inline figures in
//! the face the figures were measured in, not in a fallback whose wider
//! letters overrun their boxes.
//!
//! The cut is made by the same subsetter as the PDF writer's. Its fonts
//! carry no character map (a PDF brings its own), so one is written here
//! (a format 4 `cmap`, one segment a character), and the face's `OS/2`
//! table, which browsers require, is copied back in.

use crate::figure::{Font, FontStyle};
use base64::Engine as _;
use skrifa::raw::types::Tag;
use skrifa::{FontRef, MetadataProvider};
use std::collections::BTreeSet;
use subsetter::GlyphRemapper;

/// The `@font-face` rules that carry `fonts` for a page holding `text`:
/// for each font its regular and italic faces (and New Computer Modern's
/// maths face for the symbols its text faces lack), each cut to the
/// characters of `text` it draws, under the family names the figures ask
/// for ([`Font::css_family`]). Bold is synthesised from the regular face.
/// A face none of whose characters `text` holds is left out; empty for an
/// empty `text`. The capitals of `text`'s letters are carried too: a
/// browser sets small capitals (a caption's "Figure") from the face's
/// capitals at a smaller size, and one it lacks (the I of "Drawing")
/// comes from a system face.
pub(crate) fn font_faces(text: &str, fonts: &[Font]) -> String {
    let chars: BTreeSet<char> = text
        .chars()
        .flat_map(|c| std::iter::once(c).chain(c.to_uppercase()))
        .collect();
    faces_of(&chars, fonts)
}

/// The `@font-face` rules of [`font_faces`] for exactly the characters
/// `chars` (control characters left out); empty when `chars` is.
pub(crate) fn faces_of(chars: &BTreeSet<char>, fonts: &[Font]) -> String {
    let chars: BTreeSet<char> = chars.iter().copied().filter(|c| !c.is_control()).collect();
    let mut css = String::new();
    for font in fonts {
        let files = font.files();
        let regular = FontRef::new(font.data(FontStyle::Regular)).ok();
        let italic = FontRef::new(font.data(FontStyle::Italic)).ok();
        let has =
            |f: &Option<FontRef>, c: char| f.as_ref().is_some_and(|f| f.charmap().map(c).is_some());
        let in_text = |c: &char| has(&regular, *c);
        // A browser looks for a character the italic face lacks in the
        // next family, not in the regular face: the symbols face carries
        // those too.
        let in_both = |c: &char| has(&regular, *c) && has(&italic, *c);
        let faces = [
            (
                font.family().to_string(),
                "normal",
                font.data(FontStyle::Regular),
                true,
            ),
            (
                font.family().to_string(),
                "italic",
                font.data(FontStyle::Italic),
                true,
            ),
        ];
        for (family, style, data, text_face) in faces {
            let wanted = chars.iter().copied().filter(|c| !text_face || in_text(c));
            css.push_str(&rule(&family, style, data, wanted));
        }
        if let Some(symbols) = files.get(2) {
            let missing = chars.iter().copied().filter(|c| !in_both(c));
            css.push_str(&rule(
                &format!("{} Math", font.family()),
                "normal",
                symbols,
                missing,
            ));
        }
    }
    css
}

/// One `@font-face` rule: the face in `data` cut to `chars` (those it
/// has), or nothing when it has none of them or cannot be cut.
fn rule(family: &str, style: &str, data: &[u8], chars: impl Iterator<Item = char>) -> String {
    let Some(font) = cut(data, chars) else {
        return String::new();
    };
    let url = base64::engine::general_purpose::STANDARD.encode(font);
    format!(
        "@font-face {{ font-family: '{family}'; font-style: {style}; font-weight: 400 700; \
         src: url(data:font/otf;base64,{url}) format('opentype'); }}\n"
    )
}

/// The face in `data` with only the glyphs of `chars` (those it maps),
/// and a character map for them; `None` when it maps none of them or
/// cannot be cut.
pub(crate) fn cut(data: &[u8], chars: impl Iterator<Item = char>) -> Option<Vec<u8>> {
    let font = FontRef::new(data).ok()?;
    let charmap = font.charmap();
    let mut remapper = GlyphRemapper::new();
    let mut map: Vec<(u16, u16)> = chars
        .filter_map(|c| {
            let code = u16::try_from(u32::from(c)).ok().filter(|&c| c != 0xFFFF)?;
            let glyph = u16::try_from(charmap.map(c)?.to_u32()).ok()?;
            Some((code, remapper.remap(glyph)))
        })
        .collect();
    if map.is_empty() {
        return None;
    }
    map.sort_unstable();
    let subset = subsetter::subset(data, 0, &remapper).ok()?;
    let os2 = font.table_data(Tag::new(b"OS/2"))?;
    with_tables(
        &subset,
        &[(*b"cmap", cmap(&map)), (*b"OS/2", os2.as_bytes().to_vec())],
    )
}

/// A `cmap` table with one subtable (Windows, Unicode BMP) of format 4:
/// a segment for each `(character, glyph)` of `map` (sorted), then the
/// closing segment at U+FFFF.
fn cmap(map: &[(u16, u16)]) -> Vec<u8> {
    let segments: Vec<(u16, u16)> = map.iter().copied().chain([(0xFFFF, 0)]).collect();
    let count = segments.len() as u16;
    let selector = 15 - count.leading_zeros() as u16;
    let range = 2 * (1u16 << selector);
    let mut sub = Vec::new();
    let length = 16 + 8 * segments.len();
    for v in [
        4,
        length as u16,
        0,
        2 * count,
        range,
        selector,
        2 * count - range,
    ] {
        sub.extend(v.to_be_bytes());
    }
    sub.extend(segments.iter().flat_map(|s| s.0.to_be_bytes()));
    sub.extend(0u16.to_be_bytes());
    sub.extend(segments.iter().flat_map(|s| s.0.to_be_bytes()));
    // idDelta: glyph − character, modulo 2¹⁶; U+FFFF maps to glyph 0.
    sub.extend(segments.iter().flat_map(|&(c, g)| {
        let delta = if c == 0xFFFF { 1 } else { g.wrapping_sub(c) };
        delta.to_be_bytes()
    }));
    sub.extend(segments.iter().flat_map(|_| 0u16.to_be_bytes()));
    let mut table = Vec::new();
    for v in [0u16, 1, 3, 1] {
        table.extend(v.to_be_bytes());
    }
    table.extend(12u32.to_be_bytes());
    table.extend(sub);
    table
}

/// The OpenType font `font` with `extra` tables added, its directory
/// rewritten in tag order with the checksums and `head`'s checksum
/// adjustment; `None` when its directory points outside it.
fn with_tables(font: &[u8], extra: &[([u8; 4], Vec<u8>)]) -> Option<Vec<u8>> {
    let be16 = |at: usize| Some(u16::from_be_bytes(font.get(at..at + 2)?.try_into().ok()?));
    let be32 = |at: usize| Some(u32::from_be_bytes(font.get(at..at + 4)?.try_into().ok()?));
    let mut tables: Vec<([u8; 4], Vec<u8>)> = (0..be16(4)? as usize)
        .map(|k| {
            let record = 12 + 16 * k;
            let (offset, length) = (be32(record + 8)? as usize, be32(record + 12)? as usize);
            // The bundled faces' own directory (never a user's file).
            let tag: [u8; 4] = font.get(record..record + 4)?.try_into().ok()?;
            Some((tag, font.get(offset..offset + length)?.to_vec()))
        })
        .chain(extra.iter().cloned().map(Some))
        .collect::<Option<_>>()?;
    tables.sort_by_key(|t| t.0);
    let count = tables.len() as u16;
    let selector = 15 - count.leading_zeros() as u16;
    let range = 16 * (1u16 << selector);
    let mut out = font.get(..4)?.to_vec();
    for v in [count, range, selector, 16 * count - range] {
        out.extend(v.to_be_bytes());
    }
    let mut offset = 12 + 16 * tables.len();
    let mut head = None;
    for (tag, data) in &mut tables {
        if tag == b"head" {
            data.get_mut(8..12)?.fill(0);
            head = Some(offset + 8);
        }
        out.extend(*tag);
        out.extend(checksum(data).to_be_bytes());
        out.extend((offset as u32).to_be_bytes());
        out.extend((data.len() as u32).to_be_bytes());
        offset += data.len().next_multiple_of(4);
    }
    for (_, data) in &tables {
        out.extend(data);
        out.resize(out.len().next_multiple_of(4), 0);
    }
    if let Some(at) = head {
        let adjustment = 0xB1B0_AFBAu32.wrapping_sub(checksum(&out));
        out.get_mut(at..at + 4)?
            .copy_from_slice(&adjustment.to_be_bytes());
    }
    Some(out)
}

/// The OpenType checksum: the sum of the big-endian 32-bit words, the last
/// padded with zeros.
fn checksum(data: &[u8]) -> u32 {
    data.chunks(4).fold(0u32, |sum, word| {
        let mut w = [0u8; 4];
        for (to, from) in w.iter_mut().zip(word) {
            *to = *from;
        }
        sum.wrapping_add(u32::from_be_bytes(w))
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_cut_face_maps_its_characters_to_the_same_outlines() {
        let data = Font::NewComputerModern.data(FontStyle::Italic);
        let cut = cut(data, "θAB x".chars()).unwrap();
        assert!(cut.len() < data.len() / 20, "{} bytes", cut.len());
        let small = FontRef::new(&cut).unwrap();
        let whole = FontRef::new(data).unwrap();
        let advance = |f: &FontRef, c: char| {
            let g = f.charmap().map(c).unwrap();
            f.glyph_metrics(
                skrifa::instance::Size::unscaled(),
                skrifa::instance::LocationRef::default(),
            )
            .advance_width(g)
            .unwrap()
        };
        for c in "θAB x".chars() {
            assert_eq!(advance(&small, c), advance(&whole, c), "{c}");
        }
        assert!(small.charmap().map('q').is_none());
        assert!(small.table_data(Tag::new(b"OS/2")).is_some());
        // The directory's checksums hold: the whole font sums to the magic.
        assert_eq!(checksum(&cut), 0xB1B0_AFBA);
        assert!(super::cut(data, "\u{1F600}".chars()).is_none());
    }

    #[test]
    fn a_page_carries_the_faces_of_its_characters() {
        let css = font_faces("θ = 30° and ′", &[Font::NewComputerModern]);
        assert_eq!(css.matches("@font-face").count(), 3, "{css}");
        assert!(css.contains("font-family: 'NewComputerModern Math'"));
        let plain = font_faces("θ = 30°", &[Font::NewComputerModern]);
        assert_eq!(plain.matches("@font-face").count(), 2, "{plain}");
        assert!(font_faces("", &[Font::NewComputerModern]).is_empty());
    }

    #[test]
    fn a_page_carries_the_capitals_its_small_capitals_are_set_from() {
        // "Drawing." in small capitals is set as "DRAWING." from the
        // regular face: its cut maps the I the text does not hold.
        let css = font_faces("Drawing.", &[Font::NewComputerModern]);
        let regular = css.lines().next().unwrap();
        let start = regular.find("base64,").unwrap() + "base64,".len();
        let end = start + regular[start..].find(')').unwrap();
        let data = base64::engine::general_purpose::STANDARD
            .decode(&regular[start..end])
            .unwrap();
        let face = FontRef::new(&data).unwrap();
        for c in "DRAWINGrawing.".chars() {
            assert!(face.charmap().map(c).is_some(), "{c}");
        }
        assert!(face.charmap().map('Q').is_none());
    }
}
