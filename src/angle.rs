//! Crank angles with exact trigonometry at the multiples of 90°.

use crate::error::{Field, Result, finite};
use std::f64::consts::PI;

/// An angle together with its sine and cosine.
///
/// Built from degrees, the angle is first reduced to `[0°, 360°)` and then to
/// a quarter turn around the nearest multiple of 90°, both steps exact in
/// floating point; so `sin` and `cos` of every multiple of 90° are exactly
/// `0` and `±1` (at θ = 90° the instantaneous centre of the rod is then
/// really at infinity, not at 1e16).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Angle {
    degrees: f64,
    radians: f64,
    sin: f64,
    cos: f64,
}

impl Angle {
    /// The angle of `degrees` degrees, reduced exactly.
    ///
    /// Errors with [`crate::error::Error::NotFinite`] for NaN or infinity. Any finite
    /// value is accepted: the crank of a valid mechanism turns fully.
    #[inline]
    pub fn from_degrees(degrees: f64) -> Result<Self> {
        let degrees = finite(Field::Angle, degrees)?;
        // fmod is exact, and the identity on [0°, 360°): a sweep's angles
        // skip its call.
        let mut reduced = if (0.0..360.0).contains(&degrees) {
            degrees
        } else {
            degrees % 360.0
        };
        if reduced < 0.0 {
            reduced += 360.0;
        }
        if reduced >= 360.0 {
            reduced = 0.0;
        }
        // Quadrant and remainder in [-45°, 45°]; the subtraction is exact by
        // Sterbenz's lemma.
        let quadrant = round_half_up(reduced / 90.0);
        let rest = reduced - 90.0 * quadrant as f64;
        let (s, c) = if rest == 0.0 {
            (0.0, 1.0)
        } else {
            (rest * (PI / 180.0)).sin_cos()
        };
        let (sin, cos) = match quadrant {
            0 | 4 => (s, c),
            1 => (c, -s),
            2 => (-s, -c),
            _ => (-c, s),
        };
        Ok(Self {
            degrees: reduced,
            radians: reduced * (PI / 180.0),
            sin: sin + 0.0,
            cos: cos + 0.0,
        })
    }

    /// The angle of `degrees` degrees, reduced exactly, for a literal or a
    /// value known to be finite: `Angle::deg(30.0)`. The same angle as
    /// [`Angle::from_degrees`], without the `Result`.
    ///
    /// # Panics
    ///
    /// On NaN or infinity (use [`Angle::from_degrees`] for input).
    ///
    /// ```
    /// use slider_crank::Angle;
    /// assert_eq!(Angle::deg(90.0).cos(), 0.0);
    /// assert_eq!(Angle::deg(-30.0), Angle::from_degrees(330.0)?);
    /// # Ok::<(), slider_crank::Error>(())
    /// ```
    #[track_caller]
    pub fn deg(degrees: f64) -> Self {
        match Self::from_degrees(degrees) {
            Ok(angle) => angle,
            Err(_) => panic!("Angle::deg takes a finite number of degrees, not {degrees}"),
        }
    }

    /// The angle of `radians` radians. No exact reduction is possible here
    /// (π is not a float); prefer [`Angle::from_degrees`] for given angles.
    /// The reduced angle is in `[0, 2π)` and its degrees in `[0, 360)`
    /// even where rounding would give 2π (a tiny negative angle is 0).
    pub fn from_radians(radians: f64) -> Result<Self> {
        let radians = finite(Field::Angle, radians)?;
        let mut reduced = radians.rem_euclid(2.0 * PI);
        // rem_euclid(−1e-17) rounds up to 2π itself; and just below 2π the
        // degrees may round up to 360.
        if reduced >= 2.0 * PI || reduced.to_degrees() >= 360.0 {
            reduced = 0.0;
        }
        let (sin, cos) = radians.sin_cos();
        Ok(Self {
            degrees: reduced.to_degrees(),
            radians: reduced,
            sin,
            cos,
        })
    }

    /// The angle in degrees, reduced to `[0, 360)`.
    #[inline]
    pub fn degrees(&self) -> f64 {
        self.degrees
    }

    /// The angle in radians, reduced to `[0, 2π)`.
    #[inline]
    pub fn radians(&self) -> f64 {
        self.radians
    }

