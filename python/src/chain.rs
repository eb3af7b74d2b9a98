//! The chain of Fig. 60 for Python: the quadric crank chain (`analyze
//! --links`), the block in a curved slot (`--slot-radius`), the four
//! inversions (`--inversion`) and `check` of the first two.
//!
//! The JSON layouts mirror `src/cli/chain.rs` (python/tests/test_chain.py
//! compares the two digit for digit); every number comes from the library.

use crate::{py_err, units};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use serde_json::{Value, json};
use slider_crank::chain::{
    ChainCheckRow, CylindricChain, GrashofClass, InvertedChain, QuadricChain, SlotConstruction,
    quadric_sweep, slot_sweep,
};
use slider_crank::construct::Link;
use slider_crank::geom::{Intersection, Point};
use slider_crank::render::plain;
use slider_crank::{Angle, Assembly, Inversion, SliderCrank};

/// The chain's default allowance in `check` (the command line's).
const CHAIN_TOLERANCE: f64 = 1e-12;

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

/// `value` with the units inserted, as JSON text.
fn with_units(value: slider_crank::Result<Value>, unit: &str, force: &str) -> PyResult<String> {
    let units = units(unit, force)?;
    let mut v = value.map_err(py_err)?;
    if let Some(fields) = v.as_object_mut() {
        fields.insert("units".into(), json!(units));
    }
    Ok(v.to_string())
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

/// `analyze --links A,B,C,D --assembly MODE --json` at one angle.
#[pyfunction]
fn quadric_at(
    links: [f64; 4],
    mode: &str,
    degrees: f64,
    omega: f64,
    unit: &str,
    force_unit: &str,
) -> PyResult<String> {
    let q = quadric(links)?;
    let v = quadric_json(&q, assembly(mode)?, degrees, omega);
    with_units(v, unit, force_unit)
}

/// `analyze --slot-radius RHO --json` at one angle.
#[pyfunction]
#[allow(clippy::too_many_arguments)]
fn slot_at(
    crank: f64,
    rod: f64,
    offset: f64,
    rho: f64,
    degrees: f64,
    omega: f64,
    unit: &str,
    force_unit: &str,
) -> PyResult<String> {
    let chain = slot(crank, rod, offset, rho)?;
    with_units(slot_json(&chain, degrees, omega), unit, force_unit)
}

/// `analyze --inversion N --json` at one angle.
#[pyfunction]
#[allow(clippy::too_many_arguments)]
fn inversion_at(
    crank: f64,
    rod: f64,
    offset: f64,
    n: u32,
    degrees: f64,
    omega: f64,
    unit: &str,
    force_unit: &str,
) -> PyResult<String> {
    let chain = inverted(crank, rod, offset, n)?;
    with_units(inversion_json(&chain, degrees, omega), unit, force_unit)
}

/// One row of a chain's check: name, worst scaled difference, κ there,
/// where (degrees), poses compared, passed.
type CheckRow = (String, f64, f64, f64, usize, bool);

/// `check --links …` (`links` given) or `check --slot-radius …` (`slot`
/// = crank, rod, offset, ρ): the report the command prints, whether every
/// quantity passed, and the rows.
#[pyfunction]
#[pyo3(signature = (links=None, slot=None, samples=100_000, tolerance=None))]
fn chain_check(
    py: Python<'_>,
    links: Option<[f64; 4]>,
    slot: Option<[f64; 4]>,
    samples: usize,
    tolerance: Option<f64>,
) -> PyResult<(String, bool, Vec<CheckRow>)> {
    let tolerance = crate::check::check_arguments(samples, tolerance, CHAIN_TOLERANCE)?;
    let (title, rows) = match (links, slot) {
        (Some(links), _) => {
            let q = quadric(links)?;
            let title = format!(
                "check: quadric chain a = {}, b = {}, c = {}, d = {} ({}), both assembly modes",
                plain(q.crank()),
                plain(q.coupler()),
                plain(q.lever()),
                plain(q.frame()),
                grashof_name(q.grashof())
            );
            (title, py.detach(|| quadric_sweep(&q, samples)))
        }
        (None, Some([crank, rod, offset, rho])) => {
            let s = self::slot(crank, rod, offset, rho)?;
            let m = s.mechanism();
            let title = format!(
                "check: curved slot ρ = {}, r = {}, l = {}, e = {}",
                plain(rho),
                plain(m.crank()),
                plain(m.rod()),
                plain(m.offset())
            );
            (title, py.detach(|| slot_sweep(&s, samples)))
        }
        (None, None) => return Err(PyValueError::new_err("chain_check needs links or slot")),
    };
    let (text, ok) = report(&title, &rows, tolerance);
    let rows = rows
        .iter()
        .map(|r| {
            let pass = r.passes(tolerance);
            (
                r.name.to_string(),
                r.worst,
                r.condition,
                r.at_degrees,
                r.poses,
                pass,
            )
        })
        .collect();
    Ok((text, ok, rows))
}

/// Registers the chain's functions.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(check_quadric, m)?)?;
    m.add_function(wrap_pyfunction!(check_slot, m)?)?;
    m.add_function(wrap_pyfunction!(check_inversion, m)?)?;
    m.add_function(wrap_pyfunction!(quadric_at, m)?)?;
    m.add_function(wrap_pyfunction!(slot_at, m)?)?;
    m.add_function(wrap_pyfunction!(inversion_at, m)?)?;
    m.add_function(wrap_pyfunction!(chain_check, m)?)?;
    Ok(())
}

