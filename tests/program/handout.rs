//! `slider-crank handout`: the page works the same numbers `analyze`
//! prints, is one self-contained printable file; exercise sheets for a
//! class are reproducible from their seed and hold no answer; bad input
//! leaves no file.

use crate::command;
use command::{run, succeeded};
use serde_json::Value;
use std::collections::BTreeSet;
use std::path::Path;

/// Every `data-key="K" … data-value="V"` pair of the page, in order.
fn values(html: &str) -> Vec<(String, f64)> {
    let mut found = Vec::new();
    let mut rest = html;
    while let Some(i) = rest.find("data-key=\"") {
        rest = &rest[i + 10..];
        let end = rest.find('"').unwrap();
        let key = rest[..end].to_string();
        let tag_end = rest.find('>').unwrap();
        let tag = &rest[..tag_end];
        if let Some(j) = tag.find("data-value=\"") {
            let v = &tag[j + 12..];
            let v = &v[..v.find('"').unwrap()];
            found.push((key, v.parse::<f64>().unwrap_or_else(|_| panic!("{v}"))));
        }
        rest = &rest[end..];
    }
    found
}

/// The number at a dotted path of the JSON (`graphical.velocity`).
fn at<'a>(json: &'a Value, key: &str) -> Option<&'a Value> {
    key.split('.').try_fold(json, |v, k| v.get(k))
}

