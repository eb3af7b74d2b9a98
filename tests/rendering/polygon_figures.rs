//! The polygon figures (velocity-acceleration-polygons, the Coriolis
//! figures of inversions 2 and 3 and the inversion figures they draw
//! their mechanism with) read back from their SVG at the engines of the
//! fifth review (docs/figures/review-2026-11e.md) where a reader misread
//! them.

use crate::common::attr;
use crate::plate::{Label, Plate};
use slider_crank::catalogue::FigureOptions;
use slider_crank::{Angle, FigureName, SliderCrank};

/// The figure `name` of the engine r = 1, `rod`, `offset` at `deg`, as
/// written.
fn svg(name: FigureName, rod: f64, offset: f64, deg: f64) -> String {
    let mut options = FigureOptions::default();
    options.mechanism = Some(SliderCrank::new(1.0, rod, offset).unwrap());
    options.angle = Some(Angle::deg(deg));
    slider_crank::render::to_svg(&name.figure(&options).unwrap())
}

/// The letters of the images of one polygon: `label-` and a lower-case
/// image id, primed (`c2`) in the acceleration polygon, not in the
/// velocity polygon.
fn images(plate: &Plate, primed: bool) -> Vec<&Label> {
    (plate.texts.iter())
        .filter(|t| {
            t.id.strip_prefix("label-").is_some_and(|rest| {
                rest.chars().all(|c| c.is_ascii_lowercase() || c == '2')
                    && rest.starts_with(|c: char| c.is_ascii_lowercase())
                    && rest.ends_with('2') == primed
            })
        })
        .collect()
}

#[test]
fn the_two_polygons_letter_groups_stand_apart() {
    // At l = 2.46 r, e = 1.05 r, 90.7° both polygons are needles whose
    // letters stand on one line: "b, a, q" and "c′, a′" 11 units apart
    // read as one string. Letters of the two polygons at one height keep
    // two ems (34 units at 17) between them.
    const APART: f64 = 34.0;
    for (rod, offset, deg) in [
        (2.46, 1.05, 90.7),
        (28.8, 0.0, 90.35),
        (1.1, 0.0, 90.15),
        (1.04, 0.0, 90.95),
        (2.46, 1.05, 270.41),
        (4.0, 0.0, 45.0),
    ] {
        let svg = svg(FigureName::VelocityAccelerationPolygons, rod, offset, deg);
        let plate = Plate::read(&svg);
        let (velocity, acceleration) = (images(&plate, false), images(&plate, true));
        assert!(!velocity.is_empty() && !acceleration.is_empty());
        for v in &velocity {
            for a in &acceleration {
                let level = v.rect.y0.max(a.rect.y0) < v.rect.y1.min(a.rect.y1);
                let gap = (a.rect.x0 - v.rect.x1).max(v.rect.x0 - a.rect.x1);
                assert!(
                    !level || gap >= APART,
                    "l = {rod}, e = {offset}, {deg}°: {} and {} {gap:.1} apart",
                    v.id,
                    a.id
                );
            }
        }
    }
}

/// The points of the path `id`, in page units.
fn path(svg: &str, id: &str) -> Vec<(f64, f64)> {
    let d = attr(svg, id, "d").unwrap_or_else(|| panic!("no {id}"));
    let numbers: Vec<f64> = d
        .split(|c: char| c == 'M' || c == 'L' || c.is_whitespace())
        .filter_map(|w| w.parse().ok())
        .collect();
    numbers.chunks(2).map(|p| (p[0], p[1])).collect()
}

/// The angle in degrees between the directions `p` → `q` and `p` → `s`.
fn angle_at(p: (f64, f64), q: (f64, f64), s: (f64, f64)) -> f64 {
    let (u, v) = ((q.0 - p.0, q.1 - p.1), (s.0 - p.0, s.1 - p.1));
    let cross = u.0 * v.1 - u.1 * v.0;
    let dot = u.0 * v.0 + u.1 * v.1;
    cross.abs().atan2(dot).to_degrees()
}

#[test]
fn the_frame_d_keeps_its_shape_at_every_pose() {
    // d is rigid: its leg from C meets its slot square at every pose. A
    // leg bent 20° off the crank where the square leg would lie on it
    // (near 90° with an offset near r) was read as d changing its shape,
    // with O_ab's letter set at the bend (inversion 2 at l = 2.61 r, e =
    // 1.42 r, 90.37°, scored 1.5).
    for (name, rod, offset, deg) in [
        (FigureName::CoriolisInversion2, 2.5, -0.866, 270.44),
        (FigureName::CoriolisInversion3, 2.94, 1.07, 89.2),
        (FigureName::CoriolisInversion3, 1.95, 0.9, 95.0),
        (FigureName::Inversion2RotatingBlock, 2.61, 1.42, 90.37),
        (FigureName::Inversion2RotatingBlock, 2.61, 1.42, 0.0),
        (FigureName::Inversion3OscillatingCylinder, 1.45, 0.36, 89.05),
        (
            FigureName::Inversion3OscillatingCylinder,
            2.46,
            0.901,
            269.12,
        ),
    ] {
        let svg = svg(name, rod, offset, deg);
        let frame = path(&svg, "link-frame");
        // d's bar C, T, its far end, and 13 points of each hop over a pin
        // or a crossing on its leg.
        let n = frame.len();
        assert!(n >= 3 && (n - 3) % 13 == 0, "{name:?}: d's bar of {n} points");
        // The angle at T between the leg back to C and the slot on.
        let square = angle_at(frame[n - 2], frame[0], frame[n - 1]);
        assert!(
            (square - 90.0).abs() < 0.1,
            "{name:?} l = {rod}, e = {offset}, {deg}°: d's leg at {square:.2}° to its slot"
        );
    }
}

