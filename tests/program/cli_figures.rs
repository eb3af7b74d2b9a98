//! The `figure` and `scene` subcommands.

use crate::command;
use crate::common;
use command::{run, succeeded};
use common::metadata;

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
    assert!(svg.contains("measured (the data given)"));

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

#[test]
fn errors_about_the_data_file_name_it_and_no_others_do() {
    let dir = tempfile::tempdir().unwrap();
    let file = |name: &str, text: &str| {
        let path = dir.path().join(name);
        std::fs::write(&path, text).unwrap();
        path.to_str().unwrap().to_string()
    };
    let bad = file("bad.csv", "angle,force\n40,9.2\n50,seven\n");
    let indicator = file(
        "ind.csv",
        "fraction,expansion,compression\n0,1,1\n0.5,1,1\n",
    );
    let one = file("one.csv", "force,strain\n1,2\n");
    let good = file("good.csv", "angle,force\n40,9.2\n50,7\n");
    let cases = [
        // The data file's own errors, the indicator diagram read as a
        // figure's data among them: the path first.
        (
            vec!["figure", "ng-fig-8-forces", "--data", &bad],
            format!("{bad}: data line 3: 'seven' in column force is not a finite number"),
        ),
        (
            vec!["figure", "turning-moment", "--data", &indicator],
            format!(
                "{indicator}: data: the indicator diagram's stroke fractions rise strictly from 0 to 1"
            ),
        ),
        // The line fit through the data, and an option the figure does
        // not take, are not errors of the data file: no path.
        (
            vec!["figure", "ng-fig-7-calibration", "--data", &one],
            "a line fit needs at least 2 points, got 1".to_string(),
        ),
        (
            vec![
                "figure",
                "ng-fig-8-forces",
                "--data",
                &good,
                "--angle",
                "30",
            ],
            "ng-fig-8-forces does not use --angle".to_string(),
        ),
    ];
    for (args, says) in cases {
        let out = run(&args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        assert_eq!(
            String::from_utf8_lossy(&out.stderr),
            format!("slider-crank: error: {says}\n"),
            "{args:?}"
        );
    }
}

/// Standard output of a successful run, as text.
fn svg_of(args: &[&str]) -> String {
    let out = run(args);
    succeeded(&out);
    String::from_utf8(out.stdout).unwrap()
}

/// The text of every `<text>` element (tspans joined, superscripts set
/// as plain digits, no-break spaces as spaces), one string each.
fn texts(svg: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut rest = svg;
    while let Some(a) = rest.find("<text") {
        let b = a + rest[a..].find("</text>").unwrap();
        let inner = &rest[a..b];
        let mut plain = String::new();
        let mut in_tag = false;
        for c in inner.chars() {
            match c {
                '<' => in_tag = true,
                '>' => in_tag = false,
                c if !in_tag => plain.push(c),
                _ => {}
            }
        }
        out.push(plain.replace("&amp;", "&").replace('\u{a0}', " "));
        rest = &rest[b..];
    }
    out
}

/// The start tag of the root `<svg>` element.
fn root(svg: &str) -> &str {
    &svg[..svg.find('>').unwrap()]
}

/// Attribute `name` of a start tag.
fn attr<'a>(tag: &'a str, name: &str) -> &'a str {
    let key = format!(" {name}=\"");
    let v = tag
        .find(&key)
        .unwrap_or_else(|| panic!("no {name} in {tag}"))
        + key.len();
    &tag[v..v + tag[v..].find('"').unwrap()]
}

