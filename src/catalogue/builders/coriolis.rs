//! The Coriolis figures: inversion 2 (the crank a fixed: the rotating
//! block, Whitworth's quick return) and inversion 3 (the rod b fixed: the
//! oscillating cylinder, the crank and slotted lever) at one pose, drawn
//! as a course in the kinematics of machines draws them: the mechanism in
//! the fixed link's frame, its velocity polygon and its acceleration
//! polygon, which closes with the Coriolis component 2 ω_d v, each to the
//! scale of its bar, and the component's direction rule (v turned a
//! quarter turn in the sense of ω_d) drawn at the pose's own directions
//! ([`crate::chain::CoriolisPolygon`], docs/polygons.md).
//!
//! Lettering: the pins keep the engine's letters (C the crank centre, B
//! the crank pin, A the block's pin); each image is its point's letter in
//! lower case (c the image of C), the acceleration images primed; a_d is
//! the image of the point of d under the block's pin, o the pole (the
//! image of every fixed point), n the end of d's normal component and k
//! the end of the Coriolis component.

use super::{Ctx, Sheet, short, sig};
use crate::chain::{CoriolisPolygon, Inversion, InversionPose, InvertedChain};
use crate::diagram::Plot;
use crate::error::{Error, Result};
use crate::figure::{Figure, Hue, PageRect, RIGHT_ANGLE, RichText, Role, Shape, TextSize};
use crate::geom::{Frame, Point, Vector, perp};
use crate::scene::{COINCIDE, Canvas, Marker};
use serde_json::{Value, json};

/// Page margin, as the other builders'.
const MARGIN: f64 = 16.0;

/// The gap between panels, page units.
const GAP: f64 = 12.0;

/// The mechanism panel's least and most height, page units.
const MECHANISM_HEIGHT: (f64, f64) = (170.0, 300.0);

/// The polygons' panels' height, page units.
const POLYGON_HEIGHT: f64 = 290.0;

/// The shares of the page's width of the velocity polygon, the
/// acceleration polygon and the direction rule.
const SHARES: [f64; 3] = [0.36, 0.42, 0.22];

/// Room kept about a polygon for its letters and its bar, in shares of
/// its largest extent.
const PAD: f64 = 0.16;

/// Shortest vector drawn as an arrow, page units: shorter, its head would
/// hide it (a zero vector, at the dead centres, is not drawn).
const MIN_ARROW: f64 = 12.0;

/// The page length under which a polygon's subject (the sliding velocity,
/// the Coriolis component) in its panel gets an enlarged detail: at a
/// long rod the driven point's velocity and acceleration make the polygon
/// a needle and the subject a few units at its tip.
const SUBJECT_LEAST: f64 = 40.0;

/// The most the subject is drawn in its detail, page units.
const SUBJECT_MOST: f64 = 200.0;

/// Room kept in a detail between its frame and the points it enlarges,
/// page units (their letters).
const DETAIL_PAD: f64 = 40.0;

/// The detail panels' height, page units.
const DETAIL_HEIGHT: f64 = 240.0;

/// Page distance within which a point of a polygon crowds the subject of
/// its detail (or another point so crowding): the detail takes it in.
const CROWD: f64 = 24.0;

/// The least side of the box marking a detail's region on the polygon,
/// page units.
const BOX_LEAST: f64 = 16.0;

/// The steps a scale bar's length is chosen from (times a power of ten).
const STEPS: [f64; 4] = [1.0, 2.0, 2.5, 5.0];

/// The steps the crank detail's magnification is chosen from (times a
/// power of ten): finer, so that the crank keeps most of the room the
/// detail gives it.
const FINE_STEPS: [f64; 9] = [1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0];

/// The share of a polygon's size below which a value read off it is its
/// rounding and is written 0.
const ROUNDING: f64 = 1e-10;

/// The polygons of a pose, as drawn: each point from the pole, and how
/// each is lettered.
struct Polygons {
    inversion: Inversion,
    p: CoriolisPolygon,
    /// The length CA, from the crank centre to the block's pin.
    ca: f64,
}

/// A point of a polygon: its id (ASCII), its letter as markup, where.
type Lettered = (&'static str, &'static str, Vector);

/// A vector of a polygon: its id, its role, from, to.
type Arrow = (&'static str, Role, Vector, Vector);

/// The side of a polygon the figure is about: from, to.
type Subject = (Vector, Vector);

/// A polygon as its panels draw it.
struct Drawn<'a> {
    name: &'a str,
    caption: &'a str,
    points: Vec<Lettered>,
    arrows: Vec<Arrow>,
    hue: Hue,
    per: &'a str,
    subject: Option<Subject>,
}

/// The region of a polygon its detail enlarges (world, from the pole)
/// and the magnification over the polygon's panel.
#[derive(Debug, Clone, Copy)]
struct Window {
    frame: Frame,
    magnification: f64,
}

