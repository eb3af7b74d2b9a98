//! Which letters a figure uses: the textbook's or Ng's.

use crate::error::Input;
use serde::Deserialize;

/// The letters of a figure (docs/design.md §1): the textbook's C, B, A, D, E or
/// Ng's O, C, P, I, M for the same points.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize)]
#[serde(rename_all = "kebab-case")]
#[non_exhaustive]
pub enum Notation {
    /// Crank centre C, crank pin B, cross-head A, D, E, F, G, H.
    #[default]
    Textbook,
    /// Ng's letters: O, C, P, I, M.
    Ng,
}

crate::error::parse_by_name!(Notation);

/// The points a figure may name.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Named {
    CrankCentre,
    CrankPin,
    Slider,
    InstantCentre,
    VelocityPoint,
    F,
    G,
    H,
    K,
    L,
    MidStroke,
    Coupler,
}

impl Notation {
    /// The name used on the command line and in scene files.
    pub fn name(&self) -> &'static str {
        match self {
            Notation::Textbook => "textbook",
            Notation::Ng => "ng",
        }
    }

    /// The notation of that name (`textbook`, `ng`); the error lists the
    /// names.
    pub fn from_name(name: &str) -> crate::error::Result<Self> {
        [Notation::Textbook, Notation::Ng]
            .into_iter()
            .find(|n| n.name() == name)
            .ok_or_else(|| {
                crate::error::Error::invalid(Input::Notation, format!(
                    "unknown notation '{}': expected textbook (C, B, A, D, E) or ng (O, C, P, I, M)",
                    name.escape_default()
                ))
            })
    }

    pub(crate) fn letter(&self, p: Named) -> &'static str {
        use Named::*;
        match (self, p) {
            (Notation::Textbook, CrankCentre) => "C",
            (Notation::Textbook, CrankPin) => "B",
            (Notation::Textbook, Slider) => "A",
            (Notation::Textbook, InstantCentre) => "D",
            (Notation::Textbook, VelocityPoint) => "E",
            (Notation::Textbook, MidStroke) => "O",
            (Notation::Ng, CrankCentre) => "O",
            (Notation::Ng, CrankPin) => "C",
            (Notation::Ng, Slider) => "P",
            (Notation::Ng, InstantCentre) => "I",
            (Notation::Ng, VelocityPoint) => "M",
            (Notation::Ng, MidStroke) => "N",
            (_, F) => "F",
            (_, G) => "G",
            (_, H) => "H",
            (_, K) => "K",
            (_, L) => "L",
            (_, Coupler) => "Q",
        }
    }

    /// The letter of a velocity: the textbook's *V* (*V*_c, *V*_p), Ng's
    /// *v* (*v*_c, *v*_p).
    pub(crate) fn velocity(&self) -> &'static str {
        match self {
            Notation::Textbook => "V",
            Notation::Ng => "v",
        }
    }

    /// The id of the line between two named points (`line-CE`, `line-OM`).
    pub(crate) fn line(&self, p: Named, q: Named) -> String {
        format!("line-{}{}", self.letter(p), self.letter(q))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip() {
        for n in [Notation::Textbook, Notation::Ng] {
            assert_eq!(n.to_string().parse::<Notation>().unwrap(), n);
        }
        assert!("book".parse::<Notation>().is_err());
    }

    #[test]
    fn ng_letters_name_the_same_points() {
        assert_eq!(Notation::Ng.letter(Named::VelocityPoint), "M");
        assert_eq!(Notation::Textbook.letter(Named::VelocityPoint), "E");
        assert_eq!(
            Notation::Ng.line(Named::CrankCentre, Named::VelocityPoint),
            "line-OM"
        );
        assert_eq!(Notation::Ng.velocity(), "v");
        assert_eq!(Notation::Textbook.velocity(), "V");
    }
}
