//! Numbers to a fixed number of decimals, as tables print them.

/// Formats `x` with `decimals` decimals, never as "-0.000"; from 1e15 on
/// in exponent form (`1.2500e300`, not 300 digits).
pub fn fixed(x: f64, decimals: usize) -> String {
    if let Some(s) = fixed_fast(x, decimals) {
        return s;
    }
    if x.abs() >= 1e15 {
        return format!("{:.*e}", decimals, x);
    }
    let s = format!("{:.*}", decimals, x);
    if s.starts_with('-') && s[1..].chars().all(|c| c == '0' || c == '.') {
        s[1..].to_string()
    } else {
        s
    }
}

/// A table's angle cell: `degrees` with `decimals` decimals where they
/// write it exactly (30 → `30.0` at 1), else its shortest decimal that
/// reads back as the same double (0.001 → `0.001`, not `0.0`), so that two
/// different angles never print the same θ.
pub fn angle_cell(degrees: f64, decimals: usize) -> String {
    let s = fixed(degrees, decimals);
    if s.parse::<f64>().ok() == Some(degrees) {
        s
    } else {
        super::plain(degrees)
    }
}

/// Powers of ten exact in f64, up to the 17 decimals a table writes.
const POW10: [f64; 18] = [
    1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16,
    1e17,
];

/// [`fixed`] of an ordinary number (0, or 1e-6 ≤ |x| < 1e12, with fewer
/// than 10¹⁵ units of the last decimal) without float formatting: x
/// scaled by an exact power of ten and rounded to an integer, whose
/// digits are written. The scaled product is within half an ulp of the
/// exact one, so the rounding is the exact decimal's wherever the product
/// is more than an ulp from a half; nearer one (and outside the ordinary
/// range) `None`, and `format!` decides.
fn fixed_fast(x: f64, decimals: usize) -> Option<String> {
    let a = x.abs();
    if !(a == 0.0 || (1e-6..1e12).contains(&a)) {
        return None;
    }
    let scaled = a * POW10.get(decimals)?;
    if scaled >= 1e15 {
        return None;
    }
    let whole = scaled.floor();
    let frac = scaled - whole;
    if (frac - 0.5).abs() <= scaled * f64::EPSILON {
        return None;
    }
    let n = if frac > 0.5 { whole + 1.0 } else { whole } as u64;
    let p = 10u64.pow(decimals as u32);
    let mut digits = [0u8; 40];
    let mut at = digits.len();
    // cannot fail: n ≤ 1e15 and decimals ≤ 17 (`POW10`), so at most 17
    // decimals, a point, 16 whole digits and a sign: 35 bytes of the 40.
    #[allow(clippy::indexing_slicing)]
    let mut put = |b: u8| {
        at -= 1;
        digits[at] = b;
    };
    let mut frac_part = n % p;
    for _ in 0..decimals {
        put(b'0' + (frac_part % 10) as u8);
        frac_part /= 10;
    }
    if decimals > 0 {
        put(b'.');
    }
    let mut int_part = n / p;
    loop {
        put(b'0' + (int_part % 10) as u8);
        int_part /= 10;
        if int_part == 0 {
            break;
        }
    }
    if x < 0.0 && n != 0 {
        put(b'-');
    }
    std::str::from_utf8(digits.get(at..)?)
        .ok()
        .map(str::to_owned)
}