impl Polygons {
    /// The velocity polygon's points: o, the driven point's image, a_d.
    fn velocity_points(&self) -> Vec<Lettered> {
        let p = &self.p;
        let driven = match self.inversion {
            Inversion::Rod => ("c", "*c*"),
            _ => ("a", "*a*"),
        };
        vec![
            ("o", "*o*", Vector::zeros()),
            (driven.0, driven.1, p.driven()),
            ("ad", "*a*_{d}", p.a_d()),
        ]
    }

    /// The velocity polygon's vectors: the driven point's velocity, the
    /// meet of the line ⟂ CA and the slot's line, the sliding velocity
    /// heavier.
    fn velocity_arrows(&self) -> Vec<Arrow> {
        let p = &self.p;
        let o = Vector::zeros();
        match self.inversion {
            Inversion::Rod => vec![
                ("velocity-oc", Role::Construction, o, p.driven()),
                ("velocity-cad", Role::Construction, p.driven(), p.a_d()),
                ("velocity-oad", Role::Result, o, p.a_d()),
            ],
            _ => vec![
                ("velocity-oa", Role::Construction, o, p.driven()),
                ("velocity-oad", Role::Construction, o, p.a_d()),
                ("velocity-ada", Role::Result, p.a_d(), p.driven()),
            ],
        }
    }

    /// The end k of the Coriolis component: from o′ in inversion 3, back
    /// from a′ in inversion 2.
    fn k(&self) -> Vector {
        let p = &self.p;
        match self.inversion {
            Inversion::Rod => p.coriolis(),
            _ => p.driven_acceleration() - p.coriolis(),
        }
    }

    /// The acceleration polygon's points: o′, the driven point's image,
    /// n, k, a′_d.
    fn acceleration_points(&self) -> Vec<Lettered> {
        let p = &self.p;
        let driven = match self.inversion {
            Inversion::Rod => ("c2", "*c*′"),
            _ => ("a2", "*a*′"),
        };
        vec![
            ("o2", "*o*′", Vector::zeros()),
            (driven.0, driven.1, p.driven_acceleration()),
            ("n", "*n*", p.n()),
            ("k", "*k*", self.k()),
            ("ad2", "*a*′_{d}", p.a_d_acceleration()),
        ]
    }

    /// The acceleration polygon's vectors: the driven point's
    /// centripetal acceleration, d's normal and tangential components,
    /// the Coriolis component and the sliding acceleration, and the
    /// acceleration of d's point at A heavier.
    fn acceleration_arrows(&self) -> Vec<Arrow> {
        let p = &self.p;
        let o = Vector::zeros();
        let (n, k, ad) = (p.n(), self.k(), p.a_d_acceleration());
        match self.inversion {
            Inversion::Rod => vec![
                (
                    "acceleration-oc",
                    Role::Construction,
                    o,
                    p.driven_acceleration(),
                ),
                (
                    "acceleration-cn",
                    Role::Construction,
                    p.driven_acceleration(),
                    n,
                ),
                ("acceleration-nad", Role::Construction, n, ad),
                ("acceleration-coriolis", Role::Construction, o, k),
                ("acceleration-kad", Role::Construction, k, ad),
                ("acceleration-oad", Role::Result, o, ad),
            ],
            _ => vec![
                (
                    "acceleration-oa",
                    Role::Construction,
                    o,
                    p.driven_acceleration(),
                ),
                ("acceleration-on", Role::Construction, o, n),
                ("acceleration-nad", Role::Construction, n, ad),
                ("acceleration-adk", Role::Construction, ad, k),
                (
                    "acceleration-coriolis",
                    Role::Construction,
                    k,
                    p.driven_acceleration(),
                ),
                ("acceleration-oad", Role::Result, o, ad),
            ],
        }
    }

    /// The normal component's foot: c′ in inversion 3 (c′n from the
    /// crank pin's image), o′ in inversion 2.
    fn normal_from(&self) -> Vector {
        match self.inversion {
            Inversion::Rod => self.p.driven_acceleration(),
            _ => Vector::zeros(),
        }
    }

    /// The largest vector of the velocity polygon (`false`) or of the
    /// acceleration polygon (`true`): the scale below which a value read
    /// off it is the construction's rounding.
    fn size(&self, acceleration: bool) -> f64 {
        let points = if acceleration {
            self.acceleration_points()
        } else {
            self.velocity_points()
        };
        points.iter().map(|p| p.2.norm()).fold(0.0, f64::max)
    }

    /// `x`, a value read off the velocity (`acceleration` false) or the
    /// acceleration polygon times `length`, or 0 where it is below
    /// [`ROUNDING`] of the polygon's size (ω_d at the lever's extremes
    /// comes out 3e-15 rad/s, not 0).
    fn clean(&self, x: f64, length: f64, acceleration: bool) -> f64 {
        if (x * length).abs() <= ROUNDING * self.size(acceleration) {
            0.0
        } else {
            x
        }
    }

