//! What the crate's HTML pages share (the gallery's index, the handouts and
//! exercise sheets): the document around a body, the book-page style sheet
//! and rich text set as HTML. Every page is written through maud
//! templates, so every text is escaped. Every page carries the faces it
//! is set in ([`fonts`]).

pub(crate) mod font_face;

use crate::figure::{Font, RichText};
use maud::{DOCTYPE, Markup, PreEscaped, html};

/// The style sheet every page starts from: a plain book page, serif type,
/// ruled tables.
pub(crate) const BOOK_STYLE: &str = "
body { font-family: NewComputerModern, 'NewComputerModern Math', 'Latin Modern Roman', serif;
       max-width: 60rem; margin: 2rem auto; padding: 0 1rem; color: #111; line-height: 1.4; }
code { font-size: .9em; }
table { border-collapse: collapse; margin: 1rem 0; }
th, td { padding: .2rem .7rem; text-align: right; border-bottom: 1px solid #ddd; }
caption { text-align: left; font-weight: bold; padding-bottom: .3rem; }
";

/// A whole page: `<!DOCTYPE html>`, the head with `title` and the style
/// sheet [`BOOK_STYLE`] followed by `style`, and `body`; the style sheet
/// carries the faces of the page's text (New Computer Modern, and
/// Libertinus Serif where a figure is set in it), cut to the characters
/// the page holds.
pub(crate) fn document(title: &str, style: &str, body: Markup) -> String {
    document_covering(title, style, body, "")
}

/// [`document`] whose faces also carry the characters of `also`: the text
/// of what is written into the page after it is made (an animation's
/// frames, streamed in place of a placeholder).
pub(crate) fn document_covering(title: &str, style: &str, body: Markup, also: &str) -> String {
    let body = body.into_string();
    let fonts: Vec<Font> = Font::ALL
        .into_iter()
        .filter(|f| *f == Font::default() || body.contains(f.family()) || also.contains(f.family()))
        .collect();
    let faces = font_face::font_faces(&format!("{title}{body}{also}"), &fonts);
    html! {
        (DOCTYPE)
        html lang="en" {
            head {
                meta charset="utf-8";
                meta name="viewport" content="width=device-width, initial-scale=1";
                title { (title) }
                style { (PreEscaped(faces)) (PreEscaped(BOOK_STYLE)) (PreEscaped(style)) }
            }
            body { (PreEscaped(body)) }
        }
    }
    .into_string()
}

/// The markup of [`RichText::parse`] (`*A*` italic, `V_p` a subscript,
/// `²` a superscript) as HTML: `<i>`, `<sub>`, `<sup>`, every text escaped.
pub(crate) fn rich(markup: &str) -> Markup {
    let text = RichText::parse(markup);
    html! {
        @for run in text.runs() {
            @if run.subscript {
                sub { @if run.italic { i { (run.text) } } @else { (run.text) } }
            } @else if run.superscript {
                sup { @if run.italic { i { (run.text) } } @else { (run.text) } }
            } @else if run.italic {
                i { (run.text) }
            } @else {
                (run.text)
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rich_text_is_set_in_html_and_escaped() {
        assert_eq!(
            rich("*CE* = V_p / ω² <b>").into_string(),
            // ω italic as everywhere (the typographic convention).
            "<i>CE</i> = V<sub>p</sub> / <i>ω</i><sup>2</sup> &lt;b&gt;"
        );
    }

    #[test]
    fn a_document_has_its_title_and_both_style_sheets() {
        let page = document("a < b", "p { x: y }", html! { p { "body" } });
        assert!(page.starts_with("<!DOCTYPE html>"));
        assert!(page.contains("<title>a &lt; b</title>"));
        assert!(page.contains("border-collapse") && page.contains("p { x: y }"));
    }
}
