//! The gas force on the piston: none, a constant, or an indicator diagram
//! of pressure against the fraction of the stroke.

use crate::csv::Table as DataTable;
use crate::error::{Error, Field, Input, Result, Wording, positive};
use crate::mechanism::Pose;
use crate::units::Units;

/// The columns a one-turn indicator diagram is read from, with the other
/// names each may go by.
const ONE_TURN: &[&str] = &[
    "fraction",
    "stroke",
    "x",
    "expansion",
    "outward",
    "compression",
    "return",
];

/// The pumping lines' columns of a four-stroke diagram.
const PUMPING: &[&str] = &["exhaust", "intake"];

/// A piston whose ds/dθ is within this fraction of the crank is at rest
/// at a dead centre (within about 1e-12 rad of it), where the stroke that
/// starts there gives the pressure ([`IndicatorDiagram::force_in_turn`]).
const AT_REST: f64 = 1e-12;

/// The example indicator diagram of the turning-moment figure and the
/// handout (`examples/indicator.csv`): steam at 100 psi gauge cut off at
/// 30 % of the stroke, its pressures in lbf/ft², as its header declares.
pub const EXAMPLE_INDICATOR: &str = include_str!("../../examples/indicator.csv");

/// The example engine's bore, 10 in, in feet: the example diagram's
/// cylinder.
pub const EXAMPLE_BORE: f64 = 10.0 / 12.0;