/// `x` to `figures` significant figures (at least 1) as a table writes
/// it: [`fixed`] decimals within [1e-4, 1e9), exponent form outside
/// (`1.23457e10`); 0 is `0`.
pub fn significant(x: f64, figures: usize) -> String {
    let figures = figures.max(1);
    let a = x.abs();
    if a != 0.0 && !(1e-4..1e9).contains(&a) {
        format!("{x:.*e}", figures - 1)
    } else {
        let decimals = if a == 0.0 {
            0
        } else {
            (figures as i32 - 1 - a.log10().floor() as i32).max(0) as usize
        };
        fixed(x, decimals)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn significant_figures_as_a_table_writes_them() {
        assert_eq!(significant(1234.5678, 6), "1234.57");
        assert_eq!(significant(-0.012345678, 6), "-0.0123457");
        assert_eq!(significant(123456789012.0, 6), "1.23457e11");
        assert_eq!(significant(0.0, 6), "0");
        assert_eq!(significant(2.5e-7, 3), "2.50e-7");
    }

    /// Every double, subnormals and the largest included: at most 15
    /// digits before the point, exponent form beyond, never "inf".
    #[test]
    fn every_double_is_fixed_within_a_width() {
        let mut x = 5e-324_f64;
        while x.is_finite() {
            for v in [x, -x] {
                for decimals in [0, 3, 17] {
                    let s = fixed(v, decimals);
                    assert!(s.len() <= 17 + decimals + 7, "{v:e}: {s}");
                    // Rounded, 1.7976931348623157e308 to 0 decimals
                    // reads "2e308": beyond the largest double, but text.
                    assert!(s.parse::<f64>().is_ok(), "{v:e}: {s}");
                    assert!(!s.contains("inf") && !s.contains("NaN"), "{v:e}: {s}");
                }
            }
            // 1.37 × the least subnormal rounds back to it: step at least an ulp.
            x = (x * 1.37).max(f64::from_bits(x.to_bits() + 1));
        }
        assert_eq!(fixed(f64::MAX, 3), "1.798e308");
        assert_eq!(fixed(5e-324, 3), "0.000");
    }

    #[test]
    fn negative_zero_is_not_printed() {
        assert_eq!(fixed(-0.0, 3), "0.000");
        assert_eq!(fixed(-0.0004, 3), "0.000");
        assert_eq!(fixed(-0.0005001, 3), "-0.001");
    }

    /// What `{:.N}` writes, without a negative zero: the formatting
    /// [`fixed_fast`] must match digit for digit.
    fn formatted(x: f64, decimals: usize) -> String {
        let s = format!("{:.*}", decimals, x);
        if s.starts_with('-') && s[1..].chars().all(|c| c == '0' || c == '.') {
            s[1..].to_string()
        } else {
            s
        }
    }

    #[test]
    fn the_fast_number_writer_has_the_digits_of_the_formatter() {
        // Over 30 decades, both signs, every count of decimals, with
        // mantissas from a fixed sequence and the halves that decide a
        // rounding (0.125, 2.5, 0.0625 …, exact in binary).
        let mut state = 0x2545_f491_4f6c_dd1d_u64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        let (mut fast, mut total) = (0, 0);
        for decade in -8..22 {
            for k in 0..300 {
                let mantissa = match k {
                    0 => 1.0,
                    1 => 1.25,
                    2 => 2.5,
                    3 => 0.625,
                    4 => 9.999_999_999_999_998,
                    _ => 1.0 + 9.0 * next(),
                };
                let x = mantissa * 10f64.powi(decade);
                for x in [x, -x, (x * 8.0).round() / 8.0, x.round() + 0.5] {
                    for decimals in 0..=17 {
                        total += 1;
                        if let Some(s) = fixed_fast(x, decimals) {
                            fast += 1;
                            assert_eq!(s, formatted(x, decimals), "{x:e} to {decimals}");
                        }
                    }
                }
            }
        }
        // The ordinary range (a third of these, which reach 1e22 and 17
        // decimals) is the fast path's.
        assert!(fast * 3 > total, "{fast} of {total}");
        assert_eq!(fixed_fast(0.0, 3).as_deref(), Some("0.000"));
        assert_eq!(fixed_fast(-0.0, 2).as_deref(), Some("0.00"));
        assert_eq!(fixed_fast(-0.000_001, 2).as_deref(), Some("0.00"));
        assert_eq!(fixed_fast(-1.5, 0), None); // a half: the formatter's
        assert_eq!(fixed_fast(1e-7, 4), None); // outside the ordinary range
        assert_eq!(fixed_fast(2e12, 1), None);
        assert_eq!(fixed_fast(f64::NAN, 1), None);
        assert_eq!(fixed(-12.345_67, 3), "-12.346");
    }
}

#[cfg(test)]
mod angle_cell_tests {
    use super::angle_cell;

    #[test]
    fn an_angle_cell_identifies_its_angle() {
        assert_eq!(angle_cell(30.0, 1), "30.0");
        assert_eq!(angle_cell(0.0, 1), "0.0");
        assert_eq!(angle_cell(-0.0, 1), "0.0");
        assert_eq!(angle_cell(22.5, 1), "22.5");
        assert_eq!(angle_cell(0.001, 1), "0.001");
        assert_eq!(angle_cell(0.1 + 0.2, 1), "0.30000000000000004");
        assert_eq!(angle_cell(10.0, 0), "10");
        assert_eq!(angle_cell(10.25, 0), "10.25");
        assert_eq!(angle_cell(359.99999, 1), "359.99999");
        for (a, b) in [(0.0, 0.001), (45.0, 45.0000001), (90.0, 90.0 + 1e-13)] {
            assert_ne!(angle_cell(a, 1), angle_cell(b, 1));
        }
    }
}
