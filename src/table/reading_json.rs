//! A [`Reading`] as the JSON object `analyze --json` prints (schema in
//! `docs/design.md` §4), for the command line and the Python package alike.

use crate::analytic::statics::Friction;
use crate::chain::ChainCentres;
use crate::construct::Reading;
use crate::geom::{Intersection, Point};
use crate::mechanism::SliderCrank;
use crate::units::Units;
use serde_json::{Value, json};

/// +0.0 for −0.0, so that no "-0" is written.
fn num(x: f64) -> f64 {
    x + 0.0
}

fn point(p: Point) -> Value {
    json!([num(p.x), num(p.y)])
}

/// A point `[x, y]`, a point at infinity `{"at_infinity": [dx, dy]}` or
/// `{"indeterminate": true}`.
fn centre(c: &Intersection) -> Value {
    match c {
        Intersection::Point(p) => point(*p),
        Intersection::AtInfinity(d) => json!({"at_infinity": [num(d.x), num(d.y)]}),
        Intersection::Coincident => json!({"indeterminate": true}),
    }
}

impl Reading {
    /// The object `analyze --json` prints for this reading of `mechanism`
    /// (the engine it was read on) in `units`: the mechanism, units,
    /// angle and ω, the points C B A D E F G H (D a point at infinity at
    /// θ = 90°, 270° of an in-line engine; H `null` at the very limit of
    /// assembly), the analytic and graphical values, the six virtual
    /// centres and, with a torque, the statics. No `-0` is written.
    pub fn to_json(&self, mechanism: &SliderCrank, units: &Units) -> Value {
        let mut v = json!({
            "mechanism": {
                "crank": mechanism.crank(), "rod": mechanism.rod(), "offset": num(mechanism.offset()),
            },
            "units": units,
            "angle_deg": num(self.pose.angle().degrees()),
            "omega": num(self.omega),
            "points": {
                "C": point(self.pose.c()), "B": point(self.pose.b()), "A": point(self.pose.a()),
                "D": centre(&self.d), "E": point(self.e), "F": point(self.f),
                "G": point(self.g), "H": self.h.map(point).unwrap_or(Value::Null),
            },
            "analytic": self.analytic_json(),
            "graphical": {
                "velocity": num(self.graphical.velocity),
                "acceleration": num(self.graphical.acceleration),
                "rod_angular_velocity": num(self.graphical.rod_angular_velocity),
                "rod_angular_acceleration": num(self.graphical.rod_angular_acceleration),
            },
            "virtual_centres": ChainCentres::of_slider_crank(&self.pose).to_json(),
        });
        if let Some(s) = &self.statics {
            let (with_friction, locking) = match s.with_friction {
                Some(Friction::Force(f)) => (json!(num(f)), false),
                Some(Friction::SelfLocking(_)) => (Value::Null, true),
                None => (Value::Null, false),
            };
            let statics = json!({
                "OM": num(s.om),
                "slider_force": s.force.map(num),
                "side_thrust": s.side_thrust.map(num),
                "slider_force_with_friction": with_friction,
                "self_locking": locking,
                "friction": s.mu,
                "transmission_angle_deg": num(s.transmission_deg),
            });
            if let Some(fields) = v.as_object_mut() {
                fields.insert("statics".into(), statics);
            }
        }
        v
    }

    fn analytic_json(&self) -> Value {
        let k = &self.exact;
        json!({
            "position": num(k.position),
            "velocity": num(k.velocity),
            "acceleration": num(k.acceleration),
            "rod_angle_deg": num(k.rod_angle.to_degrees()),
            "rod_angular_velocity": num(k.rod_angular_velocity),
            "rod_angular_acceleration": num(k.rod_angular_acceleration),
        })
    }
}
