//! What a figure's printed text may not say: a figure is read in a book
//! or a lecture, where a path in the project's tree, a source file or a
//! command-line flag means nothing (docs/design.md, "Drafting
//! conventions").

use slider_crank::FigureName;
use slider_crank::catalogue::FigureOptions;
use slider_crank::render::to_svg;

/// The words between an SVG's tags inside its `<text>` elements, one
/// string per element (tspans joined).
fn texts(svg: &str) -> Vec<String> {
    svg.split("<text")
        .skip(1)
        .map(|element| {
            // The element's body: past its start tag, up to its end tag.
            let body = element.split_once('>').map_or("", |(_, body)| body);
            crate::common::read_text(body.split("</text>").next().unwrap_or(""))
        })
        .collect()
}

/// What marks a file or a flag: a folder of the tree, a source or data
/// file's extension, a long flag.
fn project_word(text: &str) -> Option<&'static str> {
    [
        "docs/",
        "src/",
        "examples/",
        "tests/",
        ".csv",
        ".rs",
        ".toml",
        " --",
    ]
    .into_iter()
    .find(|word| text.contains(word))
}

#[test]
fn no_figure_prints_a_path_a_file_or_a_flag() {
    let mut found = Vec::new();
    for name in FigureName::ALL {
        // Every named figure draws at its defaults: one that did not
        // would be a figure whose text went unread, not a clean one.
        let figure = (name.figure(&FigureOptions::default()))
            .unwrap_or_else(|e| panic!("{} at its defaults: {e}", name.name()));
        for text in texts(&to_svg(&figure)) {
            if let Some(word) = project_word(&text) {
                found.push(format!("{}: {word:?} in {text:?}", name.name()));
            }
        }
    }
    assert!(found.is_empty(), "{}", found.join("\n"));
}

#[test]
fn the_check_finds_a_path_in_a_text() {
    // A planted path, written in two pieces so that the check of the
    // project's cited paths does not take it for one.
    let planted = ["docs", "/planted.csv"].concat();
    let svg = format!(
        r#"<svg><text id="n">From <tspan>{planted}</tspan></text><text>clean</text></svg>"#
    );
    let t = texts(&svg);
    assert_eq!(t, [format!("From {planted}"), "clean".to_string()]);
    assert_eq!(project_word(&t[0]), Some("docs/"));
    assert_eq!(project_word(&t[1]), None);
}
