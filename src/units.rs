//! Unit names: what the numbers of a figure, table or JSON object are in.
//!
//! Units are names only. The crate never converts a number: the user's
//! lengths are in the user's unit, and the names say which, in notes, axis
//! titles, table headers and JSON. Speeds are written `<length>/s`,
//! accelerations `<length>/s²`, torques `<force>·<length>`; angular rates
//! are always rad/s and rad/s².

use crate::error::{Error, Input, Result};
use serde::{Deserialize, Deserializer, Serialize, Serializer};
use std::borrow::Cow;
use std::fmt;
use std::str::FromStr;

/// Longest unit name, in characters.
pub const MAX_UNIT_CHARS: usize = 16;

/// Characters a unit name may not hold: XML markup and the markup of the
/// figures' notes (`*` italic, `_` subscript, `{}` grouping), quotes and
/// backslashes.
const FORBIDDEN: [char; 11] = ['<', '>', '&', '"', '\'', '*', '_', '{', '}', '\\', '`'];

/// The name of a unit (`mm`, `ft`, `N`, `lbf`): 1 to [`MAX_UNIT_CHARS`]
/// printable characters, no spaces, no markup. Made by [`Unit::new`] or
/// [`str::parse`], which check the name once; every `Unit` is valid.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct Unit(Cow<'static, str>);

impl Unit {
    /// Feet, the length unit of the textbook's figures.
    pub const FOOT: Unit = Unit(Cow::Borrowed("ft"));
    /// Millimetres, the length unit of Ng's figures.
    pub const MILLIMETRE: Unit = Unit(Cow::Borrowed("mm"));
    /// Pounds-force, the force unit of the textbook's figures.
    pub const POUND_FORCE: Unit = Unit(Cow::Borrowed("lbf"));
    /// Newtons, the force unit of Ng's figures.
    pub const NEWTON: Unit = Unit(Cow::Borrowed("N"));

    /// The unit of that name; an error (one line) says what a name may
    /// hold when it is empty, longer than [`MAX_UNIT_CHARS`], a number
    /// (`NaN`, `inf`, `2`), or holds a space, a control character or
    /// markup (`< > & " ' * _ { } \` and the backquote).
    pub fn new(name: &str) -> Result<Self> {
        let shown: String = name
            .chars()
            .take(MAX_UNIT_CHARS + 4)
            .flat_map(char::escape_default)
            .collect();
        let bad = |why: &str| {
            Err(Error::invalid(
                Input::Unit,
                format!(
                    "invalid unit name '{shown}': {why} (a unit name is 1 to {MAX_UNIT_CHARS} printable characters without spaces or any of < > & \" ' * _ {{ }} \\ `, such as mm, in, N, lbf)"
                ),
            ))
        };
        if name.is_empty() {
            return bad("it is empty");
        }
        if name.chars().count() > MAX_UNIT_CHARS {
            return bad("it is too long");
        }
        if let Some(why) = crate::error::text_fault(name) {
            return bad(&why);
        }
        if name.parse::<f64>().is_ok() {
            // "NaN" or "inf" written as a unit read as a broken number.
            return bad("it is a number");
        }
        if let Some(c) = name
            .chars()
            .find(|c| c.is_whitespace() || FORBIDDEN.contains(c))
        {
            let what = if c.is_whitespace() {
                "a space".to_string()
            } else {
                format!("the character {c}")
            };
            return bad(&format!("it holds {what}"));
        }
        Ok(Unit(Cow::Owned(name.to_string())))
    }

    /// The name.
    pub fn as_str(&self) -> &str {
        &self.0
    }

    /// The force unit that goes with this length unit: newtons with the
    /// metric lengths (`mm`, `cm`, `m`, `km`, `µm`), pounds-force with the
    /// imperial ones (`in`, `ft`, `yd`, `mi`); `None` for any other name
    /// (a force unit, `cm/10`), which has no usual partner.
    pub fn usual_force(&self) -> Option<Unit> {
        match self.as_str() {
            "mm" | "cm" | "dm" | "m" | "km" | "µm" | "um" | "μm" | "nm" => Some(Unit::NEWTON),
            "in" | "ft" | "yd" | "mi" => Some(Unit::POUND_FORCE),
            _ => None,
        }
    }
}

