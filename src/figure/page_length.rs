//! Page lengths with a unit: pixels (page units), millimetres,
//! centimetres, inches or points.
//!
//! A page unit is the SVG user unit, the CSS pixel: 1/96 in. A page asked
//! for in millimetres or inches is laid out at that size in page units (96
//! to the inch), and the SVG then gives its `width` and `height` in the
//! unit asked (`width="120mm"`), its `viewBox` still in page units, so that
//! a book places the figure at that size.

use crate::error::{Error, Field, Input, Result};
use std::fmt;
use std::str::FromStr;

/// Page units per inch (the CSS pixel).
pub const UNITS_PER_INCH: f64 = 96.0;

/// The unit of a page length.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum PageUnit {
    /// Page units (SVG user units, CSS pixels, 1/96 in); the SVG's size is
    /// written without a unit.
    #[default]
    Px,
    /// Millimetres.
    Mm,
    /// Inches.
    In,
    /// Centimetres.
    Cm,
    /// Points, 72 to the inch.
    Pt,
}

impl PageUnit {
    /// Every unit, page units first.
    pub const ALL: [PageUnit; 5] = [
        PageUnit::Px,
        PageUnit::Mm,
        PageUnit::Cm,
        PageUnit::In,
        PageUnit::Pt,
    ];

    /// The suffix: `px`, `mm`, `cm`, `in`, `pt` (also SVG's and CSS's).
    pub fn name(&self) -> &'static str {
        match self {
            PageUnit::Px => "px",
            PageUnit::Mm => "mm",
            PageUnit::In => "in",
            PageUnit::Cm => "cm",
            PageUnit::Pt => "pt",
        }
    }

    /// Page units in one of this unit (1, 96/25.4, 96/2.54, 96, 96/72).
    pub fn page_units(&self) -> f64 {
        match self {
            PageUnit::Px => 1.0,
            PageUnit::Mm => UNITS_PER_INCH / 25.4,
            PageUnit::In => UNITS_PER_INCH,
            PageUnit::Cm => UNITS_PER_INCH / 2.54,
            PageUnit::Pt => UNITS_PER_INCH / 72.0,
        }
    }

    /// Whether it is a physical unit (mm, cm, in, pt) rather than page
    /// units.
    pub fn is_physical(&self) -> bool {
        *self != PageUnit::Px
    }
}

impl fmt::Display for PageUnit {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for PageUnit {
    type Err = Error;

    fn from_str(s: &str) -> Result<Self> {
        match PageUnit::ALL.into_iter().find(|u| u.name() == s) {
            Some(u) => Ok(u),
            None => Err(Error::invalid(
                Input::PageLength,
                format!(
                    "unknown page unit '{}': expected px, mm, cm, in or pt",
                    s.escape_default()
                ),
            )),
        }
    }
}

/// A positive, finite page length in a [`PageUnit`]: `800` or `800px`
/// (page units), `120mm`, `4.5in`. Parsed with [`str::parse`] or made by
/// [`PageLength::new`], which refuse zero, negative and non-finite values.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PageLength {
    value: f64,
    unit: PageUnit,
}

impl PageLength {
    /// `value` in `unit`; positive and finite.
    pub fn new(value: f64, unit: PageUnit) -> Result<Self> {
        if !value.is_finite() {
            return Err(Error::NotFinite {
                name: Field::PageLength,
                value,
            });
        }
        if value <= 0.0 {
            return Err(Error::NotPositive {
                name: Field::PageLength,
                value,
            });
        }
        Ok(Self { value, unit })
    }

    /// The number as given.
    pub fn value(&self) -> f64 {
        self.value
    }

    /// The unit as given.
    pub fn unit(&self) -> PageUnit {
        self.unit
    }

    /// The length in page units (96 to the inch).
    pub fn page_units(&self) -> f64 {
        self.value * self.unit.page_units()
    }
}

impl FromStr for PageLength {
    type Err = Error;

