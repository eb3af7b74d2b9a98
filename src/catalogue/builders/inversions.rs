//! The four inversions of the slider-crank chain (textbook §34), one
//! figure each: the chain seen from its fixed link, which is hatched, at
//! the relative position θ (the crank a against the frame d, as in the
//! engine), with its six virtual centres lettered O_ab … O_cd and the lines
//! of Kennedy's theorem that find O_bd and O_ac. A centre off the page is
//! shown by an arrow at the panel's edge, a centre at infinity by an arrow
//! along its direction.
//!
//! Each drawing is made in the fixed link's frame
//! ([`InversionPose::place`]): the frame d (1), the crank a (2), the rod
//! b (3) or the block c (4) lies still on the page whatever θ is; the
//! scale is that of every place the moving links reach over a turn, so
//! that it does not change with θ (Inversion 2's panel shows, at that
//! scale, only what its pose draws).

use super::{Ctx, Sheet, short};
use crate::chain::{ChainCentres, Inversion, InversionPose, InvertedChain};
use crate::construct::Link;
use crate::diagram::Plot;
use crate::error::Result;
use crate::figure::{BEARING_FOOT, Figure, Foot, Item, RichText, Role, Shape, TextSize};
use crate::geom::{
    Frame, Intersection, Point, Vector, inside_outline, point_segment_distance, unit,
};
use crate::scene::{Canvas, Marker, PIN_CLEAR, Seg, Slot};
use crate::{angle::Angle, mechanism::SliderCrank};
use serde_json::json;

/// The block's half length and half height: smaller than in Fig. 60, so
/// that the letter of its pin finds room beside it when the block turns;
/// its half length at most [`BLOCK_FOLDED`] of l − r, the distance CA at
/// the inner dead centre, so that C's pin stands clear of the block
/// there (at l = 1.05 r, 180° the block, 0.076 r each way of A, held C
/// 0.05 r from A inside it, and the ×10 details drew C as a pin of the
/// block).
fn block_size(m: &SliderCrank) -> (f64, f64) {
    let (lh, hh) = super::chains::block_size(m);
    let folded = BLOCK_FOLDED * (m.rod() - m.crank());
    ((0.7 * lh).min(folded), 0.8 * hh)
}

/// The most of the distance l − r (C to A at the inner dead centre) the
/// block's half length takes: the rest, a quarter of it, leaves C's pin
/// (4.2 units in radius) clear of the block's end where the pins are
/// drawn 17 units apart or more, as every detail of crowded pins draws
/// them (a main view with C and A nearer boxes them for its detail);
/// shorter, A's letter beside its pin stood across the block's end
/// (l = 1.03 r, 170°, the detail ×10).
const BLOCK_FOLDED: f64 = 0.75;

/// Room left at the panel's edge for an arrow at the edge, page units:
/// the sketch's arrow (34 units, 3 from the edge) and a gap of 3, so that
/// a line stopping there runs on into the arrow (at 64 the two stood 27
/// units apart and read as two things).
const EDGE_ROOM: f64 = 40.0;

/// Room kept between a link's letter and the block's end, page units
/// (a letter's height): nearer, the letter reads as the block's.
const LETTER_CLEAR: f64 = 17.0;

/// Centres nearer than this on the page (page units) to a lettered point
/// share its place and are named in the notes: a pin's width, within
/// which the two read as one spot. At 18, dots 13 to 17 units from a pin
/// were drawn unlettered while the notes called them too near to letter.
const CROWDED: f64 = 8.0;

/// Two centres closer than this fraction of the chain's size (r + l +
/// |e|) are one point (the construction's rounding, some ulps, is far
/// below it); farther apart, the notes give their distance instead of
/// calling them coincident.
const COINCIDENT: f64 = 1e-9;

/// How the notes place a centre `markup` at `p` drawn on top of the
/// lettered point `other` at `q`: "at" it when the two are one point (to
/// [`COINCIDENT`] of the chain's `size`), else their distance, so that
/// two centres 0.2 apart on a long chain are never called coincident.
fn where_near(markup: &str, p: Point, other: &str, q: Point, size: f64) -> String {
    let apart = (p - q).norm();
    if apart <= COINCIDENT * size {
        format!("{markup} is at {other}")
    } else {
        format!(
            "{markup} lies {} from {other}, too near it to letter apart",
            printed(apart)
        )
    }
}

/// Significant figures of a value the notes compute (a time ratio, a
/// distance between centres); the values given (r, l, e, θ) are printed
/// as given.
const PRINTED_FIGURES: usize = 3;

/// Below this a computed value is printed with a power of ten: a
/// distance of 0.0001783 read as seven digits.
const PRINTED_LEAST: f64 = 0.01;

/// A value the notes compute, to [`PRINTED_FIGURES`] significant figures,
/// trailing zeros dropped, and below [`PRINTED_LEAST`] as a mantissa and
/// a power of ten (`1.78×10⁻⁴`); 0 and non-finite values print `0`.
fn printed(x: f64) -> String {
    if x == 0.0 || !x.is_finite() {
        return "0".into();
    }
    let e = format!("{:.*e}", PRINTED_FIGURES - 1, x);
    let (mantissa, exponent) = e.split_once('e').unwrap_or((&e, "0"));
    let exponent: i32 = exponent.parse().unwrap_or(0);
    let mantissa: f64 = mantissa.parse().unwrap_or(0.0);
    if x.abs() >= PRINTED_LEAST {
        return short(mantissa * 10f64.powi(exponent));
    }
    format!(
        "{}×{}",
        short(mantissa),
        crate::number::power_of_ten(exponent)
    )
}

/// The chain's pieces at one pose, in the fixed link's frame.
struct Parts {
    c: Point,
    b: Point,
    a: Point,
    /// The foot of the perpendicular from C on the line of stroke.
    t: Point,
    /// The far end of the frame's guide or slotted bar.
    f: Point,
    /// The line of stroke's direction (+x in the engine) and its normal.
    u: Vector,
    v: Vector,
    /// Where d's leg is set beside the line C T (a crank lying along the
    /// leg would hide it, [`leg_jog`]): the leg's shift along the stroke,
    /// zero where it lies on that line.
    jog: Vector,
}

/// Lengths along the stroke: the slot's near and far ends of travel.
fn ends(m: &SliderCrank) -> (f64, f64) {
    let (r, l, e) = (m.crank(), m.rod(), m.offset());
    let far = ((l + r - e) * (l + r + e)).sqrt();
    let near = ((l - r - e) * (l - r + e)).sqrt();
    (near, far)
}

fn parts(m: &SliderCrank, p: &InversionPose) -> Parts {
    let (lh, _) = block_size(m);
    let e = m.offset();
    let (_, far) = ends(m);
    let pose = p.engine_pose();
    Parts {
        c: p.place(pose.c()),
        b: p.place(pose.b()),
        a: p.place(pose.a()),
        t: p.place(Point::new(0.0, e)),
        f: p.place(Point::new(far + lh + 0.15 * m.crank(), e)),
        u: p.turn(Vector::new(1.0, 0.0)),
        v: p.turn(Vector::new(0.0, 1.0)),
        jog: Vector::zeros(),
    }
}

/// The leg shorter than this many half widths of d's bar keeps to the
/// line C T: a stub the crank's pin covers, no run of it hidden.
const LEG_JOG: f64 = 3.0;

/// The shift along the stroke (towards the arm) of d's leg for an engine
/// whose leg is long enough to hide under the crank ([`LEG_JOG`]): at the
/// pose where the crank lies along the leg (θ near 90° or 270° with the
/// offset's sign) the crank covered it, and d read as welded to the crank
/// or the crank as d's slot (inversion 4 at l = 2.45 r, e = −0.745 r,
/// 270.12°; inversion 2 at l = 2.91 r, e = −1.57 r, 269.8°). The leg is
/// set beside the line C T, `across` half widths `w` off it, and joined
/// to C by an eye (the bar) or a jog (the plunger), at every pose, one
/// shape, as a rigid link is drawn; its inner side then stands `w` off
/// the crank's line where the two lie together. None where the block at
/// its near end of travel (half length `lh`) would leave the arm so set
/// back, nor with no offset.
fn leg_jog(m: &SliderCrank, q: &Parts, (lh, w): (f64, f64), across: f64) -> Vector {
    let leg = (q.t - q.c).norm();
    let (near, _) = ends(m);
    let shift = across * w;
    if !w.is_finite() || w <= 0.0 || leg < LEG_JOG * w || near - lh < shift - w {
        return Vector::zeros();
    }
    q.u * shift
}

/// How far d's leg is set off the line C T where it is ([`leg_jog`]), in
/// d's half widths: the slotted bar (inversions 2 and 3) by twice its half
/// width, its inner side a half width off the crank's line; the hand
/// pump's plunger, a line, by the barrel's half height; none where d is
/// the fixed frame.
fn jog_across(fixed: Link) -> f64 {
    match fixed {
        Link::A | Link::B => 2.0,
        Link::C => 1.0,
        Link::D => 0.0,
    }
}

/// The corners of the block about `a`.
fn block(parts: &Parts, lh: f64, hh: f64) -> [Point; 4] {
    let (a, u, v) = (parts.a, parts.u, parts.v);
    [
        a - u * lh - v * hh,
        a + u * lh - v * hh,
        a + u * lh + v * hh,
        a - u * lh + v * hh,
    ]
}

fn letter(link: Link) -> &'static str {
    match link {
        Link::A => "a",
        Link::B => "b",
        Link::C => "c",
        Link::D => "d",
    }
}

/// The world frame of every place the chain reaches over a turn, with
/// the rod's instantaneous centre's partner O_ac (E, always finite).
fn extent(m: &SliderCrank, chain: &InvertedChain) -> Frame {
    let (lh, hh) = block_size(m);
    let r = m.crank();
    let mut lo = Point::new(f64::INFINITY, f64::INFINITY);
    let mut hi = Point::new(f64::NEG_INFINITY, f64::NEG_INFINITY);
    let mut add = |p: Point| {
        lo = lo.inf(&p);
        hi = hi.sup(&p);
    };
    for k in 0..240 {
        // cannot fail: multiples of 1.5° below 360° are finite.
        #[allow(clippy::expect_used)]
        let p = chain.pose(Angle::from_degrees(1.5 * k as f64).expect("finite"));
        let q = parts(m, &p);
        for x in [q.c, q.b, q.a, q.t, q.f] {
            add(x);
        }
        for x in block(&q, lh, hh) {
            add(x);
        }
        // The crank circle about C where the frame is fixed.
        if chain.inversion() == Inversion::Frame {
            add(q.c + Vector::new(r, r));
            add(q.c - Vector::new(r, r));
        }
        if let Some(Intersection::Point(e)) = p.centres().centre(Link::A, Link::C) {
            add(e);
        }
    }
    Frame::new(lo, hi)
}

/// The page, the panel's rectangle and the world it shows: the world of
/// every place the chain reaches over a turn sets the scale (so that it
/// does not change with θ), and it is what the panel shows in inversion
/// 1; inversions 2, 3 and 4 show, at that scale, what is
/// drawn at this pose (the links, the block, the path and the centres
/// within the turn's world), on the figure's own page narrowed to it, at
/// least [`crate::scene::LEAST_FITTED_WIDTH`] wide (their bar d sweeps a
/// disc about C or B over a turn: drawn at one pose inversion 2 left the
/// top 200 and the left 450 units of its page empty, inversion 3 at
/// l = 1.65 r, e = 0.582 r the right 40 % of its 1520; inversion 4's
/// default, its handle swinging through an arc, the right third).
fn layout(
    ctx: &Ctx,
    chain: &InvertedChain,
    pose: &InversionPose,
) -> Result<(crate::scene::Page, crate::geom::Frame, Frame)> {
    let m = chain.mechanism();
    let turn = padded(extent(m, chain), 0.1);
    let page = ctx.page();
    let full = super::fitted_rect(&page, &turn, NOTES_HEIGHT);
    if chain.inversion() == Inversion::Frame {
        // Inversion 1 fills its turn's world at every pose.
        return Ok((page, full, turn));
    }
    let size = turn.max() - turn.min();
    let tall = full.height() - crate::diagram::CAPTION;
    let scale = (full.width() / size.x).min(tall / size.y);
    // On a page of a fixed width, room past O_bd would cost the drawing
    // its scale: only a page that fits its width to the drawing has it.
    let world = drawn(m, pose, &turn, EDGE_ROOM / scale, page.fits_width());
    let seen = world.max() - world.min();
    let margin = page.margin();
    let wide = (seen.x * scale + 2.0 * margin).max(crate::scene::LEAST_FITTED_WIDTH);
    let page = match page.fits_width() && wide < page.width() {
        true => page.with_width(wide.ceil())?,
        false => page,
    };
    let rect = crate::geom::Frame::from_origin_size(
        margin,
        margin,
        page.width() - 2.0 * margin,
        (seen.y * scale).min(tall) + crate::diagram::CAPTION,
    );
    Ok((page, rect, world))
}

