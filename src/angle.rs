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
    pub fn from_degrees(degrees: f64) -> Result<Self> {
        let degrees = finite(Field::Angle, degrees)?;
        let mut reduced = degrees % 360.0; // fmod is exact
        if reduced < 0.0 {
            reduced += 360.0;
        }
        if reduced >= 360.0 {
            reduced = 0.0;
        }
        // Quadrant and remainder in [-45°, 45°]; the subtraction is exact by
        // Sterbenz's lemma.
        let quadrant = (reduced / 90.0).round();
        let rest = reduced - 90.0 * quadrant;
        let (s, c) = if rest == 0.0 {
            (0.0, 1.0)
        } else {
            (rest * (PI / 180.0)).sin_cos()
        };
        let (sin, cos) = match quadrant as i64 {
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
    pub fn degrees(&self) -> f64 {
        self.degrees
    }

    /// The angle in radians, reduced to `[0, 2π)`.
    pub fn radians(&self) -> f64 {
        self.radians
    }

    /// The sine (exact at multiples of 90° when built from degrees).
    pub fn sin(&self) -> f64 {
        self.sin
    }

    /// The cosine (exact at multiples of 90° when built from degrees).
    pub fn cos(&self) -> f64 {
        self.cos
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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
