//! `slider-crank handout --mass`: the engine's dynamics worked on the
//! page (the inertia force from Klein's CG, the crank effort F·OM, the
//! turning-moment diagram and the flywheel), every number against the
//! formulas worked here, independently of the library; and the section
//! only where a mass is given.

use crate::command;
use crate::worked_engine;
use command::{run, succeeded};
use std::collections::BTreeMap;
use std::f64::consts::PI;
use worked_engine::{Engine, indicator};

/// Every `data-key="K" … data-value="V">TEXT<` of the page: the number
/// and the text shown.
fn values(html: &str) -> BTreeMap<String, (f64, String)> {
    let mut found = BTreeMap::new();
    let mut rest = html;
    while let Some(i) = rest.find("data-key=\"") {
        rest = &rest[i + 10..];
        let key = rest[..rest.find('"').unwrap()].to_string();
        let tag = &rest[..rest.find('>').unwrap()];
        if let Some(j) = tag.find("data-value=\"") {
            let v = &tag[j + 12..];
            let v: f64 = v[..v.find('"').unwrap()].parse().unwrap();
            let after = &rest[rest.find('>').unwrap() + 1..];
            let shown = after[..after.find('<').unwrap()].to_string();
            found.insert(key, (v, shown));
        }
    }
    found
}

/// Four significant figures and a true minus, as a page shows a number
/// between 10⁻⁴ and 10⁹.
fn four(x: f64) -> String {
    let digits = (3 - x.abs().log10().floor() as i32).max(0) as usize;
    format!("{x:.digits$}").replace('-', "−")
}

fn page(args: &[&str]) -> String {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("h.html");
    let mut all = vec!["handout", "--out", path.to_str().unwrap()];
    all.extend_from_slice(args);
    let out = run(&all);
    succeeded(&out);
    std::fs::read_to_string(&path).unwrap()
}

/// Asserts the page's `key` is `expected` to `relative` and shows it to
/// four figures.
fn check(v: &BTreeMap<String, (f64, String)>, key: &str, expected: f64, relative: f64) {
    let (value, shown) = v
        .get(key)
        .unwrap_or_else(|| panic!("{key} is not on the page"));
    assert!(
        (value - expected).abs() <= relative * expected.abs(),
        "{key}: {value} against {expected}"
    );
    assert_eq!(*shown, four(expected), "{key}: shown");
}

#[test]
fn the_dynamics_on_the_page_are_the_formulas() {
    // The §35 engine at 45° on the expansion stroke, and a longer rod at
    // 250° on the return stroke with its own speed, mass and C_s.
    let cases: [(f64, f64, f64, f64, f64, f64); 2] = [
        (0.5, 3.0, 45.0, 250.0, 10.0, 0.02),
        (1.0, 4.5, 250.0, 600.0, 3.0, 0.05),
    ];
    for (r, l, deg, rpm, m, cs) in cases {
        let text = |x: f64| format!("{x}");
        let html = page(&[
            "--crank",
            &text(r),
            "--rod",
            &text(l),
            "--angle",
            &text(deg),
            "--rpm",
            &text(rpm),
            "--mass",
            &text(m),
            "--fluctuation",
            &text(cs),
        ]);
        let v = values(&html);
        let omega = rpm * 2.0 * PI / 60.0;
        let e = Engine {
            r,
            l,
            omega,
            m,
            rows: indicator(),
            bore: 10.0 / 12.0,
        };
        let t = deg.to_radians();
        let (inertia, gas) = (e.inertia(t), e.gas(t));
        // Klein's CG is exact when drawn exactly: both to rounding.
        check(&v, "dynamics.inertia_force", inertia, 1e-12);
        check(&v, "dynamics.inertia_force_klein", inertia, 1e-9);
        check(&v, "dynamics.gas_force", gas, 1e-12);
        check(&v, "dynamics.piston_effort", gas + inertia, 1e-12);
        check(&v, "dynamics.crank_effort", e.torque(t), 1e-9);
        check(&v, "dynamics.crank_effort_exact", e.torque(t), 1e-12);
        // The inertia forces do no work over the turn: the turn's work is
        // the indicator diagram's.
        check(&v, "turn.work", e.indicated(), 1e-9);
        let (mean, fluctuation) = e.turn(200_000);
        check(&v, "turn.mean_torque", e.indicated() / (2.0 * PI), 1e-9);
        assert!((mean - e.indicated() / (2.0 * PI)).abs() < 1e-6 * mean.abs());
        check(&v, "turn.fluctuation", fluctuation, 1e-6);
        check(
            &v,
            "flywheel.inertia",
            fluctuation / (omega * omega * cs),
            1e-6,
        );
        // Not vacuous: the gas and the inertia both count at these poses.
        assert!(
            gas.abs() > 100.0 && inertia.abs() > 100.0,
            "{gas} {inertia}"
        );
        // The steps' text states the same numbers.
        for x in [inertia, gas, fluctuation / (omega * omega * cs)] {
            assert!(html.contains(&four(x)), "{} not in the text", four(x));
        }
    }
}

