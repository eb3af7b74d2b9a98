//! `slider-crank table`: the seeds' tables and sweeps.

use super::args::{AngleSpec, GuardArgs, UnitArgs, parse_list};
use super::output::Stdout;
use super::stream;
use clap::builder::PossibleValue;
use clap::{Args, ValueEnum};
use slider_crank::Result;
use slider_crank::lists::Angles;
use slider_crank::table::{Format, TableName, TableRequest};

/// Which table: the library's [`TableName`], with the help the command
/// line lists for each.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct TableArg(pub TableName);

/// The tables as the command line lists them.
const TABLES: [TableArg; 10] = [
    TableArg(TableName::Obliquity),
    TableArg(TableName::AccelerationFactor),
    TableArg(TableName::Kinematics),
    TableArg(TableName::Forces),
    TableArg(TableName::Dynamics),
    TableArg(TableName::Balance),
    TableArg(TableName::Harmonics),
    TableArg(TableName::PartialBalance),
    TableArg(TableName::Radial),
    TableArg(TableName::QuickReturn),
];

impl ValueEnum for TableArg {
    fn value_variants<'a>() -> &'a [Self] {
        &TABLES
    }

    fn to_possible_value(&self) -> Option<PossibleValue> {
        Some(PossibleValue::new(self.0.name()).help(help(self.0)))
    }
}

/// What `table --help` says of a table.
fn help(name: TableName) -> &'static str {
    match name {
        TableName::Obliquity => {
            "Error due to obliquity √(n² − sin²θ) − n, in crank radii, at θ = 90° (textbook §35)"
        }
        TableName::AccelerationFactor => "cos θ + cos 2θ / n, the textbook's table of eq. (3)",
        TableName::Kinematics => {
            "A θ sweep of the slider's position, velocity and acceleration and the rod's angle and rates"
        }
        TableName::Forces => {
            "Ng's Table 2: slider force F, with friction F' and transmission angle β against θ"
        }
        TableName::Dynamics => {
            "Engine dynamics against θ: gas and inertia forces, piston effort, rod force, thrust on the guides, crank effort F·OM and the rod's torque; the turn's mean torque, fluctuation of energy and flywheel as notes (engine flags --mass … --flywheel; default the §35 engine with m = 10)"
        }
        TableName::Balance => {
            "Balance of an in-line engine of several cylinders (--cranks, --planes): the unbalanced primary and secondary forces and couples against θ ÷ m r ω², each polygon's resultant and the verdict as notes (default: four cylinders, flat crank 0,180,180,0, equal pitch; n = l/r from --crank and --rod, §35's 6)"
        }
        TableName::Harmonics => {
            "The piston's acceleration of an in-line engine as a series cos θ + A₂ cos 2θ + A₄ cos 4θ + … (--order K harmonics, default 3): each exact coefficient and the largest error of the series cut after it (n = l/r from --crank and --rod, §35's 6)"
        }
        TableName::PartialBalance => {
            "Partial balance of a single cylinder: the unbalanced primary force ÷ m r ω² along and across the line of stroke and its size against θ, for each fraction c of the reciprocating mass a counterweight balances (--fractions, default 0,0.5,0.6667,1); with --wheel D --speed V --mass M the hammer blow c m r ω² of a locomotive's coupled wheel (and with --load P the speed at which it lifts the wheel)"
        }
        TableName::Radial => {
            "Cylinders on one crank, a V engine or a radial engine (--axes, default the 90° V-twin -45,45): the primary and secondary forces ÷ m r ω² in size and direction against θ, the exact force, and the direct and reverse cranks as notes (n = l/r from --crank and --rod, §35's 6)"
        }
        TableName::QuickReturn => {
            "The quick return of inversion 3 (the crank and slotted lever) or 2 (--inversion 2, Whitworth's): the tool's position, velocity and acceleration against θ over the cutting and return strokes, the time ratio and the stroke in the title (--lever L, the arm of the slotted link driving the tool, default l + r; default the chain r = 0.5, l = 1.5 ft at 250 rpm of the driver, θ every 15°)"
        }
        _ => "",
    }
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
    pub name: TableArg,
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
    /// Coefficient of friction μ ≥ 0 of the slider: for forces Ng's
    /// statics [default: 1, Ng's 45° tilt]; for dynamics the guides'
    /// friction μ|N| against the slider's motion, 0 when not given
    /// (refused where the slider would self-lock, μ |tan φ| ≥ 1)
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

/// The request the flags make ([`TableRequest`]): the lists parsed, the
/// rest as given.
fn request(args: &TableArgs) -> Result<TableRequest<'static>> {
    let list = |text: &Option<String>, name: &str| {
        text.as_deref()
            .map(|s| parse_list(s, name, false))
            .transpose()
    };
    let mut r = TableRequest::new(args.name.0);
    r.format = match args.format {
        FormatArg::Text => Format::Text,
        FormatArg::Markdown => Format::Markdown,
        FormatArg::Csv => Format::Csv,
    };
    r.n = args
        .n
        .as_deref()
        .map(|s| parse_list(s, "n", true))
        .transpose()?;
    r.angles = args
        .angles
        .as_deref()
        .map(AngleSpec::parse)
        .transpose()?
        .map(Angles::Spec);
    (r.crank, r.rod, r.offset) = (args.crank, args.rod, args.offset);
    (r.rpm, r.omega) = (args.rpm, args.omega);
    (r.torque, r.friction, r.decimals) = (args.torque, args.friction, args.decimals);
    (r.unit, r.force_unit) = (args.units.length.clone(), args.units.force.clone());
    r.engine = args.engine.given();
    r.phases = list(&args.turn.phases, "phase")?;
    (r.fluctuation, r.flywheel) = (args.turn.fluctuation, args.turn.flywheel);
    r.cranks = list(&args.cranks, "crank angle")?;
    r.planes = list(&args.planes, "plane")?;
    r.order = args.order;
    r.fractions = list(&args.fractions, "fraction")?;
    (r.wheel, r.speed, r.load) = (args.wheel, args.speed, args.load);
    r.axes = list(&args.axes, "axis")?;
    (r.inversion, r.lever) = (args.inversion, args.lever);
    r.max_cells = args.guard.max_cells;
    Ok(r)
}

/// Runs the subcommand. Every table is written a row at a time: memory
/// does not grow with the number of angles; rows × columns are bounded by
/// `--max-cells` before any is computed. A table of a row an angle is
/// computed on every core ([`stream::table`]).
pub fn run(args: &TableArgs, out: &mut Stdout) -> Result<()> {
    let plan = request(args)?.plan()?;
    match plan.row_per_angle() {
        Some((angles, row)) => {
            stream::table(plan.format(), &plan.head(), || angles.iter(), row, out)
        }
        None => plan.write(&mut |s| out.text(s)),
    }
}
