//! The dimensions layer (Fig. 62): crank angle θ, displacement x from
//! mid-stroke, the stroke, r and l.

use super::Ctx;
use crate::figure::{RichText, Role, Shape, TextSize};
use crate::geom::{Point, Vector};
use crate::scene::canvas::{Canvas, Marker};
use crate::scene::notation::Named;

/// Clear distance of the first dimension line below the guides, page units.
const FIRST: f64 = 22.0;
/// Spacing of stacked dimension lines, page units.
const STEP: f64 = 24.0;

pub(crate) fn draw(ctx: &Ctx, canvas: &mut Canvas) {
    let pose = ctx.main.pose();
    let m = pose.mechanism();
    let (r, e) = (m.crank(), m.offset());
    let (a, b, c) = (pose.a(), pose.b(), pose.c());
    let theta = pose.angle().radians();
    if theta > 0.0 {
        canvas.push(
            "angle-theta",
            Role::Dimension,
            Shape::AngleMark {
                vertex: c,
                start: 0.0,
                sweep: theta,
                text: Some(RichText::italic("θ")),
            },
        );
    }
    // Mid-stroke O and the displacement x = OA (signed: A beyond O, away
    // from C, is positive here).
    let (near, far) = ctx.sizes.travel;
    let o = Point::new(0.5 * (near + far), e);
    let below = Vector::new(0.0, -1.0);
    let guide = canvas.page(ctx.sizes.block_half_height);
    canvas.point(ctx.letter(Named::MidStroke), o, Marker::Dot, c);
    if canvas.page((a - o).norm()) > 2.0 {
        canvas.push(
            "dimension-x",
            Role::Dimension,
            Shape::Dimension {
                from: o,
                to: a,
                side: below,
                offset: guide + FIRST,
                text: RichText::italic("x"),
            },
        );
    }
    canvas.push(
        "dimension-stroke",
        Role::Dimension,
        Shape::Dimension {
            from: Point::new(near, e),
            to: Point::new(far, e),
            side: below,
            offset: guide + FIRST + STEP,
            text: RichText::parse("stroke"),
        },
    );
    canvas.label(
        "value-r",
        nalgebra::center(&c, &b),
        RichText::italic("r"),
        TextSize::Small,
    );
    canvas.label(
        "value-l",
        nalgebra::center(&b, &a),
        RichText::parse(&format!("*l* = {}*r*", super::torque::short(m.ratio()))),
        TextSize::Small,
    );
    let _ = r;
}