fn read(path: &Path) -> String {
    std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// Every value of the page that `analyze --json` also gives equals it (to
/// the last digits: serde_json's default float parsing may be an ulp or
/// two off the number written); the lengths of the constructions are the coordinates of E and
/// G. Returns how many were compared.
fn agrees_with_analyze(html: &str, json: &Value) -> usize {
    let mut compared = 0;
    for (key, value) in values(html) {
        let expected = match key.as_str() {
            "construction.CE" => json["points"]["E"][1].as_f64(),
            "construction.CG" => json["points"]["G"][0].as_f64(),
            _ => at(json, &key).and_then(Value::as_f64),
        };
        if let Some(expected) = expected {
            assert!(
                (value - expected).abs() <= 1e-14 * expected.abs(),
                "{key}: {value} against {expected}"
            );
            compared += 1;
        }
    }
    compared
}

/// The analyze JSON for the engine a page states (its data cells).
fn analyze_for(html: &str, extra: &[&str]) -> Value {
    let data: std::collections::BTreeMap<String, f64> = values(html).into_iter().collect();
    let text = |k: &str| format!("{}", data[k]);
    let (crank, rod, offset, angle, omega) = (
        text("mechanism.crank"),
        text("mechanism.rod"),
        text("mechanism.offset"),
        text("angle_deg"),
        text("omega"),
    );
    let mut args = vec![
        "analyze", "--json", "--crank", &crank, "--rod", &rod, "--offset", &offset, "--angle",
        &angle, "--omega", &omega,
    ];
    args.extend_from_slice(extra);
    let out = run(&args);
    succeeded(&out);
    serde_json::from_slice(&out.stdout).unwrap()
}

#[test]
fn the_handout_shows_the_numbers_analyze_prints() {
    let dir = tempfile::tempdir().unwrap();
    // The §35 engine; an offset engine with forces; a short rod (n = 1.5)
    // past the inner dead centre; an offset below the crank centre.
    let engines: [&[&str]; 4] = [
        &[
            "--crank", "0.5", "--rod", "3", "--angle", "45", "--rpm", "250",
        ],
        &[
            "--crank",
            "60",
            "--rod",
            "210",
            "--offset",
            "10",
            "--angle",
            "40",
            "--unit",
            "mm",
            "--torque",
            "2000",
            "--friction",
            "0.2",
        ],
        &[
            "--crank", "1", "--rod", "1.5", "--angle", "200", "--omega", "10", "--torque", "5",
        ],
        &[
            "--crank",
            "2",
            "--rod",
            "7",
            "--offset",
            "-0.5",
            "--angle",
            "300",
            "--rpm",
            "1200",
            "--torque",
            "-3",
            "--friction",
            "1",
        ],
    ];
    for (i, engine) in engines.iter().enumerate() {
        let page = dir.path().join(format!("h{i}.html"));
        let mut args = vec!["handout", "--out", page.to_str().unwrap()];
        args.extend_from_slice(engine);
        let out = run(&args);
        succeeded(&out);
        assert!(out.stdout.is_empty());
        let html = read(&page);
        let statics: Vec<&str> = engine
            .windows(2)
            .filter(|w| w[0] == "--torque" || w[0] == "--friction")
            .flatten()
            .copied()
            .collect();
        let json = analyze_for(&html, &statics);
        let compared = agrees_with_analyze(&html, &json);
        // The data (5), the exact values (6), the values read off the
        // constructions (4), CE and CG; and the statics (5) with a torque.
        let least = if statics.is_empty() { 17 } else { 22 };
        assert!(
            compared >= least,
            "{engine:?}: only {compared} values compared"
        );
        for key in [
            "graphical.velocity",
            "graphical.acceleration",
            "graphical.rod_angular_velocity",
            "graphical.rod_angular_acceleration",
            "analytic.velocity",
        ] {
            assert!(html.contains(&format!("data-key=\"{key}\"")), "{key}");
        }
    }
}

/// What a self-contained page must not have.
fn assert_self_contained(html: &str, name: &str) {
    for bad in [
        "http:", "https:", "src=", "<link", "<script", "@import", "url(http",
    ] {
        assert!(!html.contains(bad), "{name} holds {bad}");
    }
    assert!(html.contains("<svg"), "{name} has its figures inlined");
}

/// The page's style sheet.
fn style(html: &str) -> &str {
    let from = html.find("<style>").unwrap();
    let to = html.find("</style>").unwrap();
    &html[from..to]
}

/// Asserts that every selector in `blocks` is in a rule that keeps it on
/// one page.
fn assert_unbroken(css: &str, blocks: &[&str]) {
    let rules: Vec<&str> = css
        .split('}')
        .filter(|r| r.contains("break-inside: avoid"))
        .collect();
    for block in blocks {
        assert!(
            rules.iter().any(|r| r
                .split('{')
                .next()
                .unwrap()
                .split(',')
                .any(|s| s.trim() == *block)),
            "{block} may break across pages"
        );
    }
}

#[test]
fn the_page_is_self_contained_and_prints_whole_figures_on_the_paper_asked_for() {
    let dir = tempfile::tempdir().unwrap();
    for (paper, size) in [(None, "size: A4"), (Some("letter"), "size: letter")] {
        let page = dir.path().join("page.html");
        // The handout, then an exercise sheet and its key.
        for exercise in [false, true] {
            let mut args = vec!["handout", "--out", page.to_str().unwrap(), "--torque", "10"];
            if let Some(p) = paper {
                args.extend_from_slice(&["--paper", p]);
            }
            if exercise {
                args.push("--exercise");
            }
            succeeded(&run(&args));
            if !exercise {
                let html = read(&page);
                assert!(html.contains("The slider-crank engine, worked through"));
                for step in [
                    "Kisch's construction",
                    "The OM line and the forces",
                    "The velocity scale",
                ] {
                    assert!(html.contains(step), "{step}");
                }
            }
            let mut pages = vec![page.clone()];
            if exercise {
                pages.push(dir.path().join("page-key.html"));
            }
            for p in pages {
                let html = read(&p);
                let name = p.display().to_string();
                assert_self_contained(&html, &name);
                let css = style(&html);
                assert!(css.contains("@page") && css.contains(size), "{name}: {css}");
                assert_unbroken(css, &["figure", "table", ".block"]);
                assert!(html.contains("<figure>") && html.contains("<table"));
                // No two elements share an id.
                let mut ids = BTreeSet::new();
                let mut rest = html.as_str();
                while let Some(i) = rest.find(" id=\"") {
                    rest = &rest[i + 5..];
                    let id = &rest[..rest.find('"').unwrap()];
                    assert!(ids.insert(id.to_string()), "{name}: id {id} twice");
                }
            }
        }
    }
}

/// The files of a directory, by name.
fn files(dir: &Path) -> std::collections::BTreeMap<String, Vec<u8>> {
    std::fs::read_dir(dir)
        .unwrap()
        .map(|e| {
            let e = e.unwrap();
            (
                e.file_name().into_string().unwrap(),
                std::fs::read(e.path()).unwrap(),
            )
        })
        .collect()
}

fn class(dir: &Path, seed: &str) -> std::process::Output {
    let out = dir.join("sheet.html");
    run(&[
        "handout",
        "--exercise",
        "--class",
        "30",
        "--seed",
        seed,
        "--unit",
        "mm",
        "--out",
        out.to_str().unwrap(),
    ])
}

#[test]
fn a_class_is_thirty_distinct_sheets_with_keys_the_same_for_the_same_seed() {
    let (one, again, two) = (
        tempfile::tempdir().unwrap(),
        tempfile::tempdir().unwrap(),
        tempfile::tempdir().unwrap(),
    );
    let out = class(one.path(), "1");
    succeeded(&out);
    let stderr = String::from_utf8(out.stderr).unwrap();
    assert!(stderr.contains("handout: 1/61 "), "{stderr}");
    assert!(stderr.contains("handout: 61/61 "), "{stderr}");
    let made = files(one.path());
    assert_eq!(made.len(), 61, "{:?}", made.keys());
    let sheets: BTreeSet<&Vec<u8>> = (1..=30)
        .map(|k| &made[&format!("sheet-{k:02}.html")])
        .collect();
    assert_eq!(sheets.len(), 30, "30 different sheets");
    assert!(made.contains_key("sheet-answers.html"));

    // The same seed: the same bytes; another seed: other engines.
    succeeded(&class(again.path(), "1"));
    assert_eq!(made, files(again.path()));
    succeeded(&class(two.path(), "2"));
    let other = files(two.path());
    assert_eq!(other.len(), 61);
    assert!((1..=30).all(|k| {
        let name = format!("sheet-{k:02}.html");
        made[&name] != other[&name]
    }));

    let answers = String::from_utf8(made["sheet-answers.html"].clone()).unwrap();
    for k in 1..=30 {
        let sheet = String::from_utf8(made[&format!("sheet-{k:02}.html")].clone()).unwrap();
        let key = String::from_utf8(made[&format!("sheet-{k:02}-key.html")].clone()).unwrap();
        assert_self_contained(&sheet, "sheet");
        assert_self_contained(&key, "key");
        assert!(sheet.contains(&format!("Exercise {k}")));
        // The sheet draws the mechanism on a grid, no construction.
        assert!(sheet.contains("id=\"sheet-grid\"") && sheet.contains("sheet-link-rod"));
        for drawn in ["point-D", "point-E", "line-CE", "note-scales", "detail-"] {
            assert!(!sheet.contains(drawn), "sheet {k} draws {drawn}");
        }
        // The key agrees with analyze for its engine.
        let json = analyze_for(&key, &[]);
        assert!(agrees_with_analyze(&key, &json) >= 17);
        // The sheet holds no answer: no value but the data, and none of
        // the key's numbers.
        for (name, value) in values(&sheet) {
            assert!(
                !["analytic.", "graphical.", "construction.", "statics."]
                    .iter()
                    .any(|p| name.starts_with(p)),
                "sheet {k} gives {name}"
            );
            let _ = value;
        }
        for (name, value) in values(&key) {
            if name.starts_with("graphical.") || name.starts_with("analytic.") {
                let text = format!("{value}");
                assert!(!sheet.contains(&text), "sheet {k} holds {name} = {text}");
            }
        }
        // The teacher's table has the engine's velocity read off CE.
        let (_, v) = values(&key)
            .into_iter()
            .find(|(name, _)| name == "graphical.velocity")
            .unwrap();
        assert!(answers.contains(&format!("data-value=\"{v}\"")), "{k}");
    }
}

#[test]
fn bad_input_is_one_line_a_failure_and_no_file() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("h.html");
    let out = out.to_str().unwrap();
    let missing = dir.path().join("no/such/dir/h.html");
    let missing = missing.to_str().unwrap();
    let cases: [&[&str]; 6] = [
        &["handout", "--exercise", "--class", "0", "--out", out],
        &["handout", "--crank", "1", "--rod", "0.5", "--out", out],
        &["handout", "--out", missing],
        &["handout", "--exercise", "--out", missing],
        &[
            "handout", "--class", "3", "--crank", "2", "--rod", "1", "--out", out,
        ],
        &["handout", "--out", &out.replace(".html", ".pdf")],
    ];
    for args in cases {
        let result = run(args);
        assert!(!result.status.success(), "{args:?}");
        assert_eq!(result.status.code(), Some(2), "{args:?}");
        assert!(result.stdout.is_empty());
        let stderr = String::from_utf8(result.stderr).unwrap();
        assert_eq!(stderr.lines().count(), 1, "{args:?}: {stderr}");
        assert!(!stderr.contains("panicked"), "{stderr}");
        let left: Vec<_> = std::fs::read_dir(dir.path()).unwrap().collect();
        assert!(left.is_empty(), "{args:?} left {left:?}");
    }
}

