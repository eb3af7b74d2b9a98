//! The quick returns of inversions 2 and 3 against closed forms computed
//! here (docs/quick-return.md): the time ratio (180° + β)/(180° − β), the
//! tool's position, and its velocity and acceleration by finite
//! differences of that position over the driver's exact turn.

use slider_crank::chain::{Inversion, QuickReturn, Stroke};
use slider_crank::{Angle, SliderCrank};

/// The obliquity φ at θ (radians): sin φ = (r sin θ − e)/l.
fn phi(m: &SliderCrank, theta: f64) -> f64 {
    ((m.crank() * theta.sin() - m.offset()) / m.rod()).asin()
}

/// The tool's position at θ, from the geometry: the arm L along d away
/// from the block, projected square to the fixed link's line of centres.
/// Inversion 3 (B to A the line of centres, d along the stroke): the arm
/// makes the angle φ with it, L sin φ, whose ends at θ = 90° and 270°
/// are L (±r − e)/l, so from mid-stroke s = L sin φ + L e/l. Inversion 2
/// (C to B at θ to d): s = −L sin θ. Both + the way the tool cuts.
fn position(m: &SliderCrank, inversion: Inversion, lever: f64, theta: f64) -> f64 {
    match inversion {
        Inversion::Rod => lever * phi(m, theta).sin() + lever * m.offset() / m.rod(),
        _ => -lever * theta.sin(),
    }
}

/// The driver's angle against the fixed link at θ: the crank a against
/// the rod b, θ + φ (inversion 3); the rod b against the crank a, −θ − φ
/// (inversion 2).
fn driver(m: &SliderCrank, inversion: Inversion, theta: f64) -> f64 {
    match inversion {
        Inversion::Rod => theta + phi(m, theta),
        _ => -theta - phi(m, theta),
    }
}

const MECHANISMS: [(f64, f64, f64); 5] = [
    (0.5, 1.5, 0.0),
    (1.0, 2.0, 0.0),
    (1.0, 1.05, 0.0),
    (1.0, 4.0, 1.2),
    (1.0, 30.0, -8.0),
];

#[test]
fn the_time_ratio_is_180_plus_beta_over_180_minus_beta() {
    for (r, l, e) in MECHANISMS {
        let m = SliderCrank::new(r, l, e).unwrap();
        // The strokes end where d is square to the line of centres; the
        // return turns the driver through 180° − β, β the sum of the
        // obliquities there (2 asin(r/l) in line).
        let beta = ((r + e) / l).asin() + ((r - e) / l).asin();
        let expected = (std::f64::consts::PI + beta) / (std::f64::consts::PI - beta);
        for inversion in [Inversion::Crank, Inversion::Rod] {
            let q = QuickReturn::new(m, inversion, 2.0).unwrap();
            let ratio = q.time_ratio();
            assert!(
                (ratio - expected).abs() <= 1e-13 * expected,
                "{inversion:?} {r} {l} {e}: {ratio} against {expected}"
            );
            let (cutting, back) = q.stroke_angles();
            assert!((cutting + back - std::f64::consts::TAU).abs() < 1e-14);
        }
    }
    // The textbook's own case: r/l = 1/2, β = 60°, 240/120 = 2.
    let m = SliderCrank::in_line(1.0, 2.0).unwrap();
    let q = QuickReturn::new(m, Inversion::Rod, 3.0).unwrap();
    assert!((q.time_ratio() - 2.0).abs() < 1e-14);
}

