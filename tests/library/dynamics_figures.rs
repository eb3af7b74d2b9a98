//! The engine dynamics figures read back from their SVG: the lengths of
//! the drawn arrows and the numbers of the notes against formulas written
//! here, not the library's.

use crate::common;

use common::{attr, metadata, num, read_text};
use slider_crank::catalogue::FigureOptions;
use slider_crank::{Angle, FigureName, SliderCrank, render::to_svg};

/// ω of 250 rpm.
fn omega() -> f64 {
    250.0 * std::f64::consts::TAU / 60.0
}

/// The example engine's reciprocating mass (the figures' default).
const MASS: f64 = 10.0;

/// The figure `name` of the mechanism (r, l, e) at `degrees`.
fn svg(name: FigureName, (r, l, e): (f64, f64, f64), degrees: f64) -> String {
    let mut o = FigureOptions::default();
    o.mechanism = Some(SliderCrank::new(r, l, e).unwrap());
    o.angle = Some(Angle::from_degrees(degrees).unwrap());
    to_svg(&name.figure(&o).unwrap())
}

/// The six numbers of a panel's `data-page-from-world`.
fn panel_map(svg: &str, panel: &str) -> [f64; 6] {
    let text = attr(svg, panel, "data-page-from-world").unwrap();
    let v: Vec<f64> = text.split(' ').map(|s| s.parse().unwrap()).collect();
    [v[0], v[1], v[2], v[3], v[4], v[5]]
}

/// The tail and the tip of the arrow `id` on the page.
fn arrow(svg: &str, id: &str) -> ((f64, f64), (f64, f64)) {
    common::arrow_ends(svg, id)
}

fn length((a, b): ((f64, f64), (f64, f64))) -> f64 {
    (b.0 - a.0).hypot(b.1 - a.1)
}

/// d²x_A/dθ² of the slider, x_A = r cos θ + √(l² − (r sin θ − e)²),
/// differentiated by hand.
fn x2(r: f64, l: f64, e: f64, t: f64) -> f64 {
    let (u, u1, u2) = (r * t.sin() - e, r * t.cos(), -r * t.sin());
    let s = (l * l - u * u).sqrt();
    -r * t.cos() - (u1 * u1 + u * u2) / s - (u * u1).powi(2) / s.powi(3)
}

/// The engines and poses of the checks: the default, near the dead
/// centres and at 90°, the shortest and a long rod, an offset.
const CASES: [((f64, f64, f64), f64); 8] = [
    ((0.5, 3.0, 0.0), 30.0),
    ((0.5, 3.0, 0.0), 2.0),
    ((0.5, 3.0, 0.0), 90.0),
    ((0.5, 3.0, 0.0), 178.0),
    ((1.0, 1.05, 0.0), 60.0),
    ((1.0, 1.05, 0.0), 200.0),
    ((1.0, 50.0, 0.0), 30.0),
    ((1.0, 4.0, 1.0), 120.0),
];

#[test]
fn the_inertia_force_arrow_is_m_a_at_the_drawings_scale() {
    for ((r, l, e), deg) in CASES {
        let svg = svg(FigureName::InertiaForce, (r, l, e), deg);
        let t = deg.to_radians();
        let w2 = omega() * omega();
        // −m a along +x, a = ω² d²x/dθ².
        let force = -MASS * w2 * x2(r, l, e, t);
        let map = panel_map(&svg, "panel-mechanism");
        let scale = map[0].abs();
        let drawn = arrow(&svg, "force-inertia");
        // At the drawing's scale 1 length unit is m ω² force units.
        let want = force.abs() / (MASS * w2) * scale;
        assert!(
            (length(drawn) - want).abs() < 0.05,
            "{r} {l} {e} at {deg}°: drawn {} for {want}",
            length(drawn)
        );
        // Against the acceleration: along +x on the page where −m a is.
        let page_dx = drawn.1.0 - drawn.0.0;
        assert!(page_dx * map[0] * force > 0.0, "{r} {l} {e} at {deg}°");
        // In line, the two-term series is within 1/n² of it (at n = 50).
        if e == 0.0 && l / r > 10.0 {
            let n = l / r;
            let series = MASS * r * w2 * (t.cos() + (2.0 * t).cos() / n);
            assert!((series - force).abs() < MASS * r * w2 / (n * n));
        }
    }
}

#[test]
fn the_triangle_of_forces_closes_along_the_rod_and_the_guides() {
    for ((r, l, e), deg) in CASES {
        let svg = svg(FigureName::InertiaForce, (r, l, e), deg);
        let t = deg.to_radians();
        let sin_phi = (r * t.sin() - e) / l;
        let cos_phi = (1.0 - sin_phi * sin_phi).sqrt();
        let fi = length(arrow(&svg, "force-triangle-inertia"));
        let fq = length(arrow(&svg, "force-triangle-rod"));
        // The rounding of the written file (0.01) over a force ≥ 40 units.
        let tol = 0.05 / fi.min(fq);
        assert!((fq / fi - 1.0 / cos_phi).abs() < tol, "{deg}°");
        // F_N is drawn where it is longer than two arrowheads (ten units
        // each) at the triangle's scale; shorter, the notes say why it is
        // not.
        let tan_phi = (sin_phi / cos_phi).abs();
        if fi * tan_phi >= 20.0 + tol * fi {
            let fn_ = length(arrow(&svg, "force-triangle-guides"));
            assert!((fn_ / fi - tan_phi).abs() < tol, "{deg}°");
        } else if fi * tan_phi < 20.0 - tol * fi {
            assert!(!svg.contains("id=\"force-triangle-guides\""), "{deg}°");
            let text: String = read_text(&svg).split_whitespace().collect();
            assert!(text.contains("istooshorttodraw"), "{deg}°: {text}");
        }
    }
}

/// `x` to four significant figures as the notes write it (a true minus).
fn four(x: f64) -> String {
    let digits = (3 - x.abs().log10().floor() as i32).max(0) as usize;
    format!("{x:.digits$}").replace('-', "−")
}

#[test]
fn the_notes_give_the_crank_effort_f_om_with_units() {
    for ((r, l, e), deg) in CASES {
        let svg = svg(FigureName::InertiaForce, (r, l, e), deg);
        let t = deg.to_radians();
        let force = MASS * omega() * omega() * x2(r, l, e, t); // towards C
        let sin_phi = (r * t.sin() - e) / l;
        let tan_phi = sin_phi / (1.0 - sin_phi * sin_phi).sqrt();
        // OM: the rod produced meets the perpendicular through C.
        let om = r * t.sin() + r * t.cos() * tan_phi;
        // Read without spaces: a wrapped note may break a line anywhere.
        let bare = |s: &str| s.chars().filter(|c| !c.is_whitespace()).collect::<String>();
        let text = bare(&read_text(&svg));
        // T = F_i·CE as magnitudes, with its sense as the page shows it
        // (CE is Ng's OM): a mirrored drawing turns it over.
        let t = force * om;
        // The textbook's figures are drawn mirrored (the cylinder on the
        // left) unless asked otherwise.
        let on_page = -t;
        let sense = if on_page > 0.0 {
            ", counter-clockwise"
        } else if on_page < 0.0 {
            ", clockwise"
        } else {
            ""
        };
        let torque = bare(&format!("T = Fi·CE = {} lbf·ft{sense}", four(t.abs())));
        assert!(text.contains(&torque), "{deg}°: {torque} in {text}");
        let inertia = bare(&format!("= {} lbf (exact", four(force.abs())));
        assert!(text.contains(&inertia), "{deg}°: {inertia} in {text}");
        let meta = metadata(&svg);
        let om_meta = meta["inertia"]["om"].as_f64().unwrap();
        assert!((om_meta - om).abs() < 1e-9 * (r + l), "{deg}°");
    }
}

#[test]
fn the_inertia_force_figure_needs_a_positive_mass() {
    for bad in [0.0, -1.0, f64::NAN] {
        let mut o = FigureOptions::default();
        o.mass = Some(bad);
        let e = FigureName::InertiaForce.figure(&o).unwrap_err().to_string();
        assert!(e.contains("mass") && !e.contains('\n'), "{e}");
    }
    let mut o = FigureOptions::default();
    o.mass = Some(2.0);
    assert!(FigureName::Fig65Klein.figure(&o).is_err());
}

#[test]
fn the_unbalanced_forces_notes_give_the_amplitudes_and_the_remainder() {
    for (r, l, e) in [
        (0.5, 3.0, 0.0),
        (1.0, 1.05, 0.0),
        (1.0, 50.0, 0.0),
        (1.0, 4.0, 1.0),
    ] {
        let mut o = FigureOptions::default();
        o.mechanism = Some(SliderCrank::new(r, l, e).unwrap());
        let svg = to_svg(&FigureName::PrimarySecondary.figure(&o).unwrap());
        let w2 = omega() * omega();
        let (k, n) = (MASS * r * w2, l / r);
        // The largest of exact − (primary + secondary) over 721 angles.
        let worst = (0..=720)
            .map(|i| (i as f64 * 0.5).to_radians())
            .map(|t| -MASS * w2 * x2(r, l, e, t) - k * (t.cos() + (2.0 * t).cos() / n))
            .fold(0.0f64, |a, v| a.max(v.abs()));
        let meta = metadata(&svg);
        let got = meta["unbalanced"]["largest_remainder"].as_f64().unwrap();
        assert!((got - worst).abs() <= 1e-9 * k, "{l}: {got} for {worst}");
        let bare = |s: &str| s.chars().filter(|c| !c.is_whitespace()).collect::<String>();
        let text = bare(&read_text(&svg));
        // The file sets a square as a raised 2.
        for want in [
            format!("mrω2 = {} lbf", four(k)),
            format!("mrω2/n = {} lbf", four(k / n)),
        ] {
            assert!(text.contains(&bare(&want)), "{want} in {text}");
        }
        // In line the remainder is of the order of m r ω² / n³: about
        // half of it at 90° for a long rod.
        if e == 0.0 && n > 10.0 {
            assert!(
                (worst * n.powi(3) / k - 0.5).abs() < 0.01,
                "{}",
                worst * n.powi(3) / k
            );
        }
    }
}

/// The world point of a page point in a panel whose map has no rotation.
fn to_world(map: &[f64; 6], (x, y): (f64, f64)) -> (f64, f64) {
    assert!(map[1] == 0.0 && map[2] == 0.0, "{map:?}");
    ((x - map[4]) / map[0], (y - map[5]) / map[3])
}

/// The world vector of the arrow `id` in `panel`.
fn world_arrow(svg: &str, panel: &str, id: &str) -> (f64, f64) {
    let map = panel_map(svg, panel);
    let (tail, tip) = arrow(svg, id);
    let (a, b) = (to_world(&map, tail), to_world(&map, tip));
    (b.0 - a.0, b.1 - a.1)
}

#[test]
fn the_direct_and_reverse_cranks_project_to_the_primary_and_secondary_forces() {
    use slider_crank::dynamics::{Engine, unbalanced_forces};
    for ((r, l, e), deg) in CASES {
        let svg = svg(FigureName::DirectReverseCranks, (r, l, e), deg);
        let t = deg.to_radians();
        let w2 = omega() * omega();
        let n = l / r;
        // Each crank carries m/2: at r and ω (primary), at r/4n and 2ω
        // (secondary), at ±θ and ±2θ.
        for (name, force, angle, sum) in [
            ("primary", 0.5 * MASS * r * w2, t, MASS * r * w2 * t.cos()),
            (
                "secondary",
                0.5 * MASS * (r / (4.0 * n)) * 4.0 * w2,
                2.0 * t,
                MASS * r * w2 * (2.0 * t).cos() / n,
            ),
        ] {
            let panel = format!("panel-{name}");
            let d = world_arrow(&svg, &panel, &format!("force-{name}-direct"));
            let v = world_arrow(&svg, &panel, &format!("force-{name}-reverse"));
            let tol = 2e-3 * force;
            let at = |x: (f64, f64), a: f64| (x.0 - force * a.cos()).hypot(x.1 - force * a.sin());
            assert!(at(d, angle) < tol, "{name} direct at {deg}°: {d:?}");
            assert!(at(v, -angle) < tol, "{name} reverse at {deg}°: {v:?}");
            // The components on the line of stroke sum to the force; those
            // across it cancel.
            assert!((d.0 + v.0 - sum).abs() < 2.0 * tol, "{name} at {deg}°");
            assert!((d.1 + v.1).abs() < 2.0 * tol, "{name} at {deg}°");
        }
        // The secondary cranks' force is balance.rs's secondary force.
        let m = SliderCrank::new(r, l, e).unwrap();
        let engine = Engine::new(m, MASS, omega()).unwrap();
        let b = unbalanced_forces(&engine, Angle::from_degrees(deg).unwrap());
        let meta = metadata(&svg);
        let secondary = meta["cranks"]["secondary"].as_f64().unwrap();
        assert!((secondary - b.secondary).abs() <= 1e-9 * MASS * r * w2);
        assert!((MASS * r * w2 * (2.0 * t).cos() / n - b.secondary).abs() <= 1e-9 * MASS * r * w2);
    }
}

#[test]
fn on_the_line_of_stroke_primary_and_secondary_sum_to_the_series_beside_the_exact_force() {
    for ((r, l, e), deg) in CASES {
        let svg = svg(FigureName::DirectReverseCranks, (r, l, e), deg);
        let t = deg.to_radians();
        let w2 = omega() * omega();
        let k = MASS * r * w2;
        let n = l / r;
        let want = [
            ("force-sum-primary", k * t.cos()),
            ("force-sum-secondary", k * (2.0 * t).cos() / n),
            ("force-sum-exact", -MASS * w2 * x2(r, l, e, t)),
        ];
        // An arrow under a head and a half (15 units) on the page is
        // left out, its value in the notes.
        let page = panel_map(&svg, "panel-sum")[0].abs();
        for (id, value) in want {
            if value.abs() * page < 14.9 {
                assert!(!svg.contains(&format!("id=\"{id}\"")), "{id} at {deg}°");
                continue;
            }
            if value.abs() < 1e-2 * k {
                continue;
            }
            let (x, y) = world_arrow(&svg, "panel-sum", id);
            assert!(
                (x - value).abs() < 2e-3 * k && y.abs() < 1e-9 * k,
                "{id} at {deg}°: {x} for {value}"
            );
        }
    }
}

/// The on-curve points (world) of the path `id`: the ends of its
/// segments, mapped back through its panel's map.
fn path_points(svg: &str, panel: &str, id: &str) -> Vec<(f64, f64)> {
    let map = panel_map(svg, panel);
    let d = attr(svg, id, "d").unwrap();
    let mut out = Vec::new();
    for part in d.split(['M', 'L', 'C']).filter(|p| !p.trim().is_empty()) {
        let v: Vec<f64> = part
            .split_whitespace()
            .map(|x| x.parse().unwrap())
            .collect();
        // The last pair of each command is the point on the curve.
        if let [.., x, y] = v[..] {
            out.push(to_world(&map, (x, y)));
        }
    }
    out
}

#[test]
fn the_flywheel_holds_the_speed_within_its_coefficient() {
    for (cs, r, l) in [(0.02, 0.5, 3.0), (0.3, 0.5, 3.0), (0.05, 0.5, 1.2)] {
        let mut o = FigureOptions::default();
        o.fluctuation = Some(cs);
        o.mechanism = Some(SliderCrank::in_line(r, l).unwrap());
        let svg = to_svg(&FigureName::Flywheel.figure(&o).unwrap());
        let meta = metadata(&svg);
        let de = meta["flywheel"]["fluctuation"].as_f64().unwrap();
        let inertia = meta["flywheel"]["inertia"].as_f64().unwrap();
        let w = omega();
        // I = ΔE / (ω² C_s).
        assert!((inertia * w * w * cs - de).abs() <= 1e-10 * de, "{cs}");
        // Every drawn speed ω(θ) stores ½ I (ω² − ω_min²) between 0 and
        // ΔE, and the curve reaches both.
        let least = w * (1.0 - 0.5 * cs);
        let stored: Vec<f64> = path_points(&svg, "panel-speed", "curve-speed")
            .iter()
            .map(|&(_, speed)| 0.5 * inertia * (speed * speed - least * least))
            .collect();
        let lo = stored.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = stored.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        assert!(lo > -0.01 * de && lo < 0.02 * de, "{cs}: {lo} of {de}");
        assert!(hi < 1.01 * de && hi > 0.98 * de, "{cs}: {hi} of {de}");
        // The energy curve rises from 0 to ΔE as well.
        let energy = path_points(&svg, "panel-energy-above-least", "curve-energy-above-least");
        let top = energy.iter().map(|p| p.1).fold(f64::NEG_INFINITY, f64::max);
        let bottom = energy.iter().map(|p| p.1).fold(f64::INFINITY, f64::min);
        assert!(
            bottom > -0.01 * de && top < 1.01 * de && top > 0.98 * de,
            "{cs}"
        );
        let bare = |s: &str| s.chars().filter(|c| !c.is_whitespace()).collect::<String>();
        let text = bare(&read_text(&svg));
        let want = bare(&format!(
            "ωmin = {} to ωmax = {} rad/s",
            four(least),
            four(w * (1.0 + 0.5 * cs))
        ));
        assert!(text.contains(&want), "{want} in {text}");
    }
    for bad in [0.0, 2.0, -0.1, f64::NAN] {
        let mut o = FigureOptions::default();
        o.fluctuation = Some(bad);
        assert!(FigureName::Flywheel.figure(&o).is_err(), "{bad}");
    }
}

