//! The TikZ writer: the placed figure ([`crate::layout::place`]) as a
//! `tikzpicture` for a LaTeX book. Lines, hatching, arrows and detail
//! frames are TikZ paths in the figure's page units (`x` and `y` keys of
//! 0.75 bp, the program's PDF scale, so the picture is the PDF's size; the
//! `scale` key scales the drawing and leaves lines and letters their
//! size); every letter, label and note is a `\node` whose text is LaTeX
//! (`latex.rs`), set in the book's own fonts at the place the layout
//! chose with the figure's face's metrics. Each mark is preceded by a
//! comment naming its item, so that a letter can be found and changed.
//! Only TikZ and xcolor (which TikZ loads) are used, with no library.

mod latex;

use crate::figure::Figure;
use crate::layout::{
    Mark, MarkShape, Paint, PathCommand, PathData, PlacedPanel, TextAnchor, place,
};
use crate::number::fmt;
use std::collections::BTreeSet;
use std::fmt::Write as _;

/// Big points per page unit: the program's PDF scale (96 page units to
/// the inch, 72 bp).
const BP_PER_UNIT: f64 = 0.75;

/// Options of [`to_tikz`].
#[derive(Debug, Clone, Copy, Default)]
pub struct TikzOptions {
    standalone: bool,
}

impl TikzOptions {
    /// The picture wrapped in a LaTeX document of its own (an `article`
    /// whose page is the figure's, by `geometry`, the picture in a box of
    /// no height at its top so that TeX's rounding never pushes it onto a
    /// second page; with pdfLaTeX Latin
    /// Modern in T1, so that it comes at any size and `\`, `^`, `~` and
    /// `_` print as themselves), which pdfLaTeX and LuaLaTeX compile as it
    /// is; without it, the `tikzpicture` alone,
    /// for `\input` in a book that loads TikZ.
    pub fn standalone(mut self, standalone: bool) -> Self {
        self.standalone = standalone;
        self
    }
}

/// The figure as TikZ: a `tikzpicture` (in a document of its own with
/// [`TikzOptions::standalone`]). A figure without panels is its page
/// alone.
pub fn to_tikz(figure: &Figure, options: &TikzOptions) -> String {
    let picture = picture(figure);
    if !options.standalone {
        return picture;
    }
    let (w, h) = (figure.width(), figure.height());
    format!(
        "\\RequirePackage{{iftex}}\n\
         \\documentclass{{article}}\n\
         \\ifPDFTeX\\usepackage[T1]{{fontenc}}\\usepackage{{lmodern}}\\fi\n\
         \\usepackage[paperwidth={}bp,paperheight={}bp,margin=0pt,nohead,nofoot]{{geometry}}\n\
         \\usepackage{{tikz}}\n\
         \\pagestyle{{empty}}\n\
         \\setlength{{\\topskip}}{{0pt}}\n\
         \\setlength{{\\parindent}}{{0pt}}\n\
         \\begin{{document}}\n\\vbox to 0pt{{\\hbox{{%\n{}%\n}}\\vss}}\n\\end{{document}}\n",
        bp_up(w),
        bp_up(h),
        picture.trim_end()
    )
}

/// A page length in big points.
fn bp(units: f64) -> String {
    fmt(units * BP_PER_UNIT)
}

/// A page's side in big points, rounded up to a thousandth: the page
/// holds the picture whole (rounded down, a picture a hair taller than
/// its page spilled onto a second).
fn bp_up(units: f64) -> String {
    let thousandths = (units * BP_PER_UNIT * 1000.0).ceil();
    crate::number::plain(thousandths / 1000.0)
}

/// The `tikzpicture`: its colours, the page, then each panel.
fn picture(figure: &Figure) -> String {
    let placed = place(figure);
    let (w, h) = (figure.width(), figure.height());
    let mut colours = BTreeSet::from([colour_name(figure.style().paper())]);
    let mut body = String::new();
    for panel in placed.panels() {
        write_panel(&mut body, panel, &mut colours);
    }
    let mut out = format!(
        "% {}: drawn by slider-crank as a TikZ picture; its letters were\n\
         % placed for {}'s metrics. Each mark follows a comment naming it.\n",
        figure.name(),
        figure.font().name()
    );
    out.push_str("\\begin{tikzpicture}[x=0.75bp, y=-0.75bp, scale=1]\n");
    for c in &colours {
        if let Some(hex) = c.strip_prefix("sc") {
            let _ = writeln!(
                out,
                "\\definecolor{{{c}}}{{HTML}}{{{}}}",
                hex.to_uppercase()
            );
        }
    }
    let paper = colour_name(figure.style().paper());
    let (w, h) = (fmt(w), fmt(h));
    let _ = writeln!(out, "\\useasboundingbox (0,0) rectangle ({w},{h});");
    let _ = writeln!(out, "\\fill[{paper}] (0,0) rectangle ({w},{h});");
    out.push_str(&body);
    out.push_str("\\end{tikzpicture}\n");
    out
}

