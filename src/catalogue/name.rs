//! The named figures, with the seeds' own parameters: mechanism figures
//! drawn by a [`Scene`], and diagrams (plots against θ, time or position,
//! polar diagrams, centrodes, Ng's graphs).

use super::specs::Group;
use super::specs::{At, Kind, Source};
use super::{FigureName, FigureOptions, Setting, builders, scene_toml};
use crate::error::{Error, Field, Input, Result, Wording};
use crate::figure::{Figure, Style};
use crate::scene::{Layer, Notation, Page, Scene};
use crate::{angle::Angle, mechanism::SliderCrank, units::Units};

use crate::sources::NG_TORQUE;

crate::error::parse_by_name!(FigureName);

impl FigureName {
    /// The name (`fig-67-example`).
    pub fn name(&self) -> &'static str {
        self.spec().name
    }

    /// The figure of that name; the error suggests the nearest name
    /// ([`FigureName::nearest`]), if any is near, and lists them all.
    pub fn from_name(name: &str) -> Result<Self> {
        Self::ALL
            .into_iter()
            .find(|f| f.name() == name)
            .ok_or_else(|| {
                let hint = Self::nearest(name)
                    .map(|f| format!(": did you mean '{}'?", f.name()))
                    .unwrap_or_default();
                Error::invalid(
                    Input::FigureName,
                    format!(
                        "unknown figure '{name}'{hint} (the figures: {})",
                        Self::ALL.map(|f| f.name()).join(", ")
                    ),
                )
            })
    }

    /// The figure a mistyped `name` most likely meant: the only one whose
    /// name holds it whole (`klein` → `fig-65-klein`, compared without
    /// case), else the one fewest edits away when that is at most a third
    /// of the name's length (`fig-67-exmaple` → `fig-67-example`); `None`
    /// when none is near or two are equally near.
    pub fn nearest(name: &str) -> Option<Self> {
        let name = name.to_lowercase();
        let holding: Vec<Self> = Self::ALL
            .into_iter()
            .filter(|f| name.len() >= 3 && f.name().contains(name.as_str()))
            .collect();
        if let [only] = holding[..] {
            return Some(only);
        }
        let mut by_distance: Vec<(usize, Self)> = Self::ALL
            .into_iter()
            .map(|f| (strsim::levenshtein(&name, f.name()), f))
            .collect();
        by_distance.sort_by_key(|d| d.0);
        match by_distance[..] {
            [(d, f), (next, _), ..] if d < next && 3 * d <= name.chars().count() => Some(f),
            _ => None,
        }
    }

    /// Whether it follows Ng's paper (letters O, C, P, I, M; r = 25 mm,
    /// l = 72 mm; newtons) rather than the textbook (§35 engine:
    /// r = 0.5 ft, l = 3 ft, 250 rpm).
    pub fn is_ng(&self) -> bool {
        matches!(self.spec().source, Source::Ng(_))
    }

    /// Whether it is a diagram rather than a mechanism figure drawn by a
    /// [`Scene`] (then [`FigureName::scene`] is `None`).
    pub const fn is_diagram(&self) -> bool {
        matches!(self.spec().kind, Kind::Diagram(..))
    }

    /// The group it is listed in: [`Group::Mechanisms`] for a mechanism
    /// figure, a diagram's own group otherwise.
    pub fn group(&self) -> Group {
        match self.spec().kind {
            Kind::Mechanism(_) => Group::Mechanisms,
            Kind::Diagram(group, _) => group,
        }
    }

    /// The mechanism it is drawn for: Ng's rig (r = 25 mm, l = 72 mm), or
    /// the textbook's §35 engine (r = 0.5 ft, l = 3 ft) except for
    /// `fig-61-centrodes`, drawn with a shorter rod (l = 1.25 ft, n = 2.5)
    /// on which the centrodes are far enough apart to read, the chain's
    /// figures (r = 0.5, l = 1.5) and `slot-convergence` (r = 0.2,
    /// l = 0.6): the one its entry in the table gives.
    // cannot fail: the lengths are the table's constants, whose rods exceed crank + offset; `every_named_figure_builds` builds each.
    #[allow(clippy::expect_used)]
    pub fn mechanism(&self) -> SliderCrank {
        let (crank, rod) = self.spec().mechanism;
        SliderCrank::in_line(crank, rod).expect("the catalogue's mechanisms are valid")
    }

    /// The angle for this figure from `degrees` as the user gave them:
    /// a crank angle (any finite number, reduced to a turn), or for
    /// `ng-fig-2-incline` the plane's tilt, strictly between 0° and 90°
    /// and refused as given (`1e300` is not the tilt 0° it reduces to).
    pub fn angle(&self, degrees: f64) -> Result<Angle> {
        if matches!(self.spec().at, At::Tilt(_)) && !(degrees > 0.0 && degrees < 90.0) {
            return Err(Error::OutOfRange {
                name: Field::Angle,
                value: degrees,
                reason: "the tilt of the plane is between 0° and 90°".into(),
            });
        }
        Angle::from_degrees(degrees)
    }

    /// The crank angle it is drawn at (the pose whose construction a
    /// diagram shows; the plane's tilt for `ng-fig-2-incline`), in degrees;
    /// 0 for a diagram that draws no pose.
    pub fn angle_degrees(&self) -> f64 {
        self.spec().at.degrees()
    }

    /// The layers of a mechanism figure; empty for a diagram.
    pub fn layers(&self) -> Vec<Layer> {
        match self.spec().kind {
            Kind::Mechanism(layers) => layers.to_vec(),
            Kind::Diagram(..) => Vec::new(),
        }
    }

    /// The units of its seed: millimetres and newtons for Ng's figures,
    /// feet and pounds-force for the textbook's. The default of
    /// [`FigureOptions::length_unit`] and [`FigureOptions::force_unit`].
    pub fn units(&self) -> Units {
        if self.is_ng() {
            Units::MILLIMETRE_NEWTON
        } else {
            Units::FOOT_POUND
        }
    }

    /// The page it is drawn on.
    // cannot fail: the table's sizes are constants between 250 and 900 with a margin of 16.
    #[allow(clippy::expect_used)]
    pub fn page(&self) -> Page {
        let (w, h) = self.spec().page;
        Page::new(w, h, 16.0)
            .expect("catalogue pages are valid")
            .with_width_fitted()
    }

    /// The figure with `options` applied (see [`FigureOptions`]); errors
    /// for an option the figure does not use, for bad data, and for what
    /// the mechanism cannot draw.
    pub fn figure(&self, options: &FigureOptions) -> Result<Figure> {
        match self.spec().kind {
            Kind::Mechanism(layers) => self.asked_scene(layers, options)?.figure(),
            Kind::Diagram(_, build) => {
                builders::build(*self, build, options).map_err(Error::one_line)
            }
        }
    }

    /// The scene of a mechanism figure with `options` applied, the scene
    /// [`FigureName::figure`] draws; `None` for a diagram, which has no
    /// scene. Errors as [`FigureName::figure`] for an option a mechanism
    /// figure does not use (the data, the fit, the mass, the coefficient
    /// of fluctuation) or a bad value.
    pub fn scene_with(&self, options: &FigureOptions) -> Result<Option<Scene>> {
        match self.spec().kind {
            Kind::Mechanism(layers) => self.asked_scene(layers, options).map(Some),
            Kind::Diagram(..) => Ok(None),
        }
    }

    /// Whether the figure takes `setting` from its options.
    pub(crate) fn takes(&self, setting: Setting) -> bool {
        self.spec().takes.contains(&setting)
    }

    /// The first option given in `options` that the figure does not take
    /// (in the order of [`FigureOptions::given`]).
    pub(crate) fn unused(&self, options: &FigureOptions) -> Option<Setting> {
        options.given().into_iter().find(|&o| !self.takes(o))
    }

    /// Refuses an option given in `options` that the figure does not take,
    /// naming its fields.
    pub(crate) fn refuse_unused(&self, options: &FigureOptions) -> Result<()> {
        match self.unused(options) {
            Some(bad) => Err(Error::refused(
                Input::Options,
                Wording::from(format!("{} does not use ", self.name())).and(bad.wording()),
            )),
            None => Ok(()),
        }
    }

    /// The mechanism figure's scene of `layers` with `options` applied.
    fn asked_scene(&self, layers: &[Layer], options: &FigureOptions) -> Result<Scene> {
        self.refuse_unused(options)?;
        let mut scene = self.own_scene(layers);
        if let Some(m) = options.mechanism {
            scene = scene.with_mechanism(m);
        }
        if let Some(a) = options.angle {
            scene = scene.with_angles(vec![a]);
        }
        if let Some(w) = options.omega {
            scene = scene.with_omega(w);
        }
        if let Some(s) = options.style {
            scene = scene.with_style(s);
        }
        if let Some(f) = options.font {
            scene = scene.with_font(f);
        }
        if let Some(layers) = &options.layers {
            if layers.is_empty() {
                return Err(Error::invalid(
                    Input::Layers,
                    format!("{}: the list of layers is empty", self.name()),
                ));
            }
            scene = scene.with_layers(layers.iter().copied());
        }
        let units = scene
            .units()
            .clone()
            .asked(options.length_unit.as_ref(), options.force_unit.as_ref());
        scene = scene.with_units(units);
        if let Some(n) = options.notation {
            scene = scene.with_notation(n);
        }
        if let Some(m) = options.mirror {
            scene = scene.with_mirror(m);
        }
        let page = options.page(scene.page())?;
        scene = scene.with_page(page);
        if let Some(t) = &options.title {
            scene = scene.with_title(t.clone());
        }
        if let Some(p) = options.coupler {
            scene = scene.with_coupler(p);
        }
        Ok(scene)
    }

    /// The scene file of this figure, as a starting point: every key it
    /// uses at the figure's own value, each with a comment (what
    /// the command line prints as a figure's default scene). A mechanism
    /// figure's file gives every key of its scene and reads back to the
    /// same scene; a diagram's starts from `figure = "NAME"` and gives the
    /// keys that diagram takes (its data, where it has any, is given on
    /// the command line). See docs/scene-format.md.
    pub fn scene_toml(&self) -> String {
        match self.scene() {
            Some(scene) => scene_toml::scene(*self, &scene),
            None => scene_toml::diagram(*self),
        }
    }

    /// The scene of a mechanism figure with the seed's own parameters;
    /// `None` for a diagram (use [`FigureName::figure`]).
    pub fn scene(&self) -> Option<Scene> {
        match self.spec().kind {
            Kind::Mechanism(layers) => Some(self.own_scene(layers)),
            Kind::Diagram(..) => None,
        }
    }

    /// The mechanism figure's scene of `layers` with the seed's own
    /// parameters.
    fn own_scene(&self, layers: &[Layer]) -> Scene {
        // cannot fail: the figures' angles are finite constants.
        #[allow(clippy::expect_used)]
        let angle = Angle::from_degrees(self.angle_degrees()).expect("finite");
        let scene = Scene::new(self.mechanism(), angle)
            .with_name(self.name())
            .with_layers(layers.iter().copied())
            .with_page(self.page())
            .with_style(Style::Textbook)
            .with_units(self.units());
        if self.is_ng() {
            scene
                .with_notation(Notation::Ng)
                .with_mirror(false)
                .with_torque(NG_TORQUE)
        } else {
            scene.with_notation(Notation::Textbook).with_mirror(true)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_mistyped_name_is_told_the_nearest() {
        let near = |s: &str| FigureName::nearest(s).map(|f| f.name());
        assert_eq!(near("fig-67-exmaple"), Some("fig-67-example"));
        assert_eq!(near("klein"), Some("fig-65-klein"));
        assert_eq!(near("Kisch"), Some("fig-66-kisch"));
        assert_eq!(near("rod-moton"), Some("rod-motion"));
        // Held by several names, or far from all: no guess.
        assert_eq!(near("fig"), None);
        assert_eq!(near("zzzzzzzz"), None);
        let e = FigureName::from_name("fig-67-exmaple")
            .unwrap_err()
            .to_string();
        assert!(e.contains("did you mean 'fig-67-example'?"), "{e}");
        assert!(!e.contains('\n'), "{e}");
        let e = FigureName::from_name("zzzzzzzz").unwrap_err().to_string();
        assert!(
            !e.contains("did you mean") && e.contains("fig-66-kisch"),
            "{e}"
        );
    }

    #[test]
    fn names_round_trip() {
        for f in FigureName::ALL {
            assert_eq!(FigureName::from_name(f.name()).unwrap(), f);
        }
        let err = FigureName::from_name("fig-64").unwrap_err().to_string();
        assert!(err.contains("fig-63-velocity"), "{err}");
        assert!(err.contains("curve-benchmark"), "{err}");
        for f in FigureName::ALL {
            assert_eq!(f.scene().is_none(), f.is_diagram(), "{}", f.name());
            assert!(FigureName::SCENES.contains(&f) != FigureName::DIAGRAMS.contains(&f));
        }
    }
}
