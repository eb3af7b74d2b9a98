//! Every link drawn straight: a link lying over another along its line
//! is not jogged out beside it (read as a cranked bar), the one under it
//! drawn as an outlined arm about its line instead.

use super::polygon_figures::{path, svg};
use crate::common::{attr, segment_distance};
use slider_crank::FigureName;

/// How far (page units) a point of a straight link's path may stand off
/// the line between its ends: rounding in the written numbers.
const STRAIGHT: f64 = 0.5;
/// The crank lies under the rod where C stands nearer the rod's line
/// than this (page units: a link's width and a little paper).
const UNDER: f64 = 5.0;
/// An arm is seen about the line of the link under it where its outline
/// stands this far (page units) off that line each side: clear of the
/// heavy line over it (its half width 1.3) and a pin (4.2).
const SEEN: f64 = 5.0;

/// The ids of the links drawn in `svg`, with the panel's prefix and
/// suffix (`detail-link-rod`, `link-frame-a`).
fn link_ids(svg: &str) -> Vec<String> {
    svg.split("id=\"")
        .skip(1)
        .filter_map(|s| s.split('"').next())
        .filter(|id| {
            let bare = id.strip_prefix("detail-").unwrap_or(id);
            ["crank", "rod", "frame", "lever"].iter().any(|l| {
                let rest = bare.strip_prefix(&format!("link-{l}")[..]);
                matches!(rest, Some("" | "-a" | "-b" | "-c"))
            })
        })
        .map(str::to_string)
        .collect()
}

/// Whether the outline `arm` stands at least [`SEEN`] off the line
/// through `p` and `q` on each side of it.
pub(super) fn arm_seen(arm: &[(f64, f64)], p: (f64, f64), q: (f64, f64)) -> bool {
    let (dx, dy) = (q.0 - p.0, q.1 - p.1);
    let n = dx.hypot(dy);
    if n == 0.0 {
        return false;
    }
    let side = |x: &(f64, f64)| ((x.0 - p.0) * dy - (x.1 - p.1) * dx) / n;
    let most = arm.iter().map(side).fold(f64::MIN, f64::max);
    let least = arm.iter().map(side).fold(f64::MAX, f64::min);
    most >= SEEN && least <= -SEEN
}

/// The engines the reviews found links drawn bent in (figure, l, e, θ
/// at r = 1), with their neighbours and the figures' defaults.
const ENGINES: [(FigureName, f64, f64, f64); 22] = [
    (FigureName::Fig66Kisch, 39.3, 0.0, 180.0),
    (FigureName::Fig66Kisch, 39.35, 0.0, 180.0),
    (FigureName::Fig66Kisch, 39.3, 0.0, 179.0),
    (FigureName::Fig66Kisch, 55.4, 0.0, 180.0),
    (FigureName::Fig66Kisch, 4.0, 0.0, 180.0),
    (FigureName::BennettConstruction, 42.7, 0.0, 180.0),
    (FigureName::NgFig1Torque, 45.0, 0.0, 180.0),
    (FigureName::NgFig1Torque, 45.05, 0.0, 181.0),
    (FigureName::InertiaForce, 52.6, 0.0, 180.0),
    (FigureName::VelocityAccelerationPolygons, 4.0, 0.0, 180.0),
    (FigureName::VelocityAccelerationPolygons, 58.2, 0.0, 180.0),
    (FigureName::VelocityAccelerationPolygons, 37.7, 0.0, 179.2),
    (FigureName::Fig60Chains, 1.06, 0.0, 180.0),
    (FigureName::Fig60Chains, 1.01, 0.0, 180.0),
    (FigureName::Fig60Chains, 1.06, 0.0, 181.0),
    (FigureName::Fig60Chains, 1.1, 0.0, 180.0),
    (FigureName::Fig60Chains, 1.1, 0.0, 89.66),
    (FigureName::Fig60Chains, 1.1, 0.0, 90.66),
    (FigureName::Fig60Chains, 1.08, 0.0, 269.31),
    (FigureName::Fig60Chains, 1.06, 0.0, 269.09),
    (FigureName::Fig60Chains, 29.5, 0.0, 180.0),
    (FigureName::Fig60Chains, 3.0, 0.0, 30.0),
];

#[test]
fn every_link_is_drawn_straight_and_a_crank_under_the_rod_as_an_arm() {
    // Review 2026-12a: at an in-line engine's inner dead centre the rod
    // lying over the crank was drawn jogged out beside it (Kisch's detail
    // at l = 39.3 r, 180°; Ng's at l = 45 r; Fig. 60's three panels at
    // l = 1.06 r, 180°), and Fig. 60's frame d beside a link lying along
    // it (twice kinked at l = 1.1 r, 89.66°): every reviewer read a
    // cranked, bent bar. Every link's path runs straight between its
    // ends; where the crank lies under the rod, an arm outlines it,
    // standing clear of the rod's line each side.
    let mut arms = 0;
    for (name, rod, offset, deg) in ENGINES {
        let svg = svg(name, rod, offset, deg);
        let what = format!("{name:?} l = {rod}, e = {offset}, {deg}°");
        let ids = link_ids(&svg);
        assert!(!ids.is_empty(), "{what}: no link");
        for id in &ids {
            let p = path(&svg, id);
            let (s, t) = (p[0], p[p.len() - 1]);
            for &x in &p {
                let off = segment_distance(x, s, t);
                assert!(off < STRAIGHT, "{what}: {id} bent, {off:.1} off its line");
            }
        }
        for crank in ids.iter().filter(|id| id.contains("link-crank")) {
            let rod_id = crank.replace("link-crank", "link-rod");
            if attr(&svg, &rod_id, "d").is_none() {
                continue;
            }
            let (cb, ba) = (path(&svg, crank), path(&svg, &rod_id));
            let (c, b) = (cb[0], cb[cb.len() - 1]);
            if segment_distance(c, ba[0], ba[ba.len() - 1]) >= UNDER
                || (b.0 - c.0).hypot(b.1 - c.1) < 2.0 * SEEN
            {
                continue;
            }
            let arm_id = crank.replace("link-crank", "arm-crank");
            assert!(
                attr(&svg, &arm_id, "d").is_some(),
                "{what}: the crank {crank} under the rod not drawn as an arm"
            );
            arms += 1;
            assert!(
                arm_seen(&path(&svg, &arm_id), c, b),
                "{what}: {arm_id} not seen clear of the rod"
            );
        }
    }
    assert!(arms > 0, "no crank under the rod checked");
}
