//! The handout's page: its style sheet with the print rules, the data, the
//! steps with their figures and tables, the summary of every value. The
//! pieces are shared with the exercise sheets and keys.

use super::command::page_command;
use super::steps::{Picture, Row, Step, Value, data_sentence, short, show};
use super::{Handout, Paper};
use crate::figure::RichText;
use crate::html::{document, rich};
use maud::{Markup, PreEscaped, html};

/// The style of every handout page after the book page's, with the print
/// rules for `paper`: the page size and margins, and no figure or table
/// broken across two pages. Printed, tables and figures are set closer
/// and a figure is at most 180 mm tall (about two thirds of the page), so
/// that a tall figure that goes on to the next page leaves less of the
/// page before it empty (the teacher's handout of issue 22: 9 A4 pages
/// where it took 11, one of them a quarter full).
pub(super) fn style(paper: Paper) -> String {
    format!(
        "
@page {{ size: {size}; margin: 14mm 15mm 16mm; }}
body {{ max-width: 46rem; font-size: 11pt; }}
header.title {{ border-bottom: 2px solid #111; margin-bottom: 1.2rem; padding-bottom: .4rem; }}
h1 {{ font-size: 1.65rem; margin: 0 0 .2rem; font-weight: normal; }}
.subtitle {{ font-style: italic; color: #333; margin: 0; }}
section.step {{ margin: 1.8rem 0 1.2rem; }}
h2 {{ font-size: 1.2rem; font-weight: normal; border-bottom: 1px solid #888; padding-bottom: .15rem;
      break-after: avoid; page-break-after: avoid; }}
h2 .no {{ display: inline-block; min-width: 1.6rem; }}
h2 .source, .source {{ float: right; font-size: .8em; color: #555; font-style: italic; }}
p {{ margin: .5rem 0; text-align: justify; hyphens: auto; }}
.block, figure, table, .sheet-figure {{ break-inside: avoid; page-break-inside: avoid; }}
figure {{ margin: 1rem 0; }}
figure svg {{ display: block; overflow: hidden; width: 100%; height: auto; max-height: 21cm; margin: 0 auto; }}
figcaption {{ font-size: .9em; margin-top: .3rem; }}
figcaption .label {{ font-variant: small-caps; }}
table.values, table.data, table.answers {{ width: 100%; font-variant-numeric: tabular-nums; margin: .8rem 0; }}
table th {{ font-weight: normal; font-style: italic; border-bottom: 1px solid #111; }}
table th:first-child, table td:first-child {{ text-align: left; }}
td.unit, th.unit {{ text-align: left; color: #333; }}
td.none {{ color: #555; font-style: italic; }}
table.data td {{ border-bottom: 1px solid #eee; }}
table.answers td.answer {{ border-bottom: 1px solid #111; width: 11em; height: 1.9em; }}
.conventions {{ font-size: .9em; color: #333; }}
footer {{ margin-top: 2rem; border-top: 1px solid #888; font-size: .85em; color: #444; }}
footer .nobreak {{ white-space: nowrap; }}
@media print {{
  body {{ max-width: none; margin: 0; padding: 0; font-size: 10.5pt; line-height: 1.3; }}
  header.title {{ margin-bottom: .6rem; }}
  section.step {{ margin: 1rem 0 .8rem; }}
  th, td {{ padding: .05rem .6rem; }}
  table.values, table.data, table.answers {{ margin: .5rem 0; }}
  figure {{ margin: .6rem 0; }}
  figure svg {{ max-height: 180mm; }}
  a {{ color: inherit; text-decoration: none; }}
}}
",
        size = paper.css_size()
    )
}

/// The full-precision text of a number in `data-value`: the shortest that
/// reads back as the same number (what the analysis's JSON writes).
fn exact_text(x: f64) -> String {
    format!("{}", crate::number::unsigned_zero(x))
}

/// One value cell: the number shown to four figures, the full number in
/// `data-value` and its name in `data-key`; or the text for no number.
pub(super) fn value_cell(v: Option<&Value>) -> Markup {
    html! {
        @match v {
            None => td {},
            Some(v) => @match v.value {
                Some(x) => td.num data-key=(v.key) data-value=(exact_text(x)) { (show(x)) },
                None => td.none data-key=(v.key) { (v.none) },
            },
        }
    }
}

/// A datum's cell: as [`value_cell`], the number without trailing zeros.
fn data_cell(v: &Value) -> Markup {
    html! {
        @if let Some(x) = v.value {
            td.num data-key=(v.key) data-value=(exact_text(x)) { (short(x)) }
        }
    }
}

/// A table of values: quantity, read off the construction, exact, unit.
pub(super) fn values_table(rows: &[Row], caption: Option<&str>) -> Markup {
    html! {
        div.block {
            table.values {
                @if let Some(c) = caption { caption { (c) } }
                thead {
                    tr {
                        th { "quantity" }
                        th { "read off the construction" }
                        th { "exact" }
                        th.unit { "unit" }
                    }
                }
                tbody {
                    @for row in rows {
                        tr {
                            td { (rich(&row.quantity)) }
                            (value_cell(row.read.as_ref()))
                            (value_cell(row.exact.as_ref()))
                            td.unit { (rich(&row.unit)) }
                        }
                    }
                }
            }
        }
    }
}

/// The engine's data as a table; every number with its `data-key` as in
/// the analysis's JSON (`mechanism.crank`, `angle_deg`, `omega`).
pub(super) fn data_table(h: &Handout) -> Markup {
    let m = h.mechanism();
    let u = h.units();
    let len = u.length().as_str();
    let mut rows: Vec<(&str, Value, String)> = vec![
        (
            "crank radius *r*",
            Value::of("mechanism.crank", m.crank()),
            len.into(),
        ),
        (
            "connecting rod *l*",
            Value::of("mechanism.rod", m.rod()),
            len.into(),
        ),
        (
            "offset of the line of stroke *e*",
            Value::of("mechanism.offset", m.offset()),
            len.into(),
        ),
        (
            "*n* = *l*/*r*",
            Value::of("mechanism.ratio", m.ratio()),
            String::new(),
        ),
        (
            "stroke",
            Value::of("mechanism.stroke", m.stroke()),
            len.into(),
        ),
        ("crank speed *N*", Value::of("rpm", h.rpm()), "rpm".into()),
        (
            "ω = 2π*N*/60",
            Value::of("omega", h.omega()),
            "rad/s".into(),
        ),
        (
            "crank-pin speed *V*_c = *r*ω",
            Value::of("crank_pin_speed", m.crank() * h.omega()),
            u.velocity(),
        ),
        (
            "crank angle θ",
            Value::of("angle_deg", h.angle().degrees()),
            "°".into(),
        ),
    ];
    if let Some(t) = h.torque() {
        rows.push(("crank torque *T*", Value::of("torque", t), u.torque()));
        rows.push((
            "coefficient of friction μ",
            Value::of("statics.friction", h.friction()),
            String::new(),
        ));
    }
    html! {
        div.block {
            table.data {
                caption { "The engine" }
                tbody {
                    @for (name, value, unit) in &rows {
                        tr {
                            td { (rich(name)) }
                            (data_cell(value))
                            td.unit { (unit) }
                        }
                    }
                }
            }
        }
    }
}

/// A figure with its caption; the drawing is an image to assistive
/// technology, named by the caption's text.
pub(super) fn picture(p: &Picture, label: &str) -> Markup {
    let name = format!("{label} {}", RichText::parse(&p.caption).plain());
    let named = format!(
        "<svg role=\"img\" aria-label=\"{}\"",
        html! { (name) }.into_string()
    );
    let svg = p.svg.replacen("<svg", &named, 1);
    html! {
        figure {
            (PreEscaped(svg))
            figcaption { span.label { (label) } " " (rich(&p.caption)) }
        }
    }
}

/// The conventions every page states once.
pub(super) fn conventions(h: &Handout) -> Markup {
    let u = h.units();
    html! {
        p.conventions {
            "Letters of the textbook: " i { "C" } " crank centre, " i { "B" } " crank pin, "
            i { "A" } " cross-head, " i { "D" } " instantaneous centre of the rod, " i { "E" }
            " where the rod produced meets the perpendicular to the stroke through " i { "C" } ". "
            "θ is counter-clockwise from the outer dead centre; " i { "x" } " is the cross-head’s distance from "
            i { "C" } " along the stroke, and velocities and accelerations are its rates of change, signed. "
            "Lengths in " (u.length().as_str()) ", forces in " (u.force().as_str()) "."
        }
    }
}

/// The page's footer: the program and the command, which a printed line
/// breaks only between its options (each flag kept with its value).
pub(super) fn footer(command: &str) -> Markup {
    html! {
        footer {
            p {
                "Made by slider-crank " (env!("CARGO_PKG_VERSION")) " with "
                code {
                    @for (i, part) in unbroken(command).iter().enumerate() {
                        @if i > 0 { " " }
                        span.nobreak { (part) }
                    }
                }
                "."
            }
        }
    }
}

/// The parts of a shell command a line may not break inside: its words
/// (a quoted word with its spaces kept whole), each option with the
/// value after it.
fn unbroken(command: &str) -> Vec<String> {
    let mut words: Vec<String> = Vec::new();
    let (mut word, mut quoted) = (String::new(), false);
    for c in command.chars() {
        match c {
            '\'' => {
                quoted = !quoted;
                word.push(c);
            }
            ' ' if !quoted => {
                if !word.is_empty() {
                    words.push(std::mem::take(&mut word));
                }
            }
            _ => word.push(c),
        }
    }
    if !word.is_empty() {
        words.push(word);
    }
    let mut parts: Vec<String> = Vec::new();
    let mut words = words.into_iter().peekable();
    while let Some(w) = words.next() {
        let value = w.starts_with("--") && !w.contains('=');
        match words.peek() {
            Some(next) if value && !next.starts_with("--") => {
                let next = words.next().unwrap_or_default();
                parts.push(format!("{w} {next}"));
            }
            _ => parts.push(w),
        }
    }
    parts
}

/// The whole handout page.
pub(super) fn handout(h: &Handout, steps: &[Step], all: &[Row]) -> String {
    let title = h
        .title
        .clone()
        .unwrap_or_else(|| "The slider-crank engine, worked through".into());
    let mut figure_no = 0;
    let body = html! {
        header.title {
            h1 { (title) }
            p.subtitle {
                "The velocity and acceleration of the cross-head and the connecting rod by the "
                "constructions of “Slider-crank chains” (§35–37) and the static forces after "
                "T. W. Ng, for one engine"
                @if h.dynamics().is_some() {
                    "; then its inertia forces, turning moment and flywheel"
                }
                "."
            }
        }
        p { (rich(&data_sentence(h))) }
        (data_table(h))
        (conventions(h))
        @for (i, step) in steps.iter().enumerate() {
            section.step id={ "step-" (step.id) } {
                h2 {
                    span.no { (i + 1) "." }
                    (rich(&step.title))
                    span.source { (step.source) }
                }
                @for para in &step.text {
                    p { (rich(para)) }
                }
                @for p in &step.pictures {
                    ({ figure_no += 1; picture(p, &format!("Figure {figure_no}.")) })
                }
                @if !step.rows.is_empty() {
                    (values_table(&step.rows, None))
                }
            }
        }
        section.step id="summary" {
            h2 {
                span.no { (steps.len() + 1) "." }
                "Every value"
                span.source { "construction and exact" }
            }
            p {
                "The values read off the constructions are the lengths of the drawing scaled by ω or ω²; "
                "drawn exactly, they equal the exact values of the formulas. On paper, expect them to "
                "agree to the accuracy of the drawing."
            }
            (values_table(all, None))
        }
        (footer(&page_command(h)))
    };
    document(
        &format!("{}: {}", title, plain_data(h)),
        &style(h.paper()),
        body,
    )
}

/// The data in a line of plain text (for the page's title).
pub(super) fn plain_data(h: &Handout) -> String {
    let m = h.mechanism();
    let u = h.units().length().as_str();
    format!(
        "r = {} {u}, l = {} {u}, e = {} {u}, θ = {}°",
        short(m.crank()),
        short(m.rod()),
        short(m.offset()),
        short(h.angle().degrees())
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_printed_command_breaks_only_between_its_options() {
        let parts = unbroken(
            "slider-crank handout --crank 0.3 --unit mm --title 'a b c' --mirror --mass=2 --angle -30",
        );
        assert_eq!(
            parts,
            [
                "slider-crank",
                "handout",
                "--crank 0.3",
                "--unit mm",
                "--title 'a b c'",
                "--mirror",
                "--mass=2",
                "--angle -30",
            ]
        );
        let html = footer("slider-crank handout --unit mm").into_string();
        assert!(
            html.contains(r#"<span class="nobreak">--unit mm</span>"#),
            "{html}"
        );
    }
}
