//! PDF output (`--out FILE.pdf`) and the choice of format by the file's
//! extension for every command that takes `--out`.
//!
//! The font and text checks read the PDF with poppler's `pdffonts` and
//! `pdftotext`. They are ignored by a plain `cargo test`, which lists them
//! as ignored (not run) with the reason; `cargo test --test program --
//! --ignored` runs them, as `.ci/run` does after installing poppler-utils,
//! and there a missing tool fails the test.

use crate::command;
use command::{run, succeeded};
use std::path::Path;
use std::process::Command;

/// The standard output of a poppler tool run on `pdf`; a test that asked
/// for it fails when the tool is missing.
fn poppler(tool: &str, args: &[&str], pdf: &Path) -> String {
    let mut command = Command::new(tool);
    command.args(args).arg(pdf);
    if tool == "pdftotext" {
        command.arg("-"); // to standard output
    }
    let out = command.output().unwrap_or_else(|e| {
        panic!("{tool} could not be run ({e}): install poppler-utils to check the PDF")
    });
    assert!(
        out.status.success(),
        "{tool}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).unwrap()
}

/// Asserts that every font of the PDF is embedded (`pdffonts`' emb column).
fn fonts_embedded(pdf: &Path) {
    let list = poppler("pdffonts", &[], pdf);
    let rows: Vec<&str> = list.lines().skip(2).collect();
    assert!(!rows.is_empty(), "no fonts in {}:\n{list}", pdf.display());
    for row in rows {
        // name, type (one or more words), encoding, emb, sub, uni, object, generation
        let cols: Vec<&str> = row.split_whitespace().collect();
        let emb = cols[cols.len() - 5];
        assert_eq!(emb, "yes", "{}: {row}", pdf.display());
    }
}

/// A figure written as PDF into `dir` with `args` after its name.
fn figure_pdf(dir: &Path, file: &str, name: &str, args: &[&str]) -> std::path::PathBuf {
    let pdf = dir.join(file);
    let mut all = vec!["figure", name];
    all.extend_from_slice(args);
    all.extend(["--out", pdf.to_str().unwrap()]);
    let out = run(&all);
    succeeded(&out);
    assert!(out.stdout.is_empty() && out.stderr.is_empty());
    pdf
}

#[test]
fn fig_67_as_pdf_is_a_pdf_and_the_same_bytes_every_time() {
    let dir = tempfile::tempdir().unwrap();
    let pdf = figure_pdf(dir.path(), "x.pdf", "fig-67-example", &[]);
    let bytes = std::fs::read(&pdf).unwrap();
    assert!(bytes.starts_with(b"%PDF-"));
    // The same figure, the same bytes (an upper-case extension is a PDF too).
    let again = figure_pdf(dir.path(), "again.PDF", "fig-67-example", &[]);
    assert!(std::fs::read(&again).unwrap() == bytes);
}

#[test]
#[ignore = "needs poppler-utils (pdffonts, pdftotext): run with `-- --ignored` (.ci/run does)"]
fn fig_67_as_pdf_embeds_its_face_and_its_text_can_be_read() {
    let dir = tempfile::tempdir().unwrap();
    let pdf = figure_pdf(dir.path(), "x.pdf", "fig-67-example", &[]);
    fonts_embedded(&pdf);
    let fonts = poppler("pdffonts", &[], &pdf);
    assert!(fonts.contains("NewCM10-Italic"), "{fonts}");
    assert!(fonts.contains("NewCM10-Regular"), "{fonts}");
    let text = poppler("pdftotext", &[], &pdf);
    assert!(text.contains("Velocity scale"), "{text}");
    assert!(text.contains("Acceleration scale"), "{text}");
    assert!(text.contains("26.18 ft/s"), "{text}");
    let words: Vec<&str> = text.split_whitespace().collect();
    for letter in ["A", "B", "C", "D", "E", "F", "G", "H"] {
        assert!(words.contains(&letter), "point {letter} in {text}");
    }
}

#[test]
#[ignore = "needs poppler-utils (pdffonts): run with `-- --ignored` (.ci/run does)"]
fn the_chosen_face_is_the_one_embedded() {
    let dir = tempfile::tempdir().unwrap();
    let args = ["--font", "libertinus-serif", "--style", "handout"];
    let pdf = figure_pdf(dir.path(), "ng.pdf", "ng-fig-1-torque", &args);
    fonts_embedded(&pdf);
    let fonts = poppler("pdffonts", &[], &pdf);
    assert!(fonts.contains("LibertinusSerif"), "{fonts}");
    assert!(!fonts.contains("NewCM"), "{fonts}");
}

/// `examples/offset-kisch.toml` written as PDF into `dir`.
fn scene_pdf(dir: &Path) -> std::path::PathBuf {
    let pdf = dir.join("scene.pdf");
    succeeded(&run(&[
        "scene",
        "examples/offset-kisch.toml",
        "--out",
        pdf.to_str().unwrap(),
    ]));
    pdf
}

#[test]
fn a_scene_file_is_written_as_pdf() {
    let dir = tempfile::tempdir().unwrap();
    let pdf = scene_pdf(dir.path());
    assert!(std::fs::read(&pdf).unwrap().starts_with(b"%PDF-"));
}

#[test]
#[ignore = "needs poppler-utils (pdffonts): run with `-- --ignored` (.ci/run does)"]
fn a_scene_files_pdf_embeds_its_fonts() {
    let dir = tempfile::tempdir().unwrap();
    fonts_embedded(&scene_pdf(dir.path()));
}

#[test]
fn unknown_extensions_are_refused_by_every_command_with_out() {
    let dir = tempfile::tempdir().unwrap();
    for name in ["x.jpg", "x.eps", "x.svgz", "x.pdf.part"] {
        let path = dir.path().join(name);
        let path = path.to_str().unwrap();
        for args in [
            vec!["figure", "fig-63-velocity", "--out", path],
            vec!["scene", "examples/overlay.toml", "--out", path],
        ] {
            let out = run(&args);
            assert_eq!(out.status.code(), Some(2), "{args:?}");
            assert!(out.stdout.is_empty());
            let err = String::from_utf8(out.stderr).unwrap();
            assert_eq!(err.lines().count(), 1, "{err}");
            assert!(
                err.contains(
                    "is not an output format: give a file ending in .svg, .png, .pdf or .tex"
                ),
                "{err}"
            );
            assert!(err.contains(name), "{err}");
            assert!(!Path::new(path).exists(), "{path} written");
        }
    }
    // Refused before anything is read: a missing scene file is not the
    // error.
    let out = run(&["scene", "missing.toml", "--out", "x.jpg"]);
    let err = String::from_utf8(out.stderr).unwrap();
    assert!(err.contains("x.jpg"), "{err}");
    // No extension: SVG, as for a device.
    let plain = dir.path().join("figure");
    succeeded(&run(&[
        "figure",
        "fig-63-velocity",
        "--out",
        plain.to_str().unwrap(),
    ]));
    assert!(std::fs::read(&plain).unwrap().starts_with(b"<svg"));
}