    /// The velocity polygon's subject, the sliding velocity: o a_d in
    /// inversion 3, a_d a in inversion 2; `None` where it is nil.
    fn velocity_subject(&self) -> Option<Subject> {
        let p = &self.p;
        let side = match self.inversion {
            Inversion::Rod => (Vector::zeros(), p.a_d()),
            _ => (p.a_d(), p.driven()),
        };
        (self.clean((side.1 - side.0).norm(), 1.0, false) > 0.0).then_some(side)
    }

    /// The acceleration polygon's subject, the Coriolis component: o′k in
    /// inversion 3, ka′ in inversion 2; `None` where it is nil.
    fn acceleration_subject(&self) -> Option<Subject> {
        let p = &self.p;
        let side = match self.inversion {
            Inversion::Rod => (Vector::zeros(), self.k()),
            _ => (self.k(), p.driven_acceleration()),
        };
        (self.clean(p.coriolis().norm(), 1.0, true) > 0.0).then_some(side)
    }

    /// The sliding velocity v whose turn gives the Coriolis component: d's
    /// point relative to the block in inversion 3, the block relative to
    /// d in inversion 2, as a vector along the slot.
    fn v(&self) -> Vector {
        match self.inversion {
            Inversion::Rod => -self.p.slot() * self.p.sliding_velocity(),
            _ => self.p.slot() * self.p.sliding_velocity(),
        }
    }
}

/// The largest of the round `steps` times a power of ten not above `x`
/// (positive and finite).
fn round_below(x: f64, steps: &[f64]) -> f64 {
    let decade = 10f64.powf(x.log10().floor());
    steps
        .iter()
        .map(|s| s * decade)
        .filter(|s| *s <= x * (1.0 + 1e-12))
        .fold(decade, f64::max)
}

/// The world frame of `points` (from the pole), grown by [`PAD`] of its
/// largest extent each way and below by room for the bar; a frame
/// thinner than half its width is made that tall, so that a polygon
/// folded onto a line keeps room for its letters.
fn polygon_frame(points: &[Lettered]) -> (Frame, f64) {
    let lo = points.iter().fold(Vector::zeros(), |m, p| m.inf(&p.2));
    let hi = points.iter().fold(Vector::zeros(), |m, p| m.sup(&p.2));
    let size = hi - lo;
    let extent = size.x.max(size.y);
    let pad = PAD * extent;
    let grow = (0.5 * extent - size.y).max(0.0) * 0.5;
    let min = Point::from(lo) - Vector::new(pad, pad + grow + 0.18 * extent);
    let max = Point::from(hi) + Vector::new(pad, pad + grow);
    (Frame::new(min, max), extent)
}

/// The panels' rectangles across the page from `top`, by [`SHARES`].
fn row(width: f64, top: f64, height: f64) -> [PageRect; 3] {
    let room = width - 2.0 * MARGIN - 2.0 * GAP;
    let mut x = MARGIN;
    SHARES.map(|share| {
        let rect = PageRect::new(x, top, room * share, height);
        x += room * share + GAP;
        rect
    })
}

pub(in crate::catalogue) fn build(ctx: &Ctx, inversion: Inversion) -> Result<Figure> {
    let m = ctx.mechanism;
    let chain = InvertedChain::new(m, inversion);
    let pose = chain.pose(ctx.angle);
    let p = CoriolisPolygon::construct(&pose, ctx.omega)
        .ok_or_else(|| Error::Unsupported("no block slides on a turning link".into()))?;
    let engine = pose.engine_pose();
    let ca = (engine.a() - engine.c()).norm();
    let polygons = Polygons { inversion, p, ca };
    let page = ctx.page();
    let (mechanism, crank_detail) = mechanism_plot(ctx, &pose)?;
    let top = mechanism.rect().y + mechanism.rect().height + GAP;
    let [v_rect, a_rect, rule_rect] = row(page.width(), top, POLYGON_HEIGHT);
    let [v_below, a_below, _] = row(page.width(), top + POLYGON_HEIGHT + GAP, DETAIL_HEIGHT);
    let area = |r: PageRect| (r.width, r.height - crate::diagram::CAPTION);
    let velocity_drawn = Drawn {
        name: "velocity-polygon",
        caption: "velocity polygon",
        points: polygons.velocity_points(),
        arrows: polygons.velocity_arrows(),
        hue: Hue::Velocity,
        per: "/s",
        subject: polygons.velocity_subject(),
    };
    let acceleration_drawn = Drawn {
        name: "acceleration-polygon",
        caption: "acceleration polygon",
        points: polygons.acceleration_points(),
        arrows: polygons.acceleration_arrows(),
        hue: Hue::Acceleration,
        per: "/s²",
        subject: polygons.acceleration_subject(),
    };
    let nothing = |_: &mut Canvas| {};
    let angles = |s: &mut Canvas| right_angles(s, &polygons);
    let (velocity, v_bar, v_points, v_window) =
        polygon_plot(ctx, v_rect, &velocity_drawn, area(v_below), &nothing)?;
    let (acceleration, a_bar, a_points, a_window) =
        polygon_plot(ctx, a_rect, &acceleration_drawn, area(a_below), &angles)?;
    let mut details = Vec::new();
    if let Some(w) = v_window {
        details.push(detail_plot(ctx, v_below, &velocity_drawn, &w, &nothing)?);
    }
    if let Some(w) = a_window {
        details.push(detail_plot(ctx, a_below, &acceleration_drawn, &w, &angles)?);
    }
    let rule = rule_plot(ctx, rule_rect, &polygons)?;
    let mut sheet = Sheet::new(ctx);
    sheet.mechanism(ctx, true, true);
    sheet.meta("inversion", json!(inversion.number()));
    sheet.meta("coriolis", coriolis_json(&polygons, v_bar, a_bar));
    sheet.meta("velocity_polygon", v_points);
    sheet.meta("acceleration_polygon", a_points);
    sheet.plot(mechanism);
    if let Some(d) = crank_detail {
        sheet.detail(d);
    }
    sheet.plot(velocity);
    sheet.plot(acceleration);
    sheet.plot(rule);
    let mut bottom = top + POLYGON_HEIGHT + 6.0;
    if !details.is_empty() {
        bottom += GAP + DETAIL_HEIGHT;
    }
    for d in details {
        sheet.plot(d);
    }
    sheet.height(bottom + NOTES_LINES * super::NOTE_LINE + MARGIN);
    sheet.notes(
        Point::new(20.0, bottom),
        &notes(ctx, &chain, &polygons, (v_bar, a_bar)),
    );
    Ok(sheet.finish())
}

