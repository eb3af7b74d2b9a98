//! The enlarged detail of the constructions about the crank (Figs. 65–67):
//! which region, at what magnification.
//!
//! Klein's and Kisch's triangles FCG lie within about r of the crank
//! centre, while the page must also hold the rod, the slider and its
//! guides: with the §35 engine (n = 6) the crank radius is about 75 page
//! units, and F, G sit within a dozen units of B and C. The acceleration
//! layers therefore carry a detail of the whole construction while it
//! spans less than [`CORE_TARGET`] units on the main view. The velocity
//! layer gets one when its triangle ECB spans less than [`THRESHOLD`]
//! page units: below that its three letters (each about 12 × 17 units,
//! kept 4 units from their points) with the pins of B and C and the
//! right-angle mark at C cannot all sit clear of its sides.
//!
//! A construction the main view draws larger than that (a short rod,
//! where the crank fills the page) is readable there, but some of its
//! lettered points may still crowd: near 90° with l = 1.08 r, F, H, B and
//! E lie within a few units of each other. Its detail is then drawn
//! around the points that crowd (any two lettered points within
//! [`CROWD`] units), magnified until they stand [`APART`]; where nothing
//! crowds there is none (a detail repeating the whole mechanism at ×2
//! helps nobody). A detail of the whole construction takes in the
//! lettered points within [`CROWD`] of it (A and D by C on a short rod),
//! so that none stands on its frame.
//!
//! The torque layer (Ng's Fig. 1) marks the crank centre and the crank
//! pin: the torque arrow of radius 36 units about the centre, the θ arc of
//! radius 28 inside it, β and φ at the pin, the right angle at the centre,
//! and the letters of the centre, the pin and M, each about 12 × 17 units
//! within 1.5 em of its point. They fit inside the crank circle only where
//! its radius is at least [`CRANK_THRESHOLD`] units (an arrow's and a
//! letter's width beyond the torque arrow); a smaller crank (a long rod, or
//! an offset that makes the page's scale small) gets a detail of the crank
//! that carries those marks, at least [`CRANK_TARGET`] units in radius,
//! and the main view shows the links, pins and forces alone there.
//!
//! The angles layer without a torque (Fig. 62) marks less about the crank:
//! θ's arc of radius 28 units with its letter, r's letter beside the crank
//! and φ at the pin. They fit a crank circle of [`ANGLES_THRESHOLD`] units;
//! on Fig. 62's page a rod of 20 cranks draws the circle 30 units in
//! radius, where θ's letter sits on the crank and r's on the pin. A smaller
//! crank gets a detail at least [`ANGLES_TARGET`] units in radius.
//!
//! The polygons' figure marks the crank with its ω alone, and is held to
//! the angles' threshold and target: on a rod of fifty cranks its crank
//! was a few units long, B's pin on C's, their letters jammed, and the
//! polygons, drawn from the crank's velocity and acceleration, read from
//! a crank not to be seen.

use super::LayerCtx;
use crate::figure::HATCH_DEPTH;
use crate::geom::{Frame, Point, Vector};
use crate::scene::Layer;
use crate::scene::canvas::BESIDE_PIN;

/// The extent, page units, under which the velocity triangle ECB gets a
/// detail (see the module docs).
pub(crate) const THRESHOLD: f64 = 60.0;
/// The larger side of the detailed points' box in the detail, page units
/// (at least the 150 the plates require, with room for letters).
const TARGET: f64 = 230.0;
/// Room around the detailed points inside the detail, page units (letters
/// of the outer points, right-angle marks).
pub(crate) const PAD: f64 = 34.0;
/// The least height of a detail, page units: room above and below a flat
/// construction (near the dead centres) for its letters.
pub(crate) const MIN_HEIGHT: f64 = 150.0;
/// Magnifications offered: round numbers a reader takes in at a glance,
/// 2, 2.5, 3, 4, 5, 6, 8 times a power of ten, from 2 to 8e12.
fn steps() -> impl DoubleEndedIterator<Item = f64> + Clone {
    (0..13).flat_map(|k| {
        let p = 10f64.powi(k);
        let first = if k == 0 { 1 } else { 0 };
        [1.0, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0]
            .iter()
            .skip(first)
            .map(move |m| m * p)
            .collect::<Vec<_>>()
    })
}

/// The crank radius, page units, under which the torque layer gets a
/// detail of the crank (see the module docs).
pub(crate) const CRANK_THRESHOLD: f64 = 90.0;
/// The least crank radius in a crank's detail, page units.
const CRANK_TARGET: f64 = 110.0;
/// The crank radius, page units, under which a figure marking the crank's
/// angles without a torque gets a detail of the crank (see the module
/// docs).
const ANGLES_THRESHOLD: f64 = 40.0;
/// The crank radius, page units, under which the polygons' figure (its
/// crank marked by ω alone) gets a crank's detail: a crank of 30 units
/// reads, and a handout's low page (760 by 480) draws its engine's crank
/// at about that without a detail's room.
const POLYGONS_THRESHOLD: f64 = 25.0;
/// The least crank radius in the detail of such a figure, page units.
const ANGLES_TARGET: f64 = 80.0;

/// What a detail enlarges.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Focus {
    /// The velocity or acceleration construction about B and C: the
    /// main view leaves its constructed points' letters to the detail.
    Construction,
    /// The crank of a torque figure: the main view leaves the marks about
    /// the crank (angles, the torque arrow, M's letter) to the detail.
    Crank,
}