/// The handle's swing in inversion 4: B's arc about A of radius l between
/// its extremes, as [`Drawing::path`] draws it ((start, sweep) from
/// [`swing_angles`]), sampled every few degrees.
fn swing(m: &SliderCrank, a: Point) -> Vec<Point> {
    let (start, sweep) = swing_angles(m);
    (0..=32)
        .map(|k| {
            let t = start + sweep * f64::from(k) / 32.0;
            a + Vector::new(t.cos(), t.sin()) * m.rod()
        })
        .collect()
}

/// The start and sweep (radians) of the handle's swing about A: B − A =
/// l(−cos φ, sin φ), φ between its extremes.
fn swing_angles(m: &SliderCrank) -> (f64, f64) {
    let (r, l, e) = (m.crank(), m.rod(), m.offset());
    let top = ((r - e) / l).clamp(-1.0, 1.0).asin();
    let bottom = ((-r - e) / l).clamp(-1.0, 1.0).asin();
    (std::f64::consts::PI - top, top - bottom)
}

/// `frame` grown on every side by `share` of its larger side.
fn padded(frame: Frame, share: f64) -> Frame {
    let size = frame.max() - frame.min();
    let pad = share * size.x.max(size.y);
    Frame::new(
        frame.min() - Vector::new(pad, pad),
        frame.max() + Vector::new(pad, pad),
    )
}

/// The world frame of what Inversion 2, 3 or 4 draws at `pose`, grown by
/// `pad`: the links, the block, the driven pin's path about B (A's in
/// inversion 2, C's in inversion 3; B's swing about A in inversion 4), room past O_bd for O_cd
/// at infinity (`beyond`), and the centres O_bd and O_ac where they lie within the
/// turn's world `turn` grown by a quarter of its size each way (a centre
/// beyond is an arrow at the edge).
fn drawn(m: &SliderCrank, pose: &InversionPose, turn: &Frame, pad: f64, beyond: bool) -> Frame {
    let (lh, hh) = block_size(m);
    let q = parts(m, pose);
    let reach = padded(*turn, 0.25);
    let mut points = vec![q.c, q.b, q.a, q.t, q.f];
    points.extend(block(&q, lh, hh));
    // The driven pin's path about B: A's (inversion 2), C's (inversion 3);
    // in inversion 4 the handle's swing about A.
    match pose.inversion() {
        Inversion::Slider => points.extend(swing(m, q.a)),
        inversion => {
            let l = match inversion {
                Inversion::Rod => m.crank(),
                _ => m.rod(),
            };
            points.push(q.b + Vector::new(l, l));
            points.push(q.b - Vector::new(l, l));
        }
    }
    for (p, q) in [(Link::B, Link::D), (Link::A, Link::C)] {
        if let Some(Intersection::Point(x)) = pose.centres().centre(p, q)
            && reach.contains(x)
        {
            points.push(x);
        }
    }
    // O_cd at infinity continues the line A O_bd past O_bd: room there
    // for its dashed line, its arrow and its letter, apart from O_bd's.
    let (bd, cd) = (
        pose.centres().centre(Link::B, Link::D),
        pose.centres().centre(Link::C, Link::D),
    );
    if let (Some(Intersection::Point(x)), Some(Intersection::AtInfinity(_))) = (bd, cd)
        && beyond
        && reach.contains(x)
        && x != q.a
    {
        points.push(x + (x - q.a).normalize() * (BEYOND_O_BD * pad));
    }
    // O_bd beyond the turn's world (an arrow at the edge): room past A
    // towards it for O_cd's arrow and its letter beside it (by A near the
    // page's edge the letter found room only across the block, l = 3.67 r,
    // e = 2.29 r, 269.21°).
    if let (Some(Intersection::Point(x)), Some(Intersection::AtInfinity(_))) = (bd, cd)
        && beyond
        && !reach.contains(x)
        && let Some(u) = unit(x - q.a)
    {
        points.push(q.a + u * (BEYOND_A * pad));
    }
    // O_bd beyond the turn's world: its arrow from B is lettered on the
    // side away from A (and O_cd's arrow from it), room for "to O_bd"
    // there; by B at the page's edge the letter found room only on the
    // other side, on d's leg produced (inversion 4 at l = 2.69 r,
    // e = −1.01 r, 269.36°).
    if let Some(Intersection::Point(x)) = bd
        && beyond
        && !reach.contains(x)
        && let Some(u) = unit(x - q.b)
    {
        let n = Vector::new(-u.y, u.x);
        let side = if n.dot(&(q.b - q.a)) >= 0.0 { n } else { -n };
        points.push(q.b + side * (BESIDE_B * pad));
    }
    let lo = points.iter().fold(turn.max(), |lo, p| lo.inf(p));
    let hi = points.iter().fold(turn.min(), |hi, p| hi.sup(p));
    Frame::new(lo - Vector::new(pad, pad), hi + Vector::new(pad, pad))
}

/// How far past O_bd the page reaches where O_cd lies at infinity on the
/// line A O_bd, in [`EDGE_ROOM`]s: O_cd's arrow began at O_bd's dot and its
/// "at ∞" stood stacked on O_bd's letter (the default engine).
const BEYOND_O_BD: f64 = 2.0;

/// How far past A the page reaches towards O_bd beyond it, where O_cd lies
/// at infinity on the same line, in [`EDGE_ROOM`]s: O_cd's arrow and its
/// letter beside it clear of the block.
const BEYOND_A: f64 = 3.0;

/// How far across O_bd's arrow from B the page reaches beside it where
/// O_bd lies beyond the turn's world, in [`EDGE_ROOM`]s: room for "to
/// O_bd" (about three em) and its gap to the arrow.
const BESIDE_B: f64 = 2.0;

/// The inversion's title, the notes' first line at every page width and
/// whether a detail stands below the main view or not: `Inversion 2:
/// link a fixed, rotating block: … .` (set as the main view's caption
/// where it fitted, run into the notes on a narrower page, split between
/// the two on another, the title was laid out three ways).
fn titled(inversion: Inversion) -> String {
    format!(
        "Inversion {}: link *{}* fixed, {}.",
        inversion.number(),
        letter(inversion.fixed()),
        inversion.name()
    )
}

/// The height of the notes below the drawing, page units: the title's
/// line ([`titled`]) and about two more (the notes grow the page by the
/// lines they wrap to beyond one a paragraph).
const NOTES_HEIGHT: f64 = 61.0;

pub(in crate::catalogue) fn build(ctx: &Ctx, inversion: Inversion) -> Result<Figure> {
    let m = ctx.mechanism;
    let chain = InvertedChain::new(m, inversion);
    let pose = chain.pose(ctx.angle);
    let (page, rect, world) = layout(ctx, &chain, &pose)?;
    let plot = Plot::world("mechanism", rect, &world, false, ctx.tolerance, ctx.font)?;
    let map = *plot.map();
    let block = super::chains::block_on_page(block_size(&m), map.scale());
    let centres = *pose.centres();
    let mut detail = crank_detail(ctx, &pose, &rect, map.scale(), None)?;
    // The title opens the notes at every width ([`titled`]): under a
    // detail, set as the main view's caption, it split the figure in two.
    let mut plot = plot;
    let shown_frame = map.world_frame(&plot.area());
    let region = detail.as_ref().map(|(region, _, _)| *region);
    let main = |shown: Option<Shown>| {
        let canvas = Canvas::new(map, shown_frame);
        let mut d = Drawing::new(m, &pose, canvas, block)
            .holding(region)
            .showing(shown);
        let together = d.draw(&pose, &centres);
        (d, together)
    };
    let (mut d, mut together) = main(None);
    // Where a detail enlarges the crank, both views show the fixed bar by
    // one decision and stand its bearings on the sides the main view
    // chose: hatched where the detail holds the whole bar and hatches it
    // (a long rod's fixed crank, a speck in the main view), else where
    // both views would hatch it (in a long rod's main view inversion 3's
    // rod lay in d's bar unhatched while the crank's detail hatched it
    // by O_ad, and the notes said hatched, l = 50 r), else neither.
    // A detail that shows none of the fixed link (inversion 4's barrel
    // far from a long rod's crank) has no say: at l = 52.6 r, 60° the
    // barrel, 52 units long, went unhatched because the crank's detail
    // could not hatch what it did not show.
    if let Some((region, _, seen)) = detail {
        let q = parts(&m, &pose);
        let (p, r) = match inversion.fixed() {
            Link::A => (q.c, q.b),
            // The barrel about A.
            Link::C => (q.a, q.a),
            _ => (q.b, q.a),
        };
        let whole = region.contains(p) && region.contains(r);
        let (p, r) = match inversion.fixed() {
            Link::C => {
                let (lh, _) = block_size(&m);
                (q.a - q.u * lh, q.a + q.u * lh)
            }
            _ => (p, r),
        };
        let any = region.clip_segment(p, r).is_some();
        let own = d.shown();
        let both = |v: Shown| v.hatched.unwrap_or(false);
        let hatched = match any {
            true => both(seen) && (whole || both(own)),
            false => both(own),
        };
        let shown = Shown {
            hatched: Some(hatched),
            ..own
        };
        detail = crank_detail(ctx, &pose, &rect, map.scale(), Some(shown))?;
        (d, together) = main(Some(shown));
    }
    let hatched = match (d.shown.and_then(|s| s.hatched)).unwrap_or(d.hatched >= FIXED_STROKES) {
        true => FIXED_STROKES,
        false => 0,
    };
    if let Some((region, _, _)) = &detail {
        super::coriolis::mark_window(&mut d.s, "mechanism", region);
    }
    for item in d.s.finish().0 {
        plot.push(item);
    }
    let mut sheet = Sheet::new(ctx);
    sheet.narrow(page.width())?;
    sheet.mechanism(ctx, false, true);
    sheet.meta("inversion", json!(inversion.number()));
    sheet.meta("fixed", json!(letter(inversion.fixed())));
    sheet.meta("driver", json!(letter(inversion.driver())));
    sheet.meta("virtual_centres", centres.to_json());
    sheet.plot(plot);
    let mut bottom = rect.max().y + 6.0;
    if let Some((_, detail, _)) = detail {
        bottom = detail.rect().max().y + 6.0;
        sheet.detail(detail);
    }
    sheet.height(bottom + NOTES_HEIGHT);
    sheet.notes(
        Point::new(20.0, bottom),
        &notes(ctx, &chain, &together, hatched),
    );
    Ok(sheet.finish())
}

/// The page length under which the crank a gets an enlarged detail below
/// the mechanism: at a long rod (forty cranks) the fixed crank of
/// inversion 2 is a speck between its bearings, unhatched, and the
/// crank of the others hides in its pins' circles.
const CRANK_LEAST: f64 = 40.0;

/// A crank detail's reach about its centre, in cranks: the crank's two
/// pins, the path about them and room for their letters.
const CRANK_REACH: f64 = 1.5;

/// A crank's enlarged detail in the panel `rect` (its caption included),
/// for a main view at `scale` page units per world unit: the world region
/// about `centre` it shows, [`CRANK_REACH`] cranks each way across its
/// shorter side at a round magnification (at least 1), and its plot,
/// captioned with the magnification; its panel `panel-{name}`.
pub(super) fn crank_window(
    ctx: &Ctx,
    name: &str,
    centre: Point,
    rect: crate::geom::Frame,
    scale: f64,
) -> Result<(Frame, Plot)> {
    let wanted = crank_wanted(ctx, &rect, scale);
    window(ctx, name, (centre, wanted), rect, scale)
}

/// The magnification that shows [`CRANK_REACH`] cranks each way across
/// the shorter side of the panel `rect` (its caption included), for a
/// main view at `scale` page units per world unit, before rounding.
fn crank_wanted(ctx: &Ctx, rect: &crate::geom::Frame, scale: f64) -> f64 {
    let (w, h) = (rect.width(), rect.height() - crate::diagram::CAPTION);
    w.min(h) / (2.0 * CRANK_REACH * ctx.mechanism.crank()) / scale
}

/// The least magnification of an inversion's detail: below it the
/// detail draws what the main view shows at nearly its size, and is not
/// drawn (the main view letters it all).
const DETAIL_LEAST: f64 = 1.5;

/// An enlarged detail in the panel `rect` (its caption included) of a
/// main view at `scale` page units per world unit, about `centre` at
/// the round magnification below `wanted` (at least 1): the world region
/// it shows and its plot, captioned with the magnification and framed.
fn window(
    ctx: &Ctx,
    name: &str,
    (centre, wanted): (Point, f64),
    rect: crate::geom::Frame,
    scale: f64,
) -> Result<(Frame, Plot)> {
    let steps = super::coriolis::FINE_STEPS;
    let magnification = super::coriolis::round_below(wanted, &steps).max(1.0);
    window_at(ctx, name, (centre, magnification), rect, scale)
}

