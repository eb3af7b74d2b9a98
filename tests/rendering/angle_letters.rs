//! Each angle's letter of Ng's Fig. 1 (θ, φ, β) read back from its SVG:
//! its middle inside its own sector, the wedge between the two legs its
//! arc runs between (angle measured from the vertex), where the sector
//! is wide enough beyond its arc to hold it, else outside it with a
//! leader to its arc; and near its arc, or farther out with a leader to
//! it. Outside its sector a letter reads
//! as the neighbouring angle's; beyond a link from its arc, as the angle
//! on the link's far side.

use crate::common;
use crate::plate::{Panel, Plate, Pt, Rect};

use slider_crank::catalogue::FigureOptions;
use slider_crank::render::to_svg;
use slider_crank::{Angle, FigureName, SliderCrank};
use std::f64::consts::FRAC_PI_2;

/// How far (degrees) a letter's middle may stand outside its sector: the
/// rounding of the SVG's numbers and of the flattened arc.
const SLACK_DEG: f64 = 1.0;

/// How far (page units) a letter's glyphs may stand from their arc
/// without a leader: two and a half ems of the angle's letter.
const NEAR_ARC: f64 = 40.0;

/// How much wider (page units) than a letter's glyphs its sector's chord
/// a letter's height beyond the arc is for the letter to be held
/// inside it: room for the two
/// legs (links 2.6 wide) and a clearance each side. A narrower sector
/// has its letter beside it.
const WIDE: f64 = 10.0;

/// Ng's Fig. 1 for the engine r, l, e at `deg`.
fn svg((r, l, e, deg): (f64, f64, f64, f64)) -> String {
    let mut options = FigureOptions::default();
    options.mechanism = Some(SliderCrank::new(r, l, e).unwrap());
    options.angle = Some(Angle::deg(deg));
    to_svg(&FigureName::NgFig1Torque.figure(&options).unwrap())
}

/// The centre of the circle through three points.
fn circumcentre(a: Pt, b: Pt, c: Pt) -> Option<Pt> {
    let d = 2.0 * (a.0 * (b.1 - c.1) + b.0 * (c.1 - a.1) + c.0 * (a.1 - b.1));
    if d.abs() < 1e-9 {
        return None;
    }
    let sq = |p: Pt| p.0 * p.0 + p.1 * p.1;
    Some((
        (sq(a) * (b.1 - c.1) + sq(b) * (c.1 - a.1) + sq(c) * (a.1 - b.1)) / d,
        (sq(a) * (c.0 - b.0) + sq(b) * (a.0 - c.0) + sq(c) * (b.0 - a.0)) / d,
    ))
}

/// An angle's arc as drawn: its vertex, radius, the page direction of
/// its start (radians, y down) and its signed sweep, and its points.
struct Arc {
    vertex: Pt,
    radius: f64,
    start: f64,
    sweep: f64,
    points: Vec<Pt>,
}

/// The arc of the stroke `id` in `panel`, its points in drawing order;
/// `None` where less than three of its points are drawn.
fn arc(panel: &Panel, id: &str) -> Option<Arc> {
    let stroke = panel.strokes.iter().find(|s| s.id == id)?;
    let mut points: Vec<Pt> = Vec::new();
    for s in &stroke.segs {
        for p in [s.0, s.1] {
            if points
                .last()
                .is_none_or(|q| (q.0 - p.0).hypot(q.1 - p.1) > 1e-6)
            {
                points.push(p);
            }
        }
    }
    if points.len() < 3 {
        return None;
    }
    let (a, b, c) = (
        points[0],
        points[points.len() / 2],
        points[points.len() - 1],
    );
    let vertex = circumcentre(a, b, c)?;
    let bearing = |p: Pt| (p.1 - vertex.1).atan2(p.0 - vertex.0);
    let start = bearing(a);
    // The sweep unwrapped along the arc's points.
    let mut sweep = 0.0;
    for w in points.windows(2) {
        let mut d = bearing(w[1]) - bearing(w[0]);
        while d > std::f64::consts::PI {
            d -= std::f64::consts::TAU;
        }
        while d < -std::f64::consts::PI {
            d += std::f64::consts::TAU;
        }
        sweep += d;
    }
    let radius = (a.0 - vertex.0).hypot(a.1 - vertex.1);
    Some(Arc {
        vertex,
        radius,
        start,
        sweep,
        points,
    })
}

