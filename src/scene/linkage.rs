//! Drawing a linkage on a [`Canvas`]: links, pins, bearings, ground
//! hatching kept clear of the moving links, and slots with their guides;
//! the catalogue's chain and inversion sketches draw with it, and its
//! page sizes are the mechanism layer's too.

use super::canvas::Canvas;
use crate::figure::{Foot, RichText, Role, Shape, TextSize};
use crate::figure::{HATCH_DEPTH, HATCH_SPACING};
use crate::geom::{Frame, Point, Vector, crossing, perp, segment_distance, unit};

/// Clear distance, page units, kept between a guide (with its hatching)
/// and a link passing in front of it: the link's half width, the
/// guide's, and a little paper.
pub(crate) const LINK_CLEARANCE: f64 = 5.0;
/// Shortest piece of guide drawn, page units.
pub(crate) const GUIDE_MIN: f64 = 12.0;
/// How far the hatching leans back along a guide, page units.
pub(crate) const HATCH_SLANT: f64 = 6.0;
/// Half width and depth of a bearing below its centre, page units (the
/// pedestal and its hatched foot, see the SVG writer's bearing).
pub(crate) const BEARING_REACH: f64 = 25.0;
/// Room left unhatched at a fixed link's pins, page units.
pub(crate) const PIN_CLEAR: f64 = 8.0;
/// How far past the canvas's edges (page units, beyond a link end's
/// room) a fixed link is hatched ([`Canvas::hatch_edge_of_at_least`]).
const HATCH_MARGIN: f64 = 20.0;
/// Clear distance kept between a hatch stroke and a moving link, page units.
const HATCH_CLEAR: f64 = 2.5;
/// Shortest run of hatch strokes drawn.
const HATCH_RUN: usize = 2;
/// A moving link within this angle (radians, 5°) of a hatched edge…
const ALONG_EDGE: f64 = 0.087;
/// …and within this of its line (page units) behind it, away from the
/// strokes, beside a stroke…
const LYING: f64 = 3.0;
/// …and no farther than this in front (the quarter pixel a stroke's foot
/// may touch a link) lies along it.
const LYING_IN_FRONT: f64 = 0.25;
/// Length of one chord of a curved guide, page units.
const CHORD: f64 = 12.0;
/// Clear distance between a guide and the crank circle or a bearing.
const CIRCLE_CLEARANCE: f64 = 7.0;
/// How far beyond the block's ends the rod may come close to its guides,
/// page units.
const BLOCK_MARGIN: f64 = 4.0;

/// Runs of hatch strokes: (chord, first stroke, last stroke) in page
/// units along the chord.
type Runs = Vec<(usize, f64, f64)>;

/// A piece of a moving link, in world coordinates.
pub(crate) type Seg = (Point, Point);

/// A slot the block slides in: the path of its middle, `point(σ, δ)` at
/// arc length σ and normal offset δ, and the arc-length range its guides
/// cover.
pub(crate) struct Slot<'a> {
    /// The point at arc length σ along the slot, offset δ across it
    /// (δ > 0 on the side of +y at the slot's middle).
    pub point: &'a dyn Fn(f64, f64) -> Point,
    /// Whether the slot is straight (one chord per guide).
    pub straight: bool,
    /// The arc lengths the guides run between (towards the crank first).
    pub range: (f64, f64),
    /// Half the block's height: the guides are this far from the middle.
    pub half_height: f64,
    /// The block's arc length and half length: the guides always run under
    /// it, and alongside it (within [`BLOCK_MARGIN`]) the rod, which starts
    /// at its middle, may come close to them.
    pub block: (f64, f64),
}

/// One guide of a slot being drawn: its offset from the slot's middle,
/// the steps it is walked in from its far end (whose ends are `far` and
/// `near` on the page), and the rod it keeps clear of (in the world and
/// on the page).
struct Walk<'s, 'a> {
    slot: &'s Slot<'a>,
    delta: f64,
    steps: usize,
    far: Point,
    near: Point,
    rod: Seg,
    rod_page: Seg,
}

