//! The gas force on the piston: none, a constant, or an indicator diagram
//! of pressure against the fraction of the stroke.

use crate::csv::Table as DataTable;
use crate::error::{Error, Result, positive};
use crate::mechanism::Pose;

/// Most rows of an indicator diagram.
pub const MAX_INDICATOR_ROWS: usize = 10_000;

/// The gas force on the piston, positive towards the crank centre.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum GasForce {
    /// No gas force (the inertia forces alone).
    None,
    /// The same force at every pose.
    Constant(f64),
    /// Pressure from an indicator diagram times the piston's area.
    Indicator(IndicatorDiagram),
}

impl GasForce {
    /// The force at `pose` for a crank turning at `omega` (its sign says
    /// which stroke the piston is on).
    pub fn at(&self, pose: &Pose, omega: f64) -> f64 {
        match self {
            GasForce::None => 0.0,
            GasForce::Constant(f) => *f,
            GasForce::Indicator(d) => d.force(pose, omega),
        }
    }
}

/// An indicator diagram for a cycle of one turn (a two-stroke engine, or
/// one side of a steam engine's piston): the gauge pressure on the piston
/// against the fraction of the stroke x = (x_outer − x_A) / stroke (0 at
/// the outer dead centre, the cylinder's head end; 1 at the inner), on the
/// expansion stroke (the piston moving towards the crank) and on the
/// compression stroke (moving away), each interpolated linearly between
/// the rows. The force is pressure × bore area π D²/4, positive towards
/// the crank. At a dead centre the two strokes' pressures may differ: OM
/// is zero there and the crank effort stays continuous.
#[derive(Debug, Clone, PartialEq)]
pub struct IndicatorDiagram {
    fractions: Vec<f64>,
    expansion: Vec<f64>,
    compression: Vec<f64>,
    area: f64,
}

impl IndicatorDiagram {
    /// A diagram from its rows and the bore D (area π D²/4).
    ///
    /// Errors: fewer than two rows or more than [`MAX_INDICATOR_ROWS`];
    /// fractions not strictly increasing from exactly 0 to exactly 1; a
    /// value not finite; a bore not positive; a force beyond the largest
    /// number.
    pub fn new(
        fractions: Vec<f64>,
        expansion: Vec<f64>,
        compression: Vec<f64>,
        bore: f64,
    ) -> Result<Self> {
        let bore = positive("bore", bore)?;
        let n = fractions.len();
        if !(2..=MAX_INDICATOR_ROWS).contains(&n) || expansion.len() != n || compression.len() != n
        {
            return Err(Error::Parse(format!(
                "an indicator diagram has 2 to {MAX_INDICATOR_ROWS} rows, each with a fraction and two pressures"
            )));
        }
        if fractions.first() != Some(&0.0)
            || fractions.last() != Some(&1.0)
            || successive(&fractions).any(|(a, b)| a >= b)
        {
            return Err(Error::Parse(
                "the indicator diagram's stroke fractions rise strictly from 0 to 1".into(),
            ));
        }
        let area = std::f64::consts::PI * bore * bore / 4.0;
        for &p in expansion.iter().chain(&compression) {
            let p = crate::error::finite("pressure", p)?;
            if !(p * area).is_finite() {
                return Err(Error::OutOfRange {
                    name: "pressure",
                    value: p,
                    reason: "pressure × bore area exceeds the largest number".into(),
                });
            }
        }
        Ok(Self {
            fractions,
            expansion,
            compression,
            area,
        })
    }

    /// Reads CSV text with the columns `fraction` (or `stroke`),
    /// `expansion` and `compression` (pressures, force per length²), as
    /// the project's data reader does (a header line, `#` comments);
    /// `what` names the source in errors.
    pub fn from_csv(text: &str, bore: f64, what: &str) -> Result<Self> {
        let table = DataTable::parse(text, what)?;
        let col = |names: &[&str]| table.column(names).and_then(|c| table.numbers(c));
        Self::new(
            col(&["fraction", "stroke", "x"])?,
            col(&["expansion", "outward"])?,
            col(&["compression", "return"])?,
            bore,
        )
        .map_err(|e| match e {
            Error::Parse(m) => Error::Parse(format!("{what}: {m}")),
            e => e,
        })
    }

    /// The piston's area π D²/4.
    pub fn area(&self) -> f64 {
        self.area
    }

