//! The flywheel: the moment of inertia that holds the speed within a
//! coefficient of fluctuation, or the coefficient a given flywheel gives.

use crate::error::{Error, Field, Result, positive};

/// A flywheel on the crank shaft and the fluctuation of speed it allows.
///
/// Between the crank angles of least and most stored energy the flywheel
/// takes up ΔE = ½ I (ω_max² − ω_min²) = I ω_mean² C_s, with ω_mean =
/// (ω_max + ω_min)/2 taken as the crank speed ω and C_s = (ω_max −
/// ω_min)/ω_mean the coefficient of fluctuation of speed (exact for that
/// definition of the mean speed).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Flywheel {
    /// The fluctuation of energy ΔE.
    pub fluctuation: f64,
    /// The mean crank speed ω, rad/s.
    pub omega: f64,
    /// The flywheel's moment of inertia I.
    pub inertia: f64,
    /// The coefficient of fluctuation of speed C_s.
    pub coefficient: f64,
}

impl Flywheel {
    /// The flywheel I = ΔE / (ω² C_s) that keeps the speed within the
    /// coefficient `coefficient` (0 < C_s < [`MAX_COEFFICIENT`]).
    ///
    /// Errors: ΔE negative or not finite, ω zero, C_s not positive or not
    /// below 2 (the least speed ω (1 − C_s/2) would be zero or negative),
    /// or I beyond the largest number.
    pub fn for_coefficient(fluctuation: f64, omega: f64, coefficient: f64) -> Result<Self> {
        let coefficient = checked_coefficient(coefficient)?;
        let w2 = check(fluctuation, omega)?;
        let inertia = fluctuation / w2 / coefficient;
        if !inertia.is_finite() {
            return Err(Error::OutOfRange {
                name: Field::FluctuationOfSpeed,
                value: coefficient,
                reason: "the flywheel's moment of inertia exceeds the largest number".into(),
            });
        }
        Ok(Self {
            fluctuation,
            omega,
            inertia,
            coefficient,
        })
    }

    /// The coefficient C_s = ΔE / (I ω²) of the flywheel of moment of
    /// inertia `inertia` (> 0).
    ///
    /// Errors: as [`Flywheel::for_coefficient`], for I; a flywheel too
    /// light to carry the engine through its turn (C_s ≥ 2: the speed
    /// would fall to zero before the energy is given back), which the
    /// formula would otherwise answer with a meaningless C_s.
    pub fn for_inertia(fluctuation: f64, omega: f64, inertia: f64) -> Result<Self> {
        let inertia = positive(Field::Flywheel, inertia)?;
        let w2 = check(fluctuation, omega)?;
        let coefficient = fluctuation / w2 / inertia;
        below_limit(inertia, coefficient)?;
        Ok(Self {
            fluctuation,
            omega,
            inertia,
            coefficient,
        })
    }
}

/// The coefficient of fluctuation of speed below which the least speed
/// ω (1 − C_s/2) stays above zero: C_s = (ω_max − ω_min)/ω is below it.
pub const MAX_COEFFICIENT: f64 = 2.0;

/// The coefficient of fluctuation of speed a flywheel is sized for when
/// none is given (the figure, the handout, the command line and Python):
/// an illustration, the sources give none.
pub const DEFAULT_FLUCTUATION: f64 = 0.02;

/// A coefficient of fluctuation of speed C_s asked for, checked: above 0
/// and below [`MAX_COEFFICIENT`], the one rule every figure, table and
/// handout that sizes a flywheel keeps.
///
/// Errors: C_s not in (0, 2), or not a number.
pub fn checked_coefficient(coefficient: f64) -> Result<f64> {
    if coefficient > 0.0 && coefficient < MAX_COEFFICIENT {
        return Ok(coefficient);
    }
    Err(Error::OutOfRange {
        name: Field::Fluctuation,
        value: coefficient,
        reason: "the coefficient of fluctuation of speed C_s = (ω_max − ω_min)/ω is above 0 and below 2 (where the least speed would be zero)".into(),
    })
}

/// Refuses the flywheel of moment of inertia `inertia` that would let the
/// speed vary by `coefficient` ≥ [`MAX_COEFFICIENT`] (or by no finite
/// amount).
fn below_limit(inertia: f64, coefficient: f64) -> Result<()> {
    if coefficient < MAX_COEFFICIENT {
        return Ok(());
    }
    Err(Error::OutOfRange {
        name: Field::Flywheel,
        value: inertia,
        reason: format!(
            "this flywheel is too light: the speed would vary by C_s = (ω_max − ω_min)/ω = {}, and from C_s = 2 the least speed is zero",
            crate::number::significant(coefficient, 4)
        ),
    })
}

/// ω² after checking ΔE ≥ 0 and ω ≠ 0.
fn check(fluctuation: f64, omega: f64) -> Result<f64> {
    crate::error::non_negative(Field::FluctuationOfEnergy, fluctuation)?;
    let w2 = omega * omega;
    if w2 > 0.0 {
        Ok(w2)
    } else {
        Err(Error::OutOfRange {
            name: Field::Omega,
            value: omega,
            reason: "a flywheel is sized for a turning crank, ω ≠ 0".into(),
        })
    }
}

/// What the flywheel note works out: the flywheel for a coefficient of
/// fluctuation of speed, or the coefficient of a given flywheel.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum FlywheelAsk {
    /// No flywheel note.
    None,
    /// The moment of inertia for this coefficient C_s.
    Coefficient(f64),
    /// The coefficient for this moment of inertia I.
    Inertia(f64),
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn inertia_and_coefficient_are_inverse() {
        // ΔE = 1000, ω = 20: I = 1000 / (400 × 0.02) = 125.
        let f = Flywheel::for_coefficient(1000.0, 20.0, 0.02).unwrap();
        assert!((f.inertia - 125.0).abs() < 1e-12);
        let g = Flywheel::for_inertia(1000.0, 20.0, 125.0).unwrap();
        assert!((g.coefficient - 0.02).abs() < 1e-16);
        assert!(Flywheel::for_coefficient(1000.0, 0.0, 0.02).is_err());
        assert!(Flywheel::for_coefficient(1000.0, 20.0, 0.0).is_err());
        assert!(Flywheel::for_inertia(-1.0, 20.0, 1.0).is_err());
    }

    #[test]
    fn a_speed_that_would_reach_zero_is_refused() {
        // C_s = 2 would make ω_min = 0; 1.999 still turns.
        assert!(Flywheel::for_coefficient(1000.0, 20.0, 2.0).is_err());
        assert!(Flywheel::for_coefficient(1000.0, 20.0, 5.0).is_err());
        assert!(Flywheel::for_coefficient(1000.0, 20.0, f64::INFINITY).is_err());
        assert!(Flywheel::for_coefficient(1000.0, 20.0, 1.999).is_ok());
        // I = 1e-300: C_s = 1000 / 400 / 1e-300, far past 2.
        let e = Flywheel::for_inertia(1000.0, 20.0, 1e-300).unwrap_err();
        assert!(e.to_string().contains("too light"), "{e}");
        assert!(Flywheel::for_inertia(1000.0, 20.0, 1.25 + 1e-9).is_ok());
        assert!(Flywheel::for_inertia(1000.0, 20.0, 1.25).is_err());
        // With no fluctuation at all any flywheel holds the speed.
        assert_eq!(
            Flywheel::for_inertia(0.0, 20.0, 1e-300)
                .unwrap()
                .coefficient,
            0.0
        );
    }
}
