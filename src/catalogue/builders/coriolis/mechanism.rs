//! The mechanism panel of a Coriolis figure: the chain in the fixed
//! link's frame, its pins lettered and the driver's ω, with an enlarged
//! detail of the crank where it is drawn too short to read.

use super::super::Ctx;
use super::super::inversions::{Shown, crank_window, slot_half_width, window_at};
use super::panel::mark_window;
use super::{FINE_STEPS, GAP, MARGIN, MECHANISM_HEIGHT, round_below};

use crate::chain::{Inversion, InversionPose};
use crate::diagram::Plot;
use crate::error::Result;
use crate::figure::{Foot, Item, RichText, Role, Shape, TextSize};
use crate::geom::{Frame, Point, Vector, unit};
use crate::scene::{Canvas, Marker};

/// The page length under which inversion 3's crank CB, the driver, gets
/// an enlarged detail beside the mechanism panel: at a long rod (a rod of
/// fifty cranks) its pins touch, the crank hides in B's bearing and its ω
/// finds no room.
pub(super) const CRANK_LEAST: f64 = 40.0;

/// The page length under which inversion 2's crank CB, the fixed link,
/// gets the same detail: drawn whole by its bearings it reads down to
/// here (its pins, 4.2 units in radius, a few units of link between;
/// the default engine, a rod of three cranks, draws it 39 units), but at
/// a rod of thirty cranks it is four units long, C's and B's pins touch,
/// link a is not to be seen and B's letter may stand on the wrong side
/// of C's. A detail beside a mechanism it need not enlarge takes the
/// room of it (a rod of six cranks on a page 120 mm wide).
pub(super) const FIXED_CRANK_LEAST: f64 = 15.0;

/// The page distance under which the block's pin A and the crank centre
/// C crowd: at a short rod's inner dead centre (l = 1.09 r, 180° in
/// inversion 2, 10 units apart; 1.02 r in inversion 3, 2.4) A, C and the
/// block's c stood on one another, the block's outline round both pins.
/// Two diameters of a pin (4.2 units in radius): at two em (34 units, as
/// the inversions' figures' crowded pins) the plate sweep found the
/// detail's block drawn through C's letter (l = 1.05 r to 1.1 r, 120° to
/// 150°), where the pins read on the mechanism.
pub(super) const PINS_APART: f64 = 17.0;

/// How far apart crowded pins C and A are drawn in their detail, page
/// units, at most (the magnification is rounded down).
pub(super) const PINS_SPREAD: f64 = 64.0;

/// The angle (degrees) between the crank CB and the line CA within which
/// the chain lies along the line of stroke at its inner dead centre, A
/// by C inside the block and their letters stacked; with the pins
/// crowded there, the mechanism takes their detail. Farther from it
/// (l = 1.08 r at 160° and 200°, 20°) the detail, its block enlarged
/// across both pins, drew the block through C's letter.
const FOLDED: f64 = 15.0;

/// The least page length of the crank on a mechanism drawn beside the
/// crowded pins' detail: shorter, the detail goes below the mechanism,
/// drawn across the page (inversion 3 at l = 1.09 r, 180° on a page 120
/// mm wide set B, ω, a and b within a few units of one another on a
/// mechanism drawn beside the detail).
const BESIDE_CRANK: f64 = 60.0;

/// The most of the pins' detail's height the slotted bar d (as wide as
/// the block) may take: enlarged further, the bar and the block filled
/// the detail (inversion 3 at l = 1.02 r, 180°: ×25, a grey field with
/// C and A inside it and c's letter at its far corner), and the
/// magnification is held to this.
const BAR_SHARE: f64 = 0.3;

