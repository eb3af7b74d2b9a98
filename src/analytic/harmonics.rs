//! The piston's acceleration of an in-line engine as a series of
//! harmonics, cos θ + A₂ cos 2θ + A₄ cos 4θ + …, to any order, and the
//! error of each truncation.

use crate::error::{Error, Field, Result};
use std::f64::consts::TAU;

/// Samples of a turn for the coefficients: the series of an engine with
/// n ≥ [`MIN_RATIO`] falls below the last bit well before the 2048th
/// harmonic, so the samples alias nothing that shows.
const SAMPLES: usize = 4096;

/// The shortest rod the series is given for, n = l/r: nearer the limit
/// of assembly the harmonics fall too slowly for the samples of a turn (4096).
pub const MIN_RATIO: f64 = 1.01;

/// The harmonics of `table harmonics` when no order is given: cos 2θ,
/// cos 4θ and cos 6θ, the textbooks' A₂, A₄, A₆.
pub const DEFAULT_ORDER: usize = 3;

/// The decimals of the coefficients when none are asked for.
pub const DEFAULT_DECIMALS: usize = 8;

/// Most harmonics asked for.
pub const MAX_ORDER: usize = 1000;

/// The series of −s″/r, the piston's acceleration towards the crank per
/// unit r ω² (e = 0): cos θ + Σ A₂ₖ cos 2kθ. The textbooks' leading
/// terms, with λ = 1/n: A₂ = λ + λ³/4 + 15λ⁵/128 + …, A₄ = −(λ³/4 +
/// 3λ⁵/16 + …), A₆ = 9λ⁵/128 + …; here every coefficient is the exact
/// one (to rounding), from the exact acceleration.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Harmonics {
    /// n = l/r.
    pub ratio: f64,
    /// A₂, A₄, …, A₂ₖ: the coefficient of cos 2kθ at index k − 1.
    pub even: Vec<f64>,
    /// The largest |error| over a turn of the series cut after cos θ
    /// (index 0), after cos 2θ (1), …, after cos 2kθ (k).
    pub truncation_error: Vec<f64>,
}

impl Harmonics {
    /// The coefficients of the in-line engine of ratio `ratio` up to
    /// cos 2kθ, k = `order`, and the error of each truncation (the
    /// largest over the samples of a turn).
    ///
    /// Errors: n below [`MIN_RATIO`] or not finite; an order of 0 or above
    /// [`MAX_ORDER`].
    pub fn new(ratio: f64, order: usize) -> Result<Self> {
        if !(ratio.is_finite() && ratio >= MIN_RATIO) {
            return Err(Error::OutOfRange {
                name: Field::Ratio,
                value: ratio,
                reason: format!(
                    "the series is given for n = l/r from {MIN_RATIO}, where its harmonics fall fast enough to be found to the last bit"
                ),
            });
        }
        if !(1..=MAX_ORDER).contains(&order) {
            return Err(Error::OutOfRange {
                name: Field::Order,
                value: order as f64,
                reason: format!("the series runs to cos 2kθ with k from 1 to {MAX_ORDER}"),
            });
        }
        let values: Vec<f64> = (0..SAMPLES)
            .map(|j| acceleration(ratio, TAU * j as f64 / SAMPLES as f64))
            .collect();
        let even: Vec<f64> = (1..=order).map(|k| coefficient(&values, 2 * k)).collect();
        let mut truncation_error = Vec::with_capacity(order + 1);
        let mut rest: Vec<f64> = values
            .iter()
            .enumerate()
            .map(|(j, v)| v - angle(j).cos())
            .collect();
        truncation_error.push(largest(&rest));
        for (k, a) in even.iter().enumerate() {
            for (j, r) in rest.iter_mut().enumerate() {
                *r -= a * (2.0 * (k + 1) as f64 * angle(j)).cos();
            }
            truncation_error.push(largest(&rest));
        }
        Ok(Self {
            ratio,
            even,
            truncation_error,
        })
    }

