//! Ng: the OM line and the forces, when a torque is given.

use super::work::Work;
use super::{Picture, Row, Step, Value};
use super::{short, show};
use crate::analytic::statics::Friction;
use crate::catalogue::FigureName;
use crate::construct::Statics;
use crate::error::Result;
use crate::handout::figures;

/// What a force row says where there is no force.
const DEAD_CENTRE: &str = "none (dead centre)";

/// Ng, Fig. 1: the torque line *OM*, the slider force, the side thrust and
/// friction; `None` when no torque is given.
pub(super) fn forces(w: &Work) -> Result<Option<Step>> {
    let (Some(s), Some(t)) = (&w.r.statics, w.h.torque()) else {
        return Ok(None);
    };
    let ng1 = figures::mechanism(w.h, FigureName::NgFig1Torque, None)?;
    Ok(Some(Step {
        id: "forces",
        title: "The OM line and the forces".into(),
        source: "Ng, Fig. 1, eq. 2–11",
        text: vec![
            "In Ng's letters the crank centre is *O*, the crank pin *C*, the slider *P*, and *M* is the textbook's *E*: *OM* = *CE*. With no friction, virtual work gives *F*_p · *OM* = *T* (eq. 2).".to_string(),
            slider_force(w, s, t),
            friction(w, s),
        ],
        pictures: vec![Picture::of(
            &ng1,
            "ng-fig-1",
            "Ng's Fig. 1 for this engine: the torque line *OM*, the slider force and the side thrust.",
        )],
        rows: forces_rows(w),
    }))
}

/// The slider force and the side thrust for the torque `t`, or none at a
/// dead centre.
fn slider_force(w: &Work, s: &Statics, t: f64) -> String {
    let force = &w.n.force;
    match s.force {
        Some(f) => format!(
            "The crank torque *T* = {} {} and *OM* = {} {} give the slider force *F*_p = *T*/*OM* = {} {force} (eq. 6), and the side thrust on the guides *F*_s = *F*_p tan φ = {} {force} (eq. 7).",
            short(t),
            w.n.torque,
            show(s.om),
            w.length(),
            show(f),
            show(s.side_thrust.unwrap_or(0.0))
        ),
        None => "At a dead centre *OM* = 0: no finite slider force balances the torque.".into(),
    }
}

/// The slider force with friction, or self-locking, and the transmission
/// angle.
fn friction(w: &Work, s: &Statics) -> String {
    match s.with_friction {
        Some(Friction::Force(f)) => format!(
            "With friction μ = {} in the guides, *F*_p′ = *F*_p(1 − μ tan φ) = {} {} (eq. 8). The transmission angle at the crank pin is β = {}° (eq. 11).",
            short(s.mu),
            show(f),
            w.n.force,
            show(s.transmission_deg)
        ),
        Some(Friction::SelfLocking(k)) => format!(
            "With friction μ = {} in the guides μ tan φ = {} ≥ 1: friction alone holds the slider. The transmission angle at the crank pin is β = {}°.",
            short(s.mu),
            show(k),
            show(s.transmission_deg)
        ),
        None => format!(
            "The transmission angle at the crank pin is β = {}°.",
            show(s.transmission_deg)
        ),
    }
}

/// *OM*, the forces and the transmission angle, exact (and *OM* read off
/// as *CE*); none without statics.
pub(super) fn forces_rows(w: &Work) -> Vec<Row> {
    let Some(s) = &w.r.statics else {
        return Vec::new();
    };
    let force = |quantity: &str, exact| Row::new(quantity, None, Some(exact), &w.n.force);
    vec![
        Row::new(
            "torque line *OM* (= *CE*)",
            Some(Value::of("construction.CE", w.r.ce)),
            Some(Value::of("statics.OM", s.om)),
            w.length(),
        ),
        force(
            "slider force *F*_p = *T*/*OM*",
            Value::maybe("statics.slider_force", s.force, DEAD_CENTRE),
        ),
        force(
            "side thrust *F*_s = *F*_p tan φ",
            Value::maybe("statics.side_thrust", s.side_thrust, DEAD_CENTRE),
        ),
        force(
            "with friction *F*_p′ = *F*_p(1 − μ tan φ)",
            with_friction(s),
        ),
        Row::new(
            "transmission angle β",
            None,
            Some(Value::of(
                "statics.transmission_angle_deg",
                s.transmission_deg,
            )),
            "°",
        ),
    ]
}

/// The slider force with friction, or what stands in its place:
/// self-locking, or none at a dead centre.
fn with_friction(s: &Statics) -> Value {
    let (value, none) = match s.with_friction {
        Some(Friction::Force(f)) => (Some(f), DEAD_CENTRE),
        Some(Friction::SelfLocking(_)) => (None, "self-locking"),
        None => (None, DEAD_CENTRE),
    };
    Value::maybe("statics.slider_force_with_friction", value, none)
}
