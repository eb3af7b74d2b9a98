//! Fig. 60 (the quadric crank chain and its two slotted forms) read back
//! from its SVG at the engines where a reader misread it: a link's letter
//! by another link, two links lying along one another with their letters
//! side by side over one line, O_cd's letter loose from its arrow, the
//! slot's middle line run on past its guides along the rod, the block over
//! the crank's bearing unremarked, a rod run through the crank centre's
//! ground mark.

use super::polygon_figures::{path, svg, text_centre};
use crate::common::{group_path, group_strokes, read_text, segment_distance};
use crate::plate::{Plate, Seg};
use slider_crank::FigureName;

const FIG: FigureName = FigureName::Fig60Chains;

/// The reviewed engines (l, e, θ at r = 1) and their neighbours.
const ENGINES: [(f64, f64, f64); 16] = [
    (1.06, 0.0, 269.41),
    (1.06, 0.0, 268.41),
    (1.06, 0.0, 270.41),
    (1.1, 0.0, 269.41),
    (1.06, 0.0, 180.0),
    (1.1, 0.0, 180.0),
    (1.1, 0.0, 179.0),
    (1.1, 0.0, 181.0),
    (1.14, 0.0, 180.0),
    (1.1, 0.0, 90.73),
    (1.1, 0.0, 270.58),
    (3.0, 0.0, 50.0),
    (2.5, 0.5, 180.0),
    (2.5, -0.5, 180.0),
    (30.0, 0.0, 90.0),
    (60.0, 0.0, 270.0),
];

/// The signed distance of `p` from the line through `s` (positive on the
/// left of its direction on the page).
fn side(p: (f64, f64), s: &Seg) -> f64 {
    let (d, q) = ((s.1.0 - s.0.0, s.1.1 - s.0.1), (p.0 - s.0.0, p.1 - s.0.1));
    (d.0 * q.1 - d.1 * q.0) / d.0.hypot(d.1)
}

/// Whether `t` lies along `s`: both its ends within a pixel of `s`'s line
/// (a crank lying on its frame, a rod folded back on the crank).
fn lies_along(t: &Seg, s: &Seg) -> bool {
    side(t.0, s).abs() < 1.5 && side(t.1, s).abs() < 1.5
}

/// The part of `s` (0 to 1 along it) that `t`, lying along it, covers.
fn covered(s: &Seg, t: &Seg) -> (f64, f64) {
    let (d0, d1) = (s.1.0 - s.0.0, s.1.1 - s.0.1);
    let len2 = d0 * d0 + d1 * d1;
    let at = |p: (f64, f64)| ((p.0 - s.0.0) * d0 + (p.1 - s.0.1) * d1) / len2;
    let (a, b) = (at(t.0), at(t.1));
    (a.min(b), a.max(b))
}

/// Whether the foot of `p` on `s` falls on `s` outside the part `t`
/// covers.
fn bare(p: (f64, f64), s: &Seg, t: &Seg) -> bool {
    let (lo, hi) = covered(s, t);
    let (d0, d1) = (s.1.0 - s.0.0, s.1.1 - s.0.1);
    let at = ((p.0 - s.0.0) * d0 + (p.1 - s.0.1) * d1) / (d0 * d0 + d1 * d1);
    (0.0..=1.0).contains(&at) && !(lo - 0.02..=hi + 0.02).contains(&at)
}

/// A link's run on the page from its path: its ends, or for the frame d
/// drawn beside the line C O_cd (four points, turned in to its pins at
/// either end) the straight run between the turns.
fn run(p: &[(f64, f64)]) -> Seg {
    match p.len() {
        4 => Seg(p[1], p[2]),
        _ => Seg(p[0], p[p.len() - 1]),
    }
}

