//! The inertia-force construction on the mechanism: (a) Klein's
//! construction (textbook §36, Fig. 65) drawn by the scene, its CG read as
//! the piston's acceleration a = ω² · CG, directed from G towards C, and
//! so, scaled by m ω², as the inertia force of the reciprocating parts,
//! m ω² · CG from C towards G; that force drawn at the cross-head, against
//! the acceleration, to the scale of the drawing (1 length unit = m ω²
//! force units); the crank effort T = F · OM about C through Ng's torque
//! line (OM = CE, drawn by the construction); (b) the force at the
//! cross-head resolved into the thrust along the rod, F_Q = F / cos φ, and
//! the thrust on the guides, F_N = F tan φ, a triangle of forces to its
//! own scale.
//!
//! The force is the inertia force alone (no gas force): the piston effort
//! F of `docs/dynamics.md` §2 with the cylinder empty. At θ = 90° and 270°
//! in line D is at infinity and the scene draws Kisch's G, which is the
//! same point.

use super::{Ctx, Sheet, positive_mass, short, sig};
use crate::construct::{AccelerationPoints, InstantCentre, Kisch, Klein, VelocityLine};
use crate::diagram::Plot;
use crate::dynamics::{Engine, EnginePose};
use crate::error::Result;
use crate::figure::{
    ARROW_LENGTH, Figure, HATCH_DEPTH, Item, NOTE_LINE, Panel, RichText, Role, Shape, TextSize,
};
use crate::geom::{Frame, Point, Vector};
use crate::scene::{Layer, torque_arrow};

/// Height given to the scene of the mechanism, page units (it ends
/// shorter when the drawing is flat, and grows by an enlarged detail).
const SCENE: f64 = 430.0;

/// The most height and width of the triangle of forces, page units.
const TRIANGLE: (f64, f64) = (440.0, 180.0);

/// Room for the notes below the triangle, page units: their three lines
/// (each line more, one said left out of the drawing, takes a
/// [`NOTE_LINE`] more).
const NOTES: f64 = 64.0;

/// Radius of the crank effort's arc arrow about C, page units.
const TORQUE_RADIUS: f64 = 30.0;

/// Room kept for an arrow's name and between arrows, page units.
const ROOM: f64 = 12.0;

/// An inertia-force arrow with a stretch at least this long on the page
/// (page units) beside no guide is lettered by that stretch's middle, not
/// beyond its free end.
const LONG_ARROW: f64 = 5.0 * ROOM;

/// An arrow shorter than this on the page (page units) is left out: the
/// notes give its value.
const SHORTEST: f64 = 2.0;

/// The engine's forces at the figure's pose.
struct Forces {
    /// The forces and torques by the dynamics module.
    at: EnginePose,
    /// Klein's F and G (Kisch's where D is at infinity).
    points: AccelerationPoints,
    /// The reciprocating mass.
    mass: f64,
    /// m ω², force units per length unit of CG.
    scale: f64,
}

impl Forces {
    fn new(ctx: &Ctx) -> Result<Self> {
        let mass = positive_mass(ctx)?;
        let engine = Engine::new(ctx.mechanism, mass, ctx.omega)?;
        let at = engine.at(ctx.angle)?;
        Ok(Self {
            at,
            points: acceleration_points(&ctx.pose()),
            mass,
            scale: mass * ctx.omega * ctx.omega,
        })
    }

    /// The inertia force as a world vector: m ω² (G − C).
    fn vector(&self) -> Vector {
        Vector::new(-self.at.piston_effort, 0.0)
    }
}

/// The points of the scene's Klein layer: Klein's, or Kisch's where D is
/// at infinity (the same F and G, `docs/design.md` §2).
fn acceleration_points(pose: &crate::mechanism::Pose) -> AccelerationPoints {
    let e = VelocityLine::construct(pose);
    match Klein::construct(pose, &InstantCentre::construct(pose), &e) {
        Some(k) => *k.points(),
        None => *Kisch::construct(pose, &e).points(),
    }
}

pub(in crate::catalogue) fn build(ctx: &Ctx) -> Result<Figure> {
    let forces = Forces::new(ctx)?;
    let mut sheet = Sheet::new(ctx);
    sheet.mechanism(ctx, true, true);
    metadata(&mut sheet, &forces);
    let (bottom, fi_left_out, shown) = mechanism(ctx, &forces, &mut sheet)?;
    let (bottom, enlarged) = match shown {
        Some((panel, main_scale)) => {
            cg_detail(ctx, &forces, &mut sheet, &panel, main_scale, bottom)?
        }
        None => (bottom, None),
    };
    let (top, fn_left_out) = match triangle(ctx, &forces, bottom + 8.0)? {
        Some((plot, left_out)) => {
            let rect = plot.rect();
            sheet.plot(plot);
            (rect.max().y, left_out)
        }
        None => (bottom, false),
    };
    // The page holds what was set: a detail or the triangle may take it
    // past the figure's own height, a note of a force left out past
    // the notes' room.
    let notes = notes(ctx, &forces, fn_left_out, fi_left_out, enlarged);
    let more = NOTE_LINE * notes.len().saturating_sub(3) as f64;
    sheet.height(top + NOTES + more + 16.0);
    sheet.notes(Point::new(20.0, top + 8.0), &notes);
    Ok(sheet.finish())
}

/// The values of the figure in its metadata (the length and force units
/// of the mechanism's).
fn metadata(sheet: &mut Sheet, f: &Forces) {
    let at = &f.at;
    sheet.meta(
        "inertia",
        serde_json::json!({
            "mass": f.mass,
            "force_per_length": f.scale,
            "cg": f.points.cg(),
            "inertia_force": at.inertia_force,
            "inertia_force_graphical": at.inertia_force_graphical,
            "rod_force": at.rod_force,
            "guide_thrust": at.guide_thrust,
            "om": at.om,
            "crank_effort": at.crank_effort,
            "crank_effort_exact": at.crank_effort_exact,
        }),
    );
}

/// The panel that shows G and the main view's scale (page units to the
/// world unit).
type Shown = (Panel, f64);

