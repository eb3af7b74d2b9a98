//! Fig. 60 (the quadric crank chain and its two slotted forms) read back
//! from its SVG at the engines where a reader misread it: a link's letter
//! by another link, two links lying along one another with their letters
//! side by side over one line, O_cd's letter loose from its arrow, the
//! slot's middle line run on past its guides along the rod, the block over
//! the crank's bearing unremarked.

use super::polygon_figures::{path, svg, text_centre};
use crate::common::{group_path, read_text, segment_distance};
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
            let seg = |id: &str| {
                let p = path(&svg, &format!("link-{id}-{suffix}"));
                Seg(p[0], p[p.len() - 1])
            };
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
                let by_rod = segment_distance(p, link_b[0], link_b[link_b.len() - 1]);
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
        let noted = text.contains("blockstandsoverthecrankcentre");
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
