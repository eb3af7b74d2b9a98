//! `slider_crank._core`: the library's entry points for the Python package.
//!
//! The Python half (`slider_crank/__init__.py`) holds the classes users see
//! and their documentation; these functions take plain values, validate
//! them with the library (the command line's checks and messages), compute
//! with the library and hand back text, bytes or filled numpy arrays. A
//! library error becomes `ValueError` (`OSError` for a file that cannot be
//! read or written), its message the line the command line prints after
//! `slider-crank: ` with the fields it names written as keywords
//! (`gas_force=` where the command line writes its flag).

use numpy::{PyReadonlyArray1, PyReadwriteArray2, PyUntypedArrayMethods};
use pyo3::exceptions::{PyOSError, PyOverflowError, PyValueError};
use pyo3::prelude::*;
use slider_crank::animate::{
    AnimateRequest, AnimationFormat, DEFAULT_FRAMES, DEFAULT_PERIOD, frames_refused,
};
use slider_crank::catalogue::FigureRequest;
use slider_crank::construct::Graphical;
use slider_crank::dynamics::Gravity;
use slider_crank::files::{MAX_DATA_BYTES, read_text};
use slider_crank::gallery::{Gallery, GalleryRequest};
use slider_crank::handout::HandoutRequest;
use slider_crank::lists::{Angles, parse_list};
use slider_crank::render::{
    FileFormat, TikzOptions, no_link_at_derived, to_pdf, to_png, to_svg, to_tikz, write_atomic,
    write_atomic_all,
};
use slider_crank::table::{
    AnalyzeRequest, DEFAULT_MAX_CELLS, GivenEngine, TableName, TableRequest,
};
use slider_crank::{
    Angle, Error, Field, FigureName, Input, Kinematics, Layer, SliderCrank, Spelling, Unit, Units,
};
use std::path::{Path, PathBuf};

mod balance;
mod chain;
mod check;
mod dynamics;

/// How the package writes the fields a library message names: as its
/// keywords, `gas_force=` and `bore=D`.
struct Keywords;

impl Spelling for Keywords {
    fn option(&self, field: Field) -> String {
        format!("{}=", field.key())
    }

    fn set(&self, field: Field, value: &str) -> String {
        format!("{}{value}", self.option(field))
    }
}

/// The Python exception for a library error, with the command line's message
/// (the one line the command line prints, control characters escaped), its
/// fields written as keywords.
fn py_err(e: Error) -> PyErr {
    let e = e.spelled(&Keywords).one_line();
    match e {
        Error::Io { .. } => PyOSError::new_err(e.to_string()),
        e => PyValueError::new_err(e.to_string()),
    }
}

fn parse<T: std::str::FromStr<Err = Error>>(text: &str) -> PyResult<T> {
    text.parse().map_err(py_err)
}

/// A list of numbers as a keyword takes it: a sequence, or one
/// comma-separated string read as the command line reads its flag's value
/// (`lists::parse_list`: the same refusals, a word, NaN or an infinity
/// named with its place in the list). An empty string is one empty item,
/// refused as the flag's `--cranks=` is.
#[derive(FromPyObject)]
enum Numbers {
    Text(String),
    Values(Vec<f64>),
}

impl Numbers {
    /// The numbers, a string read as a list of `name`s.
    fn values(self, name: &str) -> PyResult<Vec<f64>> {
        match self {
            Numbers::Text(text) => parse_list(&text, name, false).map_err(py_err),
            Numbers::Values(values) => Ok(values),
        }
    }
}

/// The engine, validated as `--crank --rod --offset` are.
fn engine(crank: f64, rod: f64, offset: f64) -> PyResult<SliderCrank> {
    SliderCrank::new(crank, rod, offset).map_err(py_err)
}

/// The units `--unit` and `--force-unit` name, validated.
fn units(unit: &str, force_unit: &str) -> PyResult<Units> {
    Ok(Units::FOOT_POUND
        .with_length(parse::<Unit>(unit)?)
        .with_force(parse::<Unit>(force_unit)?))
}