impl FromStr for Unit {
    type Err = Error;

    fn from_str(s: &str) -> Result<Self> {
        Unit::new(s)
    }
}

impl fmt::Display for Unit {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl Serialize for Unit {
    fn serialize<S: Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        s.serialize_str(&self.0)
    }
}

impl<'de> Deserialize<'de> for Unit {
    fn deserialize<D: Deserializer<'de>>(d: D) -> std::result::Result<Self, D::Error> {
        let name = String::deserialize(d)?;
        Unit::new(&name).map_err(serde::de::Error::custom)
    }
}

/// The units of a figure, table or JSON object: a length unit and a force
/// unit, from which the others are named ([`Units::velocity`],
/// [`Units::acceleration`], [`Units::torque`]).
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct Units {
    length: Unit,
    force: Unit,
}

impl Units {
    /// Feet and pounds-force: the textbook's (the §35 engine), and the
    /// default of the command line's numbers and of [`crate::scene::Scene::new`].
    pub const FOOT_POUND: Units = Units {
        length: Unit::FOOT,
        force: Unit::POUND_FORCE,
    };
    /// Millimetres and newtons: Ng's.
    pub const MILLIMETRE_NEWTON: Units = Units {
        length: Unit::MILLIMETRE,
        force: Unit::NEWTON,
    };

    /// Lengths in `length`, forces in `force`.
    pub fn new(length: Unit, force: Unit) -> Self {
        Self { length, force }
    }

    /// The same with another length unit.
    pub fn with_length(mut self, length: Unit) -> Self {
        self.length = length;
        self
    }

    /// The same with another force unit.
    pub fn with_force(mut self, force: Unit) -> Self {
        self.force = force;
        self
    }

    /// These units with `length` and `force` in place of their own, as a
    /// user asks for them: a length unit given without a force unit brings
    /// the force unit that goes with it ([`Unit::usual_force`]: `mm` brings
    /// `N`, `in` brings `lbf`), so that millimetres never meet
    /// pounds-force unless asked. With neither given, the units unchanged;
    /// a length unit with no usual partner keeps the force unit.
    pub fn asked(self, length: Option<&Unit>, force: Option<&Unit>) -> Self {
        let force = force
            .cloned()
            .or_else(|| length.and_then(Unit::usual_force))
            .unwrap_or(self.force);
        Units {
            length: length.cloned().unwrap_or(self.length),
            force,
        }
    }

    /// The unit of lengths (`mm`).
    pub fn length(&self) -> &Unit {
        &self.length
    }

    /// The unit of forces (`N`).
    pub fn force(&self) -> &Unit {
        &self.force
    }

    /// The unit of speeds: the length unit per second (`mm/s`).
    pub fn velocity(&self) -> String {
        format!("{}/s", self.length)
    }

    /// The unit of accelerations: the length unit per second squared
    /// (`mm/s²`).
    pub fn acceleration(&self) -> String {
        format!("{}/s²", self.length)
    }

    /// The unit of torques: force times length (`N·mm`).
    pub fn torque(&self) -> String {
        format!("{}·{}", self.force, self.length)
    }

    /// The unit of pressures: force per length squared (`N/mm²`), the
    /// unit an indicator diagram's pressures are in for these units.
    pub fn pressure(&self) -> String {
        format!("{}/{}²", self.force, self.length)
    }

