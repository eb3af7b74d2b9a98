//! `slider-crank table`: the seeds' tables and sweeps.

use super::args::{AngleSpec, GuardArgs, MechanismArgs, SpeedArgs, UnitArgs, parse_list};
use super::output::Stdout;
use super::stream;
use clap::{Args, ValueEnum};
use slider_crank::sources::{ENGINE_35, NG_RIG, NG_TORQUE};
use slider_crank::table::{self, Format, Head, TEXTBOOK_ANGLES, TEXTBOOK_RATIOS};
use slider_crank::{Error, Field, Input, Result, SliderCrank, Units};

/// Which table.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum TableName {
    /// Error due to obliquity √(n² − sin²θ) − n, in crank radii, at θ = 90° (textbook §35)
    Obliquity,
    /// cos θ + cos 2θ / n, the textbook's table of eq. (3)
    AccelerationFactor,
    /// A θ sweep of the slider's position, velocity and acceleration and the rod's angle and rates
    Kinematics,
    /// Ng's Table 2: slider force F, with friction F' and transmission angle β against θ
    Forces,
    /// Engine dynamics against θ: gas and inertia forces, piston effort, rod force, thrust on the guides, crank effort F·OM and the rod's torque; the turn's mean torque, fluctuation of energy and flywheel as notes (engine flags --mass … --flywheel; default the §35 engine with m = 10)
    Dynamics,
    /// Balance of an in-line engine of several cylinders (--cranks, --planes): the unbalanced primary and secondary forces and couples against θ ÷ m r ω², each polygon's resultant and the verdict as notes (default: four cylinders, flat crank 0,180,180,0, equal pitch; n = l/r from --crank and --rod, §35's 6)
    Balance,
    /// The piston's acceleration of an in-line engine as a series cos θ + A₂ cos 2θ + A₄ cos 4θ + … (--order K harmonics, default 3): each exact coefficient and the largest error of the series cut after it (n = l/r from --crank and --rod, §35's 6)
    Harmonics,
    /// Partial balance of a single cylinder: the unbalanced primary force ÷ m r ω² along and across the line of stroke and its size against θ, for each fraction c of the reciprocating mass a counterweight balances (--fractions, default 0,0.5,0.6667,1); with --wheel D --speed V --mass M the hammer blow c m r ω² of a locomotive's coupled wheel (and with --load P the speed at which it lifts the wheel)
    PartialBalance,
    /// Cylinders on one crank, a V engine or a radial engine (--axes, default the 90° V-twin -45,45): the primary and secondary forces ÷ m r ω² in size and direction against θ, the exact force, and the direct and reverse cranks as notes (n = l/r from --crank and --rod, §35's 6)
    Radial,
    /// The quick return of inversion 3 (the crank and slotted lever) or 2 (--inversion 2, Whitworth's): the tool's position, velocity and acceleration against θ over the cutting and return strokes, the time ratio and the stroke in the title (--lever L, the arm of the slotted link driving the tool, default l + r; default the chain r = 0.5, l = 1.5 ft at 250 rpm of the driver, θ every 15°)
    QuickReturn,
}

/// Output formats.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum FormatArg {
    /// Aligned columns
    Text,
    /// Markdown table
    Markdown,
    /// Comma-separated values
    Csv,
}

