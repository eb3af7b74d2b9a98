//! The drawing scale of an exercise sheet: the drawing printed at a round
//! scale (1:4, not about 1:3.5) that the sheet states, so that a student
//! measuring with a ruler knows what a millimetre on the paper stands for.

use super::Paper;

/// The round scales a sheet is drawn at, per decade: 1:1, 1:1.5, 1:2 …
/// 1:8, then 1:10 and so on (and 2:1, 5:1 … for a small engine).
const ROUND: [f64; 9] = [1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0];

/// Millimetres in one of a length unit, for the units the scale can be
/// stated in; `None` for a name that is not a length the crate knows.
fn millimetres(unit: &str) -> Option<f64> {
    match unit {
        "mm" => Some(1.0),
        "cm" => Some(10.0),
        "dm" => Some(100.0),
        "m" => Some(1000.0),
        "in" => Some(25.4),
        "ft" => Some(304.8),
        "yd" => Some(914.4),
        _ => None,
    }
}

/// The width of the printable page, mm (the handout's margins are 15 mm
/// each side).
pub(super) fn printable_width(paper: Paper) -> f64 {
    match paper {
        Paper::A4 => 210.0 - 30.0,
        Paper::Letter => 215.9 - 30.0,
    }
}

/// A drawing printed at a round scale.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Scale {
    /// The printed width of the whole figure, mm.
    pub width_mm: f64,
    /// The scale as the sheet states it: `1:4`, `2:1`.
    pub ratio: String,
}

/// The round scale at which a figure `width` page units wide, whose
/// drawing has `per_unit` page units per unit of `unit`, fits across
/// `paper` largest: the scale it would print at full width, made smaller
/// to the next [`ROUND`] one. `None` for a unit that is not a known length
/// or a degenerate figure.
pub(super) fn round_scale(width: f64, per_unit: f64, unit: &str, paper: Paper) -> Option<Scale> {
    let unit_mm = millimetres(unit)?;
    let full = printable_width(paper);
    // Paper millimetres per engine millimetre at full width.
    let at_full = per_unit * full / width / unit_mm;
    if !(at_full.is_finite() && at_full > 0.0) {
        return None;
    }
    // The reduction 1:q with q ≥ 1/at_full, q the next round number.
    let q = 1.0 / at_full;
    let decade = 10f64.powf(q.log10().floor());
    let round = ROUND
        .iter()
        .chain(&[10.0])
        .map(|m| m * decade)
        .find(|&r| r >= q * (1.0 - 1e-12))?;
    let ratio = if round >= 1.0 {
        format!("1:{}", crate::number::plain(round))
    } else {
        format!("{}:1", crate::number::plain(1.0 / round))
    };
    Some(Scale {
        width_mm: full * q / round,
        ratio,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_scale_is_the_next_round_one_down() {
        // 760 page units across, 2 units per mm: at 180 mm the drawing is
        // at 180/380 = 1:2.11, so 1:2.5, printed 180 · 2.11/2.5 wide.
        let s = round_scale(760.0, 2.0, "mm", Paper::A4).unwrap();
        assert_eq!(s.ratio, "1:2.5");
        assert!((s.width_mm - 180.0 * (380.0 / 180.0) / 2.5).abs() < 1e-9);
        // Drawn to that width, 1 mm of the engine is 0.4 mm of paper.
        assert!((s.width_mm / 760.0 * 2.0 - 0.4).abs() < 1e-12);
        // A round scale at full width stays.
        let s = round_scale(760.0, 760.0 / 720.0, "mm", Paper::A4).unwrap();
        assert_eq!(s.ratio, "1:4");
        assert!((s.width_mm - 180.0).abs() < 1e-9);
        // Feet: 1 ft = 304.8 mm.
        let s = round_scale(760.0, 200.0, "ft", Paper::Letter).unwrap();
        assert!(s.ratio.starts_with("1:"), "{}", s.ratio);
        assert!(s.width_mm <= 185.9);
        // A tiny engine is enlarged: 2:1, 5:1.
        let s = round_scale(760.0, 760.0 / 40.0, "mm", Paper::A4).unwrap();
        assert_eq!(s.ratio, "4:1");
        assert!(round_scale(760.0, 2.0, "cubit", Paper::A4).is_none());
        assert!(round_scale(760.0, 0.0, "mm", Paper::A4).is_none());
    }
}
