//! The options of `figure`, one table for every front end
//! (`tests/options/figure.csv`, which the Python package's tests read
//! too): each case is a figure, an option (its flag, its Python keyword,
//! its scene-file key where a scene file has one) and a value, and what
//! becomes of it: drawn as the figure's own (`default`: the same bytes as
//! the figure without the option), drawn (`ok`) or refused. Here the
//! command line and the scene file are held to it; the table holds every
//! option `figure --help` lists. The options of `table` and of `analyze`
//! have tables of their own, `tests/options/table.csv` and
//! `tests/options/analyze.csv`, held the same way.

use crate::command::run;
use std::collections::BTreeSet;

/// One case of the table.
struct Case {
    figure: String,
    flag: String,
    scene: String,
    value: String,
    outcome: String,
}

/// The fields of a CSV line: commas split them, a field in double quotes
/// may hold commas and `""` for a quote.
fn fields(line: &str) -> Vec<String> {
    let (mut out, mut field, mut quoted) = (Vec::new(), String::new(), false);
    let mut chars = line.chars().peekable();
    while let Some(c) = chars.next() {
        match (c, quoted) {
            ('"', true) if chars.peek() == Some(&'"') => {
                field.push('"');
                chars.next();
            }
            ('"', _) => quoted = !quoted,
            (',', false) => out.push(std::mem::take(&mut field)),
            _ => field.push(c),
        }
    }
    out.push(field);
    out
}

/// The table's cases.
fn cases() -> Vec<Case> {
    let text = std::fs::read_to_string("tests/options/figure.csv").unwrap();
    let mut lines = text.lines();
    assert_eq!(
        lines.next(),
        Some("figure,flag,keyword,scene,value,outcome")
    );
    lines
        .map(|line| {
            let f = fields(line);
            assert_eq!(f.len(), 6, "{line}");
            Case {
                figure: f[0].clone(),
                flag: f[1].clone(),
                scene: f[3].clone(),
                value: f[4].clone(),
                outcome: f[5].clone(),
            }
        })
        .collect()
}

/// The command-line argument of a case: `--flag=value`, a switch as
/// itself (`--mirror`, or `--no-mirror` for false).
fn argument(case: &Case) -> String {
    match (case.flag.as_str(), case.value.as_str()) {
        ("--mirror", "true") => "--mirror".into(),
        ("--mirror", _) => "--no-mirror".into(),
        (flag, value) => format!("{flag}={value}"),
    }
}

/// Asserts that `out` is what `case` says: the figure's own bytes
/// (`own`), a figure, or a refusal (exit 2, one line).
fn holds(outcome: &str, out: &std::process::Output, own: &[u8], how: &str) {
    let stderr = String::from_utf8_lossy(&out.stderr);
    match outcome {
        "refused" => {
            assert_eq!(out.status.code(), Some(2), "{how}: not refused");
            assert_eq!(stderr.lines().count(), 1, "{how}: {stderr}");
            assert!(out.stdout.is_empty(), "{how}");
        }
        outcome => {
            assert!(out.status.success(), "{how}: {stderr}");
            if outcome == "default" {
                assert!(out.stdout == own, "{how}: not the command's own");
            }
        }
    }
}

/// The long options `command --help` lists.
fn help_flags(command: &str) -> BTreeSet<String> {
    let help = String::from_utf8(run(&[command, "--help"]).stdout).unwrap();
    help.split(|c: char| !(c.is_ascii_alphanumeric() || c == '-'))
        .filter(|w| w.starts_with("--") && w.len() > 2)
        .map(String::from)
        .collect()
}

/// Every flag `listed` but those in `skip` has a case (flag, outcome)
/// that takes it (`default` or `ok`) and one that refuses it, in the
/// table `tests/options/{csv}`.
fn every_flag_has_cases(
    listed: &BTreeSet<String>,
    skip: &[&str],
    cases: &[(&str, &str)],
    csv: &str,
) {
    for flag in listed.iter().filter(|f| !skip.contains(&f.as_str())) {
        for outcome in [["default", "ok"].as_slice(), &["refused"]] {
            assert!(
                (cases.iter()).any(|(f, o)| f == flag && outcome.contains(o)),
                "{flag} has no case {outcome:?} in tests/options/{csv}"
            );
        }
    }
}

#[test]
fn every_option_of_figure_is_in_the_table() {
    let listed = help_flags("figure");
    // What writes the figure, not what it draws; `--no-mirror` is
    // `--mirror`'s false.
    let output = [
        "--out",
        "--embed-fonts",
        "--tikz-standalone",
        "--help",
        "--no-mirror",
    ];
    let all = cases();
    let cases: Vec<(&str, &str)> = (all.iter())
        .map(|c| (c.flag.as_str(), c.outcome.as_str()))
        .collect();
    every_flag_has_cases(&listed, &output, &cases, "figure.csv");
    assert!(
        listed.contains("--gas-force") && listed.len() > 20,
        "{listed:?}"
    );
}