/// The scene's mechanism with Klein's construction, the inertia force at
/// the cross-head and the crank effort added to its main view; its
/// details as drawn. Returns the bottom of what it set on the page,
/// whether F_i was left out of the main view (shorter than
/// [`SHORTEST`] there), and the panel that shows G (the first detail
/// whose frame holds it, else the main view) with the main view's scale.
fn mechanism(ctx: &Ctx, f: &Forces, sheet: &mut Sheet) -> Result<(f64, bool, Option<Shown>)> {
    let scene = ctx
        .scene(ctx.page().width(), SCENE)?
        .with_layers([Layer::Mechanism, Layer::Klein]);
    let base = scene.figure()?;
    let mut panels = base.panels().iter();
    let Some(main) = panels.next() else {
        return Ok((base.height(), false, None));
    };
    let scale = main.transform().scale();
    let pose = ctx.pose();
    let details: Vec<&Panel> = panels.collect();
    // The crank effort's arc goes where C has room for it: in a detail
    // that holds C with the arc's reach about it (a short rod, where the
    // block, A's letter and F_i crowd about C on the main view), else on
    // the main view.
    let home = details.iter().position(|d| holds_the_arc(d, pose.c()));
    // F_i keeps clear of the arc where it is drawn here, and the arc,
    // set again, of F_i.
    let arc = |shafts: &[(Point, Point)]| {
        torque_arc_clear(
            main,
            pose.c(),
            pose.b(),
            nearest_face(main, &pose),
            f.at.crank_effort,
            shafts,
        )
    };
    let arc_radius = match home {
        None => arc(&[]).iter().find_map(|i| match i.shape {
            Shape::Arc { radius, .. } => Some(radius * scale),
            _ => None,
        }),
        Some(_) => None,
    };
    let mut items = inertia_arrow(main, &pose, f, scale, arc_radius);
    // Too short to read on the main view (a bare arrowhead on the block's
    // corner at a short rod's dead centre, l = 1.07 r at 180°), F_i is
    // drawn in the first detail that holds it whole, enlarged, instead.
    let enlarged = match shaft_length(&items) * scale < READABLE {
        true => details.iter().enumerate().find_map(|(k, detail)| {
            enlarged_arrow(detail, &pose, f, home == Some(k)).map(|items| (k, items))
        }),
        false => None,
    };
    if enlarged.is_some() {
        items.clear();
    }
    let fi_left_out = items.is_empty() && enlarged.is_none();
    if home.is_none() {
        // The arc keeps clear of F_i's shaft as of the block's edges.
        let shaft = shafts(&items);
        items.extend(arc(&shaft));
    }
    sheet.panel(main.clone().with_items(items));
    for (k, &detail) in details.iter().enumerate() {
        let own = if home == Some(k) {
            // Its gap and letter below C, as at any pose: the enlarged
            // block is drawn about C, and a gap facing its nearer face
            // would set T between A's and C's letters.
            let shaft = match &enlarged {
                Some((j, arrow)) if *j == k => shafts(arrow),
                _ => Vec::new(),
            };
            torque_arc_clear(detail, pose.c(), pose.b(), None, f.at.crank_effort, &shaft)
        } else {
            Vec::new()
        };
        let mut own: Vec<Item> = match &enlarged {
            Some((j, arrow)) if *j == k => arrow.iter().cloned().chain(own).collect(),
            _ => own,
        };
        for item in &mut own {
            item.id.insert_str(0, "detail-");
        }
        sheet.panel(detail.clone().with_items(own));
    }
    let g = f.points.g();
    let shown = details
        .iter()
        .find(|d| d.rect().contains(d.transform().apply(g)))
        .copied()
        .unwrap_or(main);
    Ok((base.height(), fi_left_out, Some((shown.clone(), scale))))
}

/// CG shorter than this on the page (page units) in the panel that
/// shows G leaves G's dot within C's pin, its letter and its ground
/// symbol: G, the figure's subject, could not be seen (l = 38 r at
/// 90.09°, CG 9 units in the ×20 detail).
const CG_READS: f64 = 2.0 * ROOM;

/// The length CG is drawn on the page in its own detail at C, at most,
/// page units.
const CG_SHOWN: f64 = 100.0;

/// The plot area of the detail at C and G, page units.
const CG_AREA: (f64, f64) = (260.0, 110.0);

/// The magnifications offered for the detail at C and G over the main
/// view, times a power of ten ([`super::coriolis::round_below`]).
const CG_STEPS: [f64; 8] = [1.0, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0];

