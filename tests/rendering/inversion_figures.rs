//! The figures of inversions 2 and 3 (the rotating block, the
//! oscillating cylinder) read back from their SVG at the engines of the
//! eleventh review (docs/figures/review-2026-11k.md) where a reader
//! misread them: the fixed link the notes call hatched and nothing showed
//! fixed, O_ad and O_bc overlapping as a figure 8, the block's letter in
//! the bar's empty end, a fixed pin's ground mark run through by a link or
//! drawn inside d's bar.

use super::polygon_figures::{path, svg, text_centre};
use crate::common::{read_text, tag};
use crate::plate::Plate;
use slider_crank::FigureName;

const I2: FigureName = FigureName::Inversion2RotatingBlock;
const I3: FigureName = FigureName::Inversion3OscillatingCylinder;

/// Whether the page point `p` lies inside the closed outline `outline`
/// (even-odd rule).
fn within(outline: &[(f64, f64)], p: (f64, f64)) -> bool {
    let n = outline.len();
    let mut inside = false;
    for i in 0..n {
        let (a, b) = (outline[i], outline[(i + n - 1) % n]);
        if (a.1 > p.1) != (b.1 > p.1) && p.0 < a.0 + (b.0 - a.0) * (p.1 - a.1) / (b.1 - a.1) {
            inside = !inside;
        }
    }
    inside
}

/// The page distance from `p` to the segment `a b`.
fn to_segment(p: (f64, f64), a: (f64, f64), b: (f64, f64)) -> f64 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let len = dx * dx + dy * dy;
    let t = match len > 0.0 {
        true => (((p.0 - a.0) * dx + (p.1 - a.1) * dy) / len).clamp(0.0, 1.0),
        false => 0.0,
    };
    (p.0 - a.0 - t * dx).hypot(p.1 - a.1 - t * dy)
}

/// The hatch strokes drawn whose ids start with `prefix` (one `M` a stroke).
fn strokes(svg: &str, prefix: &str) -> usize {
    let key = format!("id=\"{prefix}");
    (svg.match_indices(&key))
        .filter_map(|(at, _)| {
            let start = svg[..at].rfind('<')?;
            let end = at + svg[at..].find('>')?;
            let d = svg[start..end].split(" d=\"").nth(1)?.split('"').next()?;
            Some(d.matches('M').count())
        })
        .sum()
}

/// The fixed bar of an inversion: its name in the ids and its two pins.
fn fixed_bar(name: FigureName) -> (&'static str, [&'static str; 2]) {
    match name {
        FigureName::Inversion2RotatingBlock => ("crank", ["C", "B"]),
        _ => ("rod", ["B", "A"]),
    }
}

#[test]
fn the_notes_say_how_the_fixed_link_is_shown_and_the_drawing_shows_it() {
    // The eleventh review: inversion 2 at l = 1.06 r and 51.8 r, 0°, and
    // inversion 3 at l = 1.03 r, 0°: the notes said the fixed link is
    // hatched, the link lay inside d's bar unhatched (every stroke on the
    // bar's outline), and in inversion 3 nothing showed b fixed. Where the
    // notes say hatched, the fixed bar carries three strokes at least;
    // else they name the bearings at its two pins, and both are drawn.
    for (name, rod, offset, deg) in [
        (I2, 1.06, 0.0, 0.0),
        (I2, 1.07, 0.0, 0.0),
        (I2, 51.8, 0.0, 0.0),
        (I2, 36.8, 0.0, 0.0),
        (I2, 3.0, 0.0, 60.0),
        (I3, 1.03, 0.0, 0.0),
        (I3, 1.05, 0.0, 0.0),
        (I3, 1.06, 0.0, 0.0),
        (I3, 3.0, 0.0, 60.0),
        (I3, 3.0, -1.19, 270.05),
        (I3, 1.05, 0.0, 200.0),
    ] {
        let svg = svg(name, rod, offset, deg);
        // The notes' words, the lines they are broken into run together.
        let text: String = read_text(&svg).split_whitespace().collect();
        let (bar, pins) = fixed_bar(name);
        let hatched = strokes(&svg, &format!("hatch-{bar}-"))
            + strokes(&svg, &format!("detail-hatch-{bar}-"));
        let at = format!("{name:?} l = {rod}, e = {offset}, {deg}°");
        if text.contains("Thefixedlinkishatched") {
            assert!(hatched >= 3, "{at}: notes say hatched, {hatched} strokes");
            continue;
        }
        assert!(
            text.contains("isshownfixedbythebearingsatitspins"),
            "{at}: the notes say nothing of the fixed link"
        );
        for pin in pins {
            let drawn = [format!("bearing-{pin}"), format!("detail-bearing-{pin}")]
                .iter()
                .any(|id| tag(&svg, id).is_some());
            assert!(drawn, "{at}: the notes name a bearing at {pin}, none drawn");
        }
    }
}

