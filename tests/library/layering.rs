//! The layering of `src/` (docs/design.md, "Layering"): every module
//! imports only from the modules its row of the table names, read from
//! every `crate::` path of the code the library compiles: comments,
//! literals and `#[cfg(test)] mod … { … }` blocks left out (the code after
//! a test module read), a `use crate::{ … }` group read whole however many
//! lines it takes; a name the crate root re-exports is imported from its
//! defining module, never through the root. The crate root only declares
//! modules and re-exports.

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

/// The table of docs/design.md: module → the modules it may import.
fn allowed() -> BTreeMap<String, BTreeSet<String>> {
    let design = std::fs::read_to_string("docs/design.md").unwrap();
    let start = design.find("### Layering").expect("a Layering section");
    let section = &design[start..];
    let end = section[4..].find("\n### ").map_or(section.len(), |e| e + 4);
    let mut table = BTreeMap::new();
    for line in section[..end].lines() {
        let cells: Vec<&str> = line.split('|').map(str::trim).collect();
        let [_, module, imports, _] = cells.as_slice() else {
            continue;
        };
        let Some(module) = module.strip_prefix('`').and_then(|m| m.strip_suffix('`')) else {
            continue;
        };
        let may = imports
            .split(',')
            .map(str::trim)
            .filter(|m| !m.is_empty() && !m.starts_with('('))
            .map(String::from)
            .collect();
        table.insert(module.to_string(), may);
    }
    table
}

/// The names the crate root re-exports, by the module that defines them
/// (`Angle` → `angle`), read from its `pub use` items.
fn root_names() -> BTreeMap<String, String> {
    let lib = std::fs::read_to_string("src/lib.rs").unwrap();
    let mut names = BTreeMap::new();
    for item in lib.split(';') {
        let item = item.trim();
        let Some(rest) = item.rsplit("\n").next().and_then(|_| item.find("pub use ")) else {
            continue;
        };
        let path = &item[rest + "pub use ".len()..];
        let module = path.split("::").next().unwrap_or("").to_string();
        let tail = path.rsplit("::").next().unwrap_or("");
        let tail = match (path.find('{'), path.rfind('}')) {
            (Some(a), Some(b)) => &path[a + 1..b],
            _ => tail,
        };
        for name in tail.split(',').map(str::trim).filter(|n| !n.is_empty()) {
            names.insert(name.to_string(), module.clone());
        }
    }
    names
}

/// The source files of `dir`, recursively.
pub(super) fn files(dir: &Path, out: &mut Vec<std::path::PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// `text` with its comments and the insides of its string and character
/// literals blanked (spaces; each newline kept, so that a line of the
/// result is the same line of the file): what is left is code. Handles
/// nested block comments, raw strings (`r#"…"#`), escapes, and tells a
/// character literal (`'{'`, `'\''`) from a lifetime or label (`'a`).
pub(super) fn blank_comments_and_literals(text: &str) -> String {
    let chars: Vec<char> = text.chars().collect();
    let mut out = String::with_capacity(text.len());
    let blank = |out: &mut String, c: char| out.push(if c == '\n' { '\n' } else { ' ' });
    let ident = |c: char| c.is_alphanumeric() || c == '_';
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        let next = chars.get(i + 1).copied();
        if c == '/' && next == Some('/') {
            while i < chars.len() && chars[i] != '\n' {
                blank(&mut out, chars[i]);
                i += 1;
            }
        } else if c == '/' && next == Some('*') {
            let mut depth = 0;
            while i < chars.len() {
                if chars[i] == '/' && chars.get(i + 1) == Some(&'*') {
                    depth += 1;
                    out.push_str("  ");
                    i += 2;
                } else if chars[i] == '*' && chars.get(i + 1) == Some(&'/') {
                    depth -= 1;
                    out.push_str("  ");
                    i += 2;
                    if depth == 0 {
                        break;
                    }
                } else {
                    blank(&mut out, chars[i]);
                    i += 1;
                }
            }
        } else if c == 'r'
            && (i == 0
                || !ident(chars[i - 1])
                || (chars[i - 1] == 'b' && (i < 2 || !ident(chars[i - 2]))))
            && matches!(next, Some('"' | '#'))
        {
            // A raw string r"…", r#"…"# (or a raw identifier r#name, left).
            let hashes = chars[i + 1..].iter().take_while(|&&h| h == '#').count();
            if chars.get(i + 1 + hashes) != Some(&'"') {
                out.push(c);
                i += 1;
                continue;
            }
            let open = i + 1 + hashes + 1;
            out.extend(&chars[i..open]);
            i = open;
            let closes = |at: usize| {
                chars[at] == '"' && (1..=hashes).all(|k| chars.get(at + k) == Some(&'#'))
            };
            while i < chars.len() && !closes(i) {
                blank(&mut out, chars[i]);
                i += 1;
            }
            let close = (i + 1 + hashes).min(chars.len());
            out.extend(&chars[i..close]);
            i = close;
        } else if c == '"' {
            out.push('"');
            i += 1;
            while i < chars.len() && chars[i] != '"' {
                if chars[i] == '\\' {
                    blank(&mut out, chars[i]);
                    i += 1;
                }
                if i < chars.len() {
                    blank(&mut out, chars[i]);
                    i += 1;
                }
            }
            if i < chars.len() {
                out.push('"');
                i += 1;
            }
        } else if c == '\'' && (next == Some('\\') || chars.get(i + 2) == Some(&'\'')) {
            // A character literal: '\…' up to its closing quote, or 'x'.
            out.push('\'');
            i += 1;
            if chars[i] == '\\' {
                // the backslash and the character it escapes (`'\''`)
                blank(&mut out, chars[i]);
                if let Some(&escaped) = chars.get(i + 1) {
                    blank(&mut out, escaped);
                }
                i += 2;
            }
            while i < chars.len() && chars[i] != '\'' {
                blank(&mut out, chars[i]);
                i += 1;
            }
            if i < chars.len() {
                out.push('\'');
                i += 1;
            }
        } else {
            out.push(c);
            i += 1;
        }
    }
    out
}

