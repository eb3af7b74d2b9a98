//! Single figures at the engines and pages where their layout once failed
//! (issue 20), each read back from its SVG alone: how much of the page the
//! drawing takes, which letter stands by which point, what crosses what.

use crate::common;
use crate::plate;

use plate::{Plate, Rect};
use slider_crank::catalogue::FigureOptions;
use slider_crank::render::to_svg;
use slider_crank::{Angle, FigureName, SliderCrank};

/// `name`'s SVG for the engine r, l, e at `deg`, on `width` if given.
fn svg(name: FigureName, engine: Option<(f64, f64, f64, f64)>, width: Option<&str>) -> String {
    let mut options = FigureOptions::default();
    if let Some((r, l, e, deg)) = engine {
        options.mechanism = Some(SliderCrank::new(r, l, e).unwrap());
        options.angle = Some(Angle::deg(deg));
    }
    options.width = width.map(|w| w.parse().unwrap());
    to_svg(&name.figure(&options).unwrap())
}

fn centre(r: &Rect) -> (f64, f64) {
    ((r.x0 + r.x1) / 2.0, (r.y0 + r.y1) / 2.0)
}

fn distance(a: (f64, f64), b: (f64, f64)) -> f64 {
    (a.0 - b.0).hypot(a.1 - b.1)
}

/// The box of every ink whose owner's id starts with one of `prefixes`.
fn ink_of(plate: &Plate, prefixes: &[&str]) -> Rect {
    Rect::around(
        plate
            .ink
            .iter()
            .filter(|(id, _)| prefixes.iter().any(|p| id.starts_with(p)))
            .flat_map(|(_, r)| [(r.x0, r.y0), (r.x1, r.y1)]),
    )
    .unwrap()
}

/// The coupler curves at a short offset rod (issue 20): the drawing took
/// a third of a 760-unit page, A's and C's letters overprinted, and P₁'s
/// letter stood nearer P₂'s and P₃'s dots than its own.
#[test]
fn coupler_curves_at_a_short_rod_fill_the_page_and_letter_their_own_points() {
    let engine = Some((1.0, 1.1, 0.08, 110.0));
    let text = svg(FigureName::CouplerCurves, engine, None);
    let plate = Plate::read(&text);
    let drawn = ink_of(
        &plate,
        &[
            "curve-", "link-", "point-", "guide", "hatch", "circle", "block",
        ],
    );
    let share = (drawn.x1 - drawn.x0) / plate.width;
    assert!(
        share >= 0.6,
        "the drawing spans {share:.2} of the page's width"
    );
    let panel = &plate.panels[0];
    let label = |id: &str| panel.labels.iter().find(|l| l.id == id).unwrap().rect;
    for k in 1..=3 {
        let own = format!("P{k}");
        let at = centre(&label(&format!("label-{own}")));
        let mine = distance(at, panel.markers[&own]);
        for (other, p) in &panel.markers {
            assert!(
                other == &own || distance(at, *p) > mine,
                "{own}'s letter is {mine:.1} from its dot, {:.1} from {other}'s",
                distance(at, *p)
            );
        }
    }
    let (a, c) = (label("label-A"), label("label-C"));
    assert!(!a.overlaps(&c), "A {a:?} and C {c:?} overprint");
}

/// Inversion 2 (issue 20): its panel was the world the frame sweeps over
/// a turn, a disc about C, and at one pose the drawing sat low on its
/// page, the top 200 and the left 450 units empty. At its default, on
/// 120 mm and at a short rod near the inner dead centre, the drawing now
/// starts within 60 units of the page's top and spans 60 % of its width.
#[test]
fn inversion_2_fits_its_page_to_the_drawing() {
    let cases = [
        (None, None),
        (None, Some("120mm")),
        (Some((1.0, 1.2, 0.0, 170.0)), None),
    ];
    for (engine, width) in cases {
        let text = svg(FigureName::Inversion2RotatingBlock, engine, width);
        let plate = Plate::read(&text);
        let drawn = ink_of(
            &plate,
            &[
                "link-",
                "point-",
                "circle-",
                "block",
                "line-",
                "offpage-",
                "infinity-",
            ],
        );
        let share = (drawn.x1 - drawn.x0) / plate.width;
        assert!(
            share >= 0.6,
            "{engine:?} {width:?}: the drawing spans {share:.2} of the width"
        );
        assert!(
            drawn.y0 <= 60.0,
            "{engine:?} {width:?}: the drawing starts {:.0} down",
            drawn.y0
        );
    }
}

