//! Every row of `docs/robustness.md`, run as written: the command in a
//! scratch directory under `ulimit -v 4000000` and a timeout, its exit code,
//! a text its standard error contains, and no `inf` or `NaN` printed.
//!
//! `ROBUSTNESS_BIN` runs another binary (the release build, say) and
//! `ROBUSTNESS_TIMEOUT` sets the timeout in seconds (default 180, for a
//! slower build or machine; `.ci/run` holds the test build's optimised
//! binary to the table's 10 s: its slowest row, 100 000 angles, takes
//! about 4 s on a loaded 2-core machine).

#![cfg(unix)]

use std::path::Path;
use std::process::Command;

use crate::hostile;

/// One row of the table.
struct Row {
    command: String,
    exit: i32,
    stderr: Option<String>,
}

/// The text of a Markdown code span, `\|` unescaped.
fn code(cell: &str) -> Option<String> {
    let inner = cell.trim().strip_prefix('`')?.strip_suffix('`')?;
    Some(inner.replace("\\|", "|"))
}

fn rows() -> Vec<Row> {
    let doc = include_str!("../../docs/robustness.md");
    doc.lines()
        .filter(|l| l.starts_with("| `slider-crank"))
        .map(|line| {
            let cells: Vec<&str> = line.trim_matches('|').split(" | ").collect();
            assert_eq!(cells.len(), 4, "a row of four cells: {line}");
            Row {
                command: code(cells[0]).expect("a command in backticks"),
                exit: cells[2].trim().parse().expect("an exit code"),
                stderr: code(cells[3]),
            }
        })
        .collect()
}

/// The files the table's rows name.
fn scratch() -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    let p = |name: &str| dir.path().join(name);
    let header = "curve,tolerance_px,method,steps,segments,measured_error_px,time_us,timed_by\n";
    std::fs::write(
        p("tiny.csv"),
        format!("{header}polar,1e-1,cubic,,10,5e-324,10.4,criterion\npolar,1e-2,cubic,,16,2.3e-3,24.8,criterion\n"),
    )
    .unwrap();
    std::fs::write(p("big.csv"), "angle,force\n40,1e308\n50,-1e308\n60,3\n").unwrap();
    std::fs::write(p("nan.csv"), "angle,force\n40,nan\n").unwrap();
    std::fs::write(p("empty.csv"), "").unwrap();
    std::fs::write(p("binary.csv"), [0x61, 0x6e, 0xff, 0xfe, 0x0a]).unwrap();
    std::fs::write(p("bad.toml"), "[mechanism]\ncrank = \"x\"\nrod = 3.0\n").unwrap();
    std::fs::write(p("nan.toml"), "[mechanism]\ncrank = nan\nrod = 3.0\n").unwrap();
    std::fs::write(
        p("huge-page.toml"),
        "[page]\nwidth = 20000\nheight = 20000\n",
    )
    .unwrap();
    std::fs::write(
        p("huge-torque.toml"),
        "angle = 45\nlayers = [\"mechanism\", \"velocity\", \"torque\"]\ntorque = 1e308\n\
         [mechanism]\ncrank = 1e-100\nrod = 3e-100\n",
    )
    .unwrap();
    std::fs::write(p("old.svg"), "old").unwrap();
    std::fs::write(p("real.svg"), "old").unwrap();
    std::os::unix::fs::symlink("real.svg", p("link.svg")).unwrap();
    std::os::unix::fs::symlink("loop.svg", p("loop.svg")).unwrap();
    second_round(dir.path());
    dir
}

