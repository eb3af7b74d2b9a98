//! A detail's points that its enlargement does not set apart: those whose
//! markers still run into one on its page take one marker and one joint
//! letter there, as the main view letters them.

use super::COINCIDE;
use crate::figure::{Item, Part, RichText, Role, Shape};
use crate::geom::{Point, farthest_from_segment};

/// A marked point of a detail: its name, its place and whether it is a
/// pin.
struct Marked {
    name: String,
    at: Point,
    pin: bool,
    /// Whether its letter names a result.
    result: bool,
}

/// Letters together the points of a detail's `items` (ids `{prefix}point-…`
/// and `{prefix}label-…`) whose markers stand within `UNDER_PIN` page
/// units of each other at the detail's `scale` (page units per world
/// unit: a dot under a pin's circle or within two of its pen widths; one
/// lettered with a result of `results`, only with its disc reaching the
/// circle, [`crate::scene::canvas::ON_PIN`]):
/// where the enlargement is held to the page's width, G at 0.02 of
/// the crank from C, K between them, stay under C's pin at ×25, and their
/// own dots and letters named points the reader cannot find. A dot is
/// joined to a pin whose marker it runs into, the pin heading the group
/// and the dots by name after it; two pins are never joined (each is a
/// part drawn), nor two dots alone (the detail was chosen to set the
/// constructed points apart, and two dots side by side still show two
/// points). The dots' markers and letters are taken out and their names
/// added to the pin's letter.
///
/// `results` are the letters of the points whose distance from C the
/// figure is read by (E, CE the piston's velocity; G, CG its
/// acceleration): seen beside a pin and lettered with it, G read as
/// standing at B (Bennett's construction at l = 39 r, 0°: "B, F, G, K,
/// L" with CG = 1.026 r in the notes), and the figure gave another
/// acceleration than its notes.
pub(crate) fn letter_near_together(
    items: &mut Vec<Item>,
    prefix: &str,
    scale: f64,
    results: &[&str],
) {
    let point_id = format!("{prefix}point-");
    let label_id = |name: &str| format!("{prefix}label-{name}");
    let text_of = |items: &[Item], name: &str| {
        let id = label_id(name);
        (items.iter().find(|it| it.id == id)).and_then(|it| match &it.shape {
            Shape::Label { text, .. } => Some(text.clone()),
            _ => None,
        })
    };
    // Whether a point's letter names a result (alone or with the points
    // at its place, "F, G, K, L").
    let names_a_result = |name: &str| {
        text_of(items, name).is_some_and(|t| t.plain().split(", ").any(|n| results.contains(&n)))
    };
    let marked: Vec<Marked> = (items.iter())
        .filter_map(|it| {
            let name = it.id.strip_prefix(&point_id)?;
            let (at, pin) = match it.shape {
                Shape::Pin { centre } => (centre, true),
                Shape::Dot { centre } => (centre, false),
                _ => return None,
            };
            Some(Marked {
                name: name.to_string(),
                at,
                pin,
                result: names_a_result(name),
            })
        })
        .collect();
    let near = |p: &Marked, q: &Marked| {
        let within = match p.result || q.result {
            true => crate::scene::canvas::ON_PIN,
            false => crate::scene::canvas::UNDER_PIN,
        };
        (p.pin != q.pin) && (p.at - q.at).norm() * scale < within
    };
    let mut left: Vec<&Marked> = marked.iter().collect();
    let mut groups: Vec<Vec<&Marked>> = Vec::new();
    while !left.is_empty() {
        let first = left.remove(0);
        let mut group = vec![first];
        while let Some(j) = (left.iter()).position(|p| group.iter().any(|g| near(g, p))) {
            group.push(left.remove(j));
        }
        if group.len() > 1 {
            groups.push(group);
        }
    }
    for mut group in groups {
        // Pins first in the order drawn, then the others by name.
        group.sort_by_key(|m| (!m.pin, (!m.pin).then_some(m.name.as_str())));
        let Some((head, rest)) = group.split_first() else {
            continue;
        };
        let Some(mut joint) = text_of(items, &head.name) else {
            continue;
        };
        for m in rest {
            if let Some(text) = text_of(items, &m.name) {
                joint = joint.then(RichText::parse(", ")).then(text);
            }
        }
        let gone: Vec<String> = (rest.iter())
            .flat_map(|m| [label_id(&m.name), format!("{point_id}{}", m.name)])
            .collect();
        items.retain(|it| !gone.contains(&it.id));
        let id = label_id(&head.name);
        if let Some(Shape::Label { text, .. }) = (items.iter_mut())
            .find(|it| it.id == id)
            .map(|it| &mut it.shape)
        {
            *text = joint;
        }
    }
}

/// Takes out of a detail's `items` the construction lines (constructed,
/// results and auxiliaries, each one straight segment) that lie along a
/// link of the mechanism (`{prefix}link-crank`, `{prefix}link-rod`) for
/// their whole length: both ends within [`COINCIDE`] page units of the
/// link at the detail's `scale`, so that the line runs beside the link
/// all the way, where the two read as one doubled link (CE beside the
/// crank near 90°, E at B; Bennett's LK and FG from B to C at a long rod).
/// The link draws the line there, and the points it joins are lettered
/// with the link's pins ([`letter_near_together`]).
pub(super) fn leave_out_along_links(items: &mut Vec<Item>, prefix: &str, scale: f64) {
    let ends = |it: &Item| match &it.shape {
        Shape::Polyline {
            points,
            closed: false,
        } => match points.as_slice() {
            [p, q] => Some((*p, *q)),
            _ => None,
        },
        _ => None,
    };
    let links: Vec<(Point, Point)> = (items.iter())
        .filter(|it| {
            it.role == Role::Link
                && [format!("{prefix}link-crank"), format!("{prefix}link-rod")].contains(&it.id)
        })
        .filter_map(ends)
        .collect();
    items.retain(|it| {
        // The line of stroke is the frame's centre line, not a
        // construction: it stays where the crank lies along it.
        let drawn = matches!(it.role, Role::Construction | Role::Result | Role::Auxiliary)
            && it.part != Part::CentreLine;
        let Some((p, q)) = ends(it).filter(|_| drawn) else {
            return true;
        };
        !(links.iter()).any(|&(a, b)| farthest_from_segment(p, q, a, b) * scale < COINCIDE)
    });
}
