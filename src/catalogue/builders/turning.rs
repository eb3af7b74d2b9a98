//! The turning-moment diagram: (a) the torque on the crank against θ with
//! its mean line and the areas between them, (b) the energy stored in the
//! flywheel, E(θ) = ∫ (T − T_mean) dθ, with its fluctuation ΔE.
//!
//! The engine is the catalogue's (§35's by default) with the example
//! reciprocating mass unless the mass is given, its gas force a constant
//! (the gas force given) or from an indicator diagram: the example's
//! (examples/indicator.csv, lbf/ft² on a 10 in bore, in feet and
//! pounds-force only) unless the data and the bore give the engine's own.
//! Tangents are central differences within each smooth piece (T has kinks
//! at the dead centres and the diagram's rows); the values are exact.

use super::{Ctx, Sheet, short, sig};
use crate::diagram::{Axis, Curve, Plot};
use crate::dynamics::quadrature::integrate;
use crate::dynamics::turning::total_torque;
use crate::dynamics::{
    EXAMPLE_BORE, EXAMPLE_INDICATOR, EXAMPLE_MASS, Engine, GasForce, IndicatorDiagram,
    TurningMoment, example_indicator,
};
use crate::error::{Error, Field, Input, Result, Wording};
use crate::figure::{Align, Dash, Figure, Item, RichText, Role, Shape, Symbol, TextSize};
use crate::geom::{Frame, Point, Vector};
use crate::units::Units;

/// Step of the tangents' differences, radians.
const STEP: f64 = 1e-6;

/// The figure's engine: the mechanism with the reciprocating mass
/// (the one asked for, the example's by default) and the gas force
/// [`gas`] gives.
pub(crate) fn engine(ctx: &Ctx) -> Result<Engine> {
    let o = ctx.options;
    let mass = o.mass.unwrap_or(EXAMPLE_MASS);
    let mut engine = Engine::new(ctx.mechanism, mass, ctx.omega)?.with_gas(gas(ctx)?)?;
    if let Some(g) = o.gravity {
        engine = engine.with_gravity(g.in_unit(ctx.unit())?)?;
    }
    match o.friction {
        Some(mu) => engine.with_friction(mu),
        None => Ok(engine),
    }
}

/// What the notes add for gravity and the guides' friction, given:
/// "; a vertical engine, the cylinder above the crank (g = 32.174
/// ft/s²); the guides' friction μ = 0.1"; empty without either.
pub(super) fn guides_note(ctx: &Ctx) -> String {
    let o = ctx.options;
    let mut note = String::new();
    if let Some(g) = o.gravity {
        let size = g.in_unit(ctx.unit()).map_or(0.0, |v| v[0].abs());
        note.push_str(&format!(
            "; a vertical engine, the cylinder {} the crank (*g* = {} {}/s²)",
            match g {
                crate::dynamics::Gravity::TowardsCrank => "above",
                crate::dynamics::Gravity::AwayFromCrank => "below",
            },
            sig(size),
            ctx.unit()
        ));
    }
    if let Some(mu) = o.friction.filter(|mu| *mu > 0.0) {
        note.push_str(&format!("; the guides’ friction μ = {}", short(mu)));
    }
    note
}

