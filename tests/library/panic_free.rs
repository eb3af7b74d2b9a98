//! No panic on a path from input. Clippy (`.ci/run`: `-D warnings`)
//! refuses `unwrap`, `expect`, indexing and slicing in the library and the
//! program through the `deny` at the top of src/lib.rs and src/main.rs;
//! this test holds that `deny` in place and every allowance of it to a
//! proof: each `#[allow(clippy::unwrap_used)]`,
//! `#[allow(clippy::expect_used)]` or `#[allow(clippy::indexing_slicing)]`
//! in src/ sits under a comment that starts `// cannot fail:` and says
//! why. It also reads the code outside the tests for an `unwrap` or
//! `expect` with no allowance above it in its function, so that the rule
//! holds where clippy is not run.

use std::path::{Path, PathBuf};

/// Every `.rs` file under src/.
fn sources() -> Vec<PathBuf> {
    let mut out = Vec::new();
    let mut stack = vec![Path::new(env!("CARGO_MANIFEST_DIR")).join("src")];
    while let Some(dir) = stack.pop() {
        for entry in std::fs::read_dir(dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                stack.push(path);
            } else if path.extension().is_some_and(|e| e == "rs") {
                out.push(path);
            }
        }
    }
    out.sort();
    out
}

/// The lines of a file before its test module (`#[cfg(test)]` followed
/// by `mod`), which by the project's convention ends the file.
fn code_lines(text: &str) -> Vec<&str> {
    let lines: Vec<&str> = text.lines().collect();
    let end = lines
        .windows(2)
        .position(|w| w[0].trim() == "#[cfg(test)]" && w[1].trim_start().starts_with("mod "))
        .unwrap_or(lines.len());
    lines[..end].to_vec()
}

const ALLOWANCES: [&str; 2] = ["allow(clippy::unwrap_used)", "allow(clippy::expect_used)"];

/// The allowance of an index or a slice.
const INDEXING: &str = "allow(clippy::indexing_slicing)";

/// The `deny` at the top of both crate roots.
const DENY: &str = "#![deny(clippy::unwrap_used, clippy::expect_used, clippy::indexing_slicing)]";

#[test]
fn the_library_and_the_program_deny_unwrap_expect_and_indexing() {
    for file in ["src/lib.rs", "src/main.rs"] {
        let text =
            std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join(file)).unwrap();
        assert!(text.contains(DENY), "{file} lost its deny");
    }
}

/// The allowances among `lines` (code before the tests) that `is_allowance`
/// picks: their 1-based line numbers, and those of them with no comment
/// starting `// cannot fail:` in the comment block right above.
fn allowances(lines: &[&str], is_allowance: impl Fn(&str) -> bool) -> (Vec<usize>, Vec<usize>) {
    let mut all = Vec::new();
    let mut missing = Vec::new();
    for (i, line) in lines.iter().enumerate() {
        if !is_allowance(line) {
            continue;
        }
        all.push(i + 1);
        let proof = lines[..i]
            .iter()
            .rev()
            .take_while(|l| l.trim_start().starts_with("//") && !l.trim_start().starts_with("///"))
            .any(|l| l.contains("// cannot fail:"));
        if !proof {
            missing.push(i + 1);
        }
    }
    (all, missing)
}

/// Every allowance `is_allowance` picks in src/ has its proof, and there
/// are at most `most` of them.
fn every_allowance_of(is_allowance: impl Fn(&str) -> bool, most: usize) {
    let mut count = 0;
    let mut missing = Vec::new();
    for path in sources() {
        let text = std::fs::read_to_string(&path).unwrap();
        let (all, bare) = allowances(&code_lines(&text), &is_allowance);
        count += all.len();
        missing.extend(bare.iter().map(|n| format!("{}:{n}", path.display())));
    }
    assert!(
        missing.is_empty(),
        "allowances without a proof:\n{}",
        missing.join("\n")
    );
    // The count is the audit's: raise it only with a proof for each.
    assert!(count <= most, "{count} allowances");
}

#[test]
fn every_allowance_carries_its_proof() {
    every_allowance_of(|l| ALLOWANCES.iter().any(|a| l.contains(a)), 30);
}

#[test]
fn every_index_allowance_carries_its_proof() {
    every_allowance_of(|l| l.contains(INDEXING), 20);
}

#[test]
fn an_index_allowance_without_its_proof_is_found() {
    let code = [
        "// cannot fail: i < 4, the array's length.",
        "#[allow(clippy::indexing_slicing)]",
        "fn proved(a: [u8; 4], i: usize) -> u8 { a[i % 4] }",
        "/// Documented, but no proof.",
        "#[allow(clippy::indexing_slicing)]",
        "fn bare(a: &[u8]) -> u8 { a[0] }",
        "    // A comment that proves nothing.",
        "    #[allow(clippy::indexing_slicing)]",
        "    let x = v[3];",
    ];
    let (all, missing) = allowances(&code, |l| l.contains(INDEXING));
    assert_eq!(all, [2, 5, 8]);
    assert_eq!(missing, [5, 8]);
}

/// Whether a clippy allowance of `unwrap` or `expect` stands in the
/// function whose lines so far are `lines` (the last holds the call).
fn allowed_in_function(lines: &[&str]) -> bool {
    let is_fn = |l: &str| {
        let t = l.trim_start();
        [
            "fn ",
            "pub fn ",
            "pub(crate) fn ",
            "pub(super) fn ",
            "const fn ",
            "pub const fn ",
        ]
        .iter()
        .any(|p| t.starts_with(p))
    };
    let mut above = lines.iter().rev();
    for line in above.by_ref() {
        if ALLOWANCES.iter().any(|a| line.contains(a)) {
            return true;
        }
        if is_fn(line) {
            break;
        }
    }
    above
        .take_while(|l| {
            let t = l.trim_start();
            t.starts_with("#[") || t.starts_with("//")
        })
        .any(|l| ALLOWANCES.iter().any(|a| l.contains(a)))
}

#[test]
fn no_unwrap_or_expect_without_an_allowance() {
    let mut bare = Vec::new();
    for path in sources() {
        let text = std::fs::read_to_string(&path).unwrap();
        let lines = code_lines(&text);
        for (i, line) in lines.iter().enumerate() {
            let code = line.split("//").next().unwrap_or("");
            if !(code.contains(".unwrap()") || code.contains(".expect(")) {
                continue;
            }
            // An allowance in the function the call is in: between its
            // `fn` line (and the attributes and comments above it) and
            // the call.
            let allowed = allowed_in_function(&lines[..=i]);
            if !allowed {
                bare.push(format!("{}:{}: {}", path.display(), i + 1, line.trim()));
            }
        }
    }
    assert!(
        bare.is_empty(),
        "unwrap or expect without a proof:\n{}",
        bare.join("\n")
    );
}