/// Ng's Fig. 2 tilted to 80° (issue 20): the weight and its component
/// along the plane end close together, and their names stood side by
/// side on one line, reading as "mg sin φ mg". Each name now keeps its
/// own side: the two never share a line within an em of each other.
#[test]
fn the_inclines_weight_and_its_component_are_named_apart() {
    for deg in [45.0, 60.0, 70.0, 80.0, 85.0] {
        let mut options = FigureOptions::default();
        options.angle = Some(Angle::deg(deg));
        let text = to_svg(&FigureName::NgFig2Incline.figure(&options).unwrap());
        let plate = Plate::read(&text);
        let find = |id: &str| plate.texts.iter().find(|t| t.id == id).unwrap().clone();
        let (weight, along) = (find("label-force-weight"), find("label-force-along"));
        let (w, a) = (weight.rect, along.rect);
        let same_line = w.y0 < a.y1 && a.y0 < w.y1;
        let gap = (w.x0 - a.x1).max(a.x0 - w.x1);
        assert!(
            !same_line || gap > weight.font_size,
            "{deg}°: mg and mg sin φ side by side, {gap:.1} apart"
        );
    }
}

/// Fig. 64 at a short offset rod on a narrow page (issue 20): the view
/// was fitted to the mechanism alone, and the distance base, whose height
/// CE exceeds the crank there, ran off the top of the page and through
/// the detail's caption "Detail ×8". Both diagrams now lie on the page
/// and clear of the detail and its caption.
#[test]
fn fig_64s_diagrams_stay_on_the_page_and_off_the_detail() {
    let engine = Some((1.0, 1.1, 0.08, 178.0));
    let text = svg(FigureName::Fig64VelocityDiagrams, engine, Some("120mm"));
    let plate = Plate::read(&text);
    let detail = ink_of(&plate, &["detail-border", "detail-caption"]);
    for id in ["curve-distance-base", "curve-polar-velocity"] {
        let curve = ink_of(&plate, &[id]);
        assert!(
            curve.y0 >= 0.0 && curve.x0 >= 0.0,
            "{id} leaves the page: {curve:?}"
        );
        assert!(curve.x1 <= plate.width, "{id} leaves the page: {curve:?}");
        let strokes = plate.panels[0].strokes.iter().filter(|s| s.id == id);
        for seg in strokes.flat_map(|s| s.segs.iter()) {
            for (x, y) in [seg.0, seg.1] {
                let inside = x > detail.x0 && x < detail.x1 && y > detail.y0 && y < detail.y1;
                assert!(!inside, "{id} runs through the detail at ({x:.0}, {y:.0})");
            }
        }
    }
}

/// The curve benchmark on an 800 × 300 page (issue 20): each plot kept
/// its legend in a corner, and on plots that short both legends lay on
/// the data. Every legend's ink is now clear of every series and marker.
#[test]
fn the_curve_benchmarks_legends_keep_off_the_data_on_a_short_page() {
    for (width, height) in [("800", Some("300")), ("900", None), ("4.5in", None)] {
        let options = common::on_page(width, height);
        let text = to_svg(&FigureName::CurveBenchmark.figure(&options).unwrap());
        let plate = Plate::read(&text);
        let data: Vec<_> = plate
            .ink
            .iter()
            .filter(|(id, _)| id.starts_with("series-") || id.starts_with("point-"))
            .collect();
        let legends = plate.ink.iter().filter(|(id, _)| id.contains("-legend"));
        let mut seen = 0;
        for (id, box_) in legends {
            seen += 1;
            for (other, r) in &data {
                assert!(!box_.overlaps(r), "{width}: {id} lies on {other}");
            }
        }
        assert!(seen > 0, "{width}: no legend drawn");
    }
}

