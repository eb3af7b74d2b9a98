//! The data of the engine, as the pages state them.

use super::work::Names;
use super::{short, show};
use crate::handout::Handout;

/// "above" or "below" the crank centre.
pub(super) fn side(e: f64) -> &'static str {
    if e > 0.0 { "above" } else { "below" }
}

/// The data of the engine, as a sentence.
pub(in crate::handout) fn data_sentence(h: &Handout) -> String {
    let n = Names::of(h);
    let m = h.mechanism();
    let u = &n.length;
    let mut s = format!(
        "Crank radius *r* = {} {u}, connecting rod *l* = {} {u} (*n* = *l*/*r* = {}), ",
        short(m.crank()),
        short(m.rod()),
        short(m.ratio())
    );
    if m.offset() == 0.0 {
        s.push_str("in line; ");
    } else {
        s.push_str(&format!(
            "line of stroke *e* = {} {u} {} the crank centre; ",
            short(m.offset().abs()),
            side(m.offset())
        ));
    }
    s.push_str(&format!(
        "{} rpm (ω = {} rad/s); crank angle θ = {}°",
        short(h.rpm()),
        show(h.omega()),
        short(h.angle().degrees())
    ));
    if let Some(t) = h.torque() {
        s.push_str(&format!(
            "; crank torque *T* = {} {}, μ = {}",
            short(t),
            n.torque,
            short(h.friction())
        ));
    }
    s.push('.');
    s
}
