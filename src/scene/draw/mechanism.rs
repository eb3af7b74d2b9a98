//! The mechanism layer: frame, crank circle, links, slider and guides.

use super::LayerCtx;
use crate::figure::{Foot, HATCH_DEPTH, Part, RichText, Role, Shape, TextSize};
use crate::geom::{Point, Vector};
use crate::scene::cache::Constructions;
use crate::scene::canvas::{Canvas, Marker};
use crate::scene::linkage::{BEARING_REACH, GUIDE_MIN, HATCH_SLANT, LINK_CLEARANCE};
use crate::scene::notation::Named;

/// The bearing's reach about the crank centre, page units: the pedestal
/// and its hatched foot below (see the SVG writer's bearing), the shaft's
/// pin above, with a little paper all round. Left, right, below, above.
const BEARING_BOX: [f64; 4] = [BEARING_REACH, 20.0, 26.0, 8.0];

/// A stretch of a guide along x, world units.
type Span = (f64, f64);

/// The crank within this angle (radians, 40°) of straight down the page
/// runs through a bearing's pedestal below its centre.
const THROUGH_PEDESTAL: f64 = 0.7;

/// The side of the crank centre its bearing stands on: below, save where
/// a line the scene draws from the crank centre points down the page
/// within [`THROUGH_PEDESTAL`] and a pedestal below had it drawn through
/// it: the crank (about 270°), or the result CE of a construction that
/// finds E (E below C: an in-line engine past 180°, an offset engine
/// whose rod crosses below the crank centre), or CB produced to D
/// through C, or an acceleration construction's CF or its result CG.
/// Then it hangs from above where no such line runs up through it and
/// the guides do not run there (an offset engine with the block by the
/// crank centre: the hanging foot and its hatching read as a piece of
/// the guide), else it stands out to the side the lines leave clear.
/// Where every side is taken, it stands below, save where the crank
/// points down through it: then on the side, of those that keep clear of
/// the guides and links, where the line through it weighs least
/// ([`Through`]: a construction line before a link or a result), or
/// hanging where none keeps clear.
/// The right angle marking CE at C takes its leg along the stroke on the
/// side the bearing leaves ([`mark_leg`]): at Kisch's construction with
/// the crank down, l = 1.09 r at 269.67°, the crank took the foot below,
/// the mark's leg the side of the slider, and the pedestal stood on the
/// side of G with CG drawn through it.
/// A view held over a series of poses keeps it standing, so that it does
/// not turn over from frame to frame; a detail keeps the main view's
/// ([`LayerCtx::foot`]).
pub(super) fn foot(ctx: &LayerCtx, canvas: &Canvas) -> Foot {
    let pose = ctx.main.pose();
    let v = canvas.transform().apply_vector(pose.b() - pose.c());
    if let Some(kept) = ctx.foot {
        return kept;
    }
    if ctx.scene.held_view().is_some() || v.norm() == 0.0 {
        return Foot::Below;
    }
    let lines: Vec<(Vector, Through)> = (lines_from_centre(ctx).into_iter())
        .map(|(w, through)| (canvas.transform().apply_vector(w), through))
        // However short on the main view: a line hidden under the pin
        // there is drawn in the crank's detail, which keeps this foot
        // (Klein's CG at l = 29.7 r, 90.91°, 0.05 r to the right of C:
        // left out, the bearing stood out to the right, and G's dot
        // stood in its hatching at ×20).
        .filter(|(w, _)| w.norm() > 0.0)
        .collect();
    // The heaviest of the lines within the cone about `foot`'s direction,
    // which a pedestal standing there has run through it.
    let pierced = |foot: Foot| {
        let out = foot.axes().0;
        (lines.iter())
            .filter(|(w, _)| w.dot(&out) / w.norm() > THROUGH_PEDESTAL.cos())
            .map(|&(_, through)| through)
            .max()
    };
    if pierced(Foot::Below).is_none() {
        return Foot::Below;
    }
    let sides = [Foot::Above, Foot::Left, Foot::Right];
    if let Some(f) =
        (sides.into_iter()).find(|&f| pierced(f).is_none() && clear_for(ctx, canvas, f))
    {
        return f;
    }
    // Every side taken: as the crank alone would have it, hanging or to
    // a side where the crank points down through the foot below (the
    // least weighed of the sides clear, the first of equals; above where
    // none is), else below.
    let crank_down = v.y / v.norm() > THROUGH_PEDESTAL.cos();
    if !crank_down {
        return Foot::Below;
    }
    (sides.into_iter())
        .filter(|&f| clear_for(ctx, canvas, f))
        .min_by_key(|&f| pierced(f))
        .unwrap_or(Foot::Above)
}