#[test]
fn the_dynamics_on_the_page_are_what_analyze_prints() {
    // The §35 engine on its return stroke; an offset engine with a short
    // rod past the inner dead centre; the outer dead centre (OM = 0).
    let engines: [&[&str]; 3] = [
        &["--angle", "130", "--rpm", "400", "--mass", "4"],
        &[
            "--crank", "0.5", "--rod", "2", "--offset", "0.3", "--angle", "200", "--mass", "10",
        ],
        &["--angle", "0", "--mass", "10"],
    ];
    let bore = format!("{}", 10.0f64 / 12.0);
    for engine in engines {
        let html = page(engine);
        let mut args = vec!["analyze", "--json"];
        args.extend_from_slice(engine);
        args.extend(["--indicator", "examples/indicator.csv", "--bore", &bore]);
        let out = run(&args);
        succeeded(&out);
        let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        let mut compared = 0;
        for (key, (value, _)) in values(&html) {
            if let Some(name) = key.strip_prefix("dynamics.") {
                let expected = json["dynamics"][name].as_f64().unwrap();
                assert!(
                    (value - expected).abs() <= 1e-14 * expected.abs(),
                    "{engine:?} {key}: {value} against {expected}"
                );
                compared += 1;
            }
        }
        // The six values of the four rows (read off and exact), by key.
        assert_eq!(compared, 6, "{engine:?}");
    }
}

/// The ids of the page's steps, in order.
fn steps(html: &str) -> Vec<&str> {
    html.match_indices("<section class=\"step\" id=\"step-")
        .map(|(i, s)| {
            let rest = &html[i + s.len()..];
            &rest[..rest.find('"').unwrap()]
        })
        .collect()
}

#[test]
fn the_dynamics_are_on_the_page_only_with_a_mass() {
    let plain = page(&[]);
    assert!(!plain.contains("data-key=\"dynamics."));
    assert!(!plain.contains("data-key=\"turn."));
    let with = page(&["--mass", "10"]);
    let (a, b) = (steps(&plain), steps(&with));
    assert_eq!(b[..a.len()], a[..], "the steps before the dynamics");
    assert_eq!(b[a.len()..], ["inertia", "turning-moment", "flywheel"]);
    assert_eq!(a.last(), Some(&"diagrams"));
    // Each step has its figure, named by its caption.
    for id in ["inertia", "turning-moment", "flywheel"] {
        let at = with.find(&format!("id=\"step-{id}\"")).unwrap();
        let section = &with[at..at + with[at..].find("</section>").unwrap()];
        assert_eq!(section.matches("<svg role=\"img\"").count(), 1, "{id}");
    }
    // The summary holds the dynamics' rows too, and the command gives
    // them back.
    let summary = &with[with.find("id=\"summary\"").unwrap()..];
    for key in [
        "dynamics.crank_effort",
        "turn.fluctuation",
        "flywheel.inertia",
    ] {
        assert!(summary.contains(&format!("data-key=\"{key}\"")), "{key}");
    }
    let command = with
        .replace("<span class=\"nobreak\">", "")
        .replace("</span>", "");
    assert!(command.contains("--paper a4 --mass 10 --fluctuation 0.02"));
}