    /// The sine (exact at multiples of 90° when built from degrees).
    #[inline]
    pub fn sin(&self) -> f64 {
        self.sin
    }

    /// The cosine (exact at multiples of 90° when built from degrees).
    #[inline]
    pub fn cos(&self) -> f64 {
        self.cos
    }
}

/// `q.round()` for `q` in [0, 4], without the library call that
/// `round` is on a processor without SSE4.1: the integer part, and one more
/// where the fraction (exact: `q` and its integer part are within a factor
/// of two, or the part is 0) is at least a half.
#[inline]
fn round_half_up(q: f64) -> i64 {
    let whole = q as i64;
    whole + i64::from(q - whole as f64 >= 0.5)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_quadrant_is_rounded_as_round_rounds() {
        let mut q = 0.0f64;
        let mut cases = vec![
            0.49999999999999994,
            0.5,
            1.5,
            2.5,
            3.5,
            4.0,
            3.9999999999999996,
        ];
        while q <= 4.0 {
            cases.push(q);
            q += 1.0 / 1024.0;
        }
        for q in cases {
            for v in [
                q,
                f64::from_bits(q.to_bits() + 1),
                f64::from_bits(q.to_bits().saturating_sub(1)),
            ] {
                if (0.0..=4.0).contains(&v) {
                    assert_eq!(round_half_up(v), v.round() as i64, "{v}");
                }
            }
        }
    }

    #[test]
    fn angles_within_a_turn_reduce_as_fmod_reduces() {
        for d in [
            0.0,
            -0.0,
            1e-300,
            0.5,
            89.99999999999999,
            90.0,
            359.99999999999994,
            360.0,
            720.5,
            -0.5,
        ] {
            let a = Angle::from_degrees(d).unwrap();
            let mut r = d % 360.0;
            if r < 0.0 {
                r += 360.0;
            }
            if r >= 360.0 {
                r = 0.0;
            }
            assert_eq!(a.degrees().to_bits(), r.to_bits(), "{d}");
        }
    }

    #[test]
    fn multiples_of_ninety_are_exact() {
        for k in -8i32..=8 {
            let a = Angle::deg(90.0 * k as f64);
            let expected =
                [(0.0, 1.0), (1.0, 0.0), (0.0, -1.0), (-1.0, 0.0)][k.rem_euclid(4) as usize];
            assert_eq!((a.sin(), a.cos()), expected, "k = {k}");
        }
    }

    #[test]
    fn reduction_keeps_other_angles_accurate() {
        for d in [
            1.0, 29.0, 45.0, 134.0, 136.0, 200.0, 314.0, 359.5, -30.0, 725.0,
        ] {
            let a = Angle::deg(d);
            let r = d.rem_euclid(360.0).to_radians();
            assert!((a.sin() - r.sin()).abs() < 1e-15, "{d}");
            assert!((a.cos() - r.cos()).abs() < 1e-15, "{d}");
            assert!((0.0..360.0).contains(&a.degrees()));
        }
    }

    #[test]
    fn symmetric_angles_are_bit_identical() {
        let a = Angle::deg(30.0);
        let b = Angle::deg(-330.0);
        let c = Angle::deg(150.0);
        assert_eq!((a.sin(), a.cos()), (b.sin(), b.cos()));
        assert_eq!((a.sin(), -a.cos()), (c.sin(), c.cos()));
    }

    #[test]
    fn tiny_negative_angle_reduces_into_range() {
        let a = Angle::deg(-1e-20);
        assert!((0.0..360.0).contains(&a.degrees()));
    }

    #[test]
    fn tiny_negative_radians_reduce_into_range() {
        // Issue 9 (10): −1e-17 rad gave 360° and 2π.
        for r in [-1e-17, -1e-300, -5e-324, -0.0, 2.0 * PI, -2.0 * PI, 1e300] {
            let a = Angle::from_radians(r).unwrap();
            assert!((0.0..360.0).contains(&a.degrees()), "{r}: {}", a.degrees());
            assert!((0.0..2.0 * PI).contains(&a.radians()), "{r}");
        }
    }

    #[test]
    fn non_finite_is_rejected() {
        assert!(Angle::from_degrees(f64::NAN).is_err());
        assert!(Angle::from_degrees(f64::INFINITY).is_err());
        assert!(Angle::from_radians(f64::NEG_INFINITY).is_err());
    }
}