#[test]
fn fig_64_in_millimetres_says_mm_and_mm_per_second_everywhere() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("x.svg");
    let out = run(&[
        "figure",
        "fig-64-velocity-diagrams",
        "--crank",
        "150",
        "--rod",
        "600",
        "--unit",
        "mm",
        "--rpm",
        "1200",
        "--out",
        path.to_str().unwrap(),
    ]);
    succeeded(&out);
    let svg = std::fs::read_to_string(&path).unwrap();
    assert!(!svg.contains("ft"), "feet left in the SVG");
    // The axis title of the time base, in the metadata and on the page.
    let meta = metadata(&svg);
    assert_eq!(meta["mechanism"]["unit"], "mm");
    let y = meta["plots"][0]["y"]["title"].as_str().unwrap();
    assert!(y.contains("(mm/s)"), "{y}");
    let texts = texts(&svg);
    assert!(texts.iter().any(|t| t.contains("(mm/s)")), "{texts:?}");
    // The scale notes: r in mm, V_c in mm/s.
    let notes: Vec<&String> = texts.iter().filter(|t| t.contains("represents")).collect();
    assert!(!notes.is_empty());
    for n in notes {
        assert!(n.contains(" mm") && n.contains("mm/s"), "{n}");
    }
    // The seed's feet stay the default.
    let default = svg_of(&["figure", "fig-64-velocity-diagrams"]);
    assert!(default.contains("ft/s") && !default.contains("mm/s"));
}

#[test]
fn fig_67_notes_follow_the_unit() {
    let svg = svg_of(&[
        "figure",
        "fig-67-example",
        "--crank",
        "50",
        "--rod",
        "300",
        "--unit",
        "mm",
    ]);
    let notes: Vec<String> = texts(&svg)
        .into_iter()
        .filter(|t| t.contains("scale") || t.contains("represents"))
        .collect();
    assert!(notes.len() >= 3, "{notes:?}");
    assert!(notes.iter().any(|n| n.contains("CB = 50 mm")), "{notes:?}");
    for n in &notes {
        assert!(!n.contains(" ft"), "{n}");
    }
    assert!(notes.iter().any(|n| n.contains("mm/s2")), "{notes:?}");
    assert_eq!(metadata(&svg)["mechanism"]["unit"], "mm");
    // Ng's figure keeps millimetres and newtons unless told; forces and
    // torques follow --force-unit.
    let ng = svg_of(&["figure", "ng-fig-1-torque"]);
    assert!(texts(&ng).iter().any(|t| t.contains("N·mm")));
    let ng = svg_of(&[
        "figure",
        "ng-fig-1-torque",
        "--force-unit",
        "kN",
        "--unit",
        "m",
    ]);
    let t = texts(&ng).join("\n");
    // No length in millimetres but where the notes say whose torque it is
    // (Ng's number, N·mm on his rig, kept as a number in metres).
    let own = |l: &&str| !l.contains("Ng’s rig");
    assert!(
        t.contains("kN·m.")
            && t.contains(" kN,")
            && !t.lines().filter(own).any(|l| l.contains("mm")),
        "{t}"
    );
    assert!(t.contains("that of Ng’s rig"), "{t}");
    // Inches bring pounds-force to Ng's figure, millimetres newtons to the
    // textbook's.
    let inch = svg_of(&["figure", "ng-fig-1-torque", "--unit", "in"]);
    let t = texts(&inch).join("\n");
    assert!(t.contains("lbf·in") && !t.contains("N·in"), "{t}");
    let f = svg_of(&["figure", "ng-fig-8-forces", "--unit", "in"]);
    assert_eq!(
        metadata(&f)["plots"][0]["y"]["title"],
        "force on the slider (lbf)"
    );
    // A diagram of forces names the force unit on its axis.
    let f = svg_of(&["figure", "ng-fig-8-forces", "--force-unit", "lbf"]);
    let y = metadata(&f)["plots"][0]["y"]["title"]
        .as_str()
        .unwrap()
        .to_string();
    assert_eq!(y, "force on the slider (lbf)");
}