#[test]
fn each_link_letter_stands_nearer_its_own_link_than_any_other() {
    // At l = 1.06 r, 269.41° (a) set b right of the lever c, ~37 units
    // from c and ~69 from the rod b; at 180° the rod's b and the crank's a
    // stood side by side over one line. A letter is nearer its own link
    // than any other; where two links lie along one another, the letters
    // stand on the line's two sides or each by its own link's part the
    // other leaves bare.
    let mut lettered = 0;
    for (rod, offset, deg) in ENGINES {
        let svg = svg(FIG, rod, offset, deg);
        let plate = Plate::read(&svg);
        for (suffix, links) in [
            (
                "a",
                &[("a", "crank"), ("b", "rod"), ("c", "lever"), ("d", "frame")][..],
            ),
            ("b", &[("a", "crank"), ("b", "rod")][..]),
            ("c", &[("a", "crank"), ("b", "rod")][..]),
        ] {
            let seg = |id: &str| run(&path(&svg, &format!("link-{id}-{suffix}")));
            let segs: Vec<(&str, Seg)> = links.iter().map(|&(l, id)| (l, seg(id))).collect();
            for (letter, own) in &segs {
                let id = format!("label-link-{letter}-{suffix}");
                let Some(p) = text_centre(&plate, &id) else {
                    continue;
                };
                lettered += 1;
                let mine = segment_distance(p, own.0, own.1);
                for (other, theirs) in &segs {
                    if other == letter {
                        continue;
                    }
                    let what = format!("l = {rod}, e = {offset}, {deg}°: {id} at {p:?}");
                    if lies_along(theirs, own) || lies_along(own, theirs) {
                        let q = text_centre(&plate, &format!("label-link-{other}-{suffix}"));
                        let apart = q.is_some_and(|q| side(p, own) * side(q, own) < 0.0);
                        // Either letter by its link's part the other
                        // leaves bare.
                        let bare = bare(p, own, theirs) || q.is_some_and(|q| bare(q, theirs, own));
                        assert!(
                            apart || bare,
                            "{what}: {letter} and {other} lie along one another, letters on one side over one line"
                        );
                    } else {
                        let d = segment_distance(p, theirs.0, theirs.1);
                        assert!(
                            mine < d,
                            "{what}: {mine:.1} from its link {letter}, {d:.1} from {other}"
                        );
                    }
                }
            }
        }
    }
    assert!(lettered > 0, "no link letter found to check");
}

#[test]
fn o_cd_at_infinity_is_lettered_at_its_arrow() {
    // At l = 1.1 r, 90.73° and 270.58° (c)'s "O_cd at ∞" floated under
    // the crank circle with a gap above its arrow (and at the default).
    let mut checked = 0;
    for (rod, offset, deg) in ENGINES {
        let svg = svg(FIG, rod, offset, deg);
        let plate = Plate::read(&svg);
        let Some(label) = plate.texts.iter().find(|t| t.id == "label-O-cd-c") else {
            continue;
        };
        checked += 1;
        let arrow = group_path(&svg, "infinity-O-cd-c");
        let shaft = Seg(arrow[0], arrow[arrow.len() - 1]);
        let gap = label.rect.distance_to_seg(&shaft);
        // Within a letter's height of its arrow.
        assert!(
            gap < label.font_size,
            "l = {rod}, e = {offset}, {deg}°: O_cd's letter {gap:.1} from its arrow"
        );
    }
    assert!(checked > 0, "no engine drew O_cd at infinity");
}

#[test]
fn the_slot_middle_line_ends_with_its_guides() {
    // At the default (l = 3 r, 50°) (b)'s dashed middle line ran on past
    // the guides' open end, along the rod b and across it below its
    // letter. Every point of it lies between the guides drawn, and off
    // the rod outside the block.
    let mut slots = 0;
    for (rod, offset, deg) in ENGINES {
        let svg = svg(FIG, rod, offset, deg);
        for suffix in ["b", "c"] {
            let Some(_) = crate::common::tag(&svg, &format!("guide-slot-upper-{suffix}")) else {
                continue;
            };
            slots += 1;
            let guides: Vec<Vec<(f64, f64)>> = ["upper", "lower"]
                .iter()
                .map(|g| path(&svg, &format!("guide-slot-{g}-{suffix}")))
                .collect();
            let width = segment_distance(guides[0][0], guides[1][0], guides[1][1]);
            let middle = path(&svg, &format!("line-slot-{suffix}"));
            let link_b = path(&svg, &format!("link-rod-{suffix}"));
            let block = path(&svg, &format!("block-slider-{suffix}"));
            for &p in &middle {
                let d = (guides.iter().flat_map(|g| g.windows(2)))
                    .map(|w| segment_distance(p, w[0], w[1]))
                    .fold(f64::INFINITY, f64::min);
                assert!(
                    d < 0.5 * width + 1.5,
                    "l = {rod}, e = {offset}, {deg}°: ({suffix}) middle line at {p:?} {d:.1} from the guides, past their end"
                );
                // The rod as drawn (beside the crank where it lies
                // along it, turned in to its pins).
                let by_rod = (link_b.windows(2))
                    .map(|w| segment_distance(p, w[0], w[1]))
                    .fold(f64::INFINITY, f64::min);
                assert!(
                    by_rod > 2.0 || super::inversion_figures::within(&block, p),
                    "l = {rod}, e = {offset}, {deg}°: ({suffix}) middle line at {p:?} {by_rod:.1} from the rod b, outside the block"
                );
            }
        }
    }
    assert!(slots > 0, "no slot drawn to check");
}