/// Where CG is shorter than [`CG_READS`] on the page in `shown` (the
/// panel that shows G; the main view is drawn at `main_scale`), C and G
/// drawn again in a detail of their own below the mechanism (from
/// `top`), CG at most [`CG_SHOWN`] long there: the lines through them
/// as `shown` draws them, without C's ground symbol (drawn at a page
/// size, it stood over CG again), C and G lettered. Returns the bottom
/// of what is set on the page and the detail's magnification over the
/// main view, if drawn (none where G is C: the notes say so).
fn cg_detail(
    ctx: &Ctx,
    f: &Forces,
    sheet: &mut Sheet,
    shown: &Panel,
    main_scale: f64,
    top: f64,
) -> Result<(f64, Option<f64>)> {
    let pose = ctx.pose();
    let (c, g) = (pose.c(), f.points.g());
    let cg = (g - c).norm();
    let t = shown.transform();
    if cg == 0.0 || (t.apply(g) - t.apply(c)).norm() >= CG_READS {
        return Ok((top, None));
    }
    let most = CG_SHOWN / (cg * main_scale);
    if !(most.is_finite() && most >= 1.0) {
        return Ok((top, None));
    }
    let magnification = super::coriolis::round_below(most, &CG_STEPS);
    let scale = magnification * main_scale;
    let (w, h) = CG_AREA;
    let width = w.min(ctx.page().width() - 32.0);
    let mid = c + (g - c) * 0.5;
    let half = Vector::new(0.5 * width / scale, 0.5 * h / scale);
    let world = Frame::new(mid - half, mid + half);
    let rect = Frame::from_origin_size(
        0.5 * (ctx.page().width() - width),
        top + 8.0,
        width,
        h + crate::diagram::CAPTION,
    );
    let mut plot = Plot::world("cg", rect, &world, ctx.mirror, ctx.tolerance, ctx.font)?
        .with_caption(&format!("*C* and *G* ×{}", short(magnification)));
    let seen = plot.map().world_frame(&plot.area());
    let at = |p: Point, q: Point| (p - q).norm() * scale < 1.0;
    let own = |id: &str| id.strip_prefix("detail-").unwrap_or(id).to_string();
    let mut kept = Vec::new();
    for item in shown.items() {
        let name = own(&item.id);
        // C's and G's letters, and G's dot, are the detail's own (drawn
        // below): the panel's letter there may join them ("*C*, *G*").
        let keep = match &item.shape {
            Shape::Label { .. } => false,
            Shape::Bearing { .. } | Shape::Block { .. } | Shape::Hatch { .. } => false,
            Shape::Dot { centre } if at(*centre, g) => false,
            Shape::Pin { centre } | Shape::Dot { centre } => seen.contains(*centre),
            _ => {
                !(name.starts_with("offpage")
                    || name.starts_with("guide")
                    || name.starts_with("detail")
                    || name.starts_with("torque")
                    || name.starts_with("value")
                    || name.starts_with("dimension"))
            }
        };
        if keep {
            let mut item = item.clone();
            item.id = format!("cg-{name}");
            kept.push(item);
        }
    }
    kept.extend(own_letters(c, g));
    for item in kept {
        plot.push(item);
    }
    super::inversions::border(&mut plot, "cg");
    sheet.detail(plot);
    Ok((rect.max().y, Some(magnification)))
}

/// F_i shorter than this on the main view (page units: a head and a
/// shaft of its length) is drawn in a detail that holds it whole instead.
const READABLE: f64 = 2.0 * ARROW_LENGTH;

/// The world segments of the arrows among `items` (F_i's shaft).
fn shafts(items: &[Item]) -> Vec<(Point, Point)> {
    items
        .iter()
        .filter_map(|i| match i.shape {
            Shape::Arrow { from, to } => Some((from, to)),
            _ => None,
        })
        .collect()
}

/// The length of the longest arrow among `items`, world units (none:
/// zero).
fn shaft_length(items: &[Item]) -> f64 {
    shafts(items)
        .iter()
        .map(|(p, q)| (q - p).norm())
        .fold(0.0, f64::max)
}

/// F_i in the detail `panel` (which draws the crank effort's arc about
/// C where `holds_arc`), clear of that arc: where the panel holds A and
/// the whole arrow, at least [`READABLE`] long there, else none.
fn enlarged_arrow(
    panel: &Panel,
    pose: &crate::mechanism::Pose,
    f: &Forces,
    holds_arc: bool,
) -> Option<Vec<Item>> {
    let t = panel.transform();
    let scale = t.scale();
    let r = panel.rect();
    if !r.contains(t.apply(pose.a())) {
        return None;
    }
    let arc_radius = holds_arc
        .then(|| {
            torque_arc_clear(panel, pose.c(), pose.b(), None, f.at.crank_effort, &[])
                .iter()
                .find_map(|i| match i.shape {
                    Shape::Arc { radius, .. } => Some(radius * scale),
                    _ => None,
                })
        })
        .flatten();
    let items = inertia_arrow(panel, pose, f, scale, arc_radius);
    let whole = shafts(&items)
        .iter()
        .all(|(p, q)| r.contains(t.apply(*p)) && r.contains(t.apply(*q)));
    (whole && shaft_length(&items) * scale >= READABLE).then_some(items)
}

/// Whether the detail `panel` shows the crank centre `c` with the crank
/// effort's arc, its head and its letter inside its frame.
fn holds_the_arc(panel: &Panel, c: Point) -> bool {
    let p = panel.transform().apply(c);
    let r = panel.rect();
    let reach = TORQUE_RADIUS + 2.0 * ROOM;
    p.x - r.min().x >= reach
        && r.max().x - p.x >= reach
        && p.y - r.min().y >= reach
        && r.max().y - p.y >= reach
}

/// The point of the block's face nearer the crank centre, on the line of
/// stroke (where the torque arc opens towards the block).
fn nearest_face(panel: &Panel, pose: &crate::mechanism::Pose) -> Option<Point> {
    block_extent(panel).map(|(lo, hi)| {
        let x = if (pose.c().x - lo).abs() < (pose.c().x - hi).abs() {
            lo
        } else {
            hi
        };
        Point::new(x, pose.a().y)
    })
}

/// The slider block's extent along x in the panel, world units.
fn block_extent(panel: &Panel) -> Option<(f64, f64)> {
    block_span(panel, |p| p.x)
}

/// The least and greatest of `coordinate` over the slider block's
/// corners in the panel.
fn block_span(panel: &Panel, coordinate: impl Fn(&Point) -> f64) -> Option<(f64, f64)> {
    panel.items().iter().find_map(|item| match &item.shape {
        Shape::Block { points } => Some(
            points
                .iter()
                .map(&coordinate)
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
                    (lo.min(v), hi.max(v))
                }),
        ),
        _ => None,
    })
}

