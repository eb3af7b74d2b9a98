//! The chain of Fig. 60 for Python: the checks of the quadric crank chain
//! (`analyze --links`), the block in a curved slot (`--slot-radius`) and
//! the four inversions (`--inversion`), and `check` of the first two;
//! each is analysed at an angle by `analyze`, the library's request.
//!
//! The check reports are the library's (`slider_crank::table`), the ones
//! the command line prints.

use crate::py_err;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use slider_crank::chain::{CylindricChain, InvertedChain, QuadricChain};
use slider_crank::table::{CheckRequest, CheckRows};
use slider_crank::{Assembly, Inversion, SliderCrank};

fn mechanism(crank: f64, rod: f64, offset: f64) -> PyResult<SliderCrank> {
    SliderCrank::new(crank, rod, offset).map_err(py_err)
}

fn quadric(links: [f64; 4]) -> PyResult<QuadricChain> {
    let [a, b, c, d] = links;
    QuadricChain::new(a, b, c, d).map_err(py_err)
}

fn assembly(name: &str) -> PyResult<Assembly> {
    match name {
        "open" => Ok(Assembly::Open),
        "crossed" => Ok(Assembly::Crossed),
        _ => Err(PyValueError::new_err(format!(
            "invalid assembly '{name}': expected open or crossed"
        ))),
    }
}

fn slot(crank: f64, rod: f64, offset: f64, rho: f64) -> PyResult<CylindricChain> {
    CylindricChain::new(mechanism(crank, rod, offset)?, rho).map_err(py_err)
}

fn inverted(crank: f64, rod: f64, offset: f64, n: u32) -> PyResult<InvertedChain> {
    let inversion = Inversion::from_number(n).map_err(py_err)?;
    Ok(InvertedChain::new(
        mechanism(crank, rod, offset)?,
        inversion,
    ))
}

/// Checks a quadric chain's links and assembly mode.
#[pyfunction]
fn check_quadric(links: [f64; 4], mode: &str) -> PyResult<()> {
    quadric(links)?;
    assembly(mode)?;
    Ok(())
}

/// Checks an engine with its block in a slot of radius `rho`.
#[pyfunction]
fn check_slot(crank: f64, rod: f64, offset: f64, rho: f64) -> PyResult<()> {
    slot(crank, rod, offset, rho).map(|_| ())
}

/// Checks an inversion of an engine.
#[pyfunction]
fn check_inversion(crank: f64, rod: f64, offset: f64, n: u32) -> PyResult<()> {
    inverted(crank, rod, offset, n).map(|_| ())
}

/// One row of a chain's check: name, worst scaled difference, κ there,
/// where (degrees), poses compared, passed.
type CheckRow = (String, f64, f64, f64, usize, bool);

/// `check --links …` (`links` given), `check --slot-radius …` (`slot`
/// = crank, rod, offset, ρ) or `check --inversion …` (`inversion` =
/// crank, rod, offset, number): the report the command prints, whether
/// every quantity passed, and the rows (the library's request of `check`,
/// as the command line fills it).
#[pyfunction]
#[pyo3(signature = (links=None, slot=None, inversion=None, samples=100_000, tolerance=None,
    max_cells=slider_crank::table::DEFAULT_MAX_CELLS))]
#[allow(clippy::too_many_arguments)]
fn chain_check(
    py: Python<'_>,
    links: Option<[f64; 4]>,
    slot: Option<[f64; 4]>,
    inversion: Option<(f64, f64, f64, u32)>,
    samples: usize,
    tolerance: Option<f64>,
    max_cells: u64,
) -> PyResult<(String, bool, Vec<CheckRow>)> {
    let mut request = CheckRequest::default();
    match (links, slot, inversion) {
        (Some(links), None, None) => request.links = Some(links),
        (None, Some([crank, rod, offset, rho]), None) => {
            (request.crank, request.rod, request.offset) = (Some(crank), Some(rod), Some(offset));
            request.slot_radius = Some(rho);
        }
        (None, None, Some((crank, rod, offset, n))) => {
            (request.crank, request.rod, request.offset) = (Some(crank), Some(rod), Some(offset));
            request.inversion = Some(n);
        }
        _ => {
            return Err(PyValueError::new_err(
                "chain_check needs one of links, slot and inversion",
            ));
        }
    }
    (request.samples, request.tolerance, request.max_cells) = (samples, tolerance, max_cells);
    let plan = request.plan().map_err(py_err)?;
    let outcome = py.detach(|| plan.run());
    let CheckRows::Chain(rows) = &outcome.rows else {
        unreachable!("a chain's check has a chain's rows")
    };
    let rows = rows
        .iter()
        .map(|r| {
            let pass = r.passes(outcome.tolerance);
            let name = r.name.to_string();
            (name, r.worst, r.condition, r.at_degrees, r.poses, pass)
        })
        .collect();
    Ok((outcome.text, outcome.passed, rows))
}

/// Registers the chain's functions.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(check_quadric, m)?)?;
    m.add_function(wrap_pyfunction!(check_slot, m)?)?;
    m.add_function(wrap_pyfunction!(check_inversion, m)?)?;
    m.add_function(wrap_pyfunction!(chain_check, m)?)?;
    Ok(())
}