#[test]
fn millimetres_bring_newtons_to_the_sheet_and_the_handout() {
    // Issue 22: `--unit mm` with a torque once printed lbf·mm.
    let dir = tempfile::tempdir().unwrap();
    let page = dir.path().join("page.html");
    let base = [
        "handout",
        "--crank",
        "60",
        "--rod",
        "240",
        "--rpm",
        "1500",
        "--angle",
        "30",
        "--unit",
        "mm",
        "--torque",
        "5000",
        "--friction",
        "0.1",
        "--out",
    ];
    let mut args = base.to_vec();
    args.push(page.to_str().unwrap());
    succeeded(&run(&args));
    let html = read(&page);
    assert!(html.contains("N·mm") && !html.contains("lbf"), "{html}");
    args.push("--exercise");
    succeeded(&run(&args));
    let sheet = read(&page);
    assert!(
        sheet.contains("Lengths in mm, forces in N.") && !sheet.contains("lbf"),
        "{sheet}"
    );
}

#[test]
fn every_drawing_of_a_page_is_an_image_named_by_its_caption() {
    let dir = tempfile::tempdir().unwrap();
    let page = dir.path().join("page.html");
    let out = page.to_str().unwrap();
    succeeded(&run(&[
        "handout",
        "--torque",
        "10",
        "--exercise",
        "--out",
        out,
    ]));
    succeeded(&run(&[
        "handout",
        "--out",
        out.replace("page", "whole").as_str(),
    ]));
    for name in ["page.html", "page-key.html", "whole.html"] {
        let html = read(&dir.path().join(name));
        let roots: Vec<&str> = html.split("<svg").skip(1).collect();
        assert!(!roots.is_empty(), "{name}");
        for root in roots {
            let tag = &root[..root.find('>').unwrap()];
            assert!(tag.contains("role=\"img\""), "{name}: {tag}");
            let label = tag.split("aria-label=\"").nth(1).unwrap_or("");
            assert!(
                label.starts_with("Figure ") || label.starts_with("Drawing."),
                "{name}: {tag}"
            );
            assert!(label.len() > 20, "{name}: {tag}");
        }
    }
}

