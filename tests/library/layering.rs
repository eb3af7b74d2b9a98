//! The layering of `src/` (docs/design.md, "Layering"): every module
//! imports only from the modules its row of the table names, read from
//! the `use` lines and `crate::` paths of the code outside its tests; a
//! name the crate root re-exports is imported from its defining module,
//! never through the root. The crate root only declares modules and
//! re-exports.

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
fn files(dir: &Path, out: &mut Vec<std::path::PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// The names right after each `crate::` of a line of code:
/// `crate::geom::Point` gives `geom`, `crate::{Angle, render::fmt}` gives
/// `Angle` and `render`.
fn heads(line: &str) -> Vec<&str> {
    let mut out = Vec::new();
    let mut rest = line;
    while let Some(at) = rest.find("crate::") {
        let after = &rest[at + "crate::".len()..];
        let starts: Vec<&str> = match after.strip_prefix('{') {
            Some(g) => g[..g.find('}').unwrap_or(g.len())]
                .split(',')
                .map(str::trim)
                .collect(),
            None => vec![after],
        };
        for head in starts {
            let end = head
                .find(|c: char| !(c.is_alphanumeric() || c == '_'))
                .unwrap_or(head.len());
            if end > 0 {
                out.push(&head[..end]);
            }
        }
        rest = after;
    }
    out
}

/// The modules a line of code reaches through `crate::` (a name the root
/// re-exports counted as its defining module).
fn reached(line: &str, roots: &BTreeMap<String, String>) -> Vec<String> {
    heads(line)
        .into_iter()
        .map(|name| roots.get(name).cloned().unwrap_or_else(|| name.to_string()))
        .collect()
}

/// A name of the crate root's re-exports reached through the root
/// (`crate::Angle`, `crate::{Angle, …}`), if the line has one: modules
/// import a name from the module that defines it, so that no arrow runs
/// up through the root. (A module's own name, `crate::angle::…`, is not
/// one: the root's names are its types, constants and functions.)
fn root_name_in(line: &str, roots: &BTreeMap<String, String>) -> Option<String> {
    heads(line)
        .into_iter()
        .find(|name| roots.contains_key(*name))
        .map(String::from)
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
        let may = table
            .get(&module)
            .unwrap_or_else(|| panic!("src/{first} has no row in the layering table"));
        let text = std::fs::read_to_string(path).unwrap();
        for (n, line) in text.lines().enumerate() {
            let code = line.trim_start();
            if code.starts_with("#[cfg(test)]") {
                break;
            }
            if code.starts_with("//") {
                continue;
            }
            if let Some(name) = root_name_in(code, &roots) {
                through_root.push(format!("{}:{}: crate::{name}", path.display(), n + 1));
            }
            for target in reached(code, &roots) {
                let known = table.contains_key(&target);
                if known && target != module && !may.contains(&target) {
                    wrong.push(format!("{}:{}: {module} → {target}", path.display(), n + 1));
                }
            }
        }
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
    assert_eq!(reached(line, &roots), ["angle", "geom", "render"]);
    assert_eq!(root_name_in(line, &roots).as_deref(), Some("Angle"));
    let call = "let w = crate::rpm_to_omega(250.0);";
    assert_eq!(root_name_in(call, &roots).as_deref(), Some("rpm_to_omega"));
    assert_eq!(root_name_in("use crate::angle::Angle;", &roots), None);
}

/// The crate root declares modules and re-exports, nothing else: no
/// function, type, impl or macro sits there for lower modules to import.
#[test]
fn the_crate_root_only_declares_and_reexports() {
    let lib = std::fs::read_to_string("src/lib.rs").unwrap();
    let body = lib.split("#[cfg(test)]").next().unwrap();
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
