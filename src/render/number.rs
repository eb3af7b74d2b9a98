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
    if v == 0.0 { "0".into() } else { format!("{v}") }
}

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
        assert_eq!(plain(1e-100), "1e-100");
        assert_eq!(plain(-1e308), "-1e308");
        assert_eq!(plain(0.025), "0.025");
        assert_eq!(plain(-0.0), "-0");
        assert_eq!(plain(f64::NAN), "NaN");
    }
}
