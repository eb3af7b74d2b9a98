//! The polar load diagram of the crank pin (`docs/dynamics.md` §3): the
//! force of the rod on the crank pin over the gas force's cycle, the
//! vector's end traced from a pole, with the rod's inertia (full line)
//! and without it (dashed): (a) in fixed axes, which with the crank
//! massless is also the load on the main bearing; (b) relative to the
//! crank, along it (outwards) and across it (in the sense of rotation),
//! the load the crank pin carries where it turns with the crank.
//!
//! The engine is the turning-moment figure's ([`super::turning::engine`]:
//! its mass, gas force or indicator diagram) with an illustrative rod of
//! mass 0.6 m, its centre of mass l/3 from the crank pin and its radius of
//! gyration 0.3 l. Every value is
//! [`crate::dynamics::EngineLoads::crank_pin`] of
//! [`crate::dynamics::Engine::at_turn`]. x runs from the crank centre
//! towards the slider. Each curve's points at 0°, 90°, 180° and 270° are
//! marked and lettered (one dot and letter where the two curves' meet),
//! the other points every 30° marked where they stand clear of every
//! mark and of the pole: where a curve lingers, as about the pole at long
//! and short rods, its dots would pile into a blob.

use super::load_letters::Letters;
use super::{Ctx, Sheet, short};
use crate::angle::Angle;
use crate::diagram::{Curve, Plot};
use crate::dynamics::{EXAMPLE_MASS, Engine, RodMass, TurningMoment};
use crate::error::{Error, Field, Input, Result, Wording};
use crate::figure::{Dash, Figure, Item, RichText, Role, Shape, Symbol, TextSize};
use crate::geom::{Frame, Point, Vector, cross, perp, unit};

/// The illustrative rod's mass per unit reciprocating mass.
pub(crate) const ROD_MASS: f64 = 0.6;
/// Its centre of mass from the crank pin per unit rod length.
pub(crate) const ROD_CG: f64 = 1.0 / 3.0;
/// Its radius of gyration about the centre of mass per unit rod length.
pub(crate) const ROD_GYRATION: f64 = 0.3;

/// The angle between marked points, degrees.
const MARK: f64 = 30.0;

/// How far inside a piece its ends are evaluated, degrees: the gas force
/// jumps at the dead centres and each end takes its own side.
const INSIDE: f64 = 1e-7;

/// Height of the notes' band.
const NOTES: f64 = 72.0;

/// The least distance, page units, between two marks' centres, and from
/// an unlettered mark to the pole: two and a half dots' diameters, and
/// more than a letter's em, so that the layout keeps each letter nearer
/// its own mark than any other.
pub(crate) const APART: f64 = 18.0;

/// Quarters whose points are nearer than this, page units, are one
/// place, marked by one dot lettered with both ("0°, 180°"): a dot's
/// diameter, so that the two dots would overlap. Farther apart, each has
/// its own dot and letter, however near: one letter for two points
/// apart reads as one load at both angles.
pub(crate) const MEET: f64 = 4.0;

/// The shortest scale bar, page units: as long as its text.
const BAR_TEXT: f64 = 84.0;
/// The least width of a panel set beside the other, page units: on a
/// narrower page (120 mm, 4.5 in) side by side the curves shrank to a
/// few ems under full-size letters and a bar three times the largest
/// load; there the panels stand one above the other.
const STACK_BELOW: f64 = 300.0;

/// Room below the curves for the scale bar and its text, page units.
const BAR_ROOM: f64 = 30.0;

/// How near the pole, page units, lettered marks crowd it: within two
/// ems, where a short rod's (l = 1.06 r) 0°, 180° and their primes, the
/// pole's × and *O* piled into a knot a few millimetres wide, a leader
/// across *O* (the eleventh review).
const CROWD: f64 = 30.0;

/// How many lettered marks within [`CROWD`] of the pole crowd it (with
/// the pole's own letter, three letters in two ems).
const CROWDED: usize = 2;

/// How many lettered marks, each within [`KNOT_REACH`] of another, are a
/// knot a detail enlarges wherever it stands ([`knots`]).
const KNOT: usize = 3;

/// Lettered marks (the pole among them) nearer each other than this,
/// page units, are in one knot: two ems, where three letters beside
/// three dots on crossing curves cannot each stand nearer its own (an em
/// and a fifth left the default engine's (a) without a detail, its
/// letters led across the curves about the pole: the fifteenth review).
const KNOT_REACH: f64 = CROWD;

/// A lettered mark this near the pole, page units, stands on its ×
/// (a dot's diameter): the pole is crowded by it and by the lettered
/// marks within [`ON_POLE_CROWD`] times [`CROWD`]. At r = 1, l = 2.97 r,
/// e = −1.2 r the dashed 270° lay on the × and 0°′ and 270° 32 units off
/// on the default page, just beyond [`CROWD`]: their letters led across
/// the curves in a tangle, while narrower pages, where the three stood
/// within it, enlarged them in a detail (the twelfth review).
const ON_POLE: f64 = 4.2;

/// How much farther than [`CROWD`] the marks crowd a pole a mark stands
/// on ([`ON_POLE`]).
const ON_POLE_CROWD: f64 = 1.5;

/// Room about the crowded marks in the region a detail enlarges, page
/// units of the panel: room for their letters.
const WINDOW_MARGIN: f64 = 10.0;

/// The least magnification worth a detail: less, and the knot stays one.
const LEAST_MAGNIFICATION: f64 = 2.0;

/// How far inside a detail's edge a mark is lettered there, page units
/// of the detail: nearer the edge its letter would leave the detail, and
/// the panel letters it (its dot outside the box as drawn there).
const EDGE: f64 = 16.0;

/// The largest size on the page of a detail, page units (its caption
/// included in the height).
const DETAIL: (f64, f64) = (300.0, 190.0);

/// Room above a detail, page units, between it and the panels.
const DETAIL_GAP: f64 = 16.0;

/// The two engines: with the rod asked for (each of its values not given
/// the illustrative rod's), and with a massless one.
fn engines(ctx: &Ctx) -> Result<(Engine, Engine)> {
    let bare = super::turning::engine(ctx)?;
    let l = ctx.mechanism.rod();
    let mass = bare.reciprocating_mass();
    let o = ctx.options;
    let rod = RodMass::new(
        o.rod_mass.unwrap_or(ROD_MASS * mass),
        o.rod_cg.unwrap_or(ROD_CG * l),
        o.rod_gyration.unwrap_or(ROD_GYRATION * l),
    )?;
    Ok((bare.clone().with_rod(rod)?, bare))
}

