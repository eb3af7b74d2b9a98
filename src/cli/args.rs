//! Flags shared by the subcommands and the parsing of angle specifications.

use clap::Args;
use slider_crank::analytic::kinematics::{check_omega, omega_from_rpm};
use slider_crank::table::{DEFAULT_MAX_CELLS, MaxCells};
use slider_crank::{Error, Input, Result, SliderCrank, Unit, Units, rpm_to_omega};

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

/// The mechanism flags of `handout`, each `None` where not given, so that
/// a class varies around the teacher's engine only when one is given;
/// the defaults otherwise those of [`MechanismArgs`].
#[derive(Debug, Clone, Args)]
pub struct GivenMechanismArgs {
    /// Crank radius r, in any length unit, named by --unit (give the rod and
    /// the offset in the same unit) [default: 0.5]
    #[arg(long, allow_hyphen_values = true, value_name = "R")]
    pub crank: Option<f64>,
    /// Connecting-rod length l; must exceed r + |e| so the crank turns
    /// fully [default: 3]
    #[arg(long, allow_hyphen_values = true, value_name = "L")]
    pub rod: Option<f64>,
    /// Offset e of the line of stroke from the crank centre: the stroke is
    /// the line y = e (0: in line; positive: above the crank centre)
    /// [default: 0]
    #[arg(long, allow_hyphen_values = true, value_name = "E")]
    pub offset: Option<f64>,
}

impl GivenMechanismArgs {
    /// Whether any of the flags was given.
    pub fn given(&self) -> bool {
        self.crank.is_some() || self.rod.is_some() || self.offset.is_some()
    }

    /// The validated mechanism, the §35 engine's lengths where not given.
    pub fn mechanism(&self) -> Result<SliderCrank> {
        SliderCrank::new(
            self.crank.unwrap_or(0.5),
            self.rod.unwrap_or(3.0),
            self.offset.unwrap_or(0.0),
        )
    }
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
    /// [default: the figure's own, ft for the textbook's engine, mm for
    /// Ng's rig]
    #[arg(long = "unit", value_name = "UNIT")]
    pub length: Option<Unit>,
    /// Name of the force unit (N, kN, lbf, ...), written beside forces and
    /// torques (FORCE·UNIT) [default: the one that goes with --unit, N for
    /// mm, cm, m and lbf for in, ft; without --unit the figure's own, lbf
    /// for the textbook's engine, N for Ng's rig]
    #[arg(long = "force-unit", value_name = "FORCE")]
    pub force: Option<Unit>,
}

impl UnitArgs {
    /// The units asked for, each defaulting to that of `own`, the force
    /// unit following --unit when only that is given ([`Units::asked`]).
    pub fn units(&self, own: Units) -> Units {
        own.asked(self.length.as_ref(), self.force.as_ref())
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
            (None, None) => Ok(rpm_to_omega(slider_crank::sources::RPM)),
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
    #[arg(long, allow_hyphen_values = true, value_name = "T")]
    pub torque: Option<f64>,
    /// Coefficient of friction μ ≥ 0 of the slider in its guides (with
    /// --torque)
    #[arg(
        long,
        allow_hyphen_values = true,
        value_name = "MU",
        default_value_t = 0.0,
        requires = "torque"
    )]
    pub friction: f64,
}

/// Most angles one range may describe: 2⁵³, past which the angles of a
/// range are no longer distinct numbers. What a command may compute is
/// bounded by [`GuardArgs`], not here.
pub const MAX_RANGE: f64 = 9_007_199_254_740_992.0;

/// The one guard on the size of a request: the values a command computes
/// (rows × columns), checked before any work ([`MaxCells`]).
#[derive(Debug, Clone, Args)]
pub struct GuardArgs {
    /// Most values a command computes: rows × columns of a table, angles
    /// × the values of each for analyze, poses × quantities for check. A
    /// larger request is refused before any work, with its size; give a
    /// larger N to lift the bound (the rows are streamed: memory does not
    /// grow with them)
    #[arg(
        long,
        value_name = "N",
        default_value_t = DEFAULT_MAX_CELLS,
        allow_hyphen_values = true
    )]
    pub max_cells: u64,
}

impl GuardArgs {
    /// The library's bound, set by `--max-cells`.
    pub fn bound(&self) -> MaxCells {
        MaxCells::new(self.max_cells)
    }

    /// Checks `rows` × `columns` against `--max-cells` (see
    /// [`MaxCells::check`]).
    pub fn check(&self, command: &str, rows: (u64, &str), columns: (u64, &str)) -> Result<()> {
        self.bound().check(command, rows, columns)
    }
}

fn parse_number(text: &str, what: &str) -> Result<f64> {
    let value: f64 = text.trim().parse().map_err(|_| {
        Error::invalid(Input::Angles, format!(
            "invalid {what} '{}': expected degrees like 45, a list 0,30,60 or a range START:STOP:STEP",
            shorten(text)
        ))
    })?;
    if !value.is_finite() {
        return Err(Error::invalid(
            Input::Angles,
            format!(
                "invalid {what} '{}': the angle must be a finite number of degrees",
                shorten(text)
            ),
        ));
    }
    Ok(value)
}

/// One part of an angle specification.
#[derive(Debug, Clone, Copy, PartialEq)]
enum AnglePart {
    One(f64),
    /// start + k · step for k = 0 ..= last, never past `stop`.
    Range {
        start: f64,
        step: f64,
        last: u64,
        stop: f64,
    },
}

/// A parsed angle specification (`45`, `0,30,60`, `START:STOP:STEP`), held
/// as its parts so that a range of a million angles takes no memory.
#[derive(Debug, Clone, PartialEq)]
pub struct AngleSpec {
    parts: Vec<AnglePart>,
    count: u64,
}

