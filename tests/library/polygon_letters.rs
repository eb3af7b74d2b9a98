//! The letters of the polygon figures read back from their SVG at the
//! engines the fourth review drew (docs/figures/review-2026-11d.md): a
//! letter naming several images ("*b*′, *x*") names only images that
//! coincide on the page, and the links of the Coriolis figures' mechanism
//! are lettered by their own link.

use crate::common::{metadata, num, read_text};
use slider_crank::catalogue::FigureOptions;
use slider_crank::{Angle, FigureName, SliderCrank};

/// Two dots 2.1 px in radius whose centres stand more than this apart
/// leave a dot's width between them and read as two vertices: a letter
/// naming both names one it does not stand by.
const ONE_PLACE: f64 = 8.0;

/// The reviewed engines (r = 1): rod, offset, angle.
const ENGINES: [(FigureName, f64, f64, f64); 24] = [
    (FigureName::VelocityAccelerationPolygons, 38.2, 0.0, 0.0),
    (FigureName::VelocityAccelerationPolygons, 38.2, 0.0, 90.15),
    (FigureName::VelocityAccelerationPolygons, 38.2, 0.0, 269.09),
    (FigureName::VelocityAccelerationPolygons, 3.47, -1.25, 0.0),
    (FigureName::VelocityAccelerationPolygons, 3.47, -1.25, 180.0),
    (
        FigureName::VelocityAccelerationPolygons,
        3.47,
        -1.25,
        269.98,
    ),
    (FigureName::VelocityAccelerationPolygons, 1.51, 0.382, 0.0),
    (FigureName::VelocityAccelerationPolygons, 1.51, 0.382, 180.0),
    (FigureName::VelocityAccelerationPolygons, 1.06, 0.0, 180.0),
    (FigureName::VelocityAccelerationPolygons, 2.0, 0.0, 40.0),
    (FigureName::CoriolisInversion2, 1.02, 0.0, 89.51),
    (FigureName::CoriolisInversion2, 1.02, 0.0, 269.18),
    (FigureName::CoriolisInversion2, 2.65, 1.44, 0.0),
    (FigureName::CoriolisInversion2, 2.65, 1.44, 180.0),
    (FigureName::CoriolisInversion2, 1.1, 0.0, 180.0),
    (FigureName::CoriolisInversion2, 3.49, 1.54, 0.0),
    (FigureName::CoriolisInversion2, 3.49, 1.54, 180.0),
    (FigureName::CoriolisInversion2, 3.49, 1.54, 89.99),
    (FigureName::CoriolisInversion3, 4.0, 0.0, 30.0),
    (FigureName::CoriolisInversion3, 1.06, 0.0, 180.0),
    (FigureName::CoriolisInversion3, 1.06, 0.0, 269.89),
    (FigureName::CoriolisInversion3, 28.5, 0.0, 0.0),
    (FigureName::CoriolisInversion3, 28.5, 0.0, 180.0),
    (FigureName::CoriolisInversion3, 50.0, 0.0, 0.0),
];

/// The figure `name` of the engine r = 1, `rod`, `offset` at `deg`.
fn svg(name: FigureName, rod: f64, offset: f64, deg: f64) -> String {
    let mut options = FigureOptions::default();
    options.mechanism = Some(SliderCrank::new(1.0, rod, offset).unwrap());
    options.angle = Some(Angle::deg(deg));
    slider_crank::render::to_svg(&name.figure(&options).unwrap())
}

/// Every letter of the SVG: its id and the panel it is drawn in.
fn letters(svg: &str) -> Vec<(String, String)> {
    let mut out = Vec::new();
    for (at, _) in svg.match_indices("<text ") {
        let tag = &svg[at..at + svg[at..].find('>').unwrap()];
        let Some(v) = tag.find(" id=\"").map(|v| v + 5) else {
            continue;
        };
        let id = tag[v..v + tag[v..].find('"').unwrap()].to_string();
        if !id.contains("label-") {
            continue;
        }
        let before = &svg[..at];
        let panel = before.rfind("id=\"panel-").map(|p| {
            let rest = &before[p + 4..];
            rest[..rest.find('"').unwrap()].to_string()
        });
        out.push((id, panel.unwrap_or_default()));
    }
    out
}

