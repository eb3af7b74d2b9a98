//! Textbook Fig. 64: the polar diagram of piston velocity, the velocity on
//! a distance base and on a time base against simple harmonic motion.
//!
//! The polar diagram sets E′ off on the crank CB itself with CE′ = CE, as
//! the textbook marks it, so the loop of the return stroke lies below the
//! line of stroke. ([`crate::diagram::LocusKind::PolarVelocity`] keeps the
//! sign of CE and lays the return stroke on the crank produced backwards,
//! which folds its loop onto the first one, mirrored: less legible.)
//! The distance base sets E″ off above A at the height CE (the velocity
//! towards the crank positive), so it is one closed curve over the turn.

use super::{Ctx, PER_DEGREE, Sheet, against_time, dead_centres, extent, short, sig};
use crate::diagram::{Axis, Curve, Locus, LocusKind, Plot};
use crate::error::Result;
use crate::figure::{Dash, Figure, Item, Panel, Role, Shape, Symbol};
use crate::geom::{Frame, Point, Vector};
use crate::scene::{Layer, letter_near_together};
use crate::{angle::Angle, mechanism::Pose, mechanism::SliderCrank};

/// Height of the mechanism panel with its scale notes.
const TOP: f64 = 400.0;

/// A mechanism drawing less tall than this (page units) cannot hold the
/// two-line legend in a corner clear of it.
const FLAT: f64 = 120.0;

/// Paper added below a legend set in a band of its own under the
/// mechanism's notes, page units, between it and the time graph.
const BAND_APART: f64 = 16.0;

/// Nor can one narrower than this: the legend is about 270 units wide, and
/// on a page of 120 mm or 4.5 in it lay over the block and the crank
/// circle.
const NARROW: f64 = 700.0;

pub(in crate::catalogue) fn build(ctx: &Ctx) -> Result<Figure> {
    let page = ctx.page();
    let mut sheet = Sheet::new(ctx);
    sheet.mechanism(ctx, true, true);
    let grown = mechanism(ctx, &mut sheet)?;
    sheet.plot(time_base(ctx, TOP + grown + 6.0)?);
    sheet.height(page.height() + grown);
    sheet.notes(Point::new(20.0, page.height() + grown - 48.0), &notes(ctx));
    Ok(sheet.finish())
}

/// (a) The mechanism at the drawn pose with E, and the two diagrams in
/// its own world coordinates, set on `sheet` with the scene's details;
/// returns how much taller than [`TOP`] it is drawn.
fn mechanism(ctx: &Ctx, sheet: &mut Sheet) -> Result<f64> {
    let reach = reach(ctx.mechanism);
    let scene = ctx
        .scene(ctx.page().width(), TOP * taller(ctx.mechanism, &reach))?
        .with_layers([Layer::Mechanism, Layer::Velocity, Layer::Scales])
        .with_view_holding(reach)
        .with_detail_subject(loops(ctx.mechanism));
    let base = scene.figure()?;
    // A velocity triangle too small to letter gets an enlarged detail, set
    // by the scene below its drawing with the scale notes: the rest of the
    // sheet moves down by what that adds.
    let grown = (base.height() - TOP).max(0.0);
    // cannot fail: a scene's figure has its main view as its first panel
    // (`draw::build` puts it there).
    #[allow(clippy::indexing_slicing)]
    let panel = base.panels()[0].clone();
    // A drawing too flat (a long rod) or too narrow (a narrow page) to
    // hold the legend beside it has it in a band of its own below the
    // scene's notes, at the left with them (at the right it read as the
    // time graph's legend below it).
    let r = *panel.rect();
    let band = if r.height() < FLAT || r.width() < NARROW {
        Plot::band(2)
    } else {
        0.0
    };
    let area = Frame::from_origin_size(
        r.min().x,
        r.min().y,
        r.width(),
        TOP + grown + band - r.min().y,
    );
    let plot = Plot::with_map(
        "mechanism",
        r,
        if band > 0.0 { area } else { r },
        *panel.transform(),
        ctx.tolerance,
        ctx.font,
    );
    let mut plot = if band > 0.0 {
        plot.blocks_below_at_left()
    } else {
        plot
    };
    for item in panel.items() {
        plot.avoid(item);
    }
    diagrams(&mut plot, ctx.mechanism)?;
    construction(&mut plot, &ctx.pose());
    let drawn = plot.finish();
    // The polar diagram is the subject of the scene's detail where a long
    // rod draws the crank small: the detail draws it too, with E′ where
    // its frame holds it (the main view then leaves E′'s letter to it).
    let copied = |i: &&Item| {
        i.id.starts_with("curve-polar-velocity")
            || ["arc-E-E1", "point-E1", "label-E1"].contains(&i.id.as_str())
    };
    let in_detail: Vec<Item> = (drawn.items().iter())
        .filter(copied)
        .map(|i| Item {
            id: format!("detail-{}", i.id),
            ..i.clone()
        })
        .collect();
    // The detail of the loops (the scene's detail of its subject) holds
    // them whole; a detail of the crowded construction (a short rod) is
    // left as the scene drew it, E′ lettered on the main view.
    let frame = loops(ctx.mechanism);
    // Within a unit of the rectangle: the frame's corners round to it.
    let holds = |d: &Panel, p: Point| {
        let r = d.rect();
        let grown = Frame::from_origin_size(
            r.min().x - 1.0,
            r.min().y - 1.0,
            r.width() + 2.0,
            r.height() + 2.0,
        );
        grown.contains(d.transform().apply(p))
    };
    let of_loops = |d: &Panel| holds(d, frame.min()) && holds(d, frame.max());
    let details: Vec<Panel> = base.panels().iter().skip(1).cloned().collect();
    let lettered_there = details.iter().any(of_loops) && e_prime(&ctx.pose()).is_some();
    // E′ copied in by C's pin joins C's letter, as the scene's points
    // there do (E′ stood apart at a long rod's dead centre, led from past
    // "C, E"); the main view then leaves its dot to the detail too, as it
    // does the scene's points inside the detail's frame.
    let mut joined_e1 = false;
    let mut panels = Vec::new();
    for detail in details {
        let copied = of_loops(&detail);
        let scale = detail.transform().scale();
        let joined = detail
            .with_items(copied.then(|| in_detail.clone()).into_iter().flatten())
            .with_items_edited(|all| letter_near_together(all, "detail-", scale, &[]));
        joined_e1 |= copied && joined.item("detail-point-E1").is_none();
        panels.push(joined);
    }
    let left =
        |i: &&Item| (lettered_there && i.id == "label-E1") || (joined_e1 && i.id == "point-E1");
    let main = (drawn.items().iter()).filter(|i| !left(i)).cloned();
    sheet.panel(panel.with_items(main));
    for detail in panels {
        sheet.panel(detail);
    }
    // The band's legend is the mechanism's: more paper below it than
    // above, so that it does not read with the time graph.
    let apart = if band > 0.0 { BAND_APART } else { 0.0 };
    Ok(grown + band + apart)
}