// What follows mirrors `src/cli/chain.rs`.

/// The report `check` prints for a chain, and whether all passed.
fn report(title: &str, rows: &[ChainCheckRow], tolerance: f64) -> (String, bool) {
    let mut out = format!(
        "{title}\na difference passes when at most {tolerance:.3e} × κ, κ the condition number of the quantity at that pose (1 far from a toggle or the slot's limit)\n\n"
    );
    out.push_str(&format!(
        "{:<40}{:>14}{:>12}{:>16}{:>10}  result\n",
        "quantity (scaled difference)", "worst", "κ there", "at θ (°)", "poses"
    ));
    let mut ok = true;
    for row in rows {
        let pass = row.passes(tolerance);
        ok &= pass;
        out.push_str(&format!(
            "{:<40}{:>14.3e}{:>12.3e}{:>16.6}{:>10}  {}\n",
            row.name,
            row.worst,
            row.condition,
            row.at_degrees,
            row.poses,
            if pass { "ok" } else { "FAIL" }
        ));
    }
    out.push_str(if ok {
        "\nall within tolerance\n"
    } else {
        "\nsome quantities exceed the tolerance\n"
    });
    (out, ok)
}

/// +0.0 for −0.0, so that no "-0" is printed.
fn num(x: f64) -> f64 {
    x + 0.0
}

fn point_json(p: Point) -> Value {
    json!([num(p.x), num(p.y)])
}

/// A point, or `{"at_infinity": [dx, dy]}`, or `{"indeterminate": true}`.
fn centre_json(c: &Intersection) -> Value {
    match c {
        Intersection::Point(p) => point_json(*p),
        Intersection::AtInfinity(d) => json!({"at_infinity": [num(d.x), num(d.y)]}),
        Intersection::Coincident => json!({"indeterminate": true}),
    }
}

fn opt(x: Option<f64>) -> Value {
    x.map(|x| json!(num(x))).unwrap_or(Value::Null)
}

fn slot_json(chain: &CylindricChain, degrees: f64, omega: f64) -> slider_crank::Result<Value> {
    let p = chain.pose(Angle::from_degrees(degrees)?);
    let s = SlotConstruction::construct(&p);
    let m = chain.mechanism();
    let w2 = omega * omega;
    Ok(json!({
        "mechanism": {"crank": m.crank(), "rod": m.rod(), "offset": num(m.offset()),
                      "slot_radius": chain.slot_radius()},
        "angle_deg": num(p.angle().degrees()),
        "omega": num(omega),
        "points": {
            "C": point_json(p.c()), "B": point_json(p.b()), "A": point_json(p.a()),
            "D": centre_json(&s.d()),
            "E": s.e().map(point_json).unwrap_or(Value::Null),
            "O_cd": centre_json(&chain.slot_centre()),
        },
        "analytic": {
            "arc_position": num(p.arc_position()),
            "velocity": num(omega * p.arc_rate()),
            "acceleration": num(w2 * p.arc_acceleration()),
            "slot_angle_deg": num(p.slot_angle().to_degrees()),
            "lever_angular_velocity": num(omega * p.lever_rate()),
            "lever_angular_acceleration": num(w2 * p.lever_acceleration()),
            "rod_angle_deg": num(p.obliquity().to_degrees()),
            "rod_angular_velocity": num(omega * p.obliquity_rate()),
            "rod_angular_acceleration": num(w2 * p.obliquity_acceleration()),
        },
        "graphical": {
            "velocity": opt(s.arc_rate_from_e().map(|v| omega * v)),
            "velocity_from_D": opt(s.arc_rate_from_d().map(|v| omega * v)),
            "acceleration": opt(s.arc_acceleration_from_klein().map(|a| w2 * a)),
            "rod_angular_velocity": opt(s.obliquity_rate_from_d().map(|v| omega * v)),
        },
        "virtual_centres": s.centres().to_json(),
    }))
}