/// What a line from the crank centre through a bearing's pedestal is, in
/// the order of the harm done by drawing it through: a construction
/// line, then a link or a result.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
enum Through {
    /// A construction line: CB produced to D, Klein's CF.
    Construction,
    /// The crank, or a result: CE, CG.
    Part,
}

/// The world vectors from the crank centre along the lines the scene
/// draws from it, each with what it is: the crank CB; CE where a layer
/// finds E (the velocity layer's, and every acceleration construction's
/// velocity part); CB produced through C to D where the velocity or
/// Klein's layer draws BD and D lies beyond C from B; each acceleration construction's result CG, and
/// Klein's CF.
fn lines_from_centre(ctx: &LayerCtx) -> Vec<(Vector, Through)> {
    use crate::scene::Layer;
    let scene = ctx.scene;
    let pose = ctx.main.pose();
    let (b, c) = (pose.b(), pose.c());
    let mut lines = vec![(b - c, Through::Part)];
    let finds_e = [
        Layer::Velocity,
        Layer::Klein,
        Layer::Kisch,
        Layer::Ritterhaus,
        Layer::Bennett,
    ]
    .into_iter()
    .any(|l| scene.has(l));
    if finds_e {
        let ce = ctx.main.e().e() - c;
        lines.push((ce, Through::Part));
    }
    if (scene.has(Layer::Velocity) || scene.has(Layer::Klein))
        && let crate::geom::Intersection::Point(d) = ctx.main.d().d()
        && (d - c).dot(&(b - c)) < 0.0
    {
        lines.push((d - c, Through::Construction));
    }
    for points in super::acceleration::drawn_points(ctx) {
        lines.push((points.g() - c, Through::Part));
    }
    if scene.has(Layer::Klein) {
        let f = super::acceleration::klein_points(ctx).f();
        lines.push((f - c, Through::Construction));
    }
    lines
}

/// The world direction along the stroke of the leg of the right angle
/// that marks CE at C: towards the slider, save where the crank
/// centre's bearing stands out to that side on the page, whose pedestal
/// the mark was drawn into; then the other way, along the stroke's line
/// through C all the same.
pub(super) fn mark_leg(ctx: &LayerCtx, canvas: &Canvas) -> Vector {
    let towards_slider = Vector::new(1.0, 0.0);
    let page = canvas.transform().apply_vector(towards_slider);
    if page.dot(&foot(ctx, canvas).axes().0) > 0.5 * page.norm() {
        -towards_slider
    } else {
        towards_slider
    }
}

