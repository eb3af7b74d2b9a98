//! Engine dynamics checked against independent formulas written here:
//! virtual work at every pose, the two rod models against each other and
//! against the rod's kinetic energy, the work of a turn against the
//! indicator diagram's area, the fluctuation of energy against a brute
//! sum, and the two-term series' error against 1/n³.

use proptest::prelude::*;
use slider_crank::dynamics::{
    Engine, Flywheel, GasForce, IndicatorDiagram, RodMass, TurningMoment, unbalanced_forces,
};
use slider_crank::{Angle, SliderCrank};
use std::f64::consts::{PI, TAU};

fn engine(r: f64, n: f64, frac: f64, mass: f64, omega: f64) -> Engine {
    let l = r * n;
    let m = SliderCrank::new(r, l, frac * (l - r)).unwrap();
    Engine::new(m, mass, omega).unwrap()
}

/// x_A(θ) of the slider, written out.
fn x(r: f64, l: f64, e: f64, t: f64) -> f64 {
    r * t.cos() + (l * l - (r * t.sin() - e).powi(2)).sqrt()
}

/// dx_A/dθ, written out.
fn x1(r: f64, l: f64, e: f64, t: f64) -> f64 {
    let h = r * t.sin() - e;
    -r * t.sin() - r * t.cos() * h / (l * l - h * h).sqrt()
}

/// Fourth-order central difference.
fn diff(f: impl Fn(f64) -> f64, x: f64, h: f64) -> f64 {
    (-f(x + 2.0 * h) + 8.0 * f(x + h) - 8.0 * f(x - h) + f(x - 2.0 * h)) / (12.0 * h)
}