fn grashof_name(g: GrashofClass) -> &'static str {
    match g {
        GrashofClass::CrankRocker => "crank_rocker",
        GrashofClass::DoubleCrank => "double_crank",
        GrashofClass::RockerCrank => "rocker_crank",
        GrashofClass::DoubleRocker => "double_rocker",
        GrashofClass::ChangePoint => "change_point",
        GrashofClass::TripleRocker => "triple_rocker",
    }
}

fn quadric_json(
    q: &QuadricChain,
    mode: Assembly,
    degrees: f64,
    omega: f64,
) -> slider_crank::Result<Value> {
    let p = q.pose(Angle::from_degrees(degrees)?, mode)?;
    let reach = q.reach();
    let rates = p.rates();
    let w2 = omega * omega;
    Ok(json!({
        "mechanism": {
            "crank": q.crank(), "coupler": q.coupler(), "lever": q.lever(), "frame": q.frame(),
            "assembly": if mode == Assembly::Open { "open" } else { "crossed" },
            "grashof": grashof_name(q.grashof()),
            "reach_deg": [num(reach.lower().to_degrees()), num(reach.upper().to_degrees())],
        },
        "angle_deg": num(p.angle().degrees()),
        "omega": num(omega),
        "points": {
            "C": point_json(p.c()), "B": point_json(p.b()), "A": point_json(p.a()),
            "O_cd": point_json(q.lever_pivot()),
        },
        "analytic": {
            "toggle": p.is_toggle(),
            "coupler_angle_deg": num(p.coupler_angle().to_degrees()),
            "lever_angle_deg": num(p.lever_angle().to_degrees()),
            "coupler_angular_velocity": opt(rates.map(|r| omega * r.coupler_velocity)),
            "lever_angular_velocity": opt(rates.map(|r| omega * r.lever_velocity)),
            "coupler_angular_acceleration": opt(rates.map(|r| w2 * r.coupler_acceleration)),
            "lever_angular_acceleration": opt(rates.map(|r| w2 * r.lever_acceleration)),
        },
        "virtual_centres": slider_crank::chain::ChainCentres::of_quadric(&p).to_json(),
    }))
}

fn link_name(l: Link) -> &'static str {
    match l {
        Link::A => "a",
        Link::B => "b",
        Link::C => "c",
        Link::D => "d",
    }
}

fn inversion_json(chain: &InvertedChain, degrees: f64, omega: f64) -> slider_crank::Result<Value> {
    let p = chain.pose(Angle::from_degrees(degrees)?);
    let inv = chain.inversion();
    let m = chain.mechanism();
    let motion = p.motion(omega);
    let mut links = serde_json::Map::new();
    for (i, l) in [Link::A, Link::B, Link::C, Link::D].into_iter().enumerate() {
        links.insert(
            link_name(l).into(),
            json!({
                "angular_velocity": opt(motion.and_then(|x| x.velocity.get(i).copied())),
                "angular_acceleration": opt(motion.and_then(|x| x.acceleration.get(i).copied())),
            }),
        );
    }
    Ok(json!({
        "mechanism": {"crank": m.crank(), "rod": m.rod(), "offset": num(m.offset())},
        "inversion": inv.number(),
        "fixed": link_name(inv.fixed()),
        "driver": link_name(inv.driver()),
        "name": inv.name(),
        "angle_deg": num(p.engine_pose().angle().degrees()),
        "omega": num(omega),
        "links": links,
        "sliding": {
            "velocity": opt(motion.map(|x| x.sliding_velocity)),
            "acceleration": opt(motion.map(|x| x.sliding_acceleration)),
        },
        "time_ratio": opt(chain.time_ratio()),
        "virtual_centres": p.centres().to_json(),
    }))
}
