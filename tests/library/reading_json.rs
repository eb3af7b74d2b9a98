//! `Reading::json`, the object `analyze --json` prints serialised straight
//! from the reading, against the tree of `serde_json::Value`s it was built
//! as before (kept here, as it was, for the comparison): the same bytes,
//! pretty and compact, and the same value, over engines of every shape and
//! size at poses through the whole turn, dead centres, points at infinity,
//! the limit of assembly, self-locking friction and an indeterminate
//! centre.

use serde_json::{Value, json};
use slider_crank::analytic::statics::Friction;
use slider_crank::chain::ChainCentres;
use slider_crank::construct::{
    AccelerationPolygon, Bennett, CouplerPoint, Reading, Ritterhaus, VelocityLine, VelocityPolygon,
};
use slider_crank::geom::{Intersection, Point, Vector};
use slider_crank::{Angle, SliderCrank, Unit, Units};

/// The object as `Reading::to_json` built it before the typed writer.
mod old {
    use super::*;

    fn num(x: f64) -> f64 {
        x + 0.0
    }

    fn point(p: Point) -> Value {
        json!([num(p.x), num(p.y)])
    }

    fn centre(c: &Intersection) -> Value {
        match c {
            Intersection::Point(p) => point(*p),
            Intersection::AtInfinity(d) => json!({"at_infinity": [num(d.x), num(d.y)]}),
            Intersection::Coincident => json!({"indeterminate": true}),
        }
    }

    fn centres(r: &Reading) -> Value {
        let mut map = serde_json::Map::new();
        for (name, c) in ChainCentres::of_slider_crank(&r.pose).named() {
            map.insert(name.to_string(), centre(&c));
        }
        Value::Object(map)
    }

    /// The polygons member, added with the relative-velocity method: the
    /// images of the rod's middle.
    fn polygons(r: &Reading) -> Value {
        let (w, q) = (r.omega, Some(CouplerPoint::new(0.5).unwrap()));
        let v = VelocityPolygon::construct(&r.pose, q);
        let a = AccelerationPolygon::construct(&r.pose, &v, q);
        let at = |x: Vector, k: f64| json!([num(k * x.x), num(k * x.y)]);
        let w2 = w * w;
        json!({
            "coupler": 0.5,
            "velocity": {"a": at(v.a(), w), "b": at(v.b(), w), "q": at(v.q().unwrap(), w)},
            "acceleration": {
                "a": at(a.a(), w2), "b": at(a.b(), w2), "q": at(a.q().unwrap(), w2),
                "x": at(a.x(), w2),
            },
            "slider_velocity": num(w * v.slider_velocity_ratio()),
            "rod_angular_velocity": num(w * v.rod_angular_velocity_ratio()),
            "slider_acceleration": num(w2 * a.slider_acceleration_ratio()),
            "rod_angular_acceleration": num(w2 * a.rod_angular_acceleration_ratio()),
            "normal_component": num(w2 * (a.x() - a.b()).norm()),
            "tangential_component": num(w2 * a.tangential().norm()),
            "off_rod": {
                "along": 0.5, "across": 0.25,
                "velocity": at(off(v.a(), v.b()), w),
                "acceleration": at(off(a.a(), a.b()), w2),
            },
        })
    }

    /// The image of the point halfway along AB and AB/4 to its left, by
    /// the similar triangles: a + (b − a)/2 + J(b − a)/4.
    fn off(a: Vector, b: Vector) -> Vector {
        let ab = b - a;
        a + ab * 0.5 + Vector::new(-ab.y, ab.x) * 0.25
    }

    /// Ritterhaus's construction, added beside the polygons.
    fn ritterhaus(r: &Reading) -> Value {
        let c = Ritterhaus::construct(&r.pose, &VelocityLine::construct(&r.pose));
        let p = c.points();
        json!({
            "K": point(c.k()), "F": point(p.f()), "G": point(p.g()),
            "acceleration": num(r.omega * r.omega * p.acceleration_ratio()),
        })
    }

