//! The polygons layer: the velocity and acceleration polygons of the
//! relative-velocity method (docs/polygons.md), drawn below the mechanism
//! to the scales their notes state.
//!
//! Lettering: each point's image is its own letter in lower case (b the
//! image of B), the acceleration images primed (b′); the pole is the
//! image of the crank centre, and of every fixed point; x ends the rod's
//! normal component b′x, as Rattan and Khurmi letter it.

use super::LayerCtx;
use crate::construct::{AccelerationPolygon, VelocityPolygon};
use crate::figure::{Align, Hue, RIGHT_ANGLE, RichText, Role, Shape, TextSize};
use crate::geom::{Frame, Point, Vector, side_by_side_ends};
use crate::number::{short, sig};
use crate::scene::canvas::{Canvas, Marker};
use crate::scene::notation::Named::{self, *};

/// The steps the polygons' magnification k is chosen from (times a power
/// of ten): round numbers, so that the scale is read at a glance.
const STEPS: [f64; 9] = [1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0];

/// The share of the mechanism's length, l + 2r, that ob = k r is made
/// at most (and never shorter than the crank).
const SHARE: f64 = 0.25;

/// The room between the mechanism and the polygons, and between the two
/// polygons, in lengths ob = k r.
const GAP: f64 = 0.5;

/// Room kept for letters between the mechanism and the polygons, page
/// units.
const LETTER_ROOM: f64 = 24.0;

/// The least room between the two polygons, page units: a letter group
/// of three images ("*b*, *a*, *q*", about 57 units) set beside the
/// velocity polygon's right vertex, one beside the acceleration polygon's
/// left vertex, and two ems between (near 90° the polygons are needles
/// whose letters stand on one line: 0.5 k r apart, "*b*, *a*, *q*  *c*′,
/// *a*′" read as one string).
const LETTERS_APART: f64 = 150.0;

/// Shortest vector drawn as an arrow, page units: shorter, its head would
/// hide it (a zero vector, at a dead centre or 90°, is not drawn).
const MIN_ARROW: f64 = 12.0;

/// The two polygons placed on the drawing: the magnification k (a
/// vector v per ω or per ω² is drawn k v long), the sign of ω (the
/// velocities turn with it), the poles, and the polygons.
pub(crate) struct Placed {
    pub k: f64,
    sign: f64,
    pub velocity_pole: Point,
    pub acceleration_pole: Point,
    pub velocity: VelocityPolygon,
    pub acceleration: AccelerationPolygon,
}

/// The velocity polygon's points: o, b, a, q.
pub(crate) struct VelocityPoints {
    pub o: Point,
    pub b: Point,
    pub a: Point,
    pub q: Option<Point>,
}

/// The acceleration polygon's points: o′, b′, x, a′, q′.
pub(crate) struct AccelerationPoints {
    pub o: Point,
    pub b: Point,
    pub x: Point,
    pub a: Point,
    pub q: Option<Point>,
}

/// The magnification k for a crank `r` on a rod `l`: the largest round
/// step that keeps k r within [`SHARE`] of l + 2r, at least 1 (a short
/// rod's polygons are drawn to the crank's own scale, CB representing
/// V_B = rω and ω²r).
pub(crate) fn magnification(r: f64, l: f64) -> f64 {
    let most = SHARE * (l + 2.0 * r) / r;
    if !(most.is_finite() && most > 1.0) {
        return 1.0;
    }
    let decade = 10f64.powf(most.log10().floor());
    STEPS
        .iter()
        .map(|s| s * decade)
        .filter(|k| *k <= most)
        .fold(1.0, f64::max)
}

/// The corners of the smallest box round `points`.
fn bounds(points: &[Vector]) -> (Vector, Vector) {
    let lo = points.iter().fold(Vector::zeros(), |m, p| m.inf(p));
    let hi = points.iter().fold(Vector::zeros(), |m, p| m.sup(p));
    (lo, hi)
}