#[test]
fn the_steps_sign_what_the_tables_sign_and_the_command_gives_rpm() {
    // Issue 22's engine: FG and the rod's angular acceleration are
    // negative at 30°, the footer once wrote --omega 157.0796…
    let dir = tempfile::tempdir().unwrap();
    let page = dir.path().join("page.html");
    succeeded(&run(&[
        "handout",
        "--crank",
        "60",
        "--rod",
        "240",
        "--rpm",
        "1500",
        "--angle",
        "30",
        "--unit",
        "mm",
        "--out",
        page.to_str().unwrap(),
    ]));
    let html = read(&page);
    let step = html
        .split("<p")
        .find(|p| p.contains("gives its angular acceleration"))
        .expect("the step of FG");
    let values: std::collections::BTreeMap<String, f64> = values(&html).into_iter().collect();
    let fg = values["construction.FG"];
    assert!(fg < 0.0, "{fg}");
    let shown = |x: f64| format!("{:.2}", x).replace('-', "−");
    assert!(step.contains(&format!("= {} mm", shown(fg))), "{step}");
    assert!(step.contains("= −"), "{step}");
    // The footer's command, its options each kept whole on a printed line.
    let command = html
        .replace("<span class=\"nobreak\">", "")
        .replace("</span>", "");
    assert!(
        html.contains("<span class=\"nobreak\">--rpm 1500</span>"),
        "footer"
    );
    assert!(
        command.contains("--rpm 1500 ") && !command.contains("--omega"),
        "footer"
    );
    // The caption of the engine says where x is measured from, as the
    // table does.
    assert!(
        !html.contains("from mid-stroke.") && html.contains("distance from the crank centre"),
        "caption"
    );
}

