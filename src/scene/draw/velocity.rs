//! The velocity layer (Fig. 63; Ng Fig. A1): D, E and the similar
//! triangles ADB and ECB.

use super::LayerCtx;
use crate::figure::{Hue, RIGHT_ANGLE, Role, Shape};
use crate::geom::{Intersection, Point, Vector, cross, farthest_from_segment};
use crate::scene::canvas::{Canvas, Marker};
use crate::scene::notation::Named::{self, *};

/// How far past its ends the perpendicular through C is produced at
/// most, page units.
const PRODUCED: f64 = 6.0;

/// Page units within which a thin construction line beside a link along
/// its whole length reads as the link drawn double: a pin's radius (4.2)
/// and its pen, closer than which the two lines leave no gap a reader
/// tells from the heavy line's own width (Kisch's HG and the
/// perpendicular through C along the crank at a long rod near 90°).
const ON_LINK: f64 = 6.0;

/// Whether the segment `p`–`q` lies along a link (the crank CB or the
/// rod AB) on the canvas's page: both its ends within [`ON_LINK`] of the
/// link, and so all of it. Such a line is left out, its construction
/// read from the link it lies on.
pub(super) fn along_link(ctx: &LayerCtx, canvas: &Canvas, p: Point, q: Point) -> bool {
    let pose = ctx.main.pose();
    let links = [(pose.c(), pose.b()), (pose.b(), pose.a())];
    (links.iter()).any(|&(s, t)| canvas.page(farthest_from_segment(p, q, s, t)) < ON_LINK)
}

/// E: the perpendicular to the stroke through C, AB produced to meet it,
/// the right angle at C.
pub(crate) fn basics_e(ctx: &LayerCtx, canvas: &mut Canvas) {
    let hue = canvas.set_hue(Some(Hue::Velocity));
    let pose = ctx.main.pose();
    let (a, b, c) = (pose.a(), pose.b(), pose.c());
    let e = ctx.main.e().e();
    let r = pose.mechanism().crank();
    // Produced a little past C and E: an eighth of the crank, but no more
    // than [`PRODUCED`] on the page, so that a large crank leaves room
    // for E's letter beyond it.
    let ext = (0.12 * r).min(canvas.world(PRODUCED));
    // The perpendicular through C, and on it the result CE, heavier; the
    // perpendicular left out where CE lies along the crank (near 90°,
    // E by B), where it drew the crank double.
    if !along_link(ctx, canvas, c, e) {
        canvas.segment(
            format!("{}-produced", ctx.line(CrankCentre, VelocityPoint)),
            Role::Construction,
            Point::new(0.0, e.y.min(0.0) - ext),
            Point::new(0.0, e.y.max(0.0) + ext),
        );
    }
    canvas.segment(ctx.line(CrankCentre, VelocityPoint), Role::Result, c, e);
    if (e - b).dot(&(b - a)) > 0.0 {
        canvas.segment(ctx.line(CrankPin, VelocityPoint), Role::Auxiliary, b, e);
    }
    // The mark needs a leg longer than itself: with C and E closer than
    // two marks' sides it would hide E.
    if canvas.page((e - c).norm()) >= 2.0 * RIGHT_ANGLE && !canvas.is_bare(c) {
        canvas.push(
            format!("angle-{}", ctx.letter(CrankCentre)),
            Role::Construction,
            Shape::RightAngle {
                vertex: c,
                u: super::mechanism::mark_leg(ctx, canvas),
                v: e - c,
            },
        );
    }
    // At a dead centre E is C: the two are lettered together ("C, E"),
    // as the canvas letters every pair that coincides, in a detail too.
    canvas.point(ctx.letter(VelocityPoint), e, Marker::Dot, c);
    canvas.set_hue(hue);
}

/// D: CB produced meets the perpendicular to the stroke at A; a point off
/// the page or at infinity is shown by an arrow at the frame edge.
pub(crate) fn basics_d(ctx: &LayerCtx, canvas: &mut Canvas) {
    let hue = canvas.set_hue(Some(Hue::Velocity));
    let pose = ctx.main.pose();
    let (a, b) = (pose.a(), pose.b());
    let name = ctx.letter(InstantCentre);
    let d = ctx.main.d().d();
    match d {
        Intersection::Point(p) => {
            canvas.segment(ctx.line(CrankPin, InstantCentre), Role::Construction, b, p);
            canvas.segment(ctx.line(Slider, InstantCentre), Role::Construction, a, p);
            // The block hides a mark at A; only a bare construction has one.
            if p != a && !ctx.scene.has(crate::scene::Layer::Mechanism) {
                canvas.push(
                    format!("angle-{}", ctx.letter(Slider)),
                    Role::Construction,
                    Shape::RightAngle {
                        vertex: a,
                        u: Vector::new(-1.0, 0.0),
                        v: p - a,
                    },
                );
            }
        }
        Intersection::AtInfinity(_) => {
            let up = Vector::new(0.0, b.y.signum());
            canvas.ray(ctx.line(CrankPin, InstantCentre), Role::Construction, b, up);
            canvas.ray(ctx.line(Slider, InstantCentre), Role::Construction, a, up);
        }
        Intersection::Coincident => {}
    }
    let towards = Vector::new(0.0, b.y.signum());
    canvas.intersection(name, &d, Marker::Dot, a, towards);
    canvas.set_hue(hue);
}

fn region(ctx: &LayerCtx, canvas: &mut Canvas, names: [Named; 3], points: [Point; 3]) {
    let area = cross(&(points[1] - points[0]), &(points[2] - points[0]));
    if canvas.page(canvas.page(area.abs())) < 4.0 || !points.iter().all(|p| canvas.contains(*p)) {
        return;
    }
    let id = format!(
        "triangle-{}{}{}",
        ctx.letter(names[0]),
        ctx.letter(names[1]),
        ctx.letter(names[2])
    );
    canvas.push(
        id,
        Role::Construction,
        Shape::Region {
            points: points.to_vec(),
        },
    );
}

pub(crate) fn draw(ctx: &LayerCtx, canvas: &mut Canvas) {
    basics_e(ctx, canvas);
    basics_d(ctx, canvas);
    let pose = ctx.main.pose();
    let (a, b, c) = (pose.a(), pose.b(), pose.c());
    if let Intersection::Point(d) = ctx.main.d().d() {
        region(ctx, canvas, [Slider, InstantCentre, CrankPin], [a, d, b]);
    }
    let e = ctx.main.e().e();
    region(
        ctx,
        canvas,
        [VelocityPoint, CrankCentre, CrankPin],
        [e, c, b],
    );
}