#[test]
fn o_ad_and_o_bc_crowded_at_the_inner_dead_centre_stand_apart_in_a_detail() {
    // The eleventh review (2.5): at a short rod's inner dead centre the
    // pins O_ad and O_bc, 0.03 to 0.07 cranks apart, overlapped as a
    // figure 8 inside the block with no enlarged detail. A detail draws
    // them two em (34 units) apart at least, each lettered there.
    const APART: f64 = 34.0;
    for (name, rod) in [(I2, 1.06), (I2, 1.07), (I3, 1.03), (I3, 1.05)] {
        let svg = svg(name, rod, 0.0, 180.0);
        let plate = Plate::read(&svg);
        let at = format!("{name:?} l = {rod}, 180°");
        let centre = |key: &str| {
            let id = format!("detail-point-{key}");
            let cx: f64 = crate::common::attr(&svg, &id, "cx")?.parse().ok()?;
            let cy: f64 = crate::common::attr(&svg, &id, "cy")?.parse().ok()?;
            Some((cx, cy))
        };
        let (Some(c), Some(a)) = (centre("C"), centre("A")) else {
            panic!("{at}: no detail draws O_ad and O_bc");
        };
        let gap = (c.0 - a.0).hypot(c.1 - a.1);
        assert!(
            gap >= APART,
            "{at}: O_ad and O_bc {gap:.1} apart in the detail"
        );
        for key in ["C", "A"] {
            let id = format!("detail-label-{key}");
            assert!(
                text_centre(&plate, &id).is_some(),
                "{at}: {id} not lettered"
            );
        }
    }
}

#[test]
fn the_block_s_letter_stands_out_of_the_bar_by_the_block() {
    // The eleventh review: the letter c stood in the bar's empty end
    // beyond the block and named the bar (both defaults, inversion 3 with
    // e = −1.19 at 180°). It stands outside d's slotted bar, within a
    // letter's height of the block's outline.
    const BY: f64 = 17.0;
    for (name, rod, offset, deg) in [
        (I2, 3.0, 0.0, 60.0),
        (I3, 3.0, 0.0, 60.0),
        (I3, 3.0, -1.19, 180.0),
        (I3, 3.0, -1.19, 0.0),
        (I2, 1.06, 0.0, 89.49),
        (I2, 1.06, 0.0, 269.22),
        (I2, 1.06, 0.0, 0.0),
        (I3, 1.05, 0.0, 89.17),
        (I2, 51.8, 0.0, 270.81),
    ] {
        let svg = svg(name, rod, offset, deg);
        let plate = Plate::read(&svg);
        let at = format!("{name:?} l = {rod}, e = {offset}, {deg}°");
        let c = text_centre(&plate, "label-link-c").unwrap_or_else(|| panic!("{at}: no c"));
        let bar = path(&svg, "link-frame");
        assert!(!within(&bar, c), "{at}: c inside d's bar at {c:?}");
        let block = path(&svg, "block-slider");
        let near = (0..block.len())
            .map(|i| to_segment(c, block[i], block[(i + 1) % block.len()]))
            .fold(f64::INFINITY, f64::min);
        assert!(near <= BY, "{at}: c {near:.1} from the block");
    }
}

/// The points of a path, in page units.
type Points = Vec<(f64, f64)>;

/// The pedestal (a triangle) and the base line of the bearing `id`, in
/// page units: the first two paths of its group.
fn bearing(svg: &str, id: &str) -> Option<(Points, Points)> {
    let at = svg.find(&format!("id=\"{id}\""))?;
    let mut paths = svg[at..].split(" d=\"").skip(1).map(|rest| {
        let d = rest.split('"').next().unwrap_or("");
        let n: Vec<f64> = (d.split(|c: char| c == ' ' || c.is_ascii_alphabetic()))
            .filter_map(|t| t.parse().ok())
            .collect();
        n.chunks(2).map(|p| (p[0], p[1])).collect::<Vec<_>>()
    });
    Some((paths.next()?, paths.next()?))
}