/// The detail of [`window`] at `magnification` itself (a round one, at
/// least 1), for a figure that chooses it by a rule of its own (the
/// Coriolis figures' pins).
pub(super) fn window_at(
    ctx: &Ctx,
    name: &str,
    (centre, magnification): (Point, f64),
    rect: crate::geom::Frame,
    scale: f64,
) -> Result<(Frame, Plot)> {
    let (w, h) = (rect.width(), rect.height() - crate::diagram::CAPTION);
    let half = Vector::new(w, h) * (0.5 / (magnification * scale));
    let region = Frame::new(centre - half, centre + half);
    let caption = format!("the boxed region enlarged ×{}", short(magnification));
    let mut plot =
        Plot::world(name, rect, &region, false, ctx.tolerance, ctx.font)?.with_caption(&caption);
    border(&mut plot, name);
    Ok((region, plot))
}

/// A detail's border (`{name}-border`), half a unit inside the area the
/// detail `plot` is clipped to, so that the links cut there end on a
/// line, not in the air.
pub(super) fn border(plot: &mut Plot, name: &str) {
    let map = *plot.map();
    let inside = BORDER_INSET / map.scale();
    let seen = map.world_frame(&plot.area());
    let (lo, hi) = (
        seen.min() + Vector::new(inside, inside),
        seen.max() - Vector::new(inside, inside),
    );
    plot.push(Item::new(
        format!("{name}-border"),
        Role::Frame,
        Shape::Polyline {
            points: vec![lo, Point::new(hi.x, lo.y), hi, Point::new(lo.x, hi.y)],
            closed: true,
        },
    ));
}

/// How far inside its clipped area a crank detail's border is drawn,
/// page units: half its line's width, so that it is drawn whole.
const BORDER_INSET: f64 = 0.5;

/// The crank detail's size on the page, page units (its caption
/// included in the height).
const CRANK_DETAIL: (f64, f64) = (300.0, 200.0);

/// The length of an arrow at the frame's edge and its gap to the edge,
/// page units, as the canvas draws them.
const EDGE_ARROW: f64 = 34.0;
const EDGE_GAP: f64 = 3.0;

/// How far behind an edge arrow's tail its letter is set beside its
/// line, page units: one em of a letter.
const SET_BACK: f64 = 17.0;

/// Room between the mechanism and the crank detail below it, page units.
const DETAIL_GAP: f64 = 12.0;

/// Pins O_ad and O_bc (C and A) nearer than this on the page, page
/// units (two em of a letter), are crowded: at a short rod's inner dead
/// centre (l = 1.06 r at 180°) their circles overlapped as a figure 8
/// inside the block, their letters anyone's.
pub(super) const PINS_APART: f64 = 34.0;

/// How far apart crowded pins are drawn in their detail, page units, at
/// most (the magnification is rounded down).
pub(super) const PINS_SPREAD: f64 = 64.0;

/// The least magnification of the crowded pins' detail: below it the
/// detail draws them nearly as the main view does, a copy that enlarges
/// nothing (inversion 3 at l = 1.05 r, 270.05°: pins 33 units apart,
/// just within [`PINS_APART`], drawn again ×1.5), and the main view
/// letters them.
pub(super) const PINS_ENLARGED: f64 = 2.0;

/// The centre and the wanted magnification of the inversion's detail
/// at `scale` page units per world unit: about the crank a where it is
/// drawn shorter than [`CRANK_LEAST`] (`None` for the crank window's
/// own), about O_ad and O_bc where they stand nearer than
/// [`PINS_APART`] in d's slotted bar or the barrel (inversions 2 to 4;
/// `slotted`),
/// spread [`PINS_SPREAD`] apart; none where both read.
fn detail_about(
    m: &SliderCrank,
    q: &Parts,
    scale: f64,
    slotted: bool,
) -> Option<(Point, Option<f64>)> {
    let pins = (q.a - q.c).norm() * scale;
    if m.crank() * scale < CRANK_LEAST {
        Some((mid(q.c, q.b), None))
    } else if slotted
        && pins < PINS_APART
        // l > r keeps C and A apart: `pins` is not zero.
        && super::coriolis::round_below(PINS_SPREAD / pins, &super::coriolis::FINE_STEPS)
            >= PINS_ENLARGED
    {
        Some((mid(q.c, q.a), Some(PINS_SPREAD / pins)))
    } else {
        None
    }
}

/// Where the crank a is drawn shorter than [`CRANK_LEAST`] in the panel
/// `rect` at `scale` page units per world unit, or the pins O_ad and O_bc
/// crowd ([`PINS_APART`]), the world region about them and the detail
/// below the panel that enlarges it (the chain drawn again there, its
/// fixed link hatched and its centres lettered), captioned with the
/// magnification, and how it shows the fixed bar ([`Shown`]: as `shown`
/// says where given, the main view's decision); none where the crank and
/// the pins read.
fn crank_detail(
    ctx: &Ctx,
    pose: &InversionPose,
    rect: &crate::geom::Frame,
    scale: f64,
    shown: Option<Shown>,
) -> Result<Option<(Frame, Plot, Shown)>> {
    let m = ctx.mechanism;
    let q = parts(&m, pose);
    // O_ad and O_bc crowd in d's slotted bar, and in inversion 4's barrel
    // (at l = 1.05 r, 180° their pins overlapped in it).
    let crowding = pose.inversion() != Inversion::Frame;
    let Some((centre, wanted)) = detail_about(&m, &q, scale, crowding) else {
        return Ok(None);
    };
    let w = CRANK_DETAIL.0.min(rect.width());
    let detail_rect = crate::geom::Frame::from_origin_size(
        rect.min().x + 0.5 * (rect.width() - w),
        rect.max().y + DETAIL_GAP,
        w,
        CRANK_DETAIL.1,
    );
    // A detail enlarges, or is not drawn: at l = 3.89 r, e = −1.57 r, 0°
    // the crank, 39.7 units long in the main view, was drawn again ×1
    // below it, a copy that added nothing, and the main view left its
    // pins to the copy.
    let enlarged = match wanted {
        None => crank_wanted(ctx, &detail_rect, scale),
        Some(wanted) => wanted,
    };
    if super::coriolis::round_below(enlarged, &super::coriolis::FINE_STEPS) < DETAIL_LEAST {
        return Ok(None);
    }
    let (region, mut plot) = match wanted {
        None => crank_window(ctx, "detail", centre, detail_rect, scale)?,
        Some(wanted) => window(ctx, "detail", (centre, wanted), detail_rect, scale)?,
    };
    let map = *plot.map();
    let block = match wanted {
        None => super::chains::block_on_page(block_size(&m), map.scale()),
        // The crowded pins' detail enlarges where they stand, not the
        // block and d's slot about them: drawn at their size in the main
        // view, they show in it (at l = 1.02 r, 180° the block ×30 was
        // wider than the detail, which showed neither block nor bar).
        Some(_) => {
            let main = super::chains::block_on_page(block_size(&m), scale);
            let k = scale / map.scale();
            (main.0 * k, main.1 * k)
        }
    };
    let canvas = Canvas::new(map, map.world_frame(&plot.area())).detail("detail-");
    let mut d = Drawing::new(m, pose, canvas, block)
        .showing(shown)
        .in_detail();
    d.draw(pose, pose.centres());
    let seen = d.shown();
    let seen = Shown {
        hatched: shown.and_then(|s| s.hatched).or(seen.hatched),
        ..seen
    };
    for item in d.s.finish().0 {
        plot.push(item);
    }
    Ok(Some((region, plot, seen)))
}

/// The chain at `pose` drawn on `canvas`: the driven pin's path, the
/// frame d (guides or the slotted bar), the fixed link hatched, the links
/// and the block lettered a, b, c, d, by the rules of the inversions'
/// own figures (the fixed pins' bearings, the block's letter out of the
/// bar); for a figure that draws more on it (the Coriolis polygons'
/// mechanism). The block is drawn no smaller on the page than Fig. 60's.
///
/// `follow`: how the figure's other view showed the fixed bar, whose
/// bearings' sides this one keeps for the pins in its region
/// ([`LinksDrawn::shown`]); none for a view of its own.
pub(super) fn draw_links(
    m: SliderCrank,
    pose: &InversionPose,
    canvas: Canvas,
    follow: Option<Shown>,
) -> LinksDrawn {
    let block = super::chains::block_on_page(block_size(&m), canvas.transform().scale());
    let mut d = Drawing::new(m, pose, canvas, block)
        .showing(follow)
        .leg_on_line()
        .without_centres();
    d.path(pose.inversion());
    d.frame(pose);
    d.hatch();
    d.letter_bar();
    d.links(Vector::zeros());
    LinksDrawn {
        shown: d.shown(),
        b_foot: d.b_bearing.then_some(d.b_foot),
        a_way: d.pin_a_way,
        canvas: d.s,
    }
}

/// The chain as [`draw_links`] drew it: the canvas, and what the figure
/// drawing more on it keeps clear of.
pub(super) struct LinksDrawn {
    /// The canvas drawn on.
    pub canvas: Canvas,
    /// How it showed the fixed bar, for another view of the figure to
    /// follow ([`Shown::about`]).
    pub shown: Shown,
    /// The side B's bearing stands on, if one is drawn (ω's arc about B
    /// keeps off it).
    pub b_foot: Option<Foot>,
    /// The way A's letter is tried first (the other side of the bar from
    /// the block's letter), if the block's letter stands beside it.
    pub a_way: Option<Vector>,
}

/// The half width (world units) of the slotted bar d that [`draw_links`]
/// draws on a page at `scale` page units per world unit: the block's
/// half height as drawn ([`band`]).
pub(super) fn slot_half_width(m: &SliderCrank, scale: f64) -> f64 {
    super::chains::block_on_page(block_size(m), scale).1
}

/// The world frame of what [`draw_links`] draws at `pose`: the pins, the
/// frame's bar to its far end, the block and the driven pin's path.
pub(super) fn links_frame(m: &SliderCrank, pose: &InversionPose) -> Frame {
    let (lh, hh) = block_size(m);
    let q = parts(m, pose);
    let mut points = vec![q.c, q.b, q.a, q.t, q.f];
    points.extend(block(&q, lh, hh));
    if matches!(pose.inversion(), Inversion::Crank | Inversion::Rod) {
        points.extend(band(&q, hh));
    }
    let (centre, radius) = match pose.inversion() {
        Inversion::Frame => (q.c, m.crank()),
        Inversion::Crank => (q.b, m.rod()),
        Inversion::Rod => (q.b, m.crank()),
        Inversion::Slider => (q.a, m.rod()),
    };
    points.push(centre + Vector::new(radius, radius));
    points.push(centre - Vector::new(radius, radius));
    let lo = points.iter().fold(q.c, |lo, p| lo.inf(p));
    let hi = points.iter().fold(q.c, |hi, p| hi.sup(p));
    Frame::new(lo, hi)
}

/// One inversion's drawing in progress: the canvas, and what its steps
/// share.
struct Drawing {
    s: Canvas,
    m: SliderCrank,
    /// The fixed link, hatched.
    fixed: Link,
    q: Parts,
    /// The block's corners ([`block`]).
    corners: [Point; 4],
    /// The block's half length and half height as drawn.
    block: (f64, f64),
    /// The region a detail enlarges, whose pins and crank the detail
    /// letters: a few units apart here, their letters would stand by the
    /// wrong pin.
    held: Option<Frame>,
    /// The foot of the bearing at B ([`Drawing::foot`]), the side it
    /// stands or would stand on.
    b_foot: Foot,
    /// Whether a bearing is drawn at B (inversion 3 draws none where its
    /// rod is hatched).
    b_bearing: bool,
    /// The strokes of hatching drawn on the fixed bar (inversions 2 and
    /// 3): fewer than [`FIXED_STROKES`] and its pins carry bearings and the
    /// notes say so.
    hatched: usize,
    /// The foot of the bearing drawn at A, if any (inversion 3's rod
    /// unhatched): the block's letter stands on the other side.
    trunnion: Option<Foot>,
    /// The way O_bc's letter is tried first, where the block's letter
    /// stands beside the block: the other side of the bar, towards C (on
    /// the same side the two read as one label, "O_bc c").
    pin_a_way: Option<Vector>,
    /// The centres drawn as dots where they are finite (O_bd, O_ac),
    /// which a bearing's pedestal and hatching keep clear of.
    dots: Vec<Point>,
    /// Kennedy's lines where the figure draws them ([`Drawing::draw`]),
    /// which the fixed link's hatching keeps clear of as of a moving link:
    /// the layout opened the strokes they crossed after the scene had
    /// counted them, and the notes called hatched a link that showed
    /// fewer than [`FIXED_STROKES`].
    kennedy: Vec<Seg>,
    /// How the other view of the figure (its main view or its detail)
    /// shows the fixed link, which this one follows ([`Shown`]); none for
    /// a drawing of its own.
    shown: Option<Shown>,
    /// The feet of the bearings drawn at the fixed bar's two pins (C and
    /// B in inversion 2, B and A in inversion 3), where drawn.
    feet: [Option<Foot>; 2],
    /// The way the normal at A is drawn ([`Drawing::normal_way`]; zero
    /// where none is): the block's letter stands on its side of the bar,
    /// which A's bearing leaves clear.
    normal: Vector,
    /// The side of d's bar its letter stands on, once lettered (world);
    /// none before or where d is not lettered beside its bar.
    d_way: Option<Vector>,
    /// Whether the links' letters are set by their runs clear of pins,
    /// dots and crossings ([`Drawing::letter_run`]); else by their
    /// middles (the Coriolis figures' mechanism, which draws no centres).
    runs: bool,
    /// Whether a centre off the page or at infinity is shown by an arrow
    /// at the frame's edge: not in a detail, whose edge is not the
    /// drawing's (its links run on beyond it).
    edge_arrows: bool,
}

