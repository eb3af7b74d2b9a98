//! Ng Fig. 2: the free-body diagram of a block on a plane tilted at φ, at
//! the instant it starts to slide: its weight mg with the components
//! mg sin φ down the plane and mg cos φ into it, the normal reaction N and
//! the friction μN up the plane, whence mg sin φ = μ mg cos φ (eq. 9) and
//! μ = tan φ (eq. 10). The tilt is the figure's angle (45° on Ng's rig).

use super::{Ctx, Sheet, short};
use crate::analytic::statics::mu_from_tilt_degrees;
use crate::diagram::Plot;
use crate::error::{Error, Result};
use crate::figure::{Figure, Item, PageRect, RichText, Role, Shape, TextSize};
use crate::geom::{Frame, Point, Vector};

pub(in crate::catalogue) fn build(ctx: &Ctx) -> Result<Figure> {
    let page = ctx.page();
    let tilt = ctx.angle.degrees();
    if !(tilt > 0.0 && tilt < 90.0) {
        return Err(Error::OutOfRange {
            name: "angle",
            value: tilt,
            reason: "the tilt of the plane is between 0° and 90°".into(),
        });
    }
    let mu = mu_from_tilt_degrees(tilt)?;
    let mut sheet = Sheet::new(ctx);
    sheet.mechanism(ctx, false, false);
    sheet.meta("tilt_deg", serde_json::json!(tilt));
    sheet.meta("mu", serde_json::json!(mu));
    let phi = ctx.angle.radians();
    let (s, c) = (ctx.angle.sin(), ctx.angle.cos());
    let u = Vector::new(c, s); // up the plane
    let n = Vector::new(-s, c); // out of the plane
    let length = 1.0;
    let side = 0.2;
    let o = Point::origin();
    let top = o + u * length;
    let foot = Point::new(top.x, 0.0);
    let contact = o + u * (0.55 * length);
    let g = contact + n * (0.5 * side);
    let weight = 0.42;
    let mut items = vec![
        Item::new(
            "plane",
            Role::Frame,
            Shape::Polyline {
                points: vec![o, top, foot],
                closed: true,
            },
        ),
        Item::new(
            "hatch-ground",
            Role::Frame,
            Shape::Hatch {
                from: Point::new(-0.08, 0.0),
                to: Point::new(foot.x + 0.08, 0.0),
                side: Vector::new(0.0, -1.0),
            },
        ),
        // Open, so that the forces at its centre show.
        Item::new(
            "block",
            Role::Link,
            Shape::Polyline {
                points: vec![
                    contact - u * (0.5 * side),
                    contact + u * (0.5 * side),
                    contact + u * (0.5 * side) + n * side,
                    contact - u * (0.5 * side) + n * side,
                ],
                closed: true,
            },
        ),
        Item::new("point-G", Role::Construction, Shape::Dot { centre: g }),
    ];
    let arrow = |id: &str, role: Role, from: Point, to: Point| {
        Item::new(id, role, Shape::Arrow { from, to })
    };
    let down = Vector::new(0.0, -1.0);
    let normal = weight * c;
    let friction = mu * normal;
    items.push(arrow("force-weight", Role::Force, g, g + down * weight));
    // N acts across the contact face; drawn on its line through G.
    let face = g + n * (0.5 * side);
    items.push(arrow("force-normal", Role::Force, face, face + n * normal));
    // Friction acts in the contact face: drawn from the block's uphill
    // face, parallel to the plane and just clear of its line, so that the
    // arrow reads as a force and not as the plane's edge.
    let clear = n * (0.1 * side);
    let friction_at = contact + u * (0.5 * side) + clear;
    items.push(arrow(
        "force-friction",
        Role::Force,
        friction_at,
        friction_at + u * friction,
    ));
    items.push(arrow(
        "component-along",
        Role::Auxiliary,
        g,
        g - u * (weight * s),
    ));
    items.push(arrow(
        "component-across",
        Role::Auxiliary,
        g,
        g - n * (weight * c),
    ));
    items.push(Item::new(
        "angle-tilt",
        Role::Dimension,
        Shape::AngleMark {
            vertex: o,
            start: 0.0,
            sweep: phi,
            text: Some(RichText::italic("φ")),
        },
    ));
    // The angle between the weight and its component into the plane.
    let into = (-n).y.atan2((-n).x);
    items.push(Item::new(
        "angle-weight",
        Role::Dimension,
        Shape::AngleMark {
            vertex: g,
            start: into,
            sweep: -phi,
            text: Some(RichText::italic("φ")),
        },
    ));
    items.push(Item::new(
        "angle-components",
        Role::Dimension,
        Shape::RightAngle {
            vertex: g,
            u: -u,
            v: -n,
        },
    ));
    let mut label = |id: &str, at: Point, text: &str| {
        items.push(Item::new(
            format!("label-force-{id}"),
            Role::Label,
            Shape::Label {
                anchor: at,
                text: RichText::parse(text),
                size: TextSize::Small,
            },
        ));
    };
    label("weight", g + down * weight, "*mg*");
    label("normal", face + n * normal, "*N*");
    label("friction", friction_at + u * friction, "μ*N*");
    label("along", g - u * (weight * s), "*mg* sin φ");
    label("across", g - n * (weight * c), "*mg* cos φ");
    let world = Frame::new(
        Point::new(-0.12, -0.06),
        Point::new(foot.x + 0.12, top.y + 0.06),
    );
    let rect = PageRect::new(16.0, 16.0, page.width() - 32.0, page.height() - 32.0 - 64.0);
    let mut plot = Plot::world("incline", rect, &world, false, ctx.tolerance, ctx.font)?
        .with_caption(&format!(
            "A block on a plane tilted at φ = {}°, on the point of sliding",
            short(tilt)
        ));
    for item in items {
        plot.push(item);
    }
    sheet.plot(plot);
    sheet.notes(
        Point::new(20.0, page.height() - 60.0),
        &[
            "Along the plane: *mg* sin φ = μ*N* = μ*mg* cos φ (eq. 9), so μ = tan φ (eq. 10)."
                .into(),
            format!(
                "φ = {}°: μ = tan φ = {}{}",
                short(tilt),
                short(mu),
                if tilt == 45.0 {
                    " (Ng’s rig first slid at 45°: μ = 1)."
                } else {
                    "."
                }
            ),
        ],
    );
    Ok(sheet.finish())
}
