//! Numbers written to SVG: rounded to a fixed grid so that output is
//! reproducible to the byte.

/// The grid of page coordinates: 0.01 units.
pub const GRID: f64 = 0.01;

/// `x` rounded to the grid, without trailing zeros or a negative zero.
/// Non-finite input writes `0` (the model never holds one; this keeps NaN
/// out of the file whatever happens).
pub fn fmt(x: f64) -> String {
    if !x.is_finite() {
        return "0".into();
    }
    let v = (x / GRID).round() / (1.0 / GRID);
    if v == 0.0 {
        return "0".into();
    }
    format!("{v}")
}

/// A coefficient of a map, to 6 decimals.
pub fn fmt_coefficient(x: f64) -> String {
    if !x.is_finite() {
        return "0".into();
    }
    let v = (x * 1e6).round() / 1e6;
    if v == 0.0 { "0".into() } else { format!("{v}") }
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
    }
}
