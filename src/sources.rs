//! The numbers the sources give, each written once: the engines, speed,
//! load and measurements of the textbook's worked examples and of Ng's
//! paper (`docs/seed-errata.md` records where a source slips). The
//! figures, tables, handouts and every front end take their defaults
//! from here.

/// The textbook's §35 engine: crank r = 0.5 ft, connecting rod l = 3 ft
/// (in line).
pub const ENGINE_35: (f64, f64) = (0.5, 3.0);

/// The §35 engine's crank speed, rpm: the speed a figure, table, handout
/// or scene turns at when none is given.
pub const RPM: f64 = 250.0;

/// Ng's rig: crank r = 25 mm, connecting rod l = 72 mm (in line).
pub const NG_RIG: (f64, f64) = (25.0, 72.0);

/// Ng's crank torque, the one his Table 2's force column implies: 1 kg ×
/// 9.81 m/s² × 27 mm, in N·mm (264.87).
pub const NG_TORQUE: f64 = 9.81 * 27.0;

/// Ng's coefficient of friction of the slider in its guides: his block
/// first slid on a plane tilted at 45°, μ = tan 45° = 1.
pub const NG_FRICTION: f64 = 1.0;

/// The chain of the textbook's Fig. 60, with a rod short enough for its
/// inversions to read: crank r = 0.5, rod l = 1.5 (the quick return's
/// default).
pub const CHAIN_60: (f64, f64) = (0.5, 1.5);

/// Ng's Table 1: force in newtons (weights of 0.25 … 1.5 kg) against
/// strain reading (×10⁻⁶), the points his calibration line is fitted
/// through.
pub const NG_TABLE_1: [(f64, f64); 6] = [
    (2.45, 50.0),
    (4.91, 95.0),
    (7.36, 148.0),
    (9.81, 190.0),
    (12.27, 238.0),
    (14.72, 290.0),
];
