//! `slider-crank check` for the engine: every construction against the
//! analytic core over the whole turn, the report the command prints (the
//! library's `slider_crank::table::engine_check_report`).

use crate::py_err;
use pyo3::prelude::*;
use slider_crank::SliderCrank;
use slider_crank::construct::{Quantity, sweep};
use slider_crank::table::{
    DEFAULT_MAX_CELLS, DEFAULT_ULPS, MaxCells, check_allowance, engine_check_report,
};

/// One row: quantity, worst scaled difference, κ there, where (degrees),
/// poses compared, passed, and the difference in ulps × κ.
type Row = (String, f64, f64, f64, usize, bool, f64);

/// Checks `samples` and `tolerance` as `check` does, and the poses ×
/// quantities against `max_cells` (the library's guard, `--max-cells`);
/// the tolerance (`default` when not given).
pub fn check_arguments(
    samples: usize,
    tolerance: Option<f64>,
    default: f64,
    max_cells: u64,
) -> PyResult<f64> {
    let t = check_allowance(samples, tolerance, default).map_err(py_err)?;
    MaxCells::new(max_cells)
        .check_poses(samples as u64, Quantity::ALL.len())
        .map_err(py_err)?;
    Ok(t)
}

/// `slider-crank check --crank --rod --offset --samples --tolerance`: the
/// report it prints, whether every quantity passed, and the rows.
#[pyfunction]
#[pyo3(signature = (crank, rod, offset, samples=100_000, tolerance=None, max_cells=DEFAULT_MAX_CELLS))]
pub fn engine_check(
    py: Python<'_>,
    crank: f64,
    rod: f64,
    offset: f64,
    samples: usize,
    tolerance: Option<f64>,
    max_cells: u64,
) -> PyResult<(String, bool, Vec<Row>)> {
    let m = SliderCrank::new(crank, rod, offset).map_err(py_err)?;
    let tolerance = check_arguments(samples, tolerance, DEFAULT_ULPS * f64::EPSILON, max_cells)?;
    let report = py.detach(|| sweep(&m, samples));
    let (out, ok) = engine_check_report(&m, &report, tolerance);
    let allowed = tolerance / f64::EPSILON;
    let rows = (report.worst.iter().zip(&report.worst_ulps))
        .map(|((q, err, _, poses), (_, ulps, kappa, at))| {
            let pass = *ulps <= allowed;
            (q.name().to_string(), *err, *kappa, *at, *poses, pass, *ulps)
        })
        .collect();
    Ok((out, ok, rows))
}