/// The inertia force at the cross-head: an arrow of the length CG (the
/// drawing's scale is 1 length unit to m ω² force units) along the line
/// of stroke, pulling the block from one face or pushing on it, on the
/// crank's side of the block where it keeps clear of the crank centre's
/// torque arrow, else on the far side, within the panel; set off the
/// line of stroke in the channel on the side away from the rod, or,
/// where a link or CG runs along it there or it would cross the crank
/// effort's arc of page radius `arc_radius` (where drawn on this panel),
/// beyond the guides and that arc.
fn inertia_arrow(
    panel: &Panel,
    pose: &crate::mechanism::Pose,
    f: &Forces,
    scale: f64,
    arc_radius: Option<f64>,
) -> Vec<Item> {
    let (a, c) = (pose.a(), pose.c());
    let length = f.points.cg().abs();
    if length * scale < SHORTEST {
        return Vec::new();
    }
    let toward = if c.x < a.x { -1.0 } else { 1.0 };
    let (lo, hi) = block_extent(panel).unwrap_or((a.x, a.x));
    let (near, far) = if toward < 0.0 { (lo, hi) } else { (hi, lo) };
    // Room on the crank's side: up to the torque arrow about C.
    let clear = (near - c.x).abs() - (TORQUE_RADIUS + 2.0 * ROOM) / scale;
    // Room beyond the far face: up to the panel's edge, less room for the
    // arrow's name.
    let edge = |corner: Point| panel.transform().invert(corner).x;
    let r = panel.rect();
    let ends = [
        edge(Point::new(r.min().x, r.min().y)),
        edge(Point::new(r.max().x, r.min().y)),
    ];
    let beyond = ends.iter().map(|x| (x - far) * -toward).fold(0.0, f64::max) - ROOM / scale;
    let (face, out) = if length <= clear || length > beyond {
        (near, toward)
    } else {
        (far, -toward)
    };
    // Between the line of stroke and a guide running beside it, midway
    // (a quarter of the block's height off the line); with no guide
    // beside it, nearer the block's edge, clear of the line of stroke and
    // of CG along it: a quarter off, it ran tight beside the thick CG and
    // read as that line.
    let end = face + out * length;
    let (x0, x1) = (face.min(end), face.max(end));
    let guides = guide_spans(panel);
    let beside = guides
        .iter()
        .any(|&(u, v)| u.max(x0) < v.min(x1) - 2.0 * ROOM / scale);
    let share = if beside { 0.25 } else { 0.4 };
    let height = block_span(panel, |p| p.y).map_or(0.0, |(lo, hi)| hi - lo);
    let away = if pose.b().y > a.y { -1.0 } else { 1.0 };
    // Within the channel where no link or CG runs beside it and it keeps
    // clear of the crank effort's arc about C; else beyond the guides'
    // hatching (and the arc's reach): at a short rod's dead centres the
    // crank and the rod lie on the line of stroke, and at 90° and 270° CG
    // does, tight beside an arrow in the channel, which read as theirs.
    let t = panel.transform();
    let strokes = along_strokes(panel);
    let r = panel.rect();
    let stroke_y = t.apply(a).y;
    let fits = |off: f64| {
        let (p, q) = (
            t.apply(Point::new(x0, a.y + off)),
            t.apply(Point::new(x1, a.y + off)),
        );
        let on_page = [p, q]
            .iter()
            .all(|p| p.y >= r.min().y + ROOM && p.y <= r.max().y - ROOM);
        let by_arc = arc_radius
            .is_some_and(|r| crate::geom::point_segment_distance(t.apply(c), p, q) < r + ARC_REACH);
        on_page && !by_arc && share_beside(p, q, stroke_y, &strokes) < ALONG_SHARE
    };
    let inside = share * height;
    let mut outside = 0.5 * height + (HATCH_DEPTH + 0.5 * ROOM) / scale;
    if let Some(r) = arc_radius {
        outside = outside.max((r + ARC_REACH) / scale);
    }
    let off = [
        away * inside,
        -away * inside,
        away * outside,
        -away * outside,
    ]
    .into_iter()
    .find(|&o| fits(o))
    .unwrap_or(away * inside);
    let side = if off < 0.0 { -1.0 } else { 1.0 };
    let face = Point::new(face, a.y + off);
    let along = Vector::new(out * length, 0.0);
    // Pulled from the face where the force points away from the block on
    // this side, pushed on it where it points into the block.
    let (from, to) = if f.vector().x * out > 0.0 {
        (face, face + along)
    } else {
        (face + along, face)
    };
    // Its letter beyond the arrow's free end, at its height between the
    // guides: set above or below its middle beside a guide, it stood on
    // the line of stroke or across the guide from its arrow. A long
    // arrow's free end reaches C or G, whose letters it ran into
    // ("C F_i"): where a long stretch of it runs with no guide beside it,
    // its letter by that stretch's middle, on its side away from the line
    // of stroke; beyond the guides, by its middle on that side.
    // By a stretch's middle, that of a piece the crank circle does not
    // cross (at its middle F_i stood on the circle): of those long enough
    // for it, the one farthest from the panel's other letters (by a
    // detail's "×N" tag it was pushed off above the tag), else the
    // longest.
    let circle = (c, pose.mechanism().crank());
    let letters: Vec<Point> = panel
        .items()
        .iter()
        .filter_map(|i| match &i.shape {
            Shape::Label { anchor, .. } => Some(t.apply(*anchor)),
            _ => None,
        })
        .collect();
    let middle = |u: f64, v: f64| {
        let pieces = uncrossed(u, v, face.y, circle);
        let room = |&(p, q): &(f64, f64)| {
            let m = t.apply(Point::new(0.5 * (p + q), face.y));
            letters
                .iter()
                .map(|l| (*l - m).norm())
                .fold(f64::INFINITY, f64::min)
        };
        let long: Vec<&(f64, f64)> = pieces
            .iter()
            .filter(|(p, q)| (q - p) * scale >= 3.0 * ROOM)
            .collect();
        let (u, v) = match long.is_empty() {
            false => long.into_iter().max_by(|a, b| room(a).total_cmp(&room(b))),
            true => pieces
                .iter()
                .max_by(|a, b| (a.1 - a.0).total_cmp(&(b.1 - b.0))),
        }
        .copied()
        .unwrap_or((u, v));
        (Point::new(0.5 * (u + v), face.y), Vector::new(0.0, side))
    };
    let (anchor, toward) = match unguided(x0, x1, &guides) {
        _ if off.abs() > 0.5 * height => middle(x0, x1),
        Some((u, v)) if (v - u) * scale >= LONG_ARROW => middle(u, v),
        _ => (face + along, along),
    };
    vec![
        Item::new("force-inertia", Role::Force, Shape::Arrow { from, to }),
        Item::new(
            "value-inertia",
            Role::Label,
            Shape::Label {
                anchor,
                text: RichText::parse("*F*_i"),
                size: TextSize::Small,
                toward: Some(toward),
                line: None,
            },
        ),
    ]
}

