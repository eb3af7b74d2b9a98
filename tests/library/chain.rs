//! The chain of Fig. 60 against independent formulations: circle
//! intersections, Newton's method on the slot's arc, finite differences,
//! the straight slot's first-order perturbation, Kennedy's theorem, and the
//! inversions' link angles read off their own frames.

use crate::common;

use common::read_text;
use proptest::prelude::*;
use slider_crank::chain::{arc_position_by_iteration, quadric_sweep, slot_sweep};
use slider_crank::construct::Link;
use slider_crank::geom::{Intersection, Vector};
use slider_crank::{
    Angle, Assembly, ChainCentres, CylindricChain, GrashofClass, Inversion, InvertedChain,
    QuadricChain, SliderCrank, SlotConstruction, slot_convergence,
};
use std::f64::consts::PI;

fn rad(t: f64) -> Angle {
    Angle::from_radians(t).unwrap()
}

/// The angle of `v` unwrapped to lie within π of `near`.
fn unwrap(v: Vector, near: f64) -> f64 {
    let t = v.y.atan2(v.x);
    t + 2.0 * PI * ((near - t) / (2.0 * PI)).round()
}

#[test]
fn every_grashof_class_passes_the_sweep_in_both_modes() {
    let chains = [
        ([1.0, 3.0, 2.5, 3.2], GrashofClass::CrankRocker),
        ([3.0, 2.5, 3.2, 1.0], GrashofClass::DoubleCrank),
        ([3.0, 2.5, 1.0, 3.2], GrashofClass::RockerCrank),
        ([3.0, 1.0, 2.5, 3.2], GrashofClass::DoubleRocker),
        ([1.0, 3.0, 1.0, 3.0], GrashofClass::ChangePoint),
        ([2.0, 1.0, 2.0, 1.0], GrashofClass::ChangePoint),
        ([1.0, 2.0, 2.0, 1.0], GrashofClass::ChangePoint),
        ([3.0, 2.0, 3.0, 4.5], GrashofClass::TripleRocker),
    ];
    for (l, class) in chains {
        let q = QuadricChain::new(l[0], l[1], l[2], l[3]).unwrap();
        assert_eq!(q.grashof(), class, "{l:?}");
        for row in quadric_sweep(&q, 3600) {
            assert!(row.worst < 1e-12, "{l:?}: {row:?}");
            assert!(row.poses > 0, "{l:?}: {row:?}");
        }
    }
}

/// Coupler and lever angles at θ, unwrapped near `near`.
fn link_angles(q: &QuadricChain, t: f64, mode: Assembly, near: (f64, f64)) -> (f64, f64) {
    let p = q.pose(rad(t), mode).unwrap();
    (
        unwrap(p.coupler_vector(), near.0),
        unwrap(p.lever_vector(), near.1),
    )
}

#[test]
fn change_point_rates_are_the_limits_from_the_counter_clockwise_side() {
    // Parallelogram, anti-parallelogram and kite at θ = 0 and 180°:
    // forward differences (the angular accelerations vanish at the node, so
    // they are accurate to O(h²)).
    let mut nodes = 0;
    for l in [
        [1.0, 3.0, 1.0, 3.0],
        [2.0, 1.0, 2.0, 1.0],
        [1.0, 2.0, 2.0, 1.0],
    ] {
        let q = QuadricChain::new(l[0], l[1], l[2], l[3]).unwrap();
        for t0 in [0.0, 180.0] {
            for mode in [Assembly::Open, Assembly::Crossed] {
                let p = q.pose(Angle::deg(t0), mode).unwrap();
                let Some(rates) = p.rates() else {
                    panic!("{l:?} {t0} {mode:?}: no rates")
                };
                let base = (
                    p.coupler_vector().y.atan2(p.coupler_vector().x),
                    p.lever_vector().y.atan2(p.lever_vector().x),
                );
                let h = 1e-6;
                let t = t0.to_radians();
                let (b1, c1) = link_angles(&q, t + h, mode, base);
                let (b2, c2) = link_angles(&q, t + 2.0 * h, mode, base);
                let (fb, fc) = ((b2 - b1) / h, (c2 - c1) / h);
                let tol = 1e-5 * (1.0 + fb.abs() + fc.abs());
                assert!(
                    (rates.coupler_velocity - fb).abs() < tol,
                    "{l:?} {t0} {mode:?}: {rates:?} vs {fb}"
                );
                assert!(
                    (rates.lever_velocity - fc).abs() < tol,
                    "{l:?} {t0} {mode:?}"
                );
                if p.is_toggle() {
                    // At the node itself the accelerations vanish.
                    assert_eq!(rates.coupler_acceleration, 0.0);
                    nodes += 1;
                }
            }
        }
    }
    // Parallelogram and anti-parallelogram at 0° and 180°, the kite at 0°.
    assert_eq!(nodes, 10);
}

