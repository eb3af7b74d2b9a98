//! §35: the mechanism to scale, the position of the cross-head and the
//! obliquity of the rod.

use super::data::side;
use super::work::Work;
use super::{Picture, Row, Step, Value};
use super::{short, show};
use crate::catalogue::FigureName;
use crate::error::Result;
use crate::handout::figures;

/// §35, Fig. 62: the engine drawn at its angle.
pub(super) fn mechanism(w: &Work) -> Result<Step> {
    let fig62 = figures::mechanism(w.h, FigureName::Fig62Displacement, None)?;
    Ok(Step {
        id: "mechanism",
        title: "The mechanism to scale".into(),
        source: "§35, Fig. 62",
        text: vec![crank(w), drawing(w), obliquity(w)],
        pictures: vec![Picture::of(
            &fig62,
            "fig-62",
            format!(
                "The engine at θ = {}°: crank angle θ, obliquity φ, and the cross-head's displacement from mid-stroke *O* as the textbook draws it; the table gives *x*, its distance from the crank centre *C*.",
                short(w.h.angle().degrees())
            ),
        )],
        rows: mechanism_rows(w),
    })
}

/// The crank, its speed and the speed of the crank pin.
fn crank(w: &Work) -> String {
    let m = w.mechanism();
    format!(
        "The crank *CB* of radius *r* = {} {} turns about *C* at *N* = {} rpm, so ω = 2π*N*/60 = {} rad/s and the crank pin *B* moves at *V*_c = *r*ω = {} {}.",
        short(m.crank()),
        w.length(),
        short(w.h.rpm()),
        show(w.omega()),
        show(w.vc()),
        w.n.velocity
    )
}

/// How the engine is drawn: the crank at θ, the cross-head found with the
/// compasses.
fn drawing(w: &Work) -> String {
    format!(
        "Draw the crank at θ = {}°, counter-clockwise from the outer dead centre (the crank pointing at the cross-head), and find the cross-head *A* on the line of stroke with the compasses set to the rod's length *l* = {} {} about *B*.",
        short(w.h.angle().degrees()),
        short(w.mechanism().rod()),
        w.length()
    )
}

/// The obliquity and the position of the cross-head: with the error due
/// to obliquity in line, from the offset otherwise.
fn obliquity(w: &Work) -> String {
    let m = w.mechanism();
    let u = w.length();
    if w.in_line() {
        format!(
            "The rod's obliquity φ follows from sin φ = sin θ/*n* with *n* = *l*/*r* = {}, and the cross-head stands at *x* = *r* cos θ + *r*√(*n*² − sin²θ) from *C*. Its difference from simple harmonic motion, the error due to obliquity *r*(√(*n*² − sin²θ) − *n*), is {} {u} here.",
            short(m.ratio()),
            show(w.pose().obliquity_error())
        )
    } else {
        format!(
            "The line of stroke is *e* = {} {u} {} the crank centre, so sin φ = (*r* sin θ − *e*)/*l* and *x* = *r* cos θ + √(*l*² − (*r* sin θ − *e*)²).",
            short(m.offset().abs()),
            side(m.offset())
        )
    }
}

/// The position of the cross-head and the obliquity of the rod, exact
/// only.
pub(super) fn mechanism_rows(w: &Work) -> Vec<Row> {
    let k = &w.r.exact;
    vec![
        Row::new(
            "position of the cross-head *x*",
            None,
            Some(Value::of("analytic.position", k.position)),
            w.length(),
        ),
        Row::new(
            "obliquity of the rod φ",
            None,
            Some(Value::of(
                "analytic.rod_angle_deg",
                k.rod_angle.to_degrees(),
            )),
            "°",
        ),
    ]
}