/// The letters of C and G and G's dot for their detail, each from its
/// own place: the panel the detail copies may letter them together
/// ("*C*, *G*", G's dot within C's pin), as the construction's detail
/// does where CG is short.
fn own_letters(c: Point, g: Point) -> [Item; 3] {
    let letter = |id: &str, at: Point, name: &str| {
        Item::new(
            id,
            Role::Label,
            Shape::Label {
                anchor: at,
                text: RichText::parse(name),
                size: TextSize::Letter,
                toward: None,
                line: None,
            },
        )
    };
    [
        letter("cg-label-C", c, "*C*"),
        Item::new("cg-point-G", Role::Construction, Shape::Dot { centre: g }),
        letter("cg-label-G", g, "*G*"),
    ]
}

/// Beyond the crank effort's arc radius, the page room F_i's shaft keeps
/// from C where the arc is drawn on its panel: room for T's letter set
/// on the arc (at the arc's clearance only, T stood on the arrow).
const ARC_REACH: f64 = 2.0 * ROOM;

/// A link or CG nearer F_i's shaft than this (page units), parallel to it
/// within [`ALONG_ANGLE`], reads as running along it (CG 14 units off the
/// arrow at 90° did).
const BESIDE: f64 = 1.5 * ROOM;

/// The greatest angle (degrees) between F_i's shaft and a stroke running
/// along it.
const ALONG_ANGLE: f64 = 10.0;

/// The share of F_i's shaft beside a link or CG at which it reads as
/// lying along it.
const ALONG_SHARE: f64 = 1.0 / 3.0;

/// The page segments of the panel's links and of CG within
/// [`ALONG_ANGLE`] of the line of stroke (the page's x axis).
fn along_strokes(panel: &Panel) -> Vec<(Point, Point)> {
    let t = panel.transform();
    let tan = ALONG_ANGLE.to_radians().tan();
    panel
        .items()
        .iter()
        .filter(|i| i.id.starts_with("link-") || i.id == "line-CG")
        .filter_map(|i| match &i.shape {
            Shape::Polyline { points, .. } => Some(points),
            _ => None,
        })
        .flat_map(|points| {
            let page: Vec<Point> = points.iter().map(|p| t.apply(*p)).collect();
            page.iter()
                .zip(page.iter().skip(1))
                .map(|(a, b)| (*a, *b))
                .collect::<Vec<_>>()
        })
        .filter(|(p, q)| (q.y - p.y).abs() <= tan * (q.x - p.x).abs() && p != q)
        .collect()
}

/// A stroke whose ends both lie this near the line of stroke (page units)
/// lies on it: CG, the crank and the rod at a dead centre or a degree
/// from it.
const ON_LINE: f64 = 4.0;

/// The share of the page shaft `p q` (level, off the line of stroke at
/// page height `stroke_y`) within [`BESIDE`] of one of `strokes` where
/// that stroke lies on the line of stroke ([`ON_LINE`]) or on the
/// shaft's side of it: the rod rising from A on the other side of the
/// line (the default engine's) stands apart from it across the channel.
fn share_beside(p: Point, q: Point, stroke_y: f64, strokes: &[(Point, Point)]) -> f64 {
    const STEPS: u32 = 32;
    let side = p.y - stroke_y;
    let near = (0..=STEPS)
        .map(|k| p + (q - p) * (f64::from(k) / f64::from(STEPS)))
        .filter(|s| {
            strokes.iter().any(|&(u, v)| {
                let d = v - u;
                let k = ((s - u).dot(&d) / d.dot(&d)).clamp(0.0, 1.0);
                let n = u + d * k;
                let on_line =
                    (u.y - stroke_y).abs() <= ON_LINE && (v.y - stroke_y).abs() <= ON_LINE;
                (on_line || (n.y - stroke_y) * side > 0.0) && (s - n).norm() < BESIDE
            })
        })
        .count();
    near as f64 / f64::from(STEPS + 1)
}

/// Room kept between the crank effort's arc (its head's half width
/// included) and the block, the guides, their hatching and the bearing,
/// page units.
const ARC_CLEAR: f64 = 5.0;

/// The radii tried for the crank effort's arc, page units, from the usual
/// one outwards: the first whose arc stands clear of the block, the
/// guides and the bearing.
const ARC_RADII: [f64; 6] = [
    TORQUE_RADIUS,
    TORQUE_RADIUS + 4.0,
    TORQUE_RADIUS + 8.0,
    TORQUE_RADIUS + 12.0,
    TORQUE_RADIUS + 16.0,
    TORQUE_RADIUS + 20.0,
];

