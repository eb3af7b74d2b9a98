//! Text: `<text>` elements of rich runs, and the boxes that keep labels
//! and notes clear of each other.

use crate::figure::{Font, RichText, Role, SUBSCRIPT_DROP, SUBSCRIPT_SIZE, SUPERSCRIPT_RISE};
use crate::geom::{Point, Vector};
use crate::number::fmt;
use crate::render::labels::ROOM;
use crate::render::{Element, Node, escape_text};
use std::fmt::Write as _;

/// Where [`text_node`] puts the baseline: this fraction of the size below
/// the text's centre (half the cap height, near enough).
pub(super) const BASELINE: f64 = 0.35;

/// Half the width and height of the box about a text's centre that holds
/// its ink (advances and glyph bounds of `font`) with [`ROOM`] to spare, for
/// placement.
pub(super) fn text_half(text: &RichText, size: f64, font: Font) -> Vector {
    let b = text.measure(font, size);
    let baseline = BASELINE * size;
    Vector::new(
        0.5 * b.width + ROOM,
        (b.above - baseline).max(b.below + baseline) + ROOM,
    )
}

/// The half-size of the box around the ink of `text` ([`ROOM`] on
/// every side), and the shift from the box's centre to the point
/// [`text_node`] takes (the middle of the advances, `BASELINE` × `size`
/// above the baseline): the box of a placed label, tight on every side (a
/// subscript's drop or a letter's descender counts only on its own side,
/// an italic capital's overhang only on the right). A text without ink
/// (spaces) gets the box of its advances.
pub(super) fn ink_box(text: &RichText, size: f64, font: Font) -> (Vector, Vector) {
    let b = text.measure(font, size);
    let (left, right) = if b.right > b.left {
        (b.left, b.right)
    } else {
        (0.0, b.width)
    };
    let half = Vector::new(
        0.5 * (right - left) + ROOM,
        0.5 * (b.above + b.below) + ROOM,
    );
    let shift = Vector::new(
        0.5 * b.width - 0.5 * (left + right),
        0.5 * (b.above - b.below) - BASELINE * size,
    );
    (half, shift)
}

pub(super) fn starts_italic(text: &RichText) -> bool {
    text.runs().first().is_some_and(|r| r.italic)
}

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

/// A `<text>`; `italic` is the base style its runs differ from. Written as
/// a plain element so that no line breaks get between its runs.
pub(super) fn text_node(
    id: &str,
    centre: Point,
    text: &RichText,
    size: f64,
    colour: &'static str,
    anchor: &'static str,
    italic: bool,
) -> Element {
    let mut t = Element::new("text");
    t.assign("id", id.to_owned());
    t.assign("class", Role::Label.name());
    t.assign("x", fmt(centre.x));
    t.assign("y", fmt(centre.y + BASELINE * size));
    t.assign("font-size", fmt(size));
    t.assign("fill", colour);
    t.assign("text-anchor", anchor);
    t.assign("font-style", if italic { "italic" } else { "normal" });
    t.append(Node::Raw(runs_markup(text, size, italic)));
    t
}
