//! Plot axes: a range of values, linear or logarithmic, with round ticks
//! and their labels.

use crate::error::{Error, Field, Result, finite};
use crate::figure::RichText;
use crate::number::{format_number, power_of_ten};

/// How an axis places values.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Scale {
    /// Equal steps of value are equal lengths; the world coordinate is the
    /// value.
    Linear,
    /// Equal ratios are equal lengths; the world coordinate is log₁₀ of the
    /// value, which must be positive.
    Log,
}

/// One tick of an axis.
#[derive(Debug, Clone, PartialEq)]
pub struct Tick {
    /// The value it marks.
    pub value: f64,
    /// Its label; `None` for a minor tick (log axes: 2 … 9 × 10ᵏ).
    pub label: Option<String>,
}

/// An axis: a title (with its unit), a range of values, a scale and the
/// step of its ticks.
///
/// Ticks of a linear axis are the multiples of the step inside the range,
/// labelled with as many decimals as the step needs and a true minus sign;
/// a log axis has a labelled tick at each power of ten (10ᵏ) and minor
/// ticks between. The range may be widened to round values with
/// [`Axis::nice`] and [`Axis::log`].
#[derive(Debug, Clone, PartialEq)]
pub struct Axis {
    title: String,
    min: f64,
    max: f64,
    scale: Scale,
    step: f64,
}

/// How many labelled ticks a linear axis aims at.
const TARGET_TICKS: f64 = 6.0;

/// Largest |value| an axis shows: 1e300, so that spans, round steps and
/// the page map of values up to it stay finite (any unit: choose one that
/// brings the data in range).
pub const MAX_AXIS_VALUE: f64 = 1e300;

/// Smallest positive value a log axis shows (its decades stay normal
/// numbers, 10⁻³⁰⁰ … 10³⁰⁰).
pub const MIN_LOG_VALUE: f64 = 1e-300;

/// Most decades of a log axis (9 ticks each).
pub const MAX_DECADES: f64 = 100.0;

/// The largest |end| of a linear axis labelled in plain digits: from it
/// on, a power of ten is taken into the title ([`Axis::shared_power`]).
pub const LARGEST_PLAIN_LABEL: f64 = 1e5;

/// The smallest step of a linear axis labelled in plain digits.
pub const SMALLEST_PLAIN_STEP: f64 = 1e-4;

/// Checks that `value` is finite and within ±[`MAX_AXIS_VALUE`].
fn axis_value(name: Field, value: f64) -> Result<f64> {
    let value = finite(name, value)?;
    if value.abs() > MAX_AXIS_VALUE {
        return Err(Error::OutOfRange {
            name,
            value,
            reason: format!(
                "a plot shows values within ±{MAX_AXIS_VALUE:e} (give the data in a larger unit)"
            ),
        });
    }
    Ok(value)
}

/// The round step (1, 2, 2.5 or 5 × 10ᵏ) nearest above `span / target`.
fn round_step(span: f64, target: f64) -> f64 {
    let raw = span / target;
    let mag = 10f64.powf(raw.log10().floor());
    [1.0, 2.0, 2.5, 5.0, 10.0]
        .iter()
        .map(|k| k * mag)
        .find(|s| *s >= raw * (1.0 - 1e-9))
        .unwrap_or(10.0 * mag)
}

/// Decimals needed to write multiples of `step` exactly (at most 9).
fn decimals(step: f64) -> usize {
    (0..=9)
        .find(|d| {
            let v = step * 10f64.powi(*d as i32);
            (v - v.round()).abs() <= 1e-6 * v.abs().max(1e-300)
        })
        .unwrap_or(9)
}

impl Axis {
    /// The label of the `k`-th multiple of the step, in the unit the
    /// title names (a shared power of ten taken out, [`Axis::shared_power`]).
    fn label(&self, k: i64) -> String {
        let unit = 10f64.powi(self.shared_power().unwrap_or(0));
        format_number(k as f64 * self.step / unit, decimals(self.step / unit))
    }