#[test]
fn a_scene_file_sets_the_units_of_a_diagram_and_of_a_figure() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("fig-64-mm.toml");
    std::fs::write(
        &file,
        "figure = \"fig-64-velocity-diagrams\"\nrpm = 1200\ntitle = \"Velocity diagrams in mm\"\n\n\
         [mechanism]\ncrank = 150\nrod = 600\n\n[units]\nlength = \"mm\"\n",
    )
    .unwrap();
    let svg = svg_of(&["scene", file.to_str().unwrap()]);
    assert!(!svg.contains("ft") && svg.contains("(mm/s)"));
    assert!(svg.contains("<title>Velocity diagrams in mm</title>"));
    // The command line's unit goes over the file's.
    let svg = svg_of(&["scene", file.to_str().unwrap(), "--unit", "cm"]);
    assert!(svg.contains("(cm/s)") && !svg.contains("mm/s"));
    // A mechanism figure, units in the older spelling too.
    std::fs::write(
        &file,
        "figure = \"ng-fig-1-torque\"\nforce_unit = \"kN\"\n\n[mechanism]\ncrank = 25\nrod = 72\nunit = \"in\"\n",
    )
    .unwrap();
    let t = texts(&svg_of(&["scene", file.to_str().unwrap()])).join("\n");
    assert!(t.contains("kN·in"), "{t}");
    // Both spellings at once: one line naming the new one.
    std::fs::write(
        &file,
        "[mechanism]\ncrank = 1\nrod = 3\nunit = \"in\"\n[units]\nlength = \"mm\"\n",
    )
    .unwrap();
    let out = run(&["scene", file.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("line 6") && err.contains("[units] length"),
        "{err}"
    );
    assert_eq!(err.lines().count(), 1);
}

#[test]
fn bad_unit_names_are_one_line_with_exit_2() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("s.toml");
    std::fs::write(&file, "[units]\nlength = \"m m\"\n").unwrap();
    let scene = file.to_str().unwrap();
    let cases: Vec<Vec<&str>> = vec![
        vec!["analyze", "--unit", ""],
        vec!["analyze", "--unit", "a b"],
        vec!["analyze", "--force-unit", "<b>"],
        vec!["table", "kinematics", "--unit", "*ft*"],
        vec!["figure", "fig-67-example", "--unit", "m_m"],
        vec![
            "figure",
            "fig-64-velocity-diagrams",
            "--unit",
            "millimetres-please",
        ],
        vec!["figure", "ng-fig-1-torque", "--force-unit", "N\u{7}"],
        vec!["scene", "examples/overlay.toml", "--unit", "&"],
        vec!["scene", scene],
    ];
    for args in cases {
        let out = run(&args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        assert!(out.stdout.is_empty());
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(err.contains("invalid unit name"), "{args:?}: {err}");
    }
    let err = String::from_utf8_lossy(&run(&["scene", scene]).stderr).to_string();
    assert!(err.contains("line 2, column 10"), "{err}");
}

#[test]
fn a_physical_width_gives_the_svg_a_physical_size() {
    let svg = svg_of(&["figure", "fig-67-example", "--width", "120mm"]);
    let top = root(&svg);
    assert_eq!(attr(top, "width"), "120mm");
    let view: Vec<f64> = attr(top, "viewBox")
        .split(' ')
        .map(|v| v.parse().unwrap())
        .collect();
    // Laid out 96 page units to the inch: 120 mm is 453.54 units.
    assert!((view[2] - 120.0 * 96.0 / 25.4).abs() < 0.01, "{view:?}");
    let height = attr(top, "height");
    let mm: f64 = height.strip_suffix("mm").unwrap().parse().unwrap();
    assert!(
        (mm - 120.0 * view[3] / view[2]).abs() < 0.01,
        "{height} {view:?}"
    );
    assert!((metadata(&svg)["width"].as_f64().unwrap() - view[2]).abs() < 0.01);

    // Inches, a height alone, and page units.
    let svg = svg_of(&["figure", "ng-fig-8-forces", "--width", "4.5in"]);
    assert_eq!(attr(root(&svg), "width"), "4.5in");
    assert!(attr(root(&svg), "height").ends_with("in"));
    let svg = svg_of(&["figure", "fig-62-displacement", "--height", "100mm"]);
    assert_eq!(attr(root(&svg), "width"), "201.08mm"); // 760 units
    let svg = svg_of(&["figure", "fig-63-velocity", "--width", "800"]);
    assert_eq!(attr(root(&svg), "width"), "800");
    assert!(attr(root(&svg), "viewBox").starts_with("0 0 800 "));

    // The PNG stays in pixels: 2 to the page unit.
    let dir = tempfile::tempdir().unwrap();
    let png = dir.path().join("f.png");
    let out = run(&[
        "figure",
        "fig-67-example",
        "--width",
        "120mm",
        "--out",
        png.to_str().unwrap(),
    ]);
    succeeded(&out);
    let bytes = std::fs::read(&png).unwrap();
    let width = u32::from_be_bytes(bytes[16..20].try_into().unwrap());
    assert_eq!(width, 908); // 2 × 453.54, rounded
}

