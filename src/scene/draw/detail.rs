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
//! helps nobody).
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

use super::LayerCtx;
use crate::geom::{Frame, Point, Vector};
use crate::scene::Layer;

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
    let scene = ctx.scene;
    let acceleration = scene.has(Layer::Klein) || scene.has(Layer::Kisch);
    let velocity = scene.has(Layer::Velocity);
    if !scene.has(Layer::Mechanism) {
        return None;
    }
    if !(acceleration || velocity) {
        return crank(ctx, scale, max_width);
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
    // rod) need their letters' room inside the frame; the velocity
    // triangle's frame stays tight, clear of the letters about it.
    let room = if acceleration { CROWD_ROOM } else { 0.0 };
    let crowding = crowded(&lettered, room, scale, max_width);
    if !readable {
        let all = whole(&core, h, core_extent, scale, max_width);
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
        Crowding::Together if acceleration => whole(&core, h, core_extent, scale, max_width),
        Crowding::Together => None,
        Crowding::Separable(d) => Some(d),
    }
}

/// The detail of the whole construction about the crank (B, C, E, F, G,
/// with Kisch's H where the core keeps [`CORE_TARGET`] with it), whose
/// core spans `core_extent` page units in a main view at `scale`.
fn whole(
    core: &[Point],
    h: Option<Point>,
    core_extent: f64,
    scale: f64,
    max_width: f64,
) -> Option<Detail> {
    let with_h = h.map(|h| [core, &[h]].concat());
    let fitted = |pts: &[Point]| {
        let (min, max) = bounds(pts);
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
/// Room (main view's page units) between the crowded points and their
/// detail's region, so that its frame on the main view leaves the pins'
/// letters room.
const CROWD_ROOM: f64 = 12.0;
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
/// one, which the detail does not try to separate) grown by `room` page
/// units each way, magnified until the closest such pair is [`APART`], the box
/// at most [`CROWD_EXTENT`], and the detail within `max_width`.
fn crowded(lettered: &[Point], room: f64, scale: f64, max_width: f64) -> Crowding {
    let mut members: Vec<Point> = Vec::new();
    let mut closest = f64::INFINITY;
    let mut together = false;
    for (i, a) in lettered.iter().enumerate() {
        for b in lettered.iter().skip(i + 1) {
            let d = (b - a).norm() * scale;
            if (CROWD / MOST_CROWDED..CROWD).contains(&d) {
                members.extend([*a, *b]);
                closest = closest.min(d);
            } else if d > 0.0 && d < CROWD / MOST_CROWDED {
                // Their letters still need the detail's room.
                members.extend([*a, *b]);
                together = true;
            }
        }
    }
    if !closest.is_finite() {
        return match together {
            true => Crowding::Together,
            false => Crowding::Apart,
        };
    }
    let (lo, hi) = bounds(&members);
    let size = (hi - lo) * scale;
    let wanted = (APART / closest).min(CROWD_EXTENT / size.max().max(1e-9));
    let Some(first) = magnify(wanted.max(1.0), size.x, max_width) else {
        return Crowding::Together;
    };
    // The frame on the main view kept clear of the crowded points, so
    // that the letters of the pins among them find room inside it; no
    // more than [`ROOM_IN_DETAIL`] of the detail's units, so that a large
    // magnification does not pad the detail with empty paper.
    let room = room.min(ROOM_IN_DETAIL / first) / scale;
    let (lo, hi) = (lo - Vector::new(room, room), hi + Vector::new(room, room));
    match magnify(first, (hi.x - lo.x) * scale, max_width) {
        Some(magnification) => Crowding::Separable(Detail {
            region: Frame::new(lo, hi),
            magnification,
            focus: Focus::Construction,
        }),
        None => Crowding::Together,
    }
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