/// The mechanism panel: the chain at the pose in the fixed link's frame,
/// its pins lettered C, B, A and the driver's sense of turning; where
/// inversion 3's crank is drawn shorter than [`CRANK_LEAST`] (inversion
/// 2's than [`FIXED_CRANK_LEAST`]), a detail of the region about it
/// beside the panel (boxed there), which carries ω and letters the pins
/// inside the box; where the crank reads but C and A stand nearer than
/// [`PINS_APART`] (a short rod at the inner dead centre), the same
/// detail about them, spread to [`PINS_SPREAD`], lettering C, A and the
/// block there (below the mechanism where beside it the crank would be
/// drawn shorter than [`BESIDE_CRANK`]).
pub(super) fn mechanism_plot(ctx: &Ctx, pose: &InversionPose) -> Result<(Plot, Option<Plot>)> {
    let m = ctx.mechanism;
    let frame = super::super::inversions::links_frame(&m, pose);
    let size = frame.max() - frame.min();
    let pad = 0.06 * size.x.max(size.y);
    let world = Frame::new(
        frame.min() - Vector::new(pad, pad),
        frame.max() + Vector::new(pad, pad),
    );
    let width = ctx.page().width() - 2.0 * MARGIN;
    let seen = world.max() - world.min();
    let least = match pose.inversion() {
        Inversion::Rod => CRANK_LEAST,
        _ => FIXED_CRANK_LEAST,
    };
    let engine = pose.engine_pose();
    let (c, a) = (pose.place(engine.c()), pose.place(engine.a()));
    let b = pose.place(engine.b());
    let folded = unit(b - c)
        .zip(unit(a - c))
        .is_some_and(|(u, v)| u.dot(&v).abs() > FOLDED.to_radians().cos());
    // Whether a plot at `scale` needs no detail: its crank long enough
    // and its pins C and A not crowded at the inner dead centre.
    let crowded =
        |scale: f64| m.crank() * scale >= least && (a - c).norm() * scale < PINS_APART && folded;
    let clear = |scale: f64| m.crank() * scale >= least && !crowded(scale);
    let panel =
        |tall: f64| Frame::from_origin_size(MARGIN, MARGIN, width, tall + crate::diagram::CAPTION);
    if let Some(tall) = taller(width, seen, m.crank()) {
        let whole = Plot::world(
            "mechanism",
            panel(tall),
            &world,
            false,
            ctx.tolerance,
            ctx.font,
        )?;
        if clear(whole.map().scale()) {
            return Ok((links_plot(ctx, pose, whole, (None, false), None)?.0, None));
        }
    }
    let tall = (width * seen.y / seen.x).clamp(MECHANISM_HEIGHT.0, MECHANISM_HEIGHT.1);
    let rect = panel(tall);
    let whole = Plot::world("mechanism", rect, &world, false, ctx.tolerance, ctx.font)?;
    let scale = whole.map().scale();
    if clear(scale) {
        return Ok((links_plot(ctx, pose, whole, (None, false), None)?.0, None));
    }
    let crowded = crowded(scale);
    let side = tall;
    let main = Frame::from_origin_size(MARGIN, MARGIN, width - side - GAP, rect.height());
    let beside = Plot::world("mechanism", main, &world, false, ctx.tolerance, ctx.font)?;
    let (plot, detail_rect) = if crowded && m.crank() * beside.map().scale() < BESIDE_CRANK {
        let x = MARGIN + 0.5 * (width - side);
        (
            whole,
            Frame::from_origin_size(x, MARGIN + rect.height() + GAP, side, rect.height()),
        )
    } else {
        (
            beside,
            Frame::from_origin_size(MARGIN + width - side, MARGIN, side, rect.height()),
        )
    };
    let scale = plot.map().scale();
    let pins = (a - c).norm() * scale;
    // `panel-detail-mechanism`: a crank's detail, read as the plate check
    // reads every mechanism's detail (`panel-detail…`, its ids `detail-…`).
    let (region, detail) = match crowded {
        false => crank_window(ctx, "detail-mechanism", b, detail_rect, scale)?,
        // l > r keeps C and A apart: `pins` is not zero.
        true => pins_window(
            ctx,
            c + (a - c) * 0.5,
            PINS_SPREAD / pins,
            detail_rect,
            scale,
        )?,
    };
    // The detail stands the bearings of its pins on the sides the whole
    // mechanism does: one rule for both views.
    let (plot, shown) = links_plot(ctx, pose, plot, (Some(region), crowded), None)?;
    let follow = Some(shown.about(region));
    let (detail, _) = links_plot(ctx, pose, detail, (Some(region), crowded), follow)?;
    Ok((plot, Some(detail)))
}

/// A taller mechanism panel's height (its caption apart) for a world of
/// size `seen` drawn `width` page units wide, where at its usual height
/// (its width's share by the world's shape within [`MECHANISM_HEIGHT`])
/// the crank of length `crank` would be drawn shorter than
/// [`CRANK_ROOM`]: the height that draws it so, or as near as the
/// world's shape and [`MECHANISM_TALLEST`] allow (the driven pin's
/// circle about B sized a square world, the pins, the links' and d's
/// letters and ω crowded round a crank of 39 units: inversion 2 at
/// l = 2.84 r, e = -1.38 r, 270.23°). None where that is no taller, or
/// for a world with no height or width. The caller keeps it only where
/// the mechanism then needs no detail: a long rod's crank, which no
/// height makes readable, is left to its detail at the usual height.
fn taller(width: f64, seen: Vector, crank: f64) -> Option<f64> {
    let shaped = width * seen.y / seen.x;
    if !(shaped.is_finite() && seen.y > 0.0) {
        return None;
    }
    let usual = shaped.clamp(MECHANISM_HEIGHT.0, MECHANISM_HEIGHT.1);
    let room = (CRANK_ROOM * seen.y / crank)
        .min(MECHANISM_TALLEST)
        .min(shaped);
    (room > usual).then_some(room)
}

/// The page length the crank is given room for on the mechanism panel,
/// by a taller panel ([`mechanism_height`]).
const CRANK_ROOM: f64 = 60.0;