/// How a view showed the fixed bar, which the figure's other view
/// follows: one rule for both (inversion 3 at l = 51.7 r, 180° hatched
/// the rod in the detail, four strokes by O_ad, where the main view drew
/// bearings and the notes said too short to hatch; the detail left O_ab
/// bare; the main view stood its bearing sideways, the detail upright).
#[derive(Debug, Clone, Copy)]
pub(super) struct Shown {
    /// Whether the fixed bar is hatched (else its pins carry bearings);
    /// none: as each view would.
    hatched: Option<bool>,
    /// The feet of the bearings at its two pins ([`Drawing::feet`]).
    feet: [Option<Foot>; 2],
    /// The region the detail enlarges: `feet` are given for its pins, a
    /// pin out of it has its bearing stood by each view's own rule; none:
    /// for every pin.
    region: Option<Frame>,
}

impl Shown {
    /// The bearings' sides of the pins in `region` (the region a detail
    /// enlarges), each view hatching the fixed bar by its own rule: the
    /// Coriolis figures' mechanism and its crank's detail (at l = 55.2 r,
    /// 180° B's bearing stood sideways in the mechanism, upright in the
    /// detail).
    pub(super) fn about(self, region: Frame) -> Self {
        Shown {
            hatched: None,
            region: Some(region),
            ..self
        }
    }
}

/// Where the block's letter stands beside it, in half lengths of the
/// block from its middle towards its far end: by its far corner, away
/// from the normal at A and O_bc's letter at its middle.
const BLOCK_LETTER_ALONG: f64 = 0.75;

/// The block riding within this of the bar's end (page units) is
/// lettered beyond its end, outside the bar; else beside it.
const AT_BAR_END: f64 = 4.0;

/// The least strokes of hatching the scene draws for the notes to call a
/// fixed bar hatched; with fewer (the bar lying inside d's slot, every
/// stroke on d's outline, or a short bar), the notes name the bearings at
/// its pins instead. Twice the three the plate check asks to see: the
/// layout opens strokes under the letters crowding a short bar after the
/// scene has counted them (inversion 2's default crank, 49 units between
/// its bearings, counted 4 and showed 2 under O_ab's letter).
const FIXED_STROKES: usize = 6;

/// A bearing's foot within this angle (radians, 60°) of a link meeting
/// at its pin is set on another side: the pedestal spans 30° each side
/// of its axis, and a link nearer ran through it (inversion 3's crank
/// through O_ab's pedestal near 90° with an offset).
const FOOT_CLEAR: f64 = std::f64::consts::FRAC_PI_3;

/// How far a bearing reaches from its pin, page units: the foot
/// ([`BEARING_FOOT`], as the layout draws it) and the first 3 units of
/// its hatching, and half the foot's length.
const FOOT_REACH: (f64, f64) = (BEARING_FOOT.0 + 3.0, BEARING_FOOT.1);

/// How far (page units) a dot at `d` towards a bearing's foot and `s`
/// along it (from its pin) stands off the bearing's ink: its pedestal, a
/// triangle from the pin to the foot ([`PEDESTAL_HALF`] each way there),
/// and the foot with its hatching, a strip [`FOOT_REACH`] and
/// [`HATCH_DEPTH`] deep; 0 inside either. Where no side of a pin is
/// clear of the dots by [`Drawing::foot`]'s box, the side farthest by
/// this is taken: between sides equally crowded by the box, the first
/// was kept, and the bearing stood on the dot (inversion 2 at
/// l = 1.42 r, e = 0.255 r, 0°: O_ac, 14 units below O_ad, inside its
/// bearing, where a bearing to the left stood 12 units off it).
fn bearing_room(d: f64, s: f64) -> f64 {
    let (depth, half) = FOOT_REACH;
    let (foot, end) = (BEARING_FOOT.0, depth + HATCH_DEPTH);
    let strip = {
        let dd = (foot - d).max(d - end).max(0.0);
        let ds = (s.abs() - half).max(0.0);
        dd.hypot(ds)
    };
    let x = Point::new(d, s);
    let tri = [
        Point::new(0.0, 0.0),
        Point::new(foot, -PEDESTAL_HALF),
        Point::new(foot, PEDESTAL_HALF),
    ];
    let pedestal = match inside_outline(&tri, x) {
        true => 0.0,
        false => (tri.iter().zip(tri.iter().cycle().skip(1)))
            .map(|(p, q)| point_segment_distance(x, *p, *q))
            .fold(f64::INFINITY, f64::min),
    };
    strip.min(pedestal)
}

/// The room off a bearing's ink ([`bearing_room`]) beyond which a dot
/// is as clear as farther, page units: two dots' widths.
const DOT_ROOM: f64 = 10.0;

/// Half the width of a bearing's pedestal at its foot, page units, as
/// the layout draws it.
const PEDESTAL_HALF: f64 = 10.0;

/// How far a bearing's hatching reaches beyond [`FOOT_REACH`]'s depth,
/// page units (the strokes stand 6 units beyond the foot).
const HATCH_DEPTH: f64 = 3.0;

/// The outline of the turning frame d with a slot for the block: a bar
/// `w` wide each side of its middle line (the block's half height, so
/// that the block fills the slot), from `w` behind its pivot C to its
/// far end, bent square at the foot T of C's leg where the stroke is
/// offset. A body, not a line: a link lying along its leg or its arm
/// (the crank along the leg near 90° with an offset near r, the fixed
/// rod along the arm at 270°) shows inside it instead of hiding it, and
/// a pin it passes reads as passed, not joined. With no offset, a
/// rectangle; as the offset goes to 0 the leg shortens to nothing and
/// the outline to the same rectangle.
fn band(q: &Parts, w: f64) -> Vec<Point> {
    let (c, t, f, u) = (q.c, q.t, q.f, q.u);
    let leg = t - c;
    if leg.norm() == 0.0 {
        let (s, v) = (c - u * w, q.v);
        return vec![s - v * w, f - v * w, f + v * w, s + v * w];
    }
    let g = leg / leg.norm();
    let s = c - g * w;
    if q.jog.norm() == 0.0 {
        return vec![
            s - u * w,
            t + g * w - u * w,
            f + g * w,
            f - g * w,
            t - g * w + u * w,
            s + u * w,
        ];
    }
    // The leg beside C T, joined to C by an eye about the pin.
    let j = q.jog;
    vec![
        s - u * w,
        c + g * w - u * w,
        c + j + g * w - u * w,
        t + j + g * w - u * w,
        f + g * w,
        f - g * w,
        t + j - g * w + u * w,
        s + j + u * w,
    ]
}

/// The centres drawn as dots where they are finite: O_bd and O_ac.
fn dots(centres: &ChainCentres) -> Vec<Point> {
    [(Link::B, Link::D), (Link::A, Link::C)]
        .into_iter()
        .filter_map(|(p, q)| match centres.centre(p, q) {
            Some(Intersection::Point(x)) => Some(x),
            _ => None,
        })
        .collect()
}

/// How far a dot is kept from a bearing's pedestal and hatching, page
/// units: a dot's radius and a stroke's width, so that it reads apart.
const DOT_CLEAR: f64 = 5.0;

/// A centre within this of a link's line, page units (a link's half
/// width and its rim of paper), is drawn over the links.
const ON_LINK: f64 = 4.0;

/// Lines filling the slotted bar of [`band`] (`w` its half width): its
/// middle line and the lines halfway to its sides, along its leg and its
/// arm. A stroke of hatching that starts inside the bar meets one of
/// them (they stand half a half width apart, less than a stroke's
/// length), so that a fixed link lying in the bar keeps no stroke there:
/// at l = 54.1 r, 90° inversion 3's rod b, running inside d's bar, was
/// hatched inside it and the moving bar read as fixed.
fn band_fill(q: &Parts, w: f64) -> Vec<Seg> {
    let (c, t, f, u, j) = (q.c, q.t, q.f, q.u, q.jog);
    let leg = t - c;
    let shares = [-0.5, 0.0, 0.5];
    if leg.norm() == 0.0 {
        let (s, v) = (c - u * w, q.v);
        return shares.map(|k| (s + v * (k * w), f + v * (k * w))).to_vec();
    }
    let g = leg / leg.norm();
    let s = c - g * w;
    let mut fill: Vec<Seg> = (shares.iter())
        .flat_map(|k| {
            let (across_leg, across_arm) = (u * (k * w), g * (k * w));
            [
                (s + j + across_leg, t + j + across_leg + g * w),
                (t + j - u * w + across_arm, f + across_arm),
            ]
        })
        .collect();
    if j.norm() > 0.0 {
        // Across the eye about C.
        fill.extend(shares.map(|k| (c - u * w + g * (k * w), c + j + u * w + g * (k * w))));
    }
    fill
}

/// The middle of `p` and `q`.
fn mid(p: Point, q: Point) -> Point {
    Point::from((p.coords + q.coords) * 0.5)
}

/// The crank and the rod within this angle of one line (radians, 10°)
/// lie along each other: their letters take sides ([`Drawing::letter_ways`]).
const ALONG_LINE: f64 = 0.175;

/// The crank and the rod within this angle of one line (radians, 40°)
/// but not along it make a wedge at B too narrow for a letter of each:
/// their letters are tried outside it ([`Drawing::letter_ways`]).
const WEDGE: f64 = 0.70;

/// How far along a link its letter's place is kept from a pin, a
/// centre's dot on the link or a line crossing it, page units: two ems
/// of a letter, so that the letter stands by its own link's run and
/// clear of the dot's name.
const LETTER_RUN_CLEAR: f64 = 36.0;

/// A centre's dot within this of a link's line, page units (an em),
/// stands on the link for its letter ([`Drawing::letter_run`]).
const ON_LINE: f64 = 18.0;

/// How far across the fixed barrel (in its half heights) the normal at
/// A is kept from its hatching: past both faces and the strokes' depth.
const BARREL_REACH: f64 = 4.0;

/// The least half length of inversion 4's fixed barrel on the page, page
/// units: [`FIXED_STROKES`] strokes a spacing apart stand on one face
/// clear of the normal at A across its middle (Fig. 60's least block,
/// 24 units long, held three).
const BARREL_LEAST: f64 = 26.0;

/// The block's half sizes as drawn at `scale` page units per world unit:
/// in inversion 4, the fixed barrel, at least [`BARREL_LEAST`] long each
/// way, so that it carries the fixed link's hatching.
fn barrel((lh, hh): (f64, f64), fixed: Link, scale: f64) -> (f64, f64) {
    match fixed == Link::C && scale.is_finite() && scale > 0.0 {
        true => (lh.max(BARREL_LEAST / scale), hh),
        false => (lh, hh),
    }
}

impl Drawing {
    /// The drawing of the chain `m` at `pose` on `canvas`, its block
    /// `block` (half length, half height) as drawn.
    fn new(m: SliderCrank, pose: &InversionPose, canvas: Canvas, block: (f64, f64)) -> Self {
        let mut q = parts(&m, pose);
        let fixed = pose.inversion().fixed();
        let block = barrel(block, fixed, canvas.transform().scale());
        q.jog = leg_jog(&m, &q, block, jog_across(fixed));
        Drawing {
            s: canvas,
            m,
            fixed,
            corners: self::block(&q, block.0, block.1),
            block,
            q,
            held: None,
            b_foot: Foot::Below,
            b_bearing: false,
            hatched: 0,
            trunnion: None,
            pin_a_way: None,
            dots: dots(pose.centres()),
            kennedy: Vec::new(),
            shown: None,
            feet: [None, None],
            normal: Vector::zeros(),
            d_way: None,
            runs: true,
            edge_arrows: true,
        }
    }

    /// The same drawing as a detail's: no arrows at its edge.
    fn in_detail(mut self) -> Self {
        self.edge_arrows = false;
        self
    }

    /// The same drawing with d's leg on the line C T ([`leg_jog`] not
    /// applied): for the Coriolis figures' mechanism, whose driver's arc
    /// about B keeps clear of d's arm and its line C T, not of a leg set
    /// beside it (the arc ran along such a leg at l = 4 r, e = −2.4 r,
    /// 340°).
    fn leg_on_line(mut self) -> Self {
        self.q.jog = Vector::zeros();
        self
    }