/// The numbers of a path's `d`.
fn path_numbers(d: &str) -> Vec<f64> {
    d.split(|c: char| c == ' ' || c == ',' || c.is_ascii_alphabetic())
        .filter_map(|t| t.parse().ok())
        .collect()
}

/// Ng's Fig. 1 (issue 20, point 5): F_c, perpendicular to the crank at
/// the crank pin C, arrived at C along the rod wherever the rod is nearly
/// perpendicular to the crank (at the default, 60°, and round it), its
/// shaft drawn over the rod's. Over a turn, at Ng's rig and at a short
/// rod, the shaft never runs within 3 units of the rod's line at under
/// 20° to it, and its head ends within 10 units of C.
#[test]
fn ngs_crank_force_never_lies_along_the_rod() {
    for (r, l) in [(25.0, 72.0), (1.0, 1.08), (1.0, 2.0)] {
        for deg in (0..360).step_by(10).map(f64::from) {
            let text = svg(FigureName::NgFig1Torque, Some((r, l, 0.0, deg)), None);
            let Some(at) = text.find("id=\"force-Fc\"") else {
                continue;
            };
            let rest = &text[at..];
            let d = &rest[rest.find(" d=\"").unwrap() + 4..];
            let shaft = path_numbers(&d[..d.find('"').unwrap()]);
            let rod = path_numbers(&common::attr(&text, "link-rod", "d").unwrap());
            let c = (rod[0], rod[1]);
            let (rx, ry) = (rod[2] - rod[0], rod[3] - rod[1]);
            let (sx, sy) = (shaft[2] - shaft[0], shaft[3] - shaft[1]);
            let (rn, sn) = (rx.hypot(ry), sx.hypot(sy));
            // The angle between the shaft, read from its head back, and
            // the rod from C.
            let cos = -(rx * sx + ry * sy) / (rn * sn);
            let off = |p: (f64, f64)| ((p.0 - c.0) * ry - (p.1 - c.1) * rx).abs() / rn;
            let head = (shaft[2], shaft[3]);
            let along = cos > 20f64.to_radians().cos() && off(head) < 3.0;
            assert!(
                !along,
                "l = {l} r, {deg}°: F_c along the rod ({:.1} off it)",
                off(head)
            );
            // The arrowhead's tip: the first point of the group's second path.
            let after = &d[d.find('"').unwrap()..];
            let tip = &after[after.find(" d=\"").unwrap() + 4..];
            let tip = path_numbers(&tip[..tip.find('"').unwrap()]);
            let reach = distance((tip[0], tip[1]), c);
            assert!(
                reach < 10.0,
                "l = {l} r, {deg}°: F_c ends {reach:.1} from C"
            );
        }
    }
}

/// Ng's Fig. 1 (issue 20): at a short rod the slider's velocity v_p,
/// drawn under the slider towards the crank, ran into the torque's arc
/// about O and its head lay on the arc's (`--rod 1.08 --angle 93`). Over
/// a turn, at Ng's rig and at short rods, no point of v_p's arrow comes
/// within the torque arc's radius and its head's room (44 units) of O.
#[test]
fn the_sliders_velocity_keeps_off_the_torque_arrow() {
    for (r, l) in [(25.0, 72.0), (1.0, 1.05), (1.0, 1.08), (1.0, 1.2)] {
        for deg in (0..360).step_by(5).map(f64::from) {
            let text = svg(FigureName::NgFig1Torque, Some((r, l, 0.0, deg)), None);
            let (Some(at), true) = (text.find("id=\"velocity-vp\""), text.contains("torque-T"))
            else {
                continue;
            };
            let o = (
                common::num(&text, "point-O", "cx"),
                common::num(&text, "point-O", "cy"),
            );
            let group = &text[at..at + text[at..].find("</g>").unwrap()];
            for d in group.split(" d=\"").skip(1) {
                let xy = path_numbers(&d[..d.find('"').unwrap()]);
                // Every vertex, and ten points along each straight piece.
                let along = xy.chunks(2).zip(xy.chunks(2).skip(1)).flat_map(|(p, q)| {
                    (0..=10).map(move |k| {
                        let t = f64::from(k) / 10.0;
                        (p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1]))
                    })
                });
                for p in along {
                    let near = distance(p, o);
                    assert!(
                        near >= 44.0,
                        "l = {l}, {deg}°: v_p {near:.1} from O, on the torque's arc"
                    );
                }
            }
        }
    }
}