/// What the detail shows: the world region (the detailed points' box),
/// the magnification over the main view, and what it enlarges.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Detail {
    pub region: Frame,
    pub magnification: f64,
    pub focus: Focus,
}

/// The points of the constructions about the crank that the scene draws:
/// B, C, E and the construction's F and G first (the core the plates
/// measure), then Kisch's H where it exists.
fn points(ctx: &LayerCtx) -> (Vec<Point>, Option<Point>) {
    let scene = ctx.scene;
    let pose = ctx.main.pose();
    let mut pts = vec![pose.b(), pose.c()];
    pts.push(ctx.main.e().e());
    let mut h = None;
    if scene.has(Layer::Kisch) {
        let k = ctx.main.kisch();
        pts.extend([k.points().f(), k.points().g()]);
        h = k.h();
    } else if scene.has(Layer::Klein) {
        let k = super::acceleration::klein_points(ctx);
        pts.extend([k.f(), k.g()]);
    } else if scene.has(Layer::Ritterhaus) {
        let r = ctx.main.ritterhaus();
        pts.extend([r.points().f(), r.points().g()]);
        h = Some(r.k());
    } else if scene.has(Layer::Bennett)
        && let Some(bn) = ctx.main.bennett()
    {
        pts.extend([bn.points().f(), bn.points().g(), bn.l()]);
        h = Some(bn.k());
    }
    (pts, h)
}

/// The least larger side of the core points' box (B, C, E, F, G) in the
/// detail, page units: the 150 the plates require, with a margin.
const CORE_TARGET: f64 = 160.0;

/// The box of `pts` (the origin's when there are none).
fn bounds(pts: &[Point]) -> (Point, Point) {
    let first = pts.first().copied().unwrap_or_else(Point::origin);
    let mut min = first;
    let mut max = first;
    for p in pts {
        min = min.inf(p);
        max = max.sup(p);
    }
    (min, max)
}

/// The detail a scene drawn at `scale` page units per world unit needs,
/// if any, no wider than `max_width` page units. Kisch's H joins the
/// region only where the core still gets [`CORE_TARGET`] with it.
pub(crate) fn detail(ctx: &LayerCtx, scale: f64, max_width: f64) -> Option<Detail> {
    let d = chosen(ctx, scale, max_width)?;
    Some(match d.focus {
        Focus::Crank => clear_of_block(ctx, d, scale, max_width),
        Focus::Construction => {
            with_guides(ctx, joint_room(ctx, d, scale, max_width), scale, max_width)
        }
    })
}

/// The most the guides' height apart may take in a detail grown to them
/// ([`with_guides`]), page units: the block is drawn to the main view's
/// page sizes, and where the main view is drawn small (a page whose
/// height is fixed low) it is many cranks tall in the world, and a
/// detail grown to it ran to thousands of units.
const GUIDES_EXTENT: f64 = 400.0;

/// `d`, a construction's detail, its region grown up and down to the
/// guides where its frame (the region and [`PAD`] about it) crosses the
/// slider block without holding its height: at a rod of little more than
/// a crank near the inner dead centre the detail about A, C and the
/// points by them stood within the channel, and of the block it showed
/// one face, a lone line across the panel, its corners and the guides
/// outside. Taking in the guides, and the block's length where the page
/// holds it, it shows the block between them, as the main view draws it.
fn with_guides(ctx: &LayerCtx, d: Detail, scale: f64, max_width: f64) -> Detail {
    let page = scale * d.magnification;
    if !(page > 0.0 && page.is_finite()) {
        return d;
    }
    let pad = PAD / page;
    let a = ctx.main.pose().a();
    let (l, h) = (ctx.sizes.block_half_length, ctx.sizes.block_half_height);
    let (lo, hi) = (d.region.min(), d.region.max());
    let across = lo.x - pad < a.x + l && hi.x + pad > a.x - l;
    let meets = lo.y - pad < a.y + h && hi.y + pad > a.y - h;
    let holds = lo.y - pad <= a.y - h && hi.y + pad >= a.y + h;
    if !(across && meets) || holds {
        return d;
    }
    // The frame [`ABOUT_HATCH`] off the guides' hatching on the main
    // view at least: [`ABOUT_BLOCK_MAIN`] off the guides alone, it ran
    // along the hatching's ends and, as near the block's ends, read as a
    // second block about it.
    let room = |page: f64| ((ABOUT_HATCH + HATCH_DEPTH) / scale - PAD / page).max(0.0);
    let tall = |page: f64| 2.0 * (h + room(page)) * page > GUIDES_EXTENT;
    // Too tall at its magnification, the detail is lowered to the step
    // that holds the guides, while its closest lettered points still
    // stand [`CROWD`] apart there: grown at ×8 to the guides, with its
    // frame on their hatching, Kisch's detail at a rod of 1.02 cranks
    // read as a second block; not grown, its frame crossed the block.
    let d = match tall(page) {
        false => d,
        true => {
            let closest = closest_within(ctx, &d.region, scale);
            let lower = steps()
                .rev()
                .find(|m| *m <= d.magnification && !tall(scale * m));
            match lower {
                Some(m) if closest * m >= APART => Detail {
                    magnification: m,
                    ..d
                },
                _ => return d,
            }
        }
    };
    let page = scale * d.magnification;
    let room = room(page);
    let (lo, hi) = (
        Point::new(lo.x, lo.y.min(a.y - h - room)),
        Point::new(hi.x, hi.y.max(a.y + h + room)),
    );
    // The block whole, where its length fits the page at the detail's
    // magnification, the frame [`ABOUT_BLOCK_MAIN`] off its ends (which
    // carry no hatching).
    let side = (ABOUT_BLOCK_MAIN / scale - PAD / page).max(0.0);
    let (x0, x1) = (lo.x.min(a.x - l - side), hi.x.max(a.x + l + side));
    let whole = (x1 - x0) * page + 2.0 * PAD <= max_width;
    let (lo, hi) = match whole {
        true => (Point::new(x0, lo.y), Point::new(x1, hi.y)),
        false => (lo, hi),
    };
    Detail {
        region: Frame::new(lo, hi),
        ..d
    }
}