/// How far (degrees) the direction of `p` from the arc's vertex lies
/// outside its sector; 0 inside.
fn outside(arc: &Arc, p: Pt) -> f64 {
    let t = (p.1 - arc.vertex.1).atan2(p.0 - arc.vertex.0);
    let along = ((t - arc.start) * arc.sweep.signum()).rem_euclid(std::f64::consts::TAU);
    let size = arc.sweep.abs();
    if along <= size {
        return 0.0;
    }
    (along - size)
        .min(std::f64::consts::TAU - along)
        .to_degrees()
}

/// How much (radians) of `arc`'s sector the smaller angles at its
/// vertex inside it take (Ng's φ inside β at an offset engine's crank
/// pin, both measured from the rod): their sectors are theirs, and the
/// rest is what holds the letter.
fn nested(panel: &Panel, arc: &Arc) -> f64 {
    (panel.strokes.iter())
        .filter(|s| s.id.contains("angle-"))
        .filter_map(|s| self::arc(panel, &s.id))
        .filter(|o| {
            let at = (o.vertex.0 - arc.vertex.0).hypot(o.vertex.1 - arc.vertex.1) < 1.0;
            let t = o.start + 0.5 * o.sweep;
            let middle = (arc.vertex.0 + t.cos(), arc.vertex.1 + t.sin());
            at && o.sweep.abs() < arc.sweep.abs() && outside(arc, middle) == 0.0
        })
        .map(|o| o.sweep.abs())
        .sum()
}

/// The least distance from the box `r` to the arc's points.
fn from_arc(arc: &Arc, r: &Rect) -> f64 {
    (arc.points.iter())
        .map(|p| r.distance_to(*p))
        .fold(f64::INFINITY, f64::min)
}

/// What is wrong with the angle letters of the figure `text`, one line
/// each.
fn faults(text: &str) -> Vec<String> {
    let plate = Plate::read(text);
    let mut out = Vec::new();
    for panel in &plate.panels {
        for label in &panel.labels {
            let Some(name) = ["theta", "phi", "beta"].into_iter().find(|n| {
                label.id.ends_with(&format!("label-{n}"))
                    || label.id.ends_with(&format!("angle-{n}"))
            }) else {
                continue;
            };
            let arc_id = format!("{}angle-{name}", panel.prefix);
            let Some(arc) = arc(panel, &arc_id) else {
                continue;
            };
            let r = &label.rect;
            let centre = ((r.x0 + r.x1) / 2.0, (r.y0 + r.y1) / 2.0);
            let led = common::tag(text, &label.id.replacen("label-", "leader-", 1)).is_some();
            let off = outside(&arc, centre);
            let beyond = arc.radius + (r.y1 - r.y0);
            let free = arc.sweep.abs() - nested(panel, &arc);
            let chord = 2.0 * beyond * (0.5 * free).clamp(0.0, FRAC_PI_2).sin();
            let wide = chord >= r.x1 - r.x0 + WIDE;
            if wide && off > SLACK_DEG && !led {
                out.push(format!(
                    "{}: {name} {off:.1}° outside its sector (arc of {:.1}° at {:.1}, {:.1}, radius {:.1})",
                    panel.id,
                    arc.sweep.to_degrees(),
                    arc.vertex.0,
                    arc.vertex.1,
                    arc.radius
                ));
            }
            let far = from_arc(&arc, r);
            if far > NEAR_ARC && !led {
                out.push(format!(
                    "{}: {name} {far:.1} from its arc with no leader",
                    panel.id
                ));
            }
        }
    }
    out
}

/// The engines a review found an angle's letter outside its sector at,
/// and a sweep of poses of those and of Ng's rig and an offset engine.
fn cases() -> Vec<(f64, f64, f64, f64)> {
    let mut cases = vec![
        (1.0, 1.08, 0.0, 89.87),
        (1.0, 1.08, 0.0, 269.98),
        (1.0, 3.7, -1.46, 180.0),
        (25.0, 72.0, 0.0, 30.0),
    ];
    for (r, l, e) in [
        (1.0, 1.08, 0.0),
        (1.0, 3.7, -1.46),
        (1.0, 1.37, -0.233),
        (25.0, 72.0, 0.0),
        (1.0, 1.55, 0.402),
    ] {
        cases.extend((0..12).map(|k| (r, l, e, 15.0 + 30.0 * f64::from(k))));
    }
    cases
}

/// θ, φ and β each lettered inside its own sector near its arc.
#[test]
fn an_angles_letter_stands_in_its_own_sector() {
    let cases = cases();
    let found = common::in_threads(&cases, |&case| {
        faults(&svg(case))
            .into_iter()
            .map(|f| format!("{case:?} {f}"))
            .collect::<Vec<_>>()
    });
    let all: Vec<String> = found.into_iter().flatten().collect();
    assert!(all.is_empty(), "{}", all.join("\n"));
}
