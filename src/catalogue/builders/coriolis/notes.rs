//! What a Coriolis figure says in words and metadata: the notes reading
//! each polygon to its bar, and the values in the SVG's metadata.

use super::super::{Ctx, short, sig};
use super::panel::Lined;
use super::polygons::Polygons;

use crate::chain::{Inversion, InvertedChain};
use crate::geom::Vector;
use crate::scene::COINCIDE;
use serde_json::{Value, json};

/// The figure's metadata: the polygons' vectors from their poles, the
/// values read off them and the bars' lengths.
pub(super) fn coriolis_json(polygons: &Polygons, v_bar: f64, a_bar: f64) -> Value {
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

/// How long the sliding acceleration, the Coriolis component and d's
/// tangential component are drawn at their largest, page units, each
/// with the detail's magnification where a detail draws it (`None`
/// without one).
pub(super) type Seen = ((f64, Option<f64>), (f64, Option<f64>), (f64, Option<f64>));

/// The notes: the pose and the driver, then each polygon read to its bar,
/// then the Coriolis component and its rule.
pub(super) fn notes(
    ctx: &Ctx,
    chain: &InvertedChain,
    polygons: &Polygons,
    bars: (f64, f64),
    (seen, plain, lines): (Seen, &[String], &[Lined]),
) -> Vec<String> {
    let read = Read::new(polygons);
    vec![
        pose_note(ctx, chain, polygons),
        velocity_note(ctx, polygons, &read, bars.0),
        acceleration_note(ctx, polygons, &read, bars.1, (seen.0, seen.2)),
        coriolis_note(ctx, polygons, &read, bars.1, seen.1)
            + &headless_said(plain)
            + &lined_up_said(lines),
    ]
}

/// The values the notes read off the polygons, each 0 where it is the
/// construction's rounding ([`Polygons::clean`]).
struct Read {
    /// The sliding velocity's size.
    v: f64,
    /// d's angular velocity.
    omega_d: f64,
    /// d's angular acceleration.
    alpha_d: f64,
    /// The sliding acceleration (signed, as the engine's d²x_A/dt²).
    sliding: f64,
    /// The Coriolis component's size.
    coriolis: f64,
}

impl Read {
    fn new(polygons: &Polygons) -> Self {
        let p = &polygons.p;
        let ca = polygons.ca;
        Read {
            v: polygons.clean(p.sliding_velocity().abs(), 1.0, false),
            omega_d: polygons.clean(p.omega_d(), ca, false),
            alpha_d: polygons.clean(p.alpha_d(), ca, true),
            sliding: polygons.clean(p.sliding_acceleration(), 1.0, true),
            coriolis: polygons.clean(p.coriolis().norm(), 1.0, true),
        }
    }
}

/// The first note: the inversion, the engine and the pose (θ, with what
/// it is measured between: the drawing marks no angle, and a reader took
/// it for the driver's), the driver and its speed, CA, and the quick
/// return's time ratio where it has one.
fn pose_note(ctx: &Ctx, chain: &InvertedChain, polygons: &Polygons) -> String {
    let m = &ctx.mechanism;
    let (r, l, e) = (m.crank(), m.rod(), m.offset());
    let inversion = polygons.inversion;
    let offset = if e == 0.0 {
        String::new()
    } else {
        format!(", *e* = {}", short(e))
    };
    let ratio = chain.time_ratio().map_or(String::new(), |t| {
        format!(" Time ratio of the quick return {}.", short(t))
    });
    let (fixed, driver) = match inversion {
        Inversion::Rod => ("b", "the crank *a* (*BC*)"),
        _ => ("a", "the rod *b* (*BA*)"),
    };
    format!(
        "Inversion {}, link *{fixed}* fixed ({}) at θ = {}° (the angle at *C* from the direction of *d*’s slot, the line of stroke, to the crank *CB*, counter-clockwise); *r* = {}, *l* = {}{offset}; {driver} turns about *B* at ω = {} rad/s ({} rpm), *CA* = {} {}.{ratio}",
        inversion.number(),
        inversion.name(),
        short(ctx.angle.degrees()),
        short(r),
        short(l),
        sig(ctx.omega),
        short(ctx.rpm()),
        sig(polygons.ca),
        ctx.unit(),
    )
}

/// The velocity polygon read to its bar of `bar`: the driven point's
/// velocity, the two directions that meet at a_d, the sliding velocity
/// and ω_d.
fn velocity_note(ctx: &Ctx, polygons: &Polygons, read: &Read, bar: f64) -> String {
    let u = ctx.unit();
    // The driven point's image, its link, the side ⟂ CA, the slot's.
    let (driven, link, across, along) = match polygons.inversion {
        Inversion::Rod => ("*oc*", "*BC*", "*ca*_{d}", "*oa*_{d}"),
        _ => ("*oa*", "*BA*", "*oa*_{d}", "*a*_{d}*a*"),
    };
    format!(
        "Velocity polygon (the bar {} {u}/s): {driven} = ω·{link} = {} {u}/s, perpendicular to {link}; {across} perpendicular to *CA*; {along} along the slot, *v* = {} {u}/s; ω_{{d}} = {across}/*CA* = {} rad/s.",
        short(bar),
        sig(polygons.p.driven().norm()),
        sig(read.v),
        sig(read.omega_d),
    )
}

/// The acceleration polygon read to its bar of `bar`: the driven point's
/// centripetal acceleration, d's normal and tangential components, the
/// sliding acceleration with its sense, and, where it or the tangential
/// component is drawn too short to be seen at its largest (`seen`: the
/// sliding acceleration's, the tangential component's), how long it is
/// drawn (inversion 2 at l = 2.84 r, e = -1.38 r, 0°: the tangential
/// component n a′_d, 11 units, was drawn nowhere and not said).
fn acceleration_note(
    ctx: &Ctx,
    polygons: &Polygons,
    read: &Read,
    bar: f64,
    (seen, tangent_seen): ((f64, Option<f64>), (f64, Option<f64>)),
) -> String {
    let u = ctx.unit();
    let p = &polygons.p;
    let per_s2 = format!("{u}/s²");
    // A sliding acceleration too short to draw even where the polygon is
    // enlarged (inversion 2 at l = 40 r, 89°: 12 ft/s² against a Coriolis
    // component of 1370, under a unit at ×20) is said so: k stands on a′_d.
    let sliding_said = said(&[
        sliding_sense(polygons.inversion, read.sliding),
        unseen(read.sliding, seen, (bar, &per_s2), ("*k*", "*a*′_{d}")),
    ]);
    let (pin, link) = match polygons.inversion {
        Inversion::Rod => ("*c*", "C"),
        _ => ("*a*", "A"),
    };
    let normal = read.omega_d * read.omega_d * polygons.ca;
    let tangential = read.alpha_d * polygons.ca;
    let tangent_said = said(&[unseen(
        tangential,
        tangent_seen,
        (bar, &per_s2),
        ("*n*", "*a*′_{d}"),
    )]);
    format!(
        "Acceleration polygon (the bar {} {u}/s²): *o*′{pin}′ = ω²·*B{link}* = {} {u}/s² towards *B*; the normal component ω_{{d}}²·*CA* = {} {u}/s² towards *C* and the tangential component perpendicular to *CA*, α_{{d}} = {} rad/s²{tangent_said}; the sliding acceleration along the slot {} {u}/s²{sliding_said}.",
        short(bar),
        sig(p.driven_acceleration().norm()),
        sig(normal),
        sig(read.alpha_d),
        sig(read.sliding),
    )
}

/// The Coriolis component and its rule: its size, where it is drawn too
/// short to be seen at its largest (`seen`) how long, the sliding
/// velocity it turns, and why it vanishes where it does.
fn coriolis_note(
    ctx: &Ctx,
    polygons: &Polygons,
    read: &Read,
    bar: f64,
    seen: (f64, Option<f64>),
) -> String {
    let u = ctx.unit();
    let per_s2 = format!("{u}/s²");
    // A narrow space after the prime: set in italic with its o, it leant
    // onto k's ascender ("o′k" read as one glyph).
    let (side, from, to, sliding) = match polygons.inversion {
        Inversion::Rod => ("*o*′\u{202f}*k*", "*k*", "*o*′", "of *d* on the block"),
        _ => ("*ka*′", "*k*", "*a*′", "of the block on *d*"),
    };
    let unseen_said = said(&[unseen(read.coriolis, seen, (bar, &per_s2), (from, to))]);
    let vanishes = if read.v == 0.0 {
        "; here *v* = 0 and it vanishes"
    } else if read.omega_d == 0.0 {
        "; here ω_{d} = 0 and it vanishes"
    } else {
        ""
    };
    format!(
        "The Coriolis component {side} = 2ω_{{d}}*v* = {} {u}/s²{unseen_said}: the sliding velocity *v* ({sliding}) turned 90° in the sense of ω_{{d}}{vanishes}.",
        sig(read.coriolis),
    )
}

/// The notes' word on the sides `plain` drawn without a head
/// ([`super::panel::headless`]): too short for one, their sense read
/// from the letters at their ends. Nothing where there are none.
fn headless_said(plain: &[String]) -> String {
    match plain {
        [] => String::new(),
        [one] => format!(
            " {one} is drawn without a head, too short for one: its sense is from the letters at its ends."
        ),
        [rest @ .., last] => format!(
            " {} and {last} are drawn without heads, too short for them: their sense is from the letters at their ends.",
            rest.join(", ")
        ),
    }
}

/// The notes' word on the sides that meet at a point and run on from it
/// the opposite ways along one line ([`super::panel::lined_up`]: each
/// pair's names and the point's letter): drawn, they read as one side.
/// Nothing where there are none.
fn lined_up_said(lines: &[Lined]) -> String {
    (lines.iter())
        .map(|(p, q, at)| format!(" {p} and {q} lie on one line, the opposite ways from {at}."))
        .collect()
}

/// The remarks `parts` after a value, in one bracket ("; " between them),
/// those empty left out; nothing where all are.
fn said(parts: &[String]) -> String {
    let kept: Vec<&str> = (parts.iter())
        .map(String::as_str)
        .filter(|p| !p.is_empty())
        .collect();
    match kept.is_empty() {
        true => String::new(),
        false => format!(" ({})", kept.join("; ")),
    }
}

/// What the notes say of a side of value `value` drawn `seen` page units
/// long at its largest (at the detail's magnification, if any) where
/// that is too short to be seen (under [`super::MIN_ARROW`]): how long,
/// as a share of the polygon's bar `bar` (the length `unit`, in the
/// value's unit: page units are no length a reader can use, and the
/// tenth review read "drawn 1.5 units long" as the drawing's internals),
/// and what the drawing shows of its ends `(from, to)`: under
/// [`COINCIDE`] one dot lettered for both, `from` standing on `to`;
/// longer, two dots each lettered (inversion 2 at l = 30.3 r, 0°: the
/// sliding acceleration 7.2 units, k lettered with a′ and a′_d with n,
/// where the notes had k standing on a′_d). Nothing for a nil side, one
/// seen, or a bar that is not positive and finite.
fn unseen(
    value: f64,
    (seen, magnified): (f64, Option<f64>),
    (bar, unit): (f64, &str),
    (from, to): (&str, &str),
) -> String {
    if value == 0.0 || seen >= super::MIN_ARROW || !(bar > 0.0 && bar.is_finite()) {
        return String::new();
    }
    let share = value.abs() * magnified.unwrap_or(1.0) / bar;
    let ends = match seen < COINCIDE {
        true => format!("too short to be seen: {from} stands on {to}"),
        false => format!("too short for an arrow: {from} and {to} are the two dots at its ends"),
    };
    format!(
        "{}drawn {} as long as the {} {unit} bar, {ends}",
        magnified.map_or(String::new(), |m| format!("at ×{} ", short(m))),
        share_words(share),
        short(bar),
    )
}

/// The least share of a bar written as a number: smaller is "under a
/// thousandth".
const LEAST_SHARE: f64 = 1e-3;

/// `share` (positive) of a length in words: two significant figures
/// ("0.096"), "under a thousandth" below [`LEAST_SHARE`].
fn share_words(share: f64) -> String {
    if share < LEAST_SHARE {
        return "under a thousandth".to_string();
    }
    let digits = (1.0 - share.log10().floor()).max(0.0) as usize;
    format!("{share:.digits$}")
}

/// The sense of the sliding acceleration `s` (the block's along d, the
/// engine's d²x_A/dt²: positive as CA grows) in words: towards or away
/// from C; in inversion 3, where the polygon draws d's past the block
/// (k a′_d), that it is drawn the other way (the ninth review read
/// −145.9 ft/s² drawn away from C as a sign left unsaid). Nil: nothing.
fn sliding_sense(inversion: Inversion, s: f64) -> String {
    if s == 0.0 {
        return String::new();
    }
    let (block, drawn) = match s < 0.0 {
        true => ("towards", "away from"),
        false => ("away from", "towards"),
    };
    match inversion {
        Inversion::Rod => format!(
            "the block’s along *d*: {block} *C*; *ka*′_{{d}}, *d*’s past the block, is drawn {drawn} *C*"
        ),
        _ => format!("the block’s along *d*: {block} *C*"),
    }
}