    /// The same drawing with no centres' dots to keep the bearings clear
    /// of: for the Coriolis figures' mechanism, which draws no centres
    /// (an undrawn O_bd at A turned C's bearing along the crank, its
    /// hatching out of the detail's box, at l = 1.1 r, 180°). Its links'
    /// letters stand by their middles, as its reviewed plates have them.
    fn without_centres(mut self) -> Self {
        self.dots.clear();
        self.runs = false;
        self
    }

    /// The same drawing showing the fixed link as `shown` says.
    fn showing(mut self, shown: Option<Shown>) -> Self {
        self.shown = shown;
        self
    }

    /// How this drawing showed the fixed bar: hatched or by its bearings,
    /// and their feet.
    fn shown(&self) -> Shown {
        Shown {
            hatched: Some(self.hatched >= FIXED_STROKES),
            feet: self.feet,
            region: self.held,
        }
    }

    /// The least strokes of hatching drawn on the fixed bar: as
    /// [`Shown`] says where it is given (none, or every one), else
    /// [`FIXED_STROKES`].
    fn least_strokes(&self) -> usize {
        match self.shown {
            Some(Shown {
                hatched: Some(true),
                ..
            }) => 1,
            Some(Shown {
                hatched: Some(false),
                ..
            }) => usize::MAX,
            _ => FIXED_STROKES,
        }
    }

    /// The foot [`Shown`] gives the bearing at the fixed bar's pin `p`
    /// (its `k`th): the main view's, for a pin in the region the detail
    /// enlarges, where its base stands out of d's bar here too (in a
    /// detail that draws d's bar wider than the main view, the main view's
    /// side could set it inside).
    fn shown_foot(&self, p: Point, k: usize) -> Option<Foot> {
        let shown = self.shown?;
        let foot = match shown.region {
            Some(region) if !region.contains(p) => None,
            _ => shown.feet.get(k).copied().flatten(),
        }?;
        self.base_out(p, foot).then_some(foot)
    }

    /// The same drawing leaving the pins, the crank's letter and the
    /// centres inside `region` to the detail that enlarges it.
    fn holding(mut self, region: Option<Frame>) -> Self {
        if let Some(r) = region {
            self.s = self.s.quiet(r);
        }
        self.held = region;
        self
    }

    /// Whether `p` lies in the region a detail letters instead.
    fn held(&self, p: Point) -> bool {
        self.held.is_some_and(|r| r.contains(p))
    }

    /// The whole figure's drawing: the path, the frame, the fixed link
    /// hatched, the links and the centres; the centres' names that share
    /// a lettered point's place ([`Drawing::centres`]).
    fn draw(&mut self, pose: &InversionPose, centres: &ChainCentres) -> Vec<String> {
        self.kennedy = kennedy_lines(&self.q, centres);
        self.normal = self.normal_way(centres);
        self.path(pose.inversion());
        self.frame(pose);
        self.hatch();
        self.letter_bar();
        self.links(self.normal);
        self.centres(centres)
    }

    /// The way the normal to the stroke at A is drawn from A: towards
    /// O_bd, or, where O_bd is at A or at infinity, towards O_cd's arrow
    /// ([`Drawing::centres`]); zero where neither is drawn.
    fn normal_way(&self, centres: &ChainCentres) -> Vector {
        let a = self.q.a;
        let along = match centres.centre(Link::B, Link::D) {
            Some(Intersection::Point(d)) => d - a,
            _ => Vector::zeros(),
        };
        if along != Vector::zeros() {
            return along;
        }
        match centres.centre(Link::C, Link::D) {
            Some(Intersection::AtInfinity(dir)) => self.towards(dir.into_inner(), a, along),
            _ => Vector::zeros(),
        }
    }

    /// The foot a fixed pin `p`'s bearing stands on: below, unless a link
    /// meeting there (towards `meeting`) runs within [`FOOT_CLEAR`] of it,
    /// its base lies inside d's slotted bar or a centre's dot (O_bd, O_ac)
    /// stands on its pedestal or hatching ([`DOT_CLEAR`]); then the first
    /// side clear of all three, else the best side, its base out of the
    /// bar first, then clear of the dots, then farthest from the links
    /// (the default of inversion 2 hung O_ab's bearing from above, O_ac's
    /// dot on its hatching, read as part of the bearing). The inversions'
    /// figures and the Coriolis figures' mechanism draw by this one rule
    /// (the latter kept every bearing below, B's in d's slot).
    fn foot(&self, p: Point, meeting: &[Point]) -> Foot {
        self.foot_clear(p, meeting).0
    }

    /// [`Drawing::foot`], and whether its base stands out of d's bar.
    fn foot_clear(&self, p: Point, meeting: &[Point]) -> (Foot, bool) {
        let map = *self.s.transform();
        let at = map.apply(p);
        let ways: Vec<Vector> = (meeting.iter())
            .filter_map(|q| unit(map.apply(*q) - at))
            .collect();
        let out = |f: Foot| self.base_out(p, f);
        let spread = |f: Foot| {
            let down = f.axes().0;
            (ways.iter())
                .map(|w| w.dot(&down).clamp(-1.0, 1.0).acos())
                .fold(std::f64::consts::PI, f64::min)
        };
        // The centres' dots off the pin (one on it is named with it).
        let dots: Vec<Point> = (self.dots.iter())
            .map(|x| map.apply(*x))
            .filter(|x| (x - at).norm() > CROWDED)
            .collect();
        let (depth, half) = FOOT_REACH;
        let clear = |f: Foot| {
            let (down, along) = f.axes();
            dots.iter().all(|x| {
                let (d, s) = ((x - at).dot(&down), (x - at).dot(&along));
                d < -DOT_CLEAR || d > depth + HATCH_DEPTH + DOT_CLEAR || s.abs() > half + DOT_CLEAR
            })
        };
        // Where no side is clear of the dots by that box, the one whose
        // ink stands farthest from them.
        let room = |f: Foot| {
            let (down, along) = f.axes();
            (dots.iter())
                .map(|x| bearing_room((x - at).dot(&down), (x - at).dot(&along)))
                .fold(f64::INFINITY, f64::min)
        };
        let feet = [Foot::Below, Foot::Above, Foot::Left, Foot::Right];
        let score = |f: Foot| (out(f), clear(f), room(f).min(DOT_ROOM), spread(f));
        // Of sides equally good, the first (below) is kept.
        let foot = (feet.into_iter())
            .find(|&f| out(f) && clear(f) && spread(f) >= FOOT_CLEAR)
            .or_else(|| {
                (feet.into_iter().rev()).max_by(|&f, &g| {
                    let (a, b) = (score(f), score(g));
                    ((a.0, a.1).cmp(&(b.0, b.1)))
                        .then(a.2.total_cmp(&b.2))
                        .then(a.3.total_cmp(&b.3))
                })
            })
            .unwrap_or(Foot::Below);
        (foot, out(foot))
    }

    /// Whether the base of a bearing at `p` on the side `foot` as drawn,
    /// and the first units of its hatching, stand out of d's slotted bar.
    fn base_out(&self, p: Point, foot: Foot) -> bool {
        if !self.slotted() {
            return true;
        }
        let map = *self.s.transform();
        let at = map.apply(p);
        let outline: Vec<Point> = (band(&self.q, self.block.1).iter())
            .map(|x| map.apply(*x))
            .collect();
        let (depth, half) = FOOT_REACH;
        let (down, along) = foot.axes();
        [BEARING_FOOT.0, depth].iter().all(|&deep| {
            let base = at + down * deep;
            [base, base + along * half, base - along * half]
                .iter()
                .all(|x| !inside_outline(&outline, *x))
        })
    }

    /// The path of the driven link's far pin: a circle, or the hand
    /// pump's handle swinging about A.
    fn path(&mut self, inversion: Inversion) {
        let (r, l) = (self.m.crank(), self.m.rod());
        let (c, b, a) = (self.q.c, self.q.b, self.q.a);
        let path = match inversion {
            Inversion::Frame => Some((c, r, b)),
            Inversion::Crank => Some((b, l, a)),
            Inversion::Rod => Some((b, r, c)),
            Inversion::Slider => None,
        };
        if let Some((centre, radius, _)) = path {
            self.s
                .push("circle-path", Role::Curve, Shape::Circle { centre, radius });
        } else {
            let (start, sweep) = swing_angles(&self.m);
            self.s.push(
                "arc-path",
                Role::Curve,
                Shape::Arc {
                    centre: a,
                    radius: l,
                    start,
                    sweep,
                    arrow: false,
                },
            );
        }
    }

    /// The frame d's bar from C (through the foot T of its leg
    /// perpendicular to the line of stroke, where the stroke is offset):
    /// one shape at every pose, as a rigid link is drawn. A leg bent off
    /// the crank only where the two would lie together (near 90° with an
    /// offset near r) was read as d changing its shape from pose to pose
    /// and put O_ab's letter at the bend; the leg set beside C T at every
    /// pose ([`leg_jog`]) keeps one shape and shows both links. Its
    /// foot runs from C slanting to the leg, not square along the stroke:
    /// square, it continued the crank's line at the dead centres, and
    /// crank, pin and foot read as one straight link (inversion 4 at
    /// l = 2.4 r, e = 1.11 r, 180°).
    fn bar(&self) -> Vec<Point> {
        let q = &self.q;
        if self.m.offset() == 0.0 {
            vec![q.c, q.f]
        } else if q.jog.norm() > 0.0 {
            let g = unit(q.t - q.c).unwrap_or(q.v);
            vec![q.c, q.c + q.jog + g * q.jog.norm(), q.t + q.jog, q.f]
        } else {
            vec![q.c, q.t, q.f]
        }
    }

    /// Whether d is drawn as a slotted body ([`band`]): where the block
    /// slides in it as it turns (inversions 2 and 3). In inversion 4 d is
    /// the plunger that slides through the fixed barrel, a rod.
    fn slotted(&self) -> bool {
        matches!(self.fixed, Link::A | Link::B)
    }

    /// The frame d: the guides and the line of stroke if it is fixed,
    /// else the slotted bar from C.
    fn frame(&mut self, pose: &InversionPose) {
        let (lh, hh) = self.block;
        let q = &self.q;
        if self.fixed != Link::D {
            if self.slotted() {
                let points = band(q, self.block.1);
                self.s
                    .push("link-frame", Role::Link, Shape::Body { points });
            } else {
                self.s.link("frame", self.bar());
            }
            return;
        }
        let (near, far) = ends(&self.m);
        let r = self.m.crank();
        self.s.bearing("C", q.c);
        let (u, v, t) = (q.u, q.v, q.t);
        let point = move |sigma: f64, delta: f64| t + u * sigma + v * delta;
        let slot = Slot {
            point: &point,
            straight: true,
            range: (near - lh - 0.15 * r, far + lh + 0.15 * r),
            half_height: hh,
            block: (pose.engine_pose().a().x, lh),
        };
        self.s.centre_line("line-stroke", t - u * r, q.f);
        self.s.guides("stroke", &slot, q.c, (q.b, q.a));
        self.s
            .letter("link-d", point(slot.range.1, hh), "*d*", TextSize::Letter);
    }

    /// Where the turning bar d is lettered: 0.85 of the way from T to its
    /// far end, or, where something stands on the bar there, the middle
    /// of the longest run of bar clear of it: the block (at the outer dead
    /// centre it rides at the bar's end, and a letter there names the
    /// block), the pins B and C where they lie on the bar's line (at
    /// the dead centres B lies in the bar, and the letter over it read
    /// "d O_ab" as one label), two em each way, and, an em and a half
    /// each way, the middles of the links lying along it, where their
    /// letters stand (beside a's, d read "a d"); none where no run is clear.
    /// With the side of the bar the letter stands on
    /// ([`Drawing::bar_letter_side`]). Where no run is clear on both
    /// sides, a run clear on one side of the slotted bar: a pin or a link
    /// standing off the bar on the other side, past its edge, does not
    /// take the letter's place, the bar standing between them
    /// (inversion 2 at l = 1.42 r, e = 0.255 r, 0°: the crank 13 units
    /// below the bar's lower edge took every place along it, and d went
    /// under the crank, by a's letter, "d a", far from its bar).
    fn bar_letter(&self) -> Option<(Point, Vector)> {
        if let Some(at) = self.bar_letter_on(None) {
            return Some((at, self.bar_letter_side(at)));
        }
        if !self.slotted() {
            return None;
        }
        let q = &self.q;
        let usual = q.t + q.u * (0.85 * (q.f - q.t).dot(&q.u));
        let first = self.bar_letter_side(usual);
        [first, -first]
            .into_iter()
            .find_map(|way| Some((self.bar_letter_on(Some(way))?, way)))
    }