/// The files of the second round's rows (docs/robustness.md, "Second
/// round: files, links and processes").
fn second_round(dir: &Path) {
    let p = |name: &str| dir.join(name);
    // A gallery's directory holding what --check must not read whole or
    // wait on: a link to an endless device, a 3 GB sparse file, a FIFO.
    std::fs::create_dir(p("hostile")).unwrap();
    std::os::unix::fs::symlink("/dev/zero", p("hostile/index.html")).unwrap();
    let sparse = std::fs::File::create(p("hostile/fig-63-velocity.svg")).unwrap();
    sparse.set_len(3 << 30).unwrap();
    let fifo = Command::new("mkfifo")
        .arg(p("hostile/fig-63-velocity.png"))
        .status()
        .unwrap();
    assert!(fifo.success());
    // A link planted in a gallery's directory, pointing out of it.
    std::fs::create_dir(p("planted")).unwrap();
    std::fs::write(p("victim.txt"), "victim").unwrap();
    std::os::unix::fs::symlink("../victim.txt", p("planted/index.html")).unwrap();
    std::fs::write(p("nonchar.toml"), "name = \"a\\uFFFEb\"\n").unwrap();
    std::fs::write(p("v-huge.toml"), "version = 99999999999999999999\n").unwrap();
    std::fs::write(p("v-2e63.toml"), "version = 9223372036854775808\n").unwrap();
    // Inputs that an output must not replace.
    std::fs::write(p("myscene"), "[mechanism]\ncrank = 0.5\nrod = 3.0\n").unwrap();
    std::os::unix::fs::symlink("myscene", p("myscene-link")).unwrap();
    std::fs::write(p("data.svg"), "angle,force\n40,3\n50,4\n").unwrap();
    std::fs::write(p("ro.svg"), "old").unwrap();
    let mut readonly = std::fs::metadata(p("ro.svg")).unwrap().permissions();
    readonly.set_readonly(true);
    std::fs::set_permissions(p("ro.svg"), readonly).unwrap();
}

/// After the second round's rows: the files they must not have replaced
/// or followed.
fn second_round_kept(dir: &Path) -> Vec<String> {
    let read = |name: &str| std::fs::read_to_string(dir.join(name)).unwrap_or_default();
    let mut broken = Vec::new();
    for (name, was) in [
        ("victim.txt", "victim"),
        ("myscene", "[mechanism]\ncrank = 0.5\nrod = 3.0\n"),
        ("data.svg", "angle,force\n40,3\n50,4\n"),
        ("ro.svg", "old"),
    ] {
        if read(name) != was {
            broken.push(format!("{name} was replaced"));
        }
    }
    let planted = std::fs::symlink_metadata(dir.join("planted/index.html")).unwrap();
    if !planted.is_file() || !read("planted/index.html").starts_with("<!DOCTYPE html>") {
        broken.push("planted/index.html is not the gallery's index".into());
    }
    if !std::fs::symlink_metadata(dir.join("myscene-link"))
        .unwrap()
        .is_symlink()
    {
        broken.push("myscene-link is no longer a link".into());
    }
    for sub in ["planted", "hostile"] {
        let left = std::fs::read_dir(dir.join(sub))
            .unwrap()
            .filter_map(|e| e.ok())
            .any(|e| {
                e.file_name()
                    .to_string_lossy()
                    .starts_with(".slider-crank-")
            });
        if left {
            broken.push(format!("temporary files left in {sub}"));
        }
    }
    broken
}

fn run(row: &Row, dir: &Path, bin: &str, timeout: &str) -> std::process::Output {
    let command = row.command.replacen("slider-crank", bin, 1);
    let script = format!("set -o pipefail; ulimit -v 4000000; timeout {timeout} {command}");
    // A row that runs the program again after the first (`… | diff -
    // <(slider-crank …)`) finds the same binary, by name, first on the
    // path.
    let programs = dir.join(".programs");
    if !programs.join("slider-crank").exists() {
        std::fs::create_dir_all(&programs).unwrap();
        std::os::unix::fs::symlink(bin, programs.join("slider-crank")).unwrap();
    }
    let path = format!(
        "{}:{}",
        programs.display(),
        std::env::var("PATH").unwrap_or_default()
    );
    Command::new("bash")
        .arg("-c")
        .arg(script)
        .env("PATH", path)
        .current_dir(dir)
        .output()
        .expect("bash runs")
}

