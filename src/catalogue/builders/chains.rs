//! Textbook Fig. 60: (a) the quadric crank chain, (b) the same chain with
//! the lever c replaced by a block sliding in a circular slot of the
//! lever's radius (the cylindric slider-crank chain), (c) the radius grown
//! to infinity: the straight slot, O_cd at infinity. Side by side, at one
//! scale and the same crank angle, links lettered a, b, c, d.
//!
//! (a) is computed as a quadric chain ([`QuadricChain`], from
//! [`CylindricChain::as_quadric`]) and turned into the slot's frame; (b) by
//! the cylindric chain; (c) is today's engine. The slot radius is
//! [`slot_radius`] of the mechanism.

use super::{Ctx, Sheet, crank_detail, short};
use crate::chain::{ChainCentres, CylindricChain, QuadricPose};
use crate::diagram::Plot;
use crate::error::{Error, Field, Result};
use crate::figure::{Align, Figure, Foot, Item, RichText, Role, Shape, TextSize};
use crate::geom::{Frame, Intersection, Point, Vector, crossing, segment_distance, unit};
use crate::number::plain;
use crate::scene::{
    BEARING_REACH, Canvas, LINK_BESIDE, LINK_JOG, Marker, PIN_CLEAR, Seg, Slot, path_beside,
};
use crate::scene::{LINK_LETTER_NEAR, letter_ways};
use crate::{angle::Angle, mechanism::SliderCrank};
use serde_json::json;

/// The distance between the lines of a panel's caption, page units.
const CAPTION_LINE: f64 = 16.0;

/// The slot radius drawn in (b): 0.8 (l + r + |e|), well above the
/// least radius the crank turns with, (l + r + e)/2.
pub(crate) fn slot_radius(m: &SliderCrank) -> f64 {
    0.8 * (m.rod() + m.crank() + m.offset().abs())
}

/// Half length and half height of the block (as the mechanism figures:
/// smaller for a short rod).
pub(super) fn block_size(m: &SliderCrank) -> (f64, f64) {
    let r = m.crank();
    let k = ((m.rod() - r) / r).clamp(0.3, 1.0);
    (0.36 * r * k, 0.17 * r * k)
}

/// The least half length and half height of a block on the page, page
/// units: a long rod draws the crank small, and a block in proportion to
/// it would vanish into its pin (Fig. 60 (b) and (c) at l = 35 r).
const BLOCK_LEAST: (f64, f64) = (12.0, 7.0);

/// The block's half sizes `(lh, hh)` (world units) made at least
/// [`BLOCK_LEAST`] on a page drawn at `scale` page units per world unit.
pub(super) fn block_on_page((lh, hh): (f64, f64), scale: f64) -> (f64, f64) {
    if !(scale.is_finite() && scale > 0.0) {
        return (lh, hh);
    }
    (lh.max(BLOCK_LEAST.0 / scale), hh.max(BLOCK_LEAST.1 / scale))
}

/// The middle of the slot of radius `rho` (`None`: straight) at arc length
/// σ from T = (0, e), offset δ across it.
fn slot_point(e: f64, rho: Option<f64>, s: f64, delta: f64) -> Point {
    match rho {
        None => Point::new(s, e + delta),
        Some(rho) => {
            let (sin, cos) = (s / rho).sin_cos();
            Point::new((rho + delta) * sin, e - rho + (rho + delta) * cos)
        }
    }
}

/// The arc lengths the block's middle reaches over a turn.
fn travel(chain: &CylindricChain) -> (f64, f64) {
    (0..720)
        // Half degrees from 0 to 359.5 are finite angles: `ok()` drops none.
        .filter_map(|k| Angle::from_degrees(0.5 * k as f64).ok())
        .map(|a| chain.pose(a).arc_position())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), s| {
            (lo.min(s), hi.max(s))
        })
}

/// The three chains of Fig. 60 at the figure's pose.
struct Chains {
    m: SliderCrank,
    angle: Angle,
    /// The slot's radius in (b), the lever's in (a).
    rho: f64,
    curved: CylindricChain,
    straight: CylindricChain,
    /// (a)'s pose, in the quadric chain's frame (O_cd on +x).
    quadric: QuadricPose,
    /// The angle, degrees, that turns the quadric chain's frame into the
    /// slot's.
    turn: f64,
    /// The arc lengths the block's middle reaches over a turn, in the
    /// curved slot and the straight one.
    travel: [(f64, f64); 2],
}

impl Chains {
    /// The chains of the figure's mechanism, refused where the slot's
    /// radius, a lever of the quadric chain, passes the largest length.
    fn new(ctx: &Ctx) -> Result<Self> {
        let m = ctx.mechanism;
        let rho = slot_radius(&m);
        let curved = CylindricChain::new(m, rho)?;
        let straight = CylindricChain::straight(m);
        // The slot's radius is a lever of the quadric chain, whose lengths end
        // at MAX_LENGTH as the mechanism's do: 0.8 (l + r + |e|) passes it for
        // a rod and crank near the largest length.
        let Some((quadric, mode, turn)) = curved.as_quadric() else {
            return Err(Error::OutOfRange {
                name: Field::Rod,
                value: m.rod(),
                reason: format!(
                    "fig-60-chains draws a slot of radius 0.8 (l + r + |e|) = {}, beyond the largest length {}: give l + r + |e| at most {}",
                    plain(rho),
                    plain(crate::mechanism::MAX_LENGTH),
                    plain(crate::mechanism::MAX_LENGTH / 0.8)
                ),
            });
        };
        let angle = ctx.angle;
        let quadric = quadric.pose(Angle::from_degrees(angle.degrees() - turn)?, mode)?;
        let travel = [travel(&curved), travel(&straight)];
        Ok(Self {
            m,
            angle,
            rho,
            curved,
            straight,
            quadric,
            turn,
            travel,
        })
    }

