//! Numbers as a page writes them.

/// A number as a page shows it: four significant figures, a true minus
/// sign, powers of ten beyond 10⁹ and below 10⁻⁴.
pub(in crate::handout) fn show(x: f64) -> String {
    if x == 0.0 || !x.is_finite() {
        return "0".into();
    }
    let a = x.abs();
    let text = if (1e-4..1e9).contains(&a) {
        let digits = (3 - a.log10().floor() as i32).clamp(0, 12) as usize;
        format!("{x:.digits$}")
    } else {
        // The mantissa and exponent as `{:e}` rounds them (4 figures): no
        // division by 10ᵏ, which is 0 for subnormals (inf × 10⁻³²⁴) and
        // rounds 9.9996e10 to "10.000 × 10¹⁰".
        let e = format!("{x:.3e}");
        let (m, k) = e.split_once('e').unwrap_or((&e, "0"));
        format!("{m} × 10{}", superscript(k.parse().unwrap_or(0)))
    };
    text.replace('-', "−")
}

/// A given number (a datum, not a result) as a page shows it: [`show`]
/// without trailing zeros (`250`, `0.5`, `40`).
pub(in crate::handout) fn short(x: f64) -> String {
    let s = show(x);
    if s.contains('.') && !s.contains('×') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    }
}

/// `k` in Unicode superscripts (`⁻¹²`).
fn superscript(k: i32) -> String {
    k.to_string()
        .chars()
        .filter_map(|c| match c {
            '-' => Some('⁻'),
            d => d
                .to_digit(10)
                .and_then(|d| ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'].get(d as usize))
                .copied(),
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_show_four_figures_and_a_true_minus() {
        assert_eq!(show(10.3466), "10.35");
        assert_eq!(show(-0.351), "−0.3510");
        assert_eq!(show(242.1), "242.1");
        assert_eq!(show(1.5e10), "1.500 × 10¹⁰");
        assert_eq!(show(-2e-6), "−2.000 × 10⁻⁶");
        assert_eq!(show(0.0), "0");
        assert_eq!(short(250.0), "250");
        assert_eq!(short(0.5), "0.5");
        assert_eq!(short(1.5e10), "1.500 × 10¹⁰");
    }

    /// Every double, subnormals and the largest included, shows as a
    /// mantissa of four figures in [1, 10) and an exponent (was "inf ×
    /// 10⁻³²⁴" for 5e-324 and "10.000 × 10¹⁰" for 9.9996e10).
    #[test]
    fn every_double_shows_a_mantissa_below_ten() {
        assert_eq!(show(5e-324), "4.941 × 10⁻³²⁴");
        assert_eq!(show(-2.2250738585072014e-308), "−2.225 × 10⁻³⁰⁸");
        assert_eq!(show(f64::MAX), "1.798 × 10³⁰⁸");
        assert_eq!(show(9.9996e10), "1.000 × 10¹¹");
        assert_eq!(show(9.99996e-5), "1.000 × 10⁻⁴");
        let mut x = 5e-324_f64;
        while x.is_finite() {
            let s = show(x);
            assert!(!s.contains("inf") && !s.contains("NaN"), "{x:e}: {s}");
            if let Some((m, _)) = s.split_once(" × ") {
                let m: f64 = m.parse().unwrap();
                assert!((1.0..10.0).contains(&m), "{x:e}: {s}");
            } else {
                assert!(s.len() <= 16, "{x:e}: {s}");
            }
            x *= 3.7;
        }
    }
}