/// Checks an engine and its units; raises the command line's message.
#[pyfunction]
fn check_engine(crank: f64, rod: f64, offset: f64, unit: &str, force_unit: &str) -> PyResult<()> {
    engine(crank, rod, offset)?;
    units(unit, force_unit)?;
    Ok(())
}

/// The crank speed the command line takes when neither `--rpm` nor
/// `--omega` is given, in rpm (the §35 engine's).
const DEFAULT_RPM: f64 = slider_crank::sources::RPM;

/// ω in rad/s from `rpm` or `omega` (at most one given), checked as
/// `--rpm` and `--omega` are; [`DEFAULT_RPM`] when neither is.
#[pyfunction]
#[pyo3(signature = (rpm=None, omega=None))]
fn crank_speed(rpm: Option<f64>, omega: Option<f64>) -> PyResult<f64> {
    let omega = match (rpm, omega) {
        (Some(_), Some(_)) => {
            return Err(PyValueError::new_err(
                "give the crank speed as rpm or as omega, not both",
            ));
        }
        (_, Some(w)) => slider_crank::analytic::kinematics::check_omega(w),
        (Some(n), None) => slider_crank::omega_from_rpm(n),
        (None, None) => Ok(slider_crank::rpm_to_omega(DEFAULT_RPM)),
    };
    omega.map_err(py_err)
}

/// The object `analyze --json` prints at one angle (`angle`, 45° when
/// not given), as JSON text: each keyword the field of the library's
/// request of that name (`None`: the command's default), checked and
/// planned by the library as the command line's flags are
/// ([`AnalyzeRequest::plan`]), refused in the command line's words with
/// the fields spelt as keywords.
#[pyfunction]
#[pyo3(signature = (crank=None, rod=None, offset=None, angle=None, rpm=None, omega=None,
    torque=None, friction=None, unit=None, force_unit=None, mass=None, rod_mass=None,
    rod_cg=None, rod_gyration=None, gas_force=None, indicator=None, bore=None,
    slot_radius=None, links=None, assembly=None, inversion=None, max_cells=DEFAULT_MAX_CELLS,
    gravity=None))]
#[allow(clippy::too_many_arguments)]
fn analyze(
    crank: Option<f64>,
    rod: Option<f64>,
    offset: Option<f64>,
    angle: Option<f64>,
    rpm: Option<f64>,
    omega: Option<f64>,
    torque: Option<f64>,
    friction: Option<f64>,
    unit: Option<&str>,
    force_unit: Option<&str>,
    mass: Option<f64>,
    rod_mass: Option<f64>,
    rod_cg: Option<f64>,
    rod_gyration: Option<f64>,
    gas_force: Option<f64>,
    indicator: Option<PathBuf>,
    bore: Option<f64>,
    slot_radius: Option<f64>,
    links: Option<[f64; 4]>,
    assembly: Option<&str>,
    inversion: Option<u32>,
    max_cells: u64,
    gravity: Option<&str>,
) -> PyResult<String> {
    let angle = angle.map(|a| [a]);
    let mut r = AnalyzeRequest::default();
    (r.crank, r.rod, r.offset) = (crank, rod, offset);
    r.angles = angle.as_ref().map(|a| Angles::List(a));
    (r.rpm, r.omega, r.torque, r.friction) = (rpm, omega, torque, friction);
    r.unit = unit.map(parse::<Unit>).transpose()?;
    r.force_unit = force_unit.map(parse::<Unit>).transpose()?;
    r.engine = given_engine(
        mass,
        (rod_mass, rod_cg, rod_gyration),
        (gas_force, indicator, bore),
        gravity.map(parse).transpose()?,
    );
    (r.slot_radius, r.links, r.inversion) = (slot_radius, links, inversion);
    r.assembly = assembly.map(parse).transpose()?;
    r.max_cells = max_cells;
    let plan = r.plan().map_err(py_err)?;
    let degrees = plan.angles().iter().next().unwrap_or(0.0);
    let json = plan.json_at(degrees).map_err(py_err)?;
    serde_json::to_string(&json).map_err(|e| PyValueError::new_err(e.to_string()))
}

