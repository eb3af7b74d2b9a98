//! The printed tables: the textbook's obliquity and acceleration-factor
//! tables, kinematics sweeps and Ng's Table 2, in text, Markdown or CSV.

mod analyze;
mod balance;
mod chain_json;
mod check_report;
mod check_request;
mod dynamics;
mod dynamics_json;
mod engine;
mod guard;
mod harmonics;
mod partial;
mod quick_return;
mod radial;
mod reading_json;
mod request;

use crate::analytic::approx::acceleration_factor;
use crate::analytic::kinematics::Kinematics;
use crate::analytic::statics::{Friction, slider_force, with_friction};
use crate::angle::Angle;
use crate::error::{Error, Field, Input, Result};
use crate::mechanism::SliderCrank;
pub use crate::number::fixed;
use crate::number::{angle_cell, plain};
use crate::sources::{ENGINE_35, NG_RIG, RPM};
use crate::units::Units;
pub use analyze::{
    Analysis, AnalysisJson, AnalyzePlan, AnalyzeRequest, DEFAULT_ANGLE, EngineAnalysis,
    STATICS_VALUES, VALUES_PER_ANGLE,
};
pub use balance::{balance_head, balance_row};
pub use chain_json::{
    CHAIN_TOLERANCE, centre_json, chain_check_report, coriolis_check_title, grashof_name,
    inversion_json, quadric_check_title, quadric_json, slot_check_title, slot_json,
};
pub use check_report::{DEFAULT_ULPS, MAX_TOLERANCE, check_allowance, engine_check_report};
pub use check_request::{CheckOutcome, CheckPlan, CheckRequest, CheckRows, DEFAULT_SAMPLES};
pub use dynamics::{dynamics_head, dynamics_row, example_table};
pub use dynamics_json::{dynamics_json, mass_unit};
pub use engine::GivenEngine;
pub use guard::{DEFAULT_MAX_CELLS, MaxCells};
pub use harmonics::harmonics_table;
pub use partial::{Locomotive, partial_balance_head, partial_balance_row};
pub use quick_return::{quick_return_head, quick_return_row};
pub use radial::{radial_head, radial_row};
pub use reading_json::ReadingJson;
pub use request::{TablePlan, TableRequest};

/// The textbook's n columns of the acceleration-factor table (∞ last).
pub const TEXTBOOK_RATIOS: [f64; 6] = [4.0, 4.5, 5.0, 5.5, 6.0, f64::INFINITY];

/// The textbook's θ rows of the acceleration-factor table, degrees.
pub const TEXTBOOK_ANGLES: [f64; 7] = [0.0, 30.0, 60.0, 90.0, 120.0, 150.0, 180.0];

/// Output format of a table.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum Format {
    /// Aligned columns for a terminal.
    Text,
    /// A GitHub-flavoured Markdown table.
    Markdown,
    /// Comma-separated values with a header row.
    Csv,
}

crate::error::parse_by_name!(Format, TableName);

impl Format {
    /// The name on the command line: `text`, `markdown`, `csv`.
    pub fn name(&self) -> &'static str {
        match self {
            Format::Text => "text",
            Format::Markdown => "markdown",
            Format::Csv => "csv",
        }
    }

    /// The format of that name; the error lists the names.
    pub fn from_name(name: &str) -> Result<Self> {
        [Format::Text, Format::Markdown, Format::Csv]
            .into_iter()
            .find(|f| f.name() == name)
            .ok_or_else(|| {
                Error::invalid(
                    Input::TableFormat,
                    format!("unknown format '{name}': expected text, markdown or csv"),
                )
            })
    }
}

/// A table of formatted cells with a title and notes.
#[derive(Debug, Clone, PartialEq)]
pub struct Table {
    /// What the table shows.
    pub title: String,
    /// Column headers.
    pub headers: Vec<String>,
    /// Rows of cells, as printed.
    pub rows: Vec<Vec<String>>,
    /// Notes printed under the table (text and Markdown only).
    pub notes: Vec<String>,
}

