//! The engine's dynamics for Python: an [`Engine`] built from the keywords
//! that mirror `analyze --mass …` and `table dynamics`'s flags, its
//! dynamics object at one pose (the `dynamics` member of `analyze --json`),
//! a sweep of its forces and torques into numpy rows, and the turn's
//! turning moment and flywheel.

use crate::{py_err, units};
use numpy::{PyReadonlyArray1, PyReadwriteArray2, PyUntypedArrayMethods};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use serde_json::json;
use slider_crank::dynamics::{
    Engine, EngineParts, EnginePose, Flywheel, FlywheelAsk, Gravity, IndicatorText, TurningMoment,
    unbalanced_forces,
};
use slider_crank::files::{MAX_DATA_BYTES, read_text};
use slider_crank::table::{GivenEngine, dynamics_json};
use slider_crank::{Angle, Input, SliderCrank, Unit};
use std::path::PathBuf;

/// An engine with its masses, gas force and crank speed, validated as
/// `analyze --mass … --rod-mass … --gas-force … --indicator … --bore …`
/// validate them (the library's checks and messages).
#[pyclass(module = "slider_crank._core", name = "Engine", frozen)]
pub struct PyEngine {
    engine: Engine,
}

#[pymethods]
impl PyEngine {
    /// The engine of crank `crank`, rod `rod`, offset `offset` at crank
    /// speed `omega` (rad/s) with reciprocating mass `mass` (0 when not
    /// given), a rod of mass `rod_mass` with its centre of mass `rod_cg`
    /// from the crank pin and radius of gyration `rod_gyration`, and a
    /// constant `gas_force` or the indicator diagram read from the CSV
    /// file `indicator` with the cylinder's `bore`; a unit the diagram's
    /// header declares for its pressures is checked against `unit` and
    /// `force_unit` where they are given, as `analyze` checks it;
    /// `gravity` (`towards-crank`, `away-from-crank`) a vertical engine's
    /// standard gravity in `unit` (feet when not given) and `friction` the
    /// slider's coefficient of friction in its guides.
    #[new]
    #[pyo3(signature = (crank, rod, offset, omega, mass=None, rod_mass=None, rod_cg=None,
        rod_gyration=None, gas_force=None, indicator=None, bore=None, unit=None, force_unit=None,
        gravity=None, friction=None))]
    #[allow(clippy::too_many_arguments)]
    fn new(
        crank: f64,
        rod: f64,
        offset: f64,
        omega: f64,
        mass: Option<f64>,
        rod_mass: Option<f64>,
        rod_cg: Option<f64>,
        rod_gyration: Option<f64>,
        gas_force: Option<f64>,
        indicator: Option<PathBuf>,
        bore: Option<f64>,
        unit: Option<&str>,
        force_unit: Option<&str>,
        gravity: Option<&str>,
        friction: Option<f64>,
    ) -> PyResult<Self> {
        let units = match unit.zip(force_unit) {
            Some((u, f)) => Some(units(u, f)?),
            None => None,
        };
        // The fields that go together, refused by the library's request
        // (`table dynamics`' and `analyze`'s) in the keywords' names.
        let given = GivenEngine {
            mass,
            rod_mass,
            rod_cg,
            rod_gyration,
            gas_force,
            indicator: indicator.clone(),
            bore,
            // Gravity pairs with no other field; it is read below.
            gravity: None,
        };
        given.refuse_pairs().map_err(py_err)?;
        let m = SliderCrank::new(crank, rod, offset).map_err(py_err)?;
        let text = match &indicator {
            Some(path) => Some((
                read_text(path, MAX_DATA_BYTES, Input::Indicator).map_err(py_err)?,
                format!("indicator diagram {}", path.display()),
            )),
            None => None,
        };
        let parts = EngineParts {
            mass,
            rod: rod_mass
                .zip(rod_cg)
                .zip(rod_gyration)
                .map(|((m, cg), k)| (m, cg, k)),
            gas_force,
            indicator: (text.as_ref().zip(bore)).map(|((text, what), bore)| IndicatorText {
                text,
                bore,
                what,
                units: units.as_ref(),
            }),
            gravity: match gravity {
                Some(g) => {
                    let length = Unit::new(unit.unwrap_or("ft")).map_err(py_err)?;
                    let g: Gravity = g.parse().map_err(py_err)?;
                    Some(g.in_unit(&length).map_err(py_err)?)
                }
                None => None,
            },
            friction,
        };
        Ok(Self {
            engine: parts.build(m, omega).map_err(py_err)?,
        })
    }

    /// The dynamics at `degrees` as `analyze --json` writes its member
    /// `dynamics`, as JSON text, in the units `unit` and `force_unit`.
    fn at(&self, degrees: f64, unit: &str, force_unit: &str) -> PyResult<String> {
        let units = units(unit, force_unit)?;
        let angle = Angle::from_degrees(degrees).map_err(py_err)?;
        let at = self.engine.at(angle).map_err(py_err)?;
        Ok(dynamics_json(&self.engine, &at, angle, &units).to_string())
    }

    /// Fills `out` (SWEEP_ROWS × n, C order) with the forces and torques
    /// at the angles `thetas` (degrees), the GIL released; errors with the
    /// first bad angle's message (nothing is promised of `out` then).
    fn sweep(
        &self,
        py: Python<'_>,
        thetas: PyReadonlyArray1<'_, f64>,
        mut out: PyReadwriteArray2<'_, f64>,
    ) -> PyResult<()> {
        let n = thetas.len();
        if out.shape() != [SWEEP_ROWS, n] {
            return Err(PyValueError::new_err(format!(
                "out must be {SWEEP_ROWS} rows of {n} values"
            )));
        }
        let thetas = thetas.as_slice()?;
        let out = out.as_slice_mut()?;
        py.detach(|| fill(&self.engine, thetas, out))
            .map_err(py_err)
    }

    /// The turning moment of cylinders at `phases` (degrees ahead of the
    /// first) as JSON text: the diagram's work, mean, lobes and
    /// fluctuation of energy, and the flywheel for the coefficient of
    /// fluctuation of speed `fluctuation` or the coefficient of the
    /// flywheel `flywheel` (at most one), `null` with neither.
    #[pyo3(signature = (phases, fluctuation=None, flywheel=None))]
    fn turning_moment(
        &self,
        py: Python<'_>,
        phases: Vec<f64>,
        fluctuation: Option<f64>,
        flywheel: Option<f64>,
    ) -> PyResult<String> {
        let ask = flywheel_ask(fluctuation, flywheel)?;
        let engine = &self.engine;
        py.detach(|| {
            let turn = TurningMoment::new(engine, &phases)?;
            let (de, w) = (turn.fluctuation, engine.omega());
            let wheel = match ask {
                FlywheelAsk::Coefficient(c) => Some(Flywheel::for_coefficient(de, w, c)?),
                FlywheelAsk::Inertia(i) => Some(Flywheel::for_inertia(de, w, i)?),
                _ => None,
            };
            Ok(json!({"turn": turn, "flywheel": wheel}).to_string())
        })
        .map_err(py_err)
    }
}