/// The most height the mechanism panel takes to give its crank
/// [`CRANK_ROOM`], page units.
const MECHANISM_TALLEST: f64 = 420.0;

/// The detail of the crowded pins C and A in `rect` (its caption
/// included), for a main view at `scale` page units per world unit: the
/// world region about `centre` it shows at the round magnification below
/// `wanted` (at least 1; lower where the slotted bar would take more than
/// [`BAR_SHARE`] of its height), and its plot, captioned with the magnification
/// and framed, its panel `panel-detail-mechanism`.
fn pins_window(
    ctx: &Ctx,
    centre: Point,
    wanted: f64,
    rect: Frame,
    scale: f64,
) -> Result<(Frame, Plot)> {
    let h = rect.height() - crate::diagram::CAPTION;
    let m = ctx.mechanism;
    let mut magnification = round_below(wanted, &FINE_STEPS).max(1.0);
    // The bar's width at a magnification: its world half width (the
    // block's, at least a few units on the page) times two, enlarged.
    let bar = |k: f64| 2.0 * slot_half_width(&m, k * scale) * k * scale;
    while magnification > 1.0 && bar(magnification) > BAR_SHARE * h {
        magnification = round_below(magnification * (1.0 - 1e-9), &FINE_STEPS).max(1.0);
    }
    window_at(
        ctx,
        "detail-mechanism",
        (centre, magnification),
        rect,
        scale,
    )
}

/// The chain drawn on `plot`: its links, pins C, B, A lettered where on
/// the panel, the driver's ω; on the whole mechanism (named `mechanism`)
/// the caption and, where a detail enlarges `region`, its box; with how
/// it showed the fixed bar, which a view drawn after it follows where
/// `follow` says so ([`Shown`]). Where the detail is the crowded pins'
/// (`pins`), the whole mechanism of inversion 2 still letters its fixed
/// pin C by its place in the box, its pin left to the detail.
pub(super) fn links_plot(
    ctx: &Ctx,
    pose: &InversionPose,
    plot: Plot,
    (region, pins): (Option<Frame>, bool),
    follow: Option<Shown>,
) -> Result<(Plot, Shown)> {
    let m = ctx.mechanism;
    let whole = plot.panel_id() == "panel-mechanism";
    let inversion = pose.inversion();
    let mut plot = if whole {
        plot.with_caption(&format!(
            "Inversion {}, {}: the relative-velocity method with the Coriolis component",
            inversion.number(),
            match inversion {
                Inversion::Rod => "the crank and slotted lever",
                _ => "Whitworth’s quick return",
            }
        ))
    } else {
        plot
    };
    let map = *plot.map();
    let mut canvas = Canvas::new(map, map.world_frame(&plot.area()));
    if !whole {
        canvas = canvas.detail("detail-");
    }
    let drawn = super::super::inversions::draw_links(m, pose, canvas, follow);
    let shown = drawn.shown;
    let mut s = drawn.canvas;
    let engine = pose.engine_pose();
    let (c, b, a) = (
        pose.place(engine.c()),
        pose.place(engine.b()),
        pose.place(engine.a()),
    );
    // The whole mechanism leaves the pins inside the region a detail
    // enlarges to it: their letters, among pins a few units apart, would
    // stand by the wrong pin (B's left of C's at l = 35 r, 180°).
    let held = |at| whole && region.is_some_and(|r: Frame| r.contains(at));
    for (key, at) in [("C", c), ("B", b), ("A", a)] {
        if key == "C" && pins && held(at) && inversion != Inversion::Rod {
            // The crowded pins' detail: C, the fixed pin whose bearing the
            // whole mechanism draws, is lettered there too (its letter
            // only in the detail, the reader found no C on the mechanism:
            // inversion 2 at l = 1.1 r, 180°), its letter across the bar
            // from the block's, its pin left to the detail (drawn here,
            // it stood in the block, drawn at its least size about A).
            // Inversion 3's C, a moving pin, is left to the detail with A:
            // lettered here it stood by the block's letter, "C c" read as
            // one label (l = 1.05 r, 180°).
            let across = unit(a - c).map_or(Vector::new(0.0, 1.0), |u| Vector::new(-u.y, u.x));
            let way = match drawn.a_way {
                Some(way) => way,
                None if across.y < 0.0 => -across,
                None => across,
            };
            s.label_toward("label-C", at, way, RichText::parse("*C*"), TextSize::Letter);
            continue;
        }
        if (whole || s.contains(at)) && !held(at) {
            match drawn.a_way.filter(|_| key == "A") {
                // Across the bar from the block's letter ("A c" read as
                // one label).
                Some(way) => {
                    s.push(
                        format!("point-{key}"),
                        Role::Link,
                        Shape::Pin { centre: at },
                    );
                    let text = RichText::parse(&format!("*{key}*"));
                    s.label_toward(format!("label-{key}"), at, way, text, TextSize::Letter);
                }
                None => s.lettered(key, at, &format!("*{key}*"), Marker::Pin, c),
            }
        }
    }
    let em = ctx.style.font_size(TextSize::Letter);
    driver_turn(&mut s, pose, (ctx.omega, em), drawn.b_foot);
    if let (true, Some(region)) = (whole, region) {
        mark_window(&mut s, "mechanism", &region);
    }
    let scale = s.transform().scale();
    let mut items = s.finish().0;
    if let (true, Some(region)) = (whole, region) {
        bar_letter_out_of(&mut items, pose, (scale, em), &region);
    }
    if whole {
        rod_letter_out_of_bar(&mut items, pose, (scale, em), region);
    }
    for item in items {
        plot.push(item);
    }
    Ok((plot, shown))
}