/// Places the polygons of the pose of `ctx` below its mechanism, side by
/// side (the velocity polygon first as the page reads, on the left also
/// when the figure is mirrored), centred under the crank and the guides.
pub(crate) fn place(ctx: &LayerCtx) -> Placed {
    let scene = ctx.scene;
    let m = scene.mechanism();
    let (r, l, e) = (m.crank(), m.rod(), m.offset());
    let (velocity, acceleration) = *ctx.main.polygons(scene.coupler());
    let k = magnification(r, l);
    let sign = if scene.omega() < 0.0 { -1.0 } else { 1.0 };
    let v: Vec<Vector> = [Some(velocity.b()), Some(velocity.a()), velocity.q()]
        .into_iter()
        .flatten()
        .map(|p| p * (k * sign))
        .collect();
    let acc = acceleration;
    let a: Vec<Vector> = [Some(acc.b()), Some(acc.x()), Some(acc.a()), acc.q()]
        .into_iter()
        .flatten()
        .map(|p| p * k)
        .collect();
    let (v_lo, v_hi) = bounds(&v);
    let (a_lo, a_hi) = bounds(&a);
    let (v_width, a_width) = (v_hi.x - v_lo.x, a_hi.x - a_lo.x);
    // In world lengths only: a gap that followed the page scale would
    // move the frame the fit is made for between its passes.
    let gap = GAP * k * r;
    let apart = ctx.sizes.page_scale.map_or(0.0, |s| LETTERS_APART / s);
    let between = gap.max(apart);
    let width = v_width + between + a_width;
    let (_, right) = ctx.sizes.guides();
    let left = 0.5 * (-r + right) - 0.5 * width;
    // Below the mechanism by the gap and, once the page scale is known,
    // room for the letters between (a drawing made small by a page held
    // to a low height would otherwise set them among the mechanism's).
    let letters = ctx.sizes.page_scale.map_or(0.0, |s| LETTER_ROOM / s);
    // Q off the rod's line may stand below the crank circle.
    let q = scene.coupler().point(ctx.main.pose()).y;
    let top = (-r).min(e - ctx.sizes.block_half_height).min(q) - gap - letters;
    // Mirrored, world x runs right to left on the page.
    let (v_left, a_left) = if scene.is_mirrored() {
        (left + a_width + between, left)
    } else {
        (left, left + v_width + between)
    };
    let velocity_pole = Point::new(v_left - v_lo.x, top - v_hi.y);
    let acceleration_pole = Point::new(a_left - a_lo.x, top - a_hi.y);
    Placed {
        k,
        sign,
        velocity_pole,
        acceleration_pole,
        velocity,
        acceleration,
    }
}

impl Placed {
    /// The velocity polygon's points on the drawing.
    pub(crate) fn velocity_points(&self) -> VelocityPoints {
        let o = self.velocity_pole;
        let at = |v: Vector| o + v * (self.k * self.sign);
        VelocityPoints {
            o,
            b: at(self.velocity.b()),
            a: at(self.velocity.a()),
            q: self.velocity.q().map(at),
        }
    }

    /// The acceleration polygon's points on the drawing.
    pub(crate) fn acceleration_points(&self) -> AccelerationPoints {
        let o = self.acceleration_pole;
        let at = |v: Vector| o + v * self.k;
        let p = &self.acceleration;
        AccelerationPoints {
            o,
            b: at(p.b()),
            x: at(p.x()),
            a: at(p.a()),
            q: p.q().map(at),
        }
    }

    /// Every point drawn, for the fit.
    pub(crate) fn points(&self) -> Vec<Point> {
        let v = self.velocity_points();
        let a = self.acceleration_points();
        let mut out = vec![v.o, v.b, v.a, a.o, a.b, a.x, a.a];
        out.extend(v.q);
        out.extend(a.q);
        out
    }
}

/// The lower-case letter of the image of `n` as markup (`*b*`), primed
/// for the acceleration polygon (`*b*′`).
fn image(ctx: &LayerCtx, n: Named, prime: bool) -> String {
    let letter = ctx.letter(n).to_lowercase();
    if prime {
        format!("*{letter}*′")
    } else {
        format!("*{letter}*")
    }
}

/// The id part of an image (`b`, `b2` for b′).
fn id(ctx: &LayerCtx, n: Named, prime: bool) -> String {
    let letter = ctx.letter(n).to_lowercase();
    if prime { format!("{letter}2") } else { letter }
}

/// A vector of a polygon as an arrow (`{kind}-{p}{q}`), with its head,
/// where it is long enough on the page to carry one ([`MIN_ARROW`]).
/// Every vector drawn carries its head: at the default a plain b′x,
/// two dots joined by a line, left its sense to the notes.
fn vector(canvas: &mut Canvas, id: String, role: Role, from: Point, to: Point) {
    let length = canvas.page((to - from).norm());
    if length < MIN_ARROW {
        return;
    }
    canvas.push(id, role, Shape::Arrow { from, to });
}

