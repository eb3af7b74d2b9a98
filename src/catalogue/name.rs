//! The named figures, with the seeds' own parameters: mechanism figures
//! drawn by a [`Scene`], and diagrams (plots against θ, time or position,
//! polar diagrams, centrodes, Ng's graphs).

use super::{FigureOptions, diagrams, scene_toml};
use crate::error::{Error, Result};
use crate::figure::{Figure, Style};
use crate::scene::{Layer, Notation, Page, Scene};
use crate::{angle::Angle, mechanism::SliderCrank, units::Units};

use crate::analytic::statics::NG_TORQUE;

/// A figure of the seeds.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
#[non_exhaustive]
pub enum FigureName {
    /// Textbook Fig. 62: the crank angle θ and the displacement x of the
    /// cross-head from mid-stroke.
    Fig62Displacement,
    /// Textbook Fig. 63: the velocity construction, D and E, the similar
    /// triangles ADB and ECB.
    Fig63Velocity,
    /// Textbook Fig. 65: Klein's acceleration construction.
    Fig65Klein,
    /// Textbook Fig. 66: Kisch's construction (D not needed, here off the
    /// page).
    Fig66Kisch,
    /// Textbook Fig. 67: the 45° engine with its velocity and acceleration
    /// scales and values.
    Fig67Example,
    /// Ng Fig. 1: the OM torque line, slider force and side thrust.
    NgFig1Torque,
    /// Ng Fig. A1: the velocity construction in Ng's letters (I, M).
    NgFigA1Velocity,
    /// Textbook Fig. 61: the rod's fixed centrode (full) and moving
    /// centrode (dotted), with the construction of D for one pose.
    Fig61Centrodes,
    /// Textbook Fig. 64: the polar diagram of piston velocity (E′ on the
    /// crank, CE′ = CE), the velocity on a distance base (E″ over A) and on
    /// a time base against simple harmonic motion.
    Fig64VelocityDiagrams,
    /// Piston acceleration on a distance base and a time base against
    /// simple harmonic motion, and a polar acceleration diagram.
    AccelerationDiagrams,
    /// The rod's angular velocity and acceleration against θ (§37), with
    /// eq. (2a).
    RodMotion,
    /// The error of the textbook's approximations (eq. 2, 3, 2a and the
    /// obliquity term) against θ for n = 4, 5, 6.
    ApproximationError,
    /// Ovals traced by points of the rod (§34).
    CouplerCurves,
    /// Ng Fig. 2: the block on an inclined plane, μ = tan φ.
    NgFig2Incline,
    /// Ng Fig. 7: the calibration points, fitted line(s), equation and R².
    NgFig7Calibration,
    /// Ng Fig. 8: F and F′ (theory) against θ with the measured F′, and the
    /// transmission angle.
    NgFig8Forces,
    /// The curve engine's benchmark: segments and time against measured
    /// error, log–log (docs/curve-benchmarks.csv).
    CurveBenchmark,
    /// Textbook Fig. 60: (a) the quadric crank chain, (b) the block in a
    /// curved slot with its centre O_cd, (c) the straight slot, O_cd at
    /// infinity; links a, b, c, d, one crank angle.
    Fig60Chains,
    /// Inversion 1, the frame d fixed: the direct-acting engine, with its
    /// six virtual centres.
    Inversion1Engine,
    /// Inversion 2, the crank a fixed: the rotating block (Whitworth's
    /// quick return, the Gnome engine).
    Inversion2RotatingBlock,
    /// Inversion 3, the rod b fixed: the oscillating cylinder, the crank
    /// and slotted lever quick return.
    Inversion3OscillatingCylinder,
    /// Inversion 4, the block c fixed: the hand pump.
    Inversion4HandPump,
    /// The curved slot's difference from the straight slot against its
    /// radius ρ from 1 to 1e15, log–log.
    SlotConvergence,
    /// The turning-moment diagram of an engine (§37's inertia force and
    /// Ng's T = F · OM over a turn) with its mean line and the areas
    /// between them, and the flywheel's energy diagram.
    TurningMoment,
    /// The inertia force of the reciprocating parts on the mechanism:
    /// Klein's CG read as the piston's acceleration and scaled by m ω² to
    /// the force, drawn at the cross-head against the acceleration,
    /// resolved along the rod and on the guides, and the crank effort
    /// T = F · OM through Ng's torque line.
    InertiaForce,
    /// The primary and secondary unbalanced forces of the reciprocating
    /// parts (m r ω² cos θ, m r ω² cos 2θ / n), their sum and the exact
    /// inertia force against θ, and what the two terms leave out.
    PrimarySecondary,
    /// The direct and reverse crank method: the primary force as the
    /// resultant of cranks at ±θ, the secondary as that of cranks of
    /// radius r/4n at ±2θ, their components on the line of stroke summing
    /// to the force.
    DirectReverseCranks,
    /// The flywheel: the energy stored above its least over the turn,
    /// rising by the fluctuation of energy ΔE, and the crank speed with
    /// the flywheel I = ΔE / (ω² C_s) of a coefficient of fluctuation of
    /// speed C_s.
    Flywheel,
}

