//! Least-squares calibration lines (Ng, Table 1 and Fig. 7).

use crate::error::{Error, Field, Input, Result, finite};
use crate::number::plain;

pub use crate::sources::NG_TABLE_1;

/// A straight line y = slope · x + intercept fitted by least squares.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct LineFit {
    /// Slope of the fitted line.
    pub slope: f64,
    /// Intercept (exactly 0 for a fit through the origin).
    pub intercept: f64,
    /// R² about the mean, 1 − SS_res / Σ(y − ȳ)²: the coefficient of
    /// determination of an ordinary fit. For a fit through the origin it can
    /// be negative.
    pub r_squared: f64,
    /// R² about zero, 1 − SS_res / Σ y²: what a spreadsheet trendline with
    /// its intercept set to 0 prints (Ng's 0.9998). Equal in meaning to
    /// `r_squared` only for a fit with an intercept when ȳ = 0.
    pub r_squared_uncentred: f64,
}

impl LineFit {
    /// The line's value at `x`.
    pub fn at(&self, x: f64) -> f64 {
        self.slope * x + self.intercept
    }
}

fn check(points: &[(f64, f64)], needed: usize) -> Result<()> {
    if points.len() < needed {
        return Err(Error::invalid(
            Input::Calibration,
            format!(
                "a line fit needs at least {needed} points, got {}",
                points.len()
            ),
        ));
    }
    for &(x, y) in points {
        finite(Field::X, x)?;
        finite(Field::Y, y)?;
    }
    Ok(())
}

fn r_squared(points: &[(f64, f64)], slope: f64, intercept: f64) -> (f64, f64) {
    let n = points.len() as f64;
    let mean_y = points.iter().map(|p| p.1).sum::<f64>() / n;
    let mut ss_res = 0.0;
    let mut ss_tot = 0.0;
    let mut ss_zero = 0.0;
    for &(x, y) in points {
        let r = y - (slope * x + intercept);
        ss_res += r * r;
        ss_tot += (y - mean_y) * (y - mean_y);
        ss_zero += y * y;
    }
    let centred = if ss_tot == 0.0 {
        1.0
    } else {
        1.0 - ss_res / ss_tot
    };
    let uncentred = if ss_zero == 0.0 {
        1.0
    } else {
        1.0 - ss_res / ss_zero
    };
    (centred, uncentred)
}

/// The points divided by powers of two that bring the largest |x| and the
/// largest |y| into [1, 2) (exact, unless a tiny value falls below the
/// smallest normal number), and the two divisors (1 for a column of
/// zeros): the sums of squares below neither overflow nor underflow
/// (data of 1e-300 squared to 0 and read as "all x = 0").
fn scaled(points: &[(f64, f64)]) -> (Vec<(f64, f64)>, f64, f64) {
    let unit = |largest: f64| {
        if largest > 0.0 {
            2f64.powi(largest.log2().floor() as i32)
        } else {
            1.0
        }
    };
    let sx = unit(points.iter().fold(0.0, |m, p| p.0.abs().max(m)));
    let sy = unit(points.iter().fold(0.0, |m, p| p.1.abs().max(m)));
    let scaled = points.iter().map(|&(x, y)| (x / sx, y / sy)).collect();
    (scaled, sx, sy)
}

/// The fit of the scaled points turned back into the data's units; an
/// error when its slope (y per unit x) exceeds the largest number.
fn unscaled(fit: LineFit, sx: f64, sy: f64) -> Result<LineFit> {
    let slope = fit.slope / sx * sy;
    if !slope.is_finite() {
        return Err(Error::invalid(
            Input::Calibration,
            format!(
                "the fitted line's slope exceeds the largest number: y of about {} against x of about {}",
                plain(sy),
                plain(sx)
            ),
        ));
    }
    Ok(LineFit {
        slope,
        intercept: fit.intercept * sy,
        ..fit
    })
}

/// Ordinary least squares y = a x + b. Needs two points with distinct x.
/// The data are scaled first: any finite numbers fit (1e-300 as 1e300).
pub fn fit_with_intercept(points: &[(f64, f64)]) -> Result<LineFit> {
    check(points, 2)?;
    let (points, sx, sy) = scaled(points);
    unscaled(fit_with_intercept_scaled(&points)?, sx, sy)
}

