//! Placed marks as SVG elements: paths (their data on the grid),
//! circles, groups and texts, each with its id, class and paint.

use super::text::text_element;
use crate::layout::{Mark, MarkShape, Paint, PathCommand, PathData};
use crate::number::{OnGrid, fmt};
use crate::render::Element;
use std::fmt::Write as _;

/// The element of `mark`, with its id and class.
pub(super) fn element(mark: &Mark) -> Element {
    let mut e = match &mark.shape {
        MarkShape::Path(d, paint) => painted(Element::new("path").set("d", path_data(d)), paint),
        MarkShape::Circle {
            centre,
            radius,
            paint,
        } => painted(
            Element::new("circle")
                .set("cx", fmt(centre.x))
                .set("cy", fmt(centre.y))
                .set("r", fmt(*radius)),
            paint,
        ),
        MarkShape::Text(t) => text_element(t),
        MarkShape::Group(children) => {
            (children.iter()).fold(Element::new("g"), |g, c| g.add(element(c)))
        }
    };
    if let Some(id) = &mark.id {
        e.assign("id", id.clone());
    }
    if let Some(class) = mark.class {
        e.assign("class", class);
    }
    e
}

/// `e` with the attributes of `paint`.
fn painted(mut e: Element, paint: &Paint) -> Element {
    match paint.stroke {
        Some(s) => {
            e.assign("stroke", s.colour);
            e.assign("stroke-width", fmt(s.width));
            if let Some(dash) = s.dash {
                e.assign("stroke-dasharray", dash);
            }
            if s.round {
                e.assign("stroke-linecap", "round");
                e.assign("stroke-linejoin", "round");
            }
        }
        None => e.assign("stroke", "none"),
    }
    e.assign("fill", paint.fill);
    if let Some(o) = paint.fill_opacity {
        e.assign("fill-opacity", fmt(o));
    }
    e
}

/// A path's data: each command's letter and its points on the grid,
/// commands one space apart.
fn path_data(d: &PathData) -> String {
    let mut out = String::new();
    for c in d.commands() {
        if !out.is_empty() {
            out.push(' ');
        }
        let _ = match *c {
            PathCommand::Move(p) => write!(out, "M{} {}", OnGrid(p.x), OnGrid(p.y)),
            PathCommand::Line(p) => write!(out, "L{} {}", OnGrid(p.x), OnGrid(p.y)),
            PathCommand::Cubic(a, b, p) => write!(
                out,
                "C{} {} {} {} {} {}",
                OnGrid(a.x),
                OnGrid(a.y),
                OnGrid(b.x),
                OnGrid(b.y),
                OnGrid(p.x),
                OnGrid(p.y)
            ),
            PathCommand::Close => write!(out, "Z"),
        };
    }
    out
}