/// The gas force on the piston: the constant asked for, else the
/// indicator diagram of the data on the bore asked for, else the example's
/// ([`example_indicator`]). The example's diagram and bore are in feet
/// and pounds-force: in other units the figure is given the engine's own
/// diagram and bore (a diagram's declared unit checked against the
/// figure's, [`IndicatorDiagram::check_units`]), or a constant force.
fn gas(ctx: &Ctx) -> Result<GasForce> {
    let o = ctx.options;
    let refuse = |why: Wording| {
        Err(Error::refused(
            Input::Options,
            Wording::from(format!("{}: ", ctx.name.name())).and(why),
        ))
    };
    if let Some(f) = o.gas_force {
        if o.data.is_some() || o.bore.is_some() {
            return refuse(
                Wording::from("give the gas force as a constant (")
                    .option(Field::GasForce)
                    .then(") or by an indicator diagram (")
                    .option(Field::Data)
                    .then(", ")
                    .option(Field::Bore)
                    .then("), not both"),
            );
        }
        return Ok(GasForce::Constant(f));
    }
    let own = || {
        Wording::default()
            .set(Field::Data, "CSV")
            .then(" with ")
            .set(Field::Bore, "D")
            .then(", or ")
            .set(Field::GasForce, "F")
    };
    let example = || example_indicator(&ctx.units, own());
    let diagram = match (o.data.as_deref(), o.bore) {
        (None, None) => example()?,
        (Some(text), bore) => {
            let bore = match bore {
                Some(b) => b,
                None if ctx.units == Units::FOOT_POUND => EXAMPLE_BORE,
                None => {
                    return refuse(
                        Wording::from("give the bore of the indicator diagram's cylinder with ")
                            .set(Field::Bore, "D")
                            .then(format!(", in {}", ctx.units.length())),
                    );
                }
            };
            // The diagram is the figure's data file.
            let d =
                IndicatorDiagram::from_csv(text, bore, "data").map_err(|e| e.about(Input::Data))?;
            d.check_units(&ctx.units, "data")
                .map_err(|e| e.about(Input::Data))?;
            d
        }
        (None, Some(bore)) => {
            // The example's diagram on another bore, in its own units.
            example()?;
            IndicatorDiagram::from_csv(EXAMPLE_INDICATOR, bore, "examples/indicator.csv")?
        }
    };
    Ok(GasForce::Indicator(diagram))
}

pub(in crate::catalogue) fn build(ctx: &Ctx) -> Result<Figure> {
    let page = ctx.page();
    let engine = engine(ctx)?;
    let tm = TurningMoment::new(&engine, &[0.0])?;
    let mut sheet = Sheet::new(ctx);
    sheet.mechanism(ctx, true, false);
    sheet.meta("mean_torque", serde_json::json!(tm.mean));
    sheet.meta("fluctuation", serde_json::json!(tm.fluctuation));
    let height = 0.5 * (page.height() - 32.0 - 24.0 - 72.0);
    sheet.plot(torque_plot(ctx, &engine, &tm, height)?);
    sheet.plot(energy_plot(ctx, &engine, &tm, height)?);
    sheet.notes(Point::new(20.0, page.height() - 56.0), &notes(ctx, &tm));
    Ok(sheet.finish())
}

/// The torque on the crank of `engine` (one cylinder) at `deg` degrees.
fn torque(engine: &Engine, deg: f64) -> f64 {
    total_torque(engine, &[0.0], deg.to_radians())
}

/// The crank angle's axis over a turn.
fn theta() -> Result<Axis> {
    Axis::linear("crank angle θ (°)", 0.0, 360.0)?.with_step(30.0)
}

/// The least room between the torque's extremes and the ends of its
/// axis, a share of its range: 3 %, some 4 units on a plot 150 high.
const AXIS_MARGIN: f64 = 0.03;

/// (a) T against θ, `height` page units high, in smooth pieces between
/// its kinks, with the mean line and the areas between them.
fn torque_plot(ctx: &Ctx, engine: &Engine, tm: &TurningMoment, height: f64) -> Result<Plot> {
    let t_unit = ctx.units.torque();
    let torque = |deg: f64| torque(engine, deg);
    let (lo, hi) = (0..=720)
        .map(|k| torque(k as f64 * 0.5))
        .fold((tm.mean, tm.mean), |(a, b), t| (a.min(t), b.max(t)));
    // The axis a share of the range beyond the curve's extremes
    // ([`AXIS_MARGIN`]): at r = 1, l = 1.07 r the trough at 274° reached
    // −19 990 and the round axis ended at −20 000, the curve on the
    // frame as if cut off.
    let margin = AXIS_MARGIN * (hi - lo);
    let mut plot = Plot::new(
        "turning-moment",
        ctx.band(16.0, height),
        theta()?,
        Axis::nice(
            &format!("torque on the crank *T* ({t_unit})"),
            lo - margin,
            hi + margin,
        )?,
        ctx.tolerance,
        ctx.font,
    )?
    .with_caption(
        "(a) Turning-moment diagram, *T* = *F*·*OM*, the mean line and the areas between them",
    );
    lobes(ctx, &mut plot, engine, tm);
    let kinks = &tm.kinks_deg;
    let pieces: Vec<(f64, f64)> = kinks
        .iter()
        .copied()
        .zip(kinks.iter().copied().skip(1))
        .collect();
    let curves: Vec<Box<dyn Curve>> = pieces.iter().map(|&(a, b)| piece(&torque, a, b)).collect();
    let traced: Vec<(&dyn Curve, _)> = curves
        .iter()
        .zip(&pieces)
        .map(|(c, &(a, b))| (c.as_ref(), a..=b))
        .collect();
    plot.curve("curve-torque", &traced, Dash::Solid, Some("*T*(θ)"))?;
    plot.line(
        "line-mean-torque",
        &[(0.0, tm.mean), (360.0, tm.mean)],
        Dash::Dashed,
        Some(&format!("mean torque {} {t_unit}", sig(tm.mean))),
    );
    Ok(plot)
}

