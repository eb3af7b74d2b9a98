//! The mechanism layer: frame, crank circle, links, slider and guides.

use super::Ctx;
use crate::figure::{RichText, Role, Shape, TextSize};
use crate::geom::{Point, Vector};
use crate::scene::cache::Constructions;
use crate::scene::canvas::{Canvas, Marker};
use crate::scene::notation::Named;

/// Clear distance, page units, kept between a guide's open end and the
/// rod (the rod's half width, the guide's, and the slant of the hatching).
const ROD_CLEARANCE: f64 = 5.0;
/// Clear distance, page units, between a guide and the crank circle or
/// the bearing.
const CIRCLE_CLEARANCE: f64 = 7.0;
/// The bearing's half width and depth below the crank centre, page units
/// (with its hatching).
const BEARING_REACH: f64 = 25.0;
/// Shortest guide drawn, page units.
const GUIDE_MIN: f64 = 12.0;

/// Where the guide at height `y` may begin (its end towards the crank):
/// clear of the crank circle and the bearing, and beyond the point where
/// the rod crosses its line, so that no link is ever drawn through it.
fn guide_start(ctx: &Ctx, canvas: &Canvas, y: f64) -> f64 {
    let m = ctx.scene.mechanism();
    let pose = ctx.main.pose();
    let (a, b) = (pose.a(), pose.b());
    let reach = m.crank().max(canvas.world(BEARING_REACH)) + canvas.world(CIRCLE_CLEARANCE);
    let mut start = if y.abs() < reach {
        (reach * reach - y * y).sqrt()
    } else {
        f64::NEG_INFINITY
    };
    // The rod from A (on the stroke, between the guides) towards B crosses
    // the line y when B is beyond it.
    if (b.y - y) * (a.y - y) < 0.0 {
        let t = (y - a.y) / (b.y - a.y);
        let x = a.x + t * (b.x - a.x);
        let sin = ((b.y - a.y) / (b - a).norm()).abs();
        start = start.max(x + canvas.world(ROD_CLEARANCE) / sin + canvas.world(HATCH_SLANT));
    }
    start
}

/// How far the hatching leans along the guide, page units.
const HATCH_SLANT: f64 = 6.0;

pub(crate) fn draw(ctx: &Ctx, ghosts: &[Constructions], canvas: &mut Canvas) {
    let m = ctx.scene.mechanism();
    let (r, e) = (m.crank(), m.offset());
    let pose = ctx.main.pose();
    let (c, b, a) = (pose.c(), pose.b(), pose.a());
    let s = &ctx.sizes;
    let (g0, g1) = s.guides(r);

    // The line of stroke (a centre line) and the crank-pin circle.
    canvas.segment(
        "line-stroke",
        Role::Auxiliary,
        Point::new(g0.min(-1.15 * r), e),
        Point::new(g1 + 0.1 * r, e),
    );
    canvas.push(
        "circle-crank",
        Role::Curve,
        Shape::Circle {
            centre: c,
            radius: r,
        },
    );
    canvas.push(
        format!("bearing-{}", ctx.letter(Named::CrankCentre)),
        Role::Frame,
        Shape::Bearing { centre: c },
    );

    // Guides with their hatching on the outside, open where the rod or
    // the crank circle would cross them.
    let h = s.block_half_height;
    for (id, y, side) in [("upper", e + h, 1.0), ("lower", e - h, -1.0)] {
        let start = guide_start(ctx, canvas, y).max(g0);
        if canvas.page(g1 - start) < GUIDE_MIN {
            continue;
        }
        let (p, q) = (Point::new(start, y), Point::new(g1, y));
        canvas.segment(format!("guide-{id}"), Role::Frame, p, q);
        canvas.push(
            format!("hatch-guide-{id}"),
            Role::Frame,
            Shape::Hatch {
                from: p,
                to: q,
                side: Vector::new(0.0, side),
            },
        );
    }

    // Ghost poses first, so the main pose is drawn over them.
    for (k, g) in ghosts.iter().enumerate() {
        let p = g.pose();
        let n = k + 1;
        let (gb, ga) = (p.b(), p.a());
        canvas.push(
            format!("pose-{n}-links"),
            Role::Auxiliary,
            Shape::Polyline {
                points: vec![c, gb, ga],
                closed: false,
            },
        );
        for (named, pt) in [(Named::CrankPin, gb), (Named::Slider, ga)] {
            let name = format!("{}{}", ctx.letter(named), n);
            canvas.push(
                format!("point-{name}"),
                Role::Auxiliary,
                Shape::Dot { centre: pt },
            );
            canvas.label(
                format!("label-{name}"),
                pt,
                RichText::italic(&format!("{}_{{{}}}", ctx.letter(named), n)),
                TextSize::Small,
            );
        }
    }

    // The slider block about A.
    let l = s.block_half_length;
    canvas.push(
        "block-slider",
        Role::Link,
        Shape::Block {
            points: vec![
                Point::new(a.x - l, a.y - h),
                Point::new(a.x + l, a.y - h),
                Point::new(a.x + l, a.y + h),
                Point::new(a.x - l, a.y + h),
            ],
        },
    );
    canvas.segment("link-crank", Role::Link, c, b);
    canvas.segment("link-rod", Role::Link, b, a);
    canvas.point(ctx.letter(Named::CrankCentre), c, Marker::Pin, c);
    canvas.point(ctx.letter(Named::CrankPin), b, Marker::Pin, c);
    canvas.point(ctx.letter(Named::Slider), a, Marker::Pin, c);
}