/// Print one of the tables.
#[derive(Debug, Args)]
pub struct TableArgs {
    /// The table to print
    #[arg(value_enum)]
    pub name: TableName,
    /// Output format
    #[arg(long, value_enum, default_value_t = FormatArg::Text)]
    pub format: FormatArg,
    /// Ratios n = l/r for obliquity and acceleration-factor, comma-separated
    /// (inf for the infinitely long rod) [default: the textbook's, 4,5,6
    /// for obliquity and 4,4.5,5,5.5,6,inf for acceleration-factor]
    #[arg(long, value_name = "LIST", allow_hyphen_values = true)]
    pub n: Option<String>,
    /// Crank angles in degrees: a list or START:STOP:STEP [default: 90 for
    /// obliquity, the textbook's rows 0:180:30 for acceleration-factor,
    /// 0:360:30 for kinematics, Ng's rows 10:160:10 for forces]; --angle,
    /// as `analyze` spells it, is the same
    #[arg(
        long,
        visible_alias = "angle",
        value_name = "DEG",
        allow_hyphen_values = true
    )]
    pub angles: Option<String>,
    /// Crank radius r for kinematics and forces, in any length unit
    /// [default: 0.5 (ft, §35) for kinematics, 25 (mm, Ng) for forces]
    #[arg(long, allow_hyphen_values = true, value_name = "R")]
    pub crank: Option<f64>,
    /// Rod length l for kinematics and forces, in the unit of --crank
    /// [default: 3 (ft, §35) for kinematics, 72 (mm, Ng) for forces]
    #[arg(long, allow_hyphen_values = true, value_name = "L")]
    pub rod: Option<f64>,
    /// Offset e of the line of stroke for kinematics and forces, in the
    /// unit of --crank [default: 0]
    #[arg(long, value_name = "E", allow_hyphen_values = true)]
    pub offset: Option<f64>,
    /// Crank speed for kinematics, in revolutions per minute, positive
    /// counter-clockwise (or give --omega) [default: 250]
    #[arg(
        long,
        allow_hyphen_values = true,
        value_name = "N",
        conflicts_with = "omega"
    )]
    pub rpm: Option<f64>,
    /// Crank speed ω for kinematics, in rad/s, positive counter-clockwise
    /// (instead of --rpm)
    #[arg(long, allow_hyphen_values = true, value_name = "W")]
    pub omega: Option<f64>,
    /// Crank torque T for forces, in force × the length unit [default:
    /// 264.87 N·mm = 1 kg × 9.81 m/s² × 27 mm, the torque Ng's F column
    /// implies]
    #[arg(long, allow_hyphen_values = true, value_name = "T")]
    pub torque: Option<f64>,
    /// Coefficient of friction μ ≥ 0 of the slider for forces [default: 1,
    /// Ng's 45° tilt]
    #[arg(long, allow_hyphen_values = true, value_name = "MU")]
    pub friction: Option<f64>,
    /// Decimals printed by kinematics and forces [default: 4 for
    /// kinematics, 2 for forces]
    #[arg(long, value_name = "D", allow_hyphen_values = true)]
    pub decimals: Option<usize>,
    /// Crank angles of an in-line engine's cylinders for balance, degrees
    /// ahead of the first, comma-separated [default: 0,180,180,0]
    #[arg(long, value_name = "LIST", allow_hyphen_values = true)]
    pub cranks: Option<String>,
    /// Distances of the cylinders' lines of stroke from the reference
    /// plane along the shaft for balance, in the length unit,
    /// comma-separated (a couple depends on the plane where its force is
    /// not balanced) [default: a pitch of 1 about the middle, −1.5,−0.5,0.5,1.5
    /// for four]
    #[arg(long, value_name = "LIST", allow_hyphen_values = true)]
    pub planes: Option<String>,
    /// Harmonics cos 2θ … cos 2Kθ of the series for harmonics [default: 3]
    #[arg(long, value_name = "K")]
    pub order: Option<usize>,
    /// Fractions c of the reciprocating mass balanced, 0 to 1, for
    /// partial-balance, comma-separated [default: 0,0.5,0.6667,1 (⅔)]
    #[arg(long, value_name = "LIST", allow_hyphen_values = true)]
    pub fractions: Option<String>,
    /// A locomotive's wheel diameter D for partial-balance's hammer blow,
    /// in the length unit (give --speed and --mass with it)
    #[arg(long, value_name = "D", allow_hyphen_values = true, requires_all = ["speed", "mass", "crank"])]
    pub wheel: Option<f64>,
    /// The locomotive's speed v along the rails for the hammer blow, in
    /// the length unit per second (the wheel turns at 2v/D)
    #[arg(long, value_name = "V", allow_hyphen_values = true, requires = "wheel")]
    pub speed: Option<f64>,
    /// The wheel's static load P on the rail, in the force unit: the
    /// hammer blow's note adds the speed at which the wheel lifts off
    #[arg(long, value_name = "P", allow_hyphen_values = true, requires = "wheel")]
    pub load: Option<f64>,
    /// Axes of the cylinders on one crank for radial, degrees from the
    /// reference line, comma-separated (a V of included angle 2α: -α,α;
    /// a radial engine of k cylinders: 360/k apart) [default: -45,45]
    #[arg(long, value_name = "LIST", allow_hyphen_values = true)]
    pub axes: Option<String>,
    /// The inversion of quick-return: 3, the crank and slotted lever, or
    /// 2, Whitworth's [default: 3]
    #[arg(long, value_name = "N")]
    pub inversion: Option<u32>,
    /// The arm L of the slotted link that drives the tool for
    /// quick-return, in the length unit [default: l + r]
    #[arg(long, allow_hyphen_values = true, value_name = "L")]
    pub lever: Option<f64>,
    #[command(flatten)]
    pub units: UnitArgs,
    #[command(flatten)]
    pub guard: GuardArgs,
    #[command(flatten)]
    pub engine: super::dynamics::EngineArgs,
    #[command(flatten)]
    pub turn: super::dynamics::TurnArgs,
}