#[test]
fn every_row_of_the_robustness_table_holds() {
    let rows = rows();
    assert!(rows.len() >= 60, "{} rows", rows.len());
    let readme = include_str!("../../README.md");
    assert!(
        readme.contains(&format!("{} bad or extreme inputs", rows.len())),
        "README.md gives another count than the table's {} rows",
        rows.len()
    );
    let dir = scratch();
    let bin = std::env::var("ROBUSTNESS_BIN").unwrap_or(env!("CARGO_BIN_EXE_slider-crank").into());
    let bin = std::fs::canonicalize(bin).unwrap();
    let timeout = std::env::var("ROBUSTNESS_TIMEOUT").unwrap_or("180".into());
    let mut failures = Vec::new();
    let mut times = Vec::new();
    for row in &rows {
        let start = std::time::Instant::now();
        let out = run(row, dir.path(), bin.to_str().unwrap(), &timeout);
        times.push((start.elapsed().as_secs_f64(), row.command.as_str()));
        let stderr = String::from_utf8_lossy(&out.stderr);
        let stdout = String::from_utf8_lossy(&out.stdout);
        let code = out.status.code();
        let mut problems = Vec::new();
        if code == Some(124) || code.is_none() {
            problems.push(format!("killed or timed out ({code:?})"));
        } else if code != Some(row.exit) {
            problems.push(format!("exit {code:?}, expected {}", row.exit));
        }
        match &row.stderr {
            Some(text) if !stderr.contains(text.as_str()) => {
                problems.push(format!("stderr lacks '{text}'"))
            }
            None if !stderr.is_empty() => problems.push("stderr not empty".into()),
            _ => {}
        }
        if row.exit != 0 && !stderr.is_empty() {
            if stderr.lines().count() != 1 || !stderr.starts_with("slider-crank: ") {
                problems.push("a refusal is one line starting 'slider-crank: '".into());
            }
            if !stdout.is_empty() && !row.command.contains('|') {
                problems.push("a refusal printed to standard output".into());
            }
        }
        if let Err(e) = std::panic::catch_unwind(|| hostile::assert_no_non_finite(&stdout)) {
            problems.push(format!("non-finite output: {e:?}"));
        }
        if !problems.is_empty() {
            failures.push(format!(
                "{}\n    {}\n    stderr: {}",
                row.command,
                problems.join("; "),
                stderr.trim()
            ));
        }
    }
    times.sort_by(|a, b| b.0.total_cmp(&a.0));
    for (t, command) in times.iter().take(3) {
        eprintln!("slowest: {t:.2} s  {command}");
    }
    // The files that refused or redirected writes must not have changed.
    let read = |name: &str| std::fs::read_to_string(dir.path().join(name)).unwrap();
    assert_eq!(read("old.svg"), "old", "a refused run replaced old.svg");
    assert!(
        std::fs::symlink_metadata(dir.path().join("link.svg"))
            .unwrap()
            .file_type()
            .is_symlink()
    );
    assert!(
        read("real.svg").starts_with("<svg"),
        "the link's target was not written"
    );
    let kept = second_round_kept(dir.path());
    assert!(kept.is_empty(), "{}", kept.join("\n"));
    let leftovers: Vec<_> = std::fs::read_dir(dir.path())
        .unwrap()
        .filter_map(|e| e.ok())
        .filter(|e| {
            e.file_name()
                .to_string_lossy()
                .starts_with(".slider-crank-")
        })
        .collect();
    assert!(leftovers.is_empty(), "temporary files left behind");
    assert!(
        failures.is_empty(),
        "{} of {} rows fail:\n{}",
        failures.len(),
        rows.len(),
        failures.join("\n")
    );
}

/// The code spans of a Markdown cell, `\|` unescaped.
fn spans(cell: &str) -> Vec<String> {
    cell.split('`')
        .skip(1)
        .step_by(2)
        .map(|s| s.replace("\\|", "|"))
        .collect()
}

/// One row of the regression table: its cells.
fn regression_rows() -> Vec<Vec<String>> {
    five_cell_rows("## Regressions against the version before hardening", |l| {
        l.as_bytes().get(2).is_some_and(u8::is_ascii_digit)
    })
}

