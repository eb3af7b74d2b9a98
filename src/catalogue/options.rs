//! What may be changed in a named figure ([`super::FigureName::figure`]).

use crate::error::{Error, Field, Input, Result, Wording};
use crate::figure::{Font, PageLength, PageUnit, Style, Title};
use crate::scene::Page;
use crate::{angle::Angle, mechanism::SliderCrank, scene::Layer, scene::Notation, units::Unit};

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

crate::error::parse_by_name!(Fit);

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
                Error::invalid(
                    Input::Fit,
                    format!("unknown fit '{name}': expected origin, intercept or both"),
                )
            })
    }
}

/// Changes to a named figure; `None` keeps the figure's own value. A
/// figure that has no use for an option given refuses it (an error naming
/// the option) rather than ignoring it. The units, the page size and the
/// title are taken by every figure: a figure that writes no force (or no
/// length) has nowhere to name that unit, and its metadata keeps the
/// length unit.
///
/// Options may be added in later versions: start from
/// [`FigureOptions::default`] and set the fields wanted.
///
/// ```
/// use slider_crank::{FigureName, catalogue::{FigureOptions, Fit}};
/// let mut options = FigureOptions::default();
/// options.fit = Some(Fit::Origin);
/// let figure = FigureName::NgFig7Calibration.figure(&options)?;
/// # Ok::<(), slider_crank::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq, Default)]
#[non_exhaustive]
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
    /// The layers of a mechanism figure (default: the seed's).
    pub layers: Option<Vec<Layer>>,
    /// CSV text of measured data: columns `angle` and `force` for
    /// `ng-fig-8-forces` (Ng's measured F′ by default), `force` and
    /// `strain` for `ng-fig-7-calibration` (Ng's Table 1), the columns of
    /// `docs/curve-benchmarks.csv` for `curve-benchmark`.
    pub data: Option<String>,
    /// Which calibration line `ng-fig-7-calibration` draws (default both).
    pub fit: Option<Fit>,
    /// The name of the length unit the mechanism is given in (the
    /// figure's own by default: `ft` for the textbook's, `mm` for Ng's);
    /// speeds are written in it per second. A name only: no number is
    /// converted.
    pub length_unit: Option<Unit>,
    /// The name of the force unit; torques are written force·length. By
    /// default the one that goes with [`FigureOptions::length_unit`] (`N`
    /// for `mm`, `lbf` for `in`: [`crate::units::Unit::usual_force`]), else the
    /// figure's own (`lbf` for the textbook's, `N` for Ng's).
    pub force_unit: Option<Unit>,
    /// The letters of a mechanism figure (default: the seed's).
    pub notation: Option<Notation>,
    /// The reciprocating mass m (piston and cross-head) of the engine
    /// dynamics figures (`turning-moment`, `inertia-force`,
    /// `primary-secondary`, `direct-reverse-cranks`), in the unit that
    /// makes mass × length/s² the force unit (slug, lbf·s²/ft, for the
    /// §35 engine in feet); default 10 ([`crate::dynamics::EXAMPLE_MASS`]).
    /// The figures that draw the inertia force need it positive.
    pub mass: Option<f64>,
    /// The coefficient of fluctuation of speed C_s = (ω_max − ω_min)/ω of
    /// the `flywheel` figure, 0 < C_s < 2 (default 0.02).
    pub fluctuation: Option<f64>,
    /// The cylinder's bore D, in the length unit, on which the indicator
    /// diagram of `turning-moment` and `flywheel` ([`FigureOptions::data`])
    /// acts (default the example's 10 in, in feet and pounds-force only).
    pub bore: Option<f64>,
    /// A constant gas force on the piston of `turning-moment` and
    /// `flywheel`, positive towards the crank centre, in the force unit, in
    /// place of an indicator diagram.
    pub gas_force: Option<f64>,
    /// Whether the mechanism is drawn mirrored, the cylinder on the left
    /// (default: the seed's, mirrored for the textbook, not for Ng); the
    /// mechanism figures and the diagrams drawn on the mechanism
    /// (`fig-61-centrodes`, `fig-64-velocity-diagrams`, `coupler-curves`).
    pub mirror: Option<bool>,
    /// The page's width (default the figure's own); in mm, cm, in or pt, the SVG
    /// gives its size in that unit ([`crate::scene::Page::sized`]).
    pub width: Option<PageLength>,
    /// The page's height (default the figure's own, which a mechanism
    /// figure's enlarged detail grows): given, a mechanism figure ends
    /// within it or is refused naming the height it needs
    /// ([`crate::scene::Page::with_fixed_height`]); a diagram lays its bands out
    /// on it.
    pub height: Option<PageLength>,
    /// A title, set below the figure and written as the SVG's `<title>`.
    pub title: Option<Title>,
    /// The point of the rod's plane a mechanism figure marks Q, whose
    /// path the coupler layer draws and whose images the polygons layer
    /// draws (default the rod's middle); off the rod's line, the rod is
    /// drawn as the plate ABQ and the polygons with their triangles abq
    /// and a′b′q′.
    pub coupler: Option<crate::construct::CouplerPoint>,
    /// The connecting rod's mass m_r of `crank-pin-loads`, in the mass
    /// unit (default 0.6 times the reciprocating mass); 0 is a massless
    /// rod, whose curve is then the dashed one's.
    pub rod_mass: Option<f64>,
    /// The distance BG of the rod's centre of mass from the crank pin of
    /// `crank-pin-loads`, in the length unit, 0 ≤ BG ≤ l (default l/3).
    pub rod_cg: Option<f64>,
    /// The rod's radius of gyration k about its centre of mass, of
    /// `crank-pin-loads`, in the length unit (default 0.3 l).
    pub rod_gyration: Option<f64>,
    /// The cranks of `inline-balance`, each cylinder's in degrees ahead
    /// of the first's (default 0, 120, 240: three cylinders at 120°).
    pub cranks: Option<Vec<f64>>,
    /// The planes of `inline-balance`'s cylinders, each line of stroke's
    /// distance from the reference plane along the shaft, in pitches, one
    /// for each crank (default a pitch of 1 about the middle cylinder).
    pub planes: Option<Vec<f64>>,
    /// A vertical engine's gravity along the line of stroke, of
    /// `turning-moment`, `flywheel` and `crank-pin-loads` (standard
    /// gravity in the length unit; default none).
    pub gravity: Option<crate::dynamics::Gravity>,
    /// The slider's coefficient of friction in its guides, of
    /// `turning-moment`, `flywheel` and `crank-pin-loads` (default 0).
    pub friction: Option<f64>,
}

