//! The marks of the dynamics figures read back from their SVG: the crank
//! effort's arc of the inertia force figure and the torque arrow of Ng's
//! Fig. 1, each by what it names and clear of what it does not.

use crate::plate;

use plate::{Label, Panel, Plate, Pt, Seg};
use slider_crank::catalogue::FigureOptions;
use slider_crank::{Angle, FigureName, SliderCrank, render::to_svg};

/// The plate of `figure` at a crank of 1, `rod`, `offset` and `degrees`.
fn plate_at(figure: &str, rod: f64, offset: f64, degrees: f64) -> Plate {
    let mut options = FigureOptions::default();
    options.mechanism = Some(SliderCrank::new(1.0, rod, offset).unwrap());
    options.angle = Some(Angle::deg(degrees));
    let f = FigureName::from_name(figure).unwrap().figure(&options);
    Plate::read(&to_svg(&f.unwrap()))
}

/// The pieces of the strokes of `panel` with the id `id`.
fn segs<'a>(panel: &'a Panel, id: &str) -> Vec<&'a Seg> {
    panel
        .strokes
        .iter()
        .filter(|s| s.id == id)
        .flat_map(|s| &s.segs)
        .collect()
}

fn label<'a>(panel: &'a Panel, id: &str) -> &'a Label {
    let found = panel.labels.iter().find(|l| l.id == id);
    found.unwrap_or_else(|| panic!("no {id}"))
}

fn centre(l: &Label) -> Pt {
    (0.5 * (l.rect.x0 + l.rect.x1), 0.5 * (l.rect.y0 + l.rect.y1))
}

fn distance(p: Pt, q: Pt) -> f64 {
    (p.0 - q.0).hypot(p.1 - q.1)
}

#[test]
fn the_crank_effort_s_arc_keeps_off_the_ends_of_the_construction() {
    // The inertia force at l = 2.04 r, e = 0.562 r, 90.16°: CG on the
    // main view as long as the arc's radius, the arc ran through G,
    // where CG and the line from B end, its head there: it read as the
    // arrowhead of the line from B. The arc keeps a letter's room from
    // the ends of the lines.
    let plate = plate_at("inertia-force", 2.04, 0.562, 90.16);
    let main = &plate.panels[0];
    let arc = segs(main, "torque-T");
    assert!(!arc.is_empty(), "no crank effort on the main view");
    // G: the end of CG away from C.
    let c = plate.point(main, "C").expect("C");
    let cg = segs(main, "line-CG");
    let g = [cg.first().expect("no CG").0, cg.last().expect("no CG").1]
        .into_iter()
        .max_by(|p, q| distance(*p, c).total_cmp(&distance(*q, c)))
        .unwrap();
    let near = arc
        .iter()
        .map(|s| s.distance_to(g))
        .fold(f64::INFINITY, f64::min);
    assert!(near >= 10.0, "the arc {near:.1} from G");
}

#[test]
fn ng_s_torque_letter_stands_by_its_arc_clear_of_the_rest() {
    // Ng's Fig. 1 at l = 1.53 r, e = 0.467 r, 0°: the torque line OM ran
    // down through the arc's gap and T, set off it, stood beyond M's dot,
    // far from its arc; at l = 1.93 r, e = −0.732 r, 180°, on the rod in
    // a row with l and M. The gap turns where nothing runs through it
    // (the crank, OM, the rod, the offset's extension line), and T stands
    // in it on the arc's circle, clear of the links and the other
    // letters.
    for (rod, offset, degrees) in [(1.53, 0.467, 0.0), (1.93, -0.732, 180.0)] {
        let at = format!("at l = {rod}, e = {offset}, {degrees}°");
        let plate = plate_at("ng-fig-1-torque", rod, offset, degrees);
        let main = &plate.panels[0];
        let o = plate.point(main, "O").expect("O");
        let arc = segs(main, "torque-T");
        let radius = distance(arc[0].0, o);
        let t = label(main, "value-T");
        let off = (distance(centre(t), o) - radius).abs();
        // Within an em of the circle: nearer than a point's letter to
        // its point (the plate check's 1.5 em).
        assert!(off <= t.font_size, "T {off:.1} off its arc {at}");
        let mut lines = segs(main, "link-rod");
        lines.extend(segs(main, "link-crank"));
        let near = lines
            .iter()
            .map(|s| t.rect.distance_to_seg(s))
            .fold(f64::INFINITY, f64::min);
        assert!(near >= 0.5 * t.font_size, "T {near:.1} from a line {at}");
        for other in main.labels.iter().filter(|l| l.id != t.id) {
            let r = &other.rect;
            let dx = (t.rect.x0 - r.x1).max(r.x0 - t.rect.x1).max(0.0);
            let dy = (t.rect.y0 - r.y1).max(r.y0 - t.rect.y1).max(0.0);
            let gap = dx.hypot(dy);
            assert!(
                gap >= 0.5 * t.font_size,
                "T {gap:.1} from {} {at}",
                other.id
            );
        }
    }
}