    /// A point of (a) turned from the quadric chain's frame into the
    /// slot's.
    fn rotate(&self, p: Point) -> Point {
        let (s, c) = self.turn.to_radians().sin_cos();
        Point::new(c * p.x - s * p.y, s * p.x + c * p.y)
    }

    /// O_cd, the centre of (b)'s slot.
    fn o_cd(&self) -> Point {
        Point::new(0.0, self.m.offset() - self.rho)
    }

    /// The distance (world units) from the crank centre C to the block
    /// of half sizes `(lh, hh)` in the slotted panel (b) (`curved`) or
    /// (c) (0 where the block covers C).
    fn block_over_c(&self, curved: bool, (lh, hh): (f64, f64)) -> f64 {
        let a = self.slotted(curved).0.pose(self.angle).a();
        // The slot's tangent at the block: square to the radius from O_cd
        // in (b), along x in (c).
        let t = if curved {
            unit(a - self.o_cd()).map_or(Vector::new(1.0, 0.0), |u| Vector::new(-u.y, u.x))
        } else {
            Vector::new(1.0, 0.0)
        };
        let v = Point::origin() - a;
        let along = (v.dot(&t).abs() - lh).max(0.0);
        let across = ((v.x * t.y - v.y * t.x).abs() - hh).max(0.0);
        along.hypot(across)
    }

    /// The chain of the slotted panel (b) (`curved`) or (c): the chain,
    /// its slot's radius (`None`: straight) and its block's travel.
    fn slotted(&self, curved: bool) -> (&CylindricChain, Option<f64>, (f64, f64)) {
        if curved {
            (&self.curved, Some(self.rho), self.travel[0])
        } else {
            (&self.straight, None, self.travel[1])
        }
    }
}

/// One panel's drawing extent, the same for all three, and the step
/// from one panel to the next, world units.
struct Layout {
    /// The left end of the first panel's drawing.
    x0: f64,
    width: f64,
    pad: f64,
    gap: f64,
    step: f64,
    /// How far the slot runs past the block's travel.
    reach: f64,
    /// The three panels.
    world: Frame,
}

impl Layout {
    fn new(chains: &Chains) -> Self {
        let m = &chains.m;
        let (r, e) = (m.crank(), m.offset());
        let (lh, hh) = block_size(m);
        let [(_, hi), (_, hi_s)] = chains.travel;
        let reach = 0.15 * r;
        let x0 = -r - reach;
        let far = slot_point(e, Some(chains.rho), hi + lh + reach, 0.0)
            .x
            .max(hi_s + lh + reach);
        let y0 = chains.o_cd().y;
        let y1 = r.max(e + hh);
        let width = far - x0;
        let height = y1 - y0;
        // Room about each panel's drawing: at 0.12 the default engine
        // (l = 3 r) drew its crank 39.9 units long, under the least a
        // link is drawn (crank_detail::CRANK_SEEN), and got a detail that enlarged it
        // ×1.5.
        let pad = 0.11 * width.max(height);
        let gap = 0.5 * pad;
        let step = width + 2.0 * pad + gap;
        let world = Frame::new(
            Point::new(x0 - pad, y0 - pad),
            Point::new(x0 + 3.0 * step - gap - pad, y1 + pad),
        );
        Self {
            x0,
            width,
            pad,
            gap,
            step,
            reach,
            world,
        }
    }
}

/// One of the three panels: (a) when `k` is 0, (b) at 1, (c) at 2, moved
/// right by `dx`, with its crank centre C, crank pin B and A, the end of
/// the rod.
struct Panel {
    k: usize,
    /// Whether the crank a is lettered here (not where a detail of the
    /// crank letters it).
    crank_letter: bool,
    dx: Vector,
    c: Point,
    b: Point,
    a: Point,
    /// The rod as drawn: B A, or beside the crank folded under it.
    rod: Vec<Seg>,
    /// The side the rod is drawn beside the crank on, if it is.
    rod_side: Option<Vector>,
}

/// A block nearer the crank centre than this (page units: the pin's
/// radius and a little paper) stands over C's pin and its bearing, which
/// the notes say.
const OVER: f64 = 6.0;

/// The slot's middle line stops this short of the rod (page units: the
/// rod's half width and a little paper).
const ROD_CLEAR: f64 = 4.0;
/// Nearer than this (page units: the rod's half width, the line's and a
/// little paper) the slot's middle line runs on the rod.
const ROD_TOUCH: f64 = 2.5;

/// The height of the notes below the panels, page units.
const NOTES_HEIGHT: f64 = 44.0;

