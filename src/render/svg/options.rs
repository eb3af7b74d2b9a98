//! How a figure's SVG is written: a document of its own, or a part of a
//! page or an animation that holds others.

use crate::render::Element;

/// Options of [`to_svg_with`](super::to_svg_with). The default writes the
/// document [`to_svg`](super::to_svg) writes.
#[derive(Debug, Clone, Default)]
pub struct SvgOptions {
    pub(super) id_prefix: String,
    pub(super) inline: bool,
    pub(super) underlay: Option<Element>,
}

impl SvgOptions {
    /// Every `id` starting with `prefix` (`sheet-paper`, `f001-point-E`),
    /// and every reference to one (`url(#…)`, `href="#…"`) with it, so
    /// that figures set in one page share no id and each keeps its own
    /// references. Only attributes change: a title or a label reading
    /// `id="x"` is left as it is. An empty prefix changes nothing.
    pub fn with_id_prefix(mut self, prefix: &str) -> Self {
        self.id_prefix = prefix.to_owned();
        self
    }

    /// Without the SVG namespace attribute, which an `<svg>` inside an
    /// HTML page does not need (so that the page names no address).
    pub fn inline(mut self) -> Self {
        self.inline = true;
        self
    }

    /// `layer` set just above the paper (the white page), below
    /// everything drawn: a teaching sheet's grid (the handout's, built
    /// with the `html` feature).
    #[cfg_attr(not(feature = "html"), allow(dead_code))]
    pub(crate) fn with_underlay(mut self, layer: Element) -> Self {
        self.underlay = Some(layer);
        self
    }
}
