//! Lines: fitted paths, polylines, tinted regions, circles and arcs (an
//! arrowed arc is a torque). Every line they draw is kept clear by labels.

use super::mark::{Mark, Paint, PathCommand, PathData, Shape};
use super::markup::{
    arc_beziers, arrow_head, bezier_d, finite, path, polyline_d, stroked_circle, unit,
};
use super::{Ink, PanelLayout, centre};
use crate::figure::{Part, Path, PathSegment, Pen, Role};
use crate::geom::Frame;
use crate::geom::{Point, inside_outline};

/// The rim of paper each side of a link lying over a body, page units
/// ([`PanelLayout::polyline`]).
const CASING: f64 = 2.0;

/// The step a link is sampled at for lying over a body, page units.
const BODY_SAMPLE: f64 = 4.0;

impl PanelLayout<'_> {
    /// A fitted path of lines and cubic Béziers.
    pub(super) fn fitted_path(&mut self, ink: &Ink, p: &Path) -> Option<Mark> {
        let mut d = PathData::new();
        let mut last = Point::origin();
        let mut pieces = Vec::new();
        let mut straight = Vec::new();
        for seg in p.segments() {
            match *seg {
                PathSegment::MoveTo(q) => {
                    let q = self.p(q);
                    d.push(PathCommand::Move(q));
                    last = q;
                }
                PathSegment::LineTo(q) => {
                    let q = self.p(q);
                    d.push(PathCommand::Line(q));
                    self.obstacles.segment(last, q);
                    straight.push((last, q));
                    last = q;
                }
                PathSegment::CubicTo(c1, c2, q) => {
                    let (c1, c2, q) = (self.p(c1), self.p(c2), self.p(q));
                    d.push(PathCommand::Cubic(c1, c2, q));
                    pieces.push([last, c1, c2, q]);
                    last = q;
                }
                PathSegment::Close => d.push(PathCommand::Close),
            }
        }
        if !p.points().all(|q| finite(&self.p(q))) {
            return None;
        }
        let chords = self.bezier_obstacles(&pieces);
        if ink.role == Role::Curve {
            // A point's path through hatching breaks it, as a line does.
            self.crossing.extend(chords);
            self.crossing.extend(straight);
        }
        Some(ink.tag(path(d, ink.pen)))
    }

    /// A polyline, open or closed, of the item that is `part`. The line of
    /// stroke ([`Part::CentreLine`]) is drawn as a centre line, long dash
    /// and dot.
    pub(super) fn polyline(
        &mut self,
        ink: &Ink,
        points: &[Point],
        closed: bool,
        part: Part,
    ) -> Option<Mark> {
        let pts: Vec<Point> = points.iter().map(|p| self.p(*p)).collect();
        if pts.len() < 2 || !pts.iter().all(finite) {
            return None;
        }
        self.obstacles.polyline(&pts);
        if matches!(
            ink.role,
            Role::Construction | Role::Result | Role::Auxiliary
        ) {
            self.crossing
                .extend(pts.iter().zip(pts.iter().skip(1)).map(|(p, q)| (*p, *q)));
        }
        if ink.role == Role::Link && !closed {
            self.links
                .extend(pts.iter().zip(pts.iter().skip(1)).map(|(p, q)| (*p, *q)));
        }
        if closed && let (Some(&last), Some(&first)) = (pts.last(), pts.first()) {
            self.obstacles.segment(last, first);
        }
        if let [from, to] = *pts.as_slice()
            && !closed
            && centre::is_centre_line(part)
        {
            // Written once the labels are placed (with gaps for them).
            return Some(self.open_line(ink, centre::Course::Centre { from, to }));
        }
        if let [a, b, c, d] = *pts.as_slice()
            && closed
            && part == Part::DetailMark
        {
            // A detail's frame or border, likewise.
            let corners = [a, b, c, d];
            if let Some(marked) = Frame::enclosing(&corners) {
                self.detail_marks.push(marked);
            }
            return Some(self.open_line(ink, centre::Course::Frame { corners }));
        }
        let line = ink.tag(path(polyline_d(&pts, closed), ink.pen));
        if ink.role == Role::Link && !closed && self.over_a_body(&pts) {
            // A link lying over a body drawn in the paper's colour a
            // little wider first: a rim of paper between its line and the
            // tone, as a part passing over another (inversion 3 at
            // l = 2.75 r, e = −1.14 r, 270.32°: a in d's leg and b in its
            // slot read as one L-shaped body).
            let casing = Pen {
                colour: self.style.paper(),
                width: ink.pen.width + 2.0 * CASING,
                dash: None,
            };
            let under = path(polyline_d(&pts, false), casing);
            return Some(Mark::group().with(under).with(line));
        }
        Some(line)
    }

    /// Whether the polyline `pts` (page points) runs over a body drawn
    /// before it ([`PanelLayout::body`]): a point of it, sampled a few
    /// units apart, inside a body's outline.
    fn over_a_body(&self, pts: &[Point]) -> bool {
        let samples = pts.iter().zip(pts.iter().skip(1)).flat_map(|(p, q)| {
            let n = ((q - p).norm() / BODY_SAMPLE).ceil().clamp(1.0, 1000.0) as usize;
            (0..=n).map(move |k| p + (q - p) * (k as f64 / n as f64))
        });
        let bodies = &self.bodies;
        samples
            .into_iter()
            .any(|x| bodies.iter().any(|b| inside_outline(b, x)))
    }

    /// A tinted area without outline, where the style tints (the similar
    /// triangles of the handout); not an obstacle.
    pub(super) fn region(&mut self, ink: &Ink, points: &[Point]) -> Option<Mark> {
        let (colour, opacity) = self.style.region()?;
        let pts: Vec<Point> = points.iter().map(|p| self.p(*p)).collect();
        if pts.len() < 3 || !pts.iter().all(finite) {
            return None;
        }
        let paint = Paint {
            fill_opacity: Some(opacity),
            ..Paint::filled(colour)
        };
        Some(ink.tag(Mark::new(Shape::Path(polyline_d(&pts, true), paint))))
    }

    /// A full circle: a `<circle>` where the panel's map is a similarity,
    /// else its Bézier image.
    pub(super) fn circle(&mut self, ink: &Ink, centre: Point, radius: f64) -> Option<Mark> {
        let c = self.p(centre);
        let pieces: Vec<[Point; 4]> = arc_beziers(centre, radius, 0.0, 2.0 * std::f64::consts::PI)
            .into_iter()
            .map(|b| b.map(|p| self.p(p)))
            .collect();
        self.bezier_obstacles(&pieces);
        if !finite(&c) {
            return None;
        }
        let [a, b, cc, d, _, _] = self.t.coefficients();
        if (a * a + b * b - cc * cc - d * d).abs() <= 1e-9 * (a * a + b * b) {
            Some(ink.tag(stroked_circle(c, radius * self.t.scale(), ink.pen)))
        } else {
            Some(ink.tag(path(bezier_d(&pieces), ink.pen)))
        }
    }

    /// A circular arc (world angles), with an arrowhead at its end for a
    /// torque.
    pub(super) fn arc(
        &mut self,
        ink: &Ink,
        centre: Point,
        radius: f64,
        (start, sweep): (f64, f64),
        arrow: bool,
    ) -> Option<Mark> {
        let pieces: Vec<[Point; 4]> = arc_beziers(centre, radius, start, sweep)
            .into_iter()
            .map(|b| b.map(|p| self.p(p)))
            .collect();
        if !pieces.iter().flatten().all(finite) {
            return None;
        }
        self.bezier_obstacles(&pieces);
        let line = path(bezier_d(&pieces), ink.pen);
        if !arrow {
            return Some(ink.tag(line));
        }
        let last = pieces.last()?;
        let u = unit(last[3] - last[2])?;
        Some(
            ink.tag(Mark::group())
                .with(line)
                .with(arrow_head(last[3], u, ink.pen.colour)),
        )
    }

    /// A line that opens for letters, written whole now and again with
    /// its gaps once the labels are placed.
    pub(super) fn open_line(&mut self, ink: &Ink, course: centre::Course) -> Mark {
        let line = centre::OpenLine {
            node: usize::MAX,
            id: ink.id.to_string(),
            role: ink.role,
            pen: ink.pen,
            course,
        };
        let node = line.written(&[]).unwrap_or_else(Mark::group);
        self.open_lines.push(line);
        node
    }

    /// Page Bézier pieces as obstacles, each by enough points along it
    /// that the chords keep within [`FLAT`] of the curve (at least six:
    /// a large arc, in a magnified detail, bows far from a chord of a
    /// sixth of it); returns the chords.
    pub(super) fn bezier_obstacles(&mut self, pieces: &[[Point; 4]]) -> Vec<(Point, Point)> {
        let mut written = Vec::new();
        for b in pieces {
            let n = chords(b);
            let pts: Vec<Point> = (0..=n)
                .map(|k| {
                    let t = k as f64 / n as f64;
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
            written.extend(pts.iter().zip(pts.iter().skip(1)).map(|(p, q)| (*p, *q)));
        }
        written
    }
}

/// How far, page units, an obstacle's chords may stray from its curve.
const FLAT: f64 = 0.25;

/// The number of chords that follow the cubic `b` within [`FLAT`]: its
/// control points' distance `d` from the chord bounds the curve's bow,
/// and `n` equal steps in t leave at most about 3d / (4 n²).
fn chords(b: &[Point; 4]) -> usize {
    let chord = b[3] - b[0];
    let len = chord.norm();
    let off = |p: Point| {
        let v = p - b[0];
        if len > 0.0 {
            (v.x * chord.y - v.y * chord.x).abs() / len
        } else {
            v.norm()
        }
    };
    let d = off(b[1]).max(off(b[2]));
    let n = (0.75 * d / FLAT).sqrt().ceil();
    if n.is_finite() {
        n.clamp(6.0, 256.0) as usize
    } else {
        6
    }
}