/// The crank effort's arc in `panel` ([`torque_arc`]) at the smallest
/// radius of [`ARC_RADII`], and with its gap facing the block (`block`)
/// or set as at any pose, at which the arc, its head and its tail keep
/// [`ARC_CLEAR`] from the block, the guides with their hatching and the
/// bearing and stay inside the panel: drawn over the block or the guides'
/// hatching it read as a mark of theirs. Where no such place is, the
/// clearest. Its letter is kept off the directions of the panel's other
/// letters within its reach (a detail's "×N" tag beside C read as one
/// label with T). It keeps [`END_CLEAR`] from the ends of the panel's
/// links and lines ([`line_ends`]). The arc keeps clear of `shafts` (world segments: F_i's,
/// where it passes by C) as of the block.
fn torque_arc_clear(
    panel: &Panel,
    c: Point,
    b: Point,
    block: Option<Point>,
    t: f64,
    shafts: &[(Point, Point)],
) -> Vec<Item> {
    let scale = panel.transform().scale();
    let page = panel.transform();
    // C's own letter, where it has one, stands first above and to the
    // right of it on the page: T kept off that direction too (set there,
    // by the arc's clearest share between the line of stroke and CE, it
    // stood against C's letter once F_i left that corner free).
    let lettered = panel.items().iter().any(|i| match &i.shape {
        Shape::Label { anchor, .. } => page.apply_vector(anchor - c).norm() < ROOM,
        _ => false,
    });
    let up_right = {
        let (x, y) = (
            page.apply_vector(Vector::new(1.0, 0.0)).x,
            page.apply_vector(Vector::new(0.0, 1.0)).y,
        );
        Vector::new(x.signum(), -y.signum())
    };
    let own_letter = lettered.then(|| up_right.y.atan2(up_right.x));
    let mut obstacles = arc_obstacles(panel);
    obstacles.extend(shafts.iter().map(|(p, q)| (page.apply(*p), page.apply(*q))));
    let ends = line_ends(panel, c);
    let gaps = match block {
        Some(_) => vec![block, None],
        None => vec![None],
    };
    let mut best: Option<(f64, Vec<Item>)> = None;
    for radius in ARC_RADII {
        let mut labels = nearby_letters(panel, c, radius);
        labels.extend(own_letter);
        for gap in &gaps {
            let items = torque_arc(c, b, *gap, t, scale, radius, &labels);
            let clear = arc_clearance(panel, &items, &obstacles)
                .min(arc_clearance(panel, &items, &ends) - (END_CLEAR - ARC_CLEAR));
            if clear >= ARC_CLEAR {
                return items;
            }
            if best.as_ref().is_none_or(|(c, _)| clear > *c) {
                best = Some((clear, items));
            }
        }
    }
    best.map(|(_, items)| items).unwrap_or_default()
}

/// The world directions from `c` of the panel's letters whose anchors lie
/// within two [`ROOM`]s of the circle of page radius `radius` about it,
/// where the crank effort's letter stands.
fn nearby_letters(panel: &Panel, c: Point, radius: f64) -> Vec<f64> {
    let t = panel.transform();
    panel
        .items()
        .iter()
        .filter_map(|item| match &item.shape {
            Shape::Label { anchor, .. } => {
                let d = anchor - c;
                let page = t.apply_vector(d).norm();
                ((page - radius).abs() <= 2.0 * ROOM).then(|| d.y.atan2(d.x))
            }
            _ => None,
        })
        .collect()
}

/// The page segments the crank effort's arc keeps clear of: the block's
/// edges, the guides and the outer edge of their hatching, and the
/// bearing's pedestal with its hatched foot.
fn arc_obstacles(panel: &Panel) -> Vec<(Point, Point)> {
    use crate::figure::BEARING_FOOT;
    let t = panel.transform();
    let mut out = Vec::new();
    let ring = |points: &[Point], closed: bool, out: &mut Vec<(Point, Point)>| {
        let page: Vec<Point> = points.iter().map(|p| t.apply(*p)).collect();
        out.extend(page.iter().zip(page.iter().skip(1)).map(|(a, b)| (*a, *b)));
        if closed
            && page.len() > 2
            && let (Some(last), Some(first)) = (page.last(), page.first())
        {
            out.push((*last, *first));
        }
    };
    for item in panel.items() {
        match &item.shape {
            Shape::Block { points } => ring(points, true, &mut out),
            Shape::Polyline { points, .. } if item.id.starts_with("guide-") => {
                ring(points, false, &mut out);
            }
            Shape::Hatch { from, to, side } => {
                let (p, q) = (t.apply(*from), t.apply(*to));
                let v = t.apply_vector(*side);
                let n = v.norm();
                if n > 0.0 {
                    let d = v * (HATCH_DEPTH / n);
                    out.extend([(p, q), (p + d, q + d), (p, p + d), (q, q + d)]);
                }
            }
            Shape::Bearing { centre, foot } => {
                let (down, along) = foot.axes();
                let o = t.apply(*centre);
                let (depth, half) = BEARING_FOOT;
                let at = |a: f64, s: f64| o + down * a + along * s;
                let outer = depth + HATCH_DEPTH;
                out.extend([
                    (o, at(depth, -0.6 * half)),
                    (o, at(depth, 0.6 * half)),
                    (at(depth, -half), at(depth, half)),
                    (at(outer, -half), at(outer, half)),
                    (at(depth, -half), at(outer, -half)),
                    (at(depth, half), at(outer, half)),
                ]);
            }
            _ => {}
        }
    }
    out
}

/// Room kept between the crank effort's arc and the ends of the panel's
/// links and construction lines off C (and a detail frame's corners),
/// page units: an arc through G, where CG and the line from B end, with
/// its head there, read as that line's arrowhead.
const END_CLEAR: f64 = ROOM;

/// The page points (as segments of no length) where the panel's links
/// and construction lines end, and the corners of a detail's frame drawn
/// on it (the arc's head on one read as the frame's mark), other than at
/// the crank centre `c`.
fn line_ends(panel: &Panel, c: Point) -> Vec<(Point, Point)> {
    let t = panel.transform();
    let centre = t.apply(c);
    panel
        .items()
        .iter()
        .filter_map(|i| match &i.shape {
            Shape::Polyline {
                points,
                closed: false,
            } if i.id.starts_with("line-") || i.id.starts_with("link-") => {
                Some(vec![*points.first()?, *points.last()?])
            }
            Shape::Polyline { points, .. } if i.id == "detail-frame" => Some(points.clone()),
            _ => None,
        })
        .flatten()
        .map(|p| t.apply(p))
        .filter(|p| (p - centre).norm() > ROOM)
        .map(|p| (p, p))
        .collect()
}