/// The angles every property is also checked at: dead centres and 90°.
const SPECIAL: [f64; 5] = [0.0, 90.0, 180.0, 270.0, 359.0];

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    /// T ω = −F v at every pose, for both the construction's OM and the
    /// exact arm, to 1e-12 of |F| r |ω| (which scales the dead centres,
    /// where both sides vanish).
    #[test]
    fn virtual_work_holds_at_every_pose(
        r in 0.01f64..10.0, n in 1.2f64..12.0, frac in -0.8f64..0.8,
        mass in 0.0f64..50.0, w in -400.0f64..400.0, gas in -1e4f64..1e4,
        theta in 0.0f64..360.0, special in 0usize..6,
    ) {
        let engine = engine(r, n, frac, mass, w).with_gas(GasForce::Constant(gas)).unwrap();
        let m = *engine.mechanism();
        let degrees = SPECIAL.get(special).copied().unwrap_or(theta);
        let at = engine.at(Angle::deg(degrees)).unwrap();
        let v = w * x1(r, m.rod(), m.offset(), Angle::deg(degrees).radians());
        let scale = at.piston_effort.abs() * r * w.abs() + 1e-300;
        prop_assert!((at.crank_effort * w + at.piston_effort * v).abs() <= 1e-12 * scale,
            "OM: {} vs {}", at.crank_effort * w, -at.piston_effort * v);
        prop_assert!((at.crank_effort_exact * w + at.piston_effort * v).abs() <= 1e-12 * scale,
            "exact: {} vs {}", at.crank_effort_exact * w, -at.piston_effort * v);
    }

    /// The reciprocating inertia force m a towards the crank against the
    /// in-line closed form a = −r ω² (cos θ + (n² cos 2θ + sin⁴θ) /
    /// (n² − sin²θ)^{3/2}), and Klein's CG against it.
    #[test]
    fn inertia_force_matches_the_closed_form(
        n in 1.2f64..12.0, mass in 0.1f64..50.0, w in -400.0f64..400.0,
        theta in 0.0f64..360.0, special in 0usize..6,
    ) {
        let r = 0.5;
        let engine = engine(r, n, 0.0, mass, w);
        let degrees = SPECIAL.get(special).copied().unwrap_or(theta);
        let at = engine.at(Angle::deg(degrees)).unwrap();
        let t = degrees.to_radians();
        let (s, c) = t.sin_cos();
        let q = n * n - s * s;
        let a = -r * w * w * (c + (n * n * (2.0 * c * c - 1.0) + s.powi(4)) / q.powf(1.5));
        let scale = mass * r * w * w * (1.0 + 1.0 / (n - 1.0)).powi(3);
        prop_assert!((at.inertia_force - mass * a).abs() <= 1e-12 * scale);
        prop_assert!((at.inertia_force_graphical - mass * a).abs() <= 1e-10 * scale);
    }

    /// The rod's exact inertia torque is −dK/dθ (K its kinetic energy,
    /// ½ m_r |v_G|² + ½ m_r k² Ω², from positions written here and
    /// differentiated numerically), and the equivalent system of two
    /// masses and the correction couple gives the same torque.
    #[test]
    fn rod_models_agree_with_each_other_and_the_energy(
        n in 1.5f64..8.0, frac in -0.5f64..0.5, cg in 0.0f64..1.0, k in 0.0f64..0.6,
        mr in 0.1f64..20.0, w in 1.0f64..300.0, theta in 0.0f64..360.0, special in 0usize..6,
    ) {
        let r = 0.4;
        let base = engine(r, n, frac, 0.0, w);
        let m = *base.mechanism();
        let (l, e) = (m.rod(), m.offset());
        let rod = RodMass::new(mr, cg * l, k * l).unwrap();
        let engine = base.with_rod(rod).unwrap();
        let degrees = SPECIAL.get(special).copied().unwrap_or(theta);
        let at = engine.at(Angle::deg(degrees)).unwrap();
        let rod_at = at.rod.unwrap();
        let scale = mr * w * w * r * r * (1.0 + k * k * l * l / (r * r)) * (1.0 + 1.0 / (n - 1.0)).powi(3);
        prop_assert!((rod_at.torque - rod_at.equivalent_torque).abs() <= 1e-12 * scale,
            "{} vs {}", rod_at.torque, rod_at.equivalent_torque);
        // G = B + (BG/l)(A − B); φ from sin φ = (r sin θ − e)/l.
        let gx = |t: f64| r * t.cos() + cg * (x(r, l, e, t) - r * t.cos());
        let gy = |t: f64| r * t.sin() + cg * (e - r * t.sin());
        let phi = |t: f64| ((r * t.sin() - e) / l).asin();
        let energy = |t: f64| {
            let (vx, vy, om) = (w * diff(gx, t, 1e-4), w * diff(gy, t, 1e-4), w * diff(phi, t, 1e-4));
            0.5 * mr * (vx * vx + vy * vy) + 0.5 * mr * k * k * l * l * om * om
        };
        let t = degrees.to_radians();
        let expected = -diff(energy, t, 1e-3);
        prop_assert!((rod_at.torque - expected).abs() <= 1e-6 * scale,
            "{} vs {expected}", rod_at.torque);
        // The correction couple acts on the crank through Ω/ω = −cos θ /
        // √(n² − sin²θ) (in line) — checked in general as −dφ/dθ.
        let ratio = -diff(phi, t, 1e-4);
        prop_assert!((rod_at.correction_torque - rod_at.correction_couple * ratio).abs()
            <= 1e-8 * scale);
    }
}

/// The inertia forces do no net work over a turn, rod and all.
#[test]
fn inertia_forces_do_no_work_over_a_turn() {
    for (n, frac, phases) in [
        (4.0, 0.0, vec![0.0]),
        (3.0, 0.3, vec![0.0]),
        (1.3, -0.2, vec![0.0, 90.0]),
        (6.0, 0.0, vec![0.0, 120.0, 240.0]),
    ] {
        let base = engine(0.5, n, frac, 3.0, 120.0);
        let l = base.mechanism().rod();
        let e = base
            .with_rod(RodMass::new(2.0, 0.3 * l, 0.35 * l).unwrap())
            .unwrap();
        let tm = TurningMoment::new(&e, &phases).unwrap();
        assert!(tm.peak > 1e3, "{}", tm.peak);
        assert!(tm.work.abs() <= 1e-11 * tm.peak * TAU, "{n}: {}", tm.work);
        let areas: f64 = tm.lobes.iter().map(|l| l.area).sum();
        assert!(areas.abs() <= 1e-11 * tm.peak * TAU);
    }
}