pub(in crate::catalogue) fn build(ctx: &Ctx) -> Result<Figure> {
    let chains = Chains::new(ctx)?;
    let layout = Layout::new(&chains);
    let rect = super::fitted_rect(&ctx.page(), &layout.world, NOTES_HEIGHT);
    let mut plot = Plot::world(
        "mechanism",
        rect,
        &layout.world,
        false,
        ctx.tolerance,
        ctx.font,
    )?;
    let map = *plot.map();
    let block = block_on_page(block_size(&chains.m), map.scale());
    let shown = map.world_frame(&plot.area());
    let room = (layout.step - layout.gap) * map.scale() - 4.0;
    let captions = captions(ctx, chains.rho, room);
    // Below O_cd's bearing, which keeps its page size however small the
    // panel's pad is drawn.
    let clear = (BEARING_REACH - layout.pad * map.scale()).max(0.0);
    let extra =
        clear + CAPTION_LINE * (captions.iter().map(Vec::len).max().unwrap_or(1) - 1) as f64;
    let mut centres = serde_json::Map::new();
    let captions_end = rect.max().y + 6.0 + extra;
    // A crank drawn shorter than CRANK_SEEN (a long rod: the lever, the
    // frame and the slot's radius are as long as the rod) is enlarged in
    // a detail below each panel, which letters it.
    let enlarged = crank_detail::too_short(chains.m.crank() * map.scale());
    let mut details = Vec::new();
    for (k, suffix) in ["-a", "-b", "-c"].into_iter().enumerate() {
        let dx = Vector::new(k as f64 * layout.step, 0.0);
        let frame = Frame::new(
            Point::new(layout.x0 - layout.pad + dx.x, shown.min().y),
            Point::new(layout.x0 + layout.width + layout.pad + dx.x, shown.max().y),
        );
        let about = match enlarged {
            true => Some(About::Crank),
            false => crowded(&chains, k, map.scale(), detail_area(&frame, map).3)
                .map(|(mid, m)| About::Pins(mid + dx, m)),
        };
        let detail = match about {
            Some(about) => crank_detail(
                ctx,
                (&chains, &layout),
                &frame,
                map,
                captions_end,
                (k, suffix, about),
            )?,
            None => None,
        };
        let mut s = Canvas::new(map, frame).suffixed(suffix);
        let (key, panel_centres) = panel(&mut s, &chains, &layout, block, (k, !enlarged, false));
        centres.insert(key.into(), panel_centres);
        if let Some((region, _)) = &detail {
            super::coriolis::mark_window(&mut s, "mechanism", region);
        }
        for item in s.finish().0 {
            plot.push(item);
        }
        details.extend(detail.map(|(_, d)| d));
        let at = Point::new(layout.x0 + 0.5 * layout.width + dx.x, shown.min().y);
        let lines = captions.get(k).map_or(&[][..], Vec::as_slice);
        push_caption(&mut plot, lines, at, clear, suffix);
    }
    let mut sheet = Sheet::new(ctx);
    sheet.mechanism(ctx, false, true);
    sheet.meta("slot_radius", json!(chains.rho));
    sheet.meta("virtual_centres", serde_json::Value::Object(centres));
    sheet.plot(plot);
    let mut bottom = captions_end;
    for detail in details {
        bottom = bottom.max(detail.rect().max().y + 6.0);
        sheet.detail(detail);
    }
    sheet.height(bottom + NOTES_HEIGHT);
    // The panels whose block stands over the crank's bearing at C.
    let over: Vec<&str> = [(true, "(b)"), (false, "(c)")]
        .into_iter()
        .filter(|&(curved, _)| chains.block_over_c(curved, block) * map.scale() < OVER)
        .map(|(_, name)| name)
        .collect();
    sheet.notes(Point::new(20.0, bottom), &notes(&chains, &over));
    Ok(sheet.finish())
}

/// The crank's radius in its detail, page units, at least (as near as a
/// narrow page's panel allows): a crank's length and a little more.
const CRANK_ENLARGED: f64 = 44.0;

/// A crank detail's reach about the crank centre, in cranks: the crank
/// circle, B's pin on it and a little paper.
const DETAIL_REACH: f64 = 1.2;

/// The most a detail's panel is wide and tall (its caption included),
/// page units.
const DETAIL_SIZE: (f64, f64) = (200.0, 170.0);

/// Room between the captions and the details below them, page units.
const DETAIL_GAP: f64 = 10.0;

/// A panel's detail on the page below its `frame` (drawn by `map`): the
/// panel's left and right ends, the detail's width and the side of its
/// square area below the caption, page units.
fn detail_area(frame: &Frame, map: crate::figure::PageFromWorld) -> (f64, f64, f64, f64) {
    let (x0, x1) = (
        map.apply(frame.min()).x.min(map.apply(frame.max()).x),
        map.apply(frame.min()).x.max(map.apply(frame.max()).x),
    );
    let w = DETAIL_SIZE.0.min(x1 - x0);
    // A square area below the caption, the crank circle and its reach
    // across it.
    let side = w.min(DETAIL_SIZE.1 - crate::diagram::CAPTION);
    (x0, x1, w, side)
}

/// The share of a crowded pins' detail's height the block's height
/// across the slot (the slot runs across the detail by the crank centre,
/// its middle at the height of the offset) and the pins take: enlarged
/// further, the block's sides and the guides left the detail, which
/// showed two pins on bare links (×30 at l = 1.03 r, 180°).
const BLOCK_SEEN: f64 = 0.8;

/// What a panel's detail enlarges.
#[derive(Clone, Copy)]
enum About {
    /// The crank, drawn too short to be seen, about the crank centre.
    Crank,
    /// The crank centre C and the pin A at the rod's end, crowded on the
    /// page: about the world point between them, at the magnification.
    Pins(Point, f64),
}