#[test]
fn ng_s_crank_pin_force_keeps_off_phi_s_reference() {
    // Ng's Fig. 1 at l = 1.53 r, e = 0.467 r, 90.98°: the crank upright,
    // F_c came level from the block's side onto the pin along the dashed
    // parallel to the stroke from which φ is measured, and read as a mark
    // of φ's. It is set off that line, as beside the rod.
    let plate = plate_at("ng-fig-1-torque", 1.53, 0.467, 90.98);
    let main = &plate.panels[0];
    let parallel = segs(main, "line-parallel-B");
    assert!(!parallel.is_empty(), "no parallel for φ");
    let shaft = segs(main, "force-Fc");
    let s = shaft.first().expect("no F_c");
    let mid = (0.5 * (s.0.0 + s.1.0), 0.5 * (s.0.1 + s.1.1));
    let near = parallel
        .iter()
        .map(|p| p.distance_to(mid))
        .fold(f64::INFINITY, f64::min);
    assert!(near >= 4.0, "F_c's shaft {near:.1} from φ's reference");
}

/// The inertia figure's SVG at a crank of 1, `rod` and `degrees`.
fn inertia_svg(rod: f64, degrees: f64) -> String {
    let mut options = FigureOptions::default();
    options.mechanism = Some(SliderCrank::new(1.0, rod, 0.0).unwrap());
    options.angle = Some(Angle::deg(degrees));
    let f = FigureName::from_name("inertia-force")
        .unwrap()
        .figure(&options);
    to_svg(&f.unwrap())
}

/// F_i shorter than its least length on the main view (l = 38 r and
/// 58.1 r near 90°: CG under 0.03 r) is left out there and the notes say
/// so, every line of them on the page (with F_N's note too, five lines
/// ran past the notes' room and off the page's foot); at the default it
/// is drawn and nothing is said.
#[test]
fn an_inertia_force_too_short_to_draw_is_said_so_on_the_page() {
    let said = "too short to draw at the cross-head";
    for (rod, degrees) in [(38.0, 90.09), (58.1, 90.62)] {
        let svg = inertia_svg(rod, degrees);
        assert!(
            !svg.contains("id=\"force-inertia\""),
            "l = {rod}: F_i drawn"
        );
        assert!(svg.contains(said), "l = {rod}: nothing said");
        let plate = Plate::read(&svg);
        for t in &plate.texts {
            assert!(
                t.rect.y1 <= plate.height,
                "l = {rod}: {} at {} past the page's {}",
                t.id,
                t.rect.y1,
                plate.height
            );
        }
    }
    let svg = to_svg(
        &FigureName::from_name("inertia-force")
            .unwrap()
            .figure(&FigureOptions::default())
            .unwrap(),
    );
    assert!(svg.contains("id=\"force-inertia\"") && !svg.contains(said));
}