/// The longest run of `(from, to)` (along a bar, page units from its
/// start) clear of every `taken` stretch; `None` where none is longer
/// than nothing.
fn longest_clear_run(taken: &[(f64, f64)], (from, to): (f64, f64)) -> Option<(f64, f64)> {
    let mut cuts: Vec<f64> = vec![from, to];
    cuts.extend(taken.iter().flat_map(|(lo, hi)| [*lo, *hi]));
    let mut cuts: Vec<f64> = cuts.into_iter().map(|x| x.clamp(from, to)).collect();
    cuts.sort_by(f64::total_cmp);
    let free = |x: f64| taken.iter().all(|(lo, hi)| x < *lo || x > *hi);
    (cuts.iter().copied())
        .zip(cuts.iter().copied().skip(1))
        .filter(|(lo, hi)| hi > lo && free(0.5 * (lo + hi)))
        .max_by(|x, y| (x.1 - x.0).total_cmp(&(y.1 - y.0)))
}

/// The slotted bar d on the page: `t`, where its middle line meets the
/// line through C square to the stroke (the engine's T), the pins `a`
/// (A, the block's) and `b` (B), its direction `u` from T to A and
/// `across` it. `None` where A stands at T (no direction).
struct Bar {
    t: Point,
    a: Point,
    b: Point,
    u: Vector,
    across: Vector,
}

impl Bar {
    fn of(pose: &InversionPose) -> Option<Bar> {
        let engine = pose.engine_pose();
        let t = pose.place(Point::new(0.0, engine.mechanism().offset()));
        let (a, b) = (pose.place(engine.a()), pose.place(engine.b()));
        let u = unit(a - t)?;
        Some(Bar {
            t,
            a,
            b,
            u,
            across: Vector::new(-u.y, u.x),
        })
    }
}

/// The slotted bar d's letter, on the whole mechanism, moved out of the
/// `region` its detail enlarges where it was set inside it (among
/// `items`, drawn at `scale` page units per world unit, its letters an
/// `em` of page units): there it stood
/// by the crank's middle, the fixed link a few units long in its box,
/// beside the pivot C and its ground, past the bar's end, and read as
/// naming them, the bar named by b alone (inversion 2 at l = 26.4 r,
/// 180°). It goes by the bar's edge on the side it was set on, in the
/// middle of the longest run of the bar from C to A clear of the region
/// and of the block (an em each way) and of the rod's middle, where b's
/// letter stands (an em and a half each way); left where no run is.
fn bar_letter_out_of(
    items: &mut [Item],
    pose: &InversionPose,
    (scale, em): (f64, f64),
    region: &Frame,
) {
    let letter = (items.iter()).find_map(|i| match (&i.id[..], &i.shape) {
        ("label-link-d", Shape::Label { anchor, toward, .. }) => Some((*anchor, *toward)),
        _ => None,
    });
    let Some((_, toward)) = letter.filter(|(at, _)| region.contains(*at)) else {
        return;
    };
    let Some(Bar { t, a, b, u, across }) = Bar::of(pose) else {
        return;
    };
    let way = toward.and_then(unit).map_or(across, |w| {
        if w.dot(&across) < 0.0 {
            -across
        } else {
            across
        }
    });
    let em = em / scale;
    let along = |p: Point| (p - t).dot(&u);
    let end = along(a);
    let mut taken = Vec::new();
    if let Some((p, q)) = region.clip_segment(t, a) {
        let (x, y) = (along(p), along(q));
        taken.push((x.min(y) - em, x.max(y) + em));
    }
    let block = (items.iter()).find_map(|i| match (&i.id[..], &i.shape) {
        ("block-slider", Shape::Block { points }) => Some(points.clone()),
        _ => None,
    });
    let (lo, hi) = block
        .unwrap_or_default()
        .iter()
        .map(|p| along(*p))
        .fold((end, end), |(lo, hi), x| (lo.min(x), hi.max(x)));
    taken.push((lo - em, hi + em));
    let rod = along(Point::from((a.coords + b.coords) * 0.5));
    taken.push((rod - 1.5 * em, rod + 1.5 * em));
    let Some((lo, hi)) = longest_clear_run(&taken, (0.0, end)) else {
        return;
    };
    let half = super::super::inversions::slot_half_width(pose.engine_pose().mechanism(), scale);
    let at = t + u * (0.5 * (lo + hi)) + way * half;
    let item = items.iter_mut().find(|i| i.id == "label-link-d");
    if let Some(Shape::Label { anchor, toward, .. }) = item.map(|i| &mut i.shape) {
        *anchor = at;
        *toward = Some(way);
    }
}