/// A diagram written here: pressure 10 falling linearly to 2 on the
/// expansion stroke, 1 to 3 on compression, on a 0.2 bore.
const CSV: &str = "fraction,expansion,compression\n0,10,1\n0.1,9,1\n0.4,5,1.5\n1,2,3\n";

/// The area of [`CSV`] by hand: expansion 0.1·19/2 + 0.3·14/2 + 0.6·7/2
/// = 0.95 + 2.1 + 2.1 = 5.15; compression 0.1·2/2 + 0.3·2.5/2 + 0.6·4.5/2
/// = 0.1 + 0.375 + 1.35 = 1.825; loop 3.325.
const LOOP: f64 = 3.325;

#[test]
fn the_turn_does_the_indicator_diagrams_work() {
    for (n, frac, mass, w) in [
        (4.0, 0.0, 0.0, 50.0),
        (5.0, 0.4, 2.0, 30.0),
        (1.5, -0.3, 0.5, -40.0),
    ] {
        let d = IndicatorDiagram::from_csv(CSV, 0.2, "csv").unwrap();
        let e = engine(0.3, n, frac, mass, w)
            .with_gas(GasForce::Indicator(d))
            .unwrap();
        let stroke = e.mechanism().stroke();
        let expected = PI * 0.01 * stroke * LOOP;
        let tm = TurningMoment::new(&e, &[0.0]).unwrap();
        // ω < 0 runs the cycle backwards: the same area, negative work
        // (the torque is still counter-clockwise positive).
        let expected = expected * w.signum();
        assert!(
            (tm.work - expected).abs() <= 1e-10 * expected.abs(),
            "{n}: {} vs {expected}",
            tm.work
        );
        // Two cylinders at 180° do twice the work.
        let two = TurningMoment::new(&e, &[0.0, 180.0]).unwrap();
        assert!((two.work - 2.0 * expected).abs() <= 1e-10 * expected.abs());
    }
}

/// A four-stroke diagram written here: [`CSV`]'s expansion and
/// compression, and the pumping strokes' lines (gauge, the intake below
/// the atmosphere).
const CSV4: &str = "fraction,expansion,exhaust,intake,compression\n\
    0,10,0.6,-0.2,1\n0.1,9,0.5,-0.3,1\n0.4,5,0.4,-0.3,1.5\n1,2,0.3,-0.1,3\n";

/// The pumping loop of [`CSV4`] by hand: intake 0.1·(−0.5)/2 +
/// 0.3·(−0.6)/2 + 0.6·(−0.4)/2 = −0.025 − 0.09 − 0.12 = −0.235; exhaust
/// 0.1·1.1/2 + 0.3·0.9/2 + 0.6·0.7/2 = 0.055 + 0.135 + 0.21 = 0.4; intake
/// less exhaust −0.635. With [`LOOP`], 2.69 over the cycle.
const LOOP4: f64 = 2.69;

