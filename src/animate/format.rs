//! The two files an animation is written as, told by the file's
//! extension.

use crate::error::{Error, Input, Result};
use std::path::Path;

/// The format of an animation's file.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum AnimationFormat {
    /// A self-playing SVG ([`super::Animation::to_svg`]).
    Svg,
    /// An HTML page with a slider and a play button
    /// ([`super::Animation::to_html`]; feature `html`).
    #[cfg(feature = "html")]
    Html,
}

impl AnimationFormat {
    /// The extension, without the dot (`svg`, `html`).
    pub fn extension(&self) -> &'static str {
        match self {
            AnimationFormat::Svg => "svg",
            #[cfg(feature = "html")]
            AnimationFormat::Html => "html",
        }
    }

    /// The format of a file by its extension, `.svg` or `.html` (in any
    /// case); SVG for a name without one (a device such as
    /// `/dev/stdout`, a FIFO). Any other extension, `.htm` included, is an
    /// error that names the two (the one, SVG, without the feature
    /// `html`).
    pub fn from_path(path: &Path) -> Result<Self> {
        let Some(ext) = path.extension() else {
            return Ok(AnimationFormat::Svg);
        };
        [
            AnimationFormat::Svg,
            #[cfg(feature = "html")]
            AnimationFormat::Html,
        ]
        .into_iter()
        .find(|f| ext.eq_ignore_ascii_case(f.extension()))
        .ok_or_else(|| {
            Error::invalid(Input::OutputFile, format!(
                "cannot write {}: .{} is not an animation format: give a file ending in {FORMATS}",
                path.display(),
                ext.to_string_lossy()
            ))
        })
    }
}

/// The formats `from_path` names in its error.
#[cfg(feature = "html")]
const FORMATS: &str = ".svg (plays by itself) or .html (with a slider)";
#[cfg(not(feature = "html"))]
const FORMATS: &str = ".svg (plays by itself; the feature `html` writes .html pages)";

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_extension_tells_the_format() {
        for (path, format) in [
            ("a.svg", AnimationFormat::Svg),
            #[cfg(feature = "html")]
            ("a.HTML", AnimationFormat::Html),
            ("/dev/stdout", AnimationFormat::Svg),
        ] {
            assert_eq!(AnimationFormat::from_path(Path::new(path)).unwrap(), format);
        }
        for bad in ["a.gif", "a.htm", "a.png", "a.svg.bak"] {
            let e = AnimationFormat::from_path(Path::new(bad)).unwrap_err();
            let e = e.to_string();
            assert!(e.contains(".svg") && e.contains(".html"), "{e}");
        }
        // Without the feature, a page is refused, naming the feature.
        #[cfg(not(feature = "html"))]
        assert!(AnimationFormat::from_path(Path::new("a.html")).is_err());
    }
}
