//! The SVG writer: the placed figure ([`crate::layout::place`]) written as
//! SVG text, numbers on a fixed grid, ids and order stable. It decides
//! nothing: each panel is a `<g>` with its map in `data-page-from-world`
//! (clipped to its rectangle if it is a detail), each mark an element
//! (`mark.rs`: paths, circles, groups; `text.rs`: texts of rich runs).

#[cfg(feature = "html")]
mod embed;
mod mark;
mod options;
mod text;

use crate::figure::{Figure, PageFromWorld, PageUnit};
use crate::layout::{PlacedPanel, place};
use crate::number::{fmt, fmt_coefficient};
use crate::render::Element;
#[cfg(feature = "html")]
pub use embed::to_svg_with_fonts;
pub use options::SvgOptions;
use serde_json::{Map, Value, json};

/// A panel as a `<g>` with its map in `data-page-from-world`, clipped to
/// its rectangle if it is a detail, its marks in order.
fn panel_group(panel: &PlacedPanel) -> Element {
    let coefficients = (panel.page_from_world().coefficients())
        .map(fmt_coefficient)
        .join(" ");
    let mut g = Element::new("g")
        .set("id", panel.id().to_owned())
        .set("data-page-from-world", coefficients);
    if let Some(r) = panel.clip() {
        let clip = format!("clip-{}", panel.id());
        let rect = Element::new("rect")
            .set("x", fmt(r.min().x))
            .set("y", fmt(r.min().y))
            .set("width", fmt(r.width()))
            .set("height", fmt(r.height()));
        g = g
            .add(
                Element::new("defs")
                    .add(Element::new("clipPath").set("id", clip.clone()).add(rect)),
            )
            .set("clip-path", format!("url(#{clip})"));
    }
    for m in panel.marks() {
        g = g.add(mark::element(m));
    }
    g
}

/// A map's coefficients as JSON numbers, as written in the panels' attributes.
fn coefficients(t: &PageFromWorld) -> Value {
    t.coefficients()
        .iter()
        .map(|c| json!(fmt_coefficient(*c).parse::<f64>().unwrap_or(0.0)))
        .collect()
}

/// The `<metadata>` element: [`metadata_of`] as JSON.
fn metadata(figure: &Figure) -> Element {
    let json =
        serde_json::to_string(&Value::Object(metadata_of(figure))).unwrap_or_else(|_| "{}".into());
    Element::text("metadata", json)
}

/// The JSON object of a figure's `<metadata>` (docs/design.md §4): the
/// figure's own keys and the renderer's (`figure`, `style`, `tolerance`,
/// page size, the first panel's map and every panel's map and
/// rectangle).
pub fn metadata_of(figure: &Figure) -> Map<String, Value> {
    let mut meta = figure.metadata().to_json();
    meta.insert("figure".into(), json!(figure.name()));
    meta.insert("style".into(), json!(figure.style().name()));
    meta.insert("tolerance".into(), json!(figure.tolerance()));
    meta.insert("width".into(), json!(figure.width()));
    meta.insert("height".into(), json!(figure.height()));
    if let Some(title) = figure.title() {
        meta.insert("title".into(), json!(title.rich().plain()));
    }
    if let Some(first) = figure.panels().first() {
        meta.insert("page_from_world".into(), coefficients(first.transform()));
    }
    let panels = figure.panels().iter().map(|p| {
        let r = p.rect();
        json!({
            "id": p.id(),
            "page_from_world": coefficients(p.transform()),
            "rect": [r.min().x, r.min().y, r.width(), r.height()],
        })
    });
    meta.insert("panels".into(), panels.collect());
    meta
}

/// A page length for the root's `width` or `height`: page units as they
/// are, a physical size with its unit (`120mm`).
pub(crate) fn root_size(x: f64, unit: PageUnit) -> String {
    if unit.is_physical() {
        format!("{}{unit}", fmt(x / unit.page_units()))
    } else {
        fmt(x)
    }
}

/// The figure as SVG text: a `<title>` if the figure has one, `<metadata>`
/// JSON (docs/design.md §4), a paper rectangle, one `<g
/// data-page-from-world>` per panel. The root's `width` and `height` are
/// in the figure's [`Figure::size_unit`], its `viewBox` in page units.
pub fn to_svg(figure: &Figure) -> String {
    document(figure, &SvgOptions::default()).to_document()
}

/// [`to_svg`] with `options`: ids prefixed, without the namespace, a
/// layer under the drawing.
pub fn to_svg_with(figure: &Figure, options: &SvgOptions) -> String {
    document(figure, options).to_document()
}

/// What [`to_svg_with`] writes inside its root element, without the root
/// (the children one to a line): a frame of an animation, set in a group
/// of a document that holds the others.
pub fn svg_body(figure: &Figure, options: &SvgOptions) -> String {
    document(figure, options).children_text()
}

/// The root element of [`to_svg_with`].
fn document(figure: &Figure, options: &SvgOptions) -> Element {
    let style = figure.style();
    let (w, h) = (figure.width(), figure.height());
    let unit = figure.size_unit();
    let paper = Element::new("rect")
        .set("id", "paper")
        .set("x", "0")
        .set("y", "0")
        .set("width", fmt(w))
        .set("height", fmt(h))
        .set("fill", style.paper());
    let root = match options.inline {
        true => Element::new("svg"),
        false => Element::document(),
    };
    let mut doc = root
        .set("width", root_size(w, unit))
        .set("height", root_size(h, unit))
        .set("viewBox", format!("0 0 {} {}", fmt(w), fmt(h)))
        .set("font-family", figure.font().css_family());
    if let Some(title) = figure.title() {
        doc = doc.add(Element::text("title", title.rich().plain()));
    }
    let mut doc = doc.add(metadata(figure)).add(paper);
    if let Some(layer) = &options.underlay {
        doc = doc.add(layer.clone());
    }
    for panel in place(figure).panels() {
        doc = doc.add(panel_group(panel));
    }
    if !options.id_prefix.is_empty() {
        doc.prefix_ids(&options.id_prefix);
    }
    doc
}