/// The least distance, page units on the main view at `scale`, between
/// two lettered points of the construction within `region` that a
/// detail separates (at least [`CROWD`] / [`MOST_CROWDED`] apart: those
/// closer are taken as one); infinite where there are none.
fn closest_within(ctx: &LayerCtx, region: &Frame, scale: f64) -> f64 {
    let (core, h) = points(ctx);
    let mut lettered = [core.as_slice(), &[ctx.main.pose().a()]].concat();
    lettered.extend(h);
    let (lo, hi) = (region.min(), region.max());
    let inside = |p: &Point| p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y;
    lettered.retain(inside);
    (within(&lettered, CROWD, scale).iter())
        .map(|&(_, _, d)| d)
        .filter(|d| *d >= CROWD / MOST_CROWDED)
        .fold(f64::INFINITY, f64::min)
}

/// Page units (in the detail) a joint letter takes for each name after
/// its first: ", *G*" at the letters' size, a comma, its space and an
/// italic capital.
const JOINT_NAME: f64 = 18.0;

/// Page units (in the detail) a joint letter keeps each side beyond
/// [`JOINT_NAME`] for each of its names inside the frame: its first
/// name's comma-less remainder, the room about its glyphs and the labels'
/// inset from the frame ("*B*, *E*, *F*, *H*" is 81 units wide).
const JOINT_ROOM: f64 = 10.0;

/// Page units (in the detail) under which two lettered points coincide
/// there and take one joint letter ("*F*, *G*, *K*, *L*" at a dead
/// centre), as the canvas letters them.
const ONE_POINT: f64 = 1.0;

/// `d`, a construction's detail, its region grown on the side (left or
/// right) where lettered points that coincide stand on its edge, by the
/// width their joint letter takes beyond a single letter's
/// ([`JOINT_NAME`] for each name after the first), so that the letter
/// finds its room there beside its dot rather than across the lines
/// leaving it (at a long rod's outer dead centre F, G, K and L by B,
/// the joint letter on the frame's edge had no room and its names were
/// scattered along the frame). Lowered a step where the grown region no
/// longer fits `max_width`.
fn joint_room(ctx: &LayerCtx, d: Detail, scale: f64, max_width: f64) -> Detail {
    let (core, h) = points(ctx);
    let mut lettered = [core.as_slice(), &[ctx.main.pose().a()]].concat();
    lettered.extend(h);
    let page = scale * d.magnification;
    if !(page > 0.0 && page.is_finite()) {
        return d;
    }
    let (lo, hi) = (d.region.min(), d.region.max());
    let edge_room = |x: f64| {
        // The most lettered points at one point on the edge at x.
        let on_edge = |p: &&Point| ((p.x - x) * page).abs() < ONE_POINT;
        let at: Vec<&Point> = lettered.iter().filter(on_edge).collect();
        let most = (at.iter())
            .map(|p| {
                (lettered.iter())
                    .filter(|q| (*q - *p).norm() * page < ONE_POINT)
                    .count()
            })
            .max()
            .unwrap_or(0);
        most.saturating_sub(1) as f64 * JOINT_NAME / page
    };
    let (left, right) = (edge_room(lo.x), edge_room(hi.x));
    let (mut lo, mut hi) = (lo - Vector::new(left, 0.0), hi + Vector::new(right, 0.0));
    // A joint letter of the points under one pin ("B, E, F, H" under
    // Kisch's B at a long rod near 90°) wholly to either side of the pin
    // within the frame, clear of a line leaving the pin up or down (the
    // semicircle on AB, the crank): its width and a letter's room each
    // side of the pin. The letters of dots just beside the pin, within
    // two of its pen widths though not under it (Bennett's E by B at
    // l = 30 r, 91°), take as much room beside it as their joint letter
    // would.
    for p in &lettered {
        let under = |q: &&Point| (*q - p).norm() * page < BESIDE_PIN;
        let names = lettered.iter().filter(under).count();
        if names > 1 {
            let half = (names as f64 * JOINT_NAME + 2.0 * JOINT_ROOM - PAD).max(0.0) / page;
            lo.x = lo.x.min(p.x - half);
            hi.x = hi.x.max(p.x + half);
        }
    }
    if lo == d.region.min() && hi == d.region.max() {
        return d;
    }
    match magnify(d.magnification, (hi.x - lo.x) * scale, max_width) {
        Some(magnification) => Detail {
            region: Frame::new(lo, hi),
            magnification,
            ..d
        },
        None => d,
    }
}

