//! A [`Reading`] as the analysis's JSON object (schema in
//! `docs/design.md` §4), for the command line and the Python package alike.
//!
//! The object is serialised straight from the reading ([`ReadingJson`]),
//! never built as a tree of `serde_json::Value`s first: a million angles
//! of the analysis's JSON spent most of their time allocating, sorting and
//! freeing those trees. The keys are written in the order a tree's sorted
//! maps gave them (byte order), so the text is the one the tree wrote;
//! `tests/library/reading_json.rs` holds the two to the same bytes.

use crate::analytic::statics::Friction;
use crate::chain::ChainCentres;
use crate::construct::{
    AccelerationPolygon, Bennett, CouplerPoint, Reading, Ritterhaus, Statics, VelocityLine,
    VelocityPolygon,
};
use crate::geom::{Intersection, MeetJson, Point};
use crate::mechanism::SliderCrank;
use crate::units::Units;
use serde::ser::{Serialize, SerializeMap, Serializer};
use serde_json::Value;

use crate::number::unsigned_zero as num;

/// A point `[x, y]`.
fn pair(x: f64, y: f64) -> [f64; 2] {
    [num(x), num(y)]
}

/// A point as `[x, y]`.
struct At(Point);

impl Serialize for At {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        pair(self.0.x, self.0.y).serialize(s)
    }
}

/// A point `[x, y]`, a point at infinity `{"at_infinity": [dx, dy]}` or
/// `{"indeterminate": true}` ([`MeetJson`]).
struct Centre(Intersection);

impl Serialize for Centre {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        MeetJson(&self.0, num).serialize(s)
    }
}

/// Writes `entries` as one JSON object, each value +0.0 for −0.0.
fn numbers<S: Serializer>(s: S, entries: &[(&str, f64)]) -> Result<S::Ok, S::Error> {
    let mut m = s.serialize_map(Some(entries.len()))?;
    for (key, value) in entries {
        m.serialize_entry(key, &num(*value))?;
    }
    m.end()
}

/// `mechanism`: crank, offset, rod.
struct Mechanism<'a>(&'a SliderCrank);

impl Serialize for Mechanism<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let m = self.0;
        let mut map = s.serialize_map(Some(3))?;
        map.serialize_entry("crank", &m.crank())?;
        map.serialize_entry("offset", &num(m.offset()))?;
        map.serialize_entry("rod", &m.rod())?;
        map.end()
    }
}

/// `units`: the seven names of [`Units`]' own serialisation, in byte
/// order of their keys.
struct UnitNames<'a>(&'a Units);

impl Serialize for UnitNames<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let u = self.0;
        let mut m = s.serialize_map(Some(7))?;
        m.serialize_entry("acceleration", &u.acceleration())?;
        m.serialize_entry("angular_acceleration", "rad/s²")?;
        m.serialize_entry("angular_velocity", "rad/s")?;
        m.serialize_entry("force", u.force().as_str())?;
        m.serialize_entry("length", u.length().as_str())?;
        m.serialize_entry("torque", &u.torque())?;
        m.serialize_entry("velocity", &u.velocity())?;
        m.end()
    }
}

/// `points`: A to H (D a centre, H `null` where there is none).
struct Points<'a>(&'a Reading);

impl Serialize for Points<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let r = self.0;
        let mut m = s.serialize_map(Some(8))?;
        m.serialize_entry("A", &At(r.pose.a()))?;
        m.serialize_entry("B", &At(r.pose.b()))?;
        m.serialize_entry("C", &At(r.pose.c()))?;
        m.serialize_entry("D", &Centre(r.d))?;
        m.serialize_entry("E", &At(r.e))?;
        m.serialize_entry("F", &At(r.f))?;
        m.serialize_entry("G", &At(r.g))?;
        m.serialize_entry("H", &r.h.map(At))?;
        m.end()
    }
}

/// `analytic`: the exact values.
struct Analytic<'a>(&'a Reading);

impl Serialize for Analytic<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let k = &self.0.exact;
        numbers(
            s,
            &[
                ("acceleration", k.acceleration),
                ("position", k.position),
                ("rod_angle_deg", k.rod_angle.to_degrees()),
                ("rod_angular_acceleration", k.rod_angular_acceleration),
                ("rod_angular_velocity", k.rod_angular_velocity),
                ("velocity", k.velocity),
            ],
        )
    }
}

/// `graphical`: the values read off the constructions.
struct Graphical<'a>(&'a Reading);

impl Serialize for Graphical<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let g = &self.0.graphical;
        numbers(
            s,
            &[
                ("acceleration", g.acceleration),
                ("rod_angular_acceleration", g.rod_angular_acceleration),
                ("rod_angular_velocity", g.rod_angular_velocity),
                ("velocity", g.velocity),
            ],
        )
    }
}

/// `virtual_centres`: O_ab to O_cd, as [`ChainCentres::to_json`] writes
/// them.
struct Centres(ChainCentres);