/// The sum of the world vectors of the arrows `ids` in `panel` (those
/// the figure draws).
fn arrow_sum(svg: &str, panel: &str, ids: &[String]) -> (f64, f64) {
    ids.iter()
        .filter(|id| svg.contains(&format!("id=\"{id}\"")))
        .map(|id| world_arrow(svg, panel, id))
        .fold((0.0, 0.0), |a, v| (a.0 + v.0, a.1 + v.1))
}

#[test]
fn the_balance_polygons_close_or_leave_the_couples_of_three_cranks_at_120_degrees() {
    for l in [3.0, 0.6, 15.0] {
        let r = 0.5;
        let n = l / r;
        let mut o = FigureOptions::default();
        o.mechanism = Some(SliderCrank::in_line(r, l).unwrap());
        let svg = to_svg(&FigureName::InlineBalance.figure(&o).unwrap());
        // Cranks at 0°, 120°, 240°, planes −1, 0, 1: each side
        // a (cos α, sin α), a = 1 for a force, the plane for a couple, at
        // 2α and ÷ n for the secondary.
        let planes = [-1.0, 0.0, 1.0];
        for (name, twice, couple) in [
            ("primary-force", 1.0, false),
            ("primary-couple", 1.0, true),
            ("secondary-force", 2.0, false),
            ("secondary-couple", 2.0, true),
        ] {
            let panel = format!("panel-{name}");
            let scale = if twice > 1.0 { 1.0 / n } else { 1.0 };
            let mut want = (0.0, 0.0);
            let mut ids = Vec::new();
            for (i, a) in planes.iter().enumerate() {
                let t = (twice * 120.0 * i as f64).to_radians();
                let w = scale * if couple { *a } else { 1.0 };
                want = (want.0 + w * t.cos(), want.1 + w * t.sin());
                let id = format!("force-{name}-{}", i + 1);
                if w == 0.0 {
                    assert!(!svg.contains(&format!("id=\"{id}\"")), "{id}");
                    continue;
                }
                let side = world_arrow(&svg, &panel, &id);
                let tol = 2e-3 * scale;
                assert!(
                    (side.0 - w * t.cos()).abs() < tol && (side.1 - w * t.sin()).abs() < tol,
                    "{id}: {side:?}"
                );
                ids.push(id);
            }
            // The sides end where the resultant does: at the origin for
            // the forces (closed, no closing side drawn), at √3 (÷ n) for
            // the couples, the dashed closing side from the origin.
            let end = arrow_sum(&svg, &panel, &ids);
            let closing = format!("resultant-{name}");
            if couple {
                assert!((want.0.hypot(want.1) - 3f64.sqrt() * scale).abs() < 1e-12);
                let drawn = world_arrow(&svg, &panel, &closing);
                for v in [drawn, end] {
                    assert!(
                        (v.0 - want.0).abs() < 4e-3 * scale && (v.1 - want.1).abs() < 4e-3 * scale,
                        "{name} at n = {n}: {v:?} for {want:?}"
                    );
                }
            } else {
                assert!(want.0.hypot(want.1) < 1e-12);
                assert!(end.0.hypot(end.1) < 4e-3 * scale, "{name}: {end:?}");
                assert!(!svg.contains(&format!("id=\"{closing}\"")), "{name}");
            }
        }
        let text = read_text(&svg);
        assert!(
            text.contains(&format!("primary couple {}", four(3f64.sqrt()))),
            "{text}"
        );
    }
}

#[test]
fn the_crank_pin_load_of_a_massless_rod_at_90_degrees_is_the_force_along_the_rod() {
    // A constant gas force G, in line, at θ = 90°: B = (0, r), the rod
    // runs from B to A = (w, 0), w = √(l² − r²); the slider's
    // acceleration is ω² r²/w (d²x/dθ² = −r cos θ − r² cos 2θ/w − … by
    // hand), so the piston effort towards the crank is F = G + m ω² r²/w,
    // and a massless rod, a two-force member, puts F/cos φ along A → B on
    // the crank pin: (−F, F r/w). Relative to the crank (along it, across
    // it) that is (F r/w, F).
    for (r, l, gas, mass) in [
        (0.5, 3.0, 2000.0, 10.0),
        (1.0, 1.3, -500.0, 2.0),
        (0.2, 4.0, 0.0, 7.0),
    ] {
        let mut o = FigureOptions::default();
        o.mechanism = Some(SliderCrank::in_line(r, l).unwrap());
        o.gas_force = Some(gas);
        o.mass = Some(mass);
        let svg = to_svg(&FigureName::CrankPinLoads.figure(&o).unwrap());
        let w = (l * l - r * r).sqrt();
        let f = gas + mass * omega() * omega() * r * r / w;
        let meta = metadata(&svg);
        let largest = meta["crank_pin_loads"]["largest_without_rod"]
            .as_f64()
            .unwrap();
        for (panel, want) in [("fixed", (-f, f * r / w)), ("relative", (f * r / w, f))] {
            // The marks are named by their angle.
            let id = format!("point-{panel}-without-rod-90");
            let map = panel_map(&svg, &format!("panel-{panel}"));
            let got = to_world(&map, (num(&svg, &id, "cx"), num(&svg, &id, "cy")));
            assert!(
                (got.0 - want.0).abs() < 2e-3 * largest && (got.1 - want.1).abs() < 2e-3 * largest,
                "{panel} r {r} l {l}: {got:?} for {want:?}"
            );
        }
        // The rod's own inertia changes the load: a rod of 0.6 m, its
        // centre l/3 from B, k = 0.3 l, written in the notes.
        // Written as every datum of the notes is, without trailing
        // zeros ("6 slug", not "6.000 slug").
        let text = read_text(&svg);
        let rod = four(0.6 * mass);
        let rod = rod.trim_end_matches('0').trim_end_matches('.');
        assert!(text.contains(&format!("The rod: {rod} slug")), "{text}");
    }
}

/// The two ends (world) of the dimension `id` in `panel`: the tips of its
/// two heads, the filled paths of its group.
fn dimension_ends(svg: &str, panel: &str, id: &str) -> ((f64, f64), (f64, f64)) {
    let map = panel_map(svg, panel);
    let at = svg
        .find(&format!("id=\"{id}\""))
        .unwrap_or_else(|| panic!("no {id}"));
    let group = &svg[at..at + svg[at..].find("</g>").unwrap()];
    let tips: Vec<(f64, f64)> = group
        .split("<path d=\"M")
        .skip(1)
        .filter(|p| p.contains("Z\""))
        .map(|p| {
            let mut xy = p.split([' ', 'L']).filter(|s| !s.is_empty());
            let x = xy.next().unwrap().parse().unwrap();
            let y = xy.next().unwrap().parse().unwrap();
            to_world(&map, (x, y))
        })
        .collect();
    assert_eq!(tips.len(), 2, "{id}: {group}");
    (tips[0], tips[1])
}

#[test]
fn the_direct_and_reverse_cranks_panels_each_say_their_scale_by_a_true_bar() {
    for ((r, l, e), deg) in CASES {
        let svg = svg(FigureName::DirectReverseCranks, (r, l, e), deg);
        for (panel, id) in [
            ("panel-primary", "bar-primary"),
            ("panel-secondary", "bar-secondary"),
            ("panel-sum", "bar-sum"),
        ] {
            let (a, b) = dimension_ends(&svg, panel, id);
            let at = svg.find(&format!("id=\"{id}-text\"")).unwrap();
            let start = at + svg[at..].find('>').unwrap() + 1;
            let text = &svg[start..start + svg[start..].find('<').unwrap()];
            let said: f64 = text
                .split_whitespace()
                .next()
                .unwrap()
                .parse()
                .unwrap_or_else(|_| panic!("{id}: {text}"));
            let drawn = (b.0 - a.0).hypot(b.1 - a.1);
            assert!(
                (drawn - said).abs() < 3e-3 * said,
                "{id} at {deg}°: {drawn} drawn, {said} said"
            );
            assert!(text.contains("lbf"), "{text}");
        }
    }
}

#[test]
fn the_turning_moment_letters_every_area_and_draws_delta_e_as_a_dimension() {
    let svg = to_svg(
        &FigureName::TurningMoment
            .figure(&FigureOptions::default())
            .unwrap(),
    );
    let text = read_text(&svg);
    // The notes' areas a_1 … a_k, read back: each lettered on the plot,
    // summing to 0 over the turn (the mean line's definition), and ΔE the
    // greatest less the least of their running sums from 0.
    let notes = &text[text.find("Areas between").unwrap()..];
    let areas: Vec<f64> = notes
        .split(" = ")
        .skip(1)
        .map(|s| {
            let v: String = s
                .chars()
                .take_while(|c| c.is_ascii_digit() || matches!(c, '.' | '+' | '−'))
                .collect();
            v.replace('−', "-").replace('+', "").parse().unwrap()
        })
        .collect();
    assert_eq!(areas.len(), 5, "{notes}");
    for k in 1..=areas.len() {
        assert!(svg.contains(&format!("id=\"label-lobe-{k}\"")), "a_{k}");
    }
    let largest = areas.iter().fold(0.0f64, |a, x| a.max(x.abs()));
    assert!(
        areas.iter().sum::<f64>().abs() < 1e-3 * largest,
        "{areas:?}"
    );
    let (mut run, mut hi, mut lo) = (0.0, 0.0f64, 0.0f64);
    for a in &areas {
        run += a;
        hi = hi.max(run);
        lo = lo.min(run);
    }
    let (a, b) = dimension_ends(&svg, "panel-energy", "dimension-fluctuation");
    assert!(a.0 == b.0, "a vertical dimension: {a:?} {b:?}");
    let drawn = (b.1 - a.1).abs();
    assert!(
        (drawn - (hi - lo)).abs() < 2e-3 * (hi - lo),
        "{drawn} for {}",
        hi - lo
    );
    let delta = metadata(&svg)["fluctuation"].as_f64().unwrap();
    assert!((delta - (hi - lo)).abs() < 1e-3 * delta, "{delta}");
}

/// The world point of the text `id` (where it is written) in `panel`.
fn world_text(svg: &str, panel: &str, id: &str) -> (f64, f64) {
    let map = panel_map(svg, panel);
    let x: f64 = attr(svg, id, "x").unwrap().parse().unwrap();
    let y: f64 = attr(svg, id, "y").unwrap().parse().unwrap();
    to_world(&map, (x, y))
}

/// The distance from `p` to the segment from the origin to `v`.
fn to_arrow(p: (f64, f64), v: (f64, f64)) -> f64 {
    let t = ((p.0 * v.0 + p.1 * v.1) / (v.0 * v.0 + v.1 * v.1)).clamp(0.0, 1.0);
    (p.0 - t * v.0).hypot(p.1 - t * v.1)
}

#[test]
fn past_a_half_turn_each_crank_keeps_its_name_and_its_angle_runs_the_way_it_turns() {
    // θ and 2θ just past 180° or 360°: the direct and reverse cranks lie
    // nearly along one line, the direct one below it.
    for ((r, l, e), deg) in [
        ((1.0, 2.76, -1.03), 90.82),
        ((1.0, 1.08, 0.0), 270.72),
        ((1.0, 1.1, 0.0), 269.26),
        ((1.0, 58.7, 0.0), 270.17),
        ((1.0, 2.0, 0.0), 120.0),
        ((1.0, 2.0, 0.5), 180.0),
    ] {
        let svg = svg(FigureName::DirectReverseCranks, (r, l, e), deg);
        for (name, angle) in [("primary", deg), ("secondary", 2.0 * deg)] {
            let panel = format!("panel-{name}");
            let d = world_arrow(&svg, &panel, &format!("force-{name}-direct"));
            let v = world_arrow(&svg, &panel, &format!("force-{name}-reverse"));
            let text = world_text(&svg, &panel, &format!("value-{name}-direct"));
            // (Two cranks within 5° of the line of stroke lie together:
            // either name stands by both.)
            let half = angle.rem_euclid(180.0);
            let apart = half > 5.0 && half < 175.0;
            assert!(
                !apart || to_arrow(text, d) < to_arrow(text, v),
                "{name} at {deg}°: \"direct\" nearer the reverse crank"
            );
            // The direct crank's angle is swept from the stroke the way
            // the crank turns up to 185°, past that the short way round
            // (named θ − 360°: two arcs of more than half a turn overlap
            // where their letters stand); its letter stands by the middle
            // of that sweep, the reverse's by the middle of the other.
            let turn = angle.rem_euclid(360.0);
            let sweep = if turn > 185.0 { turn - 360.0 } else { turn };
            if sweep.abs() < 5.0 || (turn - 180.0).abs() <= 5.0 {
                continue;
            }
            let text = read_text(&svg);
            let written = if name == "primary" { "θ" } else { "2θ" };
            if turn > 185.0 {
                for w in [format!("{written} − 360°"), format!("360° − {written}")] {
                    assert!(text.contains(&w), "{name} at {deg}°: no {w}");
                }
            }
            for (id, middle) in [("direct", 0.5 * sweep), ("reverse", -0.5 * sweep)] {
                let (x, y) = world_text(&svg, &panel, &format!("label-{name}-{id}"));
                let off = (y.atan2(x).to_degrees() - middle + 540.0).rem_euclid(360.0) - 180.0;
                assert!(
                    off.abs() < 35.0,
                    "{name} {id} at {deg}°: letter {off:.0}° off"
                );
            }
        }
    }
}

#[test]
fn the_sum_on_the_line_of_stroke_is_drawn_to_its_own_scale() {
    // Near 90° at long rods the primary, the secondary and the exact force
    // are a few hundredths of m r ω²: drawn to the cranks' scale they were
    // dots under their heads. The longest of them spans a good part of
    // panel (c) at every pose, its shaft read from the SVG.
    for ((r, l, e), deg) in [
        ((1.0, 58.7, 0.0), 89.33),
        ((1.0, 58.7, 0.0), 270.17),
        ((1.0, 42.6, 0.0), 89.42),
        ((1.0, 3.0, 0.0), 30.0),
        ((1.0, 1.08, 0.0), 0.0),
    ] {
        let svg = svg(FigureName::DirectReverseCranks, (r, l, e), deg);
        let longest = ["primary", "secondary", "exact"]
            .iter()
            .filter(|id| svg.contains(&format!("id=\"force-sum-{id}\"")))
            .map(|id| {
                let (a, b) = arrow(&svg, &format!("force-sum-{id}"));
                (b.0 - a.0).hypot(b.1 - a.1)
            })
            .fold(0.0, f64::max);
        assert!(
            longest > 100.0,
            "l = {l}, {deg}°: the longest arrow {longest:.1} long"
        );
    }
}

/// The page centres of the marks of `panel` ("fixed", "relative") of the
/// crank-pin-load figure, by id.
fn load_marks(svg: &str, panel: &str) -> Vec<(String, (f64, f64))> {
    let key = format!("id=\"point-{panel}-with");
    svg.match_indices(&key)
        .map(|(i, _)| {
            let s = &svg[i + 4..];
            let id = s[..s.find('"').unwrap()].to_string();
            let at = (num(svg, &id, "cx"), num(svg, &id, "cy"));
            (id, at)
        })
        .collect()
}

/// The panels drawn of a crank-pin-load figure: "fixed", "relative" and
/// the details of either, "detail-fixed", "detail-relative", where drawn.
fn drawn_load_panels(svg: &str) -> Vec<&'static str> {
    ["fixed", "relative", "detail-fixed", "detail-relative"]
        .into_iter()
        .filter(|p| svg.contains(&format!("id=\"point-{p}-pole-1\"")))
        .collect()
}

/// The detail of a crank-pin-load panel, or the panel of a detail.
fn counterpart(panel: &str) -> String {
    match panel.strip_prefix("detail-") {
        Some(p) => p.to_string(),
        None => format!("detail-{panel}"),
    }
}

/// The page width of the `case`th of [`reviewed_load_figures`].
fn width_of(case: usize) -> Option<&'static str> {
    LOAD_WIDTHS[case % LOAD_WIDTHS.len()]
}

/// The engines the fourth review drew the crank-pin loads at, with the
/// page widths it found them worst on, and the default.
fn reviewed_load_figures() -> Vec<String> {
    let engines = [
        (0.5, 3.0, 0.0),
        (1.0, 1.06, 0.0),
        (1.0, 51.8, 0.0),
        (1.0, 1.36, -0.313),
        (1.0, 1.08, 0.0),
    ];
    let figures = load_figures(&at_every_width(&engines));
    figures.into_iter().map(|(_, svg)| svg).collect()
}

/// The page widths every reviewed engine of crank-pin-loads is drawn at
/// (`None`: the figure's own).
const LOAD_WIDTHS: [Option<&str>; 4] = [None, Some("120mm"), Some("4.5in"), Some("500")];

/// Each engine (r, l, e) at every one of [`LOAD_WIDTHS`], in that order.
fn at_every_width(engines: &[(f64, f64, f64)]) -> Vec<(f64, f64, f64, Option<&'static str>)> {
    (engines.iter())
        .flat_map(|&(r, l, e)| LOAD_WIDTHS.map(|w| (r, l, e, w)))
        .collect()
}

