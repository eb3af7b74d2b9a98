//! Sizes of the renderer's symbols and text, in page units: the same at
//! every scale and in both styles.

/// Room between a point and its letter's box.
pub(crate) const LETTER_GAP: f64 = 4.0;
/// Half the width of an arrowhead at its back.
pub(crate) const ARROW_HALF_WIDTH: f64 = 3.2;
pub(crate) use crate::figure::{
    ANGLE_RADIUS, ARROW_LENGTH, DOT_RADIUS, HATCH_DEPTH, HATCH_SPACING, NOTE_LINE, NOTE_SIZE,
    PIN_PEN, PIN_RADIUS, RIGHT_ANGLE,
};
/// How much larger each further angle mark at the same vertex is drawn,
/// so that two adjacent angles (Ng's φ and β at the crank pin) read as
/// two arcs, not one.
pub(crate) const ANGLE_STEP: f64 = 12.0;
/// Half the size of a data marker.
pub(crate) const MARKER_RADIUS: f64 = 3.6;