#[test]
fn a_sheet_is_drawn_at_the_round_scale_it_states() {
    let dir = tempfile::tempdir().unwrap();
    let page = dir.path().join("sheet.html");
    for (engine, unit_mm) in [
        (&["--crank", "60", "--rod", "240", "--unit", "mm"][..], 1.0),
        (&["--crank", "0.5", "--rod", "2.5"][..], 304.8),
    ] {
        let mut args = vec!["handout", "--exercise", "--angle", "40"];
        args.extend_from_slice(engine);
        args.extend(["--out", page.to_str().unwrap()]);
        succeeded(&run(&args));
        let html = read(&page);
        let stated = html.split("Drawn at 1:").nth(1).expect("a stated scale");
        let ratio: f64 = stated[..stated.find(' ').unwrap()].parse().unwrap();
        let svg = &html[html.find("<svg").unwrap()..];
        let root = &svg[..svg.find('>').unwrap()];
        let width: f64 = root
            .split("style=\"width: ")
            .nth(1)
            .unwrap()
            .split("mm")
            .next()
            .unwrap()
            .parse()
            .unwrap();
        let view: Vec<f64> = root
            .split("viewBox=\"")
            .nth(1)
            .unwrap()
            .split('"')
            .next()
            .unwrap()
            .split(' ')
            .map(|v| v.parse().unwrap())
            .collect();
        let map = svg.split("\"page_from_world\":[").nth(1).unwrap();
        let m: Vec<f64> = map[..map.find(']').unwrap()]
            .split(',')
            .map(|v| v.parse().unwrap())
            .collect();
        let per_unit = m[0].hypot(m[1]);
        // Paper millimetres per millimetre of the engine.
        let drawn = width / view[2] * per_unit / unit_mm;
        assert!(
            (drawn * ratio - 1.0).abs() < 1e-4, // to the digits the page writes
            "1:{ratio} against 1:{}",
            1.0 / drawn
        );
        assert!(width <= 180.0 + 1e-9, "{width} mm");
    }
}

#[test]
fn an_exercise_whose_key_cannot_be_written_keeps_the_old_sheet() {
    // The sheet and its key are written both or neither: a key that
    // cannot be written leaves the old sheet, not a new sheet without its
    // key (the sheet was replaced before the key failed).
    let dir = tempfile::tempdir().unwrap();
    let sheet = dir.path().join("sheet.html");
    std::fs::write(&sheet, "old sheet").unwrap();
    std::fs::create_dir(dir.path().join("sheet-key.html")).unwrap();
    let result = run(&["handout", "--exercise", "--out", sheet.to_str().unwrap()]);
    assert_eq!(result.status.code(), Some(2));
    let stderr = String::from_utf8(result.stderr).unwrap();
    assert!(
        stderr.ends_with("sheet-key.html: it is a directory\n"),
        "{stderr}"
    );
    assert_eq!(read(&sheet), "old sheet");
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 2);
}

