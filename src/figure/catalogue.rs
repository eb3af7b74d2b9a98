//! The seeds' mechanism figures, by name, with the seeds' own parameters.

use crate::error::{Error, Result};
use crate::render::Style;
use crate::scene::{Layer, Notation, Page, Scene};
use crate::{Angle, SliderCrank};

/// Ng's crank torque implied by his Table 2 (1 kg × 9.81 m/s² × 27 mm), in
/// N·mm.
pub const NG_TORQUE: f64 = 9.81 * 27.0;

/// A figure of the seeds.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
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
}

impl FigureName {
    /// Every named figure.
    pub const ALL: [FigureName; 7] = [
        FigureName::Fig62Displacement,
        FigureName::Fig63Velocity,
        FigureName::Fig65Klein,
        FigureName::Fig66Kisch,
        FigureName::Fig67Example,
        FigureName::NgFig1Torque,
        FigureName::NgFigA1Velocity,
    ];

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
        }
    }

    /// The figure of that name; the error lists the names.
    pub fn from_name(name: &str) -> Result<Self> {
        Self::ALL
            .into_iter()
            .find(|f| f.name() == name)
            .ok_or_else(|| {
                Error::Parse(format!(
                    "unknown figure '{name}': expected one of {}",
                    Self::ALL.map(|f| f.name()).join(", ")
                ))
            })
    }

    /// Whether it follows Ng's paper (letters O, C, P, I, M; r = 25 mm,
    /// l = 72 mm) rather than the textbook (§35 engine: r = 0.5 ft,
    /// l = 3 ft, 250 rpm).
    pub fn is_ng(&self) -> bool {
        matches!(self, FigureName::NgFig1Torque | FigureName::NgFigA1Velocity)
    }

    /// The crank angle it is drawn at, in degrees.
    pub fn angle_degrees(&self) -> f64 {
        match self {
            FigureName::Fig62Displacement => 40.0,
            FigureName::Fig63Velocity | FigureName::Fig65Klein => 30.0,
            FigureName::Fig66Kisch => 60.0,
            FigureName::Fig67Example => 45.0,
            FigureName::NgFig1Torque => 60.0,
            FigureName::NgFigA1Velocity => 40.0,
        }
    }

    /// The layers it draws.
    pub fn layers(&self) -> Vec<Layer> {
        use Layer::*;
        match self {
            FigureName::Fig62Displacement => vec![Mechanism, Dimensions],
            FigureName::Fig63Velocity => vec![Mechanism, Velocity],
            FigureName::Fig65Klein => vec![Mechanism, Klein],
            FigureName::Fig66Kisch => vec![Mechanism, Kisch],
            FigureName::Fig67Example => vec![Mechanism, Velocity, Kisch, Scales],
            FigureName::NgFig1Torque => vec![Mechanism, Torque],
            FigureName::NgFigA1Velocity => vec![Mechanism, Velocity],
        }
    }

    /// The page it is drawn on.
    pub fn page(&self) -> Page {
        let (w, h) = match self {
            FigureName::Fig62Displacement => (760.0, 250.0),
            FigureName::Fig63Velocity | FigureName::Fig65Klein => (760.0, 480.0),
            FigureName::Fig66Kisch => (760.0, 420.0),
            FigureName::Fig67Example => (760.0, 520.0),
            FigureName::NgFig1Torque => (640.0, 270.0),
            FigureName::NgFigA1Velocity => (600.0, 480.0),
        };
        Page::new(w, h, 16.0).expect("catalogue pages are valid")
    }

    /// The scene with the seed's own parameters.
    pub fn scene(&self) -> Scene {
        let (mechanism, unit, force) = if self.is_ng() {
            (SliderCrank::in_line(25.0, 72.0), "mm", "N")
        } else {
            (SliderCrank::in_line(0.5, 3.0), "ft", "lbf")
        };
        let mechanism = mechanism.expect("the seeds' mechanisms are valid");
        let angle = Angle::from_degrees(self.angle_degrees()).expect("finite");
        let scene = Scene::new(mechanism, angle)
            .named(self.name())
            .with_layers(self.layers())
            .with_page(self.page())
            .with_style(Style::Textbook)
            .with_unit(unit)
            .with_force_unit(force);
        if self.is_ng() {
            scene
                .with_notation(Notation::Ng)
                .mirrored(false)
                .with_torque(NG_TORQUE)
                .expect("finite")
        } else {
            scene.with_notation(Notation::Textbook).mirrored(true)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip() {
        for f in FigureName::ALL {
            assert_eq!(FigureName::from_name(f.name()).unwrap(), f);
        }
        let err = FigureName::from_name("fig-64").unwrap_err().to_string();
        assert!(err.contains("fig-63-velocity"), "{err}");
    }
}
