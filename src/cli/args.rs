//! Flags shared by the subcommands and the parsing of angle specifications.

use clap::Args;
use slider_crank::analytic::kinematics::{check_omega, omega_from_rpm};
use slider_crank::{Error, Result, SliderCrank, Unit, Units, rpm_to_omega};

/// The mechanism flags. Defaults: the engine of textbook §35 (12 in stroke,
/// 3 ft rod: r = 0.5 ft, l = 3 ft, in line).
#[derive(Debug, Clone, Args)]
pub struct MechanismArgs {
    /// Crank radius r, in any length unit, named by --unit (give the rod and
    /// the offset in the same unit)
    #[arg(
        long,
        allow_hyphen_values = true,
        default_value_t = 0.5,
        value_name = "R"
    )]
    pub crank: f64,
    /// Connecting-rod length l; must exceed r + |e| so the crank turns fully
    #[arg(
        long,
        allow_hyphen_values = true,
        default_value_t = 3.0,
        value_name = "L"
    )]
    pub rod: f64,
    /// Offset e of the line of stroke from the crank centre: the stroke is
    /// the line y = e (0: in line; positive: above the crank centre)
    #[arg(
        long,
        allow_hyphen_values = true,
        default_value_t = 0.0,
        value_name = "E"
    )]
    pub offset: f64,
}

impl MechanismArgs {
    /// The validated mechanism.
    pub fn mechanism(&self) -> Result<SliderCrank> {
        SliderCrank::new(self.crank, self.rod, self.offset)
    }
}

/// The unit flags of every command that prints or draws quantities. Units
/// are names only: the numbers are taken to be in them, never converted.
#[derive(Debug, Clone, Args)]
pub struct UnitArgs {
    /// Name of the length unit the lengths are given in (mm, m, in, ft,
    /// ...), written beside lengths, speeds (UNIT/s), accelerations
    /// (UNIT/s²) and torques; a name only, no number is converted
    /// [default: the seed's, ft for the textbook's engine, mm for Ng's rig]
    #[arg(long = "unit", value_name = "UNIT")]
    pub length: Option<Unit>,
    /// Name of the force unit (N, kN, lbf, ...), written beside forces and
    /// torques (FORCE·UNIT) [default: the seed's, lbf for the textbook's
    /// engine, N for Ng's rig]
    #[arg(long = "force-unit", value_name = "FORCE")]
    pub force: Option<Unit>,
}

impl UnitArgs {
    /// The units asked for, each defaulting to that of `own`.
    pub fn units(&self, own: Units) -> Units {
        let mut units = own;
        if let Some(u) = &self.length {
            units = units.with_length(u.clone());
        }
        if let Some(u) = &self.force {
            units = units.with_force(u.clone());
        }
        units
    }
}

/// Crank speed flags: `--rpm` or `--omega`, default 250 rpm (§35).
#[derive(Debug, Clone, Args)]
pub struct SpeedArgs {
    /// Crank speed in revolutions per minute, positive counter-clockwise
    /// (or give --omega) [default: 250]
    #[arg(
        long,
        allow_hyphen_values = true,
        value_name = "N",
        conflicts_with = "omega"
    )]
    pub rpm: Option<f64>,
    /// Crank speed ω in rad/s, positive counter-clockwise (instead of
    /// --rpm)
    #[arg(long, allow_hyphen_values = true, value_name = "W")]
    pub omega: Option<f64>,
}

impl SpeedArgs {
    /// ω in rad/s.
    pub fn omega(&self) -> Result<f64> {
        match (self.rpm, self.omega) {
            (_, Some(w)) => check_omega(w),
            (Some(n), None) => omega_from_rpm(n),
            (None, None) => Ok(rpm_to_omega(250.0)),
        }
    }
}

/// The load on the crank: `--torque` and, with it, `--friction`. The
/// values are checked where the statics are computed.
#[derive(Debug, Clone, Args)]
pub struct LoadArgs {
    /// Crank torque T, counter-clockwise positive, in force × the length
    /// unit (FORCE·UNIT, N·mm for lengths in mm): adds the statics of Ng
    /// eq. 6–11 (the OM line, slider force, side thrust, friction,
    /// transmission angle), the forces in the force unit
    #[arg(long, allow_negative_numbers = true, value_name = "T")]
    pub torque: Option<f64>,
    /// Coefficient of friction μ ≥ 0 of the slider in its guides (with
    /// --torque)
    #[arg(
        long,
        allow_negative_numbers = true,
        value_name = "MU",
        default_value_t = 0.0,
        requires = "torque"
    )]
    pub friction: f64,
}

/// Most angles a range may produce.
pub const MAX_ANGLES: usize = 100_000;

fn parse_number(text: &str, what: &str) -> Result<f64> {
    let value: f64 = text.trim().parse().map_err(|_| {
        Error::Parse(format!(
            "invalid {what} '{}': expected degrees like 45, a list 0,30,60 or a range START:STOP:STEP",
            shorten(text)
        ))
    })?;
    if !value.is_finite() {
        return Err(Error::Parse(format!(
            "invalid {what} '{}': the angle must be a finite number of degrees",
            shorten(text)
        )));
    }
    Ok(value)
}

/// One part of an angle specification.
#[derive(Debug, Clone, Copy, PartialEq)]
enum AnglePart {
    One(f64),
    /// start + k · step for k = 0 ..= last.
    Range {
        start: f64,
        step: f64,
        last: usize,
    },
}