    /// The place along the bar for d's letter ([`Drawing::bar_letter`]),
    /// standing on the side `way` of it, or on either (none).
    fn bar_letter_on(&self, way: Option<Vector>) -> Option<Point> {
        let q = &self.q;
        let (lh, hh) = self.block;
        let along = |p: Point| (p - q.t).dot(&q.u);
        let clear = self.s.world(LETTER_CLEAR);
        // Two em beyond the block, as about a pin (one left d's letter
        // 27 units from A's pin at l = 2.65 r, e = 1.44 r, 89.28°, where
        // it read as the block's).
        // In the hand pump five: "O_cd at ∞" stands beside its arrow
        // down from A past the block, and a letter of d two em off sent
        // it over the barrel (l = 25 r, 0°: no room between them for the
        // half em two labels keep apart).
        let ems = if self.fixed == Link::C { 5.0 } else { 2.0 };
        let mut taken = vec![(along(q.a) - lh - ems * clear, along(q.a) + lh + ems * clear)];
        // Within an em of the bar's edge on the letter's side, or in the
        // bar, not beyond its other edge.
        let on_bar = |p: Point| {
            let off = (p - q.t).dot(&q.v);
            match way {
                Some(w) => {
                    let off = off * w.dot(&q.v).signum();
                    off >= -hh && off <= hh + clear
                }
                None => off.abs() <= hh + clear,
            }
        };
        // Two em about a pin: its letter stands beside it.
        for p in [q.b, q.c] {
            if on_bar(p) {
                taken.push((along(p) - 2.0 * clear, along(p) + 2.0 * clear));
            }
        }
        // The letters of links lying along the bar, at their middles.
        for (p, r) in [(q.c, q.b), (q.b, q.a)] {
            if on_bar(p) && on_bar(r) {
                let x = along(mid(p, r));
                taken.push((x - 1.5 * clear, x + 1.5 * clear));
            }
        }
        let end = along(q.f);
        let free = |x: f64| taken.iter().all(|(lo, hi)| x < *lo || x > *hi);
        let usual = 0.85 * end;
        if free(usual) {
            return Some(q.t + q.u * usual);
        }
        // The runs between what is taken, the longest kept.
        let mut cuts: Vec<f64> = vec![0.0, end];
        cuts.extend(taken.iter().flat_map(|(lo, hi)| [*lo, *hi]));
        let mut cuts: Vec<f64> = cuts.into_iter().map(|x| x.clamp(0.0, end)).collect();
        cuts.sort_by(f64::total_cmp);
        (cuts.iter().copied())
            .zip(cuts.iter().copied().skip(1))
            .filter(|(lo, hi)| free(0.5 * (lo + hi)))
            .max_by(|x, y| (x.1 - x.0).total_cmp(&(y.1 - y.0)))
            .map(|run| q.t + q.u * (0.5 * (run.0 + run.1)))
    }

    /// The turning bar d lettered ([`Drawing::bar_letter`]); where no run
    /// of it is clear (the links along it at a dead centre on a small
    /// page), by the fixed bar's middle on the side of B's bearing,
    /// between the two bearings, the other side holding the links'
    /// letters and the pins' (at l = 1.07 r, 0° on a page of 420 every
    /// place along the bar stood within an em of one).
    fn letter_bar(&mut self) {
        if self.fixed == Link::D {
            return;
        }
        if let Some((at, way)) = self.bar_letter() {
            if !self.slotted() {
                // The hand pump's plunger, a line: its letter by it; where
                // the crank and the rod lie along it (a dead centre), on
                // the side away from the rod's letter ("d b" side by side
                // at l = 1.07 r, 0°).
                match self.letter_ways() {
                    (_, Some(rod)) if self.along_line() => {
                        let d = RichText::parse("*d*");
                        self.s
                            .label_toward("label-link-d", at, -rod, d, TextSize::Letter);
                    }
                    _ => self.s.letter("link-d", at, "*d*", TextSize::Letter),
                }
                return;
            }
            let hh = self.block.1;
            self.d_way = Some(way);
            let d = RichText::parse("*d*");
            self.s
                .label_toward("label-link-d", at + way * hh, way, d, TextSize::Letter);
            return;
        }
        let q = &self.q;
        let at = match self.fixed {
            Link::A => mid(q.c, q.b),
            _ => mid(q.b, q.a),
        };
        let (down, _) = self.b_foot.axes();
        // The page's y runs down, the world's up.
        let way = Vector::new(down.x, -down.y);
        self.d_way = Some(way);
        let d = RichText::parse("*d*");
        // From the bar's edge, as beside a clear run: tried from its
        // middle line, the first place out that way met the bar's edge,
        // and d went to the other side, by a's letter ("a d", l = 1.08 r,
        // 0°).
        let edge = at + way * self.block.1;
        self.s
            .label_toward("label-link-d", edge, way, d, TextSize::Letter);
    }

    /// The side of d's bar its letter at `at` (on the bar's middle line)
    /// stands on: away from the nearer of the crank's and the rod's
    /// middles, where their letters stand (inversion 2's default set d in
    /// the wedge between the bar and b, nearer b's line than d's edge).
    fn bar_letter_side(&self, at: Point) -> Vector {
        let q = &self.q;
        let (crank, rod) = (mid(q.c, q.b), mid(q.b, q.a));
        let near = match (crank - at).norm() < (rod - at).norm() {
            true => crank,
            false => rod,
        };
        if (near - at).dot(&q.v) > 0.0 {
            -q.v
        } else {
            q.v
        }
    }

    /// The segments of the links that move, which the fixed link's
    /// hatching keeps clear of.
    fn moving(&self) -> Vec<Seg> {
        let (c, b, a) = (self.q.c, self.q.b, self.q.a);
        let bar = self.bar();
        let corners = self.corners;
        let mut moving: Vec<Seg> = Vec::new();
        if self.fixed != Link::A {
            moving.push((c, b));
        }
        if self.fixed != Link::B {
            moving.push((b, a));
        }
        if self.slotted() {
            let outline = band(&self.q, self.block.1);
            let sides = outline.iter().zip(outline.iter().cycle().skip(1));
            moving.extend(sides.map(|(p, q)| (*p, *q)));
            moving.extend(band_fill(&self.q, self.block.1));
            moving.extend(self.kennedy.iter().copied());
        } else if self.fixed != Link::D {
            moving.extend(bar.iter().copied().zip(bar.iter().copied().skip(1)));
            // The normal at A (O_bd's line, O_cd's at infinity) and
            // Kennedy's lines run across the fixed barrel: the layout
            // opens the strokes they cross.
            let reach = self.q.v * (BARREL_REACH * self.block.1);
            moving.push((a - reach, a + reach));
            moving.extend(self.kennedy.iter().copied());
        }
        if self.fixed != Link::C {
            moving.extend(corners.into_iter().zip(corners.into_iter().cycle().skip(1)));
        }
        moving
    }

    /// The fixed crank, rod or block hatched, with its bearings (the
    /// fixed frame's hatching is its guides').
    fn hatch(&mut self) {
        let moving = self.moving();
        let (c, b, a) = (self.q.c, self.q.b, self.q.a);
        match self.fixed {
            Link::A => {
                // d turns about C: its bar leaves C along the leg (or the
                // arm, with no offset).
                let leg = if self.m.offset() == 0.0 {
                    self.q.f
                } else {
                    self.q.t + self.q.jog
                };
                let foot = self
                    .shown_foot(c, 0)
                    .unwrap_or_else(|| self.foot(c, &[b, leg]));
                self.s.bearing_on("C", c, foot);
                self.feet[0] = Some(foot);
                let foot = self
                    .shown_foot(b, 1)
                    .unwrap_or_else(|| self.foot(b, &[c, a]));
                self.s.bearing_on("B", b, foot);
                self.feet[1] = Some(foot);
                (self.b_foot, self.b_bearing) = (foot, true);
                let least = self.least_strokes();
                self.hatched =
                    (self.s).hatch_link_of_at_least("crank", (c, b), &moving, PIN_CLEAR, least);
            }
            Link::B => {
                let least = self.least_strokes();
                self.hatched =
                    (self.s).hatch_link_of_at_least("rod", (b, a), &moving, PIN_CLEAR, least);
                // The block's trunnion at A is a fixed pin as B is: the two
                // carry a bearing each or neither (O_ab's alone read as
                // the only fixed pin). Both where the rod is too little
                // hatched to show it fixed; else the hatching alone (at
                // most poses the bar about the block takes every side of
                // A, a base inside it read as a pin on d, and a bearing
                // beside it took the place of the block's letter, which
                // went into the bar: l = 1.05 r, 89.17°).
                let (u, lh) = (self.q.u, self.block.0);
                let at_b = self
                    .shown_foot(b, 0)
                    .unwrap_or_else(|| self.foot(b, &[c, a]));
                // The side of the bar the block's letter is tried on first
                // ([`Drawing::block_letter`]) is kept clear too.
                let v = self.q.v;
                let side = if self.normal.dot(&v) >= 0.0 { v } else { -v };
                let by = a + side * self.block.1;
                let at_a = (self.shown_foot(a, 1))
                    .unwrap_or_else(|| self.foot(a, &[b, a + u * lh, a - u * lh, by]));
                self.b_foot = at_b;
                self.feet = [Some(at_b), Some(at_a)];
                let hatched = (self.shown)
                    .and_then(|shown| shown.hatched)
                    .unwrap_or(self.hatched >= FIXED_STROKES);
                if !hatched {
                    self.s.bearing_on("B", b, at_b);
                    self.b_bearing = true;
                    self.s.bearing_on("A", a, at_a);
                    self.trunnion = Some(at_a);
                }
            }
            Link::C => {
                // The block is the fixed barrel: hatched on the face away from
                // the handle, or on the other where more strokes stand clear
                // of the links and of the normal at A across its middle, by
                // the fixed bars' rule ([`FIXED_STROKES`]): three strokes
                // on a barrel 24 units long were called hatched (l = 1.05 r,
                // 180°, 120 mm).
                let corners = self.corners;
                let (lower, upper) = ((corners[0], corners[1]), (corners[3], corners[2]));
                let faces = if self.q.v.dot(&(b - a)) > 0.0 {
                    [(lower, -self.q.v), (upper, self.q.v)]
                } else {
                    [(upper, self.q.v), (lower, -self.q.v)]
                };
                let count = |s: &mut Canvas, (edge, side): (Seg, Vector)| {
                    s.hatch_edge_of_at_least("block", edge, &[side], &moving, 0.0, usize::MAX)
                };
                let [away, other] = faces;
                let face = match count(&mut self.s, other) > count(&mut self.s, away) {
                    true => other,
                    false => away,
                };
                let least = self.least_strokes();
                self.hatched = (self.s).hatch_edge_of_at_least(
                    "block",
                    face.0,
                    &[face.1],
                    &moving,
                    0.0,
                    least,
                );
                // Too short or too crossed to hatch: the barrel's pin A
                // carries a bearing, as a fixed bar's pins do, so that
                // the fixed link shows fixed (at l = 52.6 r, 60° it was
                // neither hatched nor grounded).
                if self.hatched < least {
                    let (u, lh) = (self.q.u, self.block.0);
                    let mut meeting = vec![b, a + u * lh, a - u * lh];
                    if self.normal != Vector::zeros() {
                        meeting.push(a + self.normal);
                    }
                    let foot = self.foot(a, &meeting);
                    self.s.bearing_on("A", a, foot);
                }
            }
            Link::D => {}
        }
    }

    /// The crank, the rod and the block, lettered a, b and c; where d is
    /// a slotted bar in the inversion's own figure, c out of the bar by
    /// the block ([`Drawing::block_letter`], `normal` the way the normal
    /// at A is drawn): in the bar's empty end beyond the block it named
    /// the bar; left to the detail where it holds A.
    fn links(&mut self, normal: Vector) {
        let (c, b, a) = (self.q.c, self.q.b, self.q.a);
        let corners = self.corners;
        let s = &mut self.s;
        s.link("crank", vec![c, b]);
        s.link("rod", vec![b, a]);
        s.push(
            "block-slider",
            Role::Link,
            Shape::Block {
                points: corners.to_vec(),
            },
        );
        let (crank_way, rod_way) = self.letter_ways();
        let (crank_run, rod_run) = (self.letter_run((c, b)), self.letter_run((b, a)));
        if !self.held(mid(c, b)) {
            self.s
                .link_letter_toward("link-a", crank_run, "*a*", crank_way);
        }
        self.s.link_letter_toward("link-b", rod_run, "*b*", rod_way);
        let v = self.q.v;
        if self.held(self.q.a) {
            // The detail letters the block where it enlarges it: here, by
            // pins a few units apart, c stood in d's bar beside the block
            // (l = 1.02 r, 180°).
            return;
        }
        if self.slotted() {
            let (at, out) = self.block_letter(normal);
            if out != self.q.u {
                self.pin_a_way = Some(-out - self.q.u);
            }
            let c = RichText::parse("*c*");
            self.s
                .label_toward("label-link-c", at, out, c, TextSize::Letter);
            return;
        }
        let s = &mut self.s;
        let at = if self.fixed == Link::D {
            // Below the block, between the guides' hatching.
            mid(corners[0], corners[1]) - v * s.world(4.0)
        } else {
            // At its far end, clear of the normal at A.
            mid(corners[1], corners[2]) + self.q.u * s.world(4.0)
        };
        s.letter("link-c", at, "*c*", TextSize::Letter);
    }