#[test]
fn bad_dynamics_are_one_line_and_no_file() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("h.html");
    let out = out.to_str().unwrap();
    let cases: [(&[&str], &str); 15] = [
        (&["--mass", "0"], "mass"),
        (&["--mass", "-1"], "mass"),
        (&["--mass", "nan"], "mass"),
        (&["--mass", "10", "--fluctuation", "2"], "fluctuation"),
        (&["--fluctuation", "0.1"], "--mass"),
        (
            &["--mass", "10", "--unit", "mm"],
            "--indicator CSV with --bore D",
        ),
        (&["--mass", "10", "--class", "3"], "--class"),
        (
            &[
                "--mass",
                "1",
                "--unit",
                "mm",
                "--indicator",
                "examples/indicator.csv",
                "--bore",
                "100",
            ],
            "its pressures are in lbf/ft², but lengths in mm and forces in N need them in N/mm²",
        ),
        (
            &[
                "--mass",
                "1",
                "--unit",
                "mm",
                "--indicator",
                "examples/indicator.csv",
            ],
            "give --bore D",
        ),
        (
            &["--mass", "1", "--gas-force", "5", "--bore", "1"],
            "--bore is the bore",
        ),
        (
            &[
                "--mass",
                "1",
                "--gas-force",
                "5",
                "--indicator",
                "examples/indicator.csv",
                "--bore",
                "1",
            ],
            "not both",
        ),
        (&["--gas-force", "5"], "give --mass M with it"),
        (&["--mass", "1", "--gas-force", "inf"], "gas force"),
        (
            &[
                "--mass",
                "1",
                "--indicator",
                "examples/indicator.csv",
                "--bore",
                "-1",
            ],
            "bore",
        ),
        (
            &["--mass", "1", "--indicator", "no-such.csv", "--bore", "1"],
            "no-such.csv",
        ),
    ];
    for (args, says) in cases {
        let mut all = vec!["handout", "--out", out];
        all.extend_from_slice(args);
        let result = run(&all);
        assert_eq!(result.status.code(), Some(2), "{args:?}");
        let stderr = String::from_utf8(result.stderr).unwrap();
        assert!(stderr.contains(says), "{args:?}: {stderr}");
        assert_eq!(stderr.lines().count(), 1, "{args:?}: {stderr}");
        assert!(!stderr.contains("panicked"), "{stderr}");
        let left: Vec<_> = std::fs::read_dir(dir.path()).unwrap().collect();
        assert!(left.is_empty(), "{args:?} left {left:?}");
    }
}

/// An indicator diagram in N/mm², declared in its header, for an engine in
/// millimetres: its rows (fraction, expansion, compression) and its text.
fn si_diagram() -> (Vec<[f64; 3]>, String) {
    let rows = vec![
        [0.0, 3.0, 0.1],
        [0.1, 3.0, 0.1],
        [0.5, 0.8, 0.2],
        [1.0, 0.3, 0.6],
    ];
    let mut text = "# a test diagram\nfraction,expansion (N/mm²),compression (N/mm²)\n".to_string();
    for r in &rows {
        text.push_str(&format!("{},{},{}\n", r[0], r[1], r[2]));
    }
    (rows, text)
}

