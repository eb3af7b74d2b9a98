//! The force and couple polygons of an in-line engine (`docs/dynamics.md`
//! §6): (a) the primary forces, a side m r ω² along each cylinder's crank
//! at δ_i; (b) the primary couples about the reference plane, each side
//! times the cylinder's distance a_i from it (reversed for a negative
//! a_i); (c) and (d) the secondary forces and couples, sides 1/n at 2δ_i.
//! The crank angle is δ here, not the α of `InlineEngine`: set in
//! italics, α reads as the pitch's a.
//! Each polygon is drawn head to tail from the origin at θ = 0; where it
//! does not close, its closing side from the origin to the last side's
//! end is the resultant R, lettered with its size, the largest unbalanced
//! force or couple over a turn. Every side and resultant is [`InlineEngine`]'s.
//!
//! The engine is the textbooks' three cylinders with cranks at 120°, a
//! pitch of 1 and the reference plane through the middle cylinder
//! (the balance table of cranks 0°, 120°, 240°): the forces balance, the couples
//! do not. Its ratio n is the figure's mechanism's, and so is its
//! offset: every side of a polygon of harmonic k is the in-line one's
//! times |c_k| and turned by arg c_k (`offset_harmonic`), and the notes
//! say by how much.

use super::cranks::{arrow, line};
use super::{Ctx, Sheet, short, sig};
use crate::diagram::Plot;
use crate::dynamics::{InlineEngine, Polygon, default_planes, offset_harmonic};
use crate::error::Result;
use crate::figure::{Dash, Figure, Item, RichText, Role, Shape, Symbol, TextSize};
use crate::geom::{Frame, Point};

/// The cranks of the engine drawn, degrees ahead of the first's.
pub(crate) const CRANKS: [f64; 3] = [0.0, 120.0, 240.0];

/// A side or resultant shorter than this fraction of the panel's longest
/// side is not drawn (a cylinder in the reference plane, a closed
/// polygon's rounding).
const SHORTEST: f64 = 1e-9;

/// Height of the notes' band.
const NOTES: f64 = 88.0;

/// A caption's second line, page units.
const CAPTION_LINE: f64 = 16.0;

pub(in crate::catalogue) fn build(ctx: &Ctx) -> Result<Figure> {
    let page = ctx.page();
    let cranks = ctx.options.cranks.clone().unwrap_or(CRANKS.to_vec());
    let planes = (ctx.options.planes.clone()).unwrap_or_else(|| default_planes(cranks.len()));
    let engine = InlineEngine::new(&cranks, &planes, ctx.mechanism.ratio())?;
    let mut sheet = Sheet::new(ctx);
    sheet.mechanism(ctx, false, false);
    let half = 0.5 * (page.width() - 48.0);
    // Each row as tall as its polygons need at the width's scale and a
    // caption of two lines, no taller than half the page: taller, the
    // flat polygons stood in bands of white above their captions.
    let most = (0.5 * (page.height() - 16.0 - 16.0 - 16.0 - NOTES)).max(120.0);
    let need = (Polygon::ALL.into_iter())
        .map(|part| {
            let w = drawn(ctx, &engine, part).world;
            half * (w.max().y - w.min().y) / (w.max().x - w.min().x)
        })
        .fold(0.0, f64::max);
    let tall = (need + crate::diagram::CAPTION + CAPTION_LINE).clamp(120.0, most);
    let mut meta = serde_json::Map::new();
    for (k, part) in Polygon::ALL.into_iter().enumerate() {
        let (row, col) = ((k / 2) as f64, (k % 2) as f64);
        let rect = Frame::from_origin_size(
            16.0 + col * (half + 16.0),
            16.0 + row * (tall + 16.0),
            half,
            tall,
        );
        sheet.plot(polygon_plot(ctx, &engine, part, rect)?);
        let r = engine.resultant(part);
        let (times, turn) = offset_factor(ctx, part).unwrap_or((1.0, 0.0));
        let (s, c) = turn.to_radians().sin_cos();
        let v = [
            times * (c * r.vector[0] - s * r.vector[1]),
            times * (s * r.vector[0] + c * r.vector[1]),
        ];
        meta.insert(
            id(part).into(),
            serde_json::json!({"resultant": v, "amplitude": times * r.amplitude, "balanced": r.balanced}),
        );
    }
    meta.insert("cranks_deg".into(), serde_json::json!(cranks));
    meta.insert("planes".into(), serde_json::json!(planes));
    sheet.meta("balance", serde_json::Value::Object(meta));
    let top = 16.0 + 2.0 * (tall + 16.0);
    sheet.height(top + NOTES + 16.0);
    sheet.notes(Point::new(20.0, top), &notes(ctx, &engine));
    Ok(sheet.finish())
}

