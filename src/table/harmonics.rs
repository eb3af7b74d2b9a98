//! `table harmonics`: the piston's acceleration of an in-line engine as a
//! series of harmonics, each coefficient and the error of the series cut
//! after it.

use super::Table;
use crate::analytic::harmonics::Harmonics;
use crate::number::{fixed, plain};

/// The harmonics table of `series`: a row for cos θ and one for each
/// cos 2kθ, with its coefficient and the largest error over a turn of the
/// series cut after it; `decimals` for the coefficients, the errors to
/// four significant figures in exponent form.
pub fn harmonics_table(series: &Harmonics, decimals: usize) -> Table {
    let mut rows = vec![vec![
        "cos θ".to_string(),
        fixed(1.0, decimals),
        error_cell(series.truncation_error.first().copied().unwrap_or(0.0)),
    ]];
    for (k, (a, e)) in series
        .even
        .iter()
        .zip(series.truncation_error.iter().skip(1))
        .enumerate()
    {
        rows.push(vec![
            format!("cos {}θ", 2 * (k + 1)),
            fixed(*a, decimals),
            error_cell(*e),
        ]);
    }
    Table {
        title: format!(
            "The piston's acceleration as a series of harmonics, n = {} (in line), ÷ r ω²",
            plain(series.ratio)
        ),
        headers: vec![
            "harmonic".into(),
            "coefficient".into(),
            "largest error of the series cut here".into(),
        ],
        rows,
        notes: vec![
            "The acceleration towards the crank −d²x/dt² = r ω² (cos θ + A₂ cos 2θ + A₄ cos 4θ + …), each A₂ₖ the exact coefficient (from the exact acceleration sampled 4096 times a turn), not the textbooks' leading terms in λ = 1/n (A₂ ≈ λ + λ³/4, A₄ ≈ −λ³/4). The series cut after cos 2θ is the textbook's eq. (3); the last column is the largest error over a turn of each cut, ÷ r ω² (rounding sets its floor, about 1e-15).".into(),
        ],
    }
}

/// An error to four significant figures in exponent form.
fn error_cell(e: f64) -> String {
    format!("{:.3e}", e)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_row_for_each_harmonic_with_its_truncation_error() {
        let t = harmonics_table(&Harmonics::new(4.0, 2).unwrap(), 6);
        assert_eq!(t.rows.len(), 3);
        assert_eq!(t.rows[0][0], "cos θ");
        assert_eq!(t.rows[1][0], "cos 2θ");
        assert_eq!(t.rows[2][0], "cos 4θ");
        // A₂ at n = 4: 0.2540250423…, by a trapezoid sum of 20 000
        // samples of the exact acceleration × cos 2θ written out apart
        // (the λ series to λ⁷ gives 0.2540249).
        assert_eq!(t.rows[1][1], "0.254025");
        // Cut after cos θ the error is A₂ and more, about 0.258.
        assert!(t.rows[0][2].starts_with("2.5"), "{}", t.rows[0][2]);
    }
}