/// The least page distance between the arc of `items` and `obstacles`;
/// nothing where it leaves the panel (less [`ROOM`] for its letter).
fn arc_clearance(panel: &Panel, items: &[Item], obstacles: &[(Point, Point)]) -> f64 {
    let Some((centre, radius, start, sweep)) = items.iter().find_map(|i| match i.shape {
        Shape::Arc {
            centre,
            radius,
            start,
            sweep,
            ..
        } => Some((centre, radius, start, sweep)),
        _ => None,
    }) else {
        return f64::INFINITY;
    };
    let t = panel.transform();
    const STEPS: u32 = 72;
    let points: Vec<Point> = (0..=STEPS)
        .map(|k| {
            let a = start + sweep * f64::from(k) / f64::from(STEPS);
            t.apply(centre + Vector::new(a.cos(), a.sin()) * radius)
        })
        .collect();
    let r = panel.rect();
    let inside = points.iter().all(|p| {
        p.x >= r.min().x + ROOM
            && p.x <= r.max().x - ROOM
            && p.y >= r.min().y + ROOM
            && p.y <= r.max().y - ROOM
    });
    if !inside {
        return f64::NEG_INFINITY;
    }
    points
        .iter()
        .zip(points.iter().skip(1))
        .flat_map(|(a, b)| {
            obstacles
                .iter()
                .map(move |(p, q)| crate::geom::segment_distance(*a, *b, *p, *q))
        })
        .fold(f64::INFINITY, f64::min)
}

/// The pieces of the level stretch `x0`..`x1` at height `y` (world)
/// between the crossings of the circle `(centre, radius)`.
fn uncrossed(x0: f64, x1: f64, y: f64, (centre, radius): (Point, f64)) -> Vec<(f64, f64)> {
    let h = radius * radius - (y - centre.y).powi(2);
    let mut cuts = vec![x0];
    if h > 0.0 {
        cuts.extend(
            [centre.x - h.sqrt(), centre.x + h.sqrt()]
                .into_iter()
                .filter(|x| *x > x0 && *x < x1),
        );
    }
    cuts.push(x1);
    cuts.iter()
        .zip(cuts.iter().skip(1))
        .map(|(a, b)| (*a, *b))
        .collect()
}

/// The longest stretch of `x0`..`x1` (world x) beside none of the
/// `guides`' spans.
fn unguided(x0: f64, x1: f64, guides: &[(f64, f64)]) -> Option<(f64, f64)> {
    let mut pieces = vec![(x0, x1)];
    for &(u, v) in guides {
        pieces = pieces
            .into_iter()
            .flat_map(|(p, q)| [(p, q.min(u)), (p.max(v), q)])
            .filter(|(p, q)| q > p)
            .collect();
    }
    pieces
        .into_iter()
        .max_by(|a, b| (a.1 - a.0).total_cmp(&(b.1 - b.0)))
}

/// The guides' extents along x in the panel, world units.
fn guide_spans(panel: &Panel) -> Vec<(f64, f64)> {
    panel
        .items()
        .iter()
        .filter_map(|item| match &item.shape {
            Shape::Polyline { points, .. } if item.id.starts_with("guide-") => {
                let xs = points.iter().map(|p| p.x);
                Some((
                    xs.clone().fold(f64::INFINITY, f64::min),
                    xs.fold(f64::NEG_INFINITY, f64::max),
                ))
            }
            _ => None,
        })
        .collect()
}

/// The crank effort `t` as the scene's torque arrow about the crank
/// centre `c` ([`torque_arrow`]), its letter clear of the crank to the
/// pin `b`, its gap facing the slider's block where
/// the block comes within the arc's reach (`block`, its nearest point, a
/// short rod near the inner dead centre). Nothing at a dead centre, where
/// T = 0.
fn torque_arc(
    c: Point,
    b: Point,
    block: Option<Point>,
    t: f64,
    scale: f64,
    page_radius: f64,
    letters: &[f64],
) -> Vec<Item> {
    if t == 0.0 || scale.is_nan() || scale <= 0.0 {
        return Vec::new();
    }
    let radius = page_radius / scale;
    let gap = block
        .filter(|b| (b - c).norm() < radius + ROOM / scale)
        .map(|b| (b.y - c.y).atan2(b.x - c.x));
    // Its letter clear of the crank, of the line of stroke through C (CG
    // lies on it) and of the perpendicular CE: set in the gap, below or
    // above C, it stood beside CE and read as E's or CE's name.
    let crank = (b.y - c.y).atan2(b.x - c.x);
    let [right, up] = [0.0, std::f64::consts::FRAC_PI_2];
    let mut avoid = vec![
        crank,
        right,
        up,
        right + std::f64::consts::PI,
        up - std::f64::consts::PI,
    ];
    avoid.extend_from_slice(letters);
    torque_arrow(c, t, radius, gap, &avoid).to_vec()
}