#[test]
fn a_block_over_the_crank_centre_is_noted() {
    // At l = 1.1 r, 180° the block and slot of (b) and (c) covered the
    // crank's pin and its ground mark, unremarked. Where the block's
    // outline comes within a few units of C's pin the notes say so; not
    // otherwise.
    for (rod, offset, deg) in ENGINES {
        let svg = svg(FIG, rod, offset, deg);
        let text: String = read_text(&svg).split_whitespace().collect();
        let noted = text.contains("blockstandsoverthecrank’scentre");
        let mut over = false;
        for suffix in ["b", "c"] {
            let c = (
                crate::common::num(&svg, &format!("pin-C-{suffix}"), "cx"),
                crate::common::num(&svg, &format!("pin-C-{suffix}"), "cy"),
            );
            let block = path(&svg, &format!("block-slider-{suffix}"));
            let n = block.len();
            let d = (0..n)
                .map(|i| segment_distance(c, block[i], block[(i + 1) % n]))
                .fold(f64::INFINITY, f64::min);
            let inside = super::inversion_figures::within(&block, c);
            over |= inside || d < 6.0;
        }
        assert_eq!(
            noted, over,
            "l = {rod}, e = {offset}, {deg}°: the block over C {over}, noted {noted}"
        );
    }
}

/// Engines where a link ran through a bearing's pedestal or base (l, e, θ
/// at r = 1): the rod just under the crank centre, the crank pointing
/// straight down, the rod folded back onto the crank.
const THROUGH_BEARING: [(f64, f64, f64); 8] = [
    (1.97, -0.484, 180.0),
    (1.97, -0.484, 179.0),
    (1.97, 0.484, 180.0),
    (1.93, -0.484, 180.0),
    (1.97, -0.484, 269.32),
    (1.08, 0.0, 269.31),
    (1.08, 0.0, 180.0),
    (2.5, -0.5, 181.0),
];

#[test]
fn no_link_runs_through_a_bearing() {
    // At l = 1.97 r, e = -0.484 r, 180° the rod b passed through the
    // crank's pedestal and hatched base just under C in all three panels
    // and read as pinned there; at 269.32° the crank a ran down through
    // its own pedestal. A bearing turns to a side clear of the links: no
    // link comes within a line's width of its ink away from the shaft's
    // pin (the links leave the pin between its pedestal's sides).
    let mut bearings = 0;
    for (rod, offset, deg) in ENGINES.into_iter().chain(THROUGH_BEARING) {
        let svg = svg(FIG, rod, offset, deg);
        for (suffix, links) in [
            ("a", &["crank", "rod", "lever"][..]),
            ("b", &["crank", "rod"][..]),
            ("c", &["crank", "rod"][..]),
        ] {
            // Each piece of a link as drawn (a rod folded over the crank
            // drawn beside it, turned in to its pins).
            let links: Vec<Seg> = (links.iter())
                .flat_map(|id| {
                    let p = path(&svg, &format!("link-{id}-{suffix}"));
                    (p.windows(2).map(|w| Seg(w[0], w[1]))).collect::<Vec<_>>()
                })
                .collect();
            for (bearing, pin) in [("C", "pin-C"), ("O-cd", "point-O-cd")] {
                let strokes = group_strokes(&svg, &format!("bearing-{bearing}-{suffix}"));
                if strokes.is_empty() {
                    continue;
                }
                bearings += 1;
                let pin = format!("{pin}-{suffix}");
                let centre = (
                    crate::common::num(&svg, &pin, "cx"),
                    crate::common::num(&svg, &pin, "cy"),
                );
                for (p, q) in strokes {
                    for k in 0..=20 {
                        let t = f64::from(k) / 20.0;
                        let x = (p.0 + (q.0 - p.0) * t, p.1 + (q.1 - p.1) * t);
                        if (x.0 - centre.0).hypot(x.1 - centre.1) < 9.0 {
                            continue;
                        }
                        for link in &links {
                            let d = segment_distance(x, link.0, link.1);
                            assert!(
                                d > 1.5,
                                "l = {rod}, e = {offset}, {deg}°: ({suffix}) a link {d:.1} from {bearing}'s bearing at {x:?}"
                            );
                        }
                    }
                }
            }
        }
    }
    assert!(bearings > 0, "no bearing found to check");
}

#[test]
fn the_frame_is_never_hidden_along_a_moving_link() {
    // At l = 1.08 r, 269.31° (a)'s crank a pointed at O_cd and lay on the
    // frame d, hidden in it, its pin read as a joint halfway along d; at
    // 180° the lever c, folded onto d, merged with it. d is drawn beside
    // the line C O_cd there: no moving link comes within 3 units of it
    // over more than a pin's width.
    let mut checked = 0;
    for (rod, offset, deg) in ENGINES.into_iter().chain(THROUGH_BEARING) {
        let svg = svg(FIG, rod, offset, deg);
        let d = run(&path(&svg, "link-frame-a"));
        for id in ["crank", "rod", "lever"] {
            let p = path(&svg, &format!("link-{id}-a"));
            let (s, t) = (p[0], p[p.len() - 1]);
            let length = (t.0 - s.0).hypot(t.1 - s.1);
            let n = (length.ceil() as usize).max(1);
            let near = (0..=n)
                .map(|k| {
                    let u = k as f64 / n as f64;
                    (s.0 + (t.0 - s.0) * u, s.1 + (t.1 - s.1) * u)
                })
                .filter(|&x| segment_distance(x, d.0, d.1) < 3.0)
                .count() as f64
                * length
                / n as f64;
            checked += 1;
            assert!(
                near <= 10.0,
                "l = {rod}, e = {offset}, {deg}°: the {id} lies along the frame d over {near:.1} units"
            );
        }
    }
    assert!(checked > 0, "no link checked");
}