/// The coupler curves (issue 20): P₁'s oval turned 2 units inside the
/// guides' lines at the default engine (its half height r/4 against the
/// block's), so that near its top and bottom it ran along them. No oval
/// runs more than 40 units within 4 units of a guide's line or on its
/// hatching (a crossing, even at 15°, runs less).
#[test]
fn the_coupler_ovals_do_not_run_along_the_guides() {
    let engines = [
        None,
        Some((1.0, 1.1, 0.08, 110.0)),
        Some((1.0, 4.0, 0.5, 200.0)),
    ];
    for engine in engines {
        let plate = Plate::read(&svg(FigureName::CouplerCurves, engine, None));
        let main = &plate.panels[0];
        let stroke = |id: &str| main.strokes.iter().find(|s| s.id == id);
        let ends = |s: &plate::Stroke| Rect::around(s.segs.iter().flat_map(|g| [g.0, g.1]));
        for oval in ["curve-coupler-25", "curve-coupler-50", "curve-coupler-75"] {
            let segs = &stroke(oval).unwrap().segs;
            for (guide, hatch) in [
                ("guide-upper", "hatch-guide-upper"),
                ("guide-lower", "hatch-guide-lower"),
            ] {
                let (Some(line), Some(hatching)) = (stroke(guide), stroke(hatch)) else {
                    continue;
                };
                let (line, hatching) = (ends(line).unwrap(), ends(hatching).unwrap());
                let band = (
                    hatching.y0.min(line.y0 - 4.0),
                    hatching.y1.max(line.y0 + 4.0),
                );
                // The oval's length in the band over the guide's stretch,
                // each piece cut in ten.
                let along: f64 = segs
                    .iter()
                    .flat_map(|g| {
                        (0..10).map(move |k| {
                            let at =
                                |t: f64| (g.0.0 + t * (g.1.0 - g.0.0), g.0.1 + t * (g.1.1 - g.0.1));
                            (at(f64::from(k) / 10.0), at(f64::from(k + 1) / 10.0))
                        })
                    })
                    .filter(|(p, q)| {
                        let mid = ((p.0 + q.0) / 2.0, (p.1 + q.1) / 2.0);
                        (line.x0..=line.x1).contains(&mid.0) && (band.0..=band.1).contains(&mid.1)
                    })
                    .map(|(p, q)| distance(p, q))
                    .sum();
                println!("{engine:?} {oval} {guide}: {along:.1}");
                assert!(
                    along <= 40.0,
                    "{engine:?}: {oval} runs {along:.1} units along {guide}"
                );
            }
        }
    }
}

#[test]
fn a_curve_through_hatching_breaks_it() {
    // The centrodes cross the guides at Fig. 61's default; P₁'s oval runs
    // through the lower guide's hatching at `--rod 3 --offset 1.5
    // --angle 3`, where no channel clears every turn of the ovals. No
    // hatch stroke is left under a curve (every one was drawn).
    let cases = [
        (FigureName::Fig61Centrodes, None),
        (FigureName::CouplerCurves, Some((1.0, 3.0, 1.5, 3.0))),
    ];
    for (name, engine) in cases {
        let plate = Plate::read(&svg(name, engine, None));
        let main = &plate.panels[0];
        let of = |pick: fn(&plate::Stroke) -> bool| {
            (main.strokes.iter())
                .filter(move |s| pick(s))
                .flat_map(|s| s.segs.iter())
        };
        let hatching: Vec<_> = of(|s| s.id.starts_with("hatch-")).collect();
        assert!(!hatching.is_empty(), "{name:?}: no hatching");
        let crossed = of(|s| s.class == "curve" && s.id.starts_with("curve-"))
            .flat_map(|c| hatching.iter().filter(move |h| h.meets(c)))
            .count();
        assert_eq!(
            crossed, 0,
            "{name:?}: {crossed} hatch strokes under a curve"
        );
    }
}

