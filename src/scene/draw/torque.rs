//! Ng's torque line (Fig. 1): OM, the crank torque, the slider force and
//! the side thrust.

use super::velocity::basics_e;
use super::{LayerCtx, NamedArrow};
use crate::figure::{ARROW_LENGTH, HATCH_DEPTH, Hue, Item, RichText, Role, Shape, TextSize};
use crate::geom::{Point, Vector, cross};
use crate::number::{given, sig};
use crate::scene::canvas::Canvas;
use crate::scene::notation::Named::*;
use crate::sources::NG_TORQUE;

/// Length of the slider-force arrow, page units.
const FORCE_ARROW: f64 = 64.0;
/// Radius of the torque arrow about the crank centre, page units: wide
/// enough for the centre's letter to sit inside it.
const TORQUE_RADIUS: f64 = 36.0;
/// What the torque arc turns through, radians (about 252°): the rest is
/// the gap its letter sits in.
const TORQUE_SWEEP: f64 = 4.4;
/// Room kept between the torque arc and the slider's block, page units
/// (an arrowhead's length).
const ARROW_ROOM: f64 = 8.0;
/// How far from the crank centre the torque arrow reaches with the room
/// for its head, page units: what the slider's arrows keep out of.
pub(super) const TORQUE_REACH: f64 = TORQUE_RADIUS + ARROW_ROOM;

/// The values the figure names by symbol only, for the notes below it:
/// OM and T, then the forces (or why there is no finite slider force).
pub(crate) fn notes(ctx: &LayerCtx) -> Vec<RichText> {
    let scene = ctx.scene;
    let tl = ctx.main.torque();
    let (unit, force) = (scene.units().length(), scene.units().force());
    let om = format!("*{}{}*", ctx.letter(CrankCentre), ctx.letter(VelocityPoint));
    let t = scene.torque();
    // OM below the smallest number (a tiny crank a hair from a dead
    // centre) is not written 0: that is a dead centre.
    let arm = if tl.om() == 0.0 && tl.om_per_crank() != 0.0 {
        format!("< {} {unit}", sig(f64::from_bits(1)))
    } else {
        format!("= {} {unit}", sig(tl.om().abs()))
    };
    let mut out = vec![RichText::parse(&format!(
        "Torque line: {om} {arm}, crank torque *T* = {} {force}·{unit}.",
        given(t)
    ))];
    let r = ctx.main.pose().mechanism().crank();
    let fc = format!("*F*_c = *T*/*r* {}", amount(t / r, force));
    out.push(RichText::parse(&match tl.slider_force(t) {
        Ok(Some(fp)) => format!(
            "Forces: {fc}, *F*_p {}, *F*_s {}.",
            amount(fp, force),
            amount(tl.side_thrust(fp).unwrap_or(f64::INFINITY), force)
        ),
        Ok(None) => format!("Forces: {fc}; dead centre: {om} = 0, no finite slider force."),
        // T / OM beyond the largest number: OM is small, not zero.
        Err(_) => format!(
            "Forces: {fc}, *F*_p = *T*/{om} {}, *F*_s {}.",
            amount(f64::INFINITY, force),
            amount(
                tl.side_thrust_from_torque(t)
                    .ok()
                    .flatten()
                    .unwrap_or(f64::INFINITY),
                force
            )
        ),
    }));
    if let Some(note) = borrowed_torque(ctx, t) {
        out.push(RichText::parse(&note));
    }
    out
}

/// A note when the torque is Ng's (264.87 N·mm, 1 kg on a 27 mm arm)
/// drawn for another engine or in another unit: the number is kept as it
/// is (a unit is a name, nothing is converted), so the figure says where
/// it came from and how to give the engine's own. `None` for Ng's rig in
/// millimetres, or any other torque.
fn borrowed_torque(ctx: &LayerCtx, t: f64) -> Option<String> {
    let m = ctx.main.pose().mechanism();
    let units = ctx.scene.units();
    let ngs_rig = m.crank() == 25.0 && m.rod() == 72.0 && units.length().to_string() == "mm";
    (t == NG_TORQUE && !ngs_rig).then(|| {
        format!(
            "The torque *T* is that of Ng’s rig: 1 kg on a 27 mm arm, {} N·mm.",
            given(NG_TORQUE)
        )
    })
}

