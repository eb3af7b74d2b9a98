//! The crate's one error type.

use thiserror::Error;

/// Everything that can go wrong at the boundary of the crate: bad numbers,
/// a mechanism that cannot be assembled, a malformed request.
///
/// Each message names the offending value and what would be needed instead,
/// so that the command line can print it as one line on standard error.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum Error {
    /// A parameter is NaN or infinite.
    #[error("{name} must be a finite number, got {value}")]
    NotFinite {
        /// Which parameter (for example `crank`).
        name: &'static str,
        /// The value given.
        value: f64,
    },
    /// A length or other parameter that must be positive is zero or negative.
    #[error("{name} must be greater than zero, got {value}")]
    NotPositive {
        /// Which parameter.
        name: &'static str,
        /// The value given.
        value: f64,
    },
    /// A parameter that must not be negative is negative.
    #[error("{name} must not be negative, got {value}")]
    Negative {
        /// Which parameter.
        name: &'static str,
        /// The value given.
        value: f64,
    },
    /// The connecting rod is too short for the crank to turn a full revolution.
    #[error(
        "rod {rod} is too short for crank {crank} and offset {offset}: the crank turns fully only when rod > crank + |offset| = {needed}"
    )]
    RodTooShort {
        /// Crank radius given.
        crank: f64,
        /// Rod length given.
        rod: f64,
        /// Offset of the line of stroke given.
        offset: f64,
        /// The bound the rod must exceed, crank + |offset|.
        needed: f64,
    },
    /// A value that is outside the range a computation accepts.
    #[error("{name} = {value} is out of range: {reason}")]
    OutOfRange {
        /// Which parameter.
        name: &'static str,
        /// The value given.
        value: f64,
        /// What the range is.
        reason: String,
    },
    /// Input text that could not be understood (angle ranges, lists, files).
    #[error("{0}")]
    Parse(String),
    /// Reading or writing a file failed.
    #[error("{0}")]
    Io(String),
}

/// The crate's result type.
pub type Result<T> = std::result::Result<T, Error>;

/// Checks that `value` is finite, naming it in the error otherwise.
pub(crate) fn finite(name: &'static str, value: f64) -> Result<f64> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(Error::NotFinite { name, value })
    }
}

/// Checks that `value` is finite and strictly positive.
pub(crate) fn positive(name: &'static str, value: f64) -> Result<f64> {
    let value = finite(name, value)?;
    if value > 0.0 {
        Ok(value)
    } else {
        Err(Error::NotPositive { name, value })
    }
}

/// Checks that `value` is finite and not negative.
pub(crate) fn non_negative(name: &'static str, value: f64) -> Result<f64> {
    let value = finite(name, value)?;
    if value >= 0.0 {
        Ok(value)
    } else {
        Err(Error::Negative { name, value })
    }
}