/// crank-pin-loads drawn for each case (r, l, e and the page width, the
/// figure's own where none), in the cases' order: the case in words and
/// the SVG.
fn load_figures(cases: &[(f64, f64, f64, Option<&'static str>)]) -> Vec<(String, String)> {
    common::in_threads(cases, |&(r, l, e, width)| {
        let mut o = match width {
            Some(w) => common::on_page(w, None),
            None => FigureOptions::default(),
        };
        o.mechanism = Some(SliderCrank::new(r, l, e).unwrap());
        let svg = to_svg(&FigureName::CrankPinLoads.figure(&o).unwrap());
        (format!("r {r} l {l} e {e} on {width:?}"), svg)
    })
}

#[test]
fn the_crank_pin_load_marks_stand_apart_and_each_letter_by_its_own_dot() {
    // Two and a half dots' diameters between centres, less the 0.01 px
    // grid; two lettered quarters a dot's diameter (nearer, they are one
    // place and one dot letters both).
    let apart = 18.0 - 0.02;
    let meet = 4.0 - 0.02;
    for (case, svg) in reviewed_load_figures().into_iter().enumerate() {
        let text = read_text(&svg)
            .split_whitespace()
            .collect::<Vec<_>>()
            .join(" ");
        for panel in drawn_load_panels(&svg) {
            let marks = load_marks(&svg, panel);
            assert!(marks.len() >= 2, "{panel}: {marks:?}");
            let map = panel_map(&svg, &format!("panel-{panel}"));
            let pole = (map[4], map[5]);
            // A quarter is lettered in its panel or, about a crowded
            // pole, in the panel's detail (or, beyond the detail's
            // middle, in the panel).
            let other = counterpart(panel);
            let lettered_at = |point: &str| {
                let label = point.replacen("point-", "label-", 1);
                svg.contains(&format!("id=\"{label}\""))
                    || svg.contains(&format!("id=\"{}\"", label.replacen(panel, &other, 1)))
            };
            for (k, (a, p)) in marks.iter().enumerate() {
                let lettered = lettered_at(a);
                for (b, q) in &marks[k + 1..] {
                    let d = (p.0 - q.0).hypot(p.1 - q.1);
                    let both = lettered && lettered_at(b);
                    let least = if both { meet } else { apart };
                    assert!(d >= least, "{a} and {b} {d:.1} px apart");
                }
                let d = (p.0 - pole.0).hypot(p.1 - pole.1);
                assert!(lettered || d >= apart, "{a} {d:.1} px from the pole");
            }
            // Each curve's quarters lettered (one letter naming the
            // quarters whose marks meet), each letter nearer its own dot
            // than any other.
            for curve in ["with-rod", "without-rod"] {
                for deg in [0, 90, 180, 270] {
                    let id = format!("label-{panel}-{curve}-{deg}");
                    if !svg.contains(&format!("id=\"{id}\"")) {
                        let dot = format!("point-{panel}-{curve}-{deg}");
                        assert!(
                            !svg.contains(&format!("id=\"{dot}\"")) || lettered_at(&dot),
                            "{id}: a quarter's dot without its letter"
                        );
                        continue;
                    }
                    // The letter's box, its width taken as half an em a
                    // character (about the serif digits'), middle-anchored.
                    let (x, y) = (num(&svg, &id, "x"), num(&svg, &id, "y"));
                    let em = num(&svg, &id, "font-size");
                    let at = svg.find(&format!("id=\"{id}\"")).unwrap();
                    let start = at + svg[at..].find('>').unwrap() + 1;
                    let said =
                        read_text(&svg[start..start + svg[start..].find("</text>").unwrap()]);
                    let half = 0.25 * em * said.chars().count() as f64;
                    let to_box = |p: (f64, f64)| {
                        let dx = (x - half - p.0).max(p.0 - x - half).max(0.0);
                        let dy = (y - 0.75 * em - p.1).max(p.1 - y - 1.0).max(0.0);
                        dx.hypot(dy)
                    };
                    let own_id = id.replace("label-", "point-");
                    let own = marks.iter().find(|m| m.0 == own_id).unwrap().1;
                    let angles: Vec<String> = said
                        .split(", ")
                        .map(|a| {
                            a.trim_end_matches(['′', 'ʹ'])
                                .trim_end_matches('°')
                                .to_string()
                        })
                        .collect();
                    assert!(angles.contains(&deg.to_string()), "{id}: {said}");
                    // A letter set farther out has a leader to its dot,
                    // which names it (read in
                    // the_crank_pin_loads_letters_stand_by_their_dots_unpiled_and_off_the_curves
                    // and the_crank_pin_loads_leaders_each_end_on_their_own_dot).
                    let led =
                        svg.contains(&format!("id=\"{}\"", id.replacen("label-", "leader-", 1)));
                    if led {
                        let p = path_numbers(&svg, &id.replacen("label-", "leader-", 1));
                        let end = p[p.len() - 1];
                        let d = (end.0 - own.0).hypot(end.1 - own.1);
                        assert!(d < 2.1 + 0.35, "case {case}: {id}'s leader ends {d:.2} off");
                    }
                    if angles.len() > 1 {
                        // A letter naming several quarters at one place,
                        // by its dot or led to it.
                        assert!(
                            led || to_box(own) < 1.5 * em + 8.0,
                            "case {case}: {id} ({said}) {:.1} from its dot",
                            to_box(own)
                        );
                        continue;
                    }
                    // Another angle's dot, farther than an em from this
                    // one (nearer, the two are one place), stands no
                    // nearer the letter than its own by more than 5 (the
                    // layout's 2, and the width taken here for the glyphs'
                    // own; at r = 1, l = 51.8 on 4.5 in a letter that finds
                    // no place clear stands 4.8 nearer another), 9 in a
                    // crowded panel of a short page: since each curve's
                    // quarters are lettered at their own dots, two letters
                    // find no place clear by their own (the default engine
                    // on 120 mm, fixed axes, the dashed 270°: 8.1 nearer
                    // the full curve's 330° dot; r = 1, l = 51.8 on 500,
                    // relative, the full 270°: 8.3 nearer the dashed 0°,
                    // itself lettered).
                    let slack = if width_of(case) == Some("120mm") || width_of(case) == Some("500")
                    {
                        9.0
                    } else {
                        5.0
                    };
                    for (other, q) in &marks {
                        let far = (q.0 - own.0).hypot(q.1 - own.1) > em;
                        let angle = other.rsplit('-').next().unwrap().to_string();
                        if far && !led && !angles.contains(&angle) {
                            assert!(
                                to_box(*q) + slack >= to_box(own),
                                "{id} stands by {other} in case {case}: {} vs {}",
                                to_box(*q),
                                to_box(own)
                            );
                        }
                    }
                }
            }
            // Every quarter of the dashed curve is lettered, by its own
            // mark or by one its point meets.
            for deg in [0, 90, 180, 270] {
                let own = format!("id=\"label-{panel}-without-rod-{deg}\"");
                let elsewhere = own.replacen(panel, &other, 1);
                let named = [panel, other.as_str()].iter().any(|panel| {
                    svg.match_indices(&format!("id=\"label-{panel}-"))
                        .any(|(i, _)| {
                            let start = i + svg[i..].find('>').unwrap() + 1;
                            let end = start + svg[start..].find("</text>").unwrap();
                            read_text(&svg[start..end]).split(", ").any(|a| {
                                a.trim_end_matches(['′', 'ʹ']) == format!("{deg}°")
                                    && a != format!("{deg}°")
                            }) && svg[i..].starts_with(&format!("id=\"label-{panel}-with"))
                        })
                });
                assert!(
                    svg.contains(&own) || svg.contains(&elsewhere) || named,
                    "{panel}: the dashed curve's {deg}°"
                );
            }
        }
        // The scale bar below every dot, and long enough for its text
        // unless the next round force (at most 2.5 times it) would be
        // longer than the largest load, which no bar is.
        let (a, b) = dimension_ends(&svg, "panel-fixed", "fixed-bar");
        let map = panel_map(&svg, "panel-fixed");
        let bar_y = map[1] * a.0 + map[3] * a.1 + map[5];
        for (id, p) in load_marks(&svg, "fixed") {
            assert!(p.1 + 3.6 < bar_y - 13.0, "{id} on the scale bar");
        }
        let largest = ["largest_with_rod", "largest_without_rod"]
            .map(|k| metadata(&svg)["crank_pin_loads"][k].as_f64().unwrap());
        let bar = (b.0 - a.0).abs();
        assert!(
            bar * map[0].hypot(map[1]) >= 80.0 || 2.5 * bar > largest[0].max(largest[1]),
            "a bar shorter than its text"
        );
        // The rod's mass is said as a share of the reciprocating mass,
        // not "0.6 m", which reads as metres.
        assert!(!text.contains("0.6 m,"), "{text}");
        assert!(text.contains("0.6 times the reciprocating mass"), "{text}");
    }
}

#[test]
fn the_balance_polygons_are_drawn_for_the_cranks_and_planes_given() {
    // The textbooks' four-cylinder flat crank (0°, 180°, 180°, 0°) at a
    // pitch of 1 about the middle of the engine, and a 2-cylinder engine
    // on its own planes: every side a_i (cos δ_i, sin δ_i) (a_i = 1 for a
    // force; at 2δ_i and ÷ n for the secondary), the resultant their sum.
    let n = 6.0;
    for (cranks, planes, given) in [
        (
            vec![0.0, 180.0, 180.0, 0.0],
            vec![-1.5, -0.5, 0.5, 1.5],
            false,
        ),
        (vec![0.0, 90.0], vec![0.0, 2.0], true),
    ] {
        let mut o = FigureOptions::default();
        o.mechanism = Some(SliderCrank::in_line(0.5, 0.5 * n).unwrap());
        o.cranks = Some(cranks.clone());
        o.planes = given.then(|| planes.clone());
        let svg = to_svg(&FigureName::InlineBalance.figure(&o).unwrap());
        for (name, twice, couple) in [
            ("primary-force", 1.0, false),
            ("primary-couple", 1.0, true),
            ("secondary-force", 2.0, false),
            ("secondary-couple", 2.0, true),
        ] {
            let panel = format!("panel-{name}");
            let scale = if twice > 1.0 { 1.0 / n } else { 1.0 };
            let mut want = (0.0, 0.0);
            for (i, (d, a)) in cranks.iter().zip(&planes).enumerate() {
                let t = (twice * d).to_radians();
                let w = scale * if couple { *a } else { 1.0 };
                want = (want.0 + w * t.cos(), want.1 + w * t.sin());
                let id = format!("force-{name}-{}", i + 1);
                if w == 0.0 {
                    assert!(!svg.contains(&format!("id=\"{id}\"")), "{id}");
                    continue;
                }
                let side = world_arrow(&svg, &panel, &id);
                let tol = 2e-3 * scale;
                assert!(
                    (side.0 - w * t.cos()).abs() < tol && (side.1 - w * t.sin()).abs() < tol,
                    "{name} side {}: {side:?}",
                    i + 1
                );
            }
            let closing = format!("resultant-{name}");
            if want.0.hypot(want.1) < 1e-9 {
                assert!(!svg.contains(&format!("id=\"{closing}\"")), "{name}");
            } else {
                let drawn = world_arrow(&svg, &panel, &closing);
                assert!(
                    (drawn.0 - want.0).abs() < 4e-3 * scale
                        && (drawn.1 - want.1).abs() < 4e-3 * scale,
                    "{name}: {drawn:?} for {want:?}"
                );
            }
        }
        let text = read_text(&svg)
            .split_whitespace()
            .collect::<Vec<_>>()
            .join(" ");
        let count = if given {
            "Two cylinders"
        } else {
            "Four cylinders"
        };
        assert!(text.contains(count), "{text}");
        if !given {
            // The flat crank: only the secondary forces unbalanced, 4/n.
            assert!(
                text.contains(&format!("secondary force {}", four(4.0 / n))),
                "{text}"
            );
        }
    }
}

#[test]
fn the_balance_polygons_name_the_crank_angle_apart_from_the_pitch_and_letter_the_resultants() {
    for l in [3.0, 1.08, 52.0] {
        let mut o = FigureOptions::default();
        o.mechanism = Some(SliderCrank::in_line(1.0, l).unwrap());
        let svg = to_svg(&FigureName::InlineBalance.figure(&o).unwrap());
        let text = read_text(&svg);
        // The fifth review: α set in italics reads as the pitch's a
        // ("sides m rω² a_i at a_i"). The crank angle is δ, the pitch a.
        assert!(!text.contains('α'), "{text}");
        assert!(text.contains("at δi") && text.contains("at 2δi"), "{text}");
        assert!(text.contains("angles δi = 0, 120, 240°"), "{text}");
        assert!(text.contains("distances ai = −1, 0, 1 pitches"), "{text}");
        // Each dashed resultant lettered R with its size: the couples'
        // √3 and √3/n (the forces close and have none).
        for (name, want) in [
            ("primary-couple", Some(3f64.sqrt())),
            ("secondary-couple", Some(3f64.sqrt() / l)),
            ("primary-force", None),
            ("secondary-force", None),
        ] {
            let id = format!("value-resultant-{name}");
            match want {
                Some(v) => {
                    let at = svg
                        .find(&format!("id=\"{id}\""))
                        .unwrap_or_else(|| panic!("no {id}"));
                    let start = at + svg[at..].find('>').unwrap() + 1;
                    let said =
                        read_text(&svg[start..start + svg[start..].find("</text>").unwrap()]);
                    assert_eq!(said, format!("R = {}", four(v)), "{name} at n = {l}");
                }
                None => assert!(!svg.contains(&format!("id=\"{id}\"")), "{id}"),
            }
        }
    }
}

#[test]
fn the_balance_polygons_are_drawn_for_the_offset_and_say_by_how_much() {
    // The seventh review: at r = 1, l = 2.7, e = 1.03 "the offset engine
    // is drawn as if it were in line" (4), the offset only in the notes.
    // Each side is drawn the in-line one's times |c_k| (n |c₂| for the
    // secondary), turned by arg c_k, and the notes give both.
    for (r, l, e) in [
        (1.0, 2.59, 1.29),
        (1.0, 2.16, 0.608),
        (1.0, 2.7, 1.03),
        (1.0, 38.9, 0.0),
    ] {
        let mut o = FigureOptions::default();
        o.mechanism = Some(SliderCrank::new(r, l, e).unwrap());
        let svg = to_svg(&FigureName::InlineBalance.figure(&o).unwrap());
        let text = read_text(&svg);
        // The notes' lines joined.
        let text = text.split_whitespace().collect::<Vec<_>>().join(" ");
        // The resultants in units of m r ω², not "R ÷ m r ω²" (the
        // review: "odd").
        assert!(text.contains("Resultants R in units of m rω2"), "{text}");
        assert!(!text.contains('÷'), "{text}");
        let said = text.find("the polygons are drawn for it");
        if e == 0.0 {
            assert!(said.is_none(), "{text}");
            continue;
        }
        said.expect("the offset drawn, said");
        let note = &text[text.find("The offset").unwrap()..];
        // The first and second harmonics of −x_A″/r by a sum of 2000
        // samples of a turn, against the notes' factors (four figures):
        // the primary's |c₁|, the secondary's n |c₂| (its sides are 1/n).
        let harmonic = |k: f64| {
            let (mut re, mut im) = (0.0, 0.0);
            for j in 0..2000 {
                let t = std::f64::consts::TAU * j as f64 / 2000.0;
                let f = -x2(r, l, e, t) / r / 1000.0;
                re += f * (k * t).cos();
                im -= f * (k * t).sin();
            }
            (re.hypot(im), im.atan2(re).to_degrees())
        };
        let numbers = |from: &str| -> Vec<f64> {
            let at = note.find(from).unwrap_or_else(|| panic!("{from}: {note}"));
            note[at + from.len()..]
                .split(|c: char| !(c.is_ascii_digit() || c == '.' || c == '−'))
                .filter(|s| s.chars().any(|c| c.is_ascii_digit()))
                .map(|s| s.trim_end_matches('.').replace('−', "-").parse().unwrap())
                .collect()
        };
        let (c1, p1) = harmonic(1.0);
        let (c2, p2) = harmonic(2.0);
        assert!((numbers("e = ")[0] - e).abs() < 1e-9, "{note}");
        let factors = numbers("the primary sides");
        assert!(factors.len() >= 4, "{note}");
        for (k, (got, want)) in factors.iter().zip([c1, p1, c2 * l / r, p2]).enumerate() {
            assert!(
                (got - want).abs() <= 6e-4 * want.abs().max(1e-3),
                "value {k}: {got} for {want} in {note}"
            );
        }
        // The primary couple of cranks at 120° (√3 in line) times |c₁|.
        let couple = first_number(&text[text.find("primary couple ").unwrap()..]);
        assert!(
            (couple - 3f64.sqrt() * c1).abs() < 6e-4 * couple,
            "{couple} for {}",
            3f64.sqrt() * c1
        );
        // The first cylinder's sides (its crank at 0°, its plane −1):
        // the primary force c₁ (cos 0, sin 0) turned, the secondary
        // c₂ likewise, world units of m r ω² (a couple's times −1).
        for (name, c, p, plane) in [
            ("primary-force", c1, p1, 1.0),
            ("primary-couple", c1, p1, -1.0),
            ("secondary-force", c2, p2, 1.0),
            ("secondary-couple", c2, p2, -1.0),
        ] {
            let side = world_arrow(&svg, &format!("panel-{name}"), &format!("force-{name}-1"));
            let want = (
                plane * c * p.to_radians().cos(),
                plane * c * p.to_radians().sin(),
            );
            assert!(
                (side.0 - want.0).abs() < 3e-3 * c && (side.1 - want.1).abs() < 3e-3 * c,
                "{name} at l {l}, e {e}: {side:?} for {want:?}"
            );
        }
    }
}

/// The page extent (x and y ranges) of the path `id`, from its data.
fn page_extent(svg: &str, id: &str) -> ((f64, f64), (f64, f64)) {
    let d = attr(svg, id, "d").unwrap();
    let v: Vec<f64> = d
        .split(|c: char| c.is_ascii_alphabetic() || c.is_whitespace())
        .filter_map(|x| x.parse().ok())
        .collect();
    let range = |k: usize| {
        (v.iter().skip(k).step_by(2))
            .fold((f64::MAX, f64::MIN), |(lo, hi), x| (lo.min(*x), hi.max(*x)))
    };
    (range(0), range(1))
}

#[test]
fn the_crank_pin_loads_panels_stand_one_above_the_other_on_a_narrow_page() {
    // Side by side on a page of 120 mm or 4.5 in, each panel was under
    // 200 units wide: the curves a few ems across under full-size
    // letters, the force bar three times the largest load (scored 1.5).
    // There (a) stands above (b), each the page's width; on a wide page
    // they stand side by side.
    let mut options = common::on_page("120mm", None);
    options.mechanism = Some(SliderCrank::new(1.0, 39.6, 0.0).unwrap());
    for (width, stacked) in [
        ("120mm", true),
        ("4.5in", true),
        ("500", true),
        ("900", false),
    ] {
        options.width = Some(width.parse().unwrap());
        let svg = to_svg(&FigureName::CrankPinLoads.figure(&options).unwrap());
        let page = num(&svg, "paper", "width");
        let ((ax0, ax1), (_, ay1)) = page_extent(&svg, "curve-fixed-with-rod");
        let ((bx0, _), (by0, _)) = page_extent(&svg, "curve-relative-with-rod");
        assert_eq!(by0 > ay1, stacked, "{width}: (b) below (a)");
        assert_eq!(bx0 > ax1, !stacked, "{width}: (b) right of (a)");
        if stacked {
            assert!(
                ax1 - ax0 > 0.5 * page,
                "{width}: panel (a)'s curve {} of a page {page} wide",
                ax1 - ax0
            );
        }
    }
}

/// The crank-pin-load figures of the sixth review (its engines on its
/// four page widths), and with `low` on two low pages too, where the
/// panels' scale is the height's: (what, SVG).
fn sixth_review_load_figures(low: bool) -> Vec<(String, String)> {
    let mut out = Vec::new();
    let pages: &[(Option<&str>, Option<&str>)] = &[
        (None, None),
        (Some("120mm"), None),
        (Some("4.5in"), None),
        (Some("500"), None),
        (Some("4.5in"), Some("3in")),
        (Some("120mm"), Some("90mm")),
    ];
    let pages = if low { pages } else { &pages[..4] };
    for (r, l, e) in [
        (0.5, 3.0, 0.0),
        (1.0, 3.21, -1.36),
        (1.0, 39.6, 0.0),
        (1.0, 1.05, 0.0),
        (1.0, 51.0, 0.0),
    ] {
        for &(width, height) in pages {
            let mut o = match width {
                Some(w) => common::on_page(w, height),
                None => FigureOptions::default(),
            };
            o.mechanism = Some(SliderCrank::new(r, l, e).unwrap());
            let svg = to_svg(&FigureName::CrankPinLoads.figure(&o).unwrap());
            out.push((format!("r {r} l {l} e {e} on {width:?} x {height:?}"), svg));
        }
    }
    out
}

/// The first number in `text` (digits and one point).
fn first_number(text: &str) -> f64 {
    let start = text.find(|c: char| c.is_ascii_digit()).unwrap();
    let rest = &text[start..];
    let end = rest
        .find(|c: char| !(c.is_ascii_digit() || c == '.'))
        .unwrap_or(rest.len());
    rest[..end].parse().unwrap()
}

#[test]
fn the_crank_pin_loads_scale_bar_is_no_longer_than_the_largest_load() {
    // The sixth review: a 40000 lbf bar under an 11754 lbf load (1.5);
    // on a low page (4.5 in by 3 in) the bar was 20000 lbf for 6637. The
    // bar is chosen from the load: a round force no longer than the
    // largest load the notes give, and drawn at the panel's scale.
    for (case, svg) in sixth_review_load_figures(true) {
        let text = read_text(&svg)
            .split_whitespace()
            .collect::<Vec<_>>()
            .join(" ");
        let said = &text[text.find("Largest load on the crank pin").unwrap()..];
        let with = first_number(said);
        let without = first_number(&said[said.find("with the rod").unwrap()..]);
        let bar_text = text_content(&svg, "fixed-bar-text");
        let bar = first_number(&bar_text);
        assert!(
            bar <= with.max(without),
            "{case}: a bar of {bar_text} for loads of {with} and {without}"
        );
        let (a, b) = dimension_ends(&svg, "panel-fixed", "fixed-bar");
        assert!(
            ((b.0 - a.0).abs() - bar).abs() < 1e-3 * bar,
            "{case}: the bar drawn {} long for {bar}",
            (b.0 - a.0).abs()
        );
    }
}

/// The text of the element `id` as a reader sees it.
fn text_content(svg: &str, id: &str) -> String {
    let at = svg.find(&format!("id=\"{id}\"")).unwrap();
    let start = at + svg[at..].find('>').unwrap() + 1;
    read_text(&svg[start..start + svg[start..].find("</text>").unwrap()])
}

/// The texts of the letters of `panel`'s marks on `curve`, by id.
fn curve_letters(svg: &str, panel: &str, curve: &str) -> Vec<(String, String)> {
    let key = format!("id=\"label-{panel}-{curve}-");
    svg.match_indices(&key)
        .map(|(i, _)| {
            let s = &svg[i + 4..];
            let id = s[..s.find('"').unwrap()].to_string();
            let start = i + svg[i..].find('>').unwrap() + 1;
            let end = start + svg[start..].find("</text>").unwrap();
            // The writer sets a prime as the letter-like ʹ (U+02B9).
            (id, read_text(&svg[start..end]).replace('ʹ', "′"))
        })
        .collect()
}

#[test]
fn the_crank_pin_loads_letters_say_which_curve_they_name() {
    // The sixth review: two "90°" letters in a panel, one for each curve,
    // and no telling which is which. The dashed curve's angles are
    // primed (90°′), so that no two letters of a panel read the same, and
    // each letter's own angle says its curve.
    for (case, svg) in sixth_review_load_figures(false) {
        for panel in ["fixed", "relative"] {
            let mut seen: Vec<String> = Vec::new();
            for (curve, dashed) in [("with-rod", false), ("without-rod", true)] {
                for (id, text) in curve_letters(&svg, panel, curve) {
                    let deg = id.rsplit('-').next().unwrap();
                    let own = if dashed {
                        format!("{deg}°′")
                    } else {
                        format!("{deg}°")
                    };
                    assert!(
                        text.split(", ").any(|a| a == own),
                        "{case}: {id} reads {text}, not {own}"
                    );
                    assert!(!seen.contains(&text), "{case}: two letters {text}");
                    seen.push(text);
                }
            }
        }
    }
}

/// The start and end (page) of each subpath of the path `id`.
fn subpath_ends(svg: &str, id: &str) -> Vec<((f64, f64), (f64, f64))> {
    let d = attr(svg, id, "d").unwrap();
    d.split('M')
        .filter(|s| !s.trim().is_empty())
        .map(|s| {
            let v: Vec<f64> = s
                .split(|c: char| c.is_ascii_alphabetic() || c.is_whitespace())
                .filter_map(|x| x.parse().ok())
                .collect();
            let n = v.len();
            ((v[0], v[1]), (v[n - 2], v[n - 1]))
        })
        .collect()
}

#[test]
fn the_crank_pin_load_curves_end_only_where_a_jump_leads_on() {
    // The sixth review: at the gas force's jumps the curves' ends stopped
    // in mid-air with a hook that read as an arrowhead ("a full curve
    // stops in mid-air with no mark"). Each end of a curve's pieces is
    // the start of the next piece or an end of a dotted jump line of the
    // same curve, which leads to the load on the jump's other side.
    let near = |p: (f64, f64), q: (f64, f64)| (p.0 - q.0).hypot(p.1 - q.1) < 0.05;
    for (case, svg) in sixth_review_load_figures(false) {
        for panel in ["fixed", "relative"] {
            for curve in ["with-rod", "without-rod"] {
                let pieces = subpath_ends(&svg, &format!("curve-{panel}-{curve}"));
                let key = format!("id=\"jump-{panel}-{curve}-");
                let jumps: Vec<(f64, f64)> = svg
                    .match_indices(&key)
                    .flat_map(|(i, _)| {
                        let s = &svg[i + 4..];
                        let id = &s[..s.find('"').unwrap()];
                        assert_eq!(attr(&svg, id, "stroke-dasharray").as_deref(), Some("0 3.5"));
                        let (a, b) = subpath_ends(&svg, id)[0];
                        [a, b]
                    })
                    .collect();
                let ends = pieces.iter().flat_map(|(a, b)| [*a, *b]);
                for (k, p) in ends.enumerate() {
                    let joined = pieces
                        .iter()
                        .flat_map(|(a, b)| [*a, *b])
                        .enumerate()
                        .any(|(j, q)| j != k && near(p, q));
                    assert!(
                        joined || jumps.iter().any(|q| near(p, *q)),
                        "{case}: curve-{panel}-{curve} ends in mid-air at {p:?}"
                    );
                }
            }
        }
    }
}

#[test]
fn the_crank_pin_loads_pole_is_lettered_by_its_cross() {
    // The sixth review: "O" inside a loop or below-right of the ×, well
    // away from it, so that it seemed to name another point. Its letter
    // stands within two ems of the ×'s centre (1.9 at r = 1, l = 1.05,
    // where the pole is inside the dead centres' knot and the nearest
    // clear place is outside it; under 1.1 elsewhere).
    for (case, svg) in sixth_review_load_figures(false) {
        for panel in ["fixed", "relative"] {
            // Lettered in the panel, or in its detail about a crowded pole.
            let detail = format!("detail-{panel}");
            let panel = match svg.contains(&format!("id=\"label-{panel}-pole\"")) {
                true => panel,
                false => detail.as_str(),
            };
            let ((x0, x1), (y0, y1)) = page_extent(&svg, &format!("point-{panel}-pole-1"));
            let pole = (0.5 * (x0 + x1), 0.5 * (y0 + y1));
            let id = format!("label-{panel}-pole");
            let em = num(&svg, &id, "font-size");
            let centre = (num(&svg, &id, "x"), num(&svg, &id, "y") - em / 3.0);
            let d = (centre.0 - pole.0).hypot(centre.1 - pole.1);
            assert!(d <= 2.0 * em, "{case}, {panel}: O {d:.1} from the ×");
        }
    }
}

/// The turning-moment figures of the sixth review: its engines on its
/// four page widths, (what, SVG).
fn sixth_review_turning_figures() -> Vec<(String, String)> {
    let mut out = Vec::new();
    for (l, e) in [(52.3, 0.0), (1.09, 0.0), (3.75, 1.85), (49.4, 0.0)] {
        for width in [None, Some("120mm"), Some("4.5in"), Some("500")] {
            let mut o = match width {
                Some(w) => common::on_page(w, None),
                None => FigureOptions::default(),
            };
            o.mechanism = Some(SliderCrank::new(1.0, l, e).unwrap());
            let svg = to_svg(&FigureName::TurningMoment.figure(&o).unwrap());
            out.push((format!("l {l} e {e} on {width:?}"), svg));
        }
    }
    out
}

/// The pieces of the path `id` (each from a move), each its page points,
/// ends and control points in order.
fn path_pieces(svg: &str, id: &str) -> Vec<Vec<(f64, f64)>> {
    let d = attr(svg, id, "d").unwrap();
    (d.split('M').filter(|p| !p.trim().is_empty()))
        .map(|p| {
            let v: Vec<f64> = (p.split(|c: char| c.is_ascii_alphabetic() || c.is_whitespace()))
                .filter_map(|x| x.parse().ok())
                .collect();
            v.chunks(2).map(|q| (q[0], q[1])).collect()
        })
        .collect()
}

/// The page points of the path `id`, ends and control points in order.
fn path_numbers(svg: &str, id: &str) -> Vec<(f64, f64)> {
    let d = attr(svg, id, "d").unwrap();
    let v: Vec<f64> = d
        .split(|c: char| c.is_ascii_alphabetic() || c.is_whitespace())
        .filter_map(|x| x.parse().ok())
        .collect();
    v.chunks(2).map(|p| (p[0], p[1])).collect()
}

#[test]
fn the_turning_moments_values_stand_clear_of_the_mean_line_and_the_axis() {
    // The sixth review: at 120 mm with an offset "a₄ = −9702" was wedged
    // in the band between the mean line and T = 0, a unit and a half
    // from each. A letter with its value keeps 3 units from both (its
    // ink: 0.7 em above the baseline, a subscript 0.3 em below).
    for (case, svg) in sixth_review_turning_figures() {
        let mean = path_numbers(&svg, "line-mean-torque")[0].1;
        let zero = panel_map(&svg, "panel-turning-moment")[5];
        for k in 1.. {
            let id = format!("label-lobe-{k}");
            if !svg.contains(&format!("id=\"{id}\"")) {
                break;
            }
            let said = text_content(&svg, &id);
            if !said.contains('=') {
                continue;
            }
            let (y, em) = (num(&svg, &id, "y"), num(&svg, &id, "font-size"));
            let (top, bottom) = (y - 0.7 * em, y + 0.3 * em);
            for (line, what) in [(mean, "the mean line"), (zero, "T = 0")] {
                let gap = (top - line).max(line - bottom);
                assert!(gap >= 3.0, "{case}: {said} {gap:.2} from {what}");
            }
        }
    }
}

#[test]
fn the_fluctuations_value_stands_by_its_dimension_with_no_curve_between() {
    // The sixth review: on a narrow page "ΔE = 6254 lbf·ft" stood on the
    // far side of the rising curve from its dimension line ("the curve
    // runs between the label and its arrow"). No part of the energy
    // curve crosses the band of the text's height between the line and
    // the text's middle.
    for (case, svg) in sixth_review_turning_figures() {
        // The dimension line's x: where its first path (an extension
        // line from the least energy) starts.
        let line = {
            let at = svg.find("id=\"dimension-fluctuation\"").unwrap();
            let d = &svg[at..];
            let d = &d[d.find("d=\"M").unwrap() + 4..];
            d[..d.find(' ').unwrap()].parse::<f64>().unwrap()
        };
        let id = "label-fluctuation";
        let (x, y, em) = (
            num(&svg, id, "x"),
            num(&svg, id, "y"),
            num(&svg, id, "font-size"),
        );
        let (top, bottom) = (y - 0.7 * em, y + 0.25 * em);
        let (x0, x1) = (line.min(x), line.max(x));
        let curve = path_numbers(&svg, "curve-energy");
        for w in curve.windows(2) {
            let (p, q) = (w[0], w[1]);
            let across_x = p.0.max(q.0) >= x0 && p.0.min(q.0) <= x1;
            let across_y = p.1.max(q.1) >= top && p.1.min(q.1) <= bottom;
            assert!(
                !(across_x && across_y),
                "{case}: the curve at {p:?}..{q:?} between ΔE's value at ({x}, {y}) and its line at x = {line}"
            );
        }
    }
}

#[test]
fn the_balance_notes_keep_each_list_on_one_line() {
    // The sixth review: at 4.5 in the notes broke "a_i = −1, 0, / 1
    // pitches", and the "1" that began the line read as a stray number.
    // No line of the notes ends in a list's comma with the next line
    // beginning with its next number.
    for l in [1.09, 28.4, 1.04] {
        for width in ["120mm", "4.5in", "500"] {
            let mut o = common::on_page(width, None);
            o.mechanism = Some(SliderCrank::in_line(1.0, l).unwrap());
            let svg = to_svg(&FigureName::InlineBalance.figure(&o).unwrap());
            let lines: Vec<String> = svg
                .match_indices("id=\"note-")
                .map(|(i, _)| {
                    let s = &svg[i + 4..];
                    text_content(&svg, &s[..s.find('"').unwrap()])
                })
                .collect();
            for pair in lines.windows(2) {
                let next = pair[1].trim_start();
                let number = next.starts_with(|c: char| c.is_ascii_digit() || c == '−');
                assert!(
                    !(pair[0].trim_end().ends_with(',') && number),
                    "l {l} on {width}: '{}' / '{}'",
                    pair[0],
                    pair[1]
                );
            }
        }
    }
}

/// The crank-pin-load figures of the seventh review's engines that it
/// found letters by the wrong dot at (the default, r = 1, l = 3.83,
/// e = −1.63), on its four page widths: (what, SVG).
fn seventh_review_load_figures() -> Vec<(String, String)> {
    load_figures(&at_every_width(&[(0.5, 3.0, 0.0), (1.0, 3.83, -1.63)]))
}

/// The distance from the page point `p` to the box of the letter `id`:
/// its width taken as half an em a character (about the serif digits'),
/// middle-anchored, from its baseline up three quarters of an em.
fn to_letter(svg: &str, id: &str, p: (f64, f64)) -> f64 {
    let (x, y) = (num(svg, id, "x"), num(svg, id, "y"));
    let em = num(svg, id, "font-size");
    let half = 0.25 * em * text_content(svg, id).chars().count() as f64;
    box_to((x - half, x + half, y - 0.75 * em, y), p)
}

/// The distance from the page point `p` to the box `(x0, x1, y0, y1)`:
/// 0 inside it.
fn box_to((x0, x1, y0, y1): (f64, f64, f64, f64), p: (f64, f64)) -> f64 {
    let dx = (x0 - p.0).max(p.0 - x1).max(0.0);
    let dy = (y0 - p.1).max(p.1 - y1).max(0.0);
    dx.hypot(dy)
}

#[test]
fn the_crank_pin_loads_letters_stand_nearer_their_own_dot_than_any_other_and_the_pole() {
    // The seventh review: at r = 1, l = 3.83, e = −1.63 "O" stood beside
    // the dashed curve's 270° dot 13 px above the ×, and "270°′" against
    // the ×: the reader took that dot for the pole (2.5); at the default,
    // 0°′, 180°′ and 0° strung along the axis each had its letter between
    // two dots. "O" stands nearer the × than any dot, and at the default
    // each letter nearer its own dot than any other dot or the ×, by a
    // unit (the ink's room); among the loops of the offset engine, where
    // dots stand within an em of each other and of the ×, a letter may
    // stand nearer another by the layout's 2 units and the share of an
    // em the two are closer than it (the two read as a pair, lettered on
    // either side), by no more.
    let mut wrong = Vec::new();
    for (case, svg) in seventh_review_load_figures() {
        for panel in drawn_load_panels(&svg) {
            let ((x0, x1), (y0, y1)) = page_extent(&svg, &format!("point-{panel}-pole-1"));
            let pole = (0.5 * (x0 + x1), 0.5 * (y0 + y1));
            let marks = load_marks(&svg, panel);
            let mut points: Vec<(String, (f64, f64))> = marks.clone();
            points.push((format!("point-{panel}-pole"), pole));
            let key = format!("id=\"label-{panel}-");
            let letters: Vec<String> = svg
                .match_indices(&key)
                .map(|(i, _)| {
                    let s = &svg[i + 4..];
                    s[..s.find('"').unwrap()].to_string()
                })
                .collect();
            // Fewer where a detail letters the pole's region.
            assert!(
                letters.len() >= 5 || svg.contains("id=\"panel-detail-"),
                "{case}: {letters:?}"
            );
            for id in letters {
                // A letter with a leader is named by it (read in
                // the_crank_pin_loads_letters_stand_by_their_dots_unpiled_and_off_the_curves).
                if svg.contains(&format!("id=\"{}\"", id.replacen("label-", "leader-", 1))) {
                    continue;
                }
                let own_id = id.replacen("label-", "point-", 1);
                let own = points.iter().find(|m| m.0 == own_id).unwrap().1;
                let mine = to_letter(&svg, &id, own);
                for (other, q) in &points {
                    if *other == own_id || (q.0 - own.0).hypot(q.1 - own.1) < 4.0 {
                        continue;
                    }
                    let theirs = to_letter(&svg, &id, *q);
                    let em = num(&svg, &id, "font-size");
                    let pair = (em - (q.0 - own.0).hypot(q.1 - own.1)).max(0.0);
                    let slack = if case.starts_with("r 0.5") || id.ends_with("-pole") {
                        1.0
                    } else {
                        2.0 + pair
                    };
                    if theirs < mine - slack {
                        wrong.push(format!(
                            "{case}: {id} ({}) stands {theirs:.1} from {other}, {mine:.1} from its own",
                            text_content(&svg, &id)
                        ));
                    }
                }
            }
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

/// The turning-moment figures of the seventh review's engines (r = 1,
/// l = 1.05, 1.06, 1.07, 1.09) and the default, on its four page widths:
/// (what, SVG).
fn seventh_review_turning_figures() -> Vec<(String, String)> {
    let mut out = Vec::new();
    for (r, l) in [
        (0.5, 3.0),
        (1.0, 1.05),
        (1.0, 1.06),
        (1.0, 1.07),
        (1.0, 1.09),
    ] {
        for width in [None, Some("120mm"), Some("4.5in"), Some("500")] {
            let mut o = match width {
                Some(w) => common::on_page(w, None),
                None => FigureOptions::default(),
            };
            o.mechanism = Some(SliderCrank::new(r, l, 0.0).unwrap());
            let svg = to_svg(&FigureName::TurningMoment.figure(&o).unwrap());
            out.push((format!("r {r} l {l} on {width:?}"), svg));
        }
    }
    out
}

#[test]
fn the_turning_moment_stays_off_its_frame_and_letters_every_area_alike() {
    // The seventh review: at l = 1.07 r the trough at 274° lay on the
    // axis's end at −20000, as if cut off (3.5); "a₂" went without its
    // value beside "a₄ = +9517", and the bare "a₁" stood on the curve's
    // dip at 25°. The torque keeps 3 units inside its axis's ends; every
    // area is lettered alike, by its letter (its value in the notes),
    // and no letter's ink meets the curve.
    for (case, svg) in seventh_review_turning_figures() {
        let axis = path_numbers(&svg, "turning-moment-axis-y");
        let (top, bottom) = axis
            .iter()
            .fold((f64::MAX, f64::MIN), |(a, b), p| (a.min(p.1), b.max(p.1)));
        let curve = path_numbers(&svg, "curve-torque");
        let (high, low) = curve
            .iter()
            .fold((f64::MAX, f64::MIN), |(a, b), p| (a.min(p.1), b.max(p.1)));
        assert!(
            high >= top + 3.0 && low <= bottom - 3.0,
            "{case}: the torque from {high:.1} to {low:.1}, its axis {top:.1} to {bottom:.1}"
        );
        let notes = read_text(&svg);
        for k in 1.. {
            let id = format!("label-lobe-{k}");
            if !svg.contains(&format!("id=\"{id}\"")) {
                assert!(k > 2, "{case}: {k} letters");
                break;
            }
            let said = text_content(&svg, &id);
            assert!(!said.contains('='), "{case}: {id} reads {said}");
            assert!(
                notes.contains(&format!("{said} = ")),
                "{case}: no value of {said} in the notes"
            );
            // The ink of a bare letter: its italic 0.45 em above the
            // baseline, the subscript 0.3 em below, a width of 0.8 em.
            let (x, y, em) = (
                num(&svg, &id, "x"),
                num(&svg, &id, "y"),
                num(&svg, &id, "font-size"),
            );
            let (x0, x1, y0, y1) = (x - 0.4 * em, x + 0.4 * em, y - 0.45 * em, y + 0.3 * em);
            for w in curve.windows(2) {
                // Each piece of the path (ends and control points) as a
                // straight step, checked at ten points along it.
                for i in 0..=10 {
                    let t = i as f64 / 10.0;
                    let p = (
                        w[0].0 + t * (w[1].0 - w[0].0),
                        w[0].1 + t * (w[1].1 - w[0].1),
                    );
                    assert!(
                        !(p.0 > x0 && p.0 < x1 && p.1 > y0 && p.1 < y1),
                        "{case}: {id} ({said}) on the curve at {p:?}"
                    );
                }
            }
        }
    }
}

#[test]
fn the_balance_captions_stand_level_and_close_under_their_polygons() {
    // The seventh review: "large empty gaps between the drawings and
    // their captions, and the captions of (c) and (d) do not line up".
    // At the default, the two captions of a row are one line each at one
    // height, and each stands within two ems and a half (the caption's
    // band) below the lowest point of its polygon.
    let svg = to_svg(
        &FigureName::InlineBalance
            .figure(&FigureOptions::default())
            .unwrap(),
    );
    let caption_y = |name: &str| {
        assert!(
            !svg.contains(&format!("id=\"{name}-caption-2\"")),
            "{name}: a caption of two lines"
        );
        num(&svg, &format!("{name}-caption"), "y")
    };
    for (left, right) in [
        ("primary-force", "primary-couple"),
        ("secondary-force", "secondary-couple"),
    ] {
        let (a, b) = (caption_y(left), caption_y(right));
        assert!((a - b).abs() < 0.01, "{left} at {a}, {right} at {b}");
        for name in [left, right] {
            let em = num(&svg, &format!("{name}-caption"), "font-size");
            let lowest = (1..=3)
                .map(|k| format!("force-{name}-{k}"))
                .chain([format!("resultant-{name}")])
                .filter(|id| svg.contains(&format!("id=\"{id}\"")))
                .map(|id| {
                    let (tail, tip) = arrow(&svg, &id);
                    tail.1.max(tip.1)
                })
                .fold(f64::MIN, f64::max);
            let gap = caption_y(name) - em - lowest;
            assert!(
                gap <= 2.5 * em,
                "{name}: {gap:.1} between the polygon and its caption"
            );
        }
    }
}

/// The crank-pin-load figures of the tenth review's engines (the default,
/// r = 1 with l = 47.6, 48.2, 1.05 and 1.04), on its four page widths:
/// (what, SVG).
fn tenth_review_load_figures() -> Vec<(String, String)> {
    load_figures(&at_every_width(&[
        (0.5, 3.0, 0.0),
        (1.0, 47.6, 0.0),
        (1.0, 48.2, 0.0),
        (1.0, 1.05, 0.0),
        (1.0, 1.04, 0.0),
    ]))
}

/// The ink box of the letter `id`: (left, right, top, bottom), page
/// units, middle-anchored, from its baseline up three quarters of an em;
/// its width half an em a digit (the serif digits' advance), a third of
/// an em a space and three tenths any other character (°, ′, the comma:
/// half an em each took "180°, 180°′" 13 units wider than its ink).
fn letter_box(svg: &str, id: &str) -> (f64, f64, f64, f64) {
    let (x, y) = (num(svg, id, "x"), num(svg, id, "y"));
    let em = num(svg, id, "font-size");
    let wide: f64 = (text_content(svg, id).chars())
        .map(|c| match c {
            '0'..='9' => 0.5,
            ' ' => 0.33,
            _ => 0.3,
        })
        .sum();
    let half = 0.5 * wide * em;
    (x - half, x + half, y - 0.75 * em, y)
}

/// The distance from the page point `p` to [`letter_box`] of `id`.
fn to_box_of(svg: &str, id: &str, p: (f64, f64)) -> f64 {
    box_to(letter_box(svg, id), p)
}

#[test]
fn the_crank_pin_loads_letters_stand_by_their_dots_unpiled_and_off_the_curves() {
    // The tenth review: at r = 1, l = 47.6 on 4.5 in the dashed curve's
    // "270°′" stood on the full curve some 60 px (at twice the size) from
    // its dot beside O (2.5); at l = 1.04 and 1.05 r the letters about the
    // pole piled into a knot no reader could match to its dots (2.5).
    // Every quarter's letter stands within an em of its own dot, nearer
    // it than any other dot farther than 4 units from it (a pair nearer
    // is one place) by the layout's 2 units, or, set farther out, has a
    // leader from its ink to within 5 units of its dot; its ink is clear
    // of every other letter's, and no part of either curve crosses it.
    let mut wrong = Vec::new();
    for (case, svg) in tenth_review_load_figures() {
        for panel in drawn_load_panels(&svg) {
            let marks = load_marks(&svg, panel);
            let key = format!("id=\"label-{panel}-with");
            let letters: Vec<String> = svg
                .match_indices(&key)
                .map(|(i, _)| {
                    let s = &svg[i + 4..];
                    s[..s.find('"').unwrap()].to_string()
                })
                .collect();
            assert!(
                letters.len() >= 4 || panel.starts_with("detail-") || svg.contains("detail-"),
                "{case}: {letters:?}"
            );
            // Each curve drawn (a detail may show one only), each piece
            // of its path (a detail's curves leave and enter its area).
            let curves: Vec<Vec<(f64, f64)>> = ["with-rod", "without-rod"]
                .iter()
                .map(|c| format!("curve-{panel}-{c}"))
                .filter(|id| attr(&svg, id, "d").is_some())
                .flat_map(|id| path_pieces(&svg, &id))
                .collect();
            for (k, id) in letters.iter().enumerate() {
                let said = text_content(&svg, id);
                let own_id = id.replacen("label-", "point-", 1);
                let own = marks.iter().find(|m| m.0 == own_id).unwrap().1;
                let em = num(&svg, id, "font-size");
                let mine = to_box_of(&svg, id, own);
                let leader = id.replacen("label-", "leader-", 1);
                if svg.contains(&format!("id=\"{leader}\"")) {
                    let ends = path_numbers(&svg, &leader);
                    let (start, end) = (ends[0], ends[ends.len() - 1]);
                    let to_dot = (end.0 - own.0).hypot(end.1 - own.1);
                    let to_ink = to_box_of(&svg, id, start);
                    // From the ink's edge (a comma's descent and the box's
                    // room below the baseline: 5).
                    if to_dot > 5.0 || to_ink > 5.0 {
                        wrong.push(format!(
                            "{case}: {id} ({said}) led from {to_ink:.1} off its ink to {to_dot:.1} off its dot"
                        ));
                    }
                } else if mine > em + 0.5 {
                    wrong.push(format!("{case}: {id} ({said}) {mine:.1} from its dot"));
                }
                let led = svg.contains(&format!("id=\"{leader}\""));
                for (other, q) in &marks {
                    if led || *other == own_id || (q.0 - own.0).hypot(q.1 - own.1) < 4.0 {
                        continue;
                    }
                    let theirs = to_box_of(&svg, id, *q);
                    if theirs + 2.0 < mine {
                        wrong.push(format!(
                            "{case}: {id} ({said}) {theirs:.1} from {other}, {mine:.1} from its own"
                        ));
                    }
                }
                let (x0, x1, y0, y1) = letter_box(&svg, id);
                for other in &letters[k + 1..] {
                    let (u0, u1, v0, v1) = letter_box(&svg, other);
                    if x0 < u1 && u0 < x1 && y0 < v1 && v0 < y1 {
                        wrong.push(format!("{case}: {id} ({said}) on {other}"));
                    }
                }
                for curve in &curves {
                    let on = curve.windows(2).any(|w| {
                        (0..=10).any(|i| {
                            let t = i as f64 / 10.0;
                            let p = (
                                w[0].0 + t * (w[1].0 - w[0].0),
                                w[0].1 + t * (w[1].1 - w[0].1),
                            );
                            p.0 > x0 && p.0 < x1 && p.1 > y0 && p.1 < y1
                        })
                    });
                    if on {
                        wrong.push(format!("{case}: {id} ({said}) on a curve"));
                    }
                }
            }
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

#[test]
fn the_fluctuation_stands_on_one_or_two_lines_by_its_dimension() {
    // The tenth review: at r = 1, l = 29.9 on 4.5 in ΔE's value broke
    // over three lines, "ΔE =", "6281", "lbf·ft", the equation split after
    // "=" (3.5). On every page width of the ninth and tenth reviews'
    // engines it is set on one line or two (the value, then its unit),
    // beside its dimension line: its nearer edge within 2 ems of the
    // line, its middle no farther beyond the line's ends (the marks of
    // the greatest and least energy) than its own height.
    for l in [29.9, 54.4, 36.2, 52.3, 2.09, 1.03, 1.06] {
        for width in [None, Some("120mm"), Some("4.5in"), Some("500")] {
            let mut o = match width {
                Some(w) => common::on_page(w, None),
                None => FigureOptions::default(),
            };
            o.mechanism = Some(SliderCrank::in_line(1.0, l).unwrap());
            let svg = to_svg(&FigureName::TurningMoment.figure(&o).unwrap());
            let case = format!("l {l} on {width:?}");
            assert!(
                !svg.contains("id=\"label-fluctuation-value\""),
                "{case}: ΔE on three lines"
            );
            let first: String = text_content(&svg, "label-fluctuation")
                .chars()
                .filter(|c| !c.is_whitespace())
                .collect();
            assert!(first.starts_with("ΔE="), "{case}: {first}");
            let two = svg.contains("id=\"label-fluctuation-unit\"");
            assert!(two || first.ends_with("lbf·ft"), "{case}: {first}");
            let line = {
                let at = svg.find("id=\"dimension-fluctuation\"").unwrap();
                let d = &svg[at..];
                let d = &d[d.find("d=\"M").unwrap() + 4..];
                d[..d.find(' ').unwrap()].parse::<f64>().unwrap()
            };
            let ends = ["point-energy-1", "point-energy-2"].map(|id| num(&svg, id, "cy"));
            let (hi, lo) = (ends[0].min(ends[1]), ends[0].max(ends[1]));
            let ids: &[&str] = if two {
                &["label-fluctuation", "label-fluctuation-unit"]
            } else {
                &["label-fluctuation"]
            };
            let em = num(&svg, ids[0], "font-size");
            let (x0, x1, top, bottom) = ids.iter().fold(
                (f64::MAX, f64::MIN, f64::MAX, f64::MIN),
                |(a, b, c, d), id| {
                    let (u0, u1, v0, v1) = letter_box(&svg, id);
                    (a.min(u0), b.max(u1), c.min(v0), d.max(v1))
                },
            );
            // The box taken a little wide (half an em a character): the
            // line outside its middle three fifths.
            let near = (x0 - line).abs().min((x1 - line).abs());
            let off = (0.5 * (x0 + x1) - line).abs();
            assert!(
                near <= 2.0 * em && off >= 0.3 * (x1 - x0),
                "{case}: ΔE's value from {x0:.1} to {x1:.1}, its line at {line:.1}"
            );
            let middle = 0.5 * (top + bottom);
            let tall = bottom - top;
            assert!(
                middle >= hi - tall && middle <= lo + tall,
                "{case}: ΔE's middle at {middle:.1}, its line from {hi:.1} to {lo:.1}"
            );
        }
    }
}

#[test]
fn an_offset_is_said_signed_with_its_side_in_the_dynamics_notes() {
    // The tenth review: "e = −0.388 ft" had no direction (the other
    // figures say "below"). The notes of the turning-moment and
    // crank-pin-load figures give e signed, and say on which side of the
    // crank centre the line of stroke runs.
    for (e, side) in [(-0.388, "below"), (0.25, "above")] {
        for name in [FigureName::TurningMoment, FigureName::CrankPinLoads] {
            let mut o = FigureOptions::default();
            o.mechanism = Some(SliderCrank::new(1.0, 1.51, e).unwrap());
            let svg = to_svg(&name.figure(&o).unwrap());
            let text = read_text(&svg)
                .split_whitespace()
                .collect::<Vec<_>>()
                .join(" ");
            let said = if e < 0.0 { "−0.388" } else { "0.25" };
            let want = format!("e = {said} ft (the line of stroke {side} the crank centre)");
            assert!(text.contains(&want), "{name:?} at e = {e}: {text}");
        }
    }
}

/// The crank-pin-load figures of the eleventh review's short rods (r = 1,
/// l = 1.06 and 1.1) on its four page widths: (what, SVG).
fn eleventh_review_short_rods() -> Vec<(String, String)> {
    let mut cases = Vec::new();
    for l in [1.06, 1.1] {
        for width in [None, Some("120mm"), Some("4.5in"), Some("500")] {
            cases.push((l, width));
        }
    }
    common::in_threads(&cases, |&(l, width)| {
        let mut o = match width {
            Some(w) => common::on_page(w, None),
            None => FigureOptions::default(),
        };
        o.mechanism = Some(SliderCrank::in_line(1.0, l).unwrap());
        let svg = to_svg(&FigureName::CrankPinLoads.figure(&o).unwrap());
        (format!("l {l} on {width:?}"), svg)
    })
}

/// The ids of the quarters' letters of the panel `panel` of a
/// crank-pin-load figure.
fn quarter_letters(svg: &str, panel: &str) -> Vec<String> {
    let key = format!("id=\"label-{panel}-with");
    svg.match_indices(&key)
        .map(|(i, _)| {
            let s = &svg[i + 4..];
            s[..s.find('"').unwrap()].to_string()
        })
        .collect()
}

/// The gap between two boxes (left, right, top, bottom): 0 where they
/// meet.
fn boxes_apart(a: (f64, f64, f64, f64), b: (f64, f64, f64, f64)) -> f64 {
    let dx = (a.0 - b.1).max(b.0 - a.1).max(0.0);
    let dy = (a.2 - b.3).max(b.2 - a.3).max(0.0);
    dx.hypot(dy)
}

/// Whether the segment `p`–`q` passes through the box `b` (left, right,
/// top, bottom), tried at a hundred points.
fn through(b: (f64, f64, f64, f64), p: (f64, f64), q: (f64, f64)) -> bool {
    (0..=100).any(|i| {
        let t = i as f64 / 100.0;
        box_to(b, (p.0 + t * (q.0 - p.0), p.1 + t * (q.1 - p.1))) == 0.0
    })
}

#[test]
fn the_crank_pin_loads_pole_of_a_short_rod_is_read_in_an_enlarged_detail() {
    // The eleventh review: at r = 1, l = 1.06 on 120 mm, 4.5 in and 500
    // units 0°, 180°, their primes, the × and O piled into a knot a few
    // millimetres wide, a leader across O and the × hidden under dots
    // (2 of 5); at l = 1.1 the same. Each panel whose pole is crowded
    // has an enlarged detail (×2 at least, said in its caption and the
    // metadata); each curve's every quarter is lettered once, in its
    // panel or its detail, and O once; where O stands, no leader crosses
    // it, every quarter's letter keeps an em from it (its estimated box,
    // 0.8 em) and no letter covers the ×.
    let mut wrong = Vec::new();
    for (case, svg) in eleventh_review_short_rods() {
        let details = metadata(&svg)["crank_pin_loads"]["details"]
            .as_array()
            .unwrap()
            .clone();
        assert!(!details.is_empty(), "{case}: no detail");
        for d in &details {
            let panel = d["panel"].as_str().unwrap();
            let times = d["magnification"].as_f64().unwrap();
            assert!(times >= 2.0, "{case}: {panel} ×{times}");
            let caption = ["", "-2", "-3"]
                .iter()
                .map(|k| format!("detail-{panel}-caption{k}"))
                .filter(|id| svg.contains(&format!("id=\"{id}\"")))
                .map(|id| text_content(&svg, &id))
                .collect::<String>();
            assert!(caption.contains('×'), "{case}: {caption}");
        }
        for panel in ["fixed", "relative"] {
            let places = [panel.to_string(), format!("detail-{panel}")];
            let mut said: Vec<String> = Vec::new();
            for p in &places {
                for id in quarter_letters(&svg, p) {
                    let text = text_content(&svg, &id).replace('ʹ', "′");
                    said.extend(text.split(", ").map(String::from));
                }
            }
            said.sort();
            let mut all: Vec<String> = [0, 90, 180, 270]
                .iter()
                .flat_map(|d| [format!("{d}°"), format!("{d}°′")])
                .collect();
            all.sort();
            assert_eq!(said, all, "{case}: {panel}'s quarters");
            let poles: Vec<&String> = (places.iter())
                .filter(|p| svg.contains(&format!("id=\"label-{p}-pole\"")))
                .collect();
            assert_eq!(poles.len(), 1, "{case}: {panel}'s O in {poles:?}");
            let p = poles[0];
            let o = letter_box(&svg, &format!("label-{p}-pole"));
            let em = num(&svg, &format!("label-{p}-pole"), "font-size");
            let ((x0, x1), (y0, y1)) = page_extent(&svg, &format!("point-{p}-pole-1"));
            let cross = (0.5 * (x0 + x1), 0.5 * (y0 + y1));
            for id in quarter_letters(&svg, p) {
                let text = text_content(&svg, &id);
                let gap = boxes_apart(letter_box(&svg, &id), o);
                if gap < 0.8 * em {
                    wrong.push(format!("{case}: {id} ({text}) {gap:.1} from O"));
                }
                if to_box_of(&svg, &id, cross) < 2.0 {
                    wrong.push(format!("{case}: {id} ({text}) over the ×"));
                }
                let leader = id.replacen("label-", "leader-", 1);
                if svg.contains(&format!("id=\"{leader}\"")) {
                    let ends = path_numbers(&svg, &leader);
                    if through(o, ends[0], ends[ends.len() - 1]) {
                        wrong.push(format!("{case}: {leader} across O"));
                    }
                }
            }
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

#[test]
fn the_crank_pin_loads_quarters_letters_stand_an_em_from_o_and_their_leaders_off_the_curves() {
    // The eleventh review: at the default "0°" stood a word space from
    // "O" in both panels and read with it as one label, "0° O"; at
    // r = 1, l = 3.83, e = −1.63 the leaders of 270°′, 180°′ and 0°′
    // crossed the curves. Every quarter's letter keeps an em from O (its
    // estimated box, 0.8 em), and no leader crosses either curve (their
    // paths' points joined, the leader short of its dot by more than the
    // curves' own dot).
    let mut wrong = Vec::new();
    for (r, l, e) in [(0.5, 3.0, 0.0), (1.0, 3.83, -1.63)] {
        let mut o = FigureOptions::default();
        o.mechanism = Some(SliderCrank::new(r, l, e).unwrap());
        let svg = to_svg(&FigureName::CrankPinLoads.figure(&o).unwrap());
        let case = format!("r {r} l {l} e {e}");
        for panel in ["fixed", "relative", "detail-fixed", "detail-relative"] {
            let pole = format!("label-{panel}-pole");
            if !svg.contains(&format!("id=\"{pole}\"")) {
                continue;
            }
            let em = num(&svg, &pole, "font-size");
            // (A detail that one curve does not pass through draws no
            // path of it.)
            let curves: Vec<Vec<(f64, f64)>> = ["with-rod", "without-rod"]
                .iter()
                .map(|c| format!("curve-{panel}-{c}"))
                .filter(|id| svg.contains(&format!("id=\"{id}\"")))
                .map(|id| path_numbers(&svg, &id))
                .collect();
            for id in quarter_letters(&svg, panel) {
                let text = text_content(&svg, &id);
                let gap = boxes_apart(letter_box(&svg, &id), letter_box(&svg, &pole));
                if gap < 0.8 * em {
                    wrong.push(format!("{case}: {id} ({text}) {gap:.1} from O"));
                }
                let leader = id.replacen("label-", "leader-", 1);
                if !svg.contains(&format!("id=\"{leader}\"")) {
                    continue;
                }
                let ends = path_numbers(&svg, &leader);
                let (a, b) = (ends[0], ends[ends.len() - 1]);
                let crossed = curves.iter().flat_map(|c| c.windows(2)).any(|w| {
                    let side = |p: (f64, f64), q: (f64, f64), s: (f64, f64)| {
                        (q.0 - p.0) * (s.1 - p.1) - (q.1 - p.1) * (s.0 - p.0)
                    };
                    side(a, b, w[0]) * side(a, b, w[1]) < 0.0
                        && side(w[0], w[1], a) * side(w[0], w[1], b) < 0.0
                });
                if crossed {
                    wrong.push(format!("{case}: {leader} ({text}) crosses a curve"));
                }
            }
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

/// The crank-pin-load figures of the twelfth review's engines (the
/// default, r = 1 with l = 2.97, e = −1.2; l = 3.18, e = −1.79; l = 3.83,
/// e = −1.63; l = 40), on its four page widths: (what, SVG).
fn twelfth_review_load_figures() -> Vec<(String, String)> {
    load_figures(&at_every_width(&[
        (0.5, 3.0, 0.0),
        (1.0, 2.97, -1.2),
        (1.0, 3.18, -1.79),
        (1.0, 3.83, -1.63),
        (1.0, 40.0, 0.0),
    ]))
}

/// Whether the segments `a`–`b` and `c`–`d` cross.
fn segments_cross(a: (f64, f64), b: (f64, f64), c: (f64, f64), d: (f64, f64)) -> bool {
    let side = |p: (f64, f64), q: (f64, f64), s: (f64, f64)| {
        (q.0 - p.0) * (s.1 - p.1) - (q.1 - p.1) * (s.0 - p.0)
    };
    side(a, b, c) * side(a, b, d) < 0.0 && side(c, d, a) * side(c, d, b) < 0.0
}

#[test]
fn the_crank_pin_loads_letters_read_apart_and_a_pairs_each_beyond_its_own_dot() {
    // The twelfth review: at r = 1, l = 2.97, e = −1.2 on 120 mm, 4.5 in
    // and 500 units "180°" and "0°" touched, read as "180°0°", their
    // leaders crossing in an X; at l = 3.18, e = −1.79 "0°′" and "180°′"
    // named two dots almost on each other and no reader could say which
    // was which (2 of 5). In every panel and detail: two letters on one line (their boxes
    // level) stand at least half an em apart; no two leaders cross, and none
    // runs through another letter; where two lettered dots stand within
    // three quarters of an em (and apart, farther than a dot's diameter),
    // each letter (or
    // its leader's start) lies beyond its own dot, away from the other.
    let mut wrong = Vec::new();
    for (case, svg) in twelfth_review_load_figures() {
        for panel in drawn_load_panels(&svg) {
            let marks = load_marks(&svg, panel);
            let mut letters = quarter_letters(&svg, panel);
            let pole = format!("label-{panel}-pole");
            if svg.contains(&format!("id=\"{pole}\"")) {
                letters.push(pole);
            }
            let leader_of = |id: &str| {
                let leader = id.replacen("label-", "leader-", 1);
                svg.contains(&format!("id=\"{leader}\""))
                    .then(|| path_numbers(&svg, &leader))
                    .map(|p| (p[0], p[p.len() - 1]))
            };
            for (k, id) in letters.iter().enumerate() {
                let em = num(&svg, id, "font-size");
                let b = letter_box(&svg, id);
                let said = text_content(&svg, id);
                for other in &letters[k + 1..] {
                    let o = letter_box(&svg, other);
                    let level = b.2 < o.3 && o.2 < b.3;
                    let gap = (b.0 - o.1).max(o.0 - b.1);
                    if level && gap < 0.5 * em {
                        let theirs = text_content(&svg, other);
                        wrong.push(format!(
                            "{case}: {id} ({said}) {gap:.1} from {other} ({theirs}) on its line"
                        ));
                    }
                }
                if let Some((a, z)) = leader_of(id) {
                    for other in letters.iter().filter(|o| *o != id) {
                        if through(letter_box(&svg, other), a, z) {
                            wrong.push(format!("{case}: {id}'s leader through {other}"));
                        }
                        if let Some((c, d)) = leader_of(other)
                            && segments_cross(a, z, c, d)
                        {
                            wrong.push(format!("{case}: {id}'s leader crosses {other}'s"));
                        }
                    }
                }
                let Some(own) = marks
                    .iter()
                    .find(|m| m.0 == id.replacen("label-", "point-", 1))
                    .map(|m| m.1)
                else {
                    continue;
                };
                let led = leader_of(id);
                for (other, q) in &marks {
                    let apart = (q.0 - own.0).hypot(q.1 - own.1);
                    if apart <= 4.0 || id.replacen("label-", "point-", 1) == *other {
                        continue;
                    }
                    let lettered = letters
                        .iter()
                        .any(|l| l.replacen("label-", "point-", 1) == *other);
                    if lettered && apart < 0.75 * em {
                        // Beyond its own dot, away from the other.
                        let u = ((own.0 - q.0) / apart, (own.1 - q.1) / apart);
                        let beyond = match led {
                            Some((a, _)) => (a.0 - own.0) * u.0 + (a.1 - own.1) * u.1 > 0.0,
                            None => [(b.0, b.2), (b.1, b.2), (b.0, b.3), (b.1, b.3)]
                                .iter()
                                .all(|c| (c.0 - own.0) * u.0 + (c.1 - own.1) * u.1 > -1.0),
                        };
                        if !beyond {
                            wrong.push(format!(
                                "{case}: {id} ({said}) not beyond its dot from {other}, {apart:.1} away"
                            ));
                        }
                    }
                }
            }
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

#[test]
fn the_crank_pin_loads_two_curves_jumps_never_run_on_one_line() {
    // The twelfth review: at long rods (l = 40 r) both curves jump along
    // the x axis at the dead centres, one dotted line after the other
    // through 0°′, 180°′ and 0°, and a reader could not tell which jump
    // joins which dots. Where the full curve's jump and the dashed
    // curve's would lie on one line (each end of the dashed one within 2
    // units of the full one's line), the dashed one is not straight.
    let mut wrong = Vec::new();
    for (case, svg) in twelfth_review_load_figures() {
        for panel in drawn_load_panels(&svg) {
            for deg in [0, 180, 360, 540] {
                let (full, dashed) = (
                    format!("jump-{panel}-with-rod-{deg}"),
                    format!("jump-{panel}-without-rod-{deg}"),
                );
                if attr(&svg, &full, "d").is_none() || attr(&svg, &dashed, "d").is_none() {
                    continue;
                }
                let f = path_numbers(&svg, &full);
                let d = path_numbers(&svg, &dashed);
                let (a, b) = (f[0], f[f.len() - 1]);
                let len = (b.0 - a.0).hypot(b.1 - a.1);
                let off = |p: (f64, f64)| {
                    ((b.0 - a.0) * (p.1 - a.1) - (b.1 - a.1) * (p.0 - a.0)).abs() / len
                };
                let straight = d.len() == 2;
                if len > 0.0 && straight && off(d[0]) < 2.0 && off(d[1]) < 2.0 {
                    wrong.push(format!("{case}: {dashed} on the line of {full}"));
                }
            }
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

/// The crank-pin-load figures of the thirteenth review's engines (the
/// default, and r = 1 with l = 46.2, 31.7, l = 2.32 with e = −0.685 and
/// l = 3.35 with e = 1.72, each on its four page widths): (what, SVG).
fn thirteenth_review_load_figures() -> Vec<(String, String)> {
    let mut cases = vec![(0.5, 3.0, 0.0, None)];
    cases.extend(at_every_width(&[
        (1.0, 46.2, 0.0),
        (1.0, 31.7, 0.0),
        (1.0, 2.32, -0.685),
        (1.0, 3.35, 1.72),
    ]));
    load_figures(&cases)
}

/// The page centre of the pole's × of `panel`.
fn pole_of(svg: &str, panel: &str) -> (f64, f64) {
    let p = path_numbers(svg, &format!("point-{panel}-pole-1"));
    let n = p.len() as f64;
    (
        p.iter().map(|q| q.0).sum::<f64>() / n,
        p.iter().map(|q| q.1).sum::<f64>() / n,
    )
}

#[test]
fn the_crank_pin_loads_letters_name_one_dot_each() {
    // The thirteenth review: "270°" under the 0° dot with "0°" over it at
    // l = 46.2 r, 31.7 r (read as one place); "0°′" about as near the
    // 180° dot as its own at l = 3.35 r, e = 1.72 r on 120 mm, 4.5 in,
    // 500 units; "270°′" between two dots in (a′); the 270°′ leader
    // through the pole's × at l = 2.32 r, e = −0.685 r; "180°′" stacked
    // over "180°", one leader starting between them (2 of 5). In every
    // panel and detail: a letter with no leader stands a quarter of an
    // em nearer its own dot than any other dot farther than 4 units
    // from it (its box as the tests measure it, within a tenth of an
    // em of the font's); a leader passes no other dot within 3 units
    // nor the pole's centre within 5, and starts a quarter of an em
    // from every other letter.
    let mut wrong = Vec::new();
    for (case, svg) in thirteenth_review_load_figures() {
        for panel in drawn_load_panels(&svg) {
            let pole = pole_of(&svg, panel);
            let marks = load_marks(&svg, panel);
            let mut letters = quarter_letters(&svg, panel);
            let o = format!("label-{panel}-pole");
            if svg.contains(&format!("id=\"{o}\"")) {
                letters.push(o);
            }
            for id in &letters {
                let em = num(&svg, id, "font-size");
                let said = text_content(&svg, id);
                let point = id.replacen("label-", "point-", 1);
                let own = match marks.iter().find(|m| m.0 == point) {
                    Some(m) => m.1,
                    None if id.ends_with("-pole") => pole,
                    None => continue,
                };
                let mut others: Vec<(String, (f64, f64))> = (marks.iter())
                    .filter(|m| m.0 != point)
                    .filter(|m| (m.1.0 - own.0).hypot(m.1.1 - own.1) > 4.0)
                    .cloned()
                    .collect();
                if !id.ends_with("-pole") {
                    others.push(("the pole".to_string(), pole));
                }
                let leader = id.replacen("label-", "leader-", 1);
                if !svg.contains(&format!("id=\"{leader}\"")) {
                    let near = to_box_of(&svg, id, own);
                    for (other, q) in &others {
                        let d = to_box_of(&svg, id, *q);
                        if d < near + 0.25 * em {
                            wrong.push(format!(
                                "{case}: {id} ({said}) {near:.1} from its dot, {d:.1} from {other}"
                            ));
                        }
                    }
                    continue;
                }
                let p = path_numbers(&svg, &leader);
                let (a, z) = (p[0], p[p.len() - 1]);
                for (other, q) in &others {
                    let keep = if other == "the pole" { 5.0 } else { 3.0 };
                    let d = crate::common::segment_distance(*q, a, z);
                    if d < keep {
                        wrong.push(format!(
                            "{case}: {id}'s leader ({said}) {d:.1} from {other}"
                        ));
                    }
                }
                for other in letters.iter().filter(|l| *l != id) {
                    let d = to_box_of(&svg, other, a);
                    if d < 0.25 * em {
                        let theirs = text_content(&svg, other);
                        wrong.push(format!(
                            "{case}: {id}'s leader ({said}) starts {d:.1} from {other} ({theirs})"
                        ));
                    }
                }
            }
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

#[test]
fn the_crank_pin_loads_knot_of_lettered_marks_is_read_in_a_detail() {
    // The thirteenth review: at r = 1, l = 2.32 r, e = −0.685 r on
    // 120 mm, 4.5 in and 500 units three leaders in (b) ended on three
    // dots a few points apart (0°′, 180°′, 270°), 30 units from the
    // pole, with no detail (2 of 5). In no whole panel do three lettered
    // marks stand each within 20 units of another of them: such a knot
    // is lettered in a detail.
    let mut wrong = Vec::new();
    for (case, svg) in thirteenth_review_load_figures() {
        for panel in ["fixed", "relative"] {
            let marks = load_marks(&svg, panel);
            let lettered: Vec<(f64, f64)> = (marks.iter())
                .filter(|m| {
                    let label = m.0.replacen("point-", "label-", 1);
                    svg.contains(&format!("id=\"{label}\""))
                })
                .map(|m| m.1)
                .collect();
            let near = |a: (f64, f64), b: (f64, f64)| (a.0 - b.0).hypot(a.1 - b.1) < 20.0;
            // Each mark's group: the marks reached from it by near steps.
            for start in &lettered {
                let mut group = vec![*start];
                let mut k = 0;
                while k < group.len() {
                    let at = group[k];
                    for q in &lettered {
                        if near(at, *q) && !group.contains(q) {
                            group.push(*q);
                        }
                    }
                    k += 1;
                }
                if group.len() >= 3 {
                    wrong.push(format!(
                        "{case}: ({panel}) {} lettered marks knot at {start:?}",
                        group.len()
                    ));
                    break;
                }
            }
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

/// The crank-pin-load figures of the fifteenth review's worst engines:
/// the default, r = 1 with l = 1.05 on 500 units and 120 mm, l = 1.09 on
/// 120 mm, l = 31.3 on the default page and 4.5 in: (what, SVG).
fn fifteenth_review_load_figures() -> Vec<(String, String)> {
    load_figures(&[
        (0.5, 3.0, 0.0, None),
        (1.0, 1.05, 0.0, Some("500")),
        (1.0, 1.05, 0.0, Some("120mm")),
        (1.0, 1.09, 0.0, Some("120mm")),
        (1.0, 31.3, 0.0, None),
        (1.0, 31.3, 0.0, Some("4.5in")),
    ])
}

/// The page centres of every mark of `panel` (both curves'), by id.
fn all_load_marks(svg: &str, panel: &str) -> Vec<(String, (f64, f64))> {
    let key = format!("id=\"point-{panel}-with");
    let mut marks = load_marks(svg, panel);
    let dashed = key.replace("-with", "-without");
    marks.extend(svg.match_indices(&dashed).map(|(i, _)| {
        let s = &svg[i + 4..];
        let id = s[..s.find('"').unwrap()].to_string();
        let at = (num(svg, &id, "cx"), num(svg, &id, "cy"));
        (id, at)
    }));
    marks
}

#[test]
fn the_crank_pin_loads_leaders_each_end_on_their_own_dot() {
    // The fifteenth review: the 270°′ leader of (a) at the default
    // engine ended 3.6 units short of its dot's centre, on the x axis
    // where the dotted jump and a dashed strand run, read as naming no
    // dot (or the unlettered one by it); the 0°′ leader of (b′) at
    // l = 1.05 r on 500 units stopped on the wedge's line. Every leader
    // of a quarter's letter ends on its own dot: within its radius (2.1)
    // and a third of a unit of its centre, and nearer it than any other.
    let mut wrong = Vec::new();
    for (case, svg) in fifteenth_review_load_figures() {
        for panel in drawn_load_panels(&svg) {
            let marks = all_load_marks(&svg, panel);
            for (id, at) in &marks {
                let leader = id.replacen("point-", "leader-", 1);
                if !svg.contains(&format!("id=\"{leader}\"")) {
                    continue;
                }
                let p = path_numbers(&svg, &leader);
                let end = p[p.len() - 1];
                let d = (end.0 - at.0).hypot(end.1 - at.1);
                if d > 2.1 + 0.35 {
                    wrong.push(format!(
                        "{case}: {leader} ends {d:.2} from its dot's centre"
                    ));
                }
                for (other, q) in marks.iter().filter(|m| m.0 != *id) {
                    let e = (end.0 - q.0).hypot(end.1 - q.1);
                    if e < d && (q.0 - at.0).hypot(q.1 - at.1) > 0.5 {
                        wrong.push(format!("{case}: {leader} ends nearer {other}"));
                    }
                }
            }
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

#[test]
fn the_crank_pin_loads_default_fixed_panel_has_its_knot_about_the_pole_enlarged() {
    // The fifteenth review: at the default engine (a)'s pole region was
    // the most tangled of the figure ("O", "270°′" and "0°" 25 and 27
    // units apart on the x axis, their leaders across the dotted jump
    // and a dashed strand) and had no detail. Its knot, the pole's
    // letter among it, is lettered in a detail (a′).
    let svg = to_svg(
        &FigureName::CrankPinLoads
            .figure(&FigureOptions::default())
            .unwrap(),
    );
    let panels = drawn_load_panels(&svg);
    assert!(panels.contains(&"detail-fixed"), "{panels:?}");
    for id in [
        "label-detail-fixed-with-rod-0",
        "label-detail-fixed-without-rod-270",
    ] {
        assert!(svg.contains(&format!("id=\"{id}\"")), "no {id}");
    }
}

#[test]
fn the_crank_pin_loads_fixed_panel_is_fitted_to_its_curves() {
    // The fifteenth review: (a) at the default engine drawn in a world as
    // high as (b)'s, small and flat, 110 units below the page's margin
    // and its bar 114 units under it; at l = 31.3 r the bar far below
    // (a). No band wider than three ems of the letters (51 units) stands
    // above (a)'s ink (its curves and letters, from the page's margin,
    // 16) or between its curves and the top of the bar's text.
    let mut wrong = Vec::new();
    for (case, svg) in fifteenth_review_load_figures() {
        let ys: Vec<f64> = ["with-rod", "without-rod"]
            .iter()
            .flat_map(|c| path_numbers(&svg, &format!("curve-fixed-{c}")))
            .map(|p| p.1)
            .collect();
        // The ink's top: the curves' and the letters'.
        let tops = (svg.match_indices("id=\"label-fixed-")).map(|(i, _)| {
            let s = &svg[i + 4..];
            letter_box(&svg, &s[..s.find('"').unwrap()]).2
        });
        let top = ys.iter().copied().chain(tops).fold(f64::MAX, f64::min);
        let bottom = ys.iter().copied().fold(f64::MIN, f64::max);
        let text = num(&svg, "fixed-bar-text", "y") - num(&svg, "fixed-bar-text", "font-size");
        if top - 16.0 > 51.0 {
            wrong.push(format!(
                "{case}: {:.0} units above (a)'s curves",
                top - 16.0
            ));
        }
        if text - bottom > 51.0 {
            wrong.push(format!(
                "{case}: {:.0} units between (a)'s curves and its bar",
                text - bottom
            ));
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

/// The note lines of a figure, joined by spaces.
fn note_text(svg: &str) -> String {
    let mut lines = vec![text_content(svg, "note-diagram")];
    let mut k = 1;
    while svg.contains(&format!("id=\"note-diagram-{k}\"")) {
        lines.push(text_content(svg, &format!("note-diagram-{k}")));
        k += 1;
    }
    lines
        .join(" ")
        .split_whitespace()
        .collect::<Vec<_>>()
        .join(" ")
}

#[test]
fn the_crank_pin_loads_notes_speak_in_short_plain_sentences() {
    // The fifteenth review: the caption was one long paragraph (its first
    // sentence over 120 words) with odd phrases ("the data's, not the
    // drawing's"), and said nothing of the curve doubling back at the
    // default's 90° in a sliver read as an arrowhead. No sentence of the
    // notes runs past 32 words; the turning point is said.
    let svg = to_svg(
        &FigureName::CrankPinLoads
            .figure(&FigureOptions::default())
            .unwrap(),
    );
    let notes = note_text(&svg);
    for sentence in notes.split(". ") {
        let words = sentence.split_whitespace().count();
        assert!(words <= 32, "{words} words: {sentence}");
    }
    assert!(!notes.contains("the data’s"), "{notes}");
    assert!(
        notes.contains("turning point of the load, not an arrowhead"),
        "{notes}"
    );
}

#[test]
fn the_crank_effort_s_arc_turns_as_the_notes_say_on_the_page() {
    let mut arcs = 0;
    for ((r, l, e), deg) in CASES {
        let svg = svg(FigureName::InertiaForce, (r, l, e), deg);
        let id = ["torque-T", "detail-torque-T"]
            .into_iter()
            .find(|id| svg.contains(&format!("id=\"{id}\"")));
        let Some(id) = id else {
            continue; // no arc where T = 0 (a dead centre)
        };
        arcs += 1;
        // The arc's turn seen on the page: the sum of the cross products
        // of its points about their mean, positive for a clockwise turn
        // on a page whose y runs down.
        let p = common::group_path(&svg, id);
        let n = p.len() as f64;
        let c = (
            p.iter().map(|q| q.0).sum::<f64>() / n,
            p.iter().map(|q| q.1).sum::<f64>() / n,
        );
        let turn: f64 = p
            .windows(2)
            .map(|w| (w[0].0 - c.0) * (w[1].1 - c.1) - (w[0].1 - c.1) * (w[1].0 - c.0))
            .sum();
        let text: String = read_text(&svg).split_whitespace().collect();
        let said_clockwise = text.contains("lbf·ft,clockwise");
        let said_counter = text.contains("lbf·ft,counter-clockwise");
        assert!(
            said_clockwise != said_counter,
            "{deg}°: one sense said in {text}"
        );
        assert_eq!(
            turn > 0.0,
            said_clockwise,
            "{r} {l} {e} at {deg}°: the arc's turn {turn}"
        );
    }
    // Every case has a torque: none is at a dead centre.
    assert_eq!(arcs, CASES.len(), "the arc drawn at {arcs} cases");
}

/// The crank-pin-load figures of the sixteenth review's engines: the
/// default and r = 1 with l = 1.05, 1.07, 1.1, 30 and 52, each on its four
/// page widths: (what, SVG).
fn sixteenth_review_load_figures() -> Vec<(String, String)> {
    load_figures(&at_every_width(&[
        (0.5, 3.0, 0.0),
        (1.0, 1.05, 0.0),
        (1.0, 1.07, 0.0),
        (1.0, 1.1, 0.0),
        (1.0, 30.0, 0.0),
        (1.0, 52.0, 0.0),
    ]))
}

/// The page extent of the path `id`: its least and greatest x and y.
fn path_extent(svg: &str, id: &str) -> (f64, f64, f64, f64) {
    let p = path_numbers(svg, id);
    let (xs, ys) = (p.iter().map(|q| q.0), p.iter().map(|q| q.1));
    (
        xs.clone().fold(f64::INFINITY, f64::min),
        xs.fold(f64::NEG_INFINITY, f64::max),
        ys.clone().fold(f64::INFINITY, f64::min),
        ys.fold(f64::NEG_INFINITY, f64::max),
    )
}

#[test]
fn the_crank_pin_loads_details_frame_their_box_enlarged() {
    // The sixteenth review: at r = 1, l = 1.07 r on 4.5 in each detail's
    // frame was about a tenth lower than its box in the panel times the
    // enlargement its caption gives (its caption on two lines took them
    // off its area). Each detail's frame (drawn half a unit inside the
    // area) is its box's width and height times the ratio of the two
    // maps, to a unit.
    let mut wrong = Vec::new();
    let mut seen = 0;
    for (case, svg) in sixteenth_review_load_figures() {
        for panel in ["fixed", "relative"] {
            let detail = format!("detail-{panel}");
            let boxed = format!("{panel}-detail-box");
            if !svg.contains(&format!("id=\"{boxed}\"")) {
                continue;
            }
            seen += 1;
            let map = |p: &str| panel_map(&svg, &format!("panel-{p}"))[0];
            let m = map(&detail) / map(panel);
            let (a, b) = (
                path_extent(&svg, &boxed),
                path_extent(&svg, &format!("{detail}-border")),
            );
            // The caption's enlargement is the maps' ratio.
            let caption = ["", "-2", "-3"]
                .iter()
                .map(|k| format!("{detail}-caption{k}"))
                .filter(|id| svg.contains(&format!("id=\"{id}\"")))
                .map(|id| text_content(&svg, &id))
                .collect::<Vec<_>>()
                .join(" ");
            let said: f64 = caption[caption.find('×').unwrap() + '×'.len_utf8()..]
                .split_whitespace()
                .next()
                .unwrap()
                .parse()
                .unwrap();
            if (said - m).abs() > 0.01 {
                wrong.push(format!("{case}: {detail} said ×{said}, drawn ×{m:.3}"));
            }
            let (w, h) = ((a.1 - a.0) * m, (a.3 - a.2) * m);
            let (fw, fh) = (b.1 - b.0 + 1.0, b.3 - b.2 + 1.0);
            if (w - fw).abs() > 1.0 || (h - fh).abs() > 1.0 {
                wrong.push(format!(
                    "{case}: {detail} {fw:.1} × {fh:.1}, its box × {m:.2} {w:.1} × {h:.1}"
                ));
            }
        }
    }
    assert!(seen > 10, "only {seen} details");
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

#[test]
fn the_crank_pin_loads_notes_say_the_dashed_curve_lies_flat_only_where_it_does() {
    // The sixteenth review: the notes said the dashed curve of (a) lies
    // almost flat on the x axis at r = 1, l = 1.07 r, where it stands far
    // off it. Said at l = 30 r, where it is drawn flat; not at l = 1.07 r
    // nor at the default (l = 6 r, its dashed curve a wedge).
    let flat = "lies almost flat on the";
    for ((r, l), said) in [
        ((1.0, 30.0), true),
        ((1.0, 1.07), false),
        ((0.5, 3.0), false),
    ] {
        let (_, svg) = load_figures(&[(r, l, 0.0, None)]).remove(0);
        let notes = note_text(&svg);
        assert_eq!(notes.contains(flat), said, "r {r} l {l}: {notes}");
        assert!(notes.contains("turn a small corner at each row"), "{notes}");
    }
}

/// The strokes of the path `id` on the page, each a polyline: its cubic
/// pieces flattened at eight points each.
fn flattened(svg: &str, id: &str) -> Vec<Vec<(f64, f64)>> {
    match attr(svg, id, "d") {
        Some(d) => flatten_d(&d),
        None => Vec::new(),
    }
}

/// The strokes of the path data `d`, as [`flattened`].
fn flatten_d(d: &str) -> Vec<Vec<(f64, f64)>> {
    let mut strokes: Vec<Vec<(f64, f64)>> = Vec::new();
    let tokens = d.split_whitespace();
    let mut cmd = 'M';
    let mut nums: Vec<f64> = Vec::new();
    let flush = |cmd: char, nums: &mut Vec<f64>, strokes: &mut Vec<Vec<(f64, f64)>>| {
        let p: Vec<(f64, f64)> = nums.chunks(2).map(|q| (q[0], q[1])).collect();
        match cmd {
            'M' => strokes.push(p),
            'C' => {
                for c in p.chunks(3).filter(|c| c.len() == 3) {
                    let from = *strokes.last().and_then(|s| s.last()).unwrap();
                    let s = strokes.last_mut().unwrap();
                    for k in 1..=8 {
                        let t = f64::from(k) / 8.0;
                        let u = 1.0 - t;
                        let b = |a: f64, b1: f64, b2: f64, e: f64| {
                            u * u * u * a
                                + 3.0 * u * u * t * b1
                                + 3.0 * u * t * t * b2
                                + t * t * t * e
                        };
                        s.push((
                            b(from.0, c[0].0, c[1].0, c[2].0),
                            b(from.1, c[0].1, c[1].1, c[2].1),
                        ));
                    }
                }
            }
            _ => {
                if let Some(s) = strokes.last_mut() {
                    s.extend(p);
                }
            }
        }
        nums.clear();
    };
    for t in tokens {
        let (head, rest) = t.split_at(
            t.find(|c: char| !c.is_ascii_alphabetic())
                .unwrap_or(t.len()),
        );
        if let Some(c) = head.chars().next() {
            flush(cmd, &mut nums, &mut strokes);
            cmd = c;
        }
        if let Ok(v) = rest.parse() {
            nums.push(v);
        }
    }
    flush(cmd, &mut nums, &mut strokes);
    strokes
}

#[test]
fn the_crank_pin_loads_letters_see_their_dots_across_no_curve() {
    // The sixteenth review: at r = 1, l = 1.07 and 1.1 r on 120 mm and
    // 4.5 in, the 0° of (b′) stood over the wedge's two strands, its dot
    // under them, with no leader: read as naming neither. A letter set
    // by its dot with no leader sees it across no line of either curve:
    // the way from a little off its dot (four units, past the dot and
    // its own curve there) to its box's nearest point crosses none.
    let mut wrong = Vec::new();
    for (case, svg) in sixteenth_review_load_figures() {
        for panel in drawn_load_panels(&svg) {
            let strokes: Vec<Vec<(f64, f64)>> = ["with-rod", "without-rod"]
                .iter()
                .flat_map(|c| flattened(&svg, &format!("curve-{panel}-{c}")))
                .collect();
            for (id, at) in all_load_marks(&svg, panel) {
                let label = id.replacen("point-", "label-", 1);
                let leader = id.replacen("point-", "leader-", 1);
                if !svg.contains(&format!("id=\"{label}\""))
                    || svg.contains(&format!("id=\"{leader}\""))
                {
                    continue;
                }
                let (x0, x1, y0, y1) = letter_box(&svg, &label);
                // The box a unit smaller all round, for the estimate of
                // its glyphs.
                let near = (
                    at.0.clamp(x0 + 1.0, x1 - 1.0),
                    at.1.clamp(y0 + 1.0, y1 - 1.0),
                );
                let d = (near.0 - at.0).hypot(near.1 - at.1);
                if d <= 4.0 {
                    continue;
                }
                let from = (
                    at.0 + (near.0 - at.0) * 4.0 / d,
                    at.1 + (near.1 - at.1) * 4.0 / d,
                );
                let crossed = (strokes.iter())
                    .flat_map(|s| s.windows(2))
                    .any(|w| segments_cross(from, near, w[0], w[1]));
                if crossed {
                    wrong.push(format!("{case}: {label} across a curve from its dot"));
                }
            }
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

#[test]
fn the_crank_pin_loads_letters_stand_with_their_middles_nearest_their_own_dots() {
    // The sixteenth review: at r = 1, l = 30 and 52 r the dashed curve's
    // "90°′" in (a) stood under two of its dots, its box by both, read as
    // naming either. A letter set by its dot with no leader has its
    // middle nearer its own dot than any other dot of its panel.
    let mut wrong = Vec::new();
    for (case, svg) in sixteenth_review_load_figures() {
        for panel in drawn_load_panels(&svg) {
            let marks = all_load_marks(&svg, panel);
            for (id, at) in &marks {
                let label = id.replacen("point-", "label-", 1);
                let leader = id.replacen("point-", "leader-", 1);
                if !svg.contains(&format!("id=\"{label}\""))
                    || svg.contains(&format!("id=\"{leader}\""))
                {
                    continue;
                }
                let (x0, x1, y0, y1) = letter_box(&svg, &label);
                let c = (0.5 * (x0 + x1), 0.5 * (y0 + y1));
                let own = (c.0 - at.0).hypot(c.1 - at.1);
                for (other, q) in &marks {
                    let apart = (q.0 - at.0).hypot(q.1 - at.1);
                    if apart > 4.0 && (c.0 - q.0).hypot(c.1 - q.1) < own {
                        wrong.push(format!("{case}: {label} nearer {other}"));
                    }
                }
            }
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

/// The inertia-force figures of the reviewed engines (r, l, e, θ in
/// degrees) on their page widths (`None` the default): (what, SVG).
fn inertia_figures(cases: &[(f64, f64, f64, f64, Option<&'static str>)]) -> Vec<(String, String)> {
    common::in_threads(cases, |&(r, l, e, deg, width)| {
        let mut o = match width {
            Some(w) => common::on_page(w, None),
            None => FigureOptions::default(),
        };
        o.mechanism = Some(SliderCrank::new(r, l, e).unwrap());
        o.angle = Some(Angle::from_degrees(deg).unwrap());
        let svg = to_svg(&FigureName::InertiaForce.figure(&o).unwrap());
        (format!("r {r} l {l} e {e} at {deg}° on {width:?}"), svg)
    })
}

/// The short rods of the nineteenth review at and about l = 1.03 r near
/// 270° and at the dead centres, an offset engine and the default, each
/// on the default page and on the narrower widths.
fn nineteenth_review_inertia_figures() -> Vec<(String, String)> {
    let engines = [
        (1.0, 1.03, 0.0, 270.17),
        (1.0, 1.02, 0.0, 270.17),
        (1.0, 1.04, 0.0, 270.17),
        (1.0, 1.1, 0.0, 270.17),
        (1.0, 1.03, 0.0, 269.17),
        (1.0, 1.03, 0.0, 271.17),
        (1.0, 1.03, 0.0, 0.0),
        (1.0, 1.03, 0.0, 1.0),
        (1.0, 1.03, 0.0, 180.0),
        (1.0, 2.24, 0.91, 90.63),
        (1.0, 2.24, -0.91, 90.63),
        (0.5, 3.0, 0.0, 30.0),
    ];
    inertia_at_widths(&engines, &[None, Some("500"), Some("4.5in")])
}

/// The inertia-force figures of `engines` (r, l, e, θ in degrees) on
/// each of `widths` (`None` the default): (what, SVG).
fn inertia_at_widths(
    engines: &[(f64, f64, f64, f64)],
    widths: &[Option<&'static str>],
) -> Vec<(String, String)> {
    let cases: Vec<_> = engines
        .iter()
        .flat_map(|&(r, l, e, deg)| widths.iter().map(move |&w| (r, l, e, deg, w)))
        .collect();
    inertia_figures(&cases)
}

/// The short rods of the twentieth review about l = 1.09 r at the dead
/// centres and at and about 90° and 270°, where CG and the inertia force
/// are longest, on every page width.
fn twentieth_review_inertia_figures() -> Vec<(String, String)> {
    let mut engines = Vec::new();
    for l in [1.02, 1.04, 1.09, 1.1] {
        for deg in [0.0, 1.0, 89.0, 90.0, 91.0, 180.0, 270.0, 359.0] {
            engines.push((1.0, l, 0.0, deg));
        }
    }
    engines.extend([
        (1.0, 2.5, 0.9, 90.0),
        (1.0, 2.5, -0.9, 270.0),
        (0.5, 3.0, 0.0, 30.0),
    ]);
    inertia_at_widths(&engines, &[None, Some("500"), Some("120mm"), Some("4.5in")])
}

/// The page segments of every path inside the element `id` (a group or
/// a path): its strokes flattened, as pairs of points.
fn segments_of(svg: &str, id: &str) -> Vec<((f64, f64), (f64, f64))> {
    let Some(at) = svg.find(&format!("id=\"{id}\"")) else {
        return Vec::new();
    };
    let start = svg[..at].rfind('<').unwrap();
    let tag = &svg[start + 1..];
    let name: String = tag
        .chars()
        .take_while(|c| c.is_ascii_alphanumeric())
        .collect();
    let body = if name == "g" {
        &svg[start..start + svg[start..].find("</g>").unwrap()]
    } else {
        &svg[start..start + svg[start..].find('>').unwrap()]
    };
    body.split(" d=\"")
        .skip(1)
        .filter_map(|s| s.split('"').next())
        .flat_map(flatten_d)
        .flat_map(|stroke| stroke.windows(2).map(|w| (w[0], w[1])).collect::<Vec<_>>())
        .collect()
}

/// The distance between the page segments `a b` and `c d` (0 where they
/// cross).
fn segment_gap(a: (f64, f64), b: (f64, f64), c: (f64, f64), d: (f64, f64)) -> f64 {
    if segments_cross(a, b, c, d) {
        return 0.0;
    }
    let to = common::segment_distance;
    [to(a, c, d), to(b, c, d), to(c, a, b), to(d, a, b)]
        .into_iter()
        .fold(f64::INFINITY, f64::min)
}

/// The ids of the elements of `svg` whose ids begin with `prefix`.
fn ids_starting(svg: &str, prefix: &str) -> Vec<String> {
    svg.split(&format!("id=\"{prefix}"))
        .skip(1)
        .map(|s| format!("{prefix}{}", s.split('"').next().unwrap()))
        .collect()
}

#[test]
fn the_crank_effort_s_arc_stands_clear_of_the_block_and_the_guides_hatching() {
    // The nineteenth review: at r = 1, l = 1.03 r, 270.17° the arc T about
    // C, 15 units from the block, ran over the block's corner and through
    // the lower guide's hatching, read as a mark of theirs. The arc (its
    // stroke and the block's or a hatch stroke's halves, and two units
    // between) stands clear of the block's outline, the guides and every
    // hatch stroke of its panel.
    let mut arcs = 0;
    for (what, svg) in nineteenth_review_inertia_figures() {
        for prefix in ["", "detail-"] {
            let arc = format!("{prefix}torque-T");
            let path = segments_of(&svg, &arc);
            if path.is_empty() {
                continue;
            }
            arcs += 1;
            let mut things = vec![format!("{prefix}block-slider")];
            things.extend(ids_starting(&svg, &format!("{prefix}guide-")));
            things.extend(ids_starting(&svg, &format!("{prefix}hatch-guide-")));
            for id in things {
                let least = segments_of(&svg, &id)
                    .iter()
                    .flat_map(|&(c, d)| path.iter().map(move |&(a, b)| segment_gap(a, b, c, d)))
                    .fold(f64::INFINITY, f64::min);
                let room = 0.5 * 1.4 + 0.5 * 1.6 + 2.0;
                assert!(
                    least >= room,
                    "{what}: {arc} {least:.2} from {id}, under {room}"
                );
            }
        }
    }
    assert!(arcs >= 20, "the arc drawn at only {arcs} figures");
}

#[test]
fn the_inertia_force_letters_stand_an_em_from_every_other_letter() {
    // The nineteenth review: at r = 1, l = 1.03 r, 270.17° the crank
    // effort's T stood beside the detail's "×2" above C and read "T ×2"; F_i
    // stood beside G ("F_i G") and at the dead centre beside C ("C F_i");
    // the flat triangle of forces set "F_Q F_i" side by side on its one
    // arrow. A letter of a force or torque stands an em (its own size)
    // from every other letter of its panel.
    for (what, svg) in nineteenth_review_inertia_figures() {
        let ids: Vec<String> = svg
            .split("<text ")
            .skip(1)
            .filter_map(|t| t.split("id=\"").nth(1))
            .map(|t| t.split('"').next().unwrap().to_string())
            .filter(|id| !id.starts_with("note") && !id.contains("caption"))
            .collect();
        let ours = ids.iter().filter(|id| {
            ["value-T", "detail-value-T", "value-inertia"].contains(&id.as_str())
                || id.starts_with("value-triangle")
        });
        for id in ours {
            let em = num(&svg, id, "font-size");
            let mine = letter_box(&svg, id);
            for other in ids.iter().filter(|o| *o != id) {
                // Letters of one panel: the detail's own beside its own.
                if id.starts_with("detail-") != other.starts_with("detail-")
                    || id.starts_with("value-triangle") != other.starts_with("value-triangle")
                {
                    continue;
                }
                let gap = boxes_apart(mine, letter_box(&svg, other));
                assert!(
                    gap >= em,
                    "{what}: {id} {gap:.1} from {other} ({}), under an em {em}",
                    text_content(&svg, other)
                );
            }
        }
    }
}

#[test]
fn the_inertia_force_arrow_stands_off_cg_where_no_guide_runs_beside_it() {
    // The nineteenth review: at r = 1, l = 1.03 r, 270.17° the arrow F_i,
    // as long as CG and a quarter of the block's height off the line of
    // stroke, ran tight beside the thick CG from the block to G and read
    // as that line. Where no guide runs beside it, the arrow stands at
    // least a third of the block's height off CG over their common run.
    let mut runs = 0;
    for (what, svg) in nineteenth_review_inertia_figures() {
        // Drawn in the detail at the cross-head (too short on the main
        // view), it runs beside no CG of the main view.
        if !svg.contains("id=\"force-inertia\"") {
            continue;
        }
        let shaft = common::group_path(&svg, "force-inertia");
        let Some(cg) = attr(&svg, "line-CG", "d") else {
            continue;
        };
        let cg = flatten_d(&cg).concat();
        let block = segments_of(&svg, "block-slider");
        let (top, bottom) = block
            .iter()
            .map(|s| s.0)
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| {
                (a.min(p.1), b.max(p.1))
            });
        let (a, b) = (shaft[0], shaft[1]);
        let (c, d) = (cg[0], cg[cg.len() - 1]);
        if (a.1 - b.1).abs() > 1e-6 || (c.1 - d.1).abs() > 1e-6 {
            continue;
        }
        let (lo, hi) = (
            a.0.min(b.0).max(c.0.min(d.0)),
            a.0.max(b.0).min(c.0.max(d.0)),
        );
        let guided = ids_starting(&svg, "guide-").iter().any(|id| {
            let g = segments_of(&svg, id);
            let (u, v) = (g[0].0.0.min(g[0].1.0), g[0].0.0.max(g[0].1.0));
            u.max(lo) < v.min(hi)
        });
        if hi - lo < 34.0 || guided {
            continue;
        }
        runs += 1;
        let off = (a.1 - c.1).abs();
        assert!(
            off >= (bottom - top) / 3.0,
            "{what}: F_i {off:.2} off CG over {:.0} units, the block {:.1} high",
            hi - lo,
            bottom - top
        );
    }
    assert!(runs >= 3, "a long run beside CG at only {runs} figures");
}

#[test]
fn the_inertia_force_arrow_runs_along_no_link_nor_cg_and_clear_of_the_arc() {
    // The twentieth review: at r = 1, l = 1.09 r, 0° the arrow F_i, in
    // the channel 9 units off the line of stroke, ran beside the crank
    // and the rod lying on that line from the block to C, and at 90° and
    // 270° 14 units beside the heavy CG, through the crank effort's arc
    // about C: it read as a mark of the links'. No link or CG within 10°
    // of the shaft, on the line of stroke or on the shaft's side of it,
    // comes within an em (17 units) of it over a third of its length, and the
    // arc T keeps clear of the shaft. (A link lies on that line where
    // both its ends come within 4 units of it; the rod rising from A
    // across the channel, the default engine's, stands apart.)
    const EM: f64 = 17.0;
    let mut arrows = 0;
    for (what, svg) in twentieth_review_inertia_figures() {
        if !svg.contains("id=\"force-inertia\"") {
            continue;
        }
        arrows += 1;
        let shaft = common::group_path(&svg, "force-inertia");
        let (p, q) = (shaft[0], shaft[1]);
        let stroke_y = flatten_d(&attr(&svg, "line-stroke", "d").unwrap()).concat()[0].1;
        let side = p.1 - stroke_y;
        let tan = 10f64.to_radians().tan();
        let mut strokes = Vec::new();
        for id in ["link-crank", "link-rod", "line-CG"] {
            strokes.extend(
                segments_of(&svg, id)
                    .into_iter()
                    .filter(|(a, b)| (b.1 - a.1).abs() <= tan * (b.0 - a.0).abs()),
            );
        }
        let steps = 64;
        let near = (0..=steps)
            .map(|k| {
                let k = f64::from(k) / f64::from(steps);
                (p.0 + (q.0 - p.0) * k, p.1 + (q.1 - p.1) * k)
            })
            .filter(|&s| {
                strokes.iter().any(|&(a, b)| {
                    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
                    let k = (((s.0 - a.0) * dx + (s.1 - a.1) * dy) / (dx * dx + dy * dy))
                        .clamp(0.0, 1.0);
                    let n = (a.0 + dx * k, a.1 + dy * k);
                    let on_line = (a.1 - stroke_y).abs() <= 4.0 && (b.1 - stroke_y).abs() <= 4.0;
                    (on_line || (n.1 - stroke_y) * side > 0.0) && (s.0 - n.0).hypot(s.1 - n.1) < EM
                })
            })
            .count();
        let share = near as f64 / f64::from(steps + 1);
        assert!(
            share < 1.0 / 3.0,
            "{what}: F_i within an em of a link or CG over {:.0}% of it",
            100.0 * share
        );
        let arc = segments_of(&svg, "torque-T");
        let least = arc
            .iter()
            .map(|&(a, b)| segment_gap(a, b, p, q))
            .fold(f64::INFINITY, f64::min);
        assert!(least >= 4.0, "{what}: the arc T {least:.1} from F_i");
    }
    assert!(arrows >= 100, "F_i drawn at only {arrows} figures");
}

#[test]
fn the_crank_pin_loads_pole_letter_stands_nearer_its_cross_than_any_dot() {
    // The nineteenth review: at r = 1, l = 3.87 r, e = 1.85 r on 120 mm
    // the pole's O, led off, stood 16 units from the dashed curve's
    // plain 60° dot and 42 from its ×, its leader along that curve: it
    // named the plain dot. The pole's letter stands nearer its × than any
    // dot of its panel, lettered or plain.
    let mut poles = 0;
    let engines = [
        (1.0, 3.87, 1.85),
        (1.0, 3.87, -1.85),
        (1.0, 3.82, 1.85),
        (1.0, 3.92, 1.85),
    ];
    for (what, svg) in load_figures(&at_every_width(&engines)) {
        for panel in drawn_load_panels(&svg) {
            let id = format!("label-{panel}-pole");
            if !svg.contains(&format!("id=\"{id}\"")) {
                continue;
            }
            poles += 1;
            let own = to_box_of(&svg, &id, pole_of(&svg, panel));
            for (dot, at) in all_load_marks(&svg, panel) {
                let other = to_box_of(&svg, &id, at);
                assert!(
                    other > own,
                    "{what}: O of {panel} {other:.1} from {dot}, {own:.1} from its ×"
                );
            }
        }
    }
    assert!(poles >= 16, "the pole lettered in only {poles} panels");
}