fn fit_with_intercept_scaled(points: &[(f64, f64)]) -> Result<LineFit> {
    let n = points.len() as f64;
    let mx = points.iter().map(|p| p.0).sum::<f64>() / n;
    let my = points.iter().map(|p| p.1).sum::<f64>() / n;
    let sxx: f64 = points.iter().map(|p| (p.0 - mx) * (p.0 - mx)).sum();
    let sxy: f64 = points.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    if sxx == 0.0 {
        return Err(Error::invalid(
            Input::Calibration,
            "a line fit needs two distinct x values".into(),
        ));
    }
    let slope = sxy / sxx;
    let intercept = my - slope * mx;
    let (r_squared, r_squared_uncentred) = r_squared(points, slope, intercept);
    Ok(LineFit {
        slope,
        intercept,
        r_squared,
        r_squared_uncentred,
    })
}

/// Least squares through the origin, y = a x. Needs one point with x ≠ 0.
/// The data are scaled first, as for [`fit_with_intercept`].
pub fn fit_through_origin(points: &[(f64, f64)]) -> Result<LineFit> {
    check(points, 1)?;
    let (points, sx, sy) = scaled(points);
    unscaled(fit_through_origin_scaled(&points)?, sx, sy)
}

fn fit_through_origin_scaled(points: &[(f64, f64)]) -> Result<LineFit> {
    let sxx: f64 = points.iter().map(|p| p.0 * p.0).sum();
    let sxy: f64 = points.iter().map(|p| p.0 * p.1).sum();
    if sxx == 0.0 {
        return Err(Error::invalid(
            Input::Calibration,
            "a fit through the origin needs some x ≠ 0".into(),
        ));
    }
    let slope = sxy / sxx;
    let (r_squared, r_squared_uncentred) = r_squared(points, slope, 0.0);
    Ok(LineFit {
        slope,
        intercept: 0.0,
        r_squared,
        r_squared_uncentred,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exact_line_is_recovered() {
        let pts = [(1.0, 3.0), (2.0, 5.0), (4.0, 9.0)];
        let f = fit_with_intercept(&pts).unwrap();
        assert!((f.slope - 2.0).abs() < 1e-15 && (f.intercept - 1.0).abs() < 1e-14);
        assert!((f.r_squared - 1.0).abs() < 1e-15);
    }

    /// The fits are the same at every scale: 1e-300 data were read as
    /// "all x = 0" (their squares underflow), 1e200 data overflowed.
    #[test]
    fn fits_are_scale_invariant() {
        let pts = [(1.0, 3.0), (2.0, 5.0), (4.0, 9.5)];
        let one = fit_with_intercept(&pts).unwrap();
        let origin = fit_through_origin(&pts).unwrap();
        for (sx, sy) in [
            (1e-300, 1e-300),
            (1e300, 1e300),
            (1e-300, 1.0),
            // x at the least normal numbers, y small with it so that the
            // slope (about 7e-8 / 3e-308) is a number.
            (3e-308, 7e-8),
            (1e150, 1e-150),
        ] {
            let p: Vec<_> = pts.iter().map(|&(x, y)| (x * sx, y * sy)).collect();
            let f = fit_with_intercept(&p).unwrap();
            let slope = one.slope * sy / sx;
            assert!(
                (f.slope - slope).abs() <= 1e-12 * slope.abs(),
                "{sx} {sy}: {f:?}"
            );
            assert!(
                (f.intercept - one.intercept * sy).abs() <= 1e-12 * sy,
                "{sx} {sy}: {f:?}"
            );
            assert!((f.r_squared - one.r_squared).abs() <= 1e-12, "{f:?}");
            let o = fit_through_origin(&p).unwrap();
            let slope = origin.slope * sy / sx;
            assert!(
                (o.slope - slope).abs() <= 1e-12 * slope.abs(),
                "{sx} {sy}: {o:?}"
            );
        }
        let e = fit_with_intercept(&[(1e-300, 1e300), (2e-300, 3e300)]).unwrap_err();
        assert!(
            e.to_string().contains("slope exceeds the largest number"),
            "{e}"
        );
    }

    #[test]
    fn degenerate_input_is_an_error() {
        assert!(fit_with_intercept(&[(1.0, 2.0)]).is_err());
        assert!(fit_with_intercept(&[(1.0, 2.0), (1.0, 3.0)]).is_err());
        assert!(fit_through_origin(&[(0.0, 2.0)]).is_err());
        assert!(fit_through_origin(&[(f64::NAN, 2.0)]).is_err());
    }
}