/// The angles of `table kinematics` and `table dynamics` when none are
/// given: the turn every 30°.
const TURN_ANGLES: &str = "0:360:30";

fn mechanism(args: &TableArgs, (crank, rod): (f64, f64)) -> Result<SliderCrank> {
    MechanismArgs {
        crank: args.crank.unwrap_or(crank),
        rod: args.rod.unwrap_or(rod),
        offset: args.offset.unwrap_or(0.0),
    }
    .mechanism()
}

/// Runs the subcommand. Every table is written a row at a time: memory
/// does not grow with the number of angles; rows × columns are bounded by
/// `--max-cells` before any is computed.
pub fn run(args: &TableArgs, out: &mut Stdout) -> Result<()> {
    if let Some(bad) = unused(args) {
        return Err(Error::invalid(
            Input::Options,
            format!("table {} does not use {bad}", table_name(args.name)),
        ));
    }
    let ratios = args
        .n
        .as_deref()
        .map(|s| parse_list(s, "n", true))
        .transpose()?;
    let spec = args.angles.as_deref().map(AngleSpec::parse).transpose()?;
    let decimals = args.decimals.unwrap_or(match args.name {
        TableName::Forces => 2,
        _ => 4,
    });
    if decimals > 17 {
        return Err(Error::OutOfRange {
            name: Field::Decimals,
            value: decimals as f64,
            reason: "at most 17 decimals are meaningful in f64".into(),
        });
    }
    let format = match args.format {
        FormatArg::Text => Format::Text,
        FormatArg::Markdown => Format::Markdown,
        FormatArg::Csv => Format::Csv,
    };
    match args.name {
        TableName::Obliquity => obliquity(args, ratios, spec, format, out),
        TableName::AccelerationFactor => acceleration_factor(args, ratios, spec, format, out),
        TableName::Kinematics => kinematics(args, spec, decimals, format, out),
        TableName::Forces => forces(args, spec, decimals, format, out),
        TableName::Dynamics => dynamics(args, spec, decimals, format, out),
        TableName::Balance => balance(args, spec, decimals, format, out),
        TableName::Harmonics => harmonics(args, decimals, format, out),
        TableName::PartialBalance => partial_balance(args, spec, decimals, format, out),
        TableName::Radial => radial(args, spec, decimals, format, out),
        TableName::QuickReturn => quick_return(args, spec, decimals, format, out),
    }
}

/// The angles of `table quick-return` when none are given: every 15°,
/// the strokes' ends at 90° and 270° among them.
const QUICK_RETURN_ANGLES: &str = "0:360:15";