/// Where panel `k`'s crank centre C and the pin A at the rod's end (the
/// joint of the rod b and the lever or block c) stand nearer than
/// [`super::inversions::PINS_APART`] on the page at `scale` page units
/// per world unit (a short rod about the inner dead centre: at
/// l = 1.03 r, 180° their circles merged under one ground mark in (a),
/// the block stood over C in (b) and (c)), the world point between them
/// (C at the origin, before the panel is moved to its place) and the
/// magnification that draws them [`super::inversions::PINS_SPREAD`] apart
/// at most, if it is [`super::inversions::PINS_ENLARGED`] at least; none
/// where both read.
fn crowded(chains: &Chains, k: usize, scale: f64, side: f64) -> Option<(Point, f64)> {
    use super::inversions::{PINS_APART, PINS_ENLARGED, PINS_SPREAD};
    let a = match k {
        0 => chains.rotate(chains.quadric.a()),
        _ => chains.slotted(k == 1).0.pose(chains.angle).a(),
    };
    let c = Point::origin();
    let pins = (a - c).norm() * scale;
    if !(pins > 0.0 && pins < PINS_APART) {
        return None;
    }
    // The block of (b) and (c) seen across the slot with both pins, at
    // the same magnification in (a): the block's height and the pins'
    // rise within BLOCK_SEEN of the area's height.
    let across = 2.0 * block_size(&chains.m).1 + (a - c).y.abs();
    let fit = BLOCK_SEEN * side / (across * scale);
    let m =
        super::coriolis::round_below((PINS_SPREAD / pins).min(fit), &super::coriolis::FINE_STEPS);
    (m >= PINS_ENLARGED).then(|| (c + (a - c) * 0.5, m))
}

