//! `table quick-return`: the tool's position, velocity and acceleration
//! over the cutting and return strokes of a quick return (inversion 2,
//! Whitworth's, or 3, the crank and slotted lever), with the time ratio in
//! the title.

use super::{Table, sig};
use crate::angle::Angle;
use crate::chain::{Inversion, QuickReturn};
use crate::error::Result;
use crate::number::{angle_cell, fixed, plain};

use crate::units::Units;

/// The title, headers and notes of the table, without rows.
pub fn quick_return_head(q: &QuickReturn, omega: f64, units: &Units) -> Table {
    let m = q.chain().mechanism();
    let u = units.length();
    let (cutting, back) = q.stroke_angles();
    let inversion = q.chain().inversion();
    let (name, driver) = match inversion {
        Inversion::Rod => ("the crank and slotted lever", "the crank a about B"),
        _ => ("Whitworth’s", "the rod b about B"),
    };
    Table {
        title: format!(
            "Quick return, inversion {} ({name}): r = {} {u}, l = {} {u}, e = {} {u}, arm L = {} {u}, {} rpm (ω = {} rad/s); time ratio {} (cutting {}°, return {}° of the driver’s turn), stroke {} {u}",
            inversion.number(),
            plain(m.crank()),
            plain(m.rod()),
            plain(m.offset()),
            plain(q.lever()),
            crate::number::short(omega * 60.0 / std::f64::consts::TAU),
            sig(omega),
            sig(q.time_ratio()),
            sig(cutting.to_degrees()),
            sig(back.to_degrees()),
            sig(q.stroke_length()),
        ),
        headers: vec![
            "θ (°)".into(),
            "stroke".into(),
            "driver (°)".into(),
            format!("s ({u})"),
            format!("ds/dt ({})", units.velocity()),
            format!("d²s/dt² ({})", units.acceleration()),
        ],
        rows: vec![],
        notes: vec![
            format!(
                "θ: the crank a against the slotted link d; the driver ({driver}) turns at ω counter-clockwise; driver: its turn since the cutting stroke began."
            ),
            "s: the tool along its stroke from mid-stroke, square to the fixed link's line of centres, driven by the arm L of d through a pin in a slot of the ram; the strokes end at θ = 90° and 270°.".into(),
        ],
    }
}

/// One row: θ, the stroke, the driver's turn since the cutting stroke
/// began, and the tool's position, velocity and acceleration.
pub fn quick_return_row(
    q: &QuickReturn,
    omega: f64,
    degrees: f64,
    decimals: usize,
) -> Result<Vec<String>> {
    let t = q.at(Angle::from_degrees(degrees)?, omega);
    Ok(vec![
        angle_cell(degrees, 1),
        t.stroke.name().into(),
        fixed(t.driver_angle.to_degrees(), 2),
        fixed(t.position, decimals),
        fixed(t.velocity, decimals),
        fixed(t.acceleration, decimals),
    ])
}