/// The notes' lines before wrapping.
const NOTES_LINES: f64 = 5.0;

/// The page length under which the crank CB in the mechanism panel gets
/// an enlarged detail: at a long rod (inversion 3 on a rod of fifty
/// cranks) its pins touch, the crank hides in B's bearing and the
/// driver's ω finds no room.
const CRANK_LEAST: f64 = 40.0;

/// The crank detail's reach about B, in cranks: the crank's circle and
/// room for its letters (a panel 170 units tall draws the crank at least
/// 170 / 3 / (4/3), about 42 units, the finest steps being 4/3 apart).
const CRANK_REACH: f64 = 1.5;

/// The mechanism panel: the chain at the pose in the fixed link's frame,
/// its pins lettered C, B, A and the driver's sense of turning; where the
/// crank is drawn shorter than [`CRANK_LEAST`], a detail of the region
/// about it beside the panel (boxed there), which carries ω.
fn mechanism_plot(ctx: &Ctx, pose: &InversionPose) -> Result<(Plot, Option<Plot>)> {
    let m = ctx.mechanism;
    let frame = super::inversions::links_frame(&m, pose);
    let size = frame.max() - frame.min();
    let pad = 0.06 * size.x.max(size.y);
    let world = Frame::new(
        frame.min() - Vector::new(pad, pad),
        frame.max() + Vector::new(pad, pad),
    );
    let width = ctx.page().width() - 2.0 * MARGIN;
    let seen = world.max() - world.min();
    let tall = (width * seen.y / seen.x).clamp(MECHANISM_HEIGHT.0, MECHANISM_HEIGHT.1);
    let rect = PageRect::new(MARGIN, MARGIN, width, tall + crate::diagram::CAPTION);
    let whole = Plot::world("mechanism", rect, &world, false, ctx.tolerance, ctx.font)?;
    let scale = whole.map().scale();
    if m.crank() * scale >= CRANK_LEAST {
        return Ok((links_plot(ctx, pose, whole, None)?, None));
    }
    let side = tall;
    let main = PageRect::new(MARGIN, MARGIN, width - side - GAP, rect.height);
    let plot = Plot::world("mechanism", main, &world, false, ctx.tolerance, ctx.font)?;
    let scale = plot.map().scale();
    let b = pose.place(pose.engine_pose().b());
    let wanted = side / (2.0 * CRANK_REACH * m.crank()) / scale;
    let magnification = round_below(wanted, &FINE_STEPS).max(1.0);
    let half = Vector::new(side, tall) * (0.5 / (magnification * scale));
    let region = Frame::new(b - half, b + half);
    let detail_rect = PageRect::new(MARGIN + width - side, MARGIN, side, rect.height);
    let caption = format!("the boxed region enlarged ×{}", short(magnification));
    let detail = Plot::world(
        "mechanism-detail",
        detail_rect,
        &region,
        false,
        ctx.tolerance,
        ctx.font,
    )?
    .with_caption(&caption);
    let detail = links_plot(ctx, pose, detail, Some(region))?;
    Ok((links_plot(ctx, pose, plot, Some(region))?, Some(detail)))
}

