//! The construction details at the engines where a review found them
//! faulty (issue 38, its second round), each read back from its SVG: the
//! points a detail's enlargement does not set apart take one marker and
//! one joint letter there.

use crate::common;

use common::{attr, metadata};
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

/// The detail's markers: (name, centre, radius) of each `detail-point-…`.
fn markers(svg: &str) -> Vec<(String, (f64, f64), f64)> {
    let key = "id=\"detail-point-";
    let mut out = Vec::new();
    let mut from = 0;
    while let Some(at) = svg[from..].find(key) {
        let start = from + at + key.len();
        let name = &svg[start..start + svg[start..].find('"').unwrap()];
        let id = format!("detail-point-{name}");
        if let (Some(x), Some(y), Some(r)) = (
            attr(svg, &id, "cx"),
            attr(svg, &id, "cy"),
            attr(svg, &id, "r"),
        ) {
            out.push((
                name.to_string(),
                (x.parse().unwrap(), y.parse().unwrap()),
                r.parse().unwrap(),
            ));
        }
        from = start;
    }
    out
}

/// Every letter of the detail as a reader sees it, joined.
fn detail_letters(svg: &str) -> String {
    let key = "id=\"detail-label-";
    let mut out = String::new();
    let mut from = 0;
    while let Some(at) = svg[from..].find(key) {
        let start = from + at;
        let body = &svg[start..start + svg[start..].find("</text>").unwrap()];
        out.push_str(&common::read_text(body));
        out.push(' ');
        from = start + key.len();
    }
    out
}

/// Page units under which two markers run into one: a dot's radius is
/// 2.1, a pin's 4.2; closer than 6 a dot is under a pin or touches
/// another dot.
const RUN_INTO_ONE: f64 = 6.0;

/// Bennett's ×25 detail at a long rod near 90° and 270° (G at 0.02 and
/// 0.03 of the crank from C, K between them), Fig. 63's and Fig. 66's at
/// their long rods near 90° (E under B's pin): no dot stands within a
/// marker's reach of another marker, where it was drawn half hidden under
/// C's or B's pin with a letter naming no point the reader could find;
/// every point the construction finds is still named by a letter there.
#[test]
fn detail_points_not_set_apart_take_one_joint_letter() {
    type Case = (FigureName, (f64, f64, f64, f64), &'static [&'static str]);
    let cases: [Case; 5] = [
        (
            FigureName::BennettConstruction,
            (1.0, 56.2, 0.0, 90.03),
            &["C", "G", "K"],
        ),
        (
            FigureName::BennettConstruction,
            (1.0, 56.2, 0.0, 269.03),
            &["C", "G", "K"],
        ),
        (
            FigureName::Fig63Velocity,
            (1.0, 28.2, 0.0, 90.42),
            &["B", "E"],
        ),
        (
            FigureName::Fig66Kisch,
            (1.0, 58.6, 0.0, 89.04),
            &["B", "E", "H"],
        ),
        (
            FigureName::Fig66Kisch,
            (1.0, 58.6, 0.0, 270.15),
            &["B", "E", "H"],
        ),
    ];
    for (name, engine, named) in cases {
        let text = svg(name, engine);
        let marks = markers(&text);
        assert!(marks.len() >= 2, "{name:?} {engine:?}: no detail read");
        for (i, (p, a, ra)) in marks.iter().enumerate() {
            for (q, b, rb) in &marks[i + 1..] {
                let both_pins = *ra > 3.0 && *rb > 3.0;
                let d = (a.0 - b.0).hypot(a.1 - b.1);
                assert!(
                    both_pins || d >= RUN_INTO_ONE,
                    "{name:?} {engine:?}: {p} and {q} drawn {d:.2} apart in the detail"
                );
            }
        }
        let letters = detail_letters(&text);
        for n in named {
            assert!(
                letters.contains(n),
                "{name:?} {engine:?}: no letter names {n} in the detail: {letters:?}"
            );
        }
        let meta = metadata(&text);
        for n in named {
            assert!(
                meta["points"][*n].is_array(),
                "{name:?} {engine:?}: {n} not recorded"
            );
        }
    }
}

