//! The request of a named figure as a front end gives it: every option
//! as the user wrote it, the same for the command line (its flags), the
//! Python package (its keywords) and the explorer, validated once here
//! and resolved against the figure into its [`FigureOptions`].

use super::{FigureName, FigureOptions, Fit};
pub use crate::analytic::kinematics::crank_speed;
use crate::construct::CouplerPoint;
use crate::error::{Error, Field, Input, Result, Wording};
use crate::figure::{Font, PageLength, Style, Title};
use crate::{mechanism::SliderCrank, scene::Layer, scene::Notation, units::Unit};

/// What a user asks of a named figure; `None` leaves the figure's own
/// value (the §35 engine's r = 0.5 ft, l = 3 ft and 250 rpm for the
/// textbook's figures, Ng's rig for his: [`crate::sources`]). Each field
/// is the option of its name on every front end ([`Field::key`]): the
/// field `crank` is the command line's option and the Python package's
/// keyword of that name. [`FigureRequest::options`] checks it.
///
/// Fields may be added in later versions: start from
/// [`FigureRequest::default`] and set the fields wanted.
#[derive(Debug, Clone, Default, PartialEq)]
#[non_exhaustive]
pub struct FigureRequest {
    /// The crank radius r; any of the three lengths given, the others are
    /// the figure's own.
    pub crank: Option<f64>,
    /// The rod length l.
    pub rod: Option<f64>,
    /// The offset e of the line of stroke.
    pub offset: Option<f64>,
    /// The crank angle in degrees of the pose drawn; for
    /// `ng-fig-2-incline` the tilt of the plane ([`FigureName::angle`]).
    pub angle: Option<f64>,
    /// The crank speed in revolutions per minute (not with `omega`).
    pub rpm: Option<f64>,
    /// The crank speed ω in rad/s (not with `rpm`).
    pub omega: Option<f64>,
    /// The layers of a mechanism figure ([`Layer::parse_list`] reads a
    /// list); an empty list is refused.
    pub layers: Option<Vec<Layer>>,
    /// The drawing style.
    pub style: Option<Style>,
    /// The face of the text.
    pub font: Option<Font>,
    /// The measured data, CSV text ([`FigureOptions::data`]).
    pub data: Option<String>,
    /// The calibration line of `ng-fig-7-calibration`.
    pub fit: Option<Fit>,
    /// The name of the length unit.
    pub unit: Option<Unit>,
    /// The name of the force unit.
    pub force_unit: Option<Unit>,
    /// The letters of a mechanism figure.
    pub notation: Option<Notation>,
    /// The reciprocating mass m of the engine dynamics figures.
    pub mass: Option<f64>,
    /// The coefficient of fluctuation of speed of the flywheel figure.
    pub fluctuation: Option<f64>,
    /// The bore D of the indicator diagram's cylinder.
    pub bore: Option<f64>,
    /// A constant gas force on the piston.
    pub gas_force: Option<f64>,
    /// Whether the mechanism is drawn mirrored.
    pub mirror: Option<bool>,
    /// The page's width.
    pub width: Option<PageLength>,
    /// The page's height.
    pub height: Option<PageLength>,
    /// A title set below the figure.
    pub title: Option<Title>,
    /// The coupler point Q of a mechanism figure as (t, h): t along the
    /// rod from A (0) to B (1), h rod lengths off its line, to the left
    /// of A → B where positive ([`CouplerPoint::off_rod`]: 0 ≤ t ≤ 1,
    /// |h| ≤ 100, else refused).
    pub coupler: Option<(f64, f64)>,
    /// The connecting rod's mass of `crank-pin-loads`.
    pub rod_mass: Option<f64>,
    /// The distance of the rod's centre of mass from the crank pin.
    pub rod_cg: Option<f64>,
    /// The rod's radius of gyration about its centre of mass.
    pub rod_gyration: Option<f64>,
    /// The cranks of `inline-balance`, degrees ahead of the first's.
    pub cranks: Option<Vec<f64>>,
    /// The planes of `inline-balance`'s cylinders, in pitches.
    pub planes: Option<Vec<f64>>,
    /// A vertical engine's gravity along the line of stroke.
    pub gravity: Option<crate::dynamics::Gravity>,
    /// The slider's coefficient of friction in its guides.
    pub friction: Option<f64>,
}