/// The polygon's name in ids (`primary-force`).
fn id(part: Polygon) -> &'static str {
    match part {
        Polygon::PrimaryForce => "primary-force",
        Polygon::PrimaryCouple => "primary-couple",
        Polygon::SecondaryForce => "secondary-force",
        Polygon::SecondaryCouple => "secondary-couple",
    }
}

/// The caption of the polygon's panel: short, so that at a page's
/// usual width each is one line and the captions of a row stand level
/// (with its verdict after a semicolon, (b)'s and (d)'s broke in two and
/// stood higher than (a)'s and (c)'s).
fn caption(part: Polygon, closed: bool) -> String {
    let (letter, what) = match part {
        Polygon::PrimaryForce => ("(a)", "Primary forces, sides *m\u{a0}r*ω² at δ_{i}"),
        Polygon::PrimaryCouple => (
            "(b)",
            "Primary couples, sides *m\u{a0}r*ω² *a*_{i} at δ_{i}",
        ),
        Polygon::SecondaryForce => ("(c)", "Secondary forces, sides *m\u{a0}r*ω²/*n* at 2δ_{i}"),
        Polygon::SecondaryCouple => (
            "(d)",
            "Secondary couples, sides *m\u{a0}r*ω² *a*_{i}/*n* at 2δ_{i}",
        ),
    };
    let verdict = if closed {
        "closed, balanced"
    } else {
        "resultant *R* dashed"
    };
    format!("{letter} {what}: {verdict}")
}

/// A polygon as drawn: the corners of its sides (the offset's included)
/// from the origin, the last side's end, the longest side, the corners'
/// box and the world shown about it, and the offset's factor.
struct Drawn {
    corners: Vec<Point>,
    end: Point,
    unit: f64,
    lo: Point,
    hi: Point,
    world: Frame,
    times: f64,
}

/// The polygon `part` of `engine` as drawn ([`Drawn`]).
fn drawn(ctx: &Ctx, engine: &InlineEngine, part: Polygon) -> Drawn {
    // The offset engine's sides: the in-line ones times its factor,
    // turned by its angle ([`offset_factor`]).
    let (times, turn) = offset_factor(ctx, part).unwrap_or((1.0, 0.0));
    let (s, c) = turn.to_radians().sin_cos();
    let sides: Vec<[f64; 2]> = (engine.sides(part).iter())
        .map(|v| [times * (c * v[0] - s * v[1]), times * (s * v[0] + c * v[1])])
        .collect();
    let mut corners = vec![Point::origin()];
    let mut end = Point::origin();
    for s in &sides {
        end = Point::new(end.x + s[0], end.y + s[1]);
        corners.push(end);
    }
    let longest = sides.iter().map(|s| s[0].hypot(s[1])).fold(0.0, f64::max);
    let unit = if longest > 0.0 { longest } else { 1.0 };
    let (lo, hi) = corners
        .iter()
        .fold((Point::origin(), Point::origin()), |(lo, hi), p| {
            (
                Point::new(lo.x.min(p.x), lo.y.min(p.y)),
                Point::new(hi.x.max(p.x), hi.y.max(p.y)),
            )
        });
    // Room beside the polygon for the line of stroke's ends (0.2 of the
    // longest side beyond it); above and below, for a side's number.
    let (pad, rise) = (0.25 * unit, 0.1 * unit);
    let world = Frame::new(
        Point::new(lo.x - pad, lo.y - rise),
        Point::new(hi.x + pad, hi.y + rise),
    );
    Drawn {
        corners,
        end,
        unit,
        lo,
        hi,
        world,
        times,
    }
}