#[test]
fn an_si_handout_works_the_engines_own_diagram_and_bore() {
    let dir = tempfile::tempdir().unwrap();
    let csv = dir.path().join("diesel.csv");
    let (rows, text) = si_diagram();
    std::fs::write(&csv, text).unwrap();
    let csv = csv.to_str().unwrap();
    // r = 60 mm, l = 240 mm, 100 mm bore, 2 kg = 0.002 t (N·s²/mm) at
    // 1500 rpm, on the expansion stroke at 40° and the return at 300°.
    for deg in [40.0f64, 300.0] {
        let angle = format!("{deg}");
        let html = page(&[
            "--crank",
            "60",
            "--rod",
            "240",
            "--angle",
            &angle,
            "--rpm",
            "1500",
            "--unit",
            "mm",
            "--mass",
            "0.002",
            "--indicator",
            csv,
            "--bore",
            "100",
        ]);
        let v = values(&html);
        let omega = 1500.0 * 2.0 * PI / 60.0;
        let e = Engine {
            r: 60.0,
            l: 240.0,
            omega,
            m: 0.002,
            rows: rows.clone(),
            bore: 100.0,
        };
        let t = deg.to_radians();
        let (inertia, gas) = (e.inertia(t), e.gas(t));
        check(&v, "dynamics.inertia_force", inertia, 1e-12);
        check(&v, "dynamics.gas_force", gas, 1e-12);
        check(&v, "dynamics.crank_effort_exact", e.torque(t), 1e-12);
        check(&v, "turn.work", e.indicated(), 1e-9);
        let (_, fluctuation) = e.turn(200_000);
        check(&v, "turn.fluctuation", fluctuation, 1e-6);
        check(
            &v,
            "flywheel.inertia",
            fluctuation / (omega * omega * 0.02),
            1e-6,
        );
        assert!(
            gas.abs() > 1000.0 && inertia.abs() > 1000.0,
            "{gas} {inertia}"
        );
        // Named in the page's units, the example's nowhere.
        assert!(html.contains("N/mm<sup>2</sup>") && html.contains("t·mm<sup>2</sup>"));
        assert!(
            !html.contains("lbf") && !html.contains("10 in bore"),
            "the example's units"
        );
        assert!(html.contains("acts on a bore <i>D</i> = 100 mm"));
        assert!(html.contains("bore 100 mm"), "the figure's note");
        let command = html
            .replace("<span class=\"nobreak\">", "")
            .replace("</span>", "");
        assert!(
            command.contains(&format!("--indicator {csv} --bore 100")),
            "the command"
        );
    }
}

#[test]
fn an_si_exercise_asks_the_forces_at_its_pose() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("s.html");
    let args = [
        "handout",
        "--exercise",
        "--out",
        out.to_str().unwrap(),
        "--crank",
        "0.06",
        "--rod",
        "0.24",
        "--angle",
        "40",
        "--rpm",
        "1500",
        "--unit",
        "m",
        "--mass",
        "2",
        "--gas-force",
        "5000",
    ];
    succeeded(&run(&args));
    let sheet = std::fs::read_to_string(&out).unwrap();
    let key = std::fs::read_to_string(dir.path().join("s-key.html")).unwrap();
    let e = Engine {
        r: 0.06,
        l: 0.24,
        omega: 1500.0 * 2.0 * PI / 60.0,
        m: 2.0,
        rows: vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0]],
        bore: 1.0,
    };
    let t = 40f64.to_radians();
    let (inertia, gas) = (e.inertia(t), 5000.0);
    let phi = (0.06 * t.sin() / 0.24f64).asin();
    let torque = (gas + inertia) * 0.06 * (t.sin() + t.cos() * phi.tan());
    // The sheet gives the mass and the gas force and asks the rest, with
    // no answer on it.
    assert!(sheet.contains("= 2 kg"), "mass in kg");
    assert!(sheet.contains(&four(gas)), "the gas force given");
    assert!(
        !sheet.contains("data-key=\"dynamics."),
        "no answer on the sheet"
    );
    assert!(sheet.contains("inertia force") && sheet.contains("crank effort"));
    // The key has the answers, the formulas' values.
    let v = values(&key);
    check(&v, "dynamics.inertia_force", inertia, 1e-12);
    check(&v, "dynamics.piston_effort", gas + inertia, 1e-12);
    check(&v, "dynamics.crank_effort_exact", torque, 1e-12);
    let command = key
        .replace("<span class=\"nobreak\">", "")
        .replace("</span>", "");
    assert!(command.contains("--mass 2 --fluctuation 0.02 --gas-force 5000 --exercise"));
}
