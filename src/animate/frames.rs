//! The frames of an animation: each a still figure's SVG, and the same
//! SVG with its ids made its own, to sit beside the others in one
//! document.

use crate::error::{Error, Result};
use crate::figure::{Figure, PageUnit};
use crate::render::to_svg;
use crate::{Angle, Scene};

/// One frame: the crank angle and the still figure drawn there.
#[derive(Debug, Clone, PartialEq)]
pub struct Frame {
    angle: Angle,
    svg: String,
    height: f64,
}

impl Frame {
    /// The crank angle of the frame's pose.
    pub fn angle(&self) -> Angle {
        self.angle
    }

    /// The still figure as its own SVG document: what
    /// [`render::to_svg`](crate::render::to_svg) writes for the figure of
    /// [`Scene::frames`] at this angle, byte for byte.
    pub fn svg(&self) -> &str {
        &self.svg
    }

    /// The figure's page height in page units.
    pub fn height(&self) -> f64 {
        self.height
    }

    /// The ids' prefix of frame `index` in an animation: `f000-`, `f001-`,
    /// … (at least three digits, more past 999).
    pub fn prefix(index: usize) -> String {
        format!("f{index:03}-")
    }

    /// What the still figure draws, without its root element, every id and
    /// reference to one prefixed with `prefix` ([`prefixed`]), to be set
    /// in a group or an inline `<svg>` beside other frames.
    pub fn body(&self, prefix: &str) -> String {
        prefixed(inner(&self.svg), prefix)
    }
}

/// What every frame shares, read off the first: the page's width and the
/// unit of its size, the font family and the title.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Sheet {
    pub width: f64,
    pub unit: PageUnit,
    pub font_family: &'static str,
    pub title: Option<String>,
}

impl Sheet {
    fn of(figure: &Figure) -> Self {
        Self {
            width: figure.width(),
            unit: figure.size_unit(),
            font_family: figure.font().css_family(),
            title: figure.title().map(|t| t.rich().plain()),
        }
    }
}

/// The frames of `scene` at `angles` (at least one), in a view held over
/// the whole revolution and the frames' angles
/// ([`super::Animation::new`]), calling `progress` after each, and what
/// they share.
pub(super) fn draw(
    scene: &Scene,
    angles: &[Angle],
    mut progress: impl FnMut(usize, usize),
) -> Result<(Vec<Frame>, Sheet)> {
    let mut held: Vec<Angle> = match scene.held() {
        Some(poses) => poses.to_vec(),
        None => (0..360).map(|d| Angle::deg(f64::from(d))).collect(),
    };
    held.extend_from_slice(angles);
    let scene = scene.clone().with_held_view(held);
    let mut frames = Vec::with_capacity(angles.len());
    let mut sheet = None;
    for (angle, figure) in angles.iter().zip(scene.frame_series(angles)?) {
        sheet.get_or_insert_with(|| Sheet::of(&figure));
        frames.push(Frame {
            angle: *angle,
            svg: to_svg(&figure),
            height: figure.height(),
        });
        progress(frames.len(), angles.len());
    }
    let sheet = sheet.ok_or_else(|| Error::Parse("an animation has at least one frame".into()))?;
    Ok((frames, sheet))
}

/// The content of an SVG document: what lies between its root's start
/// and end tags (all of it when there is no root).
fn inner(svg: &str) -> &str {
    let start = svg
        .find("<svg")
        .and_then(|at| svg[at..].find('>').map(|end| at + end + 1))
        .unwrap_or(0);
    let end = svg
        .rfind("</svg>")
        .filter(|&e| e >= start)
        .unwrap_or(svg.len());
    svg[start..end].trim_matches('\n')
}

/// `svg` (markup as the renderer writes it) with every id and every
/// reference to one made to start with `prefix`: the `id="…"` attributes,
/// `url(#…)` and `href="#…"`. Only the tags are rewritten, never text or
/// metadata between them, so a title or a label that reads `id="x"` is
/// left alone. Markup without ids comes back unchanged.
pub fn prefixed(svg: &str, prefix: &str) -> String {
    let mut out = String::with_capacity(svg.len() + svg.len() / 16);
    let mut rest = svg;
    while let Some(open) = rest.find('<') {
        out.push_str(&rest[..open]);
        let close = rest[open..].find('>').map_or(rest.len(), |c| open + c + 1);
        out.push_str(&prefix_tag(&rest[open..close], prefix));
        rest = &rest[close..];
    }
    out.push_str(rest);
    out
}

/// One tag with its ids and references prefixed.
fn prefix_tag(tag: &str, prefix: &str) -> String {
    tag.replace(" id=\"", &format!(" id=\"{prefix}"))
        .replace("url(#", &format!("url(#{prefix}"))
        .replace("href=\"#", &format!("href=\"#{prefix}"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ids_and_references_are_prefixed_in_tags_only() {
        let svg = r##"<svg width="1"><title>id="x" url(#y)</title><g id="a" clip-path="url(#c)"><use href="#a"/></g></svg>"##;
        let body = prefixed(inner(svg), "f001-");
        assert_eq!(
            body,
            r##"<title>id="x" url(#y)</title><g id="f001-a" clip-path="url(#f001-c)"><use href="#f001-a"/></g>"##
        );
        assert_eq!(prefixed("plain", "p-"), "plain");
        assert_eq!(inner("no root"), "no root");
    }

    #[test]
    fn prefixes_keep_their_order() {
        assert_eq!(Frame::prefix(0), "f000-");
        assert_eq!(Frame::prefix(719), "f719-");
        assert_eq!(Frame::prefix(1234), "f1234-");
    }
}
