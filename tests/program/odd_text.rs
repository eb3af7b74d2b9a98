//! Every text a user gives (a title, a length or force unit) reaches
//! every figure written well formed: the characters markup gives meaning
//! to are escaped, so that each SVG parses and shows the text as given;
//! a hostile character (a control, a non-character, a bidirectional
//! control, an invisible one) is refused in one line before anything is
//! written, by every command that takes the text.

use crate::command::run;
use resvg::usvg;
use slider_crank::FigureName;

/// A title holding what SVG, XML and LaTeX give meaning to.
const ODD_TITLE: &str = r#"<b>&amp; "q" 'a' ü µ </svg> \LaTeX{} $x$ #1 % ~"#;
/// The same as the SVG's `<title>` writes it, escaped.
const ODD_TITLE_ESCAPED: &str = "&lt;b&gt;&amp;amp;";

/// Texts that no figure or page may carry, each refused.
const HOSTILE: [&str; 7] = [
    "a\u{FFFF}",
    "a\u{202E}b",
    "a\u{2066}b",
    "a\u{200B}b",
    "a\u{FEFF}b",
    "a\u{7}b",
    "a\u{1b}[31mb",
];

/// The figures that need a gas force in other units than the bundled
/// steam diagram's (those drawn over a turn of the example engine).
fn gas(f: FigureName) -> &'static [&'static str] {
    match f.name() {
        "flywheel" | "turning-moment" | "crank-pin-loads" => &["--gas-force", "100"],
        _ => &[],
    }
}

#[test]
fn every_figure_written_with_odd_text_parses_and_keeps_it() {
    let options = usvg::Options::default();
    for f in FigureName::ALL {
        let mut args = vec!["figure", f.name(), "--title", ODD_TITLE];
        args.extend(["--unit", "µm", "--force-unit", "kgf"]);
        args.extend(gas(f));
        let out = run(&args);
        assert!(
            out.status.success(),
            "{}: {}",
            f.name(),
            String::from_utf8_lossy(&out.stderr)
        );
        let svg = String::from_utf8(out.stdout).expect("UTF-8");
        if let Err(e) = usvg::Tree::from_str(&svg, &options) {
            panic!("{}: not a well-formed SVG: {e}", f.name());
        }
        assert!(svg.contains(ODD_TITLE_ESCAPED), "{}: the title", f.name());
        assert!(!svg.contains("<b>"), "{}: markup from the title", f.name());
    }
}

#[test]
fn a_hostile_text_is_refused_in_one_line_and_nothing_is_written() {
    let dir = tempfile::tempdir().unwrap();
    let out_path = dir.path().join("x.svg");
    let out = out_path.to_str().unwrap();
    for text in HOSTILE {
        let page = dir.path().join("h.html");
        let tries: [Vec<&str>; 5] = [
            vec!["figure", "fig-65-klein", "--title", text, "--out", out],
            vec!["figure", "fig-65-klein", "--unit", text, "--out", out],
            vec!["figure", "fig-65-klein", "--force-unit", text, "--out", out],
            vec!["animate", "fig-65-klein", "--unit", text, "--out", out],
            vec!["handout", "--unit", text, "--out", page.to_str().unwrap()],
        ];
        for args in tries {
            let run = run(&args);
            let stderr = String::from_utf8_lossy(&run.stderr);
            assert_eq!(run.status.code(), Some(2), "{args:?}: {stderr}");
            assert_eq!(stderr.trim_end().lines().count(), 1, "{args:?}: {stderr}");
            assert!(
                !stderr.contains('\u{1b}'),
                "{args:?}: an escape reached the terminal"
            );
            assert!(
                !out_path.exists() && !page.exists(),
                "{args:?} wrote a file"
            );
        }
    }
}
