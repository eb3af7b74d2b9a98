//! A standalone SVG that carries its faces: the figure's SVG with a
//! `<style>` of `@font-face` rules whose sources are `data:` URLs of the
//! bundled faces cut to exactly the characters its texts draw (the cut of
//! the HTML pages, `src/html/font_face.rs`). A browser opening the file
//! sets it in the face it was measured in, not in a system serif.

use super::to_svg;
use crate::figure::Figure;
use crate::html::font_face::faces_of;
use std::collections::BTreeSet;

/// [`to_svg`] with the figure's face embedded: regular and italic (and
/// New Computer Modern's maths face for the symbols its text faces lack),
/// each cut to the characters of the figure's `<text>` elements, in a
/// `<style>` first in the document. A figure without text is written as
/// [`to_svg`] writes it. The faces weigh about 2 to 4 kB per character
/// set in them (docs/design.md, "Fonts in standalone SVG").
pub fn to_svg_with_fonts(figure: &Figure) -> String {
    let svg = to_svg(figure);
    let css = faces_of(&drawn_chars(&svg), &[figure.font()]);
    // The root's start tag ends at the first '>' after "<svg" (no
    // attribute value of the root holds one: they are numbers and the
    // font list).
    let root = svg
        .find("<svg")
        .and_then(|at| svg[at..].find('>').map(|end| at + end + 1));
    match root {
        Some(end) if !css.is_empty() => {
            format!("{}\n<style>\n{css}</style>{}", &svg[..end], &svg[end..])
        }
        _ => svg,
    }
}

/// The characters the `<text>` elements of `svg` draw: their contents
/// with the tags of their `<tspan>`s left out and the five escapes read.
fn drawn_chars(svg: &str) -> BTreeSet<char> {
    let mut chars = BTreeSet::new();
    let mut rest = svg;
    while let Some(open) = rest.find("<text") {
        let body = &rest[open..];
        let (Some(start), Some(end)) = (body.find('>'), body.find("</text>")) else {
            break;
        };
        let mut inside = String::new();
        let mut in_tag = false;
        for c in body[start + 1..end].chars() {
            match c {
                '<' => in_tag = true,
                '>' => in_tag = false,
                c if !in_tag => inside.push(c),
                _ => {}
            }
        }
        let text = inside
            .replace("&lt;", "<")
            .replace("&gt;", ">")
            .replace("&quot;", "\"")
            .replace("&apos;", "'")
            .replace("&amp;", "&");
        chars.extend(text.chars());
        rest = &body[end..];
    }
    chars
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::catalogue::FigureName;
    use base64::Engine as _;
    use skrifa::{FontRef, MetadataProvider};

    #[test]
    fn the_drawn_characters_are_the_texts_contents() {
        let svg = "<svg><title>Q</title><metadata>{\"z\":1}</metadata>\
                   <text x=\"1\">A<tspan dy=\"2\">b</tspan> &amp;&lt;</text><path d=\"M0\"/></svg>";
        let chars: String = drawn_chars(svg).into_iter().collect();
        assert_eq!(chars, " &<Ab");
    }

    #[test]
    fn a_standalone_figure_carries_its_faces_cut_to_its_characters() {
        let figure = FigureName::Fig63Velocity.scene().unwrap().figure().unwrap();
        let plain = to_svg(&figure);
        let embedded = to_svg_with_fonts(&figure);
        assert!(!plain.contains("@font-face"));
        // Only the style is added: the rest of the document is the same.
        let start = embedded.find("<style>").unwrap();
        let end = embedded.find("</style>").unwrap() + "</style>".len();
        assert_eq!(
            format!("{}{}", &embedded[..start - 1], &embedded[end..]),
            plain
        );
        let css = &embedded[start..end];
        assert!(css.contains("font-family: 'NewComputerModern'; font-style: italic"));
        // The italic face maps the figure's italic letters and no letter
        // the figure does not draw.
        let italic = css.lines().find(|l| l.contains("italic")).unwrap();
        let from = italic.find("base64,").unwrap() + "base64,".len();
        let to = from + italic[from..].find(')').unwrap();
        let data = base64::engine::general_purpose::STANDARD
            .decode(&italic[from..to])
            .unwrap();
        let face = FontRef::new(&data).unwrap();
        let drawn = drawn_chars(&plain);
        for c in ['A', 'B', 'C'] {
            assert!(drawn.contains(&c) && face.charmap().map(c).is_some(), "{c}");
        }
        for c in ('a'..='z').chain('A'..='Z').filter(|c| !drawn.contains(c)) {
            assert!(face.charmap().map(c).is_none(), "{c} is not drawn");
        }
    }
}
