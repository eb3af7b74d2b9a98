//! Symbols at a point: pins, constructed points and the data markers of
//! plots, each kept clear by labels as a whole.

use super::mark::{Mark, Paint, PathData, Shape, Stroke};
use super::markup::{finite, path, polyline_d, stroked_circle};
use super::symbol_sizes::{DOT_RADIUS, MARKER_RADIUS, PIN_PEN, PIN_RADIUS};
use super::{Ink, PanelLayout};
use crate::figure::{Pen, Symbol};
use crate::geom::Frame;
use crate::geom::{Point, Vector};

impl PanelLayout<'_> {
    /// A disc of page `radius` about a world point (pins and dots) painted
    /// with `paint`, kept clear by the labels; `None` if the point does
    /// not map to a finite one.
    fn disc(&mut self, ink: &Ink, centre: Point, radius: f64, paint: Paint) -> Option<Mark> {
        let c = self.p(centre);
        if !finite(&c) {
            return None;
        }
        self.obstacles
            .boxed(Frame::around(c, Vector::new(radius, radius)));
        self.points.push(c);
        Some(ink.tag(Mark::new(Shape::Circle {
            centre: c,
            radius,
            paint,
        })))
    }

    /// A pin joint: a small open circle on the paper.
    pub(super) fn pin(&mut self, ink: &Ink, centre: Point) -> Option<Mark> {
        let paint = Paint {
            stroke: Some(Stroke {
                colour: ink.pen.colour,
                width: PIN_PEN,
                dash: None,
                round: false,
            }),
            ..Paint::filled(self.style.paper())
        };
        self.disc(ink, centre, PIN_RADIUS, paint)
    }

    /// A constructed point: a small filled dot.
    pub(super) fn dot(&mut self, ink: &Ink, centre: Point) -> Option<Mark> {
        self.disc(ink, centre, DOT_RADIUS, Paint::filled(ink.pen.colour))
    }

    /// A data point: its symbol at a fixed page size, full lines.
    pub(super) fn marker(&mut self, ink: &Ink, centre: Point, symbol: Symbol) -> Option<Mark> {
        let c = self.p(centre);
        if !finite(&c) {
            return None;
        }
        let r = MARKER_RADIUS;
        self.obstacles.boxed(Frame::around(c, Vector::new(r, r)));
        // A point a letter may name (a polar diagram's pole, lettered O):
        // another point's letter does not stand nearer it than its own.
        self.points.push(c);
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
            return Some(ink.tag(stroked_circle(c, r, pen)).fill(fill));
        };
        let fill = if symbol == Symbol::Cross {
            "none"
        } else {
            self.style.paper()
        };
        Some(ink.tag(path(d, pen)).fill(fill))
    }
}

/// The path data of a marker's symbol about the page point `c`, `r` its
/// half size; `None` for the circles, written as `<circle>`s.
fn outline(symbol: Symbol, c: Point, r: f64) -> Option<PathData> {
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
        Symbol::Cross => {
            let mut d = polyline_d(&[v(-r, -r), v(r, r)], false);
            d.extend(polyline_d(&[v(-r, r), v(r, -r)], false));
            d
        }
    })
}
