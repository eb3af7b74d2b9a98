//! The world rectangle a figure must show whole.

use super::LayerCtx;
use crate::construct::Kisch;
use crate::figure::Shape;
use crate::geom::{Frame, Intersection, Point, Vector};
use crate::scene::Layer;

/// D is fitted into the page only while its height above the stroke stays
/// within this many (rod + crank) lengths; farther, it is shown by an arrow
/// at the frame edge.
pub(crate) const FAR_POINT: f64 = 0.8;

/// Whether D is near enough to be fitted.
pub(crate) fn d_is_near(ctx: &LayerCtx) -> Option<Point> {
    let m = ctx.scene.mechanism();
    match ctx.main.d().d() {
        Intersection::Point(d) if (d.y - m.offset()).abs() <= FAR_POINT * (m.rod() + m.crank()) => {
            Some(d)
        }
        _ => None,
    }
}

/// The world rectangle the scene's figure shows: the crank circle, the
/// guides and block, and the points of each layer drawn (E, D while near,
/// Klein's and Kisch's points, the arrows once the page scale is known,
/// the polar curve and the coupler curve, the polygons), and the frame the scene is
/// asked to hold ([`crate::scene::Scene::with_view_holding`]). Points that are not finite are
/// left out: at worst the frame is the crank circle's with the guides.
pub(crate) fn frame(ctx: &LayerCtx) -> Frame {
    frame_with(ctx, true)
}

/// [`frame`] without D: the rectangle a view held over many poses fits
/// each pose to ([`super::held`]). Over a turn D climbs towards infinity
/// at the quarter turns, and a view that kept room for it at every pose
/// would draw the mechanism a fraction of the page wide; D off the page
/// is shown by its arrow at the frame's edge, as at infinity.
pub(crate) fn frame_without_d(ctx: &LayerCtx) -> Frame {
    frame_with(ctx, false)
}

/// [`frame`], with D where it is near only if `with_d`.
fn frame_with(ctx: &LayerCtx, with_d: bool) -> Frame {
    let m = ctx.scene.mechanism();
    let (r, e) = (m.crank(), m.offset());
    let s = &ctx.sizes;
    let (g0, g1) = s.guides();
    let mut b = Frame::new(Point::new(-r, -r), Point::new(r, r));
    b.include(Point::new(g0.min(-r), e - s.block_half_height));
    b.include(Point::new(g1, e + s.block_half_height));
    add_e_and_d(&mut b, ctx, with_d);
    let scene = ctx.scene;
    if scene.has(Layer::Klein) {
        let k = super::acceleration::klein_points(ctx);
        b.include(k.f());
        b.include(k.g());
    }
    if scene.has(Layer::Kisch) {
        add_kisch(&mut b, ctx);
    }
    if scene.has(Layer::Ritterhaus) {
        let r = ctx.main.ritterhaus();
        for p in [r.k(), r.points().f(), r.points().g()] {
            b.include(p);
        }
    }
    if scene.has(Layer::Bennett)
        && let Some(bn) = ctx.main.bennett()
    {
        for p in [bn.l(), bn.k(), bn.points().f(), bn.points().g()] {
            b.include(p);
        }
    }
    add_arrows(&mut b, ctx);
    if scene.has(Layer::Polar) {
        add_polar(&mut b, ctx);
    }
    if scene.has(Layer::Coupler) {
        add_coupler(&mut b, ctx);
    }
    if scene.has(Layer::Polygons) {
        // Each polygon's caption below it, once the page scale is known.
        let below = ctx
            .sizes
            .page_scale
            .map_or(0.0, |s| super::polygons::CAPTION_ROOM / s);
        for p in super::polygons::place(ctx).points() {
            b.include(p);
            b.include(p - Vector::new(0.0, below));
        }
        // Q, which may stand off the rod's line.
        b.include(scene.coupler().point(ctx.main.pose()));
    }
    if let Some(f) = scene.holding() {
        b.include(f.min());
        b.include(f.max());
    }
    b
}

