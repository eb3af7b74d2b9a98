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
use crate::figure::{Dash, Figure, Item, NOTE_LINE, Part, Role, Shape, Symbol};
use crate::geom::{Frame, Point, Vector};
use crate::{angle::Angle, mechanism::Pose};

/// The narrowest page (page units) that sets (a) and (b) side by side:
/// each column then holds the ordinate's title, about 260 units at the
/// small size, and the abscissa's.
const NARROWEST_COLUMNS: f64 = 700.0;

pub(in crate::catalogue) fn build(ctx: &Ctx) -> Result<Figure> {
    let page = ctx.page();
    let m = ctx.mechanism;
    let (r, omega) = (m.crank(), ctx.omega);
    let w2 = omega * omega;
    let unit = ctx.unit();
    let mut sheet = Sheet::new(ctx);
    sheet.mechanism(ctx, true, true);
    let (lo, hi) = extent(&m, |p| -w2 * p.position_acceleration());
    let f_axis = |title: &str| Axis::nice(title, lo.min(-r * w2), hi.max(r * w2));
    let f_title = format!("*f* = −d²*x*/d*t*² ({unit}/s²), towards the crank");
    // Two columns where a column holds the axes' titles; on a narrower
    // page the three panels are stacked at the page's width and the notes
    // go below them.
    let columns = page.width() >= NARROWEST_COLUMNS;
    let half = match columns {
        true => 0.5 * (page.width() - 32.0 - 16.0),
        false => page.width() - 32.0,
    };
    let row = 350.0;
    // Where (b) and (c) go: beside (a) and below both, or each below.
    let (b_at, c_top) = match columns {
        true => (Point::new(16.0 + half + 16.0, 16.0), 16.0 + row + 12.0),
        false => (
            Point::new(16.0, 16.0 + row + 12.0),
            16.0 + 2.0 * (row + 12.0),
        ),
    };
    let exact = |p: &Pose| (-w2 * p.position_acceleration(), -w2 * p.position_jerk());
    let (o, i) = dead_centres(&m);

    // (a) Distance base.
    let far = ((m.rod() + r - m.offset()) * (m.rod() + r + m.offset())).sqrt();
    let near = ((m.rod() - r - m.offset()) * (m.rod() - r + m.offset())).sqrt();
    let rect = super::PageRect::new(16.0, 16.0, half, row);
    let x = Axis::nice(
        &format!("displacement of *A* from the outer dead centre ({unit})"),
        0.0,
        (far - near).max(2.0 * r),
    )?;
    let mut distance = Plot::new(
        "distance-base",
        rect,
        x,
        f_axis(&f_title)?,
        ctx.tolerance,
        ctx.font,
    )?
    .with_caption("(a) Acceleration on a distance base");
    let outward = against_travel(m, exact);
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
        Dash::Dashed,
        Some("simple harmonic motion"),
    )?;
    sheet.plot(distance);

    // (b) Time base.
    let period = std::f64::consts::TAU / omega;
    let rect = super::PageRect::new(b_at.x, b_at.y, half, row);
    let x = Axis::linear("time *t* (s);  θ = ω*t*", 0.0, period)?;
    // Headroom above the curves for the legend.
    let headroom = Axis::nice(
        &f_title,
        lo.min(-r * w2),
        hi.max(r * w2) + 0.2 * (hi.max(r * w2) - lo.min(-r * w2)),
    )?;
    let mut time = Plot::new("time-base", rect, x, headroom, ctx.tolerance, ctx.font)?
        .with_caption(&format!(
            "(b) Acceleration on a time base, {} rpm",
            short(ctx.rpm())
        ));
    let exact_t = against_time(m, omega, exact);
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
        Dash::Dashed,
        Some("simple harmonic motion, *r*ω² cos θ"),
    )?;
    sheet.plot(time);

    // (c) Polar diagram, in the mechanism's world coordinates.
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
    let top = c_top;
    // As tall as beside the notes on the figure's own page.
    let tall = page.height() - (16.0 + row + 12.0) - 16.0;
    let rect = super::PageRect::new(16.0, top, half, tall);
    let mut plot = Plot::world("polar", rect, &world, false, ctx.tolerance, ctx.font)?
        .with_caption("(c) Polar diagram, *CG*′ = *CG* = *f*/ω² on the crank; SHM dashed");
    polar_construction(&mut plot, &ctx.pose(), reach);
    plot.curve(
        "curve-polar-acceleration",
        &[(&polar, 0.0..=360.0)],
        Dash::Solid,
        None,
    )?;
    plot.curve(
        "curve-polar-acceleration-shm",
        &[(&shm_polar, 0.0..=180.0)],
        Dash::Dashed,
        None,
    )?;
    sheet.plot(plot);

    let pose = ctx.pose();
    let cg = -pose.position_acceleration();
    let corner = match columns {
        true => Point::new(16.0 + half + 28.0, top + 30.0),
        false => {
            let below = top + tall + 12.0;
            sheet.height(below + 6.0 * NOTE_LINE + 16.0);
            Point::new(28.0, below)
        }
    };
    sheet.notes(
        corner,
        &[
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
                "At θ = {}°: *CG* = {} {unit}, so *f* = {} {unit}/s².",
                short(pose.angle().degrees()),
                sig(cg),
                sig(w2 * cg)
            ),
            "Outer dead centre: *f* = *r*ω²(1 + 1/*n*);".to_string(),
            "inner dead centre: *f* = −*r*ω²(1 − 1/*n*) (in line).".to_string(),
        ],
    );
    Ok(sheet.finish())
}

/// The crank circle, the line of stroke, the crank at the drawn pose, G
/// on the line of stroke and G′ on the crank with the arc between them.
fn polar_construction(plot: &mut Plot, pose: &Pose, reach: f64) {
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
    let mut labels = vec![("C", "C", c), ("B", "B", b)];
    if cg.abs() > 1e-6 * r {
        let start = if cg > 0.0 { 0.0 } else { std::f64::consts::PI };
        let end = (g1.y).atan2(g1.x);
        plot.push(Item::new(
            "arc-G-G1",
            Role::Auxiliary,
            super::short_arc(c, cg.abs(), start, end),
        ));
        plot.push(Item::new(
            "point-G",
            Role::Construction,
            Shape::Dot { centre: g },
        ));
        plot.push(Item::new(
            "point-G1",
            Role::Construction,
            Shape::Marker {
                centre: g1,
                symbol: Symbol::Disc,
            },
        ));
        labels.push(("G", "G", g));
        labels.push(("G1", "G′", g1));
    }
    for (id, name, p) in labels {
        plot.push(super::letter(id, p, name));
    }
}
