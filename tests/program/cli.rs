//! The command line: the contract of docs/design.md §4 and clear errors.

use serde_json::Value;
use std::path::Path;
use std::process::{Command, Output};

fn run(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_slider-crank"))
        .args(args)
        .output()
        .expect("the binary runs")
}

fn json(args: &[&str]) -> Value {
    let out = run(args);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).expect("valid JSON")
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs().max(1e-300)
}

#[test]
fn analyze_json_matches_the_exact_formulas() {
    // §35 engine at 45°, 250 rpm: closed forms of the textbook.
    let v = json(&[
        "analyze", "--crank", "0.5", "--rod", "3", "--angle", "45", "--rpm", "250", "--json",
    ]);
    let w = 250.0 * 2.0 * std::f64::consts::PI / 60.0;
    let (r, n) = (0.5f64, 6.0f64);
    let s = 0.5f64.sqrt();
    let q = (n * n - s * s).sqrt();
    let a = &v["analytic"];
    assert!(rel(a["position"].as_f64().unwrap(), r * s + r * q) < 1e-12);
    assert!(rel(a["velocity"].as_f64().unwrap(), -r * w * (s + s * s / q)) < 1e-12);
    let acc = -r * w * w * (s + s.powi(4) / (n * n - s * s).powf(1.5));
    assert!(rel(a["acceleration"].as_f64().unwrap(), acc) < 1e-12);
    assert!(rel(a["rod_angular_velocity"].as_f64().unwrap(), w * s / q) < 1e-12);
    let rod_acc = -w * w * s / q * (n * n - 1.0) / (n * n - s * s);
    assert!(rel(a["rod_angular_acceleration"].as_f64().unwrap(), rod_acc) < 1e-12);
    assert!(
        rel(
            a["rod_angle_deg"].as_f64().unwrap(),
            (s / n).asin().to_degrees()
        ) < 1e-12
    );
    assert_eq!(v["angle_deg"], 45.0);
    assert!(rel(v["omega"].as_f64().unwrap(), w) < 1e-15);
    // graphical agrees with analytic.
    for key in [
        "velocity",
        "acceleration",
        "rod_angular_velocity",
        "rod_angular_acceleration",
    ] {
        let g = v["graphical"][key].as_f64().unwrap();
        assert!(rel(g, a[key].as_f64().unwrap()) < 1e-12, "{key}");
    }
    assert_eq!(v["points"]["C"], serde_json::json!([0.0, 0.0]));
    assert!(v.get("statics").is_none());
}

#[test]
fn analyze_json_offset_mechanism() {
    // e = 0.4, r = 1, l = 3.5 at 200°: against the formulas of docs/design.md §1.
    let v = json(&[
        "analyze", "--crank", "1", "--rod", "3.5", "--offset", "-0.4", "--angle", "200", "--omega",
        "3", "--json",
    ]);
    let t = 200f64.to_radians();
    let (s, c) = t.sin_cos();
    let h = s + 0.4;
    let wr = (3.5f64 * 3.5 - h * h).sqrt();
    let vel = 3.0 * (-s - c * h / wr);
    assert!(rel(v["analytic"]["velocity"].as_f64().unwrap(), vel) < 1e-12);
    assert!(rel(v["analytic"]["position"].as_f64().unwrap(), c + wr) < 1e-12);
    assert_eq!(v["points"]["A"][1], -0.4);
    assert!(rel(v["graphical"]["velocity"].as_f64().unwrap(), vel) < 1e-12);
}

#[test]
fn analyze_at_90_degrees_has_d_at_infinity() {
    let v = json(&["analyze", "--angle", "90", "--json"]);
    assert_eq!(
        v["points"]["D"],
        serde_json::json!({"at_infinity": [0.0, 1.0]})
    );
    assert_eq!(v["virtual_centres"]["O_bd"], v["points"]["D"]);
    assert_eq!(
        v["virtual_centres"]["O_cd"],
        serde_json::json!({"at_infinity": [0.0, 1.0]})
    );
    assert_eq!(v["virtual_centres"]["O_ac"], v["points"]["E"]);
    assert_eq!(v["graphical"]["rod_angular_velocity"], 0.0);
    // Every other number is finite (JSON cannot carry NaN anyway: check all).
    fn all_finite(v: &Value) -> bool {
        match v {
            Value::Number(n) => n.as_f64().is_some_and(f64::is_finite),
            Value::Array(a) => a.iter().all(all_finite),
            Value::Object(o) => o.values().all(all_finite),
            _ => true,
        }
    }
    assert!(all_finite(&v));
    let near = json(&["analyze", "--angle", "89.999999", "--json"]);
    let d = &near["points"]["D"];
    let x = d[0].as_f64().unwrap();
    let y = d[1].as_f64().unwrap();
    let t = 89.999999f64.to_radians();
    assert!(rel(x, near["points"]["A"][0].as_f64().unwrap()) < 1e-15);
    assert!(rel(y, x * t.tan()) < 1e-8, "D = ({x}, {y})");
}