/// Draws both polygons, each point lettered, and Q on the rod; a Q off
/// the rod's line on the rod drawn as the plate ABQ, and its images with
/// the triangles abq and a′b′q′ similar to it.
pub(crate) fn draw(ctx: &LayerCtx, canvas: &mut Canvas) {
    omega(ctx, canvas, false);
    let placed = place(ctx);
    let pose = ctx.main.pose();
    let coupler = ctx.scene.coupler().point(pose);
    if off_rod(ctx) {
        canvas.link("rod-plate", vec![pose.a(), coupler, pose.b()]);
    }
    // On the rod as drawn: beside the crank where the rod is drawn so.
    let dot = super::mechanism::on_rod_as_drawn(ctx, canvas, coupler);
    canvas.point(ctx.letter(Coupler), dot, Marker::Dot, pose.c());
    let hue = canvas.set_hue(Some(Hue::Velocity));
    let v = placed.velocity_points();
    velocity(ctx, canvas, &v);
    canvas.set_hue(Some(Hue::Acceleration));
    let a = placed.acceleration_points();
    acceleration(ctx, canvas, &a);
    canvas.set_hue(hue);
    let mut v_points = vec![v.o, v.a, v.b];
    v_points.extend(v.q);
    let mut a_points = vec![a.o, a.a, a.b, a.x];
    a_points.extend(a.q);
    let middle = |p: &[Point]| {
        let xs = p.iter().map(|p| p.x);
        0.5 * (xs.clone().fold(f64::INFINITY, f64::min) + xs.fold(f64::NEG_INFINITY, f64::max))
    };
    // Named below each where their names fit side by side, else both
    // in one line below the pair (a folded polygon near 90° is a needle
    // a few units wide, and the two stand closer than their names).
    if canvas.page((middle(&v_points) - middle(&a_points)).abs()) >= CAPTIONS_APART {
        caption(
            canvas,
            "caption-velocity-polygon",
            "velocity polygon",
            &v_points,
        );
        caption(
            canvas,
            "caption-acceleration-polygon",
            "acceleration polygon",
            &a_points,
        );
    } else {
        caption(
            canvas,
            "caption-polygons",
            "velocity polygon (left), acceleration polygon (right)",
            &[v_points, a_points].concat(),
        );
    }
}

/// The radius of the crank's ω about its centre, page units, at most.
const OMEGA_RADIUS: f64 = 60.0;

/// The share of the crank's radius on the page that ω's arc takes: inside
/// the crank circle, clear of the pin's path, and far enough from C that
/// its letter stands clear of C's (at 40 units in a crank's detail 200
/// units in radius, "ω C" read as one group).
const OMEGA_SHARE: f64 = 0.45;

/// The crank's sense of turning, ω's arrow about C ahead of the crank
/// (`polygons-omega`): the polygons are drawn from the crank's velocity
/// rω and acceleration ω²r, and a reader needs ω's sense to read cb's
/// direction. Drawn once, where its arc and letter fit whole
/// ([`omega_radius`]): on the main view, round the frame of a detail
/// the crank is left to ([`Canvas::is_bare`]) where the crank circle
/// holds it there, else in the detail (`detail`: `canvas` is a detail's)
/// where its frame holds it. At l = 1.03 r, 269.12° the ×2 detail of the
/// crowding pins showed only a fragment of the arc in its corner and the
/// main view none. Not drawn on a crank shorter on the page than a
/// letter (no detail could be given it).
pub(crate) fn omega(ctx: &LayerCtx, canvas: &mut Canvas, detail: bool) {
    if detail {
        // The main view at its scale draws it round this detail's frame.
        let main = (ctx.sizes.page_scale)
            .and_then(|scale| round_frame(ctx, canvas.frame(), &|w| w * scale));
        if main.is_some() {
            return;
        }
    }
    if let Some(radius) = omega_radius(ctx, canvas) {
        super::motion::omega(ctx, canvas, "polygons-omega", radius);
    }
}

/// The room (page units) ω's letter takes beyond its arc: a letter about
/// 12 units wide set 4 units off.
const OMEGA_LETTER_ROOM: f64 = 18.0;

/// The share of the crank's radius on the page within which ω's arc is
/// drawn round a detail's frame on the main view: inside the crank
/// circle, clear of the pin's path.
const OMEGA_ROUND_SHARE: f64 = 0.85;

/// The radius (page units) of ω's arc on `canvas`, or none where it is not
/// drawn there: in the crank's room ([`OMEGA_SHARE`] of the crank, at most
/// [`OMEGA_RADIUS`]) where C is the canvas's own, round the frame of the
/// detail C is left to where it is not ([`round_frame`]); either at least
/// [`OMEGA_LEAST`], with its letter ([`OMEGA_LETTER_ROOM`]) inside the
/// canvas's frame.
fn omega_radius(ctx: &LayerCtx, canvas: &Canvas) -> Option<f64> {
    let c = ctx.main.pose().c();
    let crank = canvas.page(ctx.main.pose().mechanism().crank());
    let frame = canvas.frame();
    let (lo, hi) = (frame.min(), frame.max());
    let room = canvas.page((c.x - lo.x).min(hi.x - c.x).min(c.y - lo.y).min(hi.y - c.y))
        - OMEGA_LETTER_ROOM;
    let radius = match canvas.bare_region() {
        Some(bare) if bare.contains(c) => round_frame(ctx, bare, &|w| canvas.page(w))?,
        _ => OMEGA_RADIUS.min(OMEGA_SHARE * crank).min(room),
    };
    (radius >= OMEGA_LEAST && radius <= room).then_some(radius)
}

/// The radius (page units, by `page` from world lengths) of ω's arc
/// drawn round the detail's `region` about C: [`OMEGA_CLEAR_OF_FRAME`]
/// beyond its farthest corner from C, where that is within
/// [`OMEGA_ROUND_SHARE`] of the crank; none where it is not.
fn round_frame(ctx: &LayerCtx, region: &Frame, page: &dyn Fn(f64) -> f64) -> Option<f64> {
    let pose = ctx.main.pose();
    let c = pose.c();
    let (lo, hi) = (region.min(), region.max());
    let far = [lo, hi, Point::new(lo.x, hi.y), Point::new(hi.x, lo.y)]
        .iter()
        .map(|q| page((q - c).norm()))
        .fold(0.0, f64::max);
    let radius = far + OMEGA_CLEAR_OF_FRAME;
    (radius <= OMEGA_ROUND_SHARE * page(pose.mechanism().crank())).then_some(radius)
}