/// A value in a title or note: six significant figures.
fn sig(x: f64) -> String {
    crate::number::significant(x, 6)
}

fn ratio_label(n: f64) -> String {
    if n.is_infinite() {
        "∞".into()
    } else if n >= 1e15 {
        format!("{n:e}")
    } else {
        format!("{n}")
    }
}

/// A root of the obliquity table: 2 decimals as printed in §35, exponent
/// form beyond 1e15, ∞ for the infinitely long rod.
fn root_label(x: f64) -> String {
    if x.is_infinite() {
        "∞".into()
    } else if x >= 1e15 {
        format!("{x:.2e}")
    } else {
        fixed(x, 2)
    }
}

impl Table {
    /// Renders the table.
    pub fn render(&self, format: Format) -> String {
        let mut out = String::new();
        let rows = || self.rows.iter().cloned().map(Ok);
        let head = Head {
            title: &self.title,
            headers: &self.headers,
            notes: &self.notes,
        };
        // Rows held in memory cannot fail.
        let _ = render_rows(format, &head, rows, &mut |s| {
            out.push_str(s);
            Ok(())
        });
        out
    }
}

/// What a table says around its rows.
#[derive(Debug, Clone, Copy)]
pub struct Head<'a> {
    /// What the table shows.
    pub title: &'a str,
    /// Column headers.
    pub headers: &'a [String],
    /// Notes printed under the table (in CSV as `#` comment lines).
    pub notes: &'a [String],
}

/// A CSV record (RFC 4180): a cell with a comma, a quote or a line break
/// is quoted, its quotes doubled.
fn csv_line(cells: &[String]) -> String {
    let quoted: Vec<String> = cells
        .iter()
        .map(|c| {
            if c.contains([',', '"', '\n', '\r']) {
                format!("\"{}\"", c.replace('"', "\"\""))
            } else {
                c.clone()
            }
        })
        .collect();
    quoted.join(",") + "\n"
}

fn text_line(cells: &[String], width: &[usize]) -> String {
    let mut line = String::with_capacity(width.iter().sum::<usize>() + 2 * width.len() + 1);
    for (i, (c, w)) in cells.iter().zip(width).enumerate() {
        let pad = w.saturating_sub(c.chars().count());
        if i == 0 {
            line.push_str(c);
            line.extend(std::iter::repeat_n(' ', pad));
        } else {
            line.push_str("  ");
            line.extend(std::iter::repeat_n(' ', pad));
            line.push_str(c);
        }
    }
    line.truncate(line.trim_end().len());
    line.push('\n');
    line
}

/// Writes a table whose rows are computed as they are written, so that
/// memory does not grow with the number of rows: `rows` makes a fresh
/// iterator of the rows each time it is called. It is called twice: a
/// first pass finds the column widths and any error, so that nothing is
/// written when a row fails; the second pass writes, one row at a time,
/// through `out`.
pub fn render_rows<I>(
    format: Format,
    head: &Head,
    rows: impl Fn() -> I,
    out: &mut dyn FnMut(&str) -> Result<()>,
) -> Result<()>
where
    I: Iterator<Item = Result<Vec<String>>>,
{
    let mut width = header_widths(head);
    for row in rows() {
        widen(&mut width, &row?);
    }
    out(&head_text(format, head, &width))?;
    let mut line = String::new();
    for row in rows() {
        line.clear();
        push_row(format, &row?, &width, &mut line);
        out(&line)?;
    }
    out(&tail_text(format, head))
}

/// The width of each column from its header alone, in characters (text
/// tables pad the cells to the widest of a column).
pub fn header_widths(head: &Head) -> Vec<usize> {
    head.headers.iter().map(|h| h.chars().count()).collect()
}

/// `widths` made wide enough for the cells of `row`; a row with more cells
/// than there are widths adds none.
pub fn widen(widths: &mut [usize], row: &[String]) {
    for (w, c) in widths.iter_mut().zip(row) {
        *w = (*w).max(c.chars().count());
    }
}