/// The areas between T and its mean line, each lettered inside it
/// ([`area_letter`]), their values in the notes.
fn lobes(ctx: &Ctx, plot: &mut Plot, engine: &Engine, tm: &TurningMoment) {
    for (k, lobe) in tm.lobes.iter().enumerate() {
        let n = ((lobe.to_deg - lobe.from_deg) * 2.0).ceil().max(2.0) as usize;
        let mut points: Vec<Point> = (0..=n)
            .map(|i| {
                let d = lobe.from_deg + (lobe.to_deg - lobe.from_deg) * i as f64 / n as f64;
                Point::new(d, torque(engine, d))
            })
            .collect();
        let column = points.clone();
        points.push(Point::new(lobe.to_deg, tm.mean));
        points.push(Point::new(lobe.from_deg, tm.mean));
        plot.push(Item::new(
            format!("region-lobe-{}", k + 1),
            Role::Construction,
            Shape::Region { points },
        ));
        // Every area by its letter alone, the values in the notes: with
        // the value where it fitted, a large area went without and a
        // small one with ("a₂" beside "a₄ = +9517").
        let texts = [format!("*a*_{{{}}}", k + 1)];
        for item in area_letter(ctx, plot, &column, tm.mean, &texts, k + 1) {
            plot.push(item);
        }
    }
}

/// Room, page units, between an area's letter and the curve, the mean
/// line or the line T = 0 about it.
const AREA_ROOM: f64 = 2.0;

/// Room, page units, about an area's letter with its value ("a₄ =
/// −9702"): a third of its size. With [`AREA_ROOM`] the value was set in
/// the thin band between the mean line and T = 0, a unit and a half from
/// each (at 120 mm with an offset); where it has not this room the bare
/// letter is set in the area's wider part and the value is in the notes.
const VALUE_ROOM: f64 = 4.0;

/// Room, page units, about a bare letter set inside a thin area when it
/// has not [`AREA_ROOM`]: a sliver 12 units deep at an offset (a₂ at
/// r = 1, l = 2.09, e = 0.93) holds its letter this close to its lines
/// rather than outside it: half a unit clear of a line's stroke.
const SLIVER_ROOM: f64 = 1.0;

/// How far, page units, the letter of an area too thin to hold it stands
/// beyond the curve, a leader from it ending inside the area.
const LEADER_REACH: f64 = 7.0;

/// Where a text set at a fixed place has its place: the middle of its
/// letters, this many ems above its baseline ([`Shape::Text`]).
const MIDDLE: f64 = 0.35;