    /// Bennett's, `null` for an offset engine.
    fn bennett(r: &Reading) -> Value {
        match Bennett::construct(&r.pose) {
            Some(c) => {
                let p = c.points();
                json!({
                    "L": point(c.l()), "K": point(c.k()), "F": point(p.f()), "G": point(p.g()),
                    "acceleration": num(r.omega * r.omega * p.acceleration_ratio()),
                })
            }
            None => Value::Null,
        }
    }

    pub fn to_json(r: &Reading, mechanism: &SliderCrank, units: &Units) -> Value {
        let k = &r.exact;
        let mut v = json!({
            "mechanism": {
                "crank": mechanism.crank(), "rod": mechanism.rod(), "offset": num(mechanism.offset()),
            },
            "units": units,
            "angle_deg": num(r.pose.angle().degrees()),
            "omega": num(r.omega),
            "points": {
                "C": point(r.pose.c()), "B": point(r.pose.b()), "A": point(r.pose.a()),
                "D": centre(&r.d), "E": point(r.e), "F": point(r.f),
                "G": point(r.g), "H": r.h.map(point).unwrap_or(Value::Null),
            },
            "analytic": {
                "position": num(k.position),
                "velocity": num(k.velocity),
                "acceleration": num(k.acceleration),
                "rod_angle_deg": num(k.rod_angle.to_degrees()),
                "rod_angular_velocity": num(k.rod_angular_velocity),
                "rod_angular_acceleration": num(k.rod_angular_acceleration),
            },
            "graphical": {
                "velocity": num(r.graphical.velocity),
                "acceleration": num(r.graphical.acceleration),
                "rod_angular_velocity": num(r.graphical.rod_angular_velocity),
                "rod_angular_acceleration": num(r.graphical.rod_angular_acceleration),
            },
            "virtual_centres": centres(r),
            "polygons": polygons(r),
            "ritterhaus": ritterhaus(r),
            "bennett": bennett(r),
        });
        if let Some(s) = &r.statics {
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
            v.as_object_mut().unwrap().insert("statics".into(), statics);
        }
        v
    }
}

/// Asserts the typed writer gives the old tree's bytes and value.
fn same(r: &Reading, m: &SliderCrank, units: &Units, what: &str) {
    let old = old::to_json(r, m, units);
    let new = r.json(m, units);
    assert_eq!(
        serde_json::to_string_pretty(&new).unwrap(),
        serde_json::to_string_pretty(&old).unwrap(),
        "{what}"
    );
    assert_eq!(
        serde_json::to_string(&new).unwrap(),
        old.to_string(),
        "{what}"
    );
    assert_eq!(r.to_json(m, units), old, "{what}");
}

fn engines() -> Vec<SliderCrank> {
    let mut engines = Vec::new();
    for (crank, rod, offset) in [
        (0.5, 3.0, 0.0),
        (1.0, 4.0, 0.3),
        (1.0, 4.0, -0.3),
        (1.0, 2.0, -0.9999999999999998),
        (1.0, 1.0000000000000002, 0.0),
        (1e-100, 1.0000000000000002e-100, 0.0),
        (1e-100, 3e-100, 5e-101),
        (9e99, 1e100, 9.9e98),
        (2.5, 7.25, 0.0),
        (25.0, 100.0, -10.0),
    ] {
        engines.push(SliderCrank::new(crank, rod, offset).unwrap());
    }
    engines
}

fn angles() -> Vec<f64> {
    let mut angles: Vec<f64> = (0..72).map(|k| 5.0 * k as f64).collect();
    angles.extend([
        1e-300,
        5e-324,
        89.99999999999999,
        90.0,
        270.0,
        359.9999999999999,
        1e300,
    ]);
    angles
}