/// `table quick-return`: the tool's motion over the two strokes.
fn quick_return(
    args: &TableArgs,
    spec: Option<AngleSpec>,
    decimals: usize,
    format: Format,
    out: &mut Stdout,
) -> Result<()> {
    let m = mechanism(args, (0.5, 1.5))?;
    let omega = omega(args)?;
    let inversion = slider_crank::Inversion::from_number(args.inversion.unwrap_or(3))?;
    let lever = args
        .lever
        .unwrap_or_else(|| slider_crank::chain::QuickReturn::default_lever(&m));
    let q = slider_crank::chain::QuickReturn::new(m, inversion, lever)?;
    let spec = spec.map_or_else(|| AngleSpec::parse(QUICK_RETURN_ANGLES), Ok)?;
    let units = args.units.units(Units::FOOT_POUND);
    let head = table::quick_return_head(&q, omega, &units);
    guard_angles(args, "table quick-return", &spec, &head)?;
    let row = |d| table::quick_return_row(&q, omega, d, decimals);
    write_angle_rows(format, &head, || spec.iter(), row, out)
}

/// `table harmonics`: the acceleration's series and each cut's error.
fn harmonics(args: &TableArgs, decimals: usize, format: Format, out: &mut Stdout) -> Result<()> {
    let m = mechanism(args, ENGINE_35)?;
    let order = args
        .order
        .unwrap_or(slider_crank::analytic::harmonics::DEFAULT_ORDER);
    let series = slider_crank::analytic::harmonics::Harmonics::new(m.ratio(), order)?;
    let t = table::harmonics_table(
        &series,
        args.decimals
            .map_or(slider_crank::analytic::harmonics::DEFAULT_DECIMALS, |_| {
                decimals
            }),
    );
    write_rows(format, &t, || t.rows.iter().cloned().map(Ok), out)
}

/// `table balance`: an in-line engine's unbalanced forces and couples.
fn balance(
    args: &TableArgs,
    spec: Option<AngleSpec>,
    decimals: usize,
    format: Format,
    out: &mut Stdout,
) -> Result<()> {
    let m = mechanism(args, ENGINE_35)?;
    let cranks = match &args.cranks {
        Some(s) => parse_list(s, "crank angle", false)?,
        None => slider_crank::dynamics::DEFAULT_CRANKS.to_vec(),
    };
    let planes = match &args.planes {
        Some(s) => parse_list(s, "plane", false)?,
        None => slider_crank::dynamics::default_planes(cranks.len()),
    };
    let engine = slider_crank::dynamics::InlineEngine::new(&cranks, &planes, m.ratio())?;
    let spec = spec.map_or_else(|| AngleSpec::parse(TURN_ANGLES), Ok)?;
    let units = args.units.units(Units::FOOT_POUND);
    let head = table::balance_head(&engine, &units);
    guard_angles(args, "table balance", &spec, &head)?;
    let row = |d| table::balance_row(&engine, d, decimals);
    write_angle_rows(format, &head, || spec.iter(), row, out)
}

/// `table partial-balance`: a single cylinder's unbalanced force for
/// each fraction, and the hammer blow.
fn partial_balance(
    args: &TableArgs,
    spec: Option<AngleSpec>,
    decimals: usize,
    format: Format,
    out: &mut Stdout,
) -> Result<()> {
    use slider_crank::dynamics::{DEFAULT_FRACTIONS, PartialBalance};
    let fractions = match &args.fractions {
        Some(s) => parse_list(s, "fraction", false)?,
        None => DEFAULT_FRACTIONS.to_vec(),
    };
    let balances = fractions
        .iter()
        .map(|&c| PartialBalance::new(c))
        .collect::<Result<Vec<_>>>()?;
    let locomotive = match args.wheel {
        Some(wheel) => Some(locomotive(args, wheel)?),
        None if args.engine.mass.is_some() || args.crank.is_some() => {
            return Err(Error::invalid(
                Input::Options,
                "table partial-balance takes --mass and --crank for the hammer blow only: give --wheel and --speed with them".into(),
            ));
        }
        None => None,
    };
    let spec = spec.map_or_else(|| AngleSpec::parse(TURN_ANGLES), Ok)?;
    let units = args.units.units(Units::FOOT_POUND);
    let head = table::partial_balance_head(&balances, locomotive.as_ref(), &units)?;
    guard_angles(args, "table partial-balance", &spec, &head)?;
    let row = |d| table::partial_balance_row(&balances, d, decimals);
    write_angle_rows(format, &head, || spec.iter(), row, out)
}