impl Serialize for Centres {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        // `named` keeps O_ab … O_cd, which is their byte order.
        let named = self.0.named();
        let mut m = s.serialize_map(Some(named.len()))?;
        for (name, centre) in named {
            m.serialize_entry(name, &Centre(centre))?;
        }
        m.end()
    }
}

/// `statics`, with a torque.
struct StaticsJson<'a>(&'a Statics);

impl Serialize for StaticsJson<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let st = self.0;
        let (with_friction, locking) = match st.with_friction {
            Some(Friction::Force(f)) => (Some(num(f)), false),
            Some(Friction::SelfLocking(_)) => (None, true),
            None => (None, false),
        };
        let mut m = s.serialize_map(Some(7))?;
        m.serialize_entry("OM", &num(st.om))?;
        m.serialize_entry("friction", &st.mu)?;
        m.serialize_entry("self_locking", &locking)?;
        m.serialize_entry("side_thrust", &st.side_thrust.map(num))?;
        m.serialize_entry("slider_force", &st.force.map(num))?;
        m.serialize_entry("slider_force_with_friction", &with_friction)?;
        m.serialize_entry("transmission_angle_deg", &num(st.transmission_deg))?;
        m.end()
    }
}

/// The fraction of the rod, from A, of the point whose images `polygons`
/// gives: its middle.
const POLYGON_COUPLER: f64 = 0.5;

/// The point off the rod's line whose images `polygons` gives as
/// `off_rod`: halfway along AB and a quarter of AB to its left (a point
/// of the rod as a plate, a bearing lug or a link's pin).
const POLYGON_OFF_ROD: (f64, f64) = (0.5, 0.25);

/// `polygons`: the velocity and acceleration polygons (docs/polygons.md)
/// at the reading's ω, their vectors from the pole in the user's units
/// (velocities ob, oa, oq; accelerations o′b′, o′x, o′a′, o′q′ of the
/// images of B, A, the rod's middle Q and the end x of the normal
/// component), and the values read off them.
struct Polygons<'a>(&'a Reading);

impl Serialize for Polygons<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let r = self.0;
        let (w, pose) = (r.omega, &r.pose);
        let coupler = CouplerPoint::new(POLYGON_COUPLER).ok();
        let v = VelocityPolygon::construct(pose, coupler);
        let a = AccelerationPolygon::construct(pose, &v, coupler);
        let vec = |x: Option<crate::geom::Vector>, k: f64| x.map(|x| pair(k * x.x, k * x.y));
        let w2 = w * w;
        let mut m = s.serialize_map(Some(10))?;
        let mut acc = std::collections::BTreeMap::new();
        acc.insert("a", vec(Some(a.a()), w2));
        acc.insert("b", vec(Some(a.b()), w2));
        acc.insert("q", vec(a.q(), w2));
        acc.insert("x", vec(Some(a.x()), w2));
        m.serialize_entry("acceleration", &acc)?;
        m.serialize_entry("coupler", &POLYGON_COUPLER)?;
        m.serialize_entry("normal_component", &num(w2 * (a.x() - a.b()).norm()))?;
        let (along, across) = POLYGON_OFF_ROD;
        let off = CouplerPoint::off_rod(along, across).ok();
        let (off_v, off_a) = (
            off.map(|p| p.image(v.a(), v.b())),
            off.map(|p| p.image(a.a(), a.b())),
        );
        let mut off_rod = std::collections::BTreeMap::new();
        off_rod.insert("along", Some(serde_json::json!(along)));
        off_rod.insert("across", Some(serde_json::json!(across)));
        off_rod.insert("velocity", vec(off_v, w).map(|p| serde_json::json!(p)));
        off_rod.insert("acceleration", vec(off_a, w2).map(|p| serde_json::json!(p)));
        m.serialize_entry("off_rod", &off_rod)?;
        m.serialize_entry(
            "rod_angular_acceleration",
            &num(w2 * a.rod_angular_acceleration_ratio()),
        )?;
        m.serialize_entry(
            "rod_angular_velocity",
            &num(w * v.rod_angular_velocity_ratio()),
        )?;
        m.serialize_entry(
            "slider_acceleration",
            &num(w2 * a.slider_acceleration_ratio()),
        )?;
        m.serialize_entry("slider_velocity", &num(w * v.slider_velocity_ratio()))?;
        m.serialize_entry("tangential_component", &num(w2 * a.tangential().norm()))?;
        let mut vel = std::collections::BTreeMap::new();
        vel.insert("a", vec(Some(v.a()), w));
        vel.insert("b", vec(Some(v.b()), w));
        vel.insert("q", vec(v.q(), w));
        m.serialize_entry("velocity", &vel)?;
        m.end()
    }
}

/// `ritterhaus` and `bennett`: the points of each construction (K, F, G;
/// L, K, F, G) and the piston's acceleration ω² · CG read off it.
struct Classical<'a> {
    reading: &'a Reading,
    points: Vec<(&'static str, Point)>,
    ratio: f64,
}

