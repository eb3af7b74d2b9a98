//! The SVG writer: each panel's primitives mapped to the page by the
//! panel's one transform, numbers on a fixed grid, ids and order stable.

use super::labels::{Bounds, Obstacles, place};
use super::number::{fmt, fmt_coefficient};
use super::style::*;
use crate::figure::{
    Align, Figure, Font, Item, PageFromWorld, Panel, Path, PathSegment, RichText, Role,
    SUBSCRIPT_DROP, SUBSCRIPT_SIZE, SUPERSCRIPT_RISE, Shape, Symbol, TextSize,
};
use crate::geom::{Point, Vector};
use crate::render::Style;
use serde_json::{Value, json};
use std::collections::hash_map::DefaultHasher;
use std::fmt as stdfmt;
use std::fmt::Write as _;
use std::hash::Hash;
use svg::Document;
use svg::node::element::{
    Circle, ClipPath, Definitions, Element, Group, Path as SvgPath, Rectangle,
};
use svg::node::{Node, NodeDefaultHash};

/// Markup written as is inside a `<text>` (runs as `<tspan>`s), without
/// the line breaks the `svg` crate puts between child elements, which
/// would show as spaces.
#[derive(Debug, Clone)]
struct Raw(String);

impl stdfmt::Display for Raw {
    fn fmt(&self, f: &mut stdfmt::Formatter<'_>) -> stdfmt::Result {
        f.write_str(&self.0)
    }
}

impl Node for Raw {
    fn get_name(&self) -> &str {
        "raw"
    }

    fn is_bare(&self) -> bool {
        true
    }
}

impl NodeDefaultHash for Raw {
    fn default_hash(&self, state: &mut DefaultHasher) {
        self.0.hash(state);
    }
}

fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

fn pt(p: Point) -> String {
    format!("{} {}", fmt(p.x), fmt(p.y))
}

fn finite(p: &Point) -> bool {
    p.x.is_finite() && p.y.is_finite()
}

fn unit(v: Vector) -> Option<Vector> {
    let n = v.norm();
    (n > 0.0 && n.is_finite()).then(|| v / n)
}

/// The cubic Béziers of a circular arc, pieces of at most 30°.
fn arc_beziers(centre: Point, radius: f64, start: f64, sweep: f64) -> Vec<[Point; 4]> {
    let n = ((sweep.abs() / (std::f64::consts::PI / 6.0)).ceil() as usize).clamp(1, 64);
    let delta = sweep / n as f64;
    let k = 4.0 / 3.0 * (delta / 4.0).tan();
    (0..n)
        .map(|i| {
            let a0 = start + delta * i as f64;
            let a1 = a0 + delta;
            let (s0, c0) = a0.sin_cos();
            let (s1, c1) = a1.sin_cos();
            let p0 = centre + Vector::new(c0, s0) * radius;
            let p3 = centre + Vector::new(c1, s1) * radius;
            let p1 = p0 + Vector::new(-s0, c0) * (k * radius);
            let p2 = p3 - Vector::new(-s1, c1) * (k * radius);
            [p0, p1, p2, p3]
        })
        .collect()
}

fn bezier_d(pieces: &[[Point; 4]]) -> String {
    let mut d = String::new();
    if let Some(first) = pieces.first() {
        let _ = write!(d, "M{}", pt(first[0]));
    }
    for [_, c1, c2, p] in pieces {
        let _ = write!(d, " C{} {} {}", pt(*c1), pt(*c2), pt(*p));
    }
    d
}

fn polyline_d(points: &[Point], closed: bool) -> String {
    let mut d = String::new();
    for (i, p) in points.iter().enumerate() {
        let _ = write!(d, "{}{}", if i == 0 { "M" } else { " L" }, pt(*p));
    }
    if closed {
        d.push_str(" Z");
    }
    d
}

fn stroke<T: Node>(mut node: T, pen: Pen) -> T {
    node.assign("stroke", pen.colour);
    node.assign("stroke-width", fmt(pen.width));
    node.assign("fill", "none");
    if let Some(d) = pen.dash {
        node.assign("stroke-dasharray", d);
    }
    node
}

fn path(d: String, pen: Pen) -> SvgPath {
    stroke(SvgPath::new().set("d", d), pen)
        .set("stroke-linecap", "round")
        .set("stroke-linejoin", "round")
}