/// What the notes say of the rod's values in brackets after them: the
/// illustrative rod's ratios (" (0.6 times the reciprocating mass, l/3,
/// 0.3 l)"), those of the values not given where some are, nothing where
/// all are.
fn rod_said(ctx: &Ctx) -> String {
    let o = ctx.options;
    let own = [
        (o.rod_mass, "the mass 0.6 times the reciprocating mass"),
        (o.rod_cg, "the centre of mass *l*/3"),
        (o.rod_gyration, "the radius of gyration 0.3 *l*"),
    ];
    let left: Vec<&str> = own
        .iter()
        .filter(|(given, _)| given.is_none())
        .map(|(_, said)| *said)
        .collect();
    match left.len() {
        3 => " (0.6 times the reciprocating mass, *l*/3, 0.3 *l*)".into(),
        0 => String::new(),
        _ => format!(" ({}, the illustrative rod’s)", left.join(", ")),
    }
}

/// The crank-pin load of `engine` at `deg` degrees of its cycle, in fixed
/// axes, or relative to the crank when `relative`.
fn load(engine: &Engine, deg: f64, relative: bool) -> Option<Vector> {
    let angle = Angle::from_degrees(deg).ok()?;
    let at = engine.at_turn(angle, engine.turn_at_degrees(deg)).ok()?;
    let [x, y] = at.loads.crank_pin;
    if !relative {
        return Some(Vector::new(x, y));
    }
    let (s, c) = (angle.sin(), angle.cos());
    Some(Vector::new(x * c + y * s, -x * s + y * c))
}

pub(in crate::catalogue) fn build(ctx: &Ctx) -> Result<Figure> {
    let page = ctx.page();
    let (rod, bare) = engines(ctx)?;
    let tm = TurningMoment::new(&rod, &[0.0])?;
    let cycle = tm.cycle_deg;
    let mut kinks: Vec<f64> = tm.kinks_deg.clone();
    kinks.retain(|k| (0.0..=cycle).contains(k));
    kinks.extend([0.0, cycle]);
    kinks.sort_by(f64::total_cmp);
    kinks.dedup_by(|a, b| (*a - *b).abs() < 1e-9);
    let engines = [&rod, &bare];
    let samples = [false, true].map(|relative| sampled(engines, cycle, relative, 2.0));
    // Both panels to one scale: worlds of one size, each about its own
    // curves (and the pole).
    drawable(ctx, &samples)?;
    let boxes = samples.each_ref().map(|s| bounds(s));
    let size = boxes.iter().fold(Vector::zeros(), |a, (lo, hi)| {
        Vector::new(a.x.max(hi.x - lo.x), a.y.max(hi.y - lo.y))
    });
    let pad = 0.1 * size.x.max(size.y).max(f64::MIN_POSITIVE);
    // Side by side where each panel keeps [`STACK_BELOW`] units, else
    // (a) above (b), each the page's width.
    let half = 0.5 * (page.width() - 48.0);
    let stacked = half < STACK_BELOW;
    let (half, rows) = if stacked {
        (page.width() - 32.0, 2.0)
    } else {
        (half, 1.0)
    };
    let most = (page.height() - 16.0 - 16.0 - 16.0 - NOTES) / rows;
    // No legend: on a narrow page one set in a panel's free corner fell
    // on the curve and the scale bar; the notes say which curve is which.
    let tall = (half * (size.y + 2.0 * pad) / (size.x + 2.0 * pad) + crate::diagram::CAPTION)
        .clamp(160.0, most.max(160.0));
    let mut sheet = Sheet::new(ctx);
    sheet.mechanism(ctx, true, false);
    let mut bar = 0.0;
    // A detail's size: under its panel, or side by side under the
    // stacked panels.
    let detail_size = (
        DETAIL
            .0
            .min(if stacked { 0.5 * (half - 16.0) } else { half }),
        DETAIL.1,
    );
    let mut windows = Vec::new();
    let curves = samples.each_ref().map(|sampled| Curves {
        engines,
        sampled,
        kinks: &kinks,
        cycle,
    });
    // One scale for both panels: the width's, or on a low page the
    // height's with the bar's band and the longer caption's lines after
    // its first taken off (as a plot takes them off its area).
    let (wide, high) = (size.x + 2.0 * pad, size.y + 2.0 * pad);
    let extras = [false, true].map(|relative| {
        caption_extra(
            ctx,
            &panel_caption(
                relative,
                View::Whole {
                    detail: detail_size,
                },
            ),
            half,
        )
    });
    let lines = extras.iter().flatten().copied().fold(0.0, f64::max);
    let room = tall - crate::diagram::CAPTION - lines - BAR_ROOM;
    let scale = (half / wide).min(room.max(1.0) / high);
    let mut ends = [0.0; 2];
    let mut y = 16.0;
    let panels = [false, true].into_iter().zip(boxes).zip(&curves);
    for (k, ((relative, (lo, hi)), drawn)) in panels.enumerate() {
        let view = View::Whole {
            detail: detail_size,
        };
        // Each panel as high as its own curves (and, in (a), the bar
        // below them): a flat (a) drawn in a world as high as (b)'s
        // stood between wide empty bands (the fifteenth review).
        let below = if relative { 0.0 } else { BAR_ROOM / scale };
        let middle = 0.5 * (lo.x + hi.x);
        let room = pad.max(LETTER_ROOM / scale);
        let world = Frame::new(
            Point::new(middle - 0.5 * wide, lo.y - room - below),
            Point::new(middle + 0.5 * wide, hi.y + room),
        );
        let extra = caption_extra(ctx, &panel_caption(relative, view), half)?;
        let area = ((world.max().y - world.min().y) * scale).max(LEAST_AREA);
        let height = area + crate::diagram::CAPTION + extra;
        let rect = if stacked {
            Frame::from_origin_size(16.0, y, half, height)
        } else {
            Frame::from_origin_size(16.0 + k as f64 * (half + 16.0), 16.0, half, height)
        };
        y += height + 16.0;
        if let Some(end) = ends.get_mut(k) {
            *end = rect.min().y + height;
        }
        let (mut plot, window) = polar_plot(ctx, drawn, relative, rect, (&world, below), view)?;
        if !relative {
            bar = bar_length(largest_load(&samples), plot.map().scale());
            plot.push(scale_bar(ctx, &world, bar, pad, below, plot.map().scale()));
        }
        if let Some(w) = window {
            windows.push((k, relative, w));
        }
        sheet.plot(plot);
    }
    let layout = (stacked, half, ends);
    let end = details(ctx, &mut sheet, &curves, &windows, layout, detail_size)?;
    let [fixed, _] = &samples;
    let largest = [0, 1].map(|i| {
        fixed
            .iter()
            .filter_map(|p| p.get(i))
            .map(|v| v.norm())
            .fold(0.0, f64::max)
    });
    sheet.meta(
        "crank_pin_loads",
        serde_json::json!({
            "rod_mass": rod.rod().map(RodMass::mass),
            "rod_cg": rod.rod().map(RodMass::cg),
            "rod_gyration": rod.rod().map(RodMass::gyration),
            "largest_with_rod": largest[0],
            "largest_without_rod": largest[1],
            "cycle_deg": cycle,
            "bar": bar,
            "details": windows.iter().map(|(_, relative, w)| serde_json::json!({
                "panel": if *relative { "relative" } else { "fixed" },
                "magnification": w.magnification,
            })).collect::<Vec<_>>(),
        }),
    );
    let top = end + 8.0;
    sheet.height(top + NOTES + 16.0);
    // The dashed curve of (a) within an em of the *x* axis on the page:
    // it reads as lying on it, and the notes say why.
    let across = (fixed.iter())
        .filter_map(|p| p.get(1))
        .map(|v| v.y.abs())
        .fold(0.0, f64::max);
    let flat = across * scale < ctx.style.font_size(TextSize::Letter);
    sheet.notes(Point::new(20.0, top), &notes(ctx, &rod, largest, bar, flat));
    Ok(sheet.finish())
}