/// The segments of the strokes `id` (after the panel's prefix) in `panel`.
fn pieces(panel: &plate::Panel, id: &str) -> Vec<plate::Seg> {
    let id = format!("{}{id}", panel.prefix);
    panel
        .strokes
        .iter()
        .filter(|s| s.id == id)
        .flat_map(|s| s.segs.iter().copied())
        .collect()
}

/// The least distance from points along `a`'s pieces (21 to a piece) to
/// `b`'s pieces; infinite where either is not drawn.
fn nearest(a: &[plate::Seg], b: &[plate::Seg]) -> f64 {
    a.iter()
        .flat_map(|s| {
            (0..=20).map(move |k| {
                let t = f64::from(k) / 20.0;
                (s.0.0 + t * (s.1.0 - s.0.0), s.0.1 + t * (s.1.1 - s.0.1))
            })
        })
        .flat_map(|p| b.iter().map(move |s| s.distance_to(p)))
        .fold(f64::INFINITY, f64::min)
}

/// Ng's Fig. 1 (eighth review): at long rods near 270° v_c, which would
/// lie along the rod, came to the crank pin from the other side, on F_c's
/// line in F_c's sense, and the two were one arrow named "v_c F_c"; and
/// v_p's tail stood on F_s's shaft above the block, a branch of F_s, at
/// short and long rods. Over the turn at short, middling and long rods,
/// in the main view and the crank's detail: v_c's arrow keeps 3 units
/// from F_c's, and v_p's 4 units from F_s's.
#[test]
fn ngs_velocities_keep_off_the_forces_arrows() {
    let angles = (0..360)
        .step_by(15)
        .map(f64::from)
        .chain([269.52, 270.82, 90.32, 269.27]);
    let angles: Vec<f64> = angles.collect();
    for l in [1.04, 1.07, 1.1, 3.0, 26.0, 39.7, 50.0] {
        for &deg in &angles {
            let text = svg(FigureName::NgFig1Torque, Some((1.0, l, 0.0, deg)), None);
            let plate = Plate::read(&text);
            for panel in &plate.panels {
                let vc = nearest(&pieces(panel, "velocity-vc"), &pieces(panel, "force-Fc"));
                assert!(
                    vc >= 3.0,
                    "l = {l} r, {deg}°, {}: v_c {vc:.1} from F_c",
                    panel.id
                );
                let vp = nearest(&pieces(panel, "velocity-vp"), &pieces(panel, "force-Fs"));
                assert!(
                    vp >= 4.0,
                    "l = {l} r, {deg}°, {}: v_p {vp:.1} from F_s",
                    panel.id
                );
            }
        }
    }
}

/// Ng's Fig. 1 (tenth review): F_c, coming to the crank pin in the
/// torque's sense, and v_c, leaving it in ω's, lay on one line through
/// the pin, read as one line with two heads (at the dead centres, and at
/// the default). v_c now stands off F_c's line: the farthest of F_c's
/// points from v_c's line is 4 units off it or more.
#[test]
fn ngs_crank_pin_velocity_is_not_on_the_forces_line() {
    for l in [1.02, 1.38, 2.88, 30.0] {
        for deg in [0.0, 60.0, 120.0, 180.0, 240.0, 300.0] {
            let text = svg(FigureName::NgFig1Torque, Some((1.0, l, 0.0, deg)), None);
            let plate = Plate::read(&text);
            for panel in &plate.panels {
                let (vc, fc) = (pieces(panel, "velocity-vc"), pieces(panel, "force-Fc"));
                let Some(line) = vc.first() else {
                    continue;
                };
                let (d, n) = ((line.1.0 - line.0.0, line.1.1 - line.0.1), 0.0);
                let len = (d.0 * d.0 + d.1 * d.1).sqrt();
                let off =
                    |p: plate::Pt| ((p.0 - line.0.0) * d.1 - (p.1 - line.0.1) * d.0).abs() / len;
                let farthest = (fc.iter())
                    .flat_map(|s| [off(s.0), off(s.1)])
                    .fold(n, f64::max);
                assert!(
                    fc.is_empty() || farthest >= 4.0,
                    "l = {l} r, {deg}°, {}: F_c within {farthest:.1} of v_c's line",
                    panel.id
                );
            }
        }
    }
}

