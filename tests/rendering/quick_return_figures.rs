//! The quick returns' figures read back from their SVG: the tool's motion
//! drawn against the driver's turn (time), so that the cutting stroke
//! takes its larger share of the axis and the return its smaller, the
//! stroke's end where the time ratio puts it (computed here from the
//! geometry, not read from the program), the cutting stroke's velocity
//! forward and the return's back.

use super::polygon_figures::{path as points, svg};
use slider_crank::FigureName;

/// Engines (l, e, θ at r = 1): the default chain's proportions, a short
/// rod (time ratio about 9), a long one (about 1), offsets of both signs,
/// poses in either stroke and at its ends.
const ENGINES: [(f64, f64, f64); 8] = [
    (3.0, 0.0, 60.0),
    (1.05, 0.0, 90.46),
    (1.08, 0.0, 180.0),
    (33.4, 0.0, 269.43),
    (3.12, 1.29, 0.0),
    (3.12, -1.29, 300.0),
    (2.0, 0.5, 90.0),
    (48.5, 0.0, 270.0),
];

/// The driver's turn over the cutting stroke, degrees: 180° + β with
/// β = asin((r + e)/l) + asin((r − e)/l) (docs/quick-return.md).
fn cutting(l: f64, e: f64) -> f64 {
    180.0 + ((1.0 + e) / l).asin().to_degrees() + ((1.0 - e) / l).asin().to_degrees()
}

#[test]
fn the_tool_moves_against_the_driver_s_turn_its_strokes_in_their_shares_of_it() {
    for name in [
        FigureName::QuickReturnSlottedLever,
        FigureName::QuickReturnWhitworth,
    ] {
        for (l, e, deg) in ENGINES {
            let svg = svg(name, l, e, deg);
            let at = format!("{name:?} at l = {l}, e = {e}, θ = {deg}");
            let axis = points(&svg, "tool-velocity-axis-x");
            let (x0, x1, zero) = (axis[0].0, axis[1].0, axis[0].1);
            let x = |turn: f64| x0 + turn / 360.0 * (x1 - x0);
            let end = points(&svg, "line-tool-velocity-end");
            let cut = cutting(l, e);
            assert!(
                (end[0].0 - x(cut)).abs() < 0.01,
                "{at}: the stroke's end drawn at {} for {cut}° of the turn ({})",
                end[0].0,
                x(cut)
            );
            let cutting = points(&svg, "curve-tool-velocity-cutting");
            let back = points(&svg, "curve-tool-velocity-return");
            let within = |p: &(f64, f64), a: f64, b: f64| p.0 >= a - 0.01 && p.0 <= b + 0.01;
            assert!(cutting.iter().all(|p| within(p, x0, x(cut))), "{at}");
            assert!(back.iter().all(|p| within(p, x(cut), x1)), "{at}");
            // At rest at both ends of the turn and at the stroke's end (the
            // curves' points nearest there, read on either side).
            let nearest = |curve: &[(f64, f64)], to: f64| {
                *(curve.iter())
                    .min_by(|a, b| (a.0 - to).abs().total_cmp(&(b.0 - to).abs()))
                    .unwrap()
            };
            let rest = nearest(&cutting, x0).1;
            for p in [
                nearest(&cutting, x(cut)),
                nearest(&back, x(cut)),
                nearest(&back, x1),
            ] {
                assert!(
                    (p.1 - rest).abs() < 0.05,
                    "{at}: {p:?} not at rest ({rest})"
                );
            }
            // Forward (up the page) on the cutting stroke, back on the
            // return: no point of either on the other side of rest.
            assert!(cutting.iter().all(|p| p.1 <= rest + 0.05), "{at}");
            assert!(back.iter().all(|p| p.1 >= rest - 0.05), "{at}");
            assert!(zero > rest, "{at}: the axis below the curve's rest");
        }
    }
}