/// The loads of the two engines at `per_degree` samples a degree over
/// the cycle.
fn sampled(engines: [&Engine; 2], cycle: f64, relative: bool, per_degree: f64) -> Vec<[Vector; 2]> {
    let samples = (per_degree * cycle) as usize;
    (0..=samples)
        .filter_map(|i| {
            let d = (cycle * i as f64 / samples as f64).clamp(INSIDE, cycle - INSIDE);
            Some([
                load(engines[0], d, relative)?,
                load(engines[1], d, relative)?,
            ])
        })
        .collect()
}

/// Refuses loads too small or too large to draw (none at all, with no
/// mass and no gas force), naming the largest and what sets it: the
/// force scale of [`super::MIN_DRAWN_FORCE`] to [`super::MAX_DRAWN_FORCE`]
/// that every dynamics figure draws within.
fn drawable(ctx: &Ctx, samples: &[Vec<[Vector; 2]>; 2]) -> Result<()> {
    let largest = samples
        .iter()
        .flatten()
        .flatten()
        .map(|v| v.norm())
        .fold(0.0, f64::max);
    if (super::MIN_DRAWN_FORCE..=super::MAX_DRAWN_FORCE).contains(&largest) {
        return Ok(());
    }
    let f = ctx.units.force();
    Err(Error::refused(
        Input::Options,
        Wording::from(format!(
            "{} draws the crank pin's load, {} over the cycle here, which must lie between {} and {} {f} to be drawn: give the mass (",
            ctx.name.name(),
            if largest.is_finite() {
                format!("at most {} {f}", crate::number::plain(largest))
            } else {
                "beyond the largest number".to_string()
            },
            crate::number::plain(super::MIN_DRAWN_FORCE),
            crate::number::plain(super::MAX_DRAWN_FORCE),
        ))
        .option(Field::Mass)
        .then("), the gas force (")
        .option(Field::GasForce)
        .then(", ")
        .option(Field::Data)
        .then(", ")
        .option(Field::Bore)
        .then("), the lengths or the speed in other units"),
    ))
}

/// The smallest box holding the pole and every sampled load.
fn bounds(samples: &[[Vector; 2]]) -> (Point, Point) {
    let (mut lo, mut hi) = (Point::origin(), Point::origin());
    for v in samples.iter().flatten() {
        lo = Point::new(lo.x.min(v.x), lo.y.min(v.y));
        hi = Point::new(hi.x.max(v.x), hi.y.max(v.y));
    }
    (lo, hi)
}

/// The largest load of either curve in either panel (the size of the
/// vector, the same in both).
fn largest_load(samples: &[Vec<[Vector; 2]>; 2]) -> f64 {
    (samples.iter().flatten().flatten())
        .map(|v| v.norm())
        .fold(0.0, f64::max)
}

/// The force scale's bar for loads up to `largest` drawn at `scale` page
/// units to the force: the shortest round force ([`super::round_below`]'s
/// 1, 2, 2.5, 5 × 10ᵏ) as long as the bar's text, [`BAR_TEXT`], but
/// never longer than the largest load (the round force at or below it):
/// a bar three times the largest load dwarfed the curves it measures.
/// Where the loads are so small on the page that the largest is shorter
/// than the text, the bar is the largest round force and its text is
/// wider than it.
fn bar_length(largest: f64, scale: f64) -> f64 {
    let most = super::round_below(largest);
    let mut bar = super::round_below(BAR_TEXT / scale);
    while bar * scale < BAR_TEXT * (1.0 - 1e-9) && bar < most {
        bar = round_above(bar);
    }
    bar.min(most)
}

/// The next round force above the round force `bar` (1, 2, 2.5, 5 × 10ᵏ).
fn round_above(bar: f64) -> f64 {
    let decade = 10f64.powf(bar.log10().floor());
    [2.0, 2.5, 5.0, 10.0]
        .iter()
        .map(|s| s * decade)
        .find(|s| *s > bar * (1.0 + 1e-9))
        .unwrap_or(10.0 * decade)
}

/// The force scale's bar, `bar` long, at the lower left of `world`, in
/// the room `below` the curves: its middle at least half its text's
/// width in from the panel's edge, so that a bar shorter than its text
/// keeps the text in the panel.
fn scale_bar(ctx: &Ctx, world: &Frame, bar: f64, pad: f64, below: f64, scale: f64) -> Item {
    let left = (0.5 * BAR_TEXT / scale - 0.5 * bar).max(0.0);
    let from = Point::new(
        world.min().x + 0.5 * pad + left,
        world.min().y + 0.25 * below,
    );
    let text = format!("{} {}", short(bar), ctx.units.force());
    super::scale_bar("fixed-bar", from, bar, &text)
}

