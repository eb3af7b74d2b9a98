//! Ovals traced by points of the rod (§34): "a point on the link b between
//! A and B describes an oval curve", here for AP = ¼, ½ and ¾ of AB, drawn
//! on the mechanism with each point marked at the drawn pose.

use super::{Ctx, PER_DEGREE, Sheet, short};
use crate::angle::Angle;
use crate::construct::CouplerPoint;
use crate::diagram::{Curve, Plot};
use crate::error::Result;
use crate::figure::{Dash, Figure, Item, PageRect, Role, Shape};
use crate::geom::{Point, Vector};
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
    let scene = ctx
        .scene(page.width(), page.height() - notes_height - band)?
        .with_layers([Layer::Mechanism]);
    // cannot fail: a scene's figure has its main view as its first panel
    // (`draw::build` puts it there).
    #[allow(clippy::indexing_slicing)]
    let panel = scene.figure()?.panels()[0].clone();
    let r = *panel.rect();
    let area = PageRect::new(r.x, r.y, r.width, r.height + band);
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
        plot.avoid(item);
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
    let top = area.y + area.height;
    sheet.fit(top + notes_height);
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