/// `code` (comments and literals blanked) with every `#[cfg(test)] mod
/// name { … }` blanked whole, newlines kept; other attributes may stand
/// between the two. Any other `#[cfg(test)]` item is kept and read.
fn without_test_modules(code: &str) -> String {
    let mut out = String::with_capacity(code.len());
    let mut kept = 0;
    for span in test_module_spans(code) {
        out.push_str(&code[kept..span.start]);
        let skipped = &code[span.clone()];
        out.extend(skipped.chars().map(|c| if c == '\n' { '\n' } else { ' ' }));
        kept = span.end;
    }
    out.push_str(&code[kept..]);
    out
}

/// Where each `#[cfg(test)] mod name { … }` of `code` (comments and
/// literals blanked) stands, from its attribute to its closing brace, as
/// byte ranges in order.
pub(super) fn test_module_spans(code: &str) -> Vec<std::ops::Range<usize>> {
    const MARK: &str = "#[cfg(test)]";
    let mut spans = Vec::new();
    let mut from = 0;
    while let Some(found) = code[from..].find(MARK) {
        let at = from + found;
        let after = &code[at + MARK.len()..];
        let Some(open) = test_module_body(after) else {
            from = at + MARK.len();
            continue;
        };
        // The matching brace: literals and comments are blanked already.
        let mut depth = 0;
        let mut close = after.len();
        for (k, ch) in after[open..].char_indices() {
            match ch {
                '{' => depth += 1,
                '}' => {
                    depth -= 1;
                    if depth == 0 {
                        close = open + k + 1;
                        break;
                    }
                }
                _ => {}
            }
        }
        spans.push(at..at + MARK.len() + close);
        from = at + MARK.len() + close;
    }
    spans
}

/// Where the body (`{`) of the module opens in `after`, the text after a
/// `#[cfg(test)]`, if the item it marks is a `mod name { … }` (past other
/// attributes and an optional visibility).
fn test_module_body(after: &str) -> Option<usize> {
    let mut rest = after.trim_start();
    while rest.starts_with("#[") {
        rest = rest[rest.find(']')? + 1..].trim_start();
    }
    for vis in ["pub(crate) ", "pub(super) ", "pub "] {
        rest = rest.strip_prefix(vis).unwrap_or(rest).trim_start();
    }
    let name = rest.strip_prefix("mod ")?.trim_start();
    let end = name
        .find(|c: char| !(c.is_alphanumeric() || c == '_'))
        .unwrap_or(name.len());
    let body = name[end..].trim_start();
    body.starts_with('{').then(|| after.len() - body.len())
}

/// The code of a source file as the library is compiled: its comments,
/// literals and test modules blanked, each line where it was.
fn production(text: &str) -> String {
    without_test_modules(&blank_comments_and_literals(text))
}

