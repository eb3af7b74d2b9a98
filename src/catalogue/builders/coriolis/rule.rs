//! The Coriolis component's direction rule drawn at the pose's own
//! directions: v along the slot, the quarter turn in the sense of ω_d,
//! and 2 ω_d v.

use super::super::Ctx;
use super::polygons::Polygons;

use crate::diagram::Plot;
use crate::error::Result;
use crate::figure::{Hue, RichText, Role, Shape, TextSize};
use crate::geom::{Frame, Point, Vector, perp};
use crate::scene::Canvas;

/// The direction rule at the pose's own directions: the sliding velocity
/// v along the slot, the quarter turn in the sense of ω_d, and 2 ω_d v.
/// A vector that is zero is drawn as no arrow: where v is zero, the slot
/// (a plain line, lettered v = 0) and the sense of ω_d; where ω_d is
/// zero, v alone; in either case no 2 ω_d v (a nominal arrow there, at
/// inversion 3's l = 29.5 r, 0°, read as a component of a length).
/// Lettered so that the rule says which vanishes.
pub(super) fn rule_plot(ctx: &Ctx, rect: Frame, polygons: &Polygons) -> Result<Plot> {
    let p = &polygons.p;
    let v = polygons.v();
    let moving = polygons.clean(v.norm(), 1.0, false) > 0.0;
    let turning = polygons.clean(p.omega_d(), polygons.ca, false) != 0.0;
    let u = if moving { v.normalize() } else { p.slot() };
    let sense = if p.omega_d() < 0.0 { -1.0 } else { 1.0 };
    let turned = perp(&u) * sense;
    let world = Frame::new(Point::new(-1.5, -1.5), Point::new(1.5, 1.5));
    let mut plot = Plot::world(
        "coriolis-rule",
        rect,
        &world,
        false,
        ctx.tolerance,
        ctx.font,
    )?
    .with_caption(match (moving, turning) {
        (true, true) => "the Coriolis direction",
        (false, _) => "the Coriolis direction (here *v* = 0)",
        (true, false) => "the Coriolis direction (here ω_{d} = 0)",
    });
    let map = *plot.map();
    let mut s = Canvas::new(map, map.world_frame(&plot.area()));
    let o = Point::origin();
    s.set_hue(Some(Hue::Velocity));
    if moving {
        s.push(
            "rule-v",
            Role::Construction,
            Shape::Arrow { from: o, to: o + u },
        );
    } else {
        // v = 0: the slot's direction, along which v would lie, as a
        // plain line (an arrow there drew a velocity that is nil).
        s.push(
            "rule-slot",
            Role::Construction,
            Shape::Polyline {
                points: vec![o, o + u],
                closed: false,
            },
        );
    }
    // Each letter set beyond its arrow's head, or the arc's middle, by
    // [`RULE_LETTER`]: set at them, "2ω_d v" and "ω_d" ran together
    // (inversion 3 at l = 1.09 r, 89.99°).
    let beyond = s.world(RULE_LETTER);
    s.label_toward(
        "label-rule-v",
        o + u * (1.0 + beyond),
        u,
        RichText::parse(if moving { "*v*" } else { "*v* = 0" }),
        TextSize::Letter,
    );
    if moving && turning {
        s.set_hue(Some(Hue::Acceleration));
        s.push(
            "rule-coriolis",
            Role::Result,
            Shape::Arrow {
                from: o,
                to: o + turned,
            },
        );
        s.label_toward(
            "label-rule-coriolis",
            o + turned * (1.0 + beyond),
            turned,
            RichText::parse("2ω_{d}*v*"),
            TextSize::Letter,
        );
    }
    s.set_hue(None);
    if !turning {
        // ω_d = 0: no sense to turn v in.
        for item in s.finish().0 {
            plot.push(item);
        }
        return Ok(plot);
    }
    let start = u.y.atan2(u.x);
    s.push(
        "rule-turn",
        Role::Force,
        Shape::Arc {
            centre: o,
            radius: RULE_ARC,
            start,
            sweep: sense * 0.5 * std::f64::consts::PI,
            arrow: true,
        },
    );
    let mid = start + sense * 0.25 * std::f64::consts::PI;
    let out = Vector::new(mid.cos(), mid.sin());
    s.label_toward(
        "label-rule-omega",
        o + out * (RULE_ARC + beyond),
        out,
        RichText::parse("ω_{d}"),
        TextSize::Letter,
    );
    for item in s.finish().0 {
        plot.push(item);
    }
    Ok(plot)
}

/// The radius of the rule's quarter turn, in lengths of its arrows.
const RULE_ARC: f64 = 0.55;

/// How far beyond its arrow's head (or the arc's middle) each of the
/// rule's letters is set, page units: most of a letter's height, so that
/// the letter stands clear of the head and of its neighbour's letter.
const RULE_LETTER: f64 = 8.0;