/// The letter `label-lobe-{k}` of the area between the mean line at
/// `mean` and the torque sampled at `column` (θ, T): the first of `texts`
/// whose box, with [`AREA_ROOM`] about it, fits wholly between the two
/// somewhere and off the line T = 0, set where it has the most room (a
/// text at a fixed place); else the last with [`SLIVER_ROOM`]. Where none
/// fits (a sliver), the last text beyond the curve by the area's tallest
/// point with a leader `leader-lobe-{k}` into the area: set beside the
/// area without one, a₁ and a₂ of an offset engine read as the letters
/// of the areas beyond the curve.
fn area_letter(
    ctx: &Ctx,
    plot: &Plot,
    column: &[Point],
    mean: f64,
    texts: &[String],
    k: usize,
) -> Vec<Item> {
    let map = plot.map();
    let size = ctx.style.font_size(TextSize::Small);
    let y_of = |t: f64| map.apply(Point::new(0.0, t)).y;
    // Each column's page x and the page interval between the mean line
    // and the curve, top to bottom.
    let page: Vec<(f64, f64, f64)> = column
        .iter()
        .map(|p| {
            let (a, b) = (map.apply(*p).y, y_of(mean));
            (map.apply(*p).x, a.min(b), a.max(b))
        })
        .collect();
    let zero = y_of(0.0);
    let id = format!("label-lobe-{k}");
    // Each text with room about it (a value more), then the last (the
    // bare letter) with less.
    let room_of = |t: &String| {
        if t.contains('=') {
            VALUE_ROOM
        } else {
            AREA_ROOM
        }
    };
    // Not the bare letter with no room (it stood on the curve's dip at
    // 25° at l = 1.05 r): with [`SLIVER_ROOM`] its ink stays off the
    // lines' strokes; where it has not that, it is set beyond the curve
    // with a leader.
    let bare = texts.last().into_iter().map(|t| (t, SLIVER_ROOM));
    let tries = texts.iter().map(|t| (t, room_of(t))).chain(bare);
    for (text, room) in tries {
        let rich = RichText::parse(text);
        let ink = rich.measure(ctx.font, size);
        // The ink above and below the place a text is set at (the middle
        // of its letters), a subscript's drop included.
        let (above, below) = (ink.above - MIDDLE * size, ink.below + MIDDLE * size);
        let half = (0.5 * ink.width + room, 0.5 * (above + below) + room);
        if let Some(centre) = roomiest(&page, half, zero) {
            let world = map.invert(centre - Vector::new(0.0, 0.5 * (below - above)));
            return vec![fixed_text(id, world, rich)];
        }
    }
    // The column the leader runs into: the tallest, weighed by its
    // distance from the area's ends (a tent, 1 at the middle), so that a
    // sliver tallest at θ = 0 has its leader off the axis there.
    let (first, last) = (
        column.first().map_or(0.0, |p| p.x),
        column.last().map_or(0.0, |p| p.x),
    );
    let weight = |p: &Point| {
        let span = (last - first).abs().max(f64::MIN_POSITIVE);
        (p.y - mean).abs() * (1.0 - (2.0 * p.x - first - last).abs() / span).max(0.0)
    };
    let tallest = (column.iter())
        .copied()
        .fold(Point::new(0.5 * (first + last), mean), |a, p| {
            if weight(&p) > weight(&a) { p } else { a }
        });
    let text = RichText::parse(texts.last().map_or("", String::as_str));
    let ink = text.measure(ctx.font, size);
    let (above, below) = (ink.above - MIDDLE * size, ink.below + MIDDLE * size);
    // The leader runs from the middle of that column out
    // across the curve to the letter's nearest corner, which stands
    // [`LEADER_REACH`] beyond the curve, towards the middle of the turn
    // (so not past the axis's ends).
    let inside = map.apply(Point::new(tallest.x, 0.5 * (tallest.y + mean)));
    let curve = map.apply(tallest);
    let out = if curve.y > inside.y { 1.0 } else { -1.0 };
    let across = if tallest.x > 180.0 { -1.0 } else { 1.0 };
    let corner = Point::new(curve.x + across * AREA_ROOM, curve.y + out * LEADER_REACH);
    let centre = corner + Vector::new(across * 0.5 * ink.width, out * 0.5 * (above + below));
    let at = map.invert(centre - Vector::new(0.0, 0.5 * (below - above)));
    let leader = Item::new(
        format!("leader-lobe-{k}"),
        // A thin full line, as a dimension's (Auxiliary is dashed).
        Role::Dimension,
        Shape::Polyline {
            points: vec![map.invert(inside), map.invert(corner)],
            closed: false,
        },
    );
    vec![fixed_text(id, at, text), leader]
}

