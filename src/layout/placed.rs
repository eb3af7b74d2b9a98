//! The placed figure: what the layout decided, for the writers to write.

use super::mark::Mark;
use crate::figure::{Figure, PageFromWorld, Panel};
use crate::geom::Frame;

/// A panel laid out: its id, its page-from-world map (written as the
/// panel's metadata), the rectangle its marks are clipped to if it is a
/// detail, and its marks in drawing order, labels last.
#[derive(Debug, Clone)]
pub struct PlacedPanel {
    id: String,
    page_from_world: PageFromWorld,
    clip: Option<Frame>,
    marks: Vec<Mark>,
}

impl PlacedPanel {
    /// `panel`'s id, map and clip with `marks`.
    pub(super) fn new(panel: &Panel, marks: Vec<Mark>) -> Self {
        PlacedPanel {
            id: panel.id().to_owned(),
            page_from_world: *panel.transform(),
            clip: panel.is_clipped().then(|| *panel.rect()),
            marks,
        }
    }

    /// The panel's id.
    pub fn id(&self) -> &str {
        &self.id
    }

    /// The panel's map from world to page.
    pub fn page_from_world(&self) -> &PageFromWorld {
        &self.page_from_world
    }

    /// The rectangle a detail's marks are clipped to; `None` for a panel
    /// drawn whole.
    pub fn clip(&self) -> Option<&Frame> {
        self.clip.as_ref()
    }

    /// The marks, in drawing order (later over earlier), the labels and
    /// their leaders last.
    pub fn marks(&self) -> &[Mark] {
        &self.marks
    }
}

/// A figure laid out: the figure (its page, title, style, font and
/// metadata, which the writers copy) and its panels placed. Every place
/// is decided: a writer only writes it.
#[derive(Debug, Clone)]
pub struct PlacedFigure<'a> {
    figure: &'a Figure,
    panels: Vec<PlacedPanel>,
}

impl<'a> PlacedFigure<'a> {
    pub(super) fn new(figure: &'a Figure, panels: Vec<PlacedPanel>) -> Self {
        PlacedFigure { figure, panels }
    }

    /// The figure laid out.
    pub fn figure(&self) -> &'a Figure {
        self.figure
    }

    /// The panels, in the figure's order.
    pub fn panels(&self) -> &[PlacedPanel] {
        &self.panels
    }
}