/// The rod b's letter, on the whole mechanism, where the rod lies inside
/// the slotted bar d (both its pins within the bar's half width of its
/// middle line: a long rod near 90° or 270° in inversion 2): anchored on
/// the rod, the letter was set inside d's outline, in its tone, beside
/// d's own letter across the bar's edge ("d b" read as one label at the
/// tail of ω's arrow, inversion 2 at l = 29.5 r, 90.08°). It goes by the
/// bar's edge on the side away from d's letter, in the middle of the
/// longest run of the rod clear (an em each way) of its pins, of the
/// `region` a detail enlarges, of the block and of ω's arc and letter;
/// left where no run is. Among `items`, drawn at `scale` page units per
/// world unit, its letters an `em` of page units.
fn rod_letter_out_of_bar(
    items: &mut [Item],
    pose: &InversionPose,
    (scale, em): (f64, f64),
    region: Option<Frame>,
) {
    let Some(Bar { t, a, b, u, across }) = Bar::of(pose) else {
        return;
    };
    let half = super::super::inversions::slot_half_width(pose.engine_pose().mechanism(), scale);
    let along = |p: Point| (p - t).dot(&u);
    let off = |p: Point| (p - t).dot(&across);
    if off(b).abs() > half || along(b) < -half {
        return;
    }
    let label = |id: &str| {
        (items.iter()).find_map(|i| match (&i.id[..], &i.shape) {
            (x, Shape::Label { anchor, toward, .. }) if x == id => Some((*anchor, *toward)),
            _ => None,
        })
    };
    if label("label-link-b").is_none() {
        return;
    }
    // Away from d's letter: the side its anchor (set by the bar's edge)
    // or the way it is tried first stands on.
    let d_side = label("label-link-d").map(|(at, toward)| {
        let side = off(at);
        if side.abs() > 1e-9 * half.max(1e-300) {
            side.signum()
        } else {
            toward.map_or(1.0, |w| w.dot(&across).signum())
        }
    });
    let way = across * -d_side.unwrap_or(1.0);
    let em = em / scale;
    let (lo_end, hi_end) = (along(b).min(along(a)), along(b).max(along(a)));
    let mut taken: Vec<(f64, f64)> = [a, b]
        .iter()
        .map(|p| (along(*p) - em, along(*p) + em))
        .collect();
    let mut span = |points: &[Point], reach: f64| {
        let near: Vec<f64> = (points.iter())
            .filter(|p| {
                (off(**p) - way.dot(&across) * half).abs() <= reach || off(**p).abs() <= half
            })
            .map(|p| along(*p))
            .collect();
        if let (Some(lo), Some(hi)) = (
            near.iter().copied().reduce(f64::min),
            near.iter().copied().reduce(f64::max),
        ) {
            taken.push((lo - em, hi + em));
        }
    };
    if let Some(r) = region {
        let (p, q) = (r.min(), r.max());
        let corners = [p, Point::new(p.x, q.y), q, Point::new(q.x, p.y)];
        span(&corners, f64::INFINITY);
    }
    for item in items.iter() {
        match (&item.id[..], &item.shape) {
            ("block-slider", Shape::Block { points }) => span(points, f64::INFINITY),
            (
                "arc-omega",
                Shape::Arc {
                    centre,
                    radius,
                    start,
                    sweep,
                    ..
                },
            ) => {
                let points: Vec<Point> = (0..=16)
                    .map(|k| start + sweep * (k as f64 / 16.0))
                    .map(|g| centre + Vector::new(g.cos(), g.sin()) * *radius)
                    .collect();
                span(&points, 2.0 * em);
            }
            ("label-omega", Shape::Label { anchor, .. }) => span(&[*anchor], 2.0 * em),
            _ => {}
        }
    }
    let Some((lo, hi)) = longest_clear_run(&taken, (lo_end, hi_end)) else {
        return;
    };
    let at = t + u * (0.5 * (lo + hi)) + way * half;
    let item = items.iter_mut().find(|i| i.id == "label-link-b");
    if let Some(Shape::Label {
        anchor,
        toward,
        line,
        ..
    }) = item.map(|i| &mut i.shape)
    {
        *anchor = at;
        *toward = Some(way);
        *line = None;
    }
}