/// One of the things a named figure may take from its options: each
/// figure's spec lists those it takes, and a figure refuses any other
/// that is given.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Setting {
    /// The mechanism (its crank, rod and offset).
    Mechanism,
    /// The crank speed (in rpm or as ω).
    Speed,
    /// The crank angle of the pose drawn, or the plane's tilt.
    Angle,
    /// The drawing style.
    Style,
    /// The face of the text.
    Font,
    /// The layers of a mechanism figure.
    Layers,
    /// Measured data.
    Data,
    /// The calibration line.
    Fit,
    /// The letters of a mechanism figure.
    Notation,
    /// The mechanism drawn mirrored or not.
    Mirror,
    /// The reciprocating mass.
    Mass,
    /// The coefficient of fluctuation of speed.
    Fluctuation,
    /// The bore of the indicator diagram's cylinder.
    Bore,
    /// A constant gas force.
    GasForce,
    /// The coupler point Q.
    Coupler,
    /// The connecting rod's mass, centre of mass and radius of gyration.
    Rod,
    /// The cylinders of an in-line engine: their cranks and planes.
    Cylinders,
    /// Gravity along a vertical engine's line of stroke.
    Gravity,
    /// The slider's friction in its guides.
    Friction,
}

impl Setting {
    /// How a message names it, by its fields (`angle`, `mechanism
    /// (crank, rod, offset)`), which each front end spells its way: the
    /// library's refusal ([`super::FigureName::figure`]: `rod-motion does
    /// not use data`) is what every caller prints.
    pub(crate) fn wording(self) -> Wording {
        let field = match self {
            Setting::Mechanism => {
                return Wording::from("mechanism (")
                    .option(Field::Crank)
                    .then(", ")
                    .option(Field::Rod)
                    .then(", ")
                    .option(Field::Offset)
                    .then(")");
            }
            Setting::Speed => {
                return Wording::from("crank speed (")
                    .option(Field::Rpm)
                    .then(", ")
                    .option(Field::Omega)
                    .then(")");
            }
            Setting::Angle => Field::Angle,
            Setting::Style => Field::Style,
            Setting::Font => Field::Font,
            Setting::Layers => Field::Layers,
            Setting::Data => Field::Data,
            Setting::Fit => Field::Fit,
            Setting::Notation => Field::Notation,
            Setting::Mirror => Field::Mirror,
            Setting::Mass => Field::Mass,
            Setting::Fluctuation => Field::Fluctuation,
            Setting::Bore => Field::Bore,
            Setting::GasForce => Field::GasForce,
            Setting::Coupler => Field::Coupler,
            Setting::Gravity => Field::Gravity,
            Setting::Friction => Field::Friction,
            Setting::Rod => {
                return Wording::from("rod (")
                    .option(Field::RodMass)
                    .then(", ")
                    .option(Field::RodCg)
                    .then(", ")
                    .option(Field::RodGyration)
                    .then(")");
            }
            Setting::Cylinders => {
                return Wording::from("cylinders (")
                    .option(Field::Cranks)
                    .then(", ")
                    .option(Field::Plane)
                    .then(")");
            }
        };
        Wording::default().option(field)
    }
}