/// The engine of a request the keywords give, the one place the package
/// fills it (`analyze` and `table` alike).
fn given_engine(
    mass: Option<f64>,
    (rod_mass, rod_cg, rod_gyration): (Option<f64>, Option<f64>, Option<f64>),
    (gas_force, indicator, bore): (Option<f64>, Option<PathBuf>, Option<f64>),
    gravity: Option<Gravity>,
) -> GivenEngine {
    GivenEngine {
        mass,
        rod_mass,
        rod_cg,
        rod_gyration,
        gas_force,
        indicator,
        bore,
        gravity,
    }
}

/// The rows `sweep` fills: the six analytic values, then the four
/// graphical ones.
const ANALYTIC_ROWS: usize = 6;
const GRAPHICAL_ROWS: usize = 4;

/// Fills `out` (rows × n, C order) for the angles `thetas` (degrees):
/// position, velocity, acceleration, rod angle (degrees), rod angular
/// velocity and acceleration, and with 10 rows also the velocity,
/// acceleration and rod rates read off the constructions. The GIL is
/// released while it computes. Errors with the first angle that is not
/// finite, in the words of `analyze --angle` (nothing is written to `out`
/// then).
#[pyfunction]
fn sweep(
    py: Python<'_>,
    crank: f64,
    rod: f64,
    offset: f64,
    omega: f64,
    thetas: PyReadonlyArray1<'_, f64>,
    mut out: PyReadwriteArray2<'_, f64>,
) -> PyResult<()> {
    let m = engine(crank, rod, offset)?;
    let shape = out.shape().to_vec();
    let n = thetas.len();
    let graphical = match shape[0] {
        ANALYTIC_ROWS => false,
        r if r == ANALYTIC_ROWS + GRAPHICAL_ROWS => true,
        r => return Err(PyValueError::new_err(format!("out has {r} rows"))),
    };
    if shape[1] != n {
        return Err(PyValueError::new_err("out and thetas differ in length"));
    }
    let thetas = thetas.as_slice()?;
    // The first angle that is not finite, refused as `at` and the command
    // line's `--angle` refuse it.
    Angles::List(thetas).check().map_err(py_err)?;
    let out = out.as_slice_mut()?;
    py.detach(|| fill(&m, omega, thetas, out, graphical))
        .map_err(py_err)
}

/// Angles per thread below which a sweep stays on one thread.
const MIN_CHUNK: usize = 16_384;

/// The machine's cores, asked once: the standard library finds them by
/// reading the control group's quota from files, which took about 100 µs
/// a call, more than a sweep of a thousand angles.
fn cores() -> usize {
    static CORES: std::sync::OnceLock<usize> = std::sync::OnceLock::new();
    *CORES.get_or_init(|| std::thread::available_parallelism().map_or(1, |t| t.get()))
}

/// Fills the rows of `out` (rows × n) for `thetas`, split by columns over
/// the machine's cores for long sweeps. Each value depends on its angle
/// alone, so the split changes no number; the error is that of the first
/// bad angle.
fn fill(
    m: &SliderCrank,
    omega: f64,
    thetas: &[f64],
    out: &mut [f64],
    graphical: bool,
) -> slider_crank::Result<()> {
    let n = thetas.len();
    if n == 0 {
        return Ok(());
    }
    let pieces_wanted = n.div_ceil(MIN_CHUNK);
    let threads = if pieces_wanted > 1 { cores() } else { 1 };
    let chunk = n.div_ceil(threads.min(pieces_wanted).max(1));
    let mut pieces: Vec<Vec<&mut [f64]>> = (0..n.div_ceil(chunk)).map(|_| Vec::new()).collect();
    for row in out.chunks_mut(n) {
        for (piece, part) in pieces.iter_mut().zip(row.chunks_mut(chunk)) {
            piece.push(part);
        }
    }
    let mut jobs = thetas.chunks(chunk).zip(pieces);
    let Some((first, mut rows)) = jobs.next() else {
        return Ok(());
    };
    std::thread::scope(|scope| {
        let others: Vec<_> = jobs
            .map(|(t, mut r)| scope.spawn(move || fill_chunk(m, omega, t, &mut r, graphical)))
            .collect();
        let mut result = fill_chunk(m, omega, first, &mut rows, graphical);
        for handle in others {
            let r = handle
                .join()
                .unwrap_or_else(|e| std::panic::resume_unwind(e));
            result = result.and(r);
        }
        result
    })
}

