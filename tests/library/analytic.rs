//! Properties of the analytic core: exact derivatives against finite
//! differences, approximations converging as n grows, invariance under
//! scaling.

use proptest::prelude::*;
use slider_crank::analytic::approx;
use slider_crank::{Angle, Kinematics, SliderCrank};

fn mech(r: f64, n: f64, frac: f64) -> SliderCrank {
    let l = r * n;
    SliderCrank::new(r, l, frac * (l - r)).unwrap()
}

/// Fourth-order central difference of f at x with step h.
fn diff(f: impl Fn(f64) -> f64, x: f64, h: f64) -> f64 {
    (-f(x + 2.0 * h) + 8.0 * f(x + h) - 8.0 * f(x - h) + f(x - 2.0 * h)) / (12.0 * h)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(500))]

    #[test]
    fn derivatives_match_finite_differences(
        n in 1.2f64..20.0, frac in -0.8f64..0.8, theta in 0.0f64..360.0,
    ) {
        let m = mech(1.0, n, frac);
        let at = |t: f64| m.pose(Angle::from_radians(t).unwrap());
        let t = theta.to_radians();
        let h = 1e-3;
        let p = at(t);
        let scale = 1.0 + p.position_acceleration().abs();
        prop_assert!((diff(|x| at(x).position(), t, h) - p.position_rate()).abs() < 1e-8 * scale);
        prop_assert!((diff(|x| at(x).position_rate(), t, h) - p.position_acceleration()).abs() < 1e-7 * scale);
        prop_assert!((diff(|x| at(x).obliquity(), t, h) - p.obliquity_rate()).abs() < 1e-8 * scale);
        prop_assert!((diff(|x| at(x).obliquity_rate(), t, h) - p.obliquity_acceleration()).abs() < 1e-7 * scale);
    }

    #[test]
    fn kinematics_scale_with_omega(n in 1.1f64..50.0, theta in 0.0f64..360.0, w in -500.0f64..500.0) {
        let m = mech(0.3, n, 0.2);
        let p = m.pose(Angle::deg(theta));
        let k = Kinematics::new(&p, w).unwrap();
        prop_assert_eq!(k.velocity, w * p.position_rate());
        prop_assert_eq!(k.acceleration, w * w * p.position_acceleration());
        prop_assert_eq!(k.rod_angular_velocity, w * p.obliquity_rate());
    }

    #[test]
    fn invariant_under_scaling_r_l_e_together(
        n in 1.05f64..1e3, frac in -0.9f64..0.9, theta in 0.0f64..360.0, log_k in -8.0f64..8.0,
    ) {
        let k = 10f64.powf(log_k);
        let (a, b) = (mech(1.0, n, frac), mech(k, n, frac));
        let pa = a.pose(Angle::deg(theta));
        let pb = b.pose(Angle::deg(theta));
        let close = |x: f64, y: f64| (x - y).abs() <= 1e-13 * (1.0 + x.abs().max(y.abs()));
        prop_assert!(close(pb.position() / k, pa.position()));
        prop_assert!(close(pb.position_rate() / k, pa.position_rate()));
        prop_assert!(close(pb.position_acceleration() / k, pa.position_acceleration()));
        prop_assert!(close(pb.obliquity(), pa.obliquity()));
        prop_assert!(close(pb.obliquity_rate(), pa.obliquity_rate()));
        prop_assert!(close(pb.obliquity_acceleration(), pa.obliquity_acceleration()));
    }

    #[test]
    fn approximations_converge_as_n_grows(theta in 0.0f64..360.0) {
        // The errors of eq. (2), (3), (2a) are bounded by 3/n³ (the first
        // neglected terms), and the error due to obliquity by 1/(2n) crank
        // radii (to 1/n more).
        for n in [10.0, 100.0, 1000.0] {
            let p = mech(1.0, n, 0.0).pose(Angle::deg(theta));
            let n3 = n * n * n;
            prop_assert!(approx::velocity(&p, 1.0).error().abs() * n3 <= 3.0);
            prop_assert!(approx::acceleration(&p, 1.0).error().abs() * n3 <= 3.0);
            prop_assert!(approx::rod_angular_acceleration(&p, 1.0).error().abs() * n3 <= 3.0);
            prop_assert!(p.obliquity_error().abs() * 2.0 * n <= 1.0 + 1.0 / n);
        }
    }
}

#[test]
fn approximation_errors_at_45_degrees_fall_like_n_cubed() {
    let e = |n: f64| {
        let p = mech(1.0, n, 0.0).pose(Angle::deg(45.0));
        approx::velocity(&p, 1.0).error().abs()
    };
    let ratio = e(10.0) / e(20.0);
    assert!((ratio - 8.0).abs() < 0.3, "{ratio}");
}