impl FigureOptions {
    /// The options that are set, in the order of [`Setting`], for refusing
    /// those a figure does not take.
    pub(crate) fn given(&self) -> Vec<Setting> {
        [
            (self.mechanism.is_some(), Setting::Mechanism),
            (self.omega.is_some(), Setting::Speed),
            (self.angle.is_some(), Setting::Angle),
            (self.style.is_some(), Setting::Style),
            (self.font.is_some(), Setting::Font),
            (self.layers.is_some(), Setting::Layers),
            (self.data.is_some(), Setting::Data),
            (self.fit.is_some(), Setting::Fit),
            (self.notation.is_some(), Setting::Notation),
            (self.mirror.is_some(), Setting::Mirror),
            (self.mass.is_some(), Setting::Mass),
            (self.fluctuation.is_some(), Setting::Fluctuation),
            (self.bore.is_some(), Setting::Bore),
            (self.gas_force.is_some(), Setting::GasForce),
            (self.coupler.is_some(), Setting::Coupler),
            (
                self.rod_mass.is_some() || self.rod_cg.is_some() || self.rod_gyration.is_some(),
                Setting::Rod,
            ),
            (
                self.cranks.is_some() || self.planes.is_some(),
                Setting::Cylinders,
            ),
            (self.gravity.is_some(), Setting::Gravity),
            (self.friction.is_some(), Setting::Friction),
        ]
        .into_iter()
        .filter_map(|(set, s)| set.then_some(s))
        .collect()
    }

    /// `page` with the width and height asked for in place of its own;
    /// the SVG's size is then in the unit of the width if that is physical,
    /// else in that of the height. A height asked for alone leaves the
    /// width to be narrowed to the drawing where `page`'s would be.
    pub(crate) fn page(&self, page: &Page) -> Result<Page> {
        if self.width.is_none() && self.height.is_none() {
            return Ok(*page);
        }
        let own = |v: f64| PageLength::new(v, PageUnit::Px);
        let sized = Page::sized(
            self.width.map_or_else(|| own(page.width()), Ok)?,
            self.height.map_or_else(|| own(page.height()), Ok)?,
            page.margin(),
        )?;
        // A width not asked for is narrowed as the figure's own would be.
        let sized = match self.width {
            None if page.fits_width() => sized.with_width_fitted(),
            _ => sized,
        };
        // A height asked for is the page's: the figure ends within it.
        Ok(match self.height {
            Some(_) => sized.with_fixed_height(),
            None if page.has_fixed_height() => sized.with_fixed_height(),
            None => sized,
        })
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
        assert_eq!(o.given(), [Setting::Data, Setting::Fit]);
        assert_eq!(
            Setting::Data.wording().fields().collect::<Vec<_>>(),
            [Field::Data]
        );
        assert_eq!(
            Setting::Mechanism.wording().to_string(),
            "mechanism (`crank`, `rod`, `offset`)"
        );
        assert!(FigureOptions::default().given().is_empty());
    }
}