/// The polar curve of the load between the kinks `a` and `b` (degrees),
/// its ends a little inside, its tangent by central differences kept
/// inside the piece.
fn piece<'a>(engine: &'a Engine, relative: bool, a: f64, b: f64) -> impl Curve + 'a {
    move |deg: f64| -> Option<(Point, Vector)> {
        let d = deg.clamp(a + INSIDE, b - INSIDE);
        let h = 1e-4f64.min(0.25 * (b - a));
        let (lo, hi) = ((d - h).max(a + INSIDE), (d + h).min(b - INSIDE));
        let v = load(engine, d, relative)?;
        let slope = (load(engine, hi, relative)? - load(engine, lo, relative)?) / (hi - lo);
        Some((Point::origin() + v, slope))
    }
}

/// The curves a panel draws: the two engines (with the rod's inertia and
/// without it), their loads sampled, the cycle's kinks and its length
/// (degrees).
#[derive(Clone, Copy)]
struct Curves<'a> {
    engines: [&'a Engine; 2],
    sampled: &'a [[Vector; 2]],
    kinks: &'a [f64],
    cycle: f64,
}

/// What a panel shows.
#[derive(Clone, Copy)]
enum View {
    /// The whole of both curves; where the lettered marks crowd about the
    /// pole, the region about it left to a detail of `detail` (width,
    /// height with its caption, page units): its marks drawn, lettered
    /// there, and the region boxed.
    Whole { detail: (f64, f64) },
    /// The detail of a panel's region about the pole ([`Window`]).
    Detail(Window),
}

/// The region about the pole a panel leaves to a detail: the region
/// (world), the part of it whose marks the detail letters, and its
/// magnification over the panel.
#[derive(Clone, Copy)]
struct Window {
    region: Frame,
    core: Frame,
    magnification: f64,
}

/// The window about the pole of a panel at `scale` page units to the
/// force whose marks are `taken`, for a detail of `size` (page units,
/// its caption included): where [`CROWDED`] lettered marks or more lie
/// within [`CROWD`] of the pole (or, one on the pole, [`ON_POLE`], within
/// [`ON_POLE_CROWD`] times that), the box holding them and the pole and
/// [`WINDOW_MARGIN`] more, enlarged to fill the detail at a round
/// magnification (at least [`LEAST_MAGNIFICATION`]) about its middle;
/// none where the pole is not crowded or the detail would enlarge it
/// less.
fn window(taken: &[Mark], scale: f64, size: (f64, f64)) -> Option<Window> {
    let lettered: Vec<Point> = (taken.iter())
        .filter(|t| !t.3.is_empty())
        .map(|t| t.2)
        .collect();
    let within = |reach: f64| -> Vec<Point> {
        (lettered.iter().copied())
            .filter(|p| (*p - Point::origin()).norm() * scale < reach)
            .collect()
    };
    let pole = match within(CROWD) {
        near if near.len() >= CROWDED => near,
        _ if !within(ON_POLE).is_empty() => within(ON_POLE_CROWD * CROWD),
        _ => Vec::new(),
    };
    let pole = if pole.len() < CROWDED {
        Vec::new()
    } else {
        pole
    };
    // A knot elsewhere only where the pole is not crowded: the pole's
    // detail is sized for the pole (r = 1, l = 1.05 r).
    // The pole's letter is one of a knot's: at the default engine in (a)
    // "O", "270°′" and "0°" on the *x* axis, 25 and 27 units apart, their
    // leaders across the dotted jump and a dashed strand (the fifteenth
    // review).
    let knots = if pole.is_empty() {
        let with_pole: Vec<Point> = (lettered.iter().copied())
            .chain([Point::origin()])
            .collect();
        knots(&with_pole, scale)
    } else {
        Vec::new()
    };
    if pole.is_empty() && knots.is_empty() {
        return None;
    }
    // The pole held where it crowds, or stands within [`CROWD`] of a
    // knot (its letter among the knot's).
    let near_pole = |p: &Point| (*p - Point::origin()).norm() * scale < CROWD;
    let mut held = match (pole.first(), knots.first()) {
        (Some(_), _) => Frame::new(Point::origin(), Point::origin()),
        (None, Some(k)) => Frame::new(*k, *k),
        (None, None) => return None,
    };
    if knots.iter().any(near_pole) {
        held.include(Point::origin());
    }
    pole.iter().chain(&knots).for_each(|p| held.include(*p));
    let margin = Vector::new(WINDOW_MARGIN, WINDOW_MARGIN) / scale;
    let reach = (held.max() - held.min()) + 2.0 * margin;
    let middle = held.min() + 0.5 * (held.max() - held.min());
    let area = Vector::new(size.0, size.1 - crate::diagram::CAPTION);
    let wanted = (area.x / (reach.x * scale)).min(area.y / (reach.y * scale));
    if wanted.is_nan() || wanted < LEAST_MAGNIFICATION {
        return None;
    }
    let magnification = super::coriolis::round_below(wanted, &super::coriolis::FINE_STEPS);
    let half = area * (0.5 / (magnification * scale));
    let edge = EDGE / (magnification * scale);
    let inner = half - Vector::new(edge, edge);
    Some(Window {
        region: Frame::new(middle - half, middle + half),
        core: Frame::new(middle - inner, middle + inner),
        magnification,
    })
}

/// The lettered marks (`lettered`, world) of a panel at `scale` page
/// units to the world unit that stand in knots away from the pole: each
/// group of [`KNOT`] or more, each within [`KNOT_REACH`] of another of
/// it. Three letters with leaders to three dots a few units apart
/// (r = 1, l = 2.32 r, e = −0.685 r in (b): 0°′, 180°′ and 270°, 8 to
/// 17 units apart, 30 from the pole) could not be told apart (the
/// thirteenth review), though the pole was not crowded.
fn knots(lettered: &[Point], scale: f64) -> Vec<Point> {
    let near = |a: Point, b: Point| (a - b).norm() * scale < KNOT_REACH;
    // Single linkage: a group grows by every mark near one of it.
    let mut groups: Vec<Vec<Point>> = Vec::new();
    for &p in lettered {
        let (joined, apart): (Vec<_>, Vec<_>) =
            (groups.into_iter()).partition(|g| g.iter().any(|q| near(p, *q)));
        groups = apart;
        let mut group: Vec<Point> = joined.into_iter().flatten().collect();
        group.push(p);
        groups.push(group);
    }
    (groups.into_iter())
        .filter(|g| g.len() >= KNOT)
        .flatten()
        .collect()
}