#[test]
fn the_four_stroke_cycle_does_its_indicator_diagrams_work_over_720_degrees() {
    let d = IndicatorDiagram::from_csv_cycle(CSV4, 0.2, "csv").unwrap();
    assert_eq!(d.turns(), 2);
    for (n, frac, mass, w) in [
        (4.0, 0.0, 0.0, 50.0),
        (5.0, 0.4, 2.0, 30.0),
        (1.5, -0.3, 0.5, -40.0),
    ] {
        let e = engine(0.3, n, frac, mass, w)
            .with_gas(GasForce::Indicator(d.clone()))
            .unwrap();
        let stroke = e.mechanism().stroke();
        let expected = PI * 0.01 * stroke * LOOP4 * w.signum();
        let tm = TurningMoment::new(&e, &[0.0]).unwrap();
        assert_eq!(tm.cycle_deg, 720.0);
        assert!(
            (tm.work - expected).abs() <= 1e-10 * expected.abs(),
            "{n}: {} vs {expected}",
            tm.work
        );
        assert!((tm.mean - expected / (2.0 * TAU)).abs() <= 1e-10 * tm.mean.abs());
        assert_eq!(tm.kinks_deg.last(), Some(&720.0));
        assert!(tm.lobes.last().unwrap().to_deg == 720.0);
        // Two cylinders half a cycle apart (360°) do twice the work.
        let two = TurningMoment::new(&e, &[0.0, 360.0]).unwrap();
        assert!((two.work - 2.0 * expected).abs() <= 1e-10 * expected.abs());
        // Four firing every 180° of the cycle: four times the work, and a
        // torque that repeats every half turn, each cylinder in its turn.
        let firing = [0.0, 180.0, 360.0, 540.0];
        let four = TurningMoment::new(&e, &firing).unwrap();
        assert!((four.work - 4.0 * expected).abs() <= 1e-10 * expected.abs());
        for k in 0..36 {
            let deg = 5.0 * k as f64 + 0.5;
            let t = |d: f64| e.torque_of_cylinders(&firing, Angle::deg(d)).unwrap();
            let (a, b) = (t(deg), t(deg + 180.0));
            assert!((a - b).abs() <= 1e-9 * four.peak, "{n}: {deg}°: {a} vs {b}");
        }
        let spans: Vec<f64> = four.lobes.iter().map(|l| l.to_deg - l.from_deg).collect();
        assert!(four.lobes.len() >= 8, "{n}: {spans:?}");
    }
}

#[test]
fn the_four_stroke_fluctuation_of_energy_matches_a_brute_sum_over_720_degrees() {
    let d = IndicatorDiagram::from_csv_cycle(CSV4, 0.2, "csv").unwrap();
    let e = engine(0.3, 5.0, 0.4, 0.05, 30.0)
        .with_gas(GasForce::Indicator(d))
        .unwrap();
    let tm = TurningMoment::new(&e, &[0.0]).unwrap();
    // Trapezoids of T over 400 000 steps of the two turns, each turn's T
    // from the library's per-pose torque in that turn. The cycle's turns
    // change where the strokes do, at the outer dead centre
    // θ₀ = asin(e / (l + r)) (not at 360°: with this offset the piston is
    // still compressing between 360° and 360° + θ₀).
    let m = *e.mechanism();
    let outer = (m.offset() / (m.rod() + m.crank())).asin();
    let steps = 400_000;
    let h = 2.0 * TAU / steps as f64;
    let values: Vec<f64> = (0..=steps)
        .map(|i| {
            let t = i as f64 * h;
            let pose = e.mechanism().pose(Angle::from_radians(t).unwrap());
            let turn = ((t - outer).div_euclid(TAU) as i64).rem_euclid(2) as usize;
            e.torque_in_turn(&pose, turn)
        })
        .collect();
    let work: f64 = values.windows(2).map(|p| 0.5 * h * (p[0] + p[1])).sum();
    assert!((tm.work - work).abs() <= 1e-7 * tm.peak * 2.0 * TAU);
    let mean = work / (2.0 * TAU);
    let swing = brute_fluctuation(&values, h, mean);
    assert!(
        (tm.fluctuation - swing).abs() <= 1e-6 * swing,
        "{} vs {swing}",
        tm.fluctuation
    );
    // The inertia forces count (a fluctuation unlike the gas alone's).
    let gas_only = TurningMoment::new(
        &engine(0.3, 5.0, 0.4, 0.0, 30.0)
            .with_gas(GasForce::Indicator(
                IndicatorDiagram::from_csv_cycle(CSV4, 0.2, "csv").unwrap(),
            ))
            .unwrap(),
        &[0.0],
    )
    .unwrap();
    assert!((gas_only.fluctuation - tm.fluctuation).abs() > 0.01 * tm.fluctuation);
}

