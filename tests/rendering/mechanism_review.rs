//! The mechanism figures at the engines where a review found them
//! faulty (issue 38), each read back from its SVG: one letter for the
//! points that coincide in a detail, the crank's bearing clear of the
//! lines drawn from its centre, the stroke's dimensions clear of the
//! links.

use crate::common;

use common::{attr, group_strokes, metadata, segment_distance};
use slider_crank::catalogue::FigureOptions;
use slider_crank::render::to_svg;
use slider_crank::{Angle, FigureName, SliderCrank};

/// `name`'s SVG for the engine r, l, e at `deg`.
fn svg(name: FigureName, (r, l, e, deg): (f64, f64, f64, f64)) -> String {
    let mut options = FigureOptions::default();
    options.mechanism = Some(SliderCrank::new(r, l, e).unwrap());
    options.angle = Some(Angle::deg(deg));
    to_svg(&name.figure(&options).unwrap())
}

/// The two ends of the single-segment path `id`.
fn segment(svg: &str, id: &str) -> ((f64, f64), (f64, f64)) {
    let d = attr(svg, id, "d").unwrap_or_else(|| panic!("no {id}"));
    let n: Vec<f64> = (d.split(|c: char| c.is_ascii_alphabetic() || c.is_whitespace()))
        .filter_map(|w| w.parse().ok())
        .collect();
    ((n[0], n[1]), (n[n.len() - 2], n[n.len() - 1]))
}

/// Bennett's construction at a long rod's dead centres: F, G, K and L
/// are one point, by B, in the ×20 detail. At 180° they took one joint
/// letter; at 0°, where they stand by the detail's frame, the joint
/// letter found no room and was scattered: F above the dot and G below
/// it, K and L on the frame's edge where no dot is. One dot and one
/// letter at both, the letter beside its dot.
#[test]
fn bennetts_coinciding_points_take_one_letter_at_both_dead_centres() {
    for deg in [0.0, 180.0] {
        let text = svg(FigureName::BennettConstruction, (1.0, 31.6, 0.0, deg));
        let dot = (
            attr(&text, "detail-point-F", "cx").map(|v| v.parse::<f64>().unwrap()),
            attr(&text, "detail-point-F", "cy").map(|v| v.parse::<f64>().unwrap()),
        );
        let (Some(x), Some(y)) = dot else {
            panic!("{deg}°: no dot at F in the detail");
        };
        for name in ["G", "K", "L"] {
            assert!(
                attr(&text, &format!("detail-point-{name}"), "cx").is_none(),
                "{deg}°: a dot of its own at {name}"
            );
            assert!(
                attr(&text, &format!("detail-label-{name}"), "x").is_none(),
                "{deg}°: a letter of its own at {name}"
            );
        }
        let at = text.find("id=\"detail-label-F\"").expect("F's letter");
        let body = &text[at..at + text[at..].find("</text>").unwrap()];
        let read = common::read_text(body);
        assert!(
            ["F", "G", "K", "L"].iter().all(|n| read.contains(n)),
            "{deg}°: F's letter reads {read:?}"
        );
        let (lx, ly) = (
            common::num(&text, "detail-label-F", "x"),
            common::num(&text, "detail-label-F", "y"),
        );
        // The joint letter, some 70 units wide, centred within its width
        // of its dot.
        assert!(
            (lx - x).abs() < 60.0 && (ly - y).abs() < 30.0,
            "{deg}°: the letter at ({lx}, {ly}) stands away from its dot at ({x}, {y})"
        );
        let meta = metadata(&text);
        assert_eq!(meta["points"]["K"], meta["points"]["F"], "{deg}°");
    }
}

/// The crank centre's bearing stands clear of every line drawn from the
/// centre: at l = 3.23 r, e = −1.14 r, 180° the result CE runs down from
/// C to the rod, and the pedestal standing below had it drawn through its
/// triangle and hatched base, in the main view and in the detail.
#[test]
fn the_bearing_stands_clear_of_ce() {
    for (l, e, deg) in [
        (3.23, -1.14, 180.0),
        (3.18, -1.14, 180.0),
        (3.23, -1.14, 181.0),
    ] {
        let text = svg(FigureName::BennettConstruction, (1.0, l, e, deg));
        for prefix in ["", "detail-"] {
            let ce = format!("{prefix}line-CE");
            if attr(&text, &ce, "d").is_none() {
                continue;
            }
            let line = segment(&text, &ce);
            let c = (
                common::num(&text, &format!("{prefix}point-C"), "cx"),
                common::num(&text, &format!("{prefix}point-C"), "cy"),
            );
            let bearing = group_strokes(&text, &format!("{prefix}bearing-C"));
            assert!(!bearing.is_empty(), "no {prefix}bearing-C");
            // Every point of the bearing's strokes off the shaft's pin
            // (4.2 in radius) stands off the line.
            for s in bearing {
                for k in 0..=20 {
                    let t = f64::from(k) / 20.0;
                    let p = (s.0.0 + t * (s.1.0 - s.0.0), s.0.1 + t * (s.1.1 - s.0.1));
                    if (p.0 - c.0).hypot(p.1 - c.1) < 6.0 {
                        continue;
                    }
                    let d = segment_distance(p, line.0, line.1);
                    assert!(
                        d > 1.0,
                        "l = {l}, e = {e}, {deg}°: {ce} runs through {prefix}bearing-C at {p:?}"
                    );
                }
            }
        }
    }
}