crate::error::parse_by_name!(FigureName);

impl FigureName {
    /// The mechanism figures, drawn by a [`Scene`].
    pub const SCENES: [FigureName; 7] = [
        FigureName::Fig62Displacement,
        FigureName::Fig63Velocity,
        FigureName::Fig65Klein,
        FigureName::Fig66Kisch,
        FigureName::Fig67Example,
        FigureName::NgFig1Torque,
        FigureName::NgFigA1Velocity,
    ];

    /// The diagrams: plots, polar diagrams, centrodes and coupler curves.
    pub const DIAGRAMS: [FigureName; 21] = [
        FigureName::Fig61Centrodes,
        FigureName::Fig64VelocityDiagrams,
        FigureName::AccelerationDiagrams,
        FigureName::RodMotion,
        FigureName::ApproximationError,
        FigureName::CouplerCurves,
        FigureName::NgFig2Incline,
        FigureName::NgFig7Calibration,
        FigureName::NgFig8Forces,
        FigureName::CurveBenchmark,
        FigureName::Fig60Chains,
        FigureName::Inversion1Engine,
        FigureName::Inversion2RotatingBlock,
        FigureName::Inversion3OscillatingCylinder,
        FigureName::Inversion4HandPump,
        FigureName::SlotConvergence,
        FigureName::TurningMoment,
        FigureName::InertiaForce,
        FigureName::PrimarySecondary,
        FigureName::DirectReverseCranks,
        FigureName::Flywheel,
    ];

    /// Every named figure: the scenes, then the diagrams.
    // cannot fail: evaluated when the crate is built, where an index out of
    // range is a build error.
    #[allow(clippy::indexing_slicing)]
    pub const ALL: [FigureName; FigureName::SCENES.len() + FigureName::DIAGRAMS.len()] = {
        let mut all =
            [FigureName::Fig62Displacement; FigureName::SCENES.len() + FigureName::DIAGRAMS.len()];
        let mut i = 0;
        while i < FigureName::SCENES.len() {
            all[i] = FigureName::SCENES[i];
            i += 1;
        }
        let mut j = 0;
        while j < FigureName::DIAGRAMS.len() {
            all[i + j] = FigureName::DIAGRAMS[j];
            j += 1;
        }
        all
    };

