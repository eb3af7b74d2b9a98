//! The motion layer (Ng Figs. 1 and A1): the crank's ω and the rod's Ω as
//! turning arrows, the velocity v_c of the crank pin and v_p of the slider
//! as arrows drawn to one scale.

use super::Ctx;
use crate::figure::{Hue, RichText, Role, Shape, TextSize};
use crate::geom::{Point, Vector};
use crate::scene::canvas::Canvas;

/// Length of the arrow v_c, page units; v_p is drawn to the same scale.
const VC_ARROW: f64 = 54.0;
/// Shortest velocity arrow drawn, page units.
const MIN_ARROW: f64 = 14.0;
/// Radius of the ω arrow about the crank centre, page units.
const OMEGA_RADIUS: f64 = 40.0;
/// Radius of the Ω arrow about the rod's middle, page units.
const ROD_RADIUS: f64 = 16.0;

pub(crate) fn draw(ctx: &Ctx, canvas: &mut Canvas) {
    let pose = ctx.main.pose();
    let (a, b) = (pose.a(), pose.b());
    let turn = ctx.scene.omega().signum();
    // With the torque layer (Ng Fig. 1) the torque's arrow holds the crank
    // centre: the turning arrows are Fig. A1's.
    if !ctx.scene.has(crate::scene::Layer::Torque) {
        turning(ctx, canvas);
    }
    // v_c: perpendicular to the crank, in the sense of ω.
    let cb = b - pose.c();
    if cb.norm() > 0.0 {
        let u = Vector::new(-cb.y, cb.x) / cb.norm() * turn;
        velocity(canvas, "vc", b, u, VC_ARROW, "*v*_c");
    }
    // v_p: along the stroke, to the scale of v_c, beside the block.
    let vp = pose.position_rate() / pose.mechanism().crank() * turn;
    let len = VC_ARROW * vp.abs();
    if len >= 1.0 {
        let h = ctx.sizes.block_half_height;
        let side = if b.y >= a.y { -1.0 } else { 1.0 };
        let from = a + Vector::new(0.0, side * h) + Vector::new(0.0, side * canvas.world(12.0));
        velocity(
            canvas,
            "vp",
            from,
            Vector::new(vp.signum(), 0.0),
            len.max(MIN_ARROW),
            "*v*_p",
        );
    }
}

/// ω about the crank centre and Ω about the rod's middle.
fn turning(ctx: &Ctx, canvas: &mut Canvas) {
    let pose = ctx.main.pose();
    let (a, b, c) = (pose.a(), pose.b(), pose.c());
    let w = ctx.scene.omega();
    let turn = w.signum();

    // ω: a turning arrow about C, in the crank's sense.
    let start = pose.angle().radians() + 0.5 * turn;
    canvas.push_hued(
        "motion-omega",
        Role::Force,
        Hue::Velocity,
        Shape::Arc {
            centre: c,
            radius: canvas.world(OMEGA_RADIUS),
            start,
            sweep: turn * 1.4,
            arrow: true,
        },
    );
    let mid = start + turn * 0.7;
    canvas.label(
        "value-omega",
        c + Vector::new(mid.cos(), mid.sin()) * canvas.world(OMEGA_RADIUS),
        RichText::parse("ω"),
        TextSize::Letter,
    );

    // Ω: the rod's counter-clockwise angular velocity is −dφ/dt.
    let rod_rate = -w * pose.obliquity_rate();
    let centre = nalgebra::center(&a, &b);
    if rod_rate != 0.0 {
        let along = (a - b).y.atan2((a - b).x);
        let s = rod_rate.signum();
        canvas.push_hued(
            "motion-Omega",
            Role::Force,
            Hue::Velocity,
            Shape::Arc {
                centre,
                radius: canvas.world(ROD_RADIUS),
                start: along + std::f64::consts::FRAC_PI_2 - s * 1.2,
                sweep: s * 2.4,
                arrow: true,
            },
        );
        let up = along + std::f64::consts::FRAC_PI_2;
        canvas.label(
            "value-Omega",
            centre + Vector::new(up.cos(), up.sin()) * canvas.world(ROD_RADIUS),
            RichText::parse("Ω"),
            TextSize::Letter,
        );
    }
}

/// A velocity arrow from `from` along the unit `u`, `length` page units,
/// with its name at the head.
fn velocity(canvas: &mut Canvas, id: &str, from: Point, u: Vector, length: f64, name: &str) {
    let to = from + u * canvas.world(length);
    if !(canvas.contains(from) && canvas.contains(to)) {
        return;
    }
    canvas.push_hued(
        format!("velocity-{id}"),
        Role::Force,
        Hue::Velocity,
        Shape::Arrow { from, to },
    );
    canvas.label(
        format!("value-{id}"),
        to,
        RichText::parse(name),
        TextSize::Small,
    );
}
