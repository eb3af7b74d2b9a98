//! Piston acceleration on a distance base and on a time base against
//! simple harmonic motion, and a polar acceleration diagram.
//!
//! The acceleration is taken towards the crank, f = −d²x/dt² (the sign of
//! the textbook's eq. 3). The distance base is the displacement of A from
//! the outer dead centre. The polar diagram sets G′ off along the crank at
//! the signed length CG′ = CG = f/ω² (Kisch's and Klein's G; backwards
//! along the crank where CG is negative), as Fig. 64 does with E′ for the
//! velocity; simple harmonic motion gives the circle on the diameter r.

use super::{
    Ctx, PER_DEGREE, Sheet, against_time, against_travel, dead_centres, extent, short, sig,
};
use crate::diagram::{Axis, Plot};
use crate::error::Result;
use crate::figure::{Dash, Figure, Item, NOTE_LINE, Part, RichText, Role, Shape, Symbol};
use crate::geom::{Frame, Point, Vector};
use crate::scene::COINCIDE;
use crate::{angle::Angle, mechanism::Pose};

/// The narrowest page (page units) that sets (a) and (b) side by side:
/// each column then holds the ordinate's title, about 260 units at the
/// small size, and the abscissa's.
const NARROWEST_COLUMNS: f64 = 700.0;

/// The height of a row of plots, page units.
const ROW: f64 = 350.0;

/// Where the three panels go: (a) and (b) side by side with (c) below
/// both, the notes beside (c), where a column holds the axes' titles; on
/// a narrower page the three stacked at the page's width and the notes
/// below them.
struct Layout {
    columns: bool,
    /// A panel's width.
    half: f64,
    /// (b)'s top left corner.
    b_at: Point,
    /// (c)'s top.
    c_top: f64,
}

impl Layout {
    fn new(page_width: f64) -> Self {
        let columns = page_width >= NARROWEST_COLUMNS;
        let half = match columns {
            true => 0.5 * (page_width - 32.0 - 16.0),
            false => page_width - 32.0,
        };
        // Where (b) and (c) go: beside (a) and below both, or each below.
        let (b_at, c_top) = match columns {
            true => (Point::new(16.0 + half + 16.0, 16.0), 16.0 + ROW + 12.0),
            false => (
                Point::new(16.0, 16.0 + ROW + 12.0),
                16.0 + 2.0 * (ROW + 12.0),
            ),
        };
        Self {
            columns,
            half,
            b_at,
            c_top,
        }
    }
}

/// The acceleration's axis: its title, and the range of f over a turn
/// with simple harmonic motion's ±rω² inside it.
struct FAxis {
    title: String,
    lo: f64,
    hi: f64,
}

impl FAxis {
    fn new(ctx: &Ctx) -> Self {
        let m = ctx.mechanism;
        let w2 = ctx.omega * ctx.omega;
        let rw2 = m.crank() * w2;
        let (lo, hi) = extent(&m, |p| -w2 * p.position_acceleration());
        Self {
            title: format!("*f* = −d²*x*/d*t*² ({}/s²), towards the crank", ctx.unit()),
            lo: lo.min(-rw2),
            hi: hi.max(rw2),
        }
    }
}

pub(in crate::catalogue) fn build(ctx: &Ctx) -> Result<Figure> {
    let page = ctx.page();
    let layout = Layout::new(page.width());
    let mut sheet = Sheet::new(ctx);
    sheet.mechanism(ctx, true, true);
    let f = FAxis::new(ctx);
    sheet.plot(distance_base(ctx, &layout, &f)?);
    sheet.plot(time_base(ctx, &layout, &f)?);
    // As tall as beside the notes on the figure's own page.
    let tall = page.height() - (16.0 + ROW + 12.0) - 16.0;
    let (polar, with_c) = polar_diagram(ctx, &layout, tall)?;
    sheet.plot(polar);
    let corner = match layout.columns {
        true => Point::new(16.0 + layout.half + 28.0, layout.c_top + 30.0),
        false => {
            let below = layout.c_top + tall + 12.0;
            sheet.height(below + 6.0 * NOTE_LINE + 16.0);
            Point::new(28.0, below)
        }
    };
    sheet.notes(corner, &notes(ctx, with_c));
    Ok(sheet.finish())
}