/// The text of the element `id` as read.
fn text(svg: &str, id: &str) -> String {
    let at = svg.find(&format!("id=\"{id}\"")).unwrap();
    let body = &svg[at..];
    let body = &body[body.find('>').unwrap() + 1..body.find("</text>").unwrap()];
    read_text(body)
}

/// The id of an image read as a letter: a′ → a2, a′_d (read "a′d") → ad2.
fn image_id(letter: &str) -> String {
    let primed = letter.contains('\u{2b9}') || letter.contains('′');
    let base: String = letter
        .chars()
        .filter(|c| c.is_ascii_alphanumeric())
        .collect();
    if primed { format!("{base}2") } else { base }
}

/// The metadata's places of the images a panel draws.
fn images<'a>(meta: &'a serde_json::Value, panel: &str) -> &'a serde_json::Value {
    if panel.starts_with("panel-velocity-polygon") {
        &meta["velocity_polygon"]
    } else if panel.starts_with("panel-acceleration-polygon") {
        &meta["acceleration_polygon"]
    } else {
        &meta["points"]
    }
}

/// The page place of the world point `p` on the panel `panel`.
fn on_page(meta: &serde_json::Value, panel: &str, p: &serde_json::Value) -> (f64, f64) {
    let panels = meta["panels"].as_array().unwrap();
    let m = panels
        .iter()
        .find(|q| q["id"] == panel)
        .unwrap_or_else(|| panic!("no {panel}"))["page_from_world"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect::<Vec<_>>();
    let (x, y) = (p[0].as_f64().unwrap(), p[1].as_f64().unwrap());
    (m[0] * x + m[2] * y + m[4], m[1] * x + m[3] * y + m[5])
}

#[test]
fn a_joint_letter_names_only_images_that_coincide_on_the_page() {
    let mut joint = 0;
    for (name, rod, offset, deg) in ENGINES {
        let svg = svg(name, rod, offset, deg);
        let meta = metadata(&svg);
        for (id, panel) in letters(&svg) {
            let read = text(&svg, &id);
            if !read.contains(", ") {
                continue;
            }
            let members: Vec<String> = read.split(", ").map(image_id).collect();
            let Some(first) = images(&meta, &panel).get(&members[0]) else {
                continue;
            };
            joint += 1;
            let own = on_page(&meta, &panel, first);
            for m in &members[1..] {
                let p = on_page(&meta, &panel, &images(&meta, &panel)[m]);
                let d = (p.0 - own.0).hypot(p.1 - own.1);
                assert!(
                    d <= ONE_PLACE,
                    "{name:?} l = {rod}, e = {offset}, {deg}°: {id} \"{read}\" names {m} {d:.1} px from {}",
                    members[0]
                );
            }
        }
    }
    // Images that do coincide (the rod translating at 90°, the dead
    // centres' folded polygons) still share their letter.
    assert!(joint >= 10, "{joint} joint letters");
}

/// The centre of the letter `id` (its baseline's middle raised by a
/// third of its size).
fn letter_centre(svg: &str, id: &str) -> (f64, f64) {
    let size = num(svg, id, "font-size");
    (num(svg, id, "x"), num(svg, id, "y") - size / 3.0)
}

#[test]
fn the_block_and_the_turning_bar_of_inversion_2_each_have_their_letter() {
    // At the outer dead centre the block rides at the slotted bar's end:
    // "d" was set on the block and "c" beyond it on the bar's tail.
    for (rod, offset, deg) in [
        (2.65, 1.44, 0.0),
        (3.49, 1.54, 0.0),
        (1.1, 0.0, 0.0),
        (2.65, 1.44, 89.28),
        (2.65, 1.44, 180.0),
        (4.0, 0.0, 30.0),
    ] {
        let svg = svg(FigureName::CoriolisInversion2, rod, offset, deg);
        let pin = (num(&svg, "point-A", "cx"), num(&svg, "point-A", "cy"));
        let from_pin = |id: &str| {
            let c = letter_centre(&svg, id);
            (c.0 - pin.0).hypot(c.1 - pin.1)
        };
        let (c, d) = (from_pin("label-link-c"), from_pin("label-link-d"));
        assert!(
            c < d && d >= 30.0,
            "l = {rod}, e = {offset}, {deg}°: c {c:.1} px from the block's pin, d {d:.1}"
        );
    }
}