    /// The power of ten a linear axis's labels share, named once in its
    /// title (`d²s/dt² (10⁶ ft/s²)`, labels 0.5 … 1.5) rather than in six
    /// or more digits on every tick (`1500000`) or a power on each
    /// (`2×10⁹⁹`): a multiple of 3 at or below the largest |end|, where
    /// that is 10⁵ or more or the step is below 10⁻⁴. `None` otherwise
    /// and on a log axis (its labels are powers already).
    pub fn shared_power(&self) -> Option<i32> {
        let largest = self.min.abs().max(self.max.abs());
        let wanted = self.scale == Scale::Linear
            && largest > 0.0
            && (largest >= LARGEST_PLAIN_LABEL || self.step < SMALLEST_PLAIN_STEP);
        wanted.then(|| 3 * (largest.log10() / 3.0).floor() as i32)
    }

    /// A linear axis over `[min, max]` (finite, min < max) with a round
    /// step of about six ticks. The title is [`RichText`] markup
    /// (`V_p (ft/s)`).
    pub fn linear(title: &str, min: f64, max: f64) -> Result<Self> {
        let min = axis_value(Field::AxisMinimum, min)?;
        let max = axis_value(Field::AxisMaximum, max)?;
        let span = max - min;
        if !(span > 0.0 && span.is_finite()) {
            return Err(Error::OutOfRange {
                name: Field::AxisMaximum,
                value: max,
                reason: format!("an axis must increase from its minimum {min}"),
            });
        }
        Ok(Self {
            title: title.to_string(),
            min,
            max,
            scale: Scale::Linear,
            step: round_step(span, TARGET_TICKS),
        })
    }

    /// A linear axis that covers `[lo, hi]`, widened outwards to the
    /// nearest round ticks. An empty range (lo = hi) is widened by 1 or by
    /// a tenth of |lo| each way. Errors for non-finite or reversed bounds.
    pub fn nice(title: &str, lo: f64, hi: f64) -> Result<Self> {
        let lo = axis_value(Field::AxisMinimum, lo)?;
        let hi = axis_value(Field::AxisMaximum, hi)?;
        if lo > hi {
            return Err(Error::OutOfRange {
                name: Field::AxisMaximum,
                value: hi,
                reason: format!("below the axis minimum {lo}"),
            });
        }
        let (lo, hi) = if hi - lo <= 1e-12 * lo.abs().max(hi.abs()) {
            let d = if lo == 0.0 { 1.0 } else { 0.1 * lo.abs() };
            (lo - d, hi + d)
        } else {
            (lo, hi)
        };
        // Halves: hi − lo may exceed the largest f64, hi/2 − lo/2 cannot.
        let step = round_step(hi / 2.0 - lo / 2.0, TARGET_TICKS / 2.0);
        let min = (lo / step + 1e-9).floor() * step;
        let max = (hi / step - 1e-9).ceil() * step;
        let mut axis = Self::linear(title, min, max)?;
        axis.step = step;
        Ok(axis)
    }

    /// A logarithmic axis covering `[lo, hi]` (1e-300 ≤ lo ≤ hi ≤ 1e300),
    /// widened outwards to whole powers of ten; at most 100 decades.
    pub fn log(title: &str, lo: f64, hi: f64) -> Result<Self> {
        let lo = axis_value(Field::AxisMinimum, lo)?;
        let hi = axis_value(Field::AxisMaximum, hi)?;
        if !(lo > 0.0 && hi >= lo) {
            return Err(Error::OutOfRange {
                name: Field::AxisMinimum,
                value: lo,
                reason: format!("a log axis needs 0 < minimum ≤ maximum ({hi})"),
            });
        }
        if lo < MIN_LOG_VALUE {
            return Err(Error::OutOfRange {
                name: Field::AxisMinimum,
                value: lo,
                reason: format!(
                    "a log axis shows values from {MIN_LOG_VALUE:e} (give the data in a smaller unit)"
                ),
            });
        }
        if hi.log10() - lo.log10() > MAX_DECADES {
            return Err(Error::OutOfRange {
                name: Field::AxisMaximum,
                value: hi,
                reason: format!(
                    "a log axis shows at most {MAX_DECADES} decades (the minimum is {lo:e})"
                ),
            });
        }
        let a = (lo.log10() + 1e-9).floor();
        let mut b = (hi.log10() - 1e-9).ceil();
        if b <= a {
            b = a + 1.0;
        }
        Ok(Self {
            title: title.to_string(),
            min: 10f64.powf(a),
            max: 10f64.powf(b),
            scale: Scale::Log,
            step: 1.0,
        })
    }