/// Where (a)'s lever c leaves O_cd 11° off the line C O_cd (l = 1.42 r,
/// e = 0.255 r, 180°), with its neighbours.
const LEVER_BY_D: [(f64, f64, f64); 7] = [
    (1.42, 0.255, 180.0),
    (1.42, 0.255, 179.0),
    (1.42, 0.255, 181.0),
    (1.37, 0.255, 180.0),
    (1.47, 0.255, 180.0),
    (1.42, -0.255, 180.0),
    (1.5, 0.0, 50.0),
];

#[test]
fn the_frame_ends_at_its_pins_not_on_a_moving_link() {
    // At l = 1.42 r, e = 0.255 r, 180° the lever c leaves O_cd 11° off
    // the line C O_cd, along it over more than a pin's width, and d was
    // drawn 7 units beside that line, straight: its end met the crank a
    // halfway along, short of C's pin (as at l = 1.1 r, 180°, the lever
    // folded along d). Each end of d lies at a pin (C's or O_cd's), or
    // else clear of every moving link.
    const PIN: f64 = 4.2;
    let mut checked = 0;
    for (rod, offset, deg) in ENGINES.into_iter().chain(THROUGH_BEARING).chain(LEVER_BY_D) {
        let svg = svg(FIG, rod, offset, deg);
        let centre = |id: &str| {
            let at = |k: &str| {
                crate::common::attr(&svg, id, k)
                    .unwrap()
                    .parse::<f64>()
                    .unwrap()
            };
            (at("cx"), at("cy"))
        };
        let pins = [centre("pin-C-a"), centre("point-O-cd-a")];
        let frame = path(&svg, "link-frame-a");
        for end in [frame[0], frame[frame.len() - 1]] {
            checked += 1;
            if pins.iter().any(|p| (end.0 - p.0).hypot(end.1 - p.1) <= PIN) {
                continue;
            }
            for id in ["crank", "rod", "lever"] {
                let p = path(&svg, &format!("link-{id}-a"));
                let d = segment_distance(end, p[0], p[p.len() - 1]);
                assert!(
                    d > 2.6,
                    "l = {rod}, e = {offset}, {deg}°: the frame d ends {d:.1} from the {id}, off its pins"
                );
            }
        }
    }
    assert!(checked > 0, "no end of d checked");
}

/// Long rods (l, e, θ at r = 1) and page widths where the crank a of
/// every panel was a speck (l = 53 r: two pin circles, its letter naming
/// nothing seen), with their neighbours.
const LONG: [(f64, f64, f64, Option<&str>); 9] = [
    (53.0, 0.0, 0.0, None),
    (53.0, 0.0, 1.0, None),
    (30.0, 0.0, 90.0, None),
    (30.0, 0.0, 91.0, None),
    (25.0, 1.5, 270.0, None),
    (60.0, -1.9, 180.0, None),
    (40.0, 0.0, 90.0, Some("500")),
    (40.0, 0.0, 89.0, Some("120mm")),
    (3.0, 0.0, 50.0, Some("120mm")),
];

/// Fig. 60 at `(rod, offset, deg)` (r = 1) on a page `width` wide (the
/// figure's own where `None`).
fn svg_at(rod: f64, offset: f64, deg: f64, width: Option<&str>) -> String {
    use slider_crank::catalogue::FigureOptions;
    use slider_crank::{Angle, SliderCrank};
    let mut options = FigureOptions::default();
    options.mechanism = Some(SliderCrank::new(1.0, rod, offset).unwrap());
    options.angle = Some(Angle::deg(deg));
    options.width = width.map(|w| w.parse().unwrap());
    slider_crank::render::to_svg(&FIG.figure(&options).unwrap())
}

/// The length on the page of the link `id` (its ends), none where it is
/// not drawn.
fn drawn_length(svg: &str, id: &str) -> Option<f64> {
    crate::common::tag(svg, id)?;
    let p = path(svg, id);
    let (s, t) = (p[0], p[p.len() - 1]);
    Some((t.0 - s.0).hypot(t.1 - s.1))
}

