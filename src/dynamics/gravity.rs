//! Gravity in a vertical engine: the direction of the weights along the
//! line of stroke, and standard gravity in the engine's length unit.

use crate::error::{Error, Field, Input, Result, Wording};
use crate::units::Unit;

/// Standard gravity g₀ = 9.806 65 m/s² (exact by definition), in m/s².
pub const STANDARD_GRAVITY: f64 = 9.80665;

/// Which way gravity points along the line of stroke (x from the crank
/// centre towards the slider): a vertical engine.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Gravity {
    /// Towards the crank centre (−x): the cylinder above the crank, the
    /// usual vertical engine.
    TowardsCrank,
    /// Away from the crank centre (+x): the cylinder below the crank (an
    /// inverted engine).
    AwayFromCrank,
}

crate::error::parse_by_name!(Gravity);

impl Gravity {
    /// The value's name as the options write it.
    pub fn name(self) -> &'static str {
        match self {
            Gravity::TowardsCrank => "towards-crank",
            Gravity::AwayFromCrank => "away-from-crank",
        }
    }

    /// The value named `name` (`towards-crank`, `away-from-crank`).
    ///
    /// Errors: any other name.
    pub fn from_name(name: &str) -> Result<Self> {
        match name {
            "towards-crank" => Ok(Gravity::TowardsCrank),
            "away-from-crank" => Ok(Gravity::AwayFromCrank),
            other => Err(Error::refused(
                Input::Options,
                Wording::from(format!(
                    "unknown gravity '{}': expected towards-crank (the cylinder above the crank) or away-from-crank (below it)",
                    Error::show(other)
                )),
            )),
        }
    }

    /// The acceleration of gravity as a vector (x along the line of
    /// stroke, y across it) for g = `g` in length units per s².
    pub fn vector(self, g: f64) -> [f64; 2] {
        match self {
            Gravity::TowardsCrank => [-g, 0.0],
            Gravity::AwayFromCrank => [g, 0.0],
        }
    }

    /// Standard gravity along the line of stroke in `unit` per s², for the
    /// lengths the crate knows (mm, cm, dm, m, km, in, ft, yd).
    ///
    /// Errors: another unit, in which g cannot be given.
    pub fn in_unit(self, unit: &Unit) -> Result<[f64; 2]> {
        let metres = match unit.as_str() {
            "mm" => 1e-3,
            "cm" => 1e-2,
            "dm" => 1e-1,
            "m" => 1.0,
            "km" => 1e3,
            "in" => 0.0254,
            "ft" => 0.3048,
            "yd" => 0.9144,
            other => {
                return Err(Error::refused(
                    Input::Options,
                    Wording::default().option(Field::Gravity).then(format!(
                        " needs g in the length unit, and '{other}' is not one of mm, cm, dm, m, km, in, ft or yd"
                    )),
                ));
            }
        };
        Ok(self.vector(STANDARD_GRAVITY / metres))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn standard_gravity_in_each_unit() {
        let down = Gravity::TowardsCrank;
        assert_eq!(
            down.in_unit(&Unit::new("m").unwrap()).unwrap(),
            [-9.80665, 0.0]
        );
        let mm = down.in_unit(&Unit::MILLIMETRE).unwrap()[0];
        assert!((mm + 9806.65).abs() < 1e-9);
        // 32.174 ft/s², the textbooks' g in feet.
        let ft = Gravity::AwayFromCrank.in_unit(&Unit::FOOT).unwrap()[0];
        assert!((ft - 32.174_048_556).abs() < 1e-8, "{ft}");
        assert!(down.in_unit(&Unit::new("furlong").unwrap()).is_err());
        assert_eq!(Gravity::from_name("towards-crank").unwrap(), down);
        let e = Gravity::from_name("down").unwrap_err().to_string();
        assert!(e.contains("unknown gravity 'down'"), "{e}");
    }
}