fn arrow_head(tip: Point, u: Vector, colour: &'static str) -> SvgPath {
    let n = Vector::new(-u.y, u.x);
    let back = tip - u * ARROW_LENGTH;
    let pts = [
        tip,
        back + n * ARROW_HALF_WIDTH,
        back - n * ARROW_HALF_WIDTH,
    ];
    SvgPath::new()
        .set("d", polyline_d(&pts, true))
        .set("fill", colour)
        .set("stroke", "none")
}

/// Where [`text_node`] puts the baseline: this fraction of the size below
/// the text's centre (half the cap height, near enough).
const BASELINE: f64 = 0.35;

/// Half the width and height of the box about a text's centre that holds
/// its ink (advances and glyph bounds of `font`) with 1 unit to spare, for
/// placement.
fn text_half(text: &RichText, size: f64, font: Font) -> Vector {
    let b = text.measure(font, size);
    let baseline = BASELINE * size;
    Vector::new(
        0.5 * b.width + 1.0,
        (b.above - baseline).max(b.below + baseline) + 1.0,
    )
}

fn starts_italic(text: &RichText) -> bool {
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
        escape(t),
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
fn text_node(
    id: &str,
    centre: Point,
    text: &RichText,
    size: f64,
    colour: &str,
    anchor: &str,
    italic: bool,
) -> Element {
    let mut t = Element::new("text");
    t.assign("id", id);
    t.assign("class", Role::Label.name());
    t.assign("x", fmt(centre.x));
    t.assign("y", fmt(centre.y + BASELINE * size));
    t.assign("font-size", fmt(size));
    t.assign("fill", colour);
    t.assign("text-anchor", anchor);
    t.assign("font-style", if italic { "italic" } else { "normal" });
    t.append(Raw(runs_markup(text, size, italic)));
    t
}

/// A label waiting to be placed once every line is known.
struct Pending {
    id: String,
    anchor: Point,
    text: RichText,
    size: f64,
    gap: f64,
}

struct PanelWriter<'a> {
    t: &'a PageFromWorld,
    page_width: f64,
    style: crate::render::Style,
    font: Font,
    obstacles: Obstacles,
    pending: Vec<Pending>,
}

