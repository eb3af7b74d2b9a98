//! The JSON form of a point and of where two lines meet, written once:
//! `[x, y]`, `{"at_infinity": [dx, dy]}` for parallel lines, and
//! `{"indeterminate": true}` for one line twice. The analysis's JSON, the
//! chain's centres and the figures' metadata all write it here, each
//! number passed through the writer's own rounding.

use super::{Intersection, Point};
use serde::ser::{Serialize, SerializeMap, Serializer};

/// A point as JSON `[x, y]`, each coordinate passed through `.1`
/// ([`crate::number::unsigned_zero`] in the analysis's JSON, twelve digits in a figure's
/// metadata).
#[derive(Debug, Clone, Copy)]
pub struct PointJson(pub Point, pub fn(f64) -> f64);

impl Serialize for PointJson {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let PointJson(p, num) = *self;
        [num(p.x), num(p.y)].serialize(s)
    }
}

/// Where two lines meet as JSON, each number passed through `.1`: the
/// point `[x, y]`, `{"at_infinity": [dx, dy]}` (the direction of the
/// parallel lines), or `{"indeterminate": true}` (one line twice, which
/// leaves the point anywhere on it).
#[derive(Debug, Clone, Copy)]
pub struct MeetJson<'a>(pub &'a Intersection, pub fn(f64) -> f64);

impl MeetJson<'_> {
    /// The same JSON as a value (for a map built as a tree).
    pub fn value(&self) -> serde_json::Value {
        // Numbers and one-key maps serialise to a value without failing.
        serde_json::to_value(self).unwrap_or(serde_json::Value::Null)
    }
}

impl Serialize for MeetJson<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let MeetJson(meet, num) = *self;
        match meet {
            Intersection::Point(p) => PointJson(*p, num).serialize(s),
            Intersection::AtInfinity(d) => {
                let mut m = s.serialize_map(Some(1))?;
                m.serialize_entry("at_infinity", &[num(d.x), num(d.y)])?;
                m.end()
            }
            Intersection::Coincident => {
                let mut m = s.serialize_map(Some(1))?;
                m.serialize_entry("indeterminate", &true)?;
                m.end()
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::Vector;
    use crate::number::unsigned_zero;
    use nalgebra::Unit;

    #[test]
    fn each_meeting_has_its_form() {
        let at = |m: &Intersection| MeetJson(m, unsigned_zero).value().to_string();
        assert_eq!(at(&Intersection::Point(Point::new(-0.0, 2.5))), "[0.0,2.5]");
        let d = Unit::new_normalize(Vector::new(0.0, -1.0));
        assert_eq!(
            at(&Intersection::AtInfinity(d)),
            r#"{"at_infinity":[0.0,-1.0]}"#
        );
        assert_eq!(at(&Intersection::Coincident), r#"{"indeterminate":true}"#);
        // The value and the stream are one writer.
        let streamed =
            serde_json::to_string(&MeetJson(&Intersection::AtInfinity(d), unsigned_zero)).unwrap();
        assert_eq!(streamed, r#"{"at_infinity":[0.0,-1.0]}"#);
        assert_eq!(unsigned_zero(-0.0).to_bits(), 0.0f64.to_bits());
    }
}
