//! The options of `figure`, one table for every front end
//! (`tests/options/figure.csv`, which the Python package's tests read
//! too): each case is a figure, an option (its flag, its Python keyword,
//! its scene-file key where a scene file has one) and a value, and what
//! becomes of it: drawn as the figure's own (`default`: the same bytes as
//! the figure without the option), drawn (`ok`) or refused. Here the
//! command line and the scene file are held to it; the table holds every
//! option `figure --help` lists. The options of `table` and of `analyze`
//! have tables of their own, `tests/options/table.csv` and
//! `tests/options/analyze.csv`, and of `animate`,
//! `tests/options/animate.csv`, held the same way.

use crate::command::run;
use std::collections::{BTreeMap, BTreeSet, HashMap};

/// What the program prints for each command run so far: a command's own
/// output (without the option a case gives) is the same for every case
/// that gives the same other options, so it is run once (the program's
/// output depends on its arguments alone; `figure`'s determinism is
/// tested on its own).
#[derive(Default)]
struct Printed(HashMap<Vec<String>, Vec<u8>>);

impl Printed {
    /// The standard output of the program run with `args`.
    fn of(&mut self, args: &[&str]) -> &[u8] {
        let key: Vec<String> = args.iter().map(|s| s.to_string()).collect();
        self.0.entry(key).or_insert_with(|| run(args).stdout)
    }
}

/// One case of a table: each field by its column's name.
struct Case(BTreeMap<String, String>);

impl Case {
    /// The field of the column `name`.
    fn get(&self, name: &str) -> &str {
        self.0.get(name).map_or("", String::as_str)
    }

    /// The options of the column `with`: flags, each `--flag=value`,
    /// apart by spaces.
    fn with(&self) -> Vec<String> {
        self.get("with")
            .split_whitespace()
            .map(String::from)
            .collect()
    }
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

/// The cases of `tests/options/{csv}`, whose header is `header`.
fn cases_of(csv: &str, header: &str) -> Vec<Case> {
    let text = std::fs::read_to_string(format!("tests/options/{csv}")).unwrap();
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some(header), "{csv}");
    let columns: Vec<&str> = header.split(',').collect();
    lines
        .map(|line| {
            let f = fields(line);
            assert_eq!(f.len(), columns.len(), "{csv}: {line}");
            Case(columns.iter().map(|c| c.to_string()).zip(f).collect())
        })
        .collect()
}

/// The cases of `figure`'s table.
fn cases() -> Vec<Case> {
    cases_of("figure.csv", "figure,flag,keyword,scene,value,outcome")
}

/// Each case's flag and outcome.
fn flags_and_outcomes(cases: &[Case]) -> Vec<(&str, &str)> {
    (cases.iter())
        .map(|c| (c.get("flag"), c.get("outcome")))
        .collect()
}

/// The command-line argument of a case: `--flag=value`, a switch as
/// itself (`--mirror`, or `--no-mirror` for false).
fn argument(case: &Case) -> String {
    match (case.get("flag"), case.get("value")) {
        ("--mirror", "true") => "--mirror".into(),
        ("--mirror", _) => "--no-mirror".into(),
        ("--projector", _) => "--projector".into(),
        (flag, value) => format!("{flag}={value}"),
    }
}

/// Asserts that `out` is what `case` says: the figure's own bytes
/// (`own`, run only for a `default` case: a refused case's own command
/// may be long, such as every layer at the default 72 frames), a figure,
/// or a refusal (exit 2, one line).
fn holds<'a>(outcome: &str, out: &std::process::Output, own: impl FnOnce() -> &'a [u8], how: &str) {
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
                assert!(out.stdout == own(), "{how}: not the command's own");
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
    every_flag_has_cases(&listed, &output, &flags_and_outcomes(&all), "figure.csv");
    assert!(
        listed.contains("--gas-force") && listed.len() > 20,
        "{listed:?}"
    );
}

