//! Every row of `docs/robustness.md`, run as written: the command in a
//! scratch directory under `ulimit -v 4000000` and a timeout, its exit code,
//! a text its standard error contains, and no `inf` or `NaN` printed.
//!
//! `ROBUSTNESS_BIN` runs another binary (the release build) and
//! `ROBUSTNESS_TIMEOUT` sets the timeout in seconds (default 60, for the
//! unoptimised build).

#![cfg(unix)]

use std::path::Path;
use std::process::Command;

#[path = "common/hostile.rs"]
#[allow(dead_code)]
mod hostile;

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
    let doc = include_str!("../docs/robustness.md");
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
    std::fs::write(p("old.svg"), "old").unwrap();
    std::fs::write(p("real.svg"), "old").unwrap();
    std::os::unix::fs::symlink("real.svg", p("link.svg")).unwrap();
    std::os::unix::fs::symlink("loop.svg", p("loop.svg")).unwrap();
    dir
}

fn run(row: &Row, dir: &Path, bin: &str, timeout: &str) -> std::process::Output {
    let command = row.command.replacen("slider-crank", bin, 1);
    let script = format!("set -o pipefail; ulimit -v 4000000; timeout {timeout} {command}");
    Command::new("bash")
        .arg("-c")
        .arg(script)
        .current_dir(dir)
        .output()
        .expect("bash runs")
}

#[test]
fn every_row_of_the_robustness_table_holds() {
    let rows = rows();
    assert!(rows.len() >= 60, "{} rows", rows.len());
    let dir = scratch();
    let bin = std::env::var("ROBUSTNESS_BIN").unwrap_or(env!("CARGO_BIN_EXE_slider-crank").into());
    let bin = std::fs::canonicalize(bin).unwrap();
    let timeout = std::env::var("ROBUSTNESS_TIMEOUT").unwrap_or("60".into());
    let mut failures = Vec::new();
    for row in &rows {
        let out = run(row, dir.path(), bin.to_str().unwrap(), &timeout);
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