/// Whether a bearing standing on `foot` keeps clear: hanging, of the
/// guides (their lines and hatching and the channel between, over the
/// block's travel); standing to a side, of the crank, the rod and the
/// block. Its box is [`bearing_box`].
fn clear_for(ctx: &LayerCtx, canvas: &Canvas, foot: Foot) -> bool {
    let pose = ctx.main.pose();
    let (c, b, a) = (pose.c(), pose.b(), pose.a());
    let s = &ctx.sizes;
    if foot == Foot::Above {
        let [left, right, below, above] = bearing_box(foot).map(|v| canvas.world(v));
        let (x0, x1, y0, y1) = (c.x - left, c.x + right, c.y - below, c.y + above);
        let (h, e) = (s.block_half_height, ctx.scene.mechanism().offset());
        let depth = canvas.world(HATCH_DEPTH + FRAME_GAP);
        let (g0, g1) = s.guides();
        let across = g0.min(g1) < x1 && g0.max(g1) > x0;
        return !(across && e - h - depth < y1 && e + h + depth > y0);
    }
    // To a side: the pedestal and its hatched base, on the page, from
    // the shaft's pin out to the hatching's far edge, across the base
    // and its slant.
    let t = canvas.transform();
    let (out, along) = foot.axes();
    let cp = t.apply(c);
    let within = |p: Point| {
        let v = t.apply(p) - cp;
        let (o, w) = (v.dot(&out), v.dot(&along).abs());
        o > PIN_CLEAR_OF_BEARING && o < SIDE_REACH.0 && w < SIDE_REACH.1
    };
    let (bl, bh) = (s.block_half_length, s.block_half_height);
    let corner = |x: f64, y: f64| a + Vector::new(x, y);
    let block = [
        (corner(-bl, -bh), corner(bl, -bh)),
        (corner(bl, -bh), corner(bl, bh)),
        (corner(bl, bh), corner(-bl, bh)),
        (corner(-bl, bh), corner(-bl, -bh)),
    ];
    ![(c, b), (b, a)]
        .into_iter()
        .chain(block)
        .any(|(p, q)| (0..=32).any(|k| within(p + (q - p) * (f64::from(k) / 32.0))))
}

/// A bearing standing to a side reaches this far out from its centre and
/// this far across, page units: the foot at 17, its hatching to 23 and
/// the letter's gap; the base 17 each way and its slant.
const SIDE_REACH: (f64, f64) = (30.0, 24.0);

/// Room (page units) about the crank centre inside which the crank and
/// the rod are not counted against a bearing to the side: the shaft's
/// pin, which the links leave from.
const PIN_CLEAR_OF_BEARING: f64 = 6.0;

/// Room (page units) a hanging bearing keeps beyond the guides' hatching.
const FRAME_GAP: f64 = 4.0;

/// The bearing's reach about the crank centre standing on `foot`, page
/// units: left, right, below, above ([`BEARING_BOX`] for one standing
/// below, turned with it; one to a side on the page's left or right).
fn bearing_box(foot: Foot) -> [f64; 4] {
    let [left, right, below, above] = BEARING_BOX;
    match foot {
        Foot::Below => [left, right, below, above],
        Foot::Above => [left, right, above, below],
        Foot::Left => [below, above, left, right],
        Foot::Right => [above, below, left, right],
    }
}

/// The stretches of the guide at height `y`, hatched towards `side`
/// (±1), that stay open (of its `hatch`ing, or of its line): where the
/// crank or the rod passes in front of it (a link is a part in front of
/// the frame, and the frame's line behind it is broken on either side, as
/// a draughtsman breaks a hidden line), and round the bearing (a part of
/// the frame the guide does not run through). The crank circle is the
/// path of the pin, not a part: the guide runs across it unbroken. The
/// line is never open under the block: the block always slides on its
/// guide (the rod leaves it through its edge on the guide's line, and a
/// block standing over the bearing, with rods of little more than a
/// crank near the inner dead centre, keeps its guide there).
fn openings(ctx: &LayerCtx, canvas: &Canvas, y: f64, side: f64, hatch: bool) -> Vec<Span> {
    let pose = ctx.main.pose();
    let (c, b, a) = (pose.c(), pose.b(), pose.a());
    let depth = y + side * canvas.world(HATCH_DEPTH);
    let (lo, hi) = (y.min(depth), y.max(depth));
    let slant = canvas.world(HATCH_SLANT);
    let d = canvas.world(LINK_CLEARANCE);
    let stand = foot(ctx, canvas);
    // The rod as drawn: beside the crank where it lies over it (there it
    // crosses a guide a little way from its line's crossing).
    let rod = rod_beside_crank(canvas, (c, b, a), stand).unwrap_or_else(|| vec![b, a]);
    let mut open: Vec<Span> = std::iter::once((c, b))
        .chain(rod.iter().zip(rod.iter().skip(1)).map(|(&p, &q)| (p, q)))
        .filter_map(|(p, q)| x_within(p, q, lo - d, hi + d))
        .map(|(x0, x1)| (x0 - d, x1 + d + slant))
        .collect();
    let mut reach = bearing_box(stand);
    // A bearing to a side is boxed on the page; the world runs the other
    // way on a mirrored page.
    let mirrored = canvas.transform().apply_vector(Vector::new(1.0, 0.0)).x < 0.0;
    if mirrored && matches!(stand, Foot::Left | Foot::Right) {
        reach.swap(0, 1);
    }
    let [left, right, below, above] = reach.map(|v| canvas.world(v));
    if hi > c.y - below && lo < c.y + above {
        open.push((c.x - left, c.x + right + slant));
    }
    if hatch {
        return open;
    }
    let l = ctx.sizes.block_half_length;
    open.into_iter()
        .flat_map(|o| pieces(o, vec![(a.x - l, a.x + l)]))
        .collect()
}