#[test]
fn analyze_range_prints_an_array_and_statics() {
    let v = json(&[
        "analyze",
        "--crank",
        "25",
        "--rod",
        "72",
        "--angle",
        "0:180:90",
        "--torque",
        "264.87",
        "--friction",
        "1",
        "--json",
    ]);
    let a = v.as_array().unwrap();
    assert_eq!(a.len(), 3);
    // Dead centre: no finite slider force.
    assert_eq!(a[0]["statics"]["slider_force"], Value::Null);
    assert_eq!(a[0]["statics"]["OM"], 0.0);
    // 90°: OM = r, F = T / r.
    assert!(rel(a[1]["statics"]["OM"].as_f64().unwrap(), 25.0) < 1e-15);
    assert!(
        rel(
            a[1]["statics"]["slider_force"].as_f64().unwrap(),
            264.87 / 25.0
        ) < 1e-15
    );
    let tan_phi = (25.0f64 / 72.0).asin().tan();
    let fp = a[1]["statics"]["slider_force_with_friction"]
        .as_f64()
        .unwrap();
    assert!(rel(fp, 264.87 / 25.0 * (1.0 - tan_phi)) < 1e-13);
    assert!(
        rel(
            a[1]["statics"]["transmission_angle_deg"].as_f64().unwrap(),
            90.0 - (25.0f64 / 72.0).asin().to_degrees()
        ) < 1e-13
    );
}

#[test]
fn self_locking_is_reported_not_negative() {
    let v = json(&[
        "analyze",
        "--angle",
        "90",
        "--torque",
        "1",
        "--friction",
        "10",
        "--json",
    ]);
    assert_eq!(v["statics"]["self_locking"], true);
    assert_eq!(v["statics"]["slider_force_with_friction"], Value::Null);
}

#[test]
fn bad_input_exits_non_zero_with_one_clear_line() {
    let cases: &[(&[&str], &str)] = &[
        (
            &["analyze", "--crank", "0.5", "--rod", "0.4"],
            "rod 0.4 is too short",
        ),
        (
            &["analyze", "--crank", "nan"],
            "crank must be a finite number",
        ),
        (
            &["analyze", "--crank", "inf"],
            "crank must be a finite number",
        ),
        (
            &["analyze", "--crank", "-1"],
            "crank must be greater than zero",
        ),
        (&["analyze", "--angle", "abc"], "invalid angle 'abc'"),
        (
            &["analyze", "--angle", "1e400"],
            "must be a finite number of degrees",
        ),
        (
            &["analyze", "--crank", "1", "--rod", "3", "--offset", "2.5"],
            "rod > crank + |offset| = 3.5",
        ),
        (
            &["analyze", "--omega", "nan"],
            "omega must be a finite number",
        ),
        (
            &["analyze", "--torque", "1", "--friction", "-1"],
            "friction",
        ),
        // Friction acts only with a load on the crank.
        (
            &["analyze", "--friction", "0.2"],
            "--friction applies with a torque (the statics) or the engine's dynamics",
        ),
        (&["table", "obliquity", "--n", "0.5"], "n = l/r > 1"),
        (&["check", "--samples", "0"], "samples"),
        // Regression: products of such lengths overflowed into a panic.
        (
            &["analyze", "--crank", "1e300", "--rod", "3e300"],
            "lengths must lie between",
        ),
        (
            &[
                "figure",
                "fig-67-example",
                "--crank",
                "1e-300",
                "--rod",
                "3e-300",
            ],
            "lengths must lie between",
        ),
    ];
    for (args, needle) in cases {
        let out = run(args);
        assert!(!out.status.success(), "{args:?} succeeded");
        assert!(out.stdout.is_empty(), "{args:?} printed to stdout");
        let err = String::from_utf8(out.stderr).unwrap();
        assert_eq!(err.trim_end().lines().count(), 1, "{args:?}: {err}");
        assert!(err.contains(needle), "{args:?}: {err}");
        assert!(!err.contains("panicked"), "{args:?}: {err}");
    }
}

#[test]
fn acceleration_factor_table_prints_the_textbooks_rows() {
    let out = run(&["table", "acceleration-factor", "--format", "csv"]);
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines[0], "θ,n = 4,n = 4.5,n = 5,n = 5.5,n = 6,n = ∞");
    assert_eq!(lines[1], "0° or 360°,1.250,1.222,1.200,1.182,1.167,1.000");
    assert_eq!(
        lines[4],
        "90° or 270°,-0.250,-0.222,-0.200,-0.182,-0.167,0.000"
    );
    assert_eq!(lines[7], "180°,-0.750,-0.778,-0.800,-0.818,-0.833,-1.000");
    assert_eq!(lines.len(), 8);
}

#[test]
fn forces_table_reproduces_ng_where_ng_is_right() {
    let out = run(&["table", "forces", "--format", "csv"]);
    let text = String::from_utf8(out.stdout).unwrap();
    let row80 = text.lines().find(|l| l.starts_with("80,")).unwrap();
    // β = 80.00 printed and right; F within 0.1 % of 10.11.
    assert!(row80.ends_with(",80.00"), "{row80}");
    let f: f64 = row80.split(',').nth(1).unwrap().parse().unwrap();
    assert!((f - 10.11).abs() < 0.011, "{f}");
}

#[test]
fn check_passes_and_fails_as_it_should() {
    let out = run(&[
        "check",
        "--crank",
        "1",
        "--rod",
        "1.05",
        "--offset",
        "0.045",
        "--samples",
        "20000",
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stdout)
    );
    assert!(String::from_utf8_lossy(&out.stdout).contains("all within tolerance"));
    // An impossible tolerance fails with exit code 1.
    let out = run(&["check", "--samples", "1000", "--tolerance", "1e-300"]);
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stdout).contains("FAIL"));
}

