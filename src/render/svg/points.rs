//! Symbols at a point: pins, constructed points and the data markers of
//! plots, each kept clear by labels as a whole.

use super::markup::{finite, path, polyline_d, stroke};
use super::{Ink, PanelWriter};
use crate::figure::{Pen, Symbol};
use crate::geom::{Point, Vector};
use crate::number::fmt;
use crate::render::Element;
use crate::render::labels::Bounds;
use crate::render::symbol_sizes::{DOT_RADIUS, MARKER_RADIUS, PIN_RADIUS};

impl PanelWriter<'_> {
    /// A disc of page `radius` about a world point (pins and dots), kept
    /// clear by the labels; `None` if the point does not map to a finite one.
    fn disc(&mut self, ink: &Ink, centre: Point, radius: f64) -> Option<Element> {
        let c = self.p(centre);
        if !finite(&c) {
            return None;
        }
        self.obstacles
            .boxed(Bounds::around(c, Vector::new(radius, radius)));
        self.points.push(c);
        Some(
            ink.tag(Element::new("circle"))
                .set("cx", fmt(c.x))
                .set("cy", fmt(c.y))
                .set("r", fmt(radius)),
        )
    }

    /// A pin joint: a small open circle on the paper.
    pub(super) fn pin(&mut self, ink: &Ink, centre: Point) -> Option<Element> {
        let paper = self.style.paper();
        let disc = self.disc(ink, centre, PIN_RADIUS)?;
        Some(
            disc.set("fill", paper)
                .set("stroke", ink.pen.colour)
                .set("stroke-width", fmt(1.3)),
        )
    }

    /// A constructed point: a small filled dot.
    pub(super) fn dot(&mut self, ink: &Ink, centre: Point) -> Option<Element> {
        let disc = self.disc(ink, centre, DOT_RADIUS)?;
        Some(disc.set("fill", ink.pen.colour).set("stroke", "none"))
    }

    /// A data point: its symbol at a fixed page size, full lines.
    pub(super) fn marker(&mut self, ink: &Ink, centre: Point, symbol: Symbol) -> Option<Element> {
        let c = self.p(centre);
        if !finite(&c) {
            return None;
        }
        let r = MARKER_RADIUS;
        self.obstacles.boxed(Bounds::around(c, Vector::new(r, r)));
        let pen = Pen {
            width: 1.1,
            dash: None,
            ..ink.pen
        };
        let Some(d) = outline(symbol, c, r) else {
            let fill = if symbol == Symbol::Disc {
                pen.colour
            } else {
                self.style.paper()
            };
            return Some(
                ink.tag(stroke(Element::new("circle"), pen))
                    .set("cx", fmt(c.x))
                    .set("cy", fmt(c.y))
                    .set("r", fmt(r))
                    .set("fill", fill),
            );
        };
        let fill = if symbol == Symbol::Cross {
            "none"
        } else {
            self.style.paper()
        };
        Some(ink.tag(path(d, pen)).set("fill", fill))
    }
}

/// The path data of a marker's symbol about the page point `c`, `r` its
/// half size; `None` for the circles, written as `<circle>`s.
fn outline(symbol: Symbol, c: Point, r: f64) -> Option<String> {
    let v = |x: f64, y: f64| c + Vector::new(x, y);
    Some(match symbol {
        Symbol::Disc | Symbol::Circle => return None,
        Symbol::Square => polyline_d(&[v(-r, -r), v(r, -r), v(r, r), v(-r, r)], true),
        Symbol::Triangle => {
            let h = 1.2 * r;
            polyline_d(&[v(0.0, -h), v(h, 0.8 * h), v(-h, 0.8 * h)], true)
        }
        Symbol::Diamond => {
            let h = 1.3 * r;
            polyline_d(&[v(0.0, -h), v(h, 0.0), v(0.0, h), v(-h, 0.0)], true)
        }
        Symbol::Cross => format!(
            "{} {}",
            polyline_d(&[v(-r, -r), v(r, r)], false),
            polyline_d(&[v(-r, r), v(r, -r)], false)
        ),
    })
}