/// One polygon: its sides head to tail from the origin, each numbered by
/// its cylinder, and where it does not close the resultant from the
/// origin to the last side's end, dashed.
fn polygon_plot(ctx: &Ctx, engine: &InlineEngine, part: Polygon, rect: Frame) -> Result<Plot> {
    let Drawn {
        corners,
        end,
        unit,
        lo,
        hi,
        world,
        times,
    } = drawn(ctx, engine, part);
    let resultant = engine.resultant(part);
    let name = id(part);
    // A polygon flatter than its area stands at the area's foot, by its
    // caption, the room above it (centred, it stood 55 units above the
    // caption of (b) and (d)).
    let room = (rect.height() - crate::diagram::CAPTION) / rect.width();
    let (wide, high) = (world.max().x - world.min().x, world.max().y - world.min().y);
    let world = match wide * room > high {
        true => Frame::new(
            world.min(),
            Point::new(world.max().x, world.min().y + wide * room),
        ),
        false => world,
    };
    let mut plot = Plot::world(name, rect, &world, false, ctx.tolerance, ctx.font)?
        .with_caption(&caption(part, resultant.balanced));
    let least = SHORTEST * unit;
    for (i, (from, to)) in corners.iter().zip(corners.iter().skip(1)).enumerate() {
        for item in arrow(
            &format!("{name}-{}", i + 1),
            *from,
            *to,
            &format!("{}", i + 1),
            least,
        ) {
            plot.push(item);
        }
    }
    if !resultant.balanced && (end - Point::origin()).norm() > least {
        plot.push(
            Item::new(
                format!("resultant-{name}"),
                Role::Construction,
                Shape::Arrow {
                    from: Point::origin(),
                    to: end,
                },
            )
            .dashed(Dash::Dashed),
        );
        plot.push(Item::new(
            format!("value-resultant-{name}"),
            Role::Label,
            Shape::Label {
                anchor: Point::origin() + (end - Point::origin()) * 0.5,
                text: RichText::parse(&format!("*R* = {}", sig(times * resultant.amplitude))),
                size: TextSize::Small,
                toward: None,
                line: Some([Point::origin(), end]),
            },
        ));
    }
    plot.push(
        line(
            &format!("axis-{name}"),
            Role::Auxiliary,
            Point::new(lo.x - 0.2 * unit, 0.0),
            Point::new(hi.x + 0.2 * unit, 0.0),
        )
        .dashed(Dash::DashDot),
    );
    plot.points(
        &format!("point-{name}-origin"),
        &[(0.0, 0.0)],
        Symbol::Disc,
        None,
    );
    Ok(plot)
}

/// "Three cylinders", "One cylinder": the count in words to twelve.
fn cylinders(count: usize) -> String {
    const WORDS: [&str; 12] = [
        "One", "Two", "Three", "Four", "Five", "Six", "Seven", "Eight", "Nine", "Ten", "Eleven",
        "Twelve",
    ];
    match (count, WORDS.get(count.wrapping_sub(1))) {
        (1, Some(word)) => format!("{word} cylinder"),
        (_, Some(word)) => format!("{word} cylinders"),
        _ => format!("{count} cylinders"),
    }
}

/// Which cylinders lie in the reference plane (a couple's side of
/// length 0, not drawn), as the notes say it; empty for none.
fn in_plane(engine: &InlineEngine) -> String {
    let on: Vec<String> = (engine.planes().iter().enumerate())
        .filter(|(_, a)| **a == 0.0)
        .map(|(i, _)| format!("{}", i + 1))
        .collect();
    match on.as_slice() {
        [] => String::new(),
        [one] => {
            format!("; cylinder {one}, in the plane, has no couple and no side in (b) and (d)")
        }
        _ => format!(
            "; cylinders {}, in the plane, have no couple and no side in (b) and (d)",
            on.join(", ")
        ),
    }
}