#[test]
fn defaults_run_the_section_35_engine() {
    let out = run(&["analyze"]);
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.contains("r = 0.5 ft, l = 3 ft"), "{text}");
    assert!(
        text.contains("velocity dx/dt") && text.contains("ft/s\n"),
        "{text}"
    );
    assert!(text.contains("θ = 45°"));
}

#[test]
fn analyze_curved_slot_converges_to_the_straight_slot() {
    let straight = json(&["analyze", "--angle", "45", "--json"]);
    let v = json(&[
        "analyze",
        "--angle",
        "45",
        "--slot-radius",
        "1e12",
        "--json",
    ]);
    assert_eq!(v["points"]["O_cd"], serde_json::json!([0.0, -1e12]));
    assert_eq!(v["virtual_centres"]["O_cd"], v["points"]["O_cd"]);
    for (key, scale) in [("velocity", 13.0), ("acceleration", 350.0)] {
        let a = v["analytic"][key].as_f64().unwrap();
        let b = straight["analytic"][key].as_f64().unwrap();
        assert!((a - b).abs() < 1e-10 * scale, "{key}: {a} {b}");
        let g = v["graphical"][key].as_f64().unwrap();
        assert!((g - a).abs() < 1e-12 * scale, "{key}: {g} {a}");
    }
    let x = straight["analytic"]["position"].as_f64().unwrap();
    assert!((v["analytic"]["arc_position"].as_f64().unwrap() - x).abs() < 1e-10);
    let names = ["O_ab", "O_ac", "O_ad", "O_bc", "O_bd", "O_cd"];
    let keys: Vec<&String> = v["virtual_centres"].as_object().unwrap().keys().collect();
    assert_eq!(keys, names);
}

#[test]
fn analyze_quadric_chain_and_inversions() {
    let v = json(&[
        "analyze",
        "--links",
        "1,3,2.5,3.2",
        "--angle",
        "30",
        "--assembly",
        "crossed",
        "--json",
    ]);
    let p = |k: &str| {
        let a = v["points"][k].as_array().unwrap();
        (a[0].as_f64().unwrap(), a[1].as_f64().unwrap())
    };
    let (a, b, o) = (p("A"), p("B"), p("O_cd"));
    assert!(((a.0 - b.0).hypot(a.1 - b.1) - 3.0).abs() < 1e-14);
    assert!(((a.0 - o.0).hypot(a.1 - o.1) - 2.5).abs() < 1e-14);
    assert_eq!(v["mechanism"]["grashof"], "crank_rocker");
    assert_eq!(v["mechanism"]["assembly"], "crossed");
    // The slotted lever (inversion 3) in line, r/l = 1/2: time ratio 2.
    let v = json(&[
        "analyze",
        "--crank",
        "1",
        "--rod",
        "2",
        "--inversion",
        "3",
        "--json",
    ]);
    assert!((v["time_ratio"].as_f64().unwrap() - 2.0).abs() < 1e-14);
    assert_eq!(v["fixed"], "b");
    // Whitworth's (inversion 2) at r/l = 1/2: cos(α/2) = 1/2 for the
    // return's angle α = 120°, time ratio (360 − 120)/120 = 2, and the
    // chain's ratio is the quick return's.
    let w = json(&[
        "analyze",
        "--crank",
        "1",
        "--rod",
        "2",
        "--inversion",
        "2",
        "--json",
    ]);
    let ratio = w["time_ratio"].as_f64().unwrap();
    assert!((ratio - 2.0).abs() < 1e-14, "{ratio}");
    assert_eq!(w["time_ratio"], w["quick_return"]["time_ratio"]);
    assert_eq!(v["links"]["b"]["angular_velocity"], 0.0);
    // The hand pump's handle at the end of its swing: no motion, no NaN.
    let v = json(&["analyze", "--inversion", "4", "--angle", "90", "--json"]);
    assert_eq!(v["links"]["a"]["angular_velocity"], Value::Null);
    assert!(v["virtual_centres"]["O_cd"]["at_infinity"].is_array());
}

#[test]
fn check_covers_the_curved_slot_and_the_quadric_chain() {
    for args in [
        &["check", "--slot-radius", "-3.6", "--samples", "2000"][..],
        &["check", "--slot-radius", "1e15", "--samples", "2000"][..],
        &["check", "--links", "3,2,3,4.5", "--samples", "2000"][..],
    ] {
        let out = run(args);
        assert!(
            out.status.success(),
            "{args:?}: {}",
            String::from_utf8_lossy(&out.stdout)
        );
        assert!(String::from_utf8_lossy(&out.stdout).contains("all within tolerance"));
    }
}