    /// The lines a link's letter keeps its distance from where they
    /// cross the link: the crank and the rod, d's bar (its outline where
    /// it is slotted) and the block's sides.
    fn crossing_lines(&self) -> Vec<Seg> {
        let (c, b, a) = (self.q.c, self.q.b, self.q.a);
        let mut lines: Vec<Seg> = vec![(c, b), (b, a)];
        let outline = |points: &[Point], closed: bool| -> Vec<Seg> {
            let next = points.iter().copied().cycle().skip(1);
            let sides = points.iter().copied().zip(next);
            sides.take(points.len() - usize::from(!closed)).collect()
        };
        if self.slotted() {
            lines.extend(outline(&band(&self.q, self.block.1), true));
        } else if self.fixed != Link::D {
            lines.extend(outline(&self.bar(), false));
        }
        lines.extend(outline(&self.corners, true));
        lines
    }

    /// The part of the link `p q` whose middle its letter is set by: the
    /// whole link where its middle stands [`LETTER_RUN_CLEAR`] along it
    /// from its pins, from the centres' dots on it (within
    /// [`ON_LINE`]) and from every line crossing it
    /// ([`Drawing::crossing_lines`]); else the widest stretch between two
    /// of these, where that leaves more room. A letter over a dot on the
    /// link read as the dot's ("O_ac b", b over O_ac's dot, inversion 4
    /// at l = 2.4 r, e = 1.11 r, 180°), and one by a crossing as the
    /// crossing line's (b by d's leg, l = 2.88 r, e = 1.19 r).
    fn letter_run(&self, (p, q): Seg) -> Seg {
        if !self.runs {
            return (p, q);
        }
        let map = *self.s.transform();
        let (from, to) = (map.apply(p), map.apply(q));
        let length = (to - from).norm();
        let Some(u) = unit(to - from) else {
            return (p, q);
        };
        let n = Vector::new(-u.y, u.x);
        let inside = |s: f64| s > 0.0 && s < length;
        let mut stops = vec![0.0, length];
        for x in self.dots.iter().map(|x| map.apply(*x)) {
            let (s, d) = ((x - from).dot(&u), (x - from).dot(&n));
            if d.abs() <= ON_LINE && inside(s) {
                stops.push(s);
            }
        }
        for (r, t) in self.crossing_lines() {
            let (r, t) = (map.apply(r), map.apply(t));
            let w = t - r;
            let across = u.x * w.y - u.y * w.x;
            if across.abs() < 1e-9 * w.norm() {
                continue;
            }
            let k = r - from;
            // Along the link to the crossing, and along r t.
            let s = (k.x * w.y - k.y * w.x) / across;
            let h = (k.x * u.y - k.y * u.x) / across;
            if (0.0..=1.0).contains(&h) && inside(s) {
                stops.push(s);
            }
        }
        stops.sort_by(f64::total_cmp);
        let middle = length / 2.0;
        let nearest = (stops.iter())
            .map(|s| (s - middle).abs())
            .fold(f64::INFINITY, f64::min);
        if nearest >= LETTER_RUN_CLEAR {
            return (p, q);
        }
        let widest = (stops.windows(2))
            .filter_map(|w| Some((*w.first()?, *w.get(1)?)))
            .max_by(|x, y| (x.1 - x.0).total_cmp(&(y.1 - y.0)));
        match widest {
            Some((lo, hi)) if (hi - lo) / 2.0 > nearest => {
                let at = |s: f64| p + (q - p) * (s / length);
                (at(lo), at(hi))
            }
            _ => (p, q),
        }
    }

    /// Whether the crank and the rod lie along one line (within
    /// [`ALONG_LINE`]: a dead centre).
    fn along_line(&self) -> bool {
        let (c, b, a) = (self.q.c, self.q.b, self.q.a);
        match (unit(b - c), unit(a - b)) {
            (Some(crank), Some(rod)) => crank.dot(&rod).abs() >= ALONG_LINE.cos(),
            _ => false,
        }
    }

    /// The sides the crank's and the rod's letters are tried on first
    /// where the two lie along one line (within [`ALONG_LINE`], a dead
    /// centre): in inversion 4 on its two sides ("b a" read as one word
    /// at l = 1.05 r, 180°), in inversions 2 and 3 both on the side of
    /// d's bar away from d's letter ("a d" at l = 1.08 r, 0°); where they
    /// make a narrow wedge at B (within [`WEDGE`]), each outside it; none
    /// elsewhere.
    fn letter_ways(&self) -> (Option<Vector>, Option<Vector>) {
        let (c, b, a) = (self.q.c, self.q.b, self.q.a);
        let (Some(crank), Some(rod)) = (unit(b - c), unit(a - b)) else {
            return (None, None);
        };
        let cos = crank.dot(&rod).abs();
        if cos < WEDGE.cos() {
            return (None, None);
        }
        if cos < ALONG_LINE.cos() {
            // A narrow wedge at B: each letter outside it, on the side of
            // its link away from the other link's far pin ("a b" side by
            // side in the wedge named neither, inversion 3 at l = 1.07 r,
            // 89.24°).
            let away = |u: Vector, other: Point, on: Point| {
                let n = Vector::new(-u.y, u.x);
                if (other - on).dot(&n) > 0.0 { -n } else { n }
            };
            return (Some(away(crank, a, b)), Some(away(rod, c, b)));
        }
        let n = Vector::new(-rod.y, rod.x);
        match self.d_way {
            Some(d) if self.slotted() => {
                let away = if d.dot(&n) > 0.0 { -n } else { n };
                (Some(away), Some(away))
            }
            _ => (Some(-n), Some(n)),
        }
    }

    /// Where the block c riding in d's slot is lettered, and the way
    /// tried first: beyond its far end where it rides at the bar's end
    /// ([`AT_BAR_END`]); else beside its far end, out of the bar, on the
    /// side away from the bearing at A if any, else on the side of
    /// `normal` (the way the normal at A is drawn: a thin line at the
    /// block's middle, clear of a letter by its far end), so that O_bc's
    /// letter, tried first on the other side towards C, stands apart
    /// (on one side the two read as one label, "O_bc c").
    fn block_letter(&self, normal: Vector) -> (Point, Vector) {
        let (q, (lh, hh)) = (&self.q, self.block);
        let beyond = (q.f - q.a).dot(&q.u) - lh;
        if self.s.page(beyond) < AT_BAR_END {
            return (q.a + q.u * lh, q.u);
        }
        let map = *self.s.transform();
        let away = match self.trunnion {
            Some(foot) => -foot.axes().0.dot(&map.apply_vector(q.v)),
            None => normal.dot(&q.v),
        };
        let out = if away >= 0.0 { q.v } else { -q.v };
        (q.a + q.u * (BLOCK_LETTER_ALONG * lh) + out * hh, out)
    }

    /// Kennedy's lines that find O_bd (on CB and the normal at A) and O_ac
    /// (on AB and the normal at C).
    fn kennedy(&mut self, o_bd: Intersection, o_ac: Intersection) {
        let (c, b, a) = (self.q.c, self.q.b, self.q.a);
        if let Intersection::Point(d) = o_bd {
            // Off the page, both lines stop short of the edge, where
            // O_bd's arrow ("to O_bd", on CB produced) and O_cd's continue
            // them: CB produced ran on to the edge past the arrow's head.
            let from = if (d - b).dot(&(b - c)) >= 0.0 { b } else { c };
            let end = self.short_of_edge(from, d);
            produced(&mut self.s, "line-CB-O-bd", c, b, end);
            let end = self.short_of_edge(a, d);
            self.s.segment("line-A-O-bd", Role::Auxiliary, a, end);
        }
        if let Intersection::Point(x) = o_ac {
            produced(&mut self.s, "line-AB-O-ac", a, b, x);
            if let Some((from, to)) = normal_at_c(c, b, x) {
                self.s.segment("line-C-O-ac", Role::Auxiliary, from, to);
            }
        }
    }

    /// The end of a line from `from` towards `to`: `to` on the page, else
    /// [`EDGE_ROOM`] short of the page's edge (at most halfway back),
    /// where an arrow at the edge continues it.
    fn short_of_edge(&self, from: Point, to: Point) -> Point {
        let shown = *self.s.frame();
        match shown.clip_segment(from, to) {
            Some((_, edge)) if !shown.contains(to) && (edge - from).norm() > 0.0 => {
                let u = (edge - from).normalize();
                let back = self.s.world(EDGE_ROOM).min(0.5 * (edge - from).norm());
                edge - u * back
            }
            _ => to,
        }
    }

    /// The six centres and Kennedy's lines: the pins lettered as the
    /// centres they are, then O_bd, O_ac and O_cd (an arrow for one at
    /// infinity). Returns the notes' sentences for a centre drawn on a
    /// pin or another centre, named there instead of lettered on top.
    fn centres(&mut self, centres: &ChainCentres) -> Vec<String> {
        // cannot fail: it is asked only for pairs of distinct links below.
        #[allow(clippy::expect_used)]
        let get = |p: Link, q: Link| centres.centre(p, q).expect("distinct links");
        let o_bd = get(Link::B, Link::D);
        self.kennedy(o_bd, get(Link::A, Link::C));
        let (c, b, a) = (self.q.c, self.q.b, self.q.a);
        // The pins are three of the six centres, lettered as such: C = O_ad,
        // B = O_ab, A = O_bc (the notes give the letters of Figs. 62–67).
        let pins = [(c, "*O*_{ad}"), (b, "*O*_{ab}"), (a, "*O*_{bc}")];
        for ((p, markup), key) in pins.into_iter().zip(["C", "B", "A"]) {
            let way = self.pin_a_way.filter(|_| key == "A" && self.s.contains(p));
            if self.held(p) {
                self.s.record(key, p);
                self.s
                    .push(format!("point-{key}"), Role::Link, Shape::Pin { centre: p });
            } else if let Some(way) = way {
                self.s
                    .push(format!("point-{key}"), Role::Link, Shape::Pin { centre: p });
                let text = RichText::parse(markup);
                self.s
                    .label_toward(format!("label-{key}"), p, way, text, TextSize::Letter);
            } else {
                self.s.lettered(key, p, markup, Marker::Pin, c);
            }
        }
        // O_cd lies on the normal at A, as O_bd does: its arrow continues
        // the line A O_bd.
        let towards_d = match o_bd {
            Intersection::Point(d) => d - a,
            _ => Vector::zeros(),
        };
        let mut lettered: Vec<(Point, &str)> = pins.to_vec();
        let mut together: Vec<String> = Vec::new();
        // O_cd's line, the normal at A, is drawn as far as O_bd already.
        let drawn_to = match o_bd {
            Intersection::Point(d) if self.s.contains(d) => Some(d),
            _ => None,
        };
        let far = [
            ("O-bd", "*O*_{bd}", o_bd, b, b - c, None),
            ("O-ac", "*O*_{ac}", get(Link::A, Link::C), b, b - a, None),
            (
                "O-cd",
                "*O*_{cd}",
                get(Link::C, Link::D),
                a,
                towards_d,
                drawn_to,
            ),
        ];
        // The arrows at the edge, known before any is lettered: each
        // letter stands on the side of its arrow away from the others.
        let arrows: Vec<(Point, Vector)> = (far.iter())
            .filter_map(|&(_, _, centre, from, along, _)| self.edge_ray(centre, from, along))
            .filter_map(|(from, u)| Some((self.arrow_tail(from, u)?, u)))
            .collect();
        for (key, markup, centre, from, along, drawn) in far {
            match centre {
                Intersection::Point(p) if self.s.contains(p) => {
                    self.centre(key, markup, p, from, &mut lettered, &mut together)
                }
                Intersection::Point(_) | Intersection::AtInfinity(_) => {
                    let Some(ray) = self.edge_ray(centre, from, along) else {
                        continue;
                    };
                    // An off-page centre's arrow is "to" it; one at
                    // infinity's is it, its line dashed up to the arrow.
                    if let Intersection::Point(p) = centre {
                        let text = format!("to {markup}");
                        self.edge_lettered(&format!("offpage-{key}"), key, ray, &text, &arrows);
                        lettered.push((p, markup));
                    } else {
                        let text = format!("{markup} at ∞");
                        let id = format!("infinity-{key}");
                        if let Some(tail) = self.edge_lettered(&id, key, ray, &text, &arrows) {
                            self.line_to_infinity(key, from, tail, drawn);
                        }
                    }
                }
                Intersection::Coincident => {}
            }
        }
        together
    }

    /// The ray from `from` on which an arrow at the frame's edge shows
    /// `centre`: towards it where it is a point off the page, along its
    /// direction ([`Drawing::towards`], `along`) where it is at infinity;
    /// none for a centre on the page, or where no arrows are drawn.
    fn edge_ray(
        &self,
        centre: Intersection,
        from: Point,
        along: Vector,
    ) -> Option<(Point, Vector)> {
        if !self.edge_arrows {
            return None;
        }
        let u = match centre {
            Intersection::Point(p) if !self.s.contains(p) => p - from,
            Intersection::AtInfinity(dir) => self.towards(dir.into_inner(), from, along),
            _ => return None,
        };
        Some((from, unit(u)?))
    }