/// What a table prints above its rows: the CSV header line; the Markdown
/// title and header rows; the text title and headers padded to `widths`.
pub fn head_text(format: Format, head: &Head, widths: &[usize]) -> String {
    match format {
        Format::Csv => csv_line(head.headers),
        Format::Markdown => format!(
            "**{}**\n\n| {} |\n|{}\n",
            head.title,
            head.headers.join(" | "),
            "---|".repeat(head.headers.len())
        ),
        Format::Text => format!("{}\n\n{}", head.title, text_line(head.headers, widths)),
    }
}

/// The line of `row` in `format` (text padded to `widths`), pushed onto
/// `text`.
pub fn push_row(format: Format, row: &[String], widths: &[usize], text: &mut String) {
    match format {
        Format::Csv => text.push_str(&csv_line(row)),
        Format::Markdown => {
            text.push_str("| ");
            text.push_str(&row.join(" | "));
            text.push_str(" |\n");
        }
        Format::Text => text.push_str(&text_line(row, widths)),
    }
}

/// What a table prints below its rows: its notes; in CSV as comment
/// lines, each `# ` and a note (readers skip them with pandas'
/// `comment="#"`, numpy's default `comments="#"`, and this crate's own
/// data reader).
pub fn tail_text(format: Format, head: &Head) -> String {
    match format {
        Format::Csv => head
            .notes
            .iter()
            .flat_map(|n| n.lines())
            .map(|n| format!("# {n}\n"))
            .collect(),
        Format::Markdown => head.notes.iter().map(|n| format!("\n{n}\n")).collect(),
        Format::Text if head.notes.is_empty() => String::new(),
        Format::Text => {
            let mut text: String = head.notes.iter().map(|n| format!("\n{n}")).collect();
            text.push('\n');
            text
        }
    }
}

fn check_ratios(ratios: &[f64]) -> Result<()> {
    for &n in ratios {
        if n.is_nan() || n <= 1.0 {
            return Err(Error::OutOfRange {
                name: Field::Ratio,
                value: n,
                reason: "the rod must be longer than the crank, n = l/r > 1".into(),
            });
        }
    }
    Ok(())
}

/// √(n² − sin²θ) and the error due to obliquity √(n² − sin²θ) − n, in
/// crank radii, for n > 1 and s = sin θ: computed as n √((1 − s/n)(1 + s/n))
/// so that no n up to the largest f64 overflows, and the error as
/// −(s/n) s/(root/n + 1) without cancellation or overflow. n = ∞ gives (∞, 0), the infinitely
/// long rod.
pub fn obliquity_error(n: f64, s: f64) -> (f64, f64) {
    if n.is_infinite() {
        return (f64::INFINITY, 0.0);
    }
    let q = s / n;
    let unit = ((1.0 - q) * (1.0 + q)).sqrt();
    (n * unit, -q * s / (unit + 1.0))
}

/// The textbook's error due to obliquity at θ (default 90°): rows n,
/// √(n² − sin²θ) and √(n² − sin²θ) − n (in crank radii), 2 decimals as
/// printed in §35.
pub fn obliquity(ratios: &[f64], theta_degrees: f64) -> Result<Table> {
    check_ratios(ratios)?;
    let a = Angle::from_degrees(theta_degrees)?;
    let s = a.sin();
    let mut rows = Vec::new();
    for &n in ratios {
        let (root, err) = obliquity_error(n, s);
        rows.push(vec![ratio_label(n), root_label(root), fixed(err, 2)]);
    }
    Ok(Table {
        title: format!(
            "Error due to obliquity at θ = {}°, in crank radii (textbook §35)",
            plain(theta_degrees)
        ),
        headers: vec![
            "n".into(),
            "√(n² − sin²θ)".into(),
            "√(n² − sin²θ) − n".into(),
        ],
        rows,
        notes: vec![],
    })
}