#[test]
fn a_fixed_pin_s_ground_mark_stands_clear_of_its_links_and_out_of_the_bar() {
    // The eleventh review: inversion 3's crank a ran through O_ab's
    // pedestal and hatching (the default, e = −1.19 at 89.36°), and at
    // 270.05° O_ab's pedestal and base stood inside d's L, reading as a
    // pin on d (2). No link meets a fixed pin's pedestal beyond the pin,
    // and the base line lies outside d's bar.
    const PIN: f64 = 6.0;
    for (name, rod, offset, deg) in [
        (I3, 3.0, 0.0, 60.0),
        (I3, 3.0, -1.19, 89.36),
        (I3, 3.0, -1.19, 270.05),
        (I3, 1.03, 0.0, 0.0),
        (I2, 3.0, 0.0, 60.0),
        (I2, 1.06, 0.0, 89.49),
    ] {
        let svg = svg(name, rod, offset, deg);
        let at = format!("{name:?} l = {rod}, e = {offset}, {deg}°");
        let bar = path(&svg, "link-frame");
        let links: Vec<Vec<(f64, f64)>> = ["link-crank", "link-rod"]
            .iter()
            .map(|id| path(&svg, id))
            .collect();
        for pin in ["C", "B", "A"] {
            let Some((pedestal, base)) = bearing(&svg, &format!("bearing-{pin}")) else {
                continue;
            };
            let centre = pedestal[0];
            for link in &links {
                for w in link.windows(2) {
                    let through = (0..=100).map(|k| k as f64 / 100.0).any(|t| {
                        let p = (
                            w[0].0 + (w[1].0 - w[0].0) * t,
                            w[0].1 + (w[1].1 - w[0].1) * t,
                        );
                        (p.0 - centre.0).hypot(p.1 - centre.1) > PIN && within(&pedestal, p)
                    });
                    assert!(!through, "{at}: a link through {pin}'s pedestal");
                }
            }
            let mid = (0.5 * (base[0].0 + base[1].0), 0.5 * (base[0].1 + base[1].1));
            for p in [base[0], base[1], mid] {
                assert!(!within(&bar, p), "{at}: {pin}'s base inside d's bar");
            }
        }
    }
}

/// The box (x0, x1, y0, y1) of every path of the bearing group `id`: its
/// pedestal, base and hatching.
fn bearing_box(svg: &str, id: &str) -> Option<(f64, f64, f64, f64)> {
    let at = svg.find(&format!("id=\"{id}\""))?;
    let group = &svg[at..at + svg[at..].find("</g>")?];
    let points: Vec<(f64, f64)> = (group.split(" d=\"").skip(1))
        .flat_map(|rest| {
            let d = rest.split('"').next().unwrap_or("");
            let n: Vec<f64> = (d.split(|c: char| c == ' ' || c.is_ascii_alphabetic()))
                .filter_map(|t| t.parse().ok())
                .collect();
            n.chunks(2).map(|p| (p[0], p[1])).collect::<Vec<_>>()
        })
        .collect();
    Some(crate::common::bounds_of(&points))
}

#[test]
fn the_fixed_pins_carry_bearings_clear_of_the_centres_dots() {
    // The twelfth review: inversion 2's O_ac dot fell on the hatching of
    // O_ab's bearing (the default, and l = 3.56 r, e = −1.74 r at 0°),
    // read as part of the bearing; inversion 3's trunnion O_bc had no
    // bearing where its rod b was hatched while O_ab had one. Both pins
    // of the fixed bar carry a bearing, and no centre's dot stands within
    // 3 units of a bearing's pedestal, base or hatching.
    const CLEAR: f64 = 3.0;
    for (name, rod, offset, deg) in [
        (I2, 3.0, 0.0, 60.0),
        (I2, 3.56, -1.74, 0.0),
        (I2, 3.56, -1.74, 180.0),
        (I3, 3.0, 0.0, 60.0),
        (I3, 34.9, 0.0, 180.0),
        (I3, 1.06, 0.0, 180.0),
    ] {
        let svg = svg(name, rod, offset, deg);
        let at = format!("{name:?} l = {rod}, e = {offset}, {deg}°");
        let (_, pins) = fixed_bar(name);
        for pin in pins {
            let drawn = [format!("bearing-{pin}"), format!("detail-bearing-{pin}")]
                .iter()
                .any(|id| tag(&svg, id).is_some());
            assert!(drawn, "{at}: no bearing at {pin}");
        }
        for prefix in ["", "detail-"] {
            for pin in ["C", "B", "A"] {
                let Some(b) = bearing_box(&svg, &format!("{prefix}bearing-{pin}")) else {
                    continue;
                };
                for key in ["O-bd", "O-ac"] {
                    for kind in ["point", "centre"] {
                        let id = format!("{prefix}{kind}-{key}");
                        let (Some(x), Some(y)) = (
                            crate::common::attr(&svg, &id, "cx"),
                            crate::common::attr(&svg, &id, "cy"),
                        ) else {
                            continue;
                        };
                        let (x, y): (f64, f64) = (x.parse().unwrap(), y.parse().unwrap());
                        let on = x > b.0 - CLEAR
                            && x < b.1 + CLEAR
                            && y > b.2 - CLEAR
                            && y < b.3 + CLEAR;
                        assert!(!on, "{at}: {id} on {prefix}bearing-{pin}");
                    }
                }
            }
        }
    }
}
