//! The explorer's page: the figure, the controls of the engine and its
//! drawing, the exact and graphical values beside the figure, and the
//! downloads. One self-contained HTML file: its faces carried as `data:`
//! URLs, its script inline, nothing fetched but the server's own figures.

use crate::catalogue::{FigureName, Setting};
use crate::figure::{Font, Style};
use crate::scene::{Layer, Notation};
use maud::{Markup, PreEscaped, html};
use serde_json::{Value, json};

/// The page's style, after the shared book page ([`crate::html::document`]).
const STYLE: &str = include_str!("page.css");

/// The page's script: the state in the URL, a figure asked for at most
/// once at a time through the [`WORKER`] (the newest state waits, older
/// ones are dropped; a slow request is abandoned for a newer one), the
/// crank pin dragged by pointer or turned by the arrow keys; a drag or a
/// key asks ahead for the next poses at its step (three at most
/// outstanding) and draws a figure it has kept in the handler of its
/// event (docs/benchmarks.md, the explorer).
const SCRIPT: &str = include_str!("page.js");

/// The page's worker (`/worker.js`): the figure requests, made and their
/// replies parsed off the page's thread, so that a request made during a
/// drag leaves at once rather than after the frame the pointer event
/// begins.
pub const WORKER: &str = include_str!("worker.js");

/// The characters a figure may set beyond the page's own text: its faces
/// are cut to these and the page's (the figures are drawn into the page
/// after it is made).
const FIGURE_CHARACTERS: &str = " !\"#$%&'()*+,-./0123456789:;<=>?@ABCDEFGHIJKLMNOPQRSTUVWXYZ[\\]^_`abcdefghijklmnopqrstuvwxyz{|}~\
    °±²³·×÷ΔΣΦΩαβγδεθλμπρσφωϕ′″–—‘’“”…−∞√≈≠≤≥→←↑↓∠⊥∥";

/// The page, opened on the figure `name`: its state (figure, engine, pose,
/// layers, look) is read from and written to the page's URL.
pub fn page(name: FigureName) -> String {
    let figures: Vec<Value> = FigureName::ALL.iter().map(figure_entry).collect();
    let data = json!({ "initial": name.name(), "figures": figures }).to_string();
    // Inside <script>, `<` escaped so that no text can close the element.
    let data = data.replace('<', "\\u003c");
    let body = body(name, &data);
    let families: String = Font::ALL.iter().map(Font::family).collect();
    crate::html::document_covering(
        "slider-crank explorer",
        STYLE,
        body,
        &format!("{FIGURE_CHARACTERS}{families}"),
    )
}

/// What the page knows of one figure: its name, group, source and what it
/// takes, with the defaults its controls start from.
fn figure_entry(f: &FigureName) -> Value {
    let m = f.mechanism();
    let takes = |s: Setting| f.takes(s);
    let units = f.units();
    json!({
        "name": f.name(),
        "group": f.group().heading(),
        "source": f.source(),
        "mechanism": takes(Setting::Mechanism),
        "angle": takes(Setting::Angle),
        "speed": takes(Setting::Speed),
        "layers": takes(Setting::Layers),
        "notation": takes(Setting::Notation),
        "style": takes(Setting::Style),
        "font": takes(Setting::Font),
        "mirror": takes(Setting::Mirror),
        "defaults": {
            "crank": m.crank(),
            "rod": m.rod(),
            "offset": m.offset(),
            "angle": f.angle_degrees(),
            "layers": f.layers().iter().map(Layer::name).collect::<Vec<_>>(),
            "unit": units.length().to_string(),
        },
    })
}

/// A labelled select of `options` (value, text), the first chosen.
fn select(id: &str, label: &str, options: &[(&str, &str)]) -> Markup {
    html! {
        label for=(id) { (label) }
        select #(id) name=(id) {
            @for (value, text) in options { option value=(value) { (text) } }
        }
    }
}

/// A labelled number input.
fn number(id: &str, label: Markup, step: &str) -> Markup {
    html! {
        label for=(id) { (label) }
        input #(id) name=(id) type="number" step=(step) inputmode="decimal";
    }
}