/// The names right after each `crate::` of `code`, with the byte offset
/// where each stands: `crate::geom::Point` gives `geom`, `crate::{Angle,
/// render::{fmt, svg}}` gives `Angle` and `render`, its lines joined or
/// not.
fn heads(code: &str) -> Vec<(usize, &str)> {
    let name_at = |at: usize| {
        let s = &code[at..];
        let end = s
            .find(|c: char| !(c.is_alphanumeric() || c == '_'))
            .unwrap_or(s.len());
        (end > 0).then(|| (at, &s[..end]))
    };
    let mut out = Vec::new();
    let mut from = 0;
    while let Some(found) = code[from..].find("crate::") {
        let start = from + found;
        let after = start + "crate::".len();
        from = after;
        // `crate::`, not the end of a longer name (`my_crate::`)
        if code[..start]
            .chars()
            .next_back()
            .is_some_and(|c| c.is_alphanumeric() || c == '_')
        {
            continue;
        }
        let open = after + (code[after..].len() - code[after..].trim_start().len());
        if !code[open..].starts_with('{') {
            out.extend(name_at(open));
            continue;
        }
        // A group: the first name of each of its top-level items.
        let mut depth = 0;
        let mut item = open + 1;
        for (k, ch) in code[open..].char_indices() {
            let at = open + k;
            match ch {
                '{' => {
                    depth += 1;
                    if depth == 1 {
                        item = at + 1;
                    }
                }
                ',' | '}' if depth == 1 => {
                    let text = &code[item..at];
                    let lead = text.len() - text.trim_start().len();
                    out.extend(name_at(item + lead));
                    item = at + 1;
                    if ch == '}' {
                        break;
                    }
                }
                '}' => depth -= 1,
                _ => {}
            }
        }
    }
    out
}

/// The line (from 1) of byte `at` of `text`.
fn line_of(text: &str, at: usize) -> usize {
    text[..at].matches('\n').count() + 1
}

/// What of `code` (a [`production`] text) breaks the layering for
/// `module`: each import of a module of `table` outside `module`'s row, as
/// `line: module → target` (a name the root re-exports counted as its
/// defining module), and each name of the root's reached through the root,
/// as `line: crate::Name`.
fn violations(
    module: &str,
    code: &str,
    table: &BTreeMap<String, BTreeSet<String>>,
    roots: &BTreeMap<String, String>,
) -> (Vec<String>, Vec<String>) {
    let may = &table[module];
    let (mut wrong, mut through_root) = (Vec::new(), Vec::new());
    for (at, name) in heads(code) {
        let line = line_of(code, at);
        if roots.contains_key(name) {
            through_root.push(format!("{line}: crate::{name}"));
        }
        let target = roots.get(name).map_or(name, String::as_str);
        if table.contains_key(target) && target != module && !may.contains(target) {
            wrong.push(format!("{line}: {module} → {target}"));
        }
    }
    (wrong, through_root)
}

#[test]
fn every_import_runs_down_the_layering_table() {
    let table = allowed();
    let roots = root_names();
    assert!(table.len() >= 20, "the table has {} rows", table.len());
    let mut paths = Vec::new();
    files(Path::new("src"), &mut paths);
    paths.sort();
    let mut wrong = Vec::new();
    let mut through_root = Vec::new();
    let mut seen = BTreeSet::new();
    for path in &paths {
        let rel = path.strip_prefix("src").unwrap();
        let first = rel
            .components()
            .next()
            .unwrap()
            .as_os_str()
            .to_string_lossy();
        let module = first.trim_end_matches(".rs").to_string();
        if ["lib", "main", "cli"].contains(&module.as_str()) {
            continue;
        }
        seen.insert(module.clone());
        assert!(
            table.contains_key(&module),
            "src/{first} has no row in the layering table"
        );
        let text = std::fs::read_to_string(path).unwrap();
        let (w, r) = violations(&module, &production(&text), &table, &roots);
        let file = path.display();
        wrong.extend(w.into_iter().map(|v| format!("{file}:{v}")));
        through_root.extend(r.into_iter().map(|v| format!("{file}:{v}")));
    }
    assert!(
        wrong.is_empty(),
        "imports against the layering:\n{}",
        wrong.join("\n")
    );
    assert!(
        through_root.is_empty(),
        "names imported through the crate root (import them from their module):\n{}",
        through_root.join("\n")
    );
    // Every row names a module that exists, and every module has a row.
    let rows: BTreeSet<String> = table.keys().cloned().collect();
    assert_eq!(rows, seen, "the table's rows and the modules of src/");
}