/// The driver's sense of turning: an arrowed arc about its fixed pin
/// (the crank about B in inversion 3, the rod about B in inversion 2),
/// lettered ω beyond the arc's middle, clear of its head by a share of
/// the letters' `em` (page units).
pub(super) fn driver_turn(
    s: &mut Canvas,
    pose: &InversionPose,
    (omega, em): (f64, f64),
    b_foot: Option<Foot>,
) {
    let engine = pose.engine_pose();
    let b = pose.place(engine.b());
    let tip = match pose.inversion() {
        Inversion::Rod => pose.place(engine.c()),
        _ => pose.place(engine.a()),
    };
    let arm = tip - b;
    let radius = s.world(26.0).min(0.45 * arm.norm());
    if s.page(radius) < 10.0 {
        return;
    }
    let heading = arm.y.atan2(arm.x);
    let sign = omega.signum();
    // At its radius, else wider (round d's corner, where B lies inside
    // d's leg and the room between the links at B holds their letters),
    // else shortened at its radius.
    let wider = radius * OMEGA_WIDER;
    let links = |r: f64| omega_obstacles(s, pose, b_foot, r, heading);
    let placed = |r: f64| omega_place(s, &links(r), (heading, sign), r).map(|(a, w)| (a, w, r));
    let (start, sweep, radius) = placed(radius)
        .or_else(|| placed(wider))
        .unwrap_or_else(|| omega_scan(s, &[(radius, links(radius)), (wider, links(wider))], sign));
    s.push(
        "arc-omega",
        Role::Force,
        Shape::Arc {
            centre: b,
            radius,
            start,
            sweep,
            arrow: true,
        },
    );
    // Set off the arc's middle outwards by as far as the head stands out
    // of the arc's circle (its half width, and the tangent it runs along
    // leaving the circle over its length) and [`OMEGA_LETTER_CLEAR`] em
    // more, less the placer's [`LETTER_GAP`], tried first that way: set
    // at the arc's middle, the letter touched the head (inversion 2 at
    // l = 45.1 r, 269.96°).
    let mid = start + 0.5 * sweep;
    let out = Vector::new(mid.cos(), mid.sin());
    let head_out = HEAD_HALF + HEAD * HEAD / (2.0 * s.page(radius));
    let beyond = s.world(head_out + OMEGA_LETTER_CLEAR * em - LETTER_GAP);
    let at = b + out * (radius + beyond);
    s.label_toward(
        "label-omega",
        at,
        out,
        RichText::parse("ω"),
        TextSize::Letter,
    );
}

/// The directions from B that ω's arc about it, of `radius`, keeps
/// clear of: the driver (heading `heading`), the other link at B, the
/// slotted link d's bar and leg where they cross the arc's circle, and
/// B's bearing on the side `b_foot` where one is drawn.
fn omega_obstacles(
    s: &Canvas,
    pose: &InversionPose,
    b_foot: Option<Foot>,
    radius: f64,
    heading: f64,
) -> Vec<f64> {
    let engine = pose.engine_pose();
    let b = pose.place(engine.b());
    // The other link at B (the fixed rod BA of inversion 3, the fixed
    // crank BC of inversion 2) and the slotted link d where it crosses
    // the arc's circle: the arc stands ahead of the driver in ω's sense,
    // or behind it where ahead it would come within [`OMEGA_CLEAR`] of
    // one of them and behind it keeps farther off, so that its head
    // never runs along a link (inversion 3 at 20° on a long rod, where
    // d passes a fraction of the crank below B).
    let other = match pose.inversion() {
        Inversion::Rod => pose.place(engine.a()),
        _ => pose.place(engine.c()),
    } - b;
    let mut links = vec![other.y.atan2(other.x)];
    let mechanism = pose.engine_pose().mechanism();
    let e = mechanism.offset();
    let slot = (pose.place(Point::new(0.0, e)), pose.place(engine.a()));
    // d is a bar as wide as the block: its middle line and both sides.
    let half = super::super::inversions::slot_half_width(mechanism, s.transform().scale());
    let across = pose.turn(Vector::new(0.0, half));
    // d's leg, from C square to the stroke where it is offset, as far
    // as it runs (B inside it at 270° in inversion 2 with l = 2.84 r,
    // e = -1.38 r, where the arc was drawn along it and over link a).
    let c = pose.place(engine.c());
    let beyond = (slot.0 - c)
        .try_normalize(0.0)
        .unwrap_or_else(Vector::zeros)
        * half;
    let leg = (c - beyond, slot.0 + beyond);
    let (inner, circle) = (
        radius - s.world(OMEGA_MARGIN),
        radius + s.world(OMEGA_MARGIN),
    );
    for side in [-1.0, 0.0, 1.0] {
        let shift = across * side;
        let edge = (slot.0 + shift, slot.1 + shift);
        links.extend(crossings(edge, b, circle, f64::INFINITY));
        links.extend(grazing(edge, b, (inner, circle), f64::INFINITY));
        // The leg also where it crosses the circle inside the arc: with B
        // inside the leg (inversion 3 at l = 3.77 r, e = -2.2 r,
        // 270.95°, the crank along it) its edges stand farther round
        // there, and the arc kept clear only of the outer crossings
        // touched the leg's edge with its end.
        let shift = pose.turn(Vector::new(half * side, 0.0));
        let edge = (leg.0 + shift, leg.1 + shift);
        for r in [circle, inner] {
            links.extend(crossings(edge, b, r, 1.0));
        }
        links.extend(grazing(edge, b, (inner, circle), 1.0));
        // The leg's outer corners, which end inside the circle: the arc
        // passing them by less than the head (3 units outside the corner
        // in the case above) read as drawn on d.
        let corner = leg.1 + shift - b;
        if (corner.norm() - radius).abs() < s.world(OMEGA_MARGIN) {
            links.push(corner.y.atan2(corner.x));
        }
    }
    // B's bearing, where one is drawn, on the side `b_foot`: its triangle
    // and hatching span about 0.65 rad either side of its axis at the
    // arc's radius (the arc and its head lay on the hatching at
    // l = 1.05 r, 180° in inversion 2, where both links at B run to the
    // left). The page's y runs down, the world's up. Where none is (a
    // hatched rod in inversion 3), the side it would take is no obstacle:
    // kept, it left no clear place at l = 50 r, e = -39.2 r, 260°, where
    // the arc ran along the hatched rod.
    if let Some(foot) = b_foot {
        let axis = foot.axes().0;
        let down = (-axis.y).atan2(axis.x);
        links.extend([down - BEARING_SPREAD, down, down + BEARING_SPREAD]);
    }
    links.push(heading);
    links
}