/// Adds E where a layer draws it, and, if `with_d`, D where a layer draws
/// it and it is near (see [`d_is_near`]).
fn add_e_and_d(b: &mut Frame, ctx: &LayerCtx, with_d: bool) {
    let scene = ctx.scene;
    let wants_e = (scene.layers().iter()).any(|l| l.draws_e() || *l == Layer::VirtualCentres);
    if wants_e {
        b.include(ctx.main.e().e());
    }
    if with_d
        && [
            Layer::Velocity,
            Layer::Klein,
            Layer::VirtualCentres,
            Layer::Centrodes,
        ]
        .iter()
        .any(|l| scene.has(*l))
        && let Some(d) = d_is_near(ctx)
    {
        b.include(d);
    }
}

/// Adds Kisch's construction: F, G, the half of the circle on AB away
/// from C, and the arc BE about B from E to H (none where there is no H).
fn add_kisch(b: &mut Frame, ctx: &LayerCtx) {
    let pose = ctx.main.pose();
    let k = ctx.main.kisch();
    b.include(k.points().f());
    b.include(k.points().g());
    // The half of the circle on AB away from C (where H is).
    let c = Kisch::semicircle(pose);
    let ab = pose.b() - pose.a();
    let n = super::acceleration::kisch_side(pose);
    let u = ab / ab.norm();
    for k in 0..=24 {
        let t = std::f64::consts::PI * k as f64 / 24.0;
        b.include(c.centre + (u * t.cos() + n * t.sin()) * c.radius);
    }
    // The arc BE about B, from E to H.
    if let Some(h) = k.h() {
        let (pin, e) = (pose.b(), ctx.main.e().e());
        let over = super::acceleration::BE_OVERSHOOT;
        let arc = super::acceleration::arc_between(pin, k.be(), e - pin, h - pin, over);
        if let Shape::Arc {
            centre,
            radius,
            start,
            sweep,
            ..
        } = arc
        {
            for k in 0..=24 {
                let t = start + sweep * k as f64 / 24.0;
                b.include(centre + Vector::new(t.cos(), t.sin()) * radius);
            }
        }
    }
}

/// Adds the reach of the force and velocity arrows, drawn to page
/// lengths: nothing until the page scale is known.
fn add_arrows(b: &mut Frame, ctx: &LayerCtx) {
    let Some(scale) = ctx.sizes.page_scale else {
        return;
    };
    let scene = ctx.scene;
    let world = |page: f64| page / scale;
    let mut arrows = Vec::new();
    if scene.has(Layer::Torque) {
        arrows.extend(super::torque::forces(ctx, &world));
    }
    if scene.has(Layer::Motion) {
        arrows.extend(super::motion::velocities(ctx, &world));
    }
    for p in arrows.iter().flat_map(|a| a.reach(&world)) {
        b.include(p);
    }
}

/// Adds the polar velocity curve every 5° of crank angle, and its mirror
/// through the centre (the return stroke's loop), where it is defined.
fn add_polar(b: &mut Frame, ctx: &LayerCtx) {
    let m = ctx.scene.mechanism();
    let polar = crate::diagram::Locus::new(*m, crate::diagram::LocusKind::PolarVelocity);
    for k in 0..72 {
        if let Some((p, _)) = crate::diagram::Curve::eval(&polar, 5.0 * k as f64) {
            // The return stroke's loop is set off on the crank itself.
            b.include(p);
            b.include(Point::origin() - p.coords);
        }
    }
}

/// Adds the coupler curve every 5° of crank angle.
fn add_coupler(b: &mut Frame, ctx: &LayerCtx) {
    let m = ctx.scene.mechanism();
    let q = ctx.scene.coupler();
    for k in 0..72 {
        // cannot fail: multiples of 5° below 360° are finite.
        #[allow(clippy::expect_used)]
        let a = crate::angle::Angle::from_degrees(5.0 * k as f64).expect("finite");
        b.include(q.point(&m.pose(a)));
    }
}
