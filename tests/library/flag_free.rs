//! The library speaks in fields, not flags: outside the front ends (the
//! command line's `src/cli/` and `src/main.rs`) no text of `src/` (a
//! message, a caption, a note, a comment) names a command-line option as
//! the command line spells it. A refusal names a `Field`, which each
//! front end writes its own way. The one exception is the page footer
//! that prints the program's command line that makes the page again.

use super::layering::{blank_comments_and_literals, files, test_module_spans};
use std::path::Path;

/// The files that are the command line's own.
const FRONT_ENDS: [&str; 2] = ["src/cli/", "src/main.rs"];

/// The one text that is the command line by design: a handout's footer,
/// the command that makes the page again.
const COMMAND_LINE_TEXT: &str = "src/handout/command.rs";

/// The flags `text` names, with their lines: two hyphens and a letter
/// after something that is not a hyphen or part of a word (`--data`,
/// `"--gas-force"`, `(--bore`; not `a--b` or an HTML comment's `<!--`).
fn flags(text: &str) -> Vec<(usize, String)> {
    let mut found = Vec::new();
    for (n, line) in text.lines().enumerate() {
        let chars: Vec<char> = line.chars().collect();
        for i in 0..chars.len() {
            let before = i.checked_sub(1).map(|b| chars[b]);
            let starts = chars[i] == '-'
                && chars.get(i + 1) == Some(&'-')
                && chars.get(i + 2).is_some_and(|c| c.is_ascii_lowercase())
                && !before.is_some_and(|b| b == '-' || b == '!' || b.is_alphanumeric() || b == '_');
            if starts {
                let flag: String = chars[i..]
                    .iter()
                    .take_while(|c| **c == '-' || c.is_ascii_alphanumeric())
                    .collect();
                found.push((n + 1, flag));
            }
        }
    }
    found
}

/// `text` with its `#[cfg(test)] mod … { … }` blocks blanked (newlines
/// kept), its comments and literals kept: what the library says, without
/// its unit tests (which may hold a command line to test against).
fn without_unit_tests(text: &str) -> String {
    let code = blank_comments_and_literals(text);
    // Blanking keeps one character for each: a span's characters in the
    // code are the same characters of the text.
    let char_at = |byte: usize| code[..byte].chars().count();
    let spans: Vec<_> = test_module_spans(&code)
        .into_iter()
        .map(|s| char_at(s.start)..char_at(s.end))
        .collect();
    text.chars()
        .enumerate()
        .map(|(i, c)| match spans.iter().any(|s| s.contains(&i)) {
            true if c != '\n' => ' ',
            _ => c,
        })
        .collect()
}

/// The flags named in the library's files under `root`, as `file:line:
/// flag`.
fn flags_in_library(root: &Path) -> Vec<String> {
    let mut paths = Vec::new();
    files(&root.join("src"), &mut paths);
    paths.sort();
    let mut found = Vec::new();
    for path in paths {
        let name = path
            .strip_prefix(root)
            .unwrap()
            .to_string_lossy()
            .replace('\\', "/");
        if FRONT_ENDS.iter().any(|f| name.starts_with(f)) || name == COMMAND_LINE_TEXT {
            continue;
        }
        let text = std::fs::read_to_string(&path).unwrap();
        for (line, flag) in flags(&without_unit_tests(&text)) {
            found.push(format!("{name}:{line}: {flag}"));
        }
    }
    found
}

#[test]
fn the_library_names_no_flag() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    // The reader finds the flags of the one file that writes them.
    let footer = std::fs::read_to_string(root.join(COMMAND_LINE_TEXT)).unwrap();
    let written: Vec<String> = flags(&without_unit_tests(&footer))
        .into_iter()
        .map(|(_, f)| f)
        .collect();
    assert!(written.contains(&"--gas-force".to_string()), "{written:?}");
    let found = flags_in_library(root);
    assert!(
        found.is_empty(),
        "the library names fields (slider_crank::Field), the front ends spell them; flags found:\n{}",
        found.join("\n")
    );
}

#[test]
fn a_planted_flag_is_found_in_each_form() {
    let planted = [
        "const HINT: &str = \"give --data\";",
        "/// Set by `--gas-force`.",
        "// the mass (--mass) asked for",
        "let m = format!(\"{} --max-cells {}\", a, b);",
    ];
    for line in planted {
        let text = format!("fn f() {{}}\n{line}\n");
        let found = flags(&without_unit_tests(&text));
        assert_eq!(found.len(), 1, "{line}: {found:?}");
        assert_eq!(found[0].0, 2, "{line}");
    }
    assert_eq!(
        flags("give --max-cells 5 or --gas-force F")
            .into_iter()
            .map(|(_, f)| f)
            .collect::<Vec<_>>(),
        ["--max-cells", "--gas-force"]
    );
    // Not flags: a decrement, an HTML comment, a word with hyphens, two
    // hyphens and no letter.
    for text in ["x--y", "<!-- note -->", "a--b", "\"--\"", "-- 5"] {
        assert!(flags(text).is_empty(), "{text}");
    }
}

#[test]
fn a_flag_in_a_unit_test_is_left_and_one_after_it_found() {
    let text = "fn f() {}\n#[cfg(test)]\nmod tests {\n    const A: &str = \"--rpm 1500\";\n    fn g() { let _ = \"}\"; }\n}\nconst B: &str = \"(--data)\";\n";
    let found = flags(&without_unit_tests(text));
    assert_eq!(found, [(7, "--data".to_string())]);
}
