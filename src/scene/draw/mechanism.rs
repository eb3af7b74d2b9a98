//! The mechanism layer: frame, crank circle, links, slider and guides.

use super::Ctx;
use crate::figure::{RichText, Role, Shape, TextSize};
use crate::geom::{Point, Vector};
use crate::scene::cache::Constructions;
use crate::scene::canvas::{Canvas, Marker};
use crate::scene::notation::Named;

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

    // Guides with their hatching on the outside.
    let h = s.block_half_height;
    for (id, y, side) in [("upper", e + h, 1.0), ("lower", e - h, -1.0)] {
        let (p, q) = (Point::new(g0, y), Point::new(g1, y));
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
