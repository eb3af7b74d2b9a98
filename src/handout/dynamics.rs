//! The dynamics a handout is asked for: the reciprocating mass, the
//! coefficient of fluctuation of speed and the gas force, in the
//! handout's units: the example's steam indicator diagram (lbf/ft² on a
//! 10 in bore) only where they are feet and pounds-force, else the
//! engine's own diagram and bore or a constant force.

use super::Dynamics;
use crate::dynamics::{GasForce, IndicatorDiagram, checked_coefficient, example_indicator};
use crate::error::{Error, Field, Input, Result, Wording, finite, positive};
use crate::units::Units;

/// The gas force on the piston of a handout's dynamics.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum Gas {
    /// The example: the turning-moment figure's steam indicator diagram
    /// (`examples/indicator.csv`, lbf/ft² on a 10 in bore), for an engine
    /// in feet and pounds-force only.
    Example,
    /// A constant force, positive towards the crank centre, in the force
    /// unit.
    Constant(f64),
    /// The engine's own indicator diagram (one turn: fraction,
    /// expansion, compression), on a cylinder of bore `bore` in the
    /// length unit; `source` is the file as given, named in messages and
    /// in the page's command.
    Indicator {
        /// The CSV text.
        text: String,
        /// The cylinder's bore D.
        bore: f64,
        /// The file it was read from, as the user gave it.
        source: String,
    },
}

impl Gas {
    /// The indicator diagram of this gas force in `units` (`None` for a
    /// constant force), refused where its units are not `units`: the
    /// example's are feet and pounds-force, a diagram's those its header
    /// declares ([`IndicatorDiagram::check_units`]).
    pub(super) fn diagram(&self, units: &Units) -> Result<Option<IndicatorDiagram>> {
        match self {
            Gas::Example => {
                let own = Wording::default()
                    .set(Field::Indicator, "CSV")
                    .then(" with ")
                    .set(Field::Bore, "D")
                    .then(", or ")
                    .set(Field::GasForce, "F");
                example_indicator(units, own).map(Some)
            }
            Gas::Constant(_) => Ok(None),
            Gas::Indicator { text, bore, source } => {
                let what = format!("indicator diagram {source}");
                let d = IndicatorDiagram::from_csv(text, *bore, &what)?;
                d.check_units(units, &what)?;
                Ok(Some(d))
            }
        }
    }

    /// The engine's gas force in `units`, as [`Gas::diagram`] refuses.
    pub(super) fn force(&self, units: &Units) -> Result<GasForce> {
        Ok(match (self, self.diagram(units)?) {
            (Gas::Constant(f), _) => GasForce::Constant(*f),
            (_, Some(d)) => GasForce::Indicator(d),
            (_, None) => GasForce::None,
        })
    }
}

/// The dynamics a handout is asked for, each as given (`None`: not
/// given), filled alike by the command line and the Python package and
/// validated once by [`super::Handout::with_dynamics_asked`], whose
/// refusals name the fields ([`Field::Mass`] …), each front end
/// spelling them its way.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct DynamicsAsk {
    /// The reciprocating mass m ([`Field::Mass`]); without it nothing
    /// else is taken.
    pub mass: Option<f64>,
    /// The coefficient of fluctuation of speed ([`Field::Fluctuation`];
    /// 0.02 when not given).
    pub fluctuation: Option<f64>,
    /// A constant gas force ([`Field::GasForce`]).
    pub gas_force: Option<f64>,
    /// An indicator diagram ([`Field::Indicator`]): its CSV text and the
    /// file it was read from, as the user gave it.
    pub indicator: Option<(String, String)>,
    /// The bore of the diagram's cylinder ([`Field::Bore`]), in the
    /// length unit.
    pub bore: Option<f64>,
}

impl DynamicsAsk {
    /// The dynamics asked for, `None` without a mass; the gas force not
    /// yet checked against the units.
    pub(super) fn dynamics(&self) -> Result<Option<Dynamics>> {
        let refuse = |why: Wording| Err(Error::refused(Input::Options, why));
        let Some(mass) = self.mass else {
            let given = [
                (Field::Fluctuation, self.fluctuation.is_some()),
                (Field::GasForce, self.gas_force.is_some()),
                (Field::Indicator, self.indicator.is_some()),
                (Field::Bore, self.bore.is_some()),
            ];
            return match given.iter().find(|(_, g)| *g) {
                Some((field, _)) => refuse(
                    Wording::default()
                        .option(*field)
                        .then(" is for the dynamics, which need the reciprocating mass: give ")
                        .set(Field::Mass, "M")
                        .then(" with it"),
                ),
                None => Ok(None),
            };
        };
        let gas = match (self.gas_force, &self.indicator, self.bore) {
            (Some(_), Some(_), _) => {
                return refuse(
                    Wording::from("give the gas force as a constant (")
                        .option(Field::GasForce)
                        .then(") or by an indicator diagram (")
                        .option(Field::Indicator)
                        .then(" and ")
                        .option(Field::Bore)
                        .then("), not both"),
                );
            }
            (Some(f), None, None) => Gas::Constant(finite(Field::GasForce, f)?),
            (None, Some(_), None) => {
                return refuse(
                    Wording::from("an indicator diagram acts on the cylinder's bore: give ")
                        .set(Field::Bore, "D")
                        .then(" with ")
                        .option(Field::Indicator),
                );
            }
            (_, None, Some(_)) => {
                return refuse(
                    Wording::default()
                        .option(Field::Bore)
                        .then(" is the bore of the indicator diagram's cylinder: give ")
                        .set(Field::Indicator, "CSV")
                        .then(" with it"),
                );
            }
            (None, Some((text, source)), Some(bore)) => Gas::Indicator {
                text: text.clone(),
                bore: positive(Field::Bore, bore)?,
                source: source.clone(),
            },
            (None, None, None) => Gas::Example,
        };
        Ok(Some(Dynamics {
            mass: positive(Field::Mass, mass)?,
            fluctuation: checked_coefficient(
                self.fluctuation
                    .unwrap_or(crate::dynamics::DEFAULT_FLUCTUATION),
            )?,
            gas,
        }))
    }
}