/// The chain drawn on `plot`: its links, pins C, B, A lettered where on
/// the panel, the driver's ω; on the whole mechanism (named `mechanism`)
/// the caption and, where a detail enlarges `region`, its box.
fn links_plot(ctx: &Ctx, pose: &InversionPose, plot: Plot, region: Option<Frame>) -> Result<Plot> {
    let m = ctx.mechanism;
    let whole = plot.panel_id() == "panel-mechanism";
    let inversion = pose.inversion();
    let mut plot = if whole {
        plot.with_caption(&format!(
            "Inversion {}, {}: the relative-velocity method with the Coriolis component",
            inversion.number(),
            match inversion {
                Inversion::Rod => "the crank and slotted lever",
                _ => "Whitworth’s quick return",
            }
        ))
    } else {
        plot
    };
    let map = *plot.map();
    let mut canvas = Canvas::new(map, map.world_frame(&plot.area()));
    if !whole {
        canvas = canvas.detail("detail-");
    }
    let mut s = super::inversions::draw_links(m, pose, canvas);
    let engine = pose.engine_pose();
    let (c, b, a) = (
        pose.place(engine.c()),
        pose.place(engine.b()),
        pose.place(engine.a()),
    );
    for (key, at) in [("C", c), ("B", b), ("A", a)] {
        if whole || s.contains(at) {
            s.lettered(key, at, &format!("*{key}*"), Marker::Pin, c);
        }
    }
    driver_turn(&mut s, pose, ctx.omega);
    if let (true, Some(region)) = (whole, region) {
        mark_window(&mut s, "mechanism", &region);
    }
    for item in s.finish().0 {
        plot.push(item);
    }
    Ok(plot)
}

/// The driver's sense of turning: an arrowed arc about its fixed pin
/// (the crank about B in inversion 3, the rod about B in inversion 2),
/// lettered ω.
fn driver_turn(s: &mut Canvas, pose: &InversionPose, omega: f64) {
    let engine = pose.engine_pose();
    let b = pose.place(engine.b());
    let tip = match pose.inversion() {
        Inversion::Rod => pose.place(engine.c()),
        _ => pose.place(engine.a()),
    };
    let arm = tip - b;
    let radius = s.world(26.0).min(0.45 * arm.norm());
    if s.page(radius) < 10.0 {
        return;
    }
    let start = arm.y.atan2(arm.x) + 0.35;
    let sweep = 1.1 * omega.signum();
    s.push(
        "arc-omega",
        Role::Force,
        Shape::Arc {
            centre: b,
            radius,
            start,
            sweep,
            arrow: true,
        },
    );
    let mid = start + 0.5 * sweep;
    let at = b + Vector::new(mid.cos(), mid.sin()) * radius;
    s.label("label-omega", at, RichText::parse("ω"), TextSize::Letter);
}

/// A polygon's panel: its vectors as arrows (those long enough to carry
/// a head), its points lettered (those that crowd by one letter), a
/// scale bar of a round length below, and what `more` adds; where its
/// subject is drawn shorter than [`SUBJECT_LEAST`], the region about it
/// is boxed and left to a detail of `detail` page units (its points are
/// lettered there). Returns the plot, the bar's length, the points'
/// places (from the pole, in velocity or acceleration units) and the
/// detail's window.
fn polygon_plot(
    ctx: &Ctx,
    rect: PageRect,
    drawn: &Drawn,
    detail: (f64, f64),
    more: &impl Fn(&mut Canvas),
) -> Result<(Plot, f64, Value, Option<Window>)> {
    let (world, extent) = polygon_frame(&drawn.points);
    let mut plot = Plot::world(drawn.name, rect, &world, false, ctx.tolerance, ctx.font)?
        .with_caption(drawn.caption);
    let map = *plot.map();
    let window = drawn
        .subject
        .and_then(|side| window(&drawn.points, side, map.scale(), detail));
    let mut s = Canvas::new(map, map.world_frame(&plot.area()));
    if let Some(w) = window {
        s = s.quiet(w.frame);
    }
    let old = s.set_hue(Some(drawn.hue));
    for (id, role, from, to) in &drawn.arrows {
        if s.page((to - from).norm()) >= MIN_ARROW {
            s.push(
                *id,
                *role,
                Shape::Arrow {
                    from: Point::from(*from),
                    to: Point::from(*to),
                },
            );
        }
    }
    more(&mut s);
    s.set_hue(old);
    if let Some(w) = window {
        mark_window(&mut s, drawn.name, &w.frame);
    }
    letter(&mut s, &drawn.points, window.map(|w| w.frame));
    let bar = round_below(0.45 * extent, &STEPS);
    let y = world.min().y + 0.08 * extent;
    let x = world.min().x + PAD * extent * 0.5;
    let unit = format!("{}{}", ctx.unit(), drawn.per);
    s.push(
        format!("{}-bar", drawn.name),
        Role::Dimension,
        Shape::Dimension {
            from: Point::new(x, y),
            to: Point::new(x + bar, y),
            side: Vector::new(0.0, -1.0),
            offset: 0.0,
            text: RichText::parse(&format!("{} {unit}", short(bar))),
        },
    );
    let (items, points) = s.finish();
    for item in items {
        plot.push(item);
    }
    Ok((plot, bar, Value::Object(points), window))
}