/// f = −d²x/dt² of a pose and its rate per radian.
fn exact(w2: f64) -> impl Fn(&Pose) -> (f64, f64) {
    move |p: &Pose| (-w2 * p.position_acceleration(), -w2 * p.position_jerk())
}

/// (a) The acceleration on a distance base: both strokes on one curve in
/// line, each on its own where the stroke is offset, and simple harmonic
/// motion.
fn distance_base(ctx: &Ctx, layout: &Layout, f: &FAxis) -> Result<Plot> {
    let m = ctx.mechanism;
    let r = m.crank();
    let w2 = ctx.omega * ctx.omega;
    let (o, i) = dead_centres(&m);
    let far = ((m.rod() + r - m.offset()) * (m.rod() + r + m.offset())).sqrt();
    let near = ((m.rod() - r - m.offset()) * (m.rod() - r + m.offset())).sqrt();
    let rect = crate::geom::Frame::from_origin_size(16.0, 16.0, layout.half, ROW);
    let x = Axis::nice(
        &format!(
            "displacement of *A* from the outer dead centre ({})",
            ctx.unit()
        ),
        0.0,
        (far - near).max(2.0 * r),
    )?;
    let y = Axis::nice(&f.title, f.lo, f.hi)?;
    let mut distance = Plot::new("distance-base", rect, x, y, ctx.tolerance, ctx.font)?
        .with_caption("(a) Acceleration on a distance base");
    let outward = against_travel(m, exact(w2));
    let mut pieces: Vec<(&dyn crate::diagram::Curve, std::ops::RangeInclusive<f64>)> =
        vec![(&outward, o..=i)];
    if m.offset() == 0.0 {
        distance.curve(
            "curve-acceleration-distance",
            &pieces,
            Dash::Solid,
            Some("piston (both strokes)"),
        )?;
    } else {
        distance.curve(
            "curve-acceleration-distance",
            &pieces,
            Dash::Solid,
            Some("piston, stroke towards the crank"),
        )?;
        pieces = vec![(&outward, i..=o + 360.0)];
        distance.curve(
            "curve-acceleration-distance-return",
            &pieces,
            Dash::DashDot,
            Some("piston, return stroke"),
        )?;
    }
    let shm_travel = |deg: f64| {
        let a = Angle::from_degrees(deg).ok()?;
        let (s, c) = (a.sin(), a.cos());
        Some((
            Point::new(r * (1.0 - c), r * w2 * c),
            Vector::new(r * s, -r * w2 * s) * PER_DEGREE,
        ))
    };
    distance.curve(
        "curve-acceleration-distance-shm",
        &[(&shm_travel, 0.0..=180.0)],
        Dash::Dotted,
        Some("simple harmonic motion"),
    )?;
    Ok(distance)
}

/// (b) The acceleration on a time base over a turn, and simple harmonic
/// motion, with headroom above the curves for the legend.
fn time_base(ctx: &Ctx, layout: &Layout, f: &FAxis) -> Result<Plot> {
    let m = ctx.mechanism;
    let (r, omega) = (m.crank(), ctx.omega);
    let w2 = omega * omega;
    let period = std::f64::consts::TAU / omega;
    let rect = crate::geom::Frame::from_origin_size(layout.b_at.x, layout.b_at.y, layout.half, ROW);
    let x = Axis::linear("time *t* (s);  θ = ω*t*", 0.0, period)?;
    let headroom = Axis::nice(&f.title, f.lo, f.hi + 0.2 * (f.hi - f.lo))?;
    let mut time = Plot::new("time-base", rect, x, headroom, ctx.tolerance, ctx.font)?
        .with_caption(&format!(
            "(b) Acceleration on a time base, {} rpm",
            short(ctx.rpm())
        ));
    let exact_t = against_time(m, omega, exact(w2));
    time.curve(
        "curve-acceleration-time",
        &[(&exact_t, 0.0..=360.0)],
        Dash::Solid,
        Some("piston"),
    )?;
    let shm_t = against_time(m, omega, |p: &Pose| {
        (r * w2 * p.angle().cos(), -r * w2 * p.angle().sin())
    });
    time.curve(
        "curve-acceleration-time-shm",
        &[(&shm_t, 0.0..=360.0)],
        Dash::Dotted,
        Some("simple harmonic motion, *r*ω² cos θ"),
    )?;
    Ok(time)
}