    /// The same axis with ticks at the multiples of `step` (finite,
    /// positive, at most 1000 ticks over the range): 30° for crank angles.
    /// Ignored by a log axis.
    pub fn with_step(mut self, step: f64) -> Result<Self> {
        let step = crate::error::positive(Field::TickStep, step)?;
        if (self.max - self.min) / step > 1000.0 {
            return Err(Error::OutOfRange {
                name: Field::TickStep,
                value: step,
                reason: "more than 1000 ticks on one axis".into(),
            });
        }
        if self.scale == Scale::Linear {
            self.step = step;
        }
        Ok(self)
    }

    /// The title, with the labels' shared power of ten put in its unit:
    /// `d²s/dt² (ft/s²)` reads `d²s/dt² (10⁶ ft/s²)`; a title with no unit
    /// in brackets at its end gets `(×10⁶)`.
    pub fn title(&self) -> RichText {
        let Some(p) = self.shared_power() else {
            return RichText::parse(&self.title);
        };
        let power = power_of_ten(p);
        let title = self.title.trim_end();
        let markup = match title.rfind('(') {
            Some(i) if title.ends_with(')') => {
                let (head, unit) = title.split_at(i + 1);
                format!("{head}{power} {unit}")
            }
            _ => format!("{title} (×{power})"),
        };
        RichText::parse(&markup)
    }

    /// The range of values, `(min, max)`.
    pub fn range(&self) -> (f64, f64) {
        (self.min, self.max)
    }

    /// The scale.
    pub fn scale(&self) -> Scale {
        self.scale
    }

    /// The step of labelled ticks on a linear axis (1 decade on a log axis).
    pub fn step(&self) -> f64 {
        self.step
    }

    /// The world coordinate of a value: the value itself, or its log₁₀ on a
    /// log axis (`None` there for a value ≤ 0 or not finite).
    pub fn world(&self, value: f64) -> Option<f64> {
        match self.scale {
            Scale::Linear => value.is_finite().then_some(value),
            Scale::Log => (value > 0.0 && value.is_finite()).then(|| value.log10()),
        }
    }

    /// The world coordinates of the ends, `(min, max)`.
    pub fn world_range(&self) -> (f64, f64) {
        match self.scale {
            Scale::Linear => (self.min, self.max),
            Scale::Log => (self.min.log10().round(), self.max.log10().round()),
        }
    }