/// How far (page units) ω's arc drawn round a detail's frame on the main
/// view stands beyond the frame's farthest corner from C.
const OMEGA_CLEAR_OF_FRAME: f64 = 8.0;

/// The least radius of ω's arc, page units: its head's length and the
/// pin's circle.
const OMEGA_LEAST: f64 = 14.0;

/// Whether the scene's coupler point stands off the rod's line.
fn off_rod(ctx: &LayerCtx) -> bool {
    ctx.scene.coupler().across() != 0.0
}

/// The sides aq and bq of the image triangle of an off-rod Q (ids
/// `{kind}-{a}{q}`, `{kind}-{b}{q}`), dashed.
fn image_triangle(canvas: &mut Canvas, kind: &str, ids: [&str; 3], [a, b, q]: [Point; 3]) {
    let [ia, ib, iq] = ids;
    canvas.segment(format!("{kind}-{ia}{iq}"), Role::Auxiliary, a, q);
    canvas.segment(format!("{kind}-{ib}{iq}"), Role::Auxiliary, b, q);
}

/// Room between a polygon and its caption below it, page units.
const CAPTION_DROP: f64 = 34.0;

/// The least distance between the middles of the two polygons, page
/// units: their captions' half widths and room between.
const CAPTIONS_APART: f64 = 150.0;

/// What the fit keeps below a polygon for its caption, page units.
pub(crate) const CAPTION_ROOM: f64 = CAPTION_DROP + 12.0;

/// The polygon's name set below its `points`, under their middle.
fn caption(canvas: &mut Canvas, id: &str, text: &str, points: &[Point]) {
    let lo = points
        .iter()
        .fold(Point::new(f64::INFINITY, f64::INFINITY), |m, p| m.inf(p));
    let hi = points
        .iter()
        .fold(Point::new(f64::NEG_INFINITY, f64::NEG_INFINITY), |m, p| {
            m.sup(p)
        });
    let at = Point::new(0.5 * (lo.x + hi.x), lo.y);
    canvas.push(
        id,
        Role::Label,
        Shape::Text {
            at,
            offset: Vector::new(0.0, CAPTION_DROP),
            text: RichText::parse(text),
            align: Align::Middle,
            size: TextSize::Small,
        },
    );
}

/// Page distance between two sides of a polygon that lie on one line,
/// drawn side by side: more than a head's width (6.4 units), so that
/// each arrow and its head are seen on their own.
const SIDE_APART: f64 = 7.0;

/// The offsets that set each of `sides` (the result first, then the
/// others in the order drawn) clear of those before it that it would
/// run over ([`side_by_side_ends`]), each as the offsets of its tail and
/// its head: near 90° at a long rod the acceleration polygon folds, xa′
/// running back over c′b′, and the two read as one line; the velocity
/// polygon's cb and ca are one arrow where a = b. A side set beside one
/// it leaves at a narrow angle keeps its head on its point. Sides too
/// short to be drawn count as points. A needle's sides are stacked on one
/// side of its line instead ([`stacked`]), told by the flag returned.
fn apart<const N: usize>(
    canvas: &Canvas,
    sides: [(Point, Point); N],
) -> ([(Vector, Vector); N], bool) {
    let drawn = sides.map(|(p, q)| {
        let seen = canvas.page((q - p).norm()) >= MIN_ARROW;
        (p, if seen { q } else { p })
    });
    let zero = (Vector::zeros(), Vector::zeros());
    if let Some(offsets) = stacked(canvas, &drawn) {
        let offsets = std::array::from_fn(|i| offsets.get(i).map_or(zero, |o| (*o, *o)));
        return (offsets, true);
    }
    let offsets = side_by_side_ends(&drawn, canvas.world(SIDE_APART));
    let offsets = std::array::from_fn(|i| offsets.get(i).copied().unwrap_or(zero));
    (offsets, false)
}

/// Page distance from the line of a polygon's longest side within which
/// every end of its sides stands where the polygon is a needle, folded
/// onto one line (at the dead centres): half [`SIDE_APART`].
const NEEDLE: f64 = 0.5 * SIDE_APART;

