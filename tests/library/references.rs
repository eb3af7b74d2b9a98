//! Every path the repository's own text names exists.
//!
//! The documents, sources, tests, benchmarks and examples cite files by
//! their path from the repository root (`docs/accuracy.md`,
//! `tests/library/seeds.rs`, `examples/*.toml`, `snapshots/`), by a bare Markdown
//! file name (`seed-errata.md`, found at the root, beside the citing file or
//! in `docs/`) and, in Markdown, by relative links (`[…](figures/)`,
//! resolved from the citing file's directory). A path that does not exist
//! is a broken reference, reported with its file and line.

use std::path::{Path, PathBuf};

/// The folders a root-relative path starts with.
const ROOTS: [&str; 7] = [
    "docs/",
    "src/",
    "tests/",
    "snapshots/",
    "examples/",
    "benches/",
    "fuzz/",
];

/// One broken reference: the citing file, its line and the path cited.
#[derive(Debug, Clone, PartialEq, Eq)]
struct Broken {
    file: String,
    line: usize,
    cited: String,
}

fn repo() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The files whose text is checked, relative to the root.
fn scanned_files(root: &Path) -> Vec<PathBuf> {
    let mut files = vec![
        PathBuf::from("README.md"),
        PathBuf::from("Cargo.toml"),
        PathBuf::from("fuzz/README.md"),
    ];
    for (dir, exts) in [
        ("docs", &["md"][..]),
        ("src", &["rs"][..]),
        ("tests", &["rs"][..]),
        ("benches", &["rs"][..]),
        ("examples", &["rs", "toml"][..]),
        ("fuzz/fuzz_targets", &["rs"][..]),
    ] {
        walk(root, Path::new(dir), exts, &mut files);
    }
    files.retain(|f| root.join(f).is_file());
    files.sort();
    files
}

fn walk(root: &Path, dir: &Path, exts: &[&str], out: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(root.join(dir)) else {
        return;
    };
    for entry in entries.flatten() {
        let rel = dir.join(entry.file_name());
        let path = root.join(&rel);
        if path.is_dir() {
            walk(root, &rel, exts, out);
        } else if rel
            .extension()
            .and_then(|e| e.to_str())
            .is_some_and(|e| exts.contains(&e))
        {
            out.push(rel);
        }
    }
}

fn is_path_char(c: char) -> bool {
    c.is_ascii_alphanumeric() || matches!(c, '_' | '-' | '.' | '/' | '*')
}

/// Whether `text[..at]` ends where a path may begin (not inside a word, a
/// URL or a longer path).
fn starts_token(text: &str, at: usize) -> bool {
    text[..at]
        .chars()
        .next_back()
        .is_none_or(|c| !(is_path_char(c) || c == ':' || c == '\\'))
}

/// The path-like run of characters starting at `at`, without the
/// punctuation that ends a sentence.
fn token_at(text: &str, at: usize) -> &str {
    let end = text[at..]
        .char_indices()
        .find(|&(_, c)| !is_path_char(c))
        .map_or(text.len(), |(i, _)| at + i);
    text[at..end].trim_end_matches(['.', ','])
}

/// Words that stand for any name in a cited path (`docs/figures/NAME.png`),
/// as in the program's usage lines.
const PLACEHOLDERS: [&str; 2] = ["NAME", "FILE"];

/// Whether `cited` (relative to `base`) names something in the tree: a
/// file or folder, or for a pattern with `*` or a placeholder at least its
/// fixed folder.
fn exists(base: &Path, cited: &str) -> bool {
    let wild = cited.split('/').position(|part| {
        part.contains('*') || PLACEHOLDERS.contains(&part.split('.').next().unwrap_or(""))
    });
    let cited = match wild {
        Some(i) => cited
            .split('/')
            .take(i)
            .chain(["*"])
            .collect::<Vec<_>>()
            .join("/"),
        None => cited.to_string(),
    };
    match cited.find('*') {
        Some(star) => {
            let fixed = &cited[..star];
            let dir = match fixed.rfind('/') {
                Some(slash) => &fixed[..slash],
                None => "",
            };
            base.join(dir).is_dir()
        }
        None => base.join(cited).exists(),
    }
}