/// The x extent of the part of the segment `p q` between the heights
/// `lo` and `hi`; `None` where it keeps outside them.
fn x_within(p: Point, q: Point, lo: f64, hi: f64) -> Option<Span> {
    let dy = q.y - p.y;
    let (t0, t1) = if dy.abs() < 1e-12 {
        if p.y < lo || p.y > hi {
            return None;
        }
        (0.0, 1.0)
    } else {
        let (u, v) = ((lo - p.y) / dy, (hi - p.y) / dy);
        (u.min(v).max(0.0), u.max(v).min(1.0))
    };
    if t0 > t1 {
        return None;
    }
    let (x0, x1) = (p.x + t0 * (q.x - p.x), p.x + t1 * (q.x - p.x));
    Some((x0.min(x1), x0.max(x1)))
}

/// `whole` less the `openings`: the pieces of guide drawn, in order.
fn pieces(whole: Span, mut openings: Vec<Span>) -> Vec<Span> {
    openings.sort_by(|u, v| u.0.total_cmp(&v.0));
    let mut out = Vec::new();
    let mut from = whole.0;
    for (o0, o1) in openings {
        if o0 > from {
            out.push((from, o0.min(whole.1)));
        }
        from = from.max(o1);
    }
    if from < whole.1 {
        out.push((from, whole.1));
    }
    out.retain(|(u, v)| v > u);
    out
}

/// How far (page units) a guide that stops short of the crank circle
/// keeps from it.
const CLEAR_OF_CIRCLE: f64 = 6.0;

/// The stretch the guides run over: the block's whole travel
/// ([`crate::scene::draw::Sizes::guides`]), save that they stop short of
/// the crank circle unless a block drawn (the pose's, or a ghost's)
/// stands on them there. A rod of little more than a crank slides its
/// block into the circle; a guide laid under the whole travel would run
/// across the circle, the crank and its bearing, where the pin could not
/// pass it. A view held over a series of poses keeps the whole travel,
/// so the guides do not change from frame to frame.
fn guide_stretch(ctx: &LayerCtx, canvas: &Canvas, ghosts: &[Constructions]) -> Span {
    let whole = ctx.sizes.guides();
    if ctx.scene.held_view().is_some() {
        return whole;
    }
    let m = ctx.scene.mechanism();
    let (r, c) = (m.crank(), ctx.main.pose().c());
    let h = ctx.sizes.block_half_height;
    // The nearest the channel between the guides comes to the line of
    // the crank centre: where the circle reaches farthest along it.
    let (lo, hi) = (m.offset() - h - c.y, m.offset() + h - c.y);
    let nearest = if lo <= 0.0 && hi >= 0.0 {
        0.0
    } else {
        lo.abs().min(hi.abs())
    };
    if nearest >= r {
        return whole;
    }
    let edge = c.x + (r * r - nearest * nearest).sqrt() + canvas.world(CLEAR_OF_CIRCLE);
    let margin = 0.15 * r + ctx.sizes.block_half_length;
    let blocks = std::iter::once(ctx.main).chain(ghosts.iter());
    let first = blocks.map(|k| k.pose().a().x - margin).fold(edge, f64::min);
    (whole.0.max(first), whole.1)
}

