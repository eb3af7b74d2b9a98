//! The direct and reverse crank method (`docs/dynamics.md` §6): (a) the
//! primary force m r ω² cos θ as the resultant of two cranks each
//! carrying m/2 at radius r, the direct crank at θ turning with the
//! engine and the reverse crank at −θ turning against it; (b) the
//! secondary force m r ω² cos 2θ / n as the resultant of two cranks each
//! carrying m/2 at radius r/4n, at ±2θ, turning at ±2ω; (c) the two
//! resultants on the line of stroke, head to tail, against the exact
//! inertia force.
//!
//! The panels are drawn in force units (each crank as the centrifugal
//! force of its mass), unmirrored: away from the crank is to the right.
//! Each crank's component on the line of stroke is half its resultant;
//! their components across it cancel.

use super::{Ctx, Sheet, positive_mass, short, sig};
use crate::diagram::Plot;
use crate::error::Result;
use crate::figure::{Dash, Figure, Item, Part, RichText, Role, Shape, Symbol, TextSize};
use crate::geom::{Frame, Point, Vector};

/// An arrow shorter than this fraction of its panel's crank is left out
/// (a resultant at 90° or 45°): the notes give its value, zero.
const SHORTEST: f64 = 1e-3;

/// An arrow shorter than this on the page (units, a head and a half) is
/// left out too, its value in the notes (which give every resultant): at l = 2.74 r, e = −1.42 r,
/// 90.73° the primary resultant of −87 lbf beside cranks of 3427 lbf was
/// a bare head at the centre, and "primary" in (c) named a 6-unit nub.
const LEAST_ON_PAGE: f64 = 15.0;

/// Within this angle (degrees) of each other two lines read as one: the
/// projection joining the cranks' tips is left out where it lies so near
/// the cranks (θ near 90°: it doubled both), and the direct crank's
/// component on the line of stroke where the crank lies so near that
/// line (it ran along the crank, two heads on one shaft).
const ALONG: f64 = 10.0;

/// World units per page unit where `world` is shown whole in `rect` less
/// its caption, as [`Plot::world`] fits it.
fn world_per_page(rect: Frame, world: &Frame) -> f64 {
    let area = (rect.width(), rect.height() - crate::diagram::CAPTION);
    (world.width() / area.0).max(world.height() / area.1)
}

/// One pair of cranks: the force each carries and the angle of the
/// direct one, radians.
#[derive(Clone, Copy)]
struct Pair {
    /// `primary` or `secondary`, for ids.
    name: &'static str,
    /// The force each crank's mass exerts along it, m/2 × radius × speed².
    force: f64,
    /// The direct crank's angle (θ or 2θ); the reverse is at minus it.
    angle: f64,
    /// How the angle is written (θ, 2θ).
    written: &'static str,
}

impl Pair {
    /// The direct crank's force as a vector.
    fn direct(&self) -> Vector {
        Vector::new(self.angle.cos(), self.angle.sin()) * self.force
    }

    /// The reverse crank's: the direct mirrored in the line of stroke.
    fn reverse(&self) -> Vector {
        let d = self.direct();
        Vector::new(d.x, -d.y)
    }

    /// Their resultant along the line of stroke.
    fn resultant(&self) -> f64 {
        self.direct().x + self.reverse().x
    }
}

