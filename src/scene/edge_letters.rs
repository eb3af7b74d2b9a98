//! The letters of arrows at the frame's edge that run side by side: each
//! set first on the side away from the other arrow.

use crate::figure::{Item, Shape};
use crate::geom::{Point, Vector, cross};

/// How near (page units) two parallel edge arrows stand for their
/// letters to be set on their far sides: two ems of a letter.
pub(super) const SIDE_BY_SIDE: f64 = 36.0;

/// How far (page units) such a letter's anchor is moved off its arrow's
/// tail to that side, so that the nearest place on it clears the arrow.
pub(super) const SHIFT: f64 = 6.0;

/// The sine of the widest angle between two arrows read as parallel
/// (10°).
const PARALLEL: f64 = 0.173_648_177_666_930_3;

/// An edge arrow: the id of its letter, its tail, its unit direction and
/// its length.
struct EdgeArrow {
    label: String,
    tail: Point,
    along: Vector,
    length: f64,
}

/// The edge arrow of `item` (`offpage-X` or `infinity-X`, lettered
/// `label-X`, each id with the canvas's prefix), if it is one with a
/// length.
fn edge_arrow(item: &Item) -> Option<EdgeArrow> {
    let kind = ["offpage-", "infinity-"]
        .into_iter()
        .find(|k| item.id.contains(k))?;
    let Shape::Arrow { from, to } = item.shape else {
        return None;
    };
    let length = (to - from).norm();
    (length > 0.0).then(|| EdgeArrow {
        label: item.id.replacen(kind, "label-", 1),
        tail: from,
        along: (to - from) / length,
        length,
    })
}

/// Turns the letter of every edge arrow that runs beside another, in the
/// same sense and within `near` world units of its line along their
/// common length, towards the side away from the other: between two
/// parallel arrows a letter reads as naming either (inversion 2 at
/// l = 1.08 r, 269.31°: "to O_bd" between its arrow and O_cd's, nearer
/// O_cd's), its anchor moved `shift` world units to that side. A letter
/// beside several is turned from the nearest. Nothing changes where no
/// two arrows run side by side.
pub(super) fn part(items: &mut [Item], near: f64, shift: f64) {
    let arrows: Vec<EdgeArrow> = items.iter().filter_map(edge_arrow).collect();
    for a in &arrows {
        let away = (arrows.iter())
            .filter(|b| b.label != a.label && a.along.dot(&b.along) > 0.0)
            .filter(|b| cross(&a.along, &b.along).abs() < PARALLEL)
            .filter_map(|b| {
                let v = a.tail - b.tail;
                let across = v - a.along * v.dot(&a.along);
                let overlap = v.dot(&a.along).abs() < a.length.max(b.length);
                (overlap && across.norm() > 0.0 && across.norm() < near).then_some(across)
            })
            .min_by(|x, y| x.norm().total_cmp(&y.norm()));
        let Some(away) = away else {
            continue;
        };
        if let Some(item) = items.iter_mut().find(|i| i.id == a.label)
            && let Shape::Label { anchor, toward, .. } = &mut item.shape
        {
            let u = away.normalize();
            *anchor += u * shift;
            *toward = Some(u);
        }
    }
}