/// The world frame of the polar diagram's loops of `m` over a turn: E′
/// at ±CE along the crank (every half degree).
fn polar_extent(m: &SliderCrank) -> Frame {
    let ce = |p: &Pose| -p.position_rate();
    let (x0, x1) = extent(m, |p| ce(p) * p.angle().cos());
    let (y0, y1) = extent(m, |p| ce(p) * p.angle().sin());
    Frame::new(
        Point::new(x0.min(-x1), y0.min(-y1)),
        Point::new(x1.max(-x0), y1.max(-y0)),
    )
}

/// The polar diagram's loops of `m` and the crank circle: the subject
/// of the scene's detail where a long rod draws the crank small.
fn loops(m: SliderCrank) -> Frame {
    let (p, r) = (polar_extent(&m), m.crank());
    Frame::new(
        Point::new(p.min().x.min(-r), p.min().y.min(-r)),
        Point::new(p.max().x.max(r), p.max().y.max(r)),
    )
}

/// The world frame the two diagrams of `m` reach over a turn (every
/// half degree): the polar diagram's loops, and the distance base, E″ at
/// the height CE over A. At short rods CE exceeds the crank: a view
/// fitted to the mechanism alone sent the curves off the top of the page
/// and through the detail's frame.
fn reach(m: SliderCrank) -> Frame {
    let p = polar_extent(&m);
    let (s0, s1) = extent(&m, |p| p.position());
    let (c0, c1) = extent(&m, |p| -p.position_rate());
    Frame::new(
        Point::new(p.min().x.min(s0), p.min().y.min(c0)),
        Point::new(p.max().x.max(s1), p.max().y.max(c1)),
    )
}

/// How much taller the diagrams' `reach` makes the drawing than the
/// mechanism's own height (the crank circle and the line of stroke), at
/// least 1 and at most [`MOST_TALLER`]: the mechanism's drawing is given
/// that much more height, so that a short rod, whose diagrams reach 1.4
/// cranks above and below the line of stroke, is drawn to the scale it
/// would have without them where the page's width allows (drawn smaller,
/// its letters about the crank crowded at the dead centres).
fn taller(m: SliderCrank, reach: &Frame) -> f64 {
    let (r, e) = (m.crank(), m.offset());
    let (own_lo, own_hi) = ((-r).min(e), r.max(e));
    let (lo, hi) = (reach.min().y.min(own_lo), reach.max().y.max(own_hi));
    ((hi - lo) / (own_hi - own_lo)).clamp(1.0, MOST_TALLER)
}

/// The most [`taller`] gives.
const MOST_TALLER: f64 = 1.6;

