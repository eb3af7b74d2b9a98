//! The engine the dynamics fields of a request give (`table dynamics`,
//! `analyze`): the reciprocating mass, the rod, a constant gas force or
//! an indicator diagram read from a file, built once for both.

use crate::dynamics::{Engine, EngineParts, Gravity, IndicatorText};
use crate::error::{Error, Field, Input, Result, Wording};
use crate::files::{MAX_DATA_BYTES, read_text};
use crate::mechanism::SliderCrank;
use crate::units::Units;
use std::path::PathBuf;

/// The dynamics fields as a request holds them ([`super::TableRequest`]'s
/// and [`super::AnalyzeRequest`]'s `engine`), each `None` where not
/// given; a front end fills them in one place for every request. The rod
/// counts only with all three of its values (a request refuses one
/// without the others); the bore only with an indicator.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct GivenEngine {
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
    pub indicator: Option<PathBuf>,
    /// The cylinder's bore, the indicator diagram's.
    pub bore: Option<f64>,
    /// The direction of gravity along a vertical engine's line of stroke
    /// (standard gravity in the length unit); `None`: no gravity. Not an
    /// engine by itself ([`GivenEngine::is_given`]): it weighs the masses
    /// given.
    pub gravity: Option<Gravity>,
}

impl GivenEngine {
    /// Whether any of the fields that make an engine (mass, rod, gas
    /// force, indicator) is given.
    pub fn is_given(&self) -> bool {
        self.mass.is_some()
            || self.rod_mass.is_some()
            || self.gas_force.is_some()
            || self.indicator.is_some()
    }

    /// Refuses fields given that do not go together: a constant gas
    /// force and an indicator diagram, a part of the rod's mass without
    /// the rest, an indicator diagram without its bore or a bore without
    /// one; each named by its [`Field`].
    pub fn refuse_pairs(&self) -> Result<()> {
        refuse_both(
            self.gas_force.is_some(),
            self.indicator.is_some(),
            (Field::GasForce, Field::Indicator),
            "a constant gas force or an indicator diagram",
        )?;
        let rod = [
            (Field::RodMass, self.rod_mass.is_some()),
            (Field::RodCg, self.rod_cg.is_some()),
            (Field::RodGyration, self.rod_gyration.is_some()),
        ];
        if rod.iter().any(|r| r.1) && !rod.iter().all(|r| r.1) {
            let mut missing = Wording::default();
            for (i, (field, _)) in rod.iter().filter(|r| !r.1).enumerate() {
                missing = if i == 0 {
                    missing
                } else {
                    missing.then(" and ")
                }
                .option(*field);
            }
            return Err(Error::refused(
                Input::Options,
                Wording::from("the rod's mass is given by ")
                    .option(Field::RodMass)
                    .then(", ")
                    .option(Field::RodCg)
                    .then(" and ")
                    .option(Field::RodGyration)
                    .then(" together: ")
                    .and(missing)
                    .then(" not given"),
            ));
        }
        if self.indicator.is_some() != self.bore.is_some() {
            return Err(Error::refused(
                Input::Options,
                Wording::from("an indicator diagram needs the cylinder's bore: give ")
                    .option(Field::Indicator)
                    .then(" and ")
                    .option(Field::Bore)
                    .then(" together"),
            ));
        }
        Ok(())
    }

    /// The engine of `mechanism` at `omega` (rad/s) these fields ask for,
    /// the indicator's pressures read in `units`, with the slider's
    /// coefficient of friction `friction` in its guides (the request's
    /// `friction`, which its statics take too); `None` where none is
    /// given ([`GivenEngine::is_given`]).
    ///
    /// Errors: the indicator file unreadable or larger than
    /// [`MAX_DATA_BYTES`], gravity in a length unit g cannot be given in,
    /// and what [`EngineParts::build`] refuses (a self-locking μ).
    pub fn engine(
        &self,
        mechanism: SliderCrank,
        omega: f64,
        units: &Units,
        friction: Option<f64>,
    ) -> Result<Option<Engine>> {
        if !self.is_given() {
            return Ok(None);
        }
        let text = match &self.indicator {
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
            gravity: self.gravity(units)?,
            friction,
        };
        Ok(Some(parts.build(mechanism, omega)?))
    }

    /// Refuses gravity given without a mass to weigh (`analyze`, whose
    /// engine is only the one given; `table dynamics` weighs its example
    /// mass).
    pub fn refuse_gravity_alone(&self) -> Result<()> {
        if self.gravity.is_some() && self.mass.is_none() && self.rod_mass.is_none() {
            return Err(Error::refused(
                Input::Options,
                Wording::default()
                    .option(Field::Gravity)
                    .then(" weighs the engine's masses: give ")
                    .option(Field::Mass)
                    .then(" or ")
                    .option(Field::RodMass)
                    .then(" with it"),
            ));
        }
        Ok(())
    }

    /// Gravity's acceleration in `units`' length unit, `None` without.
    ///
    /// Errors: a length unit g cannot be given in ([`Gravity::in_unit`]).
    pub fn gravity(&self, units: &Units) -> Result<Option<[f64; 2]>> {
        self.gravity.map(|g| g.in_unit(units.length())).transpose()
    }
}

/// Refuses the fields `x` and `y` given together (`a` and `b` whether
/// each is given): give `what`, not both.
pub(super) fn refuse_both(a: bool, b: bool, (x, y): (Field, Field), what: &str) -> Result<()> {
    if a && b {
        Err(Error::refused(
            Input::Options,
            Wording::default()
                .option(x)
                .then(" cannot be used with ")
                .option(y)
                .then(format!(": give {what}, not both")),
        ))
    } else {
        Ok(())
    }
}