/// The offsets of the `sides` (drawn ends; the result first) of a
/// polygon folded onto one line ([`NEEDLE`]), or none where it is not
/// one: each side, in order, on the first of the line and the rows
/// [`SIDE_APART`] beside it, all on one side of it, where it shares no
/// run with a side already there (a side running on from the head of
/// another stays in its row). Set beside the line to either side, as
/// sides off a polygon's line are, the sides of a needle left its
/// letters no side of their dots clear of arrows: the engine at
/// l = 1.09 r, 0° drew c′b′ below the line and b′x above it, q′ was
/// lettered above b′x, naming it, and c′q′ was not drawn. A needle along
/// the page is stacked below its line, one up it to its right, and its
/// letters stand on the side clear of arrows.
fn stacked(canvas: &Canvas, sides: &[(Point, Point)]) -> Option<Vec<Vector>> {
    let (p, q) =
        *(sides.iter()).max_by(|a, b| (a.1 - a.0).norm().total_cmp(&(b.1 - b.0).norm()))?;
    let length = (q - p).norm();
    if length.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
        return None;
    }
    let u = (q - p) / length;
    let off = |x: Point| crate::geom::cross(&u, &(x - p)).abs();
    let needle = (sides.iter()).all(|s| canvas.page(off(s.0).max(off(s.1))) < NEEDLE);
    if !needle {
        return None;
    }
    // Below the line on the page (world y up), or to its right where it
    // runs up the page.
    let normal = Vector::new(-u.y, u.x);
    let down = if u.x.abs() >= u.y.abs() {
        normal.y < 0.0
    } else {
        normal.x > 0.0
    };
    let across = if down { normal } else { -normal };
    let step = canvas.world(SIDE_APART);
    let mut rows: Vec<Vec<(f64, f64)>> = Vec::new();
    let offsets = (sides.iter())
        .map(|(a, b)| {
            let (s, t) = ((a - p).dot(&u), (b - p).dot(&u));
            let run = (s.min(t), s.max(t));
            if t == s {
                return Vector::zeros();
            }
            let free = |row: &Vec<(f64, f64)>| {
                (row.iter()).all(|r| run.1.min(r.1) - run.0.max(r.0) < 0.5 * step)
            };
            let level = rows.iter().position(free).unwrap_or(rows.len());
            match rows.get_mut(level) {
                Some(row) => row.push(run),
                None => rows.push(vec![run]),
            }
            across * (level as f64 * step)
        })
        .collect();
    Some(offsets)
}

fn velocity(ctx: &LayerCtx, canvas: &mut Canvas, p: &VelocityPoints) {
    let (o, b, a) = (
        id(ctx, CrankCentre, false),
        id(ctx, CrankPin, false),
        id(ctx, Slider, false),
    );
    let q = p.q.unwrap_or(p.o);
    let ([oa, ob, ab, oq], _) = apart(canvas, [(p.o, p.a), (p.o, p.b), (p.a, p.b), (p.o, q)]);
    vector(
        canvas,
        format!("velocity-{o}{b}"),
        Role::Construction,
        p.o + ob.0,
        p.b + ob.1,
    );
    vector(
        canvas,
        format!("velocity-{a}{b}"),
        Role::Construction,
        p.a + ab.0,
        p.b + ab.1,
    );
    vector(
        canvas,
        format!("velocity-{o}{a}"),
        Role::Result,
        p.o + oa.0,
        p.a + oa.1,
    );
    if let Some(q) = p.q {
        vector(
            canvas,
            format!("velocity-{o}q"),
            Role::Auxiliary,
            p.o + oq.0,
            q + oq.1,
        );
        if off_rod(ctx) {
            image_triangle(canvas, "velocity", [&a, &b, "q"], [p.a, p.b, q]);
        }
    }
    let mut letters = vec![(CrankCentre, p.o), (CrankPin, p.b), (Slider, p.a)];
    letters.extend(p.q.map(|q| (Coupler, q)));
    let letters = letters
        .into_iter()
        .map(|(n, at)| (id(ctx, n, false), image(ctx, n, false), at))
        .collect::<Vec<_>>();
    letter(canvas, &letters, p.o);
}

/// Page distance under which two images of a polygon coincide for the
/// eye: their dots (2.1 units in radius) run into one, and one letter
/// names them all (b and a at θ = 90°, where the rod translates), as a
/// book letters coinciding images. Images farther apart, however near,
/// each keep their own letter at their own vertex: a joint letter would
/// name a vertex it does not stand by.
pub(crate) const COINCIDE: f64 = 6.0;

/// Letters a polygon's points (id, markup, place) from the pole `pole`,
/// those within [`COINCIDE`] of each other by one letter.
fn letter(canvas: &mut Canvas, points: &[(String, String, Point)], pole: Point) {
    let points: Vec<(&str, &str, Point)> = (points.iter())
        .map(|(id, markup, at)| (id.as_str(), markup.as_str(), *at))
        .collect();
    canvas.letter_crowded(&points, COINCIDE, pole, None);
}