/// `= 12.35 N` for a force's magnitude, or `exceeds 1.8×10³⁰⁸ N` when it is
/// beyond the largest number (a huge torque on a tiny mechanism): never
/// `inf`, never a false 0.
fn amount(x: f64, unit: &(impl std::fmt::Display + ?Sized)) -> String {
    if x.is_finite() {
        format!("= {} {unit}", sig(x.abs()))
    } else {
        format!("exceeds {} {unit}", sig(f64::MAX))
    }
}

pub(crate) fn draw(ctx: &LayerCtx, canvas: &mut Canvas) {
    basics_e(ctx, canvas);
    let scene = ctx.scene;
    let pose = ctx.main.pose();
    let (a, b, c) = (pose.a(), pose.b(), pose.c());
    // The crank torque: an arc arrow about the crank centre (left to a
    // detail of the crank where there is one).
    if !canvas.is_bare(c) {
        // Where the slider's block comes within the arc's reach (a short
        // rod near the inner dead centre), the arc opens towards it.
        let s = &ctx.sizes;
        let ca = a - c;
        let block = s.block_half_length.hypot(s.block_half_height);
        let near = ca.norm() - block < canvas.world(TORQUE_REACH);
        let gap = near.then(|| ca.y.atan2(ca.x));
        // The arc clear of the rod and the rod produced to M where they
        // run by it about as far from the centre as its radius.
        let m = ctx.main.e().e();
        let produced = (m - b).dot(&(b - a)) > 0.0;
        let rods = std::iter::once((b, a)).chain(produced.then_some((b, m)));
        let passing: Vec<f64> = rods
            .map(|(p, q)| canvas.page(crate::geom::point_segment_distance(c, p, q)))
            .collect();
        let radius = canvas.world(clear_of_the_rod(&passing));
        // The crank, θ's letter on its mark's bisector, and the rod where
        // it passes within the arc's reach (a short rod or an offset).
        let crank = (b - c).y.atan2((b - c).x);
        let reach = canvas.world(TORQUE_REACH);
        // The torque line OM from the centre, the rod produced to M and
        // the offset's dimension line (world −x from the centre) too: at
        // a dead centre OM ran down through the gap, and T, set off it by
        // its letter's placing, stood by M's dot, far from the arc, or on
        // the rod.
        let e = pose.mechanism().offset();
        let extension = (canvas.page(e.abs()) >= 4.0).then_some(std::f64::consts::PI);
        let avoid: Vec<f64> = [crank, 0.5 * crank.rem_euclid(std::f64::consts::TAU)]
            .into_iter()
            .chain(extension)
            .chain(within(c, reach, b, a))
            .chain(within(c, reach, c, m))
            .chain(within(c, reach, b, m).filter(|_| produced))
            .collect();
        for item in torque_arrow(c, scene.torque(), radius, gap, &avoid) {
            canvas.push_item(item);
        }
    }
    for f in forces(ctx, &|page| canvas.world(page)) {
        if !canvas.contains(f.from) {
            continue;
        }
        f.draw(canvas, "force", Hue::Force);
    }

    // The transmission angle β at the crank pin, between its two links.
    let (u, v) = (c - b, a - b);
    let sweep = cross(&u, &v).atan2(u.dot(&v));
    if sweep.abs() > 1e-3 && !canvas.is_bare(b) {
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

/// The least room (page units) between the torque arc and a rod that
/// runs by the crank centre at about the arc's radius: at l = 1.55 r,
/// e = 0.402 r, 180° the rod passed 3 units over the arc's top at M,
/// arc, rod, M and θ's arc piled up there.
const ROD_ROOM: f64 = 8.0;

/// The least radius of the torque arc, page units: O's letter within it.
const TORQUE_LEAST: f64 = 26.0;

/// The torque arc's radius, page units: [`TORQUE_RADIUS`], or where a
/// rod runs by the centre (`passing`, its least page distances from it)
/// within [`ROD_ROOM`] of that circle, along it, the largest radius down
/// to [`TORQUE_LEAST`] that keeps the room from them all; where none
/// does, the usual one.
fn clear_of_the_rod(passing: &[f64]) -> f64 {
    let clear = |r: f64| passing.iter().all(|d| (d - r).abs() >= ROD_ROOM);
    let steps = (TORQUE_RADIUS - TORQUE_LEAST) as u32;
    (0..=steps)
        .map(|k| TORQUE_RADIUS - f64::from(k))
        .find(|&r| clear(r))
        .unwrap_or(TORQUE_RADIUS)
}

/// The torque `t` as an arc arrow of `radius` (world units) about the
/// crank centre `c` in its sense, lettered T (`torque-T`, `value-T`). The
/// gap is below the centre (above it for a clockwise torque) and holds
/// the letter; or it is centred on the world direction `gap` where one is
/// given (the slider's block, which the arc would otherwise cross), and
/// the letter goes beside the arc where it runs farthest from the world
/// directions `avoid` and the gap's (the crank, θ's letter, the rod: at
/// the inner dead centre the arc's middle lies on the crank). A gap that
/// one of `avoid` runs through (the crank at 270°, a rod passing below
/// the centre) gives its letter up in the same way. A zero torque turns
/// counter-clockwise (a caller that draws no arrow for it leaves it out).
/// Where no gap is given and one of `avoid` runs through the usual gap,
/// the gap turns to the nearest direction that leaves each of them well
/// past the arc's ends ([`free_gap`]), and T stands in it, between the
/// arrowhead and the tail, by the head; only where there is none is T
/// set beside the arc.
pub(crate) fn torque_arrow(
    c: Point,
    t: f64,
    radius: f64,
    gap: Option<f64>,
    avoid: &[f64],
) -> [Item; 2] {
    let turn = if t >= 0.0 { 1.0 } else { -1.0 };
    let sweep = turn * TORQUE_SWEEP;
    // The gap's middle is half a sweep and half a turn past the start.
    let half_gap = 0.5 * (std::f64::consts::TAU - TORQUE_SWEEP);
    let usual = -0.9 * turn;
    let gap = gap.map(|g| (g, Gap::Block)).or_else(|| {
        let middle = usual + 0.5 * sweep + std::f64::consts::PI;
        free_gap(middle, half_gap, turn, avoid).map(|(g, turned)| match turned {
            true => (g, Gap::Turned),
            false => (g, Gap::Usual),
        })
    });
    let start = match gap {
        Some((g, _)) => g - turn * (0.5 * TORQUE_SWEEP + std::f64::consts::PI),
        None => usual,
    };
    // T in the gap, or, where the gap holds the block or something to
    // avoid, beside the arc clear of what stands about the centre.
    // By the arrowhead, so that T names the arrow: at the gap's middle it
    // stood as far from the head as from the tail, and where the gap
    // turned (Ng's Fig. 1 at 180°, an offset of −2.04 r) by the end of
    // θ's arc, which it read as naming.
    let middle = start + 0.5 * sweep + std::f64::consts::PI;
    let by_head = start + sweep + turn * BY_HEAD;
    let mid = match gap {
        Some((_, Gap::Usual | Gap::Turned)) => by_head,
        Some((g, Gap::Block)) => {
            let avoid: Vec<f64> = avoid.iter().copied().chain([g]).collect();
            start + sweep * clearest_share(start, sweep, &avoid)
        }
        // One of `avoid` runs through the gap: T still by the head where
        // that stands clear of them all (set by the arc's clearest share,
        // it stood by θ's arc, struck by it, far from the head: l = 1.53 r,
        // e = 0.467 r, 270.95°).
        None if avoid.iter().any(|&a| apart(a, middle) < half_gap) => {
            if avoid.iter().all(|&a| apart(a, by_head) >= HEAD_MARGIN) {
                by_head
            } else {
                start + sweep * clearest_share(start, sweep, avoid)
            }
        }
        None => by_head,
    };
    [
        Item::new(
            "torque-T",
            Role::Force,
            Shape::Arc {
                centre: c,
                radius,
                start,
                sweep,
                arrow: true,
            },
        ),
        Item::new(
            "value-T",
            Role::Label,
            Shape::Label {
                anchor: c + Vector::new(mid.cos(), mid.sin()) * radius,
                text: RichText::italic("T"),
                size: TextSize::Small,
                toward: None,
                line: None,
            },
        ),
    ]
}

/// How far past the torque arc's head, radians (17°), its letter stands
/// in the gap: clear of the head (about 13° of the arc long) and nearer
/// it than the tail.
const BY_HEAD: f64 = 0.3;

/// Where the torque arrow's gap faces.
#[derive(Clone, Copy)]
enum Gap {
    /// The slider's block, given by the caller.
    Block,
    /// Below the centre (above it for a clockwise torque).
    Usual,
    /// Turned from there, clear of what ran through it ([`free_gap`]).
    Turned,
}

/// How far past the arc's tail (radians, 9°) every direction to be
/// avoided keeps from a turned gap…
const TAIL_MARGIN: f64 = 0.15;
/// …and past its arrowhead (23°: the head's length, about 13° of the
/// arc, and as much again): a head on a line read as that line's.
const HEAD_MARGIN: f64 = 0.4;

/// The gap's middle for T, the arc turning in the sense `turn` (±1),
/// and whether it is turned: `usual` where none of `avoid` comes within
/// `half_gap` of it, else the nearest direction, in steps of 5° either
/// way, from which each of them lies [`TAIL_MARGIN`] past the tail or
/// [`HEAD_MARGIN`] past the head, else none.
fn free_gap(usual: f64, half_gap: f64, turn: f64, avoid: &[f64]) -> Option<(f64, bool)> {
    if avoid.iter().all(|&a| apart(a, usual) >= half_gap) {
        return Some((usual, false));
    }
    let free = |g: f64| {
        avoid.iter().all(|&a| {
            // Where a lies from the gap's middle, in the arc's sense:
            // the tail at +half_gap, the head at −half_gap.
            let d = (a - g + std::f64::consts::PI).rem_euclid(std::f64::consts::TAU)
                - std::f64::consts::PI;
            let s = turn * d;
            s >= half_gap + TAIL_MARGIN || s <= -half_gap - HEAD_MARGIN
        })
    };
    let step = 5.0_f64.to_radians();
    (1..=36)
        .flat_map(|k| [usual + step * f64::from(k), usual - step * f64::from(k)])
        .find(|&g| free(g))
        .map(|g| (g, true))
}

/// The share of the arc from `start` through `sweep` (radians) at which it
/// runs farthest, in angle, from every direction of `avoid`: the share
/// nearest the arrowhead among equals (in steps of a twentieth, within
/// its middle two fifths, clear of the arrowhead, the tail and what
/// stands in the gap).
fn clearest_share(start: f64, sweep: f64, avoid: &[f64]) -> f64 {
    let clearance = |k: f64| {
        let at = start + sweep * k;
        avoid
            .iter()
            .map(|&a| apart(at, a))
            .fold(f64::INFINITY, f64::min)
    };
    // From the head's end of its middle two fifths towards the tail, so
    // that among equals T stands nearest the arrowhead it names.
    let shares = (0..=8).map(|i| 0.7 - 0.05 * f64::from(i));
    shares.fold(0.7, |best, k| match clearance(k) > clearance(best) + 1e-9 {
        true => k,
        false => best,
    })
}

/// The angle (radians, 0 to π) between the directions `a` and `b`.
fn apart(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(std::f64::consts::TAU);
    d.min(std::f64::consts::TAU - d)
}

/// The world directions from `c` of the points of the segment `p q`
/// that come within `radius` of it (every thirty-second of the segment).
fn within(c: Point, radius: f64, p: Point, q: Point) -> impl Iterator<Item = f64> {
    (0..=32)
        .map(move |k| p + (q - p) * (f64::from(k) / 32.0) - c)
        .filter(move |v| v.norm() < radius && v.norm() > 0.0)
        .map(|v| v.y.atan2(v.x))
}

/// How far F_c is set off its line, page units, where that line runs
/// along the rod: clear of the rod's stroke and the pin's circle, near
/// enough to read as the force on the pin.
pub(super) const ALONGSIDE: f64 = 7.0;

/// F_c drawn along its line arrives at the pin from the side the rod
/// leaves it by where the rod is nearly perpendicular to the crank (the
/// transmission angle near 90°, Ng's default among them): the arrow lay
/// on the rod. Within [`ALONG_THE_ROD`] of it, the arrow is set off its
/// line, parallel to it, on the side away from the rod, as a force on a
/// pin is drawn beside the member that brings it: the unit vector to
/// that side, else zero. `u` is the force's direction, `rod` the rod from
/// the pin.
///
/// So too where it runs along the parallel to the stroke through the pin
/// towards the slider (`parallel`), φ's reference: F_c from the block's
/// side at 90° lay on that dashed line and read as a mark of φ's.
fn beside_the_rod(u: Vector, rod: Vector, parallel: Vector) -> Vector {
    let along = |line: Vector| {
        let n = line.norm();
        n > 0.0 && (-u).dot(&line) >= n * ALONG_THE_ROD.cos()
    };
    if !along(rod) && !along(parallel) {
        return Vector::zeros();
    }
    let side = Vector::new(-u.y, u.x);
    if side.dot(&rod) > 0.0 { -side } else { side }
}

/// The angle (radians) between F_c's arrow and the rod within which the
/// arrow is set beside the rod ([`beside_the_rod`]): 20°.
pub(super) const ALONG_THE_ROD: f64 = 20.0 * std::f64::consts::PI / 180.0;

/// How far short of a pin (page units) an arrow that comes to it on its
/// line stops: clear of its circle.
pub(super) const PIN_SHORT: f64 = 7.0;

/// The least length of the side thrust's arrow, page units: its shaft
/// clear of the guide's hatching it leaves the block through, with its
/// head beyond (at 16 units, l = 49.4 r near 90° and 270°, the arrow was
/// a stub buried in the hatching).
const SIDE_THRUST_LEAST: f64 = HATCH_DEPTH + 2.0 * ARROW_LENGTH;

/// The force arrows, their page lengths turned to world lengths by
/// `world`: F_c = T / r on the crank pin, perpendicular to the crank in
/// the torque's sense (Ng eq. 2), pointing at the pin; the slider force
/// F_p along the stroke: from the block's face away from the rod where it
/// points away from the rod's side, else pushing on that face (an arrow
/// from the near face ran along the rod), and
/// the side thrust F_s from its top or bottom (to F_p's scale, within
/// limits). None at a dead centre, where the slider force is not finite.
pub(crate) fn forces(ctx: &LayerCtx, world: &dyn Fn(f64) -> f64) -> Vec<NamedArrow> {
    let pose = ctx.main.pose();
    let (a, b, c) = (pose.a(), pose.b(), pose.c());
    let t = ctx.scene.torque();
    let mut out = Vec::new();
    let cb = b - c;
    if t != 0.0 && cb.norm() > 0.0 {
        let u = Vector::new(-cb.y, cb.x) / cb.norm() * t.signum();
        // Short of the pin's circle on its line; beside the rod, level
        // with the pin.
        let parallel = Vector::new((a - b).x.signum(), 0.0);
        let side = beside_the_rod(u, a - b, parallel);
        let short = if side == Vector::zeros() {
            PIN_SHORT
        } else {
            2.0
        };
        let head = b - u * world(short) + side * world(ALONGSIDE);
        let tail = head - u * world(0.75 * FORCE_ARROW);
        out.push(NamedArrow {
            id: "Fc",
            name: "*F*_c",
            from: tail,
            to: head,
            name_at: tail,
        });
    }
    let s = &ctx.sizes;
    let tl = ctx.main.torque();
    // The slider force's sense along +x, and whether it is zero; a force
    // beyond the largest number still has the sense of T / OM.
    let sense = match tl.slider_force(t) {
        Ok(Some(fp)) => Some((fp.signum(), fp != 0.0)),
        Ok(None) => None,
        Err(_) => Some((t.signum() * tl.om_per_crank().signum(), true)),
    };
    if let Some((sign, nonzero)) = sense {
        let ux = Vector::new(sign, 0.0);
        let length = world(FORCE_ARROW);
        // A force towards the crank drawn from the block's near face would
        // run along the rod, which leaves the block on that side: it
        // pushes on the block's far face instead, as the gas pushes the
        // piston. A force away from the crank leaves the near face, where
        // nothing else is drawn.
        let (from, to) = if sign * (b.x - a.x) > 0.0 {
            let back = a - ux * s.block_half_length;
            (back - ux * length, back)
        } else {
            let face = a + ux * s.block_half_length;
            (face, face + ux * length)
        };
        out.push(NamedArrow {
            id: "Fp",
            name: "*F*_p",
            from,
            to,
            name_at: to,
        });
        // F_s = F_p tan φ: its sense and its length to F_p's scale need
        // only tan φ.
        let tan_phi = tl.tan_phi();
        if nonzero && tan_phi != 0.0 {
            let uy = Vector::new(0.0, sign * tan_phi.signum());
            let face = a + uy * s.block_half_height;
            let len = (FORCE_ARROW * tan_phi.abs()).clamp(SIDE_THRUST_LEAST, FORCE_ARROW);
            let to = face + uy * world(len);
            out.push(NamedArrow {
                id: "Fs",
                name: "*F*_s",
                from: face,
                to,
                name_at: to,
            });
        }
    }
    out
}

#[cfg(test)]
mod tests {
    #[test]
    fn amounts_beyond_the_largest_number_say_so() {
        assert_eq!(super::amount(-2.5, "N"), "= 2.500 N");
        assert_eq!(super::amount(f64::INFINITY, "N"), "exceeds 1.798×10³⁰⁸ N");
    }
}