pub(in crate::catalogue) fn build(ctx: &Ctx) -> Result<Figure> {
    let page = ctx.page();
    let mass = positive_mass(ctx)?;
    let m = ctx.mechanism;
    let k = mass * m.crank() * ctx.omega * ctx.omega;
    let angle = ctx.angle;
    let (s, c) = (angle.sin(), angle.cos());
    // 2θ from the angle's sine and cosine, exact where they are.
    let twice = (2.0 * s * c).atan2(2.0 * c * c - 1.0);
    let primary = Pair {
        name: "primary",
        force: 0.5 * k,
        angle: s.atan2(c),
        written: "θ",
    };
    let secondary = Pair {
        name: "secondary",
        force: 0.5 * k / m.ratio(),
        angle: twice,
        written: "2θ",
    };
    let exact = -mass * ctx.omega * ctx.omega * ctx.pose().position_acceleration();
    let mut sheet = Sheet::new(ctx);
    sheet.mechanism(ctx, true, true);
    sheet.meta(
        "cranks",
        serde_json::json!({
            "mass": mass,
            "primary_crank_force": primary.force,
            "secondary_crank_force": secondary.force,
            "primary": primary.resultant(),
            "secondary": secondary.resultant(),
            "exact": exact,
        }),
    );
    let half = 0.5 * (page.width() - 48.0);
    // The panels' world is 3.65 × 2.6 cranks (see `pair_plot`).
    let most = (page.height() - 16.0 - 24.0 - 170.0 - 64.0).max(120.0);
    let tall = (half * 2.6 / 3.65 + crate::diagram::CAPTION).min(most);
    let (pa, sa) = (
        Frame::from_origin_size(16.0, 16.0, half, tall),
        Frame::from_origin_size(32.0 + half, 16.0, half, tall),
    );
    sheet.plot(pair_plot(
        ctx,
        &primary,
        pa,
        "(a) Primary: *m*/2 at *r* on cranks at ±θ, turning at ±ω",
    )?);
    sheet.plot(pair_plot(
        ctx,
        &secondary,
        sa,
        "(b) Secondary: *m*/2 at *r*/4*n* on cranks at ±2θ, turning at ±2ω",
    )?);
    let band = ctx.band(16.0 + tall + 16.0, 170.0);
    let (sum, unseen) = sum_plot(ctx, &primary, &secondary, exact, band)?;
    sheet.plot(sum);
    let top = band.max().y + 8.0;
    sheet.height(top + 64.0 + 16.0);
    sheet.notes(
        Point::new(20.0, top),
        &notes(ctx, mass, k, &primary, &secondary, exact, &unseen),
    );
    Ok(sheet.finish())
}

/// A force arrow and its label by its middle (nearer it than any other
/// arrow or link: two arrows nearly along one line keep their names
/// apart), or nothing for an arrow shorter than `least`.
pub(super) fn arrow(id: &str, from: Point, to: Point, text: &str, least: f64) -> Vec<Item> {
    if (to - from).norm() <= least {
        return Vec::new();
    }
    vec![
        Item::new(
            format!("force-{id}"),
            Role::Force,
            Shape::Arrow { from, to },
        ),
        Item::new(
            format!("value-{id}"),
            Role::Label,
            Shape::Label {
                anchor: from + (to - from) * 0.5,
                text: RichText::parse(text),
                size: TextSize::Small,
                toward: None,
                line: Some([from, to]),
            },
        ),
    ]
}

/// A thin line between two points.
pub(super) fn line(id: &str, role: Role, from: Point, to: Point) -> Item {
    Item::new(
        id,
        role,
        Shape::Polyline {
            points: vec![from, to],
            closed: false,
        },
    )
}

/// (a) or (b): the circle of the cranks, the line of stroke, the direct
/// and reverse cranks with their angles, their components on the line of
/// stroke head to tail, and the projections.
fn pair_plot(ctx: &Ctx, pair: &Pair, rect: Frame, caption: &str) -> Result<Plot> {
    let f = pair.force;
    let o = Point::origin();
    // Room for the circle and, on its side, the resultant (up to 2f).
    let side = if pair.resultant() >= 0.0 { 1.0 } else { -1.0 };
    let (near, far) = (-1.35 * f * side, 2.3 * f * side);
    let world = Frame::new(
        Point::new(near.min(far), -1.3 * f),
        Point::new(near.max(far), 1.3 * f),
    );
    let mut plot =
        Plot::world(pair.name, rect, &world, false, ctx.tolerance, ctx.font)?.with_caption(caption);
    let name = pair.name;
    plot.push(Item::new(
        format!("circle-{name}"),
        Role::Auxiliary,
        Shape::Circle {
            centre: o,
            radius: f,
        },
    ));
    plot.push(
        line(
            &format!("line-stroke-{name}"),
            Role::Auxiliary,
            Point::new(-1.3 * f * side, 0.0),
            Point::new(2.25 * f * side, 0.0),
        )
        .dashed(Dash::DashDot)
        .as_part(Part::CentreLine),
    );
    let (d, r) = (o + pair.direct(), o + pair.reverse());
    let least = (SHORTEST * f).max(LEAST_ON_PAGE * world_per_page(rect, &world));
    let along = ALONG.to_radians().sin();
    let (sin, cos) = pair.angle.sin_cos();
    for item in arrow(&format!("{name}-direct"), o, d, "direct", least)
        .into_iter()
        .chain(arrow(&format!("{name}-reverse"), o, r, "reverse", least))
    {
        plot.push(item);
    }
    angle_marks(&mut plot, pair);
    // The components along the stroke, head to tail, and the projections.
    let foot = Point::new(d.x, 0.0);
    let tip = Point::new(pair.resultant(), 0.0);
    if (d - foot).norm() > least && cos.abs() > along {
        plot.push(
            line(&format!("projection-{name}"), Role::Construction, d, r).dashed(Dash::Dashed),
        );
    }
    for (id, from, to) in [("direct", o, foot), ("reverse", foot, tip)] {
        let on_crank = id == "direct" && sin.abs() < along;
        if (to - from).norm() > least && !on_crank {
            plot.push(Item::new(
                format!("component-{name}-{id}"),
                Role::Force,
                Shape::Arrow { from, to },
            ));
        }
    }
    plot.points(
        &format!("point-{name}-resultant"),
        &[(tip.x, 0.0)],
        Symbol::Disc,
        None,
    );
    // The panel's own force scale, below the circle at the left.
    let bar = super::round_below(0.8 * f);
    let from = Point::new(world.min().x + 0.05 * f, -1.22 * f);
    let text = format!("{} {}", short(bar), ctx.units.force());
    plot.push(super::scale_bar(&format!("bar-{name}"), from, bar, &text));
    Ok(plot)
}

