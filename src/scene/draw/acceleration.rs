//! Klein's (Fig. 65), Kisch's (Fig. 66), Ritterhaus's and Bennett's
//! acceleration constructions.

use super::LayerCtx;
use super::velocity::{along_link, basics_d, basics_e};
use crate::construct::{AccelerationPoints, Kisch};
use crate::figure::{Role, Shape};
use crate::geom::{Point, Vector};
use crate::scene::canvas::{Canvas, Marker};
use crate::scene::notation::Named::{self, *};

/// FG perpendicular to AB, CG along the line through C parallel to the
/// stroke, the right angle at F, the points F and G.
fn fg(ctx: &LayerCtx, canvas: &mut Canvas, p: &AccelerationPoints, from: Point, from_name: Named) {
    let pose = ctx.main.pose();
    let (a, b, c) = (pose.a(), pose.b(), pose.c());
    let (f, g) = (p.f(), p.g());
    // Left out where it lies along a link (Kisch's HG along the crank
    // near 90°, H by B and G by C), with F's right angle, which would
    // mark a line not drawn.
    let drawn = !along_link(ctx, canvas, from, g);
    if drawn {
        canvas.segment(ctx.line(from_name, G), Role::Construction, from, g);
    }
    // Kisch's perpendicular from H meets the line through C at G before
    // it meets AB at F where F lies beyond G from H (an offset engine at
    // its outer dead centre): carried on to F, so that a drawn line meets
    // AB at F's right angle.
    if from_name != F && (f - from).norm() > (g - from).norm() {
        canvas.segment(ctx.line(G, F), Role::Construction, g, f);
    }
    canvas.segment(ctx.line(CrankCentre, G), Role::Result, c, g);
    let along = if (a - f).norm() > (b - f).norm() {
        a - f
    } else {
        b - f
    };
    if drawn && (g - f).norm() > 0.0 {
        canvas.push(
            "angle-F",
            Role::Construction,
            Shape::RightAngle {
                vertex: f,
                u: along,
                v: g - f,
            },
        );
    }
    canvas.point(ctx.letter(F), f, Marker::Dot, c);
    canvas.point(ctx.letter(G), g, Marker::Dot, c);
}

pub(crate) fn klein(ctx: &LayerCtx, canvas: &mut Canvas) {
    basics_e(ctx, canvas);
    basics_d(ctx, canvas);
    let pose = ctx.main.pose();
    let c = pose.c();
    let e = ctx.main.e().e();
    match ctx.main.klein() {
        Some(k) => {
            let d = k.d();
            canvas.segment(
                ctx.line(InstantCentre, VelocityPoint),
                Role::Auxiliary,
                d,
                e,
            );
            let f = k.points().f();
            canvas.segment(ctx.line(CrankCentre, F), Role::Construction, c, f);
            fg(ctx, canvas, k.points(), f, F);
        }
        None => {
            let p = klein_points(ctx);
            canvas.segment(ctx.line(CrankCentre, F), Role::Construction, c, p.f());
            fg(ctx, canvas, &p, p.f(), F);
        }
    }
}

/// The F and G the Klein layer draws: Klein's, or with D at infinity
/// (θ = 90°, 270°) the limit of his construction. There DE is the
/// perpendicular to the stroke through E, so CF, parallel to it, is the
/// perpendicular through C, and meets AB at F = B: the F and G that Kisch
/// finds without D.
pub(crate) fn klein_points(ctx: &LayerCtx) -> AccelerationPoints {
    match ctx.main.klein() {
        Some(k) => *k.points(),
        None => *ctx.main.kisch().points(),
    }
}

/// The F and G of each acceleration construction the scene draws (Klein's,
/// Kisch's, Ritterhaus's, Bennett's, in that order), the ends of the CG
/// each draws from C; none for Bennett's at an offset engine, which
/// draws E alone.
pub(crate) fn drawn_points(ctx: &LayerCtx) -> Vec<AccelerationPoints> {
    use crate::scene::Layer;
    let scene = ctx.scene;
    let main = ctx.main;
    [
        scene.has(Layer::Klein).then(|| klein_points(ctx)),
        scene.has(Layer::Kisch).then(|| *main.kisch().points()),
        scene
            .has(Layer::Ritterhaus)
            .then(|| *main.ritterhaus().points()),
        scene
            .has(Layer::Bennett)
            .then(|| main.bennett().map(|b| *b.points()))
            .flatten(),
    ]
    .into_iter()
    .flatten()
    .collect()
}

/// The unit normal to AB on the side of Kisch's semicircle: away from C,
/// upwards when C is on AB (as [`Kisch`] places H).
pub(crate) fn kisch_side(pose: &crate::mechanism::Pose) -> Vector {
    let (a, b) = (pose.a(), pose.b());
    let ab = b - a;
    let n = Vector::new(-ab.y, ab.x) / ab.norm();
    let towards_c = n.dot(&(pose.c() - b));
    if towards_c > 0.0 || (towards_c == 0.0 && n.y < 0.0) {
        -n
    } else {
        n
    }
}

/// The arc about `centre` of radius `radius` from direction `from` to
/// direction `to` the short way, with `over` radians more at each end.
pub(super) fn arc_between(
    centre: Point,
    radius: f64,
    from: Vector,
    to: Vector,
    over: f64,
) -> Shape {
    let a0 = from.y.atan2(from.x);
    let a1 = to.y.atan2(to.x);
    let mut sweep = a1 - a0;
    while sweep > std::f64::consts::PI {
        sweep -= 2.0 * std::f64::consts::PI;
    }
    while sweep < -std::f64::consts::PI {
        sweep += 2.0 * std::f64::consts::PI;
    }
    let s = if sweep >= 0.0 { 1.0 } else { -1.0 };
    Shape::Arc {
        centre,
        radius,
        start: a0 - s * over,
        sweep: sweep + 2.0 * s * over,
        arrow: false,
    }
}