impl FigureRequest {
    /// The options of the figure `name` this request asks for: the
    /// mechanism of the lengths given (the figure's own for those not
    /// given), ω from the speed given, the angle as the figure takes it.
    ///
    /// Errors: a mechanism that cannot be assembled or a length not
    /// finite; a speed given both ways, or out of range; an angle not
    /// finite (or a tilt not between 0° and 90°); an empty list of
    /// layers. The options a figure does not use are refused when it is
    /// drawn ([`FigureName::figure`]).
    pub fn options(&self, name: FigureName) -> Result<FigureOptions> {
        let mut options = FigureOptions::default();
        if self.crank.is_some() || self.rod.is_some() || self.offset.is_some() {
            let m = name.mechanism();
            options.mechanism = Some(SliderCrank::new(
                self.crank.unwrap_or(m.crank()),
                self.rod.unwrap_or(m.rod()),
                self.offset.unwrap_or(m.offset()),
            )?);
        }
        options.omega = crank_speed(self.rpm, self.omega)?;
        options.angle = self.angle.map(|d| name.angle(d)).transpose()?;
        options.layers = match &self.layers {
            Some(layers) if layers.is_empty() => {
                return Err(Error::refused(
                    Input::Layers,
                    Wording::default()
                        .option(Field::Layers)
                        .then(" names no layer"),
                ));
            }
            layers => layers.clone(),
        };
        options.style = self.style;
        options.font = self.font;
        options.data = self.data.clone();
        options.fit = self.fit;
        options.length_unit = self.unit.clone();
        options.force_unit = self.force_unit.clone();
        options.notation = self.notation;
        options.mass = self.mass;
        options.fluctuation = self.fluctuation;
        options.bore = self.bore;
        options.gas_force = self.gas_force;
        options.mirror = self.mirror;
        options.width = self.width;
        options.height = self.height;
        options.title = self.title.clone();
        options.coupler = self
            .coupler
            .map(|(t, h)| CouplerPoint::off_rod(t, h))
            .transpose()?;
        options.rod_mass = self.rod_mass;
        options.rod_cg = self.rod_cg;
        options.rod_gyration = self.rod_gyration;
        options.cranks = self.cranks.clone();
        options.planes = self.planes.clone();
        options.gravity = self.gravity;
        options.friction = self.friction;
        Ok(options)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lengths_not_given_are_the_figure_s_own() {
        let request = FigureRequest {
            rod: Some(2.5),
            ..FigureRequest::default()
        };
        let options = request.options(FigureName::Fig63Velocity).unwrap();
        let m = options.mechanism.unwrap();
        // The §35 engine's crank, 0.5 ft, and offset 0.
        assert_eq!((m.crank(), m.rod(), m.offset()), (0.5, 2.5, 0.0));
        assert_eq!(
            FigureRequest::default()
                .options(FigureName::Fig63Velocity)
                .unwrap(),
            FigureOptions::default()
        );
    }

    #[test]
    fn an_empty_list_of_layers_and_a_tilt_out_of_range_are_refused() {
        let request = FigureRequest {
            layers: Some(Vec::new()),
            ..FigureRequest::default()
        };
        let e = request.options(FigureName::Fig63Velocity).unwrap_err();
        assert_eq!(e.to_string(), "`layers` names no layer");
        let tilt = FigureRequest {
            angle: Some(95.0),
            ..FigureRequest::default()
        };
        assert!(tilt.options(FigureName::NgFig2Incline).is_err());
        assert!(tilt.options(FigureName::Fig63Velocity).is_ok());
    }
}