#[test]
fn the_second_turn_of_a_four_stroke_cycle_is_intake_and_compression() {
    // Massless, so that T = −F dx/dθ with F the gas force alone.
    let d = IndicatorDiagram::from_csv_cycle(CSV4, 0.2, "csv").unwrap();
    let e = engine(0.3, 4.0, 0.0, 0.0, 50.0)
        .with_gas(GasForce::Indicator(d))
        .unwrap();
    let (r, l) = (0.3, 1.2);
    let area = PI * 0.01;
    // The line's pressure at the fraction of the stroke (rows of CSV4).
    let line = |column: usize, f: f64| {
        let rows = [
            [0.0, 10.0, 0.6, -0.2, 1.0],
            [0.1, 9.0, 0.5, -0.3, 1.0],
            [0.4, 5.0, 0.4, -0.3, 1.5],
            [1.0, 2.0, 0.3, -0.1, 3.0],
        ];
        let k = rows.windows(2).position(|w| f <= w[1][0]).unwrap();
        let (a, b) = (rows[k], rows[k + 1]);
        a[column] + (b[column] - a[column]) * (f - a[0]) / (b[0] - a[0])
    };
    // θ in the first turn, its line there and in the second turn.
    for (deg, first, second) in [(40.0, 1, 3), (130.0, 1, 3), (220.0, 2, 4), (300.0, 2, 4)] {
        let t: f64 = f64::to_radians(deg);
        let f = (r + l - x(r, l, 0.0, t)) / (2.0 * r);
        let pose = e.mechanism().pose(Angle::deg(deg));
        for (turn, column) in [(0, first), (1, second)] {
            let expected = -area * line(column, f) * x1(r, l, 0.0, t);
            let got = e.torque_in_turn(&pose, turn);
            assert!(
                (got - expected).abs() <= 1e-12 * expected.abs().max(1e-3),
                "{deg}° turn {turn}: {got} vs {expected}"
            );
        }
    }
    // The table's rows past 360° are the second turn: at 450° the
    // intake's pressure, at 90° the expansion's.
    for (deg, column) in [(90.0, 1), (450.0, 3)] {
        let t: f64 = f64::to_radians(deg);
        let f = (r + l - x(r, l, 0.0, t)) / (2.0 * r);
        let row = slider_crank::table::dynamics_row(&e, &[0.0], deg, 9).unwrap();
        assert_eq!(row[1], format!("{:.9}", area * line(column, f)), "{deg}°");
    }
    // The columns say what cycle it is: one pumping column alone is
    // refused, and the one-turn reader refuses the pumping lines rather
    // than read a four-stroke diagram over one turn.
    let half = "fraction,expansion,exhaust,compression\n0,1,0,0\n1,1,0,0\n";
    let err = IndicatorDiagram::from_csv_cycle(half, 0.2, "h.csv").unwrap_err();
    assert!(
        err.to_string().contains("both an exhaust and an intake"),
        "{err}"
    );
    let err = IndicatorDiagram::from_csv(CSV4, 0.2, "csv").unwrap_err();
    assert!(err.to_string().contains("\"exhaust\""), "{err}");
}

