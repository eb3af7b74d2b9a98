//! The report `check` prints for the engine (every construction against
//! the analytic core over the whole turn) and the checks of its
//! allowance: one copy for the command line and the Python package.

use crate::construct::SweepReport;
use crate::error::{Error, Field, Result};
use crate::mechanism::SliderCrank;
use crate::number::plain;

/// Default allowance of `check`: a difference passes when it is at most
/// this many ulps (ε = 2⁻⁵²) times the condition number κ of the quantity
/// at that pose ([`crate::construct::condition`]).
pub const DEFAULT_ULPS: f64 = 4.0;

/// The largest allowance: a scaled difference of 1 is the size of the
/// quantity (beyond it everything passes, and T/ε overflows to infinity
/// near 1e308).
pub const MAX_TOLERANCE: f64 = 1.0;

/// The allowance `tolerance`, or `default` when not given, checked with
/// the number of poses `samples`: a tolerance must be positive, finite
/// and at most [`MAX_TOLERANCE`], and at least one pose is asked for.
pub fn check_allowance(samples: usize, tolerance: Option<f64>, default: f64) -> Result<f64> {
    let t = tolerance.unwrap_or(default);
    if !(t.is_finite() && t > 0.0) {
        return Err(Error::NotPositive {
            name: Field::Tolerance,
            value: t,
        });
    }
    if t > MAX_TOLERANCE {
        return Err(Error::OutOfRange {
            name: Field::Tolerance,
            value: t,
            reason: "give at most 1: a difference of 1 in scaled units is the size of the quantity itself".into(),
        });
    }
    if samples == 0 {
        return Err(Error::OutOfRange {
            name: Field::Samples,
            value: 0.0,
            reason: "give at least 1 pose".into(),
        });
    }
    Ok(t)
}

/// A row's verdict in a check's report.
pub(super) fn verdict(pass: bool) -> &'static str {
    if pass { "ok" } else { "FAIL" }
}

/// The last line of a check's report, after a blank one.
pub(super) fn closing(ok: bool) -> &'static str {
    if ok {
        "\nall within tolerance\n"
    } else {
        "\nsome quantities exceed the tolerance\n"
    }
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

/// The report `check` prints for the engine `m` swept in `report`, and
/// whether every quantity passed: a difference passes when it is at most
/// `tolerance` × κ (an empty report passes).
pub fn engine_check_report(
    m: &SliderCrank,
    report: &SweepReport,
    tolerance: f64,
) -> (String, bool) {
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
    for ((q, err, _, count), (_, ulps, kappa, at)) in report.worst.iter().zip(&report.worst_ulps) {
        if *count == 0 {
            // A construction this mechanism does not have (Bennett's on an
            // offset engine).
            out.push_str(&format!(
                "{:<40}{:>12}{:>10}{:>12}{:>14}  not drawn for this mechanism\n",
                q.name(),
                "–",
                "–",
                "–",
                "–"
            ));
            continue;
        }
        let pass = *ulps <= allowed;
        ok &= pass;
        out.push_str(&format!(
            "{:<40}{:>12.3e}{:>10.2}{:>12.3e}{:>14.6}  {}\n",
            q.name(),
            err,
            ulps,
            kappa,
            at,
            verdict(pass)
        ));
    }
    out.push_str(closing(ok));
    (out, ok)
}
