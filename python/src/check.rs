//! `slider-crank check` for the engine: every construction against the
//! analytic core over the whole turn, the report as the command prints it
//! (its layout mirrors `src/cli/check.rs`; python/tests/test_chain.py
//! compares the two byte for byte).

use crate::py_err;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use slider_crank::construct::{Quantity, sweep};
use slider_crank::render::plain;
use slider_crank::{Error, SliderCrank};

/// The command's default allowance: 4 ulps times the condition number.
const DEFAULT_ULPS: f64 = 4.0;

/// The command line's default `--max-cells`.
const MAX_CELLS: u64 = 50_000_000;

/// One row: quantity, worst scaled difference, κ there, where (degrees),
/// poses compared, passed, and the difference in ulps × κ.
type Row = (String, f64, f64, f64, usize, bool, f64);

/// An allowance in ulps: one decimal up to a million, exponent form beyond.
fn ulps_text(ulps: f64) -> String {
    if ulps < 1e6 {
        format!("{ulps:.1}")
    } else {
        format!("{ulps:.3e}")
    }
}

/// Checks `samples` and `tolerance` as `check` does; the tolerance
/// (4 ulps when not given).
pub fn check_arguments(samples: usize, tolerance: Option<f64>, default: f64) -> PyResult<f64> {
    let t = tolerance.unwrap_or(default);
    if !(t.is_finite() && t > 0.0) {
        return Err(py_err(Error::NotPositive {
            name: "tolerance",
            value: t,
        }));
    }
    if t > 1.0 {
        return Err(py_err(Error::OutOfRange {
            name: "tolerance",
            value: t,
            reason: "give at most 1: a difference of 1 in scaled units is the size of the quantity itself".into(),
        }));
    }
    if samples == 0 {
        return Err(py_err(Error::OutOfRange {
            name: "samples",
            value: 0.0,
            reason: "give at least 1 pose".into(),
        }));
    }
    let quantities = Quantity::ALL.len();
    let cells = samples as u128 * quantities as u128;
    if cells > u128::from(MAX_CELLS) {
        return Err(PyValueError::new_err(format!(
            "check asks for {samples} poses × {quantities} quantities = {cells} values, more than {MAX_CELLS}: give fewer samples"
        )));
    }
    Ok(t)
}

/// `slider-crank check --crank --rod --offset --samples --tolerance`: the
/// report it prints, whether every quantity passed, and the rows.
#[pyfunction]
#[pyo3(signature = (crank, rod, offset, samples=100_000, tolerance=None))]
pub fn engine_check(
    py: Python<'_>,
    crank: f64,
    rod: f64,
    offset: f64,
    samples: usize,
    tolerance: Option<f64>,
) -> PyResult<(String, bool, Vec<Row>)> {
    let m = SliderCrank::new(crank, rod, offset).map_err(py_err)?;
    let tolerance = check_arguments(samples, tolerance, DEFAULT_ULPS * f64::EPSILON)?;
    let report = py.detach(|| sweep(&m, samples));
    let allowed = tolerance / f64::EPSILON;
    let mut out = format!(
        "check: r = {}, l = {}, e = {} (n = {}), {} poses\n\
         a difference passes when at most {tolerance:.3e} × κ ({} ulps × κ, κ the condition number of the quantity at that pose)\n\n",
        plain(m.crank()),
        plain(m.rod()),
        plain(m.offset()),
        plain(m.ratio()),
        report.poses,
        ulps_text(allowed),
    );
    out.push_str(&format!(
        "{:<40}{:>12}{:>10}{:>12}{:>14}  result\n",
        "quantity", "worst diff", "ulps × κ", "κ there", "at θ (°)"
    ));
    let mut ok = true;
    let mut rows = Vec::with_capacity(report.worst.len());
    for ((q, err, _, poses), (_, ulps, kappa, at)) in report.worst.iter().zip(&report.worst_ulps) {
        let pass = *ulps <= allowed;
        ok &= pass;
        out.push_str(&format!(
            "{:<40}{:>12.3e}{:>10.2}{:>12.3e}{:>14.6}  {}\n",
            q.name(),
            err,
            ulps,
            kappa,
            at,
            if pass { "ok" } else { "FAIL" }
        ));
        rows.push((q.name().to_string(), *err, *kappa, *at, *poses, pass, *ulps));
    }
    out.push_str(if ok {
        "\nall within tolerance\n"
    } else {
        "\nsome quantities exceed the tolerance\n"
    });
    Ok((out, ok, rows))
}