/// The details of the panels' `windows` (each its panel's number, whether
/// relative, and its window), `size` on the page: side by side, each
/// under its own panel (ending at `ends`, page units), where a flat (a)
/// leaves its column's room under it; under both stacked panels, side by
/// side. Where the figure's last panel or detail ends, page units.
fn details(
    ctx: &Ctx,
    sheet: &mut Sheet,
    curves: &[Curves; 2],
    windows: &[(usize, bool, Window)],
    (stacked, half, ends): (bool, f64, [f64; 2]),
    size: (f64, f64),
) -> Result<f64> {
    let last = ends.iter().copied().fold(0.0, f64::max);
    let mut end = last;
    for &(k, relative, w) in windows {
        let Some(&panel) = curves.get(k) else {
            continue;
        };
        let (slot, x, top) = if stacked {
            let slot = 0.5 * (half - 16.0);
            (slot, 16.0 + k as f64 * (slot + 16.0), last + DETAIL_GAP)
        } else {
            let under = ends.get(k).copied().unwrap_or(last);
            (half, 16.0 + k as f64 * (half + 16.0), under + DETAIL_GAP)
        };
        // Taller by its caption's lines after the first, so that its
        // area keeps the height the window was cut for: a caption on two
        // lines took them off the area, and the detail showed a tenth
        // less than its box enlarged (r = 1, l = 1.07 r on 4.5 in).
        let view = View::Detail(w);
        let high = size.1 + caption_extra(ctx, &panel_caption(relative, view), size.0)?;
        let rect = Frame::from_origin_size(x + 0.5 * (slot - size.0), top, size.0, high);
        // Sampled as finely on the page as the panel's curves, which
        // the letters keep clear of: at 2 a degree, ×6 (l = 47.6 r),
        // a letter cleared the chords and stood on the curve.
        let fine = sampled(panel.engines, panel.cycle, relative, 2.0 * w.magnification);
        let curves = Curves {
            sampled: &fine,
            ..panel
        };
        let (plot, _) = polar_plot(ctx, &curves, relative, rect, (&w.region, 0.0), view)?;
        sheet.detail(plot);
        end = end.max(top + high);
    }
    Ok(end)
}

/// The least room, page units, above and below a panel's curves: for
/// the letters of the dots on its edges, set out to three ems
/// ([`super::load_letters`]).
const LETTER_ROOM: f64 = 45.0;

/// The least height, page units, of a panel's plot area: a plot's least
/// (40) and a unit more.
const LEAST_AREA: f64 = 41.0;

/// How much higher than one line, page units, the caption `caption` of a
/// panel `width` wide stands: its lines after the first, which a plot
/// takes off its area (and so off its scale) unless its rectangle has
/// room for them.
fn caption_extra(ctx: &Ctx, caption: &str, width: f64) -> Result<f64> {
    let tall = 1000.0;
    let probe = Frame::new(Point::origin(), Point::new(1.0, 1.0));
    let rect = Frame::from_origin_size(0.0, 0.0, width, tall);
    let plot =
        Plot::world("probe", rect, &probe, false, ctx.tolerance, ctx.font)?.with_caption(caption);
    Ok((tall - crate::diagram::CAPTION - plot.area().height()).max(0.0))
}

/// The caption of a panel showing `view` (of the panel relative to the
/// crank where `relative`).
fn panel_caption(relative: bool, view: View) -> String {
    match view {
        View::Detail(w) => format!(
            "({}′) The boxed region of ({}){} enlarged ×{}",
            if relative { "b" } else { "a" },
            if relative { "b" } else { "a" },
            if w.region.contains(Point::origin()) {
                " about the pole"
            } else {
                ""
            },
            short(w.magnification)
        ),
        View::Whole { .. } if relative => "(b) Relative to the crank: along it outwards (→) and across it in the sense of rotation (↑)".to_string(),
        View::Whole { .. } => "(a) In fixed axes, *x* from the crank centre towards the slider: the load on the crank pin, which a massless crank passes to the main bearing".to_string(),
    }
}