    fn from_str(s: &str) -> Result<Self> {
        let shown: String = s.chars().take(40).flat_map(char::escape_default).collect();
        let bad = |why: &str| {
            Error::invalid(
                Input::PageLength,
                format!(
                    "invalid page length '{shown}': {why} (a positive number of px, the default, mm, cm, in or pt: 800, 120mm, 12cm, 4.5in, 340pt)"
                ),
            )
        };
        // NaN, inf and plain numbers are page units; then a known suffix;
        // other letters at the end are an unknown unit.
        let (number, unit) = if s.parse::<f64>().is_ok() {
            (s, PageUnit::Px)
        } else if let Some((n, u)) = PageUnit::ALL
            .into_iter()
            .find_map(|u| s.strip_suffix(u.name()).map(|n| (n, u)))
        {
            (n, u)
        } else {
            let n = s.trim_end_matches(char::is_alphabetic);
            if !n.is_empty() && n.len() < s.len() {
                let unit: String = s[n.len()..]
                    .chars()
                    .flat_map(char::escape_default)
                    .collect();
                return Err(bad(&format!("unknown unit '{unit}'")));
            }
            (s, PageUnit::Px)
        };
        let value: f64 = number.parse().map_err(|_| bad("not a number"))?;
        if !value.is_finite() {
            return Err(bad("not a finite number"));
        }
        if value <= 0.0 {
            return Err(bad("not positive"));
        }
        Ok(Self { value, unit })
    }
}

impl fmt::Display for PageLength {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        // In exponent form far from a page's sizes (`5e-324mm`, not 324
        // digits).
        let value = crate::number::plain(self.value);
        match self.unit {
            PageUnit::Px => write!(f, "{value}"),
            u => write!(f, "{value}{u}"),
        }
    }
}

impl<'de> serde::Deserialize<'de> for PageLength {
    /// A number (page units) or a text with its unit (`"120mm"`).
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> std::result::Result<Self, D::Error> {
        struct Visitor;
        impl serde::de::Visitor<'_> for Visitor {
            type Value = PageLength;

            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str(
                    "a page length: a number of px, or a text such as \"120mm\" or \"4.5in\"",
                )
            }

            fn visit_f64<E: serde::de::Error>(self, v: f64) -> std::result::Result<PageLength, E> {
                PageLength::new(v, PageUnit::Px).map_err(E::custom)
            }

            fn visit_i64<E: serde::de::Error>(self, v: i64) -> std::result::Result<PageLength, E> {
                self.visit_f64(v as f64)
            }

            fn visit_u64<E: serde::de::Error>(self, v: u64) -> std::result::Result<PageLength, E> {
                self.visit_f64(v as f64)
            }

            fn visit_str<E: serde::de::Error>(self, v: &str) -> std::result::Result<PageLength, E> {
                v.parse().map_err(E::custom)
            }
        }
        d.deserialize_any(Visitor)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lengths_parse_with_their_unit() {
        let l: PageLength = "120mm".parse().unwrap();
        assert_eq!((l.value(), l.unit()), (120.0, PageUnit::Mm));
        assert!((l.page_units() - 453.543_307_086_614_2).abs() < 1e-9);
        let l: PageLength = "4.5in".parse().unwrap();
        assert_eq!(l.page_units(), 432.0);
        for (text, units) in [("800", 800.0), ("800px", 800.0), ("1e3", 1000.0)] {
            assert_eq!(text.parse::<PageLength>().unwrap().page_units(), units);
        }
        assert_eq!("4.5in".parse::<PageLength>().unwrap().to_string(), "4.5in");
        assert_eq!("800".parse::<PageLength>().unwrap().to_string(), "800");
        // Centimetres and points as well (issue 22).
        let l: PageLength = "12cm".parse().unwrap();
        assert_eq!((l.value(), l.unit()), (12.0, PageUnit::Cm));
        assert!((l.page_units() - 120.0 * 96.0 / 25.4).abs() < 1e-9);
        assert_eq!("72pt".parse::<PageLength>().unwrap().page_units(), 96.0);
        assert_eq!("12cm".parse::<PageLength>().unwrap().to_string(), "12cm");
    }

    #[test]
    fn bad_lengths_are_refused_in_one_line() {
        for bad in [
            "-3mm",
            "0",
            "12parsecs",
            "NaN",
            "nanmm",
            "inf",
            "",
            "mm",
            "12 mm",
            "12km",
            "12e",
            "1e999in",
        ] {
            let e = bad.parse::<PageLength>().unwrap_err().to_string();
            assert!(e.starts_with("invalid page length"), "{bad}: {e}");
            assert!(!e.contains('\n'));
        }
        assert!(PageLength::new(f64::NAN, PageUnit::Mm).is_err());
        assert!(PageLength::new(-1.0, PageUnit::Px).is_err());
    }
}