/// Fills column `i` of each of `rows` for the angle `thetas[i]`.
fn fill_chunk(
    m: &SliderCrank,
    omega: f64,
    thetas: &[f64],
    rows: &mut [&mut [f64]],
    graphical: bool,
) -> slider_crank::Result<()> {
    for (i, &degrees) in thetas.iter().enumerate() {
        let pose = m.pose(Angle::from_degrees(degrees)?);
        let k = Kinematics::new(&pose, omega)?;
        if graphical {
            let g = Graphical::new(&pose, omega)?;
            let values = [
                g.velocity,
                g.acceleration,
                g.rod_angular_velocity,
                g.rod_angular_acceleration,
            ];
            for (row, v) in values.into_iter().enumerate() {
                rows[ANALYTIC_ROWS + row][i] = v + 0.0;
            }
        }
        let values = [
            k.position,
            k.velocity,
            k.acceleration,
            k.rod_angle.to_degrees(),
            k.rod_angular_velocity,
            k.rod_angular_acceleration,
        ];
        for (row, v) in values.into_iter().enumerate() {
            rows[row][i] = v + 0.0;
        }
    }
    Ok(())
}

/// The SVG of a named figure with the options the `figure` command's
/// flags give (`None`: the flag not given), filled into the library's
/// request ([`FigureRequest`]) and validated there; with `tikz` its TikZ
/// picture instead (`tikz = true`: a standalone document, as
/// `--tikz-standalone`); with `animate = (frames, period, projector,
/// path)` the animation `slider-crank animate` writes ([`animation`]).
#[pyfunction]
#[pyo3(signature = (name, crank=None, rod=None, offset=None, angle=None, rpm=None, omega=None,
    layers=None, style=None, font=None, data=None, fit=None, unit=None, force_unit=None,
    notation=None, mass=None, fluctuation=None, bore=None, gas_force=None, mirror=None,
    width=None, height=None, title=None, animate=None, tikz=None, coupler=None, rod_mass=None,
    rod_cg=None, rod_gyration=None, cranks=None, planes=None, gravity=None, friction=None))]
#[allow(clippy::too_many_arguments)]
fn figure<'py>(
    py: Python<'py>,
    name: &str,
    crank: Option<f64>,
    rod: Option<f64>,
    offset: Option<f64>,
    angle: Option<f64>,
    rpm: Option<f64>,
    omega: Option<f64>,
    layers: Option<&str>,
    style: Option<&str>,
    font: Option<&str>,
    data: Option<PathBuf>,
    fit: Option<&str>,
    unit: Option<&str>,
    force_unit: Option<&str>,
    notation: Option<&str>,
    mass: Option<f64>,
    fluctuation: Option<f64>,
    bore: Option<f64>,
    gas_force: Option<f64>,
    mirror: Option<bool>,
    width: Option<&str>,
    height: Option<&str>,
    title: Option<&str>,
    animate: Option<(Bound<'py, PyAny>, f64, bool, String)>,
    tikz: Option<bool>,
    coupler: Option<(f64, f64)>,
    rod_mass: Option<f64>,
    rod_cg: Option<f64>,
    rod_gyration: Option<f64>,
    cranks: Option<Numbers>,
    planes: Option<Numbers>,
    gravity: Option<&str>,
    friction: Option<f64>,
) -> PyResult<String> {
    let name: FigureName = parse(name)?;
    let mut request = FigureRequest::default();
    request.crank = crank;
    request.rod = rod;
    request.offset = offset;
    request.angle = angle;
    request.rpm = rpm;
    request.omega = omega;
    request.layers = layers.map(Layer::parse_list).transpose().map_err(py_err)?;
    request.style = style.map(parse).transpose()?;
    request.font = font.map(parse).transpose()?;
    request.data = data
        .as_ref()
        .map(|p| read_text(p, MAX_DATA_BYTES, Input::Data))
        .transpose()
        .map_err(py_err)?;
    request.fit = fit.map(parse).transpose()?;
    request.unit = unit.map(parse).transpose()?;
    request.force_unit = force_unit.map(parse).transpose()?;
    request.notation = notation.map(parse).transpose()?;
    request.mass = mass;
    request.fluctuation = fluctuation;
    request.bore = bore;
    request.gas_force = gas_force;
    request.mirror = mirror;
    request.width = width.map(parse).transpose()?;
    request.height = height.map(parse).transpose()?;
    request.title = title.map(parse).transpose()?;
    request.coupler = coupler;
    request.rod_mass = rod_mass;
    request.rod_cg = rod_cg;
    request.rod_gyration = rod_gyration;
    request.cranks = cranks.map(|c| c.values("crank angle")).transpose()?;
    request.planes = planes.map(|p| p.values("plane")).transpose()?;
    request.gravity = gravity.map(parse).transpose()?;
    request.friction = friction;
    if let Some(animate) = animate {
        return animation(py, name, request, animate);
    }
    let options = request.options(name).map_err(py_err)?;
    let text = |f: &slider_crank::Figure| match tikz {
        Some(standalone) => to_tikz(f, &TikzOptions::default().standalone(standalone)),
        None => to_svg(f),
    };
    py.detach(|| {
        name.figure(&options)
            .map(|f| text(&f))
            .map_err(|e| match &data {
                Some(path) => e.in_file(Input::Data, path),
                None => e,
            })
    })
    .map_err(py_err)
}