/// How an offset changes the polygon `part`'s sides from the in-line
/// engine's: (times as long, turned by degrees), from the harmonic of its
/// order of the offset cylinder's exact force ([`offset_harmonic`]);
/// `None` in line, or where the harmonic is not found (an engine at its
/// limit of assembly: the in-line sides are drawn and the notes say so).
fn offset_factor(ctx: &Ctx, part: Polygon) -> Option<(f64, f64)> {
    let m = ctx.mechanism;
    if m.offset() == 0.0 {
        return None;
    }
    let (k, drawn) = match part {
        Polygon::PrimaryForce | Polygon::PrimaryCouple => (1, 1.0),
        Polygon::SecondaryForce | Polygon::SecondaryCouple => (2, 1.0 / m.ratio()),
    };
    offset_harmonic(&m, k).map(|c| {
        // A turn within the sum's rounding is none.
        let turn = c[1].atan2(c[0]).to_degrees();
        (
            c[0].hypot(c[1]) / drawn,
            if turn.abs() < 1e-9 { 0.0 } else { turn },
        )
    })
}

/// What the notes say of an offset: nothing for e = 0; else that the
/// polygons are drawn for it, each side the in-line one's times one
/// factor and turned by one angle, which and why which of them close
/// holds still ([`offset_factor`]).
fn offset_note(ctx: &Ctx) -> Option<String> {
    let m = ctx.mechanism;
    if m.offset() == 0.0 {
        return None;
    }
    let head = format!(
        "The offset *e* = {} {} (*e*/*l* = {}), the same in every cylinder, multiplies every side of a polygon by one factor and turns it by one angle, so which polygons close is unchanged",
        short(m.offset()),
        ctx.unit(),
        sig(m.offset() / m.rod()),
    );
    Some(
        match (
            offset_factor(ctx, Polygon::PrimaryForce),
            offset_factor(ctx, Polygon::SecondaryForce),
        ) {
            (Some((a1, p1)), Some((a2, p2))) => format!(
                "{head}: the polygons are drawn for it, the primary sides and resultants {} times as long as in line, turned {}°, the secondary {} times, turned {}° (the first and second harmonics of the offset cylinder’s exact force).",
                sig(a1),
                sig(p1),
                sig(a2),
                sig(p2),
            ),
            _ => format!(
                "{head}; its harmonics are not found here (an engine at its limit of assembly): the polygons are drawn for the engine in line, each cylinder’s force cos θ + cos 2θ/*n*."
            ),
        },
    )
}

/// The notes: the engine, the scales, and each polygon's resultant; an
/// offset's ([`offset_note`]).
fn notes(ctx: &Ctx, engine: &InlineEngine) -> Vec<String> {
    // Each list unbroken, its unit with it: broken across lines, a line
    // began with a stray "1 pitches" (the list "−1, 0, / 1").
    let list = |v: &[f64]| {
        v.iter()
            .map(|x| short(*x))
            .collect::<Vec<_>>()
            .join(",\u{a0}")
    };
    let value = |part: Polygon| {
        let r = engine.resultant(part);
        let times = offset_factor(ctx, part).map_or(1.0, |f| f.0);
        if r.balanced {
            "0 (closed)".to_string()
        } else {
            sig(times * r.amplitude)
        }
    };
    vec![
        format!(
            "{} in line, their cranks at the angles δ_{{i}} = {}° ahead of the first, their planes at the distances *a*_{{i}} = {}\u{a0}pitches from the reference plane{}{}, *n* = {}; the polygons are drawn at θ = 0, the line of stroke dash-dotted, each to its own scale, sides in units of *m\u{a0}r*ω² (a couple’s times the pitch).",
            cylinders(engine.cranks_deg().len()),
            list(engine.cranks_deg()),
            list(engine.planes()),
            match (ctx.options.planes.is_none(), engine.cranks_deg().len() % 2) {
                (true, 1) => " (the middle cylinder’s)",
                (true, _) => " (midway along the engine)",
                _ => "",
            },
            in_plane(engine),
            short(engine.ratio()),
        ),
        format!(
            "Resultants *R* in units of *m\u{a0}r*ω² (a couple’s times the pitch): primary force {}, primary couple {}, secondary force {}, secondary couple {}: each the largest unbalanced value over a turn, reached when it lies on the line of stroke.",
            value(Polygon::PrimaryForce),
            value(Polygon::PrimaryCouple),
            value(Polygon::SecondaryForce),
            value(Polygon::SecondaryCouple),
        ),
    ]
    .into_iter()
    .chain(offset_note(ctx))
    .collect()
}