/// A CSS colour `#rrggbb` as the name of its `xcolor` colour (`sc`
/// and the hex digits); black for any other form.
fn colour_name(css: &str) -> String {
    match css.strip_prefix('#') {
        Some(hex) if hex.len() == 6 && hex.chars().all(|c| c.is_ascii_hexdigit()) => {
            format!("sc{}", hex.to_lowercase())
        }
        _ => "sc000000".into(),
    }
}

/// A panel: a scope (clipped to a detail's rectangle), its marks.
fn write_panel(out: &mut String, panel: &PlacedPanel, colours: &mut BTreeSet<String>) {
    let _ = writeln!(out, "% panel {}", panel.id());
    out.push_str("\\begin{scope}\n");
    if let Some(r) = panel.clip() {
        let _ = writeln!(
            out,
            "\\clip ({},{}) rectangle ({},{});",
            fmt(r.min().x),
            fmt(r.min().y),
            fmt(r.max().x),
            fmt(r.max().y)
        );
    }
    for m in panel.marks() {
        write_mark(out, m, colours);
    }
    out.push_str("\\end{scope}\n");
}

/// A mark, after a comment with its id.
fn write_mark(out: &mut String, mark: &Mark, colours: &mut BTreeSet<String>) {
    if let Some(id) = &mark.id {
        let _ = writeln!(out, "% {}", id.replace(['\n', '\r'], " "));
    }
    match &mark.shape {
        MarkShape::Path(d, paint) => {
            if !d.is_empty() {
                let _ = writeln!(out, "\\path[{}] {};", paint_keys(paint, colours), path(d));
            }
        }
        MarkShape::Circle {
            centre,
            radius,
            paint,
        } => {
            let _ = writeln!(
                out,
                "\\path[{}] ({},{}) circle[radius={}];",
                paint_keys(paint, colours),
                fmt(centre.x),
                fmt(centre.y),
                fmt(*radius)
            );
        }
        MarkShape::Text(t) => {
            let colour = colour_name(t.colour);
            colours.insert(colour.clone());
            let anchor = match t.anchor {
                TextAnchor::Start => "base west",
                TextAnchor::Middle => "base",
                TextAnchor::End => "base east",
            };
            let _ = writeln!(
                out,
                "\\node[anchor={anchor}, inner sep=0pt, outer sep=0pt, text={colour}, \
                 font=\\fontsize{{{}bp}}{{{}bp}}\\selectfont] at ({},{}) {{{}}};",
                bp(t.size),
                bp(1.2 * t.size),
                fmt(t.at.x),
                fmt(t.at.y),
                latex::latex(&t.text)
            );
        }
        MarkShape::Group(children) => {
            for c in children {
                write_mark(out, c, colours);
            }
        }
    }
}

/// The keys of a path's paint: its stroke (colour, width and dash in big
/// points, round ends) and fill.
fn paint_keys(paint: &Paint, colours: &mut BTreeSet<String>) -> String {
    let mut keys = Vec::new();
    if let Some(s) = paint.stroke {
        let c = colour_name(s.colour);
        keys.push(format!("draw={c}"));
        colours.insert(c);
        keys.push(format!("line width={}bp", bp(s.width)));
        if let Some(dash) = s.dash {
            keys.push(format!("dash pattern={}", dash_pattern(dash)));
        }
        if s.round {
            keys.push("line cap=round, line join=round".into());
        }
    }
    if paint.fill != "none" {
        let c = colour_name(paint.fill);
        keys.push(format!("fill={c}"));
        colours.insert(c);
        if let Some(o) = paint.fill_opacity {
            keys.push(format!("fill opacity={}", fmt(o)));
        }
    }
    keys.join(", ")
}

