//! Bounded twins of the fuzz targets in `fuzz/` (run there with
//! `cargo fuzz`): the same properties (`tests/common/hostile.rs`) over 256
//! generated inputs each, fast enough for every CI run.

use crate::hostile;

use proptest::prelude::*;

/// Numbers as a careless user or script types them: ordinary, extreme,
/// negative, zero, subnormal, infinite, NaN.
fn number() -> impl Strategy<Value = f64> {
    prop_oneof![
        4 => -1e3..1e3f64,
        1 => prop::num::f64::ANY,
        1 => prop::sample::select(vec![
            0.0, -0.0, 5e-324, 1e-100, 1e-300, 1e100, 1e300, 1e308, -1e308,
            f64::MAX, f64::INFINITY, f64::NEG_INFINITY, f64::NAN,
            1.0000000000000002, 0.9999999999999999,
        ]),
    ]
}

/// A mechanism near its limit of assembly half of the time.
fn mechanism() -> impl Strategy<Value = (f64, f64, f64)> {
    prop_oneof![
        (number(), number(), number()),
        (1e-6..1e6f64, 0.0..1e-6f64, -1.0..1.0f64).prop_map(|(r, eps, e)| (
            r,
            (r + (e * r).abs()) * (1.0 + eps),
            e * r
        )),
    ]
}

fn line() -> impl Strategy<Value = String> {
    prop_oneof![
        "[a-z_ ()]{0,12}(,[a-z_ ()]{0,12}){0,3}",
        (number(), number()).prop_map(|(a, b)| format!("{a},{b}")),
        (number(), number(), number(), number(), number(), number())
            .prop_map(|v| format!("{},{},{},{},{},{}", v.0, v.1, v.2, v.3, v.4, v.5)),
        "[ -~]{0,30}",
    ]
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn numbers_to_analyze_and_figures(
        (crank, rod, offset) in mechanism(),
        degrees in number(),
        omega in number(),
        torque in number(),
        which in any::<u8>(),
    ) {
        hostile::numbers(crank, rod, offset, degrees, omega, torque, which);
    }

    #[test]
    fn csv_data_to_figures(
        which in 0u8..3,
        header in prop::sample::select(vec![
            "angle,force", "force,strain", "angle (deg), force_N",
            "tolerance,segments,time,error,method", "",
        ]),
        lines in prop::collection::vec(line(), 0..12),
    ) {
        let text = format!("{header}\n{}", lines.join("\n"));
        hostile::csv_data(which, &text);
    }

    #[test]
    fn scene_files_to_figures(
        crank in number(), rod in number(), offset in number(),
        angles in prop::collection::vec(number(), 0..4),
        width in number(), height in number(),
        layers in prop::collection::vec(prop::sample::select(vec![
            "mechanism", "dimensions", "centrodes", "coupler", "virtual-centres",
            "velocity", "klein", "kisch", "torque", "scales", "nonsense",
        ]), 0..5),
        junk in "[ -~\n]{0,40}",
    ) {
        let list = |v: Vec<String>| v.join(", ");
        let toml = format!(
            "name = \"t\"\nangles = [{}]\nlayers = [{}]\n[mechanism]\ncrank = {}\nrod = {}\noffset = {}\n[page]\nwidth = {}\nheight = {}\n{junk}",
            list(angles.iter().map(|a| toml_number(*a)).collect()),
            list(layers.iter().map(|l| format!("\"{l}\"")).collect()),
            toml_number(crank), toml_number(rod), toml_number(offset),
            toml_number(width), toml_number(height),
        );
        hostile::scene_toml(&toml);
    }
}