impl Walk<'_, '_> {
    /// The arc length of step `k` (0 at the far end).
    fn at(&self, k: usize) -> f64 {
        let (s0, s1) = self.slot.range;
        s1 + (s0 - s1) * k as f64 / self.steps as f64
    }

    /// The point of the guide at step `k`.
    fn point(&self, k: usize) -> Point {
        (self.slot.point)(self.at(k), self.delta)
    }
}

impl Canvas {
    fn page_point(&self, p: Point) -> Point {
        self.transform().apply(p)
    }

    /// A moving link through `points` (`link-{name}`).
    pub(crate) fn link(&mut self, name: &str, points: Vec<Point>) {
        self.push(
            format!("link-{name}"),
            Role::Link,
            Shape::Polyline {
                points,
                closed: false,
            },
        );
    }

    /// A pin joint without a letter (`pin-{name}`), if on the frame.
    pub(crate) fn pin(&mut self, name: &str, p: Point) {
        if self.contains(p) {
            self.push(format!("pin-{name}"), Role::Link, Shape::Pin { centre: p });
        }
    }

    /// A fixed bearing under `p` (`bearing-{name}`), if on the frame.
    pub(crate) fn bearing(&mut self, name: &str, p: Point) {
        self.bearing_on(name, p, Foot::Below);
    }

    /// A fixed bearing at `p` standing on `foot` (`bearing-{name}`), if on
    /// the frame.
    pub(crate) fn bearing_on(&mut self, name: &str, p: Point, foot: Foot) {
        if self.contains(p) {
            self.push(
                format!("bearing-{name}"),
                Role::Frame,
                Shape::Bearing { centre: p, foot },
            );
        }
    }

    /// A link's letter (`label-{name}`) naming the line `p q`: set beside
    /// it and nearer it than any other link (a long rod's fixed b beside
    /// the turning bar d a unit above it, whose letter over b's middle
    /// named d); nothing when the line's middle is off the frame.
    pub(crate) fn link_letter(&mut self, name: &str, (p, q): Seg, markup: &str) {
        self.line_label(
            format!("label-{name}"),
            (p, q),
            RichText::parse(markup),
            TextSize::Letter,
        );
    }

    /// [`Canvas::link_letter`], tried first on the side `toward` (a world
    /// direction) where given: a link lying along another at a dead
    /// centre, the two letters on its two sides ("b a" read as one word).
    pub(crate) fn link_letter_toward(
        &mut self,
        name: &str,
        (p, q): Seg,
        markup: &str,
        toward: Option<Vector>,
    ) {
        match toward {
            Some(u) => self.line_label_toward(
                format!("label-{name}"),
                (p, q),
                u,
                RichText::parse(markup),
                TextSize::Letter,
            ),
            None => self.link_letter(name, (p, q), markup),
        }
    }

    /// A letter or short markup near `anchor` (`label-{name}`), placed clear
    /// of lines by the renderer; nothing when `anchor` is off the frame.
    pub(crate) fn letter(&mut self, name: &str, anchor: Point, markup: &str, size: TextSize) {
        self.label(
            format!("label-{name}"),
            anchor,
            RichText::parse(markup),
            size,
        );
    }