/// Panel `k`'s detail (its `frame` on the page by `map`), below `top`:
/// the world region it enlarges, and its plot with the panel drawn again
/// there ([`About::Crank`]'s crank lettered). [`About::Crank`] enlarges the crank at a
/// round magnification that draws the crank circle within the panel's
/// width, at least [`CRANK_ENLARGED`] in radius where the panel gives
/// room; [`About::Pins`] the crowded pins at their own.
fn crank_detail(
    ctx: &Ctx,
    (chains, layout): (&Chains, &Layout),
    frame: &Frame,
    map: crate::figure::PageFromWorld,
    top: f64,
    (k, suffix, about): (usize, &'static str, About),
) -> Result<Option<(Frame, Plot)>> {
    let scale = map.scale();
    let (x0, x1, w, side) = detail_area(frame, map);
    let r = chains.m.crank() * scale;
    let most = side / (2.0 * DETAIL_REACH * r);
    let (c, magnification) = match about {
        About::Crank => (
            Point::new(k as f64 * layout.step, 0.0),
            crank_detail::round_above(CRANK_ENLARGED / r, &super::coriolis::FINE_STEPS)
                .filter(|m| *m <= most)
                .unwrap_or_else(|| super::coriolis::round_below(most, &super::coriolis::FINE_STEPS))
                .max(1.0),
        ),
        About::Pins(mid, m) => (mid, m),
    };
    let rect = Frame::from_origin_size(
        0.5 * (x0 + x1 - w),
        top + DETAIL_GAP,
        w,
        side + crate::diagram::CAPTION,
    );
    let name = format!("detail{suffix}");
    let (region, mut plot) =
        super::inversions::window_at(ctx, &name, (c, magnification), rect, scale)?;
    let dmap = *plot.map();
    let block = block_on_page(block_size(&chains.m), dmap.scale());
    let mut s = Canvas::new(dmap, dmap.world_frame(&plot.area()))
        .detail("detail-")
        .suffixed(suffix);
    // The crowded pins' detail leaves the crank's letter to the panel.
    let crank_letter = matches!(about, About::Crank);
    panel(&mut s, chains, layout, block, (k, crank_letter, true));
    let items = s.finish().0;
    if !crank_letter && crank_crosses_guides(&items) {
        return Ok(None);
    }
    for item in items {
        plot.push(item);
    }
    Ok(Some((region, plot)))
}

/// Whether the crank of `items` crosses a guide of the slot or its
/// hatching's line: a crowded pins' detail where the crank leaves C
/// under the block across the slot (l = 1.05 r, 120° to 140°) would
/// draw it through the guide, which the main view draws open there; it
/// is left out, the notes saying the block stands over C.
fn crank_crosses_guides(items: &[Item]) -> bool {
    let segs = |it: &Item| -> Vec<Seg> {
        match &it.shape {
            Shape::Polyline { points, .. } => points
                .iter()
                .copied()
                .zip(points.iter().copied().skip(1))
                .collect(),
            Shape::Hatch { from, to, .. } => vec![(*from, *to)],
            _ => Vec::new(),
        }
    };
    // The crank alone: the rod enters the block through its edge on the
    // guide's line.
    let crank: Vec<Seg> = (items.iter())
        .filter(|it| it.role == Role::Link && it.id.contains("link-crank"))
        .flat_map(segs)
        .collect();
    (items.iter())
        .filter(|it| it.id.contains("guide-") || it.id.contains("hatch-"))
        .flat_map(segs)
        .any(|(a, b)| (crank.iter()).any(|&(p, q)| crossing(a, b, p, q).is_some()))
}

/// Each panel's caption broken to the panel's width `room` at its own
/// size, so that a narrow page gives two lines, never captions run
/// together.
fn captions(ctx: &Ctx, rho: f64, room: f64) -> Vec<Vec<RichText>> {
    let caption_size = ctx.style.font_size(TextSize::Small);
    [
        "(a) quadric crank chain".to_string(),
        // No-break spaces keep each equation on one line.
        format!("(b) block in a curved slot, ρ\u{a0}=\u{a0}{}", short(rho)),
        "(c) straight slot, ρ\u{a0}=\u{a0}∞".to_string(),
    ]
    .iter()
    .map(|c| RichText::parse(c).wrap(ctx.font, caption_size, room))
    .collect()
}

/// A panel's caption, its `lines` centred at `at` below the panel and
/// `clear` more below O_cd's bearing (its further lines share one id,
/// which the canvas would draw once).
fn push_caption(plot: &mut Plot, lines: &[RichText], at: Point, clear: f64, suffix: &str) {
    for (i, line) in lines.iter().enumerate() {
        let id = if i == 0 { "caption" } else { "caption-more" };
        plot.push(Item::new(
            format!("{id}{suffix}"),
            Role::Label,
            Shape::Text {
                at,
                offset: Vector::new(0.0, 12.0 + clear + CAPTION_LINE * i as f64),
                text: line.clone(),
                align: Align::Middle,
                size: TextSize::Small,
            },
        ));
    }
}

/// Panel `k` drawn on `s`: the crank circle, the crank and the rod with
/// their pins and letters, then (a)'s lever and frame or the slot and
/// block of (b) and (c); the crank lettered where `crank_letter` (not
/// in a panel whose crank a detail letters), and `detail` where `s` is a
/// crank's detail. Returns the panel's key and its virtual centres.
fn panel(
    s: &mut Canvas,
    chains: &Chains,
    layout: &Layout,
    block: (f64, f64),
    (k, crank_letter, detail): (usize, bool, bool),
) -> (&'static str, serde_json::Value) {
    let dx = Vector::new(k as f64 * layout.step, 0.0);
    let c = Point::origin() + dx;
    let r = chains.m.crank();
    // The crank circle and the crank in every panel.
    crank_detail::crank_circle(s, c, r);
    let (b, a, key) = match k {
        0 => {
            let q = &chains.quadric;
            (chains.rotate(q.b()) + dx, chains.rotate(q.a()) + dx, "a")
        }
        _ => {
            let p = chains.slotted(k == 1).0.pose(chains.angle);
            (p.b() + dx, p.a() + dx, if k == 1 { "b" } else { "c" })
        }
    };
    s.link("crank", vec![c, b]);
    // The rod folded back over the crank and ending on it (a short rod
    // about the inner dead centre, where it lies along the crank for
    // much of the turn:
    // at l = 1.06 r it leaves it at 2° at 150°) drawn beside it, as the
    // frame d beside a link lying along it, on the side away from O_cd
    // (where the lever, the frame and the slot's radius run): drawn
    // over it, the two read as one line with two letters.
    // In every panel, and only where the crank lies along the rod
    // ([`beside`]): not where A is inside the crank circle alone (at
    // l = 1.4 r, e = 0.3 r, 180° (a) bent a rod 11° off the crank). In
    // (b) and (c) the guides leave the hatching clear of the rod's turn
    // in to A.
    let o = chains.o_cd() + dx;
    let rod_side = beside(s, (b, a), &[(c, b)], LYING_SHARE)
        .map(|n| if n.dot(&(o - b)) > 0.0 { -n } else { n });
    let rod = match rod_side {
        Some(n) => beside_path(s, (b, a), n),
        None => vec![b, a],
    };
    s.link("rod", rod.clone());
    let rod_segs: Vec<Seg> = rod
        .iter()
        .zip(rod.iter().skip(1))
        .map(|(&p, &q)| (p, q))
        .collect();
    let rod_run = match rod.as_slice() {
        [_, p, q, _] => (*p, *q),
        _ => (b, a),
    };
    if k == 0 {
        // (b) and (c) draw C's bearing after the block, over it.
        // In a crank's detail clear of the frame d too, which leaves C
        // towards O_cd there alone (its base lay across d's hatching);
        // the panel keeps the side clear of the links, which their
        // letters are set about.
        let mut links = vec![(c, b), (o, a)];
        links.extend(&rod_segs);
        let frame: &[Seg] = if detail { &[(c, o)] } else { &[] };
        s.bearing_on("C", c, foot(s, c, &links, frame));
        s.pin("C", c);
    }
    s.pin("B", b);
    if k != 0 {
        let [crank, rod] = match rod_side {
            // Each letter on its own link's side.
            Some(n) => [Some(-n), Some(n)],
            None => letter_ways([(c, b), (b, a)], &[], s.world(LINK_LETTER_NEAR)),
        };
        if crank_letter {
            s.link_letter_toward("link-a", (c, b), "*a*", crank);
        }
        s.link_letter_toward("link-b", rod_run, "*b*", rod);
    }
    let panel = Panel {
        k,
        dx,
        c,
        b,
        a,
        rod: rod_segs,
        rod_side,
        crank_letter,
    };
    let centres = if k == 0 {
        lever_panel(s, chains, &panel)
    } else {
        slot_panel(s, chains, layout, block, &panel)
    };
    (key, centres)
}

/// (a): the lever c about O_cd and the frame d from C to O_cd, hatched.
/// Returns the quadric chain's virtual centres, in the slot's frame.
fn lever_panel(s: &mut Canvas, chains: &Chains, p: &Panel) -> serde_json::Value {
    let (c, b, a) = (p.c, p.b, p.a);
    let o = chains.o_cd() + p.dx;
    let mut avoid = vec![(c, b), (o, a)];
    avoid.extend(&p.rod);
    s.bearing_on("O-cd", o, foot(s, o, &avoid, &[]));
    s.link("lever", vec![o, a]);
    let ends = PIN_CLEAR;
    // The frame d on the line C O_cd, or beside it where a moving link
    // lies along that line (the crank pointing at O_cd, the lever folded
    // onto d), hatched on its far side.
    let frame = match beside(s, (c, o), &avoid, 0.0) {
        Some(n) => {
            // Beside the line over its length, and turned in to the pins
            // at its ends: a link ends at its pins (run straight beside
            // the line, its end met the crank halfway along at l =
            // 1.1 r, 180°, short of C's pin).
            let path = beside_path(s, (c, o), n);
            let frame = match path.as_slice() {
                [_, p, q, _] => (*p, *q),
                _ => (c, o),
            };
            s.link("frame", path);
            s.hatch_edge_of_at_least("frame", frame, &[n], &avoid, ends, 1);
            frame
        }
        None => {
            s.link("frame", vec![c, o]);
            s.hatch_link("frame", c, o, &avoid, ends);
            (c, o)
        }
    };
    s.pin("A", a);
    s.lettered("O-cd", o, "*O*_{cd}", Marker::Pin, c);
    let rod_run = match p.rod.as_slice() {
        [_, run, _] => *run,
        _ => (b, a),
    };
    let links = [(c, b), rod_run, (o, a), frame];
    let mut ways = letter_ways(links, &[c, b, a, o], s.world(LINK_LETTER_NEAR));
    if let (Some(n), [crank, rod, ..]) = (p.rod_side, &mut ways) {
        // Each of the crank and the rod drawn beside it lettered on its
        // own side.
        (*crank, *rod) = (Some(-n), Some(n));
    }
    for ((name, markup), (link, way)) in [("link-a", "*a*"), ("link-b", "*b*")]
        .into_iter()
        .chain([("link-c", "*c*"), ("link-d", "*d*")])
        .zip(links.into_iter().zip(ways))
        .filter(|((name, _), _)| p.crank_letter || *name != "link-a")
    {
        s.link_letter_toward(name, link, markup, way);
    }
    let (sin, cos) = chains.turn.to_radians().sin_cos();
    // Turned from the quadric chain's frame (O_cd on +x) into the slot's.
    ChainCentres::of_quadric(&chains.quadric)
        .moved(Point::origin(), Vector::new(cos, sin))
        .to_json()
}

/// (b) and (c): the slot's middle line and guides, the block following
/// the slot, and O_cd (at infinity in (c)). Returns the cylindric chain's
/// virtual centres.
fn slot_panel(
    s: &mut Canvas,
    chains: &Chains,
    layout: &Layout,
    (lh, hh): (f64, f64),
    p: &Panel,
) -> serde_json::Value {
    let (c, b, a, dx) = (p.c, p.b, p.a, p.dx);
    let (chain, rho, (lo, hi)) = chains.slotted(p.k == 1);
    let pose = chain.pose(chains.angle);
    let e = chains.m.offset();
    let point = move |sigma: f64, delta: f64| slot_point(e, rho, sigma, delta) + dx;
    let slot = Slot {
        point: &point,
        straight: rho.is_none(),
        range: (lo - lh - layout.reach, hi + lh + layout.reach),
        half_height: hh,
        block: (pose.arc_position(), lh),
    };
    // The guides, then the slot's middle line along them only, and short
    // of the rod where it nears it outside the block (run on past where the guides open
    // towards the crank, it lay along the rod and crossed it).
    // The rod's last run into A: the turn in to A where the rod is drawn
    // beside the crank, which the guides' hatching keeps clear of.
    let into_a = p.rod.last().copied().unwrap_or((b, a));
    let mut open = s.guides("slot", &slot, c, into_a).unwrap_or(slot.range.0);
    let step = s.world(1.0);
    let mut at = pose.arc_position() - lh;
    let rod_page: Vec<Seg> = (p.rod.iter())
        .map(|&(x, y)| (s.transform().apply(x), s.transform().apply(y)))
        .collect();
    let by_rod = |at: f64| {
        let q = s.transform().apply(point(at, 0.0));
        (rod_page.iter())
            .map(|&(x, y)| segment_distance(q, q, x, y))
            .fold(f64::INFINITY, f64::min)
    };
    while at > open {
        // On the rod, or near it and not drawing away from it (the rod
        // leaving the block through its edge draws away from the line).
        let d = by_rod(at);
        if d < ROD_TOUCH || (d < ROD_CLEAR && by_rod(at - step) <= d) {
            open = at + step;
            break;
        }
        at -= step;
    }
    let mid_line: Vec<Point> = (0..=48)
        .map(|j| point(open + (slot.range.1 - open) * j as f64 / 48.0, 0.0))
        .collect();
    s.push(
        "line-slot",
        Role::Auxiliary,
        Shape::Polyline {
            points: mid_line,
            closed: false,
        },
    );
    // The block, following the slot.
    let sa = pose.arc_position();
    let mut outline: Vec<Point> = (0..=8)
        .map(|j| point(sa - lh + 2.0 * lh * j as f64 / 8.0, -hh))
        .collect();
    outline.extend((0..=8).map(|j| point(sa + lh - 2.0 * lh * j as f64 / 8.0, hh)));
    // C's bearing turned to a side clear of the crank and the rod, then
    // of the block, the guides along it and O_cd's radius; drawn over the
    // block where none is clear of it.
    let mut others: Vec<Seg> = (outline.iter().zip(outline.iter().cycle().skip(1)))
        .map(|(&p, &q)| (p, q))
        .collect();
    for delta in [-hh, hh] {
        let at = |j: usize| point(sa - lh + (slot.range.1 - sa + lh) * j as f64 / 32.0, delta);
        others.extend((0..32).map(|j| (at(j), at(j + 1))));
    }
    if let Intersection::Point(o) = pose.chain().slot_centre() {
        others.push((o + dx, a));
    }
    s.push("block-slider", Role::Link, Shape::Block { points: outline });
    let mut links = vec![(c, b)];
    links.extend(&p.rod);
    let c_foot = foot(s, c, &links, &others);
    s.bearing_on("C", c, c_foot);
    s.pin("C", c);
    s.pin("A", a);
    // The block's letter by its inner side, or, where the block stands
    // over C, by the side away from C's bearing (set by the inner side,
    // it stood under the bearing's hatching at l = 1.03 r, 180°).
    let over = s.page(chains.block_over_c(p.k == 1, (lh, hh))) < OVER;
    let side = |delta: f64| {
        let t = s.transform();
        (t.apply(point(sa, delta)) - t.apply(point(sa, 0.0))).dot(&c_foot.axes().0)
    };
    let delta = if over && side(-hh) > side(hh) {
        hh
    } else {
        -hh
    };
    s.letter("link-c", point(sa, delta), "*c*", TextSize::Letter);
    s.letter("link-d", point(slot.range.1, hh), "*d*", TextSize::Letter);
    match pose.chain().slot_centre() {
        Intersection::Point(o) => {
            let o = o + dx;
            s.segment("line-radius", Role::Auxiliary, o, a);
            s.lettered("O-cd", o, "*O*_{cd}", Marker::Dot, c);
        }
        _ => {
            // Lettered beside its arrow: by the tail the renderer set it
            // loose, under the crank circle with a gap above the arrow.
            s.lettered_at_infinity("O-cd", (a, Vector::new(0.0, -1.0)), "*O*_{cd}", true);
        }
    }
    ChainCentres::of_cylindric(&pose).to_json()
}

/// The link `p q` drawn beside its line on the side `n` (a world unit
/// vector square to it), [`LINK_BESIDE`] off it over its length and
/// turned in to its pins at the ends over [`LINK_JOG`], at most a third
/// of its length each way (run straight beside the line, the frame's end
/// met the crank halfway along at l = 1.1 r, 180°, short of C's pin).
fn beside_path(s: &Canvas, (p, q): Seg, n: Vector) -> Vec<Point> {
    let jog = s.world(LINK_JOG).min((q - p).norm() / 3.0);
    path_beside(s, (p, q), n, (jog, jog))
}

/// A moving link nearer the line C O_cd than this (page units: a link's
/// width and a little paper)…
const LYING_NEAR: f64 = 5.0;
/// …over at least this length of it (page units)…
const LYING_OVER: f64 = 16.0;
/// …and, for the crank along the rod, over at least this share of the
/// crank's own length: two links leaving one pin a few degrees apart are
/// near each other by the pin whatever the angle (the rod 11° off the
/// crank at l = 1.4 r, e = 0.3 r, 180°, within [`LYING_NEAR`] of it over
/// 26 units), but they part visibly before half the crank is reached.
const LYING_SHARE: f64 = 0.5;

/// The side (a world unit vector square to `p q`) the fixed link `p q`
/// is drawn beside its line on where one of the moving `links` lies along
/// that line (within [`LYING_NEAR`] of it over [`LYING_OVER`], and over
/// `share` of the link's length): away from
/// the links lying along it, or, where these lie on the line itself, from
/// the others. `None` where none lies along it.
fn beside(s: &Canvas, (p, q): Seg, links: &[Seg], share: f64) -> Option<Vector> {
    let u = unit(q - p)?;
    let n = Vector::new(-u.y, u.x);
    let length = (q - p).norm();
    // The signed distances from the line of a link's points over it, a
    // point every page unit or so (33 points along a lever drawn 500
    // units long in a crank's detail stood 16 apart, and its end at O_cd
    // alone read as lying along d).
    let samples = |&(a, b): &Seg| (s.page((b - a).norm()).ceil() as usize).clamp(32, 4000);
    let over = |&(a, b): &Seg| -> Vec<f64> {
        let m = samples(&(a, b));
        (0..=m)
            .map(|k| a + (b - a) * (k as f64 / m as f64))
            .filter(|x| (0.0..=length).contains(&(x - p).dot(&u)))
            .map(|x| (x - p).dot(&n))
            .collect()
    };
    let lying = |link: &Seg| {
        let length = s.page((link.1 - link.0).norm());
        let step = length / samples(link) as f64;
        let near = (over(link).iter())
            .filter(|d| s.page(d.abs()) < LYING_NEAR)
            .count();
        near as f64 * step >= LYING_OVER.max(share * length)
    };
    let (along, off): (Vec<&Seg>, Vec<&Seg>) = links.iter().partition(|l| lying(l));
    if along.is_empty() {
        return None;
    }
    // The side whose line meets fewer of the links' points, then the side
    // away from the links lying along it (their mean distance from the
    // line), or from the others where these lie on the line itself.
    let crowd = |m: Vector| {
        let shift = m * s.world(LINK_BESIDE);
        let (a, b) = (p + shift, q + shift);
        (links.iter())
            .flat_map(|&(x, y)| (0..=64).map(move |k| x + (y - x) * (f64::from(k) / 64.0)))
            .filter(|&x| s.page(segment_distance(x, x, a, b)) < LYING_NEAR)
            .count()
    };
    let mean = |ls: &[&Seg]| {
        let all: Vec<f64> = ls.iter().flat_map(|l| over(l)).collect();
        all.iter().sum::<f64>() / all.len().max(1) as f64
    };
    let side = mean(&along);
    let side = if s.page(side.abs()) > 1.0 {
        side
    } else {
        mean(&off)
    };
    let away = if side > 0.0 { -n } else { n };
    // The links the link drawn on side `m` would cross, off its pins (at
    // l = 1.06 r, 180° d turned in to C on the side of A, 4 units from
    // C, and crossed the lever leaving A).
    let crossings = |m: Vector| {
        let path = beside_path(s, (p, q), m);
        let trim = s.world(END_TOUCH);
        let cut =
            |from: Point, to: Point| from + unit(to - from).map_or(Vector::zeros(), |u| u * trim);
        let runs: Vec<Seg> = match path.as_slice() {
            [a, b, c, d] => vec![(cut(*a, *b), *b), (*b, *c), (*c, cut(*d, *c))],
            _ => Vec::new(),
        };
        (links.iter())
            .filter(|&&(x, y)| (runs.iter()).any(|&(a, b)| crossing(a, b, x, y).is_some()))
            .count()
    };
    Some(
        match (crossings(n), crowd(n)).cmp(&(crossings(-n), crowd(-n))) {
            std::cmp::Ordering::Less => n,
            std::cmp::Ordering::Greater => -n,
            std::cmp::Ordering::Equal => away,
        },
    )
}

/// How near its pins (page units: a pin's radius) a link drawn beside
/// its line may meet another link there.
const END_TOUCH: f64 = 4.0;

/// A bearing's ink about its centre, page units (the SVG writer's
/// bearing): its pedestal from the shaft's pin (which the links leave
/// from) out to its base, half as wide there; the base's half width, and
/// how far out its hatching reaches.
const PEDESTAL: (f64, f64, f64) = (6.0, 17.0, 10.0);
const BASE: (f64, f64) = (17.0, 23.0);
/// Paper kept round a bearing's ink, page units: a link's half width and
/// a little more.
const INK_CLEAR: f64 = 2.5;

/// Whether the page point `v` (from a bearing's centre, `o` out towards
/// its foot and `w` across) falls on the bearing's ink or within
/// [`INK_CLEAR`] of it.
fn on_bearing(o: f64, w: f64) -> bool {
    let (pin, foot, half) = PEDESTAL;
    let (base_half, reach) = BASE;
    let pedestal = o > pin && o < foot + INK_CLEAR && w.abs() < half * o / foot + INK_CLEAR;
    // The hatching leans back across the base by its depth.
    let base = o > foot - INK_CLEAR
        && o < reach + INK_CLEAR
        && w.abs() < base_half + (reach - foot) + INK_CLEAR;
    pedestal || base
}

/// The side a fixed pin `p`'s bearing stands on: the first of below,
/// above, left and right whose pedestal and hatched base ([`on_bearing`])
/// keep clear of
/// the moving `links`, and of these the one that meets least of the
/// `others` drawn (the block, its guides, a dashed radius); where none is
/// clear of the links, the one that meets them least (a rod passing just
/// under the crank centre ran through the pedestal and read as pinned
/// there).
fn foot(s: &Canvas, p: Point, links: &[Seg], others: &[Seg]) -> Foot {
    let t = s.transform();
    let at = t.apply(p);
    let hits = |f: Foot, segs: &[Seg]| -> usize {
        let (out, along) = f.axes();
        (segs.iter())
            .map(|&(a, b)| {
                let (a, b) = (t.apply(a), t.apply(b));
                let n = ((b - a).norm() / 2.0).ceil().clamp(1.0, 4000.0) as usize;
                (0..=n)
                    .filter(|&k| {
                        let v = a + (b - a) * (k as f64 / n as f64) - at;
                        on_bearing(v.dot(&out), v.dot(&along))
                    })
                    .count()
            })
            .sum()
    };
    // Of sides equally clear, the first (below) is kept.
    [Foot::Below, Foot::Above, Foot::Left, Foot::Right]
        .into_iter()
        .min_by_key(|&f| (hits(f, links), hits(f, others)))
        .unwrap_or(Foot::Below)
}

/// The notes: the mechanism and the crank angle, and what each panel's
/// links are, and the panels (`over`) whose block stands over C.
fn notes(chains: &Chains, over: &[&str]) -> [String; 2] {
    let m = &chains.m;
    let e = m.offset();
    [
        format!(
            "Crank *a* = *r* = {}, rod *b* = *l* = {}{}, θ = {}° in all three.",
            short(m.crank()),
            short(m.rod()),
            if e == 0.0 {
                String::new()
            } else {
                format!(", offset *e* = {}", short(e))
            },
            short(chains.angle.degrees())
        ),
        format!(
            "(a) lever *c* = ρ about *O*_{{cd}}, frame *d* from the crank’s centre to *O*_{{cd}}; (b) the block *c* in a slot of radius ρ about *O*_{{cd}}; (c) ρ → ∞.{}",
            if over.is_empty() {
                String::new()
            } else {
                format!(
                    " At this pose the block stands over the crank’s centre in {}.",
                    over.join(" and ")
                )
            }
        ),
    ]
}