/// One revolution of the mechanism figure `name` the library's request
/// ([`AnimateRequest`]) asks for, its figure's options `figure`, as
/// `slider-crank animate --out PATH` writes it: a self-playing SVG or an
/// HTML page with a slider, as `path`'s extension (.svg, .html) says.
fn animation(
    py: Python<'_>,
    name: FigureName,
    figure: FigureRequest,
    (frames, period, projector, path): (Bound<'_, PyAny>, f64, bool, String),
) -> PyResult<String> {
    let format = AnimationFormat::from_path(Path::new(&path)).map_err(py_err)?;
    let mut request = AnimateRequest::default();
    request.figure = figure;
    (request.frames, request.period) = (Some(frame_count(&frames)?), Some(period));
    request.projector = Some(projector);
    py.detach(|| request.animation(name).map(|a| a.encode(format)))
        .map_err(py_err)
}

/// A count of frames as the keyword gives it: an integer no `usize` holds
/// (a negative one, or one from 2⁶⁴ up) is refused by the library's line
/// for a count out of range ([`frames_refused`], a `ValueError` naming
/// `frames=`), not by Python's `OverflowError`; one past the largest float
/// is named as an infinity of its sign.
fn frame_count(frames: &Bound<'_, PyAny>) -> PyResult<usize> {
    frames.extract::<usize>().or_else(|e| {
        if !e.is_instance_of::<PyOverflowError>(frames.py()) {
            return Err(e);
        }
        let value = match frames.extract::<f64>() {
            Ok(value) => value,
            Err(_) if frames.lt(0)? => f64::NEG_INFINITY,
            Err(_) => f64::INFINITY,
        };
        Err(py_err(frames_refused(value)))
    })
}

/// The bytes of the figure whose SVG is `svg` in `format`: SVG, PNG at 2
/// pixels per page unit, PDF. TikZ is written from the figure, not its
/// SVG: an error that says so (the package asks for it by `figure(…,
/// tikz=…)`).
fn encode_svg(format: FileFormat, svg: &str) -> slider_crank::Result<Vec<u8>> {
    match format {
        FileFormat::Svg => Ok(svg.as_bytes().to_vec()),
        FileFormat::Png => to_png(svg, 2.0),
        FileFormat::Pdf => to_pdf(svg),
        FileFormat::Tikz => Err(slider_crank::Error::Unsupported(
            "TikZ is written from the figure, not its SVG: use Figure.tikz()".into(),
        )),
    }
}

/// The bytes of the figure whose SVG is `svg` in the format `format`
/// names (`svg`, `png` at 2 pixels per page unit, `pdf`).
#[pyfunction]
fn encode<'py>(
    py: Python<'py>,
    svg: &str,
    format: &str,
) -> PyResult<Bound<'py, pyo3::types::PyBytes>> {
    let format = FileFormat::from_name(format).map_err(py_err)?;
    let bytes = py.detach(|| encode_svg(format, svg)).map_err(py_err)?;
    Ok(pyo3::types::PyBytes::new(py, &bytes))
}