impl PanelWriter<'_> {
    fn p(&self, w: Point) -> Point {
        self.t.apply(w)
    }

    fn orientation(&self) -> f64 {
        let [a, b, c, d, _, _] = self.t.coefficients();
        if a * d - b * c < 0.0 { -1.0 } else { 1.0 }
    }

    /// The page arc of a world arc about a page centre (page radius).
    fn page_arc(&self, centre: Point, radius: f64, start: f64, sweep: f64) -> Vec<[Point; 4]> {
        let dir = self.t.apply_vector(Vector::new(start.cos(), start.sin()));
        let start = dir.y.atan2(dir.x);
        arc_beziers(centre, radius, start, sweep * self.orientation())
    }

    /// A disc of page `radius` about a world point (pins and dots), kept
    /// clear by the labels; `None` if the point does not map to a finite one.
    fn disc(&mut self, id: &str, class: &str, centre: Point, radius: f64) -> Option<Circle> {
        let c = self.p(centre);
        if !finite(&c) {
            return None;
        }
        self.obstacles
            .boxed(Bounds::around(c, Vector::new(radius, radius)));
        Some(
            Circle::new()
                .set("id", id)
                .set("class", class)
                .set("cx", fmt(c.x))
                .set("cy", fmt(c.y))
                .set("r", fmt(radius)),
        )
    }

    fn item(&mut self, item: &Item) -> Option<Box<dyn Node>> {
        let mut pen = self.style.pen(item.role);
        if let Some(dash) = item.dash {
            pen.dash = Style::dash(dash);
            if let Some(colour) = self.style.series(dash) {
                pen.colour = colour;
            }
        }
        if let Some(colour) = item.hue.and_then(|h| self.style.hue(h)) {
            pen.colour = colour;
        }
        self.obstacles.set_weight(match item.role {
            Role::Link | Role::Force => 3.0,
            Role::Construction | Role::Result => 1.5,
            _ => 1.0,
        });
        let id = item.id.as_str();
        let class = item.role.name();
        let node: Box<dyn Node> = match &item.shape {
            Shape::Path(p) => Box::new(self.path(p, pen)?.set("id", id).set("class", class)),
            Shape::Polyline { points, closed } => {
                let pts: Vec<Point> = points.iter().map(|p| self.p(*p)).collect();
                if pts.len() < 2 || !pts.iter().all(finite) {
                    return None;
                }
                self.obstacles.polyline(&pts);
                if *closed {
                    self.obstacles.segment(pts[pts.len() - 1], pts[0]);
                }
                let mut node = path(polyline_d(&pts, *closed), pen)
                    .set("id", id)
                    .set("class", class);
                if item.role == Role::Auxiliary && pts.len() == 2 && id.starts_with("line-stroke") {
                    node = node.set("stroke-dasharray", "14 3 2 3");
                }
                Box::new(node)
            }
            Shape::Region { points } => {
                let (colour, opacity) = self.style.region()?;
                let pts: Vec<Point> = points.iter().map(|p| self.p(*p)).collect();
                if pts.len() < 3 || !pts.iter().all(finite) {
                    return None;
                }
                Box::new(
                    SvgPath::new()
                        .set("id", id)
                        .set("class", class)
                        .set("d", polyline_d(&pts, true))
                        .set("fill", colour)
                        .set("fill-opacity", fmt(opacity))
                        .set("stroke", "none"),
                )
            }
            Shape::Circle { centre, radius } => {
                let c = self.p(*centre);
                let pieces: Vec<[Point; 4]> =
                    arc_beziers(*centre, *radius, 0.0, 2.0 * std::f64::consts::PI)
                        .into_iter()
                        .map(|b| b.map(|p| self.p(p)))
                        .collect();
                self.bezier_obstacles(&pieces);
                if !finite(&c) {
                    return None;
                }
                let [a, b, cc, d, _, _] = self.t.coefficients();
                if (a * a + b * b - cc * cc - d * d).abs() <= 1e-9 * (a * a + b * b) {
                    Box::new(
                        stroke(Circle::new(), pen)
                            .set("id", id)
                            .set("class", class)
                            .set("cx", fmt(c.x))
                            .set("cy", fmt(c.y))
                            .set("r", fmt(radius * self.t.scale())),
                    )
                } else {
                    Box::new(
                        path(bezier_d(&pieces), pen)
                            .set("id", id)
                            .set("class", class),
                    )
                }
            }
            Shape::Arc {
                centre,
                radius,
                start,
                sweep,
                arrow,
            } => {
                let pieces: Vec<[Point; 4]> = arc_beziers(*centre, *radius, *start, *sweep)
                    .into_iter()
                    .map(|b| b.map(|p| self.p(p)))
                    .collect();
                if !pieces.iter().flatten().all(finite) {
                    return None;
                }
                self.bezier_obstacles(&pieces);
                let line = path(bezier_d(&pieces), pen);
                if *arrow {
                    let last = pieces.last()?;
                    let u = unit(last[3] - last[2])?;
                    Box::new(
                        Group::new()
                            .set("id", id)
                            .set("class", class)
                            .add(line)
                            .add(arrow_head(last[3], u, pen.colour)),
                    )
                } else {
                    Box::new(line.set("id", id).set("class", class))
                }
            }
            Shape::Pin { centre } => {
                let paper = self.style.paper();
                let disc = self.disc(id, class, *centre, PIN_RADIUS)?;
                Box::new(
                    disc.set("fill", paper)
                        .set("stroke", pen.colour)
                        .set("stroke-width", fmt(1.3)),
                )
            }
            Shape::Dot { centre } => {
                let disc = self.disc(id, class, *centre, DOT_RADIUS)?;
                Box::new(disc.set("fill", pen.colour).set("stroke", "none"))
            }
            Shape::Bearing { centre } => {
                let c = self.p(*centre);
                if !finite(&c) {
                    return None;
                }
                let (h, w, base) = (17.0, 10.0, 17.0);
                let tri = [c, c + Vector::new(-w, h), c + Vector::new(w, h)];
                let foot = [c + Vector::new(-base, h), c + Vector::new(base, h)];
                let mut hatch = String::new();
                let mut x = -base + 3.0;
                while x <= base {
                    let s = c + Vector::new(x, h);
                    let _ = write!(hatch, "M{} L{} ", pt(s), pt(s + Vector::new(-5.0, 6.0)));
                    x += 5.0;
                }
                self.obstacles.polyline(&[tri[0], tri[1], tri[2], tri[0]]);
                self.obstacles.boxed(Bounds {
                    min: c + Vector::new(-base - 5.0, 0.5 * h),
                    max: c + Vector::new(base, h + 6.0),
                });
                Box::new(
                    Group::new()
                        .set("id", id)
                        .set("class", class)
                        .add(path(polyline_d(&tri, true), pen).set("fill", self.style.paper()))
                        .add(path(polyline_d(&foot, false), pen))
                        .add(path(
                            hatch.trim_end().to_string(),
                            Pen { width: 0.7, ..pen },
                        )),
                )
            }
            Shape::Block { points } => {
                let pts: Vec<Point> = points.iter().map(|p| self.p(*p)).collect();
                if pts.len() < 3 || !pts.iter().all(finite) {
                    return None;
                }
                // No letter inside the block: the whole body is kept clear.
                let (lo, hi) = pts
                    .iter()
                    .fold((pts[0], pts[0]), |(lo, hi), p| (lo.inf(p), hi.sup(p)));
                self.obstacles.boxed(Bounds { min: lo, max: hi });
                // Unfilled, so that curves and constructions through the
                // slider (Kisch's semicircle ends at A) stay visible.
                Box::new(
                    path(polyline_d(&pts, true), Pen { width: 1.6, ..pen })
                        .set("fill", "none")
                        .set("id", id)
                        .set("class", class),
                )
            }
            Shape::Arrow { from, to } => {
                let (a, b) = (self.p(*from), self.p(*to));
                if !finite(&a) || !finite(&b) {
                    return None;
                }
                let u = unit(b - a)?;
                self.obstacles.segment(a, b);
                // The head is wider than the shaft: keep labels off it too.
                let half = 0.5 * ARROW_LENGTH;
                self.obstacles
                    .boxed(Bounds::around(b - u * half, Vector::new(half, half)));
                Box::new(
                    Group::new()
                        .set("id", id)
                        .set("class", class)
                        .add(path(
                            polyline_d(&[a, b - u * (0.6 * ARROW_LENGTH)], false),
                            pen,
                        ))
                        .add(arrow_head(b, u, pen.colour)),
                )
            }
            Shape::Hatch { from, to, side } => {
                let (a, b) = (self.p(*from), self.p(*to));
                let t = unit(b - a)?;
                let n = unit(self.t.apply_vector(*side))?;
                let len = (b - a).norm();
                let mut d = String::new();
                let mut s = 0.5 * HATCH_SPACING;
                while s < len {
                    let p = a + t * s;
                    let q = p + n * HATCH_DEPTH - t * (0.8 * HATCH_DEPTH);
                    let _ = write!(d, "M{} L{} ", pt(p), pt(q));
                    s += HATCH_SPACING;
                }
                if d.is_empty() {
                    return None;
                }
                self.obstacles
                    .segment(a + n * (0.5 * HATCH_DEPTH), b + n * (0.5 * HATCH_DEPTH));
                Box::new(
                    path(d.trim_end().to_string(), Pen { width: 0.6, ..pen })
                        .set("id", id)
                        .set("class", class),
                )
            }
            Shape::RightAngle { vertex, u, v } => {
                let c = self.p(*vertex);
                let u = unit(self.t.apply_vector(*u))?;
                let v = unit(self.t.apply_vector(*v))?;
                let s = RIGHT_ANGLE;
                let pts = [c + u * s, c + u * s + v * s, c + v * s];
                if !pts.iter().all(finite) {
                    return None;
                }
                Box::new(
                    path(
                        polyline_d(&pts, false),
                        Pen {
                            width: 0.7,
                            dash: None,
                            ..pen
                        },
                    )
                    .set("id", id)
                    .set("class", class),
                )
            }
            Shape::AngleMark {
                vertex,
                start,
                sweep,
                text,
            } => {
                let c = self.p(*vertex);
                if !finite(&c) {
                    return None;
                }
                let pieces = self.page_arc(c, ANGLE_RADIUS, *start, *sweep);
                self.bezier_obstacles(&pieces);
                if let Some(text) = text {
                    let mid = *start + 0.5 * sweep;
                    let dir = unit(self.t.apply_vector(Vector::new(mid.cos(), mid.sin())))?;
                    self.pending.push(Pending {
                        id: format!("label-{}", id.trim_start_matches("angle-")),
                        anchor: c + dir * ANGLE_RADIUS,
                        text: text.clone(),
                        size: self.style.font_size(TextSize::Small) + 2.0,
                        gap: 2.0,
                    });
                }
                Box::new(
                    path(bezier_d(&pieces), pen)
                        .set("id", id)
                        .set("class", class),
                )
            }
            Shape::Dimension {
                from,
                to,
                side,
                offset,
                text,
            } => {
                let (a, b) = (self.p(*from), self.p(*to));
                let n = unit(self.t.apply_vector(*side))?;
                let u = unit(b - a)?;
                let (a2, b2) = (a + n * *offset, b + n * *offset);
                let ext = |p: Point, q: Point| polyline_d(&[p + n * 3.0, q + n * 4.0], false);
                let size = self.style.font_size(TextSize::Small) + 1.0;
                let half = text_half(text, size, self.font);
                let centre = nalgebra::center(&a2, &b2) + n * (half.y + 3.0);
                self.obstacles.boxed(Bounds::around(centre, half));
                self.obstacles.segment(a2, b2);
                Box::new(
                    Group::new()
                        .set("id", id)
                        .set("class", class)
                        .add(path(ext(a, a2), Pen { width: 0.5, ..pen }))
                        .add(path(ext(b, b2), Pen { width: 0.5, ..pen }))
                        .add(path(polyline_d(&[a2 + u * 2.0, b2 - u * 2.0], false), pen))
                        .add(arrow_head(a2, -u, pen.colour))
                        .add(arrow_head(b2, u, pen.colour))
                        .add(text_node(
                            &format!("{id}-text"),
                            centre,
                            text,
                            size,
                            pen.colour,
                            "middle",
                            starts_italic(text),
                        )),
                )
            }
            Shape::Label { anchor, text, size } => {
                let a = self.p(*anchor);
                if !finite(&a) {
                    return None;
                }
                self.pending.push(Pending {
                    id: id.to_string(),
                    anchor: a,
                    text: text.clone(),
                    size: self.style.font_size(*size),
                    gap: if *size == TextSize::Letter { 4.0 } else { 3.0 },
                });
                return None;
            }
            Shape::Text {
                at,
                offset,
                text,
                align,
                size,
            } => {
                let c = self.p(*at) + offset;
                if !finite(&c) {
                    return None;
                }
                let size = self.style.font_size(*size);
                let half = text_half(text, size, self.font);
                let (anchor, middle) = match align {
                    Align::Start => ("start", c + Vector::new(half.x, 0.0)),
                    Align::Middle => ("middle", c),
                    Align::End => ("end", c - Vector::new(half.x, 0.0)),
                };
                self.obstacles.boxed(Bounds::around(middle, half));
                Box::new(text_node(
                    id,
                    c,
                    text,
                    size,
                    self.style.pen(Role::Label).colour,
                    anchor,
                    starts_italic(text),
                ))
            }
            Shape::Marker { centre, symbol } => {
                let c = self.p(*centre);
                if !finite(&c) {
                    return None;
                }
                let r = MARKER_RADIUS;
                self.obstacles.boxed(Bounds::around(c, Vector::new(r, r)));
                let pen = Pen {
                    width: 1.1,
                    dash: None,
                    ..pen
                };
                let v = |x: f64, y: f64| c + Vector::new(x, y);
                let d = match symbol {
                    Symbol::Disc | Symbol::Circle => {
                        let fill = if *symbol == Symbol::Disc {
                            pen.colour
                        } else {
                            self.style.paper()
                        };
                        return Some(Box::new(
                            stroke(Circle::new(), pen)
                                .set("cx", fmt(c.x))
                                .set("cy", fmt(c.y))
                                .set("r", fmt(r))
                                .set("fill", fill)
                                .set("id", id)
                                .set("class", class),
                        ));
                    }
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
                };
                let fill = if *symbol == Symbol::Cross {
                    "none"
                } else {
                    self.style.paper()
                };
                Box::new(
                    path(d, pen)
                        .set("fill", fill)
                        .set("id", id)
                        .set("class", class),
                )
            }
            Shape::Note { corner, lines } => {
                let mut g = Group::new().set("id", id).set("class", class);
                let colour = self.style.pen(Role::Label).colour;
                // One size for all lines, small enough for the longest to
                // fit between the corner and the page's right edge.
                let room = (self.page_width - corner.x - 8.0).max(10.0);
                let widest = lines
                    .iter()
                    .map(|l| l.width(self.font, NOTE_SIZE))
                    .fold(0.0, f64::max);
                let size = if widest > room {
                    NOTE_SIZE * room / widest
                } else {
                    NOTE_SIZE
                };
                for (i, line) in lines.iter().enumerate() {
                    let y = corner.y + size * 0.8 + NOTE_LINE * i as f64;
                    let half = text_half(line, size, self.font);
                    self.obstacles.boxed(Bounds::around(
                        Point::new(corner.x + half.x, y - BASELINE * size),
                        half,
                    ));
                    g = g.add(text_node(
                        &format!("{id}-{}", i + 1),
                        Point::new(corner.x, y - BASELINE * size),
                        line,
                        size,
                        colour,
                        "start",
                        false,
                    ));
                }
                Box::new(g)
            }
        };
        Some(node)
    }

    fn bezier_obstacles(&mut self, pieces: &[[Point; 4]]) {
        for b in pieces {
            let pts: Vec<Point> = (0..=6)
                .map(|k| {
                    let t = k as f64 / 6.0;
                    let s = 1.0 - t;
                    Point::from(
                        b[0].coords * (s * s * s)
                            + b[1].coords * (3.0 * s * s * t)
                            + b[2].coords * (3.0 * s * t * t)
                            + b[3].coords * (t * t * t),
                    )
                })
                .collect();
            self.obstacles.polyline(&pts);
        }
    }

    fn path(&mut self, p: &Path, pen: Pen) -> Option<SvgPath> {
        let mut d = String::new();
        let mut last = Point::origin();
        let mut pieces = Vec::new();
        for seg in p.segments() {
            match *seg {
                PathSegment::MoveTo(q) => {
                    let q = self.p(q);
                    let _ = write!(d, "{}M{}", if d.is_empty() { "" } else { " " }, pt(q));
                    last = q;
                }
                PathSegment::LineTo(q) => {
                    let q = self.p(q);
                    let _ = write!(d, " L{}", pt(q));
                    self.obstacles.segment(last, q);
                    last = q;
                }
                PathSegment::CubicTo(c1, c2, q) => {
                    let (c1, c2, q) = (self.p(c1), self.p(c2), self.p(q));
                    let _ = write!(d, " C{} {} {}", pt(c1), pt(c2), pt(q));
                    pieces.push([last, c1, c2, q]);
                    last = q;
                }
                PathSegment::Close => d.push_str(" Z"),
            }
        }
        if !p.points().all(|q| finite(&self.p(q))) {
            return None;
        }
        self.bezier_obstacles(&pieces);
        Some(path(d, pen))
    }
}