fn acceleration(ctx: &LayerCtx, canvas: &mut Canvas, p: &AccelerationPoints) {
    let (o, b, a) = (
        id(ctx, CrankCentre, true),
        id(ctx, CrankPin, true),
        id(ctx, Slider, true),
    );
    let q = p.q.unwrap_or(p.o);
    let ([oa, ob, bx, xa, oq], needle) = apart(
        canvas,
        [(p.o, p.a), (p.o, p.b), (p.b, p.x), (p.x, p.a), (p.o, q)],
    );
    vector(
        canvas,
        format!("acceleration-{o}{b}"),
        Role::Construction,
        p.o + ob.0,
        p.b + ob.1,
    );
    vector(
        canvas,
        format!("acceleration-{b}x"),
        Role::Construction,
        p.b + bx.0,
        p.x + bx.1,
    );
    vector(
        canvas,
        format!("acceleration-x{a}"),
        Role::Construction,
        p.x + xa.0,
        p.a + xa.1,
    );
    vector(
        canvas,
        format!("acceleration-{o}{a}"),
        Role::Result,
        p.o + oa.0,
        p.a + oa.1,
    );
    // The image line a′b′, q′ on it, where it does not run along a side
    // drawn: near 90° at a long rod a′ stands by c′ and x by b′, and the
    // dashed b′a′ over c′b′ read as one doubled line; at a dead centre it
    // lies on the polygon's line.
    let drawn = [
        (p.o + oa.0, p.a + oa.1),
        (p.o + ob.0, p.b + ob.1),
        (p.x + xa.0, p.a + xa.1),
    ];
    if !drawn
        .iter()
        .any(|&side| runs_along(canvas, (p.a, p.b), side))
    {
        canvas.segment(format!("acceleration-{a}{b}"), Role::Auxiliary, p.a, p.b);
    }
    if let Some(q) = p.q {
        // Set beside the sides on its line (over c′a′ and c′b′ at the
        // dead centres, beside c′b′ near 90°), c′q′ stands beyond those
        // already set beside them, on their side of the line: the other
        // side is left to the points' letters. A needle's c′q′ is
        // stacked beside the others, clear of the letters ([`stacked`]).
        let oq = if needle {
            Some(oq)
        } else {
            outside(
                canvas,
                (p.o, q),
                oq,
                &[
                    (p.o, p.a, oa),
                    (p.o, p.b, ob),
                    (p.b, p.x, bx),
                    (p.x, p.a, xa),
                ],
            )
        };
        if let Some(oq) = oq {
            vector(
                canvas,
                format!("acceleration-{o}q2"),
                Role::Auxiliary,
                p.o + oq.0,
                q + oq.1,
            );
        }
        if off_rod(ctx) {
            image_triangle(canvas, "acceleration", [&a, &b, "q2"], [p.a, p.b, q]);
        }
    }
    let (normal, tangential) = (p.b - p.x, p.a - p.x);
    if canvas.page(normal.norm()) >= 2.0 * RIGHT_ANGLE
        && canvas.page(tangential.norm()) >= 2.0 * RIGHT_ANGLE
    {
        canvas.push(
            "angle-x",
            Role::Construction,
            Shape::RightAngle {
                vertex: p.x,
                u: normal,
                v: tangential,
            },
        );
    }
    let mut letters = vec![
        (
            id(ctx, CrankCentre, true),
            image(ctx, CrankCentre, true),
            p.o,
        ),
        (id(ctx, CrankPin, true), image(ctx, CrankPin, true), p.b),
        ("x".to_string(), "*x*".to_string(), p.x),
        (id(ctx, Slider, true), image(ctx, Slider, true), p.a),
    ];
    if let Some(q) = p.q {
        letters.push((id(ctx, Coupler, true), image(ctx, Coupler, true), q));
    }
    letter(canvas, &letters, p.o);
}

/// The offsets (tail, head) of `side`, set beside the sides on its line
/// where [`apart`] moved it (`placed`): moved whole to the side of its
/// line that those of `others` (from, to, offsets) set beside along its
/// run stand on, [`SIDE_APART`] beyond the farthest of them, and further
/// by as much where it would come within half that of a side drawn;
/// `placed` where it is not moved; none (it is left out) where none was
/// set beside along it or no place is clear. Set to either side as
/// [`apart`] found room, c′q′ over c′a′ at the dead centres stood across
/// the line from c′b′, between the points and their letters (l = 2.6 r,
/// e = 1.06 r, 0°: b′'s letter on it), and beside c′b′ near 90° it stood
/// across c′b′ from xa′, its tail in the letter of c′ (l = 2.23 r,
/// e = −0.933 r, 269.25°). Leaving c′a′ at a narrow angle with nothing
/// set beside it (l = 50 r, 170°), turned about its head it ran across
/// c′a′, and drawn where it stands it crowded q′'s letter against b′'s.
fn outside(
    canvas: &Canvas,
    (p, q): (Point, Point),
    placed: (Vector, Vector),
    others: &[(Point, Point, (Vector, Vector))],
) -> Option<(Vector, Vector)> {
    const SAMPLES: usize = 32;
    let length = (q - p).norm();
    let moved = placed.0.norm() > 0.0 || placed.1.norm() > 0.0;
    if !(moved && length > 0.0) {
        return Some(placed);
    }
    let u = (q - p) / length;
    let n = Vector::new(-u.y, u.x);
    let step = canvas.world(SIDE_APART);
    let drawn: Vec<(Point, Point, (Vector, Vector))> = (others.iter().copied())
        .filter(|(s, t, _)| canvas.page((t - s).norm()) >= MIN_ARROW)
        .collect();
    // How far off the line, signed across it, each side set beside
    // stands where it runs along it.
    let mut off: Vec<f64> = Vec::new();
    for (s, t, (o0, o1)) in &drawn {
        if o0.norm() == 0.0 && o1.norm() == 0.0 {
            continue;
        }
        for i in 0..=SAMPLES {
            let f = i as f64 / SAMPLES as f64;
            let x = s + (t - s) * f;
            let along = (x - p).dot(&u);
            let across = crate::geom::cross(&u, &(x - p)).abs();
            if (0.0..=length).contains(&along) && canvas.page(across) < NEEDLE {
                off.push((x + o0 + (o1 - o0) * f - p).dot(&n));
            }
        }
    }
    let first = off.first()?;
    let sign = first.signum();
    let beyond = (off.iter())
        .filter(|d| d.signum() == sign)
        .fold(0.0, |m: f64, d| m.max(d.abs()));
    let clear = |o: Vector| {
        (drawn.iter()).all(|(s, t, (o0, o1))| {
            crate::geom::segment_distance(p + o, q + o, s + o0, t + o1) >= 0.5 * step
        })
    };
    (1..=4)
        .map(|m| n * (sign * (beyond + m as f64 * step)))
        .find(|o| clear(*o))
        .map(|o| (o, o))
}