/// (c) The polar diagram in the mechanism's world coordinates, `tall`
/// page units high: CG′ = CG on the crank over a turn, simple harmonic
/// motion's circle, and the construction at the drawn pose.
/// Also the words saying which of G and G′ are lettered with a pin
/// ([`polar_construction`]).
fn polar_diagram(ctx: &Ctx, layout: &Layout, tall: f64) -> Result<(Plot, Option<String>)> {
    let m = ctx.mechanism;
    let r = m.crank();
    let polar = |deg: f64| {
        let pose = m.pose(Angle::from_degrees(deg).ok()?);
        let (s, c) = (pose.angle().sin(), pose.angle().cos());
        let g = -pose.position_acceleration();
        let dg = -pose.position_jerk();
        Some((
            Point::new(g * c, g * s),
            Vector::new(dg * c - g * s, dg * s + g * c) * PER_DEGREE,
        ))
    };
    let shm_polar = |deg: f64| {
        let a = Angle::from_degrees(deg).ok()?;
        let (s, c) = (a.sin(), a.cos());
        Some((
            Point::new(r * c * c, r * c * s),
            Vector::new(-2.0 * r * c * s, r * (c * c - s * s)) * PER_DEGREE,
        ))
    };
    let (gmin, gmax) = extent(&m, |p| -p.position_acceleration());
    let reach = gmax.max(-gmin).max(r);
    let world = Frame::new(
        Point::new(-1.08 * r, -1.08 * reach),
        Point::new(1.08 * reach, 1.08 * reach),
    );
    let rect = crate::geom::Frame::from_origin_size(16.0, layout.c_top, layout.half, tall);
    let mut plot = Plot::world("polar", rect, &world, false, ctx.tolerance, ctx.font)?
        .with_caption("(c) Polar diagram, *CG*′ = *CG* = *f*/ω² on the crank; SHM dotted");
    let scale = (rect.width() / world.width()).min(rect.height() / world.height());
    let with_c = polar_construction(&mut plot, &ctx.pose(), reach, scale);
    plot.curve(
        "curve-polar-acceleration",
        &[(&polar, 0.0..=360.0)],
        Dash::Solid,
        None,
    )?;
    plot.curve(
        "curve-polar-acceleration-shm",
        &[(&shm_polar, 0.0..=180.0)],
        Dash::Dotted,
        None,
    )?;
    Ok((plot, with_c))
}

/// The notes: the engine and its speed, the acceleration scale, CG and f
/// at the drawn pose (saying which of G and G′ lie `within` a pin), and f
/// at the dead centres.
fn notes(ctx: &Ctx, within: Option<String>) -> [String; 6] {
    let m = ctx.mechanism;
    let (r, omega) = (m.crank(), ctx.omega);
    let w2 = omega * omega;
    let unit = ctx.unit();
    let pose = ctx.pose();
    let cg = -pose.position_acceleration();
    [
        format!(
            "Engine: *r* = {} {unit}, *l* = {} {unit} (*n* = {}), {} rpm,",
            short(r),
            short(m.rod()),
            short(m.ratio()),
            short(ctx.rpm())
        ),
        format!(
            "ω = {} rad/s, *r*ω² = {} {unit}/s².",
            sig(omega),
            sig(r * w2)
        ),
        format!(
            "Acceleration scale: 1 {unit} of *CG* represents ω² = {} {unit}/s².",
            sig(w2)
        ),
        format!(
            "At θ = {}°: *CG* = {} {unit}, so *f* = {} {unit}/s²{}.",
            short(pose.angle().degrees()),
            sig(cg),
            sig(w2 * cg),
            within.map_or(String::new(), |w| format!(" ({w} in (c))"))
        ),
        "Outer dead centre: *f* = *r*ω²(1 + 1/*n*);".to_string(),
        "inner dead centre: *f* = −*r*ω²(1 − 1/*n*) (in line).".to_string(),
    ]
}

/// Page distance from C or B under which G or G′ is lettered with that
/// pin, not drawn apart: the scene's distance within which points read
/// as one ([`COINCIDE`]); at r = 1, l = 2.96, e = −1.08, 269.36° CG =
/// 0.016 drew three letters about one ring, G and G′ not to be seen.
const WITHIN_C: f64 = COINCIDE;

