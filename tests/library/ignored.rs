//! A test that a plain `cargo test` leaves out is still run somewhere: every
//! `#[ignore]` under tests/ says why (`#[ignore = "…"]`, printed beside the
//! test's name) and sits in the `program` test binary, whose ignored tests
//! `.ci/run` runs with `--ignored` where Chromium and poppler are
//! installed; src/ ignores none (its unit tests run once, in `cargo test`).

use std::path::{Path, PathBuf};

/// The Rust files under `dir`, recursively.
fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// Each `#[ignore…]` attribute of the Rust files under `dir`: file, line
/// and the attribute.
fn ignores(dir: &str) -> Vec<(PathBuf, usize, String)> {
    let mut paths = Vec::new();
    rust_files(Path::new(dir), &mut paths);
    paths.sort();
    let mut found = Vec::new();
    for path in paths {
        let text = std::fs::read_to_string(&path).unwrap();
        for (n, line) in text.lines().enumerate() {
            let line = line.trim();
            if line.starts_with("#[ignore") {
                found.push((path.clone(), n + 1, line.to_string()));
            }
        }
    }
    found
}

#[test]
fn every_ignored_test_says_why_and_is_run_by_ci() {
    let in_tests = ignores("tests");
    // The browser and poppler checks are there (a wrong directory would
    // pass vacuously).
    assert!(in_tests.len() >= 8, "{in_tests:?}");
    for (path, line, attribute) in &in_tests {
        assert!(
            path.starts_with("tests/program"),
            "{}:{line}: an ignored test outside tests/program, which .ci/run does not run",
            path.display()
        );
        assert!(
            attribute.starts_with("#[ignore = \"needs "),
            "{}:{line}: {attribute} does not say what the test needs",
            path.display()
        );
    }
    let in_src = ignores("src");
    assert!(in_src.is_empty(), "ignored unit tests: {in_src:?}");
    let ci = std::fs::read_to_string(".ci/run").unwrap();
    assert!(
        ci.lines()
            .any(|l| l.trim() == "cargo test --locked --test program -- --ignored"),
        ".ci/run does not run the ignored tests"
    );
}