/// Whether the line `(a, b)` runs along the side `(s, t)` as drawn: the
/// side long enough to be drawn ([`MIN_ARROW`]) and both ends of the line
/// within [`SIDE_APART`] of it on the page, the two read as one.
fn runs_along(canvas: &Canvas, (a, b): (Point, Point), (s, t): (Point, Point)) -> bool {
    canvas.page((t - s).norm()) >= MIN_ARROW
        && canvas.page(crate::geom::farthest_from_segment(a, b, s, t)) < SIDE_APART
}

/// The notes that state the polygons' scales and read them: the velocity
/// and acceleration each length represents, the rod's angular velocity
/// ab/AB and angular acceleration xa′/AB.
pub(crate) fn notes(ctx: &LayerCtx) -> Vec<RichText> {
    let scene = ctx.scene;
    let placed = place(ctx);
    let (k, w) = (placed.k, scene.omega().abs());
    let u = scene.units().length();
    let r = scene.mechanism().crank();
    let rod = scene.mechanism().rod();
    let plain = |n: Named| ctx.letter(n).to_lowercase();
    let (o, b, a, q) = (
        plain(CrankCentre),
        plain(CrankPin),
        plain(Slider),
        plain(Coupler),
    );
    let primed = |n: Named| image(ctx, n, true);
    let (o2, b2, a2, q2) = (
        primed(CrankCentre),
        primed(CrankPin),
        primed(Slider),
        primed(Coupler),
    );
    // A primed image set before a letter or a colon is followed by a
    // narrow space: the italic prime leans over the next glyph ("c′:" read
    // with the prime over the colon, "c′b′" with it on the b).
    let spaced = |s: &String| format!("{s}\u{202f}");
    let (o2s, a2s, b2s) = (spaced(&o2), spaced(&a2), spaced(&b2));
    let (cap_a, cap_b) = (ctx.letter(Slider), ctx.letter(CrankPin));
    let v = &placed.velocity;
    let acc = &placed.acceleration;
    let len = |x: f64| sig(k * x.abs());
    let vq = v.q().map_or(0.0, |x| x.norm());
    let aq = acc.q().map_or(0.0, |x| x.norm());
    let ab = v.ab().norm();
    let normal = ab * ab / rod;
    let tangential = acc.tangential().norm();
    let mut notes = vec![
        RichText::parse(&format!(
            "Velocity polygon, pole *{o}*: 1 {u} represents {} {u}/s; *{o}{b}* = {} {u} is *{cap_b}*’s velocity *r*ω = {} {u}/s, perpendicular to the crank.",
            sig(w / k),
            short(k * r),
            sig(w * r)
        )),
        RichText::parse(&format!(
            "*{o}{a}* = {} {u}: the piston’s velocity {} {u}/s; *{a}{b}* = {} {u}: *{cap_b}* relative to *{cap_a}*, {} {u}/s, so the rod turns at *{a}{b}*/*{cap_a}{cap_b}* = {} rad/s; *{o}{q}* = {} {u}: {} {u}/s.",
            len(v.slider_velocity_ratio()),
            sig(w * v.slider_velocity_ratio().abs()),
            len(ab),
            sig(w * ab),
            sig(w * v.rod_angular_velocity_ratio().abs()),
            len(vq),
            sig(w * vq)
        )),
        RichText::parse(&format!(
            "Acceleration polygon, pole {o2s}: 1 {u} represents {} {u}/s²; {o2s}{b2} = {} {u} is ω²*r* = {} {u}/s² towards the crank centre.",
            sig(w * w / k),
            short(k * r),
            sig(w * w * r)
        )),
        RichText::parse(&format!(
            "{b2s}*x* = {} {u}: the rod’s normal component, *{a}{b}*²/*{cap_a}{cap_b}* = {} {u}/s²; *x{a}*′ = {} {u}: its tangential component, {} {u}/s², so the rod’s angular acceleration is *x{a}*′/*{cap_a}{cap_b}* = {} rad/s².",
            len(normal),
            sig(w * w * normal),
            len(tangential),
            sig(w * w * tangential),
            sig(w * w * acc.rod_angular_acceleration_ratio().abs())
        )),
        RichText::parse(&format!(
            "{o2s}{a2} = {} {u}: the piston’s acceleration {} {u}/s²{}; {o2s}{q2} = {} {u}: *{}*’s, {} {u}/s².",
            len(acc.slider_acceleration_ratio()),
            sig(w * w * acc.slider_acceleration_ratio().abs()),
            if too_short_to_draw(ctx, &placed) {
                ", too short for an arrow at this scale"
            } else {
                ""
            },
            len(aq),
            ctx.letter(Coupler),
            sig(w * w * aq)
        )),
    ];
    let short_sides = too_short_sides(
        ctx,
        &placed,
        [
            format!("*{a}{b}*"),
            format!("*{o}{a}*"),
            format!("*{o}{q}*"),
            format!("{b2s}*x*"),
            format!("*x{a}*′"),
            format!("{o2s}{q2}"),
        ],
    );
    notes.extend(short_sides);
    let point = scene.coupler();
    if off_rod(ctx) {
        notes.push(RichText::parse(&format!(
            "*{q_cap}* is a point of the rod’s plane, {} of *{cap_a}{cap_b}* from *{cap_a}* along it and {} of *{cap_a}{cap_b}* off it: the triangles *{a}{b}{q}* and {a2s}{b2s}{q2} are similar to *{cap_a}{cap_b}{q_cap}*.",
            short(point.t()),
            short(point.across().abs()),
            q_cap = ctx.letter(Coupler),
        )));
    }
    notes
}