#[test]
fn chain_errors_are_one_line() {
    for args in [
        &["analyze", "--slot-radius", "1.7"][..],
        &["analyze", "--links", "1,2,3"][..],
        &["analyze", "--links", "1,2,3,7"][..],
        &["analyze", "--links", "3,2,3,4.5", "--angle", "170"][..],
        &["analyze", "--inversion", "5"][..],
        &["analyze", "--slot-radius", "5", "--links", "1,3,2.5,3.2"][..],
        &["analyze", "--inversion", "2", "--torque", "1"][..],
    ] {
        let out = run(args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        assert!(out.stdout.is_empty(), "{args:?}");
        assert_eq!(
            String::from_utf8_lossy(&out.stderr).lines().count(),
            1,
            "{args:?}"
        );
    }
}

/// The `--help` text of `args` (a subcommand, or none for the program).
fn help(args: &[&str]) -> String {
    let mut all = args.to_vec();
    all.push("--help");
    let out = run(&all);
    assert!(out.status.success(), "{all:?}");
    String::from_utf8(out.stdout).expect("UTF-8")
}

/// The paragraphs of a help text that describe one option or argument:
/// from a line starting with `-` or `<` (after its indent) to the next.
fn option_blocks(text: &str) -> Vec<String> {
    let mut blocks: Vec<String> = Vec::new();
    for line in text.lines() {
        let t = line.trim_start();
        let starts = line.starts_with("  ") && (t.starts_with('-') || t.starts_with('<'));
        if starts || blocks.is_empty() {
            blocks.push(String::new());
        }
        let block = blocks.last_mut().expect("one block");
        block.push_str(line);
        block.push('\n');
    }
    blocks
}

const SUBCOMMANDS: [&str; 5] = ["analyze", "table", "check", "figure", "scene"];

#[test]
fn help_shows_each_default_once_and_numbers_as_written() {
    for cmd in SUBCOMMANDS {
        let text = help(&[cmd]);
        for block in option_blocks(&text) {
            assert!(
                block.matches("[default").count() <= 1,
                "{cmd}: a default shown twice in\n{block}"
            );
        }
        // No float printed out to its last digit (0.000000000001 for 1e-12).
        assert!(!text.contains("00000000"), "{cmd}: {text}");
    }
}

#[test]
fn check_help_gives_the_tolerances_in_exponent_form() {
    let text = help(&["check"]);
    assert!(text.contains("1e-12"), "{text}");
    assert!(!text.contains("0.000000000001"), "{text}");
    assert!(text.contains("8.9e-16"), "{text}");
    // Flags check does not take are not offered; --inversion 2 and 3
    // check the Coriolis polygons.
    assert!(!text.contains("--assembly"), "{text}");
    assert!(text.contains("--inversion"), "{text}");
    let out = run(&["check", "--inversion", "3", "--samples", "100"]);
    assert_eq!(out.status.code(), Some(0));
    assert!(String::from_utf8_lossy(&out.stdout).contains("Coriolis"));
    // but the inversions without a sliding pair on a turning link are
    // refused with the reason.
    let out = run(&["check", "--inversion", "1"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("only inversions 2 and 3"));
}

#[test]
fn table_help_shows_the_offset_default_once() {
    let text = help(&["table"]);
    let offset = option_blocks(&text)
        .into_iter()
        .find(|b| b.trim_start().starts_with("--offset"))
        .expect("--offset is listed");
    assert_eq!(offset.matches("default").count(), 1, "{offset}");
    assert!(offset.contains("[default: 0]"), "{offset}");
    // The speed is that of the kinematics table.
    assert!(text.contains("Crank speed for kinematics"), "{text}");
}

#[test]
fn d_is_the_instantaneous_centre_of_the_rod() {
    for text in [
        help(&[]),
        String::from_utf8(run(&["analyze"]).stdout).unwrap(),
    ] {
        assert!(!text.contains("rod centre"), "{text}");
        assert!(text.contains("D instantaneous centre of the rod"), "{text}");
    }
    assert!(!help(&["analyze"]).contains("rod centre"));
}

#[test]
fn help_names_the_units() {
    let top = help(&[]);
    for unit in ["rpm", "rad/s", "per second", "degrees"] {
        assert!(top.contains(unit), "{unit}: {top}");
    }
    let analyze = help(&["analyze"]);
    for unit in ["rad/s²", "per second squared", "force × the length unit"] {
        assert!(analyze.contains(unit), "{unit}: {analyze}");
    }
}

/// Runs the binary with `args` through `sh`, standard output redirected
/// by `redirect` (`>&-`, `>/dev/full`, ...).
#[cfg(unix)]
fn run_redirected(args: &[&str], redirect: &str) -> Output {
    let script = format!("\"$0\" \"$@\" {redirect}");
    Command::new("sh")
        .arg("-c")
        .arg(script)
        .arg(env!("CARGO_BIN_EXE_slider-crank"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("sh runs")
}

/// Every subcommand, help and version: what each prints to standard output.
const EVERY_OUTPUT: [&[&str]; 9] = [
    &["analyze"],
    &["analyze", "--json", "--angle", "0:360:30"],
    &["table", "obliquity"],
    &["check", "--samples", "100"],
    &["figure", "fig-66-kisch"],
    &["scene", "examples/ng-torque.toml"],
    &["--help"],
    &["analyze", "--help"],
    &["--version"],
];

/// A refusal of standard output: exit 2, one line on standard error
/// naming standard output and `why`.
#[cfg(unix)]
fn assert_stdout_refused(out: &Output, args: &[&str], why: &str) {
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
    assert_eq!(stderr.lines().count(), 1, "{args:?}: {stderr}");
    assert!(
        stderr.starts_with("slider-crank: error: cannot write to standard output: ")
            && stderr.contains(why),
        "{args:?}: {stderr}"
    );
}

#[test]
#[cfg(unix)]
fn the_null_device_is_a_sink_however_opened() {
    // Issue 40 (8): standard output on the null device opened for reading
    // and writing (Python's subprocess.DEVNULL, nohup, service managers)
    // was refused as "closed (>&-)". The null device is a sink, however
    // opened; a descriptor the shell closed (`>&-`) is the null device
    // opened so by the time the program runs (the runtime puts it there),
    // and cannot be told from it.
    for redirect in ["1<>/dev/null", ">/dev/null", ">&-"] {
        for args in EVERY_OUTPUT {
            let out = run_redirected(args, redirect);
            let stderr = String::from_utf8_lossy(&out.stderr);
            assert_eq!(out.status.code(), Some(0), "{args:?} {redirect}: {stderr}");
            assert!(stderr.is_empty(), "{args:?} {redirect}: {stderr}");
        }
    }
    // Python's DEVNULL, through the standard library's own null device.
    let out = Command::new(env!("CARGO_BIN_EXE_slider-crank"))
        .arg("analyze")
        .stdout(std::process::Stdio::null())
        .status()
        .expect("runs");
    assert!(out.success());
}

#[test]
#[cfg(unix)]
fn a_full_device_on_standard_output_is_an_error() {
    if !Path::new("/dev/full").exists() {
        eprintln!("no /dev/full here: skipped");
        return;
    }
    for args in EVERY_OUTPUT {
        let out = run_redirected(args, ">/dev/full");
        assert_stdout_refused(&out, args, "No space left on device");
    }
}

#[test]
#[cfg(unix)]
fn the_null_device_is_not_taken_for_a_closed_output() {
    // Opened for writing, by the shell or by Stdio::null(): written to, as
    // the user asked. Only the runtime's stand-in for a closed descriptor
    // (the null device opened for reading and writing) is refused.
    let out = run_redirected(&["analyze"], ">/dev/null");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let out = Command::new(env!("CARGO_BIN_EXE_slider-crank"))
        .arg("analyze")
        .stdout(std::process::Stdio::null())
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

#[test]
fn analyze_carries_the_unit_names() {
    let v = json(&["analyze", "--unit", "mm", "--json"]);
    let u = &v["units"];
    assert_eq!(u["length"], "mm");
    assert_eq!(u["velocity"], "mm/s");
    assert_eq!(u["acceleration"], "mm/s²");
    // Millimetres bring newtons (issue 22: never lbf·mm unless asked).
    assert_eq!(u["force"], "N");
    assert_eq!(u["torque"], "N·mm");
    assert_eq!(u["angular_velocity"], "rad/s");
    let torque = json(&["analyze", "--unit", "mm", "--torque", "5000", "--json"]);
    assert_eq!(torque["units"]["torque"], "N·mm");
    let asked = json(&["analyze", "--unit", "mm", "--force-unit", "lbf", "--json"]);
    assert_eq!(asked["units"]["torque"], "lbf·mm");
    let m = json(&["analyze", "--unit", "m", "--json"]);
    assert_eq!(m["units"]["torque"], "N·m");
    // Names only: the numbers are those without the flag.
    let plain = json(&["analyze", "--json"]);
    assert_eq!(plain["analytic"], v["analytic"]);
    assert_eq!(plain["units"]["length"], "ft");
    assert_eq!(plain["units"]["force"], "lbf");
    // Every object of a list, the chain's objects too.
    let list = json(&[
        "analyze",
        "--unit",
        "in",
        "--force-unit",
        "kN",
        "--angle",
        "0,90",
        "--json",
    ]);
    for v in list.as_array().unwrap() {
        assert_eq!(v["units"]["torque"], "kN·in");
    }
    for chain in [
        vec!["--slot-radius", "5"],
        vec!["--links", "1,3,4,3.5"],
        vec!["--inversion", "3"],
    ] {
        let mut args = vec!["analyze", "--json", "--unit", "m"];
        args.extend(chain.iter());
        assert_eq!(json(&args)["units"]["velocity"], "m/s", "{chain:?}");
    }
    // The text names them beside the numbers.
    let out = run(&[
        "analyze",
        "--crank",
        "25",
        "--rod",
        "72",
        "--unit",
        "mm",
        "--force-unit",
        "N",
        "--torque",
        "264.87",
    ]);
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.contains("r = 25 mm, l = 72 mm"), "{text}");
    for line in [
        "velocity dx/dt",
        "acceleration d²x/dt²",
        "slider force F_p",
        "OM (= CE)",
    ] {
        let l = text.lines().find(|l| l.contains(line)).unwrap();
        let unit = l.split_whitespace().last().unwrap();
        assert!(["mm/s", "mm/s²", "N", "mm"].contains(&unit), "{l}");
    }
    assert!(!text.contains("ft"), "{text}");
}

#[test]
fn tables_name_their_units() {
    let out = run(&["table", "kinematics", "--unit", "m", "--format", "csv"]);
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(
        text.starts_with("θ (°),x_A (m),dx/dt (m/s),d²x/dt² (m/s²),φ (°),dφ/dt (rad/s),"),
        "{text}"
    );
    // The title gives the speed as a reader would write it (issue 22).
    let out = run(&["table", "kinematics"]);
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(
        text.contains("250 rpm (ω = 26.18 rad/s)") && !text.contains("26.1799"),
        "{text}"
    );
    let out = run(&["table", "forces", "--force-unit", "kN"]);
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(
        text.contains("T = 264.87 kN·mm") && text.contains("F eq. 6 (kN)"),
        "{text}"
    );
    let out = run(&["table", "forces"]);
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(
        text.contains("r = 25 mm") && text.contains("F eq. 6 (N)"),
        "{text}"
    );
}

#[test]
fn print_default_writes_a_scene_file_that_draws_the_named_figure() {
    let dir =
        std::env::temp_dir().join(format!("slider-crank-print-default-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    for name in [
        "fig-62-displacement",
        "fig-63-velocity",
        "fig-65-klein",
        "fig-66-kisch",
        "fig-67-example",
        "ng-fig-1-torque",
        "ng-fig-a1-velocity",
        "fig-64-velocity-diagrams",
    ] {
        let toml = run(&["scene", "--print-default", name]);
        assert!(toml.status.success(), "{name}");
        assert!(toml.stderr.is_empty(), "{name}");
        let path = dir.join(format!("{name}.toml"));
        std::fs::write(&path, &toml.stdout).unwrap();
        let from_file = run(&["scene", path.to_str().unwrap()]);
        assert!(
            from_file.status.success(),
            "{name}: {}",
            String::from_utf8_lossy(&from_file.stderr)
        );
        let own = run(&["figure", name]);
        assert!(from_file.stdout == own.stdout, "{name}: the SVG differs");
    }
    // A name that is no figure, or a file as well: one line, exit 2.
    for args in [
        &["scene", "--print-default", "fig-6"][..],
        &["scene", "x.toml", "--print-default", "fig-63-velocity"],
        &[
            "scene",
            "--print-default",
            "fig-63-velocity",
            "--out",
            "x.svg",
        ],
        &["scene"],
    ] {
        let out = run(args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        assert!(out.stdout.is_empty(), "{args:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(err.trim_end().lines().count(), 1, "{args:?}: {err}");
    }
    // A newer scene file is refused for its version, in one line.
    let path = dir.join("newer.toml");
    std::fs::write(&path, "version = 2\nbrand_new_key = true\n").unwrap();
    let out = run(&["scene", path.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.trim_end().ends_with(
            "newer.toml: line 1, column 11: this scene file is version 2, newer than this program reads: it reads version 1"
        ),
        "{err}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn figure_help_names_every_layer() {
    let help = String::from_utf8(run(&["figure", "--help"]).stdout).unwrap();
    let at = help.find("--layers").expect("a --layers option");
    let text = &help[at..at + help[at..].find("[default").unwrap()];
    for layer in slider_crank::Layer::ALL {
        assert!(
            text.contains(layer.name()),
            "{} missing from: {text}",
            layer.name()
        );
    }
}

/// A refused run: exit 2, one line on standard error, returned.
fn refused(args: &[&str]) -> String {
    let out = run(args);
    assert_eq!(out.status.code(), Some(2), "{args:?}");
    let stderr = String::from_utf8(out.stderr).unwrap();
    assert_eq!(stderr.lines().count(), 1, "{args:?}: {stderr}");
    stderr
}

#[test]
fn a_mistake_is_told_what_to_write() {
    // Issue 22: each message says what the user meant.
    let e = refused(&["figure", "fig-67-exmaple"]);
    assert!(e.contains("did you mean 'fig-67-example'?"), "{e}");
    let e = refused(&["figure", "klein"]);
    assert!(e.contains("did you mean 'fig-65-klein'?"), "{e}");
    let e = refused(&["analyse"]);
    assert!(e.contains("'analyze'"), "{e}");
    // `table` takes --angle as `analyze` does, and `analyze` --angles.
    let out = run(&[
        "table",
        "kinematics",
        "--angle",
        "0:360:90",
        "--format",
        "csv",
    ]);
    let text = String::from_utf8(out.stdout).unwrap();
    assert_eq!(text.lines().count(), 6, "{text}");
    let both = json(&["analyze", "--angles", "0,90", "--json"]);
    assert_eq!(both.as_array().map(Vec::len), Some(2));
    // A missing folder is named, for every command that writes one file.
    let dir = tempfile::tempdir().unwrap();
    let missing = dir.path().join("nope");
    for (args, file) in [
        (&["figure", "fig-66-kisch", "--out"][..], "x.svg"),
        (&["handout", "--out"][..], "h.html"),
        (
            &["animate", "fig-66-kisch", "--frames", "4", "--out"][..],
            "a.html",
        ),
    ] {
        let path = missing.join(file);
        let mut args = args.to_vec();
        args.push(path.to_str().unwrap());
        let e = refused(&args);
        assert!(
            e.contains(&format!("the folder {} does not exist", missing.display())),
            "{args:?}: {e}"
        );
        assert!(!missing.exists());
    }
    // Page widths in cm and pt as well as mm and in.
    for (width, attribute) in [("12cm", "width=\"12cm\""), ("340pt", "width=\"340pt\"")] {
        let out = run(&["figure", "fig-66-kisch", "--width", width]);
        assert!(out.status.success(), "{width}");
        let svg = String::from_utf8(out.stdout).unwrap();
        assert!(svg.contains(attribute), "{width}");
    }
}

#[test]
fn analyze_reports_the_engines_dynamics() {
    // At 90° in line OM = r, so T = F r; m a from the closed form
    // a = r ω² / √(n² − 1) (n = 6): F = 5000 + 10 · 0.5 ω² / √35.
    let v = json(&[
        "analyze",
        "--angle",
        "90",
        "--omega",
        "20",
        "--mass",
        "10",
        "--gas-force",
        "5000",
        "--json",
    ]);
    let d = &v["dynamics"];
    let f = 5000.0 + 10.0 * 0.5 * 400.0 / 35f64.sqrt();
    assert!(rel(d["piston_effort"].as_f64().unwrap(), f) < 1e-12, "{d}");
    assert!(rel(d["crank_effort"].as_f64().unwrap(), 0.5 * f) < 1e-12);
    assert_eq!(d["units"]["mass"], "slug");
    assert!(d["rod"].is_null());
    // A rod's centre of mass beyond its length is one line on stderr.
    let out = run(&[
        "analyze",
        "--mass",
        "1",
        "--rod-mass",
        "1",
        "--rod-cg",
        "4",
        "--rod-gyration",
        "1",
    ]);
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.starts_with("slider-crank: error: rod-cg = 4 is out of range"),
        "{err}"
    );
    assert_eq!(err.lines().count(), 1);
}

#[test]
fn table_dynamics_gives_the_turn_and_the_flywheel() {
    let out = run(&["table", "dynamics", "--fluctuation", "0.02"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("Over the turn (1 cylinder at 0°)"), "{text}");
    assert!(text.contains("Flywheel: I = ΔE / (ω² C_s)"), "{text}");
    assert_eq!(
        text.lines().filter(|l| l.starts_with("90.0 ")).count(),
        1,
        "{text}"
    );
}

/// `analyze --json` over many angles is one array written as it is
/// computed, and a request beyond `--max-cells` is refused before any
/// output, naming its size (the million angles of the regression table
/// are measured in docs/benchmarks.md).
#[test]
fn analyze_streams_json_and_refuses_beyond_the_guard() {
    let v = json(&["analyze", "--angle", "0:359.9:0.1", "--json"]);
    let objects = v.as_array().expect("an array");
    assert_eq!(objects.len(), 3600);
    assert_eq!(objects[1234]["angle_deg"].as_f64(), Some(123.4));
    let out = run(&[
        "analyze",
        "--angle",
        "0:999999:1",
        "--json",
        "--max-cells",
        "1000",
    ]);
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stdout.is_empty());
    let e = String::from_utf8(out.stderr).unwrap();
    assert!(
        e.contains("1000000 angles") && e.contains("--max-cells"),
        "{e}"
    );
}

/// The turning-moment figure states an offset engine's offset (its stroke
/// and work differ from the in-line engine's), and no offset in line.
#[test]
fn the_turning_moment_notes_state_the_offset() {
    let svg = |extra: &[&str]| {
        let mut args = vec!["figure", "turning-moment", "--crank", "0.5", "--rod", "1.2"];
        args.extend_from_slice(extra);
        let out = run(&args);
        assert!(
            out.status.success(),
            "{:?}",
            String::from_utf8_lossy(&out.stderr)
        );
        String::from_utf8(out.stdout).unwrap()
    };
    // The notes set "= " after a letter with a no-break space, and say
    // on which side the line of stroke runs (the tenth review: a bare
    // signed e had no direction).
    let offset = svg(&["--offset", "0.1"]);
    assert!(
        offset.contains(
            "</tspan>\u{a0}= 0.1 ft (the line of stroke above the crank centre), 250 rpm"
        ),
        "offset not stated"
    );
    let in_line = svg(&[]);
    assert!(
        in_line.contains("</tspan>\u{a0}= 1.2 ft, 250 rpm"),
        "rod not stated"
    );
    assert!(!in_line.contains(">e</tspan>"), "an offset stated in line");
}

#[test]
fn embed_fonts_is_refused_for_png_and_pdf_and_writes_nothing() {
    let dir = tempfile::tempdir().unwrap();
    for file in ["x.png", "x.pdf"] {
        let path = dir.path().join(file);
        let args = [
            "figure",
            "fig-63-velocity",
            "--embed-fonts",
            "--out",
            path.to_str().unwrap(),
        ];
        let e = refused(&args);
        assert!(e.contains("--embed-fonts is for SVG output"), "{e}");
        assert!(!path.exists(), "{file} written");
    }
}

/// The engine dynamics figures refuse a mass or a coefficient they cannot
/// draw, and a mechanism figure refuses both, in one line, writing
/// nothing.
#[test]
fn dynamics_figures_refuse_bad_masses_and_coefficients_in_one_line() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("x.png");
    let out_file = path.to_str().unwrap();
    for args in [
        vec!["figure", "inertia-force", "--mass", "0"],
        vec!["figure", "direct-reverse-cranks", "--mass", "-3"],
        vec!["figure", "primary-secondary", "--mass", "nan"],
        vec!["figure", "flywheel", "--fluctuation", "2"],
        vec!["figure", "flywheel", "--fluctuation", "0"],
        vec!["figure", "fig-65-klein", "--mass", "2"],
        vec!["figure", "rod-motion", "--fluctuation", "0.1"],
    ] {
        let mut args = args.clone();
        args.extend(["--out", out_file]);
        let out = run(&args);
        assert!(!out.status.success(), "{args:?}");
        let e = String::from_utf8(out.stderr).unwrap();
        assert_eq!(e.lines().count(), 1, "{args:?}: {e}");
        assert!(e.starts_with("slider-crank: "), "{e}");
        assert!(e.contains("mass") || e.contains("fluctuation"), "{e}");
        assert!(!path.exists(), "{args:?} wrote a file");
    }
    let out = run(&[
        "figure",
        "flywheel",
        "--mass",
        "2.5",
        "--fluctuation",
        "0.05",
        "--out",
        out_file,
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(path.exists());
}

/// A sweep's JSON array, written a chunk of angles at a time on every
/// core, is the single-angle objects in order, each indented as
/// `to_string_pretty` indents an array's elements: checked across the
/// chunks' seams (2 048 angles a chunk) against `analyze --angle θ --json`.
#[test]
fn a_long_table_is_the_single_angle_rows_in_order_padded_to_the_widest() {
    let flags = ["--crank", "0.5", "--rod", "1.7", "--offset", "0.2"];
    let csv = run(&[
        &[
            "table",
            "kinematics",
            "--angles",
            "-1:4500:1",
            "--format",
            "csv",
        ],
        &flags[..],
    ]
    .concat());
    assert!(csv.status.success());
    let csv = String::from_utf8(csv.stdout).unwrap();
    let lines: Vec<&str> = csv.lines().collect();
    assert_eq!(lines.len(), 1 + 4502);
    for k in [
        0, 1, 1023, 1024, 1025, 2047, 2048, 2049, 4095, 4096, 4097, 4501,
    ] {
        let degrees = (k as i64 - 1).to_string();
        let one = run(&[
            &[
                "table",
                "kinematics",
                "--angles",
                &degrees,
                "--format",
                "csv",
            ],
            &flags[..],
        ]
        .concat());
        let one = String::from_utf8(one.stdout).unwrap();
        assert_eq!(lines[k + 1], one.lines().nth(1).unwrap(), "angle {degrees}");
    }
    // The text table pads every column to its widest cell over all the
    // chunks: each row's cells end where the headers' do.
    let text = run(&[
        &["table", "kinematics", "--angles", "-1:4500:1"],
        &flags[..],
    ]
    .concat());
    let text = String::from_utf8(text.stdout).unwrap();
    let rows: Vec<&str> = text.lines().skip(2).take(4503).collect();
    let longest = rows.iter().map(|r| r.chars().count()).max().unwrap();
    assert_eq!(
        rows[0].chars().count(),
        longest,
        "the header line is as long as the longest row"
    );
    for row in &rows[1..] {
        let n = row.chars().count();
        assert_eq!(n, longest, "{row}");
    }
}

#[test]
fn a_long_sweep_is_the_single_angle_objects_in_order() {
    let flags = [
        "--crank", "0.5", "--rod", "1.7", "--offset", "0.2", "--torque", "3",
    ];
    let out = run(&[&["analyze", "--angle", "-1:4500:1", "--json"], &flags[..]].concat());
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    let body = text
        .strip_prefix("[\n")
        .and_then(|t| t.strip_suffix("\n]\n"))
        .expect("one array");
    let elements: Vec<&str> = body.split("\n  },\n  {").collect();
    assert_eq!(elements.len(), 4502);
    for k in [0, 1, 2047, 2048, 2049, 4095, 4096, 4097, 4501] {
        let degrees = (k as i64 - 1).to_string();
        let one = run(&[&["analyze", "--angle", &degrees, "--json"], &flags[..]].concat());
        let one = String::from_utf8(one.stdout).unwrap();
        let indented: Vec<String> = one.trim_end().lines().map(|l| format!("  {l}")).collect();
        let mut want = indented.join("\n");
        // The split took the closing and opening braces of the seams.
        if k > 0 {
            want = want.replacen("  {", "", 1);
        }
        if k < 4501 {
            want = want.strip_suffix("\n  }").unwrap().to_string();
        }
        assert_eq!(elements[k], want, "angle {degrees}");
    }
}

/// The help of `figure` lists every named figure under its group, and that
/// of `animate` every mechanism figure and no diagram: both are made from
/// the catalogue's table, so a figure added there is listed.
#[test]
fn the_help_lists_every_named_figure_from_the_catalogue() {
    // The NAME argument's help, between "Arguments:" and "Options:".
    let name_help = |command: &str| {
        let help = String::from_utf8(run(&[command, "--help"]).stdout).unwrap();
        let start = help.find("Arguments:").unwrap();
        let end = help.find("Options:").unwrap();
        help[start..end].to_string()
    };
    let (figure, animate) = (name_help("figure"), name_help("animate"));
    for f in slider_crank::FigureName::ALL {
        let listed = |help: &str| {
            help.split(|c: char| c.is_whitespace() || c == ',' || c == '.')
                .any(|w| w == f.name())
        };
        assert!(listed(&figure), "{}", f.name());
        assert_eq!(listed(&animate), !f.is_diagram(), "{}", f.name());
    }
    for heading in ["Mechanism figures:", "Diagrams:", "The chain of Fig. 60:"] {
        assert!(figure.contains(heading), "{heading}");
    }
}