/// Writes the figure whose SVG is `svg` to `path` in the format its
/// extension names, whole or not at all, as `--out` does.
#[pyfunction]
fn save(py: Python<'_>, svg: &str, path: PathBuf) -> PyResult<()> {
    let format = FileFormat::from_path(&path).map_err(py_err)?;
    py.detach(|| write_atomic(&path, &encode_svg(format, svg)?))
        .map_err(py_err)
}

/// The teaching page `slider-crank handout` writes (`which` = "page"),
/// or its exercise sheet ("exercise") or answer key ("key"), as HTML:
/// each keyword the field of the library's request of that name
/// (`None`: the handout's own), made into the handout by the library as
/// the command line's flags are ([`HandoutRequest::handout`]) and
/// refused in its words, naming these keywords. With `mass` the page
/// works the engine's dynamics too, as `--mass` … `--bore` do, and an
/// exercise the forces at its pose.
#[pyfunction]
#[pyo3(signature = (which, crank=None, rod=None, offset=None, angle=None, rpm=None, omega=None,
    unit=None, force_unit=None, torque=None, friction=None, mass=None, fluctuation=None,
    gas_force=None, indicator=None, bore=None, paper=None))]
#[allow(clippy::too_many_arguments)]
fn handout(
    py: Python<'_>,
    which: &str,
    crank: Option<f64>,
    rod: Option<f64>,
    offset: Option<f64>,
    angle: Option<f64>,
    rpm: Option<f64>,
    omega: Option<f64>,
    unit: Option<&str>,
    force_unit: Option<&str>,
    torque: Option<f64>,
    friction: Option<f64>,
    mass: Option<f64>,
    fluctuation: Option<f64>,
    gas_force: Option<f64>,
    indicator: Option<PathBuf>,
    bore: Option<f64>,
    paper: Option<&str>,
) -> PyResult<String> {
    let mut r = HandoutRequest::default();
    (r.crank, r.rod, r.offset, r.angle) = (crank, rod, offset, angle);
    (r.rpm, r.omega, r.torque, r.friction) = (rpm, omega, torque, friction);
    r.unit = unit.map(parse::<Unit>).transpose()?;
    r.force_unit = force_unit.map(parse::<Unit>).transpose()?;
    (r.mass, r.fluctuation, r.gas_force) = (mass, fluctuation, gas_force);
    (r.indicator, r.bore) = (indicator, bore);
    r.paper = paper.map(parse).transpose()?;
    let h = r.handout().map_err(py_err)?;
    py.detach(|| match which {
        "exercise" => h.exercise(),
        "key" => h.key(),
        _ => h.page(),
    })
    .map_err(py_err)
}

/// A table as `slider-crank table NAME` prints it, each keyword the
/// field of the library's request of that name (`None`: the table's
/// default), checked and planned by the library as the command line's
/// flags are ([`TableRequest::plan`]): a keyword the table does not use,
/// a bad value and a size past `max_cells` (`--max-cells`, checked
/// before any row is computed) are refused in the command line's words,
/// the fields spelt as keywords. The angles are read in place, never
/// copied; the rows are computed as the command line computes them,
/// twice (once for the columns' widths, once written), so that only the
/// text is held.
#[pyfunction]
#[pyo3(signature = (name, format="text", n=None, angles=None, crank=None, rod=None, offset=None,
    rpm=None, omega=None, torque=None, friction=None, decimals=None, unit=None, force_unit=None,
    mass=None, rod_mass=None, rod_cg=None, rod_gyration=None, gas_force=None, indicator=None,
    bore=None, phases=None, fluctuation=None, flywheel=None, cranks=None, planes=None,
    order=None, fractions=None, wheel=None, speed=None, load=None, axes=None, inversion=None,
    lever=None, max_cells=DEFAULT_MAX_CELLS, gravity=None))]