#[test]
fn the_fluctuation_of_energy_matches_a_brute_sum() {
    let d = IndicatorDiagram::from_csv(CSV, 0.2, "csv").unwrap();
    let base = engine(0.3, 4.5, 0.1, 1.5, 60.0);
    let l = base.mechanism().rod();
    let e = base
        .with_rod(RodMass::new(1.0, 0.35 * l, 0.3 * l).unwrap())
        .unwrap()
        .with_gas(GasForce::Indicator(d))
        .unwrap();
    let tm = TurningMoment::new(&e, &[0.0, 90.0]).unwrap();
    // Trapezoids of T − T_mean over 200 000 steps, T from the library's
    // per-pose torque (checked by virtual work above), summed here.
    let steps = 200_000;
    let torque = |t: f64| {
        [0.0, 90.0]
            .iter()
            .map(|d: &f64| {
                e.at(Angle::from_radians(t + d.to_radians()).unwrap())
                    .unwrap()
                    .torque
            })
            .sum::<f64>()
    };
    let h = TAU / steps as f64;
    let values: Vec<f64> = (0..=steps).map(|i| torque(i as f64 * h)).collect();
    let work: f64 = values.windows(2).map(|p| 0.5 * h * (p[0] + p[1])).sum();
    assert!(
        (tm.work - work).abs() <= 1e-7 * tm.peak * TAU,
        "{} vs {work}",
        tm.work
    );
    let mean = work / TAU;
    let swing = brute_fluctuation(&values, h, mean);
    assert!(
        (tm.fluctuation - swing).abs() <= 1e-6 * swing,
        "{} vs {swing}",
        tm.fluctuation
    );
    // Lobes alternate in sign and meet end to end.
    for pair in tm.lobes.windows(2) {
        assert_eq!(pair[0].to_deg, pair[1].from_deg);
        assert!(pair[0].area * pair[1].area < 0.0, "{pair:?}");
    }
    // The flywheel for 2 % holds ΔE: I ω² C_s = ΔE.
    let f = Flywheel::for_coefficient(tm.fluctuation, 60.0, 0.02).unwrap();
    assert!((f.inertia * 3600.0 * 0.02 - tm.fluctuation).abs() <= 1e-12 * tm.fluctuation);
}

/// The two-term series m r ω² (cos θ + cos 2θ / n) errs by O(1/n³): the
/// largest remainder over a turn falls eightfold as n doubles.
#[test]
fn the_two_term_error_falls_like_the_cube_of_n() {
    let worst = |n: f64| {
        let e = engine(1.0, n, 0.0, 1.0, 1.0);
        (0..3600)
            .map(|i| {
                unbalanced_forces(&e, Angle::deg(i as f64 / 10.0))
                    .remainder
                    .abs()
            })
            .fold(0.0, f64::max)
    };
    for n in [8.0, 16.0, 32.0] {
        let ratio = worst(n) / worst(2.0 * n);
        assert!((ratio - 8.0).abs() < 0.5, "n = {n}: {ratio}");
    }
    // At θ = 0 the exact force is m r ω² (1 + 1/n): no remainder at all.
    let e = engine(0.5, 4.0, 0.0, 2.0, 10.0);
    let b = unbalanced_forces(&e, Angle::deg(0.0));
    assert!((b.exact - 2.0 * 0.5 * 100.0 * 1.25).abs() < 1e-12);
    assert!(b.remainder.abs() < 1e-12);
    // At 90°: primary 0, secondary −m r ω²/n.
    let b = unbalanced_forces(&e, Angle::deg(90.0));
    assert_eq!(b.primary, 0.0);
    assert_eq!(b.secondary, -2.0 * 0.5 * 100.0 / 4.0);
}

