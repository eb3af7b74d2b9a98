//! The `figure` and `scene` subcommands.

use std::process::Command;

fn run(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_slider-crank"))
        .args(args)
        .output()
        .unwrap()
}

/// Asserts a zero exit, showing standard error otherwise.
fn succeeded(out: &std::process::Output) {
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

#[test]
fn figure_prints_svg_and_two_runs_are_identical() {
    let a = run(&["figure", "fig-67-example"]);
    assert!(a.status.success());
    assert!(a.stdout.starts_with(b"<svg"));
    let b = run(&["figure", "fig-67-example"]);
    assert_eq!(a.stdout, b.stdout);
}

#[test]
fn figure_writes_png_or_svg_files() {
    let dir = tempfile::tempdir().unwrap();
    let png = dir.path().join("f.png");
    let out = run(&["figure", "ng-fig-1-torque", "--out", png.to_str().unwrap()]);
    succeeded(&out);
    assert!(out.stdout.is_empty());
    let bytes = std::fs::read(&png).unwrap();
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n");
    let svg = dir.path().join("f.svg");
    let out = run(&[
        "figure",
        "fig-63-velocity",
        "--angle",
        "-30",
        "--layers",
        "mechanism,velocity,scales",
        "--style",
        "handout",
        "--offset",
        "0.2",
        "--out",
        svg.to_str().unwrap(),
    ]);
    succeeded(&out);
    let text = std::fs::read_to_string(&svg).unwrap();
    assert!(text.contains("\"angle_deg\":330.0"));
    assert!(text.contains("\"style\":\"handout\""));
    assert!(text.contains("\"offset\":0.2"));
}

#[test]
fn bad_input_is_one_line_on_stderr_with_exit_2_and_no_file() {
    let dir = tempfile::tempdir().unwrap();
    let out_path = dir.path().join("never.svg");
    for args in [
        vec!["figure", "fig-64"],
        vec!["figure", "fig-63-velocity", "--angle", "nan"],
        vec!["figure", "fig-63-velocity", "--rod", "0.4"],
        vec!["figure", "fig-63-velocity", "--layers", "mechanism,kisc"],
        vec!["figure", "fig-63-velocity", "--style", "ink"],
    ] {
        let mut args = args.clone();
        args.extend(["--out", out_path.to_str().unwrap()]);
        let out = run(&args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.starts_with("slider-crank: error: "), "{err}");
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(!out_path.exists());
    }
    let out = run(&[
        "figure",
        "fig-63-velocity",
        "--out",
        "/nonexistent-dir/x.svg",
    ]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("cannot write"));
}

#[test]
fn a_scene_file_typo_is_reported_with_line_and_column() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("s.toml");
    std::fs::write(
        &file,
        "name = \"s\"\nlayers = [\"mechanism\"]\nanlge = 45\n",
    )
    .unwrap();
    let out = run(&["scene", file.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("line 3, column 1") && err.contains("anlge"),
        "{err}"
    );
    assert!(out.stdout.is_empty());
    let good = run(&["scene", "examples/overlay.toml"]);
    assert!(good.status.success());
    assert!(
        String::from_utf8_lossy(&good.stdout).contains("\"angles_deg\":[30.0,120.0,210.0,300.0]")
    );
}

#[test]
fn diagrams_take_data_and_fit_flags() {
    let dir = tempfile::tempdir().unwrap();
    let data = dir.path().join("forces.csv");
    std::fs::write(&data, "# two readings\nangle,force\n45,8.5\n95,7.9\n").unwrap();
    let out = run(&[
        "figure",
        "ng-fig-8-forces",
        "--data",
        data.to_str().unwrap(),
    ]);
    succeeded(&out);
    let svg = String::from_utf8_lossy(&out.stdout);
    assert!(svg.contains("id=\"point-measured-2\"") && !svg.contains("id=\"point-measured-3\""));
    assert!(svg.contains("measured (--data)"));

    let out = run(&["figure", "ng-fig-7-calibration", "--fit", "intercept"]);
    assert!(out.status.success());
    let svg = String::from_utf8_lossy(&out.stdout);
    assert!(svg.contains("id=\"curve-fit-intercept\"") && !svg.contains("id=\"curve-fit-origin\""));

    let png = dir.path().join("bench.png");
    let out = run(&[
        "figure",
        "curve-benchmark",
        "--data",
        "docs/curve-benchmarks.csv",
        "--out",
        png.to_str().unwrap(),
    ]);
    succeeded(&out);
    assert_eq!(&std::fs::read(&png).unwrap()[..4], b"\x89PNG");
}

#[test]
fn bad_diagram_input_is_one_line_with_exit_2_and_no_file() {
    let dir = tempfile::tempdir().unwrap();
    let bad = dir.path().join("bad.csv");
    std::fs::write(&bad, "angle,force\n40,9.2\n50,seven\n").unwrap();
    let out_path = dir.path().join("never.svg");
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (
            vec!["figure", "ng-fig-8-forces", "--data", bad.to_str().unwrap()],
            "line 3",
        ),
        (
            vec!["figure", "ng-fig-8-forces", "--data", "/nonexistent/x.csv"],
            "cannot read",
        ),
        (
            vec!["figure", "ng-fig-7-calibration", "--fit", "cubic"],
            "unknown fit",
        ),
        (
            vec!["figure", "rod-motion", "--layers", "mechanism"],
            "--layers",
        ),
        (
            vec!["figure", "fig-63-velocity", "--data", bad.to_str().unwrap()],
            "--data",
        ),
        (
            vec!["figure", "approximation-error", "--rod", "4"],
            "does not use",
        ),
        (vec!["figure", "ng-fig-2-incline", "--angle", "95"], "tilt"),
        (
            vec!["figure", "fig-64-velocity-diagrams", "--omega", "-5"],
            "positive",
        ),
        (
            vec!["figure", "acceleration-diagrams", "--rod", "0.4"],
            "too short",
        ),
    ];
    for (mut args, says) in cases {
        args.extend(["--out", out_path.to_str().unwrap()]);
        let out = run(&args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.starts_with("slider-crank: error: "), "{err}");
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(err.contains(says), "{args:?}: {err}");
        assert!(!out_path.exists());
    }
    // The file named, and the bad field in it.
    let out = run(&["figure", "ng-fig-8-forces", "--data", bad.to_str().unwrap()]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("bad.csv") && err.contains("'seven'"), "{err}");
}