/// The single-segment paths of the detail drawn as constructions,
/// results or auxiliaries (not the line of stroke): id and ends.
type Segment = (String, (f64, f64), (f64, f64));

fn detail_lines(svg: &str) -> Vec<Segment> {
    let mut out = Vec::new();
    for tag in svg.split('<').filter(|t| t.starts_with("path ")) {
        let class = ["construction", "result", "auxiliary"]
            .iter()
            .any(|c| tag.contains(&format!("class=\"{c}\"")));
        let Some(at) = tag.find("id=\"detail-") else {
            continue;
        };
        let id = &tag[at + 4..];
        let id = &id[..id.find('"').unwrap()];
        if !class || id == "detail-line-stroke" {
            continue;
        }
        let Some(d) = common::attr(svg, id, "d") else {
            continue;
        };
        let n: Vec<f64> = (d.split(|c: char| c.is_ascii_alphabetic() || c.is_whitespace()))
            .filter_map(|w| w.parse().ok())
            .collect();
        if n.len() == 4 && d.starts_with('M') && d.matches('L').count() == 1 {
            out.push((id.to_string(), (n[0], n[1]), (n[2], n[3])));
        }
    }
    out
}

/// Kisch's and Bennett's ×25 details at a long rod near 90° and 270°,
/// Fig. 63's: no construction line, result or auxiliary runs beside the
/// crank for its whole length (both its ends within a marker's reach of
/// the crank), where CE, LK and FG read as one doubled crank.
#[test]
fn no_construction_line_doubles_the_crank_in_a_detail() {
    let cases = [
        (FigureName::BennettConstruction, (1.0, 56.2, 0.0, 90.03)),
        (FigureName::BennettConstruction, (1.0, 56.2, 0.0, 269.03)),
        (FigureName::Fig63Velocity, (1.0, 28.2, 0.0, 90.42)),
        (FigureName::Fig66Kisch, (1.0, 58.6, 0.0, 89.04)),
        (FigureName::Fig66Kisch, (1.0, 58.6, 0.0, 270.15)),
    ];
    for (name, engine) in cases {
        let text = svg(name, engine);
        let d = attr(&text, "detail-link-crank", "d").expect("the crank in the detail");
        let n: Vec<f64> = (d.split(|c: char| c.is_ascii_alphabetic() || c.is_whitespace()))
            .filter_map(|w| w.parse().ok())
            .collect();
        let (c, b) = ((n[0], n[1]), (n[2], n[3]));
        for (id, p, q) in detail_lines(&text) {
            let (dp, dq) = (
                common::segment_distance(p, c, b),
                common::segment_distance(q, c, b),
            );
            assert!(
                dp >= RUN_INTO_ONE || dq >= RUN_INTO_ONE,
                "{name:?} {engine:?}: {id} runs beside the crank ({dp:.2}, {dq:.2})"
            );
        }
    }
}

/// Kisch's construction on an offset engine at its outer dead centre
/// (l = 3.99, e = −1.6, 0°): the perpendicular from H meets the line
/// through C at G before AB at F, and stopped at G, so that F's right
/// angle stood off every line but the rod. A drawn line ends at F.
#[test]
fn kisch_perpendicular_reaches_f_beyond_g() {
    let text = svg(FigureName::Fig66Kisch, (1.0, 3.99, -1.6, 0.0));
    let f = (
        common::num(&text, "detail-point-F", "cx"),
        common::num(&text, "detail-point-F", "cy"),
    );
    let at_f = |p: (f64, f64)| (p.0 - f.0).hypot(p.1 - f.1) < 0.5;
    let lines = detail_lines(&text);
    assert!(
        lines.iter().any(|(_, p, q)| at_f(*p) || at_f(*q)),
        "no line ends at F {f:?}: {lines:?}"
    );
}
