//! The balance of an in-line engine and the piston acceleration's series
//! of harmonics for Python: the library's `InlineEngine` and `Harmonics`,
//! built from the values `table balance --cranks … --planes …` and `table
//! harmonics --order K` take (n = l/r given directly), with the command
//! line's defaults and refusals.

use crate::py_err;
use numpy::{PyReadonlyArray1, PyReadwriteArray2, PyUntypedArrayMethods};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use serde_json::json;
use slider_crank::Angle;
use slider_crank::analytic::harmonics::Harmonics;
use slider_crank::dynamics::{HammerBlow, InlineEngine, PartialBalance, RadialEngine, Revolving};

/// The cranks of `table balance` when `--cranks` is not given: four
/// cylinders, the flat crank 0, 180, 180, 0.
pub const DEFAULT_CRANKS: [f64; 4] = slider_crank::dynamics::DEFAULT_CRANKS;

/// The order of `table harmonics` when `--order` is not given.
pub const DEFAULT_ORDER: usize = slider_crank::analytic::harmonics::DEFAULT_ORDER;

/// The rows `inline_sweep` fills: the primary and secondary forces, the
/// primary and secondary couples and the exact force (the columns of
/// `table balance` after θ).
pub const BALANCE_ROWS: usize = 5;

/// Refuses a value of a list that is not finite with the message the
/// command line's list parser gives (`invalid crank angle 'NaN': expected
/// a finite number`), `what` naming the list's values.
fn finite_list(values: &[f64], what: &str) -> PyResult<()> {
    match values.iter().find(|x| !x.is_finite()) {
        Some(x) => Err(PyValueError::new_err(format!(
            "invalid {what} '{x}': expected a finite number"
        ))),
        None => Ok(()),
    }
}

/// The in-line engine of the cylinders at `cranks` (degrees ahead of the
/// first; the flat crank when `None`) in the planes `planes` (a pitch of
/// 1 about the middle when `None`) and ratio n, checked as `table balance`
/// checks them.
pub fn inline_engine(
    cranks: Option<Vec<f64>>,
    planes: Option<Vec<f64>>,
    ratio: f64,
) -> PyResult<InlineEngine> {
    let cranks = cranks.unwrap_or_else(|| DEFAULT_CRANKS.to_vec());
    finite_list(&cranks, "crank angle")?;
    let planes = planes.unwrap_or_else(|| slider_crank::dynamics::default_planes(cranks.len()));
    finite_list(&planes, "plane")?;
    InlineEngine::new(&cranks, &planes, ratio).map_err(py_err)
}

/// The balance of the in-line engine as JSON text: its cranks, planes and
/// n, the four resultants (vector at θ = 0, amplitude, balanced) and
/// whether all four are balanced.
#[pyfunction]
#[pyo3(signature = (cranks, planes, n))]
pub fn inline_balance(
    cranks: Option<Vec<f64>>,
    planes: Option<Vec<f64>>,
    n: f64,
) -> PyResult<String> {
    let engine = inline_engine(cranks, planes, n)?;
    Ok(json!({
        "cranks_deg": engine.cranks_deg(),
        "planes": engine.planes(),
        "n": n,
        "primary_force": engine.primary_force,
        "primary_couple": engine.primary_couple,
        "secondary_force": engine.secondary_force,
        "secondary_couple": engine.secondary_couple,
        "balanced": engine.is_balanced(),
    })
    .to_string())
}

/// Fills `out` (BALANCE_ROWS × n, C order) with the unbalanced forces and
/// couples of the in-line engine at the first crank's angles `thetas`
/// (degrees), as `table balance` computes its rows, the GIL released;
/// errors with the first bad angle's message.
#[pyfunction]
pub fn inline_sweep(
    py: Python<'_>,
    cranks: Vec<f64>,
    planes: Vec<f64>,
    n: f64,
    thetas: PyReadonlyArray1<'_, f64>,
    mut out: PyReadwriteArray2<'_, f64>,
) -> PyResult<()> {
    let engine = inline_engine(Some(cranks), Some(planes), n)?;
    let count = thetas.len();
    if out.shape() != [BALANCE_ROWS, count] {
        return Err(PyValueError::new_err(format!(
            "out must be {BALANCE_ROWS} rows of {count} values"
        )));
    }
    let thetas = thetas.as_slice()?;
    let out = out.as_slice_mut()?;
    py.detach(|| -> slider_crank::Result<()> {
        for (i, &degrees) in thetas.iter().enumerate() {
            let angle = Angle::from_degrees(degrees)?;
            let (p, s) = engine.forces_at(angle);
            let (pc, sc) = engine.couples_at(angle);
            let exact = engine.exact_force(angle)?;
            for (row, v) in [p, s, pc, sc, exact].into_iter().enumerate() {
                out[row * count + i] = v + 0.0;
            }
        }
        Ok(())
    })
    .map_err(py_err)
}

