//! Numbers in running text: messages, titles, a value given echoed.

/// The most characters a number written in fixed notation takes where
/// the shortest decimal that reads back is written (`{}` of a double,
/// which never switches to exponent form by itself): beyond it the number
/// is written in exponent form. 24 holds every value of the catalogue's
/// scales (`0.000000001`, `123456789012.25`) and none of the hundreds of
/// digits of 1e-300 or 1e308.
pub const MAX_FIXED_WIDTH: usize = 24;

/// A number as text shows it (messages, titles, a given value echoed):
/// plainly in the usual range, in exponent form when very large or very
/// small (`1e-300`, not 300 zeros; `1e308`, not 309 digits).
pub fn plain(x: f64) -> String {
    let a = x.abs();
    if a != 0.0 && a.is_finite() && !(1e-4..1e15).contains(&a) {
        format!("{x:e}")
    } else {
        format!("{x}")
    }
}

/// `x` with −0.0 as +0.0 (`x + 0.0`), so that no `-0` is written (in
/// JSON, a page's data, a number in text); every other number, NaN and
/// the infinities among them, unchanged.
pub fn unsigned_zero(x: f64) -> f64 {
    x + 0.0
}

#[cfg(test)]
mod plain_tests {
    use super::plain;

    #[test]
    fn numbers_in_messages_are_plain_or_in_exponent_form() {
        assert_eq!(plain(1e-100), "1e-100");
        assert_eq!(plain(-1e308), "-1e308");
        assert_eq!(plain(0.025), "0.025");
        assert_eq!(plain(-0.0), "-0");
        assert_eq!(plain(f64::NAN), "NaN");
    }

    /// Every double, subnormals and the largest included, in at most 24
    /// characters that read back to it exactly.
    #[test]
    fn every_double_is_plain_within_a_width() {
        let mut x = 5e-324_f64;
        while x.is_finite() {
            for v in [x, -x] {
                let s = plain(v);
                assert!(s.len() <= super::MAX_FIXED_WIDTH, "{v:e}: {s}");
                assert_eq!(s.parse::<f64>().unwrap(), v, "{s}");
            }
            // 1.37 × the least subnormal rounds back to it: step at least an ulp.
            x = (x * 1.37).max(f64::from_bits(x.to_bits() + 1));
        }
        assert_eq!(plain(f64::MAX), "1.7976931348623157e308");
    }
}