/// A small text set at the world point `at`, its letters' middle there.
fn fixed_text(id: String, at: Point, text: RichText) -> Item {
    Item::new(
        id,
        Role::Label,
        Shape::Text {
            at,
            offset: Vector::zeros(),
            text,
            align: Align::Middle,
            size: TextSize::Small,
        },
    )
}

/// The page centre of a box of half sizes `half` inside the area whose
/// columns are `page` (x, top, bottom), off the line y = `zero`, with the
/// most room about it; `None` where no place holds it.
fn roomiest(page: &[(f64, f64, f64)], half: (f64, f64), zero: f64) -> Option<Point> {
    let (first, last) = (page.first()?.0, page.last()?.0);
    let mut best: Option<(f64, Point)> = None;
    for &(x, top, bottom) in page {
        if x - half.0 < first.min(last) || x + half.0 > first.max(last) {
            continue;
        }
        let under: Vec<(f64, f64)> = (page.iter())
            .filter(|(u, _, _)| (u - x).abs() <= half.0)
            .map(|(_, t, b)| (*t, *b))
            .collect();
        let mut y = top + half.1;
        while y <= bottom - half.1 {
            let room = (under.iter())
                .map(|(t, b)| (y - half.1 - t).min(b - y - half.1))
                .fold(f64::INFINITY, f64::min)
                .min((zero - y).abs() - half.1);
            if room >= 0.0 && best.is_none_or(|(r, _)| room > r) {
                best = Some((room, Point::new(x, y)));
            }
            y += 2.0;
        }
    }
    best.map(|(_, p)| p)
}

/// An area's value with its sign, + or −; 0 (an area within the
/// quadrature's tolerance, [`TurningMoment::settled`]) as 0.
fn signed(area: f64) -> String {
    if area == 0.0 {
        return "0".into();
    }
    let sign = if area > 0.0 { "+" } else { "−" };
    format!("{sign}{}", sig(area.abs()))
}