impl<'a> Classical<'a> {
    /// Ritterhaus's construction of the reading's pose.
    fn ritterhaus(reading: &'a Reading) -> Self {
        let pose = &reading.pose;
        let r = Ritterhaus::construct(pose, &VelocityLine::construct(pose));
        let p = r.points();
        Self {
            reading,
            points: vec![("F", p.f()), ("G", p.g()), ("K", r.k())],
            ratio: p.acceleration_ratio(),
        }
    }

    /// Bennett's, where the engine has one (in line).
    fn bennett(reading: &'a Reading) -> Option<Self> {
        let b = Bennett::construct(&reading.pose)?;
        let p = b.points();
        Some(Self {
            reading,
            points: vec![("F", p.f()), ("G", p.g()), ("K", b.k()), ("L", b.l())],
            ratio: p.acceleration_ratio(),
        })
    }
}

impl Serialize for Classical<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let w = self.reading.omega;
        let mut m = s.serialize_map(Some(self.points.len() + 1))?;
        for (name, p) in &self.points {
            m.serialize_entry(name, &At(*p))?;
        }
        m.serialize_entry("acceleration", &num(w * w * self.ratio))?;
        m.end()
    }
}

/// The analysis's JSON object for one reading, serialised
/// straight to a writer (`serde_json::to_writer_pretty`) from the
/// reading: made by [`Reading::json`], with the engine's `dynamics`
/// member added by [`ReadingJson::with_dynamics`]. A value that is not a
/// finite number is written `null` (none is, in a reading the library
/// made); no `-0` is written.
#[derive(Debug, Clone, Copy)]
pub struct ReadingJson<'a> {
    reading: &'a Reading,
    mechanism: &'a SliderCrank,
    units: &'a Units,
    dynamics: Option<&'a Value>,
}

impl<'a> ReadingJson<'a> {
    /// The same object with the member `dynamics` (the engine's forces,
    /// as the analysis of an engine with a mass prints them) written in
    /// its place.
    pub fn with_dynamics(self, dynamics: &'a Value) -> Self {
        Self {
            dynamics: Some(dynamics),
            ..self
        }
    }
}

impl Serialize for ReadingJson<'_> {
    /// The members in byte order of their keys, as a `serde_json::Map`
    /// keeps them.
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let r = self.reading;
        let fields = 11 + usize::from(self.dynamics.is_some()) + usize::from(r.statics.is_some());
        let mut m = s.serialize_map(Some(fields))?;
        m.serialize_entry("analytic", &Analytic(r))?;
        m.serialize_entry("angle_deg", &num(r.pose.angle().degrees()))?;
        m.serialize_entry("bennett", &Classical::bennett(r))?;
        if let Some(dynamics) = self.dynamics {
            m.serialize_entry("dynamics", dynamics)?;
        }
        m.serialize_entry("graphical", &Graphical(r))?;
        m.serialize_entry("mechanism", &Mechanism(self.mechanism))?;
        m.serialize_entry("omega", &num(r.omega))?;
        m.serialize_entry("points", &Points(r))?;
        m.serialize_entry("polygons", &Polygons(r))?;
        m.serialize_entry("ritterhaus", &Classical::ritterhaus(r))?;
        if let Some(statics) = &r.statics {
            m.serialize_entry("statics", &StaticsJson(statics))?;
        }
        m.serialize_entry("units", &UnitNames(self.units))?;
        let centres = ChainCentres::of_slider_crank(&r.pose);
        m.serialize_entry("virtual_centres", &Centres(centres))?;
        m.end()
    }
}

impl Reading {
    /// The analysis's JSON object for this reading of `mechanism`
    /// (the engine it was read on) in `units`: the mechanism, units,
    /// angle and ω, the points C B A D E F G H (D a point at infinity at
    /// θ = 90°, 270° of an in-line engine; H `null` at the very limit of
    /// assembly), the analytic and graphical values, the velocity and
    /// acceleration polygons with the images of the rod's middle,
    /// Ritterhaus's and Bennett's constructions (`bennett` `null` for an
    /// offset engine), the six virtual centres and, with a torque, the
    /// statics. Serialised where it is
    /// written, as [`ReadingJson`]; no `-0` is written.
    pub fn json<'a>(&'a self, mechanism: &'a SliderCrank, units: &'a Units) -> ReadingJson<'a> {
        ReadingJson {
            reading: self,
            mechanism,
            units,
            dynamics: None,
        }
    }

    /// [`Reading::json`] as a `serde_json::Value` (the Python package
    /// hands it on as text); `null` in the unreachable case that
    /// serialisation fails.
    pub fn to_json(&self, mechanism: &SliderCrank, units: &Units) -> Value {
        serde_json::to_value(self.json(mechanism, units)).unwrap_or(Value::Null)
    }
}
