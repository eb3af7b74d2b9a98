//! Every construction against the analytic core (docs/design.md §2, §6).

use proptest::prelude::*;
use slider_crank::construct::{
    Centrode, CentrodeKind, CouplerPoint, InstantCentre, Kisch, Klein, Link, Quantity, TorqueLine,
    VelocityLine, VirtualCentres, cross_check, kennedy_residual, sweep,
};
use slider_crank::geom::Intersection;
use slider_crank::{Angle, SliderCrank};

const TOL: f64 = 1e-12;

fn assert_sweep(m: &SliderCrank, samples: usize) {
    let report = sweep(m, samples);
    for (q, err, at, n) in &report.worst {
        assert!(*err <= TOL, "{m:?}: {} off by {err:e} at {at}°", q.name());
        // Bennett's construction is the in-line engine's.
        let drawn = *q != Quantity::AccelerationBennett || m.offset() == 0.0;
        assert_eq!(*n > 0, drawn, "{}", q.name());
    }
}

#[test]
fn done_when_mechanisms_pass_at_1e_12() {
    for n in [1.05, 1.5, 4.0, 6.0, 100.0, 1e6] {
        for r in [1e-9, 1.0, 1e9] {
            let l = n * r;
            for e in [0.0, 0.9 * (l - r), -0.9 * (l - r)] {
                let m = SliderCrank::new(r, l, e).unwrap();
                assert_sweep(&m, 2000);
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]
    #[test]
    fn constructions_agree_with_analytic_core(
        log_r in -9.0f64..9.0,
        log_n_minus_1 in -1.3f64..6.0,
        offset_frac in -0.9f64..0.9,
        theta in 0.0f64..360.0,
    ) {
        let r = 10f64.powf(log_r);
        let l = r * (1.0 + 10f64.powf(log_n_minus_1));
        let m = SliderCrank::new(r, l, offset_frac * (l - r)).unwrap();
        let pose = m.pose(Angle::deg(theta));
        for row in cross_check(&pose) {
            prop_assert!(row.scaled_error() <= TOL, "{:?} {} {}", row.quantity, row.graphical, row.analytic);
        }
    }
}

#[test]
fn d_is_at_infinity_exactly_at_90_and_270_and_finite_just_before() {
    let m = SliderCrank::in_line(0.5, 3.0).unwrap();
    for d in [90.0, 270.0, -90.0, 450.0] {
        let ic = InstantCentre::construct(&m.pose(Angle::deg(d)));
        assert!(matches!(ic.d(), Intersection::AtInfinity(_)), "{d}");
        assert_eq!(ic.rod_angular_velocity_ratio(), 0.0);
    }
    let pose = m.pose(Angle::deg(89.999999));
    let d = InstantCentre::construct(&pose)
        .d()
        .point()
        .expect("finite D");
    // D = (x_A, x_A tan θ).
    let t = pose.angle().sin() / pose.angle().cos();
    assert!(d.y > 1e8, "far up the crank line: {}", d.y);
    assert!((d.x - pose.position()).abs() < 1e-15 * d.x);
    assert!((d.y / (pose.position() * t) - 1.0).abs() < 1e-14);
    assert!(
        Klein::construct(
            &pose,
            &InstantCentre::construct(&pose),
            &VelocityLine::construct(&pose)
        )
        .is_some()
    );
}

#[test]
fn klein_is_unavailable_only_where_d_is_at_infinity() {
    let m = SliderCrank::new(1.0, 4.0, 0.5).unwrap();
    for k in 0..360 {
        let pose = m.pose(Angle::deg(k as f64));
        let d = InstantCentre::construct(&pose);
        let klein = Klein::construct(&pose, &d, &VelocityLine::construct(&pose));
        assert_eq!(klein.is_none(), k == 90 || k == 270, "{k}");
    }
}

#[test]
fn klein_and_kisch_give_the_same_f_and_g() {
    let m = SliderCrank::new(1.0, 3.5, -0.4).unwrap();
    for k in 0..720 {
        let pose = m.pose(Angle::deg(k as f64 * 0.5));
        let e = VelocityLine::construct(&pose);
        let kisch = Kisch::construct(&pose, &e);
        if let Some(klein) = Klein::construct(&pose, &InstantCentre::construct(&pose), &e) {
            assert!((klein.points().f() - kisch.points().f()).norm() < 1e-13);
            assert!((klein.points().g() - kisch.points().g()).norm() < 1e-13);
        }
    }
}

#[test]
fn kisch_h_is_on_the_semicircle_and_the_circle_about_b() {
    let m = SliderCrank::in_line(0.5, 3.0).unwrap();
    for k in 0..72 {
        let pose = m.pose(Angle::deg(k as f64 * 5.0));
        let e = VelocityLine::construct(&pose);
        let kisch = Kisch::construct(&pose, &e);
        let h = kisch.h().expect("BE < BA for n = 6");
        let semi = Kisch::semicircle(&pose);
        assert!(
            ((h - semi.centre).norm() - semi.radius).abs() < 1e-14,
            "{k}"
        );
        assert!(((h - pose.b()).norm() - kisch.be()).abs() < 1e-14, "{k}");
        // HF is perpendicular to AB.
        let hf = kisch.points().f() - h;
        assert!(hf.dot(&(pose.b() - pose.a())).abs() < 1e-13, "{k}");
    }
}

#[test]
fn kisch_h_exists_even_near_the_assembly_limit() {
    // BE / BA = r |cos θ| / (l cos φ) < 1 whenever l > r + |e|: the circle
    // about B always cuts the semicircle.
    for e in [0.0, 0.049, -0.049] {
        let m = SliderCrank::new(1.0, 1.05, e).unwrap();
        for k in 0..3600 {
            let pose = m.pose(Angle::deg(k as f64 * 0.1));
            let kisch = Kisch::construct(&pose, &VelocityLine::construct(&pose));
            assert!(kisch.be() < pose.mechanism().rod(), "{k}");
            assert!(kisch.h().is_some(), "{k}");
            let err = (kisch.points().acceleration_ratio() - pose.position_acceleration()).abs();
            assert!(err < 1e-12, "{k}");
        }
    }
}

#[test]
fn fig_67_cg_at_45_degrees() {
    // §36: CG = 0.351 ft measured on the drawing; the construction gives the
    // exact 0.3541 ft (r (cos θ + sin⁴θ/(n² − sin²θ)^{3/2}) at 45°, n = 6).
    let m = SliderCrank::in_line(0.5, 3.0).unwrap();
    let pose = m.pose(Angle::deg(45.0));
    let kisch = Kisch::construct(&pose, &VelocityLine::construct(&pose));
    let (s, n) = (0.5f64.sqrt(), 6.0f64);
    let exact = 0.5 * (s + s.powi(4) / (n * n - s * s).powf(1.5));
    assert!((kisch.points().cg() - exact).abs() < 1e-15);
    assert!(
        (kisch.points().cg() - 0.351).abs() < 0.004,
        "the drawing's 0.351 is within 1 %"
    );
    // Velocity scale V_c / CB = 13.08 / 0.5 = 26.16; acceleration scale its square.
    let scale = 13.08 / 0.5;
    assert!((scale - 26.16f64).abs() < 1e-12);
    assert!((0.351 * scale - 9.18).abs() < 0.005);
    assert!((0.351 * scale * scale - 240.0).abs() < 0.5);
    let acc = kisch.points().cg() * scale * scale;
    assert!((acc - 242.357).abs() < 1e-3, "{acc}");
}

#[test]
fn ng_appendix_velocity_ratio_om_over_oc() {
    // v_p / v_c = OM / OC (A3) and IP / IC (A2), on Ng's rig.
    let m = SliderCrank::in_line(25.0, 72.0).unwrap();
    for d in [10.0, 40.0, 70.0, 100.0, 130.0, 160.0] {
        let pose = m.pose(Angle::deg(d));
        let e = VelocityLine::construct(&pose);
        let i = InstantCentre::construct(&pose).d().point().unwrap();
        let ratio_a3 = e.ce() / 25.0;
        let ratio_a2 = (i - pose.a()).norm() / (i - pose.b()).norm();
        let exact = -pose.position_rate() / 25.0;
        assert!((ratio_a3 - exact).abs() < 1e-14, "{d}");
        assert!((ratio_a2 - exact.abs()).abs() < 1e-13, "{d}");
        let torque = TorqueLine::construct(&pose, &e);
        let f = torque.slider_force(1000.0).unwrap().unwrap();
        assert!((f * torque.om() - 1000.0).abs() < 1e-10);
        let phi = pose.obliquity();
        assert!((torque.side_thrust(f).unwrap() - f * phi.tan()).abs() < 1e-12 * f);
    }
}

#[test]
fn kennedy_theorem_holds_for_every_triple() {
    use Link::*;
    let m = SliderCrank::new(1.0, 3.0, 0.6).unwrap();
    for k in 0..360 {
        let pose = m.pose(Angle::deg(k as f64));
        let vc = VirtualCentres::construct(
            &pose,
            &InstantCentre::construct(&pose),
            &VelocityLine::construct(&pose),
        );
        for [p, q, s] in [[A, B, C], [A, B, D], [A, C, D], [B, C, D]] {
            let res = kennedy_residual(
                &vc.centre(p, q).unwrap(),
                &vc.centre(q, s).unwrap(),
                &vc.centre(p, s).unwrap(),
            );
            assert!(res.abs() < 1e-13, "{k}: {p:?}{q:?}{s:?} {res}");
        }
        assert!(matches!(
            vc.centre(D, C).unwrap(),
            Intersection::AtInfinity(_)
        ));
        assert_eq!(
            vc.centre(A, C).unwrap().point(),
            Some(VelocityLine::construct(&pose).e())
        );
    }
    // Not collinear: a check that the residual can fail.
    let p = |x, y| Intersection::Point(slider_crank::geom::Point::new(x, y));
    assert!(kennedy_residual(&p(0.0, 0.0), &p(1.0, 0.0), &p(0.0, 1.0)).abs() > 0.1);
}

#[test]
fn centrode_derivatives_match_finite_differences() {
    let m = SliderCrank::new(1.0, 3.0, 0.3).unwrap();
    for kind in [CentrodeKind::Fixed, CentrodeKind::Moving] {
        let c = Centrode::new(kind);
        for d in [10.0, 60.0, 120.0, 200.0, 300.0] {
            let h = 1e-6;
            let p = |x: f64| c.point(&m.pose(Angle::deg(x))).point().unwrap();
            let fd = (p(d + h) - p(d - h)) / (2.0 * h.to_radians());
            let exact = c.derivative(&m.pose(Angle::deg(d))).unwrap();
            assert!(
                (fd - exact).norm() < 1e-6 * (1.0 + exact.norm()),
                "{kind:?} {d}"
            );
        }
        assert!(matches!(
            c.point(&m.pose(Angle::deg(90.0))),
            Intersection::AtInfinity(_)
        ));
        assert!(c.derivative(&m.pose(Angle::deg(270.0))).is_none());
    }
    // The fixed centrode is D itself.
    let pose = m.pose(Angle::deg(33.0));
    assert_eq!(
        Centrode::new(CentrodeKind::Fixed).point(&pose).point(),
        InstantCentre::construct(&pose).d().point()
    );
}

#[test]
fn moving_centrode_is_d_in_the_rod_frame() {
    let m = SliderCrank::new(1.0, 3.0, -0.3).unwrap();
    let pose = m.pose(Angle::deg(40.0));
    let d = InstantCentre::construct(&pose).d().point().unwrap();
    let u = (pose.b() - pose.a()) / 3.0;
    let local = Centrode::new(CentrodeKind::Moving)
        .point(&pose)
        .point()
        .unwrap();
    let back = pose.a() + u * local.x + slider_crank::geom::perp(&u) * local.y;
    assert!((back - d).norm() < 1e-14);
}

#[test]
fn coupler_points_trace_ovals_between_line_and_circle() {
    let m = SliderCrank::in_line(1.0, 4.0).unwrap();
    let mid = CouplerPoint::new(0.5).unwrap();
    let err = CouplerPoint::new(1.5).unwrap_err().to_string();
    assert!(err.contains("from A (0) to B (1)"), "{err}");
    assert!(CouplerPoint::new(f64::NAN).is_err());
    for k in 0..36 {
        let pose = m.pose(Angle::deg(k as f64 * 10.0));
        assert_eq!(CouplerPoint::new(0.0).unwrap().point(&pose), pose.a());
        assert!((CouplerPoint::new(1.0).unwrap().point(&pose) - pose.b()).norm() < 1e-15);
        let h = 1e-6;
        let fd = (mid.point(&m.pose(Angle::deg(k as f64 * 10.0 + h)))
            - mid.point(&m.pose(Angle::deg(k as f64 * 10.0 - h))))
            / (2.0 * h.to_radians());
        assert!((fd - mid.derivative(&pose)).norm() < 1e-6);
    }
}

#[test]
fn rod_rates_have_the_seeds_sign() {
    // At 45°, n = 6: dφ/dt > 0 and d²φ/dt² < 0 (§37: 3.10 and −80.1 rad/s…).
    let m = SliderCrank::in_line(0.5, 3.0).unwrap();
    let rows = cross_check(&m.pose(Angle::deg(45.0)));
    let get = |q| rows.iter().find(|r| r.quantity == q).unwrap().graphical;
    assert!(get(Quantity::RodAngularVelocity) > 0.0);
    assert!(get(Quantity::RodAngularAccelerationKisch) < 0.0);
    assert!(get(Quantity::RodAngularAccelerationKlein) < 0.0);
    assert!(get(Quantity::Velocity) < 0.0);
}