/// The crank circle, the line of stroke, the crank at the drawn pose, G
/// on the line of stroke and G′ on the crank with the arc between them;
/// where one falls within [`WITHIN_C`] of C or B at `scale` page units to
/// the world's one, that pin lettered with it ("C, G, G′", "B, G′"), and
/// the words saying so returned.
fn polar_construction(plot: &mut Plot, pose: &Pose, reach: f64, scale: f64) -> Option<String> {
    let r = pose.mechanism().crank();
    let c = Point::origin();
    let b = pose.b();
    let cg = -pose.position_acceleration();
    let u = (b - c) / r;
    plot.push(
        Item::new(
            "circle-crank",
            Role::Auxiliary,
            Shape::Circle {
                centre: c,
                radius: r,
            },
        )
        .as_part(Part::CrankCircle),
    );
    plot.push(
        Item::new(
            "line-stroke",
            Role::Auxiliary,
            Shape::Polyline {
                points: vec![Point::new(-1.05 * r, 0.0), Point::new(1.3 * reach, 0.0)],
                closed: false,
            },
        )
        .as_part(Part::CentreLine),
    );
    plot.push(Item::new(
        "link-crank",
        Role::Link,
        Shape::Polyline {
            points: vec![c, b],
            closed: false,
        },
    ));
    plot.push(Item::new("pin-C", Role::Link, Shape::Pin { centre: c }));
    plot.push(Item::new("pin-B", Role::Link, Shape::Pin { centre: b }));
    let g = Point::new(cg, 0.0);
    let g1 = c + u * cg;
    // G and G′ each lettered with the first pin, C then B, they run into
    // on the page (at θ = 0 on long rods G′ is at B, CG ≈ r(1 + 1/n)).
    let pins = [("C", c), ("B", b)];
    let host = |p: Point| {
        pins.iter()
            .position(|(_, q)| (p - *q).norm() * scale < WITHIN_C)
    };
    let (g_host, g1_host) = (host(g), host(g1));
    let mut joined: [Vec<&str>; 2] = [vec![], vec![]];
    for (name, at) in [("*G*", g_host), ("*G*′", g1_host)] {
        if let Some(with) = at.and_then(|k| joined.get_mut(k)) {
            with.push(name);
        }
    }
    let mut labels: Vec<(&str, String, Point)> = (pins.iter().zip(&joined))
        .map(|((id, p), with)| {
            let names: Vec<String> = std::iter::once(format!("*{id}*"))
                .chain(with.iter().map(|n| n.to_string()))
                .collect();
            (*id, names.join(", "), *p)
        })
        .collect();
    if g_host.is_none() || g1_host.is_none() {
        let start = if cg > 0.0 { 0.0 } else { std::f64::consts::PI };
        let end = (g1.y).atan2(g1.x);
        plot.push(Item::new(
            "arc-G-G1",
            Role::Auxiliary,
            super::short_arc(c, cg.abs(), start, end),
        ));
    }
    if g_host.is_none() {
        plot.push(Item::new(
            "point-G",
            Role::Construction,
            Shape::Dot { centre: g },
        ));
        labels.push(("G", "*G*".into(), g));
    }
    if g1_host.is_none() {
        plot.push(Item::new(
            "point-G1",
            Role::Construction,
            Shape::Marker {
                centre: g1,
                symbol: Symbol::Disc,
            },
        ));
        labels.push(("G1", "*G*′".into(), g1));
    }
    for (id, name, p) in labels {
        plot.push(Item::new(
            format!("label-{id}"),
            Role::Label,
            Shape::Label {
                anchor: p,
                text: RichText::parse(&name),
                size: crate::figure::TextSize::Letter,
                toward: None,
                line: None,
            },
        ));
    }
    let within = |(id, with): (&(&str, Point), &Vec<&str>)| {
        (!with.is_empty()).then(|| format!("{} within *{}*’s pin", with.join(" and "), id.0))
    };
    let said: Vec<String> = pins.iter().zip(&joined).filter_map(within).collect();
    (!said.is_empty()).then(|| said.join(", "))
}
