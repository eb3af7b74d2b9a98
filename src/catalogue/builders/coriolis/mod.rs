//! The Coriolis figures: inversion 2 (the crank a fixed: the rotating
//! block, Whitworth's quick return) and inversion 3 (the rod b fixed: the
//! oscillating cylinder, the crank and slotted lever) at one pose, drawn
//! as a course in the kinematics of machines draws them: the mechanism in
//! the fixed link's frame, its velocity polygon and its acceleration
//! polygon, which closes with the Coriolis component 2 ω_d v, each to the
//! scale of its bar, and the component's direction rule (v turned a
//! quarter turn in the sense of ω_d) drawn at the pose's own directions
//! ([`crate::chain::CoriolisPolygon`], docs/polygons.md).
//!
//! Lettering: the pins keep the engine's letters (C the crank centre, B
//! the crank pin, A the block's pin); each image is its point's letter in
//! lower case (c the image of C), the acceleration images primed; a_d is
//! the image of the point of d under the block's pin, o the pole (the
//! image of every fixed point), n the end of d's normal component and k
//! the end of the Coriolis component.

mod mechanism;
mod notes;
mod panel;
mod polygons;
mod rule;

use super::{Ctx, Sheet};
use crate::chain::{CoriolisPolygon, Inversion, InvertedChain};
use crate::error::{Error, Result};
use crate::figure::{Figure, Hue};
use crate::geom::{Frame, Point, Vector};
use crate::scene::Canvas;
use serde_json::json;

use mechanism::mechanism_plot;
use notes::{coriolis_json, notes};
pub(super) use panel::mark_window;
use panel::{Drawn, Window, detail_plot, headless, lined_up, polygon_plot, right_angles};
use polygons::Polygons;
use rule::rule_plot;

/// Page margin, as the other builders'.
pub(super) const MARGIN: f64 = 16.0;

/// The gap between panels, page units.
pub(super) const GAP: f64 = 12.0;

/// The mechanism panel's least and most height, page units.
pub(super) const MECHANISM_HEIGHT: (f64, f64) = (170.0, 300.0);

/// The polygons' panels' height, page units.
pub(super) const POLYGON_HEIGHT: f64 = 290.0;

/// The shares of the page's width of the velocity polygon, the
/// acceleration polygon and the direction rule.
pub(super) const SHARES: [f64; 3] = [0.36, 0.42, 0.22];

/// Shortest vector drawn as an arrow, page units: shorter, its head would
/// hide it (a zero vector, at the dead centres, is not drawn).
pub(super) const MIN_ARROW: f64 = 12.0;

/// Shortest vector drawn with its head, page units: two and a half
/// heads. A shorter one is drawn as a plain side (its head would be most
/// of it, a stub on the point it starts from: inversion 3's normal
/// component c′n at the default, 14 units, its head on c′'s dot); its
/// sense is read from the letters at its ends.
pub(super) const HEADLESS: f64 = 25.0;

/// The detail panels' height, page units.
pub(super) const DETAIL_HEIGHT: f64 = 240.0;

/// The steps a scale bar's length is chosen from (times a power of ten).
pub(super) const STEPS: [f64; 4] = [1.0, 2.0, 2.5, 5.0];

/// The steps the crank detail's magnification is chosen from (times a
/// power of ten): finer, so that the crank keeps most of the room the
/// detail gives it.
pub(super) const FINE_STEPS: [f64; 9] = [1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0];

/// The largest of the round `steps` times a power of ten not above `x`
/// (positive and finite).
pub(super) fn round_below(x: f64, steps: &[f64]) -> f64 {
    let decade = 10f64.powf(x.log10().floor());
    steps
        .iter()
        .map(|s| s * decade)
        .filter(|s| *s <= x * (1.0 + 1e-12))
        .fold(decade, f64::max)
}

/// The panels' rectangles across the page from `top`, by [`SHARES`].
pub(super) fn row(width: f64, top: f64, height: f64) -> [Frame; 3] {
    let room = width - 2.0 * MARGIN - 2.0 * GAP;
    let mut x = MARGIN;
    SHARES.map(|share| {
        let rect = Frame::from_origin_size(x, top, room * share, height);
        x += room * share + GAP;
        rect
    })
}

