//! Flags shared by the subcommands and the parsing of angle specifications.

use clap::Args;
use slider_crank::table::DEFAULT_MAX_CELLS;
use slider_crank::{Unit, Units};

/// The mechanism flags. Defaults: the engine of textbook §35 (12 in stroke,
/// 3 ft rod: r = 0.5 ft, l = 3 ft, in line).
#[derive(Debug, Clone, Args)]
pub struct MechanismArgs {
    /// Crank radius r, in any length unit, named by --unit (give the rod and
    /// the offset in the same unit)
    #[arg(
        long,
        allow_hyphen_values = true,
        default_value_t = 0.5,
        value_name = "R"
    )]
    pub crank: f64,
    /// Connecting-rod length l; must exceed r + |e| so the crank turns fully
    #[arg(
        long,
        allow_hyphen_values = true,
        default_value_t = 3.0,
        value_name = "L"
    )]
    pub rod: f64,
    /// Offset e of the line of stroke from the crank centre: the stroke is
    /// the line y = e (0: in line; positive: above the crank centre)
    #[arg(
        long,
        allow_hyphen_values = true,
        default_value_t = 0.0,
        value_name = "E"
    )]
    pub offset: f64,
}

/// The mechanism flags of `handout`, each `None` where not given, so that
/// a class varies around the teacher's engine only when one is given;
/// the defaults otherwise those of [`MechanismArgs`].
#[derive(Debug, Clone, Args)]
pub struct GivenMechanismArgs {
    /// Crank radius r, in any length unit, named by --unit (give the rod and
    /// the offset in the same unit) [default: 0.5]
    #[arg(long, allow_hyphen_values = true, value_name = "R")]
    pub crank: Option<f64>,
    /// Connecting-rod length l; must exceed r + |e| so the crank turns
    /// fully [default: 3]
    #[arg(long, allow_hyphen_values = true, value_name = "L")]
    pub rod: Option<f64>,
    /// Offset e of the line of stroke from the crank centre: the stroke is
    /// the line y = e (0: in line; positive: above the crank centre)
    /// [default: 0]
    #[arg(long, allow_hyphen_values = true, value_name = "E")]
    pub offset: Option<f64>,
}

impl GivenMechanismArgs {
    /// Whether any of the flags was given.
    pub fn given(&self) -> bool {
        self.crank.is_some() || self.rod.is_some() || self.offset.is_some()
    }
}

/// The unit flags of every command that prints or draws quantities. Units
/// are names only: the numbers are taken to be in them, never converted.
#[derive(Debug, Clone, Args)]
pub struct UnitArgs {
    /// Name of the length unit the lengths are given in (mm, m, in, ft,
    /// ...), written beside lengths, speeds (UNIT/s), accelerations
    /// (UNIT/s²) and torques; a name only, no number is converted
    /// [default: the figure's own, ft for the textbook's engine, mm for
    /// Ng's rig]
    #[arg(long = "unit", value_name = "UNIT")]
    pub length: Option<Unit>,
    /// Name of the force unit (N, kN, lbf, ...), written beside forces and
    /// torques (FORCE·UNIT) [default: the one that goes with --unit, N for
    /// mm, cm, m and lbf for in, ft; without --unit the figure's own, lbf
    /// for the textbook's engine, N for Ng's rig]
    #[arg(long = "force-unit", value_name = "FORCE")]
    pub force: Option<Unit>,
}

impl UnitArgs {
    /// The units asked for, each defaulting to that of `own`, the force
    /// unit following --unit when only that is given ([`Units::asked`]).
    pub fn units(&self, own: Units) -> Units {
        own.asked(self.length.as_ref(), self.force.as_ref())
    }
}

/// Crank speed flags: `--rpm` or `--omega`, default 250 rpm (§35).
#[derive(Debug, Clone, Args)]
pub struct SpeedArgs {
    /// Crank speed in revolutions per minute, positive counter-clockwise
    /// (or give --omega) [default: 250]
    #[arg(
        long,
        allow_hyphen_values = true,
        value_name = "N",
        conflicts_with = "omega"
    )]
    pub rpm: Option<f64>,
    /// Crank speed ω in rad/s, positive counter-clockwise (instead of
    /// --rpm)
    #[arg(long, allow_hyphen_values = true, value_name = "W")]
    pub omega: Option<f64>,
}

/// The load on the crank: `--torque` and, with it, `--friction`. The
/// values are checked where the statics are computed.
#[derive(Debug, Clone, Args)]
pub struct LoadArgs {
    /// Crank torque T, counter-clockwise positive, in force × the length
    /// unit (FORCE·UNIT, N·mm for lengths in mm): adds the statics of Ng
    /// eq. 6–11 (the OM line, slider force, side thrust, friction,
    /// transmission angle), the forces in the force unit
    #[arg(long, allow_hyphen_values = true, value_name = "T")]
    pub torque: Option<f64>,
    /// Coefficient of friction μ ≥ 0 of the slider in its guides: with
    /// --torque, Ng's statics; analyze with the engine's masses, the
    /// running engine's friction μ|N| against the slider's motion too
    /// (refused where the slider would self-lock, μ |tan φ| ≥ 1)
    /// [default: 0]
    #[arg(long, allow_hyphen_values = true, value_name = "MU")]
    pub friction: Option<f64>,
}

/// The one guard on the size of a request: the values a command computes
/// (rows × columns), checked before any work ([`MaxCells`]).
#[derive(Debug, Clone, Args)]
pub struct GuardArgs {
    /// Most values a command computes: rows × columns of a table, angles
    /// × the values of each for analyze, poses × quantities for check. A
    /// larger request is refused before any work, with its size; give a
    /// larger N to lift the bound (the rows are streamed: memory does not
    /// grow with them)
    #[arg(
        long,
        value_name = "N",
        default_value_t = DEFAULT_MAX_CELLS,
        allow_hyphen_values = true
    )]
    pub max_cells: u64,
}

pub use slider_crank::lists::{AngleSpec, parse_list};