/// Room (page units in the detail) a detail's region keeps about the
/// slider block it would otherwise lie inside ([`clear_of_block`]): the
/// frame's least distance from a guide, so that its edges stand clear of
/// the guides' hatching without being moved off them (which would pad
/// the detail with empty paper).
const ABOUT_BLOCK: f64 = 14.0;

/// The least room (page units on the main view) about the block that a
/// crank's detail grown to it keeps: its frame there is told from the
/// block's outline.
const ABOUT_BLOCK_MAIN: f64 = 6.0;

/// The least room (page units on the main view) a detail grown to the
/// guides ([`with_guides`]) keeps beyond their hatching's ends: a line's
/// gap clear of the strokes.
const ABOUT_HATCH: f64 = 3.0;

/// The larger side, page units, a crank's detail grown to the block
/// keeps within (the magnification step at or below it): held within
/// the 320 of a crowd, a short rod's block at its inner dead centre
/// filled a frame larger than the main view, mostly empty paper.
const BLOCK_EXTENT: f64 = 200.0;

/// `d`, a crank's detail, or, where its region's middle lies inside the
/// slider block on the main view at `scale` and the region does not hold
/// the whole block (a short rod's inner dead centre: A and C within the
/// block's outline), the region grown to the block's outline and
/// [`ABOUT_BLOCK`] about it, magnified no more than holds it within
/// [`BLOCK_EXTENT`]. Its frame was a few units inside the block, hidden
/// by the pins, the block's outline read as the frame; now the frame
/// stands round the block and the detail draws the block whole. `d` as
/// it is where no step fits `max_width`. A construction's detail keeps
/// its region: grown to the block, its magnification would fall to a
/// few times, where E, D and F crowd A and C again.
fn clear_of_block(ctx: &LayerCtx, d: Detail, scale: f64, max_width: f64) -> Detail {
    let a = ctx.main.pose().a();
    let half = Vector::new(ctx.sizes.block_half_length, ctx.sizes.block_half_height);
    let (blo, bhi) = (a - half, a + half);
    let (lo, hi) = (d.region.min(), d.region.max());
    let mid = nalgebra::center(&lo, &hi);
    let inside = (blo.x..=bhi.x).contains(&mid.x) && (blo.y..=bhi.y).contains(&mid.y);
    let holds = lo.x <= blo.x && lo.y <= blo.y && hi.x >= bhi.x && hi.y >= bhi.y;
    if !inside || holds || !(scale > 0.0 && scale.is_finite()) {
        return d;
    }
    let (lo, hi) = (lo.inf(&blo), hi.sup(&bhi));
    let size = (hi - lo) * scale;
    let most = d.magnification.min(BLOCK_EXTENT / size.max());
    // The step at or below the most (the block's detail is large).
    let wanted = steps().rev().find(|m| *m <= most).unwrap_or(most);
    // The room about the block is the detail's, the frame standing
    // ABOUT_BLOCK from the guides in the detail whatever it enlarges.
    match magnify(wanted, size.x + 2.0 * ABOUT_BLOCK / wanted, max_width) {
        Some(magnification) => {
            let room = (ABOUT_BLOCK / magnification).max(ABOUT_BLOCK_MAIN) / scale;
            let room = Vector::new(room, room);
            Detail {
                region: Frame::new(lo - room, hi + room),
                magnification,
                ..d
            }
        }
        None => d,
    }
}

/// The detail a scene drawn at `scale` needs before it is kept clear of
/// the block ([`detail`]).
fn chosen(ctx: &LayerCtx, scale: f64, max_width: f64) -> Option<Detail> {
    let scene = ctx.scene;
    let acceleration = scene.layers().iter().any(|l| l.is_acceleration());
    let velocity = scene.has(Layer::Velocity);
    if !scene.has(Layer::Mechanism) {
        return None;
    }
    if !(acceleration || velocity) {
        return crank(ctx, scale, max_width).or_else(|| crowded_crank(ctx, scale, max_width));
    }
    if let Some(d) = subject(ctx, scale, max_width) {
        return d;
    }
    let (core, h) = points(ctx);
    let (cmin, cmax) = bounds(&core);
    let core_size = cmax - cmin;
    let core_extent = core_size.x.max(core_size.y) * scale;
    if !(core_extent > 0.0 && core_extent.is_finite()) {
        return None;
    }
    // A construction the main view draws large enough to read needs a
    // detail only where its lettered points crowd (a short rod: F, H, B
    // and E together near 90°).
    let readable = match acceleration {
        true => core_extent >= CORE_TARGET,
        false => core_extent >= THRESHOLD,
    };
    let mut lettered = [core.as_slice(), &[ctx.main.pose().a()]].concat();
    lettered.extend(h);
    lettered.extend(super::fit::d_is_near(ctx));
    // The acceleration constructions' pins (C among A, E, F, G on a short
    // rod) need their letters' room inside the frame, as does the crank's
    // ω arrow (Ng's Fig. A1), drawn 40 units about the crank centre with
    // its letter outside it; the velocity triangle's frame otherwise
    // stays tight, clear of the letters about it.
    let turning = scene.has(Layer::Motion) && !scene.has(Layer::Torque);
    let reach = if acceleration || turning {
        FRAME_REACH
    } else {
        0.0
    };
    // Kisch's H joins a crowd by it (its lines run to it from F, G and A).
    let by_crowd = h.filter(|_| scene.has(Layer::Kisch));
    let crowding = crowded(&lettered, by_crowd, reach, scale, max_width);
    if !readable {
        let near = neighbours(&core, &lettered, scale);
        let all = whole(&core, h, &near, core_extent, scale, max_width);
        // The whole construction enlarged may still leave a cluster of
        // points within [`CROWD`] of each other (a short rod whose
        // construction spans just under the target: C, A, D, E and F
        // within a few units); the detail is then drawn about those
        // points. Two points alone (F beside B) take their letters on
        // opposite sides.
        return match (all, crowding) {
            (Some(w), Crowding::Separable(d))
                if crowding_points(&lettered, CROWD / (w.magnification * scale)) >= CLUSTER
                    && d.magnification > w.magnification =>
            {
                Some(d)
            }
            (all, _) => all,
        };
    }
    match crowding {
        Crowding::Apart => None,
        // Points too close to separate (near a dead centre): the whole
        // construction enlarged, its letters set about it.
        Crowding::Together if acceleration => {
            let near = neighbours(&core, &lettered, scale);
            whole(&core, h, &near, core_extent, scale, max_width)
        }
        Crowding::Together => None,
        Crowding::Separable(d) => Some(d),
    }
}