#[test]
fn every_link_of_every_panel_is_drawn_at_least_40_units_long() {
    // At l = 53 r the crank a of each panel was a speck of two pin
    // circles, no enlargement; at l = 30 r, 90° it could not be seen in
    // any panel. Each link is drawn 40 units long or more, in the panel
    // or in its detail; a crank is lettered once, in its detail where
    // the panel draws it shorter, nearer its own link than the rod.
    const SEEN: f64 = 40.0;
    let mut details = 0;
    for (rod, offset, deg, width) in ENGINES.iter().map(|&(l, e, d)| (l, e, d, None)).chain(LONG) {
        let svg = svg_at(rod, offset, deg, width);
        let plate = Plate::read(&svg);
        let what = format!("l = {rod}, e = {offset}, {deg}°, width {width:?}");
        for (suffix, links) in [
            ("a", &["crank", "rod", "lever", "frame"][..]),
            ("b", &["crank", "rod"][..]),
            ("c", &["crank", "rod"][..]),
        ] {
            for link in links {
                let main = drawn_length(&svg, &format!("link-{link}-{suffix}")).unwrap_or(0.0);
                let detail = drawn_length(&svg, &format!("detail-link-{link}-{suffix}"));
                details += usize::from(detail.is_some());
                let longest = main.max(detail.unwrap_or(0.0));
                assert!(
                    longest >= SEEN,
                    "{what}: ({suffix}) the {link} drawn {main:.1} long, {detail:?} in a detail"
                );
            }
            let Some(_) = crate::common::tag(&svg, &format!("detail-link-crank-{suffix}")) else {
                continue;
            };
            // Lettered once: in the panel (a detail of crowded pins, the
            // crank seen in the panel) or in its detail.
            let panel = text_centre(&plate, &format!("label-link-a-{suffix}"));
            let detail = text_centre(&plate, &format!("detail-label-link-a-{suffix}"));
            let p = match (panel, detail) {
                (Some(_), None)
                    if drawn_length(&svg, &format!("link-crank-{suffix}"))
                        .is_some_and(|l| l >= SEEN) =>
                {
                    continue;
                }
                (None, Some(p)) => p,
                (panel, detail) => panic!(
                    "{what}: ({suffix}) a lettered in the panel {}, in its detail {}",
                    panel.is_some(),
                    detail.is_some()
                ),
            };
            // Each link as drawn (the rod beside the crank where it lies
            // along it, turned in to its pins).
            let by = |id: &str| {
                let q = path(&svg, &format!("detail-link-{id}-{suffix}"));
                (q.windows(2))
                    .map(|w| segment_distance(p, w[0], w[1]))
                    .fold(f64::INFINITY, f64::min)
            };
            let (mine, other) = (by("crank"), by("rod"));
            assert!(
                mine < other,
                "{what}: ({suffix}) the detail's a {mine:.1} from the crank, {other:.1} from the rod"
            );
        }
    }
    assert!(details > 0, "no detail drawn to check");
}

/// The coupler curves' SVG at `(rod, offset, deg)` (r = 1) on a page
/// `width` wide (the figure's own where `None`).
fn coupler_at(rod: f64, offset: f64, deg: f64, width: Option<&str>) -> String {
    use slider_crank::catalogue::FigureOptions;
    use slider_crank::{Angle, SliderCrank};
    let mut options = FigureOptions::default();
    options.mechanism = Some(SliderCrank::new(1.0, rod, offset).unwrap());
    options.angle = Some(Angle::deg(deg));
    options.width = width.map(|w| w.parse().unwrap());
    slider_crank::render::to_svg(&FigureName::CouplerCurves.figure(&options).unwrap())
}

/// The height on the page of the path `id`, none where it is not drawn.
fn drawn_height(svg: &str, id: &str) -> Option<f64> {
    crate::common::tag(svg, id)?;
    let p = path(svg, id);
    let (lo, hi) = (p.iter()).fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), q| {
        (lo.min(q.1), hi.max(q.1))
    });
    Some(hi - lo)
}