#[test]
fn a_title_is_set_below_the_figure_and_in_the_svg_title() {
    let plain = svg_of(&["figure", "fig-63-velocity"]);
    let svg = svg_of(&[
        "figure",
        "fig-63-velocity",
        "--title",
        "Fig. 63 & the velocity of *A*",
    ]);
    assert!(svg.contains("<title>Fig. 63 &amp; the velocity of A</title>"));
    assert!(texts(&svg).contains(&"Fig. 63 & the velocity of A".to_string()));
    let (h0, h1) = (
        attr(root(&plain), "height").parse::<f64>().unwrap(),
        attr(root(&svg), "height").parse::<f64>().unwrap(),
    );
    assert_eq!(h1, h0 + 30.0);
    assert_eq!(metadata(&svg)["title"], "Fig. 63 & the velocity of A");
    assert!(!plain.contains("<title>"));
    // Diagrams take a title too.
    let d = svg_of(&["figure", "rod-motion", "--title", "Rod"]);
    assert!(d.contains("<title>Rod</title>") && d.contains("id=\"title\""));
}

/// The page x of world point `p` under the map `t` (a b c d e f).
fn page_x(t: &serde_json::Value, p: &serde_json::Value) -> f64 {
    let t: Vec<f64> = t
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_f64().unwrap())
        .collect();
    let (x, y) = (p[0].as_f64().unwrap(), p[1].as_f64().unwrap());
    t[0] * x + t[2] * y + t[4]
}

#[test]
fn mirror_reflects_the_page_and_notation_changes_the_letters() {
    // Ng's figure is drawn with the slider right of the crank centre;
    // mirrored, left of it.
    for (args, right) in [
        (vec!["figure", "ng-fig-1-torque"], true),
        (vec!["figure", "ng-fig-1-torque", "--mirror"], false),
        (vec!["figure", "fig-63-velocity"], false),
        (vec!["figure", "fig-63-velocity", "--no-mirror"], true),
    ] {
        let meta = metadata(&svg_of(&args));
        let t = &meta["page_from_world"];
        let points = &meta["points"];
        let (slider, centre) = if points.get("P").is_some() {
            (&points["P"], &points["O"])
        } else {
            (&points["A"], &points["C"])
        };
        assert_eq!(
            page_x(t, slider) > page_x(t, centre),
            right,
            "{args:?}: {t}"
        );
        assert_eq!(meta["mirrored"], !right, "{args:?}");
    }
    // The same pose, reflected: the crank pin's page x about the crank
    // centre's changes sign.
    let a = metadata(&svg_of(&["figure", "ng-fig-a1-velocity"]));
    let b = metadata(&svg_of(&["figure", "ng-fig-a1-velocity", "--mirror"]));
    let dx = |m: &serde_json::Value| {
        page_x(&m["page_from_world"], &m["points"]["C"])
            - page_x(&m["page_from_world"], &m["points"]["O"])
    };
    assert!(dx(&a) > 0.0 && dx(&b) < 0.0, "{} {}", dx(&a), dx(&b));
    // A diagram drawn on the mechanism mirrors too.
    let m = metadata(&svg_of(&["figure", "coupler-curves", "--no-mirror"]));
    assert!(m["page_from_world"][0].as_f64().unwrap() > 0.0);

    // Ng's letters on a textbook figure, and the textbook's on Ng's.
    let svg = svg_of(&["figure", "fig-63-velocity", "--notation", "ng"]);
    let letters = texts(&svg);
    for l in ["O", "C", "P", "I", "M"] {
        assert!(letters.iter().any(|t| t == l), "{l}: {letters:?}");
    }
    assert!(!letters.iter().any(|t| t == "E" || t == "A"), "{letters:?}");
    assert_eq!(metadata(&svg)["notation"], "ng");
    let svg = svg_of(&["figure", "ng-fig-1-torque", "--notation", "textbook"]);
    assert!(svg.contains("id=\"line-CE\"") && !svg.contains("id=\"line-OM\""));
}