/// The locomotive of the hammer blow: `--wheel`, `--speed`, `--mass`,
/// `--crank` and `--load`, checked by the library.
fn locomotive(args: &TableArgs, wheel: f64) -> Result<table::Locomotive> {
    table::Locomotive::new(
        args.engine.mass.unwrap_or(0.0),
        args.crank.unwrap_or(0.0),
        wheel,
        args.speed.unwrap_or(0.0),
        args.load,
    )
}

/// `table radial`: cylinders on one crank.
fn radial(
    args: &TableArgs,
    spec: Option<AngleSpec>,
    decimals: usize,
    format: Format,
    out: &mut Stdout,
) -> Result<()> {
    let m = mechanism(args, ENGINE_35)?;
    let axes = match &args.axes {
        Some(s) => parse_list(s, "axis", false)?,
        None => slider_crank::dynamics::DEFAULT_AXES.to_vec(),
    };
    let engine = slider_crank::dynamics::RadialEngine::new(&axes, m.ratio())?;
    let spec = spec.map_or_else(|| AngleSpec::parse(TURN_ANGLES), Ok)?;
    let head = table::radial_head(&engine);
    guard_angles(args, "table radial", &spec, &head)?;
    let row = |d| table::radial_row(&engine, d, decimals);
    write_angle_rows(format, &head, || spec.iter(), row, out)
}

/// `table obliquity`: φ for the ratios `ratios` at the angles `spec`.
fn obliquity(
    args: &TableArgs,
    ratios: Option<Vec<f64>>,
    spec: Option<AngleSpec>,
    format: Format,
    out: &mut Stdout,
) -> Result<()> {
    let ratios = ratios.unwrap_or_else(|| vec![4.0, 5.0, 6.0]);
    let spec = spec.unwrap_or(AngleSpec::parse("90")?);
    let first = spec.iter().next().unwrap_or(90.0);
    let several = spec.len() > 1;
    let head = table::obliquity_head(&ratios, first, several)?;
    args.guard
        .bound()
        .check_obliquity(spec.len(), ratios.len() as u64, head.headers.len())?;
    let rows = || {
        spec.iter()
            .flat_map(|a| match table::obliquity_rows(&ratios, a, several) {
                Ok(rows) => rows.into_iter().map(Ok).collect::<Vec<_>>(),
                Err(e) => vec![Err(e)],
            })
    };
    write_rows(format, &head, rows, out)
}

/// `table acceleration-factor`: the textbook's factor for the ratios
/// `ratios` at the angles `spec` (the textbook's when not given).
fn acceleration_factor(
    args: &TableArgs,
    ratios: Option<Vec<f64>>,
    spec: Option<AngleSpec>,
    format: Format,
    out: &mut Stdout,
) -> Result<()> {
    let ratios = ratios.unwrap_or_else(|| TEXTBOOK_RATIOS.to_vec());
    let head = table::acceleration_factor_table(&ratios, &[])?;
    let angles = spec
        .as_ref()
        .map_or(TEXTBOOK_ANGLES.len() as u64, AngleSpec::len);
    args.guard
        .bound()
        .check_angles("table acceleration-factor", angles, head.headers.len())?;
    let row = |d: f64| {
        let t = table::acceleration_factor_table(&ratios, &[d])?;
        Ok(t.rows.into_iter().next().unwrap_or_default())
    };
    match &spec {
        Some(spec) => write_angle_rows(format, &head, || spec.iter(), row, out),
        None => write_angle_rows(format, &head, || TEXTBOOK_ANGLES.into_iter(), row, out),
    }
}

