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
        let k = a.log10().floor() as i32;
        let m = x / 10f64.powi(k);
        format!("{m:.3} × 10{}", superscript(k))
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
        .map(|c| match c {
            '-' => '⁻',
            d => ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'][d as usize - '0' as usize],
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
}