    /// The ticks in increasing order. Labels of a linear axis are in the
    /// unit its title names, a shared power of ten taken out where one is
    /// ([`Axis::shared_power`]).
    pub fn ticks(&self) -> Vec<Tick> {
        match self.scale {
            Scale::Linear => {
                let first = (self.min / self.step - 1e-9).ceil() as i64;
                let last = (self.max / self.step + 1e-9).floor() as i64;
                (first..=last)
                    .map(|k| {
                        let value = k as f64 * self.step;
                        Tick {
                            value,
                            label: Some(self.label(k)),
                        }
                    })
                    .collect()
            }
            Scale::Log => {
                let (a, b) = self.world_range();
                let (a, b) = (a as i32, b as i32);
                let mut ticks = Vec::new();
                for k in a..=b {
                    let decade = 10f64.powi(k);
                    ticks.push(Tick {
                        value: decade,
                        label: Some(power_of_ten(k)),
                    });
                    if k < b {
                        ticks.extend((2..=9).map(|m| Tick {
                            value: m as f64 * decade,
                            label: None,
                        }));
                    }
                }
                ticks
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn labels(axis: &Axis) -> Vec<String> {
        axis.ticks().into_iter().filter_map(|t| t.label).collect()
    }

    #[test]
    fn nice_ranges_end_on_round_ticks() {
        let a = Axis::nice("v", -13.7, 13.2).unwrap();
        assert_eq!(a.range(), (-15.0, 15.0));
        assert_eq!(a.step(), 5.0);
        assert_eq!(labels(&a), ["−15", "−10", "−5", "0", "5", "10", "15"]);
        let t = Axis::nice("t", 0.0, 0.24).unwrap();
        assert_eq!(t.step(), 0.05);
        assert_eq!(labels(&t), ["0.00", "0.05", "0.10", "0.15", "0.20", "0.25"]);
        let q = Axis::nice("q", 0.0, 9.0).unwrap();
        assert_eq!(q.step(), 2.0);
        assert_eq!(q.range(), (0.0, 10.0));
    }

    #[test]
    fn explicit_steps_and_quarter_steps() {
        let a = Axis::linear("θ (°)", 0.0, 360.0)
            .unwrap()
            .with_step(30.0)
            .unwrap();
        assert_eq!(a.ticks().len(), 13);
        assert_eq!(labels(&a)[12], "360");
        let b = Axis::linear("x", 0.0, 10.0)
            .unwrap()
            .with_step(2.5)
            .unwrap();
        assert_eq!(labels(&b), ["0.0", "2.5", "5.0", "7.5", "10.0"]);
        assert!(
            Axis::linear("x", 0.0, 1.0)
                .unwrap()
                .with_step(1e-6)
                .is_err()
        );
        assert!(Axis::linear("x", 0.0, 1.0).unwrap().with_step(0.0).is_err());
    }

    #[test]
    fn log_axes_have_decades_and_minor_ticks() {
        let a = Axis::log("error (px)", 3e-6, 0.09).unwrap();
        assert_eq!(a.range(), (1e-6, 0.1));
        assert_eq!(a.world_range(), (-6.0, -1.0));
        assert_eq!(labels(&a), ["10⁻⁶", "10⁻⁵", "10⁻⁴", "10⁻³", "10⁻²", "10⁻¹"]);
        assert_eq!(a.ticks().len(), 6 + 5 * 8);
        assert_eq!(a.world(100.0), Some(2.0));
        assert_eq!(a.world(0.0), None);
        let one = Axis::log("n", 10.0, 10.0).unwrap();
        assert_eq!(one.range(), (10.0, 100.0));
    }

    #[test]
    fn bad_ranges_are_errors() {
        assert!(Axis::linear("x", 1.0, 1.0).is_err());
        assert!(Axis::linear("x", f64::NAN, 1.0).is_err());
        assert!(Axis::nice("x", 2.0, 1.0).is_err());
        assert!(Axis::log("x", 0.0, 1.0).is_err());
        assert!(Axis::log("x", 1.0, f64::INFINITY).is_err());
        // An empty range is widened, not refused.
        assert_eq!(Axis::nice("x", 0.0, 0.0).unwrap().range(), (-1.0, 1.0));
    }

    #[test]
    fn extreme_ranges_are_refused_or_drawn_finite() {
        // Issue 9 (2): 5e-324 gave a world range of (−inf, 0).
        let err = Axis::log("t", 5e-324, 1.0).unwrap_err().to_string();
        assert!(err.contains("a log axis shows values from 1e-300"), "{err}");
        let a = Axis::log("t", 1e-300, 1e-250).unwrap();
        assert_eq!(a.world_range(), (-300.0, -250.0));
        assert!(Axis::log("t", 1e-200, 1e200).is_err());
        // Issue 9 (9): ±1e308 said "axis minimum must be a finite number, got NaN".
        let err = Axis::nice("F", -1e308, 1e308).unwrap_err().to_string();
        assert!(err.contains("a plot shows values within ±1e300"), "{err}");
        let a = Axis::nice("F", -1e300, 1e300).unwrap();
        let (lo, hi) = a.range();
        assert!(lo.is_finite() && hi.is_finite() && lo <= -1e300 && hi >= 1e300);
    }

    #[test]
    fn huge_and_tiny_steps_are_labelled_with_a_power_of_ten() {
        // Issue 9 (9): 100-digit labels left no room for the plot. The
        // power is named once, in the title.
        let a = Axis::nice("v", 0.0, 9e99).unwrap();
        assert_eq!(a.step(), 2e99);
        assert_eq!(labels(&a), ["0", "2", "4", "6", "8", "10"]);
        assert_eq!(a.title().plain(), "v (×10⁹⁹)");
        let b = Axis::nice("x (m)", 0.0, 2.4e-6).unwrap();
        assert_eq!(labels(&b)[1], "0.5");
        assert_eq!(b.title().plain(), "x (10⁻⁶ m)");
    }

    #[test]
    fn six_digit_labels_share_their_power_in_the_unit() {
        // The Whitworth quick return at l = 1.03 r: ticks of 1500000 ft/s².
        let a = Axis::nice("d²*s*/d*t*² (ft/s²)", -1.45e6, 1.42e6).unwrap();
        assert_eq!(a.shared_power(), Some(6));
        assert_eq!(labels(&a)[0], "−1.5");
        assert_eq!(labels(&a).last().map(String::as_str), Some("1.5"));
        assert_eq!(a.title().plain(), "d²s/dt² (10⁶ ft/s²)");
        let b = Axis::nice("F (lbf)", 0.0, 180000.0).unwrap();
        assert_eq!(b.shared_power(), Some(3));
        assert!(
            labels(&b).iter().all(|l| l.chars().count() <= 3),
            "{:?}",
            labels(&b)
        );
        // Below 10⁵ the digits stay as they are, the title untouched.
        let c = Axis::nice("F (lbf)", 0.0, 79000.0).unwrap();
        assert_eq!(c.shared_power(), None);
        assert_eq!(labels(&c).last().map(String::as_str), Some("80000"));
        assert_eq!(c.title().plain(), "F (lbf)");
    }

    #[test]
    fn numbers_use_a_true_minus_and_no_negative_zero() {
        assert_eq!(format_number(-0.0001, 2), "0.00");
        assert_eq!(format_number(-2.5, 1), "−2.5");
        assert_eq!(format_number(3.0, 0), "3");
        assert_eq!(format_number(-1e308, 2), "−1.00e308");
        // Every double in bounded width, a true minus, never "inf".
        let mut x = 5e-324_f64;
        while x.is_finite() {
            for v in [x, -x] {
                for decimals in [0, 2, 9] {
                    let s = format_number(v, decimals);
                    assert!(s.chars().count() <= 17 + decimals, "{v:e}: {s}");
                    let text = s.replace('\u{2212}', "-");
                    if let Some((mantissa, _)) = text.split_once('e') {
                        assert!(v.abs() >= 1e15, "{v:e}: {s}");
                        let m: f64 = mantissa.parse().unwrap();
                        assert!((1.0..=10.0).contains(&m.abs()), "{v:e}: {s}");
                    } else {
                        let back: f64 = text.parse().unwrap();
                        let half = 0.5 * 10f64.powi(-(decimals as i32));
                        assert!((back - v).abs() <= half + 1e-15 * v.abs(), "{v:e}: {s}");
                    }
                }
            }
            // 1.37 × the least subnormal rounds back to it: step at least an ulp.
            x = (x * 1.37).max(f64::from_bits(x.to_bits() + 1));
        }
    }
}