/// The angles of the direct crank (from the line of stroke to it) and of
/// the reverse (to it the other way), where they are wide enough to mark.
/// Past 180° each is marked the short way round and named so (θ − 360°
/// and 360° − θ): two arcs of more than half a turn overlap over their
/// middles, where their letters stand, and the letter of one read as the
/// other's. Within 5° of 180° the two cranks lie together and one arc, the
/// direct crank's, is marked: the two halves closed into a circle.
fn angle_marks(plot: &mut Plot, pair: &Pair) {
    use std::f64::consts::{PI, TAU};
    let turn = pair.angle.rem_euclid(TAU);
    let (sweep, direct, reverse) = if turn > PI + 5f64.to_radians() {
        let w = pair.written;
        (turn - TAU, format!("{w} − 360°"), format!("360° − {w}"))
    } else {
        (turn, pair.written.to_string(), format!("−{}", pair.written))
    };
    if sweep.abs() < 5f64.to_radians() || pair.force <= 0.0 {
        return;
    }
    let together = (turn - PI).abs() <= 5f64.to_radians();
    let marks = [("direct", sweep, direct), ("reverse", -sweep, reverse)];
    for (id, sweep, text) in marks.into_iter().take(if together { 1 } else { 2 }) {
        plot.push(Item::new(
            format!("angle-{}-{id}", pair.name),
            Role::Dimension,
            Shape::AngleMark {
                vertex: Point::origin(),
                start: 0.0,
                sweep,
                text: Some(RichText::parse(&text)),
            },
        ));
    }
}

/// (c) The two resultants on the line of stroke, head to tail (the
/// secondary a little above, where it would run back over the primary),
/// and below them the exact inertia force, a dashed line joining the
/// sum's end to it; also the names of the forces too short to draw
/// there.
fn sum_plot(
    ctx: &Ctx,
    p: &Pair,
    s: &Pair,
    exact: f64,
    rect: Frame,
) -> Result<(Plot, Vec<&'static str>)> {
    let (a, b) = (p.resultant(), p.resultant() + s.resultant());
    let values = [0.0, a, b, exact];
    let lo = values.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = values.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    // The panel's own scale, for the forces it draws: near 90° at long
    // rods they are a few hundredths of m r ω², and the cranks' scale
    // drew them as dots under their heads. At least a millionth of
    // m r ω², where all of them vanish together.
    let span = (hi - lo).max(2e-6 * p.force);
    let row = 0.045 * span;
    // Below the arrows a row for the panel's scale bar.
    let world = Frame::new(
        Point::new(lo - 0.12 * span, -4.0 * row),
        Point::new(hi + 0.12 * span, 2.0 * row),
    );
    let mut plot = Plot::world("sum", rect, &world, false, ctx.tolerance, ctx.font)?.with_caption(
        "(c) On the line of stroke: primary + secondary, and the exact inertia force −*m a* below",
    );
    let least = (SHORTEST * span).max(LEAST_ON_PAGE * world_per_page(rect, &world));
    let unseen: Vec<&'static str> = [
        ("the primary", a),
        ("the secondary", b - a),
        ("the exact force", exact),
    ]
    .into_iter()
    .filter(|(_, f)| f.abs() <= least)
    .map(|(name, _)| name)
    .collect();
    plot.push(
        line(
            "line-stroke-sum",
            Role::Auxiliary,
            Point::new(lo - 0.1 * span, 0.0),
            Point::new(hi + 0.1 * span, 0.0),
        )
        .dashed(Dash::DashDot)
        .as_part(Part::CentreLine),
    );
    let pt = |x: f64, y: f64| Point::new(x, y);
    let items = arrow("sum-primary", pt(0.0, 0.0), pt(a, 0.0), "primary", least)
        .into_iter()
        .chain(arrow(
            "sum-secondary",
            pt(a, row),
            pt(b, row),
            "secondary",
            least,
        ))
        .chain(arrow(
            "sum-exact",
            pt(0.0, -row),
            pt(exact, -row),
            "exact",
            least,
        ));
    for item in items {
        plot.push(item);
    }
    plot.push(
        line("line-sum-end", Role::Construction, pt(b, row), pt(b, -row)).dashed(Dash::Dashed),
    );
    plot.points(
        "point-sum-origin",
        &[(0.0, 0.0), (0.0, -row)],
        Symbol::Disc,
        None,
    );
    let bar = super::round_below(0.25 * span);
    let from = Point::new(lo - 0.1 * span, -3.7 * row);
    let text = format!("{} {}", short(bar), ctx.units.force());
    plot.push(super::scale_bar("bar-sum", from, bar, &text));
    Ok((plot, unseen))
}