/// One panel showing `world`: the two polar curves, the pole, and the
/// marks ([`marks`]): 0°, 90°, 180°, 270° (and on, over a cycle of two
/// turns) lettered, in (a) above the room `below` its curves that the
/// scale bar takes; as `view` says, the whole or a detail about the pole,
/// and the window a whole panel leaves to its detail.
fn polar_plot(
    ctx: &Ctx,
    curves: &Curves,
    relative: bool,
    rect: Frame,
    (world, below): (&Frame, f64),
    view: View,
) -> Result<(Plot, Option<Window>)> {
    let Curves {
        engines,
        sampled,
        kinks,
        cycle,
    } = *curves;
    let base = if relative { "relative" } else { "fixed" };
    let name = match view {
        View::Whole { .. } => base.to_string(),
        View::Detail(_) => format!("detail-{base}"),
    };
    let caption = panel_caption(relative, view);
    let mut plot =
        Plot::world(&name, rect, world, false, ctx.tolerance, ctx.font)?.with_caption(&caption);
    // The full curve's jumps, which the dashed curve's keep off.
    let full_jumps: Vec<(Point, Point)> = (jumps(engines[0], relative, kinks, cycle).into_iter())
        .map(|(_, a, b)| (a, b))
        .collect();
    let mut bowed = Vec::new();
    for (engine, id, dash) in [
        (engines[0], CURVES[0], Dash::Solid),
        (engines[1], CURVES[1], Dash::Dashed),
    ] {
        let pieces: Vec<_> = kinks
            .iter()
            .zip(kinks.iter().skip(1))
            .filter(|(a, b)| *b - *a > 4.0 * INSIDE)
            .map(|(&a, &b)| (piece(engine, relative, a, b), a..=b))
            .collect();
        let traced: Vec<(&dyn Curve, _)> = pieces
            .iter()
            .map(|(c, r)| (c as &dyn Curve, r.clone()))
            .collect();
        // Measured against a Newton–Euler model of its own in the
        // curve-tolerance test, as every curve-* is.
        plot.curve(&format!("curve-{name}-{id}"), &traced, dash, None)?;
        for (deg, from, to) in jumps(engine, relative, kinks, cycle) {
            let path = jump_path((from, to), &full_jumps, plot.map().scale(), dash);
            let values: Vec<(f64, f64)> = path.iter().map(|p| (p.x, p.y)).collect();
            plot.line(
                &format!("jump-{name}-{id}-{deg}"),
                &values,
                Dash::Dotted,
                None,
            );
            bowed.extend(path.iter().zip(path.iter().skip(1)).map(|(a, b)| (*a, *b)));
        }
    }
    let scale = plot.map().scale();
    let mut taken = marks(engines, cycle, relative, (APART / scale, MEET / scale));
    let seen = plot.map().world_frame(&plot.area());
    // A whole panel letters the marks outside its window, its detail
    // those inside the window's core and draws only those it shows.
    let window = match view {
        View::Whole { detail } => window(&taken, scale, detail),
        View::Detail(_) => None,
    };
    let here = |p: Point| match (view, window) {
        (View::Detail(w), _) => w.core.contains(p),
        (_, Some(w)) => !w.core.contains(p),
        _ => true,
    };
    if let View::Detail(_) = view {
        taken.retain(|t| seen.contains(t.2));
    }
    for t in taken.iter_mut().filter(|t| !here(t.2)) {
        t.3.clear();
    }
    if let Some(w) = window {
        plot.push(window_box(
            &format!("{name}-detail-box"),
            &w.region,
            &seen,
            0.0,
        ));
    }
    if let View::Detail(_) = view {
        // Its border, half a unit inside the area it is clipped to, so
        // that the curves cut there end on a line, not in the air.
        let inset = BORDER_INSET / scale;
        plot.push(window_box(&format!("{name}-border"), &seen, &seen, inset));
    }
    // Lettered, so that it is found among a short rod's loops about it;
    // before the quarters' letters, so that it takes the place beside its
    // × and a quarter's dot a few units off (the dashed 270° at r = 1,
    // l = 3.83 r, e = −1.63 r) is lettered on its own side, not over the
    // × with "O" by the dot; set away from the dots as well as the curves.
    // Letters inside the plot's area, in (a) above the scale bar's room.
    let (lo, hi) = (seen.min(), seen.max());
    let floor = if relative {
        lo.y
    } else {
        lo.y.max(world.min().y + below)
    };
    let inside = Frame::new(Point::new(lo.x, floor), hi);
    let mut letters = Letters::new(ctx, sampled, *plot.map(), inside);
    if let Some(w) = window {
        // Its box's sides kept clear of, as the dotted jumps are: "180°"
        // on the box's lower side at r = 1, l = 3.18 r, e = −1.79 r on
        // 120 mm (the twelfth review).
        letters.keep_off(&box_sides(&w.region, &seen));
    }
    letters.keep_off(&bowed);
    if here(Point::origin()) {
        let pole = RichText::parse("*O*");
        let dots: Vec<Point> = taken.iter().map(|t| t.2).collect();
        let id = format!("label-{name}-pole");
        let ids = (id.clone(), format!("leader-{name}-pole"));
        let mut set = letters.pole(pole.clone(), &dots, ids);
        if set.is_empty() {
            set.push(Item::new(
                id,
                Role::Label,
                Shape::Label {
                    anchor: Point::origin(),
                    text: pole,
                    size: TextSize::Letter,
                    toward: None,
                    line: None,
                },
            ));
        }
        for item in set {
            plot.push(item);
        }
    }
    for item in mark_items(&name, &taken, &mut letters) {
        plot.push(item);
    }
    // The pole's × over the dots, so that a quarter's dot on the pole
    // (180° at l = 1.06 r, its load a twentieth of the largest) leaves
    // its arms seen.
    plot.points(
        &format!("point-{name}-pole"),
        &[(0.0, 0.0)],
        Symbol::Cross,
        None,
    );
    Ok((plot, window))
}

/// The box `id` about `region` (world) kept inside `seen`, the world a
/// panel shows, and `inset` (world) inside it: a panel's box about the
/// region its detail enlarges, a detail's border.
fn window_box(id: &str, region: &Frame, seen: &Frame, inset: f64) -> Item {
    let inset = Vector::new(inset, inset);
    let lo = region.min().sup(&(seen.min() + inset));
    let hi = region.max().inf(&(seen.max() - inset));
    let role = if inset.x > 0.0 {
        Role::Frame
    } else {
        Role::Auxiliary
    };
    Item::new(
        id.to_string(),
        role,
        Shape::Polyline {
            points: vec![lo, Point::new(hi.x, lo.y), hi, Point::new(lo.x, hi.y)],
            closed: true,
        },
    )
}

/// The four sides (world) of the box about `region` kept inside `seen`,
/// as [`window_box`] draws it.
fn box_sides(region: &Frame, seen: &Frame) -> [(Point, Point); 4] {
    let lo = region.min().sup(&seen.min());
    let hi = region.max().inf(&seen.max());
    let [a, b, c, d] = [lo, Point::new(hi.x, lo.y), hi, Point::new(lo.x, hi.y)];
    [(a, b), (b, c), (c, d), (d, a)]
}

/// How far inside its clipped area a detail's border is drawn, page
/// units: half its line's width, so that it is drawn whole.
const BORDER_INSET: f64 = 0.5;

/// The jumps of `engine`'s load at the kinks (degrees) where the gas
/// force jumps (at the dead centres, the cycle's end joined to its
/// start): each its angle and the load just before and just after, where
/// the two differ by more than a millionth of the larger. The figure
/// draws each as a dotted line, so that a curve's end there leads to
/// the other side of the jump and is not read as a free end or an
/// arrowhead.
fn jumps(engine: &Engine, relative: bool, kinks: &[f64], cycle: f64) -> Vec<(f64, Point, Point)> {
    kinks
        .iter()
        .filter(|k| **k < cycle)
        .filter_map(|&k| {
            let before = if k == 0.0 { cycle } else { k } - INSIDE;
            let (a, b) = (
                load(engine, before, relative)?,
                load(engine, k + INSIDE, relative)?,
            );
            ((a - b).norm() > 1e-6 * a.norm().max(b.norm()))
                .then(|| (k, Point::origin() + a, Point::origin() + b))
        })
        .collect()
}

/// How far the dashed curve's jump bows off the full curve's where the
/// two would run on each other, page units: at long rods both jump along
/// the *x* axis at the dead centres, one after the other, and one dotted
/// line through four dots could not say which jump joins which (the
/// twelfth review).
const JUMP_BOW: f64 = 7.0;

/// Jumps whose ends lie nearer each other's line than this, page units,
/// run on each other: on one line, overlapping or one after the other,
/// they read as one dotted line through all their dots.
const JUMPS_MEET: f64 = 2.0;

