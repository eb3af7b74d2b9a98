//! Ng's torque line (Fig. 1): OM, the crank torque, the slider force and
//! the side thrust.

use super::velocity::basics_e;
use super::{Ctx, NamedArrow};
use crate::figure::{RichText, Role, Shape, TextSize};
use crate::geom::{Vector, cross};
use crate::scene::canvas::Canvas;
use crate::scene::notation::Named::*;

/// Length of the slider-force arrow, page units.
const FORCE_ARROW: f64 = 64.0;
/// Radius of the torque arrow about the crank centre, page units: wide
/// enough for the centre's letter to sit inside it.
const TORQUE_RADIUS: f64 = 36.0;

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

/// The values the figure names by symbol only, for the notes below it:
/// OM and T, then the forces (or why there is no finite slider force).
pub(crate) fn notes(ctx: &Ctx) -> Vec<RichText> {
    let scene = ctx.scene;
    let tl = ctx.main.torque();
    let (unit, force) = (scene.units().length(), scene.units().force());
    let om = format!("*{}{}*", ctx.letter(CrankCentre), ctx.letter(VelocityPoint));
    let t = scene.torque();
    let mut out = vec![RichText::parse(&format!(
        "Torque line: {om} = {} {unit}, crank torque *T* = {} {force}·{unit}.",
        sig(tl.om().abs()),
        short(t)
    ))];
    let r = ctx.main.pose().mechanism().crank();
    let fc = format!("*F*_c = *T*/*r* = {} {force}", sig((t / r).abs()));
    out.push(RichText::parse(&match tl.slider_force(t) {
        Some(fp) => format!(
            "Forces: {fc}, *F*_p = {} {force}, *F*_s = {} {force}.",
            sig(fp.abs()),
            sig(tl.side_thrust(fp).abs())
        ),
        None => format!("Forces: {fc}; dead centre: {om} = 0, no finite slider force."),
    }));
    out
}

pub(crate) fn draw(ctx: &Ctx, canvas: &mut Canvas) {
    basics_e(ctx, canvas);
    let scene = ctx.scene;
    let pose = ctx.main.pose();
    let (a, b, c) = (pose.a(), pose.b(), pose.c());
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
        RichText::italic("T"),
        TextSize::Small,
    );

    for f in forces(ctx, &|page| canvas.world(page)) {
        if !canvas.contains(f.from) {
            continue;
        }
        canvas.push(
            format!("force-{}", f.id),
            Role::Force,
            Shape::Arrow {
                from: f.from,
                to: f.to,
            },
        );
        let at = if f.id == "Fc" { f.from } else { f.to };
        canvas.label(
            format!("value-{}", f.id),
            at,
            RichText::parse(f.name),
            TextSize::Small,
        );
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

/// The force arrows, their page lengths turned to world lengths by
/// `world`: F_c = T / r on the crank pin, perpendicular to the crank in
/// the torque's sense (Ng eq. 2), pointing at the pin; the slider force
/// F_p from the block's face along the stroke, and the side thrust F_s
/// from its top or bottom (to F_p's scale, within limits). None at a dead
/// centre, where the slider force is not finite.
pub(crate) fn forces(ctx: &Ctx, world: &dyn Fn(f64) -> f64) -> Vec<NamedArrow> {
    let pose = ctx.main.pose();
    let (a, b, c) = (pose.a(), pose.b(), pose.c());
    let t = ctx.scene.torque();
    let mut out = Vec::new();
    let cb = b - c;
    if t != 0.0 && cb.norm() > 0.0 {
        let u = Vector::new(-cb.y, cb.x) / cb.norm() * t.signum();
        let head = b - u * world(7.0);
        let tail = head - u * world(0.75 * FORCE_ARROW);
        out.push(NamedArrow {
            id: "Fc",
            name: "*F*_c",
            from: tail,
            to: head,
        });
    }
    let s = &ctx.sizes;
    let tl = ctx.main.torque();
    if let Some(fp) = tl.slider_force(t) {
        let ux = Vector::new(fp.signum(), 0.0);
        let face = a + ux * s.block_half_length;
        out.push(NamedArrow {
            id: "Fp",
            name: "*F*_p",
            from: face,
            to: face + ux * world(FORCE_ARROW),
        });
        let fs = tl.side_thrust(fp);
        if fs != 0.0 {
            let uy = Vector::new(0.0, fs.signum());
            let face = a + uy * s.block_half_height;
            let len = (FORCE_ARROW * (fs / fp).abs()).clamp(16.0, FORCE_ARROW);
            out.push(NamedArrow {
                id: "Fs",
                name: "*F*_s",
                from: face,
                to: face + uy * world(len),
            });
        }
    }
    out
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