/// What the flywheel is asked for: the inertia for the coefficient of
/// fluctuation of speed `fluctuation`, or the coefficient of the flywheel
/// `flywheel` (`--fluctuation`, `--flywheel`: at most one).
pub fn flywheel_ask(fluctuation: Option<f64>, flywheel: Option<f64>) -> PyResult<FlywheelAsk> {
    match (fluctuation, flywheel) {
        (Some(_), Some(_)) => Err(PyValueError::new_err(
            "fluctuation cannot be used with flywheel: give the coefficient of fluctuation of speed or the flywheel, not both",
        )),
        (Some(c), _) => Ok(FlywheelAsk::Coefficient(c)),
        (_, Some(i)) => Ok(FlywheelAsk::Inertia(i)),
        _ => Ok(FlywheelAsk::None),
    }
}

impl PyEngine {
    /// The engine.
    pub fn engine(&self) -> &Engine {
        &self.engine
    }
}

/// The rows `Engine.sweep` fills, in the order of [`sweep_values`].
pub const SWEEP_ROWS: usize = 13;

/// The values of one pose in the order of the sweep's rows: gas force,
/// inertia force (exact, and by Klein's construction), piston effort, rod
/// force, guide thrust, OM, crank effort (F·OM, and by the exact formula),
/// the rod's torque (0 for a massless rod), the torque on the crank, and
/// the primary and secondary unbalanced forces.
fn sweep_values(engine: &Engine, at: &EnginePose, angle: Angle) -> [f64; SWEEP_ROWS] {
    let b = unbalanced_forces(engine, angle);
    [
        at.gas_force,
        at.inertia_force,
        at.inertia_force_graphical,
        at.piston_effort,
        at.rod_force,
        at.guide_thrust,
        at.om,
        at.crank_effort,
        at.crank_effort_exact,
        at.rod.map_or(0.0, |r| r.torque),
        at.torque,
        b.primary,
        b.secondary,
    ]
}

/// Fills the rows of `out` (SWEEP_ROWS × n) for `thetas`.
fn fill(engine: &Engine, thetas: &[f64], out: &mut [f64]) -> slider_crank::Result<()> {
    let n = thetas.len();
    for (i, &degrees) in thetas.iter().enumerate() {
        let angle = Angle::from_degrees(degrees)?;
        let at = engine.at(angle)?;
        for (row, v) in sweep_values(engine, &at, angle).into_iter().enumerate() {
            out[row * n + i] = v + 0.0;
        }
    }
    Ok(())
}