/// The head of the obliquity table over the angles from `first`: over
/// `several` angles its title names none and a θ column comes first, each
/// row naming its own angle ([`obliquity_rows`]); over one, [`obliquity`]'s.
///
/// Errors: those of [`obliquity`].
pub fn obliquity_head(ratios: &[f64], first: f64, several: bool) -> Result<Table> {
    let mut head = obliquity(ratios, first)?;
    if several {
        head.title = "Error due to obliquity, in crank radii (textbook §35)".into();
        head.headers.insert(0, "θ (°)".into());
    }
    Ok(head)
}

/// The obliquity table's rows at `degrees`, each led by its θ where the
/// table runs over `several` angles ([`obliquity_head`]).
///
/// Errors: those of [`obliquity`].
pub fn obliquity_rows(ratios: &[f64], degrees: f64, several: bool) -> Result<Vec<Vec<String>>> {
    let mut rows = obliquity(ratios, degrees)?.rows;
    if several {
        for row in &mut rows {
            row.insert(0, angle_cell(degrees, 1));
        }
    }
    Ok(rows)
}

/// Values of cos θ + cos 2θ / n (textbook §35, eq. 3), 3 decimals; rows
/// labelled "θ or 360° − θ" as printed.
pub fn acceleration_factor_table(ratios: &[f64], angles: &[f64]) -> Result<Table> {
    check_ratios(ratios)?;
    let mut rows = Vec::new();
    for &d in angles {
        let a = Angle::from_degrees(d)?;
        // `plain`: 1e308° in exponent form, not 309 digits.
        let label = if d == 0.0 {
            "0° or 360°".to_string()
        } else if a.degrees() == 180.0 || d == 180.0 {
            format!("{}°", plain(d))
        } else if (0.0..180.0).contains(&d) {
            format!("{}° or {}°", plain(d), plain(360.0 - d))
        } else {
            format!("{}°", plain(d))
        };
        let mut row = vec![label];
        for &n in ratios {
            row.push(fixed(acceleration_factor(a.sin(), a.cos(), n), 3));
        }
        rows.push(row);
    }
    let mut headers = vec!["θ".to_string()];
    headers.extend(ratios.iter().map(|&n| format!("n = {}", ratio_label(n))));
    Ok(Table {
        title: "Values of (cos θ + cos 2θ / n), textbook §35".into(),
        headers,
        rows,
        notes: vec![],
    })
}

/// A θ sweep of the slider's position, velocity and acceleration and the
/// rod's angle and rates, for crank speed `omega` (rad/s), the lengths
/// named in `units` (headers `x_A (ft)`, `dx/dt (ft/s)`).
pub fn kinematics(
    mechanism: &SliderCrank,
    omega: f64,
    angles: &[f64],
    decimals: usize,
    units: &Units,
) -> Result<Table> {
    let rows = angles
        .iter()
        .map(|&d| kinematics_row(mechanism, omega, d, decimals))
        .collect::<Result<Vec<_>>>()?;
    Ok(Table {
        rows,
        ..kinematics_head(mechanism, omega, units)
    })
}

/// One row of [`kinematics`], at `degrees`.
pub fn kinematics_row(
    mechanism: &SliderCrank,
    omega: f64,
    degrees: f64,
    decimals: usize,
) -> Result<Vec<String>> {
    let pose = mechanism.pose(Angle::from_degrees(degrees)?);
    let k = Kinematics::new(&pose, omega)?;
    Ok(vec![
        angle_cell(degrees, 1),
        fixed(k.position, decimals),
        fixed(k.velocity, decimals),
        fixed(k.acceleration, decimals),
        fixed(k.rod_angle.to_degrees(), decimals),
        fixed(k.rod_angular_velocity, decimals),
        fixed(k.rod_angular_acceleration, decimals),
    ])
}

/// The title and headers of [`kinematics`], without rows.
pub fn kinematics_head(mechanism: &SliderCrank, omega: f64, units: &Units) -> Table {
    let u = units.length();
    Table {
        title: format!(
            "Kinematics: r = {} {u}, l = {} {u}, e = {} {u}, {} rpm (ω = {} rad/s)",
            plain(mechanism.crank()),
            plain(mechanism.rod()),
            plain(mechanism.offset()),
            crate::number::short(omega * 60.0 / std::f64::consts::TAU),
            crate::number::sig(omega)
        ),
        headers: vec![
            "θ (°)".into(),
            format!("x_A ({u})"),
            format!("dx/dt ({})", units.velocity()),
            format!("d²x/dt² ({})", units.acceleration()),
            "φ (°)".into(),
            "dφ/dt (rad/s)".into(),
            "d²φ/dt² (rad/s²)".into(),
        ],
        rows: vec![],
        notes: vec![],
    }
}