#[test]
fn the_command_line_and_scene_files_do_as_the_table_says() {
    let dir = std::env::temp_dir().join(format!("sc-options-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    for (i, case) in cases().iter().enumerate() {
        let own = run(&["figure", &case.figure]).stdout;
        let arg = argument(case);
        let out = run(&["figure", &case.figure, &arg]);
        holds(
            &case.outcome,
            &out,
            &own,
            &format!("figure {} {arg}", case.figure),
        );
        if case.scene.is_empty() {
            continue;
        }
        let head = format!("figure = \"{}\"\n", case.figure);
        let key = case.scene.replace('|', "\n").replace("{}", &case.value);
        let (file, plain) = (
            dir.join(format!("{i}.toml")),
            dir.join(format!("{i}-own.toml")),
        );
        std::fs::write(&file, format!("{head}{key}\n")).unwrap();
        std::fs::write(&plain, &head).unwrap();
        let own = run(&["scene", plain.to_str().unwrap()]).stdout;
        let out = run(&["scene", file.to_str().unwrap()]);
        holds(&case.outcome, &out, &own, &format!("scene file {key:?}"));
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// One case of `tests/options/table.csv`: a table, an option (its flag,
/// its Python keyword) given with the options `with` (flags, each
/// `--flag=value`, apart by spaces) and a value, and what becomes of it:
/// the table's own text (`default`: the same bytes as without the
/// option), a table (`ok`) or a refusal.
struct TableCase {
    table: String,
    flag: String,
    with: Vec<String>,
    value: String,
    outcome: String,
}

/// The cases of `tests/options/table.csv`.
fn table_cases() -> Vec<TableCase> {
    let text = std::fs::read_to_string("tests/options/table.csv").unwrap();
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some("table,flag,keyword,with,value,outcome"));
    lines
        .map(|line| {
            let f = fields(line);
            assert_eq!(f.len(), 6, "{line}");
            TableCase {
                table: f[0].clone(),
                flag: f[1].clone(),
                with: f[3].split_whitespace().map(String::from).collect(),
                value: f[4].clone(),
                outcome: f[5].clone(),
            }
        })
        .collect()
}

#[test]
fn every_option_of_table_is_in_its_table() {
    let listed = help_flags("table");
    // `--angle` is `--angles`' other spelling.
    let not_options = ["--help", "--angle"];
    let all = table_cases();
    let cases: Vec<(&str, &str)> = (all.iter())
        .map(|c| (c.flag.as_str(), c.outcome.as_str()))
        .collect();
    every_flag_has_cases(&listed, &not_options, &cases, "table.csv");
    assert!(
        listed.contains("--max-cells") && listed.len() > 30,
        "{listed:?}"
    );
}

#[test]
fn the_command_line_does_as_the_table_of_table_says() {
    for case in table_cases() {
        let mut args = vec!["table".to_string(), case.table.clone()];
        args.extend(case.with.iter().cloned());
        let plain: Vec<&str> = args.iter().map(String::as_str).collect();
        let own = run(&plain).stdout;
        let arg = format!("{}={}", case.flag, case.value);
        args.push(arg.clone());
        let given: Vec<&str> = args.iter().map(String::as_str).collect();
        let out = run(&given);
        let how = format!("table {} {} {arg}", case.table, case.with.join(" "));
        holds(&case.outcome, &out, &own, &how);
        assert!(case.outcome == "refused" || !out.stdout.is_empty(), "{how}");
    }
}

/// One case of `tests/options/analyze.csv`: an option (its flag, its
/// Python keyword) given with the options `with` and a value, and what
/// becomes of it: the command's own JSON (`default`), an analysis (`ok`)
/// or a refusal.
struct AnalyzeCase {
    flag: String,
    with: Vec<String>,
    value: String,
    outcome: String,
}

/// The cases of `tests/options/analyze.csv`.
fn analyze_cases() -> Vec<AnalyzeCase> {
    let text = std::fs::read_to_string("tests/options/analyze.csv").unwrap();
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some("flag,keyword,with,value,outcome"));
    lines
        .map(|line| {
            let f = fields(line);
            assert_eq!(f.len(), 5, "{line}");
            AnalyzeCase {
                flag: f[0].clone(),
                with: f[2].split_whitespace().map(String::from).collect(),
                value: f[3].clone(),
                outcome: f[4].clone(),
            }
        })
        .collect()
}

#[test]
fn every_option_of_analyze_is_in_its_table() {
    let listed = help_flags("analyze");
    // `--angles` is `--angle`'s other spelling; `--json` how the analysis
    // is written (the Python package's is always the JSON object).
    let not_options = ["--help", "--angles", "--json"];
    let all = analyze_cases();
    let cases: Vec<(&str, &str)> = (all.iter())
        .map(|c| (c.flag.as_str(), c.outcome.as_str()))
        .collect();
    every_flag_has_cases(&listed, &not_options, &cases, "analyze.csv");
    assert!(
        listed.contains("--slot-radius") && listed.len() > 20,
        "{listed:?}"
    );
}

#[test]
fn the_command_line_does_as_the_table_of_analyze_says() {
    for case in analyze_cases() {
        let mut args = vec!["analyze".to_string(), "--json".to_string()];
        args.extend(case.with.iter().cloned());
        let plain: Vec<&str> = args.iter().map(String::as_str).collect();
        let own = run(&plain).stdout;
        let arg = format!("{}={}", case.flag, case.value);
        args.push(arg.clone());
        let given: Vec<&str> = args.iter().map(String::as_str).collect();
        let out = run(&given);
        let how = format!("analyze {} {arg}", case.with.join(" "));
        holds(&case.outcome, &out, &own, &how);
        assert!(
            case.outcome == "refused" || out.stdout.starts_with(b"{"),
            "{how}"
        );
    }
}