/// One `key = value` line of a scene file for a named figure, or none.
fn key_line(
    key: &'static str,
    value: impl Strategy<Value = String>,
) -> impl Strategy<Value = Option<String>> {
    prop::option::of(value.prop_map(move |v| format!("{key} = {v}\n")))
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, failure_persistence: None, ..ProptestConfig::default() })]

    /// The twin of the `named_scene` fuzz target: every named figure, each
    /// of its keys given or not (a figure refuses keys it does not use).
    #[test]
    fn named_scene_files_to_figures(
        which in 0usize..64,
        top in (
            key_line("angle", number().prop_map(toml_number)),
            key_line("rpm", number().prop_map(toml_number)),
            key_line("omega", number().prop_map(toml_number)),
            key_line("torque", number().prop_map(toml_number)),
            key_line("mirror", prop::sample::select(vec!["true".to_string(), "false".into()])),
            key_line("style", prop::sample::select(vec!["\"textbook\"".to_string(), "\"handout\"".into(), "\"x\"".into()])),
            key_line("title", "\"[ -~]{0,12}\""),
        ),
        mechanism in prop::option::of((number(), number(), number())),
        page in prop::option::of((number(), number())),
        junk in "[ -~\n]{0,30}",
    ) {
        let name = slider_crank::FigureName::ALL[which % slider_crank::FigureName::ALL.len()].name();
        let (a, b, c, d, e, f, g) = top;
        let mut text = format!("{name}\n");
        for line in [a, b, c, d, e, f, g].into_iter().flatten() {
            text.push_str(&line);
        }
        text.push_str(&junk);
        if let Some((r, l, o)) = mechanism {
            text.push_str(&format!(
                "\n[mechanism]\ncrank = {}\nrod = {}\noffset = {}\n",
                toml_number(r), toml_number(l), toml_number(o)
            ));
        }
        if let Some((w, h)) = page {
            text.push_str(&format!("\n[page]\nwidth = {}\nheight = {}\n", toml_number(w), toml_number(h)));
        }
        hostile::named_scene(&text);
    }
}

/// The seeds of the `named_scene` fuzz target, each a hostile input found
/// by hand: the chain at the largest lengths (a panic: `expect("a curved
/// slot")`), an incline tilted 1e300°, an empty list of layers, a page
/// narrower than its margins.
#[test]
fn the_named_scene_seeds_hold() {
    for text in [
        include_str!("../../fuzz/corpus/named_scene/chains-near-the-largest-length.toml"),
        include_str!("../../fuzz/corpus/named_scene/velocity-diagrams.toml"),
        include_str!("../../fuzz/corpus/named_scene/incline-huge-angle.toml"),
        include_str!("../../fuzz/corpus/named_scene/no-layers.toml"),
        include_str!("../../fuzz/corpus/named_scene/coupler-at-the-limit.toml"),
        include_str!("../../fuzz/corpus/named_scene/calibration-narrow-page.toml"),
    ] {
        hostile::named_scene(text);
    }
}

/// Fig. 60 with a rod and crank near the largest length: its slot's
/// radius, 0.8 (l + r + |e|), passes that length; the figure was a panic
/// (`expect("a curved slot")`), it is now refused naming the rod.
#[test]
fn a_chain_figure_beyond_the_largest_slot_is_refused_not_a_panic() {
    let file = slider_crank::SceneFile::from_toml(
        "figure = \"fig-60-chains\"\n[mechanism]\ncrank = 4e99\nrod = 1e100\n",
    )
    .unwrap();
    let e = file.figure().unwrap_err().to_string();
    assert!(
        e.starts_with("rod = 1e100 is out of range: fig-60-chains draws a slot of radius 0.8 (l + r + |e|) = 1.12e100"),
        "{e}"
    );
    // Just below the bound it is drawn.
    let file = slider_crank::SceneFile::from_toml(
        "figure = \"fig-60-chains\"\n[mechanism]\ncrank = 2e99\nrod = 1e100\n",
    )
    .unwrap();
    hostile::assert_svg_numbers_finite(&slider_crank::render::to_svg(&file.figure().unwrap()));
}

/// A float as TOML writes it (`inf`, `nan`, exponent form).
fn toml_number(x: f64) -> String {
    if x.is_nan() {
        "nan".into()
    } else if x.is_infinite() {
        if x > 0.0 { "inf".into() } else { "-inf".into() }
    } else {
        format!("{x:e}")
    }
}

/// Found by the scene fuzz target: a scene named "… -inf …" writes that
/// name; it is text, not a number drawn.
#[test]
fn a_name_that_says_inf_is_text_not_a_number() {
    hostile::scene_toml("name = \"a = -inf = NaN\"\nangles = [13, 121]\n");
    let crash = include_str!("../../fuzz/corpus/scene_toml/name-says-inf.toml");
    hostile::scene_toml(crash);
}

/// Found by the scene fuzz target: a layer name with a newline escape was
/// quoted into a message of two lines.
#[test]
fn a_quoted_newline_keeps_the_refusal_on_one_line() {
    hostile::scene_toml("layers = [\"mech\\nanism\"]\n");
    let crash = include_str!("../../fuzz/corpus/scene_toml/layer-name-with-newline.toml");
    hostile::scene_toml(crash);
}