/// The lettered points of `lettered` within [`CROWD`] page units of the
/// box of `core` in a main view at `scale`, outside it: the pins by a
/// short rod's construction (A and D by C) that would otherwise stand on
/// the frame of its detail, their letters cut off or pressed against the
/// construction's lines.
fn neighbours(core: &[Point], lettered: &[Point], scale: f64) -> Vec<Point> {
    let (lo, hi) = bounds(core);
    let off = |p: &Point| {
        let out = (lo - p).sup(&(p - hi)).sup(&Vector::zeros());
        out.norm() * scale
    };
    (lettered.iter())
        .filter(|p| {
            let d = off(p);
            d > 0.0 && d < CROWD
        })
        .copied()
        .collect()
}

/// The detail of the whole construction about the crank (B, C, E, F, G,
/// with Kisch's H where the core keeps [`CORE_TARGET`] with it, and the
/// lettered points `near` it, [`neighbours`]), whose core spans
/// `core_extent` page units in a main view at `scale`.
fn whole(
    core: &[Point],
    h: Option<Point>,
    near: &[Point],
    core_extent: f64,
    scale: f64,
    max_width: f64,
) -> Option<Detail> {
    let with_h = h.map(|h| [core, &[h]].concat());
    let fitted = |pts: &[Point]| {
        let (min, max) = bounds(&[pts, near].concat());
        let size = max - min;
        let extent = size.x.max(size.y) * scale;
        if !(extent > 0.0 && extent.is_finite()) {
            return None;
        }
        let wanted = (TARGET / extent).max(CORE_TARGET / core_extent);
        let magnification = magnify(wanted, size.x * scale, max_width)?;
        Some(Detail {
            region: Frame::new(min, max),
            magnification,
            focus: Focus::Construction,
        })
    };
    let enough = |d: &Detail| core_extent * d.magnification >= CORE_TARGET;
    match with_h.as_deref().and_then(fitted) {
        Some(d) if enough(&d) => Some(d),
        _ => fitted(core),
    }
}

/// Distance apart (page units) under which two lettered points crowd:
/// each letter, about 12 × 17 units set 4 units from its point, has no
/// side clear of the other point's letter and lines.
const CROWD: f64 = 30.0;
/// How far (main view's page units) the frame of a crowding detail of an
/// acceleration construction stands from the crowded points, its padding
/// ([`PAD`] of the detail's units) included: a pin's letter among them
/// (about 12 × 17 units, kept 4 from its point and within 1.5 em of it)
/// then fits on either side of the frame's line, inside beside its point
/// or outside within reach, rather than on the line (at ×2 the frame stood
/// 29 units off, where neither fits).
const FRAME_REACH: f64 = 20.0;
/// The most room (the detail's page units) the frame leaves about the
/// crowded points.
const ROOM_IN_DETAIL: f64 = 100.0;
/// How far apart crowded points are drawn in their detail, page units.
const APART: f64 = 45.0;
/// The most a crowding detail magnifies: points closer than
/// [`CROWD`] / this in the main view are taken as one (a dead centre,
/// where E meets C), which no detail separates.
const MOST_CROWDED: f64 = 16.0;
/// The largest side of a crowding detail's region in the detail, page
/// units: the crowded points and their near neighbours, not the
/// mechanism again.
const CROWD_EXTENT: f64 = 320.0;

/// The least number of lettered points crowding together (each within
/// [`CROWD`] of another) that the whole construction's detail leaves to a
/// detail of their own.
const CLUSTER: usize = 3;

/// How many of `pts` lie within `within` (world units) of another.
fn crowding_points(pts: &[Point], within: f64) -> usize {
    let near = |(i, a): (usize, &Point)| {
        pts.iter()
            .enumerate()
            .any(|(j, b)| j != i && (b - a).norm() < within)
    };
    pts.iter().enumerate().filter(|&p| near(p)).count()
}

