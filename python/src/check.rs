//! `slider-crank check` for the engine: every construction against the
//! analytic core over the whole turn, the report the command prints (the
//! library's `slider_crank::table::CheckRequest`).

use crate::py_err;
use pyo3::prelude::*;
use slider_crank::table::{CheckRequest, CheckRows, DEFAULT_MAX_CELLS, DEFAULT_SAMPLES};

// The signatures give `samples`' default as a number, which the stub
// (and stubtest, against the module's text signature) reads; a constant
// there shows as `...`. It is the library's own default:
const _: () = assert!(DEFAULT_SAMPLES == 100_000);

/// One row: quantity, worst scaled difference, κ there, where (degrees),
/// poses compared, passed, and the difference in ulps × κ.
type Row = (String, f64, f64, f64, usize, bool, f64);

/// `slider-crank check --crank --rod --offset --samples --tolerance`: the
/// report it prints, whether every quantity passed, and the rows (the
/// library's request of `check`, as the command line fills it).
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
    let mut request = CheckRequest::default();
    (request.crank, request.rod, request.offset) = (Some(crank), Some(rod), Some(offset));
    (request.samples, request.tolerance, request.max_cells) = (samples, tolerance, max_cells);
    let plan = request.plan().map_err(py_err)?;
    let outcome = py.detach(|| plan.run());
    let CheckRows::Engine(report) = &outcome.rows else {
        unreachable!("the engine's check has the engine's rows")
    };
    let allowed = outcome.tolerance / f64::EPSILON;
    let rows = (report.worst.iter().zip(&report.worst_ulps))
        .map(|((q, err, _, poses), (_, ulps, kappa, at))| {
            let pass = *ulps <= allowed;
            (q.name().to_string(), *err, *kappa, *at, *poses, pass, *ulps)
        })
        .collect();
    Ok((outcome.text, outcome.passed, rows))
}