/// The series of harmonics of the piston's acceleration for ratio n to
/// cos 2kθ, k = `order`, as JSON text: n, the coefficients A₂ … A₂ₖ and
/// the largest error of each truncation (after cos θ, cos 2θ, …).
#[pyfunction]
pub fn harmonics(py: Python<'_>, n: f64, order: usize) -> PyResult<String> {
    let series = py.detach(|| Harmonics::new(n, order)).map_err(py_err)?;
    Ok(json!({
        "n": series.ratio,
        "coefficients": series.even,
        "truncation_error": series.truncation_error,
    })
    .to_string())
}

/// The engine of cylinders on one crank at `axes` (degrees; the 90°
/// V-twin when `None`) and ratio n, checked as `table radial` checks it.
pub fn radial_engine(axes: Option<Vec<f64>>, ratio: f64) -> PyResult<RadialEngine> {
    let axes = axes.unwrap_or_else(|| slider_crank::dynamics::DEFAULT_AXES.to_vec());
    finite_list(&axes, "axis")?;
    RadialEngine::new(&axes, ratio).map_err(py_err)
}

/// Cylinders on one crank as JSON text: their axes, n and the four
/// direct and reverse cranks (vector at θ = 0, amplitude, balanced).
#[pyfunction]
#[pyo3(signature = (axes, n))]
pub fn radial(axes: Option<Vec<f64>>, n: f64) -> PyResult<String> {
    let e = radial_engine(axes, n)?;
    Ok(json!({
        "axes_deg": e.axes_deg(),
        "n": n,
        "primary_direct": e.primary_direct,
        "primary_reverse": e.primary_reverse,
        "secondary_direct": e.secondary_direct,
        "secondary_reverse": e.secondary_reverse,
    })
    .to_string())
}

/// The hammer blow c m r ω² of a locomotive's wheel of diameter `wheel`
/// at the speed `speed`, and the speed at which it equals `load` (`None`
/// without a load or with nothing balanced), checked as `table
/// partial-balance --wheel` checks them.
#[pyfunction]
#[pyo3(signature = (fraction, mass, crank, wheel, speed, load=None))]
pub fn hammer_blow(
    fraction: f64,
    mass: f64,
    crank: f64,
    wheel: f64,
    speed: f64,
    load: Option<f64>,
) -> PyResult<(f64, Option<f64>)> {
    let b = PartialBalance::new(fraction).map_err(py_err)?;
    let l =
        slider_crank::table::Locomotive::new(mass, crank, wheel, speed, load).map_err(py_err)?;
    let h = HammerBlow::new(&b, l.mass, l.crank, l.wheel).map_err(py_err)?;
    let lift = match l.load {
        Some(p) => h.lifting_speed(p).map_err(py_err)?,
        None => None,
    };
    Ok((h.at_speed(l.speed).map_err(py_err)?, lift))
}

/// The two balance masses in the planes `planes` (the wheels') of the
/// revolving `masses`, each (m r, its angle in degrees from the first
/// crank, its plane along the shaft), as the library's
/// `dynamics::two_plane_balance` finds them: each balance (m r, angle in
/// [0°, 360°), plane). Refused as the library refuses: no mass, a value
/// not finite, the two planes the same.
#[pyfunction]
#[pyo3(signature = (masses, planes))]
pub fn two_plane_balance(
    masses: Vec<(f64, f64, f64)>,
    planes: (f64, f64),
) -> PyResult<Vec<(f64, f64, f64)>> {
    let masses: Vec<Revolving> = masses
        .into_iter()
        .map(|(moment, angle_deg, plane)| Revolving {
            moment,
            angle_deg,
            plane,
        })
        .collect();
    let balances = slider_crank::dynamics::two_plane_balance(&masses, planes).map_err(py_err)?;
    Ok(balances
        .iter()
        .map(|b| (b.moment, b.angle_deg, b.plane))
        .collect())
}

/// Registers the functions and constants.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(inline_balance, m)?)?;
    m.add_function(wrap_pyfunction!(inline_sweep, m)?)?;
    m.add_function(wrap_pyfunction!(harmonics, m)?)?;
    m.add_function(wrap_pyfunction!(radial, m)?)?;
    m.add_function(wrap_pyfunction!(hammer_blow, m)?)?;
    m.add_function(wrap_pyfunction!(two_plane_balance, m)?)?;
    m.add(
        "DEFAULT_FRACTIONS",
        slider_crank::dynamics::DEFAULT_FRACTIONS.to_vec(),
    )?;
    m.add(
        "DEFAULT_AXES",
        slider_crank::dynamics::DEFAULT_AXES.to_vec(),
    )?;
    m.add("BALANCE_ROWS", BALANCE_ROWS)?;
    m.add("DEFAULT_CRANKS", DEFAULT_CRANKS.to_vec())?;
    m.add("DEFAULT_ORDER", DEFAULT_ORDER)?;
    m.add("MAX_ORDER", slider_crank::analytic::harmonics::MAX_ORDER)?;
    Ok(())
}
