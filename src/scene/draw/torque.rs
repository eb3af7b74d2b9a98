//! Ng's torque line (Fig. 1): OM, the crank torque, the slider force and
//! the side thrust.

use super::Ctx;
use super::velocity::basics_e;
use crate::figure::{RichText, Role, Shape, TextSize};
use crate::geom::{Point, Vector, cross};
use crate::scene::canvas::Canvas;
use crate::scene::notation::Named::*;

/// Length of the slider-force arrow, page units.
const FORCE_ARROW: f64 = 64.0;
/// Radius of the torque arrow about the crank centre, page units.
const TORQUE_RADIUS: f64 = 24.0;

/// A given value as written when short (0.5, 6, 25), else to four
/// significant figures.
pub(crate) fn short(x: f64) -> String {
    let s = format!("{}", x + 0.0);
    if s.len() <= 6 && !s.contains('e') {
        s
    } else {
        sig(x)
    }
}

/// Four significant figures, no exponent for ordinary magnitudes.
pub(crate) fn sig(x: f64) -> String {
    if x == 0.0 || !x.is_finite() {
        return "0".into();
    }
    let digits = (3 - x.abs().log10().floor() as i32).clamp(0, 12) as usize;
    let s = format!("{:.*}", digits, x);
    if s.starts_with("-0") && s.trim_start_matches(['-', '0', '.']).is_empty() {
        s[1..].to_string()
    } else {
        s
    }
}

pub(crate) fn draw(ctx: &Ctx, canvas: &mut Canvas) {
    basics_e(ctx, canvas);
    let scene = ctx.scene;
    let pose = ctx.main.pose();
    let (a, b, c) = (pose.a(), pose.b(), pose.c());
    let tl = ctx.main.torque();
    let m = tl.m();
    let (unit, force) = (scene.unit(), scene.force_unit());
    let om = format!(
        "*{}{}* = {} {unit}",
        ctx.letter(CrankCentre),
        ctx.letter(VelocityPoint),
        sig(tl.om().abs())
    );
    canvas.label(
        "value-OM",
        nalgebra::center(&c, &m),
        RichText::parse(&om),
        TextSize::Small,
    );

    // The crank torque: an arc arrow about the crank centre.
    let t = scene.torque();
    let radius = canvas.world(TORQUE_RADIUS);
    let turn = if t >= 0.0 { 1.0 } else { -1.0 };
    let start = -0.9 * turn;
    let sweep = turn * 4.4;
    canvas.push(
        "torque-T",
        Role::Force,
        Shape::Arc {
            centre: c,
            radius,
            start,
            sweep,
            arrow: true,
        },
    );
    let mid = start + 0.5 * sweep + std::f64::consts::PI;
    canvas.label(
        "value-T",
        c + Vector::new(mid.cos(), mid.sin()) * radius,
        RichText::parse(&format!("*T* = {} {force}·{unit}", short(t))),
        TextSize::Small,
    );

    crank_force(ctx, canvas, t);
    let s = &ctx.sizes;
    match tl.slider_force(t) {
        Some(fp) => {
            let ux = Vector::new(fp.signum(), 0.0);
            let face = a + ux * s.block_half_length;
            let tip = face + ux * canvas.world(FORCE_ARROW);
            canvas.push(
                "force-Fp",
                Role::Force,
                Shape::Arrow {
                    from: face,
                    to: tip,
                },
            );
            canvas.label(
                "value-Fp",
                tip,
                RichText::parse(&format!("*F*_p = {} {force}", sig(fp.abs()))),
                TextSize::Small,
            );
            let fs = tl.side_thrust(fp);
            if fs != 0.0 {
                let uy = Vector::new(0.0, fs.signum());
                let face = a + uy * s.block_half_height;
                let len = (FORCE_ARROW * (fs / fp).abs()).clamp(16.0, FORCE_ARROW);
                let tip = face + uy * canvas.world(len);
                canvas.push(
                    "force-Fs",
                    Role::Force,
                    Shape::Arrow {
                        from: face,
                        to: tip,
                    },
                );
                canvas.label(
                    "value-Fs",
                    tip,
                    RichText::parse(&format!("*F*_s = {} {force}", sig(fs.abs()))),
                    TextSize::Small,
                );
            }
        }
        None => {
            let r = pose.mechanism().crank();
            canvas.label(
                "note-dead-centre",
                Point::new(0.0, -0.6 * r),
                RichText::parse(&format!(
                    "dead centre: *{}{}* = 0, no finite slider force",
                    ctx.letter(CrankCentre),
                    ctx.letter(VelocityPoint)
                )),
                TextSize::Small,
            );
        }
    }

    // The transmission angle β at the crank pin, between its two links.
    let (u, v) = (c - b, a - b);
    let sweep = cross(&u, &v).atan2(u.dot(&v));
    if sweep.abs() > 1e-3 {
        canvas.push(
            "angle-beta",
            Role::Dimension,
            Shape::AngleMark {
                vertex: b,
                start: u.y.atan2(u.x),
                sweep,
                text: Some(RichText::italic("β")),
            },
        );
    }
}

/// F_c = T / r, the force on the crank pin perpendicular to the crank
/// (Ng eq. 2), as an arrow pointing at the pin in the torque's sense.
fn crank_force(ctx: &Ctx, canvas: &mut Canvas, t: f64) {
    let pose = ctx.main.pose();
    let (b, c) = (pose.b(), pose.c());
    let r = pose.mechanism().crank();
    let cb = b - c;
    if t == 0.0 || cb.norm() == 0.0 {
        return;
    }
    let u = Vector::new(-cb.y, cb.x) / cb.norm() * t.signum();
    let head = b - u * canvas.world(7.0);
    let tail = head - u * canvas.world(0.75 * FORCE_ARROW);
    if !canvas.contains(tail) {
        return;
    }
    canvas.push(
        "force-Fc",
        Role::Force,
        Shape::Arrow {
            from: tail,
            to: head,
        },
    );
    canvas.label(
        "value-Fc",
        tail,
        RichText::parse(&format!(
            "*F*_c = {} {}",
            sig((t / r).abs()),
            ctx.scene.force_unit()
        )),
        TextSize::Small,
    );
}

#[cfg(test)]
mod tests {
    use super::sig;

    #[test]
    fn four_significant_figures() {
        assert_eq!(sig(13.0899), "13.09");
        assert_eq!(sig(242.04), "242.0");
        assert_eq!(sig(0.35301), "0.3530");
        assert_eq!(sig(-0.00001), "-0.00001000");
        assert_eq!(sig(0.0), "0");
        assert_eq!(sig(12345.6), "12346");
    }
}