/// (b) The triangle of forces at the cross-head: F_i = F_Q + F_N, to its
/// own scale, drawn as the mechanism is (mirrored with it), centred on
/// the page from `top` down, no taller than it needs. `None` where there
/// is no force (a = 0).
fn triangle(ctx: &Ctx, f: &Forces, top: f64) -> Result<Option<(Plot, bool)>> {
    let pose = ctx.pose();
    let at = &f.at;
    let fi = f.vector();
    if fi.x == 0.0 {
        return Ok(None);
    }
    let rod = (pose.b() - pose.a()) / ctx.mechanism.rod();
    let q = rod * at.rod_force;
    let o = Point::origin();
    let corners = [o, o + fi, o + q];
    let (lo, hi) = corners.iter().fold(
        (
            Point::new(f64::INFINITY, f64::INFINITY),
            Point::new(f64::NEG_INFINITY, f64::NEG_INFINITY),
        ),
        |(lo, hi), p| (lo.inf(p), hi.sup(p)),
    );
    let size = (hi - lo).norm();
    let pad = Vector::new(0.12 * size, 0.12 * size);
    let world = Frame::new(lo - pad, hi + pad);
    let span = world.max() - world.min();
    let width = TRIANGLE.0.min(ctx.page().width() - 32.0);
    let tall = (width * span.y / span.x).clamp(48.0, TRIANGLE.1);
    let rect = Frame::from_origin_size(
        0.5 * (ctx.page().width() - width),
        top,
        width,
        tall + crate::diagram::CAPTION,
    );
    let mut plot = Plot::world("forces", rect, &world, ctx.mirror, ctx.tolerance, ctx.font)?
        .with_caption("The inertia force at the cross-head: *F*_i = *F*_Q + *F*_N, along the rod and on the guides");
    let arrow =
        |id: &str, from: Point, to: Point| Item::new(id, Role::Force, Shape::Arrow { from, to });
    // Each letter by its arrow's middle on the side away from the
    // triangle's third corner: in a flat triangle F_i's and F_Q's middles
    // nearly meet, and letters set about them alike stood side by side.
    let label = |id: &str, from: Point, to: Point, third: Point, text: &str| {
        let at = from + (to - from) * 0.5;
        let along = to - from;
        let across = Vector::new(-along.y, along.x);
        let out = if across.dot(&(third - at)) > 0.0 {
            -across
        } else {
            across
        };
        Item::new(
            format!("value-{id}"),
            Role::Label,
            Shape::Label {
                anchor: at,
                text: RichText::parse(text),
                size: TextSize::Small,
                toward: (out.norm() > 0.0).then_some(out),
                line: None,
            },
        )
    };
    plot.push(arrow("force-triangle-inertia", o, o + fi));
    plot.push(arrow("force-triangle-rod", o, o + q));
    if at.guide_thrust == 0.0 {
        // A flat triangle (the rod on the line of stroke): F_Q is F_i,
        // one arrow, said so in one label, not two letters side by side
        // on it.
        plot.push(label(
            "triangle-inertia",
            o,
            o + fi,
            o + Vector::new(0.0, -1.0),
            "*F*_Q = *F*_i",
        ));
        return Ok(Some((plot, false)));
    }
    plot.push(label("triangle-inertia", o, o + fi, o + q, "*F*_i"));
    plot.push(label("triangle-rod", o, o + q, o + fi, "*F*_Q"));
    // F_N no longer than two arrowheads on the page shows a head and no
    // shaft, a letter with no arrow: left out, the notes say why.
    let shown = plot.map().apply_vector(fi - q).norm() >= 2.0 * ARROW_LENGTH;
    if shown {
        plot.push(arrow("force-triangle-guides", o + q, o + fi));
        plot.push(label("triangle-guides", o + q, o + fi, o, "*F*_N"));
    }
    Ok(Some((plot, !shown)))
}

/// The notes: the engine, the scale, and every force with its value and
/// unit, the graphical beside the exact.
fn notes(
    ctx: &Ctx,
    f: &Forces,
    fn_left_out: bool,
    fi_left_out: bool,
    enlarged: Option<f64>,
) -> Vec<String> {
    let m = ctx.mechanism;
    let at = &f.at;
    let (u, fu) = (ctx.unit(), ctx.units.force());
    let mass_u = ctx.units.mass();
    let t = ctx.units.torque();
    let sense = |x: f64, towards: &str, away: &str| {
        if x > 0.0 {
            towards.to_string()
        } else if x < 0.0 {
            away.to_string()
        } else {
            String::new()
        }
    };
    let mut lines = vec![
        format!(
            "*r* = {} {u}, *l* = {} {u}{}, θ = {}°, {} rpm; reciprocating mass *m* = {} {mass_u}, no gas force. Scale: *CG* is the acceleration ω²·*CG* and the inertia force *m*ω²·*CG*: 1 {u} = {} {fu}.",
            short(m.crank()),
            short(m.rod()),
            ctx.offset_clause(),
            short(ctx.angle.degrees()),
            short(ctx.rpm()),
            short(f.mass),
            sig(f.scale),
        ),
        format!(
            "*CG* = {} {u}: *a* = {} {u}/s², inertia force *F*_i = *m*ω²·*CG* = {} {fu} (exact *m* d²*x*/d*t*² = {} {fu}){}.",
            sig(f.points.cg().abs()),
            sig(ctx.omega * ctx.omega * f.points.cg().abs()),
            sig(at.inertia_force_graphical.abs()),
            sig(at.inertia_force.abs()),
            sense(
                at.inertia_force,
                ", towards the crank",
                ", away from the crank"
            ),
        ),
        format!(
            "Along the rod *F*_Q = *F*_i/cos φ = {} {fu}, on the guides *F*_N = *F*_i tan φ = {} {fu}; *CE* (Ng’s *OM*) = {} {u}, crank effort *T* = *F*_i·*CE* = {} {t}{} (exact *F*_i *r* sin(θ + φ)/cos φ = {} {t}).",
            sig(at.rod_force.abs()),
            sig(at.guide_thrust.abs()),
            sig(at.om.abs()),
            sig(at.crank_effort.abs()),
            // The sense as the page shows it: a mirrored drawing turns
            // the world's counter-clockwise clockwise (the arc at C is
            // drawn in the world and mirrored with it).
            sense(
                if ctx.mirror {
                    -at.crank_effort
                } else {
                    at.crank_effort
                },
                ", counter-clockwise",
                ", clockwise"
            ),
            sig(rounded_off(at.crank_effort_exact, at.inertia_force * m.crank()).abs()),
        ),
    ];
    if fi_left_out {
        lines.push(
            "*F*_i, *CG* long at the drawing’s scale, is too short to draw at the cross-head in the main view: its value is given above.".to_string(),
        );
    }
    if let Some(m) = enlarged {
        lines.push(format!(
            "*CG* is too short to show *G* clear of *C* in the mechanism: *C* and *G* are drawn again below it, ×{} the main view.",
            short(m)
        ));
    }
    if fn_left_out {
        lines.push(
            "*F*_N is too short to draw in the triangle of forces at its scale: *F*_Q and *F*_i all but coincide.".to_string(),
        );
    }
    lines
}

/// `x`, a torque of the size of `scale`, or 0 where it is within the
/// rounding of that size (64 ulps): at a dead centre the exact formula's
/// sin(θ + φ) is rounding, and 4×10⁻¹⁴ beside *T* = 0 reads as a value.
fn rounded_off(x: f64, scale: f64) -> f64 {
    if x.abs() <= 64.0 * f64::EPSILON * scale.abs() {
        0.0
    } else {
        x
    }
}
