//! The velocity and acceleration polygons (the relative-velocity method)
//! against closed forms derived by hand (docs/polygons.md) and the numbers
//! of textbook §36–37.

use slider_crank::analytic::kinematics::rpm_to_omega;
use slider_crank::construct::{
    AccelerationPolygon, CouplerPoint, Quantity, VelocityPolygon, sweep,
};
use slider_crank::geom::{Vector, cross};
use slider_crank::{Angle, SliderCrank};

/// The polygons' quantities in the cross-check.
const POLYGON: [Quantity; 8] = [
    Quantity::VelocityPolygon,
    Quantity::RodAngularVelocityPolygon,
    Quantity::CouplerVelocityPolygon,
    Quantity::AccelerationPolygon,
    Quantity::RodAngularAccelerationPolygon,
    Quantity::CouplerAccelerationPolygon,
    Quantity::OffRodVelocityPolygon,
    Quantity::OffRodAccelerationPolygon,
];

fn polygons(m: &SliderCrank, deg: f64, t: f64) -> (VelocityPolygon, AccelerationPolygon) {
    let pose = m.pose(Angle::deg(deg));
    let c = Some(CouplerPoint::new(t).unwrap());
    let v = VelocityPolygon::construct(&pose, c);
    let a = AccelerationPolygon::construct(&pose, &v, c);
    (v, a)
}

/// The angles of a sweep: every 7.5° and the quarters, and a hair off them.
fn angles() -> Vec<f64> {
    let mut out: Vec<f64> = (0..48).map(|k| 7.5 * f64::from(k)).collect();
    for q in [0.0, 90.0, 180.0, 270.0] {
        out.extend([q + 1e-7, q - 1e-7]);
    }
    out
}

#[test]
fn in_line_polygons_read_the_closed_forms_for_n_from_1_02_to_60() {
    // In-line, per ω and ω² (q = √(n² − sin²θ)):
    // ds/dθ = −r (sin θ + sin 2θ / 2q), dφ/dθ = cos θ / q,
    // d²s/dθ² = −r (cos θ + (n² cos 2θ + sin⁴θ) / q³),
    // d²φ/dθ² = −sin θ (n² − 1) / q³.
    for n in [1.02, 1.05, 1.5, 4.0, 6.0, 30.0, 60.0] {
        for r in [1e-9, 0.5, 1e9] {
            let m = SliderCrank::in_line(r, n * r).unwrap();
            for deg in angles() {
                let (v, a) = polygons(&m, deg, 0.5);
                let th = deg.to_radians();
                let (s, c) = (th.sin(), th.cos());
                let q = (n * n - s * s).sqrt();
                let vel = -r * (s + (2.0 * th).sin() / (2.0 * q));
                let rate = c / q;
                let acc = -r * (c + (n * n * (2.0 * th).cos() + s.powi(4)) / q.powi(3));
                let alpha = -s * (n * n - 1.0) / q.powi(3);
                let tol = 1e-12;
                assert!(
                    (v.slider_velocity_ratio() - vel).abs() <= tol * r,
                    "{n} {deg}"
                );
                assert!(
                    (v.rod_angular_velocity_ratio() - rate).abs() <= tol,
                    "{n} {deg}"
                );
                assert!(
                    (a.slider_acceleration_ratio() - acc).abs() <= tol * r * n * n,
                    "{n} {deg}: {} {acc}",
                    a.slider_acceleration_ratio()
                );
                assert!(
                    (a.rod_angular_acceleration_ratio() - alpha).abs() <= tol * n * n,
                    "{n} {deg}"
                );
            }
        }
    }
}