/// The notes: the engine, the cranks' forces, the two resultants, their
/// sum and the exact force, with units, and which of them are too short
/// to draw in (c) (`unseen`).
fn notes(
    ctx: &Ctx,
    mass: f64,
    k: f64,
    p: &Pair,
    s: &Pair,
    exact: f64,
    unseen: &[&str],
) -> Vec<String> {
    let m = ctx.mechanism;
    let (u, f) = (ctx.unit(), ctx.units.force());
    let mass_u = ctx.units.mass();
    vec![
        format!(
            "*r* = {} {u}, *l* = {} {u} (*n* = {}), θ = {}°, {} rpm; *m* = {} {mass_u}, *m\u{a0}r*ω² = {} {f}. Each primary crank carries (*m*/2)*r*ω² = {} {f}, each secondary (*m*/2)(*r*/4*n*)(2ω)² = {} {f}; away from the crank is to the right; each panel is drawn to its own force scale, given by its bar.",
            short(m.crank()),
            short(m.rod()),
            short(m.ratio()),
            short(ctx.angle.degrees()),
            short(ctx.rpm()),
            short(mass),
            sig(k),
            sig(p.force),
            sig(s.force),
        ),
        format!(
            "Primary *m\u{a0}r*ω² cos θ = {} {f}, secondary *m\u{a0}r*ω² cos 2θ/*n* = {} {f}, their sum {} {f}; the exact inertia force −*m a* = {} {f}.{}",
            sig(p.resultant()),
            sig(s.resultant()),
            sig(p.resultant() + s.resultant()),
            sig(exact),
            shortfall(ctx, k, p.resultant() + s.resultant(), exact),
        ) + &too_short(unseen),
    ]
}

/// The sentence naming the forces too short to draw in (c), if any (at
/// 180° the exact force showed as a stray dot and at 90° the primary was
/// missing, with no word).
fn too_short(unseen: &[&str]) -> String {
    match unseen {
        [] => String::new(),
        [one] => format!(" In (c) {one} is too short to draw at the panel’s scale."),
        [first @ .., last] => format!(
            " In (c) {} and {last} are too short to draw at the panel’s scale.",
            first.join(", ")
        ),
    }
}

/// What the two cranks' sum leaves out of the exact force, where it
/// shows (more than half a percent of m r ω², `k`): the offset's terms
/// (in sin θ, of the order of m r ω² e/l) and the higher harmonics, with
/// the amount. At l = 2.74 r, e = −1.42 r, 90.73° the notes named the
/// offset's term alone, about 3 550 lbf, for a gap of 10 400 lbf; at
/// l = 1.07 r with no offset they said nothing of a gap of 11 600 lbf.
fn shortfall(ctx: &Ctx, k: f64, sum: f64, exact: f64) -> String {
    let gap = exact - sum;
    if gap.abs() <= 5e-3 * k {
        return String::new();
    }
    let f = ctx.units.force();
    let e = ctx.mechanism.offset();
    if e == 0.0 {
        return format!(
            " The cranks stop at the second harmonic: the higher ones (cos 4θ, cos 6θ, …, the larger the nearer *n* is to 1) make up the other {} {f}.",
            sig(gap)
        );
    }
    format!(
        " The line of stroke is offset by *e* = {} {}: the cranks are the series of an in-line engine, and the exact force also holds terms in sin θ (of the order of *m\u{a0}r*ω²*e*/*l*) and higher harmonics, which they leave out: here {} {f}.",
        short(e),
        ctx.unit(),
        sig(gap)
    )
}
