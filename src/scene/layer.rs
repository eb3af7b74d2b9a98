//! The layers a scene can draw.

use crate::error::{Error, Input, Result};
use serde::Deserialize;

/// One layer of a mechanism figure. Each asks for the constructions it needs
/// and nothing more.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Deserialize)]
#[serde(rename_all = "kebab-case")]
#[non_exhaustive]
pub enum Layer {
    /// Frame, crank circle, crank, rod, slider block between guides, pins.
    /// Computes no construction.
    Mechanism,
    /// The angles and lengths that define the pose: crank angle θ, rod
    /// angle φ, r and l (Fig. 62; Ng Fig. 1). Computes no construction.
    Angles,
    /// Dimensions: the displacement x from mid-stroke, the stroke, and the
    /// offset e when it is not zero (Fig. 62). Computes no construction.
    Dimensions,
    /// The rod's fixed and moving centrodes (Fig. 61); needs D.
    Centrodes,
    /// The oval traced by a point of the rod. Needs no construction.
    Coupler,
    /// The polar diagram of piston velocity (Fig. 64) as far as the crank
    /// has turned: E′ on the crank at CE′ = |CE| from C, traced from the
    /// outer dead centre to the drawn pose (nothing at the outer dead
    /// centre itself, the whole curve just before it), with E′ lettered.
    /// Computes no construction: CE comes from the analytic core.
    Polar,
    /// The six virtual centres (§34); needs D and E.
    VirtualCentres,
    /// D and E with the similar triangles ADB and ECB (Fig. 63).
    Velocity,
    /// Klein's acceleration construction (Fig. 65); needs D and E.
    Klein,
    /// Kisch's acceleration construction (Fig. 66); needs E, never D.
    Kisch,
    /// Ritterhaus's acceleration construction: EK parallel to AC meets CB
    /// produced at K, KF perpendicular to the stroke, FG perpendicular to
    /// AB; needs E, never D.
    Ritterhaus,
    /// Bennett's acceleration construction (the in-line engine's): L at
    /// r²/l from B on the rod, LK perpendicular to AB to the stroke, KF
    /// perpendicular to the stroke, FG perpendicular to AB; needs E for its
    /// velocity part, never D. Draws only E with an offset.
    Bennett,
    /// Ng's OM torque line with the slider force, the side thrust and the
    /// force F_c on the crank pin; needs E.
    Torque,
    /// The motion (Ng Figs. 1 and A1): the crank's ω and the rod's Ω as
    /// turning arrows, the velocities v_c of the crank pin and v_p of the
    /// slider. Computes no construction.
    Motion,
    /// The velocity and acceleration polygons of the relative-velocity
    /// method, drawn below the mechanism to the scales their notes state:
    /// the lower-case images of the points and the images of the coupler
    /// point Q (the scene's coupler point), the rod's normal and
    /// tangential components, and Q marked on the rod. Needs the polygons
    /// (no D, no E).
    Polygons,
    /// Scale notes ("*CB* represents V_c = ..."); needs what the drawn
    /// velocity and acceleration layers need.
    Scales,
}

crate::error::parse_by_name!(Layer);

impl Layer {
    /// Every layer, in drawing order.
    pub const ALL: [Layer; 16] = [
        Layer::Mechanism,
        Layer::Angles,
        Layer::Dimensions,
        Layer::Centrodes,
        Layer::Coupler,
        Layer::Polar,
        Layer::VirtualCentres,
        Layer::Velocity,
        Layer::Klein,
        Layer::Kisch,
        Layer::Ritterhaus,
        Layer::Bennett,
        Layer::Torque,
        Layer::Motion,
        Layer::Polygons,
        Layer::Scales,
    ];

    /// Whether it is one of the piston's acceleration constructions
    /// (Klein's, Kisch's, Ritterhaus's, Bennett's), drawn in the
    /// acceleration's hue and enlarged in a detail where small.
    pub(crate) const fn is_acceleration(self) -> bool {
        matches!(
            self,
            Layer::Klein | Layer::Kisch | Layer::Ritterhaus | Layer::Bennett
        )
    }

    /// Whether it draws E, the velocity line CE (the velocity triangle,
    /// the acceleration constructions, Ng's torque line OM = CE), so that
    /// the scale notes read CE and the view holds E.
    pub(crate) const fn draws_e(self) -> bool {
        self.is_acceleration() || matches!(self, Layer::Velocity | Layer::Torque)
    }

    /// The name used on the command line and in scene files.
    pub fn name(&self) -> &'static str {
        match self {
            Layer::Mechanism => "mechanism",
            Layer::Angles => "angles",
            Layer::Dimensions => "dimensions",
            Layer::Centrodes => "centrodes",
            Layer::Coupler => "coupler",
            Layer::Polar => "polar",
            Layer::VirtualCentres => "virtual-centres",
            Layer::Velocity => "velocity",
            Layer::Klein => "klein",
            Layer::Kisch => "kisch",
            Layer::Ritterhaus => "ritterhaus",
            Layer::Bennett => "bennett",
            Layer::Torque => "torque",
            Layer::Motion => "motion",
            Layer::Polygons => "polygons",
            Layer::Scales => "scales",
        }
    }

    /// The layer of that name.
    pub fn from_name(name: &str) -> Result<Self> {
        Self::ALL
            .into_iter()
            .find(|l| l.name() == name.trim())
            .ok_or_else(|| {
                Error::invalid(
                    Input::Layers,
                    format!(
                        "unknown layer '{}': expected one of {}",
                        name.trim(),
                        Self::ALL.map(|l| l.name()).join(", ")
                    ),
                )
            })
    }

    /// Parses a comma-separated list (`mechanism,velocity`).
    pub fn parse_list(spec: &str) -> Result<Vec<Self>> {
        spec.split(',')
            .filter(|s| !s.trim().is_empty())
            .map(Self::from_name)
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip_and_typos_are_named() {
        for l in Layer::ALL {
            assert_eq!(Layer::from_name(l.name()).unwrap(), l);
        }
        let err = Layer::from_name("kisc").unwrap_err().to_string();
        assert!(err.contains("'kisc'") && err.contains("kisch"), "{err}");
        assert_eq!(
            Layer::parse_list("mechanism, kisch").unwrap(),
            vec![Layer::Mechanism, Layer::Kisch]
        );
    }
}