#[test]
fn offset_polygons_read_the_hand_formulas() {
    // h = r sin θ − e, w = √(l² − h²): ds/dθ = −r sin θ − r cos θ h / w,
    // d²s/dθ² = −r cos θ − r² cos²θ l² / w³ + r sin θ h / w.
    for (r, l, e) in [
        (1.0, 3.0, 1.5),
        (1.0, 3.0, -1.9),
        (0.5, 1.6, 0.9),
        (2.0, 120.0, 50.0),
    ] {
        let m = SliderCrank::new(r, l, e).unwrap();
        for deg in angles() {
            let (v, a) = polygons(&m, deg, 0.25);
            let th = deg.to_radians();
            let (s, c) = (th.sin(), th.cos());
            let h = r * s - e;
            let w = (l * l - h * h).sqrt();
            let vel = -r * s - r * c * h / w;
            let acc = -r * c - r * r * c * c * l * l / w.powi(3) + r * s * h / w;
            let tol = 1e-12 * (l / w).powi(3);
            assert!(
                (v.slider_velocity_ratio() - vel).abs() <= tol * r,
                "{e} {deg}"
            );
            assert!(
                (a.slider_acceleration_ratio() - acc).abs() <= tol * r,
                "{e} {deg}: {} {acc}",
                a.slider_acceleration_ratio()
            );
        }
    }
}

#[test]
fn at_the_dead_centres_the_slider_rests_and_the_rod_has_no_tangential_component() {
    let m = SliderCrank::in_line(0.5, 3.0).unwrap();
    for deg in [0.0, 180.0] {
        let (v, a) = polygons(&m, deg, 0.5);
        assert_eq!(v.a().x, 0.0, "{deg}");
        assert_eq!(a.tangential().norm(), 0.0, "{deg}");
        assert_eq!(a.rod_angular_acceleration_ratio(), 0.0, "{deg}");
        // ab = ob: the whole of the pin's velocity is relative to A.
        assert!((v.ab() - v.b()).norm() <= 1e-16, "{deg}");
        // o′a′ = o′b′ + b′x: −r − r²/l at 0°, r − r²/l at 180°.
        let want = if deg == 0.0 {
            -0.5 - 0.25 / 3.0
        } else {
            0.5 - 0.25 / 3.0
        };
        assert!((a.a().x - want).abs() <= 1e-15, "{deg}: {}", a.a().x);
    }
}

#[test]
fn at_90_degrees_the_rod_translates_and_the_normal_component_vanishes() {
    for (r, l) in [(0.5, 3.0), (1.0, 1.05), (1.0, 60.0)] {
        let m = SliderCrank::in_line(r, l).unwrap();
        for deg in [90.0, 270.0] {
            let (v, a) = polygons(&m, deg, 0.3);
            assert_eq!(v.ab(), Vector::zeros(), "{deg}");
            assert_eq!(v.rod_angular_velocity_ratio(), 0.0);
            assert_eq!(a.x(), a.b(), "{deg}");
            // o′a′ = r²/√(l² − r²) at both: the tangential component alone.
            let want = r * r / (l * l - r * r).sqrt();
            assert!(
                (a.a().x - want).abs() <= 1e-14 * r * (l / (l - r)),
                "{l} {deg}"
            );
        }
    }
}

#[test]
fn the_polygons_are_drawn_as_the_method_says() {
    // ab ⟂ AB, b′x ∥ AB with |b′x| = ab²/AB, xa′ ⟂ AB, c and c′ the images
    // dividing ab and a′b′ as C divides AB.
    let m = SliderCrank::new(1.0, 3.5, 0.7).unwrap();
    for deg in angles() {
        let pose = m.pose(Angle::deg(deg));
        let (v, a) = polygons(&m, deg, 0.3);
        let rod = pose.b() - pose.a();
        let l = rod.norm();
        assert!(v.ab().dot(&rod).abs() <= 1e-14 * l, "{deg}");
        assert!((v.b().norm() - 1.0).abs() <= 1e-15);
        assert!((a.b().norm() - 1.0).abs() <= 1e-15);
        let normal = a.x() - a.b();
        assert!(cross(&normal, &rod).abs() <= 1e-14 * l, "{deg}");
        assert!(normal.dot(&rod) >= 0.0, "from A towards B");
        assert!(
            (normal.norm() - v.ab().norm_squared() / l).abs() <= 1e-14,
            "{deg}"
        );
        assert!(a.tangential().dot(&rod).abs() <= 1e-14 * l, "{deg}");
        let c = v.q().unwrap();
        assert!((c - (v.a() + 0.3 * v.ab())).norm() <= 1e-15, "{deg}");
        let c2 = a.q().unwrap();
        assert!(
            (c2 - (a.a() + 0.3 * (a.b() - a.a()))).norm() <= 1e-14,
            "{deg}"
        );
        // The images are the coupler point's exact velocity and acceleration.
        let p = CouplerPoint::new(0.3).unwrap();
        assert!((c - p.derivative(&pose)).norm() <= 1e-14, "{deg}");
        assert!((c2 - p.second_derivative(&pose)).norm() <= 1e-13, "{deg}");
    }
}