    /// Ground hatching along the fixed edge `p q` on whichever of `sides`
    /// (world vectors) keeps more strokes clear of the moving links
    /// `avoid`, leaving out strokes that would touch them and those within
    /// `ends` page units of either end (`hatch-{name}-k`), drawn only
    /// where at least `least` strokes would be (every fixed link by one
    /// rule: shown otherwise where fewer show, its notes saying so, as a
    /// few strokes would say it is hatched). Returns the strokes that
    /// would be drawn, drawn or not: none where every stroke would touch
    /// a moving link (a fixed link lying inside a slotted bar) or the
    /// edge is off the canvas.
    pub(crate) fn hatch_edge_of_at_least(
        &mut self,
        name: &str,
        (p, q): Seg,
        sides: &[Vector],
        avoid: &[Seg],
        ends: f64,
        least: usize,
    ) -> usize {
        // Only the part on the canvas (and a margin past its edges, where
        // the room left at a cut end falls) is hatched: a long rod's fixed
        // link in an enlarged detail ran to millions of page units, its
        // strokes counted one by one (a rod of 1e8 cranks took minutes).
        let m = self.world(ends + HATCH_MARGIN);
        let f = *self.frame();
        let grown = Frame::new(f.min() - Vector::new(m, m), f.max() + Vector::new(m, m));
        let Some((p, q)) = grown.clip_segment(p, q) else {
            return 0;
        };
        let mut best: Option<(f64, Vector, Runs)> = None;
        for &side in sides {
            let runs = self.clear_runs(&[p, q], &|_| side, avoid, ends);
            let count = runs.iter().map(|x| x.2 - x.1 + 1.0).sum::<f64>();
            if best.as_ref().is_none_or(|b| count > b.0) {
                best = Some((count, side, runs));
            }
        }
        let Some((_, side, runs)) = best else {
            return 0;
        };
        // Each run's strokes stand a spacing apart from its first to its last.
        let strokes = (runs.iter())
            .map(|&(_, first, last)| ((last - first) / HATCH_SPACING).round() as usize + 1)
            .sum();
        if strokes >= least {
            self.emit_hatch(name, &[p, q], &|_| side, &runs);
        }
        strokes
    }

    /// Ground hatching along the fixed link `p q`, on the clearer side;
    /// the strokes drawn ([`Canvas::hatch_edge_of_at_least`]).
    pub(crate) fn hatch_link(
        &mut self,
        name: &str,
        p: Point,
        q: Point,
        avoid: &[Seg],
        ends: f64,
    ) -> usize {
        self.hatch_link_of_at_least(name, (p, q), avoid, ends, 1)
    }

    /// [`Canvas::hatch_link`], drawn only where at least `least` strokes
    /// would be ([`Canvas::hatch_edge_of_at_least`]); the strokes that
    /// would be drawn.
    pub(crate) fn hatch_link_of_at_least(
        &mut self,
        name: &str,
        (p, q): Seg,
        avoid: &[Seg],
        ends: f64,
        least: usize,
    ) -> usize {
        let n = perp(&(q - p));
        self.hatch_edge_of_at_least(name, (p, q), &[n, -n], avoid, ends, least)
    }

    /// The two guides of a fixed `slot`, hatched on their outer sides,
    /// open towards the crank where the rod `rod` (from the crank pin to
    /// the block) crosses them and clear of the bearing at `centre`, but
    /// never short of the block: they run across the crank circle (a path,
    /// not a part) and under the whole block (`guide-{name}-upper`,
    /// `hatch-{name}-upper-k`, …). Returns the arc length where the
    /// longer guide drawn opens (`None`: none drawn), beyond which the
    /// slot's middle line does not run.
    pub(crate) fn guides(
        &mut self,
        name: &str,
        slot: &Slot,
        centre: Point,
        rod: Seg,
    ) -> Option<f64> {
        let h = slot.half_height;
        let mut open: Option<f64> = None;
        for (id, delta) in [("upper", h), ("lower", -h)] {
            let (s0, s1) = slot.range;
            // From the far end back towards the crank, in steps of about
            // a page unit.
            let far = self.page_point((slot.point)(s1, delta));
            let near = self.page_point((slot.point)(s0, delta));
            let steps = ((far - near).norm() * if slot.straight { 1.0 } else { 1.6 })
                .ceil()
                .clamp(2.0, 20000.0) as usize;
            let rod_page = (self.page_point(rod.0), self.page_point(rod.1));
            let walk = Walk {
                slot,
                delta,
                steps,
                far,
                near,
                rod,
                rod_page,
            };
            let last = self.guide_end(&walk, centre);
            let span = self.page_point(walk.point(last)) - far;
            if last == 0 || span.norm() < GUIDE_MIN {
                continue;
            }
            self.guide(&format!("{name}-{id}"), &walk, last, span.norm());
            let at = walk.at(last);
            open = Some(open.map_or(at, |o: f64| o.min(at)));
        }
        open
    }

