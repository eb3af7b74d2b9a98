//! Ovals traced by points of the rod (§34): "a point on the link b between
//! A and B describes an oval curve", here for AP = ¼, ½ and ¾ of AB, drawn
//! on the mechanism with each point marked at the drawn pose. A long rod,
//! which draws the ovals a few units tall and the crank a speck, adds a
//! detail of each oval and of the crank below the drawing.

use super::{Ctx, PER_DEGREE, Sheet, crank_detail, short};
use crate::angle::Angle;
use crate::construct::CouplerPoint;
use crate::diagram::{Curve, Plot};
use crate::error::Result;
use crate::figure::{Dash, Figure, Item, NOTE_LINE, Panel, Role, Shape};
use crate::geom::{Frame, Point, Vector};
use crate::scene::Layer;

/// The points drawn: fraction AP/AB, name and dash. Not long dash and
/// dot, the line of stroke's centre line through every oval: P₃'s oval,
/// so drawn, read as a second centre line where they ran together.
const POINTS: [(f64, &str, &str, Dash); 3] = [
    (0.25, "25", "¼", Dash::Solid),
    (0.5, "50", "½", Dash::Dashed),
    (0.75, "75", "¾", Dash::Dotted),
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
    // The details' boxes first, which the points' letters keep clear of.
    let top = (area.max().y).max(notes_end);
    let transform = *panel.transform();
    // Across the page as narrowed to the drawing.
    let windows = details(ctx, &transform, top, page.width().min(drawn.width()))?;
    for (k, (region, _)) in windows.iter().enumerate() {
        plot.push(Item::new(
            format!("detail-box-{k}"),
            Role::Auxiliary,
            Shape::Polyline {
                points: vec![
                    region.min(),
                    Point::new(region.max().x, region.min().y),
                    region.max(),
                    Point::new(region.min().x, region.max().y),
                ],
                closed: true,
            },
        ));
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
    let mut top = top;
    let enlarged = !windows.is_empty();
    for (_, window) in windows {
        top = top.max(window.rect().max().y + 6.0);
        sheet.detail(window);
    }
    match page.fits_width() || enlarged {
        // The figure's own page: as tall as its drawing, enlarged or not;
        // any page grown for the details below the drawing.
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

/// The least a long rod's ovals are drawn tall, and its crank long, on
/// the page, page units (in the main view or a detail): at l = 30 r the
/// ovals were a few units tall, the crank a speck with C's letter at B.
const SEEN: f64 = crank_detail::CRANK_SEEN;
/// What a detail draws them at, at least, page units: [`SEEN`] and a
/// little more.
const ENLARGED: f64 = 46.0;
/// The least magnification a detail is drawn at.
const LEAST_ENLARGED: f64 = 1.5;
/// Room about a detail's subject, page units in the detail.
const WINDOW_PAD: f64 = 22.0;
/// Room between the drawing and the details below it, and between two
/// details, page units.
const WINDOW_GAP: f64 = 12.0;

/// What a detail enlarges: the world box it shows (before its room) and
/// the length in it to be drawn [`ENLARGED`].
type Subject = ((Point, Point), f64);

/// The magnification steps (times a power of ten).
const STEPS: [f64; 9] = super::coriolis::FINE_STEPS;

/// The least of the round [`STEPS`] times a power of ten not below `x`
/// (at least 1).
fn round_above(x: f64) -> f64 {
    crank_detail::round_above(x, &STEPS)
        .filter(|_| x > 1.0)
        .unwrap_or(1.0)
}

/// Where the main view (its map `t`) draws the crank shorter than
/// [`SEEN`] or an oval less tall (a long rod), a row of details below
/// `top` across a page `width` wide: the crank about C, and each oval
/// with its point and the rod through it, each at the round
/// magnification that draws it [`ENLARGED`] (the crank's length, the
/// oval's height), captioned with it. Each with the world region it
/// enlarges (boxed in the main view). None where all read.
fn details(
    ctx: &Ctx,
    t: &crate::figure::PageFromWorld,
    top: f64,
    width: f64,
) -> Result<Vec<(Frame, Plot)>> {
    let m = ctx.mechanism;
    let scale = t.scale();
    let pose = ctx.pose();
    let r = m.crank();
    // The ovals' boxes, from a point every degree.
    let ovals: Vec<(Point, Point)> = (POINTS.iter())
        .map(|&(t, ..)| {
            let q = CouplerPoint::new(t).ok();
            let pts: Vec<Point> = (0..360)
                .filter_map(|d| Angle::from_degrees(f64::from(d)).ok())
                .filter_map(|a| Some(q.as_ref()?.point(&m.pose(a))))
                .collect();
            pts.iter().fold(
                (
                    Point::new(f64::INFINITY, f64::INFINITY),
                    Point::new(f64::NEG_INFINITY, f64::NEG_INFINITY),
                ),
                |(lo, hi), p| (lo.inf(p), hi.sup(p)),
            )
        })
        .collect();
    let least = (ovals.iter()).map(|(lo, hi)| hi.y - lo.y).fold(r, f64::min) * scale;
    if !crank_detail::too_short(least) {
        return Ok(Vec::new());
    }
    // The subjects: the crank circle about C, then each oval; the length
    // that is to be drawn ENLARGED.
    let c = pose.c();
    let reach = Vector::new(1.15 * r, 1.15 * r);
    let mut subjects = vec![((c - reach, c + reach), r)];
    subjects.extend(ovals.iter().map(|&(lo, hi)| ((lo, hi), hi.y - lo.y)));
    // Those the main view draws too small alone (at an offset engine a
    // tilted oval just under SEEN brought in every detail, the others
    // drawn again ×1, copies that enlarge nothing).
    let needed = |length: f64| {
        length * scale < SEEN && round_above(ENLARGED / (length * scale)) >= LEAST_ENLARGED
    };
    // Left to right as the main view draws them (mirrored: A on the
    // left), each detail below its box.
    let mut order: Vec<usize> = (0..subjects.len())
        .filter(|&k| subjects.get(k).is_some_and(|&(_, length)| needed(length)))
        .collect();
    if order.is_empty() {
        return Ok(Vec::new());
    }
    order.sort_by(|&i, &j| {
        let x = |k: usize| {
            (subjects.get(k)).map_or(0.0, |((lo, hi), _)| t.apply(nalgebra::center(lo, hi)).x)
        };
        x(i).total_cmp(&x(j))
    });
    let subjects: Vec<(usize, Subject)> = (order.into_iter())
        .filter_map(|k| Some((k, *subjects.get(k)?)))
        .collect();
    let magnifications: Vec<f64> = (subjects.iter())
        .map(|&(_, (_, length))| round_above(ENLARGED / (length * scale)))
        .collect();
    let sizes: Vec<Vector> = (subjects.iter().zip(&magnifications))
        .map(|(&(_, ((lo, hi), _)), &k)| {
            (hi - lo) * (k * scale) + Vector::new(2.0, 2.0) * WINDOW_PAD
        })
        .collect();
    let room = width - 2.0 * super::MARGIN;
    // Rows as wide as the page holds, left to right; a detail wider than
    // the page alone drawn smaller.
    let mut rows: Vec<Vec<usize>> = Vec::new();
    let mut used = f64::INFINITY;
    for (i, size) in sizes.iter().enumerate() {
        match rows.last_mut() {
            Some(row) if used + WINDOW_GAP + size.x <= room => {
                row.push(i);
                used += WINDOW_GAP + size.x;
            }
            _ => {
                rows.push(vec![i]);
                used = size.x;
            }
        }
    }
    let mut windows = Vec::new();
    let mut y = top + WINDOW_GAP;
    for row in rows {
        let total: f64 = (row.iter())
            .filter_map(|&i| sizes.get(i).map(|s| s.x + WINDOW_GAP))
            .sum::<f64>()
            - WINDOW_GAP;
        let shrink = (room / total).min(1.0);
        let mut x = super::MARGIN + 0.5 * (room - total * shrink);
        let mut bottom = y;
        for i in row {
            let (Some(&(k, ((lo, hi), _))), Some(&magnification), Some(size)) =
                (subjects.get(i), magnifications.get(i), sizes.get(i))
            else {
                continue;
            };
            let magnification = match shrink < 1.0 {
                true => super::coriolis::round_below(magnification * shrink, &STEPS).max(1.0),
                false => magnification,
            };
            let w = size.x * shrink;
            let s = magnification * scale;
            let pad = WINDOW_PAD / s;
            let centre = nalgebra::center(&lo, &hi);
            let half = Vector::new(0.5 * w / s, 0.5 * (hi.y - lo.y) + pad);
            let region = Frame::new(centre - half, centre + half);
            let h = (region.max().y - region.min().y) * s;
            let rect = Frame::from_origin_size(x, y, w, h.max(40.0) + crate::diagram::CAPTION);
            x += w + WINDOW_GAP;
            bottom = bottom.max(rect.max().y);
            let name = format!("detail-{k}");
            let what = match k {
                0 => "crank".to_string(),
                _ => format!("*P*_{k}"),
            };
            let mut plot = Plot::world(
                &name,
                rect,
                &region,
                t.is_mirrored(),
                ctx.tolerance,
                ctx.font,
            )?
            .with_caption(&format!("{what} ×{}", short(magnification)));
            let map = *plot.map();
            let seen = map.world_frame(&plot.area());
            plot.push(Item::new(
                format!("{name}-border"),
                Role::Frame,
                Shape::Polyline {
                    points: vec![
                        seen.min(),
                        Point::new(seen.max().x, seen.min().y),
                        seen.max(),
                        Point::new(seen.min().x, seen.max().y),
                    ],
                    closed: true,
                },
            ));
            draw_window(&mut plot, ctx, k, (&map, seen))?;
            windows.push((seen, plot));
        }
        y = bottom + WINDOW_GAP;
    }
    Ok(windows)
}

/// Detail `k` (0: the crank; else the oval of point `k`) drawn on its
/// plot, whose map and seen region are given.
fn draw_window(
    plot: &mut Plot,
    ctx: &Ctx,
    k: usize,
    (map, seen): (&crate::figure::PageFromWorld, Frame),
) -> Result<()> {
    use crate::figure::{Foot, TextSize};
    use crate::scene::Canvas;
    let m = ctx.mechanism;
    let pose = ctx.pose();
    let (a, b, c) = (pose.a(), pose.b(), pose.c());
    let mut s = Canvas::new(*map, seen).detail("detail-").suffixed(match k {
        0 => "-0",
        1 => "-1",
        2 => "-2",
        _ => "-3",
    });
    match k.checked_sub(1).and_then(|j| POINTS.get(j)) {
        None => {
            crank_detail::crank_circle(&mut s, c, m.crank());
            s.link("crank", vec![c, b]);
            s.link("rod", vec![b, a]);
            // Below the shaft unless the crank points down the page.
            let down = map.apply(b).y - map.apply(c).y > 0.5 * map.scale() * m.crank();
            s.bearing_on("C", c, if down { Foot::Above } else { Foot::Below });
            s.pin("C", c);
            s.pin("B", b);
            s.letter("C", c, "*C*", TextSize::Letter);
            s.letter("B", b, "*B*", TextSize::Letter);
        }
        Some(&(t, id, _, dash)) => {
            // cannot fail: the fractions of POINTS are constants in [0, 1].
            #[allow(clippy::expect_used)]
            let q = CouplerPoint::new(t).expect("fractions in [0, 1]");
            let curve = move |deg: f64| -> Option<(Point, Vector)> {
                let pose = m.pose(Angle::from_degrees(deg).ok()?);
                Some((q.point(&pose), q.derivative(&pose) * PER_DEGREE))
            };
            let pieces: [(&dyn crate::diagram::Curve, _); 1] = [(&curve, 0.0..=360.0)];
            plot.curve(&format!("detail-curve-coupler-{id}"), &pieces, dash, None)?;
            s.link("rod", vec![b, a]);
            let p = q.point(&pose);
            s.push(
                format!("point-P{k}"),
                Role::Construction,
                Shape::Dot { centre: p },
            );
            s.letter(&format!("P{k}"), p, &format!("*P*_{k}"), TextSize::Letter);
        }
    }
    for item in s.finish().0 {
        plot.push(item);
    }
    Ok(())
}
