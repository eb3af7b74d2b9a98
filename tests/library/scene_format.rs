//! The scene file format: its reference (docs/scene-format.md) names every
//! key the parser reads, its examples parse, the example files cover every
//! key, and the scene file printed for each named figure reads back to
//! that figure.

use slider_crank::catalogue::FigureOptions;
use slider_crank::render::to_svg;
use slider_crank::{FigureName, SceneFile};

#[test]
fn the_printed_scene_of_every_named_figure_draws_that_figure() {
    for name in FigureName::ALL {
        let text = name.scene_toml();
        let file =
            SceneFile::from_toml(&text).unwrap_or_else(|e| panic!("{}: {e}\n{text}", name.name()));
        if !name.is_diagram() {
            // Every key is written out: the file does not start from the
            // figure.
            assert!(!text.contains("\nfigure ="), "{}", name.name());
            assert!(matches!(file, SceneFile::Mechanism(_)), "{}", name.name());
        }
        let from_file = to_svg(&file.figure().unwrap());
        let own = to_svg(&name.figure(&FigureOptions::default()).unwrap());
        assert!(from_file == own, "{}: the SVG differs\n{text}", name.name());
    }
}

const REFERENCE: &str = "docs/scene-format.md";

fn reference() -> String {
    std::fs::read_to_string(REFERENCE).expect("the reference is readable")
}

/// The sections of a Markdown text: each `## ` heading's title with the
/// lines below it up to the next.
fn sections(doc: &str) -> Vec<(String, Vec<&str>)> {
    let mut out: Vec<(String, Vec<&str>)> = Vec::new();
    for line in doc.lines() {
        if let Some(title) = line.strip_prefix("## ") {
            out.push((title.trim().to_string(), Vec::new()));
        } else if let Some((_, lines)) = out.last_mut() {
            lines.push(line);
        }
    }
    out
}

/// The cells of a table row `| a | b \| c |`, escaped bars kept in their
/// cell.
fn cells(row: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut cell = String::new();
    let mut chars = row.trim().trim_start_matches('|').chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '\\' if chars.peek() == Some(&'|') => {
                cell.push('|');
                chars.next();
            }
            '|' => out.push(std::mem::take(&mut cell).trim().to_string()),
            c => cell.push(c),
        }
    }
    out
}

/// The rows of the key tables of a section: the key (the first cell, in
/// backquotes) and the cells.
fn key_rows(lines: &[&str]) -> Vec<(String, Vec<String>)> {
    lines
        .iter()
        .filter(|l| l.starts_with("| `"))
        .map(|l| {
            let c = cells(l);
            (c[0].trim_matches('`').to_string(), c)
        })
        .collect()
}

/// The section that documents the keys of `table` (`None`: the top level).
fn section_of<'a>(
    all: &'a [(String, Vec<&'a str>)],
    table: Option<&str>,
) -> Option<&'a (String, Vec<&'a str>)> {
    let title = match table {
        Some(t) => format!("`[{t}]`"),
        None => "Top level".to_string(),
    };
    all.iter().find(|(t, _)| *t == title)
}

/// `key` split into its table and its name (`page.width`).
fn split(key: &str) -> (Option<&str>, &str) {
    match key.split_once('.') {
        Some((t, k)) => (Some(t), k),
        None => (None, key),
    }
}

#[test]
fn every_key_of_the_parser_has_its_row_in_the_reference() {
    let doc = reference();
    let all = sections(&doc);
    let keys = SceneFile::keys();
    assert!(keys.len() > 20, "{keys:?}");
    let tables: Vec<&str> = keys
        .iter()
        .filter_map(|k| k.split_once('.').map(|(t, _)| t))
        .collect();
    let mut missing = Vec::new();
    for key in &keys {
        if tables.contains(&key.as_str()) {
            // A table: a section of its own.
            if section_of(&all, Some(key)).is_none() {
                missing.push(format!("a section `## \\`[{key}]\\``"));
            }
            continue;
        }
        let (table, name) = split(key);
        let found = section_of(&all, table)
            .is_some_and(|(_, lines)| key_rows(lines).iter().any(|(k, _)| k == name));
        if !found {
            missing.push(format!(
                "a row `| \\`{name}\\` |` under {}",
                table.map_or("`## Top level`".to_string(), |t| format!(
                    "`## \\`[{t}]\\``"
                ))
            ));
        }
    }
    assert!(
        missing.is_empty(),
        "{REFERENCE} lacks keys the parser reads:\n  {}",
        missing.join("\n  ")
    );
}

#[test]
fn every_row_of_the_reference_is_a_key_and_its_example_parses() {
    let doc = reference();
    let keys = SceneFile::keys();
    let mut rows = 0;
    for (title, lines) in sections(&doc) {
        let table = match title.as_str() {
            "Top level" => None,
            t if t.starts_with("`[") => Some(t.trim_matches(|c| "`[]".contains(c)).to_string()),
            _ => continue,
        };
        for (key, cells) in key_rows(&lines) {
            rows += 1;
            let full = match &table {
                Some(t) => format!("{t}.{key}"),
                None => key.clone(),
            };
            assert!(keys.contains(&full), "{full}: no such key in the parser");
            assert_eq!(cells.len(), 5, "{full}: key, type, default, range, example");
            // The example: `key = value`, read inside a minimal file.
            let example = cells[4].trim_matches('`');
            assert!(
                example.starts_with(&format!("{key} = ")),
                "{full}: the example {example:?} sets another key"
            );
            let file = match table.as_deref() {
                // The keys of the engine dynamics diagrams alone, read in
                // the file of one of them (a mechanism figure refuses them).
                None if ["mass", "fluctuation"].contains(&key.as_str()) => {
                    format!("figure = \"flywheel\"\n{example}\n")
                }
                None => format!("{example}\n"),
                Some("mechanism") => {
                    let mut f = format!("[mechanism]\n{example}\n");
                    for (k, v) in [("crank", "0.5"), ("rod", "3")] {
                        if key != k {
                            f.push_str(&format!("{k} = {v}\n"));
                        }
                    }
                    f
                }
                Some(t) => format!("[{t}]\n{example}\n"),
            };
            SceneFile::from_toml(&file)
                .and_then(|f| f.figure())
                .unwrap_or_else(|e| panic!("{full}: the example {example:?}: {e}"));
        }
    }
    assert_eq!(rows, keys.iter().filter(|k| !is_table(&keys, k)).count());
}