#[test]
fn the_polygons_give_the_numbers_of_sections_36_and_37() {
    // The engine of §35 at 45° with the book's ω = 26.16 rad/s (V_c =
    // 13.08 ft/s): V_p = 10.347 ft/s exact (§36, printed 10.348), the
    // rod's 3.10 rad/s and −80.07 rad/s² exact (§37, printed 3.11 and
    // −80.2; docs/seed-errata.md). At 250 rpm exactly, 10.354 ft/s.
    let m = SliderCrank::in_line(0.5, 3.0).unwrap();
    let w = 26.16;
    let (v, a) = polygons(&m, 45.0, 0.5);
    let vp = -w * v.slider_velocity_ratio();
    assert!((vp - 10.347).abs() < 5e-4, "{vp}");
    let rod = w * v.rod_angular_velocity_ratio();
    assert!((rod - 3.10).abs() < 5e-3, "{rod}");
    let alpha = w * w * a.rod_angular_acceleration_ratio();
    assert!((alpha + 80.07).abs() < 5e-3, "{alpha}");
    let exact = -rpm_to_omega(250.0) * v.slider_velocity_ratio();
    assert!((exact - 10.354).abs() < 5e-4, "{exact}");
}

#[test]
fn check_passes_the_polygons_within_four_ulps_times_kappa() {
    for n in [1.02, 1.05, 2.0, 6.0, 60.0, 1e6] {
        for r in [1e-9, 1.0, 1e9] {
            let l = n * r;
            for e in [0.0, 0.9 * (l - r), -0.9 * (l - r)] {
                let m = SliderCrank::new(r, l, e).unwrap();
                let report = sweep(&m, 720);
                for (q, ulps, kappa, at) in &report.worst_ulps {
                    if POLYGON.contains(q) {
                        assert!(
                            *ulps <= 4.0,
                            "{m:?} {}: {ulps} ulps (κ {kappa}) at {at}°",
                            q.name()
                        );
                    }
                }
                for (q, _, _, count) in &report.worst {
                    if POLYGON.contains(q) {
                        assert_eq!(*count, report.poses, "{}: at every pose", q.name());
                    }
                }
            }
        }
    }
}

#[test]
fn the_acceleration_polygon_is_klein_s_figure_turned_about_c() {
    // At the scale CB = ω²r the polygon o′b′xa′ is CBFG turned through
    // 180° about C: b′ = −B, x = −F, a′ = −G (docs/polygons.md).
    for (r, l, e) in [
        (0.5, 3.0, 0.0),
        (1.0, 1.05, 0.0),
        (1.0, 4.0, 1.5),
        (1.0, 60.0, -20.0),
    ] {
        let m = SliderCrank::new(r, l, e).unwrap();
        for deg in angles() {
            let pose = m.pose(Angle::deg(deg));
            let (_, a) = polygons(&m, deg, 0.5);
            let e_line = slider_crank::construct::VelocityLine::construct(&pose);
            let kisch = slider_crank::construct::Kisch::construct(&pose, &e_line);
            let (f, g) = (kisch.points().f(), kisch.points().g());
            let tol = 1e-12 * r * (l / (l - r - e.abs())).powi(3);
            assert!((a.b() + pose.b().coords).norm() <= tol, "{l} {deg}");
            assert!(
                (a.x() + f.coords).norm() <= tol,
                "{l} {deg}: x {:?} F {f:?}",
                a.x()
            );
            assert!((a.a() + g.coords).norm() <= tol, "{l} {deg}");
        }
    }
}

