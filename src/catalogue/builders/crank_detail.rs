//! The detail of a short crank below a drawing, shared by the figures
//! that draw a long rod on the mechanism (the coupler curves, Fig. 60):
//! when a crank is drawn too short to be seen, the round magnification
//! that enlarges it, and the crank circle drawn in the detail.

use crate::figure::{Part, Role, Shape};
use crate::geom::Point;
use crate::scene::Canvas;

/// The page length under which a crank is enlarged in a detail below
/// the drawing: at l = 53 r in Fig. 60, and at l = 30 r in the coupler
/// curves, it was a speck of two pin circles, its letter naming nothing
/// seen.
pub(super) const CRANK_SEEN: f64 = 40.0;

/// Whether a crank drawn `length` page units long (NaN: none drawn)
/// is too short to be seen, and so enlarged in a detail.
pub(super) fn too_short(length: f64) -> bool {
    length < CRANK_SEEN
}

/// The least of the round magnifications, `steps` (from 1 up to under
/// 10) times a power of ten, not below `x`; `None` where `x` is not
/// positive and finite.
pub(super) fn round_above(x: f64, steps: &[f64]) -> Option<f64> {
    if !(x > 0.0 && x.is_finite()) {
        return None;
    }
    let decade = 10f64.powf(x.log10().floor());
    (steps.iter().chain(&[10.0]))
        .map(|m| m * decade)
        .find(|m| *m >= x * (1.0 - 1e-12))
}

/// The crank circle about `c` of radius `r` (world units), drawn on `s`
/// as the crank circle's part.
pub(super) fn crank_circle(s: &mut Canvas, c: Point, r: f64) {
    s.with_part(Part::CrankCircle, |s| {
        s.push(
            "circle-crank",
            Role::Curve,
            Shape::Circle {
                centre: c,
                radius: r,
            },
        );
    });
}
