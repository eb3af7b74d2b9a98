//! Texts as `<text>` elements of `<tspan>` runs.

use crate::figure::{RichText, SUBSCRIPT_DROP, SUBSCRIPT_SIZE, SUPERSCRIPT_RISE};
use crate::layout::{TextAnchor, TextMark};
use crate::number::fmt;
use crate::render::{Element, Node, escape_text};
use std::fmt::Write as _;

/// A run's characters escaped, with spaces at its ends made no-break so
/// that no renderer drops them at a `<tspan>` boundary.
fn run_text(s: &str) -> String {
    let t = s.trim_matches(' ');
    if t.is_empty() {
        return "\u{a0}".repeat(s.len());
    }
    let lead = s.len() - s.trim_start_matches(' ').len();
    let trail = s.len() - s.trim_end_matches(' ').len();
    format!(
        "{}{}{}",
        "\u{a0}".repeat(lead),
        escape_text(t),
        "\u{a0}".repeat(trail)
    )
}

/// `<tspan>` runs; `size` is the base size.
fn runs_markup(text: &RichText, size: f64, base_italic: bool) -> String {
    let mut out = String::new();
    let mut shift = 0.0;
    for run in text.runs() {
        let dy = if run.subscript {
            SUBSCRIPT_DROP * size
        } else if run.superscript {
            -SUPERSCRIPT_RISE * size
        } else {
            0.0
        };
        let mut attrs = String::new();
        if dy != shift {
            let _ = write!(attrs, " dy=\"{}\"", fmt(dy - shift));
            shift = dy;
        }
        if run.subscript || run.superscript {
            let _ = write!(attrs, " font-size=\"{}\"", fmt(SUBSCRIPT_SIZE * size));
        }
        if run.italic != base_italic {
            let _ = write!(
                attrs,
                " font-style=\"{}\"",
                if run.italic { "italic" } else { "normal" }
            );
        }
        if attrs.is_empty() {
            out.push_str(&run_text(&run.text));
        } else {
            let _ = write!(out, "<tspan{attrs}>{}</tspan>", run_text(&run.text));
        }
    }
    out
}

/// The `<text>` of a placed text; written as a plain element so that no
/// line breaks get between its runs.
pub(super) fn text_element(t: &TextMark) -> Element {
    let anchor = match t.anchor {
        TextAnchor::Start => "start",
        TextAnchor::Middle => "middle",
        TextAnchor::End => "end",
    };
    let mut e = Element::new("text");
    e.assign("x", fmt(t.at.x));
    e.assign("y", fmt(t.at.y));
    e.assign("font-size", fmt(t.size));
    e.assign("fill", t.colour);
    e.assign("text-anchor", anchor);
    e.assign("font-style", if t.italic { "italic" } else { "normal" });
    e.append(Node::Raw(runs_markup(&t.text, t.size, t.italic)));
    e
}