#[test]
fn analyze_json_carries_the_polygons_readings() {
    use slider_crank::construct::Reading;
    let m = SliderCrank::new(1.0, 4.0, 0.5).unwrap();
    let w = 10.0;
    for deg in [0.0, 45.0, 90.0, 200.0] {
        let reading = Reading::new(&m.pose(Angle::deg(deg)), w, None, 0.0).unwrap();
        let json = reading.to_json(&m, &slider_crank::Units::default());
        let p = &json["polygons"];
        let exact = &json["analytic"];
        let close = |a: &serde_json::Value, b: &serde_json::Value, scale: f64| {
            (a.as_f64().unwrap() - b.as_f64().unwrap()).abs() <= 1e-12 * scale
        };
        assert!(close(&p["slider_velocity"], &exact["velocity"], w), "{deg}");
        assert!(
            close(&p["slider_acceleration"], &exact["acceleration"], w * w),
            "{deg}"
        );
        assert!(
            close(
                &p["rod_angular_velocity"],
                &exact["rod_angular_velocity"],
                w
            ),
            "{deg}"
        );
        assert!(
            close(
                &p["rod_angular_acceleration"],
                &exact["rod_angular_acceleration"],
                w * w
            ),
            "{deg}"
        );
        assert_eq!(p["coupler"].as_f64(), Some(0.5));
        // ob is the crank pin's velocity rω, o′b′ its acceleration ω²r.
        let b = &p["velocity"]["b"];
        let speed = b[0].as_f64().unwrap().hypot(b[1].as_f64().unwrap());
        assert!((speed - w).abs() <= 1e-12 * w, "{deg}");
    }
}

/// The position of the point `t` along AB and `h` across it (in lengths
/// AB, to the left of A → B) at θ, by hand: A = (r cos θ + w, e),
/// B = r (cos θ, sin θ), w = √(l² − (r sin θ − e)²).
fn off_rod_point(m: &SliderCrank, th: f64, t: f64, h: f64) -> Vector {
    let (r, l, e) = (m.crank(), m.rod(), m.offset());
    let w = (l * l - (r * th.sin() - e).powi(2)).sqrt();
    let a = Vector::new(r * th.cos() + w, e);
    let b = Vector::new(r * th.cos(), r * th.sin());
    let ab = b - a;
    a + ab * t + Vector::new(-ab.y, ab.x) * h
}

#[test]
fn a_point_off_the_rod_has_the_images_of_the_similar_triangles() {
    // Q = A + t (B − A) + h J(B − A): its velocity per ω is
    // A′ + t (B′ − A′) + h J(B′ − A′) with B′ = r (−sin θ, cos θ) and
    // A′ = (−r sin θ − r cos θ (r sin θ − e)/w, 0), and its acceleration
    // the same with B″ = −r (cos θ, sin θ) and A″ = (d²s/dθ², 0),
    // d²s/dθ² = −r cos θ − r² cos²θ l²/w³ + r sin θ (r sin θ − e)/w.
    // Each is also checked against central differences of the position.
    for (r, l, e) in [
        (1.0, 4.0, 0.0),
        (1.0, 3.0, 1.5),
        (0.5, 1.6, -0.9),
        (1.0, 60.0, 0.0),
    ] {
        let m = SliderCrank::new(r, l, e).unwrap();
        for (t, h) in [(0.5, 0.25), (0.0, -0.4), (1.0, 1.0), (0.3, -2.0)] {
            let q = CouplerPoint::off_rod(t, h).unwrap();
            for deg in angles() {
                let pose = m.pose(Angle::deg(deg));
                let v = VelocityPolygon::construct(&pose, Some(q));
                let acc = AccelerationPolygon::construct(&pose, &v, Some(q));
                let th = deg.to_radians();
                let (s, c) = (th.sin(), th.cos());
                let y = r * s - e;
                let w = (l * l - y * y).sqrt();
                let a1 = Vector::new(-r * s - r * c * y / w, 0.0);
                let b1 = Vector::new(-r * s, r * c);
                let a2 = Vector::new(
                    -r * c - r * r * c * c * l * l / w.powi(3) + r * s * y / w,
                    0.0,
                );
                let b2 = Vector::new(-r * c, -r * s);
                let turn = |x: Vector| Vector::new(-x.y, x.x);
                let vel = a1 + (b1 - a1) * t + turn(b1 - a1) * h;
                let accel = a2 + (b2 - a2) * t + turn(b2 - a2) * h;
                let size = r * (1.0 + h.abs()) * (l / w).powi(3);
                let got_v = v.q().unwrap();
                let got_a = acc.q().unwrap();
                assert!(
                    (got_v - vel).norm() <= 1e-12 * size,
                    "{r} {l} {e} {t} {h} {deg}"
                );
                assert!(
                    (got_a - accel).norm() <= 1e-12 * size,
                    "{r} {l} {e} {t} {h} {deg}"
                );
                // The point itself and the exact derivatives agree.
                let at = q.point(&pose);
                let hand = off_rod_point(&m, th, t, h);
                assert!((at.coords - hand).norm() <= 1e-12 * l * (1.0 + h.abs()));
                assert!((q.derivative(&pose) - vel).norm() <= 1e-12 * size);
                assert!((q.second_derivative(&pose) - accel).norm() <= 1e-12 * size);
                // Central differences of the hand-written position.
                let d = 1e-4;
                let (p0, pp, pm) = (
                    hand,
                    off_rod_point(&m, th + d, t, h),
                    off_rod_point(&m, th - d, t, h),
                );
                let fd_v = (pp - pm) / (2.0 * d);
                let fd_a = (pp - p0 * 2.0 + pm) / (d * d);
                assert!((fd_v - vel).norm() <= 1e-6 * size, "{deg}");
                assert!(
                    (fd_a - accel).norm() <= 1e-4 * size,
                    "{deg}: {fd_a} {accel}"
                );
                // Similar triangles: abq is ABQ turned and scaled alike,
                // |bq| / |ba| = |BQ| / |BA| and the same for a′b′q′.
                let ratio = ((1.0 - t).powi(2) + h * h).sqrt();
                let ab = v.b() - v.a();
                if ab.norm() > 1e-9 * r {
                    let bq = got_v - v.b();
                    assert!((bq.norm() - ratio * ab.norm()).abs() <= 1e-10 * size);
                }
            }
        }
    }
}