/// The detail of the points of `lettered` (world) that crowd in a main
/// view at `scale`: the box of every point within [`CROWD`] page units
/// of another (those within [`CROWD`] / [`MOST_CROWDED`] are taken as
/// one, which the detail does not try to separate), or where no detail
/// about them all fits `max_width` (near a dead centre F and G crowd by
/// A, E by C, a rod's length away) the box of the largest cluster of them
/// ([`largest_cluster`]), and where no cluster holds [`CLUSTER`] points
/// the largest of those whose pairs lie within [`NEIGHBOURS`] of each
/// other; see [`about`]. Each takes in `h`, the point the construction
/// finds, where it stands by the crowd ([`with_h`]).
fn crowded(
    lettered: &[Point],
    h: Option<Point>,
    reach: f64,
    scale: f64,
    max_width: f64,
) -> Crowding {
    let pairs = crowding_pairs(lettered, scale);
    if pairs.is_empty() {
        return Crowding::Apart;
    }
    let of = clusters(lettered.len(), &pairs);
    let every = crowd_of(lettered, &pairs, &of, None);
    // The crowd with H where the detail holding it still sets the crowd
    // [`APART`] (at the inner dead centre of a rod of 1.03 cranks, A by
    // C, H took the detail down to ×6, where C's joint letter found no
    // room clear of Kisch's arc); else the crowd alone.
    let about = |m: &[Point], closest: f64| {
        let all = with_h(m, h, scale);
        let with = (all.len() > m.len())
            .then(|| about(&all, closest, reach, scale, max_width, true))
            .flatten()
            .filter(|d| closest * d.magnification >= APART);
        with.or_else(|| about(m, closest, reach, scale, max_width, false))
    };
    let detail = (every.and_then(|(m, closest)| about(&m, closest)))
        .or_else(|| {
            let c = largest_cluster(&pairs, &of)?;
            let (m, closest) = crowd_of(lettered, &pairs, &of, Some(c))?;
            about(&m, closest)
        })
        .or_else(|| {
            // No cluster is large enough: near a dead centre the pairs
            // stand apart (A by D, F on G, C by E), but the letters of two
            // of them within [`NEIGHBOURS`] share one room.
            let linked = clusters(lettered.len(), &within(lettered, NEIGHBOURS, scale));
            let c = largest_cluster(&pairs, &linked)?;
            let (m, closest) = crowd_of(lettered, &pairs, &linked, Some(c))?;
            about(&m, closest)
        });
    match detail {
        Some(d) => Crowding::Separable(d),
        None => Crowding::Together,
    }
}

/// `members`, crowding points in a main view at `scale`, with the point
/// the construction finds by them, `h` (Kisch's H), where it lies within
/// [`NEIGHBOURS`] page units of one of them: its letter shares the
/// crowd's room, and left out of the crowd's detail, whose lines run
/// towards it, it was lettered on the main view among the crowd's lines
/// and the detail's tag (H 33 units above F and G by A at a rod of 1.02
/// cranks, its letter, right-angle mark and "×8" jammed over the block).
fn with_h(members: &[Point], h: Option<Point>, scale: f64) -> Vec<Point> {
    let mut all = members.to_vec();
    if let Some(h) = h
        && !all.contains(&h)
        && (members.iter()).any(|m| (m - h).norm() * scale < NEIGHBOURS)
    {
        all.push(h);
    }
    all
}

/// The detail about the crowding points `members` whose closest pair a
/// detail separates stands `closest` page units apart in a main view at
/// `scale`: their box grown each way so that the frame drawn about it on
/// the main view stands `reach` page units off (0: the box itself,
/// padded), magnified until that pair is [`APART`], the box at most
/// [`CROWD_EXTENT`] (by the step at or under it where `bounded`: the
/// members hold the construction's point by the crowd, [`with_h`]), and
/// the detail within `max_width` (none if no step fits).
fn about(
    members: &[Point],
    closest: f64,
    reach: f64,
    scale: f64,
    max_width: f64,
    bounded: bool,
) -> Option<Detail> {
    let (lo, hi) = bounds(members);
    let size = (hi - lo) * scale;
    // With the construction's point by the crowd (`bounded`), the step
    // that sets the closest pair [`APART`], or where it would draw the
    // box over [`CROWD_EXTENT`] the largest step within it: rounded up,
    // the bound was a step over, and H and A at the inner dead centre of
    // a rod of 1.02 cranks stood 540 units apart.
    let apart = (APART / closest).max(1.0);
    let most = CROWD_EXTENT / size.max().max(1e-9);
    let wanted = match steps().find(|m| *m >= apart) {
        Some(m) if bounded && m > most => steps().rev().find(|m| *m <= most).unwrap_or(1.0),
        _ => apart.min(most),
    };
    let first = magnify(wanted.max(1.0), size.x, max_width)?;
    // The frame on the main view `reach` from the crowded points, its
    // padding included, so that the letters of the pins among them find
    // room on one side of it; no more than [`ROOM_IN_DETAIL`] of the
    // detail's units, so that a large magnification does not pad the
    // detail with empty paper.
    let room = (reach - PAD / first).clamp(0.0, ROOM_IN_DETAIL / first) / scale;
    let (lo, hi) = (lo - Vector::new(room, room), hi + Vector::new(room, room));
    let magnification = magnify(first, (hi.x - lo.x) * scale, max_width)?;
    Some(Detail {
        region: Frame::new(lo, hi),
        magnification,
        focus: Focus::Construction,
    })
}

/// The pairs of `pts` (by their places) that crowd in a main view at
/// `scale`: closer than [`CROWD`] page units and not at one point, each
/// with its distance on the page.
fn crowding_pairs(pts: &[Point], scale: f64) -> Vec<(usize, usize, f64)> {
    within(pts, CROWD, scale)
}