/// An SVG dash array (page units, dash and gap by turns) as a TikZ dash
/// pattern in big points.
fn dash_pattern(dash: &str) -> String {
    let lengths: Vec<f64> = (dash.split([' ', ',']))
        .filter_map(|s| s.parse().ok())
        .collect();
    let mut out = Vec::new();
    for (i, l) in lengths.iter().enumerate() {
        let on = if i % 2 == 0 { "on" } else { "off" };
        out.push(format!("{on} {}bp", bp(*l)));
    }
    if lengths.len() % 2 == 1 {
        // An odd list repeats, as SVG's does.
        for (i, l) in lengths.iter().enumerate() {
            let on = if i % 2 == 0 { "off" } else { "on" };
            out.push(format!("{on} {}bp", bp(*l)));
        }
    }
    out.join(" ")
}

/// A page path as TikZ path operations.
fn path(d: &PathData) -> String {
    let pt = |p: crate::geom::Point| format!("({},{})", fmt(p.x), fmt(p.y));
    let mut out = Vec::new();
    for c in d.commands() {
        out.push(match *c {
            PathCommand::Move(p) => pt(p),
            PathCommand::Line(p) => format!("-- {}", pt(p)),
            PathCommand::Cubic(a, b, p) => {
                format!(".. controls {} and {} .. {}", pt(a), pt(b), pt(p))
            }
            PathCommand::Close => "-- cycle".into(),
        });
    }
    out.join(" ")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::catalogue::{FigureName, FigureOptions};
    use std::collections::BTreeSet;

    /// The ids of the marks the SVG writes (not the document's own: the
    /// paper, the panels and their clips).
    fn svg_ids(svg: &str) -> BTreeSet<String> {
        let own = |id: &str| id == "paper" || id.starts_with("panel-") || id.starts_with("clip-");
        (svg.split(" id=\"").skip(1))
            .filter_map(|rest| rest.split('"').next())
            .filter(|id| !own(id))
            .map(str::to_owned)
            .collect()
    }

    /// The ids TikZ names in its comments before each mark.
    fn tikz_ids(tikz: &str) -> BTreeSet<String> {
        (tikz.lines())
            .filter_map(|l| l.strip_prefix("% "))
            .filter(|l| !l.starts_with("panel ") && !l.contains(' '))
            .map(str::to_owned)
            .collect()
    }

    #[test]
    fn every_figure_as_tikz_is_its_placed_marks_item_for_item() {
        for name in FigureName::ALL {
            let figure = name.figure(&FigureOptions::default()).unwrap();
            let (svg, tikz) = (
                crate::render::to_svg(&figure),
                to_tikz(&figure, &TikzOptions::default()),
            );
            assert_eq!(svg_ids(&svg), tikz_ids(&tikz), "{}", name.name());
            let nodes = tikz.matches("\\node[").count();
            assert_eq!(nodes, svg.matches("<text ").count(), "{}", name.name());
            assert!(tikz.is_ascii(), "{}", name.name());
        }
    }

    #[test]
    fn a_standalone_document_is_the_picture_in_a_page_of_the_figures_size() {
        let figure = FigureName::Fig63Velocity
            .figure(&FigureOptions::default())
            .unwrap();
        let picture = to_tikz(&figure, &TikzOptions::default());
        let document = to_tikz(&figure, &TikzOptions::default().standalone(true));
        assert!(document.contains(picture.trim_end()) && document.ends_with("\\end{document}\n"));
        let size = format!(
            "paperwidth={}bp,paperheight={}bp",
            bp(figure.width()),
            bp(figure.height())
        );
        assert!(document.contains(&size), "{document}");
        assert!(!picture.contains("\\document"));
    }

    #[test]
    fn a_page_holds_its_picture_whole() {
        // 573.21 units are 429.9075 bp: a page of 429.9 bp was too short.
        assert_eq!(bp_up(573.21), "429.908");
        assert_eq!(bp_up(760.0), "570");
    }

    #[test]
    fn dashes_are_tikz_patterns_in_big_points_and_an_odd_list_repeats() {
        assert_eq!(dash_pattern("4 2"), "on 3bp off 1.5bp");
        assert_eq!(dash_pattern("4"), "on 3bp off 3bp");
        assert_eq!(colour_name("#C62828"), "scc62828");
        assert_eq!(colour_name("red"), "sc000000");
    }
}