fn is_table(keys: &[String], key: &str) -> bool {
    keys.iter().any(|k| k.starts_with(&format!("{key}.")))
}

/// The ```toml blocks of a Markdown text.
fn toml_blocks(doc: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut block: Option<String> = None;
    for line in doc.lines() {
        match &mut block {
            None if line.trim() == "```toml" => block = Some(String::new()),
            Some(b) if line.trim() == "```" => {
                out.push(std::mem::take(b));
                block = None;
            }
            Some(b) => {
                b.push_str(line);
                b.push('\n');
            }
            None => {}
        }
    }
    assert!(block.is_none(), "an unclosed block");
    out
}

#[test]
fn every_toml_block_of_the_reference_is_a_whole_file_that_draws() {
    let blocks = toml_blocks(&reference());
    assert!(blocks.len() >= 3, "only {} blocks", blocks.len());
    for block in blocks {
        let svg = SceneFile::from_toml(&block)
            .and_then(|f| f.figure())
            .map(|f| to_svg(&f))
            .unwrap_or_else(|e| panic!("{e}\n{block}"));
        assert!(!svg.contains("NaN"), "{block}");
    }
}

/// The example scene files, with their text.
fn examples() -> Vec<(std::path::PathBuf, String)> {
    let mut out: Vec<_> = std::fs::read_dir("examples")
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .map(|p| {
            let text = std::fs::read_to_string(&p).unwrap();
            (p, text)
        })
        .collect();
    out.sort();
    out
}

#[test]
fn every_example_parses_and_draws_its_figure() {
    let all = examples();
    assert!(all.len() >= 9, "only {} examples", all.len());
    for (path, text) in all {
        let figure = SceneFile::from_toml(&text)
            .and_then(|f| f.figure())
            .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        let svg = to_svg(&figure);
        assert!(svg.starts_with("<svg"), "{}", path.display());
        assert!(!svg.contains("NaN"), "{}", path.display());
    }
}

#[test]
fn the_examples_together_use_every_key() {
    let mut used = std::collections::BTreeSet::new();
    for (_, text) in examples() {
        let table: toml::Table = toml::from_str(&text).unwrap();
        for (k, v) in &table {
            used.insert(k.clone());
            if let toml::Value::Table(inner) = v {
                used.extend(inner.keys().map(|i| format!("{k}.{i}")));
            }
        }
    }
    let unused: Vec<String> = SceneFile::keys()
        .into_iter()
        .filter(|k| !used.contains(k))
        .collect();
    assert!(unused.is_empty(), "no example uses {unused:?}");
}

#[test]
fn the_diagram_table_says_which_keys_each_diagram_takes() {
    let doc = reference();
    let all = sections(&doc);
    let (_, lines) = all
        .iter()
        .find(|(t, _)| t == "Files that start from a diagram")
        .expect("the section on diagrams");
    let header = lines
        .iter()
        .find(|l| l.starts_with("| diagram |"))
        .map(|l| cells(l))
        .expect("the table's header");
    // Each column's keys, as a snippet that sets them.
    let snippet = |column: &str| -> Vec<&'static str> {
        match column {
            "`[mechanism]`" => vec!["[mechanism]\ncrank = 0.5\nrod = 3\n"],
            "`angle`" => vec!["angle = 30\n"],
            "`rpm`, `omega`" => vec!["rpm = 100\n", "omega = 10\n"],
            "`mirror`" => vec!["mirror = false\n"],
            "`mass`" => vec!["mass = 2\n"],
            "`fluctuation`" => vec!["fluctuation = 0.05\n"],
            other => panic!("a column of no key: {other}"),
        }
    };
    let mut named = Vec::new();
    for (name, row) in key_rows(lines) {
        let figure = FigureName::from_name(&name).unwrap();
        assert!(figure.is_diagram(), "{name}");
        named.push(figure);
        for (column, cell) in header.iter().zip(&row).skip(1) {
            let takes = match cell.split_whitespace().next() {
                Some("yes") => true,
                Some("no") => false,
                _ => panic!("{name}, {column}: {cell:?} is neither yes nor no"),
            };
            for s in snippet(column) {
                let file = format!("figure = \"{name}\"\n{s}");
                let read = SceneFile::from_toml(&file);
                assert_eq!(
                    read.is_ok(),
                    takes,
                    "{name}, {column}: the reference says {cell:?}, the parser {read:?}"
                );
            }
        }
    }
    let mut all_diagrams = FigureName::DIAGRAMS.to_vec();
    all_diagrams.sort();
    named.sort();
    assert_eq!(named, all_diagrams, "every diagram has its row");
}