/// The polar diagram (E′ on the crank, the return stroke's loop below)
/// and the distance base (E″ over A) of `m`, on the mechanism's plot.
fn diagrams(plot: &mut Plot, m: SliderCrank) -> Result<()> {
    let polar = Locus::new(m, LocusKind::PolarVelocity);
    let outward = |deg: f64| polar.eval(deg);
    let inward = |deg: f64| {
        polar
            .eval(deg)
            .map(|(p, d)| (Point::origin() - p.coords, -d))
    };
    let (o, i) = dead_centres(&m);
    plot.curve(
        "curve-polar-velocity",
        &[(&outward, o..=i), (&inward, i..=o + 360.0)],
        Dash::Solid,
        Some("polar diagram: *E*′ on the crank, *CE*′ = *CE*"),
    )?;
    let distance = |deg: f64| -> Option<(Point, Vector)> {
        let pose = m.pose(Angle::from_degrees(deg).ok()?);
        Some((
            Point::new(pose.position(), -pose.position_rate()),
            Vector::new(pose.position_rate(), -pose.position_acceleration()) * PER_DEGREE,
        ))
    };
    plot.curve(
        "curve-distance-base",
        &[(&distance, 0.0..=360.0)],
        Dash::Dashed,
        Some("distance base: *E*″ over *A*, height *CE*"),
    )
}

/// (b) The velocity on a time base over one revolution from `top` down,
/// against simple harmonic motion of the same amplitude V_c, with the
/// pose drawn above marked.
fn time_base(ctx: &Ctx, top: f64) -> Result<Plot> {
    let m = ctx.mechanism;
    let omega = ctx.omega;
    let period = std::f64::consts::TAU / omega;
    let vc = ctx.crank_speed();
    let (lo, hi) = extent(&m, |p| -omega * p.position_rate());
    let rect = ctx.band(top, ctx.page().height() - TOP - 6.0 - 60.0);
    let x = Axis::linear("time *t* (s);  θ = ω*t*", 0.0, period)?;
    let y = Axis::nice(
        &format!("*V*_p ({}/s), towards the crank", ctx.unit()),
        lo.min(-vc),
        hi.max(vc),
    )?;
    let mut time =
        Plot::new("time-base", rect, x, y, ctx.tolerance, ctx.font)?.with_caption(&format!(
            "Velocity on a time base: one revolution at {} rpm",
            short(ctx.rpm())
        ));
    let exact = against_time(m, omega, |p: &Pose| {
        (
            -omega * p.position_rate(),
            -omega * p.position_acceleration(),
        )
    });
    time.curve(
        "curve-time-base",
        &[(&exact, 0.0..=360.0)],
        Dash::Solid,
        Some("piston, *V*_p = −d*x*/d*t*"),
    )?;
    let shm = against_time(m, omega, |p: &Pose| {
        (vc * p.angle().sin(), vc * p.angle().cos())
    });
    time.curve(
        "curve-time-base-shm",
        &[(&shm, 0.0..=360.0)],
        Dash::Dashed,
        Some("simple harmonic motion, *V*_c sin θ"),
    )?;
    let pose = ctx.pose();
    let theta = pose.angle().degrees();
    time.points(
        "point-time-base",
        &[(theta * PER_DEGREE / omega, -omega * pose.position_rate())],
        Symbol::Disc,
        Some(&format!("the pose drawn above, θ = {}°", short(theta))),
    );
    Ok(time)
}

/// The notes: the velocity scale, and where E′ is set off.
fn notes(ctx: &Ctx) -> [String; 2] {
    [
        format!(
            "Scale: *CB* = *r* represents *V*_c = *r*ω = {} {}/s; *CE*′ and the height of *E*″ represent *V*_p to the same scale.",
            sig(ctx.crank_speed()),
            ctx.unit()
        ),
        "*E*′ is set off on the crank itself (*CE*′ = *CE*), so the return stroke’s loop lies below the crank centre.".to_string(),
    ]
}

/// The construction of E′ and E″ for the drawn pose: the arc about C from
/// E to E′, the line from E across to E″ over A.
/// E′ of `pose` (the polar diagram's point on the crank, CE′ = |CE|
/// from C); none at a dead centre, where CE vanishes.
fn e_prime(pose: &Pose) -> Option<Point> {
    let ce = -pose.position_rate();
    let r = pose.mechanism().crank();
    let u = Vector::new(pose.angle().cos(), pose.angle().sin());
    (ce.abs() >= 1e-6 * r).then(|| Point::origin() + u * ce.abs())
}

fn construction(plot: &mut Plot, pose: &Pose) {
    let ce = -pose.position_rate();
    let Some(e1) = e_prime(pose) else {
        return;
    };
    let u = Vector::new(pose.angle().cos(), pose.angle().sin());
    let e2 = Point::new(pose.position(), ce);
    let start = if ce > 0.0 { 0.5 } else { -0.5 } * std::f64::consts::PI;
    let end = u.y.atan2(u.x);
    plot.push(Item::new(
        "arc-E-E1",
        Role::Auxiliary,
        super::short_arc(Point::origin(), ce.abs(), start, end),
    ));
    plot.push(Item::new(
        "line-E-E2",
        Role::Auxiliary,
        Shape::Polyline {
            points: vec![Point::new(0.0, ce), e2],
            closed: false,
        },
    ));
    for (id, p, name) in [("E1", e1, "E′"), ("E2", e2, "E″")] {
        plot.push(Item::new(
            format!("point-{id}"),
            Role::Construction,
            Shape::Dot { centre: p },
        ));
        plot.push(super::letter(id, p, name));
    }
}