/// The region a polygon's detail enlarges, where its subject `side` is
/// drawn shorter than [`SUBJECT_LEAST`] at `scale` (page units per unit):
/// the points crowding about the subject (within [`CROWD`] of it or of
/// each other) whole where they fit the detail's `area` with the subject
/// at most [`SUBJECT_MOST`], else the subject at twice [`SUBJECT_LEAST`]
/// about its middle (the long sides run off the detail's edge); the
/// magnification a round step. `None` where the subject reads in the
/// polygon itself.
fn window(points: &[Lettered], side: Subject, scale: f64, area: (f64, f64)) -> Option<Window> {
    let length = (side.1 - side.0).norm();
    if length <= 0.0 || !length.is_finite() || length * scale >= SUBJECT_LEAST {
        return None;
    }
    let mut crowd = vec![side.0, side.1];
    loop {
        let near = points
            .iter()
            .map(|p| p.2)
            .find(|p| !crowd.contains(p) && crowd.iter().any(|c| (c - p).norm() * scale < CROWD));
        match near {
            Some(p) => crowd.push(p),
            None => break,
        }
    }
    let lo = crowd.iter().fold(side.0, |m, p| m.inf(p));
    let hi = crowd.iter().fold(side.0, |m, p| m.sup(p));
    let size = hi - lo;
    let room = (area.0 - 2.0 * DETAIL_PAD, area.1 - 2.0 * DETAIL_PAD);
    let fit = (room.0 / size.x).min(room.1 / size.y);
    let wanted = fit
        .min(SUBJECT_MOST / length)
        .max(2.0 * SUBJECT_LEAST / length);
    let magnification = round_below(wanted / scale, &STEPS).max(1.0);
    let detail = magnification * scale;
    let centre = if detail <= fit * (1.0 + 1e-9) {
        (lo + hi) * 0.5
    } else {
        (side.0 + side.1) * 0.5
    };
    let half = Vector::new(area.0, area.1) * (0.5 / detail);
    let frame = Frame::new(Point::from(centre - half), Point::from(centre + half));
    Some(Window {
        frame,
        magnification,
    })
}

/// The box on a polygon marking the region its detail enlarges (at
/// least [`BOX_LEAST`] a side).
fn mark_window(s: &mut Canvas, name: &str, frame: &Frame) {
    let least = s.world(BOX_LEAST);
    let size = frame.max() - frame.min();
    let grow = Vector::new((least - size.x).max(0.0), (least - size.y).max(0.0)) * 0.5;
    let seen = *s.frame();
    let lo = (frame.min() - grow).sup(&seen.min());
    let hi = (frame.max() + grow).inf(&seen.max());
    s.push(
        format!("{name}-detail-box"),
        Role::Auxiliary,
        Shape::Polyline {
            points: vec![lo, Point::new(hi.x, lo.y), hi, Point::new(lo.x, hi.y)],
            closed: true,
        },
    );
}

/// Letters the polygon's `points`, those that coincide on the page
/// (within [`COINCIDE`]) by one letter, those in the region left to a
/// detail (`quiet`) not here.
fn letter(s: &mut Canvas, points: &[Lettered], quiet: Option<Frame>) {
    let points: Vec<(&str, &str, Point)> = (points.iter())
        .map(|(id, markup, at)| (*id, *markup, Point::from(*at)))
        .collect();
    s.letter_crowded(&points, COINCIDE, Point::origin(), quiet);
}

/// The detail of a polygon: the region of `window` enlarged in `rect`,
/// its sides clipped at the edge (an arrowhead where the side ends
/// inside), its points there lettered, captioned with the
/// magnification.
fn detail_plot(
    ctx: &Ctx,
    rect: PageRect,
    drawn: &Drawn,
    window: &Window,
    more: &impl Fn(&mut Canvas),
) -> Result<Plot> {
    let name = format!("{}-detail", drawn.name);
    let caption = format!(
        "{}: the boxed region enlarged ×{}",
        drawn.caption,
        short(window.magnification)
    );
    let mut plot = Plot::world(&name, rect, &window.frame, false, ctx.tolerance, ctx.font)?
        .with_caption(&caption);
    let map = *plot.map();
    let mut s = Canvas::new(map, map.world_frame(&plot.area())).detail("detail-");
    let old = s.set_hue(Some(drawn.hue));
    for (id, role, from, to) in &drawn.arrows {
        let (from, to) = (Point::from(*from), Point::from(*to));
        // The piece inside the frame; a side that misses it has none (the
        // clip of its line lies beyond its ends).
        let inside = s.frame().clip_segment(from, to).filter(|(p, q)| {
            let middle = Point::from((p.coords + q.coords) * 0.5);
            s.contains(middle) && s.page((q - p).norm()) >= 0.5
        });
        let Some((tail, head)) = inside else {
            continue;
        };
        let role = *role;
        if s.contains(to) && s.page((to - tail).norm()) >= MIN_ARROW {
            s.push(*id, role, Shape::Arrow { from: tail, to });
        } else {
            s.segment(*id, role, tail, head);
        }
    }
    more(&mut s);
    s.set_hue(old);
    letter(&mut s, &drawn.points, None);
    for item in s.finish().0 {
        plot.push(item);
    }
    Ok(plot)
}

