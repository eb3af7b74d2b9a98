//! Numbers set on a figure: a true minus sign (U+2212), never "−0", and
//! one rule of significant figures for every value a figure names ([`sig`],
//! [`short`]).

/// `v` with `decimals` decimals and a true minus sign (U+2212); never
/// "−0".
pub fn format_number(v: f64, decimals: usize) -> String {
    // From 1e15 on in exponent form (`1.00e308`, not 309 digits).
    let s = if v.abs() >= 1e15 {
        format!("{:.*e}", decimals, v)
    } else {
        format!("{:.*}", decimals, v)
    };
    let zero = s
        .trim_start_matches('-')
        .chars()
        .all(|c| c == '0' || c == '.');
    if zero {
        s.trim_start_matches('-').to_string()
    } else if let Some(rest) = s.strip_prefix('-') {
        format!("\u{2212}{rest}")
    } else {
        s
    }
}

/// 10ᵏ with the exponent in superscript digits.
pub(crate) fn power_of_ten(k: i32) -> String {
    const SUP: [char; 10] = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];
    let mut s = String::from("10");
    if k < 0 {
        s.push('⁻');
    }
    for c in k.unsigned_abs().to_string().chars() {
        if let Some(&d) = c.to_digit(10).and_then(|d| SUP.get(d as usize)) {
            s.push(d);
        }
    }
    s
}

/// Where a number is set, which decides only where it turns to a power
/// of ten and how the times sign is spaced; the rule of four significant
/// figures is the same.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum SetOn {
    /// On a figure: a power of ten below 1e-4 and from 1e9, the times
    /// sign set tight (`8.786×10⁻¹⁰¹`), a letter's room being small (a
    /// length of 6.498e-9 was written with eight zeros).
    Figure,
    /// In a page's running text (the handout): a power of ten below 1e-4
    /// and from 1e9, the times sign spaced (`1.500 × 10¹⁰`).
    #[cfg_attr(not(feature = "html"), allow(dead_code))]
    Page,
}

impl SetOn {
    /// The magnitudes written in fixed notation.
    fn fixed(self) -> std::ops::Range<f64> {
        match self {
            SetOn::Figure => 1e-4..1e9,
            SetOn::Page => 1e-4..1e9,
        }
    }

    /// The times sign between mantissa and power.
    fn times(self) -> &'static str {
        match self {
            SetOn::Figure => "×",
            SetOn::Page => " × ",
        }
    }
}

/// Four significant figures with a true minus sign on a figure ([`sig_on`]
/// [`SetOn::Figure`]): below 1e-4 and from 1e9 a power of ten
/// (`8.786×10⁻¹⁰¹`), never hundreds of digits or a tiny value written as
/// zero. 0 and non-finite values write `0`.
pub(crate) fn sig(x: f64) -> String {
    sig_on(x, SetOn::Figure)
}

/// Four significant figures with a true minus sign, set `on` a figure or a
/// page: outside the fixed range of `on` a mantissa in [1, 10) and a power
/// of ten (the mantissa and exponent as `{:e}` rounds them: 9.9996e10 is
/// `1.000 × 10¹¹`, a subnormal is not divided to infinity). 0 and
/// non-finite values write `0`.
pub(crate) fn sig_on(x: f64, on: SetOn) -> String {
    if x == 0.0 || !x.is_finite() {
        return "0".into();
    }
    if !on.fixed().contains(&x.abs()) {
        let s = format!("{:.3e}", x.abs());
        let (mantissa, exponent) = s.split_once('e').unwrap_or((&s, "0"));
        let sign = if x < 0.0 { "\u{2212}" } else { "" };
        return format!(
            "{sign}{mantissa}{}{}",
            on.times(),
            power_of_ten(exponent.parse().unwrap_or(0))
        );
    }
    let digits = (3 - x.abs().log10().floor() as i32).clamp(0, 12) as usize;
    format_number(x, digits)
}

/// [`sig`] without trailing zeros (`50°`, `250 rpm`, `0.5 ft`, `2×10⁻⁸`).
pub(crate) fn short(x: f64) -> String {
    short_on(x, SetOn::Figure)
}

/// [`sig_on`] without trailing zeros, in the mantissa too (`250`, `0.5`,
/// `1.5 × 10¹⁰` on a page).
pub(crate) fn short_on(x: f64, on: SetOn) -> String {
    let s = sig_on(x, on);
    let trim = |m: &str| {
        if m.contains('.') {
            m.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            m.to_string()
        }
    };
    match s.split_once(on.times()) {
        Some((mantissa, power)) => format!("{}{}{power}", trim(mantissa), on.times()),
        None => trim(&s),
    }
}

