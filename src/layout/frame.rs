//! The fixed link: the crank's bearing, the ground hatching of the guides
//! and the slider block that runs in them.

use super::hatching::Hatching;
use super::mark::Mark;
use super::mark::{PathCommand, PathData};
use super::markup::{finite, path, polyline_d, unit};
use super::symbol_sizes::{HATCH_DEPTH, HATCH_SPACING, LETTER_GAP, PIN_RADIUS};
use super::{Ink, PanelLayout};
use crate::figure::{BEARING_FOOT, Foot, Pen, TextSize};
use crate::geom::{Frame, Point, Vector};

impl PanelLayout<'_> {
    /// The crank's bearing: a pedestal (a triangle on the paper) on a
    /// hatched foot on the side `foot` of the shaft's centre, the foot
    /// hatched on its far side. Kept clear by labels: the triangle's
    /// edges and the foot with its hatching.
    pub(super) fn bearing(&mut self, ink: &Ink, centre: Point, foot: Foot) -> Option<Mark> {
        let c = self.p(centre);
        if !finite(&c) {
            return None;
        }
        // `d` towards the foot, `s` along it.
        let (d, s) = foot.axes();
        let at = |along: f64, out: f64| c + s * along + d * out;
        let ((h, base), w) = (BEARING_FOOT, 10.0);
        let tri = [c, at(-w, h), at(w, h)];
        let feet = [at(-base, h), at(base, h)];
        let mut hatch = PathData::new();
        let mut x = -base + 3.0;
        while x <= base {
            let p = at(x, h);
            hatch.push(PathCommand::Move(p));
            hatch.push(PathCommand::Line(p - s * 5.0 + d * 6.0));
            x += 5.0;
        }
        // The triangle and the foot are lines to keep clear of; the
        // hatching beyond the foot is a strip no letter enters.
        self.obstacles.polyline(&[tri[0], tri[1], tri[2], tri[0]]);
        self.obstacles.segment(feet[0], feet[1]);
        let corners = [
            at(-base - 5.0, h),
            at(base, h),
            at(-base - 5.0, h + 6.0),
            at(base, h + 6.0),
        ];
        let (lo, hi) = corners[1..]
            .iter()
            .fold((corners[0], corners[0]), |(lo, hi), p| {
                (lo.inf(p), hi.sup(p))
            });
        self.obstacles.boxed(Frame::from_corners(lo, hi));
        // The triangle, the foot and the hatched strip's far edge: what a
        // block's letter keeps farther from than from its block.
        (self.grounds).extend([(tri[0], tri[1]), (tri[1], tri[2]), (tri[2], tri[0])]);
        (self.grounds).extend([(feet[0], feet[1]), (corners[2], corners[3])]);
        let pen = ink.pen;
        Some(
            ink.tag(Mark::group())
                .with(path(polyline_d(&tri, true), pen).fill(self.style.paper()))
                .with(path(polyline_d(&feet, false), pen))
                .with(path(hatch, Pen { width: 0.7, ..pen })),
        )
    }

    /// Ground hatching: short slanted strokes along `from`–`to` on the
    /// side `side` (a world vector) points to. Labels keep off the strip.
    pub(super) fn hatch(
        &mut self,
        ink: &Ink,
        from: Point,
        to: Point,
        side: Vector,
    ) -> Option<Mark> {
        let (a, b) = (self.p(from), self.p(to));
        let t = unit(b - a)?;
        let n = unit(self.t.apply_vector(side))?;
        let len = (b - a).norm();
        let mut strokes = Vec::new();
        let mut s = 0.5 * HATCH_SPACING;
        while s < len {
            let p = a + t * s;
            strokes.push((p, p + n * HATCH_DEPTH - t * (0.8 * HATCH_DEPTH)));
            s += HATCH_SPACING;
        }
        if strokes.is_empty() {
            return None;
        }
        for depth in [0.3, 0.8] {
            self.obstacles
                .segment(a + n * (depth * HATCH_DEPTH), b + n * (depth * HATCH_DEPTH));
        }
        // The strokes' tips, slanted back along the edge: a letter within
        // its room of them opens the hatching once written
        // ([`Hatching::written`]), so the placer keeps clear of them too.
        let tips = n * HATCH_DEPTH - t * (0.8 * HATCH_DEPTH);
        if let (Some(first), Some(last)) = (strokes.first(), strokes.last()) {
            self.obstacles.segment(first.0 + tips, last.0 + tips);
        }
        // Written again once the labels are placed, open where one sits.
        let hatching = Hatching {
            node: usize::MAX,
            id: ink.id.to_string(),
            role: ink.role,
            pen: Pen {
                width: 0.6,
                ..ink.pen
            },
            strokes,
        };
        let node = hatching.written(&[], &[]);
        self.hatchings.push(hatching);
        node
    }

    /// The slider block: its outline, heavier than the guides, unfilled so
    /// that curves and constructions through the slider (Kisch's
    /// semicircle ends at A) stay visible. No letter goes inside it, save
    /// its pin's where it is enlarged so much that the letter fits inside
    /// beside the pin: on both sides of it, or in a detail on one side,
    /// above or below it or to a side (a block 48 units wide and 90 tall
    /// in a ×2.5 detail: the letter could not reach past its side and had
    /// only the outline to sit on). A block on the main view that holds
    /// no letter each way keeps every letter out (the oscillating
    /// cylinder's, whose link's name belongs outside).
    pub(super) fn block(&mut self, ink: &Ink, points: &[Point]) -> Option<Mark> {
        let pts: Vec<Point> = points.iter().map(|p| self.p(*p)).collect();
        if pts.len() < 3 || !pts.iter().all(finite) {
            return None;
        }
        let closed: Vec<Point> = pts.iter().chain(pts.first()).copied().collect();
        let sides: Vec<(Point, Point)> = (closed.iter().copied())
            .zip(closed.iter().copied().skip(1))
            .collect();
        if is_bar(&pts) {
            // A slotted bar: its sides are lines to keep clear of and
            // links a link's letter must not stand nearer than its own.
            self.obstacles.polyline(&closed);
            self.links.extend(&sides);
        } else {
            self.block_room(&pts);
        }
        self.blocks.push(sides);
        Some(
            ink.tag(path(
                polyline_d(&pts, true),
                Pen {
                    width: 1.6,
                    ..ink.pen
                },
            ))
            .fill("none"),
        )
    }

    /// A link's body ([`crate::figure::Shape::Body`]): its outline as a
    /// slotted bar's ([`PanelLayout::block`]), filled in the style's body
    /// tone ([`crate::figure::Style::body`]), so that a crank or a rod lying over it, a heavier
    /// black line on the tone, reads as another link, not as d's slot; what
    /// runs under it (the path, Kennedy's lines, the centres' dots) stays
    /// seen through the tone.
    /// Its inside is kept from letters as lines are ([`body_fill`]): a
    /// link's letter inside d's outline named d (coriolis 2 at
    /// l = 40.8 r, 90.38°: "b" inside d by its edge).
    pub(super) fn body(&mut self, ink: &Ink, points: &[Point]) -> Option<Mark> {
        let (tone, opacity) = self.style.body();
        let toned = (self.block(ink, points)?).fill(tone).fill_opacity(opacity);
        let pts: Vec<Point> = points.iter().map(|p| self.p(*p)).collect();
        self.bodies.push(pts.clone());
        // Not in a detail: there d's bar, enlarged, takes much of the
        // frame with its pins inside it, and their letters' search for a
        // place out of it made the layout ten times slower (inversion 2 at
        // l = 60 r, 90°). Only where letters can go: a bar drawn far past
        // the page laid its lines across the grid's cells.
        if self.detail {
            return Some(toned);
        }
        let w = self.page_width;
        let page = Frame::new(
            Point::new(-w, -w),
            Point::new(PAGE_REACH * w, PAGE_REACH * w),
        );
        for (a, b) in body_fill(&pts) {
            if let Some((a, b)) = page.clip_segment(a, b) {
                self.obstacles.segment(a, b);
            }
        }
        Some(toned)
    }

    /// A block's room kept from letters: its box, hollow where a letter
    /// fits inside beside its pin.
    fn block_room(&mut self, pts: &[Point]) {
        let Some(&first) = pts.first() else {
            return;
        };
        let (lo, hi) = pts
            .iter()
            .fold((first, first), |(lo, hi), p| (lo.inf(p), hi.sup(p)));
        let b = Frame::from_corners(lo, hi);
        // Room beside the pin for its letter (about 0.8 of its size wide
        // and its size tall): the pin, the letter's gap and the letter,
        // each way (`roomy`), or across or up and down with the letter's
        // own room the other way (`beside`, `over`).
        let letter = self.style.font_size(TextSize::Letter);
        let roomy = PIN_RADIUS + LETTER_GAP + letter;
        let (wide, tall) = (0.8 * letter, letter);
        let size = hi - lo;
        let beside = size.x >= 2.0 * (PIN_RADIUS + LETTER_GAP + wide) && size.y >= tall;
        let over = size.y >= 2.0 * (PIN_RADIUS + LETTER_GAP + tall) && size.x >= wide;
        if size.min() >= 2.0 * roomy || (self.detail && (beside || over)) {
            self.obstacles.hollow(b);
        } else {
            self.obstacles.boxed(b);
        }
    }
}

