//! `table balance`: the unbalanced primary and secondary forces and
//! couples of an in-line engine against θ, with the polygons' resultants
//! and the verdict as notes.

use super::Table;
use crate::angle::Angle;
use crate::dynamics::{InlineEngine, Resultant};
use crate::error::Result;
use crate::number::{angle_cell, fixed, plain, significant};
use crate::units::Units;

/// The title, headers and notes of the balance table of `engine`; values
/// per unit m r ω² (couples times the length unit of the planes).
pub fn balance_head(engine: &InlineEngine, units: &Units) -> Table {
    let u = units.length();
    let cylinders = engine.cranks_deg().len();
    let list = |v: &[f64]| v.iter().map(|x| plain(*x)).collect::<Vec<_>>().join(", ");
    let part = |name: &str, r: &Resultant, per: &str| {
        if r.balanced {
            format!("{name}: balanced (its polygon closes).")
        } else {
            let direction = r.vector[1].atan2(r.vector[0]).to_degrees();
            format!(
                "{name}: unbalanced, at most {} m r ω²{per}, its resultant at {}° from the first crank at θ = 0.",
                significant(r.amplitude, 6),
                fixed(direction + 0.0, 2)
            )
        }
    };
    let per = format!(" {u}");
    let notes = vec![
        format!(
            "{cylinders} cylinder{} in line, cranks at {}° ahead of the first, their lines of stroke at {} {u} from the reference plane; every cylinder's reciprocating mass m, crank r and n = l/r; values ÷ m r ω², couples in {u} (÷ m r ω²). Primary: m r ω² cos θ a cylinder; secondary: m r ω² cos 2θ / n; exact: the inertia force −m a of every cylinder summed (its harmonics beyond the second are O(1/n³)).",
            if cylinders == 1 { "" } else { "s" },
            list(engine.cranks_deg()),
            list(engine.planes()),
        ),
        part("Primary force", &engine.primary_force, ""),
        part("Primary couple", &engine.primary_couple, &per),
        part("Secondary force", &engine.secondary_force, ""),
        part("Secondary couple", &engine.secondary_couple, &per),
        if engine.is_balanced() {
            "The engine is balanced for primary and secondary forces and couples.".into()
        } else {
            "The engine is not balanced: what is left is above.".into()
        },
    ];
    Table {
        title: format!(
            "Balance of an in-line engine of {cylinders} cylinder{}",
            if cylinders == 1 { "" } else { "s" }
        ),
        headers: vec![
            "θ (°)".into(),
            "primary force".into(),
            "secondary force".into(),
            format!("primary couple ({u})"),
            format!("secondary couple ({u})"),
            "exact force".into(),
        ],
        rows: vec![],
        notes,
    }
}

/// One row of the balance table at `degrees` (the first cylinder's crank
/// angle).
pub fn balance_row(engine: &InlineEngine, degrees: f64, decimals: usize) -> Result<Vec<String>> {
    let angle = Angle::from_degrees(degrees)?;
    let (p, s) = engine.forces_at(angle);
    let (pc, sc) = engine.couples_at(angle);
    Ok(vec![
        angle_cell(degrees, 1),
        fixed(p, decimals),
        fixed(s, decimals),
        fixed(pc, decimals),
        fixed(sc, decimals),
        fixed(engine.exact_force(angle)?, decimals),
    ])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_notes_give_each_part_and_the_verdict() {
        let four =
            InlineEngine::new(&[0.0, 180.0, 180.0, 0.0], &[-1.5, -0.5, 0.5, 1.5], 4.0).unwrap();
        let t = balance_head(&four, &Units::FOOT_POUND);
        assert_eq!(t.notes[1], "Primary force: balanced (its polygon closes).");
        assert_eq!(t.notes[2], "Primary couple: balanced (its polygon closes).");
        assert_eq!(
            t.notes[3],
            "Secondary force: unbalanced, at most 1.00000 m r ω², its resultant at 0.00° from the first crank at θ = 0."
        );
        assert!(t.notes[5].starts_with("The engine is not balanced"));
        // At θ = 0 every secondary force adds: 4 cos 0 / n = 1.
        let row = balance_row(&four, 0.0, 4).unwrap();
        assert_eq!(
            row,
            ["0.0", "0.0000", "1.0000", "0.0000", "0.0000", "1.0000"].map(String::from)
        );
    }
}
