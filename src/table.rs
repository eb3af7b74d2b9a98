//! The printed tables: the textbook's obliquity and acceleration-factor
//! tables, kinematics sweeps and Ng's Table 2, in text, Markdown or CSV.

use crate::analytic::approx::acceleration_factor;
use crate::analytic::kinematics::Kinematics;
use crate::analytic::statics::{Friction, slider_force, with_friction};
use crate::angle::Angle;
use crate::error::{Error, Result};
use crate::mechanism::SliderCrank;

/// The textbook's n columns of the acceleration-factor table (∞ last).
pub const TEXTBOOK_RATIOS: [f64; 6] = [4.0, 4.5, 5.0, 5.5, 6.0, f64::INFINITY];

/// The textbook's θ rows of the acceleration-factor table, degrees.
pub const TEXTBOOK_ANGLES: [f64; 7] = [0.0, 30.0, 60.0, 90.0, 120.0, 150.0, 180.0];

/// Output format of a table.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    /// Aligned columns for a terminal.
    Text,
    /// A GitHub-flavoured Markdown table.
    Markdown,
    /// Comma-separated values with a header row.
    Csv,
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

/// Formats `x` with `decimals` decimals, never as "-0.000".
pub fn fixed(x: f64, decimals: usize) -> String {
    let s = format!("{:.*}", decimals, x);
    if s.starts_with('-') && s[1..].chars().all(|c| c == '0' || c == '.') {
        s[1..].to_string()
    } else {
        s
    }
}

fn ratio_label(n: f64) -> String {
    if n.is_infinite() {
        "∞".into()
    } else {
        format!("{n}")
    }
}

