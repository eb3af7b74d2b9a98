//! `slider-crank table`: the seeds' tables and sweeps.

use super::args::{AngleSpec, MechanismArgs, SpeedArgs, parse_list};
use super::output::Stdout;
use clap::{Args, ValueEnum};
use slider_crank::table::{self, Format, Head, TEXTBOOK_ANGLES, TEXTBOOK_RATIOS};
use slider_crank::{Error, Result, SliderCrank};

/// Which table.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum TableName {
    /// Error due to obliquity √(n² − sin²θ) − n at θ = 90° (textbook §35)
    Obliquity,
    /// cos θ + cos 2θ / n, the textbook's table of eq. (3)
    AccelerationFactor,
    /// A θ sweep of x, v, a and the rod's angle and rates
    Kinematics,
    /// Ng's Table 2: F, F' and β against θ
    Forces,
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
    /// (inf for the infinitely long rod) [default: the textbook's]
    #[arg(long, value_name = "LIST", allow_hyphen_values = true)]
    pub n: Option<String>,
    /// Crank angles in degrees: a list or START:STOP:STEP [default: the
    /// textbook's rows; 90 for obliquity; 0:360:30 for kinematics; 10:160:10
    /// for forces]
    #[arg(long, value_name = "DEG", allow_hyphen_values = true)]
    pub angles: Option<String>,
    /// Crank radius (kinematics [default 0.5 ft]; forces [default 25 mm])
    #[arg(long, allow_hyphen_values = true, value_name = "R")]
    pub crank: Option<f64>,
    /// Rod length (kinematics [default 3 ft]; forces [default 72 mm])
    #[arg(long, allow_hyphen_values = true, value_name = "L")]
    pub rod: Option<f64>,
    /// Offset of the line of stroke [default 0]
    #[arg(
        long,
        value_name = "E",
        default_value_t = 0.0,
        allow_hyphen_values = true
    )]
    pub offset: f64,
    #[command(flatten)]
    pub speed: SpeedArgs,
    /// Crank torque for forces, in force × the length unit [default:
    /// 264.87 N·mm = 1 kg × 9.81 m/s² × 27 mm, the torque Ng's F column
    /// implies]
    #[arg(long, allow_hyphen_values = true, value_name = "T")]
    pub torque: Option<f64>,
    /// Friction coefficient for forces [default: 1, Ng's 45° tilt]
    #[arg(long, allow_hyphen_values = true, value_name = "MU")]
    pub friction: Option<f64>,
    /// Decimals for kinematics [default 4] and forces [default 2]
    #[arg(long, value_name = "D", allow_hyphen_values = true)]
    pub decimals: Option<usize>,
}

/// Ng's torque as implied by Table 2's F column, N·mm.
pub const NG_TABLE_2_TORQUE: f64 = 1.0 * 9.81 * 27.0;

fn mechanism(args: &TableArgs, crank: f64, rod: f64) -> Result<SliderCrank> {
    MechanismArgs {
        crank: args.crank.unwrap_or(crank),
        rod: args.rod.unwrap_or(rod),
        offset: args.offset,
    }
    .mechanism()
}

/// Runs the subcommand. The kinematics table is written a row at a time
/// (memory does not grow with the number of angles); the others are small.
pub fn run(args: &TableArgs, out: &mut Stdout) -> Result<()> {
    let ratios = args
        .n
        .as_deref()
        .map(|s| parse_list(s, "n", true))
        .transpose()?;
    let spec = args.angles.as_deref().map(AngleSpec::parse).transpose()?;
    let angles = || spec.as_ref().map(|s| s.iter().collect::<Vec<f64>>());
    let decimals = args.decimals.unwrap_or(match args.name {
        TableName::Forces => 2,
        _ => 4,
    });
    if decimals > 17 {
        return Err(Error::OutOfRange {
            name: "decimals",
            value: decimals as f64,
            reason: "at most 17 decimals are meaningful in f64".into(),
        });
    }
    let format = match args.format {
        FormatArg::Text => Format::Text,
        FormatArg::Markdown => Format::Markdown,
        FormatArg::Csv => Format::Csv,
    };
    let t = match args.name {
        TableName::Obliquity => {
            let ratios = ratios.unwrap_or_else(|| vec![4.0, 5.0, 6.0]);
            let angles = angles().unwrap_or_else(|| vec![90.0]);
            let mut t = table::obliquity(&ratios, angles[0])?;
            for &a in &angles[1..] {
                t.rows.extend(table::obliquity(&ratios, a)?.rows);
            }
            t
        }
        TableName::AccelerationFactor => table::acceleration_factor_table(
            &ratios.unwrap_or_else(|| TEXTBOOK_RATIOS.to_vec()),
            &angles().unwrap_or_else(|| TEXTBOOK_ANGLES.to_vec()),
        )?,
        TableName::Kinematics => {
            let m = mechanism(args, 0.5, 3.0)?;
            let omega = args.speed.omega()?;
            let spec = match &spec {
                Some(s) => s.clone(),
                None => AngleSpec::parse("0:360:30")?,
            };
            let head = table::kinematics_head(&m, omega);
            let rows = || {
                spec.iter()
                    .map(|d| table::kinematics_row(&m, omega, d, decimals))
            };
            let head = Head {
                title: &head.title,
                headers: &head.headers,
                notes: &head.notes,
            };
            return table::render_rows(format, &head, rows, &mut |s| out.text(s));
        }
        TableName::Forces => {
            let m = mechanism(args, 25.0, 72.0)?;
            let torque = args.torque.unwrap_or(NG_TABLE_2_TORQUE);
            if !torque.is_finite() {
                return Err(Error::NotFinite {
                    name: "torque",
                    value: torque,
                });
            }
            let angles = angles().unwrap_or_else(|| (1..=16).map(|k| 10.0 * k as f64).collect());
            table::forces(&m, torque, args.friction.unwrap_or(1.0), &angles, decimals)?
        }
    };
    out.text(&t.render(format))
}