    /// Whether `name` is the unit of pressures of these units
    /// ([`Units::pressure`]): written `N/mm²`, `N/mm^2` or `N/mm2`, or by
    /// a name of its own (`MPa` for N/mm², `Pa` for N/m², `kPa` for kN/m²,
    /// `GPa` for kN/mm², `psi` for lbf/in², `psf` for lbf/ft²). Names
    /// only, as everywhere: `psi` with millimetres and newtons, or `bar`
    /// with anything, is another unit and is false.
    pub fn is_pressure(&self, name: &str) -> bool {
        let (f, l) = (self.force.as_str(), self.length.as_str());
        let spelled = ["²", "^2", "2"]
            .iter()
            .any(|sq| name == format!("{f}/{l}{sq}"));
        let named = matches!(
            (name, f, l),
            ("Pa", "N", "m")
                | ("kPa", "kN", "m")
                | ("MPa", "N", "mm")
                | ("GPa", "kN", "mm")
                | ("psi", "lbf", "in")
                | ("psf", "lbf", "ft")
        );
        spelled || named
    }

    /// The unit of mass the forces imply, FORCE·s²/LENGTH, by its name
    /// where the pair is a coherent system: `kg` with N and m, `slug` with
    /// lbf and ft, `t` with N and mm or kN and m; otherwise as derived
    /// (`lbf·s²/in`). A name only: nothing is converted.
    pub fn mass(&self) -> String {
        match self.coherent_mass() {
            Some(name) => name.to_string(),
            None => format!("{}·s²/{}", self.force, self.length),
        }
    }

    /// The unit of a moment of inertia, FORCE·s²·LENGTH = mass × length²:
    /// `kg·m²`, `slug·ft²`, `t·mm²` (N and mm), `t·m²` (kN and m), or as
    /// derived (`lbf·s²·in`).
    pub fn moment_of_inertia(&self) -> String {
        match self.coherent_mass() {
            Some(name) => format!("{name}·{}²", self.length),
            None => format!("{}·s²·{}", self.force, self.length),
        }
    }

    /// The name of FORCE·s²/LENGTH where the pair is a coherent system.
    fn coherent_mass(&self) -> Option<&'static str> {
        match (self.force.as_str(), self.length.as_str()) {
            ("N", "m") => Some("kg"),
            ("lbf", "ft") => Some("slug"),
            ("N", "mm") | ("kN", "m") => Some("t"),
            _ => None,
        }
    }
}

impl Default for Units {
    /// [`Units::FOOT_POUND`].
    fn default() -> Self {
        Units::FOOT_POUND
    }
}

impl Serialize for Units {
    /// `{"length": "mm", "force": "N", "velocity": "mm/s", "acceleration":
    /// "mm/s²", "torque": "N·mm", "angular_velocity": "rad/s",
    /// "angular_acceleration": "rad/s²"}`.
    fn serialize<S: Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        use serde::ser::SerializeMap;
        let mut m = s.serialize_map(Some(7))?;
        m.serialize_entry("length", self.length.as_str())?;
        m.serialize_entry("force", self.force.as_str())?;
        m.serialize_entry("velocity", &self.velocity())?;
        m.serialize_entry("acceleration", &self.acceleration())?;
        m.serialize_entry("torque", &self.torque())?;
        m.serialize_entry("angular_velocity", "rad/s")?;
        m.serialize_entry("angular_acceleration", "rad/s²")?;
        m.end()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_are_checked_once() {
        for good in [
            "mm", "m", "in", "ft", "N", "kN", "lbf", "µm", "N·m", "cm/10",
        ] {
            assert_eq!(good.parse::<Unit>().unwrap().as_str(), good);
        }
        for bad in [
            "",
            "m m",
            " mm",
            "mm\n",
            "<b>",
            "a&b",
            "*m*",
            "m_s",
            "{m}",
            "\"",
            "abcdefghijklmnopq",
            "m\u{FFFF}",
            "m\u{FDD0}",
            "m\u{202E}",
            "\u{2066}m",
            "m\u{200B}",
            "\u{FEFF}mm",
            "NaN",
            "inf",
            "-inf",
            "2",
        ] {
            let e = bad.parse::<Unit>().unwrap_err().to_string();
            assert!(e.starts_with("invalid unit name"), "{bad}: {e}");
            assert!(!e.contains('\n'), "{e}");
        }
        assert!("abcdefghijklmnop".parse::<Unit>().is_ok());
    }