#[allow(clippy::too_many_arguments)]
fn table(
    py: Python<'_>,
    name: &str,
    format: &str,
    n: Option<Vec<f64>>,
    angles: Option<PyReadonlyArray1<'_, f64>>,
    crank: Option<f64>,
    rod: Option<f64>,
    offset: Option<f64>,
    rpm: Option<f64>,
    omega: Option<f64>,
    torque: Option<f64>,
    friction: Option<f64>,
    decimals: Option<usize>,
    unit: Option<&str>,
    force_unit: Option<&str>,
    mass: Option<f64>,
    rod_mass: Option<f64>,
    rod_cg: Option<f64>,
    rod_gyration: Option<f64>,
    gas_force: Option<f64>,
    indicator: Option<PathBuf>,
    bore: Option<f64>,
    phases: Option<Vec<f64>>,
    fluctuation: Option<f64>,
    flywheel: Option<f64>,
    cranks: Option<Vec<f64>>,
    planes: Option<Vec<f64>>,
    order: Option<usize>,
    fractions: Option<Vec<f64>>,
    wheel: Option<f64>,
    speed: Option<f64>,
    load: Option<f64>,
    axes: Option<Vec<f64>>,
    inversion: Option<u32>,
    lever: Option<f64>,
    max_cells: u64,
    gravity: Option<&str>,
) -> PyResult<String> {
    let given = angles.as_ref().map(|a| a.as_slice()).transpose()?;
    let mut r = TableRequest::new(parse::<TableName>(name)?);
    r.format = parse(format)?;
    r.n = n;
    r.angles = given.map(Angles::List);
    (r.crank, r.rod, r.offset) = (crank, rod, offset);
    (r.rpm, r.omega, r.torque, r.friction) = (rpm, omega, torque, friction);
    r.decimals = decimals;
    r.unit = unit.map(parse::<Unit>).transpose()?;
    r.force_unit = force_unit.map(parse::<Unit>).transpose()?;
    r.engine = given_engine(
        mass,
        (rod_mass, rod_cg, rod_gyration),
        (gas_force, indicator, bore),
        gravity.map(parse).transpose()?,
    );
    (r.phases, r.fluctuation, r.flywheel) = (phases, fluctuation, flywheel);
    (r.cranks, r.planes, r.order, r.fractions) = (cranks, planes, order, fractions);
    (r.wheel, r.speed, r.load, r.axes) = (wheel, speed, load, axes);
    (r.inversion, r.lever, r.max_cells) = (inversion, lever, max_cells);
    py.detach(|| r.plan()?.text()).map_err(py_err)
}

/// Writes each text of `files` to its path whole, or none of them, as the
/// command line writes its files (the library's `write_atomic_all`): staged
/// under unpredictable temporary names in each target's directory and
/// renamed into place, a symbolic link at a target kept and its target
/// replaced, a failure leaving every old file as it was. A path of
/// `derived` (a file named after the one the caller gave, an exercise's
/// key) that is a symbolic link is refused before anything is written, as
/// the command line refuses it (`render::no_link_at_derived`).
#[pyfunction]
#[pyo3(signature = (files, derived=Vec::new()))]
fn write_files(
    py: Python<'_>,
    files: Vec<(PathBuf, String)>,
    derived: Vec<PathBuf>,
) -> PyResult<()> {
    py.detach(|| {
        no_link_at_derived(&derived)?;
        write_atomic_all(&files, |_, _| ())
    })
    .map_err(py_err)
}

