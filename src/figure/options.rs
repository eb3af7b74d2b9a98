//! What may be changed in a named figure ([`super::FigureName::figure`]).

use super::Font;
use crate::error::{Error, Result};
use crate::render::Style;
use crate::{Angle, SliderCrank};

/// Which calibration line `ng-fig-7-calibration` draws.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Fit {
    /// Least squares through the origin (Ng's spreadsheet trendline, whose
    /// uncentred R² is his 0.9998).
    Origin,
    /// Ordinary least squares with an intercept.
    Intercept,
    /// Both lines.
    #[default]
    Both,
}

impl Fit {
    /// The name on the command line: `origin`, `intercept`, `both`.
    pub fn name(&self) -> &'static str {
        match self {
            Fit::Origin => "origin",
            Fit::Intercept => "intercept",
            Fit::Both => "both",
        }
    }

    /// The fit of that name; the error lists the names.
    pub fn from_name(name: &str) -> Result<Self> {
        [Fit::Origin, Fit::Intercept, Fit::Both]
            .into_iter()
            .find(|f| f.name() == name)
            .ok_or_else(|| {
                Error::Parse(format!(
                    "unknown fit '{name}': expected origin, intercept or both"
                ))
            })
    }
}

/// Changes to a named figure; `None` keeps the figure's own value. A
/// figure that has no use for an option given refuses it (an error naming
/// the option) rather than ignoring it.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct FigureOptions {
    /// The mechanism (figures of the textbook: the §35 engine, r = 0.5 ft,
    /// l = 3 ft; Ng's: r = 25 mm, l = 72 mm).
    pub mechanism: Option<SliderCrank>,
    /// Crank speed ω in rad/s (default 250 rpm); the diagrams against time
    /// need it positive.
    pub omega: Option<f64>,
    /// The crank angle of the pose whose construction is drawn; for
    /// `ng-fig-2-incline`, the tilt of the plane (0° < φ < 90°).
    pub angle: Option<Angle>,
    /// The drawing style (default textbook).
    pub style: Option<Style>,
    /// The face of the text (default [`Font::NewComputerModern`]).
    pub font: Option<Font>,
    /// CSV text of measured data: columns `angle` and `force` for
    /// `ng-fig-8-forces` (Ng's measured F′ by default), `force` and
    /// `strain` for `ng-fig-7-calibration` (Ng's Table 1), the columns of
    /// `docs/curve-benchmarks.csv` for `curve-benchmark`.
    pub data: Option<String>,
    /// Which calibration line `ng-fig-7-calibration` draws (default both).
    pub fit: Option<Fit>,
}

impl FigureOptions {
    /// The names of the options that are set, as on the command line
    /// (`--data`), for refusing those a figure does not use.
    pub(crate) fn given(&self) -> Vec<&'static str> {
        let mut v = Vec::new();
        if self.mechanism.is_some() {
            v.push("mechanism (--crank, --rod, --offset)");
        }
        if self.omega.is_some() {
            v.push("crank speed (--rpm, --omega)");
        }
        if self.angle.is_some() {
            v.push("--angle");
        }
        if self.style.is_some() {
            v.push("--style");
        }
        if self.font.is_some() {
            v.push("--font");
        }
        if self.data.is_some() {
            v.push("--data");
        }
        if self.fit.is_some() {
            v.push("--fit");
        }
        v
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fit_names_round_trip() {
        for f in [Fit::Origin, Fit::Intercept, Fit::Both] {
            assert_eq!(Fit::from_name(f.name()).unwrap(), f);
        }
        assert!(
            Fit::from_name("linear")
                .unwrap_err()
                .to_string()
                .contains("origin")
        );
    }

    #[test]
    fn given_names_each_option_set() {
        let o = FigureOptions {
            data: Some(String::new()),
            fit: Some(Fit::Both),
            ..FigureOptions::default()
        };
        assert_eq!(o.given(), ["--data", "--fit"]);
        assert!(FigureOptions::default().given().is_empty());
    }
}