#[test]
fn a_long_rods_ovals_and_crank_are_drawn_to_be_seen() {
    // At l = 30 r, 170° the ovals were a few units tall and the crank a
    // speck, C's letter standing at B, no enlargement. Each oval is drawn
    // at least 40 units tall and the crank 40 units long, in the main
    // view or a detail, and each point's letter in a detail stands within
    // an em and a half of its own dot.
    const SEEN: f64 = 40.0;
    let mut details = 0;
    for (rod, offset, deg, width) in [
        (30.0, 0.0, 170.0, None),
        (30.0, 0.0, 171.0, None),
        (30.0, 0.0, 169.0, Some("120mm")),
        (53.0, -1.9, 270.0, Some("500")),
        (25.0, 0.5, 90.0, None),
        (60.0, 1.0, 0.0, None),
        (4.0, 1.5, 90.0, None),
        (3.0, 0.0, 91.0, None),
    ] {
        let svg = coupler_at(rod, offset, deg, width);
        let plate = Plate::read(&svg);
        let what = format!("l = {rod}, e = {offset}, {deg}°, width {width:?}");
        let crank = drawn_length(&svg, "link-crank").unwrap_or(0.0);
        let enlarged = drawn_length(&svg, "detail-link-crank-0");
        assert!(
            crank.max(enlarged.unwrap_or(0.0)) >= SEEN,
            "{what}: the crank drawn {crank:.1} long, {enlarged:?} in a detail"
        );
        for (k, id) in ["25", "50", "75"].into_iter().enumerate() {
            let main = drawn_height(&svg, &format!("curve-coupler-{id}")).unwrap_or(0.0);
            let detail = drawn_height(&svg, &format!("detail-curve-coupler-{id}"));
            details += usize::from(detail.is_some());
            assert!(
                main.max(detail.unwrap_or(0.0)) >= SEEN,
                "{what}: P{}'s oval drawn {main:.1} tall, {detail:?} in a detail",
                k + 1
            );
            let suffix = format!("P{}-{}", k + 1, k + 1);
            let Some(letter) = plate
                .texts
                .iter()
                .find(|t| t.id == format!("detail-label-{suffix}"))
            else {
                continue;
            };
            let dot = format!("detail-point-{suffix}");
            let p = (
                crate::common::num(&svg, &dot, "cx"),
                crate::common::num(&svg, &dot, "cy"),
            );
            let gap = letter.rect.distance_to_seg(&Seg(p, p));
            assert!(
                gap < 1.5 * letter.font_size,
                "{what}: P{}'s letter {gap:.1} from its dot in the detail",
                k + 1
            );
        }
    }
    assert!(details > 0, "no detail drawn to check");
}

#[test]
fn no_oval_is_drawn_in_the_centre_lines_pattern() {
    // P₃'s oval was drawn long dash and dot, as the line of stroke, a
    // centre line, running through every oval: where they ran together
    // it read as a second centre line. Each oval's pattern differs from
    // the line of stroke's in its kind (dashes and dots, or not).
    let svg = coupler_at(3.0, 0.0, 40.0, None);
    let kind = |id: &str| {
        let dashes = crate::common::attr(&svg, id, "stroke-dasharray").unwrap_or_default();
        let lengths: Vec<f64> = dashes
            .split_whitespace()
            .filter_map(|w| w.parse().ok())
            .collect();
        // Dashes with dots between: a long and a short drawn length.
        let drawn: Vec<f64> = lengths.iter().step_by(2).copied().collect();
        let long = drawn.iter().any(|&d| d > 4.0);
        let dot = drawn.iter().any(|&d| d < 2.5);
        long && dot
    };
    assert!(
        kind("line-stroke"),
        "the line of stroke is not dash and dot"
    );
    for id in ["25", "50", "75"] {
        assert!(
            !kind(&format!("curve-coupler-{id}")),
            "P's oval {id} drawn long dash and dot, as the line of stroke"
        );
    }
}

#[test]
fn no_piece_of_guide_the_block_does_not_stand_on_is_shorter_than_the_block() {
    // At l = 1.37 r, e = 0.225 r, 0° the rod crossing the lower guide
    // left a piece of it, about 40 units, standing alone beside B.
    for (rod, offset, deg) in [
        (1.37, 0.225, 0.0),
        (1.37, 0.225, 180.0),
        (1.32, 0.225, 1.0),
        (1.42, -0.225, 359.0),
        (1.07, 0.0, 180.0),
        (3.0, 0.0, 40.0),
    ] {
        let svg = coupler_at(rod, offset, deg, None);
        let block = path(&svg, "block-slider");
        let xs = || block.iter().map(|p| p.0);
        let (b0, b1) = (xs().fold(f64::MAX, f64::min), xs().fold(f64::MIN, f64::max));
        let mut pieces = 0;
        for side in ["upper", "lower"] {
            for k in 1..6 {
                let id = match k {
                    1 => format!("guide-{side}"),
                    _ => format!("guide-{side}-{k}"),
                };
                if !svg.contains(&format!("id=\"{id}\"")) {
                    continue;
                }
                pieces += 1;
                let g = path(&svg, &id);
                let (u, v) = (g[0].0.min(g[1].0), g[0].0.max(g[1].0));
                let under = u <= b1 + 0.01 && v >= b0 - 0.01;
                assert!(
                    under || v - u >= b1 - b0,
                    "l = {rod}, e = {offset}, θ = {deg}: {id} over {u}..{v}, {} long, the block {} long",
                    v - u,
                    b1 - b0
                );
            }
        }
        assert!(
            pieces >= 2,
            "l = {rod}, e = {offset}, θ = {deg}: {pieces} guides"
        );
    }
}

