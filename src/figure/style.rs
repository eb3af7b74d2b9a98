//! The two styles over the same geometry: the textbook's black engraving
//! and a coloured handout. A figure carries its style; the renderer asks
//! it for the pen of each role and hue, the paper and the sizes of text.

use super::{Dash, Hue, Role, TextSize};
use crate::error::{Error, Input, Result};
use serde::Deserialize;

/// How a figure is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize)]
#[serde(rename_all = "kebab-case")]
#[non_exhaustive]
pub enum Style {
    /// Black ink on white: thick links, thin construction lines, dashed
    /// auxiliaries, italic serif letters.
    #[default]
    Textbook,
    /// The same lines in colour by role, with the similar triangles tinted.
    Handout,
}

crate::error::parse_by_name!(Style);

/// A stroke.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Pen {
    pub colour: &'static str,
    pub width: f64,
    pub dash: Option<&'static str>,
}

impl Style {
    /// The name used on the command line and in scene files.
    pub fn name(&self) -> &'static str {
        match self {
            Style::Textbook => "textbook",
            Style::Handout => "handout",
        }
    }

    /// The style of that name.
    pub fn from_name(name: &str) -> Result<Self> {
        match name {
            "textbook" => Ok(Style::Textbook),
            "handout" => Ok(Style::Handout),
            _ => Err(Error::invalid(
                Input::Style,
                format!("unknown style '{name}': expected textbook or handout"),
            )),
        }
    }

    /// The stroke of a role.
    pub(crate) fn pen(&self, role: Role) -> Pen {
        let dash = match role {
            Role::Auxiliary => Some("6 3.5"),
            _ => None,
        };
        let (width, colour) = match (self, role) {
            (Style::Textbook, Role::Frame) => (1.0, "#000000"),
            (Style::Textbook, Role::Auxiliary) => (0.7, "#000000"),
            (Style::Textbook, Role::Curve) => (1.0, "#000000"),
            (Style::Textbook, Role::Construction) => (0.9, "#000000"),
            (Style::Textbook, Role::Result) => (1.5, "#000000"),
            (Style::Textbook, Role::Dimension) => (0.6, "#000000"),
            (Style::Textbook, Role::Force) => (1.4, "#000000"),
            (Style::Textbook, Role::Link) => (2.6, "#000000"),
            (Style::Textbook, Role::Label) => (0.6, "#000000"),
            (Style::Handout, Role::Frame) => (1.0, "#5f6368"),
            (Style::Handout, Role::Auxiliary) => (0.8, "#7b8794"),
            (Style::Handout, Role::Curve) => (1.4, "#2e7d32"),
            (Style::Handout, Role::Construction) => (1.1, "#c62828"),
            (Style::Handout, Role::Result) => (1.8, "#c62828"),
            (Style::Handout, Role::Dimension) => (0.8, "#6a1b9a"),
            (Style::Handout, Role::Force) => (1.8, "#e65100"),
            (Style::Handout, Role::Link) => (3.0, "#1a237e"),
            (Style::Handout, Role::Label) => (0.6, "#111111"),
        };
        Pen {
            colour,
            width,
            dash,
        }
    }

    /// The colour of a line standing for `hue`: black in the textbook; in
    /// the handout three hues of the Okabe–Ito palette, told apart by
    /// colour-blind readers and by lightness in greyscale print.
    pub(crate) fn hue(&self, hue: Hue) -> Option<&'static str> {
        match self {
            Style::Textbook => None,
            Style::Handout => Some(match hue {
                Hue::Velocity => "#0072b2",
                Hue::Acceleration => "#d55e00",
                Hue::Force => "#009e73",
            }),
        }
    }

    /// The colour of a plotted series by its dash, in the handout (each
    /// series differs in both); `None` keeps the role's colour.
    pub(crate) fn series(&self, dash: Dash) -> Option<&'static str> {
        match self {
            Style::Textbook => None,
            Style::Handout => Some(match dash {
                Dash::Solid => "#0072b2",
                Dash::Dashed => "#d55e00",
                Dash::Dotted => "#009e73",
                Dash::DashDot => "#cc79a7",
            }),
        }
    }

    /// The dash array of a stroke pattern (`None`: a full line). Dots are
    /// zero-length dashes drawn by round caps.
    pub(crate) fn dash(dash: Dash) -> Option<&'static str> {
        match dash {
            Dash::Solid => None,
            Dash::Dashed => Some("7 4"),
            Dash::Dotted => Some("0 3.5"),
            Dash::DashDot => Some("10 3 0 3"),
        }
    }

    /// The paper colour.
    pub(crate) fn paper(&self) -> &'static str {
        match self {
            Style::Textbook => "#ffffff",
            Style::Handout => "#fffdf7",
        }
    }

    /// The fill of a tinted region; `None` where the style draws none.
    pub(crate) fn region(&self) -> Option<(&'static str, f64)> {
        match self {
            Style::Textbook => None,
            Style::Handout => Some(("#c62828", 0.10)),
        }
    }

    /// The tone a link's body is filled in (a turning slotted bar, the
    /// inversions' d) and its opacity: a light grey (0.12 of black) in
    /// both styles, under which a thin line stays plain and over which a
    /// link's heavier line stands out as another link.
    pub(crate) fn body(&self) -> (&'static str, f64) {
        match self {
            Style::Textbook | Style::Handout => ("#000", 0.12),
        }
    }

    /// Font size of a text.
    pub(crate) fn font_size(&self, size: TextSize) -> f64 {
        match size {
            TextSize::Letter => LETTER_SIZE,
            TextSize::Small => 13.0,
            TextSize::Tick => 12.0,
        }
    }
}

