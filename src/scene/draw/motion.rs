//! The motion layer (Ng Figs. 1 and A1): the crank's ω and the rod's Ω as
//! turning arrows, the velocity v_c of the crank pin and v_p of the slider
//! as arrows drawn to one scale.

use super::torque::{ALONG_THE_ROD, PIN_SHORT};
use super::{LayerCtx, NamedArrow};
use crate::figure::{HATCH_DEPTH, Hue, RichText, Role, Shape, TextSize};
use crate::geom::{Point, Vector, point_segment_distance};
use crate::scene::canvas::Canvas;

/// Length of the arrow v_c, page units; v_p is drawn to the same scale.
const VC_ARROW: f64 = 54.0;
/// Shortest velocity arrow drawn, page units.
const MIN_ARROW: f64 = 14.0;
/// Distance of the arrow v_p beyond the guide, page units (past the
/// hatching).
const VP_CLEAR: f64 = 18.0;
/// Radius about the crank centre, page units, that v_p keeps out of: the
/// torque's turning arrow with the room for its head (ω's, at
/// [`OMEGA_RADIUS`], lies within it), and a few units between.
const CRANK_KEEP: f64 = super::torque::TORQUE_REACH + 6.0;
/// Radius of the ω arrow about the crank centre, page units.
const OMEGA_RADIUS: f64 = 40.0;
/// Radius of the Ω arrow about the rod's middle, page units.
const ROD_RADIUS: f64 = 16.0;

pub(crate) fn draw(ctx: &LayerCtx, canvas: &mut Canvas) {
    // With the torque layer (Ng Fig. 1) the torque's arrow holds the crank
    // centre: the turning arrows are Fig. A1's.
    if !ctx.scene.has(crate::scene::Layer::Torque) {
        turning(ctx, canvas);
    }
    for v in velocities(ctx, &|page| canvas.world(page)) {
        if !(canvas.contains(v.from) && canvas.contains(v.to)) {
            continue;
        }
        v.draw(canvas, "velocity", Hue::Velocity);
    }
}

/// The velocity arrows, their page lengths turned to world lengths by
/// `world`: v_c at the crank pin, perpendicular to the crank in the sense
/// of ω, [`VC_ARROW`] long; v_p along the stroke to the same scale (at
/// least [`MIN_ARROW`]), beyond the guide on the side away from the crank
/// pin. v_p is left out where the slider is at rest.
pub(crate) fn velocities(ctx: &LayerCtx, world: &dyn Fn(f64) -> f64) -> Vec<NamedArrow> {
    let pose = ctx.main.pose();
    let (a, b) = (pose.a(), pose.b());
    let turn = ctx.scene.omega().signum();
    let mut out = Vec::new();
    let cb = b - pose.c();
    if cb.norm() > 0.0 {
        let u = Vector::new(-cb.y, cb.x) / cb.norm() * turn;
        let rod = a - b;
        let along = rod.norm() > 0.0 && u.dot(&rod) > rod.norm() * ALONG_THE_ROD.cos();
        let t = ctx.scene.torque();
        let shares_fc =
            ctx.scene.has(crate::scene::Layer::Torque) && t != 0.0 && t.signum() == turn;
        let arrow = if shares_fc {
            // From the pin it would continue F_c's line, F_c's head at the
            // pin (one line with two heads at a dead centre, tenth
            // review); from the other side, along the rod, it would lie on
            // F_c (long rods near 270°: one arrow named "v_c F_c"). It
            // leaves the pin beside F_c's line, set off it away from the
            // rod or the rod produced, whichever runs on its side of the
            // pin (the produced rod to M).
            let ahead = if rod.dot(&u) > 0.0 { rod } else { -rod };
            let side = away_from(ahead, cb) * world(super::torque::ALONGSIDE);
            let from = b + u * world(PIN_SHORT) + side;
            let to = from + u * world(VC_ARROW);
            (from, to, to)
        } else if along {
            // Drawn from the pin it would run along the rod: it comes to
            // the pin from the other side, its head short of the pin's
            // circle, named at its tail.
            let to = b - u * world(PIN_SHORT);
            let from = to - u * world(VC_ARROW);
            (from, to, from)
        } else {
            let to = b + u * world(VC_ARROW);
            (b, to, to)
        };
        out.push(NamedArrow {
            id: "vc",
            name: "*v*_c",
            from: arrow.0,
            to: arrow.1,
            name_at: arrow.2,
        });
    }
    let vp = pose.position_rate() / pose.mechanism().crank() * turn;
    let len = VC_ARROW * vp.abs();
    if len >= 1.0 {
        let h = ctx.sizes.block_half_height;
        let side = if b.y >= a.y { -1.0 } else { 1.0 };
        // Beyond the guide's hatching, with room for the arrow's head.
        let under = a + Vector::new(0.0, side * (h + world(VP_CLEAR)));
        let along = vp.signum() * world(len.max(MIN_ARROW));
        let mut shift = clear_of_the_crank(under, along, pose.c(), world);
        if let Some(fs) = side_thrust(ctx, world) {
            shift = clear_of_the_thrust(under, along, shift, &fs, world(VP_FROM_THRUST));
        }
        let from = under + Vector::new(shift, 0.0);
        let to = from + Vector::new(along, 0.0);
        out.push(NamedArrow {
            id: "vp",
            name: "*v*_p",
            from,
            to,
            name_at: to,
        });
    }
    out
}

