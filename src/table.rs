//! The printed tables: the textbook's obliquity and acceleration-factor
//! tables, kinematics sweeps and Ng's Table 2, in text, Markdown or CSV.

use crate::analytic::approx::acceleration_factor;
use crate::analytic::kinematics::Kinematics;
use crate::analytic::statics::{Friction, slider_force, with_friction};
use crate::angle::Angle;
use crate::error::{Error, Result};
use crate::mechanism::SliderCrank;
use crate::render::plain;
use crate::units::Units;

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
                Error::Parse(format!(
                    "unknown format '{name}': expected text, markdown or csv"
                ))
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

/// Formats `x` with `decimals` decimals, never as "-0.000"; from 1e15 on
/// in exponent form (`1.2500e300`, not 300 digits).
pub fn fixed(x: f64, decimals: usize) -> String {
    if let Some(s) = fixed_fast(x, decimals) {
        return s;
    }
    if x.abs() >= 1e15 {
        return format!("{:.*e}", decimals, x);
    }
    let s = format!("{:.*}", decimals, x);
    if s.starts_with('-') && s[1..].chars().all(|c| c == '0' || c == '.') {
        s[1..].to_string()
    } else {
        s
    }
}

/// Powers of ten exact in f64, up to the 17 decimals a table writes.
const POW10: [f64; 18] = [
    1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16,
    1e17,
];

/// [`fixed`] of an ordinary number (0, or 1e-6 ≤ |x| < 1e12, with fewer
/// than 10¹⁵ units of the last decimal) without float formatting: x
/// scaled by an exact power of ten and rounded to an integer, whose
/// digits are written. The scaled product is within half an ulp of the
/// exact one, so the rounding is the exact decimal's wherever the product
/// is more than an ulp from a half; nearer one (and outside the ordinary
/// range) `None`, and `format!` decides.
fn fixed_fast(x: f64, decimals: usize) -> Option<String> {
    let a = x.abs();
    if !(a == 0.0 || (1e-6..1e12).contains(&a)) {
        return None;
    }
    let scaled = a * POW10.get(decimals)?;
    if scaled >= 1e15 {
        return None;
    }
    let whole = scaled.floor();
    let frac = scaled - whole;
    if (frac - 0.5).abs() <= scaled * f64::EPSILON {
        return None;
    }
    let n = if frac > 0.5 { whole + 1.0 } else { whole } as u64;
    let p = 10u64.pow(decimals as u32);
    let mut digits = [0u8; 40];
    let mut at = digits.len();
    // cannot fail: n ≤ 1e15 and decimals ≤ 17 (`POW10`), so at most 17
    // decimals, a point, 16 whole digits and a sign: 35 bytes of the 40.
    #[allow(clippy::indexing_slicing)]
    let mut put = |b: u8| {
        at -= 1;
        digits[at] = b;
    };
    let mut frac_part = n % p;
    for _ in 0..decimals {
        put(b'0' + (frac_part % 10) as u8);
        frac_part /= 10;
    }
    if decimals > 0 {
        put(b'.');
    }
    let mut int_part = n / p;
    loop {
        put(b'0' + (int_part % 10) as u8);
        int_part /= 10;
        if int_part == 0 {
            break;
        }
    }
    if x < 0.0 && n != 0 {
        put(b'-');
    }
    std::str::from_utf8(digits.get(at..)?)
        .ok()
        .map(str::to_owned)
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
    /// Notes printed under the table (text and Markdown only).
    pub notes: &'a [String],
}