/// The guides under the block over [`guide_stretch`], each hatched on
/// its outer side and broken where [`openings`] says; pieces shorter
/// than [`GUIDE_MIN`] are left out, and pieces the block does not stand
/// on that are shorter than the block. Ids `guide-upper`, `guide-upper-2`,
/// … in order along the stroke, each with its `hatch-` twin.
fn guides(ctx: &LayerCtx, ghosts: &[Constructions], canvas: &mut Canvas) {
    let m = ctx.scene.mechanism();
    let e = m.offset();
    let whole = guide_stretch(ctx, canvas, ghosts);
    let h = ctx.sizes.block_half_height;
    let (a, l) = (ctx.main.pose().a().x, ctx.sizes.block_half_length);
    // A piece cut off by a link that the block does not stand on and
    // shorter than the block holds nothing on the page and reads as a
    // stray (the coupler curves at l = 1.37 r, e = 0.225 r, 0°: a piece
    // of the lower guide beside B, past the rod).
    let shortest = canvas.world(GUIDE_MIN);
    let kept =
        |(u, v): &Span| v - u >= shortest && ((*u <= a + l && *v >= a - l) || v - u >= 2.0 * l);
    for (name, y, side) in [("upper", e + h, 1.0), ("lower", e - h, -1.0)] {
        let drawn: Vec<Span> = pieces(whole, openings(ctx, canvas, y, side, false))
            .into_iter()
            .filter(kept)
            .collect();
        let hatched = pieces(whole, openings(ctx, canvas, y, side, true));
        for (k, (u, v)) in drawn.into_iter().enumerate() {
            let id = match k {
                0 => format!("guide-{name}"),
                _ => format!("guide-{name}-{}", k + 1),
            };
            canvas.segment(id.clone(), Role::Frame, Point::new(u, y), Point::new(v, y));
            let runs = hatched
                .iter()
                .map(|(p, q)| (p.max(u), q.min(v)))
                .filter(|(p, q)| canvas.page(q - p) >= GUIDE_MIN)
                .collect::<Vec<_>>();
            for (j, (p, q)) in runs.into_iter().enumerate() {
                let hatch = match j {
                    0 => format!("hatch-{id}"),
                    _ => format!("hatch-{id}-{}", j + 1),
                };
                canvas.push(
                    hatch,
                    Role::Frame,
                    Shape::Hatch {
                        from: Point::new(p, y),
                        to: Point::new(q, y),
                        side: Vector::new(0.0, side),
                    },
                );
            }
        }
    }
}

pub(crate) fn draw(ctx: &LayerCtx, ghosts: &[Constructions], canvas: &mut Canvas) {
    let m = ctx.scene.mechanism();
    let (r, e) = (m.crank(), m.offset());
    let pose = ctx.main.pose();
    let (c, b, a) = (pose.c(), pose.b(), pose.a());
    let s = &ctx.sizes;
    let (g0, g1) = s.guides();
    let h = s.block_half_height;

    // The line of stroke (a centre line) and the crank-pin circle.
    canvas.centre_line(
        "line-stroke",
        Point::new(g0.min(-1.15 * r), e),
        Point::new(g1 + 0.1 * r, e),
    );
    canvas.with_part(Part::CrankCircle, |canvas| {
        canvas.push(
            "circle-crank",
            Role::Curve,
            Shape::Circle {
                centre: c,
                radius: r,
            },
        );
    });
    let foot = foot(ctx, canvas);
    canvas.push(
        format!("bearing-{}", ctx.letter(Named::CrankCentre)),
        Role::Frame,
        Shape::Bearing { centre: c, foot },
    );

    // Guides with their hatching on the outside, under the block over
    // its travel outside the crank circle.
    guides(ctx, ghosts, canvas);

    // Ghost poses first, so the main pose is drawn over them.
    draw_ghosts(ctx, ghosts, canvas);

    // The slider block about A.
    let l = s.block_half_length;
    canvas.push(
        "block-slider",
        Role::Link,
        Shape::Block {
            points: vec![
                Point::new(a.x - l, a.y - h),
                Point::new(a.x + l, a.y - h),
                Point::new(a.x + l, a.y + h),
                Point::new(a.x - l, a.y + h),
            ],
        },
    );
    canvas.segment("link-crank", Role::Link, c, b);
    match rod_beside_crank(canvas, (c, b, a), foot) {
        Some(points) => {
            canvas.push(
                "link-rod",
                Role::Link,
                Shape::Polyline {
                    points,
                    closed: false,
                },
            );
        }
        None => canvas.segment("link-rod", Role::Link, b, a),
    }
    canvas.with_part(Part::Joint, |canvas| {
        canvas.point(ctx.letter(Named::CrankCentre), c, Marker::Pin, c);
        canvas.point(ctx.letter(Named::CrankPin), b, Marker::Pin, c);
        canvas.point(ctx.letter(Named::Slider), a, Marker::Pin, c);
    });
}

