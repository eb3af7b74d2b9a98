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
//! [`FigureName::mechanism`]: crate::FigureName::mechanism

use super::{Ctx, Sheet, short};
use crate::diagram::Plot;
use crate::error::Result;
use crate::figure::{Dash, Figure, Item, Role};
use crate::geom::Point;
use crate::scene::Layer;

pub(super) fn build(ctx: &Ctx) -> Result<Figure> {
    let page = ctx.page();
    let mut sheet = Sheet::new(ctx);
    sheet.mechanism(ctx, false, true);
    let notes_height = 44.0;
    let scene = ctx
        .scene(page.width(), page.height() - notes_height)?
        .with_layers([Layer::Mechanism, Layer::Centrodes]);
    let panel = scene.figure().panels()[0].clone();
    let items: Vec<Item> = panel
        .items()
        .iter()
        .filter(|i| !i.id.starts_with("label-centrode"))
        .map(|i| {
            if i.id.starts_with("curve-centrode-moving") {
                Item::new(i.id.clone(), Role::Curve, i.shape.clone()).dashed(Dash::Dotted)
            } else {
                i.clone()
            }
        })
        .collect();
    let mut plot = Plot::with_map(
        "centrodes",
        *panel.rect(),
        *panel.rect(),
        *panel.transform(),
        ctx.tolerance,
        ctx.font,
    );
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
    let panel = crate::figure::Panel::new(panel.id(), *panel.rect(), *panel.transform(), items)
        .with_items(legend.items().iter().cloned());
    sheet.panel(panel);
    let m = ctx.mechanism;
    sheet.notes(
        Point::new(20.0, page.height() - notes_height + 2.0),
        &[
            format!(
                "*r* = {} {u}, *l* = {} {u} (*n* = {}). *D*: *CB* produced meets the perpendicular to the stroke at *A*; the centrodes touch there and the moving one rolls on the fixed one.",
                short(m.crank()),
                short(m.rod()),
                short(m.ratio()),
                u = ctx.unit()
            ),
            "Both run off to infinity as θ → 90° and 270°, where *D* is at infinity; each is drawn in two branches.".into(),
        ],
    );
    Ok(sheet.finish())
}
