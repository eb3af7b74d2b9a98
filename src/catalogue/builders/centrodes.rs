//! Textbook Fig. 61: the rod's fixed centrode (full line: the locus of D
//! in the frame) and moving centrode (dotted: the locus of D in the rod,
//! carried with the rod at the drawn pose), with the construction of D for
//! that pose, where the two touch.
//!
//! The mechanism's centrode layer draws the curves, traced by the curve
//! engine in two branches each (θ from −90° to 90° and from 90° to 270°:
//! both centrodes run off to infinity where D does), clipped to the frame;
//! this figure gives them the textbook's line styles and a legend. The
//! default rod is shorter than §35's (n = 2.5, [`FigureName::mechanism`]):
//! with n = 6 both centrodes are nearly straight and close to the slider's
//! vertical.
//!
//! [`FigureName::mechanism`]: crate::catalogue::FigureName::mechanism

use super::{Ctx, Sheet, short};
use crate::diagram::Plot;
use crate::error::Result;
use crate::figure::{Dash, Figure, Item, Panel, Part, Role};
use crate::geom::{Frame, Point};
use crate::scene::Layer;

pub(in crate::catalogue) fn build(ctx: &Ctx) -> Result<Figure> {
    let page = ctx.page();
    let mut sheet = Sheet::new(ctx);
    sheet.mechanism(ctx, false, true);
    let m = ctx.mechanism;
    let offset = if m.offset() != 0.0 {
        Some(crate::scene::offset_note(
            &ctx.scene(page.width(), page.height())?,
        ))
    } else {
        None
    };
    // Two lines of notes, three with the offset's.
    let notes_height = if offset.is_some() { 62.0 } else { 44.0 };
    // The legend's band below the mechanism, where nothing is drawn.
    let band = Plot::band(2);
    let scene = ctx
        .scene(page.width(), page.height() - notes_height - band)?
        .with_layers([Layer::Mechanism, Layer::Centrodes]);
    // cannot fail: a scene's figure has its main view as its first panel
    // (`draw::build` puts it there).
    #[allow(clippy::indexing_slicing)]
    let panel = scene.figure()?.panels()[0].clone();
    let r = *panel.rect();
    let area = Frame::from_origin_size(r.min().x, r.min().y, r.width(), r.height() + band);
    let items = drawn(&panel);
    let mut plot = Plot::with_map(
        "centrodes",
        area,
        area,
        *panel.transform(),
        ctx.tolerance,
        ctx.font,
    )
    .blocks_below();
    for item in &items {
        plot.avoid(item);
    }
    plot.legend_line("fixed centrode: *D* in the frame *d*", Dash::Solid);
    plot.legend_line(
        &format!(
            "moving centrode: *D* in the rod *b*, here at θ = {}°",
            short(ctx.angle.degrees())
        ),
        Dash::Dotted,
    );
    let legend = plot.finish();
    let panel = Panel::new(panel.id(), *panel.rect(), *panel.transform(), items)
        .with_items(legend.items().iter().cloned());
    sheet.panel(panel);
    let top = area.max().y + 2.0;
    sheet.fit(top + notes_height);
    let mut lines = vec![
            format!(
                "*r* = {} {u}, *l* = {} {u} (*n* = {}). *D*: *CB* produced meets the perpendicular to the stroke at *A*; the centrodes touch there and the moving one rolls on the fixed one.",
                short(m.crank()),
                short(m.rod()),
                short(m.ratio()),
                u = ctx.unit()
            ),
            "Both run off to infinity as θ → 90° and 270°, where *D* is at infinity; each is drawn in two branches.".into(),
        ];
    lines.extend(offset);
    sheet.notes(Point::new(20.0, top), &lines);
    Ok(sheet.finish())
}

/// The scene's items as this figure draws them: the centrodes' names give
/// way to the legend, the offset's caption line joins the sheet's notes,
/// and the moving centrode is dotted.
fn drawn(panel: &Panel) -> Vec<Item> {
    panel
        .items()
        .iter()
        .filter(|i| {
            let centrode = matches!(i.part, Part::FixedCentrode | Part::MovingCentrode);
            !(centrode && i.role == Role::Label) && i.part != Part::Notes
        })
        .map(|i| {
            if i.part == Part::MovingCentrode {
                Item::new(i.id.clone(), Role::Curve, i.shape.clone())
                    .dashed(Dash::Dotted)
                    .as_part(i.part)
            } else {
                i.clone()
            }
        })
        .collect()
}