#[test]
fn a_point_off_the_rod_is_refused_beyond_a_hundred_rods() {
    assert!(CouplerPoint::off_rod(0.5, 100.0).is_ok());
    assert!(CouplerPoint::off_rod(0.5, 100.5).is_err());
    assert!(CouplerPoint::off_rod(0.5, f64::NAN).is_err());
    assert!(CouplerPoint::off_rod(1.5, 0.0).is_err());
    assert_eq!(
        CouplerPoint::off_rod(0.5, 0.0).unwrap(),
        CouplerPoint::new(0.5).unwrap()
    );
}

#[test]
fn analyze_json_carries_the_images_of_a_point_off_the_rod() {
    use slider_crank::construct::Reading;
    let m = SliderCrank::new(1.0, 4.0, 0.5).unwrap();
    let w = 10.0;
    for deg in [0.0, 45.0, 90.0, 200.0] {
        let pose = m.pose(Angle::deg(deg));
        let reading = Reading::new(&pose, w, None, 0.0).unwrap();
        let json = reading.to_json(&m, &slider_crank::Units::default());
        let off = &json["polygons"]["off_rod"];
        let (t, h) = (
            off["along"].as_f64().unwrap(),
            off["across"].as_f64().unwrap(),
        );
        assert_eq!((t, h), (0.5, 0.25));
        // Its velocity is the time rate of the hand-written position,
        // ω dQ/dθ, by central differences.
        let th = deg.to_radians();
        let d = 1e-5;
        let rate = (off_rod_point(&m, th + d, t, h) - off_rod_point(&m, th - d, t, h)) / (2.0 * d);
        let got = &off["velocity"];
        let got = Vector::new(got[0].as_f64().unwrap(), got[1].as_f64().unwrap());
        assert!(
            (got - rate * w).norm() <= 1e-6 * w,
            "{deg}: {got} {}",
            rate * w
        );
        let q = CouplerPoint::off_rod(t, h).unwrap();
        let acc = &off["acceleration"];
        let acc = Vector::new(acc[0].as_f64().unwrap(), acc[1].as_f64().unwrap());
        let exact = q.second_derivative(&pose) * (w * w);
        assert!((acc - exact).norm() <= 1e-12 * w * w * 4.0, "{deg}");
    }
}

