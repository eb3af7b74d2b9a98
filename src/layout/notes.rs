//! Text on the figure: letters and values placed clear of everything
//! drawn (once the panel's lines are all known), texts at fixed places
//! (ticks, axis titles, legends) and the scale notes.

use super::mark::{Mark, TextAnchor};
use super::markup::{finite, unit};
use super::symbol_sizes::{LETTER_GAP, NOTE_LINE, NOTE_SIZE};
use super::text::{BASELINE, starts_italic, text_half, text_node};
use super::{Ink, PanelLayout, Pending};
use crate::figure::{Align, Part, RichText, Role, TextSize};
use crate::geom::Frame;
use crate::geom::{Point, Vector};

impl PanelLayout<'_> {
    /// A label near `anchor`: kept to be placed after every line of the
    /// panel is known, so nothing is written now.
    pub(super) fn label(
        &mut self,
        ink: &Ink,
        anchor: Point,
        text: &RichText,
        size: TextSize,
        (toward, line): (Option<Vector>, Option<[Point; 2]>),
    ) -> Option<Mark> {
        let a = self.p(anchor);
        if !finite(&a) {
            return None;
        }
        self.pending.push(Pending {
            id: ink.id.to_string(),
            anchor: a,
            text: text.clone(),
            size: self.style.font_size(size),
            gap: if size == TextSize::Letter {
                LETTER_GAP
            } else {
                3.0
            },
            letter: size == TextSize::Letter,
            toward: toward.and_then(|u| unit(self.t.apply_vector(u))),
            joint: ink.part == Part::Joint && size == TextSize::Letter,
            line: line
                .map(|[p, q]| (self.p(p), self.p(q)))
                .filter(|(p, q)| finite(p) && finite(q) && p != q),
            along: Vec::new(),
            wedge: None,
        });
        None
    }

    /// A text set `offset` page units from the page point of `at`,
    /// aligned there by `align`; labels keep off it.
    pub(super) fn text(
        &mut self,
        ink: &Ink,
        (at, offset): (Point, Vector),
        text: &RichText,
        align: Align,
        size: TextSize,
    ) -> Option<Mark> {
        let c = self.p(at) + offset;
        if !finite(&c) {
            return None;
        }
        let size = self.style.font_size(size);
        let half = text_half(text, size, self.font);
        let (anchor, middle) = match align {
            Align::Start => (TextAnchor::Start, c + Vector::new(half.x, 0.0)),
            Align::Middle => (TextAnchor::Middle, c),
            Align::End => (TextAnchor::End, c - Vector::new(half.x, 0.0)),
        };
        self.obstacles.text(Frame::around(middle, half));
        Some(text_node(
            ink.id,
            c,
            text,
            size,
            self.style.pen(Role::Label).colour,
            anchor,
            starts_italic(text),
        ))
    }

    /// Lines of a note from the page point `corner` (top left), all in one
    /// size, small enough for the longest to fit before the page's right
    /// edge.
    pub(super) fn note(&mut self, ink: &Ink, corner: Point, lines: &[RichText]) -> Option<Mark> {
        let mut g = ink.tag(Mark::group());
        let colour = self.style.pen(Role::Label).colour;
        let size = self.note_size(corner, lines);
        for (i, line) in lines.iter().enumerate() {
            let y = corner.y + size * 0.8 + NOTE_LINE * i as f64;
            let half = text_half(line, size, self.font);
            self.obstacles.text(Frame::around(
                Point::new(corner.x + half.x, y - BASELINE * size),
                half,
            ));
            g = g.with(text_node(
                &format!("{}-{}", ink.id, i + 1),
                Point::new(corner.x, y - BASELINE * size),
                line,
                size,
                colour,
                TextAnchor::Start,
                false,
            ));
        }
        Some(g)
    }

    /// The size of a note's lines: [`NOTE_SIZE`], or less where the
    /// longest would not fit between `corner` and the page's right edge.
    fn note_size(&self, corner: Point, lines: &[RichText]) -> f64 {
        let room = (self.page_width - corner.x - 8.0).max(10.0);
        let widest = lines
            .iter()
            .map(|l| l.width(self.font, NOTE_SIZE))
            .fold(0.0, f64::max);
        if widest > room {
            NOTE_SIZE * room / widest
        } else {
            NOTE_SIZE
        }
    }
}