#[test]
fn the_tool_moves_as_the_arm_s_projection_and_its_finite_differences() {
    let w = 3.0;
    for (r, l, e) in MECHANISMS {
        let m = SliderCrank::new(r, l, e).unwrap();
        for inversion in [Inversion::Crank, Inversion::Rod] {
            let lever = 1.7 * (l + r);
            let q = QuickReturn::new(m, inversion, lever).unwrap();
            for k in 0..72 {
                let deg = 5.0 * f64::from(k) + 0.3;
                let theta = deg.to_radians();
                let t = q.at(Angle::deg(deg), w);
                let s = |x: f64| position(&m, inversion, lever, x);
                let chi = |x: f64| driver(&m, inversion, x);
                let what = format!("{inversion:?} r={r} l={l} e={e} θ={deg}");
                assert!((t.position - s(theta)).abs() <= 1e-13 * lever, "{what}");
                // d/dt = ω d/dχ, the driver at constant ω.
                let h = 1e-4;
                let (s0, s1, s2) = (s(theta - h), s(theta), s(theta + h));
                let (c0, c1, c2) = (chi(theta - h), chi(theta), chi(theta + h));
                let (ds, dds) = ((s2 - s0) / (2.0 * h), (s2 - 2.0 * s1 + s0) / (h * h));
                let (dc, ddc) = ((c2 - c0) / (2.0 * h), (c2 - 2.0 * c1 + c0) / (h * h));
                let velocity = w * ds / dc;
                let acceleration = w * w * (dds * dc - ds * ddc) / dc.powi(3);
                // Scaled by the arm and the driver's and d's fastest turn.
                let fast = (l + r) / (l - r - e.abs());
                let v_tol = 1e-6 * lever * w * fast;
                let a_tol = 1e-5 * lever * w * w * fast.powi(3);
                assert!(
                    (t.velocity - velocity).abs() <= v_tol,
                    "{what}: velocity {} against {velocity}",
                    t.velocity
                );
                assert!(
                    (t.acceleration - acceleration).abs() <= a_tol,
                    "{what}: acceleration {} against {acceleration}",
                    t.acceleration
                );
            }
        }
    }
}

#[test]
fn the_return_stroke_runs_through_the_inner_dead_centre_and_the_strokes_end_at_rest() {
    for (r, l, e) in MECHANISMS {
        let m = SliderCrank::new(r, l, e).unwrap();
        for inversion in [Inversion::Crank, Inversion::Rod] {
            let q = QuickReturn::new(m, inversion, 2.0).unwrap();
            let (cutting, _) = q.stroke_angles();
            assert_eq!(q.at(Angle::deg(180.0), 1.0).stroke, Stroke::Return);
            assert_eq!(q.at(Angle::deg(0.0), 1.0).stroke, Stroke::Cutting);
            // The tool cuts the + way and returns the − way.
            assert!(q.at(Angle::deg(0.0), 1.0).velocity > 0.0);
            assert!(q.at(Angle::deg(180.0), 1.0).velocity < 0.0);
            // The strokes' ends: the tool at rest, at ± half its stroke.
            for end in [90.0, 270.0] {
                let t = q.at(Angle::deg(end), 1.0);
                assert!(t.velocity.abs() <= 1e-14 * 2.0, "{inversion:?} {end}");
                assert!(
                    (t.position.abs() - 0.5 * q.stroke_length()).abs() <= 1e-14 * 2.0 * l,
                    "{inversion:?} {end}"
                );
            }
            // The driver has turned through the cutting stroke at its end.
            let end = match inversion {
                Inversion::Rod => 89.999_999,
                _ => 270.000_001,
            };
            let t = q.at(Angle::deg(end), 1.0);
            assert_eq!(t.stroke, Stroke::Cutting);
            assert!((t.driver_angle - cutting).abs() < 1e-6, "{inversion:?}");
        }
    }
}

#[test]
fn a_quick_return_needs_inversion_2_or_3_and_a_positive_arm() {
    let m = SliderCrank::in_line(1.0, 3.0).unwrap();
    assert!(QuickReturn::new(m, Inversion::Frame, 1.0).is_err());
    assert!(QuickReturn::new(m, Inversion::Slider, 1.0).is_err());
    for bad in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        assert!(QuickReturn::new(m, Inversion::Rod, bad).is_err(), "{bad}");
    }
}