fn draw_order(role: Role, shape: &Shape) -> (usize, usize) {
    let r = Role::ALL.iter().position(|x| *x == role).unwrap_or(0);
    let s = match shape {
        Shape::Region { .. } => 0,
        Shape::Pin { .. } => 2,
        _ => 1,
    };
    (r, s)
}

fn panel_group(
    panel: &Panel,
    style: crate::render::Style,
    font: Font,
    page: &crate::figure::PageRect,
) -> Group {
    let t = panel.transform();
    let coefficients = t.coefficients().map(fmt_coefficient).join(" ");
    let mut g = Group::new()
        .set("id", panel.id())
        .set("data-page-from-world", coefficients);
    let mut w = PanelWriter {
        t,
        page_width: page.x + page.width,
        style,
        font,
        obstacles: Obstacles::default(),
        pending: Vec::new(),
    };
    let mut order: Vec<(usize, &Item)> = panel.items().iter().enumerate().collect();
    order.sort_by_key(|(i, item)| (draw_order(item.role, &item.shape), *i));
    let mut nodes = Vec::new();
    for (_, item) in &order {
        if let Some(n) = w.item(item) {
            nodes.push(n);
        }
    }
    if panel.is_clipped() {
        let r = panel.rect();
        let clip = format!("clip-{}", panel.id());
        g = g
            .add(
                Definitions::new().add(
                    ClipPath::new().set("id", clip.clone()).add(
                        Rectangle::new()
                            .set("x", fmt(r.x))
                            .set("y", fmt(r.y))
                            .set("width", fmt(r.width))
                            .set("height", fmt(r.height)),
                    ),
                ),
            )
            .set("clip-path", format!("url(#{clip})"));
    }
    for n in nodes {
        g = g.add(n);
    }
    let colour = style.pen(Role::Label).colour;
    let pending = std::mem::take(&mut w.pending);
    for p in pending {
        let half = text_half(&p.text, p.size, font);
        let centre = place(p.anchor, half, p.gap, &w.obstacles, page);
        w.obstacles.boxed(Bounds::around(centre, half));
        g = g.add(text_node(
            &p.id,
            centre,
            &p.text,
            p.size,
            colour,
            "middle",
            starts_italic(&p.text),
        ));
    }
    g
}

