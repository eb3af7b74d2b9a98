//! `slider-crank check`: every construction against the analytic core over
//! the whole turn.

use super::args::{GuardArgs, MechanismArgs};
use super::output::Stdout;
use clap::Args;
use slider_crank::construct::{Quantity, sweep};
use slider_crank::render::plain;
use slider_crank::{Error, Result};

/// Default allowance of `check`: a difference passes when it is at most
/// this many ulps (ε = 2⁻⁵²) times the condition number κ of the quantity
/// at that pose ([`slider_crank::construct::condition`]).
pub const DEFAULT_ULPS: f64 = 4.0;

/// Default allowance of `check --slot-radius` and `check --links`: the
/// largest scaled difference (docs/design.md §6) between the chain's two
/// formulations.
pub const CHAIN_TOLERANCE: f64 = 1e-12;

/// The largest allowance: a scaled difference of 1 is the size of the
/// quantity (beyond it everything passes, and T/ε overflows to infinity
/// near 1e308).
pub const MAX_TOLERANCE: f64 = 1.0;

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

/// An allowance in ulps: one decimal up to a million (`4.0`), exponent
/// form beyond (`4.504e15` for a tolerance of 1, not 16 digits).
fn ulps_text(ulps: f64) -> String {
    if ulps < 1e6 {
        format!("{ulps:.1}")
    } else {
        format!("{ulps:.3e}")
    }
}

/// Runs the check: the report, and whether every quantity passed.
pub fn run(args: &CheckArgs, stdout: &mut Stdout) -> Result<bool> {
    let m = args.mechanism.mechanism()?;
    let tolerance = args.tolerance.unwrap_or(DEFAULT_ULPS * f64::EPSILON);
    if !(tolerance.is_finite() && tolerance > 0.0) {
        return Err(Error::NotPositive {
            name: "tolerance",
            value: tolerance,
        });
    }
    if tolerance > MAX_TOLERANCE {
        return Err(Error::OutOfRange {
            name: "tolerance",
            value: tolerance,
            reason: "give at most 1: a difference of 1 in scaled units is the size of the quantity itself".into(),
        });
    }
    if args.samples == 0 {
        return Err(Error::OutOfRange {
            name: "samples",
            value: 0.0,
            reason: "give at least 1 pose".into(),
        });
    }
    let poses = args.samples as u64;
    args.guard.check(
        "check",
        (poses, &format!("{poses} poses")),
        (Quantity::ALL.len() as u64, "quantities"),
    )?;
    let chain_tolerance = args.tolerance.unwrap_or(CHAIN_TOLERANCE);
    if let Some((text, ok)) = super::chain::check(m, &args.chain, args.samples, chain_tolerance)? {
        stdout.text(&text)?;
        return Ok(ok);
    }
    let report = sweep(&m, args.samples);
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
    for ((q, err, _, _), (_, ulps, kappa, at)) in report.worst.iter().zip(&report.worst_ulps) {
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
    }
    out.push_str(if ok {
        "\nall within tolerance\n"
    } else {
        "\nsome quantities exceed the tolerance\n"
    });
    stdout.text(&out)?;
    Ok(ok)
}
