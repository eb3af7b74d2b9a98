//! The worked steps of a handout: §35–37 and Ng for one engine, each step
//! its text, figures and the values read off the construction beside the
//! exact ones, all taken from one [`Reading`].
//!
//! One file per group of steps: the mechanism to scale (§35), the velocity
//! (D and E, the velocity scale), the acceleration (Kisch's construction,
//! the acceleration scale), the rod's rates (§37), the velocity and
//! acceleration polygons (the relative-velocity method), the OM line and the
//! forces (Ng), the diagrams and, given a mass, the engine's dynamics.
//! Each step is a function of the [`Work`]
//! they share, and its rows a function of their own, so that an exercise
//! sheet has every row without drawing a figure.

mod acceleration;
mod data;
mod diagrams;
mod dynamics;
mod forces;
mod mechanism;
mod polygons;
mod rod;
mod row;
mod velocity;
mod work;

pub(super) use data::data_sentence;
pub(super) use row::{Row, Value};

use super::Handout;
use super::figures;
use crate::construct::Reading;
use crate::error::Result;
use crate::figure::Figure;
use acceleration::{acceleration_scale, acceleration_scale_rows, kisch, kisch_rows};
use diagrams::diagrams;
use dynamics::{dynamics, exercise_dynamics};
use forces::{forces, forces_rows};
use mechanism::{mechanism, mechanism_rows};
use polygons::polygons;
use rod::{rod, rod_rows};
use velocity::{d_and_e, d_and_e_rows, velocity_scale, velocity_scale_rows};
use work::Work;

/// A figure of a step: inline SVG and its caption (rich text).
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Picture {
    pub svg: String,
    pub caption: String,
}

impl Picture {
    /// `figure` inlined, its ids prefixed with `prefix`, under `caption`.
    fn of(figure: &Figure, prefix: &str, caption: impl Into<String>) -> Self {
        Self {
            svg: figures::inline(figure, prefix),
            caption: caption.into(),
        }
    }
}

/// One step of the handout.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Step {
    pub id: &'static str,
    pub title: String,
    /// The seed's section and figure.
    pub source: &'static str,
    /// Paragraphs, rich text.
    pub text: Vec<String>,
    pub pictures: Vec<Picture>,
    pub rows: Vec<Row>,
}

/// The ids of the steps of the engine's dynamics, whose rows the page's
/// summary adds to [`rows`] (an exercise asks those of the first,
/// [`exercise_rows`]).
pub(super) const DYNAMICS: [&str; 3] = ["inertia", "turning-moment", "flywheel"];

/// Every step of the handout, in order; the OM line and the forces only
/// when a torque is given, the dynamics only when a mass is.
pub(super) fn steps(h: &Handout, r: &Reading) -> Result<Vec<Step>> {
    let w = Work::new(h, r);
    let mut steps = vec![
        mechanism(&w)?,
        d_and_e(&w)?,
        velocity_scale(&w),
        kisch(&w)?,
        acceleration_scale(&w)?,
        rod(&w)?,
        polygons(&w)?,
    ];
    steps.extend(forces(&w)?);
    steps.push(diagrams(&w)?);
    steps.extend(dynamics(&w)?);
    Ok(steps)
}

/// The rows of every value a handout and its exercise show, in order: the
/// rows of the steps, without their figures.
pub(super) fn rows(h: &Handout, r: &Reading) -> Vec<Row> {
    let w = Work::new(h, r);
    [
        mechanism_rows(&w),
        d_and_e_rows(&w),
        velocity_scale_rows(&w),
        kisch_rows(&w),
        acceleration_scale_rows(&w),
        rod_rows(&w),
        forces_rows(&w),
    ]
    .concat()
}

/// The dynamics an exercise sets, with a mass: the data sentence (the
/// mass, the gas force at the pose) and the rows of the forces at the
/// pose (the gas force given, the rest asked); `None` without a mass.
pub(super) fn exercise_rows(h: &Handout, r: &Reading) -> Result<Option<(String, Vec<Row>)>> {
    exercise_dynamics(&Work::new(h, r))
}

/// A number as a page shows it: four significant figures, a true minus
/// sign, powers of ten beyond 10⁹ and below 10⁻⁴ (`1.500 × 10¹⁰`).
pub(super) fn show(x: f64) -> String {
    crate::number::sig_on(x, crate::number::SetOn::Page)
}

/// A given number (a datum, not a result) as a page shows it: [`show`]
/// without trailing zeros (`250`, `0.5`, `40`).
pub(super) fn short(x: f64) -> String {
    crate::number::short_on(x, crate::number::SetOn::Page)
}