/// (b) The energy stored, E(θ), below (a), with its greatest and least
/// marked by the fluctuation ΔE.
fn energy_plot(ctx: &Ctx, engine: &Engine, tm: &TurningMoment, height: f64) -> Result<Plot> {
    let t_unit = ctx.units.torque();
    let values: Vec<f64> = tm.lobes.iter().map(|l| l.energy).chain([0.0]).collect();
    let (elo, ehi) = values
        .iter()
        .fold((0.0f64, 0.0f64), |(a, b), &e| (a.min(e), b.max(e)));
    // Room above the greatest and below the least, so that neither
    // mark nor the dimension's heads sit on the frame.
    let margin = 0.08 * (ehi - elo);
    let mut plot = Plot::new(
        "energy",
        ctx.band(16.0 + height + 24.0, height),
        theta()?,
        Axis::nice(
            &format!("energy stored *E* ({t_unit})"),
            elo - margin,
            ehi + margin,
        )?,
        ctx.tolerance,
        ctx.font,
    )?
    .with_caption("(b) Energy stored in the flywheel, *E*, the area under *T*\u{a0}−\u{a0}*T*_{mean} from θ\u{a0}=\u{a0}0, its greatest and least (○) and its fluctuation Δ*E*");
    let e_curve = |deg: f64| -> Option<(Point, Vector)> {
        let slope = torque(engine, deg) - tm.mean;
        Some((
            Point::new(deg, stored(engine, tm, deg)),
            Vector::new(1.0, slope * super::PER_DEGREE),
        ))
    };
    // No legend (the axis names the curve, the caption the marks): one
    // set beside the plot on a narrow page would narrow (b) out of line
    // with (a).
    plot.curve(
        "curve-energy",
        &[(&e_curve, 0.0..=360.0)],
        Dash::Solid,
        None,
    )?;
    let extremes = [(tm.max_energy_deg, ehi), (tm.min_energy_deg, elo)];
    plot.points("point-energy", &extremes, Symbol::Circle, None);
    // ΔE as a dimension at the angle of the most energy, from the least
    // (carried across by a dotted line) up to the curve.
    plot.line(
        "line-energy-least",
        &[(tm.min_energy_deg, elo), (tm.max_energy_deg, elo)],
        Dash::Dotted,
        None,
    );
    plot.push(Item::new(
        "dimension-fluctuation",
        Role::Dimension,
        Shape::Dimension {
            from: Point::new(tm.max_energy_deg, elo),
            to: Point::new(tm.max_energy_deg, ehi),
            side: Vector::new(1.0, 0.0),
            offset: 0.0,
            text: RichText::parse(""),
        },
    ));
    // Its value beside the dimension line, placed clear of it, by the
    // middle of its longer part off the line E = 0 (which the dimension
    // crosses), on the side of the wider half of the turn.
    let middle = if ehi >= -elo { 0.5 * ehi } else { 0.5 * elo };
    let away = if tm.max_energy_deg <= 180.0 {
        1.0
    } else {
        -1.0
    };
    let value = sig(tm.fluctuation);
    let text = RichText::parse(&format!("Δ*E* = {value} {t_unit}"));
    // On one line where it fits beside the dimension line, else its unit
    // under its value, else "ΔE =", the value and the unit on three
    // lines: at 120 mm and 4.5 in the value stood alone, "ΔE = 6281"
    // (the ninth review). Only where none of these fits beside the line
    // is the unit left to the axis, the value still beside the line (set
    // clear by the layout, it stood with the curve between it and its
    // line, the sixth review).
    //
    // Where neither one line nor two fit between the line's ends, one
    // line beside an end, just beyond its arrowhead, comes before three
    // (at l = 29.9 r on 4.5 in the curve's arch about the greatest energy
    // left room beside the line for "ΔE =", "6281", "lbf·ft" one under
    // the other, the equation split after "=": the tenth review).
    let one = vec![text.clone()];
    let two = vec![
        RichText::parse(&format!("Δ*E* = {value}")),
        RichText::parse(&t_unit),
    ];
    let tries = [
        (one.clone(), Along::Between),
        (two.clone(), Along::Between),
        (one, Along::Beyond),
        (two, Along::Beyond),
        (
            vec![
                RichText::parse("Δ*E* ="),
                RichText::parse(&value),
                RichText::parse(&t_unit),
            ],
            Along::Between,
        ),
        (
            vec![RichText::parse(&format!("Δ*E* = {value}"))],
            Along::Between,
        ),
    ];
    let energy = |deg: f64| stored(engine, tm, deg);
    let at = (tm.max_energy_deg, elo, ehi);
    let items = (tries.iter())
        .find_map(|(lines, along)| beside_dimension(ctx, &plot, &energy, (at, *along), away, lines))
        .unwrap_or_else(|| {
            vec![Item::new(
                "label-fluctuation",
                Role::Label,
                Shape::Label {
                    anchor: Point::new(tm.max_energy_deg, middle),
                    text: text.clone(),
                    size: TextSize::Small,
                    toward: Some(Vector::new(away, 0.0)),
                    line: None,
                },
            )]
        });
    for item in items {
        plot.push(item);
    }
    Ok(plot)
}

/// Room, page units, between ΔE's value and the dimension line, the
/// curve and the lines E = 0 and E = E_min about it.
const DIMENSION_ROOM: f64 = 4.0;

/// Between the lines of ΔE's value set in two, its middles' distance
/// over the text's size.
const LINE_SPACING: f64 = 1.25;

/// Where along the dimension line ΔE's value stands.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Along {
    /// Beside the line between its ends, nearest its middle.
    Between,
    /// Beside an end, beyond its arrowhead, at most a box's height out
    /// (read with the line still; a value farther out reads as naming
    /// the mark at E_max or E_min).
    Beyond,
}

