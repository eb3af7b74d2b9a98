//! Ritterhaus's and Bennett's constructions of the piston's acceleration
//! against the closed forms and against Kisch's F and G (docs/polygons.md).

use slider_crank::construct::{Bennett, Kisch, Ritterhaus, VelocityLine};
use slider_crank::geom::cross;
use slider_crank::{Angle, SliderCrank};

/// Every 7.5°, the quarters exactly and a hair off them.
fn angles() -> Vec<f64> {
    let mut out: Vec<f64> = (0..48).map(|k| 7.5 * f64::from(k)).collect();
    for q in [0.0, 90.0, 180.0, 270.0] {
        out.extend([q + 1e-7, q - 1e-7]);
    }
    out
}

/// d²s/dθ² by hand: −r cos θ − r² cos²θ l² / w³ + r sin θ h / w, with
/// h = r sin θ − e, w = √(l² − h²).
fn exact(r: f64, l: f64, e: f64, deg: f64) -> f64 {
    let th = deg.to_radians();
    let (s, c) = (th.sin(), th.cos());
    let h = r * s - e;
    let w = (l * l - h * h).sqrt();
    -r * c - r * r * c * c * l * l / w.powi(3) + r * s * h / w
}

#[test]
fn ritterhaus_reads_the_piston_acceleration_with_and_without_offset() {
    for (r, l, e) in [
        (0.5, 3.0, 0.0),
        (1.0, 1.02, 0.0),
        (1.0, 60.0, 0.0),
        (1.0, 4.0, 1.5),
        (1.0, 4.0, -2.7),
        (1e-9, 3e-9, 1e-9),
        (1e9, 3e9, 0.0),
    ] {
        let m = SliderCrank::new(r, l, e).unwrap();
        for deg in angles() {
            let pose = m.pose(Angle::deg(deg));
            let rit = Ritterhaus::construct(&pose, &VelocityLine::construct(&pose));
            let want = exact(r, l, e, deg);
            let tol = 1e-12 * r * (l / (l - r - e.abs())).powi(3);
            let got = rit.points().acceleration_ratio();
            assert!((got - want).abs() <= tol, "{l} {e} {deg}: {got} {want}");
        }
    }
}

#[test]
fn ritterhaus_draws_as_the_book_says() {
    // K on CB produced with EK parallel to AC; F on the rod straight above
    // K; FG perpendicular to the rod; F and G Kisch's.
    let m = SliderCrank::new(1.0, 3.5, 0.6).unwrap();
    for deg in angles() {
        let pose = m.pose(Angle::deg(deg));
        let e_line = VelocityLine::construct(&pose);
        let rit = Ritterhaus::construct(&pose, &e_line);
        let (a, b, c, e) = (pose.a(), pose.b(), pose.c(), e_line.e());
        let (k, f, g) = (rit.k(), rit.points().f(), rit.points().g());
        assert!(cross(&(k - c), &(b - c)).abs() <= 1e-13, "{deg}: K on CB");
        assert!(cross(&(k - e), &(c - a)).abs() <= 1e-12, "{deg}: EK ∥ AC");
        assert!((f.x - k.x).abs() <= 1e-13, "{deg}: KF ⟂ stroke");
        assert!(cross(&(f - a), &(b - a)).abs() <= 1e-12, "{deg}: F on AB");
        assert!((g - f).dot(&(b - a)).abs() <= 1e-12, "{deg}: FG ⟂ AB");
        let kisch = Kisch::construct(&pose, &e_line);
        assert!((f - kisch.points().f()).norm() <= 1e-13, "{deg}");
        assert!((g - kisch.points().g()).norm() <= 1e-12, "{deg}");
    }
}

#[test]
fn bennett_reads_the_in_line_piston_acceleration() {
    for (r, l) in [
        (0.5, 3.0),
        (1.0, 1.02),
        (1.0, 1.05),
        (1.0, 60.0),
        (1e-9, 4e-9),
        (1e9, 4e9),
    ] {
        let m = SliderCrank::in_line(r, l).unwrap();
        for deg in angles() {
            let pose = m.pose(Angle::deg(deg));
            let got = Bennett::construct(&pose)
                .unwrap()
                .points()
                .acceleration_ratio();
            let want = exact(r, l, 0.0, deg);
            let tol = 1e-12 * r * (l / (l - r)).powi(3);
            assert!((got - want).abs() <= tol, "{l} {deg}: {got} {want}");
        }
    }
}

#[test]
fn bennett_draws_as_the_book_says_and_is_the_in_line_engine_s() {
    let m = SliderCrank::in_line(1.0, 3.5).unwrap();
    // C₁L₁: the foot of the perpendicular from C on the rod with the crank
    // at right angles to the stroke lies r²/l from the crank pin.
    let right = m.pose(Angle::deg(90.0));
    let u = (right.a() - right.b()) / 3.5;
    assert!(((right.c() - right.b()).dot(&u) - 1.0 / 3.5).abs() <= 1e-15);
    for deg in angles() {
        let pose = m.pose(Angle::deg(deg));
        let ben = Bennett::construct(&pose).unwrap();
        let (a, b) = (pose.a(), pose.b());
        let (l, k, f, g) = (ben.l(), ben.k(), ben.points().f(), ben.points().g());
        assert!(
            ((l - b).norm() - 1.0 / 3.5).abs() <= 1e-15,
            "{deg}: BL = r²/l"
        );
        assert!((k - l).dot(&(b - a)).abs() <= 1e-12, "{deg}: LK ⟂ AB");
        assert_eq!(k.y, 0.0, "{deg}: K on the line of stroke");
        assert!((f.x - k.x).abs() <= 1e-13, "{deg}: KF ⟂ stroke");
        assert!((g - f).dot(&(b - a)).abs() <= 1e-12, "{deg}: FG ⟂ AB");
        let kisch = Kisch::construct(&pose, &VelocityLine::construct(&pose));
        assert!((f - kisch.points().f()).norm() <= 1e-13, "{deg}");
    }
    let offset = SliderCrank::new(1.0, 3.5, 0.2).unwrap();
    assert!(Bennett::construct(&offset.pose(Angle::deg(30.0))).is_none());
}

#[test]
fn both_give_fig_67_s_acceleration() {
    // The §35 engine at 45° with the book's ω = 26.16: r ω² (cos θ +
    // (n² cos 2θ + sin⁴θ)/(n² − sin²θ)^1.5) = 342.17 × 0.708289 =
    // 242.36 ft/s² exact (eq. 3: 242.1; the book read 240 off its drawing).
    let m = SliderCrank::in_line(0.5, 3.0).unwrap();
    let pose = m.pose(Angle::deg(45.0));
    let w = 26.16;
    let rit = Ritterhaus::construct(&pose, &VelocityLine::construct(&pose));
    let ben = Bennett::construct(&pose).unwrap();
    for a in [
        rit.points().acceleration_ratio(),
        ben.points().acceleration_ratio(),
    ] {
        assert!((-a * w * w - 242.36).abs() < 0.005, "{}", -a * w * w);
    }
}