/// How far (page units) a link is drawn beside the line of another that
/// lies along it (the rod over the crank here, Fig. 60's frame d beside
/// a moving link): a link's width and paper that reads as a gap between
/// two links (at 7 units, 4.4 of paper, Fig. 60's lever folded onto d
/// and d beside it read as one double line at l = 1.06 r, 180°).
pub(crate) const LINK_BESIDE: f64 = 10.0;
/// How far along its line (page units) a link drawn beside it turns in
/// at each end: twice [`LINK_BESIDE`], a slope that reads as a bend, not
/// a step.
pub(crate) const LINK_JOG: f64 = 2.0 * LINK_BESIDE;

/// The link `p q` drawn beside its line on the side `n` (a world unit
/// vector square to it), [`LINK_BESIDE`] off it between its ends and
/// turned in to them over `jogs` (world units along the line) at p and
/// at q: p, the two ends of the run beside, q. A `p q` of no length is
/// its ends.
pub(crate) fn path_beside(
    canvas: &Canvas,
    (p, q): (Point, Point),
    n: Vector,
    (at_p, at_q): (f64, f64),
) -> Vec<Point> {
    let shift = n * canvas.world(LINK_BESIDE);
    let u = crate::geom::unit(q - p).unwrap_or_else(Vector::zeros);
    vec![p, p + shift + u * at_p, q + shift - u * at_q, q]
}
/// The crank lies under the rod where the crank centre stands nearer the
/// rod than this (page units; a link's width and a little paper): the
/// two leave B along one line and read as one.
const UNDER_ROD: f64 = 5.0;
/// The shortest crank (page units) the rod is drawn beside: on a shorter
/// one the bend would be most of it (a crank a speck on a long rod is
/// shown in a detail, where it is drawn long).
const BESIDE_LEAST: f64 = 40.0;