/// The rows of the five-cell table under `heading` (up to the next
/// heading) that `keep` takes (`| ` already checked), as trimmed cells.
fn five_cell_rows(heading: &str, keep: fn(&str) -> bool) -> Vec<Vec<String>> {
    let doc = include_str!("../../docs/robustness.md");
    let section = doc.split(heading).nth(1).expect("the table's section");
    let section = section.split("\n## ").next().unwrap();
    section
        .lines()
        .filter(|l| l.starts_with("| ") && keep(l))
        .map(|line| {
            let cells: Vec<String> = line
                .trim_matches('|')
                .split(" | ")
                .map(|c| c.trim().to_string())
                .collect();
            assert_eq!(cells.len(), 5, "a row of five cells: {line}");
            cells
        })
        .collect()
}

/// Every test function a row names exists, and a row that says "table"
/// has its command in the table above (with the real devices).
#[test]
fn every_point_of_the_regression_table_is_tested() {
    let rows = regression_rows();
    let points: std::collections::BTreeSet<u32> = rows
        .iter()
        .map(|r| r[0].split(' ').next().unwrap().parse().unwrap())
        .collect();
    assert_eq!(
        points,
        (1..=10).collect(),
        "each of the ten points has rows"
    );
    let table: Vec<String> = self::rows().into_iter().map(|r| r.command).collect();
    let sources = sources();
    let commands = include_str!("../regressions/commands.tsv");
    for row in &rows {
        let tests = &row[4];
        let input = spans(&row[1]).into_iter().next().unwrap();
        if input.starts_with("slider-crank") {
            assert!(
                commands
                    .lines()
                    .any(|l| l.split('\t').nth(1) == Some(input.as_str())),
                "{input} is not in tests/regressions/commands.tsv"
            );
        }
        if tests.starts_with("table") {
            let real = input
                .replace("--out full", "--out /dev/full")
                .replace("--out stdout", "--out /dev/stdout");
            assert!(table.contains(&real), "{real} is not in the table");
        }
        for name in spans(tests) {
            assert!(
                sources.contains(&format!("fn {name}(")),
                "no test function {name}"
            );
        }
        assert!(
            tests.starts_with("table") || !spans(tests).is_empty(),
            "{input}: no test named"
        );
    }
    // Every command the script runs has its row.
    for line in commands.lines().filter(|l| !l.starts_with('#')) {
        let command = line.split('\t').nth(1).unwrap();
        assert!(
            rows.iter().any(|r| r[1] == format!("`{command}`")),
            "{command} has no row"
        );
    }
}