fn csv_line(cells: &[String]) -> String {
    let quoted: Vec<String> = cells
        .iter()
        .map(|c| {
            if c.contains(',') {
                format!("\"{c}\"")
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
    let mut width: Vec<usize> = head.headers.iter().map(|h| h.chars().count()).collect();
    for row in rows() {
        for (w, c) in width.iter_mut().zip(row?.iter()) {
            *w = (*w).max(c.chars().count());
        }
    }
    match format {
        Format::Csv => out(&csv_line(head.headers))?,
        Format::Markdown => {
            out(&format!("**{}**\n\n", head.title))?;
            out(&format!("| {} |\n", head.headers.join(" | ")))?;
            out(&format!("|{}\n", "---|".repeat(head.headers.len())))?;
        }
        Format::Text => {
            out(&format!("{}\n\n", head.title))?;
            out(&text_line(head.headers, &width))?;
        }
    }
    for row in rows() {
        let row = row?;
        match format {
            Format::Csv => out(&csv_line(&row))?,
            Format::Markdown => out(&format!("| {} |\n", row.join(" | ")))?,
            Format::Text => out(&text_line(&row, &width))?,
        }
    }
    match format {
        Format::Csv => {}
        Format::Markdown => {
            for n in head.notes {
                out(&format!("\n{n}\n"))?;
            }
        }
        Format::Text => {
            for n in head.notes {
                out(&format!("\n{n}"))?;
            }
            if !head.notes.is_empty() {
                out("\n")?;
            }
        }
    }
    Ok(())
}

fn check_ratios(ratios: &[f64]) -> Result<()> {
    for &n in ratios {
        if n.is_nan() || n <= 1.0 {
            return Err(Error::OutOfRange {
                name: "n",
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
        fixed(degrees, 1),
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
            crate::catalogue::diagrams::short(omega * 60.0 / std::f64::consts::TAU),
            crate::catalogue::diagrams::sig(omega)
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
        fixed(degrees, 0),
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

/// The tables `slider-crank table NAME` prints, each with that command's
/// defaults.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
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
}

impl TableName {
    /// Every table, in the order `slider-crank table --help` lists them.
    pub const ALL: [TableName; 5] = [
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
        }
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
        }
    }

    /// The table with the defaults of `slider-crank table NAME`: n = 4, 5, 6
    /// at 90°; the textbook's rows and columns; r = 0.5 ft, l = 3 ft,
    /// 250 rpm, 4 decimals; r = 25 mm, l = 72 mm, T = 264.87 N·mm, μ = 1,
    /// 2 decimals.
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
                &SliderCrank::in_line(0.5, 3.0)?,
                crate::rpm_to_omega(250.0),
                &every(0, 360, 30),
                4,
                &Units::FOOT_POUND,
            ),
            TableName::Forces => forces(
                &SliderCrank::in_line(25.0, 72.0)?,
                crate::analytic::statics::NG_TORQUE,
                1.0,
                &every(10, 160, 10),
                2,
                &Units::MILLIMETRE_NEWTON,
            ),
            TableName::Dynamics => crate::dynamics::example_table(&every(0, 360, 30)),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every double, subnormals and the largest included: at most 15
    /// digits before the point, exponent form beyond, never "inf".
    #[test]
    fn every_double_is_fixed_within_a_width() {
        let mut x = 5e-324_f64;
        while x.is_finite() {
            for v in [x, -x] {
                for decimals in [0, 3, 17] {
                    let s = fixed(v, decimals);
                    assert!(s.len() <= 17 + decimals + 7, "{v:e}: {s}");
                    // Rounded, 1.7976931348623157e308 to 0 decimals
                    // reads "2e308": beyond the largest double, but text.
                    assert!(s.parse::<f64>().is_ok(), "{v:e}: {s}");
                    assert!(!s.contains("inf") && !s.contains("NaN"), "{v:e}: {s}");
                }
            }
            // 1.37 × the least subnormal rounds back to it: step at least an ulp.
            x = (x * 1.37).max(f64::from_bits(x.to_bits() + 1));
        }
        assert_eq!(fixed(f64::MAX, 3), "1.798e308");
        assert_eq!(fixed(5e-324, 3), "0.000");
    }

    #[test]
    fn negative_zero_is_not_printed() {
        assert_eq!(fixed(-0.0, 3), "0.000");
        assert_eq!(fixed(-0.0004, 3), "0.000");
        assert_eq!(fixed(-0.0005001, 3), "-0.001");
    }

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

    /// What `{:.N}` writes, without a negative zero: the formatting
    /// [`fixed_fast`] must match digit for digit.
    fn formatted(x: f64, decimals: usize) -> String {
        let s = format!("{:.*}", decimals, x);
        if s.starts_with('-') && s[1..].chars().all(|c| c == '0' || c == '.') {
            s[1..].to_string()
        } else {
            s
        }
    }

    #[test]
    fn the_fast_number_writer_has_the_digits_of_the_formatter() {
        // Over 30 decades, both signs, every count of decimals, with
        // mantissas from a fixed sequence and the halves that decide a
        // rounding (0.125, 2.5, 0.0625 …, exact in binary).
        let mut state = 0x2545_f491_4f6c_dd1d_u64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        let (mut fast, mut total) = (0, 0);
        for decade in -8..22 {
            for k in 0..300 {
                let mantissa = match k {
                    0 => 1.0,
                    1 => 1.25,
                    2 => 2.5,
                    3 => 0.625,
                    4 => 9.999_999_999_999_998,
                    _ => 1.0 + 9.0 * next(),
                };
                let x = mantissa * 10f64.powi(decade);
                for x in [x, -x, (x * 8.0).round() / 8.0, x.round() + 0.5] {
                    for decimals in 0..=17 {
                        total += 1;
                        if let Some(s) = fixed_fast(x, decimals) {
                            fast += 1;
                            assert_eq!(s, formatted(x, decimals), "{x:e} to {decimals}");
                        }
                    }
                }
            }
        }
        // The ordinary range (a third of these, which reach 1e22 and 17
        // decimals) is the fast path's.
        assert!(fast * 3 > total, "{fast} of {total}");
        assert_eq!(fixed_fast(0.0, 3).as_deref(), Some("0.000"));
        assert_eq!(fixed_fast(-0.0, 2).as_deref(), Some("0.00"));
        assert_eq!(fixed_fast(-0.000_001, 2).as_deref(), Some("0.00"));
        assert_eq!(fixed_fast(-1.5, 0), None); // a half: the formatter's
        assert_eq!(fixed_fast(1e-7, 4), None); // outside the ordinary range
        assert_eq!(fixed_fast(2e12, 1), None);
        assert_eq!(fixed_fast(f64::NAN, 1), None);
        assert_eq!(fixed(-12.345_67, 3), "-12.346");
    }
}