/// `table kinematics`: the exact values at the angles `spec`.
fn kinematics(
    args: &TableArgs,
    spec: Option<AngleSpec>,
    decimals: usize,
    format: Format,
    out: &mut Stdout,
) -> Result<()> {
    let m = mechanism(args, ENGINE_35)?;
    let omega = omega(args)?;
    let spec = spec.map_or_else(|| AngleSpec::parse(TURN_ANGLES), Ok)?;
    let units = args.units.units(Units::FOOT_POUND);
    let head = table::kinematics_head(&m, omega, &units);
    guard_angles(args, "table kinematics", &spec, &head)?;
    let row = |d| table::kinematics_row(&m, omega, d, decimals);
    write_angle_rows(format, &head, || spec.iter(), row, out)
}

/// `table forces`: Ng's Table 2 at the angles `spec`.
fn forces(
    args: &TableArgs,
    spec: Option<AngleSpec>,
    decimals: usize,
    format: Format,
    out: &mut Stdout,
) -> Result<()> {
    let m = mechanism(args, NG_RIG)?;
    let torque = args.torque.unwrap_or(NG_TORQUE);
    if !torque.is_finite() {
        return Err(Error::NotFinite {
            name: Field::Torque,
            value: torque,
        });
    }
    let mu = args.friction.unwrap_or(1.0);
    let spec = spec.map_or_else(|| AngleSpec::parse("10:160:10"), Ok)?;
    let units = args.units.units(Units::MILLIMETRE_NEWTON);
    let head = table::forces_head(&m, torque, mu, &units);
    guard_angles(args, "table forces", &spec, &head)?;
    let row = |d| table::forces_row(&m, torque, mu, d, decimals);
    write_angle_rows(format, &head, || spec.iter(), row, out)
}

/// The crank speed `--rpm` or `--omega` give (the default speed when
/// neither does).
fn omega(args: &TableArgs) -> Result<f64> {
    SpeedArgs {
        rpm: args.rpm,
        omega: args.omega,
    }
    .omega()
}

/// The table's name as typed (`acceleration-factor`).
fn table_name(name: TableName) -> String {
    name.to_possible_value()
        .map_or_else(String::new, |v| v.get_name().to_string())
}

/// The first option given that the table does not use, named as on the
/// command line: a table refuses what it would silently ignore (the
/// ratio tables take no mechanism, speed, load or units; kinematics no
/// ratios, load or force unit; forces no ratios or speed).
fn unused(args: &TableArgs) -> Option<&'static str> {
    let given = [
        ("--n", args.n.is_some()),
        ("--crank", args.crank.is_some()),
        ("--rod", args.rod.is_some()),
        ("--offset", args.offset.is_some()),
        ("--rpm", args.rpm.is_some()),
        ("--omega", args.omega.is_some()),
        ("--torque", args.torque.is_some()),
        ("--friction", args.friction.is_some()),
        ("--decimals", args.decimals.is_some()),
        ("--unit", args.units.length.is_some()),
        ("--force-unit", args.units.force.is_some()),
        ("--mass", args.engine.mass.is_some()),
        ("--rod-mass", args.engine.rod_mass.is_some()),
        ("--rod-cg", args.engine.rod_cg.is_some()),
        ("--rod-gyration", args.engine.rod_gyration.is_some()),
        ("--gas-force", args.engine.gas_force.is_some()),
        ("--indicator", args.engine.indicator.is_some()),
        ("--bore", args.engine.bore.is_some()),
        ("--phases", args.turn.phases.is_some()),
        ("--fluctuation", args.turn.fluctuation.is_some()),
        ("--flywheel", args.turn.flywheel.is_some()),
        ("--cranks", args.cranks.is_some()),
        ("--planes", args.planes.is_some()),
        ("--order", args.order.is_some()),
        ("--fractions", args.fractions.is_some()),
        ("--wheel", args.wheel.is_some()),
        ("--speed", args.speed.is_some()),
        ("--load", args.load.is_some()),
        ("--axes", args.axes.is_some()),
        ("--inversion", args.inversion.is_some()),
        ("--lever", args.lever.is_some()),
    ];
    let used: &[&str] = match args.name {
        TableName::Obliquity | TableName::AccelerationFactor => &["--n"],
        TableName::Kinematics => &[
            "--crank",
            "--rod",
            "--offset",
            "--rpm",
            "--omega",
            "--decimals",
            "--unit",
        ],
        TableName::Forces => &[
            "--crank",
            "--rod",
            "--offset",
            "--torque",
            "--friction",
            "--decimals",
            "--unit",
            "--force-unit",
        ],
        TableName::Dynamics => &[
            "--crank",
            "--rod",
            "--offset",
            "--rpm",
            "--omega",
            "--decimals",
            "--unit",
            "--force-unit",
            "--mass",
            "--rod-mass",
            "--rod-cg",
            "--rod-gyration",
            "--gas-force",
            "--indicator",
            "--bore",
            "--phases",
            "--fluctuation",
            "--flywheel",
        ],
        TableName::Balance => &[
            "--crank",
            "--rod",
            "--decimals",
            "--unit",
            "--cranks",
            "--planes",
        ],
        TableName::Harmonics => &["--crank", "--rod", "--decimals", "--order"],
        TableName::PartialBalance => &[
            "--crank",
            "--decimals",
            "--unit",
            "--force-unit",
            "--mass",
            "--fractions",
            "--wheel",
            "--speed",
            "--load",
        ],
        TableName::Radial => &["--crank", "--rod", "--decimals", "--axes"],
        TableName::QuickReturn => &[
            "--crank",
            "--rod",
            "--offset",
            "--rpm",
            "--omega",
            "--decimals",
            "--unit",
            "--inversion",
            "--lever",
        ],
    };
    given
        .into_iter()
        .find(|(flag, given)| *given && !used.contains(flag))
        .map(|(flag, _)| flag)
}