/// `tests/regressions/run.sh` on the built binary: every "now" cell of
/// the regression table holds, and the devices and links are kept.
#[test]
fn the_regression_table_holds_now() {
    let bin = std::env::var("ROBUSTNESS_BIN").unwrap_or(env!("CARGO_BIN_EXE_slider-crank").into());
    let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/regressions/run.sh");
    let out = Command::new("bash")
        .arg(script)
        .arg(bin)
        .output()
        .expect("bash runs");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let report = String::from_utf8(out.stdout).unwrap();
    let lines: Vec<Vec<&str>> = report.lines().map(|l| l.split('\t').collect()).collect();
    let mut failures = Vec::new();
    for row in regression_rows() {
        let input = spans(&row[1]).into_iter().next().unwrap();
        if !input.starts_with("slider-crank") {
            continue;
        }
        let Some(line) = lines.iter().find(|l| l.get(1) == Some(&input.as_str())) else {
            failures.push(format!("{input}: not run"));
            continue;
        };
        if line.get(2).is_some_and(|s| s.starts_with("skipped")) {
            continue;
        }
        let (status, printed, stderr) = (line[2], line[5], line.get(6).copied().unwrap_or(""));
        let expected = row[3].split([':', ';']).next().unwrap();
        if status != expected {
            failures.push(format!("{input}: {status}, the table says {expected}"));
        }
        let quoted = spans(&row[3]);
        if quoted.is_empty() && !stderr.is_empty() {
            failures.push(format!("{input}: said {stderr}"));
        }
        for text in quoted {
            if !stderr.contains(&text) {
                failures.push(format!("{input}: standard error lacks '{text}': {stderr}"));
            }
        }
        if printed.contains("(holds") || printed.contains("(says") {
            failures.push(format!("{input}: printed {printed}"));
        }
    }
    for (file, now) in [
        ("link.svg", "still a link; real.svg starts <svg"),
        ("stdout", "still a link"),
        ("full", "still a device"),
    ] {
        let line = lines.iter().find(|l| l[0] == "files" && l[1] == file);
        // `full` is made only when run as root.
        if let Some(line) = line {
            if line[2] != now {
                failures.push(format!("{file}: {}", line[2]));
            }
        } else if file != "full" {
            failures.push(format!("{file}: not reported"));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// The rows of the second round's regression table: point, input,
/// before, now, tests.
fn second_round_rows() -> Vec<Vec<String>> {
    five_cell_rows("## Second round: regressions", |l| {
        !l.starts_with("| point")
    })
}

/// Each point of the second round has a row, and each row a test: a row
/// of the table above (its input, as run) or test functions that exist.
#[test]
fn every_point_of_the_second_round_is_tested() {
    let rows = second_round_rows();
    let points: std::collections::BTreeSet<&str> = rows.iter().map(|r| r[0].as_str()).collect();
    let expected = [
        "bounded reads",
        "links",
        "text",
        "processes",
        "standard error",
        "negative numbers",
        "version",
        "inputs",
        "index",
        "parallel",
    ];
    assert_eq!(points, expected.into_iter().collect());
    let table: Vec<String> = self::rows().into_iter().map(|r| r.command).collect();
    let sources = sources();
    for row in &rows {
        let input = spans(&row[1]).into_iter().next().unwrap_or_default();
        if row[4].starts_with("table") {
            assert!(table.contains(&input), "{input} is not in the table");
        }
        for name in spans(&row[4]) {
            assert!(
                sources.contains(&format!("fn {name}(")),
                "no test function {name}"
            );
        }
        assert!(
            row[4].starts_with("table") || !spans(&row[4]).is_empty(),
            "{input}: no test named"
        );
    }
}

/// The test functions `tests/program/robustness.rs`'s tables name are looked for in
/// every Rust file under src/ and tests/.
fn sources() -> String {
    let mut sources = String::new();
    for dir in ["src", "tests"] {
        let mut stack = vec![Path::new(env!("CARGO_MANIFEST_DIR")).join(dir)];
        while let Some(d) = stack.pop() {
            for entry in std::fs::read_dir(d).unwrap() {
                let path = entry.unwrap().path();
                if path.is_dir() {
                    stack.push(path);
                } else if path.extension().is_some_and(|e| e == "rs") {
                    sources.push_str(&std::fs::read_to_string(path).unwrap());
                }
            }
        }
    }
    sources
}

/// Each row of "work in proportion" names tests that count the work
/// (none times it), and they exist.
#[test]
fn every_point_of_work_in_proportion_is_tested() {
    let rows = five_cell_rows("## Second round: work in proportion", |l| {
        !l.starts_with("| point")
    });
    let points: Vec<&str> = rows.iter().map(|r| r[0].as_str()).collect();
    assert_eq!(points, ["labels"]);
    let sources = sources();
    for row in &rows {
        let names = spans(&row[4]);
        assert!(!names.is_empty(), "{}: no test named", row[1]);
        for name in names {
            assert!(
                sources.contains(&format!("fn {name}(")),
                "no test function {name}"
            );
        }
    }
}

/// Each row of "The Python package" names tests that exist: pytest
/// functions under python/tests or Rust tests under src/ and tests/.
#[test]
fn every_point_of_the_python_package_is_tested() {
    let rows = five_cell_rows("## The Python package", |l| !l.starts_with("| point"));
    let points: std::collections::BTreeSet<&str> = rows.iter().map(|r| r[0].as_str()).collect();
    assert_eq!(points, ["files", "guard", "links"].into_iter().collect());
    let mut sources = sources();
    let python = Path::new(env!("CARGO_MANIFEST_DIR")).join("python/tests");
    for entry in std::fs::read_dir(python).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|e| e == "py") {
            sources.push_str(&std::fs::read_to_string(path).unwrap());
        }
    }
    for row in &rows {
        let names = spans(&row[4]);
        assert!(!names.is_empty(), "{}: no test named", row[1]);
        for name in names {
            assert!(
                sources.contains(&format!("fn {name}("))
                    || sources.contains(&format!("def {name}(")),
                "no test function {name}"
            );
        }
    }
}
