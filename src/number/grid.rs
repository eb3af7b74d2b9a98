//! Numbers written to SVG: rounded to a fixed grid so that output is
//! reproducible to the byte.

/// The grid of page coordinates: 0.01 units.
pub const GRID: f64 = 0.01;

/// `x` rounded to the grid, without trailing zeros or a negative zero.
/// Non-finite input writes `0` (the model never holds one; this keeps NaN
/// out of the file whatever happens).
pub fn fmt(x: f64) -> String {
    OnGrid(x).to_string()
}

/// A number written as [`fmt`] writes it, straight into a formatter (no
/// string of its own: path data writes thousands of them).
#[derive(Debug, Clone, Copy)]
pub struct OnGrid(pub f64);

impl std::fmt::Display for OnGrid {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let x = self.0;
        if !x.is_finite() {
            return f.write_str("0");
        }
        let n = (x / GRID).round();
        if n == 0.0 {
            return f.write_str("0");
        }
        if n.abs() >= 1e12 {
            // From 1e15 units on in exponent form: `{}` writes every digit
            // of a double (309 for 1e308).
            // Beyond f64::MAX × GRID the hundredths overflow: x itself is
            // far coarser than the grid there.
            let units = if n.is_finite() { n / (1.0 / GRID) } else { x };
            return if units.abs() >= 1e15 {
                write!(f, "{units:e}")
            } else {
                write!(f, "{units}")
            };
        }
        // Hundredths as an integer, written without float formatting:
        // below 1e10 units the decimal of n / 100 is the shortest that
        // reads back as that double, which is what `{}` on the quotient
        // would write.
        let n = n as i64;
        let (mut rest, cents) = (n.unsigned_abs() / 100, n.unsigned_abs() % 100);
        // Written backwards into a buffer: the decimals without trailing
        // zeros, the point, the whole part, the sign.
        let mut buf = [0u8; 24];
        let mut at = buf.len();
        // cannot fail: |n| < 1e12, so at most 10 whole digits, a point, 2
        // decimals and a sign: 14 bytes of the 24.
        #[allow(clippy::indexing_slicing)]
        let mut put = |b: u8| {
            at -= 1;
            buf[at] = b;
        };
        if cents != 0 {
            if cents % 10 != 0 {
                put(b'0' + (cents % 10) as u8);
            }
            put(b'0' + (cents / 10) as u8);
            put(b'.');
        }
        loop {
            put(b'0' + (rest % 10) as u8);
            rest /= 10;
            if rest == 0 {
                break;
            }
        }
        if n < 0 {
            put(b'-');
        }
        let written = buf.get(at..).unwrap_or_default();
        f.write_str(std::str::from_utf8(written).unwrap_or("0"))
    }
}

/// A coefficient of a map, to 6 decimals, or to 7 significant digits
/// where that is finer (|x| < 1: the small scales of plot axes in large
/// units), so that the map read back from the file is good to a relative
/// 1e-7 or better.
pub fn fmt_coefficient(x: f64) -> String {
    if !x.is_finite() {
        return "0".into();
    }
    let decimals = if x != 0.0 && x.abs() < 1.0 {
        (6 - x.abs().log10().floor() as i32).clamp(6, 300)
    } else {
        6
    };
    let v: f64 = format!("{x:.*}", decimals as usize).parse().unwrap_or(0.0);
    if v == 0.0 {
        return "0".into();
    }
    // Fixed notation within MAX_FIXED_WIDTH characters (`0.000000001`),
    // exponent form beyond (`1e-97`, not 97 zeros).
    let fixed = format!("{v}");
    if fixed.len() > super::MAX_FIXED_WIDTH {
        format!("{v:e}")
    } else {
        fixed
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rounding_is_to_the_grid() {
        assert_eq!(fmt(12.345678), "12.35");
        assert_eq!(fmt(-0.001), "0");
        assert_eq!(fmt(3.0), "3");
        assert_eq!(fmt(0.1 + 0.2), "0.3");
        assert_eq!(fmt(f64::NAN), "0");
        assert_eq!(fmt(-7.126), "-7.13");
        assert_eq!(fmt_coefficient(151.123456789), "151.123457");
        assert_eq!(fmt_coefficient(-0.0123456789), "-0.01234568");
        assert_eq!(fmt_coefficient(0.4), "0.4");
        assert_eq!(fmt_coefficient(1e-9), "0.000000001");
        assert_eq!(fmt_coefficient(0.0), "0");
    }

    /// Every double, subnormals and the largest included: finite text of
    /// bounded width that reads back to the value (on the grid for `fmt`,
    /// to 7 significant digits for `fmt_coefficient`); was 309 digits for
    /// 1e308 and 300 zeros for a coefficient of 1e-300.
    #[test]
    fn every_double_is_written_within_a_width() {
        let mut x = 5e-324_f64;
        while x.is_finite() {
            for v in [x, -x] {
                let (grid, coefficient) = (fmt(v), fmt_coefficient(v));
                for s in [&grid, &coefficient] {
                    assert!(s.len() <= 26, "{v:e}: {s}");
                    assert!(s.parse::<f64>().is_ok_and(f64::is_finite), "{v:e}: {s}");
                }
                let back: f64 = grid.parse().unwrap();
                assert!((back - v).abs() <= 0.005 + 1e-15 * v.abs(), "{v:e}: {grid}");
                let back: f64 = coefficient.parse().unwrap();
                assert!(
                    (back - v).abs() <= 1e-6 * v.abs().max(1e-6),
                    "{v:e}: {coefficient}"
                );
            }
            // 1.37 × the least subnormal rounds back to it: step at least an ulp.
            x = (x * 1.37).max(f64::from_bits(x.to_bits() + 1));
        }
        assert_eq!(fmt(f64::MAX), "1.7976931348623157e308");
        assert_eq!(fmt_coefficient(1e-300), "1e-300");
        assert_eq!(fmt_coefficient(5e-324), "0");
    }

    #[test]
    fn integer_writing_matches_the_quotient_written_as_a_float() {
        // The hundredths written as integers read back as what `{}` on
        // (x / GRID).round() / 100 writes, over many scales and signs.
        let mut x = 1.234_567_89e-3_f64;
        while x < 1e13 {
            for v in [x, -x, x * 1.000_000_7, -x * 0.999_999_3] {
                let float = (v / GRID).round() / (1.0 / GRID);
                let expected = if float == 0.0 {
                    "0".to_string()
                } else {
                    format!("{float}")
                };
                assert_eq!(fmt(v), expected, "{v}");
            }
            x *= 1.37;
        }
    }
}