/// `--max-cells` against a row per angle of `spec` with the columns of
/// `head`.
fn guard_angles(
    args: &TableArgs,
    command: &str,
    spec: &AngleSpec,
    head: &table::Table,
) -> Result<()> {
    args.guard
        .bound()
        .check_angles(command, spec.len(), head.headers.len())
}

/// `table dynamics`: the engine's forces and torques at each angle; the
/// turn's results in the notes.
fn dynamics(
    args: &TableArgs,
    spec: Option<AngleSpec>,
    decimals: usize,
    format: Format,
    out: &mut Stdout,
) -> Result<()> {
    let m = mechanism(args, ENGINE_35)?;
    let omega = omega(args)?;
    let units = args.units.units(Units::FOOT_POUND);
    let engine = match args.engine.engine(m, omega, &units)? {
        Some(e) => e,
        None => {
            slider_crank::dynamics::Engine::new(m, slider_crank::dynamics::EXAMPLE_MASS, omega)?
        }
    };
    let phases = args.turn.phases()?;
    let spec = spec.map_or_else(|| AngleSpec::parse(TURN_ANGLES), Ok)?;
    let head = slider_crank::table::dynamics_head(&engine, &phases, args.turn.flywheel(), &units)?;
    args.guard
        .bound()
        .check_cylinders(spec.len(), head.headers.len(), phases.len())?;
    let row = |d| slider_crank::table::dynamics_row(&engine, &phases, d, decimals);
    write_angle_rows(format, &head, || spec.iter(), row, out)
}

/// Writes a row `row(angle)` for each of `angles()` under the title and
/// headers of `head`, on every core (see [`stream::table`]).
fn write_angle_rows<A: Iterator<Item = f64>>(
    format: Format,
    head: &table::Table,
    angles: impl Fn() -> A,
    row: impl Fn(f64) -> Result<Vec<String>> + Sync,
    out: &mut Stdout,
) -> Result<()> {
    let head = Head {
        title: &head.title,
        headers: &head.headers,
        notes: &head.notes,
    };
    stream::table(format, &head, angles, row, out)
}

/// Writes the rows as they are computed under the title and headers of
/// `head` (see [`table::render_rows`]).
fn write_rows<I>(
    format: Format,
    head: &table::Table,
    rows: impl Fn() -> I,
    out: &mut Stdout,
) -> Result<()>
where
    I: Iterator<Item = Result<Vec<String>>>,
{
    let head = Head {
        title: &head.title,
        headers: &head.headers,
        notes: &head.notes,
    };
    table::render_rows(format, &head, rows, &mut |s| out.text(s))
}
