//! Snapshots of the printed tables (reviewed against the seeds: the
//! acceleration-factor table is the textbook's digit for digit; the forces
//! table differs from Ng's Table 2 as docs/seed-errata.md explains).

use slider_crank::table::{self, Format, TEXTBOOK_ANGLES, TEXTBOOK_RATIOS};
use slider_crank::{SliderCrank, Units, rpm_to_omega};

fn settings() -> insta::Settings {
    let mut s = insta::Settings::clone_current();
    s.set_snapshot_path("../../snapshots");
    s.set_prepend_module_to_snapshot(false);
    s
}

#[test]
fn acceleration_factor_text() {
    let t = table::acceleration_factor_table(&TEXTBOOK_RATIOS, &TEXTBOOK_ANGLES).unwrap();
    settings()
        .bind(|| insta::assert_snapshot!("table-acceleration-factor", t.render(Format::Text)));
}

#[test]
fn obliquity_markdown() {
    let t = table::obliquity(&[4.0, 5.0, 6.0], 90.0).unwrap();
    settings().bind(|| insta::assert_snapshot!("table-obliquity", t.render(Format::Markdown)));
}

#[test]
fn forces_text() {
    let m = SliderCrank::in_line(25.0, 72.0).unwrap();
    let angles: Vec<f64> = (1..=16).map(|k| 10.0 * k as f64).collect();
    let t = table::forces(&m, 264.87, 1.0, &angles, 2, &Units::MILLIMETRE_NEWTON).unwrap();
    settings().bind(|| insta::assert_snapshot!("table-forces", t.render(Format::Text)));
}

#[test]
fn kinematics_csv() {
    let m = SliderCrank::in_line(0.5, 3.0).unwrap();
    let angles: Vec<f64> = (0..=12).map(|k| 30.0 * k as f64).collect();
    let t = table::kinematics(&m, rpm_to_omega(250.0), &angles, 4, &Units::FOOT_POUND).unwrap();
    settings().bind(|| insta::assert_snapshot!("table-kinematics", t.render(Format::Csv)));
}