/// The points (world) of the jump `from`–`to` of the curve drawn `dash`:
/// the straight line, or for the dashed curve where it runs on one of
/// the line of one of `full`'s jumps ([`JUMPS_MEET`] at `scale` page
/// units to the world unit), an arc through its ends bowed [`JUMP_BOW`] to the left of its
/// way (a jump is no path of the load, only where its curve goes on).
fn jump_path(
    (from, to): (Point, Point),
    full: &[(Point, Point)],
    scale: f64,
    dash: Dash,
) -> Vec<Point> {
    let along = to - from;
    let runs_on = |&(a, b): &(Point, Point)| {
        let Some(u) = unit(b - a) else {
            return false;
        };
        let off = |p: Point| cross(&(p - a), &u).abs() * scale;
        off(from) < JUMPS_MEET && off(to) < JUMPS_MEET
    };
    if dash == Dash::Solid || along.norm() == 0.0 || !full.iter().any(runs_on) {
        return vec![from, to];
    }
    let normal = perp(&along) / along.norm();
    let bow = JUMP_BOW / scale;
    (0..=16)
        .map(|k| {
            let t = f64::from(k) / 16.0;
            from + along * t + normal * (4.0 * bow * t * (1.0 - t))
        })
        .collect()
}

/// The two curves' names in ids: with the rod's inertia, without it.
const CURVES: [&str; 2] = ["with-rod", "without-rod"];

/// A mark of a panel: its curve, its angle (degrees), its point and the
/// angles it letters, each with whether it is the dashed curve's.
type Mark<'a> = (&'a str, f64, Point, Vec<(f64, bool)>);

/// The letter of the angle `deg` on a curve: "90°" on the full curve
/// (with the rod's inertia), "90°′" primed on the dashed one (without
/// it), as a book letters a second curve's points 1′, 2′, …: two "90°"
/// side by side could not say which curve each named. (Brackets,
/// "(90°)", two characters wider, crowded a flat panel's letters off
/// their dots on a narrow page.)
pub(crate) fn angle_letter(deg: f64, dashed: bool) -> String {
    if dashed {
        format!("{deg}°′")
    } else {
        format!("{deg}°")
    }
}

/// The marks of one panel ([`mark_items`] draws them): each curve's
/// quarters first, a quarter within `meet` (world units, [`MEET`]) of a
/// mark already set lettered by that mark ("0°, 180°") and not marked
/// again, then the other points every 30° where they stand `apart` from
/// every mark and from the pole and twice that from a lettered mark.
fn marks(
    engines: [&Engine; 2],
    cycle: f64,
    relative: bool,
    (apart, meet): (f64, f64),
) -> Vec<Mark<'static>> {
    let every: Vec<f64> = (0..(cycle / MARK) as usize)
        .map(|k| k as f64 * MARK)
        .collect();
    let quarter = |d: f64| d.rem_euclid(90.0) == 0.0;
    // Each mark: its curve, its angle, its point and the angles it
    // letters, each with whether it is the dashed curve's.
    let mut taken: Vec<Mark> = Vec::new();
    for lettered in [true, false] {
        for (c, engine) in CURVES.into_iter().zip(engines) {
            let dashed = c == CURVES[1];
            for &d in every.iter().filter(|d| quarter(**d) == lettered) {
                let Some(v) = load(engine, d, relative) else {
                    continue;
                };
                let p = Point::origin() + v;
                // An unlettered dot keeps twice as far from a
                // lettered one, whose letter stands beside it.
                let room = |t: &Mark| {
                    if lettered || t.3.is_empty() {
                        apart
                    } else {
                        2.0 * apart
                    }
                };
                // A quarter meets a lettered mark only on it (the two dots
                // one place); nearer, but apart, it has a dot of its own.
                let reach = |t: &Mark| {
                    if lettered { meet } else { room(t) }
                };
                let near = (taken.iter_mut())
                    .filter(|t| (p - t.2).norm() < reach(t))
                    .min_by(|a, b| (p - a.2).norm().total_cmp(&(p - b.2).norm()));
                match near {
                    // A quarter on a lettered mark: that mark letters it too.
                    Some(t) if lettered && !t.3.contains(&(d, dashed)) => t.3.push((d, dashed)),
                    Some(_) => {}
                    None if lettered || (p - Point::origin()).norm() >= apart => {
                        let letters = if lettered {
                            vec![(d, dashed)]
                        } else {
                            Vec::new()
                        };
                        taken.push((c, d, p, letters));
                    }
                    None => {}
                }
            }
        }
    }
    taken
}

/// The items of the marks `taken` of the panel `name`: each mark's dot
/// `point-{name}-{curve}-{deg}`, then each lettered mark's letter
/// ([`mark_letter`]), in the order of the marks. The letters are set in
/// that order, and where one finds no place that does not mislead (its
/// leader through a letter set before it: "180°′" through "0°′" at the
/// default engine on 120 mm, 4.5 in and 500 units), set again with that
/// one first, the hardest first, while each order still leaves one
/// misled, at most once for each letter; the order with the fewest misled
/// letters is kept.
fn mark_items(name: &str, taken: &[Mark], letters: &mut Letters) -> Vec<Item> {
    let mut items: Vec<Item> = taken
        .iter()
        .map(|(c, d, p, _)| {
            Item::new(
                format!("point-{name}-{c}-{d}"),
                Role::Curve,
                // A point of the curve, which letters keep clear of and
                // are placed nearer to than to any other.
                Shape::Dot { centre: *p },
            )
        })
        .collect();
    let lettered: Vec<&Mark> = taken.iter().filter(|t| !t.3.is_empty()).collect();
    let mut order: Vec<usize> = (0..lettered.len()).collect();
    let mut best: Option<(usize, Vec<Vec<Item>>, Letters)> = None;
    for _ in 0..=lettered.len() {
        let mut trial = letters.clone();
        let mut set: Vec<Vec<Item>> = vec![Vec::new(); lettered.len()];
        let mut misled = Vec::new();
        for &k in &order {
            let Some(mark) = lettered.get(k) else {
                continue;
            };
            let (its, misleads) = mark_letter(name, taken, mark, &mut trial);
            if misleads {
                misled.push(k);
            }
            if let Some(slot) = set.get_mut(k) {
                *slot = its;
            }
        }
        let count = misled.len();
        if best.as_ref().is_none_or(|b| count < b.0) {
            best = Some((count, set, trial));
        }
        // The first misled letter first, unless it is first already.
        match misled.first() {
            Some(&k) if order.first() != Some(&k) => {
                order.retain(|&j| j != k);
                order.insert(0, k);
            }
            _ => break,
        }
    }
    if let Some((_, set, trial)) = best {
        *letters = trial;
        items.extend(set.into_iter().flatten());
    }
    items
}

