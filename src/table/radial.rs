//! `table radial`: the primary and secondary forces of cylinders on one
//! crank (a V engine, a radial engine) against θ, in size and direction,
//! with the direct and reverse cranks as notes.

use super::Table;
use crate::angle::Angle;
use crate::dynamics::{RadialEngine, Resultant};
use crate::error::Result;
use crate::number::{angle_cell, fixed, plain, significant};

/// A direction in degrees from the reference line, or `–` for a force
/// below the rounding of its cylinders' sum (no direction).
fn direction(v: [f64; 2], cylinders: usize, decimals: usize) -> String {
    if v[0].hypot(v[1]) <= 1e-12 * cylinders as f64 {
        "–".into()
    } else {
        fixed(
            (v[1] + 0.0).atan2(v[0] + 0.0).to_degrees() + 0.0,
            decimals.min(4),
        )
    }
}

/// The note of one crank: balanced, or its size and its angle at θ = 0
/// and how it turns.
fn crank_note(name: &str, r: &Resultant, turning: &str) -> String {
    if r.balanced {
        format!("{name}: balanced (the cylinders' cranks cancel).")
    } else {
        format!(
            "{name}: {} m r ω², at {}° at θ = 0, turning at {turning}.",
            significant(r.amplitude, 6),
            fixed(
                (r.vector[1] + 0.0).atan2(r.vector[0] + 0.0).to_degrees() + 0.0,
                2
            )
        )
    }
}

/// The title, headers and notes of the table of `engine`; values per
/// unit m r ω².
pub fn radial_head(engine: &RadialEngine) -> Table {
    let axes = engine.axes_deg();
    let k = axes.len();
    let list = axes
        .iter()
        .map(|x| plain(*x))
        .collect::<Vec<_>>()
        .join(", ");
    let kind = match axes {
        [a, b] => {
            let apart = (b - a).rem_euclid(360.0);
            let included = apart.min(360.0 - apart);
            format!("A V engine of two banks {}° apart", plain(included))
        }
        _ => format!("{k} cylinder{} on one crank", if k == 1 { "" } else { "s" }),
    };
    let notes = vec![
        format!(
            "{kind}: axes at {list}° from the reference line x, the crank angle θ from it (cylinder i's crank at θ − β_i); every cylinder's reciprocating mass m, crank r and n = {}. Values ÷ m r ω², x along the reference line, y across it; each cylinder's force m r ω² (cos(θ − β_i) + cos 2(θ − β_i)/n) along its own axis, summed; exact: every cylinder's −m a along its axis (all harmonics). Direct and reverse cranks (values at θ = 0):",
            plain(engine.ratio())
        ),
        format!(
            "Primary direct crank: {} m r ω² along the crank, turning with it at ω: a counterweight of {} m at the crank radius opposite the crank balances it.",
            significant(engine.primary_direct.amplitude, 6),
            significant(engine.primary_direct.amplitude, 6)
        ),
        crank_note("Primary reverse crank", &engine.primary_reverse, "−ω"),
        crank_note("Secondary direct crank", &engine.secondary_direct, "2ω"),
        crank_note("Secondary reverse crank", &engine.secondary_reverse, "−2ω"),
        if engine.primary_reverse.balanced {
            "The primary force is the direct crank alone: constant in size, turning with the crank, balanced by the counterweight.".into()
        } else {
            "The primary force changes in size over the turn: a counterweight balances its direct crank only.".into()
        },
    ];
    Table {
        title: format!(
            "Primary and secondary forces of {} cylinders on one crank",
            k
        ),
        headers: [
            "θ (°)",
            "primary x",
            "primary y",
            "primary size",
            "primary direction (°)",
            "secondary x",
            "secondary y",
            "secondary size",
            "secondary direction (°)",
            "exact x",
            "exact y",
        ]
        .map(String::from)
        .to_vec(),
        rows: vec![],
        notes,
    }
}

/// One row at `degrees`.
pub fn radial_row(engine: &RadialEngine, degrees: f64, decimals: usize) -> Result<Vec<String>> {
    let angle = Angle::from_degrees(degrees)?;
    let k = engine.axes_deg().len();
    let p = engine.primary_at(angle);
    let s = engine.secondary_at(angle);
    let x = engine.exact_at(angle)?;
    let f = |v: f64| fixed(v, decimals);
    Ok(vec![
        angle_cell(degrees, 1),
        f(p[0]),
        f(p[1]),
        f(p[0].hypot(p[1])),
        direction(p, k, decimals),
        f(s[0]),
        f(s[1]),
        f(s[0].hypot(s[1])),
        direction(s, k, decimals),
        f(x[0]),
        f(x[1]),
    ])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_v_twin_table() {
        let e = RadialEngine::new(&[-45.0, 45.0], 4.0).unwrap();
        let t = radial_head(&e);
        assert!(
            t.notes[0].starts_with("A V engine of two banks 90° apart"),
            "{}",
            t.notes[0]
        );
        assert_eq!(
            t.notes[2],
            "Primary reverse crank: balanced (the cylinders' cranks cancel)."
        );
        assert!(t.notes[5].contains("constant in size"));
        // At 30°: the primary force is 1 along the crank, at 30°; the
        // secondary √2 sin 60° / 4 = 0.3062 across.
        let row = radial_row(&e, 30.0, 4).unwrap();
        assert_eq!(
            &row[1..6],
            ["0.8660", "0.5000", "1.0000", "30.0000", "0.0000"]
        );
        assert_eq!(row[6], "0.3062");
    }
}