/// The note naming the sides of the polygons (other than c′a′, which
/// its own note names) that are not nil but drawn shorter than
/// [`MIN_ARROW`], and so not drawn, if any: ab, ca, cq, b′x, xa′ and c′q′
/// as `names` give them. At l = 30.9 r, 0° b′x, 5 units long, was drawn
/// as nothing and said nowhere: a reader looked for the rod's normal
/// component among the dots. Not known before the page scale is.
fn too_short_sides(ctx: &LayerCtx, placed: &Placed, names: [String; 6]) -> Option<RichText> {
    let scale = ctx.sizes.page_scale?;
    let v = placed.velocity_points();
    let p = placed.acceleration_points();
    let sides = [
        (v.a, v.b),
        (v.o, v.a),
        (v.o, v.q.unwrap_or(v.o)),
        (p.b, p.x),
        (p.x, p.a),
        (p.o, p.q.unwrap_or(p.o)),
    ];
    let short: Vec<&str> = (sides.iter().zip(&names))
        .filter(|((s, t), _)| {
            let length = (t - s).norm();
            length > 0.0 && length * scale < MIN_ARROW
        })
        .map(|(_, name)| name.as_str())
        .collect();
    let (last, rest) = short.split_last()?;
    let list = match rest {
        [] => last.to_string(),
        _ => format!("{} and {last}", rest.join(", ")),
    };
    let (verb, each) = if rest.is_empty() {
        ("is", "it is left to the dots at its ends")
    } else {
        ("are", "each is left to the dots at its ends")
    };
    Some(RichText::parse(&format!(
        "{list} {verb} shorter than an arrow’s head at this scale, not drawn: {each}."
    )))
}

/// Whether the piston's acceleration c′a′, not nil, is drawn shorter
/// than [`MIN_ARROW`] and so not drawn (near 90° at a long rod, 0.26
/// units at l = 55.4 r, 90.47°): the notes say so, else only the joint
/// letter "c′, a′" told of it. Not known before the page scale is.
fn too_short_to_draw(ctx: &LayerCtx, placed: &Placed) -> bool {
    let p = placed.acceleration_points();
    let length = (p.a - p.o).norm();
    ctx.sizes
        .page_scale
        .is_some_and(|scale| length > 0.0 && length * scale < MIN_ARROW)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_magnification_is_a_round_step_of_at_least_one() {
        // (l + 2r)/4 per crank: 1 → 1 for n = 2, 2 → 2 for n = 6,
        // 15.5 → 15 for n = 60, 0.76 → 1 for n = 1.05.
        assert_eq!(magnification(0.5, 1.0), 1.0);
        assert_eq!(magnification(0.5, 3.0), 2.0);
        assert_eq!(magnification(1.0, 60.0), 15.0);
        assert_eq!(magnification(1.0, 1.05), 1.0);
        assert_eq!(magnification(1.0, 1e6), 2.5e5);
    }
}