impl AngleSpec {
    /// Parses `45`, `0,30,60` or `START:STOP:STEP` (STOP included when the
    /// steps reach it; STEP may be negative to count down); a range of at
    /// most [`MAX_RANGE`] angles (what a command computes is bounded by
    /// [`GuardArgs`]).
    pub fn parse(spec: &str) -> Result<Self> {
        no_control(spec, Input::Angles, "angles")?;
        let mut parts = Vec::new();
        let mut count = 0u64;
        for part in spec.split(',') {
            let parsed = parse_part(part)?;
            count = count.saturating_add(match parsed {
                AnglePart::One(_) => 1,
                AnglePart::Range { last, .. } => last + 1,
            });
            parts.push(parsed);
        }
        Ok(Self { parts, count })
    }

    /// The angles in order.
    pub fn iter(&self) -> impl Iterator<Item = f64> + '_ {
        self.parts.iter().flat_map(|p| {
            let (start, step, last, stop) = match *p {
                AnglePart::One(a) => (a, 0.0, 0, a),
                AnglePart::Range {
                    start,
                    step,
                    last,
                    stop,
                } => (start, step, last, stop),
            };
            (0..=last).map(move |k| {
                let v = start + step * k as f64;
                // A step's rounding never carries an angle past the STOP
                // the range reached (0:0.3:0.1 ends at 0.3, not at
                // 0.30000000000000004).
                if (v - stop) * step > 0.0 { stop } else { v }
            })
        })
    }

    /// How many angles there are.
    pub fn len(&self) -> u64 {
        self.count
    }

    /// Whether there is more than one angle or the text asked for a list.
    pub fn is_list(&self) -> bool {
        self.parts.len() > 1 || matches!(self.parts.first(), Some(AnglePart::Range { .. }))
    }
}

/// Refuses a list or range with a line break, tab or other control
/// character inside (`1,2<newline>,3,4`): spaces around the numbers are
/// what a user types; a line break is a script's mistake. The text is
/// echoed escaped, on one line.
fn no_control(spec: &str, input: Input, what: &str) -> Result<()> {
    if spec.chars().any(char::is_control) {
        let escaped: String = spec.escape_debug().collect();
        return Err(Error::invalid(
            input,
            format!(
                "invalid {what} '{}': a list holds no line break, tab or other control character",
                shorten(&escaped)
            ),
        ));
    }
    Ok(())
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
                return Err(Error::invalid(
                    Input::Angles,
                    format!(
                        "invalid range '{}': the step must be non-zero and lead from start to stop",
                        shorten(part)
                    ),
                ));
            }
            // A STOP the steps reach up to rounding is included (0:1:0.1
            // has 11 angles); 64 ulps rather than a fixed 1e-12, which
            // would add an angle to a range of 10¹² steps.
            let count = ((stop - start) / step * (1.0 + 64.0 * f64::EPSILON)).floor();
            if count.is_nan() || count >= MAX_RANGE {
                return Err(Error::invalid(
                    Input::Angles,
                    format!(
                        "invalid range '{}': more than {} angles",
                        shorten(part),
                        MAX_RANGE as u64
                    ),
                ));
            }
            Ok(AnglePart::Range {
                start,
                step,
                last: count as u64,
                stop,
            })
        }
        _ => Err(Error::invalid(
            Input::Angles,
            format!(
                "invalid angle '{}': expected degrees like 45 or a range START:STOP:STEP",
                shorten(part)
            ),
        )),
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
    no_control(spec, Input::Links, &format!("{name}s"))?;
    spec.split(',')
        .map(|t| {
            let t = t.trim();
            let v: f64 = match t {
                "inf" | "∞" if allow_inf => f64::INFINITY,
                _ => t.parse().map_err(|_| {
                    Error::invalid(
                        Input::Links,
                        format!("invalid {name} '{t}': expected a number"),
                    )
                })?,
            };
            if v.is_nan() || (v.is_infinite() && !allow_inf) {
                return Err(Error::invalid(
                    Input::Links,
                    format!("invalid {name} '{t}': expected a finite number"),
                ));
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
        // A step's rounding never carries the last angle past STOP:
        // 3 × 0.1 is 0.30000000000000004.
        assert_eq!(parse_angles("0:0.3:0.1").unwrap(), vec![0.0, 0.1, 0.2, 0.3]);
        assert_eq!(parse_angles("0.3:0:-0.1").unwrap().last(), Some(&0.0));
        for spec in ["0:0.7:0.1", "1:2.1:0.1", "-1:-0.3:0.1", "0.9:0.3:-0.2"] {
            let stop: f64 = spec.split(':').nth(1).unwrap().parse().unwrap();
            let step: f64 = spec.split(':').nth(2).unwrap().parse().unwrap();
            for a in parse_angles(spec).unwrap() {
                assert!((a - stop) * step <= 0.0, "{spec}: {a}");
            }
        }
        assert_eq!(parse_angles("10,20").unwrap(), vec![10.0, 20.0]);
        let spec = AngleSpec::parse("0:99999:1").unwrap();
        assert_eq!(spec.len(), 100_000);
        assert_eq!(spec.iter().last(), Some(99_999.0));
        // No cap on a range's length short of 2⁵³ angles: the commands
        // bound what they compute (GuardArgs).
        let spec = AngleSpec::parse("0:1e9:1e-3,5").unwrap();
        assert_eq!(spec.len(), 1_000_000_000_001 + 1);
        assert!(AngleSpec::parse("0:1e300:1e-300").is_err());
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