#[test]
fn a_class_varies_the_teachers_own_engine() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("c.html");
    let args = [
        "handout",
        "--class",
        "12",
        "--seed",
        "5",
        "--crank",
        "60",
        "--rod",
        "240",
        "--offset",
        "-15",
        "--unit",
        "mm",
        "--out",
        out.to_str().unwrap(),
    ];
    succeeded(&run(&args));
    let mut cranks = BTreeSet::new();
    for i in 1..=12 {
        let key = read(&dir.path().join(format!("c-{i:02}-key.html")));
        let v: std::collections::BTreeMap<String, f64> = values(&key).into_iter().collect();
        let (r, l, e) = (
            v["mechanism.crank"],
            v["mechanism.rod"],
            v["mechanism.offset"],
        );
        // A variation of r = 60, n = 4, e/r = −0.25 within the stated
        // bounds, to the four figures a sheet prints; and it assembles.
        assert!(
            (0.8 * 60.0 - 0.05..=1.2 * 60.0 + 0.05).contains(&r),
            "{i}: r = {r}"
        );
        assert!(
            (0.9 * 4.0 - 1e-3..=1.1 * 4.0 + 1e-3).contains(&(l / r)),
            "{i}: n = {}",
            l / r
        );
        assert!((e / r + 0.25).abs() < 1e-3, "{i}: e = {e}");
        assert!(l > r + e.abs(), "{i}: assembles");
        // The sheet works the very engine its key does.
        let sheet = read(&dir.path().join(format!("c-{i:02}.html")))
            .replace("<span class=\"nobreak\">", "")
            .replace("</span>", "");
        assert!(
            sheet.contains(&format!("--crank {r} --rod {l} --offset {e}")),
            "{i}"
        );
        cranks.insert(r.to_bits());
    }
    assert!(cranks.len() >= 3, "the crank varies");
}

#[test]
fn the_handout_works_the_polygons_against_the_hand_formulas() {
    // An offset engine past the inner dead centre: r = 2, l = 7,
    // e = −0.5 at θ = 300°, 1200 rpm. With h = r sin θ − e and
    // w = √(l² − h²): the piston's velocity ω(−r sin θ − r cos θ h/w),
    // its acceleration ω²(−r cos θ − r² cos²θ l²/w³ + r sin θ h/w), the
    // rod's sin φ = h/l so dφ/dt = ω r cos θ/w and
    // d²φ/dt² = ω² (−r sin θ/w + r² cos²θ h/w³).
    let dir = tempfile::tempdir().unwrap();
    let page = dir.path().join("h.html");
    let out = run(&[
        "handout",
        "--out",
        page.to_str().unwrap(),
        "--crank",
        "2",
        "--rod",
        "7",
        "--offset",
        "-0.5",
        "--angle",
        "300",
        "--rpm",
        "1200",
    ]);
    succeeded(&out);
    let html = read(&page);
    assert!(html.contains("id=\"step-polygons\""));
    let (r, l, e) = (2.0_f64, 7.0_f64, -0.5_f64);
    let om = 1200.0 * std::f64::consts::TAU / 60.0;
    let th = 300.0_f64.to_radians();
    let (s, c) = (th.sin(), th.cos());
    let h = r * s - e;
    let w = (l * l - h * h).sqrt();
    let expected = [
        ("polygons.slider_velocity", om * (-r * s - r * c * h / w)),
        (
            "polygons.slider_acceleration",
            om * om * (-r * c - r * r * c * c * l * l / w.powi(3) + r * s * h / w),
        ),
        ("polygons.rod_angular_velocity", om * r * c / w),
        (
            "polygons.rod_angular_acceleration",
            om * om * (-r * s / w + r * r * c * c * h / w.powi(3)),
        ),
    ];
    let found = values(&html);
    for (key, want) in expected {
        let got: Vec<f64> = (found.iter())
            .filter(|(k, _)| k == key)
            .map(|(_, v)| *v)
            .collect();
        assert!(!got.is_empty(), "{key} not on the page");
        for v in got {
            assert!(
                (v - want).abs() <= 1e-9 * want.abs().max(1.0),
                "{key}: {v} against {want}"
            );
        }
    }
}