/// The right angles of the acceleration polygon: d's tangential component
/// against its normal one at n, the Coriolis component against the slot
/// at k, each where both arms are long enough on the page to hold it.
fn right_angles(s: &mut Canvas, polygons: &Polygons) {
    let p = &polygons.p;
    let n = p.n();
    let k = polygons.k();
    let normal = polygons.normal_from() - n;
    let tangential = p.a_d_acceleration() - n;
    let coriolis = match polygons.inversion {
        Inversion::Rod => -p.coriolis(),
        _ => p.coriolis(),
    };
    let sliding = p.a_d_acceleration() - k;
    for (id, vertex, u, v) in [
        ("angle-n", n, normal, tangential),
        ("angle-k", k, coriolis, sliding),
    ] {
        let seen = s.contains(Point::from(vertex));
        if seen && s.page(u.norm()) >= 2.0 * RIGHT_ANGLE && s.page(v.norm()) >= 2.0 * RIGHT_ANGLE {
            s.push(
                id,
                Role::Construction,
                Shape::RightAngle {
                    vertex: Point::from(vertex),
                    u,
                    v,
                },
            );
        }
    }
}

/// The direction rule at the pose's own directions: the sliding velocity
/// v along the slot, the quarter turn in the sense of ω_d, and 2 ω_d v;
/// where v is zero, the slot and the sense of ω_d alone.
fn rule_plot(ctx: &Ctx, rect: PageRect, polygons: &Polygons) -> Result<Plot> {
    let p = &polygons.p;
    let v = polygons.v();
    let moving = polygons.clean(v.norm(), 1.0, false) > 0.0;
    let turning = polygons.clean(p.omega_d(), polygons.ca, false) != 0.0;
    let u = if moving { v.normalize() } else { p.slot() };
    let sense = if p.omega_d() < 0.0 { -1.0 } else { 1.0 };
    let turned = perp(&u) * sense;
    let world = Frame::new(Point::new(-1.5, -1.5), Point::new(1.5, 1.5));
    let mut plot = Plot::world(
        "coriolis-rule",
        rect,
        &world,
        false,
        ctx.tolerance,
        ctx.font,
    )?
    .with_caption(match (moving, turning) {
        (true, true) => "the Coriolis direction",
        (false, _) => "the Coriolis direction (here *v* = 0)",
        (true, false) => "the Coriolis direction (here ω_{d} = 0)",
    });
    let map = *plot.map();
    let mut s = Canvas::new(map, map.world_frame(&plot.area()));
    let o = Point::origin();
    s.set_hue(Some(Hue::Velocity));
    s.push(
        "rule-v",
        Role::Construction,
        Shape::Arrow { from: o, to: o + u },
    );
    s.label(
        "label-rule-v",
        o + u,
        RichText::parse("*v*"),
        TextSize::Letter,
    );
    s.set_hue(Some(Hue::Acceleration));
    s.push(
        "rule-coriolis",
        Role::Result,
        Shape::Arrow {
            from: o,
            to: o + turned,
        },
    );
    s.label(
        "label-rule-coriolis",
        o + turned,
        RichText::parse("2ω_{d}*v*"),
        TextSize::Letter,
    );
    s.set_hue(None);
    let start = u.y.atan2(u.x);
    s.push(
        "rule-turn",
        Role::Force,
        Shape::Arc {
            centre: o,
            radius: 0.55,
            start,
            sweep: sense * 0.5 * std::f64::consts::PI,
            arrow: true,
        },
    );
    let mid = start + sense * 0.25 * std::f64::consts::PI;
    s.label(
        "label-rule-omega",
        o + Vector::new(mid.cos(), mid.sin()) * 0.55,
        RichText::parse("ω_{d}"),
        TextSize::Letter,
    );
    for item in s.finish().0 {
        plot.push(item);
    }
    Ok(plot)
}