/// Ng's Table 2 columns: F (eq. 6), F' (eq. 8) and β (eq. 11 in general
/// form) for crank torque `torque` and friction `mu`. Lengths and torque in
/// consistent units, named by `units` (the defaults of the command line
/// are mm and N·mm, giving newtons). A dead centre prints "∞";
/// self-locking prints "self-locking".
pub fn forces(
    mechanism: &SliderCrank,
    torque: f64,
    mu: f64,
    angles: &[f64],
    decimals: usize,
    units: &Units,
) -> Result<Table> {
    let rows = angles
        .iter()
        .map(|&d| forces_row(mechanism, torque, mu, d, decimals))
        .collect::<Result<Vec<_>>>()?;
    Ok(Table {
        rows,
        ..forces_head(mechanism, torque, mu, units)
    })
}

/// One row of [`forces`], at `degrees`.
pub fn forces_row(
    mechanism: &SliderCrank,
    torque: f64,
    mu: f64,
    degrees: f64,
    decimals: usize,
) -> Result<Vec<String>> {
    let pose = mechanism.pose(Angle::from_degrees(degrees)?);
    let (f, fp) = match slider_force(&pose, torque)? {
        None => ("∞".to_string(), "∞".to_string()),
        Some(f) => {
            let fp = match with_friction(&pose, f, mu)? {
                Friction::Force(x) => fixed(x, decimals),
                Friction::SelfLocking(_) => "self-locking".into(),
            };
            (fixed(f, decimals), fp)
        }
    };
    Ok(vec![
        angle_cell(degrees, 0),
        f,
        fp,
        fixed(pose.transmission_angle().to_degrees(), 2),
    ])
}

/// The title and headers of [`forces`], without rows.
pub fn forces_head(mechanism: &SliderCrank, torque: f64, mu: f64, units: &Units) -> Table {
    let (u, f) = (units.length(), units.force());
    Table {
        title: format!(
            "Static forces (Ng Table 2): r = {} {u}, l = {} {u}, e = {} {u}, T = {} {}, μ = {}",
            plain(mechanism.crank()),
            plain(mechanism.rod()),
            plain(mechanism.offset()),
            plain(torque),
            units.torque(),
            plain(mu)
        ),
        headers: vec![
            "θ (°)".into(),
            format!("F eq. 6 ({f})"),
            format!("F' eq. 8 ({f})"),
            "β (°)".into(),
        ],
        rows: vec![],
        notes: vec![],
    }
}

/// The tables `slider-crank table NAME` prints; those of the gallery
/// ([`TableName::GALLERY`]) each with a seed it reproduces.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum TableName {
    /// The error due to obliquity at θ = 90° for n = 4, 5, 6 (textbook §35).
    Obliquity,
    /// cos θ + cos 2θ / n, θ = 0° … 180°, n = 4 … 6 and ∞ (textbook §35).
    AccelerationFactor,
    /// The §35 engine at 250 rpm, θ = 0° … 360° by 30°.
    Kinematics,
    /// Ng's Table 2 columns: F, F′ and β for θ = 10° … 160°.
    Forces,
    /// The engine of §35 with a reciprocating mass of 10 slug at 250 rpm:
    /// inertia force, piston effort and crank effort, θ = 0° … 360° by 30°.
    Dynamics,
    /// The unbalanced forces and couples of an in-line engine of several
    /// cylinders against θ (the flat four by default).
    Balance,
    /// The piston's acceleration as a series of harmonics and the error of
    /// each cut.
    Harmonics,
    /// A single cylinder's unbalanced force for each fraction of its
    /// reciprocating mass balanced, and a locomotive's hammer blow.
    PartialBalance,
    /// The primary and secondary forces of cylinders on one crank (the
    /// 90° V-twin by default).
    Radial,
    /// The tool's motion of a quick return (inversion 3 or 2) over its
    /// cutting and return strokes.
    QuickReturn,
}

