//! PDF output (`--out FILE.pdf`) and the choice of format by the file's
//! extension for every command that takes `--out`.
//!
//! The font and text checks read the PDF with poppler's `pdffonts` and
//! `pdftotext` (`.ci/run` installs them); where they are not installed
//! those checks are skipped with a note saying so.

use crate::command;
use command::{run, succeeded};
use std::path::Path;
use std::process::Command;

/// The standard output of a poppler tool run on `pdf`, or `None` (with
/// the reason printed) when the tool is not installed.
fn poppler(tool: &str, args: &[&str], pdf: &Path) -> Option<String> {
    let mut command = Command::new(tool);
    command.args(args).arg(pdf);
    if tool == "pdftotext" {
        command.arg("-"); // to standard output
    }
    match command.output() {
        Ok(out) => {
            assert!(
                out.status.success(),
                "{tool}: {}",
                String::from_utf8_lossy(&out.stderr)
            );
            Some(String::from_utf8(out.stdout).unwrap())
        }
        Err(e) => {
            eprintln!(
                "skipped: {tool} is not installed ({e}); install poppler-utils to check the PDF"
            );
            None
        }
    }
}

/// Asserts that every font of the PDF is embedded (`pdffonts`' emb column).
fn fonts_embedded(pdf: &Path) {
    let Some(list) = poppler("pdffonts", &[], pdf) else {
        return;
    };
    let rows: Vec<&str> = list.lines().skip(2).collect();
    assert!(!rows.is_empty(), "no fonts in {}:\n{list}", pdf.display());
    for row in rows {
        // name, type (one or more words), encoding, emb, sub, uni, object, generation
        let cols: Vec<&str> = row.split_whitespace().collect();
        let emb = cols[cols.len() - 5];
        assert_eq!(emb, "yes", "{}: {row}", pdf.display());
    }
}

#[test]
fn fig_67_as_pdf_embeds_its_face_and_its_text_can_be_read() {
    let dir = tempfile::tempdir().unwrap();
    let pdf = dir.path().join("x.pdf");
    let out = run(&["figure", "fig-67-example", "--out", pdf.to_str().unwrap()]);
    succeeded(&out);
    assert!(out.stdout.is_empty() && out.stderr.is_empty());
    let bytes = std::fs::read(&pdf).unwrap();
    assert!(bytes.starts_with(b"%PDF-"));
    // The same figure, the same bytes.
    let again = dir.path().join("again.PDF");
    succeeded(&run(&[
        "figure",
        "fig-67-example",
        "--out",
        again.to_str().unwrap(),
    ]));
    assert!(std::fs::read(&again).unwrap() == bytes);

    fonts_embedded(&pdf);
    if let Some(fonts) = poppler("pdffonts", &[], &pdf) {
        assert!(fonts.contains("NewCM10-Italic"), "{fonts}");
        assert!(fonts.contains("NewCM10-Regular"), "{fonts}");
    }
    if let Some(text) = poppler("pdftotext", &[], &pdf) {
        assert!(text.contains("Velocity scale"), "{text}");
        assert!(text.contains("Acceleration scale"), "{text}");
        assert!(text.contains("26.18 ft/s"), "{text}");
        let words: Vec<&str> = text.split_whitespace().collect();
        for letter in ["A", "B", "C", "D", "E", "F", "G", "H"] {
            assert!(words.contains(&letter), "point {letter} in {text}");
        }
    }
}

#[test]
fn the_chosen_face_is_the_one_embedded() {
    let dir = tempfile::tempdir().unwrap();
    let pdf = dir.path().join("ng.pdf");
    succeeded(&run(&[
        "figure",
        "ng-fig-1-torque",
        "--font",
        "libertinus-serif",
        "--style",
        "handout",
        "--out",
        pdf.to_str().unwrap(),
    ]));
    fonts_embedded(&pdf);
    if let Some(fonts) = poppler("pdffonts", &[], &pdf) {
        assert!(fonts.contains("LibertinusSerif"), "{fonts}");
        assert!(!fonts.contains("NewCM"), "{fonts}");
    }
}

#[test]
fn a_scene_file_is_written_as_pdf() {
    let dir = tempfile::tempdir().unwrap();
    let pdf = dir.path().join("scene.pdf");
    succeeded(&run(&[
        "scene",
        "examples/offset-kisch.toml",
        "--out",
        pdf.to_str().unwrap(),
    ]));
    assert!(std::fs::read(&pdf).unwrap().starts_with(b"%PDF-"));
    fonts_embedded(&pdf);
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
                err.contains("is not an output format: give a file ending in .svg, .png or .pdf"),
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