/// Room (page units) v_p keeps along the stroke from the side thrust
/// F_s's shaft where that crosses v_p's line.
const VP_FROM_THRUST: f64 = 8.0;

/// F_s's arrow where the torque layer draws it (Ng's Fig. 1).
fn side_thrust(ctx: &LayerCtx, world: &dyn Fn(f64) -> f64) -> Option<NamedArrow> {
    if !ctx.scene.has(crate::scene::Layer::Torque) {
        return None;
    }
    super::torque::forces(ctx, world)
        .into_iter()
        .find(|f| f.id == "Fs")
}

/// v_p's `shift` along the stroke (from [`clear_of_the_crank`]) moved so
/// that the arrow, `along` long from `under`, keeps `gap` (world units)
/// from F_s's shaft where that reaches v_p's line: v_p had its tail on
/// the shaft, above the block, and read as a branch of F_s (Ng's Fig. 1,
/// short and long rods). The arrow goes wholly ahead of the shaft, or
/// where it ended under the slider, wholly behind it.
fn clear_of_the_thrust(under: Point, along: f64, shift: f64, fs: &NamedArrow, gap: f64) -> f64 {
    let (y0, y1) = (fs.from.y.min(fs.to.y), fs.from.y.max(fs.to.y));
    let x = fs.from.x;
    let (x0, x1) = (under.x + shift, under.x + shift + along);
    let crosses = under.y >= y0 - gap && under.y <= y1 + gap;
    if !crosses || x0.min(x1) > x + gap || x0.max(x1) < x - gap {
        return shift;
    }
    let s = along.signum();
    let ahead = x + s * gap - under.x;
    let behind = x - s * gap - along - under.x;
    if (shift - behind).abs() < (shift - ahead).abs() && shift != 0.0 {
        behind
    } else {
        ahead
    }
}

/// The unit vector along `normal` or against it (`normal` is the crank,
/// across the velocity's line), whichever points away from `rod`.
fn away_from(rod: Vector, normal: Vector) -> Vector {
    let n = normal / normal.norm();
    if n.dot(&rod) > 0.0 { -n } else { n }
}

/// How far along the stroke v_p's tail moves from `under` (below the
/// slider) so that the arrow, `along` long (signed, world units), stays
/// out of [`CRANK_KEEP`] about the crank centre `c`, where the torque's
/// or ω's turning arrow is drawn: 0 where it is clear (the tail under the
/// slider); else the head under the slider; else the whole arrow just
/// beyond the circle on the slider's side (a short rod near the inner
/// dead centre).
fn clear_of_the_crank(under: Point, along: f64, c: Point, world: &dyn Fn(f64) -> f64) -> f64 {
    let keep = world(CRANK_KEEP);
    let dy = (under.y - c.y).abs();
    if dy >= keep {
        return 0.0;
    }
    let w = (keep * keep - dy * dy).sqrt();
    let clear = |shift: f64| {
        let (x0, x1) = (under.x + shift, under.x + shift + along);
        x0.min(x1) >= c.x + w || x0.max(x1) <= c.x - w
    };
    if clear(0.0) {
        0.0
    } else if clear(-along) {
        -along
    } else if under.x >= c.x {
        c.x + w - (under.x + along.min(0.0))
    } else {
        c.x - w - (under.x + along.max(0.0))
    }
}