    /// The step a guide runs to from its far end: short of the bearing at
    /// `centre` and of where the rod crosses or comes near it, but never
    /// short of the block.
    fn guide_end(&self, w: &Walk, centre: Point) -> usize {
        // The crank circle is the path of the pin, not a part: the guide
        // runs across it, and stops only short of the bearing.
        let reach = self.world(BEARING_REACH) + self.world(CIRCLE_CLEARANCE);
        let block = w.slot.block;
        let (rb, ra) = w.rod_page;
        let mut last = 0;
        // The last step still under the block: the guide reaches it.
        let mut block_end = 0;
        let mut crossed: Option<(usize, f64)> = None;
        for k in 1..=w.steps {
            let (p0, p1) = (w.point(k - 1), w.point(k));
            // Under the block (and beyond it) the guide always runs:
            // the block never slides on nothing, and the rod leaves it
            // through its edge on the guide's line.
            // A step that starts under the block is drawn whatever
            // it meets: it reaches the block's near edge, or lies
            // under the block.
            let under = w.at(k - 1) >= block.0 - block.1;
            if under {
                block_end = k;
            }
            if !under && (p1 - centre).norm() < reach {
                break;
            }
            let (q0, q1) = (self.page_point(p0), self.page_point(p1));
            if let Some(sin) = crossing(q0, q1, rb, ra).filter(|_| !under) {
                crossed = Some((k, sin));
                break;
            }
            // Beyond the block towards the crank the rod keeps its
            // distance from the guide (it runs inside a curved slot
            // before leaving it); on the block's far side there is no
            // rod.
            let beside = w.at(k) >= block.0 - block.1 - self.world(BLOCK_MARGIN);
            if !beside && segment_distance(q1, q1, rb, ra) < LINK_CLEARANCE + HATCH_SLANT {
                break;
            }
            last = k;
        }
        if let Some((k, sin)) = crossed {
            // Back off from the crossing so that the rod clears the
            // guide's end and its leaning hatch.
            let back = (LINK_CLEARANCE / sin.max(0.05) + HATCH_SLANT).ceil() as usize;
            let per_step = (w.far - w.near).norm() / w.steps as f64;
            let n = (back as f64 / per_step.max(1e-9)).ceil() as usize;
            last = k.saturating_sub(n + 1).min(last).max(block_end);
        }
        last
    }

    /// A guide from step `last` to its far end, `span` page units long, in
    /// chords, hatched on its outer side clear of the rod (`guide-{name}`,
    /// `hatch-{name}-k`).
    fn guide(&mut self, name: &str, w: &Walk, last: usize, span: f64) {
        let (slot, s1) = (w.slot, w.slot.range.1);
        let chords = if slot.straight {
            1
        } else {
            (span / CHORD).ceil().max(1.0) as usize
        };
        let at_last = w.at(last);
        // From the open end to the far end.
        let points: Vec<Point> = (0..=chords)
            .map(|j| {
                let s = at_last + (s1 - at_last) * j as f64 / chords as f64;
                (slot.point)(s, w.delta)
            })
            .collect();
        self.push(
            format!("guide-{name}"),
            Role::Frame,
            Shape::Polyline {
                points: points.clone(),
                closed: false,
            },
        );
        // (No direction, so no hatching, for a segment not in `points`.)
        let outward = |j: usize| {
            let (Some(&a), Some(&b)) = (points.get(j), points.get(j + 1)) else {
                return Vector::zeros();
            };
            let n = perp(&(b - a));
            // Away from the slot's middle.
            let mid = (slot.point)(
                at_last + (s1 - at_last) * (j as f64 + 0.5) / chords as f64,
                0.0,
            );
            if n.dot(&(a - mid)) >= 0.0 { n } else { -n }
        };
        let runs = self.clear_runs(&points, &outward, &[w.rod], 0.0);
        self.emit_hatch(name, &points, &outward, &runs);
    }