/// The example indicator diagram ([`EXAMPLE_INDICATOR`] on
/// [`EXAMPLE_BORE`]) for an engine in `units`: only in feet and
/// pounds-force, the diagram's own units. Any others are refused in one
/// line that says how to give the engine's own gas force instead, `own`
/// (naming the caller's fields: the diagram with its bore, or a constant
/// force).
pub fn example_indicator(units: &Units, own: Wording) -> Result<IndicatorDiagram> {
    if *units != Units::FOOT_POUND {
        return Err(Error::refused(
            Input::Options,
            Wording::from(format!(
                "the example gas force is the bundled steam indicator diagram, in lbf/ft² on a 10 in bore, for lengths in ft and forces in lbf: in {} and {} give the engine's own, ",
                units.length(),
                units.force()
            ))
            .and(own)
            .then(", in those units"),
        ));
    }
    IndicatorDiagram::from_csv(EXAMPLE_INDICATOR, EXAMPLE_BORE, "examples/indicator.csv")
}

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
    /// which stroke the piston is on), in the first turn of the cycle.
    pub fn at(&self, pose: &Pose, omega: f64) -> f64 {
        self.at_turn(pose, omega, 0)
    }

    /// The force at `pose` in turn `turn` of the cycle (0 or 1 for a
    /// four-stroke diagram; every turn is the same for a one-turn cycle).
    pub fn at_turn(&self, pose: &Pose, omega: f64, turn: usize) -> f64 {
        match self {
            GasForce::None => 0.0,
            GasForce::Constant(f) => *f,
            GasForce::Indicator(d) => d.force_in_turn(pose, omega, turn),
        }
    }

    /// The turns of its cycle: 2 for a four-stroke indicator diagram, else 1.
    pub fn turns(&self) -> usize {
        match self {
            GasForce::Indicator(d) => d.turns(),
            _ => 1,
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
///
/// A four-stroke diagram ([`IndicatorDiagram::with_pumping`]) spans two
/// turns: from the outer dead centre (θ = 0, ω > 0) expansion, exhaust
/// (turn 0), intake, compression (turn 1); the pumping strokes have lines
/// of their own.
#[derive(Debug, Clone, PartialEq)]
pub struct IndicatorDiagram {
    fractions: Vec<f64>,
    expansion: Vec<f64>,
    compression: Vec<f64>,
    /// The exhaust and intake lines of a four-stroke cycle.
    pumping: Option<(Vec<f64>, Vec<f64>)>,
    area: f64,
    /// The unit the CSV's header declares for the pressures, if it does.
    unit: Option<String>,
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
        let bore = positive(Field::Bore, bore)?;
        let n = fractions.len();
        if !(2..=MAX_INDICATOR_ROWS).contains(&n) || expansion.len() != n || compression.len() != n
        {
            return Err(Error::invalid(
                Input::Indicator,
                format!(
                    "an indicator diagram has 2 to {MAX_INDICATOR_ROWS} rows, each with a fraction and two pressures"
                ),
            ));
        }
        if fractions.first() != Some(&0.0)
            || fractions.last() != Some(&1.0)
            || successive(&fractions).any(|(a, b)| a >= b)
        {
            return Err(Error::invalid(
                Input::Indicator,
                "the indicator diagram's stroke fractions rise strictly from 0 to 1".into(),
            ));
        }
        let area = std::f64::consts::PI * bore * bore / 4.0;
        for &p in expansion.iter().chain(&compression) {
            let p = crate::error::finite(Field::Pressure, p)?;
            if !(p * area).is_finite() {
                return Err(Error::OutOfRange {
                    name: Field::Pressure,
                    value: p,
                    reason: "pressure × bore area exceeds the largest number".into(),
                });
            }
        }
        Ok(Self {
            fractions,
            expansion,
            compression,
            pumping: None,
            area,
            unit: None,
        })
    }

    /// The same diagram as a four-stroke cycle of two turns, with the
    /// exhaust and intake lines (pressures at the same fractions).
    ///
    /// Errors: a line of another length than the fractions, a value not
    /// finite, a force beyond the largest number.
    pub fn with_pumping(mut self, exhaust: Vec<f64>, intake: Vec<f64>) -> Result<Self> {
        let n = self.fractions.len();
        if exhaust.len() != n || intake.len() != n {
            return Err(Error::invalid(
                Input::Indicator,
                "the exhaust and intake lines have a pressure at each stroke fraction".into(),
            ));
        }
        let checked = Self::new(self.fractions.clone(), exhaust, intake, 1.0)?;
        for &p in checked.expansion.iter().chain(&checked.compression) {
            if !(p * self.area).is_finite() {
                return Err(Error::OutOfRange {
                    name: Field::Pressure,
                    value: p,
                    reason: "pressure × bore area exceeds the largest number".into(),
                });
            }
        }
        self.pumping = Some((checked.expansion, checked.compression));
        Ok(self)
    }

    /// The turns of the cycle: 2 with the pumping lines (four-stroke),
    /// else 1.
    pub fn turns(&self) -> usize {
        if self.pumping.is_some() { 2 } else { 1 }
    }

    /// Reads a diagram as [`IndicatorDiagram::from_csv`] does, and a
    /// four-stroke one when the CSV also has the columns `exhaust` and
    /// `intake`: the columns say what cycle the data is of.
    ///
    /// Errors: those of `from_csv`; one of the two pumping columns
    /// without the other.
    pub fn from_csv_cycle(text: &str, bore: f64, what: &str) -> Result<Self> {
        let table = DataTable::parse(text, Input::Indicator, what)?;
        table.only(&[ONE_TURN, PUMPING].concat())?;
        let d = Self::from_table(&table, bore, what)?;
        let named = |n: &str| table.column(&[n]).ok();
        match (named("exhaust"), named("intake")) {
            (None, None) => Ok(d),
            (Some(e), Some(i)) => {
                let unit = declared(&table, &pressure_columns(&table, &[e, i]), what)?;
                let mut d = d
                    .with_pumping(table.numbers(e)?, table.numbers(i)?)
                    .map_err(|e| in_source(e, what))?;
                d.unit = unit;
                Ok(d)
            }
            _ => Err(Error::invalid(
                Input::Indicator,
                format!(
                    "{what}: a four-stroke indicator diagram has both an exhaust and an intake column"
                ),
            )),
        }
    }

    /// Reads CSV text with the columns `fraction` (or `stroke`),
    /// `expansion` and `compression` (pressures, force per length²), as
    /// the project's data reader does (a header line, `#` comments);
    /// `what` names the source in errors.
    ///
    /// Errors: a column missing, or one of another name (it would not be
    /// read); those of [`IndicatorDiagram::new`].
    pub fn from_csv(text: &str, bore: f64, what: &str) -> Result<Self> {
        let table = DataTable::parse(text, Input::Indicator, what)?;
        table.only(ONE_TURN)?;
        Self::from_table(&table, bore, what)
    }

    /// The one-turn diagram in `table`'s columns.
    fn from_table(table: &DataTable, bore: f64, what: &str) -> Result<Self> {
        let col = |names: &[&str]| table.column(names).and_then(|c| table.numbers(c));
        let unit = declared(table, &pressure_columns(table, &[]), what)?;
        let mut d = Self::new(
            col(&["fraction", "stroke", "x"])?,
            col(&["expansion", "outward"])?,
            col(&["compression", "return"])?,
            bore,
        )
        .map_err(|e| in_source(e, what))?;
        d.unit = unit;
        Ok(d)
    }

    /// The unit the CSV's header declares for the pressures (`lbf/ft²` of
    /// `expansion (lbf/ft²)`); `None` where no pressure column declares
    /// one, and for a diagram made by [`IndicatorDiagram::new`]: its
    /// pressures are then taken to be in the units they are used with.
    pub fn pressure_unit(&self) -> Option<&str> {
        self.unit.as_deref()
    }

    /// Refuses a diagram whose header declares its pressures in another
    /// unit than `units`' force per length² ([`Units::is_pressure`]):
    /// the crate converts no number, so lbf/ft² on a bore in millimetres
    /// would be nonsense. `what` names the source. A diagram that
    /// declares no unit is taken to be in `units`.
    pub fn check_units(&self, units: &Units, what: &str) -> Result<()> {
        match self.pressure_unit() {
            Some(unit) if !units.is_pressure(unit) => Err(Error::invalid(
                Input::Indicator,
                format!(
                    "{what}: its pressures are in {unit}, but lengths in {} and forces in {} need them in {} (units are names: no number is converted)",
                    units.length(),
                    units.force(),
                    units.pressure()
                ),
            )),
            _ => Ok(()),
        }
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
    pub fn pressure(&self, x: f64, expansion: bool) -> f64 {
        let p = if expansion {
            &self.expansion
        } else {
            &self.compression
        };
        self.interpolate(p, x)
    }

    /// The line `p` at stroke fraction `x` (clamped to 0…1).
    // cannot fail: `new` and `with_pumping` hold every line to the
    // fractions' length n ≥ 2, and i is clamped to 1..=n − 1.
    #[allow(clippy::indexing_slicing)]
    fn interpolate(&self, p: &[f64], x: f64) -> f64 {
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
    /// expansion minus compression, and for a four-stroke cycle intake
    /// minus exhaust, by the trapezoid rule, exact for the linear pieces).
    pub fn work(&self, stroke: f64) -> f64 {
        let mut area = self.loop_area(&self.expansion, &self.compression);
        if let Some((exhaust, intake)) = &self.pumping {
            area += self.loop_area(intake, exhaust);
        }
        self.area * stroke * area
    }

    /// ∫ (out − back) dx over the stroke by the trapezoid rule.
    fn loop_area(&self, out: &[f64], back: &[f64]) -> f64 {
        successive(&self.fractions)
            .zip(successive(out))
            .zip(successive(back))
            .map(|(((f0, f1), (o0, o1)), (b0, b1))| 0.5 * (f1 - f0) * (o1 + o0 - b1 - b0))
            .sum()
    }

    /// The force at `pose` in the first turn: on the expansion stroke
    /// while the piston moves towards the crank (ω ds/dθ < 0) and at the
    /// outer dead centre, where expansion starts
    /// ([`IndicatorDiagram::force_in_turn`]).
    pub fn force(&self, pose: &Pose, omega: f64) -> f64 {
        self.force_in_turn(pose, omega, 0)
    }

    /// The force at `pose` in turn `turn` of the cycle (taken modulo its
    /// turns): towards the crank the expansion line (turn 0) or the
    /// intake (turn 1); away from it the compression line, or for a
    /// four-stroke cycle the exhaust (turn 0).
    ///
    /// At a dead centre (the piston at rest, ds/dθ = 0) the line is that
    /// of the stroke the piston starts there, in the cycle's own order:
    /// the end of compression is the start of expansion (the outer dead
    /// centre of turn 0, firing top dead centre), the end of exhaust the
    /// start of intake (the outer dead centre of turn 1), the end of
    /// expansion the start of exhaust, the end of intake the start of
    /// compression. The piston leaves the outer dead centre towards the
    /// crank and the inner one away from it, whichever way the crank
    /// turns.
    pub fn force_in_turn(&self, pose: &Pose, omega: f64, turn: usize) -> f64 {
        let m = pose.mechanism();
        let outer = m.pose(m.outer_dead_centre()).position();
        let x = (outer - pose.position()) / m.stroke();
        let direction = if omega < 0.0 { -1.0 } else { 1.0 };
        let rate = pose.position_rate();
        let towards = if rate.abs() <= AT_REST * m.crank() {
            // At rest: s is greatest at the outer dead centre (s'' < 0),
            // so the stroke that starts there runs towards the crank.
            pose.position_acceleration() < 0.0
        } else {
            direction * rate < 0.0
        };
        let line = match (&self.pumping, turn % self.turns(), towards) {
            (_, 0, true) => &self.expansion,
            (Some((exhaust, _)), 0, false) => exhaust,
            (Some((_, intake)), _, true) => intake,
            _ => &self.compression,
        };
        self.area * self.interpolate(line, x)
    }
}

/// The pressure columns of `table` (expansion and compression, and
/// `extra`, the pumping lines' columns where they are read).
fn pressure_columns(table: &DataTable, extra: &[usize]) -> Vec<usize> {
    let mut columns: Vec<usize> = [&["expansion", "outward"][..], &["compression", "return"]]
        .iter()
        .filter_map(|names| table.column(names).ok())
        .collect();
    columns.extend_from_slice(extra);
    columns
}

/// The unit the `columns` of `table` declare: the one unit of those that
/// declare one, `None` where none does.
///
/// Errors: two columns declaring different units.
fn declared(table: &DataTable, columns: &[usize], what: &str) -> Result<Option<String>> {
    let mut found: Option<(usize, &str)> = None;
    for &c in columns {
        match (found, table.unit(c)) {
            (None, Some(u)) => found = Some((c, u)),
            (Some((first, u0)), Some(u)) if u != u0 => {
                return Err(Error::invalid(
                    Input::Indicator,
                    format!(
                        "{what}: the column {} is in {u0} but {} is in {u}: give every pressure in one unit",
                        table.name(first),
                        table.name(c)
                    ),
                ));
            }
            _ => {}
        }
    }
    Ok(found.map(|(_, u)| u.to_string()))
}

/// `e` with `what` (the source's name) before its message when it is an
/// [`Error::Invalid`]; other errors name their value already.
fn in_source(e: Error, what: &str) -> Error {
    match e {
        Error::Invalid { input, message } => {
            Error::refused(input, Wording::from(format!("{what}: ")).and(message))
        }
        e => e,
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
    fn the_example_is_for_feet_and_pounds_only() {
        let d = example_indicator(&Units::FOOT_POUND, Wording::default()).unwrap();
        assert!(
            (d.area() - std::f64::consts::PI * EXAMPLE_BORE * EXAMPLE_BORE / 4.0).abs() < 1e-15
        );
        let own = Wording::default().set(crate::error::Field::GasForce, "F");
        let e = example_indicator(&Units::MILLIMETRE_NEWTON, own)
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("in mm and N give the engine's own, `gas_force = F`, in those units"),
            "{e}"
        );
    }

    #[test]
    fn a_declared_unit_is_kept_and_checked() {
        let bundled = include_str!("../../examples/indicator.csv");
        let d = IndicatorDiagram::from_csv(bundled, 10.0 / 12.0, "x").unwrap();
        assert_eq!(d.pressure_unit(), Some("lbf/ft²"));
        assert!(d.check_units(&Units::FOOT_POUND, "x").is_ok());
        let e = d
            .check_units(&Units::MILLIMETRE_NEWTON, "indicator diagram x")
            .unwrap_err()
            .to_string();
        assert!(
            e.starts_with("indicator diagram x: its pressures are in lbf/ft², but lengths in mm and forces in N need them in N/mm²"),
            "{e}"
        );
        assert!(!e.contains('\n'));
        // Undeclared: taken in the units it is used with.
        let plain = "fraction,expansion,compression\n0,1,0\n1,1,0\n";
        let d = IndicatorDiagram::from_csv(plain, 1.0, "x").unwrap();
        assert_eq!(d.pressure_unit(), None);
        assert!(d.check_units(&Units::MILLIMETRE_NEWTON, "x").is_ok());
        // One column declared is the diagram's unit; two that differ are refused.
        let one = "fraction,expansion (MPa),compression\n0,1,0\n1,1,0\n";
        let d = IndicatorDiagram::from_csv(one, 1.0, "x").unwrap();
        assert_eq!(d.pressure_unit(), Some("MPa"));
        assert!(d.check_units(&Units::MILLIMETRE_NEWTON, "x").is_ok());
        let two = "fraction,expansion (MPa),compression (bar)\n0,1,0\n1,1,0\n";
        let e = IndicatorDiagram::from_csv(two, 1.0, "x")
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("expansion is in MPa but compression is in bar"),
            "{e}"
        );
        let four = "fraction,expansion (MPa),compression (MPa),exhaust (MPa),intake (psi)\n0,1,0,0,0\n1,1,0,0,0\n";
        let e = IndicatorDiagram::from_csv_cycle(four, 1.0, "x")
            .unwrap_err()
            .to_string();
        assert!(e.contains("is in psi"), "{e}");
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
        // A column the reader would pass over is named, not ignored.
        let six = "fraction,expansion,compression,exhaust,intake,extra\n0,9,1,1,0,5\n1,2,1,1,0,5\n";
        let e = IndicatorDiagram::from_csv_cycle(six, 1.0, "d.csv").unwrap_err();
        assert!(e.to_string().contains("\"extra\""), "{e}");
        let five = six.replace(",extra", "").replace(",5\n", "\n");
        assert_eq!(
            IndicatorDiagram::from_csv_cycle(&five, 1.0, "d.csv")
                .unwrap()
                .turns(),
            2
        );
        let e = IndicatorDiagram::from_csv(&five, 1.0, "d.csv").unwrap_err();
        assert!(e.to_string().contains("\"exhaust\""), "{e}");
        let e = IndicatorDiagram::from_csv(
            "fraction,expansion,compression,p\u{202e}\n0,1,1,1\n1,1,1,1\n",
            1.0,
            "d.csv",
        )
        .unwrap_err();
        assert!(e.to_string().contains("\\u{202e}"), "{e}");
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