/// ω, a turning arrow about the crank centre in the crank's sense, from
/// half a radian ahead of the crank through 1.4 radians, `radius` page
/// units (the arc `id`, its letter `value-omega` at its middle).
pub(crate) fn omega(ctx: &LayerCtx, canvas: &mut Canvas, id: &str, radius: f64) {
    let pose = ctx.main.pose();
    let c = pose.c();
    let turn = ctx.scene.omega().signum();
    let start = omega_start(ctx, canvas, canvas.world(radius));
    canvas.push_hued(
        id,
        Role::Force,
        Hue::Velocity,
        Shape::Arc {
            centre: c,
            radius: canvas.world(radius),
            start,
            sweep: turn * 1.4,
            arrow: true,
        },
    );
    let mid = start + turn * 0.7;
    canvas.label(
        "value-omega",
        c + Vector::new(mid.cos(), mid.sin()) * canvas.world(radius),
        RichText::parse("ω"),
        TextSize::Letter,
    );
}

/// Room (page units) ω's arc keeps from the rod, the block, the guides
/// and the crank where a start clear of them is found.
const OMEGA_CLEAR: f64 = 6.0;

/// Where ω's arc of world `radius` about the crank centre starts: half
/// a radian after the crank in the sense of rotation, or, where the arc
/// there (its sweep of 1.4 rad) would come within [`OMEGA_CLEAR`] of the rod, the
/// block, a guide with its hatching or the crank, the first of seven further starts an
/// eighth of a turn apart that keeps clear; the clearest if none does.
/// At a short rod near 270° the arc after the crank ran across the rod
/// into the block, and read as the rod's or the slider's motion.
fn omega_start(ctx: &LayerCtx, canvas: &Canvas, radius: f64) -> f64 {
    let clear = canvas.world(OMEGA_CLEAR);
    let hatch = canvas.world(HATCH_DEPTH);
    let pose = ctx.main.pose();
    let (a, b, c) = (pose.a(), pose.b(), pose.c());
    let turn = ctx.scene.omega().signum();
    let s = &ctx.sizes;
    let (hl, hh) = (s.block_half_length, s.block_half_height);
    let e = pose.mechanism().offset();
    let r = pose.mechanism().crank();
    let (near, far) = s.travel;
    let corner = |dx: f64, dy: f64| Point::new(a.x + dx, a.y + dy);
    let guide = |y: f64| {
        (
            Point::new(near - hl - 0.15 * r, y),
            Point::new(far + hl + 0.15 * r, y),
        )
    };
    let parts = [
        (c, b),
        (b, a),
        (corner(-hl, -hh), corner(hl, -hh)),
        (corner(hl, -hh), corner(hl, hh)),
        (corner(hl, hh), corner(-hl, hh)),
        (corner(-hl, hh), corner(-hl, -hh)),
        // Each guide with its hatching beyond it.
        guide(e + hh + hatch),
        guide(e - hh - hatch),
    ];
    let room = |start: f64| {
        (0..=24)
            .map(|k| start + turn * 1.4 * k as f64 / 24.0)
            .map(|t| c + Vector::new(t.cos(), t.sin()) * radius)
            .flat_map(|p| {
                parts
                    .iter()
                    .map(move |&(u, v)| point_segment_distance(p, u, v))
            })
            .fold(f64::INFINITY, f64::min)
    };
    let first = pose.angle().radians() + 0.5 * turn;
    let starts = (0..8).map(|k| first + turn * std::f64::consts::FRAC_PI_4 * k as f64);
    let mut best = (f64::NEG_INFINITY, first);
    for start in starts {
        let got = room(start);
        if got >= clear {
            return start;
        }
        if got > best.0 {
            best = (got, start);
        }
    }
    best.1
}

/// ω about the crank centre and Ω about the rod's middle.
fn turning(ctx: &LayerCtx, canvas: &mut Canvas) {
    let pose = ctx.main.pose();
    let (a, b) = (pose.a(), pose.b());
    let w = ctx.scene.omega();
    omega(ctx, canvas, "motion-omega", OMEGA_RADIUS);

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