/// A hand-worked pose: r = 0.5, l = 2, θ = 90°, m = 4, ω = 10, gas 100.
/// sin φ = 1/4, cos φ = √15/4; a = −r ω² (0 + (−16 + 1)/15^{3/2}) =
/// 50 · 15/15^{1.5} = 50/√15; m a = 200/√15 = 51.6398; F = 151.6398;
/// T = F r (OM = r at 90°) = 75.8199; rod force F / cos φ.
#[test]
fn a_hand_worked_pose() {
    let e = engine(0.5, 4.0, 0.0, 4.0, 10.0)
        .with_gas(GasForce::Constant(100.0))
        .unwrap();
    let at = e.at(Angle::deg(90.0)).unwrap();
    let f = 100.0 + 200.0 / 15f64.sqrt();
    assert!((at.inertia_force - 200.0 / 15f64.sqrt()).abs() < 1e-12);
    assert!((at.piston_effort - f).abs() < 1e-12);
    assert!((at.crank_effort - 0.5 * f).abs() < 1e-12);
    assert!((at.rod_force - f * 4.0 / 15f64.sqrt()).abs() < 1e-12);
    assert!((at.guide_thrust + f / 15f64.sqrt()).abs() < 1e-12);
    assert!(at.rod.is_none());
}

/// The fluctuation of energy by brute force: the greatest less the least
/// of the running trapezoidal sum of `values − mean` at steps `h`.
fn brute_fluctuation(values: &[f64], h: f64, mean: f64) -> f64 {
    let (mut energy, mut hi, mut lo) = (0.0f64, 0.0f64, 0.0f64);
    for p in values.windows(2) {
        energy += 0.5 * h * (p[0] + p[1]) - mean * h;
        hi = hi.max(energy);
        lo = lo.min(energy);
    }
    hi - lo
}

/// Numbers as a careless user or script types them, for the balancing.
fn hostile() -> impl Strategy<Value = f64> {
    prop_oneof![
        4 => -1e3..1e3f64,
        1 => prop::num::f64::ANY,
        1 => prop::sample::select(vec![
            0.0, -0.0, 5e-324, 1e-300, 1e300, f64::MAX, f64::INFINITY, f64::NAN, 1.0000000000000002,
        ]),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// Partial balance, the hammer blow, and cylinders on one crank take
    /// any numbers: each is refused with one line or gives finite values
    /// (no inf, no NaN), at any angle.
    #[test]
    fn the_balancing_takes_any_numbers(
        c in hostile(), mass in hostile(), crank in hostile(), wheel in hostile(),
        speed in hostile(), load in hostile(), n in hostile(), degrees in hostile(),
        axes in prop::collection::vec(hostile(), 0..6),
    ) {
        use slider_crank::dynamics::{HammerBlow, PartialBalance, RadialEngine};
        let one_line = |e: slider_crank::Error| {
            let s = e.to_string();
            assert!(!s.is_empty() && !s.contains('\n'), "{s}");
        };
        let angle = Angle::from_degrees(degrees).ok();
        match PartialBalance::new(c) {
            Ok(b) => {
                if let Some(a) = angle {
                    let u = b.at(a);
                    prop_assert!(u.horizontal.is_finite() && u.vertical.is_finite());
                    prop_assert!(u.magnitude.is_finite() && u.magnitude <= 1.0);
                }
                match HammerBlow::new(&b, mass, crank, wheel) {
                    Ok(h) => {
                        match h.at_speed(speed) {
                            Ok(v) => prop_assert!(v.is_finite() && v >= 0.0),
                            Err(e) => one_line(e),
                        }
                        match h.lifting_speed(load) {
                            Ok(Some(v)) => prop_assert!(v.is_finite() && v >= 0.0),
                            Ok(None) => prop_assert_eq!(h.moment, 0.0),
                            Err(e) => one_line(e),
                        }
                    }
                    Err(e) => one_line(e),
                }
            }
            Err(e) => one_line(e),
        }
        match RadialEngine::new(&axes, n) {
            Ok(e) => {
                if let Some(a) = angle {
                    let (p, s) = (e.primary_at(a), e.secondary_at(a));
                    prop_assert!(p.iter().chain(&s).all(|v| v.is_finite()), "{p:?} {s:?}");
                    match e.exact_at(a) {
                        Ok(x) => prop_assert!(x.iter().all(|v| v.is_finite()), "{x:?}"),
                        Err(err) => one_line(err),
                    }
                }
            }
            Err(e) => one_line(e),
        }
    }
}