/// The length (page units) of the polyline `p` within `near` of the
/// segment `s`, from a point every half unit or so, leaving out its
/// points within `ends` of its first and last.
fn length_near(p: &[(f64, f64)], s: &Seg, near: f64, ends: f64) -> f64 {
    let (first, last) = (p[0], p[p.len() - 1]);
    let off = |x: (f64, f64), e: (f64, f64)| (x.0 - e.0).hypot(x.1 - e.1) >= ends;
    p.windows(2)
        .map(|w| {
            let (a, b) = (w[0], w[1]);
            let length = (b.0 - a.0).hypot(b.1 - a.1);
            let n = ((2.0 * length).ceil() as usize).max(1);
            (0..n)
                .map(|k| {
                    let u = (k as f64 + 0.5) / n as f64;
                    (a.0 + (b.0 - a.0) * u, a.1 + (b.1 - a.1) * u)
                })
                .filter(|&x| off(x, first) && off(x, last))
                .filter(|&x| segment_distance(x, s.0, s.1) < near)
                .count() as f64
                * length
                / n as f64
        })
        .sum()
}

#[test]
fn links_folded_over_one_another_are_drawn_apart() {
    // At l = 1.06 r, 180° the rod folded back over the crank in every
    // panel, drawn on it: one line with a letter either side; and (a)'s
    // frame d, 7 units beside the lever c folded onto it, read with it
    // as one double line; at l = 1.03 r and 1.08 r, 180° the rod lay on
    // the crank in (b) and (c), where (a) drew it beside. In every panel
    // the rod runs 8 units or more (a link's width and paper) from the
    // crank, and d from the lever, but where each turns in to its pins
    // (within 25 units of them).
    const APART: f64 = 8.0;
    const TURNS: f64 = 25.0;
    let mut checked = 0;
    for (rod, offset, deg) in ENGINES.into_iter().chain(FOLDED) {
        let svg = svg(FIG, rod, offset, deg);
        let seg = |p: Vec<(f64, f64)>| Seg(p[0], p[p.len() - 1]);
        let mut pairs = vec![];
        for k in ["a", "b", "c"] {
            let crank = seg(path(&svg, &format!("link-crank-{k}")));
            let rod = path(&svg, &format!("link-rod-{k}"));
            // Folded: the rod leaves B back along the crank (within 6°)
            // and ends on it, by C.
            let (b, a) = (rod[0], rod[rod.len() - 1]);
            let (u, v) = ((crank.0.0 - b.0, crank.0.1 - b.1), (a.0 - b.0, a.1 - b.1));
            let cos = (u.0 * v.0 + u.1 * v.1) / (u.0.hypot(u.1) * v.0.hypot(v.1));
            if cos > 6f64.to_radians().cos() && v.0.hypot(v.1) < 1.5 * u.0.hypot(u.1) {
                pairs.push((format!("rod b of ({k})"), rod, crank));
            }
        }
        let lever = seg(path(&svg, "link-lever-a"));
        let frame = path(&svg, "link-frame-a");
        if frame.len() == 4 {
            pairs.push(("frame d of (a)".into(), frame, lever));
        }
        for (what, p, other) in pairs {
            checked += 1;
            let near = length_near(&p, &other, APART, TURNS);
            assert!(
                near < 1.0,
                "l = {rod}, e = {offset}, {deg}°: the {what} runs {near:.1} units within {APART} of the link folded under it"
            );
        }
    }
    assert!(checked > 0, "no pair checked");
}

/// Engines where the short rod folded back over the crank lay on it in
/// (b) and (c) (l, e, θ at r = 1), and their neighbours.
const FOLDED: [(f64, f64, f64); 5] = [
    (1.03, 0.0, 180.0),
    (1.03, 0.0, 181.0),
    (1.08, 0.0, 180.0),
    (1.08, 0.0, 179.0),
    (1.06, 0.0, 181.0),
];

/// Engines where (a) drew the rod bent beside its line, the crank 11°
/// off it, A inside the crank circle (l, e, θ at r = 1).
const APART_ALREADY: [(f64, f64, f64); 4] = [
    (1.4, 0.3, 180.0),
    (1.4, -0.3, 180.0),
    (1.35, 0.3, 180.0),
    (1.4, 0.3, 181.0),
];

#[test]
fn the_rod_is_drawn_beside_its_line_only_where_the_crank_lies_along_it() {
    // At l = 1.4 r, e = 0.3 r, 180° (a) bent the rod beside its line
    // because A stood inside the crank circle, though the crank left it
    // at 11°. The rod is drawn beside its line (four points) only where
    // the crank's far end C lies within 15 units of that line (two
    // links' widths and paper: the two lie along one another).
    const ALONG: f64 = 15.0;
    let mut rods = 0;
    for (rod, offset, deg) in ENGINES.into_iter().chain(FOLDED).chain(APART_ALREADY) {
        let svg = svg(FIG, rod, offset, deg);
        for k in ["a", "b", "c"] {
            let crank = path(&svg, &format!("link-crank-{k}"));
            let p = path(&svg, &format!("link-rod-{k}"));
            rods += 1;
            if p.len() != 4 {
                continue;
            }
            let d = segment_distance(crank[0], p[0], p[3]);
            assert!(
                d < ALONG,
                "l = {rod}, e = {offset}, {deg}°: ({k}) the rod is drawn beside its line, C {d:.1} units off it"
            );
        }
    }
    assert!(rods > 0, "no rod checked");
}

