//! Exercise sheets and their answer keys. A sheet draws only the mechanism
//! to scale on a faint grid, with the data and empty answer fields; the
//! key draws the whole construction and gives every answer read off it
//! beside the exact value.

use super::command::exercise_command;
use super::page::{conventions, data_table, footer, picture, plain_data, style, values_table};
use super::scale::round_scale;
use super::steps::{Picture, data_sentence, exercise_rows, rows};
use super::{Handout, figures};
use crate::construct::Reading;
use crate::error::Result;
use crate::html::{document, rich};
use crate::render::to_svg_with;
use crate::{catalogue::FigureName, scene::Layer};
use maud::html;

/// Page units of a grid square, about: 4.5 mm when a 760-unit figure is
/// printed across an A4 page.
const GRID_SQUARE: f64 = 20.0;

/// The heading of a sheet or key.
fn heading(h: &Handout, what: &str) -> String {
    match &h.title {
        Some(t) => format!("{t}: {what}"),
        None => format!("The slider-crank engine: {what}"),
    }
}

/// The exercise sheet: data, the mechanism to scale on a grid, what to
/// construct, and a field for each answer. No answer is on it.
pub(super) fn sheet(h: &Handout, r: &Reading) -> Result<String> {
    let SheetDrawing {
        svg,
        stated,
        step,
        unit: u,
    } = sheet_drawing(h)?;
    let dynamics = exercise_rows(h, r)?;
    let mut all = rows(h, r);
    all.extend(dynamics.iter().flat_map(|d| d.1.clone()));
    let asked: Vec<_> = all.into_iter().filter(|row| row.asked).collect();
    let title = heading(h, "exercise");
    let tasks = tasks(h);
    let body = html! {
        header.title {
            h1 { (title) }
            p.subtitle { "Name: ______________________   Date: ____________" }
        }
        p { (rich(&data_sentence(h))) }
        @if let Some((data, _)) = &dynamics { p { (rich(data)) } }
        (data_table(h))
        (conventions(h))
        div.sheet-figure {
            (picture(
                &Picture {
                    svg,
                    caption: format!(
                        "The engine to scale at θ = {}°.{stated} Grid squares of {} {u}, lines through the crank centre *C*.",
                        super::steps::short(h.angle().degrees()),
                        crate::number::plain(step)
                    ),
                },
                "Drawing.",
            ))
        }
        section.step {
            h2 { "Construct" }
            ol {
                @for t in &tasks { li { (rich(t)) } }
            }
        }
        section.step {
            h2 { "Answers" }
            div.block {
                table.answers {
                    thead { tr { th { "quantity" } th { "your answer" } th.unit { "unit" } } }
                    tbody {
                        @for row in &asked {
                            tr {
                                td { (rich(&row.quantity)) }
                                td.answer {}
                                td.unit { (rich(&row.unit)) }
                            }
                        }
                    }
                }
            }
        }
        (footer(&exercise_command(h)))
    };
    Ok(document(
        &format!("{title}: {}", plain_data(h)),
        &style(h.paper()),
        body,
    ))
}

/// The sheet's drawing: the mechanism alone on a grid, and what its
/// caption says of it.
struct SheetDrawing {
    /// The inline SVG, sized in millimetres where it is drawn to a scale.
    svg: String,
    /// The sentence that states the scale; empty where there is none
    /// (the drawing then fits the page).
    stated: String,
    /// The side of a grid square, in the handout's length unit.
    step: f64,
    /// The handout's length unit.
    unit: String,
}

/// Draws the mechanism alone to scale on a faint grid: at a round scale
/// where one fits the paper (the SVG then sized in millimetres, to be
/// printed at 100 %), else fitted to the page with no scale stated.
fn sheet_drawing(h: &Handout) -> Result<SheetDrawing> {
    let fitted = figures::mechanism(
        h,
        FigureName::Fig63Velocity,
        Some(&[Layer::Mechanism, Layer::Velocity]),
    )?;
    let figure = figures::only_the_mechanism(&fitted);
    // cannot fail: `fitted` is a scene's figure, whose first panel is its
    // main view (`draw::build`), and `only_the_mechanism` keeps that one.
    #[allow(clippy::indexing_slicing)]
    let panel = &figure.panels()[0];
    let step = figures::grid_step(panel, GRID_SQUARE);
    let grid = figures::grid(panel, step);
    let svg = to_svg_with(
        &figure,
        &figures::inline_options("sheet").with_underlay(grid),
    );
    let unit = h.units().length().as_str().to_string();
    let scale = round_scale(figure.width(), panel.transform().scale(), &unit, h.paper());
    let (svg, stated) = match &scale {
        Some(s) => (
            svg.replacen(
                "<svg",
                &format!(
                    "<svg style=\"width: {}mm; height: {}mm; max-width: none; max-height: none\"",
                    crate::render::fmt(s.width_mm),
                    crate::render::fmt(s.width_mm * figure.height() / figure.width())
                ),
                1,
            ),
            format!(
                " Drawn at {} (print at 100 %, not fitted to the page).",
                s.ratio
            ),
        ),
        None => (svg, String::new()),
    };
    Ok(SheetDrawing {
        svg,
        stated,
        step,
        unit,
    })
}

