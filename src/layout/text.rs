//! Text: the texts of rich runs set on the page, and the boxes that keep
//! labels and notes clear of each other.

use super::labels::ROOM;
use super::mark::{Mark, Shape, TextAnchor, TextMark};
use crate::figure::{Font, RichText, Role};
use crate::geom::{Point, Vector};

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

/// A text of the label class whose anchor point is `centre` across (its
/// baseline [`BASELINE`] × `size` below); `italic` is the base style its
/// runs differ from.
pub(super) fn text_node(
    id: &str,
    centre: Point,
    text: &RichText,
    size: f64,
    colour: &'static str,
    anchor: TextAnchor,
    italic: bool,
) -> Mark {
    Mark::new(Shape::Text(TextMark {
        at: Point::new(centre.x, centre.y + BASELINE * size),
        text: text.clone(),
        size,
        colour,
        anchor,
        italic,
    }))
    .tagged(id, Role::Label.name())
}