/// ΔE's value `lines` (one, or two or three with its unit last) set beside its
/// dimension line at `at` = ((θ, E_min, E_max), `along`), on the side `away` (+1
/// right) first: at the height nearest the middle of the line (or, beyond
/// it, nearest an end) where the
/// lines' box, [`DIMENSION_ROOM`] from the line, has no part of the curve
/// `energy` between it and the line nor within the room about it, and
/// stands off E = 0, E_min and E_max, inside the plot. Where the label was only placed
/// clear, on a narrow page it stood on the far side of the curve from its
/// line (the curve between the two). The first line is
/// `label-fluctuation`, the last of two or three
/// `label-fluctuation-unit`, a middle one `label-fluctuation-value`, each
/// centred on the box. `None` where no place beside the line is clear.
fn beside_dimension(
    ctx: &Ctx,
    plot: &Plot,
    energy: &dyn Fn(f64) -> f64,
    ((deg, elo, ehi), along): ((f64, f64, f64), Along),
    away: f64,
    lines: &[RichText],
) -> Option<Vec<Item>> {
    let map = plot.map();
    let size = ctx.style.font_size(TextSize::Small);
    let inks: Vec<_> = lines.iter().map(|t| t.measure(ctx.font, size)).collect();
    let (first, last) = (inks.first()?, inks.last()?);
    // The ink above the first line's middle and below the last's, the
    // lines' middles LINE_SPACING apart.
    let above = first.above - MIDDLE * size;
    let below = last.below + MIDDLE * size;
    let spacing = LINE_SPACING * size;
    let height = above + below + spacing * (lines.len() - 1) as f64;
    let width = inks.iter().map(|i| i.width).fold(0.0, f64::max);
    let half_high = 0.5 * height + DIMENSION_ROOM;
    let page = |t: f64, e: f64| map.apply(Point::new(t, e));
    let curve: Vec<Point> = (0..=720)
        .map(|k| 0.5 * k as f64)
        .map(|t| page(t, energy(t)))
        .collect();
    let line = page(deg, 0.0).x;
    let (left, right) = (page(0.0, 0.0).x, page(360.0, 0.0).x);
    let levels = [0.0, elo, ehi].map(|e| page(deg, e).y);
    let heights = heights(along, (levels[2], levels[1]), half_high, plot.area());
    for side in [away, -away] {
        let (near, far) = (
            line + side * DIMENSION_ROOM,
            line + side * (DIMENSION_ROOM + width),
        );
        let (x0, x1) = (near.min(far), near.max(far));
        if x0 < left || x1 > right {
            continue;
        }
        let clear = |y: f64| {
            levels.iter().all(|l| (l - y).abs() >= half_high)
                && curve
                    .iter()
                    .filter(|p| p.x >= x0 - DIMENSION_ROOM && p.x <= x1 + DIMENSION_ROOM)
                    .all(|p| (p.y - y).abs() >= half_high)
        };
        if let Some(&y) = heights.iter().find(|y| clear(**y)) {
            let x = 0.5 * (x0 + x1);
            let first_middle = y - 0.5 * height + above;
            let ids: &[&str] = match lines.len() {
                1 => &["label-fluctuation"],
                2 => &["label-fluctuation", "label-fluctuation-unit"],
                _ => &[
                    "label-fluctuation",
                    "label-fluctuation-value",
                    "label-fluctuation-unit",
                ],
            };
            return Some(
                (lines.iter().zip(ids.iter().copied()).enumerate())
                    .map(|(i, (text, id))| {
                        let at = Point::new(x, first_middle + spacing * i as f64);
                        fixed_text(id.to_string(), map.invert(at), text.clone())
                    })
                    .collect(),
            );
        }
    }
    None
}

/// The heights (page y) tried for the middle of ΔE's box, `half_high`
/// its half height with the room: between the ends `top` (E_max) and
/// `bottom` (E_min), every 2 units from the middle outwards; or beyond
/// them, every 2 units from each end out to a box's height more, below
/// E_min first, inside the plot's `area`. Empty where none is.
fn heights(along: Along, (top, bottom): (f64, f64), half_high: f64, area: Frame) -> Vec<f64> {
    let every = |from: f64, step: f64, n: usize| (0..n).map(move |k| from + step * k as f64);
    match along {
        Along::Between => {
            let (top, bottom) = (top + half_high, bottom - half_high);
            let mid = 0.5 * (top + bottom);
            let n = if bottom >= top {
                ((bottom - top) / 2.0) as usize + 1
            } else {
                0
            };
            let mut h: Vec<f64> = every(top, 2.0, n).collect();
            h.sort_by(|a, b| (a - mid).abs().total_cmp(&(b - mid).abs()));
            h
        }
        Along::Beyond => {
            // Half a unit more than the room off each end, clear of it
            // whatever the rounding.
            let (n, off) = ((half_high as usize) + 1, half_high + 0.5);
            let above = every(top - off, -2.0, n);
            let below = every(bottom + off, 2.0, n);
            // Below E_min's end first: above E_max's, beside the circle
            // at the greatest energy, the value read as that point's
            // (l = 57.9 r on 4.5 in: the eleventh review).
            below
                .chain(above)
                .filter(|y| y - half_high >= area.min().y && y + half_high <= area.max().y)
                .collect()
        }
    }
}

