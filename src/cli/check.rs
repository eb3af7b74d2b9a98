//! `slider-crank check`: every construction against the analytic core over
//! the whole turn.

use super::args::MechanismArgs;
use clap::Args;
use slider_crank::construct::sweep;
use slider_crank::{Error, Result};

/// Default tolerance of `check`, in the scaled units of DESIGN.md §6.
pub const DEFAULT_TOLERANCE: f64 = 1e-12;

/// Sweep the whole turn and compare each construction with the analytic core.
#[derive(Debug, Args)]
pub struct CheckArgs {
    #[command(flatten)]
    pub mechanism: MechanismArgs,
    /// Equally spaced poses over the turn (the exact dead centres, 0°, 90°,
    /// 180° and 270° are always added)
    #[arg(long, default_value_t = 100_000, value_name = "N")]
    pub samples: usize,
    /// Largest allowed difference, scaled by r (slider) or 1 (rod rates
    /// per unit ω)
    #[arg(long, allow_negative_numbers = true, default_value_t = DEFAULT_TOLERANCE, value_name = "T")]
    pub tolerance: f64,
    #[command(flatten)]
    pub chain: super::chain::ChainArgs,
}

/// Runs the check: the report and whether every quantity passed.
pub fn run(args: &CheckArgs) -> Result<(String, bool)> {
    let m = args.mechanism.mechanism()?;
    if !(args.tolerance.is_finite() && args.tolerance > 0.0) {
        return Err(Error::NotPositive {
            name: "tolerance",
            value: args.tolerance,
        });
    }
    if args.samples == 0 || args.samples > 100_000_000 {
        return Err(Error::OutOfRange {
            name: "samples",
            value: args.samples as f64,
            reason: "give between 1 and 100000000 poses".into(),
        });
    }
    if let Some(done) = super::chain::check(m, &args.chain, args.samples, args.tolerance)? {
        return Ok(done);
    }
    let report = sweep(&m, args.samples);
    let mut out = format!(
        "check: r = {}, l = {}, e = {} (n = {}), {} poses, tolerance {:e}\n\n",
        m.crank(),
        m.rod(),
        m.offset(),
        m.ratio(),
        report.poses,
        args.tolerance
    );
    out.push_str(&format!(
        "{:<40}{:>14}{:>16}{:>10}  result\n",
        "quantity (scaled difference)", "worst", "at θ (°)", "poses"
    ));
    let mut ok = true;
    for (q, err, at, n) in &report.worst {
        let pass = *err <= args.tolerance;
        ok &= pass;
        out.push_str(&format!(
            "{:<40}{:>14.3e}{:>16.6}{:>10}  {}\n",
            q.name(),
            err,
            at,
            n,
            if pass { "ok" } else { "FAIL" }
        ));
    }
    out.push_str(if ok {
        "\nall within tolerance\n"
    } else {
        "\nsome quantities exceed the tolerance\n"
    });
    Ok((out, ok))
}