/// The letter of the lettered mark `mark` of the panel `name` among the
/// marks `taken`: `label-{name}-{curve}-{deg}`, on the side
/// [`Letters::beside`] finds clear nearest its dot, or, where none is,
/// set farther out by [`Letters::led`] with its leader
/// `leader-{name}-{curve}-{deg}`; and whether that place misleads
/// ([`super::load_letters::Led`]; a letter set beside its dot without
/// the pairs' and lines' rules, or left to the layout, misleads too).
fn mark_letter(
    name: &str,
    taken: &[Mark],
    mark: &Mark,
    letters: &mut Letters,
) -> (Vec<Item>, bool) {
    let (c, d, p, letters_of) = mark;
    // The pole first, then every other dot.
    let others: Vec<Point> = [Point::origin()]
        .into_iter()
        .chain(taken.iter().map(|t| t.2).filter(|q| q != p))
        .collect();
    let mut said = letters_of.clone();
    said.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
    let text = (said.iter().map(|&(a, dashed)| angle_letter(a, dashed)))
        .collect::<Vec<_>>()
        .join(", ");
    let text = RichText::parse(&text);
    let id = format!("label-{name}-{c}-{d}");
    if let Some(beside) = letters.beside(*p, text.clone(), &others, id.clone(), true) {
        return (vec![beside], false);
    }
    // No side clear within a letter's reach: set farther out with a
    // leader to the dot.
    let ids = (id.clone(), format!("leader-{name}-{c}-{d}"));
    if let Some(led) = letters.led(*p, text.clone(), &others, ids) {
        return (Vec::from(led.items), led.misleads);
    }
    // No place within three ems keeps the room a leader needs: beside
    // its dot after all, without the pairs' and lines' rules.
    if let Some(beside) = letters.beside(*p, text.clone(), &others, id.clone(), false) {
        return (vec![beside], true);
    }
    // Nor beside it: farther out, past three ems, rather than left to
    // the layout.
    let ids = (id.clone(), format!("leader-{name}-{c}-{d}"));
    if let Some(led) = letters.led_farther(*p, text.clone(), &others, ids) {
        return (Vec::from(led.items), true);
    }
    let label = Item::new(
        id,
        Role::Label,
        Shape::Label {
            anchor: *p,
            text,
            // A point's letter: placed nearer its mark than any other.
            size: TextSize::Letter,
            toward: None,
            line: None,
        },
    );
    (vec![label], true)
}

/// The notes, in short sentences: the engine and its rod, how the
/// curves are read, the largest loads, and the shapes a reader might take
/// for faults ([`SHAPES`]), the dashed curve's lying on the axis only
/// where it is drawn `flat` ([`FLAT`]).
fn notes(ctx: &Ctx, rod: &Engine, largest: [f64; 2], bar: f64, flat: bool) -> Vec<String> {
    let m = ctx.mechanism;
    let (u, f, mass_u) = (ctx.unit(), ctx.units.force(), ctx.units.mass());
    let r = rod.rod();
    vec![
        format!(
            "*r* = {} {u}, *l* = {} {u}{}, {} rpm. Reciprocating mass {} {mass_u}. The rod: {} {mass_u}, its centre of mass {} {u} from the crank pin, its radius of gyration {} {u}{}. The gas force is the turning-moment figure’s{}.",
            short(m.crank()),
            short(m.rod()),
            ctx.offset_clause(),
            short(ctx.rpm()),
            short(ctx.options.mass.unwrap_or(EXAMPLE_MASS)),
            short(r.map_or(0.0, RodMass::mass)),
            short(r.map_or(0.0, RodMass::cg)),
            short(r.map_or(0.0, RodMass::gyration)),
            rod_said(ctx),
            super::turning::guides_note(ctx),
        ),
        format!(
            "Full curves: the load with the rod’s inertia. Dashed curves: without it (a massless rod). The pole *O* is marked ×. A lettered dot marks each curve’s load at 0°, 90°, 180° and 270°; the dashed curve’s angles are primed (90°′). Two quarters at one place share one dot. Plain dots mark every other 30° where they stand clear; near the pole some are left out. Both panels are drawn to one scale: the bar is {} {f}. Where the gas force jumps, at a dead centre, a dotted line joins the curve across the jump.",
            short(bar),
        ),
        format!(
            "Largest load on the crank pin over the cycle: {} {f} with the rod’s inertia, {} {f} without it. Both are found by Newton–Euler on the slider and on the rod as a rigid body.",
            short(largest[0]),
            short(largest[1]),
        ),
        if flat {
            format!("{} {FLAT} {}", SHAPES.0, SHAPES.1)
        } else {
            format!("{} {}", SHAPES.0, SHAPES.1)
        },
    ]
}

/// The notes' word on the curves' shapes that a reader might take for
/// faults, said of any engine (a figure of another engine does not speak
/// of the default's): a small loop where the load turns back and out
/// again (at the default, the full curve's *x* component turns back from
/// −5664 lbf at 62°, by the cut-off, to −4809 lbf at 82° and out to
/// −5412 lbf at 110°, as the analysis of the default engine at those
/// angles prints); a sharp point where a curve doubles back on itself,
/// the load's own turning point (at the default the full curve in (a)
/// turns back by its 90° dot in a sliver the fifteenth review read as an
/// arrowhead); the dashed curve flat on the axis at long rods (a
/// massless rod's force lies along the rod, within φ of the line of
/// stroke); and the corners of the curves where the gas force is an
/// indicator diagram's: its pressures are joined by straight lines
/// between its rows (every 5 % of the stroke in the example), so the
/// load turns a corner at each (the twelfth review took the small
/// loops' corners for chords of too coarse a tracing; with a constant
/// gas force the same loops are smooth).
/// The two halves, about where [`FLAT`] stands.
const SHAPES: (&str, &str) = (
    "A small loop is the load turning back and out again, after the cut-off. A sharp point where a curve doubles back is a turning point of the load, not an arrowhead.",
    "With an indicator diagram the pressure runs straight between the diagram’s rows, so the curves turn a small corner at each row.",
);

/// The notes' word on the dashed curve of (a) drawn flat on the *x*
/// axis, said only where it is (within an em of the axis on the page):
/// at a short rod, where it stands well off the axis, the sentence spoke
/// of no curve drawn (r = 1, l = 1.07 r).
const FLAT: &str = "With a long rod the dashed curve in (a) lies almost flat on the *x* axis: a massless rod’s load lies along the rod, within φ of the line of stroke.";