/// A parsed angle specification (`45`, `0,30,60`, `START:STOP:STEP`), held
/// as its parts so that a range of a million angles takes no memory.
#[derive(Debug, Clone, PartialEq)]
pub struct AngleSpec {
    parts: Vec<AnglePart>,
    count: usize,
}

impl AngleSpec {
    /// Parses `45`, `0,30,60` or `START:STOP:STEP` (STOP included when the
    /// steps reach it; STEP may be negative to count down); at most
    /// [`MAX_ANGLES`] angles.
    pub fn parse(spec: &str) -> Result<Self> {
        let mut parts = Vec::new();
        let mut count = 0usize;
        for part in spec.split(',') {
            let parsed = parse_part(part)?;
            count += match parsed {
                AnglePart::One(_) => 1,
                AnglePart::Range { last, .. } => last + 1,
            };
            if count > MAX_ANGLES {
                return Err(Error::Parse(format!(
                    "invalid angles '{}': more than {MAX_ANGLES} angles",
                    shorten(spec)
                )));
            }
            parts.push(parsed);
        }
        Ok(Self { parts, count })
    }

    /// The angles in order.
    pub fn iter(&self) -> impl Iterator<Item = f64> + '_ {
        self.parts.iter().flat_map(|p| {
            let (start, step, last) = match *p {
                AnglePart::One(a) => (a, 0.0, 0),
                AnglePart::Range { start, step, last } => (start, step, last),
            };
            (0..=last).map(move |k| start + step * k as f64)
        })
    }

    /// Whether there is more than one angle or the text asked for a list.
    pub fn is_list(&self) -> bool {
        self.parts.len() > 1 || matches!(self.parts[0], AnglePart::Range { .. })
    }
}

/// At most 40 characters of a user's text, for a message.
fn shorten(text: &str) -> String {
    let mut s: String = text.chars().take(40).collect();
    if text.chars().count() > 40 {
        s.push('…');
    }
    s
}

fn parse_part(part: &str) -> Result<AnglePart> {
    let fields: Vec<&str> = part.split(':').collect();
    match fields.as_slice() {
        [one] => Ok(AnglePart::One(parse_number(one, "angle")?)),
        [start, stop, step] => {
            let (start, stop, step) = (
                parse_number(start, "range start")?,
                parse_number(stop, "range stop")?,
                parse_number(step, "range step")?,
            );
            if step == 0.0 || (stop - start) * step < 0.0 {
                return Err(Error::Parse(format!(
                    "invalid range '{}': the step must be non-zero and lead from start to stop",
                    shorten(part)
                )));
            }
            let count = ((stop - start) / step * (1.0 + 1e-12)).floor();
            if count.is_nan() || count >= MAX_ANGLES as f64 {
                return Err(Error::Parse(format!(
                    "invalid range '{}': more than {MAX_ANGLES} angles",
                    shorten(part)
                )));
            }
            Ok(AnglePart::Range {
                start,
                step,
                last: count as usize,
            })
        }
        _ => Err(Error::Parse(format!(
            "invalid angle '{}': expected degrees like 45 or a range START:STOP:STEP",
            shorten(part)
        ))),
    }
}

/// Parses `45`, `0,30,60` or `START:STOP:STEP` into the list of angles
/// (see [`AngleSpec::parse`]).
#[cfg(test)]
fn parse_angles(spec: &str) -> Result<Vec<f64>> {
    Ok(AngleSpec::parse(spec)?.iter().collect())
}

/// Parses a comma-separated list of numbers (`inf` allowed where `allow_inf`).
pub fn parse_list(spec: &str, name: &str, allow_inf: bool) -> Result<Vec<f64>> {
    spec.split(',')
        .map(|t| {
            let t = t.trim();
            let v: f64 = match t {
                "inf" | "∞" if allow_inf => f64::INFINITY,
                _ => t.parse().map_err(|_| {
                    Error::Parse(format!("invalid {name} '{t}': expected a number"))
                })?,
            };
            if v.is_nan() || (v.is_infinite() && !allow_inf) {
                return Err(Error::Parse(format!(
                    "invalid {name} '{t}': expected a finite number"
                )));
            }
            Ok(v)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ranges_include_their_stop() {
        assert_eq!(
            parse_angles("0:90:30").unwrap(),
            vec![0.0, 30.0, 60.0, 90.0]
        );
        assert_eq!(
            parse_angles("0:100:30").unwrap(),
            vec![0.0, 30.0, 60.0, 90.0]
        );
        assert_eq!(parse_angles("90:0:-45").unwrap(), vec![90.0, 45.0, 0.0]);
        assert_eq!(parse_angles("0:1:0.1").unwrap().len(), 11);
        assert_eq!(parse_angles("10,20").unwrap(), vec![10.0, 20.0]);
        let spec = AngleSpec::parse("0:99999:1").unwrap();
        assert_eq!(spec.count, 100_000);
        assert_eq!(spec.iter().last(), Some(99_999.0));
        assert!(AngleSpec::parse("0:100000:1").is_err());
        assert!(AngleSpec::parse("0:50000:1,0:50000:1").is_err());
    }

    #[test]
    fn bad_specs_are_refused() {
        for bad in [
            "abc",
            "1e400",
            "nan",
            "0:10:0",
            "0:10:-1",
            "0:1e9:1e-9",
            "1:2",
            "",
        ] {
            assert!(parse_angles(bad).is_err(), "{bad}");
        }
    }
}