/// What the sheet asks to construct, in order (the forces only with a
/// torque).
fn tasks(h: &Handout) -> Vec<String> {
    let mut tasks = vec![
        "Produce *CB* to meet the perpendicular to the stroke through *A* in *D*, and *AB* to meet the perpendicular to the stroke through *C* in *E* (§36, Fig. 63). Measure *CE* and *BD*.".to_string(),
        "Write down the velocity scale and find the piston velocity from *CE*, signed as d*x*/d*t* (negative towards the crank).".into(),
        "Find *F* and *G* by Kisch's construction (§36, Fig. 66): the semicircle on *AB*, the circle about *B* through *E*, *HFG* perpendicular to *AB*. Measure *CG* and *FG*; enlarge the construction beside the drawing if it is too small to read.".into(),
        "Write down the acceleration scale and find the piston acceleration from *CG*, and the rod's angular velocity (*V*_c/*BD*) and angular acceleration (ω² · *FG*/*l*) (§37).".into(),
    ];
    if h.torque().is_some() {
        tasks.push("With the crank torque *T*, find the slider force *F*_p = *T*/*OM* (*OM* = *CE*), the side thrust, the force with friction, and the transmission angle (Ng, eq. 6–11).".into());
    }
    if h.dynamics().is_some() {
        tasks.push("With the reciprocating mass *m*, find the inertia force *F*_i = −*m*ω²·*CG* (positive towards the crank), the piston effort *F* = *F*_g + *F*_i with the gas force *F*_g given, and the crank effort *T* = *F*·*OM* (*OM* = *CE*; §36, Ng eq. 2).".into());
    }
    tasks
}

/// The answer key: the data, the construction drawn (and Ng's figure with
/// a torque), every answer read off it beside the exact value.
pub(super) fn key(h: &Handout, r: &Reading) -> Result<String> {
    let title = heading(h, "answer key");
    let construction = figures::mechanism(h, FigureName::Fig67Example, None)?;
    let mut pictures = vec![Picture {
        svg: figures::inline(&construction, "key"),
        caption: "The construction: *D* and *E*, Kisch's construction for *F* and *G*, the scales."
            .into(),
    }];
    if h.torque().is_some() {
        let ng = figures::mechanism(h, FigureName::NgFig1Torque, None)?;
        pictures.push(Picture {
            svg: figures::inline(&ng, "key-ng"),
            caption: "The torque line *OM* and the forces (Ng's letters: *O* crank centre, *C* crank pin, *P* slider).".into(),
        });
    }
    let dynamics = exercise_rows(h, r)?;
    if dynamics.is_some() {
        let forces = figures::dynamics(h, FigureName::InertiaForce)?;
        pictures.push(Picture {
            svg: figures::inline(&forces, "key-inertia"),
            caption: "The inertia force −*m*ω²·*CG* from Klein's construction, drawn at the cross-head and resolved along the rod and on the guides, and its crank effort through *OM*.".into(),
        });
    }
    let mut all = rows(h, r);
    all.extend(dynamics.iter().flat_map(|d| d.1.clone()));
    let body = html! {
        header.title {
            h1 { (title) }
            p.subtitle { "For the teacher: the answers to the exercise sheet of the same engine." }
        }
        p { (rich(&data_sentence(h))) }
        @if let Some((data, _)) = &dynamics { p { (rich(data)) } }
        (data_table(h))
        (values_table(&all, Some("The answers")))
        @for (i, p) in pictures.iter().enumerate() {
            (picture(p, &format!("Figure {}.", i + 1)))
        }
        (footer(&exercise_command(h)))
    };
    Ok(document(
        &format!("{title}: {}", plain_data(h)),
        &style(h.paper()),
        body,
    ))
}
