//! `slider-crank gallery`: the whole catalogue in three formats, the
//! tables, and an index whose every link resolves.

use crate::command;
use command::{run, succeeded};
use slider_crank::FigureName;
use slider_crank::table::TableName;
use std::collections::BTreeSet;

/// The values of every `href="…"` and `src="…"` of the page.
fn links(html: &str) -> Vec<String> {
    let mut found = Vec::new();
    for attr in ["href=\"", "src=\""] {
        let mut rest = html;
        while let Some(i) = rest.find(attr) {
            rest = &rest[i + attr.len()..];
            let end = rest.find('"').unwrap();
            found.push(rest[..end].to_string());
            rest = &rest[end..];
        }
    }
    found
}

/// The caption of figure `name` in the page.
fn caption<'a>(html: &'a str, name: &str) -> &'a str {
    let start = html
        .find(&format!("<figure id=\"{name}\">"))
        .unwrap_or_else(|| panic!("no figure {name}"));
    let rest = &html[start..];
    let from = rest.find("<figcaption>").unwrap();
    let to = rest.find("</figcaption>").unwrap();
    &rest[from..to]
}

#[test]
fn the_gallery_holds_every_figure_table_and_a_sound_index() {
    let dir = tempfile::tempdir().unwrap();
    // A directory that does not exist yet, two levels down.
    let out_dir = dir.path().join("book/gallery");
    let out = run(&["gallery", "--out", out_dir.to_str().unwrap()]);
    succeeded(&out);
    assert!(out.stdout.is_empty());

    // One progress line per file (standard error is not a terminal here).
    let total = FigureName::ALL.len() * 3 + TableName::GALLERY.len() + 1;
    let stderr = String::from_utf8(out.stderr).unwrap();
    assert!(
        stderr.contains(&format!("gallery: 1/{total} fig-62-displacement.svg\n")),
        "{stderr}"
    );
    assert!(
        stderr.contains(&format!("gallery: {total}/{total} index.html\n")),
        "{stderr}"
    );
    assert_eq!(stderr.lines().count(), total + 1, "{stderr}");

    let files: BTreeSet<String> = std::fs::read_dir(&out_dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    assert_eq!(files.len(), total, "{files:?}"); // no temporary file left
    for f in FigureName::ALL {
        for (ext, magic) in [
            ("svg", &b"<svg"[..]),
            ("png", &b"\x89PNG"[..]),
            ("pdf", &b"%PDF-"[..]),
        ] {
            let name = format!("{}.{ext}", f.name());
            let bytes = std::fs::read(out_dir.join(&name)).unwrap();
            assert!(bytes.starts_with(magic), "{name}");
        }
        // The SVG is the one `figure NAME` prints.
        let svg = run(&["figure", f.name()]);
        assert!(
            svg.stdout == std::fs::read(out_dir.join(format!("{}.svg", f.name()))).unwrap(),
            "{}",
            f.name()
        );
    }
    // Each table is the one `table NAME` prints.
    for t in TableName::GALLERY {
        let printed = run(&["table", t.name()]);
        succeeded(&printed);
        let file = std::fs::read(out_dir.join(format!("table-{}.txt", t.name()))).unwrap();
        assert!(file == printed.stdout, "table {}", t.name());
    }

    let html = std::fs::read_to_string(out_dir.join("index.html")).unwrap();
    assert!(html.starts_with("<!DOCTYPE html>"));
    assert!(html.contains("<title>") && html.contains("</html>"));
    assert!(!html.contains("{{") && !html.contains("}}"));
    let linked: BTreeSet<String> = links(&html)
        .into_iter()
        .filter(|l| !l.starts_with('#'))
        .collect();
    for l in &linked {
        assert!(out_dir.join(l).is_file(), "index.html links to missing {l}");
    }
    for f in &files {
        assert!(
            f == "index.html" || linked.contains(f),
            "{f} not in the index"
        );
    }
    for f in FigureName::ALL {
        let c = caption(&html, f.name());
        let names_seed = (c.contains("Textbook, Chapter IV") && c.contains('§'))
            || (c.contains("Ng, ") && c.contains("Fig. "));
        assert!(
            names_seed || f == FigureName::CurveBenchmark,
            "{}: {c}",
            f.name()
        );
    }
    for fig in [
        "§36, Fig. 67",
        "§36, Fig. 65",
        "§34, Fig. 60",
        "Ng, ",
        "Fig. A1",
    ] {
        assert!(html.contains(fig), "{fig}");
    }
    assert!(
        html.contains("<caption>Static forces (Ng Table 2)"),
        "forces table"
    );
}

#[test]
fn a_path_that_is_not_a_directory_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("gallery");
    std::fs::write(&file, b"keep").unwrap();
    let out = run(&["gallery", "--out", file.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8(out.stderr).unwrap();
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.contains("it exists and is not a directory"), "{err}");
    assert_eq!(std::fs::read(&file).unwrap(), b"keep");
    // Under a file: cannot be created.
    let below = file.join("sub");
    let out = run(&["gallery", "--out", below.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8(out.stderr).unwrap();
    assert!(
        err.contains("cannot create the gallery's directory"),
        "{err}"
    );
}

#[test]
fn an_error_names_the_file_and_keeps_what_was_there() {
    let dir = tempfile::tempdir().unwrap();
    // A directory where a figure's file would go cannot be replaced.
    std::fs::create_dir(dir.path().join("fig-63-velocity.png")).unwrap();
    let out = run(&[
        "gallery",
        "--out",
        dir.path().to_str().unwrap(),
        "--only",
        "fig-63-velocity",
    ]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8(out.stderr).unwrap();
    let last = err.lines().last().unwrap();
    assert!(
        last.contains("fig-63-velocity.png") && last.contains("it is a directory"),
        "{err}"
    );
    // Refused before anything is made: the gallery is written whole or
    // not at all, and no temporary file is left.
    let names: Vec<String> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    assert_eq!(names, ["fig-63-velocity.png"]);
}

#[test]
fn a_manifest_chooses_the_contents_and_check_finds_what_differs() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::copy("examples/offset-kisch.toml", dir.path().join("kisch.toml")).unwrap();
    let manifest = dir.path().join("book.toml");
    std::fs::write(
        &manifest,
        "figures = [\"fig-63-velocity\"]\nscenes = [\"kisch.toml\"]\nformats = [\"svg\", \"pdf\"]\nfont = \"libertinus-serif\"\n",
    )
    .unwrap();
    let out_dir = dir.path().join("g");
    let (m, g) = (manifest.to_str().unwrap(), out_dir.to_str().unwrap());
    succeeded(&run(&["gallery", "--manifest", m, "--out", g]));
    let files: BTreeSet<String> = std::fs::read_dir(&out_dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    let mut expected: BTreeSet<String> = [
        "fig-63-velocity.svg",
        "fig-63-velocity.pdf",
        "kisch.svg",
        "kisch.pdf",
        "index.html",
    ]
    .map(String::from)
    .into();
    expected.extend(TableName::GALLERY.map(|t| format!("table-{}.txt", t.name())));
    assert_eq!(files, expected);
    let pdf = std::fs::read(out_dir.join("fig-63-velocity.pdf")).unwrap();
    assert!(String::from_utf8_lossy(&pdf).contains("LibertinusSerif-Italic"));
    let html = std::fs::read_to_string(out_dir.join("index.html")).unwrap();
    assert!(
        html.contains("Scene file <code>kisch.toml</code>"),
        "{html}"
    );

    // Up to date: exit 0, nothing on standard output.
    let check = run(&["gallery", "--manifest", m, "--out", g, "--check"]);
    succeeded(&check);
    assert!(check.stdout.is_empty());

    // One file changed, one removed: exit 1, each named, nothing written.
    std::fs::write(out_dir.join("kisch.svg"), b"changed").unwrap();
    std::fs::remove_file(out_dir.join("table-forces.txt")).unwrap();
    let check = run(&["gallery", "--manifest", m, "--out", g, "--check"]);
    assert_eq!(check.status.code(), Some(1));
    let said = String::from_utf8(check.stdout).unwrap();
    assert_eq!(said.lines().count(), 2, "{said}");
    assert!(said.contains("kisch.svg differs"), "{said}");
    assert!(said.contains("table-forces.txt is missing"), "{said}");
    assert_eq!(
        std::fs::read(out_dir.join("kisch.svg")).unwrap(),
        b"changed"
    );
    assert!(!out_dir.join("table-forces.txt").exists());

    // A bad manifest: one line with the line and column.
    std::fs::write(
        &manifest,
        "figures = [\"fig-63-velocity\"]\nstyle = \"sepia\"\n",
    )
    .unwrap();
    let bad = run(&["gallery", "--manifest", m, "--out", g]);
    assert_eq!(bad.status.code(), Some(2));
    let err = String::from_utf8(bad.stderr).unwrap();
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.contains("book.toml: line 2, column 9:"), "{err}");
}