/// The rod's line where the crank lies under it (the crank centre C
/// within [`UNDER_ROD`] of the rod B A: an in-line engine's rod runs over
/// C at 180°, and its crank, wholly under it, was not seen, the rod
/// appearing pinned at C, in the crank's detail of a long rod too): from
/// B turned out [`ROD_BESIDE`] beside the crank, on the side away from
/// C's bearing, past C's pin, and back in to its line on to A (clipped to
/// the canvas's frame). `None` where the crank does not lie under it, or
/// is shorter on the page than [`BESIDE_LEAST`], or where A stands
/// within [`BESIDE_LEAST`] of the rod's return to its line, or that
/// return is past the rod's middle.
fn rod_beside_crank(
    canvas: &Canvas,
    (c, b, a): (Point, Point, Point),
    foot: Foot,
) -> Option<Vec<Point>> {
    let crank = (b - c).norm();
    let length = (a - b).norm();
    if canvas.page(crank) < BESIDE_LEAST
        || length <= 0.0
        || canvas.page(crate::geom::point_segment_distance(c, b, a)) >= UNDER_ROD
    {
        return None;
    }
    let u = (a - b) / length;
    let normal = Vector::new(-u.y, u.x);
    // Away from the bearing's foot on the page (world y up).
    let out = canvas.transform().apply_vector(normal);
    let n = if out.dot(&foot.axes().0) > 0.0 {
        -normal
    } else {
        normal
    };
    let jog = canvas.world(LINK_JOG).min(crank / 3.0);
    // Past C's pin by the jog, back on the line short of A.
    let past = (c - b).dot(&u) + canvas.world(crate::scene::canvas::UNDER_PIN);
    let back = past + jog;
    // A short rod folded back over its crank (l = 1.05 r at 160°, 1.2 r
    // at 180°) ends by C: drawn beside the crank it ran into the block
    // and the guides, and drawn beside it the whole way, turned in only
    // at A (l = 1.08 r, 180°), three reviewers took it for a bent link.
    // Its middle, where its value's letter is set, kept on its line:
    // beside the crank to its middle (l = 1.5 r, e = 0.45 r at 244°),
    // the rod's l was set on the crank.
    if canvas.page(length - back) < BESIDE_LEAST || back > 0.5 * length {
        return None;
    }
    let at = |s: f64| b + u * s;
    // Out from B at 45°, within a link's width of it beside: a result's
    // dot on the crank just short of B (Klein's F, G at l = 43.5 r,
    // 180°, 8 units from B at ×20) stood under the rod turning out along
    // twice that, and CG could not be read (thirtieth review, 2).
    let out = canvas.world(LINK_BESIDE).min(jog);
    let mut points = path_beside(canvas, (b, at(back)), n, (out, jog));
    points.extend(canvas.frame().clip_segment(at(back), a).map(|(_, end)| end));
    Some(points)
}

/// Where the point `p` of the rod's line is drawn on the rod as drawn
/// ([`rod_beside_crank`]): beside the crank with the rod where the rod is
/// drawn there (Q, the rod's mid-point, over the crank of a short rod at
/// 180° stood on the crank, not on the rod); `p` itself elsewhere, or off
/// the rod.
pub(crate) fn on_rod_as_drawn(ctx: &LayerCtx, canvas: &Canvas, p: Point) -> Point {
    let pose = ctx.main.pose();
    let (c, b, a) = (pose.c(), pose.b(), pose.a());
    let Some(path) = rod_beside_crank(canvas, (c, b, a), foot(ctx, canvas)) else {
        return p;
    };
    let length = (a - b).norm();
    if canvas.page(crate::geom::point_segment_distance(p, b, a)) >= 0.5 {
        return p;
    }
    let u = (a - b) / length;
    let s = (p - b).dot(&u);
    (path.iter().zip(path.iter().skip(1)))
        .find_map(|(&p0, &p1)| {
            let (s0, s1) = ((p0 - b).dot(&u), (p1 - b).dot(&u));
            (s1 > s0 && (s0..=s1).contains(&s)).then(|| p0 + (p1 - p0) * ((s - s0) / (s1 - s0)))
        })
        .unwrap_or(p)
}

/// The ghost poses: their links, and their crank pins and cross-heads
/// numbered from 1 (`pose-1-links`, `point-B1`, `label-B1`, …).
fn draw_ghosts(ctx: &LayerCtx, ghosts: &[Constructions], canvas: &mut Canvas) {
    let c = ctx.main.pose().c();
    for (k, g) in ghosts.iter().enumerate() {
        let p = g.pose();
        let n = k + 1;
        let (gb, ga) = (p.b(), p.a());
        canvas.push(
            format!("pose-{n}-links"),
            Role::Auxiliary,
            Shape::Polyline {
                points: vec![c, gb, ga],
                closed: false,
            },
        );
        for (named, pt) in [(Named::CrankPin, gb), (Named::Slider, ga)] {
            let name = format!("{}{}", ctx.letter(named), n);
            canvas.push(
                format!("point-{name}"),
                Role::Auxiliary,
                Shape::Dot { centre: pt },
            );
            canvas.label(
                format!("label-{name}"),
                pt,
                RichText::italic(&format!("{}_{{{}}}", ctx.letter(named), n)),
                TextSize::Small,
            );
        }
    }
}
