//! The dynamics a handout is asked for: the reciprocating mass, the
//! coefficient of fluctuation of speed and the gas force, in the
//! handout's units: the example's steam indicator diagram (lbf/ft² on a
//! 10 in bore) only where they are feet and pounds-force, else the
//! engine's own diagram and bore or a constant force.

use super::Dynamics;
use crate::dynamics::{GasForce, IndicatorDiagram, checked_coefficient, example_indicator};
use crate::error::{Error, Field, Input, Result, Spelling, finite, positive};
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
    /// declares ([`IndicatorDiagram::check_units`]). `spelling` names the
    /// options in the example's refusal.
    pub(super) fn diagram(
        &self,
        units: &Units,
        spelling: Spelling,
    ) -> Result<Option<IndicatorDiagram>> {
        match self {
            Gas::Example => {
                let own = format!(
                    "{} with {}, or {}",
                    spelling.set("indicator", "CSV"),
                    spelling.set("bore", "D"),
                    spelling.set("gas-force", "F")
                );
                example_indicator(units, &own).map(Some)
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
    pub(super) fn force(&self, units: &Units, spelling: Spelling) -> Result<GasForce> {
        Ok(match (self, self.diagram(units, spelling)?) {
            (Gas::Constant(f), _) => GasForce::Constant(*f),
            (_, Some(d)) => GasForce::Indicator(d),
            (_, None) => GasForce::None,
        })
    }
}

/// The dynamics a handout is asked for, each as given (`None`: not
/// given), filled alike by the command line's flags and the Python
/// package's keywords and validated once by
/// [`super::Handout::with_dynamics_asked`].
#[derive(Debug, Clone, Default, PartialEq)]
pub struct DynamicsAsk {
    /// The reciprocating mass m (`--mass`); without it nothing else is
    /// taken.
    pub mass: Option<f64>,
    /// The coefficient of fluctuation of speed (`--fluctuation`; 0.02 when
    /// not given).
    pub fluctuation: Option<f64>,
    /// A constant gas force (`--gas-force`).
    pub gas_force: Option<f64>,
    /// An indicator diagram (`--indicator`): its CSV text and the file it
    /// was read from, as the user gave it.
    pub indicator: Option<(String, String)>,
    /// The bore of the diagram's cylinder (`--bore`), in the length unit.
    pub bore: Option<f64>,
    /// How the messages name the options: `--bore` or `bore=`.
    pub spelling: Spelling,
}

impl DynamicsAsk {
    /// The dynamics asked for, `None` without a mass; the gas force not
    /// yet checked against the units.
    pub(super) fn dynamics(&self) -> Result<Option<Dynamics>> {
        let sp = self.spelling;
        let refuse = |why: String| Err(Error::invalid(Input::Options, why));
        let Some(mass) = self.mass else {
            let given = [
                ("fluctuation", self.fluctuation.is_some()),
                ("gas-force", self.gas_force.is_some()),
                ("indicator", self.indicator.is_some()),
                ("bore", self.bore.is_some()),
            ];
            return match given.iter().find(|(_, g)| *g) {
                Some((name, _)) => refuse(format!(
                    "{} is for the dynamics, which need the reciprocating mass: give {} with it",
                    sp.option(name),
                    sp.set("mass", "M")
                )),
                None => Ok(None),
            };
        };
        let gas = match (self.gas_force, &self.indicator, self.bore) {
            (Some(_), Some(_), _) => {
                return refuse(format!(
                    "give the gas force as a constant ({}) or by an indicator diagram ({} and {}), not both",
                    sp.option("gas-force"),
                    sp.option("indicator"),
                    sp.option("bore")
                ));
            }
            (Some(f), None, None) => Gas::Constant(finite(Field::GasForce, f)?),
            (None, Some(_), None) => {
                return refuse(format!(
                    "an indicator diagram acts on the cylinder's bore: give {} with {}",
                    sp.set("bore", "D"),
                    sp.option("indicator")
                ));
            }
            (_, None, Some(_)) => {
                return refuse(format!(
                    "{} is the bore of the indicator diagram's cylinder: give {} with it",
                    sp.option("bore"),
                    sp.set("indicator", "CSV")
                ));
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
            spelling: sp,
        }))
    }
}