/// What the notes say of the gas force after the mass: the constant, or
/// the bore and whose indicator diagram.
fn gas_note(ctx: &Ctx) -> String {
    let o = ctx.options;
    if let Some(f) = o.gas_force {
        return format!("; constant gas force {} {}", short(f), ctx.units.force());
    }
    format!(
        ", bore {} {}; gas force from the indicator diagram{}",
        short(o.bore.unwrap_or(EXAMPLE_BORE)),
        ctx.unit(),
        if o.data.is_some() {
            " given"
        } else {
            " of an illustrative steam engine (admission at 100 psi to 30 % of the stroke)"
        }
    )
}

/// The notes: the engine, its speed, mass, bore and gas force, then the
/// work per turn, the areas and where the energy is greatest and least.
fn notes(ctx: &Ctx, tm: &TurningMoment) -> [String; 3] {
    let m = ctx.mechanism;
    let t_unit = ctx.units.torque();
    [
        format!(
            "*r* = {} {u}, *l* = {} {u}{}, {} rpm; reciprocating mass {} {mass_u}{}{}.",
            short(m.crank()),
            short(m.rod()),
            // An offset engine says so (its stroke, and so its work, differ).
            ctx.offset_clause(),
            short(ctx.rpm()),
            short(ctx.options.mass.unwrap_or(EXAMPLE_MASS)),
            gas_note(ctx),
            guides_note(ctx),
            u = ctx.unit(),
            mass_u = ctx.units.mass()
        ),
        format!(
            "Work per turn {} {t_unit}; fluctuation of energy Δ*E* = {} {t_unit}; {} areas between the crossings; most energy at θ = {}°, least at {}°.",
            sig(tm.settled(tm.work)),
            sig(tm.fluctuation),
            tm.lobes.len(),
            short(tm.max_energy_deg),
            short(tm.min_energy_deg)
        ),
        format!(
            "Areas between *T* and the mean line ({t_unit}): {}; Δ*E* is the greatest less the least of their running sums.",
            (tm.lobes.iter().enumerate())
                .map(|(k, l)| format!("*a*_{{{}}} = {}", k + 1, signed(tm.settled(l.area))))
                .collect::<Vec<_>>()
                .join(", ")
        ),
    ]
}

/// The energy stored in the flywheel at `deg` degrees of the turn of
/// `tm`, E(θ) = ∫₀^θ (T − T_mean) dθ: the lobes' energy up to the one
/// holding θ, and the integral over that one to θ (one cylinder).
pub(super) fn stored(engine: &Engine, tm: &TurningMoment, deg: f64) -> f64 {
    let t = deg.to_radians();
    let Some(lobe) = tm.lobes.iter().find(|l| t <= l.to_deg.to_radians()) else {
        return 0.0;
    };
    let before = lobe.energy - lobe.area;
    let excess = |x: f64| total_torque(engine, &[0.0], x) - tm.mean;
    let from = lobe.from_deg.to_radians();
    before + integrate(&excess, from, t.max(from), tm.tolerance).value
}

/// T on [a, b] degrees as a curve with its slope by central differences
/// kept inside the piece.
fn piece<'a>(torque: &'a dyn Fn(f64) -> f64, a: f64, b: f64) -> Box<dyn Curve + 'a> {
    Box::new(move |deg: f64| -> Option<(Point, Vector)> {
        let h = STEP.to_degrees();
        let (lo, hi) = ((deg - h).max(a), (deg + h).min(b));
        let slope = (torque(hi) - torque(lo)) / (hi - lo);
        Some((Point::new(deg, torque(deg)), Vector::new(1.0, slope)))
    })
}