/// The cutting stroke's greatest height from the zero line on the page,
/// the return's, and the zero line's page y, read from a panel's curves.
fn heights(svg: &str, panel: &str) -> (f64, f64, f64) {
    let cutting = points(svg, &format!("curve-{panel}-cutting"));
    let back = points(svg, &format!("curve-{panel}-return"));
    // The zero line: rest for the velocity, no acceleration for the
    // acceleration.
    let rest = points(svg, &format!("{panel}-zero-y"))[0].1;
    let peak = |c: &[(f64, f64)]| c.iter().map(|p| (p.1 - rest).abs()).fold(0.0, f64::max);
    (peak(&cutting), peak(&back), rest)
}

#[test]
fn a_cutting_stroke_the_return_dwarfs_is_drawn_again_enlarged_to_be_read() {
    // Whitworth at l = 1.1 r: a 49° return, its spike 21 times the
    // cutting speed; the default chain and a long rod: no enlargement.
    for (name, l, e, deg) in [
        (FigureName::QuickReturnWhitworth, 1.1, 0.0, 0.0),
        (FigureName::QuickReturnWhitworth, 1.05, 0.0, 90.46),
        (FigureName::QuickReturnSlottedLever, 1.05, 0.0, 180.0),
        (FigureName::QuickReturnWhitworth, 3.0, 0.0, 60.0),
        (FigureName::QuickReturnSlottedLever, 33.4, 0.0, 269.43),
    ] {
        let svg = svg(name, l, e, deg);
        let at = format!("{name:?} at l = {l}, e = {e}, θ = {deg}");
        for panel in ["tool-velocity", "tool-acceleration"] {
            let (cut, back, rest) = heights(&svg, panel);
            let id = format!("curve-{panel}-cutting-enlarged");
            let drawn = svg.contains(&format!("id=\"{id}\""));
            assert_eq!(
                drawn,
                back > 10.0 * cut,
                "{at}, {panel}: {cut} against {back}"
            );
            if !drawn {
                continue;
            }
            let enlarged = points(&svg, &id);
            let cutting = points(&svg, &format!("curve-{panel}-cutting"));
            let big = enlarged
                .iter()
                .map(|p| (p.1 - rest).abs())
                .fold(0.0, f64::max);
            // To a round factor (1, 2, 5 in each decade), to between a
            // fifth and half the return. Page coordinates are written to
            // 0.01.
            let round = [5.0, 10.0, 20.0, 50.0, 100.0, 200.0, 500.0, 1000.0];
            let k = round
                .into_iter()
                .find(|r| (big - r * cut).abs() < 0.01 * (r + 1.0))
                .unwrap_or_else(|| panic!("{at}, {panel}: enlarged ×{}", big / cut));
            assert!(
                big >= 0.2 * back && big <= 0.5 * back + 1e-6,
                "{at}, {panel}: {big} of {back}"
            );
            // The same stroke: over the same turn, at rest where it is.
            let (a, b) = (cutting[0].0, cutting[cutting.len() - 1].0);
            assert!(
                (enlarged[0].0 - a).abs() < 0.01
                    && (enlarged[enlarged.len() - 1].0 - b).abs() < 0.01,
                "{at}"
            );
            let named = format!("×{k}");
            assert!(svg.contains(&named), "{at}, {panel}: ×{k} not named");
        }
    }
}

/// The x extent of a curve on the page.
fn extent(curve: &[(f64, f64)]) -> f64 {
    let xs = curve.iter().map(|p| p.0);
    xs.clone().fold(f64::MIN, f64::max) - xs.fold(f64::MAX, f64::min)
}