/// The references of one file's `text` (`file` relative to `root`) that
/// do not resolve.
fn broken_in(root: &Path, file: &Path, text: &str) -> Vec<Broken> {
    let dir = file.parent().unwrap_or(Path::new(""));
    let markdown = file.extension().is_some_and(|e| e == "md");
    let mut broken = Vec::new();
    for (n, line) in text.lines().enumerate() {
        let mut report = |cited: &str| {
            broken.push(Broken {
                file: file.display().to_string(),
                line: n + 1,
                cited: cited.to_string(),
            })
        };
        // Root-relative paths: docs/…, src/…, tests/…
        for prefix in ROOTS {
            for (at, _) in line.match_indices(prefix) {
                if !starts_token(line, at) {
                    continue;
                }
                let cited = token_at(line, at);
                if !exists(root, cited) {
                    report(cited);
                }
            }
        }
        // Bare Markdown file names: at the root, beside the file, in docs/.
        for (at, _) in line.match_indices(".md") {
            let after = line[at + 3..].chars().next();
            if after.is_some_and(|c| c.is_ascii_alphanumeric()) {
                continue;
            }
            let start = line[..at]
                .char_indices()
                .rev()
                .take_while(|&(_, c)| c.is_ascii_alphanumeric() || c == '_' || c == '-')
                .last()
                .map_or(at, |(i, _)| i);
            if start == at || !starts_token(line, start) {
                continue;
            }
            let name = &line[start..at + 3];
            if ![root.to_path_buf(), root.join(dir), root.join("docs")]
                .iter()
                .any(|base| base.join(name).is_file())
            {
                report(name);
            }
        }
        // Markdown links, relative to the file's folder.
        if markdown {
            for (at, _) in line.match_indices("](") {
                let rest = &line[at + 2..];
                let Some(close) = rest.find(')') else {
                    continue;
                };
                let target = rest[..close].split_whitespace().next().unwrap_or("");
                let target = target.split('#').next().unwrap_or("");
                if target.is_empty() || target.contains("://") || target.starts_with("mailto:") {
                    continue;
                }
                if !exists(&root.join(dir), target) {
                    report(target);
                }
            }
        }
    }
    // A name cited twice on a line (a link to a bare file name) once.
    broken.sort_by(|a, b| (a.line, &a.cited).cmp(&(b.line, &b.cited)));
    broken.dedup();
    broken
}

#[test]
fn every_cited_path_exists() {
    let root = repo();
    let files = scanned_files(&root);
    // The walk found the tree (a wrong root would pass vacuously).
    assert!(files.len() > 50, "{files:?}");
    for must in [
        "README.md",
        "docs/design.md",
        "src/lib.rs",
        "tests/program/cli.rs",
    ] {
        assert!(files.contains(&PathBuf::from(must)), "{must} not scanned");
    }
    let mut broken = Vec::new();
    for file in &files {
        let text = std::fs::read_to_string(root.join(file)).expect("UTF-8 text");
        broken.extend(broken_in(&root, file, &text));
    }
    assert!(
        broken.is_empty(),
        "references to paths that do not exist:\n{}",
        broken
            .iter()
            .map(|b| format!("  {}:{}: {}", b.file, b.line, b.cited))
            .collect::<Vec<_>>()
            .join("\n")
    );
}

#[test]
fn a_broken_reference_is_caught() {
    let root = repo();
    // Written in pieces so that this file itself cites nothing missing.
    let missing_doc = ["docs/", "no-such-page", ".md"].concat();
    let missing_bare = ["NO-SUCH-NOTES", ".md"].concat();
    let missing_glob = ["examples/", "nowhere/*.toml"].concat();
    let text = [
        format!("see {missing_doc} §2; the PNGs are docs/figures/NAME.png"),
        format!("the design in `{missing_bare}`"),
        "the tests in tests/program/cli.rs and the figures in docs/figures/".to_string(),
        format!("scene files: examples/*.toml; none in {missing_glob}"),
        "https://example.org/src/not-here.rs is a URL, not a path".to_string(),
        ["[errata](seed-errata.md) and [gone](", "gone", ".md#top)"].concat(),
    ]
    .join("\n");
    let citing = Path::new("docs").join(["x", ".md"].concat());
    let cited: Vec<(usize, String)> = broken_in(&root, &citing, &text)
        .into_iter()
        .map(|b| (b.line, b.cited))
        .collect();
    assert_eq!(
        cited,
        vec![
            (1, missing_doc),
            (2, missing_bare),
            (4, missing_glob),
            (6, ["gone", ".md"].concat()),
        ]
    );
}
