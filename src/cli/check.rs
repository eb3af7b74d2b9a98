//! `slider-crank check`: every construction against the analytic core over
//! the whole turn.

use super::args::{GivenMechanismArgs, GuardArgs};
use super::output::Stdout;
use clap::Args;
use slider_crank::Result;
use slider_crank::table::{CheckRequest, DEFAULT_SAMPLES};

/// Sweep the whole turn and compare each construction with the analytic core.
#[derive(Debug, Args)]
pub struct CheckArgs {
    #[command(flatten)]
    pub mechanism: GivenMechanismArgs,
    /// Equally spaced poses over the turn, at least 1 (the dead centres
    /// and 0°, 90°, 180° and 270° are always added); poses × the quantities
    /// compared are bounded by --max-cells
    #[arg(
        long,
        default_value_t = DEFAULT_SAMPLES,
        value_name = "N",
        allow_hyphen_values = true
    )]
    pub samples: usize,
    /// Allowed difference, in the scaled units of docs/design.md §6. For
    /// the engine a difference passes when it is at most T · κ, κ the
    /// condition number of the quantity at that pose; with --slot-radius or
    /// --links, when it is at most T itself [default: 4 × 2⁻⁵² ≈ 8.9e-16
    /// (4 ulps) for the engine, 1e-12 with --slot-radius or --links]
    #[arg(long, allow_hyphen_values = true, value_name = "T")]
    pub tolerance: Option<f64>,
    #[command(flatten)]
    pub chain: super::chain::ChainArgs,
    #[command(flatten)]
    pub guard: GuardArgs,
}

/// Runs the check: the report, and whether every quantity passed.
pub fn run(args: &CheckArgs, stdout: &mut Stdout) -> Result<bool> {
    let outcome = request(args)?.plan()?.run();
    stdout.text(&outcome.text)?;
    Ok(outcome.passed)
}

/// The request the flags make ([`CheckRequest`]): the links parsed, the
/// rest as given.
fn request(args: &CheckArgs) -> Result<CheckRequest> {
    let mut r = CheckRequest::default();
    let m = &args.mechanism;
    (r.crank, r.rod, r.offset) = (m.crank, m.rod, m.offset);
    (r.samples, r.tolerance) = (args.samples, args.tolerance);
    (r.slot_radius, r.links, r.assembly, r.inversion) = args.chain.fields()?;
    r.max_cells = args.guard.max_cells;
    Ok(r)
}
