//! `table partial-balance`: the unbalanced primary force of a single
//! cylinder against θ for several balanced fractions c, with the largest
//! and least over the turn and the locomotive's hammer blow as notes.

use super::Table;
use crate::angle::Angle;
use crate::dynamics::{HammerBlow, PartialBalance};
use crate::error::{Field, Result, finite, non_negative, positive};
use crate::number::{angle_cell, fixed, significant};
use crate::units::Units;

/// The locomotive of the hammer blow note: its wheel, the crank's
/// reciprocating mass and radius, the speed along the rails and, if
/// given, the wheel's static load on the rail.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Locomotive {
    /// The reciprocating mass m.
    pub mass: f64,
    /// The crank radius r.
    pub crank: f64,
    /// The wheel's diameter D.
    pub wheel: f64,
    /// The speed v along the rails.
    pub speed: f64,
    /// The wheel's static load P on the rail.
    pub load: Option<f64>,
}

impl Locomotive {
    /// The locomotive, checked.
    ///
    /// Errors: a mass negative, a crank, a wheel or a load not positive,
    /// any value not finite (the speed's sign does not matter).
    pub fn new(mass: f64, crank: f64, wheel: f64, speed: f64, load: Option<f64>) -> Result<Self> {
        Ok(Self {
            mass: non_negative(Field::Mass, mass)?,
            crank: positive(Field::Crank, crank)?,
            wheel: positive(Field::Wheel, wheel)?,
            speed: finite(Field::Speed, speed)?,
            load: load.map(|p| positive(Field::Load, p)).transpose()?,
        })
    }
}

/// How a fraction is written in the headers and notes: to four figures,
/// without trailing zeros (0.5, 0.6667, 1).
fn written(c: f64) -> String {
    let s = significant(c, 4);
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    }
}

/// The title, headers and notes of the table for the fractions
/// `balances`; values per unit m r ω². With `locomotive`, a note of the
/// hammer blow for each fraction (and the speed at which the wheel lifts
/// off a rail of the given load).
///
/// Errors: a locomotive's value out of range ([`HammerBlow::new`]).
pub fn partial_balance_head(
    balances: &[PartialBalance],
    locomotive: Option<&Locomotive>,
    units: &Units,
) -> Result<Table> {
    let mut headers = vec!["θ (°)".to_string()];
    let mut notes = vec![
        "A counterweight opposite the crank balances the rotating mass m_R at the crank pin and the fraction c of the reciprocating mass m: B b = (m_R + c m) r. Values ÷ m r ω² (the primary force): along the line of stroke (horizontal in a horizontal engine) (1 − c) cos θ, across it (vertical) −c sin θ, in size √((1 − c)² cos²θ + c² sin²θ). The secondary force m r ω² cos 2θ / n is left as it was (table balance, table dynamics).".to_string(),
    ];
    for b in balances {
        let c = written(b.fraction());
        headers.extend(["horizontal", "vertical", "size"].map(|h| format!("c = {c}: {h}")));
        let (most, least) = (significant(b.largest(), 6), significant(b.least(), 6));
        let place = if b.fraction() == 0.5 {
            "the same at every angle".to_string()
        } else if b.fraction() < 0.5 {
            format!("at most {most} at the dead centres, at least {least} at 90° and 270°")
        } else {
            format!("at most {most} at 90° and 270°, at least {least} at the dead centres")
        };
        notes.push(format!("c = {c}: the unbalanced force {place}."));
    }
    if let Some(l) = locomotive {
        notes.extend(hammer_notes(balances, l, units)?);
    }
    Ok(Table {
        title: "Partial balance of a single cylinder".into(),
        headers,
        rows: vec![],
        notes,
    })
}