    /// The name (`fig-67-example`).
    pub fn name(&self) -> &'static str {
        match self {
            FigureName::Fig62Displacement => "fig-62-displacement",
            FigureName::Fig63Velocity => "fig-63-velocity",
            FigureName::Fig65Klein => "fig-65-klein",
            FigureName::Fig66Kisch => "fig-66-kisch",
            FigureName::Fig67Example => "fig-67-example",
            FigureName::NgFig1Torque => "ng-fig-1-torque",
            FigureName::NgFigA1Velocity => "ng-fig-a1-velocity",
            FigureName::Fig61Centrodes => "fig-61-centrodes",
            FigureName::Fig64VelocityDiagrams => "fig-64-velocity-diagrams",
            FigureName::AccelerationDiagrams => "acceleration-diagrams",
            FigureName::RodMotion => "rod-motion",
            FigureName::ApproximationError => "approximation-error",
            FigureName::CouplerCurves => "coupler-curves",
            FigureName::NgFig2Incline => "ng-fig-2-incline",
            FigureName::NgFig7Calibration => "ng-fig-7-calibration",
            FigureName::NgFig8Forces => "ng-fig-8-forces",
            FigureName::CurveBenchmark => "curve-benchmark",
            FigureName::Fig60Chains => "fig-60-chains",
            FigureName::Inversion1Engine => "inversion-1-engine",
            FigureName::Inversion2RotatingBlock => "inversion-2-rotating-block",
            FigureName::Inversion3OscillatingCylinder => "inversion-3-oscillating-cylinder",
            FigureName::Inversion4HandPump => "inversion-4-hand-pump",
            FigureName::SlotConvergence => "slot-convergence",
            FigureName::TurningMoment => "turning-moment",
            FigureName::InertiaForce => "inertia-force",
            FigureName::PrimarySecondary => "primary-secondary",
            FigureName::DirectReverseCranks => "direct-reverse-cranks",
            FigureName::Flywheel => "flywheel",
        }
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
                Error::Parse(format!(
                    "unknown figure '{name}'{hint} (the figures: {})",
                    Self::ALL.map(|f| f.name()).join(", ")
                ))
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
        matches!(
            self,
            FigureName::NgFig1Torque
                | FigureName::NgFigA1Velocity
                | FigureName::NgFig2Incline
                | FigureName::NgFig7Calibration
                | FigureName::NgFig8Forces
        )
    }

    /// Whether it is a diagram rather than a mechanism figure drawn by a
    /// [`Scene`] (then [`FigureName::scene`] is `None`).
    pub fn is_diagram(&self) -> bool {
        FigureName::DIAGRAMS.contains(self)
    }

    /// The mechanism it is drawn for: Ng's rig (r = 25 mm, l = 72 mm), or
    /// the textbook's §35 engine (r = 0.5 ft, l = 3 ft) except for
    /// `fig-61-centrodes`, drawn with a shorter rod (l = 1.25 ft, n = 2.5)
    /// on which the centrodes are far enough apart to read.
    // cannot fail: the lengths are constants above whose rods exceed crank + offset; `every_named_figure_builds` builds each.
    #[allow(clippy::expect_used)]
    pub fn mechanism(&self) -> SliderCrank {
        let m = match self {
            _ if self.is_ng() => SliderCrank::in_line(25.0, 72.0),
            FigureName::Fig61Centrodes => SliderCrank::in_line(0.5, 1.25),
            FigureName::Fig60Chains
            | FigureName::Inversion1Engine
            | FigureName::Inversion2RotatingBlock
            | FigureName::Inversion3OscillatingCylinder
            | FigureName::Inversion4HandPump => SliderCrank::in_line(0.5, 1.5),
            FigureName::SlotConvergence => SliderCrank::in_line(0.2, 0.6),
            _ => SliderCrank::in_line(0.5, 3.0),
        };
        m.expect("the catalogue's mechanisms are valid")
    }

    /// The angle for this figure from `degrees` as the user gave them:
    /// a crank angle (any finite number, reduced to a turn), or for
    /// `ng-fig-2-incline` the plane's tilt, strictly between 0° and 90°
    /// and refused as given (`1e300` is not the tilt 0° it reduces to).
    pub fn angle(&self, degrees: f64) -> Result<Angle> {
        if *self == FigureName::NgFig2Incline && !(degrees > 0.0 && degrees < 90.0) {
            return Err(Error::OutOfRange {
                name: "angle",
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
        match self {
            FigureName::Fig62Displacement => 40.0,
            FigureName::Fig63Velocity | FigureName::Fig65Klein => 30.0,
            FigureName::Fig66Kisch => 60.0,
            FigureName::Fig67Example => 45.0,
            FigureName::NgFig1Torque => 60.0,
            FigureName::NgFigA1Velocity => 40.0,
            FigureName::Fig61Centrodes => 35.0,
            FigureName::Fig64VelocityDiagrams => 50.0,
            FigureName::AccelerationDiagrams => 45.0,
            FigureName::RodMotion => 45.0,
            FigureName::InertiaForce | FigureName::DirectReverseCranks => 30.0,
            FigureName::CouplerCurves => 40.0,
            FigureName::NgFig2Incline => 45.0,
            FigureName::Fig60Chains => 50.0,
            FigureName::Inversion1Engine
            | FigureName::Inversion2RotatingBlock
            | FigureName::Inversion3OscillatingCylinder
            | FigureName::Inversion4HandPump => 60.0,
            FigureName::ApproximationError
            | FigureName::SlotConvergence
            | FigureName::NgFig7Calibration
            | FigureName::NgFig8Forces
            | FigureName::CurveBenchmark
            | FigureName::TurningMoment
            | FigureName::PrimarySecondary
            | FigureName::Flywheel => 0.0,
        }
    }

    /// The layers of a mechanism figure; empty for a diagram.
    pub fn layers(&self) -> Vec<Layer> {
        use Layer::*;
        match self {
            FigureName::Fig62Displacement => vec![Mechanism, Angles, Dimensions],
            FigureName::Fig63Velocity => vec![Mechanism, Velocity],
            FigureName::Fig65Klein => vec![Mechanism, Klein],
            FigureName::Fig66Kisch => vec![Mechanism, Kisch],
            FigureName::Fig67Example => vec![Mechanism, Velocity, Kisch, Scales],
            FigureName::NgFig1Torque => vec![Mechanism, Angles, Torque, Motion],
            FigureName::NgFigA1Velocity => vec![Mechanism, Velocity, Motion],
            _ => Vec::new(),
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
    // cannot fail: the sizes are constants between 250 and 900 with a margin of 16.
    #[allow(clippy::expect_used)]
    pub fn page(&self) -> Page {
        let (w, h) = match self {
            FigureName::Fig62Displacement => (760.0, 250.0),
            FigureName::Fig63Velocity | FigureName::Fig65Klein => (760.0, 480.0),
            FigureName::Fig66Kisch => (760.0, 420.0),
            FigureName::Fig67Example => (760.0, 520.0),
            FigureName::NgFig1Torque => (640.0, 460.0),
            FigureName::NgFigA1Velocity => (600.0, 480.0),
            FigureName::Fig61Centrodes => (760.0, 600.0),
            FigureName::Fig64VelocityDiagrams => (860.0, 860.0),
            FigureName::AccelerationDiagrams => (900.0, 760.0),
            FigureName::RodMotion => (760.0, 640.0),
            FigureName::ApproximationError => (900.0, 680.0),
            FigureName::CouplerCurves => (760.0, 340.0),
            FigureName::NgFig2Incline => (620.0, 520.0),
            FigureName::NgFig7Calibration => (640.0, 460.0),
            FigureName::NgFig8Forces => (760.0, 700.0),
            FigureName::CurveBenchmark => (900.0, 540.0),
            FigureName::Fig60Chains => (900.0, 420.0),
            FigureName::Inversion1Engine
            | FigureName::Inversion2RotatingBlock
            | FigureName::Inversion3OscillatingCylinder
            | FigureName::Inversion4HandPump => (760.0, 620.0),
            FigureName::SlotConvergence => (760.0, 560.0),
            FigureName::TurningMoment => (900.0, 760.0),
            FigureName::InertiaForce => (760.0, 760.0),
            FigureName::PrimarySecondary => (900.0, 760.0),
            FigureName::DirectReverseCranks => (900.0, 660.0),
            FigureName::Flywheel => (900.0, 760.0),
        };
        Page::new(w, h, 16.0)
            .expect("catalogue pages are valid")
            .with_width_fitted()
    }

    /// The figure with `options` applied (see [`FigureOptions`]); errors
    /// for an option the figure does not use, for bad data, and for what
    /// the mechanism cannot draw.
    pub fn figure(&self, options: &FigureOptions) -> Result<Figure> {
        match self.scene_with(options)? {
            Some(scene) => scene.figure(),
            None => diagrams::build(*self, options).map_err(Error::one_line),
        }
    }

    /// The scene of a mechanism figure with `options` applied, the scene
    /// [`FigureName::figure`] draws; `None` for a diagram, which has no
    /// scene. Errors as [`FigureName::figure`] for an option a mechanism
    /// figure does not use (`--data`, `--fit`, `--mass`, `--fluctuation`) or a
    /// bad value.
    pub fn scene_with(&self, options: &FigureOptions) -> Result<Option<Scene>> {
        let Some(mut scene) = self.scene() else {
            return Ok(None);
        };
        if let Some(bad) = options
            .given()
            .into_iter()
            .find(|o| ["--data", "--fit", "--mass", "--fluctuation"].contains(o))
        {
            return Err(Error::Parse(format!("{} does not use {bad}", self.name())));
        }
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
                return Err(Error::Parse(format!(
                    "{}: the list of layers is empty",
                    self.name()
                )));
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
        Ok(Some(scene))
    }

    /// The scene file of this figure, as a starting point: every key it
    /// uses at the figure's own value, each with a comment (what
    /// `slider-crank scene --print-default NAME` prints). A mechanism
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
        if self.is_diagram() {
            return None;
        }
        // cannot fail: the figures' angles are finite constants.
        #[allow(clippy::expect_used)]
        let angle = Angle::from_degrees(self.angle_degrees()).expect("finite");
        let scene = Scene::new(self.mechanism(), angle)
            .with_name(self.name())
            .with_layers(self.layers())
            .with_page(self.page())
            .with_style(Style::Textbook)
            .with_units(self.units());
        Some(if self.is_ng() {
            scene
                .with_notation(Notation::Ng)
                .with_mirror(false)
                .with_torque(NG_TORQUE)
        } else {
            scene.with_notation(Notation::Textbook).with_mirror(true)
        })
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