#[test]
fn the_command_line_and_scene_files_do_as_the_table_says() {
    let dir = std::env::temp_dir().join(format!("sc-options-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let mut printed = Printed::default();
    for (i, case) in cases().iter().enumerate() {
        let figure = case.get("figure");
        let arg = argument(case);
        let out = run(&["figure", figure, &arg]);
        let outcome = case.get("outcome");
        let how = format!("figure {figure} {arg}");
        holds(outcome, &out, || printed.of(&["figure", figure]), &how);
        if case.get("scene").is_empty() {
            continue;
        }
        let head = format!("figure = \"{figure}\"\n");
        let key = (case.get("scene").replace('|', "\n")).replace("{}", case.get("value"));
        let (file, plain) = (
            dir.join(format!("{i}.toml")),
            dir.join(format!("{figure}-own.toml")),
        );
        std::fs::write(&file, format!("{head}{key}\n")).unwrap();
        std::fs::write(&plain, &head).unwrap();
        let out = run(&["scene", file.to_str().unwrap()]);
        let how = format!("scene file {key:?}");
        holds(
            outcome,
            &out,
            || printed.of(&["scene", plain.to_str().unwrap()]),
            &how,
        );
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Runs each case of a table of options given `with` others
/// (`tests/options/table.csv`, `analyze.csv`, `animate.csv`): the
/// command `head` (the case's `figure` or `table` after it, if the
/// table has the column) with the case's `with`, then with its option
/// too, held to the case's outcome; what a case's command prints
/// (unless refused) must satisfy `printed`.
fn the_command_line_does_as(cases: &[Case], head: &[&str], printed: fn(&[u8]) -> bool) {
    let mut own_output = Printed::default();
    for case in cases {
        let mut args: Vec<String> = head.iter().map(|s| s.to_string()).collect();
        for column in ["figure", "table"] {
            if !case.get(column).is_empty() {
                args.insert(1, case.get(column).to_string());
            }
        }
        args.extend(case.with());
        let without = args.clone();
        let arg = argument(case);
        args.push(arg.clone());
        let given: Vec<&str> = args.iter().map(String::as_str).collect();
        let out = run(&given);
        let how = format!("{} {arg}", without.join(" "));
        let plain: Vec<&str> = without.iter().map(String::as_str).collect();
        holds(case.get("outcome"), &out, || own_output.of(&plain), &how);
        assert!(
            case.get("outcome") == "refused" || printed(&out.stdout),
            "{how}"
        );
    }
}

/// The cases of `tests/options/table.csv`: a table, an option (its flag,
/// its Python keyword) given with the options `with` and a value, and
/// what becomes of it: the table's own text (`default`: the same bytes as
/// without the option), a table (`ok`) or a refusal.
fn table_cases() -> Vec<Case> {
    cases_of("table.csv", "table,flag,keyword,with,value,outcome")
}

#[test]
fn every_option_of_table_is_in_its_table() {
    let listed = help_flags("table");
    // `--angle` is `--angles`' other spelling.
    let not_options = ["--help", "--angle"];
    let all = table_cases();
    every_flag_has_cases(
        &listed,
        &not_options,
        &flags_and_outcomes(&all),
        "table.csv",
    );
    assert!(
        listed.contains("--max-cells") && listed.len() > 30,
        "{listed:?}"
    );
}

#[test]
fn the_command_line_does_as_the_table_of_table_says() {
    the_command_line_does_as(&table_cases(), &["table"], |out| !out.is_empty());
}

/// The cases of `tests/options/analyze.csv`: an option (its flag, its
/// Python keyword) given with the options `with` and a value, and what
/// becomes of it: the command's own JSON (`default`), an analysis (`ok`)
/// or a refusal.
fn analyze_cases() -> Vec<Case> {
    cases_of("analyze.csv", "flag,keyword,with,value,outcome")
}

#[test]
fn every_option_of_analyze_is_in_its_table() {
    let listed = help_flags("analyze");
    // `--angles` is `--angle`'s other spelling; `--json` how the analysis
    // is written (the Python package's is always the JSON object).
    let not_options = ["--help", "--angles", "--json"];
    let all = analyze_cases();
    every_flag_has_cases(
        &listed,
        &not_options,
        &flags_and_outcomes(&all),
        "analyze.csv",
    );
    assert!(
        listed.contains("--slot-radius") && listed.len() > 20,
        "{listed:?}"
    );
}

#[test]
fn the_command_line_does_as_the_table_of_analyze_says() {
    the_command_line_does_as(&analyze_cases(), &["analyze", "--json"], |out| {
        out.starts_with(b"{")
    });
}

/// The cases of `tests/options/animate.csv`: a mechanism figure, an
/// option (its flag, its Python keyword) given with the options `with`
/// and a value, and what becomes of it: the animation's own SVG
/// (`default`), an animation (`ok`) or a refusal.
fn animate_cases() -> Vec<Case> {
    cases_of("animate.csv", "figure,flag,keyword,with,value,outcome")
}

#[test]
fn every_option_of_animate_is_in_its_table() {
    let listed = help_flags("animate");
    // `--out` where the animation goes; `--no-mirror` is `--mirror`'s
    // false; the switches `--mirror` and `--projector` take every figure
    // the command draws, so no value of theirs is refused.
    let not_refused = ["--mirror", "--projector"];
    let all = animate_cases();
    let mut cases = flags_and_outcomes(&all);
    cases.extend(not_refused.iter().map(|&f| (f, "refused")));
    let not_options = ["--help", "--out", "--no-mirror"];
    every_flag_has_cases(&listed, &not_options, &cases, "animate.csv");
    assert!(
        listed.contains("--frames") && listed.contains("--coupler") && listed.len() > 15,
        "{listed:?}"
    );
}

#[test]
fn the_command_line_does_as_the_table_of_animate_says() {
    the_command_line_does_as(&animate_cases(), &["animate", "--out=-"], |out| {
        out.starts_with(b"<svg")
    });
}