/// The centre of the box of the text `id` as drawn, if drawn.
fn text_centre(plate: &Plate, id: &str) -> Option<(f64, f64)> {
    (plate.texts.iter())
        .find(|t| t.id == id)
        .map(|t| (0.5 * (t.rect.x0 + t.rect.x1), 0.5 * (t.rect.y0 + t.rect.y1)))
}

#[test]
fn each_pin_letter_stands_by_its_own_pin_and_link_a_is_seen() {
    // The sixth review: inversion 2 at l = 35 r, 180° set B's letter left
    // of the hub, by C's pin (2.5); at l = 35 to 52 r link a (CB) was four
    // units long, C and B one knot. Every pin letter, in the mechanism
    // and in any detail, is nearer its own pin than any other pin, and a
    // detail draws CB at least 40 units long where the mechanism does not.
    const SEEN: f64 = 40.0;
    for (name, rod, offset, deg) in [
        (FigureName::CoriolisInversion2, 35.0, 0.0, 180.0),
        (FigureName::CoriolisInversion2, 35.0, 0.0, 0.0),
        (FigureName::CoriolisInversion2, 38.5, 0.0, 180.0),
        (FigureName::CoriolisInversion2, 52.2, 0.0, 89.02),
        (FigureName::CoriolisInversion2, 1.76, 0.423, 180.0),
        (FigureName::CoriolisInversion3, 51.3, 0.0, 180.0),
        (FigureName::CoriolisInversion3, 1.05, 0.0, 0.0),
    ] {
        let svg = svg(name, rod, offset, deg);
        let plate = Plate::read(&svg);
        let mut crank_seen = false;
        for prefix in ["", "detail-"] {
            let pins: Vec<(&str, (f64, f64))> = ["C", "B", "A"]
                .into_iter()
                .filter_map(|k| {
                    let id = format!("{prefix}point-{k}");
                    let cx = attr(&svg, &id, "cx")?.parse().ok()?;
                    let cy = attr(&svg, &id, "cy")?.parse().ok()?;
                    Some((k, (cx, cy)))
                })
                .collect();
            let at = |k: &str| pins.iter().find(|p| p.0 == k).map(|p| p.1);
            if let (Some(c), Some(b)) = (at("C"), at("B")) {
                crank_seen |= (c.0 - b.0).hypot(c.1 - b.1) >= SEEN;
            }
            for (key, _) in &pins {
                let Some(letter) = text_centre(&plate, &format!("{prefix}label-{key}")) else {
                    continue;
                };
                let nearest = (pins.iter())
                    .min_by(|p, q| {
                        let d = |x: (f64, f64)| (x.0 - letter.0).hypot(x.1 - letter.1);
                        d(p.1).total_cmp(&d(q.1))
                    })
                    .unwrap();
                assert_eq!(
                    nearest.0, *key,
                    "{name:?} l = {rod}, e = {offset}, {deg}°: {prefix}{key}'s letter by {}'s pin",
                    nearest.0
                );
            }
        }
        assert!(
            crank_seen,
            "{name:?} l = {rod}, e = {offset}, {deg}°: CB nowhere {SEEN} units long"
        );
    }
}

#[test]
fn the_acceleration_polygon_letters_its_pole() {
    // The sixth review: inversion 3 near 90° at a long rod left o′ to the
    // detail of the Coriolis component, so the main polygon began at an
    // unlettered box (3.5). The polygon is read from its pole: each
    // polygon panel letters it.
    for (name, rod, offset, deg) in [
        (FigureName::CoriolisInversion3, 51.3, 0.0, 90.83),
        (FigureName::CoriolisInversion3, 51.3, 0.0, 269.76),
        (FigureName::CoriolisInversion3, 3.96, -2.39, 90.75),
        (FigureName::CoriolisInversion3, 1.05, 0.0, 269.2),
        (FigureName::CoriolisInversion3, 3.36, 1.78, 90.06),
        (FigureName::CoriolisInversion2, 38.5, 0.0, 90.6),
        (FigureName::CoriolisInversion2, 1.5, 0.0, 60.0),
    ] {
        let svg = svg(name, rod, offset, deg);
        // The acceleration polygon's panel, up to the next panel: its
        // letters, o′ written "oʹ" alone or with a point it coincides with.
        let start = svg
            .find("id=\"panel-acceleration-polygon\"")
            .unwrap_or_else(|| panic!("no acceleration polygon"));
        let rest = &svg[start + 10..];
        let end = rest.find("id=\"panel-").unwrap_or(rest.len());
        let panel = &rest[..end];
        assert!(
            panel.contains(">oʹ<") || panel.contains(">oʹ,") || panel.contains(", oʹ<"),
            "{name:?} l = {rod}, e = {offset}, {deg}°: the acceleration polygon without o′"
        );
    }
}