/// CG of a few hundredths of the crank (l = 38 r at 90.09° and 269.98°,
/// l = 54.9 r at 89.84° and 270.56°: 9 units or less in the ×20 detail)
/// left G, the figure's subject, under C's pin and its ground symbol,
/// and nothing said so. C and G are drawn again in a detail of their
/// own, apart there by more than two letters' room, each lettered, and
/// the notes say why; at the default, where CG reads, there is none.
#[test]
fn a_cg_too_short_to_read_gets_its_own_detail_and_a_note() {
    use crate::common::{num, read_text};
    let said = "too short to show G clear of C";
    for (rod, degrees) in [(38.0, 90.09), (38.0, 269.98), (54.9, 89.84), (54.9, 270.56)] {
        let svg = inertia_svg(rod, degrees);
        assert!(
            svg.contains("id=\"panel-cg\""),
            "l = {rod}, {degrees}°: no detail at C and G"
        );
        let at = |id: &str| (num(&svg, id, "cx"), num(&svg, id, "cy"));
        let (c, g) = (at("cg-point-C"), at("cg-point-G"));
        let apart = distance(c, g);
        assert!(
            apart >= 24.0,
            "l = {rod}, {degrees}°: CG {apart:.1} in its detail"
        );
        // Both inside the detail's border.
        let d = crate::common::attr(&svg, "cg-border", "d").expect("no border");
        let v: Vec<f64> = (d.split(|ch: char| !(ch.is_ascii_digit() || ch == '.' || ch == '-')))
            .filter_map(|w| w.parse().ok())
            .collect();
        let (xs, ys): (Vec<f64>, Vec<f64>) = v.chunks(2).map(|p| (p[0], p[1])).unzip();
        let within = |p: (f64, f64)| {
            let lo = |w: &[f64]| w.iter().copied().fold(f64::INFINITY, f64::min);
            let hi = |w: &[f64]| w.iter().copied().fold(f64::NEG_INFINITY, f64::max);
            p.0 > lo(&xs) && p.0 < hi(&xs) && p.1 > lo(&ys) && p.1 < hi(&ys)
        };
        assert!(
            within(c) && within(g),
            "l = {rod}, {degrees}°: C or G outside"
        );
        for id in ["cg-label-C", "cg-label-G"] {
            assert!(
                svg.contains(&format!("id=\"{id}\"")),
                "l = {rod}, {degrees}°: no {id}"
            );
        }
        assert!(
            read_text(&svg).contains(said),
            "l = {rod}, {degrees}°: nothing said"
        );
    }
    let svg = to_svg(
        &FigureName::from_name("inertia-force")
            .unwrap()
            .figure(&FigureOptions::default())
            .unwrap(),
    );
    assert!(!svg.contains("id=\"panel-cg\"") && !read_text(&svg).contains(said));
}

/// T names its torque arrow where it stands by the arrowhead: at the
/// gap's middle it stood as far from the head as from the tail, and where
/// the gap turned (l = 3.72 r, e = −2.04 r at 180° and 269.1°) it stood
/// by the end of θ's arc, read as naming θ; where the crank ran through
/// the gap (l = 1.53 r, e = 0.467 r, 270.95°) it was set on the arc's
/// far side, struck by θ's arc. At every pose it stands nearer the head
/// than the tail, within two ems of it.
#[test]
fn ng_s_torque_letter_stands_by_its_arrowhead() {
    use crate::common::group_path;
    let poses = [
        (3.72, -2.04, 180.0),
        (3.72, -2.04, 269.1),
        (1.53, 0.467, 270.95),
        (49.4, 0.0, 269.66),
        (72.0 / 25.0, 0.0, 60.0),
    ];
    for (rod, offset, degrees) in poses {
        let at = format!("at l = {rod}, e = {offset}, {degrees}°");
        let mut options = FigureOptions::default();
        options.mechanism = Some(SliderCrank::new(1.0, rod, offset).unwrap());
        options.angle = Some(Angle::deg(degrees));
        let f = FigureName::from_name("ng-fig-1-torque")
            .unwrap()
            .figure(&options);
        let svg = to_svg(&f.unwrap());
        let prefix = if svg.contains("id=\"detail-torque-T\"") {
            "detail-"
        } else {
            ""
        };
        let arc = group_path(&svg, &format!("{prefix}torque-T"));
        let (tail, head) = (arc[0], *arc.last().unwrap());
        let plate = Plate::read(&svg);
        let id = format!("{prefix}value-T");
        let t = plate
            .panels
            .iter()
            .flat_map(|p| &p.labels)
            .find(|l| l.id == id)
            .unwrap_or_else(|| panic!("no T {at}"));
        let (to_head, to_tail) = (distance(centre(t), head), distance(centre(t), tail));
        assert!(
            to_head <= 0.75 * to_tail && to_head <= 2.0 * t.font_size,
            "T {to_head:.1} from the head, {to_tail:.1} from the tail {at}"
        );
    }
}