/// A value given as input, set on a figure as it was given: its shortest
/// decimal (Ng's torque 264.87 stays 264.87, where [`short`] would round
/// it to 264.9) with a true minus sign; outside [1e-4, 1e15) as [`sig`].
pub(crate) fn given(x: f64) -> String {
    let a = x.abs();
    if !x.is_finite() || (a != 0.0 && !(1e-4..1e15).contains(&a)) {
        return sig(x);
    }
    let s = format!("{}", super::unsigned_zero(x));
    match s.strip_prefix('-') {
        Some(rest) => format!("\u{2212}{rest}"),
        None => s,
    }
}

#[cfg(test)]
mod page_tests {
    use super::{SetOn, short_on, sig_on};

    fn show(x: f64) -> String {
        sig_on(x, SetOn::Page)
    }

    #[test]
    fn numbers_on_a_page_show_four_figures_and_a_true_minus() {
        assert_eq!(show(10.3466), "10.35");
        assert_eq!(show(-0.351), "−0.3510");
        assert_eq!(show(242.1), "242.1");
        assert_eq!(show(1.5e10), "1.500 × 10¹⁰");
        assert_eq!(show(-2e-6), "−2.000 × 10⁻⁶");
        assert_eq!(show(0.0), "0");
        assert_eq!(short_on(250.0, SetOn::Page), "250");
        assert_eq!(short_on(0.5, SetOn::Page), "0.5");
        assert_eq!(short_on(1.5e10, SetOn::Page), "1.5 × 10¹⁰");
        // The same number on a figure, tight.
        assert_eq!(sig_on(1.5e10, SetOn::Figure), "1.500×10¹⁰");
        assert_eq!(short_on(-2e-10, SetOn::Figure), "−2×10⁻¹⁰");
    }

    /// Every double, subnormals and the largest included, shows as a
    /// mantissa of four figures in [1, 10) and an exponent (was "inf ×
    /// 10⁻³²⁴" for 5e-324 and "10.000 × 10¹⁰" for 9.9996e10).
    #[test]
    fn every_double_on_a_page_shows_a_mantissa_below_ten() {
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
                let m: f64 = m.replace('\u{2212}', "-").parse().unwrap();
                assert!((1.0..10.0).contains(&m.abs()), "{x:e}: {s}");
            } else {
                assert!(s.chars().count() <= 16, "{x:e}: {s}");
            }
            x *= 3.7;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn four_significant_figures_with_a_true_minus() {
        assert_eq!(sig(264.8712), "264.9");
        assert_eq!(sig(-0.0123456), "\u{2212}0.01235");
        assert_eq!(sig(1234567.0), "1234567");
        assert_eq!(sig(8.7861e-101), "8.786×10⁻¹⁰¹");
        assert_eq!(sig(-2.5e20), "\u{2212}2.500×10²⁰");
        assert_eq!(sig(f64::NAN), "0");
        assert_eq!(short(0.5), "0.5");
        assert_eq!(short(250.0), "250");
        assert_eq!(short(12.345), "12.35");
        assert_eq!(short(-1.5), "\u{2212}1.5");
        assert_eq!(short(1e20), "1×10²⁰");
        assert_eq!(short(2.5e-10), "2.5×10⁻¹⁰");
        assert_eq!(given(264.87), "264.87");
        assert_eq!(given(-2.5), "\u{2212}2.5");
        assert_eq!(given(1e-300), "1.000×10⁻³⁰⁰");
    }

    #[test]
    fn four_significant_figures() {
        assert_eq!(sig(13.0899), "13.09");
        assert_eq!(sig(242.04), "242.0");
        assert_eq!(sig(0.35301), "0.3530");
        assert_eq!(sig(-0.00001), "\u{2212}1.000×10⁻⁵");
        assert_eq!(sig(0.0001), "0.0001000");
        assert_eq!(sig(0.0), "0");
        assert_eq!(sig(12345.6), "12346");
        // Issue 9: no 309-digit integers, no tiny value written as 0.
        assert_eq!(sig(8.786053663290565e-101), "8.786×10⁻¹⁰¹");
        assert_eq!(sig(f64::MAX), "1.798×10³⁰⁸");
        assert_eq!(sig(-2.6487e102), "\u{2212}2.649×10¹⁰²");
        assert_eq!(sig(1e15), "1.000×10¹⁵");
        // A length of 6.498e-9 on the polygons' notes had eight zeros.
        assert_eq!(sig(6.498e-9), "6.498×10⁻⁹");
        assert_eq!(sig(123456789.0), "123456789");
    }
}