/// Writes the gallery `slider-crank gallery --out DIR [--only LIST |
/// --manifest FILE]` writes into the directory `out` (made if missing), as
/// the command writes it (the library's `GalleryRequest` and
/// `Gallery::write_into`): every named figure (or those of `only`, or what
/// the manifest holds) as SVG, PNG and PDF, the tables and `index.html`,
/// all staged before any is renamed into place, a link of a gallery's
/// name replaced rather than followed, the directory locked; a failure
/// leaves every old file and no staged one. Returns the names of the
/// files.
#[pyfunction]
#[pyo3(signature = (out, only=None, manifest=None))]
fn gallery(
    py: Python<'_>,
    out: PathBuf,
    only: Option<Vec<String>>,
    manifest: Option<PathBuf>,
) -> PyResult<Vec<String>> {
    let gallery = gallery_request(only, manifest.clone())?;
    py.detach(|| gallery.write_into(&out, manifest.as_deref(), |_, _| ()))
        .map_err(py_err)?;
    Ok(gallery.file_names())
}

/// Compares the gallery `gallery(out, only, manifest)` would write with
/// the files in `out`, writing nothing, as `slider-crank gallery --check`
/// does (the library's `Gallery::compare_with`): the path of each file
/// that differs, is missing, is not a regular file or was left by an
/// interrupted gallery, with those words; none when `out` holds the
/// gallery.
#[pyfunction]
#[pyo3(signature = (out, only=None, manifest=None))]
fn gallery_differences(
    py: Python<'_>,
    out: PathBuf,
    only: Option<Vec<String>>,
    manifest: Option<PathBuf>,
) -> PyResult<Vec<(PathBuf, &'static str)>> {
    let gallery = gallery_request(only, manifest)?;
    let mut found = Vec::new();
    py.detach(|| {
        gallery.compare_with(
            &out,
            |_, _| (),
            |path, difference| {
                found.push((path.to_path_buf(), difference.words()));
                Ok(())
            },
        )
    })
    .map_err(py_err)?;
    Ok(found)
}

/// The gallery of the keywords `only` and `manifest`, as the command
/// line's `--only` and `--manifest` ask for it.
fn gallery_request(only: Option<Vec<String>>, manifest: Option<PathBuf>) -> PyResult<Gallery> {
    let mut request = GalleryRequest::default();
    (request.only, request.manifest) = (only, manifest);
    request.gallery().map_err(py_err)
}

/// The names of the figures, in the order `--help` lists them.
#[pyfunction]
fn figure_names() -> Vec<String> {
    FigureName::ALL.iter().map(|n| n.to_string()).collect()
}

/// The native half of the `slider_crank` package.
#[pymodule]
fn _core(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(check_engine, m)?)?;
    m.add_function(wrap_pyfunction!(crank_speed, m)?)?;
    m.add_function(wrap_pyfunction!(analyze, m)?)?;
    m.add_function(wrap_pyfunction!(sweep, m)?)?;
    m.add_function(wrap_pyfunction!(figure, m)?)?;
    m.add_function(wrap_pyfunction!(encode, m)?)?;
    m.add_function(wrap_pyfunction!(save, m)?)?;
    m.add_function(wrap_pyfunction!(figure_names, m)?)?;
    m.add_function(wrap_pyfunction!(handout, m)?)?;
    m.add_function(wrap_pyfunction!(table, m)?)?;
    m.add_function(wrap_pyfunction!(gallery, m)?)?;
    m.add_function(wrap_pyfunction!(gallery_differences, m)?)?;
    m.add_function(wrap_pyfunction!(write_files, m)?)?;
    m.add("DEFAULT_MAX_CELLS", DEFAULT_MAX_CELLS)?;
    m.add("DEFAULT_RPM", DEFAULT_RPM)?;
    m.add("DEFAULT_FRAMES", DEFAULT_FRAMES)?;
    m.add("DEFAULT_PERIOD", DEFAULT_PERIOD)?;
    m.add_class::<dynamics::PyEngine>()?;
    m.add("EXAMPLE_MASS", slider_crank::dynamics::EXAMPLE_MASS)?;
    m.add("DYNAMICS_ROWS", dynamics::SWEEP_ROWS)?;
    chain::register(m)?;
    balance::register(m)?;
    m.add_function(wrap_pyfunction!(check::engine_check, m)?)?;
    m.add("VERSION", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
