//! The lists a user writes: crank angles (`45`, `0,30,60`, a range
//! `START:STOP:STEP`) and lists of numbers (`4,4.5,inf`), read once for
//! every front end; and the angles of a request, a written list or one
//! given as numbers ([`Angles`]).

use crate::error::{Error, Input, Result};

/// Most angles one range may describe: 2⁵³, past which the angles of a
/// range are no longer distinct numbers. What a command may compute is
/// bounded by the command's guard on its cost, not here.
pub const MAX_RANGE: f64 = 9_007_199_254_740_992.0;

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
    /// [`crate::table::MaxCells`]).
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

    /// Whether there is no angle (never, for a parsed specification: the
    /// empty text is refused).
    pub fn is_empty(&self) -> bool {
        self.count == 0
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

/// The crank angles of a request: a written specification, or angles
/// given as numbers (the Python package's array, read in place).
#[derive(Debug, Clone, PartialEq)]
pub enum Angles<'a> {
    /// A parsed specification ([`AngleSpec::parse`]).
    Spec(AngleSpec),
    /// Angles in degrees, each to be checked finite
    /// ([`Angles::check`]); an empty list has no angle.
    List(&'a [f64]),
}

impl Angles<'_> {
    /// The angles in order.
    pub fn iter(&self) -> impl Iterator<Item = f64> + '_ {
        let (spec, list) = match self {
            Angles::Spec(s) => (Some(s.iter()), None),
            Angles::List(l) => (None, Some(l.iter().copied())),
        };
        spec.into_iter().flatten().chain(list.into_iter().flatten())
    }

    /// How many angles there are.
    pub fn len(&self) -> u64 {
        match self {
            Angles::Spec(s) => s.len(),
            Angles::List(l) => l.len() as u64,
        }
    }

    /// Whether there is no angle (only a list given as numbers may be
    /// empty).
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Refuses an angle given as a number that is not finite, as
    /// [`AngleSpec::parse`] refuses it written.
    pub fn check(&self) -> Result<()> {
        match self {
            Angles::Spec(_) => Ok(()),
            Angles::List(l) => match l.iter().find(|a| !a.is_finite()) {
                Some(a) => Err(Error::invalid(
                    Input::Angles,
                    format!("invalid angle '{a}': the angle must be a finite number of degrees"),
                )),
                None => Ok(()),
            },
        }
    }
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
        // bound what they compute (MaxCells).
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