    /// The tail of the arrow at the frame's edge on the ray from `from`
    /// along the unit `u`, where the arrow fits between `from` and the
    /// edge.
    fn arrow_tail(&self, from: Point, u: Vector) -> Option<Point> {
        let (_, edge) = self.s.frame().clip_ray(from, u)?;
        let tail = edge - u * self.s.world(EDGE_GAP + EDGE_ARROW);
        ((tail - from).dot(&u) >= 0.0).then_some(tail)
    }

    /// The arrow `id` at the frame's edge on the ray `(from, u)`, lettered
    /// `text` (`label-{key}`) by its tail, where it leaves the figure, on
    /// the side away from the nearest other of the `arrows` (tails and
    /// directions), else from the pins: by its middle, as a line's name,
    /// "O_cd at ∞" stood between two slanting arrows (inversion 3 at
    /// l = 1.07 r, 90.03°); between two, "to O_bd" and "O_cd at ∞" ran
    /// together as one label (l = 2.36 r, e = 1.14 r, 269.57°); beside a
    /// lone arrow up from O_ad, "to O_bd" stood on the line of d's leg
    /// produced (inversion 4 at l = 2.69 r, e = −1.01 r, 269.36°).
    /// Returns the tail; none where the arrow does not fit.
    fn edge_lettered(
        &mut self,
        id: &str,
        key: &str,
        (from, u): (Point, Vector),
        text: &str,
        arrows: &[(Point, Vector)],
    ) -> Option<Point> {
        let tail = self.arrow_tail(from, u)?;
        let (_, edge) = self.s.frame().clip_ray(from, u)?;
        let n = crate::geom::perp(&u);
        let apart = |p: &Point| (p - tail).norm();
        let other = (arrows.iter())
            .map(|(t, _)| *t)
            .filter(|t| self.s.page(apart(t)) > 1.0)
            .min_by(|p, q| apart(p).total_cmp(&apart(q)));
        let pins = Point::from((self.q.c.coords + self.q.b.coords + self.q.a.coords) / 3.0);
        // Across its arrow from the other's tail; where the two lie on
        // one line, away from the pins.
        let away = (other.map(|t| n.dot(&(tail - t))))
            .filter(|s| self.s.page(s.abs()) >= 1.0)
            .unwrap_or_else(|| n.dot(&(tail - pins)));
        let side = if away < 0.0 { -n } else { n };
        // Beside the line [`SET_BACK`] behind the tail: square to the
        // tail itself, a letter by an arrow near the page's edge ran off
        // it and was set anywhere (between two arrows at l = 2.36 r).
        // No farther back than where the line leaves the block about its
        // start (a short arrow from A: set back to A, the letter stood by
        // the block, and across it from its arrow at l = 45 r, 0°), nor
        // than the line's start (a short arrow from B); where that leaves
        // less than SET_BACK before the tail, by the middle of the
        // arrow's run past the block, the letter beside its arrow on the
        // arrow's side of the block.
        let along = |p: &Point| (p - from).dot(&u);
        let clear = if inside_outline(&self.corners, from) {
            (self.corners.iter()).map(along).fold(0.0, f64::max)
        } else {
            0.0
        };
        let (to_tail, to_edge) = (along(&tail), along(&edge));
        let back = self.s.world(SET_BACK);
        let at = if to_tail - back >= clear || clear >= to_edge {
            tail - u * back.min(to_tail)
        } else {
            // No farther than the arrow's middle: a letter by its head
            // half reads as naming where it points.
            let middle = (to_tail + to_edge - self.s.world(EDGE_GAP)) / 2.0;
            from + u * ((clear + to_edge) / 2.0).min(middle)
        };
        self.s.edge_arrow(id.to_string(), edge, u, EDGE_ARROW);
        let text = RichText::parse(text);
        self.s
            .label_toward(format!("label-{key}"), at, side, text, TextSize::Letter);
        Some(tail)
    }

    /// The line on which a centre at infinity lies, dashed from `from` to
    /// its arrow's `tail`, so that the arrow never stands alone; where the
    /// line is `drawn` already from `from` to a point towards the arrow, it
    /// is continued from there (O_cd's normal at A beyond O_bd).
    fn line_to_infinity(&mut self, key: &str, from: Point, tail: Point, drawn: Option<Point>) {
        let start = match drawn {
            Some(d) if (d - from).dot(&(tail - from)) > 0.0 => d,
            _ => from,
        };
        if (tail - start).dot(&(tail - from)) > 0.0 {
            self.s.segment(
                format!("line-{key}-at-infinity"),
                Role::Auxiliary,
                start,
                tail,
            );
        }
    }

    /// The centre `p` lettered `markup` from the side of `from`, or, on
    /// the page within [`CROWDED`] of a centre `lettered` already, a dot
    /// named in `together` instead.
    fn centre<'m>(
        &mut self,
        key: &str,
        markup: &'m str,
        p: Point,
        from: Point,
        lettered: &mut Vec<(Point, &'m str)>,
        together: &mut Vec<String>,
    ) {
        let map = *self.s.transform();
        // The nearest of those within CROWDED on the page (a long rod's
        // crank is a few units: O_ac at O_ab was said to lie "0.9995 from
        // O_ad", the first found).
        let apart = |q: &Point| map.apply_vector(p - q).norm();
        let near = (lettered.iter())
            .filter(|(q, _)| apart(q) < CROWDED)
            .min_by(|(q, _), (s, _)| apart(q).total_cmp(&apart(s)));
        match near {
            Some(&(q, other)) if self.s.contains(p) => {
                let (r, l, e) = (self.m.crank(), self.m.rod(), self.m.offset());
                together.push(where_near(markup, p, other, q, r + l + e.abs()));
                self.s.push(
                    format!("centre-{key}"),
                    Role::Construction,
                    Shape::Dot { centre: p },
                );
            }
            _ => {
                // A centre in d's body (O_ac where b crosses d's leg) or
                // on a moving link (O_ac on b beside the leg set off C T)
                // is drawn over them: under them, the tone and b's rim hid
                // it.
                let in_body = self.slotted() && inside_outline(&band(&self.q, self.block.1), p);
                let on_link = [(self.q.c, self.q.b), (self.q.b, self.q.a)]
                    .into_iter()
                    .any(|(x, y)| point_segment_distance(p, x, y) <= self.s.world(ON_LINK));
                let marker = if in_body || on_link {
                    Marker::DotOver
                } else {
                    Marker::Dot
                };
                self.s.lettered(key, p, markup, marker, from);
                lettered.push((p, markup));
            }
        }
    }

    /// The direction `u` of a centre at infinity seen from `from`: along
    /// `along`, or where `along` is zero (the normal at A with no O_bd to
    /// follow), the way with the longer run on the page.
    fn towards(&self, u: Vector, from: Point, along: Vector) -> Vector {
        let mut u = u;
        if u.dot(&along) < 0.0 {
            u = -u;
        }
        if along == Vector::zeros() {
            let shown = *self.s.frame();
            let room = |w: Vector| shown.clip_ray(from, w).map_or(0.0, |(p, q)| (q - p).norm());
            if room(-u) > room(u) {
                u = -u;
            }
        }
        u
    }
}

/// The notes: the inversion's title ([`titled`]), the pose and the mechanism, the quick
/// return's time ratio where there is one and the centres drawn together,
/// then the pins' letters and Kennedy's theorem.
fn notes(ctx: &Ctx, chain: &InvertedChain, together: &[String], hatched: usize) -> [String; 3] {
    let m = &ctx.mechanism;
    let (r, l, e) = (m.crank(), m.rod(), m.offset());
    let mut line = format!(
        "The crank *a* at θ = {}° to {}; *r* = {}, *l* = {}{}. {}",
        short(ctx.angle.degrees()),
        // d is the engine's frame, fixed only in the first inversion.
        match chain.inversion() {
            Inversion::Frame => "the frame *d*",
            _ => "*d* (the engine’s frame, here moving)",
        },
        short(r),
        short(l),
        if e == 0.0 {
            String::new()
        } else {
            format!(", *e* = {}", short(e))
        },
        fixed_shown(chain.inversion(), hatched),
    );
    if let Some(ratio) = chain.time_ratio() {
        line.push_str(&format!(
            " Time ratio of the quick return {}.",
            printed(ratio)
        ));
    }
    if !together.is_empty() {
        line.push_str(&format!(" Here {}.", together.join("; ")));
    }
    [
        titled(chain.inversion()),
        line,
        "The pins *O*_{ad}, *O*_{ab}, *O*_{bc} are *C*, *B*, *A* of Figs. 62–67; by Kennedy’s theorem *O*_{bd} on *O*_{ad}*O*_{ab} and on the normal to the stroke at *O*_{bc}, *O*_{ac} on *O*_{ab}*O*_{bc} and on the normal at *O*_{ad}.".to_string(),
    ]
}

/// How the notes say the fixed link is shown: hatched, or, for a fixed
/// bar with fewer than [`FIXED_STROKES`] strokes of hatching (`hatched`,
/// the bar lying in d's slot or short), by the bearings at its two pins.
fn fixed_shown(inversion: Inversion, hatched: usize) -> String {
    let pins = match inversion {
        Inversion::Crank => "*O*_{ad} and *O*_{ab}",
        Inversion::Rod => "*O*_{ab} and *O*_{bc}",
        Inversion::Frame => return "The fixed link is hatched.".to_string(),
        Inversion::Slider if hatched >= FIXED_STROKES => {
            return "The fixed link is hatched.".to_string();
        }
        Inversion::Slider => {
            return "The fixed link *c*, the barrel *d* slides in, too short or too crossed here to hatch, is shown fixed by the bearing at its pin *O*_{bc}."
                .to_string();
        }
    };
    if hatched >= FIXED_STROKES {
        return "The fixed link is hatched.".to_string();
    }
    format!(
        "The fixed link *{}*, too short or too near the moving links here to hatch, is shown fixed by the bearings at its pins {pins}.",
        letter(inversion.fixed())
    )
}

/// The line `p q` produced to `x` on it, from whichever of p and q is
/// nearer; nothing when x lies between them (the link itself shows it).
fn produced(s: &mut Canvas, id: &str, p: Point, q: Point, x: Point) {
    if let Some((from, x)) = produced_seg(p, q, x) {
        s.segment(id, Role::Auxiliary, from, x);
    }
}

/// The segment of the line `p q` produced to `x` ([`produced`]): from
/// the nearer of p and q to x; none when x lies between them.
fn produced_seg(p: Point, q: Point, x: Point) -> Option<Seg> {
    let along = (x - p).dot(&(q - p)) / (q - p).norm_squared();
    if (0.0..=1.0).contains(&along) {
        return None;
    }
    Some((if along > 1.0 { q } else { p }, x))
}

/// The normal at C to O_ac at `x` as drawn: from C, or where it runs
/// along the crank C B (within [`ALONG_LINE`]), the crank produced to
/// `x` (none where `x` lies by the crank): drawn from C beside the crank
/// it read as a doubled stroke on it (inversion 4 at l = 1.05 r,
/// 269.11°, O_ac 0.05 r from B).
fn normal_at_c(c: Point, b: Point, x: Point) -> Option<Seg> {
    match (unit(x - c), unit(b - c)) {
        (Some(n), Some(crank)) if n.dot(&crank) >= ALONG_LINE.cos() => produced_seg(c, b, x),
        _ => Some((c, x)),
    }
}

/// Kennedy's lines as [`Drawing::kennedy`] draws them (up to the
/// centres, not short of the page's edge): CB produced and the normal at
/// A to O_bd, AB produced and the normal at C to O_ac.
fn kennedy_lines(q: &Parts, centres: &ChainCentres) -> Vec<Seg> {
    let (c, b, a) = (q.c, q.b, q.a);
    let mut lines = Vec::new();
    if let Some(Intersection::Point(d)) = centres.centre(Link::B, Link::D) {
        lines.extend(produced_seg(c, b, d));
        lines.push((a, d));
    }
    if let Some(Intersection::Point(x)) = centres.centre(Link::A, Link::C) {
        lines.extend(produced_seg(a, b, x));
        lines.extend(normal_at_c(c, b, x));
    }
    lines
}

#[cfg(test)]
mod tests {
    use super::printed;

    #[test]
    fn computed_values_print_to_three_figures() {
        assert_eq!(printed(0.000_178_3), "1.78×10⁻⁴");
        assert_eq!(printed(0.005_592), "5.59×10⁻³");
        assert_eq!(printed(0.031_11), "0.0311");
        assert_eq!(printed(7.111), "7.11");
        assert_eq!(printed(1.502), "1.5");
        assert_eq!(printed(9.996), "10");
        assert_eq!(printed(0.0), "0");
        assert_eq!(printed(f64::NAN), "0");
    }
}