/// Inversion 2 at its default (eighth review): O_cd at infinity on the
/// line A O_bd had its arrow begin at O_bd's dot by the page's edge, and
/// "O_cd at ∞" stood stacked on O_bd's letter over the one dot. The page
/// now reaches past O_bd for O_cd's line and arrow, its letter by the
/// arrow: the two letters' boxes keep 20 units apart.
#[test]
fn o_cd_at_infinity_is_lettered_apart_from_o_bd() {
    let text = svg(FigureName::Inversion2RotatingBlock, None, None);
    let plate = Plate::read(&text);
    let label = |id: &str| {
        plate
            .panels
            .iter()
            .flat_map(|p| p.labels.iter())
            .find(|l| l.id == id)
            .map(|l| l.rect)
            .unwrap_or_else(|| panic!("{id} not lettered"))
    };
    let (cd, bd) = (label("label-O-cd"), label("label-O-bd"));
    let gap = (cd.x0 - bd.x1)
        .max(bd.x0 - cd.x1)
        .max(cd.y0 - bd.y1)
        .max(bd.y0 - cd.y1);
    assert!(gap >= 20.0, "O_cd's and O_bd's letters {gap:.1} apart");
}

/// Whether the straight way from the point `at` to the middle of the box
/// `r`, less its first 5 units (the pin), crosses one of the panel's
/// lines whose ids start with one of `prefixes`.
fn way_back_crosses(
    panel: &plate::Panel,
    at: (f64, f64),
    r: &Rect,
    prefixes: &[&str],
) -> Vec<String> {
    let c = centre(r);
    let d = distance(at, c);
    let from = (at.0 + (c.0 - at.0) * 5.0 / d, at.1 + (c.1 - at.1) * 5.0 / d);
    let way = plate::Seg(from, c);
    (panel.strokes.iter())
        .filter(|s| prefixes.iter().any(|p| s.id.starts_with(p)))
        .filter(|s| s.segs.iter().any(|g| g.meets(&way)))
        .map(|s| s.id.clone())
        .collect()
}

/// The relative-velocity figure at l = 2.34 r, e = 0.672 r, 269.45°
/// (issue 38): A's letter stood below the lower guide, the way from it
/// back to A's pin across the ground line, read as lettering the rod
/// beside it. A letter now keeps on its point's side of the links and
/// guides where a place there is as clear: A's way back crosses no guide
/// nor link.
#[test]
fn a_letter_keeps_on_its_points_side_of_the_guides() {
    let engine = Some((1.0, 2.34, 0.672, 269.45));
    let text = svg(FigureName::VelocityAccelerationPolygons, engine, None);
    let plate = Plate::read(&text);
    let panel = &plate.panels[0];
    let a = panel
        .labels
        .iter()
        .find(|l| l.id == "label-A")
        .unwrap()
        .rect;
    let crossed = way_back_crosses(panel, panel.markers["A"], &a, &["guide-", "link-"]);
    assert!(crossed.is_empty(), "A's letter {a:?} across {crossed:?}");
}