/// The hammer blow's notes: the wheel's speed, and for each fraction the
/// blow c m r ω² and the speed at which it lifts the wheel.
fn hammer_notes(balances: &[PartialBalance], l: &Locomotive, units: &Units) -> Result<Vec<String>> {
    let (u, f) = (units.length(), units.force());
    let mut notes = vec![format!(
        "Hammer blow of a locomotive's coupled wheel (diameter D = {} {u}, crank r = {} {u}, m = {} {}) at v = {} {u}/s, the wheel turning at ω = 2v/D = {} rad/s: the counterweight's share for the reciprocating parts, c m r, is not cancelled across the line of stroke, and its vertical centrifugal force c m r ω² sin θ loads and unloads the rail once a turn; its largest value c m r ω² is the hammer blow.",
        significant(l.wheel, 6),
        significant(l.crank, 6),
        significant(l.mass, 6),
        units.mass(),
        significant(l.speed, 6),
        significant(2.0 * l.speed / l.wheel, 6),
    )];
    for b in balances {
        let h = HammerBlow::new(b, l.mass, l.crank, l.wheel)?;
        let lifting = match l.load {
            Some(p) => h.lifting_speed(p)?.map(|v| (p, v)),
            None => None,
        };
        let lift = lifting.map_or_else(String::new, |(p, v)| {
            format!(
                "; it equals the wheel's load {} {f} at v = {} {u}/s, where the wheel lifts off the rail",
                significant(p, 6),
                significant(v, 6)
            )
        });
        notes.push(format!(
            "c = {}: hammer blow {} {f}{lift}.",
            written(b.fraction()),
            significant(h.at_speed(l.speed)?, 6)
        ));
    }
    Ok(notes)
}

/// One row at `degrees`: the horizontal, vertical and size of the
/// unbalanced force for each fraction.
pub fn partial_balance_row(
    balances: &[PartialBalance],
    degrees: f64,
    decimals: usize,
) -> Result<Vec<String>> {
    let angle = Angle::from_degrees(degrees)?;
    let mut row = vec![angle_cell(degrees, 1)];
    for b in balances {
        let u = b.at(angle);
        row.extend([u.horizontal, u.vertical, u.magnitude].map(|x| fixed(x, decimals)));
    }
    Ok(row)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_rows_and_notes() {
        let bs: Vec<PartialBalance> = [0.0, 0.5, 1.0]
            .iter()
            .map(|&c| PartialBalance::new(c).unwrap())
            .collect();
        let t = partial_balance_head(&bs, None, &Units::FOOT_POUND).unwrap();
        assert_eq!(t.headers.len(), 10);
        assert_eq!(t.headers[4], "c = 0.5: horizontal");
        assert!(
            t.notes[2].contains("the same at every angle"),
            "{}",
            t.notes[2]
        );
        // At 90°: c = 0 leaves nothing, c = ½ half across, c = 1 all across.
        let row = partial_balance_row(&bs, 90.0, 3).unwrap();
        assert_eq!(
            row,
            [
                "90.0", "0.000", "0.000", "0.000", "0.000", "-0.500", "0.500", "0.000", "-1.000",
                "1.000"
            ]
            .map(String::from)
        );
    }

    #[test]
    fn the_hammer_blow_note() {
        let b = [PartialBalance::new(2.0 / 3.0).unwrap()];
        let l = Locomotive {
            mass: 180.0,
            crank: 0.3,
            wheel: 1.8,
            speed: 25.0,
            load: Some(60_000.0),
        };
        let units = Units::FOOT_POUND
            .with_length("m".parse().unwrap())
            .with_force("N".parse().unwrap());
        let t = partial_balance_head(&b, Some(&l), &units).unwrap();
        // (2/3)(180)(0.3)(50/1.8)² = 27777.8 N; lifts at
        // 0.9 √(60000/36) = 36.7423 m/s.
        let last = t.notes.last().unwrap();
        assert!(last.contains("hammer blow 27777.8 N"), "{last}");
        assert!(last.contains("36.7423 m/s"), "{last}");
    }
}