/// The side thrust F_s of a long rod near 90° and 270° (l = 49.4 r and
/// 53.3 r: tan φ about 0.02) was drawn at its least length, 16 units
/// from the block's face, of which the guide's hatching (6.5 deep) took
/// the first and the head (10 long) the rest: a stub buried in the
/// hatching. Its shaft now runs out of the hatching by a head's length
/// before its head.
#[test]
fn ng_s_side_thrust_clears_the_guide_s_hatching() {
    use crate::common::arrow_ends;
    const HATCH: f64 = 6.5;
    const HEAD: f64 = 10.0;
    for (rod, degrees) in [(49.4, 90.2), (49.4, 269.66), (53.3, 89.66)] {
        let mut options = FigureOptions::default();
        options.mechanism = Some(SliderCrank::new(1.0, rod, 0.0).unwrap());
        options.angle = Some(Angle::deg(degrees));
        let f = FigureName::from_name("ng-fig-1-torque")
            .unwrap()
            .figure(&options);
        let svg = to_svg(&f.unwrap());
        let (tail, tip) = arrow_ends(&svg, "force-Fs");
        let long = distance(tail, tip);
        assert!(
            long >= HATCH + 2.0 * HEAD - 0.5,
            "F_s {long:.1} long at l = {rod}, {degrees}°"
        );
    }
}

/// The detail of C and G letters them from their own places, each by its
/// own letter alone, G with a dot of its own, whatever the panel it
/// copies joined there (the construction's detail letters them "C, G"
/// where CG is short).
#[test]
fn the_cg_detail_letters_c_and_g_each_alone() {
    use crate::common::{attr, tag};
    for (rod, offset, degrees) in [
        (38.0, 0.0, 90.09),
        (54.9, 0.0, 270.56),
        (2.14, -0.923, 269.19),
    ] {
        let at = format!("at l = {rod}, e = {offset}, {degrees}°");
        let mut options = FigureOptions::default();
        options.mechanism = Some(SliderCrank::new(1.0, rod, offset).unwrap());
        options.angle = Some(Angle::deg(degrees));
        let f = FigureName::from_name("inertia-force")
            .unwrap()
            .figure(&options);
        let svg = to_svg(&f.unwrap());
        assert!(svg.contains("id=\"panel-cg\""), "no detail of C and G {at}");
        let ids: Vec<&str> = svg
            .split("id=\"cg-label-")
            .skip(1)
            .map(|s| &s[..s.find('"').unwrap()])
            .collect();
        assert_eq!(ids, ["C", "G"], "the detail's letters {at}");
        for (id, name) in [("cg-label-C", "C"), ("cg-label-G", "G")] {
            let t = tag(&svg, id).unwrap_or_else(|| panic!("no {id} {at}"));
            let start = svg.find(t).unwrap() + t.len() + 1;
            let text = &svg[start..start + svg[start..].find("</text>").unwrap()];
            assert_eq!(text, name, "{id} reads {text} {at}");
        }
        assert!(attr(&svg, "cg-point-G", "cx").is_some(), "no dot at G {at}");
    }
}

/// F_i at a short rod's dead centre (l = 1.07 r at 180°: CG 0.065 r)
/// was a bare arrowhead on the block's corner of the main view and
/// missing from the ×4 detail that holds the cross-head. It is drawn in
/// that detail instead, its shaft at least as long as its head, its
/// tail or tip on a face of the enlarged block, inside the detail's
/// border; the main view draws no stub of it. Its neighbours (180° ± 1°,
/// l = 1.12 r) alike.
#[test]
fn a_short_inertia_force_is_drawn_in_the_detail_at_the_cross_head() {
    use crate::common::{arrow_ends, bounds_of};
    for (rod, degrees) in [(1.07, 180.0), (1.07, 179.0), (1.07, 181.0), (1.12, 180.0)] {
        let svg = inertia_svg(rod, degrees);
        assert!(
            !svg.contains("id=\"force-inertia\""),
            "l = {rod}, {degrees}°: a stub of F_i on the main view"
        );
        let (tail, tip) = arrow_ends(&svg, "detail-force-inertia");
        let length = (tip.0 - tail.0).hypot(tip.1 - tail.1);
        assert!(
            length >= 20.0,
            "l = {rod}, {degrees}°: F_i {length:.1} long"
        );
        let (x0, x1, y0, y1) = bounds_of(&path_points(&svg, "detail-block-slider"));
        let on_face = |p: (f64, f64)| {
            ((p.0 - x0).abs() < 0.5 || (p.0 - x1).abs() < 0.5) && p.1 > y0 && p.1 < y1
        };
        assert!(
            on_face(tail) || on_face(tip),
            "l = {rod}, {degrees}°: F_i {tail:?}–{tip:?} off the block {x0}–{x1}, {y0}–{y1}"
        );
        let border = bounds_of(&path_points(&svg, "detail-border"));
        for p in [tail, tip] {
            assert!(
                p.0 > border.0 && p.0 < border.1 && p.1 > border.2 && p.1 < border.3,
                "l = {rod}, {degrees}°: F_i's end {p:?} outside the detail"
            );
        }
    }
}

