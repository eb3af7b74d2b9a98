//! Ovals traced by points of the rod (§34): "a point on the link b between
//! A and B describes an oval curve", here for AP = ¼, ½ and ¾ of AB, drawn
//! on the mechanism with each point marked at the drawn pose.

use super::{Ctx, PER_DEGREE, Sheet, short};
use crate::angle::Angle;
use crate::construct::CouplerPoint;
use crate::diagram::{Curve, Plot};
use crate::error::Result;
use crate::figure::{Dash, Figure, Item, NOTE_LINE, Panel, Role, Shape};
use crate::geom::{Frame, Point, Vector};
use crate::scene::Layer;

/// The points drawn: fraction AP/AB, name and dash.
const POINTS: [(f64, &str, &str, Dash); 3] = [
    (0.25, "25", "¼", Dash::Solid),
    (0.5, "50", "½", Dash::Dashed),
    (0.75, "75", "¾", Dash::DashDot),
];

pub(in crate::catalogue) fn build(ctx: &Ctx) -> Result<Figure> {
    let page = ctx.page();
    let m = ctx.mechanism;
    let mut sheet = Sheet::new(ctx);
    sheet.mechanism(ctx, false, true);
    sheet.meta("coupler_points", serde_json::json!(POINTS.map(|(t, ..)| t)));
    let notes_height = 30.0;
    // The legend's band below the mechanism, where nothing is drawn.
    let band = Plot::band(POINTS.len());
    let drawn = drawing(ctx, page.height() - notes_height - band)?;
    sheet.narrow(drawn.width())?;
    // cannot fail: a scene's figure has its main view as its first panel
    // (`draw::build` puts it there).
    #[allow(clippy::indexing_slicing)]
    let panel = drawn.panels()[0].clone();
    let r = *panel.rect();
    // The scene's notes go below the legend's band, which lies on the
    // drawing's foot: a narrow page has no room beside them for it.
    let (panel, notes_end) = notes_below(panel, band);
    let area = Frame::from_origin_size(r.min().x, r.min().y, r.width(), r.height() + band);
    let mut plot = Plot::with_map(
        "coupler",
        area,
        area,
        *panel.transform(),
        ctx.tolerance,
        ctx.font,
    )
    .blocks_below();
    for item in panel.items() {
        if !matches!(item.shape, Shape::Note { .. }) {
            plot.avoid(item);
        }
    }
    let pose = ctx.pose();
    for (k, (t, id, frac, dash)) in POINTS.into_iter().enumerate() {
        // cannot fail: the fractions of POINTS are constants in [0, 1].
        #[allow(clippy::expect_used)]
        let q = CouplerPoint::new(t).expect("fractions in [0, 1]");
        let curve = move |deg: f64| -> Option<(Point, Vector)> {
            let pose = m.pose(Angle::from_degrees(deg).ok()?);
            Some((q.point(&pose), q.derivative(&pose) * PER_DEGREE))
        };
        let name = format!("P_{}", k + 1);
        let pieces: [(&dyn Curve, _); 1] = [(&curve, 0.0..=360.0)];
        plot.curve(
            &format!("curve-coupler-{id}"),
            &pieces,
            dash,
            Some(&format!("*{name}*, *AP*_{} = {frac} *AB*", k + 1)),
        )?;
        let p = q.point(&pose);
        plot.push(Item::new(
            format!("point-P{}", k + 1),
            Role::Construction,
            Shape::Dot { centre: p },
        ));
        plot.push(super::letter(&format!("P{}", k + 1), p, &name));
    }
    let drawn = plot.finish();
    sheet.panel(panel.with_items(drawn.items().iter().cloned()));
    let top = (area.max().y).max(notes_end);
    match page.fits_width() {
        // The figure's own page: as tall as its drawing, enlarged or not.
        true => sheet.height(top + notes_height + super::MARGIN),
        false => sheet.fit(top + notes_height),
    }
    sheet.notes(
        Point::new(20.0, top),
        &[format!(
            "*r* = {} {u}, *l* = {} {u} (*n* = {}), drawn at θ = {}°. *A* traces the line of stroke, *B* the crank circle, every point between an oval.",
            short(m.crank()),
            short(m.rod()),
            short(m.ratio()),
            short(ctx.angle.degrees()),
            u = ctx.unit()
        )],
    );
    Ok(sheet.finish())
}

/// `panel` with its notes (the scene's, below its drawing) moved down by
/// `band`, and where the lowest of them then ends (the panel's foot
/// where it has none).
fn notes_below(panel: Panel, band: f64) -> (Panel, f64) {
    let r = *panel.rect();
    let mut end = r.max().y;
    let items: Vec<Item> = panel
        .items()
        .iter()
        .cloned()
        .map(|mut item| {
            if let Shape::Note { corner, lines } = &mut item.shape {
                corner.y += band;
                end = end.max(corner.y + NOTE_LINE * lines.len() as f64);
            }
            item
        })
        .collect();
    (Panel::new(panel.id(), r, *panel.transform(), items), end)
}

/// Where the ovals turn, world x and height above the line of stroke:
/// P = A + t (B − A) with A on the line of stroke, so P is highest, t
/// (r − e) above it, with B at the top of the crank circle, and lowest,
/// t (r + e) below it, with B at the foot.
fn turns(ctx: &Ctx) -> Vec<(f64, f64)> {
    let m = ctx.mechanism;
    let (r, l, e) = (m.crank(), m.rod(), m.offset());
    // A's distance from the crank centre's perpendicular with B at
    // (0, ±r): l² = x² + (e ∓ r)².
    let top = (l * l - (e - r) * (e - r)).sqrt();
    let foot = (l * l - (e + r) * (e + r)).sqrt();
    POINTS
        .iter()
        .flat_map(|&(t, ..)| {
            [
                ((1.0 - t) * top, t * (r - e)),
                ((1.0 - t) * foot, -t * (r + e)),
            ]
        })
        .collect()
}

/// The most a narrowed drawing is enlarged by ([`drawing`]).
const MOST_ENLARGED: f64 = 1.6;

/// The mechanism at the pose, `height` units tall. On the figure's own
/// page it is narrowed to what it draws, as a mechanism figure's is; a
/// drawing that then takes less than 85 % of the page's width (a short
/// rod, whose crank circle is as tall as the engine is long) is drawn
/// again larger, up to [`MOST_ENLARGED`] times, so that the three points
/// on its rod and their letters stand apart.
fn drawing(ctx: &Ctx, height: f64) -> Result<Figure> {
    let page = ctx.page();
    let scene = |height: f64| -> Result<Figure> {
        let scene = ctx
            .scene(page.width(), height)?
            .with_layers([Layer::Mechanism])
            .with_guides_clear_of(turns(ctx));
        let fitted = scene.page().with_width_fitted();
        match page.fits_width() {
            true => scene.with_page(fitted).figure(),
            false => scene.figure(),
        }
    };
    let drawn = scene(height)?;
    let larger = (0.85 * page.width() / drawn.width()).min(MOST_ENLARGED);
    match page.fits_width() && larger > 1.05 {
        true => scene(height * larger),
        false => Ok(drawn),
    }
}