/// How far Kisch's arc BE runs on past E and H, radians.
pub(super) const BE_OVERSHOOT: f64 = 0.12;

pub(crate) fn kisch(ctx: &LayerCtx, canvas: &mut Canvas) {
    basics_e(ctx, canvas);
    let pose = ctx.main.pose();
    let (a, b) = (pose.a(), pose.b());
    let k = ctx.main.kisch();
    let e = ctx.main.e().e();
    let circle = Kisch::semicircle(pose);
    // The half of the circle on AB away from C, where H is.
    let to_a = a - circle.centre;
    let start = to_a.y.atan2(to_a.x);
    let side = kisch_side(pose);
    let mid = Vector::new(-to_a.y, to_a.x); // start turned +90°
    let sweep = if mid.dot(&side) >= 0.0 {
        std::f64::consts::PI
    } else {
        -std::f64::consts::PI
    };
    let (nb, nh) = (ctx.letter(CrankPin), ctx.letter(H));
    let na = ctx.letter(Slider);
    canvas.push(
        format!("semicircle-{na}{nh}{nb}"),
        Role::Auxiliary,
        Shape::Arc {
            centre: circle.centre,
            radius: circle.radius,
            start,
            sweep,
            arrow: false,
        },
    );
    if let Some(h) = k.h() {
        let be = k.be();
        if canvas.page(be) > 1.0 {
            canvas.push(
                format!("arc-{nb}{}", ctx.letter(VelocityPoint)),
                Role::Auxiliary,
                arc_between(b, be, e - b, h - b, BE_OVERSHOOT),
            );
        }
        canvas.segment(ctx.line(CrankPin, H), Role::Auxiliary, b, h);
        canvas.segment(ctx.line(H, Slider), Role::Auxiliary, h, a);
        if (h - a).norm() > 0.0
            && (h - b).norm() > 0.0
            && canvas.page((h - k.points().f()).norm()) > 8.0
        {
            canvas.push(
                "angle-H",
                Role::Auxiliary,
                Shape::RightAngle {
                    vertex: h,
                    u: a - h,
                    v: b - h,
                },
            );
        }
        canvas.point(nh, h, Marker::Dot, pose.c());
        fg(ctx, canvas, k.points(), h, H);
    } else {
        fg(ctx, canvas, k.points(), k.points().f(), F);
    }
}

/// A right angle at `vertex` between `u` and `v` where both legs are
/// long enough on the page to carry it.
fn right_angle(canvas: &mut Canvas, id: &str, vertex: Point, u: Vector, v: Vector) {
    let legs = canvas.page(u.norm()).min(canvas.page(v.norm()));
    if legs >= 2.0 * crate::figure::RIGHT_ANGLE {
        canvas.push(id, Role::Construction, Shape::RightAngle { vertex, u, v });
    }
}

/// Ritterhaus's construction: E, EK parallel to AC to the crank CB
/// produced, KF perpendicular to the stroke, then FG as Klein's.
pub(crate) fn ritterhaus(ctx: &LayerCtx, canvas: &mut Canvas) {
    basics_e(ctx, canvas);
    let pose = ctx.main.pose();
    let (b, c) = (pose.b(), pose.c());
    let e = ctx.main.e().e();
    let r = ctx.main.ritterhaus();
    let (k, f) = (r.k(), r.points().f());
    // CB produced to K where K lies beyond B (else K is on the crank).
    if (k - c).norm() > (b - c).norm() {
        canvas.segment(ctx.line(CrankPin, K), Role::Auxiliary, b, k);
    }
    canvas.segment(ctx.line(VelocityPoint, K), Role::Construction, e, k);
    canvas.segment(ctx.line(K, F), Role::Construction, k, f);
    canvas.point(ctx.letter(K), k, Marker::Dot, c);
    fg(ctx, canvas, r.points(), f, F);
}

/// Bennett's construction: E (the velocity part), L at r²/l from B on the
/// rod, LK perpendicular to AB to the stroke, KF perpendicular to the
/// stroke, then FG as Klein's; E alone for an offset engine.
pub(crate) fn bennett(ctx: &LayerCtx, canvas: &mut Canvas) {
    basics_e(ctx, canvas);
    let Some(bn) = ctx.main.bennett() else {
        return;
    };
    let pose = ctx.main.pose();
    let (a, c) = (pose.a(), pose.c());
    let (l, k, f) = (bn.l(), bn.k(), bn.points().f());
    // LK and KF left out where they lie along a link (the crank near
    // 90°, L and F by B, K by C), LK with its right angle; L's right
    // angle left out too where it stands within a mark's two sides of
    // F's, which marks the same right angle with AB (at a long rod L and
    // F a few units apart on the rod, the two marks drew one double box).
    let lk = !along_link(ctx, canvas, l, k);
    if lk {
        canvas.segment(ctx.line(L, K), Role::Construction, l, k);
    }
    if !along_link(ctx, canvas, k, f) {
        canvas.segment(ctx.line(K, F), Role::Construction, k, f);
    }
    let f_marked = !along_link(ctx, canvas, f, bn.points().g());
    let by_f = canvas.page((l - f).norm()) < 2.0 * crate::figure::RIGHT_ANGLE;
    if lk && !(by_f && f_marked) {
        right_angle(canvas, "angle-L", l, a - l, k - l);
    }
    canvas.point(ctx.letter(L), l, Marker::Dot, c);
    canvas.point(ctx.letter(K), k, Marker::Dot, c);
    fg(ctx, canvas, bn.points(), f, F);
}
