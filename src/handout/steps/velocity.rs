//! §36, the velocity: D and E, and the velocity scale that turns *CE*
//! into the piston velocity.

use super::work::Work;
use super::{Picture, Row, Step, Value};
use super::{short, show};
use crate::analytic::approx;
use crate::catalogue::FigureName;
use crate::error::Result;
use crate::handout::figures;

/// §36, Fig. 63: the instantaneous centre *D* and the point *E*.
pub(super) fn d_and_e(w: &Work) -> Result<Step> {
    let fig63 = figures::mechanism(w.h, FigureName::Fig63Velocity, None)?;
    Ok(Step {
        id: "velocity",
        title: "D and E: the velocity construction".into(),
        source: "§36, Fig. 63",
        text: vec![
            "*A* moves along the line of stroke and *B* at right angles to *CB*, so the rod's instantaneous centre *D* is where *CB* produced meets the perpendicular to the stroke through *A*. Produce *AB* to meet the perpendicular to the stroke through *C* in *E*. The triangles *ADB* and *ECB* are similar, so *V*_p/*V*_c = *AD*/*BD* = *CE*/*CB*.".to_string(),
            measured(w),
        ],
        pictures: vec![Picture::of(
            &fig63,
            "fig-63",
            "*D*, the instantaneous centre of the rod, and *E* on the perpendicular to the stroke through *C*; *CE* represents the piston velocity.",
        )],
        rows: d_and_e_rows(w),
    })
}

/// *CE* and *BD* as measured, or *D* at infinity.
fn measured(w: &Work) -> String {
    let (r, u) = (w.r, w.length());
    match r.bd() {
        Some(bd) => format!(
            "Measured: *CE* = {} {u} and *BD* = {} {u}. Where *D* falls off the drawing, *E* can still be found: it needs only the rod produced.",
            show(r.ce.abs()),
            show(bd)
        ),
        None => format!(
            "At this angle *CB* is perpendicular to the stroke: *D* is at infinity and the rod, for the instant, does not turn. *E* is still found, *CE* = {} {u}.",
            show(r.ce.abs())
        ),
    }
}

/// The lengths *CE* and *BD*, read off the construction only.
pub(super) fn d_and_e_rows(w: &Work) -> Vec<Row> {
    let (r, len) = (w.r, w.length());
    vec![
        Row::new("*CE*", Some(Value::of("construction.CE", r.ce)), None, len),
        Row::new(
            "*BD*",
            Some(Value::maybe("construction.BD", r.bd(), "at infinity")),
            None,
            len,
        ),
    ]
}

/// §36: the velocity scale, 1 unit of length to ω, and the piston
/// velocity it gives; beside the textbook's eq. (2) in line.
pub(super) fn velocity_scale(w: &Work) -> Step {
    let mut text = vec![scale(w)];
    text.push(
        "Signed as the rate of change of *x*, d*x*/d*t* = −ω · *CE*: negative while the piston moves towards the crank.".into(),
    );
    if w.in_line() {
        text.push(format!(
            "The textbook's approximation, eq. (2), *V*_p ≈ *V*_c(sin θ + sin 2θ/2*n*), gives {} {} against the exact {}.",
            show(approx::velocity(w.pose(), w.omega()).approx.abs()),
            w.n.velocity,
            show(w.r.exact.velocity.abs())
        ));
    }
    Step {
        id: "velocity-scale",
        title: "The velocity scale".into(),
        source: "§36",
        text,
        pictures: vec![],
        rows: velocity_scale_rows(w),
    }
}

/// The scale and the piston velocity *CE* represents, with its direction.
fn scale(w: &Work) -> String {
    let (u, velocity) = (w.length(), &w.n.velocity);
    format!(
        "*CB* = {} {u} represents *V*_c = {} {velocity}, so the velocity scale is 1 {u} = *V*_c/*CB* = ω = {} {velocity}. *CE* = {} {u} therefore represents a piston velocity of {} {velocity}, {}.",
        short(w.mechanism().crank()),
        show(w.vc()),
        show(w.omega()),
        show(w.r.ce.abs()),
        show(w.r.graphical.velocity.abs()),
        direction(w.r.graphical.velocity)
    )
}

/// Which way the piston moves at velocity `v` (d*x*/d*t*).
fn direction(v: f64) -> &'static str {
    if v < 0.0 {
        "towards the crank"
    } else if v > 0.0 {
        "away from the crank"
    } else {
        "at rest"
    }
}

/// The piston velocity, read off and exact.
pub(super) fn velocity_scale_rows(w: &Work) -> Vec<Row> {
    vec![Row::new(
        "piston velocity d*x*/d*t* = −ω · *CE*",
        Some(Value::of("graphical.velocity", w.r.graphical.velocity)),
        Some(Value::of("analytic.velocity", w.r.exact.velocity)),
        &w.n.velocity,
    )]
}