/// The clearance (radians) of ω's arc from `start` sweeping `sweep`,
/// with its head (which runs on past its end along the tangent about a
/// head's length), on a circle of `radius`, from the nearest of the
/// directions `links`.
fn omega_room(s: &Canvas, links: &[f64], (start, sweep): (f64, f64), radius: f64) -> f64 {
    let reach = sweep + sweep.signum() * s.world(HEAD) / radius;
    (links.iter())
        .map(|d| clearance(start, reach, *d))
        .fold(f64::INFINITY, f64::min)
}

/// Where ω's arc about B stands among the directions `links`
/// ([`omega_obstacles`]) for a driver heading `heading`, turning in the
/// sense `sign`, on a circle of `radius`: its start and sweep (radians),
/// the first of the usual places clear by [`OMEGA_CLEAR`] (ahead of the
/// driver, behind it, else about B where the links and the bearing leave
/// room: the default of inversion 3, whose crank points into the
/// bearing's side); none where none is.
fn omega_place(
    s: &Canvas,
    links: &[f64],
    (heading, sign): (f64, f64),
    radius: f64,
) -> Option<(f64, f64)> {
    let sweep = OMEGA_SWEEP * sign;
    let ahead = heading + OMEGA_GAP * sign;
    let behind = heading - OMEGA_GAP * sign - sweep;
    let about = OMEGA_ABOUT.map(|middle: f64| middle.to_radians() - 0.5 * sweep);
    let candidates = [[ahead, behind].as_slice(), &about].concat();
    (candidates.into_iter())
        .find(|c| omega_room(s, links, (*c, sweep), radius) >= OMEGA_CLEAR)
        .map(|start| (start, sweep))
}

/// ω's arc where no usual place is clear at either radius: set in the
/// widest room between the directions to keep clear of at each radius
/// (`around`: the radius and its [`omega_obstacles`]), scanned round B,
/// shortened (to [`OMEGA_SHORT`]) where none is clear at its full
/// sweep; the first length and radius clear by [`OMEGA_CLEAR`], else
/// the roomiest. Its start, sweep and radius. The five places tried,
/// all crossing a link, once put it over link a and d's leg between C
/// and B (inversion 2 at l = 2.84 r, e = -1.38 r, 270.23°, where B lies
/// inside d's leg: the room is round d's corner, at the wider radius).
fn omega_scan(s: &Canvas, around: &[(f64, Vec<f64>); 2], sign: f64) -> (f64, f64, f64) {
    let scan = |sweep: f64, radius: f64, links: &[f64]| {
        (0..OMEGA_SCAN)
            .map(|i| std::f64::consts::TAU * i as f64 / OMEGA_SCAN as f64)
            .map(|start| (start, omega_room(s, links, (start, sweep), radius)))
            .fold((0.0, f64::NEG_INFINITY), |best, next| {
                if next.1 > best.1 { next } else { best }
            })
    };
    let mut best = (0.0, OMEGA_SWEEP * sign, around[0].0, f64::NEG_INFINITY);
    for length in [OMEGA_SWEEP, 0.5 * (OMEGA_SWEEP + OMEGA_SHORT), OMEGA_SHORT] {
        for (radius, links) in around {
            let (start, room) = scan(length * sign, *radius, links);
            if room >= OMEGA_CLEAR {
                return (start, length * sign, *radius);
            }
            if room > best.3 {
                best = (start, length * sign, *radius, room);
            }
        }
    }
    (best.0, best.1, best.2)
}