#[test]
fn an_off_rod_point_s_images_are_its_motion_by_finite_differences() {
    // The images q and q′ of a point of the rod's plane off its line
    // against central differences of its place over θ (step 1e-4 rad:
    // truncation of order 1e-9 of r, rounding of 1e-8 in the second), at offsets and short rods.
    let h = 1e-4;
    for (r, l, e) in [
        (0.5, 3.0, 0.0),
        (1.0, 1.05, 0.0),
        (1.0, 4.0, 1.5),
        (1.0, 2.5, -1.2),
    ] {
        let m = SliderCrank::new(r, l, e).unwrap();
        for (t, across) in [(0.5, 0.25), (0.0, -1.0), (1.0, 3.0)] {
            let p = CouplerPoint::off_rod(t, across).unwrap();
            for k in 0..24 {
                let deg = 15.0 * f64::from(k) + 0.5;
                let at = |d: f64| {
                    let angle = Angle::from_radians(deg.to_radians() + d).unwrap();
                    p.point(&m.pose(angle)).coords
                };
                let rate = (at(h) - at(-h)) / (2.0 * h);
                let second = (at(h) - 2.0 * at(0.0) + at(-h)) / (h * h);
                let pose = m.pose(Angle::deg(deg));
                let v = VelocityPolygon::construct(&pose, Some(p));
                let a = AccelerationPolygon::construct(&pose, &v, Some(p));
                let scale = r * (1.0 + across.abs()) * (l / (l - r - e.abs())).powi(3);
                assert!(
                    (v.q().unwrap() - rate).norm() <= 1e-6 * scale,
                    "{l} {e} {deg}"
                );
                assert!(
                    (a.q().unwrap() - second).norm() <= 1e-5 * scale,
                    "{l} {e} {deg}: {:?} {second:?}",
                    a.q()
                );
            }
        }
    }
}

#[test]
fn a_scene_file_gives_a_point_off_the_rod_and_writes_it_back() {
    use slider_crank::SceneFile;
    let text = "figure = \"velocity-acceleration-polygons\"\ncoupler = [0.3, -0.4]\n";
    let scene = SceneFile::from_toml(text).unwrap().into_scene().unwrap();
    assert_eq!(scene.coupler(), CouplerPoint::off_rod(0.3, -0.4).unwrap());
    // The scene written back reads to the same point; on the rod, a number.
    let written = slider_crank::FigureName::VelocityAccelerationPolygons.scene_toml();
    assert!(written.contains("\ncoupler = 0.5\n"), "{written}");
    let back = written.replace("\ncoupler = 0.5\n", "\ncoupler = [0.3, -0.4]\n");
    let again = SceneFile::from_toml(&back).unwrap().into_scene().unwrap();
    assert_eq!(again.coupler(), scene.coupler());
    for bad in ["[0.3, 0.1, 0.2]", "[]", "[1.5, 0]", "[0.5, 101]"] {
        let text = format!("figure = \"velocity-acceleration-polygons\"\ncoupler = {bad}\n");
        let e = SceneFile::from_toml(&text)
            .and_then(|f| f.into_scene())
            .unwrap_err()
            .to_string();
        assert!(e.contains("line 2") && !e.contains('\n'), "{bad}: {e}");
    }
}

#[test]
fn the_figure_draws_a_point_off_the_rod_as_the_plate_abq_with_its_image_triangles() {
    use slider_crank::catalogue::FigureRequest;
    let mut request = FigureRequest::default();
    request.coupler = Some((0.5, 0.25));
    let name = slider_crank::FigureName::VelocityAccelerationPolygons;
    let svg = slider_crank::render::to_svg(&name.figure(&request.options(name).unwrap()).unwrap());
    for id in [
        "link-rod-plate",
        "velocity-aq",
        "velocity-bq",
        "acceleration-a2q2",
        "acceleration-b2q2",
    ] {
        assert!(svg.contains(&format!("id=\"{id}\"")), "{id}");
    }
    // Q stands where the point's formula puts it: on the page, the plate's
    // middle vertex is the marker of Q.
    let plate = crate::common::attr(&svg, "link-rod-plate", "d").unwrap();
    let q = (
        crate::common::num(&svg, "point-Q", "cx"),
        crate::common::num(&svg, "point-Q", "cy"),
    );
    assert!(
        plate.contains(&format!("L{} {}", q.0, q.1)),
        "{plate} {q:?}"
    );
    // On the rod (the default) none of them is drawn.
    let own = slider_crank::render::to_svg(&name.figure(&Default::default()).unwrap());
    assert!(!own.contains("rod-plate") && !own.contains("velocity-aq"));
}