#[test]
fn bad_page_sizes_titles_and_letters_are_one_line_with_exit_2() {
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (vec!["--width", "-3mm"], "not positive"),
        (vec!["--width", "12parsecs"], "unknown unit"),
        (vec!["--width", "NaN"], "not a finite number"),
        (vec!["--height", "nanmm"], "not a finite number"),
        (vec!["--width", "inf"], "not a finite number"),
        (vec!["--width", "0"], "not positive"),
        (vec!["--width", "twelve"], "invalid page length"),
        (vec!["--width", "0.1in"], "between 50 and 20000"),
        (vec!["--height", "6m"], "invalid page length"),
        (vec!["--title", ""], "invalid title"),
        (vec!["--notation", "greek"], "unknown notation"),
    ];
    for (flags, says) in cases {
        let mut args = vec!["figure", "fig-63-velocity"];
        args.extend(flags);
        let out = run(&args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        assert!(out.stdout.is_empty());
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(err.contains(says), "{args:?}: {err}");
    }
    // Diagrams without a mechanism drawing refuse --mirror; no diagram
    // takes --notation.
    for args in [
        vec!["figure", "rod-motion", "--mirror"],
        vec!["figure", "fig-64-velocity-diagrams", "--notation", "ng"],
    ] {
        let out = run(&args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains("does not use --"), "{err}");
    }
}

/// A height asked for is held: the figure ends within it (a short one
/// stays shorter), and one whose detail and notes need more is refused in
/// one line naming the height it needs, which is then enough.
#[test]
fn a_height_asked_for_is_never_exceeded() {
    let height = |svg: &str| -> f64 { attr(root(svg), "height").parse().unwrap() };
    for (name, asked) in [
        ("fig-62-displacement", "200"),
        ("fig-62-displacement", "600"),
        ("ng-fig-1-torque", "700"),
        ("fig-67-example", "1000"),
    ] {
        let svg = svg_of(&["figure", name, "--height", asked]);
        let h = height(&svg);
        assert!(
            h <= asked.parse::<f64>().unwrap() + 0.5,
            "{name} at {asked}: {h}"
        );
    }
    let out = run(&[
        "figure",
        "fig-67-example",
        "--width",
        "800",
        "--height",
        "300",
    ]);
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stdout.is_empty());
    let err = String::from_utf8(out.stderr).unwrap();
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.contains("page height = 300"), "{err}");
    let needed: f64 = err
        .split("needs ")
        .nth(1)
        .and_then(|t| t.split(' ').next())
        .and_then(|n| n.parse().ok())
        .unwrap_or_else(|| panic!("no height named: {err}"));
    assert!(needed > 300.0, "{err}");
    let asked = format!("{needed}");
    let svg = svg_of(&[
        "figure",
        "fig-67-example",
        "--width",
        "800",
        "--height",
        &asked,
    ]);
    assert!(height(&svg) <= needed + 0.5);
}