/// The figure's metadata: the polygons' vectors from their poles, the
/// values read off them and the bars' lengths.
fn coriolis_json(polygons: &Polygons, v_bar: f64, a_bar: f64) -> Value {
    let p = &polygons.p;
    let v = |x: Vector| json!([x.x, x.y]);
    json!({
        "slot": v(p.slot()),
        "driven_velocity": v(p.driven()),
        "a_d_velocity": v(p.a_d()),
        "driven_acceleration": v(p.driven_acceleration()),
        "normal_end": v(p.n()),
        "coriolis": v(p.coriolis()),
        "k": v(polygons.k()),
        "a_d_acceleration": v(p.a_d_acceleration()),
        "omega_d": p.omega_d(),
        "alpha_d": p.alpha_d(),
        "sliding_velocity": p.sliding_velocity(),
        "sliding_acceleration": p.sliding_acceleration(),
        "velocity_bar": v_bar,
        "acceleration_bar": a_bar,
    })
}

/// The notes: the pose and the driver, then each polygon read to its bar,
/// then the Coriolis component and its rule.
fn notes(ctx: &Ctx, chain: &InvertedChain, polygons: &Polygons, bars: (f64, f64)) -> Vec<String> {
    let m = &ctx.mechanism;
    let u = ctx.unit();
    let p = &polygons.p;
    let (r, l, e) = (m.crank(), m.rod(), m.offset());
    let w = ctx.omega;
    let inversion = polygons.inversion;
    let offset = if e == 0.0 {
        String::new()
    } else {
        format!(", *e* = {}", short(e))
    };
    let ratio = chain.time_ratio().map_or(String::new(), |t| {
        format!(" Time ratio of the quick return {}.", short(t))
    });
    let (driver, pin, about) = match inversion {
        Inversion::Rod => ("the crank *a* (*BC*)", "*c*", "*B*"),
        _ => ("the rod *b* (*BA*)", "*a*", "*B*"),
    };
    let ca = polygons.ca;
    let v = polygons.clean(p.sliding_velocity().abs(), 1.0, false);
    let omega_d = polygons.clean(p.omega_d(), ca, false);
    let alpha_d = polygons.clean(p.alpha_d(), ca, true);
    let sliding = polygons.clean(p.sliding_acceleration(), 1.0, true);
    let coriolis_size = polygons.clean(p.coriolis().norm(), 1.0, true);
    let first = format!(
        "Inversion {}, link *{}* fixed ({}) at θ = {}°; *r* = {}, *l* = {}{offset}; {driver} turns about {about} at ω = {} rad/s ({} rpm), *CA* = {} {u}.{ratio}",
        inversion.number(),
        match inversion {
            Inversion::Rod => "b",
            _ => "a",
        },
        inversion.name(),
        short(ctx.angle.degrees()),
        short(r),
        short(l),
        sig(w),
        short(ctx.rpm()),
        sig(ca),
    );
    let velocity = match inversion {
        Inversion::Rod => format!(
            "Velocity polygon (the bar {} {u}/s): *oc* = ω·*BC* = {} {u}/s, perpendicular to *BC*; *ca*_{{d}} perpendicular to *CA*; *oa*_{{d}} along the slot, *v* = {} {u}/s; ω_{{d}} = *ca*_{{d}}/*CA* = {} rad/s.",
            short(bars.0),
            sig(p.driven().norm()),
            sig(v),
            sig(omega_d),
        ),
        _ => format!(
            "Velocity polygon (the bar {} {u}/s): *oa* = ω·*BA* = {} {u}/s, perpendicular to *BA*; *oa*_{{d}} perpendicular to *CA*; *a*_{{d}}*a* along the slot, *v* = {} {u}/s; ω_{{d}} = *oa*_{{d}}/*CA* = {} rad/s.",
            short(bars.0),
            sig(p.driven().norm()),
            sig(v),
            sig(omega_d),
        ),
    };
    let normal = omega_d * omega_d * ca;
    let acceleration = format!(
        "Acceleration polygon (the bar {} {u}/s²): *o*′{pin}′ = ω²·*B{}* = {} {u}/s² towards *B*; the normal component ω_{{d}}²·*CA* = {} {u}/s² towards *C* and the tangential component perpendicular to *CA*, α_{{d}} = {} rad/s²; the sliding acceleration along the slot {} {u}/s².",
        short(bars.1),
        match inversion {
            Inversion::Rod => "C",
            _ => "A",
        },
        sig(p.driven_acceleration().norm()),
        sig(normal),
        sig(alpha_d),
        sig(sliding),
    );
    let coriolis = format!(
        "The Coriolis component {} = 2ω_{{d}}*v* = {} {u}/s²: the sliding velocity *v* ({}) turned 90° in the sense of ω_{{d}}{}.",
        match inversion {
            Inversion::Rod => "*o*′*k*",
            _ => "*ka*′",
        },
        sig(coriolis_size),
        match inversion {
            Inversion::Rod => "of *d* on the block",
            _ => "of the block on *d*",
        },
        if v == 0.0 {
            "; here *v* = 0 and it vanishes"
        } else if omega_d == 0.0 {
            "; here ω_{d} = 0 and it vanishes"
        } else {
            ""
        },
    );
    vec![first, velocity, acceleration, coriolis]
}
