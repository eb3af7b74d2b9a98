//! §36, Fig. 64: the velocity and acceleration diagrams over the turn.

use super::work::Work;
use super::{Picture, Step};
use crate::catalogue::FigureName;
use crate::error::Result;
use crate::handout::figures;

/// §36, Fig. 64: the construction repeated round the turn, as diagrams of
/// the piston's velocity and acceleration; no rows of its own.
pub(super) fn diagrams(w: &Work) -> Result<Step> {
    let velocity = figures::diagram(w.h, FigureName::Fig64VelocityDiagrams)?;
    let acceleration = figures::diagram(w.h, FigureName::AccelerationDiagrams)?;
    Ok(Step {
        id: "diagrams",
        title: "Velocity and acceleration diagrams".into(),
        source: "§36, Fig. 64",
        text: vec![
            "Repeating the construction for a number of crank positions gives the diagrams: the polar diagram of piston velocity (*CE*′ = *CE* set off on the crank), the velocity on a distance base (*E*″ over *A*) and on a time base, against simple harmonic motion; then the same for the acceleration (*CG*). The pose worked above is marked.".into(),
        ],
        pictures: vec![
            Picture::of(
                &velocity,
                "fig-64",
                "Piston velocity: polar diagram, distance base, time base.",
            ),
            Picture::of(
                &acceleration,
                "acceleration",
                "Piston acceleration: distance base, time base, polar diagram.",
            ),
        ],
        rows: Vec::new(),
    })
}