/// Kisch's construction at l = 1.09 r, 0° (issue 38): the foot of the
/// perpendicular F, G lies inside the detail's frame, its dot and letter
/// left to the detail, and A's letter on the main view stood under it,
/// outside the block, far from A's pin: read as naming the foot. A point
/// left to a detail is still a point the letters of the main view keep
/// farther from than from their own: A's letter, where it stands, is
/// nearer A than any other named point (from the metadata) on the page.
#[test]
fn a_letter_keeps_nearer_its_own_point_than_one_left_to_the_detail() {
    let text = svg(FigureName::Fig66Kisch, Some((1.0, 1.09, 0.0, 0.0)), None);
    let plate = Plate::read(&text);
    let meta = common::metadata(&text);
    let m: Vec<f64> = (meta["page_from_world"].as_array().unwrap().iter())
        .map(|v| v.as_f64().unwrap())
        .collect();
    let page = |p: &serde_json::Value| {
        let (x, y) = (p[0].as_f64().unwrap(), p[1].as_f64().unwrap());
        (m[0] * x + m[2] * y + m[4], m[1] * x + m[3] * y + m[5])
    };
    let points = meta["points"].as_object().unwrap();
    let own = page(&points["A"]);
    let panel = &plate.panels[0];
    let Some(a) = panel.labels.iter().find(|l| l.id == "label-A") else {
        return;
    };
    let mine = a.rect.distance_to(own);
    for (name, p) in points {
        let q = page(p);
        if distance(q, own) > 1.0 {
            let d = a.rect.distance_to(q);
            assert!(
                mine <= d,
                "A's letter {:?} {mine:.1} from A, {d:.1} from {name}",
                a.rect
            );
        }
    }
}

/// The line of stroke, opened for a letter near its end, leaves no stub
/// beyond it shorter than one period of its dashes (14 3 2 3): alone
/// beside the letter it reads as a sign, "−A" (the polygons at
/// l = 58.2 r, 180° and l = 37.7 r, 89.61°).
#[test]
fn the_line_of_stroke_leaves_no_stub_beside_a_letter() {
    for (l, deg) in [(58.2, 180.0), (37.7, 89.61)] {
        let svg = svg(
            FigureName::VelocityAccelerationPolygons,
            Some((1.0, l, 0.0, deg)),
            None,
        );
        let d = common::attr(&svg, "line-stroke", "d").unwrap();
        let pieces: Vec<f64> = (d.split('M').filter(|s| !s.trim().is_empty()))
            .map(|piece| {
                let n = path_numbers(piece);
                (n[2] - n[0]).hypot(n[3] - n[1])
            })
            .collect();
        assert!(
            pieces.len() == 1 || pieces.iter().all(|&length| length >= 22.0),
            "l = {l}, {deg}°: pieces {pieces:?} of {d}"
        );
    }
}

/// The block's letter in Fig. 60 (issue 38): at l = 1.06 r, 269.09°,
/// (b)'s "c" stood between the crank and the rod hugging the rod, read
/// as the rod's name; at 90.03° (c)'s stood under C's bearing, nowhere
/// near the block. A block's letter stands nearer the block's outline
/// than any link or bearing of its panel (by the glyphs' box, read from
/// the main view's strokes).
#[test]
fn a_blocks_letter_stands_nearer_its_block_than_a_link_or_a_bearing() {
    for deg in [269.09, 90.03] {
        let text = svg(FigureName::Fig60Chains, Some((1.0, 1.06, 0.0, deg)), None);
        let plate = Plate::read(&text);
        let panel = &plate.panels[0];
        for k in ["b", "c"] {
            let Some(letter) = (panel.labels.iter()).find(|l| l.id == format!("label-link-c-{k}"))
            else {
                panic!("{deg}°: no letter of the block in ({k})");
            };
            let nearest = |prefix: &str| {
                (panel.strokes.iter())
                    .filter(|s| s.id.starts_with(prefix) && s.id.ends_with(&format!("-{k}")))
                    .flat_map(|s| s.segs.iter())
                    .map(|s| letter.rect.distance_to_seg(s))
                    .fold(f64::INFINITY, f64::min)
            };
            let own = nearest("block-slider");
            assert!(own.is_finite(), "{deg}°: no block read in ({k})");
            for rival in ["link-crank", "link-rod", "bearing-C"] {
                let d = nearest(rival);
                assert!(
                    own + 1.0 <= d,
                    "{deg}°: ({k})'s c {:?} {own:.1} from its block, {d:.1} from {rival}",
                    letter.rect
                );
            }
        }
    }
}