#[test]
fn the_typed_writer_writes_the_old_trees_bytes() {
    let units = [
        Units::FOOT_POUND,
        Units::MILLIMETRE_NEWTON,
        Units::new("in".parse::<Unit>().unwrap(), "kN".parse::<Unit>().unwrap()),
    ];
    let mut count = 0;
    for (i, m) in engines().iter().enumerate() {
        let u = &units[i % units.len()];
        for degrees in angles() {
            let pose = m.pose(Angle::from_degrees(degrees).unwrap());
            for (omega, load) in [
                (26.16, None),
                (0.0, None),
                (-1e100, None),
                (1.0, Some((100.0, 0.0))),
                (1.0, Some((-3.5, 0.2))),
                (1.0, Some((1e-30, 1e308))),
            ] {
                let (torque, mu) = load.map_or((None, 0.0), |(t, mu)| (Some(t), mu));
                let Ok(r) = Reading::new(&pose, omega, torque, mu) else {
                    continue;
                };
                same(
                    &r,
                    m,
                    u,
                    &format!("{m:?} at {degrees}°, ω {omega}, {load:?}"),
                );
                count += 1;
            }
        }
    }
    assert!(count > 3000, "{count} readings compared");
}

#[test]
fn centres_at_infinity_and_indeterminate_are_written_as_before() {
    let m = SliderCrank::new(0.5, 3.0, 0.0).unwrap();
    // In line at 90°: D is a point at infinity.
    let pose = m.pose(Angle::from_degrees(90.0).unwrap());
    let r = Reading::new(&pose, 26.16, Some(10.0), 0.1).unwrap();
    assert!(matches!(r.d, Intersection::AtInfinity(_)));
    same(&r, &m, &Units::FOOT_POUND, "D at infinity");
    // A dead centre: no slider force.
    let dead = Reading::new(
        &m.pose(Angle::from_degrees(0.0).unwrap()),
        1.0,
        Some(1.0),
        0.0,
    )
    .unwrap();
    assert_eq!(dead.statics.unwrap().force, None);
    same(&dead, &m, &Units::FOOT_POUND, "dead centre");
    // The forms no engine reaches through `Reading::new`, written all the
    // same: D indeterminate, H missing, a non-finite value (null).
    let mut odd = r;
    odd.d = Intersection::Coincident;
    odd.h = None;
    odd.graphical.velocity = f64::NAN;
    odd.exact.position = -0.0;
    same(&odd, &m, &Units::FOOT_POUND, "indeterminate D, no H");
    let text = serde_json::to_string(&odd.json(&m, &Units::FOOT_POUND)).unwrap();
    assert!(text.contains(r#""D":{"indeterminate":true}"#), "{text}");
    assert!(text.contains(r#""H":null"#), "{text}");
    assert!(text.contains(r#""position":0.0"#), "{text}");
    assert!(!text.contains("-0.0,") && !text.contains("-0.0}"), "{text}");
}

#[test]
fn dynamics_take_their_place_among_the_keys() {
    let m = SliderCrank::new(1.0, 4.0, 0.0).unwrap();
    let r = Reading::new(
        &m.pose(Angle::from_degrees(30.0).unwrap()),
        2.0,
        Some(5.0),
        0.1,
    )
    .unwrap();
    let dynamics = json!({"torque": -1.5, "rod": null, "unbalanced": {"primary": 2.0}});
    let mut old = old::to_json(&r, &m, &Units::FOOT_POUND);
    old.as_object_mut()
        .unwrap()
        .insert("dynamics".into(), dynamics.clone());
    let new = r.json(&m, &Units::FOOT_POUND).with_dynamics(&dynamics);
    let text = serde_json::to_string_pretty(&new).unwrap();
    assert_eq!(text, serde_json::to_string_pretty(&old).unwrap());
    // "dynamics" sorts between "angle_deg" and "graphical".
    let at = |key: &str| text.find(&format!("\n  \"{key}\"")).unwrap();
    assert!(at("angle_deg") < at("dynamics") && at("dynamics") < at("graphical"));
}