/// How much wider than its usual radius ω's arc is tried where no usual
/// place is clear at it.
const OMEGA_WIDER: f64 = 1.4;

/// The shortest sweep (radians) ω's arc is cut to where it finds no
/// clear place at its full [`OMEGA_SWEEP`].
const OMEGA_SHORT: f64 = 0.6;

/// The starts tried round B for ω's arc where none of the usual places
/// is clear: every 5°.
const OMEGA_SCAN: usize = 72;

/// The directions from `centre` of the points where a line of the
/// slotted link d, from `slot.0` through `slot.1` and on to `reach`
/// times their distance (infinite for its bar, which runs on beyond the
/// block; 1 for its leg), crosses the circle of `radius` about `centre`;
/// none where it passes outside it or its ends coincide.
fn crossings(slot: (Point, Point), centre: Point, radius: f64, reach: f64) -> Vec<f64> {
    let (p, q) = slot;
    let u = q - p;
    let len = u.norm();
    if !(len > 0.0 && len.is_finite()) {
        return Vec::new();
    }
    let u = u / len;
    let w = p - centre;
    // |w + t u| = radius: t² + 2 (w·u) t + |w|² − radius² = 0.
    let half = w.dot(&u);
    let disc = half * half - (w.norm_squared() - radius * radius);
    if disc < 0.0 {
        return Vec::new();
    }
    let root = disc.sqrt();
    [-half - root, -half + root]
        .into_iter()
        .filter(|t| *t >= 0.0 && *t <= reach * len)
        .map(|t| {
            let at = w + u * t;
            at.y.atan2(at.x)
        })
        .collect()
}

/// The direction from `centre` of the point of a line of d (from
/// `slot.0` through `slot.1`, on to `reach` times their distance)
/// nearest it, where that stands between `band.0` and `band.1` from it:
/// the line grazes the arc there, which lies between the places it
/// crosses the wider circle and was drawn along it (inversion 2 at
/// l = 1.5 r, e = 0.45 r, 10°, the wider arc under d's bar). None
/// otherwise, or where the line's ends coincide.
fn grazing(slot: (Point, Point), centre: Point, band: (f64, f64), reach: f64) -> Option<f64> {
    let (p, q) = slot;
    let len = (q - p).norm();
    if !(len > 0.0 && len.is_finite()) {
        return None;
    }
    let u = (q - p) / len;
    let w = p - centre;
    let t = -w.dot(&u);
    let foot = w + u * t;
    let near = foot.norm();
    (t >= 0.0 && t <= reach * len && near >= band.0 && near <= band.1).then(|| foot.y.atan2(foot.x))
}

/// Room about ω's arc within which the slotted link d counts as
/// crossing it, page units: the head (its half width across the arc,
/// its tip off the circle along the tangent) and the link's half
/// stroke (at l = 30 r, 30°, d passed 2.5 units below the arc and the
/// head lay on d).
const OMEGA_MARGIN: f64 = 8.0;

/// A head's length along ω's arc, page units: the arrowhead's.
const HEAD: f64 = 10.0;

/// Half an arrowhead's width at its back, page units: the renderer's.
const HEAD_HALF: f64 = 3.2;

/// The least room between ω's letter and its arc's head, in ems.
const OMEGA_LETTER_CLEAR: f64 = 0.25;

/// The room the placer leaves between a letter's anchor and its box,
/// page units: ω's anchor stands that much nearer the arc than the room
/// its letter keeps from the head.
const LETTER_GAP: f64 = 4.0;

/// The middles (degrees, from the frame's +x) of the arcs about B tried
/// where neither ahead of the driver nor behind it is clear: above B
/// first, away from its bearing.
const OMEGA_ABOUT: [f64; 5] = [90.0, 45.0, 135.0, 0.0, 180.0];

/// The angles (radians) either side of straight down below B that its
/// bearing's edges are counted at, as links ω's arc keeps
/// [`OMEGA_CLEAR`] from: with it, 0.65 rad each side.
const BEARING_SPREAD: f64 = 0.4;

/// The angle (radians) between the driver and the end of ω's arc nearer
/// it.
const OMEGA_GAP: f64 = 0.35;

/// The least angle (radians) between ω's arc and the other link at its
/// centre before the arc goes behind the driver instead.
const OMEGA_CLEAR: f64 = 0.25;

/// The angle (radians) ω's arc sweeps.
const OMEGA_SWEEP: f64 = 1.1;

/// How far (radians) the direction `dir` stands from the arc that
/// sweeps `sweep` from `start`: 0 where the arc crosses it.
fn clearance(start: f64, sweep: f64, dir: f64) -> f64 {
    use std::f64::consts::TAU;
    let (lo, width) = if sweep >= 0.0 {
        (start, sweep)
    } else {
        (start + sweep, -sweep)
    };
    let past = (dir - lo).rem_euclid(TAU);
    if past <= width {
        0.0
    } else {
        (past - width).min(TAU - past)
    }
}