#[test]
fn a_short_return_is_drawn_again_over_its_own_span_its_stretch_named() {
    // Whitworth at l = 1.03 r: a 28° return had been a hair-thin spike
    // against the whole turn. Returns under 60° (l below about 1.16 r)
    // are drawn again beside each panel over their own span; the
    // default chain's 105° return is not.
    for (l, e, deg, beside) in [
        (1.03, 0.0, 0.0, true),
        (1.1, 0.0, 270.5, true),
        (1.05, 0.0, 90.46, true),
        (3.0, 0.0, 60.0, false),
        (2.0, 0.5, 90.0, false),
    ] {
        let svg = svg(FigureName::QuickReturnWhitworth, l, e, deg);
        let at = format!("l = {l}, e = {e}, θ = {deg}");
        let back = 360.0 - cutting(l, e);
        assert_eq!(back < 60.0, beside, "{at}: a {back}° return");
        for (panel, own) in [
            ("tool-velocity", "return-velocity"),
            ("tool-acceleration", "return-acceleration"),
        ] {
            let id = format!("curve-{own}");
            assert_eq!(svg.contains(&format!("id=\"{id}\"")), beside, "{at}: {id}");
            if !beside {
                continue;
            }
            let whole = extent(&points(&svg, &format!("curve-{panel}-return")));
            let drawn = extent(&points(&svg, &id));
            // The dotted end clear of the axis (at l = 1.1 r it ran into
            // it, 0.8° apart).
            let end = points(&svg, &format!("line-{own}-end"))[0].0;
            let axis = points(&svg, &format!("{own}-axis-y"))[0].0;
            assert!(
                (end - axis).abs() >= 5.0,
                "{at}, {own}: the end {end} by the axis {axis}"
            );
            let stretch = drawn / whole;
            assert!(stretch >= 2.5, "{at}, {own}: ×{stretch}");
            let caption = text_of(&svg, &format!("{own}-caption"));
            let named: f64 = caption
                .rsplit('×')
                .next()
                .and_then(|k| k.trim().parse().ok())
                .unwrap_or_else(|| panic!("{at}: {caption}"));
            assert!(
                (named - stretch).abs() <= 0.051,
                "{at}, {own}: ×{named} named, ×{stretch} drawn"
            );
        }
    }
}

/// The text of the element `id`.
fn text_of(svg: &str, id: &str) -> String {
    let start = svg
        .find(&format!("id=\"{id}\""))
        .unwrap_or_else(|| panic!("no {id}"));
    let rest = &svg[start..];
    let open = rest.find('>').unwrap_or(0) + 1;
    let close = rest.find("</text>").unwrap_or(rest.len());
    crate::common::read_text(&rest[open..close])
}

#[test]
fn tick_labels_keep_to_five_digits_the_power_named_in_the_unit() {
    // At l = 1.03 r the acceleration's ticks read 1500000 ft/s².
    let svg = svg(FigureName::QuickReturnWhitworth, 1.03, 0.0, 0.0);
    let text = crate::common::read_text(&svg);
    assert!(
        text.contains("(10⁶ ft/s²)") || text.contains("(106 ft/s²)"),
        "no shared power"
    );
    let mut n = 0;
    for piece in svg.split("-tick-y-").skip(1) {
        let label = piece
            .split_once('>')
            .map_or("", |(_, t)| t.split('<').next().unwrap_or(""));
        let digits = label.chars().filter(char::is_ascii_digit).count();
        assert!(digits <= 5, "tick label {label}");
        n += 1;
    }
    assert!(n >= 12, "{n} tick labels read");
}

#[test]
fn an_offset_is_named_as_the_chain_has_it_the_slot_in_d() {
    // The figures draw no mechanism: "the line of stroke above the crank
    // centre" read as the ram's line, which the offset does not move.
    for name in [
        FigureName::QuickReturnWhitworth,
        FigureName::QuickReturnSlottedLever,
    ] {
        // The notes' lines read run together, without their breaks.
        let squeeze = |t: &str| t.split_whitespace().collect::<String>();
        let text = squeeze(&crate::common::read_text(&svg(name, 3.31, 0.5, 30.0)));
        let wanted =
            "the slot in d, the engine’s line of stroke, set 0.5 ft off the crank’s centre C";
        assert!(text.contains(&squeeze(wanted)), "{name:?}: {text}");
        assert!(
            !text.contains(&squeeze("the line of stroke above")),
            "{name:?}"
        );
    }
}