/// Distance apart (page units) within which two pairs of crowding points
/// near a dead centre share the room of their letters: a pair taken as
/// one (F on G) needs two letters' room beside it, about 2 × 16 units
/// with their gaps, which a pair one letter's room away (A by D, 30 units
/// off) takes too.
const NEIGHBOURS: f64 = 1.5 * CROWD;

/// The pairs of `pts` (by their places) closer than `apart` page units
/// in a main view at `scale` and not at one point, each with its
/// distance on the page.
fn within(pts: &[Point], apart: f64, scale: f64) -> Vec<(usize, usize, f64)> {
    let mut pairs = Vec::new();
    for (i, a) in pts.iter().enumerate() {
        for (j, b) in pts.iter().enumerate().skip(i + 1) {
            let d = (b - a).norm() * scale;
            if d > 0.0 && d < apart {
                pairs.push((i, j, d));
            }
        }
    }
    pairs
}

/// The cluster of each of `count` points that `pairs` join (a chain of
/// pairs joins two points), named by the least place in it.
fn clusters(count: usize, pairs: &[(usize, usize, f64)]) -> Vec<usize> {
    let mut of: Vec<usize> = (0..count).collect();
    // Each pair merges its two clusters whole.
    for &(i, j, _) in pairs {
        let (ci, cj) = (cluster(&of, i), cluster(&of, j));
        let (keep, gone) = (ci.min(cj), ci.max(cj));
        of.iter_mut()
            .filter(|k| **k == gone)
            .for_each(|k| *k = keep);
    }
    of
}

/// The cluster of point `i` in `of` ([`clusters`]).
fn cluster(of: &[usize], i: usize) -> usize {
    of.get(i).copied().unwrap_or(i)
}

/// The points of cluster `c` of `of` (every crowding point for `None`)
/// and the distance of its closest pair a detail separates (at least
/// [`CROWD`] / [`MOST_CROWDED`] apart: points closer are taken as one,
/// but their letters still need the detail's room); none where it has no
/// such pair.
fn crowd_of(
    pts: &[Point],
    pairs: &[(usize, usize, f64)],
    of: &[usize],
    c: Option<usize>,
) -> Option<(Vec<Point>, f64)> {
    let mine = |i: usize| c.is_none_or(|c| cluster(of, i) == c);
    let closest = (pairs.iter())
        .filter(|&&(i, _, d)| mine(i) && d >= CROWD / MOST_CROWDED)
        .map(|&(_, _, d)| d)
        .reduce(f64::min)?;
    let crowding = |i: usize| pairs.iter().any(|&(a, b, _)| a == i || b == i);
    let members = (pts.iter().enumerate())
        .filter(|&(i, _)| mine(i) && crowding(i))
        .map(|(_, p)| *p)
        .collect();
    Some((members, closest))
}

/// The cluster of `of` with the most points, at least [`CLUSTER`], among
/// those a detail separates something in, the first on a tie: one
/// detail about the points that crowd most (A, D, F and G by the block
/// near a dead centre) rather than none. None where there is none.
fn largest_cluster(pairs: &[(usize, usize, f64)], of: &[usize]) -> Option<usize> {
    let size = |c: usize| of.iter().filter(|&&k| k == c).count();
    (pairs.iter())
        .filter(|&&(_, _, d)| d >= CROWD / MOST_CROWDED)
        .map(|&(i, _, _)| cluster(of, i))
        .filter(|&c| size(c) >= CLUSTER)
        .fold(None, |best: Option<usize>, c| match best {
            Some(b) if size(b) >= size(c) => Some(b),
            _ => Some(c),
        })
}

/// How the lettered points of a construction lie in the main view.
enum Crowding {
    /// No two within [`CROWD`] page units.
    Apart,
    /// Some crowd, and this detail separates them.
    Separable(Detail),
    /// Some lie closer than any detail separates (and none that one
    /// would).
    Together,
}

/// The first magnification step of at least `wanted` at which a region
/// `width` page units wide in the main view fits `max_width` with its
/// padding, else the largest step that fits (none if none does).
fn magnify(wanted: f64, width: f64, max_width: f64) -> Option<f64> {
    let fits = |m: f64| width * m + 2.0 * PAD <= max_width;
    steps()
        .find(|m| *m >= wanted)
        .filter(|m| fits(*m))
        .or_else(|| steps().rev().find(|m| fits(*m)))
}

/// The detail of the crank a torque figure drawn at `scale` needs, if
/// any (its crank radius under [`CRANK_THRESHOLD`] page units): the crank
/// circle and M, enlarged to [`CRANK_TARGET`] or as near as `max_width`
/// allows. A figure marking the crank's angles without a torque has the
/// crank circle alone, under [`ANGLES_THRESHOLD`], enlarged to
/// [`ANGLES_TARGET`]. None for a figure marking neither.
fn crank(ctx: &LayerCtx, scale: f64, max_width: f64) -> Option<Detail> {
    let torque = ctx.scene.has(Layer::Torque);
    let (threshold, target) = if torque {
        (CRANK_THRESHOLD, CRANK_TARGET)
    } else if ctx.scene.has(Layer::Angles) {
        (ANGLES_THRESHOLD, ANGLES_TARGET)
    } else if ctx.scene.has(Layer::Polygons) {
        (POLYGONS_THRESHOLD, ANGLES_TARGET)
    } else {
        return None;
    };
    let pose = ctx.main.pose();
    let r = pose.mechanism().crank();
    let radius = r * scale;
    if !(radius > 0.0 && radius < threshold) {
        return None;
    }
    let c = pose.c();
    let mut pts = vec![c - Vector::new(r, r), c + Vector::new(r, r)];
    if torque {
        pts.push(ctx.main.e().e());
    }
    let (lo, hi) = bounds(&pts);
    let magnification = magnify(target / radius, (hi.x - lo.x) * scale, max_width)?;
    Some(Detail {
        region: Frame::new(lo, hi),
        magnification,
        focus: Focus::Crank,
    })
}