impl TableName {
    /// Every table, in the order the command line's help lists them.
    pub const ALL: [TableName; 10] = [
        TableName::Obliquity,
        TableName::AccelerationFactor,
        TableName::Kinematics,
        TableName::Forces,
        TableName::Dynamics,
        TableName::Balance,
        TableName::Harmonics,
        TableName::PartialBalance,
        TableName::Radial,
        TableName::QuickReturn,
    ];

    /// The tables the gallery writes, each with the seed it reproduces
    /// ([`TableName::source`]).
    pub const GALLERY: [TableName; 5] = [
        TableName::Obliquity,
        TableName::AccelerationFactor,
        TableName::Kinematics,
        TableName::Forces,
        TableName::Dynamics,
    ];

    /// The name the `table` command takes (`acceleration-factor`).
    pub fn name(&self) -> &'static str {
        match self {
            TableName::Obliquity => "obliquity",
            TableName::AccelerationFactor => "acceleration-factor",
            TableName::Kinematics => "kinematics",
            TableName::Forces => "forces",
            TableName::Dynamics => "dynamics",
            TableName::Balance => "balance",
            TableName::Harmonics => "harmonics",
            TableName::PartialBalance => "partial-balance",
            TableName::Radial => "radial",
            TableName::QuickReturn => "quick-return",
        }
    }

    /// The table of that name; the error lists the names.
    pub fn from_name(name: &str) -> Result<Self> {
        Self::ALL
            .into_iter()
            .find(|t| t.name() == name)
            .ok_or_else(|| {
                let names: Vec<&str> = Self::ALL.iter().map(TableName::name).collect();
                Error::invalid(
                    Input::Options,
                    format!(
                        "unknown table '{name}': the tables are {}",
                        names.join(", ")
                    ),
                )
            })
    }

    /// The seed and section it reproduces.
    pub fn source(&self) -> &'static str {
        match self {
            TableName::Obliquity => {
                "Textbook, Chapter IV “Slider-crank chains”, §35: the error due to obliquity"
            }
            TableName::AccelerationFactor => {
                "Textbook, Chapter IV “Slider-crank chains”, §35: the table of eq. (3)"
            }
            TableName::Kinematics => {
                "Textbook, Chapter IV “Slider-crank chains”, §35–37: the engine of §35, exact values (no table in the chapter)"
            }
            TableName::Forces => {
                "Ng, “A slider-crank experiment to determine the action of static forces”, Table 2"
            }
            TableName::Dynamics => {
                "Textbook §37 (Klein's CG) and Ng (T = F · OM), carried on by standard engine dynamics: the turning moment and the fluctuation of energy (no table in either seed)"
            }
            TableName::Balance
            | TableName::Harmonics
            | TableName::PartialBalance
            | TableName::Radial => {
                "Textbook §35–37 (the acceleration of eq. (3)), carried on by the standard balance of reciprocating masses (no table in either seed)"
            }
            TableName::QuickReturn => {
                "Textbook, Chapter IV “Slider-crank chains”: the quick return of inversions 2 and 3 (no table in the chapter)"
            }
        }
    }

    /// The table with the defaults of `slider-crank table NAME`: n = 4, 5, 6
    /// at 90°; the textbook's rows and columns; r = 0.5 ft, l = 3 ft,
    /// 250 rpm, 4 decimals; r = 25 mm, l = 72 mm, T = 264.87 N·mm, μ = 1,
    /// 2 decimals; the other tables as [`TableRequest::new`] asks them.
    pub fn table(&self) -> Result<Table> {
        let every = |from: u32, to: u32, step: u32| -> Vec<f64> {
            (from..=to).step_by(step as usize).map(f64::from).collect()
        };
        match self {
            TableName::Obliquity => obliquity(&[4.0, 5.0, 6.0], 90.0),
            TableName::AccelerationFactor => {
                acceleration_factor_table(&TEXTBOOK_RATIOS, &TEXTBOOK_ANGLES)
            }
            TableName::Kinematics => kinematics(
                &SliderCrank::in_line(ENGINE_35.0, ENGINE_35.1)?,
                crate::analytic::kinematics::rpm_to_omega(RPM),
                &every(0, 360, 30),
                4,
                &Units::FOOT_POUND,
            ),
            TableName::Forces => forces(
                &SliderCrank::in_line(NG_RIG.0, NG_RIG.1)?,
                crate::sources::NG_TORQUE,
                1.0,
                &every(10, 160, 10),
                2,
                &Units::MILLIMETRE_NEWTON,
            ),
            TableName::Dynamics => dynamics::example_table(&every(0, 360, 30)),
            other => TableRequest::new(*other).plan()?.table(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn csv_quotes_commas() {
        let t = Table {
            title: "t".into(),
            headers: vec!["a".into(), "b".into()],
            rows: vec![vec!["1,5".into(), "2".into()]],
            notes: vec![],
        };
        assert_eq!(t.render(Format::Csv), "a,b\n\"1,5\",2\n");
    }

    #[test]
    fn csv_doubles_quotes_and_keeps_its_notes_as_comments() {
        let t = Table {
            title: "t".into(),
            headers: vec!["a".into(), "b \"x\"".into()],
            rows: vec![vec!["1".into(), "2".into()]],
            notes: vec!["ΔE = 3.\nI = 4.".into(), "last".into()],
        };
        assert_eq!(
            t.render(Format::Csv),
            "a,\"b \"\"x\"\"\"\n1,2\n# ΔE = 3.\n# I = 4.\n# last\n"
        );
    }

    #[test]
    fn obliquity_of_huge_ratios_is_finite() {
        // Issue 9 (5): n = 1e308 printed inf. √(n² − 1) − n → −1/(2n).
        let (root, err) = obliquity_error(1e308, 1.0);
        assert_eq!(root, 1e308);
        assert_eq!(err, -0.5 / 1e308);
        let t = obliquity(&[1e308, f64::INFINITY], 90.0).unwrap();
        assert_eq!(t.rows[0][..2], ["1e308", "1.00e308"]);
        assert_eq!(t.rows[1][1..], ["∞", "0.00"]);
        assert!(!t.render(Format::Csv).contains("inf"));
    }

    #[test]
    fn rows_written_one_at_a_time_match_the_whole_table() {
        let m = SliderCrank::in_line(0.5, 3.0).unwrap();
        let angles = [0.0, 30.0, 45.0, 90.0];
        let whole = kinematics(&m, 26.0, &angles, 4, &Units::FOOT_POUND).unwrap();
        let head = kinematics_head(&m, 26.0, &Units::FOOT_POUND);
        let h = Head {
            title: &head.title,
            headers: &head.headers,
            notes: &head.notes,
        };
        for format in [Format::Text, Format::Csv, Format::Markdown] {
            let mut out = String::new();
            let rows = || angles.iter().map(|&d| kinematics_row(&m, 26.0, d, 4));
            render_rows(format, &h, rows, &mut |s| {
                out.push_str(s);
                Ok(())
            })
            .unwrap();
            assert_eq!(out, whole.render(format));
        }
        // A failing row writes nothing.
        let mut out = String::new();
        let rows = || {
            [1e99, f64::NAN]
                .into_iter()
                .map(|d| kinematics_row(&m, 26.0, d, 4))
        };
        assert!(
            render_rows(Format::Csv, &h, rows, &mut |s| {
                out.push_str(s);
                Ok(())
            })
            .is_err()
        );
        assert!(out.is_empty());
    }

    #[test]
    fn bad_ratio_is_refused() {
        assert!(obliquity(&[1.0], 90.0).is_err());
        assert!(acceleration_factor_table(&[f64::NAN], &[0.0]).is_err());
    }
}