/// Whether a body's outline `pts` (page units) is a bar rather than a
/// block: bent (more than four corners), or with a side longer than
/// [`BAR_LENGTHS`] times its shortest (a slider block is about twice as
/// long as it is tall; a slotted bar runs the stroke's length). A bar's
/// box would cover the page beside a slanting bar.
fn is_bar(pts: &[Point]) -> bool {
    let sides = pts
        .iter()
        .zip(pts.iter().cycle().skip(1))
        .map(|(p, q)| (q - p).norm());
    let (least, most) = sides.fold((f64::INFINITY, 0.0_f64), |(lo, hi), d| {
        (lo.min(d), hi.max(d))
    });
    pts.len() > 4 || most > BAR_LENGTHS * least
}

/// How many times its shortest side a four-cornered body's longest side
/// may be and the body still be a block ([`is_bar`]).
const BAR_LENGTHS: f64 = 4.0;

/// Lines across the inside of the outline `pts` (page units), one every
/// [`BODY_FILL_STEP`], along its longest side: each run between the
/// outline's crossings of a line, the outside left out (even–odd). Along
/// the bar, not down the page: a long bar drawn far past a detail's frame
/// takes a few lines, not one every 4 units of its length (at
/// l = 60 r, 90° that made inversion 2 ten times slower to lay out).
/// At most [`BODY_FILL_MOST`] lines.
fn body_fill(pts: &[Point]) -> Vec<(Point, Point)> {
    let sides: Vec<(Point, Point)> = (pts.iter().copied())
        .zip(pts.iter().copied().cycle().skip(1))
        .collect();
    let Some(u) = (sides.iter())
        .max_by(|a, b| (a.1 - a.0).norm().total_cmp(&(b.1 - b.0).norm()))
        .and_then(|(p, q)| unit(q - p))
    else {
        return Vec::new();
    };
    let n = Vector::new(-u.y, u.x);
    let across = |p: &Point| p.coords.dot(&n);
    let (lo, hi) = (pts.iter()).fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
        (lo.min(across(p)), hi.max(across(p)))
    });
    let levels = (((hi - lo) / BODY_FILL_STEP) as usize).min(BODY_FILL_MOST);
    let mut runs = Vec::new();
    for k in 0..levels {
        let t = lo + (k as f64 + 0.5) * BODY_FILL_STEP;
        let mut xs: Vec<Point> = (sides.iter())
            .filter(|(p, q)| (across(p) <= t) != (across(q) <= t))
            .map(|(p, q)| p + (q - p) * ((t - across(p)) / (across(q) - across(p))))
            .collect();
        xs.sort_by(|a, b| a.coords.dot(&u).total_cmp(&b.coords.dot(&u)));
        runs.extend((xs.chunks_exact(2)).filter_map(|x| match x {
            [p, q] => Some((*p, *q)),
            _ => None,
        }));
    }
    runs
}

/// How far down and across the page (in page widths) a body's inside is
/// kept from letters ([`PanelLayout::body`]): past every page's height.
const PAGE_REACH: f64 = 4.0;

/// The most lines [`body_fill`] draws across a body.
const BODY_FILL_MOST: usize = 64;

/// The step between [`body_fill`]'s lines, page units: less than a
/// letter's height, so that none stands between two.
const BODY_FILL_STEP: f64 = 6.0;