    /// The series cut after cos 2kθ, k = `terms` (all it has if more), at
    /// `theta` radians.
    pub fn sum(&self, theta: f64, terms: usize) -> f64 {
        theta.cos()
            + self
                .even
                .iter()
                .take(terms)
                .enumerate()
                .map(|(k, a)| a * (2.0 * (k + 1) as f64 * theta).cos())
                .sum::<f64>()
    }
}

/// θ of sample j.
fn angle(j: usize) -> f64 {
    TAU * j as f64 / SAMPLES as f64
}

/// −s″/r of the in-line engine: cos θ + (n² cos 2θ + sin⁴θ)/(n² − sin²θ)^{3/2}.
fn acceleration(n: f64, theta: f64) -> f64 {
    let (s, c) = theta.sin_cos();
    let w = (n * n - s * s).sqrt();
    c + (n * n * (c * c - s * s) + s.powi(4)) / (w * w * w)
}

/// The coefficient of cos mθ of the samples (a discrete cosine sum).
fn coefficient(values: &[f64], m: usize) -> f64 {
    let n = values.len();
    2.0 / n as f64
        * values
            .iter()
            .enumerate()
            .map(|(j, v)| v * (TAU * ((m * j) % n) as f64 / n as f64).cos())
            .sum::<f64>()
}

/// The largest |value|.
fn largest(values: &[f64]) -> f64 {
    values.iter().fold(0.0, |m, v| m.max(v.abs()))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The textbooks' leading terms, within the next order of λ.
    #[test]
    fn the_leading_coefficients_are_the_textbooks() {
        for n in [4.0, 6.0, 20.0] {
            let h = Harmonics::new(n, 3).unwrap();
            let l: f64 = 1.0 / n;
            let (a2, a4, a6) = (
                l + l.powi(3) / 4.0 + 15.0 * l.powi(5) / 128.0,
                -(l.powi(3) / 4.0 + 3.0 * l.powi(5) / 16.0),
                9.0 * l.powi(5) / 128.0,
            );
            assert!(
                (h.even[0] - a2).abs() <= 0.1 * l.powi(7),
                "{n}: {}",
                h.even[0]
            );
            assert!(
                (h.even[1] - a4).abs() <= 0.2 * l.powi(7),
                "{n}: {}",
                h.even[1]
            );
            assert!(
                (h.even[2] - a6).abs() <= 0.2 * l.powi(7),
                "{n}: {}",
                h.even[2]
            );
        }
    }

    /// Enough terms give the exact acceleration back to rounding, at
    /// angles off the samples, down to n = 1.01; each truncation's error
    /// falls.
    #[test]
    fn the_series_sums_to_the_exact_acceleration() {
        for n in [1.01, 1.05, 1.5, 3.0, 60.0] {
            let h = Harmonics::new(n, 600).unwrap();
            for k in 0..100 {
                let t = 0.0637 * k as f64 + 0.01;
                let exact = acceleration(n, t);
                let sum = h.sum(t, 600);
                assert!(
                    (sum - exact).abs() <= 1e-12 * (1.0 + exact.abs()),
                    "{n} {t}: {sum} vs {exact}"
                );
            }
            let e = &h.truncation_error;
            assert!(e[1] < e[0] && e[2] < e[1], "{n}: {:?}", &e[..3]);
            assert!(e[600] <= 1e-11, "{n}: {}", e[600]);
        }
        // The series cut after cos 2θ is the textbook's eq. (3); its
        // error at n = 4 is about A₄ = λ³/4 ≈ 0.004.
        let h = Harmonics::new(4.0, 2).unwrap();
        assert!(
            (h.truncation_error[1] - 0.0041).abs() < 3e-4,
            "{}",
            h.truncation_error[1]
        );
    }

    #[test]
    fn bad_requests_are_refused() {
        assert!(Harmonics::new(1.0, 3).is_err());
        assert!(Harmonics::new(f64::INFINITY, 3).is_err());
        assert!(Harmonics::new(4.0, 0).is_err());
        assert!(Harmonics::new(4.0, MAX_ORDER + 1).is_err());
    }
}
