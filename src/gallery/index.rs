//! The gallery's `index.html`: each figure shown with its caption (the
//! seed, section and figure it reproduces, what it shows, its files and
//! the command that draws it), then the tables as HTML tables.

use super::quote::{shell_word, url_path};
use super::{Gallery, SceneEntry};
use crate::catalogue::{FigureName, Group};
use crate::error::Error;
use crate::html::document;
use crate::render::FileFormat;
use crate::table::{Table, TableName};
use maud::{Markup, html};

/// The page's own style, after the book page of [`crate::html::BOOK_STYLE`].
const STYLE: &str = "
h2 { break-after: avoid; page-break-after: avoid; }
.keep { break-inside: avoid; page-break-inside: avoid; }
figure { margin: 2.5rem 0; }
figure img { max-width: 100%; height: auto; border: 1px solid #ddd; }
figcaption { margin-top: .5rem; }
.source { font-weight: bold; }
.files a { margin-right: .6rem; }
";

/// The groups of figures, each with its anchor, heading and figures: the
/// teaching figures, then the developers' benchmark on its own.
fn groups(figures: &[FigureName]) -> Vec<(&'static str, &'static str, Vec<FigureName>)> {
    Group::ALL
        .into_iter()
        .map(|group| {
            let anchor = match group {
                Group::Mechanisms => "mechanisms",
                Group::Diagrams => "diagrams",
                Group::Chain => "chain",
                Group::Developers => "developers",
            };
            let members = figures
                .iter()
                .copied()
                .filter(|f| f.group() == group)
                .collect();
            (anchor, group.heading(), members)
        })
        .collect()
}

/// The whole page.
pub(super) fn page(gallery: &Gallery, tables: &[(TableName, Table)]) -> String {
    let body = html! {
        h1 { "The slider-crank chain: figures and tables of a textbook chapter and Ng’s paper" }
        p {
            "The classical graphical constructions of the slider-crank mechanism, drawn anew "
            "at each source’s own parameters from two texts. The first is the chapter "
            "“Slider-crank chains” of a textbook (Chapter IV, §34–37; the text "
            "of the chapter gives neither the book’s title nor its author). The second is "
            "T. W. Ng, “A slider-crank experiment to determine the action of static forces”, "
            "Faculty of Engineering, National University of Singapore (the text of the paper "
            "gives no journal or year). Each figure is given as "
            (formats(gallery.formats())) "; the picture links to the first."
        }
        nav {
            ul {
                @for (id, heading, figures) in groups(gallery.figures()) {
                    @if !figures.is_empty() {
                        li { a href={ "#" (id) } { (heading) } }
                    }
                }
                @if !gallery.scenes.is_empty() {
                    li { a href="#scenes" { "Scene files" } }
                }
                li { a href="#tables" { "Tables" } }
            }
        }
        @for (id, heading, figures) in groups(gallery.figures()) {
            @if !figures.is_empty() {
                section id=(id) {
                    // A heading is printed on the page of what it heads:
                    // it and its first figure are not broken apart.
                    div.keep {
                        h2 { (heading) }
                        @if let Some(first) = figures.first() {
                            (figure(*first, gallery.formats()))
                        }
                    }
                    @for f in figures.iter().skip(1) {
                        (figure(*f, gallery.formats()))
                    }
                }
            }
        }
        @if !gallery.scenes.is_empty() {
            section id="scenes" {
                div.keep {
                    h2 { "Scene files" }
                    @if let Some(first) = gallery.scenes.first() {
                        (scene(first, gallery.formats()))
                    }
                }
                @for entry in gallery.scenes.iter().skip(1) {
                    (scene(entry, gallery.formats()))
                }
            }
        }
        section id="tables" {
            div.keep {
                h2 { "Tables" }
                @if let Some((name, t)) = tables.first() {
                    (table(*name, t))
                }
            }
            @for (name, t) in tables.iter().skip(1) {
                (table(*name, t))
            }
        }
        footer {
            p {
                "Made by slider-crank " (env!("CARGO_PKG_VERSION"))
                " with " code { "slider-crank gallery" } "."
            }
        }
    };
    document(
        "slider-crank: figures and tables of the slider-crank chain",
        STYLE,
        body,
    )
}

/// "SVG, PNG and PDF".
fn formats(formats: &[FileFormat]) -> String {
    let names: Vec<String> = formats.iter().map(|f| f.label().to_owned()).collect();
    match names.as_slice() {
        [] => String::new(),
        [one] => one.clone(),
        [rest @ .., last] => format!("{} and {last}", rest.join(", ")),
    }
}

/// One figure: its picture (the PNG, else the SVG), caption and files.
fn figure(f: FigureName, formats: &[FileFormat]) -> Markup {
    let file = |format| Gallery::figure_file(f, format);
    let picture = [FileFormat::Png, FileFormat::Svg]
        .into_iter()
        .find(|p| formats.contains(p))
        .map(file);
    html! {
        figure id=(f.name()) {
            @if let (Some(src), Some(&first)) = (&picture, formats.first()) {
                a href=(file(first)) {
                    img src=(src) alt=(f.description()) loading="lazy";
                }
            }
            figcaption {
                span.source { (f.source()) } ". "
                (f.description())
                br;
                span.files {
                    @for &format in formats {
                        a href=(file(format)) { (format.label()) }
                    }
                }
                br;
                code { "slider-crank figure " (f.name()) }
            }
        }
    }
}

/// One scene: its picture, the scene file it was drawn from, its files.
fn scene(entry: &SceneEntry, formats: &[FileFormat]) -> Markup {
    let file = |format: FileFormat| url_path(&format!("{}.{}", entry.name, format.extension()));
    let picture = [FileFormat::Png, FileFormat::Svg]
        .into_iter()
        .find(|p| formats.contains(p))
        .map(file);
    // An escape sequence or a bidirectional override in a directory's name
    // is not written into the page (its name, the scene's, is checked).
    let file_shown = Error::printable(&entry.file);
    html! {
        figure id={ "scene-" (entry.name) } {
            @if let (Some(src), Some(&first)) = (&picture, formats.first()) {
                a href=(file(first)) {
                    img src=(src) alt={ "The scene of " (file_shown) } loading="lazy";
                }
            }
            figcaption {
                span.source { "Scene file " code { (file_shown) } } ". "
                br;
                span.files {
                    @for &format in formats {
                        a href=(file(format)) { (format.label()) }
                    }
                }
                br;
                code { "slider-crank scene " (shell_word(&entry.file)) }
            }
        }
    }
}

/// One table: its title as the caption, the seed it reproduces, its text
/// file.
fn table(name: TableName, t: &Table) -> Markup {
    html! {
        div.table id={ "table-" (name.name()) } {
            table {
                caption { (t.title) }
                thead { tr { @for h in &t.headers { th { (h) } } } }
                tbody {
                    @for row in &t.rows {
                        tr { @for cell in row { td { (minus(cell)) } } }
                    }
                }
            }
            @for note in &t.notes {
                p { (note) }
            }
            p {
                span.source { (name.source()) } ". "
                a href=(Gallery::table_file(name)) { "Text" } " "
                code { "slider-crank table " (name.name()) }
            }
        }
    }
}

/// A table cell as a reader sees it: a minus sign (U+2212) where the
/// text files write a hyphen before a number (`-399.8104`).
fn minus(cell: &str) -> String {
    match cell.strip_prefix('-') {
        Some(rest) if rest.starts_with(|c: char| c.is_ascii_digit() || c == '.') => {
            format!("−{rest}")
        }
        _ => cell.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_negative_cell_has_a_minus_sign() {
        assert_eq!(minus("-399.8104"), "−399.8104");
        assert_eq!(minus("-.5"), "−.5");
        assert_eq!(minus("3.5"), "3.5");
        assert_eq!(minus("-"), "-");
        assert_eq!(minus("self-locking"), "self-locking");
    }

    #[test]
    fn the_benchmark_is_kept_apart_from_the_teaching_figures() {
        let groups = groups(&FigureName::ALL);
        let [mechanisms, diagrams, chain, developers] = &groups[..] else {
            panic!("four groups");
        };
        for (_, _, figures) in [mechanisms, diagrams, chain] {
            assert!(!figures.contains(&FigureName::CurveBenchmark));
        }
        assert_eq!(developers.2, vec![FigureName::CurveBenchmark]);
    }

    #[test]
    fn each_heading_is_kept_with_what_it_heads() {
        let html = page(&Gallery::new(), &[]);
        let headings = html.matches("<h2>").count();
        assert!(headings >= 4, "{headings}");
        // Each heading opens a block that a printed page does not break,
        // holding its first figure (the tables' has none here).
        assert_eq!(html.matches(r#"<div class="keep"><h2>"#).count(), headings);
        for block in html.split(r#"<div class="keep"><h2>"#).skip(1) {
            let inside = block.split("</div>").next().unwrap_or("");
            let heading = inside.split("</h2>").next().unwrap_or("");
            assert!(
                inside.contains("<figure") || heading == "Tables",
                "{heading}"
            );
        }
        assert!(STYLE.contains(".keep { break-inside: avoid;"));
    }

    #[test]
    fn formats_are_listed_as_a_sentence() {
        assert_eq!(formats(&FileFormat::PICTURES), "SVG, PNG and PDF");
        assert_eq!(formats(&FileFormat::ALL), "SVG, PNG, PDF and TikZ");
        assert_eq!(formats(&[FileFormat::Pdf]), "PDF");
    }

    #[test]
    fn text_is_escaped() {
        let t = Table {
            title: "a < b & c".into(),
            headers: vec!["<th>".into()],
            rows: vec![vec!["\"x\"".into()]],
            notes: vec![],
        };
        let html = table(TableName::Forces, &t).into_string();
        assert!(html.contains("a &lt; b &amp; c"), "{html}");
        assert!(!html.contains("<th>\"x\"") && html.contains("&lt;th&gt;"));
    }
}
