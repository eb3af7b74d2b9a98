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
    let cases: [(&[&str], &str); 7] = [
        (&["--mass", "0"], "mass"),
        (&["--mass", "-1"], "mass"),
        (&["--mass", "nan"], "mass"),
        (&["--mass", "10", "--fluctuation", "2"], "fluctuation"),
        (&["--fluctuation", "0.1"], "--mass"),
        (&["--mass", "10", "--unit", "mm"], "lbf"),
        (&["--mass", "10", "--exercise"], "--exercise"),
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
