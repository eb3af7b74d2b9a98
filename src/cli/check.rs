//! `slider-crank check`: every construction against the analytic core over
//! the whole turn.

use super::args::{GuardArgs, MechanismArgs};
use super::output::Stdout;
use clap::Args;
use slider_crank::Result;
use slider_crank::construct::{Quantity, sweep};
use slider_crank::table::{CHAIN_TOLERANCE, DEFAULT_ULPS, check_allowance, engine_check_report};

/// Sweep the whole turn and compare each construction with the analytic core.
#[derive(Debug, Args)]
pub struct CheckArgs {
    #[command(flatten)]
    pub mechanism: MechanismArgs,
    /// Equally spaced poses over the turn, at least 1 (the dead centres
    /// and 0°, 90°, 180° and 270° are always added); poses × the quantities
    /// compared are bounded by --max-cells
    #[arg(
        long,
        default_value_t = 100_000,
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
    let m = args.mechanism.mechanism()?;
    let tolerance = check_allowance(args.samples, args.tolerance, DEFAULT_ULPS * f64::EPSILON)?;
    args.guard
        .bound()
        .check_poses(args.samples as u64, Quantity::ALL.len())?;
    let chain_tolerance = args.tolerance.unwrap_or(CHAIN_TOLERANCE);
    if let Some((text, ok)) = super::chain::check(m, &args.chain, args.samples, chain_tolerance)? {
        stdout.text(&text)?;
        return Ok(ok);
    }
    let (out, ok) = engine_check_report(&m, &sweep(&m, args.samples), tolerance);
    stdout.text(&out)?;
    Ok(ok)
}