/// The larger side, page units, under which a subject a diagram draws
/// on the mechanism ([`crate::scene::Scene::with_detail_subject`]) gets
/// a detail that holds it whole: Fig. 64's polar diagram, about the crank
/// circle, whose loops a long rod's main view draws a few units across.
const SUBJECT_THRESHOLD: f64 = 90.0;
/// The least larger side of the subject in its detail, page units.
const SUBJECT_TARGET: f64 = 220.0;

/// The detail of the subject a diagram draws on the mechanism, where the
/// main view draws it under [`SUBJECT_THRESHOLD`]: its frame whole,
/// enlarged to [`SUBJECT_TARGET`] or as near as `max_width` allows
/// (`Some(None)` where no step fits); `None` where the scene names no
/// subject or draws it large enough, the construction's own detail rule
/// then applying.
fn subject(ctx: &LayerCtx, scale: f64, max_width: f64) -> Option<Option<Detail>> {
    let frame = ctx.scene.subject()?;
    let size = frame.max() - frame.min();
    let side = size.x.max(size.y) * scale;
    if !(side > 0.0 && side < SUBJECT_THRESHOLD) {
        return None;
    }
    let magnification = magnify(SUBJECT_TARGET / side, size.x * scale, max_width);
    Some(magnification.map(|magnification| Detail {
        region: *frame,
        magnification,
        focus: Focus::Construction,
    }))
}

/// How close (page units) the piston pin P comes to the crank centre O
/// before O's letter has no room between P's pin and the torque arrow
/// about O: a letter about 12 units wide with its gap of 4 each side of
/// it and P's pin (4.2). At l = 1.2 r they stand 29 apart at the inner
/// dead centre, and the letters fit; at 1.1 r, 15.
const PINS_CROWD: f64 = 24.0;

/// How close (page units) the piston pin A comes to the crank centre C
/// in a figure marking the crank's angles without a torque (Fig. 62), or
/// its ω alone (the polygons' figure), before their letters, 17 units
/// tall, cannot be told apart: two ems. Near the inner dead centre of a
/// rod of 1.1 cranks or less they stand a few units apart, A's letter
/// beside C's pin (the polygons' figure at l = 1.06 r, 180°: the two pins
/// overlapping inside the block, C's bearing drawn through it).
const PINS_TWO_EMS: f64 = 34.0;

/// The detail of a torque figure whose crank the main view draws large
/// enough (a short rod) where its pins crowd: near the inner dead centre
/// of a rod of 1.1 cranks or less the piston pin P comes within
/// [`PINS_CROWD`] of the crank centre O, whose torque arrow, the torque line's
/// foot M and their letters leave O's letter no room. Drawn about them,
/// it carries the marks about the crank as a crank's detail does (M
/// lies by O at every dead centre: a longer rod's O and M share the
/// torque arrow's room without one). A figure marking the crank's angles
/// or the polygons' ω gets one where A comes within [`PINS_TWO_EMS`] of C.
/// None for a figure marking none of these, or where the pins stand
/// apart.
fn crowded_crank(ctx: &LayerCtx, scale: f64, max_width: f64) -> Option<Detail> {
    let crowd = if ctx.scene.has(Layer::Torque) {
        PINS_CROWD
    } else if ctx.scene.has(Layer::Angles) || ctx.scene.has(Layer::Polygons) {
        PINS_TWO_EMS
    } else {
        return None;
    };
    let pose = ctx.main.pose();
    if (pose.a() - pose.c()).norm() * scale >= crowd {
        return None;
    }
    let pins = [pose.a(), pose.b(), pose.c()];
    match crowded(&pins, None, FRAME_REACH, scale, max_width) {
        Crowding::Separable(d) => Some(Detail {
            focus: Focus::Crank,
            ..d
        }),
        Crowding::Apart | Crowding::Together => None,
    }
}

/// One detail for the poses of a held view, whose `details` are those
/// each pose needs: the union of their regions at the least of their
/// magnifications, lowered to a step that fits `max_width` page units at
/// `scale` (none when not even the least step fits; none when no pose
/// needs one).
pub(crate) fn union(details: &[Detail], scale: f64, max_width: f64) -> Option<Detail> {
    let first = details.first()?;
    let (mut lo, mut hi) = (first.region.min(), first.region.max());
    let mut least = first.magnification;
    for d in details.iter().skip(1) {
        lo = lo.inf(&d.region.min());
        hi = hi.sup(&d.region.max());
        least = least.min(d.magnification);
    }
    let width = (hi.x - lo.x) * scale;
    let fits = |m: f64| width * m + 2.0 * PAD <= max_width;
    let magnification = if fits(least) {
        least
    } else {
        steps().rev().find(|m| *m <= least && fits(*m))?
    };
    Some(Detail {
        region: Frame::new(lo, hi),
        magnification,
        focus: first.focus,
    })
}