/// Fig. 62 at a rod of 1.07 cranks by 271°: the crank points down from C
/// beside the stroke's inner end and the rod runs up from B to A across
/// the stroke's span; dimensioned below the guides, the stroke's
/// extension line ran beside the crank, doubling it, and its arrowhead
/// landed on the rod. The dimensions keep clear of the links.
#[test]
fn fig_62s_dimensions_keep_off_the_links() {
    for (l, deg) in [
        (1.07, 270.97),
        (1.02, 270.97),
        (1.12, 270.97),
        (1.07, 269.97),
    ] {
        let text = svg(FigureName::Fig62Displacement, (1.0, l, 0.0, deg));
        let links = [segment(&text, "link-crank"), segment(&text, "link-rod")];
        let pins: Vec<(f64, f64)> = links.iter().flat_map(|s| [s.0, s.1]).collect();
        for dim in ["dimension-stroke", "dimension-x"] {
            let strokes = group_strokes(&text, dim);
            assert!(!strokes.is_empty(), "l = {l}, {deg}°: no {dim}");
            // Every point of the dimension's lines and heads stands more
            // than 6 units off the links (a link's half-width and a clear
            // gap), save by the pins, where an extension line begins.
            for s in strokes {
                for k in 0..=20 {
                    let t = f64::from(k) / 20.0;
                    let p = (s.0.0 + t * (s.1.0 - s.0.0), s.0.1 + t * (s.1.1 - s.0.1));
                    if pins.iter().any(|q| (p.0 - q.0).hypot(p.1 - q.1) < 8.0) {
                        continue;
                    }
                    for link in links {
                        let d = segment_distance(p, link.0, link.1);
                        assert!(
                            d > 6.0,
                            "l = {l}, {deg}°: {dim} at {p:?} {d:.2} from a link {link:?}"
                        );
                    }
                }
            }
        }
    }
}

/// Bennett's construction at l = 1.03 r by the inner dead centre: the
/// detail about A, C and the points by them stood within the guides'
/// channel, and of the block it showed one face, a lone line across the
/// panel. It takes in the guides and the block whole.
#[test]
fn a_detail_crossing_the_block_shows_it_between_its_guides() {
    for (l, deg) in [(1.03, 180.0), (1.03, 179.0), (1.03, 181.0)] {
        let text = svg(FigureName::BennettConstruction, (1.0, l, 0.0, deg));
        let meta = metadata(&text);
        let panel = (meta["panels"].as_array().unwrap().iter())
            .find(|p| p["id"] == "panel-detail")
            .unwrap_or_else(|| panic!("l = {l}, {deg}°: no detail"));
        let rect: Vec<f64> = (panel["rect"].as_array().unwrap().iter())
            .map(|v| v.as_f64().unwrap())
            .collect();
        let inside = |p: (f64, f64)| {
            p.0 >= rect[0] - 1.0
                && p.0 <= rect[0] + rect[2] + 1.0
                && p.1 >= rect[1] - 1.0
                && p.1 <= rect[1] + rect[3] + 1.0
        };
        let d = attr(&text, "detail-block-slider", "d")
            .unwrap_or_else(|| panic!("l = {l}, {deg}°: no block in the detail"));
        let n: Vec<f64> = (d.split(|c: char| c.is_ascii_alphabetic() || c.is_whitespace()))
            .filter_map(|w| w.parse().ok())
            .collect();
        for p in n.chunks(2) {
            assert!(
                inside((p[0], p[1])),
                "l = {l}, {deg}°: the block's corner {p:?} outside the detail {rect:?}"
            );
        }
        for guide in ["detail-guide-upper", "detail-guide-lower"] {
            let g =
                attr(&text, guide, "d").unwrap_or_else(|| panic!("l = {l}, {deg}°: no {guide}"));
            let y: f64 = g.split_whitespace().nth(1).unwrap().parse().unwrap();
            assert!(
                y > rect[1] && y < rect[1] + rect[3],
                "l = {l}, {deg}°: {guide} at {y} outside the detail {rect:?}"
            );
        }
    }
}
