//! An engine assembled from the parts a user gives: the command line's
//! options and the Python package's keywords build it the same way.

use super::{Engine, GasForce, IndicatorDiagram, RodMass};
use crate::error::Result;
use crate::mechanism::SliderCrank;
use crate::units::Units;

/// An indicator diagram as given: the CSV text, the cylinder's bore and
/// the name of the source for messages.
#[derive(Debug, Clone, Copy)]
pub struct IndicatorText<'a> {
    /// The CSV text (columns fraction, expansion, compression, and for a
    /// four-stroke cycle exhaust and intake).
    pub text: &'a str,
    /// The cylinder's bore D, in the length unit.
    pub bore: f64,
    /// What errors call the source (`indicator diagram FILE`).
    pub what: &'a str,
    /// The units the engine is given in, against which a unit the CSV's
    /// header declares for its pressures is checked
    /// ([`IndicatorDiagram::check_units`]); `None` not to check.
    pub units: Option<&'a Units>,
}

/// The parts of an engine besides its mechanism and speed, each as given
/// (`None`: not given).
#[derive(Debug, Clone, Copy, Default)]
pub struct EngineParts<'a> {
    /// Reciprocating mass m (0 when not given).
    pub mass: Option<f64>,
    /// The rod's mass, its centre of mass BG from the crank pin and its
    /// radius of gyration.
    pub rod: Option<(f64, f64, f64)>,
    /// A constant gas force on the piston.
    pub gas_force: Option<f64>,
    /// An indicator diagram (one turn, or a four-stroke cycle of two).
    pub indicator: Option<IndicatorText<'a>>,
    /// Gravity's acceleration ([`Engine::with_gravity`]).
    pub gravity: Option<[f64; 2]>,
    /// The slider's coefficient of friction ([`Engine::with_friction`]).
    pub friction: Option<f64>,
}

impl EngineParts<'_> {
    /// The engine of `mechanism` at crank speed `omega` (rad/s) with these
    /// parts, validated by [`Engine`] (its gravity and friction too), [`RodMass`] and
    /// [`IndicatorDiagram::from_csv_cycle`]. A constant gas force and an
    /// indicator diagram together: the diagram is the engine's gas force
    /// (callers refuse the pair before, naming their own flags).
    pub fn build(&self, mechanism: SliderCrank, omega: f64) -> Result<Engine> {
        let mut engine = Engine::new(mechanism, self.mass.unwrap_or(0.0), omega)?;
        if let Some((m, cg, k)) = self.rod {
            engine = engine.with_rod(RodMass::new(m, cg, k)?)?;
        }
        if let Some(f) = self.gas_force {
            engine = engine.with_gas(GasForce::Constant(f))?;
        }
        if let Some(d) = self.indicator {
            let diagram = IndicatorDiagram::from_csv_cycle(d.text, d.bore, d.what)?;
            if let Some(units) = d.units {
                diagram.check_units(units, d.what)?;
            }
            engine = engine.with_gas(GasForce::Indicator(diagram))?;
        }
        if let Some(g) = self.gravity {
            engine = engine.with_gravity(g)?;
        }
        if let Some(mu) = self.friction {
            engine = engine.with_friction(mu)?;
        }
        Ok(engine)
    }
}