    /// The runs of hatch strokes along the polyline `points` on the sides
    /// `side(chord)` that keep [`HATCH_CLEAR`] from every segment of
    /// `avoid` and `ends` from the polyline's ends: (chord, from, to) in
    /// page units along the chord, covering whole strokes as the renderer
    /// places them.
    fn clear_runs(
        &self,
        points: &[Point],
        side: &dyn Fn(usize) -> Vector,
        avoid: &[Seg],
        ends: f64,
    ) -> Runs {
        let avoid: Vec<Seg> = avoid
            .iter()
            .map(|(a, b)| (self.page_point(*a), self.page_point(*b)))
            .collect();
        let total: f64 = points
            .iter()
            .zip(points.iter().skip(1))
            .map(|(&a, &b)| (self.page_point(b) - self.page_point(a)).norm())
            .sum();
        let mut runs = Vec::new();
        let mut walked = 0.0;
        for (j, (&a, &b)) in points.iter().zip(points.iter().skip(1)).enumerate() {
            let (a, b) = (self.page_point(a), self.page_point(b));
            let len = (b - a).norm();
            let (Some(t), Some(n)) = (unit(b - a), unit(self.transform().apply_vector(side(j))))
            else {
                walked += len;
                continue;
            };
            // A moving link lying along the edge on it or just behind it
            // about a stroke (the rod on the fixed crank at a dead centre,
            // a bar crossing the edge at a small angle near the crossing)
            // touches only the stroke's foot, as the edge's own line does,
            // and the stroke leans away from it: it does not stop it.
            // Judged over the stretch of the link beside the stroke (from
            // a stroke's depth behind its foot to a depth ahead), so that
            // a bar in front of the edge farther along stops the strokes
            // there and not these.
            let lying = |(c, d): &Seg, s: f64| {
                let Some(u) = unit(*d - *c) else {
                    return false;
                };
                let (ca, da) = ((*c - a).dot(&t), (*d - a).dot(&t));
                if u.dot(&t).abs() <= ALONG_EDGE.cos() || (da - ca).abs() < f64::EPSILON {
                    return false;
                }
                let (lo, hi) = (s - 2.0 * HATCH_DEPTH, s + HATCH_DEPTH);
                let at = |w: f64| {
                    let k = ((w - ca) / (da - ca)).clamp(0.0, 1.0);
                    (*c + (*d - *c) * k - a).dot(&n)
                };
                let (x0, x1) = (at(lo), at(hi));
                x0.min(x1) > -LYING && x0.max(x1) < LYING_IN_FRONT
            };
            let mut run: Option<(f64, f64)> = None;
            let mut s = 0.5 * HATCH_SPACING;
            let mut strokes = 0;
            while s < len {
                let p = a + t * s;
                let q = p + n * HATCH_DEPTH - t * (0.8 * HATCH_DEPTH);
                let along = walked + s;
                let clear = along >= ends
                    && along <= total - ends
                    && (avoid.iter())
                        .filter(|g| !lying(g, s))
                        .all(|g| segment_distance(p, q, g.0, g.1) > HATCH_CLEAR);
                if clear {
                    run = Some(match run {
                        Some((first, _)) => (first, s),
                        None => (s, s),
                    });
                    strokes += 1;
                } else if let Some((first, last)) = run.take() {
                    if strokes >= HATCH_RUN {
                        runs.push((j, first, last));
                    }
                    strokes = 0;
                }
                s += HATCH_SPACING;
            }
            if let Some((first, last)) = run
                && strokes >= HATCH_RUN
            {
                runs.push((j, first, last));
            }
            walked += len;
        }
        runs
    }

    /// The hatching of `runs` along the polyline `points`, on the sides
    /// `side(chord)` (`hatch-{name}-k`).
    fn emit_hatch(
        &mut self,
        name: &str,
        points: &[Point],
        side: &dyn Fn(usize) -> Vector,
        runs: &[(usize, f64, f64)],
    ) {
        for (k, &(j, first, last)) in runs.iter().enumerate() {
            let (Some(&a), Some(&b)) = (points.get(j), points.get(j + 1)) else {
                continue;
            };
            let (a, b) = (self.page_point(a), self.page_point(b));
            let Some(t) = unit(b - a) else { continue };
            let half = 0.5 * HATCH_SPACING;
            let from = self.transform().invert(a + t * (first - half));
            let to = self.transform().invert(a + t * (last + half));
            self.push(
                format!("hatch-{name}-{k}"),
                Role::Frame,
                Shape::Hatch {
                    from,
                    to,
                    side: side(j),
                },
            );
        }
    }
}