    /// The stroke fractions of the rows.
    pub fn fractions(&self) -> &[f64] {
        &self.fractions
    }

    /// The pressure at stroke fraction `x` (clamped to 0…1) on the
    /// expansion stroke (`true`) or the compression stroke.
    // cannot fail: `new` holds the three columns to one length n ≥ 2, and
    // i is clamped to 1..=n − 1.
    #[allow(clippy::indexing_slicing)]
    pub fn pressure(&self, x: f64, expansion: bool) -> f64 {
        let p = if expansion {
            &self.expansion
        } else {
            &self.compression
        };
        let x = x.clamp(0.0, 1.0);
        let i = self
            .fractions
            .partition_point(|&f| f <= x)
            .clamp(1, self.fractions.len() - 1);
        let (x0, x1) = (self.fractions[i - 1], self.fractions[i]);
        let t = (x - x0) / (x1 - x0);
        p[i - 1] + (p[i] - p[i - 1]) * t
    }

    /// The work of one cycle, area × stroke × ∮ p dx (the diagram's area,
    /// expansion minus compression, by the trapezoid rule, exact for the
    /// linear pieces).
    pub fn work(&self, stroke: f64) -> f64 {
        let loop_area: f64 = successive(&self.fractions)
            .zip(successive(&self.expansion))
            .zip(successive(&self.compression))
            .map(|(((f0, f1), (e0, e1)), (c0, c1))| {
                let dx = f1 - f0;
                let hi = e1 + e0;
                let lo = c1 + c0;
                0.5 * dx * (hi - lo)
            })
            .sum();
        self.area * stroke * loop_area
    }

    /// The force at `pose`: on the expansion stroke while the piston
    /// moves towards the crank (ω ds/dθ < 0; at rest, while ds/dθ < 0).
    pub fn force(&self, pose: &Pose, omega: f64) -> f64 {
        let m = pose.mechanism();
        let outer = m.pose(m.outer_dead_centre()).position();
        let x = (outer - pose.position()) / m.stroke();
        let direction = if omega < 0.0 { -1.0 } else { 1.0 };
        let expansion = direction * pose.position_rate() < 0.0;
        self.area * self.pressure(x, expansion)
    }
}

/// The pairs of neighbouring values of `v`, in order.
fn successive(v: &[f64]) -> impl Iterator<Item = (f64, f64)> + '_ {
    v.iter().copied().zip(v.iter().copied().skip(1))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_and_interpolates() {
        let d = IndicatorDiagram::from_csv(
            "# a test\nfraction,expansion,compression\n0,10,2\n0.5,4,1\n1,1,0\n",
            2.0,
            "d.csv",
        )
        .unwrap();
        assert_eq!(d.pressure(0.25, true), 7.0);
        assert_eq!(d.pressure(0.75, false), 0.5);
        assert_eq!(d.pressure(1.0, true), 1.0);
        assert!((d.area() - std::f64::consts::PI).abs() < 1e-15);
        // ∮ p dx = (7 + 2.5)/2 … by hand: expansion 0.5·(14/2) + 0.5·(5/2)
        // = 4.75, compression 0.5·1.5 + 0.5·0.5 = 1.0.
        assert!((d.work(3.0) - std::f64::consts::PI * 3.0 * 3.75).abs() < 1e-12);
    }

    #[test]
    fn bad_diagrams_are_refused() {
        let e = IndicatorDiagram::from_csv(
            "fraction,expansion,compression\n0,1,1\n0.5,1,1\n",
            1.0,
            "d.csv",
        )
        .unwrap_err();
        assert!(e.to_string().starts_with("d.csv: the indicator"), "{e}");
        let e =
            IndicatorDiagram::from_csv("fraction,expansion\n0,1\n1,1\n", 1.0, "d.csv").unwrap_err();
        assert!(e.to_string().contains("no column named compression"), "{e}");
        assert!(
            IndicatorDiagram::new(vec![0.0, 1.0], vec![1.0, 1.0], vec![0.0, 0.0], 0.0).is_err()
        );
        assert!(
            IndicatorDiagram::new(vec![0.0, 1.0], vec![1e308, 1.0], vec![0.0, 0.0], 10.0).is_err()
        );
        assert!(
            IndicatorDiagram::new(vec![0.0, 0.0, 1.0], vec![1.0; 3], vec![0.0; 3], 1.0).is_err()
        );
    }
}
