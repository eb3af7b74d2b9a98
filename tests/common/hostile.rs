//! The properties every input must keep, shared by the fuzz targets
//! (`fuzz/`, libFuzzer) and their bounded proptest twins (`tests/library/fuzz_twins.rs`):
//! no panic; a refusal is one non-empty line; a figure written has no
//! NaN or infinity in it; the numbers of an analysis are finite.

use slider_crank::analytic::statics;
use slider_crank::catalogue::FigureOptions;
use slider_crank::construct::{InstantCentre, Kisch, TorqueLine, VelocityLine};
use slider_crank::render::to_svg;
use slider_crank::{Angle, Figure, FigureName, Kinematics, SceneFile, SliderCrank};

/// The diagrams that read `--data` CSV.
pub const DATA_FIGURES: [&str; 3] = ["ng-fig-8-forces", "ng-fig-7-calibration", "curve-benchmark"];

/// A refusal: one line, not empty.
pub fn assert_one_line(message: &str) {
    assert!(!message.is_empty(), "empty error message");
    assert!(
        !message.contains('\n'),
        "error of more than one line: {message}"
    );
}

/// No token of `text` is a non-finite number as Rust or JSON writes it
/// (`NaN`, `inf`, `-inf`); the word "infinity" of "D at infinity" is prose.
pub fn assert_no_non_finite(text: &str) {
    for token in text.split(|c: char| !(c.is_ascii_alphanumeric() || c == '.')) {
        let t = token.to_ascii_lowercase();
        assert!(
            t != "nan" && t != "inf",
            "non-finite number '{token}' written"
        );
    }
}

/// Every attribute value of `svg` but ids and classes (which may carry a
/// user's text, as a scene's name may say "-inf") holds no NaN or
/// infinity; the metadata is JSON, which cannot.
pub fn assert_svg_numbers_finite(svg: &str) {
    let mut rest = svg;
    while let Some(eq) = rest.find("=\"") {
        let name_start = rest[..eq]
            .rfind(|c: char| c.is_whitespace())
            .map_or(0, |i| i + 1);
        let name = &rest[name_start..eq];
        let value_start = eq + 2;
        let Some(len) = rest[value_start..].find('"') else {
            break;
        };
        if name != "id" && name != "class" {
            assert_no_non_finite(&rest[value_start..value_start + len]);
        }
        rest = &rest[value_start + len + 1..];
    }
}

fn check_figure(figure: Result<Figure, slider_crank::Error>) {
    match figure {
        Ok(f) => assert_svg_numbers_finite(&to_svg(&f)),
        Err(e) => assert_one_line(&e.to_string()),
    }
}

/// Scene file text to a figure.
pub fn scene_toml(text: &str) {
    match SceneFile::from_toml(text).and_then(|f| f.figure()) {
        Ok(figure) => assert_svg_numbers_finite(&to_svg(&figure)),
        Err(e) => assert_one_line(&e.to_string()),
    }
}

/// A scene file for a named figure, diagram or mechanism figure alike:
/// the first line of `text` names it (a line that names none picks one by
/// the sum of its bytes, so that every figure is reached), the rest is
/// the file after its `figure = "NAME"`.
pub fn named_scene(text: &str) {
    let (first, body) = text.split_once('\n').unwrap_or((text, ""));
    let name = FigureName::from_name(first.trim()).unwrap_or_else(|_| {
        let sum: usize = first.bytes().map(usize::from).sum();
        FigureName::ALL[sum % FigureName::ALL.len()]
    });
    scene_toml(&format!("figure = \"{}\"\n{body}", name.name()));
}

/// CSV text as `--data` of one of [`DATA_FIGURES`].
pub fn csv_data(which: u8, text: &str) {
    let name = DATA_FIGURES[which as usize % DATA_FIGURES.len()];
    let mut options = FigureOptions::default();
    options.data = Some(text.to_string());
    check_figure(FigureName::from_name(name).unwrap().figure(&options));
}

/// Mechanism and angle numbers to what `analyze` computes, and to the
/// named figure `which` (an index into [`FigureName::ALL`]).
pub fn numbers(
    crank: f64,
    rod: f64,
    offset: f64,
    degrees: f64,
    omega: f64,
    torque: f64,
    which: u8,
) {
    let m = match SliderCrank::new(crank, rod, offset) {
        Ok(m) => m,
        Err(e) => return assert_one_line(&e.to_string()),
    };
    let angle = match Angle::from_degrees(degrees) {
        Ok(a) => a,
        Err(e) => return assert_one_line(&e.to_string()),
    };
    analyze(&m, angle, omega, torque);
    let name = FigureName::ALL[which as usize % FigureName::ALL.len()];
    // Ng's incline takes a tilt below 90° for its angle.
    let angle = if name.name() == "ng-fig-2-incline" {
        Angle::from_degrees(degrees.rem_euclid(90.0)).ok()
    } else {
        Some(angle)
    };
    // A figure refuses options it does not use: drop them until it takes
    // the mechanism.
    let tries = [
        (Some(m), Some(omega), angle),
        (Some(m), None, angle),
        (Some(m), Some(omega), None),
        (Some(m), None, None),
        (None, Some(omega), angle),
        (None, None, angle),
        (None, Some(omega), None),
    ];
    for (mechanism, omega, angle) in tries {
        let mut options = FigureOptions::default();
        options.mechanism = mechanism;
        options.omega = omega;
        options.angle = angle;
        let figure = name.figure(&options);
        if !matches!(&figure, Err(e) if e.to_string().contains("does not use")) {
            return check_figure(figure);
        }
    }
}

fn analyze(m: &SliderCrank, angle: Angle, omega: f64, torque: f64) {
    let pose = m.pose(angle);
    match Kinematics::new(&pose, omega) {
        Ok(k) => {
            for v in [k.position, k.velocity, k.acceleration, k.rod_angle] {
                assert!(v.is_finite(), "{k:?}");
            }
            assert!(k.rod_angular_velocity.is_finite() && k.rod_angular_acceleration.is_finite());
        }
        Err(e) => assert_one_line(&e.to_string()),
    }
    let e = VelocityLine::construct(&pose);
    let d = InstantCentre::construct(&pose);
    let kisch = Kisch::construct(&pose, &e);
    for p in [
        pose.a(),
        pose.b(),
        e.e(),
        kisch.points().f(),
        kisch.points().g(),
    ] {
        assert!(p.x.is_finite() && p.y.is_finite(), "{p:?}");
    }
    assert!(d.rod_angular_velocity_ratio().is_finite());
    assert!(e.velocity_ratio().is_finite());
    assert!(kisch.points().acceleration_ratio().is_finite());
    match statics::slider_force(&pose, torque) {
        Ok(Some(f)) => {
            assert!(f.is_finite());
            match statics::side_thrust(&pose, f) {
                Ok(s) => assert!(s.is_finite()),
                Err(e) => assert_one_line(&e.to_string()),
            }
        }
        Ok(None) => assert_eq!(statics::om(&pose), 0.0),
        Err(e) => assert_one_line(&e.to_string()),
    }
    // The torque line read off the construction: a dead centre only where
    // OM is zero, never for a force beyond the largest number.
    let line = TorqueLine::construct(&pose, &e);
    match line.slider_force(torque) {
        Ok(Some(f)) => {
            assert!(f.is_finite());
            match line.side_thrust(f) {
                Ok(s) => assert!(s.is_finite()),
                Err(e) => assert_one_line(&e.to_string()),
            }
        }
        Ok(None) => assert_eq!(line.om(), 0.0),
        Err(e) => assert_one_line(&e.to_string()),
    }
}