/// Random chains of every class: four lengths spanning three decades.
fn any_chain() -> impl Strategy<Value = QuadricChain> {
    prop::array::uniform4(-1.5f64..1.5).prop_filter_map("chain must move", |e| {
        let l = e.map(|x| 10f64.powf(x));
        QuadricChain::new(l[0], l[1], l[2], l[3]).ok()
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    #[test]
    fn quadric_loop_closes_kennedy_holds_rates_match_differences(
        q in any_chain(),
        t in 0.0f64..(2.0 * PI),
        open in any::<bool>(),
    ) {
        let mode = if open { Assembly::Open } else { Assembly::Crossed };
        let Ok(p) = q.pose(rad(t), mode) else { return Ok(()) };
        let size = q.crank().max(q.coupler()).max(q.lever()).max(q.frame());
        prop_assert!(((p.a() - p.b()).norm() - q.coupler()).abs() < 1e-14 * size);
        prop_assert!(((p.a() - q.lever_pivot()).norm() - q.lever()).abs() < 1e-14 * size);
        prop_assert!(((p.b() - p.c()).norm() - q.crank()).abs() < 1e-14 * size);
        for r in ChainCentres::of_quadric(&p).kennedy_residuals() {
            prop_assert!(r.abs() < 1e-12, "{r}");
        }
        // Finite differences away from toggles (where the rates are finite
        // and the branch is smooth over the step).
        let sine = slider_crank::geom::cross(&p.coupler_vector(), &p.lever_vector())
            / (q.coupler() * q.lever());
        let h = 1e-6;
        if sine.abs() < 1e-2 || q.pose(rad(t - h), mode).is_err() || q.pose(rad(t + h), mode).is_err() {
            return Ok(());
        }
        let rates = p.rates().unwrap();
        let base = (p.coupler_angle(), p.lever_angle());
        let (bp, cp) = link_angles(&q, t + h, mode, base);
        let (bm, cm) = link_angles(&q, t - h, mode, base);
        let fb = (bp - bm) / (2.0 * h);
        let fc = (cp - cm) / (2.0 * h);
        let scale = 1.0 + rates.coupler_velocity.abs() + rates.lever_velocity.abs()
            + rates.coupler_acceleration.abs() + rates.lever_acceleration.abs();
        let tol = 1e-6 * scale * scale / sine.abs();
        prop_assert!((rates.coupler_velocity - fb).abs() < tol, "{rates:?} {fb}");
        prop_assert!((rates.lever_velocity - fc).abs() < tol, "{rates:?} {fc}");
        let rp = q.pose(rad(t + h), mode).unwrap().rates().unwrap();
        let rm = q.pose(rad(t - h), mode).unwrap().rates().unwrap();
        let ab = (rp.coupler_velocity - rm.coupler_velocity) / (2.0 * h);
        let ac = (rp.lever_velocity - rm.lever_velocity) / (2.0 * h);
        prop_assert!((rates.coupler_acceleration - ab).abs() < tol, "{rates:?} {ab}");
        prop_assert!((rates.lever_acceleration - ac).abs() < tol, "{rates:?} {ac}");
    }
}

/// A mechanism with n from 1.05 to 1e6, offsets up to 0.9 of the limit,
/// r from 1e-3 to 1e3, and a slot radius from 1.01 (l + r) to 1e15, either
/// sign.
fn any_slot() -> impl Strategy<Value = CylindricChain> {
    (
        -3.0f64..3.0,
        (0.05f64).log10()..6.0,
        -0.9f64..0.9,
        (1.01f64).log10()..15.0,
        any::<bool>(),
    )
        .prop_map(|(lr, ln, ef, lrho, up)| {
            let r = 10f64.powf(lr);
            let l = r * (1.0 + 10f64.powf(ln));
            let m = SliderCrank::new(r, l, ef * (l - r)).unwrap();
            let rho = 10f64.powf(lrho) * (l + r) * if up { -1.0 } else { 1.0 };
            CylindricChain::new(m, rho).unwrap()
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    #[test]
    fn curved_slot_agrees_with_independent_formulations(
        slot in any_slot(),
        t in 0.0f64..(2.0 * PI),
    ) {
        let m = *slot.mechanism();
        let (r, l) = (m.crank(), m.rod());
        let p = slot.pose(rad(t));
        // Loop closure: the rod keeps its length, the block its slot.
        prop_assert!(((p.a() - p.b()).norm() - l).abs() < 1e-14 * (l + r));
        if let Intersection::Point(o) = slot.slot_centre() {
            let rho = slot.slot_radius().unwrap().abs();
            prop_assert!(((p.a() - o).norm() - rho).abs() < 1e-14 * rho.max(l + r));
        }
        // Arc position against Newton's method on the arc parameter.
        let newton = arc_position_by_iteration(&slot, rad(t));
        prop_assert!((newton - p.arc_position()).abs() < 1e-14 * (l + r));
        // Velocities and acceleration against E, D and Klein.
        let s = SlotConstruction::construct(&p);
        prop_assert!((s.arc_rate_from_e().unwrap() - p.arc_rate()).abs() < 1e-12 * r);
        prop_assert!((s.arc_rate_from_d().unwrap() - p.arc_rate()).abs() < 1e-12 * r);
        prop_assert!((s.obliquity_rate_from_d().unwrap() - p.obliquity_rate()).abs() < 1e-12);
        if let Some(acc) = s.arc_acceleration_from_klein() {
            prop_assert!((acc - p.arc_acceleration()).abs() < 1e-12 * r, "{acc} {}", p.arc_acceleration());
        }
        for k in s.centres().kennedy_residuals() {
            prop_assert!(k.abs() < 1e-12, "{k}");
        }
    }

    #[test]
    fn curved_slot_derivatives_match_finite_differences(
        r in 0.1f64..10.0,
        n in 1.2f64..8.0,
        ef in -0.8f64..0.8,
        scale in 1.01f64..50.0,
        up in any::<bool>(),
        t in 0.0f64..(2.0 * PI),
    ) {
        let l = n * r;
        let m = SliderCrank::new(r, l, ef * (l - r)).unwrap();
        let rho = scale * (l + r) * if up { -1.0 } else { 1.0 };
        let slot = CylindricChain::new(m, rho).unwrap();
        let h = 1e-5;
        let (p, q, here) = (slot.pose(rad(t + h)), slot.pose(rad(t - h)), slot.pose(rad(t)));
        let tol = 1e-6 * (1.0 + here.arc_acceleration().abs() / r);
        prop_assert!(((p.arc_position() - q.arc_position()) / (2.0 * h) - here.arc_rate()).abs() < tol * r);
        prop_assert!(((p.arc_rate() - q.arc_rate()) / (2.0 * h) - here.arc_acceleration()).abs() < tol * r);
        prop_assert!(((p.slot_angle() - q.slot_angle()) / (2.0 * h) - here.lever_rate()).abs() < tol);
        prop_assert!(((p.lever_rate() - q.lever_rate()) / (2.0 * h) - here.lever_acceleration()).abs() < tol);
        prop_assert!(((p.obliquity() - q.obliquity()) / (2.0 * h) - here.obliquity_rate()).abs() < tol);
        prop_assert!(((p.obliquity_rate() - q.obliquity_rate()) / (2.0 * h) - here.obliquity_acceleration()).abs() < tol);
    }
}

#[test]
fn curved_slot_is_the_quadric_chain_with_the_lever_as_long_as_the_radius() {
    for (r, l, e) in [(1.0, 3.0, 0.0), (1.0, 1.5, 0.4), (0.5, 3.0, -1.0)] {
        let m = SliderCrank::new(r, l, e).unwrap();
        for rho in [1.01 * (l + r), -1.01 * (l + r), 7.0, -40.0] {
            let slot = CylindricChain::new(m, rho).unwrap();
            let (q, mode, turn) = slot.as_quadric().unwrap();
            // The quadric chain in its own frame, turned into the slot's.
            let (s, c) = turn.to_radians().sin_cos();
            for d in (0..360).step_by(5) {
                let p = slot.pose(Angle::deg(d as f64));
                let qp = q.pose(Angle::deg(d as f64 - turn), mode).unwrap();
                let a = qp.a();
                let a = Vector::new(c * a.x - s * a.y, s * a.x + c * a.y);
                assert!((a - p.a().coords).norm() < 1e-13 * rho.abs(), "{rho} {d}");
                let rates = qp.rates().unwrap();
                assert!(
                    (rates.lever_velocity - p.lever_rate()).abs() < 1e-12,
                    "{rho} {d}"
                );
                assert!((rates.coupler_velocity + p.obliquity_rate()).abs() < 1e-12);
                let acc = rates.lever_acceleration - p.lever_acceleration();
                assert!(acc.abs() < 1e-12 * (1.0 + rates.lever_acceleration.abs()));
            }
        }
    }
}

#[test]
fn at_rho_1e12_the_difference_is_the_first_order_term_to_rounding() {
    // First order in κ: σ = x_A − κ h x_A² / (2w) + O(κ²), from
    // differentiating |A − B| = l along the slot y = e − κx²/2 at κ = 0.
    // The difference itself is ~1e-12; it must equal that term to rounding,
    // not carry the 1e-4 a naive circle intersection would leave.
    let m = SliderCrank::new(0.5, 3.0, 0.2).unwrap();
    for rho in [1e12, -1e12, 1e15] {
        let slot = CylindricChain::new(m, rho).unwrap();
        for d in [10.0, 45.0, 100.0, 200.0, 300.0] {
            let (p, q) = (slot.pose(Angle::deg(d)), m.pose(Angle::deg(d)));
            let x = q.position();
            let first = -(1.0 / rho) * q.rise() * x * x / (2.0 * q.run());
            let residual = p.arc_position() - x - first;
            assert!(
                residual.abs() <= 4.0 * f64::EPSILON * x,
                "{rho} {d}: {residual:e}"
            );
            // The O(1/ρ) difference itself is there (at 1e12, not at 1e15
            // where it is below rounding).
            if rho.abs() == 1e12 {
                assert!((p.arc_position() - x) * first > 0.0, "{rho} {d}");
            }
        }
    }
}

#[test]
fn the_difference_falls_as_one_over_rho_until_rounding() {
    let m = SliderCrank::new(0.2, 0.6, 0.0).unwrap();
    let radii: Vec<f64> = (0..=15).map(|k| 10f64.powi(k)).collect();
    let rows = slot_convergence(&m, &radii, 360).unwrap();
    // Middle decades: ρ · difference constant to 1 %.
    let c = rows[4].position * rows[4].radius;
    for row in &rows[4..=10] {
        let k = row.position * row.radius;
        assert!((k / c - 1.0).abs() < 0.01, "{row:?}");
        let kv = row.velocity * row.radius / (rows[4].velocity * rows[4].radius);
        assert!((kv - 1.0).abs() < 0.01, "{row:?}");
    }
    // At 1e15 the difference is at rounding of the positions (x_A ≤ 0.8).
    assert!(rows[15].position < 1e-14, "{:?}", rows[15]);
    assert!(rows[15].velocity < 1e-14, "{:?}", rows[15]);
    // Larger at ρ = 1 than at 10 and so on: it falls.
    for w in rows[..12].windows(2) {
        assert!(w[1].position < w[0].position, "{w:?}");
    }
}

#[test]
fn slot_sweeps_pass_at_extreme_ratios() {
    for (r, n, ef) in [(1e-9, 1.05, 0.9), (1.0, 1e6, -0.9), (1e9, 3.0, 0.5)] {
        let l = n * r;
        let m = SliderCrank::new(r, l, ef * (l - r)).unwrap();
        for rho in [1.01 * (l + r), -1.01 * (l + r), 1e15 * r] {
            for row in slot_sweep(&CylindricChain::new(m, rho).unwrap(), 2000) {
                assert!(row.worst < 1e-12, "{r} {n} {rho}: {row:?}");
            }
        }
    }
}

/// Link angles of a, b, c (= d) read off the centres in a fixed link's
/// frame: a along O_ad → O_ab, b along O_ab → O_bc, c and d perpendicular
/// to O_cd's direction.
fn frame_angles(c: &ChainCentres, near: [f64; 3]) -> [f64; 3] {
    let p = |x: Link, y: Link| c.centre(x, y).unwrap().point().unwrap();
    let Intersection::AtInfinity(up) = c.centre(Link::C, Link::D).unwrap() else {
        panic!()
    };
    [
        unwrap(p(Link::A, Link::B) - p(Link::A, Link::D), near[0]),
        unwrap(p(Link::B, Link::C) - p(Link::A, Link::B), near[1]),
        unwrap(Vector::new(up.y, -up.x), near[2]),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    #[test]
    fn inversions_are_one_chain(
        r in 0.1f64..10.0,
        n in 1.05f64..20.0,
        ef in -0.9f64..0.9,
        t in 0.0f64..(2.0 * PI),
    ) {
        let l = n * r;
        let m = SliderCrank::new(r, l, ef * (l - r)).unwrap();
        let h = 1e-6;
        let mut relative: Vec<[f64; 3]> = Vec::new();
        for inv in Inversion::ALL {
            let chain = InvertedChain::new(m, inv);
            let here = chain.pose(rad(t));
            for k in here.centres().kennedy_residuals() {
                prop_assert!(k.abs() < 1e-12, "{inv:?}: {k}");
            }
            let near = frame_angles(here.centres(), [0.0; 3]);
            let plus = frame_angles(chain.pose(rad(t + h)).centres(), near);
            let minus = frame_angles(chain.pose(rad(t - h)).centres(), near);
            let rate: Vec<f64> = (0..3).map(|i| (plus[i] - minus[i]) / (2.0 * h)).collect();
            // The fixed link does not turn in its own frame.
            let fixed = match inv.fixed() { Link::A => 0, Link::B => 1, _ => 2 };
            prop_assert!(rate[fixed].abs() < 1e-7, "{inv:?}: {rate:?}");
            // Relative rates a−b, a−c, b−c from the angles read off.
            relative.push([rate[0] - rate[1], rate[0] - rate[2], rate[1] - rate[2]]);
            // And from the core, the same in every inversion.
            let exact = [
                here.relative_rate(Link::A, Link::B),
                here.relative_rate(Link::A, Link::C),
                here.relative_rate(Link::B, Link::C),
            ];
            for i in 0..3 {
                prop_assert!((relative.last().unwrap()[i] - exact[i]).abs() < 1e-6 * (1.0 + exact[i].abs()),
                    "{inv:?} {i}: {:?} vs {exact:?}", relative.last());
            }
        }
        for w in relative.windows(2) {
            for (x, y) in w[0].iter().zip(&w[1]) {
                prop_assert!((x - y).abs() < 1e-6 * (1.0 + x.abs()));
            }
        }
    }
}

#[test]
fn drivers_turn_without_stopping_except_the_hand_pump_handle() {
    let m = SliderCrank::new(1.0, 1.05, 0.0).unwrap();
    for inv in [Inversion::Frame, Inversion::Crank, Inversion::Rod] {
        let chain = InvertedChain::new(m, inv);
        for d in 0..360 {
            let motion = chain.pose(Angle::deg(d as f64)).motion(1.0);
            assert!(motion.is_some(), "{inv:?} {d}");
            let v = motion.unwrap().velocity;
            assert!(v.iter().all(|x| x.is_finite()), "{inv:?} {d}");
        }
    }
    let pump = InvertedChain::new(m, Inversion::Slider);
    assert!(pump.pose(Angle::deg(90.0)).motion(1.0).is_none());
    assert!(pump.pose(Angle::deg(45.0)).motion(1.0).is_some());
    // Whitworth at constant driver speed: the driver b turns at ω
    // relative to the fixed a.
    let w = InvertedChain::new(m, Inversion::Crank).pose(Angle::deg(30.0));
    let motion = w.motion(2.0).unwrap();
    assert!((motion.velocity[1] - 2.0).abs() < 1e-15);
    assert_eq!(motion.velocity[0], 0.0);
}

/// The metadata of a chain figure drawn for `mechanism` at `degrees`.
fn chain_figure(name: slider_crank::FigureName, r: f64, l: f64, degrees: f64) -> serde_json::Value {
    let mut options = slider_crank::catalogue::FigureOptions::default();
    options.mechanism = Some(SliderCrank::new(r, l, 0.0).unwrap());
    options.angle = Some(Angle::from_degrees(degrees).unwrap());
    let svg = slider_crank::render::to_svg(&name.figure(&options).unwrap());
    let start = svg.find("<metadata>").unwrap() + "<metadata>".len();
    let end = svg.find("</metadata>").unwrap();
    serde_json::from_str(&svg[start..end]).unwrap()
}

#[test]
fn fig_60_panels_a_and_b_have_the_same_six_centres_and_c_does_not() {
    // §34: the curved slot of the lever's radius moves the links exactly
    // as the lever does, so the six centres of (a) and (b) agree; (c), the
    // straight slot, has O_cd at infinity.
    for (r, l) in [(0.5, 1.5), (1.0, 1.2), (1.0, 20.0)] {
        for degrees in [0.0, 50.0, 90.0, 175.0, 270.0, 300.0] {
            let meta = chain_figure(slider_crank::FigureName::Fig60Chains, r, l, degrees);
            let centres = &meta["virtual_centres"];
            let scale = r + l;
            for key in ["O_ab", "O_ac", "O_ad", "O_bc", "O_bd", "O_cd"] {
                let (a, b) = (&centres["a"][key], &centres["b"][key]);
                let at = format!("r={r} l={l} θ={degrees}° {key}: {a} vs {b}");
                if a.get("at_infinity").is_some() {
                    assert_eq!(a, b, "{at}");
                    continue;
                }
                for k in 0..2 {
                    let (x, y) = (a[k].as_f64().unwrap(), b[k].as_f64().unwrap());
                    assert!((x - y).abs() <= 1e-11 * scale.max(x.abs()), "{at}");
                }
            }
            assert!(
                centres["c"]["O_cd"].get("at_infinity").is_some(),
                "{centres}"
            );
        }
    }
}

#[test]
fn every_inversion_figure_letters_its_pins_as_centres() {
    // Each figure letters the six centres: the three pins by their names
    // O_ad, O_ab, O_bc, the other three lettered or named in the notes.
    for name in [
        slider_crank::FigureName::Inversion1Engine,
        slider_crank::FigureName::Inversion2RotatingBlock,
        slider_crank::FigureName::Inversion3OscillatingCylinder,
        slider_crank::FigureName::Inversion4HandPump,
    ] {
        let svg = slider_crank::render::to_svg(
            &name
                .figure(&slider_crank::catalogue::FigureOptions::default())
                .unwrap(),
        );
        for (pin, sub) in [("C", "ad"), ("B", "ab"), ("A", "bc")] {
            let at = svg
                .find(&format!("id=\"label-{pin}\""))
                .unwrap_or_else(|| panic!("{}: no label {pin}", name.name()));
            let text = &svg[at..at + svg[at..].find("</text>").unwrap()];
            assert!(
                text.contains(">O<tspan") && text.contains(&format!(">{sub}</tspan>")),
                "{}: {text}",
                name.name()
            );
        }
        for key in ["bd", "ac", "cd"] {
            let lettered = svg.contains(&format!("id=\"label-O-{key}\""));
            let noted = svg.contains(&format!(">{key}</tspan> at "));
            assert!(lettered || noted, "{}: O_{key}", name.name());
        }
    }
}

/// The notes of an inversion figure call a centre "at" a pin only when
/// the two are one point. With a rod of 35 cranks at 12° (issue 20)
/// O_ac lies 0.2137 r from O_ad (C), within a letter of it on the page:
/// the notes gave "Here O_ac at O_ad"; they now give the distance. At
/// 0° the two are one point (the rod along the line of stroke) and are
/// still said to be at each other. Each clause is a sentence a reader
/// can parse ("O_ac 0.02 from O_ab" was read as garbled): a verb, and
/// why the two share one letter. The distance is printed to three
/// figures, as every value the notes compute (0.2137 to 0.214).
#[test]
fn centres_near_a_pin_are_called_coincident_only_when_they_are() {
    let notes = |degrees: f64| {
        let mut options = slider_crank::catalogue::FigureOptions::default();
        options.mechanism = Some(SliderCrank::new(1.0, 35.0, 0.0).unwrap());
        options.angle = Some(Angle::from_degrees(degrees).unwrap());
        let svg = slider_crank::render::to_svg(
            &slider_crank::FigureName::Inversion1Engine
                .figure(&options)
                .unwrap(),
        );
        // The note from "Here" on, as read.
        let at = svg
            .find("Here")
            .unwrap_or_else(|| panic!("{degrees}°: the notes name no centre"));
        // Lines broken as the notes wrap read as one text.
        let text = read_text(&svg[at..]);
        let words: Vec<&str> = text.split_whitespace().collect();
        words.join(" ").chars().take(200).collect::<String>()
    };
    let apart = notes(12.0);
    assert!(!apart.contains("Oac at "), "{apart}");
    assert!(
        apart.contains("Oac lies 0.214 from Oad, too near it to letter apart"),
        "{apart}"
    );
    let together = notes(0.0);
    assert!(together.contains("Oac is at Oad"), "{together}");
}

/// The loop closes at every scale the chain takes: B + coupler = O_cd +
/// lever, each link of its length, to rounding of the longest, for chains
/// of every Grashof class from 1e-150 to 1e150 (lengths beyond 1e±100 are
/// refused by name). Squaring lengths before scaling them made the pin
/// 10–50 % wrong above 1e77 and below 1e-78 (A = (1.207e100, 1.207e100)
/// for four links of 1e100 at 90°).
#[test]
fn the_loop_closes_at_every_scale() {
    let shapes = [
        [1.0, 3.0, 2.5, 3.2],
        [3.0, 2.5, 3.2, 1.0],
        [3.0, 1.0, 2.5, 3.2],
        [1.0, 1.0, 1.0, 1.0],
        [1.0, 2.0, 3.0, 4.0],
        [3.0, 2.0, 3.0, 4.5],
    ];
    let mut closed = 0;
    for k in -150..=150 {
        let s = 10f64.powi(k);
        for shape in shapes {
            let [a, b, c, d] = shape.map(|x| x * s);
            let q = match QuadricChain::new(a, b, c, d) {
                Ok(q) => q,
                Err(e) => {
                    assert!(!(1e-100..=1e100).contains(&s), "{s}: {e}");
                    assert!(e.to_string().contains("is out of range"), "{e}");
                    continue;
                }
            };
            let longest = a.max(b).max(c).max(d);
            for t in 0..36 {
                for mode in [Assembly::Open, Assembly::Crossed] {
                    let Ok(p) = q.pose(Angle::deg(10.0 * t as f64), mode) else {
                        continue;
                    };
                    let gap = (p.b() + p.coupler_vector()) - (q.lever_pivot() + p.lever_vector());
                    assert!(
                        gap.norm() <= 1e-14 * longest,
                        "{shape:?} × {s}, {t}0°: {gap:?}"
                    );
                    let (nb, nc) = (p.coupler_vector().norm(), p.lever_vector().norm());
                    assert!(
                        (nb - b).abs() <= 1e-13 * longest,
                        "{shape:?} × {s}: |b| = {nb}"
                    );
                    assert!(
                        (nc - c).abs() <= 1e-13 * longest,
                        "{shape:?} × {s}: |c| = {nc}"
                    );
                    closed += 1;
                }
            }
        }
    }
    assert!(closed > 50_000, "{closed} poses");
}

#[test]
fn at_a_node_each_mode_has_the_rates_of_the_branch_so_named_after_it() {
    // At exactly 180° of the parallelogram 1, 3, 1, 3 and of the change-point
    // chain 1, 2, 3, 4 (a + d = b + c, flat at 180°), a mode's rates are
    // the limits as θ decreases to 180° (forward differences of the poses
    // at 180° + h, 180° + 2h), and they differ from the limits from below
    // (backward differences), which are the other mode's at 180°: the two
    // branches through the node change sides of the diagonal there.
    let h = 1e-6;
    let t = PI;
    for l in [[1.0, 3.0, 1.0, 3.0], [1.0, 2.0, 3.0, 4.0]] {
        let q = QuadricChain::new(l[0], l[1], l[2], l[3]).unwrap();
        for (mode, other) in [
            (Assembly::Open, Assembly::Crossed),
            (Assembly::Crossed, Assembly::Open),
        ] {
            let p = q.pose(Angle::deg(180.0), mode).unwrap();
            assert!(p.is_toggle(), "{l:?} {mode:?}: flat at 180°");
            let rates = p.rates().expect("finite rates at a node");
            let base = (p.coupler_angle(), p.lever_angle());
            let (b1, c1) = link_angles(&q, t + h, mode, base);
            let (b2, c2) = link_angles(&q, t + 2.0 * h, mode, base);
            let after = ((b2 - b1) / h, (c2 - c1) / h);
            let (b1, c1) = link_angles(&q, t - h, mode, base);
            let (b2, c2) = link_angles(&q, t - 2.0 * h, mode, base);
            let before = ((b1 - b2) / h, (c1 - c2) / h);
            let close = |x: f64, y: f64| (x - y).abs() < 1e-5 * (1.0 + x.abs());
            assert!(
                close(rates.coupler_velocity, after.0) && close(rates.lever_velocity, after.1),
                "{l:?} {mode:?}: {rates:?} against the limit from above {after:?}"
            );
            assert!(
                (rates.coupler_velocity - before.0).abs() > 0.1,
                "{l:?} {mode:?}: the limits from both sides differ ({rates:?}, {before:?})"
            );
            let across = q.pose(Angle::deg(180.0), other).unwrap().rates().unwrap();
            assert!(
                close(across.coupler_velocity, before.0) && close(across.lever_velocity, before.1),
                "{l:?} {mode:?}: the limit from below {before:?} is the {other:?} mode's {across:?}"
            );
        }
    }
    // The limits in closed form for 1, 2, 3, 4: the node equation
    // −10 λ′² + 4 λ′ + 2 = 0 (src/chain/quadric.rs); the open chain at
    // 180° is on (1 + √6)/5, the root it had been on below 180° in the
    // crossed mode.
    let q = QuadricChain::new(1.0, 2.0, 3.0, 4.0).unwrap();
    let open = q
        .pose(Angle::deg(180.0), Assembly::Open)
        .unwrap()
        .rates()
        .unwrap();
    assert!(
        (open.coupler_velocity - (1.0 + 6f64.sqrt()) / 5.0).abs() < 1e-14,
        "{open:?}"
    );
}