fn body(initial: FigureName, data: &str) -> Markup {
    let styles: Vec<(&str, &str)> = [Style::Textbook, Style::Handout]
        .iter()
        .map(|s| (s.name(), s.name()))
        .collect();
    let notations: Vec<(&str, &str)> = [Notation::Textbook, Notation::Ng]
        .iter()
        .map(|n| (n.name(), n.name()))
        .collect();
    let fonts: Vec<(&str, &str)> = Font::ALL.iter().map(|f| (f.name(), f.name())).collect();
    let with_own = |list: Vec<(&'static str, &'static str)>| {
        let mut all = vec![("", "the figure’s own")];
        all.extend(list);
        all
    };
    html! {
        header {
            h1 { "Slider-crank explorer" }
            p .lead {
                "Drag the crank pin " i { "B" } " (or focus the figure and turn it with the arrow keys: 1° a press, 0.1° with Shift); "
                "change the engine and the drawing on the right. The address holds the whole state: bookmark it or share it."
            }
        }
        main .explorer {
            section .stage-column aria-label="Figure" {
                div #stage .stage tabindex="0" role="slider" aria-valuemin="0" aria-valuemax="360"
                    aria-valuenow="0" aria-label="Crank angle θ: drag the crank pin B, or use the arrow keys"
                    aria-describedby="description" {
                    p { "Drawing the figure " (initial.name()) "…" }
                }
                p #description .description {}
                p #status .status role="status" aria-live="polite" {}
            }
            section .panel aria-label="Controls and values" {
                section #values-section aria-label="Values" {
                    table #values {
                        caption { "Exact and graphical values" }
                        thead { tr { th scope="col" { "quantity" } th scope="col" { "exact" } th scope="col" { "graphical" } } }
                        tbody {}
                    }
                }
                nav .downloads aria-label="Downloads" {
                    a #download-svg download href="#" { "SVG" }
                    a #download-png download href="#" { "PNG" }
                    a #download-pdf download href="#" { "PDF" }
                    a #download-tikz download href="#" { "TikZ" }
                    a #download-handout download href="#" { "Handout for this engine" }
                }
                form #controls {
                    fieldset {
                        legend { "Figure" }
                        label for="name" { "Figure" }
                        select #name name="name" {}
                    }
                    fieldset #engine {
                        legend { "Engine and pose" }
                        div .grid {
                            (number("crank", html! { "Crank radius " i { "r" } }, "any"))
                            (number("rod", html! { "Rod length " i { "l" } }, "any"))
                            (number("offset", html! { "Offset " i { "e" } }, "any"))
                            (number("angle", html! { "Crank angle " i { "θ" } " (°)" }, "0.1"))
                            (number("speed", html! { "Crank speed" }, "any"))
                            (select("speed-unit", "Speed in", &[("rpm", "rpm"), ("omega", "rad/s (ω)")]))
                        }
                    }
                    fieldset #layers {
                        legend { "Layers" }
                        div #layer-boxes .layer-boxes {
                            @for layer in Layer::ALL {
                                label { input type="checkbox" name="layer" value=(layer.name()); " " (layer.name()) }
                            }
                        }
                    }
                    fieldset #look {
                        legend { "Drawing" }
                        div .grid {
                            (select("notation", "Letters", &with_own(notations)))
                            (select("style", "Style", &with_own(styles)))
                            (select("font", "Face", &with_own(fonts)))
                            (select("mirror", "Mirrored", &[("", "the figure’s own"), ("true", "mirrored"), ("false", "unmirrored")]))
                        }
                        label .check { input #large type="checkbox" name="large"; " Large type (projector)" }
                    }
                }
            }
        }
        script #explore-data type="application/json" { (PreEscaped(data)) }
        script { (PreEscaped(SCRIPT)) }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_page_carries_every_figure_its_faces_and_no_address_outside() {
        let page = page(FigureName::Fig66Kisch);
        assert!(page.starts_with("<!DOCTYPE html>"));
        assert!(page.contains("@font-face"));
        for f in FigureName::ALL {
            assert!(
                page.contains(&format!("\"name\":\"{}\"", f.name())),
                "{}",
                f.name()
            );
        }
        assert!(
            !page.contains("http://") && !page.contains("https://")
                || page.contains("http://www.w3.org")
        );
        for id in [
            "crank", "rod", "offset", "angle", "speed", "notation", "style", "large",
        ] {
            assert!(
                page.contains(&format!("<label for=\"{id}\""))
                    || page.contains(&format!("id=\"{id}\"")),
                "{id}"
            );
        }
    }
}