    #[test]
    fn masses_and_inertias_are_named_in_coherent_systems() {
        let units = |l: &str, f: &str| Units::new(l.parse().unwrap(), f.parse().unwrap());
        assert_eq!(units("m", "N").mass(), "kg");
        assert_eq!(units("m", "N").moment_of_inertia(), "kg·m²");
        assert_eq!(Units::FOOT_POUND.mass(), "slug");
        assert_eq!(Units::FOOT_POUND.moment_of_inertia(), "slug·ft²");
        assert_eq!(Units::MILLIMETRE_NEWTON.mass(), "t");
        assert_eq!(Units::MILLIMETRE_NEWTON.moment_of_inertia(), "t·mm²");
        assert_eq!(units("m", "kN").mass(), "t");
        assert_eq!(units("in", "lbf").mass(), "lbf·s²/in");
        assert_eq!(units("in", "lbf").moment_of_inertia(), "lbf·s²·in");
    }

    #[test]
    fn pressures_are_named_in_the_units_or_by_their_own_names() {
        let units = |l: &str, f: &str| Units::new(l.parse().unwrap(), f.parse().unwrap());
        let mm = Units::MILLIMETRE_NEWTON;
        assert_eq!(mm.pressure(), "N/mm²");
        for yes in ["N/mm²", "N/mm^2", "N/mm2", "MPa"] {
            assert!(mm.is_pressure(yes), "{yes}");
        }
        for no in ["lbf/ft²", "psi", "Pa", "bar", "N/m²", "N/mm", ""] {
            assert!(!mm.is_pressure(no), "{no}");
        }
        assert!(Units::FOOT_POUND.is_pressure("lbf/ft²"));
        assert!(Units::FOOT_POUND.is_pressure("psf"));
        assert!(!Units::FOOT_POUND.is_pressure("psi"));
        assert!(units("m", "N").is_pressure("Pa"));
        assert!(units("m", "kN").is_pressure("kPa"));
        assert!(units("in", "lbf").is_pressure("psi"));
    }

    #[test]
    fn derived_names() {
        let u = Units::new(Unit::MILLIMETRE, "kN".parse().unwrap());
        assert_eq!(u.velocity(), "mm/s");
        assert_eq!(u.acceleration(), "mm/s²");
        assert_eq!(u.torque(), "kN·mm");
        let json = serde_json::to_value(&u).unwrap();
        assert_eq!(json["length"], "mm");
        assert_eq!(json["force"], "kN");
        assert_eq!(json["velocity"], "mm/s");
        assert_eq!(Units::default(), Units::FOOT_POUND);
    }

    #[test]
    fn a_length_unit_brings_its_force_unit() {
        let unit = |s: &str| s.parse::<Unit>().unwrap();
        let textbook = Units::FOOT_POUND;
        let mm = textbook.clone().asked(Some(&unit("mm")), None);
        assert_eq!(mm.force().as_str(), "N");
        assert_eq!(mm.torque(), "N·mm");
        let m = Units::MILLIMETRE_NEWTON.asked(Some(&unit("in")), None);
        assert_eq!(m.torque(), "lbf·in");
        // Asked for both: both as given, however odd.
        let both = textbook
            .clone()
            .asked(Some(&unit("mm")), Some(&unit("lbf")));
        assert_eq!(both.torque(), "lbf·mm");
        // A name with no usual partner keeps the force unit.
        let odd = textbook.clone().asked(Some(&unit("cubit")), None);
        assert_eq!(odd.torque(), "lbf·cubit");
        assert_eq!(textbook.clone().asked(None, None), textbook);
        let kn = textbook.asked(None, Some(&unit("kN")));
        assert_eq!(kn.torque(), "kN·ft");
    }
}