/// The points of the `d` of the path `id` (not a group), page units.
fn path_points(svg: &str, id: &str) -> Vec<(f64, f64)> {
    let d = crate::common::attr(svg, id, "d").unwrap_or_else(|| panic!("no {id}"));
    let numbers: Vec<f64> = d
        .split(|c: char| c.is_ascii_alphabetic() || c.is_whitespace())
        .filter_map(|w| w.parse().ok())
        .collect();
    numbers.chunks(2).map(|p| (p[0], p[1])).collect()
}

/// The offset's extension line from the crank centre (Ng's Fig. 1 at
/// l = 3.77 r, e = −1.56 r, 90.04°) ran straight through O's letter and
/// across the torque arc about O: it starts past both. Its neighbours
/// (89.04°, l = 3.72 r) and the offset's other sign alike.
#[test]
fn the_offset_s_extension_line_keeps_off_o_s_letter_and_the_torque_arc() {
    for (rod, offset, degrees) in [
        (3.77, -1.56, 90.04),
        (3.77, -1.56, 89.04),
        (3.72, -1.56, 90.04),
        (3.77, 1.56, 90.04),
    ] {
        let at = format!("l = {rod}, e = {offset}, {degrees}°");
        let plate = plate_at("ng-fig-1-torque", rod, offset, degrees);
        let main = &plate.panels[0];
        let o = plate.point(main, "O").expect("no O");
        let extension: Vec<&Seg> = segs(main, "dimension-e")
            .into_iter()
            .filter(|s| (s.0.1 - o.1).abs() < 0.5 && (s.1.1 - o.1).abs() < 0.5)
            .collect();
        assert!(!extension.is_empty(), "{at}: no extension line from O");
        let letter = label(main, "label-O");
        let arc = segs(main, "torque-T");
        assert!(!arc.is_empty(), "{at}: no torque arc");
        for s in &extension {
            let clear = letter.rect.distance_to_seg(s);
            assert!(
                clear >= 2.0,
                "{at}: the extension line {clear:.1} from O's letter"
            );
            for a in &arc {
                let near = s.distance_to(a.0).min(s.distance_to(a.1));
                assert!(
                    !s.meets(a) && near >= 3.0,
                    "{at}: the extension line {near:.1} from the torque arc"
                );
            }
        }
    }
}

/// Ng's Fig. 1 at l = 1.55 r, e = 0.402 r, 180°: the rod passed over the
/// torque arc's top 3 units from it at M, arc, rod, M and θ's arc piled
/// up there. The arc's radius keeps its room from a rod running by the
/// centre at about its radius, M a letter's half-em and more off the
/// arc; the neighbours (±1°, l ± 0.05 r) alike.
#[test]
fn ng_s_torque_arc_keeps_off_the_rod_passing_by_m() {
    for (rod, degrees) in [
        (1.55, 180.0),
        (1.55, 179.0),
        (1.55, 181.0),
        (1.5, 180.0),
        (1.6, 180.0),
    ] {
        let at = format!("at l = {rod}, e = 0.402, {degrees}°");
        let plate = plate_at("ng-fig-1-torque", rod, 0.402, degrees);
        let main = &plate.panels[0];
        let o = plate.point(main, "O").expect("O");
        let om = segs(main, "line-OM");
        let m = om
            .iter()
            .flat_map(|s| [s.0, s.1])
            .max_by(|p, q| distance(*p, o).total_cmp(&distance(*q, o)))
            .expect("no OM");
        let arc = segs(main, "torque-T");
        assert!(!arc.is_empty(), "no torque arc {at}");
        let near = arc
            .iter()
            .map(|s| s.distance_to(m))
            .fold(f64::INFINITY, f64::min);
        assert!(near >= 6.0, "M {near:.1} from the torque arc {at}");
    }
}