pub(in crate::catalogue) fn build(ctx: &Ctx, inversion: Inversion) -> Result<Figure> {
    let m = ctx.mechanism;
    let chain = InvertedChain::new(m, inversion);
    let pose = chain.pose(ctx.angle);
    let p = CoriolisPolygon::construct(&pose, ctx.omega)
        .ok_or_else(|| Error::Unsupported("no block slides on a turning link".into()))?;
    let engine = pose.engine_pose();
    let ca = (engine.a() - engine.c()).norm();
    let polygons = Polygons { inversion, p, ca };
    let page = ctx.page();
    let (mechanism, crank_detail) = mechanism_plot(ctx, &pose)?;
    // The mechanism's detail stands beside it, or below it.
    let bottom = |r: Frame| r.max().y;
    let top = crank_detail.as_ref().map_or(bottom(mechanism.rect()), |d| {
        bottom(mechanism.rect()).max(bottom(d.rect()))
    }) + GAP;
    let [v_rect, a_rect, rule_rect] = row(page.width(), top, POLYGON_HEIGHT);
    let [v_below, a_below, _] = row(page.width(), top + POLYGON_HEIGHT + GAP, DETAIL_HEIGHT);
    let area = |r: Frame| (r.width(), r.height() - crate::diagram::CAPTION);
    let velocity_drawn = Drawn {
        name: "velocity-polygon",
        caption: "velocity polygon",
        points: polygons.velocity_points(),
        arrows: polygons.velocity_arrows(),
        hue: Hue::Velocity,
        per: "/s",
        subject: polygons.velocity_subject(),
    };
    let acceleration_drawn = Drawn {
        name: "acceleration-polygon",
        caption: "acceleration polygon",
        points: polygons.acceleration_points(),
        arrows: polygons.acceleration_arrows(),
        hue: Hue::Acceleration,
        per: "/s²",
        subject: polygons.acceleration_subject(),
    };
    let nothing = |_: &mut Canvas| {};
    let angles = |s: &mut Canvas| right_angles(s, &polygons);
    let (velocity, v_bar, v_points, v_window) =
        polygon_plot(ctx, v_rect, &velocity_drawn, area(v_below), &nothing)?;
    let (acceleration, a_bar, a_points, a_window) =
        polygon_plot(ctx, a_rect, &acceleration_drawn, area(a_below), &angles)?;
    let mut details = Vec::new();
    if let Some(w) = v_window {
        details.push(detail_plot(ctx, v_below, &velocity_drawn, &w, &nothing)?);
    }
    if let Some(w) = a_window {
        details.push(detail_plot(ctx, a_below, &acceleration_drawn, &w, &angles)?);
    }
    let a_scale = acceleration.map().scale();
    let sliding = polygons.p.a_d_acceleration() - polygons.k();
    let tangential = polygons.p.a_d_acceleration() - polygons.p.n();
    // Each as the detail draws it where the detail holds both its ends
    // (a detail about the crowded point the polygon closes at may leave
    // the Coriolis component out); else as the polygon draws it.
    let held = |ends: [Vector; 2]| {
        a_window.filter(|w| ends.iter().all(|p| w.frame.contains(Point::from(*p))))
    };
    let coriolis_ends = polygons
        .acceleration_subject()
        .map_or([Vector::zeros(); 2], |s| [s.0, s.1]);
    let seen = (
        drawn_length(
            sliding,
            a_scale,
            held([polygons.k(), polygons.p.a_d_acceleration()]),
        ),
        drawn_length(polygons.p.coriolis(), a_scale, held(coriolis_ends)),
        drawn_length(
            tangential,
            a_scale,
            held([polygons.p.n(), polygons.p.a_d_acceleration()]),
        ),
    );
    let plain = [
        headless(&velocity_drawn, velocity.map().scale(), v_window),
        headless(&acceleration_drawn, a_scale, a_window),
    ]
    .concat();
    let lines = [
        lined_up(&velocity_drawn, velocity.map().scale(), v_window),
        lined_up(&acceleration_drawn, a_scale, a_window),
    ]
    .concat();
    let rule = rule_plot(ctx, rule_rect, &polygons)?;
    let mut sheet = Sheet::new(ctx);
    sheet.mechanism(ctx, true, true);
    sheet.meta("inversion", json!(inversion.number()));
    sheet.meta("coriolis", coriolis_json(&polygons, v_bar, a_bar));
    sheet.meta("velocity_polygon", v_points);
    sheet.meta("acceleration_polygon", a_points);
    sheet.plot(mechanism);
    if let Some(d) = crank_detail {
        sheet.detail(d);
    }
    sheet.plot(velocity);
    sheet.plot(acceleration);
    sheet.plot(rule);
    let mut bottom = top + POLYGON_HEIGHT + 6.0;
    if !details.is_empty() {
        bottom += GAP + DETAIL_HEIGHT;
    }
    for d in details {
        sheet.plot(d);
    }
    sheet.height(bottom + NOTES_LINES * super::NOTE_LINE + MARGIN);
    sheet.notes(
        Point::new(20.0, bottom),
        &notes(
            ctx,
            &chain,
            &polygons,
            (v_bar, a_bar),
            (seen, &plain, &lines),
        ),
    );
    Ok(sheet.finish())
}

/// The page length of a side of the acceleration polygon (the sliding
/// acceleration k a′_d, the Coriolis component) where it is drawn
/// largest: in the acceleration polygon's detail where it has one, else
/// in the polygon at `scale` page units per unit; with the detail's
/// magnification (`None` without one).
fn drawn_length(side: Vector, scale: f64, window: Option<Window>) -> (f64, Option<f64>) {
    let length = side.norm() * scale;
    match window {
        Some(w) => (length * w.magnification, Some(w.magnification)),
        None => (length, None),
    }
}

/// The notes' lines before wrapping.
pub(super) const NOTES_LINES: f64 = 5.0;
