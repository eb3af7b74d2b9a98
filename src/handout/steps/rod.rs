//! §37: the rod's angular velocity and acceleration.

use super::work::Work;
use super::{Picture, Row, Step, Value};
use super::{short, show};
use crate::analytic::approx;
use crate::catalogue::FigureName;
use crate::error::Result;
use crate::handout::figures;

/// §37: the rod's rates from *BD* and *FG*, with their diagram over the
/// turn; beside the textbook's eq. (2a) in line.
pub(super) fn rod(w: &Work) -> Result<Step> {
    let rod_motion = figures::diagram(w.h, FigureName::RodMotion)?;
    let r = w.r;
    let mut text = vec![angular_velocity(w)];
    text.push(format!(
        "*FG* = {} {}, signed as in the table, gives its angular acceleration, ω² · *FG*/*l* = {} rad/s².",
        show(r.fg),
        w.length(),
        show(r.graphical.rod_angular_acceleration)
    ));
    if w.in_line() {
        text.push(format!(
            "The textbook's eq. (2a), −(*V*_c²/*r*²) sin θ/√(*n*² − sin²θ), gives {} rad/s² against the exact {}.",
            show(approx::rod_angular_acceleration(w.pose(), w.omega()).approx),
            show(r.exact.rod_angular_acceleration)
        ));
    }
    Ok(Step {
        id: "rod",
        title: "The rod's angular velocity and acceleration".into(),
        source: "§37",
        text,
        pictures: vec![Picture::of(
            &rod_motion,
            "rod-motion",
            "The rod's angular velocity and acceleration over the turn.",
        )],
        rows: rod_rows(w),
    })
}

/// The rod's angular velocity as it turns about *D*, zero with *D* at
/// infinity.
fn angular_velocity(w: &Work) -> String {
    match w.r.bd() {
        Some(bd) => format!(
            "The rod turns about *D* while the crank turns about *C*: its angular velocity is *V*_c/*BD* = ω · *CB*/*BD* = {} × {}/{} = {} rad/s.",
            show(w.omega()),
            short(w.mechanism().crank()),
            show(bd),
            show(w.r.graphical.rod_angular_velocity.abs())
        ),
        None => "With *D* at infinity the rod's angular velocity *V*_c/*BD* is zero.".into(),
    }
}

/// The rod's angular velocity and acceleration, read off and exact.
pub(super) fn rod_rows(w: &Work) -> Vec<Row> {
    let (g, k) = (&w.r.graphical, &w.r.exact);
    vec![
        Row::new(
            "rod angular velocity dφ/d*t*, ω · *CB*/*BD*",
            Some(Value::of(
                "graphical.rod_angular_velocity",
                g.rod_angular_velocity,
            )),
            Some(Value::of(
                "analytic.rod_angular_velocity",
                k.rod_angular_velocity,
            )),
            "rad/s",
        ),
        Row::new(
            "rod angular acceleration d²φ/d*t*², ω² · *FG*/*l*",
            Some(Value::of(
                "graphical.rod_angular_acceleration",
                g.rod_angular_acceleration,
            )),
            Some(Value::of(
                "analytic.rod_angular_acceleration",
                k.rod_angular_acceleration,
            )),
            "rad/s²",
        ),
    ]
}
