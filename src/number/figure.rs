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

/// Four significant figures with a true minus sign; below 1e-9 and from
/// 1e15 a power of ten (`8.786×10⁻¹⁰¹`), never hundreds of digits or a
/// tiny value written as zero. 0 and non-finite values write `0`.
pub(crate) fn sig(x: f64) -> String {
    if x == 0.0 || !x.is_finite() {
        return "0".into();
    }
    if !(1e-9..1e15).contains(&x.abs()) {
        let s = format!("{:.3e}", x.abs());
        let (mantissa, exponent) = s.split_once('e').unwrap_or((&s, "0"));
        let sign = if x < 0.0 { "\u{2212}" } else { "" };
        return format!(
            "{sign}{mantissa}×{}",
            power_of_ten(exponent.parse().unwrap_or(0))
        );
    }
    let digits = (3 - x.abs().log10().floor() as i32).clamp(0, 12) as usize;
    format_number(x, digits)
}

/// [`sig`] without trailing zeros (`50°`, `250 rpm`, `0.5 ft`, `2×10⁻⁸`).
pub(crate) fn short(x: f64) -> String {
    let s = sig(x);
    let trim = |m: &str| {
        if m.contains('.') {
            m.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            m.to_string()
        }
    };
    match s.split_once('×') {
        Some((mantissa, power)) => format!("{}×{power}", trim(mantissa)),
        None => trim(&s),
    }
}

/// `x` to one significant figure as a power of ten (`2×10⁻⁸`): a bound
/// or a tolerance, whose size is what a reader needs. 0 and non-finite
/// values write `0`.
pub(crate) fn power_form(x: f64) -> String {
    if x == 0.0 || !x.is_finite() {
        return "0".into();
    }
    let s = format!("{:.0e}", x.abs());
    let (mantissa, exponent) = s.split_once('e').unwrap_or((&s, "0"));
    let sign = if x < 0.0 { "\u{2212}" } else { "" };
    format!(
        "{sign}{mantissa}×{}",
        power_of_ten(exponent.parse().unwrap_or(0))
    )
}

/// A value given as input, set on a figure as it was given: its shortest
/// decimal (Ng's torque 264.87 stays 264.87, where [`short`] would round
/// it to 264.9) with a true minus sign; outside [1e-4, 1e15) as [`sig`].
pub(crate) fn given(x: f64) -> String {
    let a = x.abs();
    if !x.is_finite() || (a != 0.0 && !(1e-4..1e15).contains(&a)) {
        return sig(x);
    }
    let s = format!("{}", x + 0.0);
    match s.strip_prefix('-') {
        Some(rest) => format!("\u{2212}{rest}"),
        None => s,
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
        assert_eq!(power_form(2.2e-8), "2×10⁻⁸");
        assert_eq!(given(264.87), "264.87");
        assert_eq!(given(-2.5), "\u{2212}2.5");
        assert_eq!(given(1e-300), "1.000×10⁻³⁰⁰");
    }

    #[test]
    fn four_significant_figures() {
        assert_eq!(sig(13.0899), "13.09");
        assert_eq!(sig(242.04), "242.0");
        assert_eq!(sig(0.35301), "0.3530");
        assert_eq!(sig(-0.00001), "\u{2212}0.00001000");
        assert_eq!(sig(0.0), "0");
        assert_eq!(sig(12345.6), "12346");
        // Issue 9: no 309-digit integers, no tiny value written as 0.
        assert_eq!(sig(8.786053663290565e-101), "8.786×10⁻¹⁰¹");
        assert_eq!(sig(f64::MAX), "1.798×10³⁰⁸");
        assert_eq!(sig(-2.6487e102), "\u{2212}2.649×10¹⁰²");
        assert_eq!(sig(1e15), "1.000×10¹⁵");
        assert_eq!(sig(1e-9), "0.000000001000");
    }
}