impl Table {
    /// Renders the table.
    pub fn render(&self, format: Format) -> String {
        match format {
            Format::Csv => {
                let mut out = String::new();
                let line = |cells: &[String]| {
                    cells
                        .iter()
                        .map(|c| {
                            if c.contains(',') {
                                format!("\"{c}\"")
                            } else {
                                c.clone()
                            }
                        })
                        .collect::<Vec<_>>()
                        .join(",")
                };
                out.push_str(&line(&self.headers));
                out.push('\n');
                for r in &self.rows {
                    out.push_str(&line(r));
                    out.push('\n');
                }
                out
            }
            Format::Markdown => {
                let mut out = format!("**{}**\n\n", self.title);
                out.push_str(&format!("| {} |\n", self.headers.join(" | ")));
                out.push_str(&format!("|{}\n", "---|".repeat(self.headers.len())));
                for r in &self.rows {
                    out.push_str(&format!("| {} |\n", r.join(" | ")));
                }
                for n in &self.notes {
                    out.push_str(&format!("\n{n}\n"));
                }
                out
            }
            Format::Text => {
                let cols = self.headers.len();
                let width: Vec<usize> = (0..cols)
                    .map(|i| {
                        std::iter::once(&self.headers[i])
                            .chain(self.rows.iter().map(|r| &r[i]))
                            .map(|c| c.chars().count())
                            .max()
                            .unwrap_or(0)
                    })
                    .collect();
                let line = |cells: &[String]| {
                    let padded: Vec<String> = cells
                        .iter()
                        .enumerate()
                        .map(|(i, c)| {
                            let pad = width[i] - c.chars().count();
                            if i == 0 {
                                format!("{c}{}", " ".repeat(pad))
                            } else {
                                format!("{}{c}", " ".repeat(pad))
                            }
                        })
                        .collect();
                    padded.join("  ").trim_end().to_string()
                };
                let mut out = format!("{}\n\n", self.title);
                out.push_str(&line(&self.headers));
                out.push('\n');
                for r in &self.rows {
                    out.push_str(&line(r));
                    out.push('\n');
                }
                for n in &self.notes {
                    out.push_str(&format!("\n{n}"));
                }
                if !self.notes.is_empty() {
                    out.push('\n');
                }
                out
            }
        }
    }
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

/// The textbook's error due to obliquity at θ (default 90°): rows n,
/// √(n² − sin²θ) and √(n² − sin²θ) − n (in crank radii), 2 decimals as
/// printed in §35.
pub fn obliquity(ratios: &[f64], theta_degrees: f64) -> Result<Table> {
    check_ratios(ratios)?;
    let a = Angle::from_degrees(theta_degrees)?;
    let s = a.sin();
    let mut rows = Vec::new();
    for &n in ratios {
        let root = ((n - s) * (n + s)).sqrt();
        // root − n without cancellation.
        let err = -s * s / (root + n);
        rows.push(vec![ratio_label(n), fixed(root, 2), fixed(err, 2)]);
    }
    Ok(Table {
        title: format!(
            "Error due to obliquity at θ = {}°, in crank radii (textbook §35)",
            theta_degrees
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
        let label = if d == 0.0 {
            "0° or 360°".to_string()
        } else if a.degrees() == 180.0 || d == 180.0 {
            format!("{d}°")
        } else if (0.0..180.0).contains(&d) {
            format!("{d}° or {}°", 360.0 - d)
        } else {
            format!("{d}°")
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
/// rod's angle and rates, for crank speed `omega` (rad/s).
pub fn kinematics(
    mechanism: &SliderCrank,
    omega: f64,
    angles: &[f64],
    decimals: usize,
) -> Result<Table> {
    let mut rows = Vec::new();
    for &d in angles {
        let pose = mechanism.pose(Angle::from_degrees(d)?);
        let k = Kinematics::new(&pose, omega)?;
        rows.push(vec![
            fixed(d, 1),
            fixed(k.position, decimals),
            fixed(k.velocity, decimals),
            fixed(k.acceleration, decimals),
            fixed(k.rod_angle.to_degrees(), decimals),
            fixed(k.rod_angular_velocity, decimals),
            fixed(k.rod_angular_acceleration, decimals),
        ]);
    }
    Ok(Table {
        title: format!(
            "Kinematics: r = {}, l = {}, e = {}, ω = {} rad/s",
            mechanism.crank(),
            mechanism.rod(),
            mechanism.offset(),
            omega
        ),
        headers: [
            "θ (°)",
            "x_A",
            "dx/dt",
            "d²x/dt²",
            "φ (°)",
            "dφ/dt",
            "d²φ/dt²",
        ]
        .iter()
        .map(|s| s.to_string())
        .collect(),
        rows,
        notes: vec![],
    })
}

/// Ng's Table 2 columns: F (eq. 6), F' (eq. 8) and β (eq. 11 in general
/// form) for crank torque `torque` and friction `mu`. Lengths and torque in
/// consistent units (the defaults of the command line are mm and N·mm,
/// giving newtons). A dead centre prints "∞"; self-locking prints
/// "self-locking".
pub fn forces(
    mechanism: &SliderCrank,
    torque: f64,
    mu: f64,
    angles: &[f64],
    decimals: usize,
) -> Result<Table> {
    let mut rows = Vec::new();
    for &d in angles {
        let pose = mechanism.pose(Angle::from_degrees(d)?);
        let (f, fp) = match slider_force(&pose, torque) {
            None => ("∞".to_string(), "∞".to_string()),
            Some(f) => {
                let fp = match with_friction(&pose, f, mu)? {
                    Friction::Force(x) => fixed(x, decimals),
                    Friction::SelfLocking(_) => "self-locking".into(),
                };
                (fixed(f, decimals), fp)
            }
        };
        rows.push(vec![
            fixed(d, 0),
            f,
            fp,
            fixed(pose.transmission_angle().to_degrees(), 2),
        ]);
    }
    Ok(Table {
        title: format!(
            "Static forces (Ng Table 2): r = {}, l = {}, e = {}, T = {}, μ = {}",
            mechanism.crank(),
            mechanism.rod(),
            mechanism.offset(),
            torque,
            mu
        ),
        headers: ["θ (°)", "F (eq. 6)", "F' (eq. 8)", "β (°)"]
            .iter()
            .map(|s| s.to_string())
            .collect(),
        rows,
        notes: vec![],
    })
}

#[cfg(test)]
mod tests {
    use super::*;

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
    fn bad_ratio_is_refused() {
        assert!(obliquity(&[1.0], 90.0).is_err());
        assert!(acceleration_factor_table(&[f64::NAN], &[0.0]).is_err());
    }
}