/// A small table for the reader's own tests: `geom` may import `number`,
/// `render` may import `geom` and `number`; `angle` and `number` nothing.
fn small_table() -> BTreeMap<String, BTreeSet<String>> {
    [
        ("geom", &["number"][..]),
        ("render", &["geom", "number"][..]),
        ("angle", &[][..]),
        ("number", &[][..]),
    ]
    .into_iter()
    .map(|(m, may)| (m.to_string(), may.iter().map(|s| s.to_string()).collect()))
    .collect()
}

/// The reader catches what it must: a path, a group and a root name.
#[test]
fn the_reader_finds_modules_behind_paths_groups_and_root_names() {
    let roots = root_names();
    assert_eq!(roots.get("Angle").map(String::as_str), Some("angle"));
    assert_eq!(
        roots.get("SliderCrank").map(String::as_str),
        Some("mechanism")
    );
    let line = "use crate::{Angle, geom::Point}; let x = crate::render::fmt(1.0);";
    let names: Vec<&str> = heads(line).into_iter().map(|(_, n)| n).collect();
    assert_eq!(names, ["Angle", "geom", "render"]);
    let (wrong, through_root) = violations("geom", line, &small_table(), &roots);
    assert_eq!(wrong, ["1: geom → angle", "1: geom → render"]);
    assert_eq!(through_root, ["1: crate::Angle"]);
    let call = "let w = crate::rpm_to_omega(250.0);";
    let (_, through_root) = violations("number", call, &small_table(), &roots);
    assert_eq!(through_root, ["1: crate::rpm_to_omega"]);
    let own = violations("geom", "use crate::angle::Angle;", &small_table(), &roots);
    assert_eq!(own.1, Vec::<String>::new());
    assert_eq!(own.0, ["1: geom → angle"]);
}

/// An import after a test module is read (the reader once stopped at the
/// first `#[cfg(test)]`), and the test module itself is not, however many
/// braces its strings, characters and comments hold.
#[test]
fn a_violation_after_a_test_module_is_found() {
    let text = r##"use crate::number::plain;

#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod tests {
    use crate::render::svg; // the tests may use anything }
    fn f() -> usize {
        let s = "}}} crate::angle::Angle {";
        let c = '}';
        let q = '\'';
        let r = r#"} "crate::render" }"#;
        /* } /* } */ crate::angle */
        s.len() + r.len() + q.len_utf8() + c.len_utf8()
    }
}

#[cfg(test)]
fn test_helper<'a>(x: &'a str) -> &'a str { x }

pub fn later() -> String {
    crate::render::fmt(1.0)
}
"##;
    let code = production(text);
    let (wrong, through_root) = violations("geom", &code, &small_table(), &root_names());
    assert_eq!(wrong, ["21: geom → render"]);
    assert!(through_root.is_empty(), "{through_root:?}");
    // Only the test module is left out, and every line stays where it was.
    assert!(code.contains("test_helper"), "{code}");
    assert_eq!(code.lines().count(), text.lines().count());
}

/// An import inside a `use crate::{ … }` group written over several lines
/// (nested groups too) is read, at the line of its name.
#[test]
fn a_violation_inside_a_multi_line_use_group_is_found() {
    let text = "use crate::{
    number::plain,
    render::{
        fmt,
        svg::{self, Writer},
    },
    Angle,
};
let my_crate = 1;
let d = crate::
    angle::Angle::deg(my_crate::ONE);
";
    let (wrong, through_root) =
        violations("geom", &production(text), &small_table(), &root_names());
    assert_eq!(
        wrong,
        ["3: geom → render", "7: geom → angle", "11: geom → angle"]
    );
    assert_eq!(through_root, ["7: crate::Angle"]);
}

/// The crate root declares modules and re-exports, nothing else: no
/// function, type, impl or macro sits there for lower modules to import.
#[test]
fn the_crate_root_only_declares_and_reexports() {
    let lib = std::fs::read_to_string("src/lib.rs").unwrap();
    let body = production(&lib);
    for line in body.lines().map(str::trim) {
        let item = [
            "fn ",
            "pub fn ",
            "struct ",
            "pub struct ",
            "enum ",
            "pub enum ",
        ]
        .iter()
        .chain(&[
            "impl ",
            "impl<",
            "macro_rules!",
            "const ",
            "pub const ",
            "static ",
        ])
        .any(|k| line.starts_with(k));
        assert!(!item, "src/lib.rs holds an item: {line}");
    }
}