/// The figure as SVG text: `<metadata>` JSON (DESIGN.md §4), a paper
/// rectangle, one `<g data-page-from-world>` per panel.
pub fn to_svg(figure: &Figure) -> String {
    let style = figure.style();
    let (w, h) = (figure.width(), figure.height());
    // Labels stay a little inside the page.
    let page = crate::figure::PageRect::new(2.0, 2.0, w - 4.0, h - 4.0);
    let mut meta = figure.metadata().clone();
    meta.insert("figure".into(), json!(figure.name()));
    meta.insert("style".into(), json!(style.name()));
    meta.insert("tolerance".into(), json!(figure.tolerance()));
    meta.insert("width".into(), json!(w));
    meta.insert("height".into(), json!(h));
    let coefficients = |t: &PageFromWorld| -> Vec<Value> {
        t.coefficients()
            .iter()
            .map(|c| json!(fmt_coefficient(*c).parse::<f64>().unwrap_or(0.0)))
            .collect()
    };
    if let Some(first) = figure.panels().first() {
        meta.insert(
            "page_from_world".into(),
            Value::Array(coefficients(first.transform())),
        );
    }
    meta.insert(
        "panels".into(),
        Value::Array(
            figure
                .panels()
                .iter()
                .map(|p| {
                    let r = p.rect();
                    json!({
                        "id": p.id(),
                        "page_from_world": coefficients(p.transform()),
                        "rect": [r.x, r.y, r.width, r.height],
                    })
                })
                .collect(),
        ),
    );
    let json = serde_json::to_string(&Value::Object(meta)).unwrap_or_else(|_| "{}".into());
    let mut metadata = Element::new("metadata");
    metadata.append(svg::node::Text::new(json));
    let mut doc = Document::new()
        .set("width", fmt(w))
        .set("height", fmt(h))
        .set("viewBox", format!("0 0 {} {}", fmt(w), fmt(h)))
        .set("font-family", figure.font().css_family())
        .add(metadata)
        .add(
            Rectangle::new()
                .set("id", "paper")
                .set("x", 0)
                .set("y", 0)
                .set("width", fmt(w))
                .set("height", fmt(h))
                .set("fill", style.paper()),
        );
    for panel in figure.panels() {
        // Labels stay in their panel, or just outside it (into the
        // margin) for points near its edge, and always on the page.
        let r = panel.rect();
        // A clipped panel keeps its labels inside.
        let out = if panel.is_clipped() { -3.0 } else { 8.0 };
        let x0 = (r.x - out).max(page.x);
        let y0 = (r.y - out).max(page.y);
        let x1 = (r.x + r.width + out).min(page.x + page.width);
        let y1 = (r.y + r.height + out).min(page.y + page.height);
        let room = crate::figure::PageRect::new(x0, y0, x1 - x0, y1 - y0);
        doc = doc.add(panel_group(panel, style, figure.font(), &room));
    }
    let mut s = doc.to_string();
    s.push('\n');
    s
}
