//! The engine the dynamics fields of a request give (`table dynamics`,
//! `analyze`): the reciprocating mass, the rod, a constant gas force or
//! an indicator diagram read from a file, built once for both.

use crate::dynamics::{Engine, EngineParts, IndicatorText};
use crate::error::{Input, Result};
use crate::files::{MAX_DATA_BYTES, read_text};
use crate::mechanism::SliderCrank;
use crate::units::Units;
use std::path::Path;

/// The dynamics fields as a request holds them, each `None` where not
/// given. The rod counts only with all three of its values (a front end
/// refuses one without the others); the bore only with an indicator.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct GivenEngine<'p> {
    /// The reciprocating mass m.
    pub mass: Option<f64>,
    /// The rod's mass.
    pub rod_mass: Option<f64>,
    /// The rod's centre of mass BG from the crank pin.
    pub rod_cg: Option<f64>,
    /// The rod's radius of gyration.
    pub rod_gyration: Option<f64>,
    /// A constant gas force on the piston.
    pub gas_force: Option<f64>,
    /// The file of an indicator diagram.
    pub indicator: Option<&'p Path>,
    /// The cylinder's bore, the indicator diagram's.
    pub bore: Option<f64>,
}

impl GivenEngine<'_> {
    /// Whether any of the fields that make an engine (mass, rod, gas
    /// force, indicator) is given.
    pub fn is_given(&self) -> bool {
        self.mass.is_some()
            || self.rod_mass.is_some()
            || self.gas_force.is_some()
            || self.indicator.is_some()
    }

    /// The engine of `mechanism` at `omega` (rad/s) these fields ask for,
    /// the indicator's pressures read in `units`; `None` where none is
    /// given ([`GivenEngine::is_given`]).
    ///
    /// Errors: the indicator file unreadable or larger than
    /// [`MAX_DATA_BYTES`], and what [`EngineParts::build`] refuses.
    pub fn engine(
        &self,
        mechanism: SliderCrank,
        omega: f64,
        units: &Units,
    ) -> Result<Option<Engine>> {
        if !self.is_given() {
            return Ok(None);
        }
        let text = match self.indicator {
            Some(path) => Some((
                read_text(path, MAX_DATA_BYTES, Input::Indicator)?,
                format!("indicator diagram {}", path.display()),
            )),
            None => None,
        };
        let parts = EngineParts {
            mass: self.mass,
            rod: self
                .rod_mass
                .zip(self.rod_cg)
                .zip(self.rod_gyration)
                .map(|((m, cg), k)| (m, cg, k)),
            gas_force: self.gas_force,
            indicator: text
                .as_ref()
                .zip(self.bore)
                .map(|((text, what), bore)| IndicatorText {
                    text,
                    bore,
                    what,
                    units: Some(units),
                }),
        };
        Ok(Some(parts.build(mechanism, omega)?))
    }
}
