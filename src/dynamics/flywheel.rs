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
    /// coefficient `coefficient` (> 0).
    ///
    /// Errors: ΔE negative or not finite, ω zero, C_s not positive, or I
    /// beyond the largest number.
    pub fn for_coefficient(fluctuation: f64, omega: f64, coefficient: f64) -> Result<Self> {
        let coefficient = positive(Field::FluctuationOfSpeed, coefficient)?;
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
    /// Errors: as [`Flywheel::for_coefficient`], for I.
    pub fn for_inertia(fluctuation: f64, omega: f64, inertia: f64) -> Result<Self> {
        let inertia = positive(Field::Flywheel, inertia)?;
        let w2 = check(fluctuation, omega)?;
        let coefficient = fluctuation / w2 / inertia;
        if !coefficient.is_finite() {
            return Err(Error::OutOfRange {
                name: Field::Flywheel,
                value: inertia,
                reason: "the coefficient of fluctuation exceeds the largest number".into(),
            });
        }
        Ok(Self {
            fluctuation,
            omega,
            inertia,
            coefficient,
        })
    }
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
}