#[test]
fn the_block_over_the_crank_centre_is_lettered_away_from_its_bearing() {
    // At l = 1.03 r, 180° the block of (c) stood over C and its letter c
    // was set under C's bearing, by its hatching. Where the block stands
    // over C (A within 15 units of C), its letter stands on the other
    // side of the slot's line through A from the bearing's base.
    let mut checked = 0;
    for (rod, offset, deg) in FOLDED {
        let svg = svg(FIG, rod, offset, deg);
        let plate = Plate::read(&svg);
        for k in ["b", "c"] {
            let at = |id: &str| {
                let id = format!("{id}-{k}");
                (
                    crate::common::num(&svg, &id, "cx"),
                    crate::common::num(&svg, &id, "cy"),
                )
            };
            let (a, c) = (at("pin-A"), at("pin-C"));
            if (a.0 - c.0).hypot(a.1 - c.1) > 15.0 {
                continue;
            }
            // Across the slot at A: along the radius from O_cd in (b),
            // upright in (c).
            let across = match k {
                "b" => {
                    let r = path(&svg, "line-radius-b");
                    let (o, q) = (r[0], r[r.len() - 1]);
                    let n = (q.0 - o.0).hypot(q.1 - o.1);
                    ((q.0 - o.0) / n, (q.1 - o.1) / n)
                }
                _ => (0.0, 1.0),
            };
            let strokes = group_strokes(&svg, &format!("bearing-C-{k}"));
            let far = (strokes.iter())
                .flat_map(|&(p, q)| [p, q])
                .map(|p| (p.0 - a.0) * across.0 + (p.1 - a.1) * across.1)
                .fold(0.0, |m: f64, d| if d.abs() > m.abs() { d } else { m });
            let letter = text_centre(&plate, &format!("label-link-c-{k}")).expect("c lettered");
            let side = (letter.0 - a.0) * across.0 + (letter.1 - a.1) * across.1;
            checked += 1;
            assert!(
                side * far < 0.0,
                "l = {rod}, e = {offset}, {deg}°: ({k}) c lettered {side:.1} across the slot, C's bearing reaching {far:.1}"
            );
        }
    }
    assert!(checked > 0, "no block over C checked");
}

#[test]
fn the_crank_centre_and_the_rod_s_end_crowded_stand_apart_in_a_detail() {
    // The review of l = 1.03 r, 180° (2.5): in (a) the crank centre's
    // pin and the b–c pin merged under one ground mark, in (b) and (c)
    // the block stood over the crank centre, and no detail showed them.
    // Where C and A stand nearer than two em (34 units) on the page, each
    // panel has a detail that draws them twice as far apart at least,
    // the block of (b) and (c) drawn there.
    for (rod, offset, deg) in [
        (1.03, 0.0, 180.0),
        (1.03, 0.0, 179.0),
        (1.08, 0.0, 180.0),
        (1.03, 0.0, 90.89),
        (1.06, 0.0, 180.0),
    ] {
        let svg = svg(FIG, rod, offset, deg);
        let at = format!("l = {rod}, e = {offset}, {deg}°");
        let centre = |id: &str| {
            let cx: f64 = crate::common::attr(&svg, id, "cx")?.parse().ok()?;
            let cy: f64 = crate::common::attr(&svg, id, "cy")?.parse().ok()?;
            Some((cx, cy))
        };
        let gap = |p: (f64, f64), q: (f64, f64)| (p.0 - q.0).hypot(p.1 - q.1);
        let mut crowded = 0;
        for suffix in ["a", "b", "c"] {
            let (Some(c), Some(a)) = (
                centre(&format!("pin-C-{suffix}")),
                centre(&format!("pin-A-{suffix}")),
            ) else {
                panic!("{at}: ({suffix}) has no pins C and A");
            };
            let main = gap(c, a);
            if main >= 34.0 {
                continue;
            }
            crowded += 1;
            let (Some(dc), Some(da)) = (
                centre(&format!("detail-pin-C-{suffix}")),
                centre(&format!("detail-pin-A-{suffix}")),
            ) else {
                panic!("{at}: C and A {main:.1} apart in ({suffix}), no detail draws them");
            };
            let drawn = gap(dc, da);
            assert!(
                drawn >= 2.0 * main,
                "{at}: C and A {main:.1} apart in ({suffix}), {drawn:.1} in its detail"
            );
            if suffix != "a" {
                assert!(
                    crate::common::tag(&svg, &format!("detail-block-slider-{suffix}")).is_some(),
                    "{at}: ({suffix})'s detail leaves out the block"
                );
            }
        }
        assert!(crowded > 0, "{at}: C and A read apart in every panel");
    }
}