/// Distance between the strokes of ground hatching, page units (the
/// writer's and the hand-drawn sketches' alike).
pub(crate) const HATCH_SPACING: f64 = 6.0;

/// Font size of a point's letter ([`TextSize::Letter`]), page units.
pub(crate) const LETTER_SIZE: f64 = 17.0;

/// A detail's frame on the main view with no side this many ems (of a
/// point's letter) long is too small to letter two pins beside it: they
/// are lettered in the detail alone. The layout keeps to it, and the
/// scene keeps a detail's box grown past the crank centre's bearing
/// under it.
pub(crate) const SMALL_DETAIL_EMS: f64 = 4.0;
/// Depth of the strip of ground hatching, page units.
/// Length of an arrowhead, page units (the renderer's).
pub(crate) const ARROW_LENGTH: f64 = 10.0;
pub(crate) const HATCH_DEPTH: f64 = 6.5;
/// Font size of notes, the largest they are set in (the layouts that
/// leave room for notes and the writer that sets them share it).
pub(crate) const NOTE_SIZE: f64 = 13.0;
/// Line height of notes, page units.
pub(crate) const NOTE_LINE: f64 = 17.0;
/// Radius of a pin joint's circle, page units: the layout draws it, and
/// the scene joins to a pin's letter a dot under it.
pub(crate) const PIN_RADIUS: f64 = 4.2;
/// Radius of a constructed point's dot, page units.
pub(crate) const DOT_RADIUS: f64 = 2.1;
/// Width of the pen a pin's circle is drawn with, page units.
pub(crate) const PIN_PEN: f64 = 1.3;
/// Length of each side of a right-angle mark, page units (the scene
/// draws one only on a leg longer than two of them).
pub(crate) const RIGHT_ANGLE: f64 = 10.0;
/// Radius of an angle mark's arc, page units: the layout draws it, and
/// the scene leaves out an angle too small to open at it.
pub(crate) const ANGLE_RADIUS: f64 = 28.0;
/// The largest radius of an angle mark's arc, page units: a small angle's
/// arc is drawn farther out, up to this, so that it opens
/// ([`angle_radius`]).
pub(crate) const ANGLE_RADIUS_MOST: f64 = 60.0;
/// The arc length (page units) an angle mark is given where its radius
/// allows: φ = 6.8° at [`ANGLE_RADIUS`] drew an arc of 3 units, under
/// its letter (Fig. 62 at its default).
const ANGLE_ARC: f64 = 10.0;

/// The radius (page units) of the arc of an angle of `sweep` radians: the
/// one giving [`ANGLE_ARC`] of arc, within [`ANGLE_RADIUS`] (a large
/// angle) and [`ANGLE_RADIUS_MOST`] (a small one; a zero or non-finite
/// sweep takes the most).
pub(crate) fn angle_radius(sweep: f64) -> f64 {
    let wanted = ANGLE_ARC / sweep.abs();
    if wanted.is_nan() {
        return ANGLE_RADIUS_MOST;
    }
    wanted.clamp(ANGLE_RADIUS, ANGLE_RADIUS_MOST)
}
