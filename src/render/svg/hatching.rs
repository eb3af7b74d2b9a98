//! Hatching opened for letters: as a draughtsman interrupts hatching where
//! an inscription cannot be set outside it, a hatch stroke that a placed
//! letter's box meets is left out. The label search still treats the
//! hatching as heavily as a link, so a letter lands on it only where every
//! place near its point is crowded.

use super::Ink;
use super::markup::{path, pt};
use crate::figure::{Part, Pen, Role};
use crate::geom::{Point, Vector};
use crate::render::Element;
use crate::render::labels::{Bounds, span};
use std::fmt::Write as _;

/// Room kept between a letter's box and the strokes left, page units.
const ROOM: f64 = 1.0;

/// A hatching waiting for the labels: where its node sits in the panel's
/// drawing order, what it is written with, and its strokes (page points).
pub(super) struct Hatching {
    pub node: usize,
    pub id: String,
    pub role: Role,
    pub pen: Pen,
    pub strokes: Vec<(Point, Point)>,
}

impl Hatching {
    /// The strokes that meet none of the `boxes` (each grown by [`ROOM`]),
    /// as one path; `None` when every stroke is covered.
    pub fn written(&self, boxes: &[Bounds]) -> Option<Element> {
        let ink = Ink {
            id: &self.id,
            role: self.role,
            pen: self.pen,
            part: Part::Plain,
        };
        let d = kept(&self.strokes, boxes).fold(String::new(), |mut d, (p, q)| {
            let sep = if d.is_empty() { "" } else { " " };
            let _ = write!(d, "{sep}M{} L{}", pt(*p), pt(*q));
            d
        });
        (!d.is_empty()).then(|| ink.tag(path(d, self.pen)))
    }
}

/// The strokes that meet none of the boxes grown by [`ROOM`].
fn kept<'a>(
    strokes: &'a [(Point, Point)],
    boxes: &'a [Bounds],
) -> impl Iterator<Item = &'a (Point, Point)> + 'a {
    let room = Vector::new(ROOM, ROOM);
    strokes.iter().filter(move |(p, q)| {
        boxes.iter().all(|b| {
            let grown = Bounds {
                min: b.min - room,
                max: b.max + room,
            };
            span(*p, q - p, &grown).is_none()
        })
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_stroke_under_a_letter_is_left_out_and_only_that_one() {
        let strokes: Vec<(Point, Point)> = (0..10)
            .map(|k| {
                let x = 6.0 * f64::from(k);
                (Point::new(x, 0.0), Point::new(x - 5.2, 6.5))
            })
            .collect();
        let letter = Bounds::around(Point::new(24.0, 10.0), Vector::new(4.0, 5.0));
        let boxes = [letter];
        let left: Vec<_> = kept(&strokes, &boxes).collect();
        // The strokes from x = 24 and 30 reach into the letter's box.
        assert_eq!(left.len(), 8, "{left:?}");
        assert!(left.iter().all(|(p, _)| p.x != 24.0 && p.x != 30.0));
        let clear = Bounds::around(Point::new(24.0, 40.0), Vector::new(4.0, 5.0));
        let boxes = [clear];
        assert_eq!(kept(&strokes, &boxes).count(), 10);
    }
}
