//! A gallery manifest: a TOML file that says what a gallery holds.
//!
//! ```toml
//! figures = ["fig-67-example", "ng-fig-1-torque"]  # named figures [default: every one]
//! scenes = ["examples/offset-kisch.toml"]          # scene files, from the manifest's directory
//! formats = ["svg", "pdf"]                         # [default: svg, png, pdf; or tikz]
//! style = "handout"                                # [default: each figure's own]
//! font = "libertinus-serif"                        # [default: new-computer-modern]
//! ```
//!
//! A scene's files are named after its file (`offset-kisch.svg`). The
//! style and font apply to every named figure, and to each scene file
//! that does not set its own. Unknown keys are errors; every error names
//! its line and column, or the scene file it is about.

use super::{Gallery, SceneEntry};
use crate::catalogue::{located, toml_error};
use crate::error::{Error, Input, Result};
use crate::figure::Font;
use crate::files::{MAX_SCENE_BYTES, read_text};
use crate::render::FileFormat;
use crate::{catalogue::FigureName, catalogue::SceneFile, figure::Style};
use serde::Deserialize;
use std::path::Path;
use toml::Spanned;

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct ManifestFile {
    figures: Option<Vec<Spanned<String>>>,
    scenes: Option<Vec<Spanned<String>>>,
    formats: Option<Vec<Spanned<String>>>,
    style: Option<Spanned<String>>,
    font: Option<Spanned<String>>,
}

/// `r`, its error placed at the value of `s`.
fn at<T, U>(text: &str, s: &Spanned<U>, r: Result<T>) -> Result<T> {
    r.map_err(|e| located(Input::Manifest, text, s.span(), e.one_line()))
}

impl Gallery {
    /// The gallery a manifest describes: TOML with the keys `figures`
    /// (names; default every one), `scenes` (scene files, read from
    /// `base`, the manifest's directory, and named after their files),
    /// `formats` (svg, png, pdf, tikz), `style` and `font` (for every figure, and
    /// for each scene file that sets none). Unknown keys are errors; every
    /// error names its line and column.
    pub fn from_manifest(text: &str, base: &Path) -> Result<Gallery> {
        let file: ManifestFile =
            toml::from_str(text).map_err(|e| toml_error(Input::Manifest, text, &e))?;
        let mut gallery = Gallery::new();
        if let Some(figures) = &file.figures {
            let names = figures
                .iter()
                .map(|n| at(text, n, FigureName::from_name(n.get_ref())))
                .collect::<Result<Vec<_>>>()?;
            gallery = gallery.with_figures(names);
        }
        if let Some(formats) = &file.formats {
            let formats = formats
                .iter()
                .map(|f| at(text, f, FileFormat::from_name(f.get_ref())))
                .collect::<Result<Vec<_>>>()?;
            if formats.is_empty() {
                return Err(Error::invalid(
                    Input::Manifest,
                    "formats names no format".into(),
                ));
            }
            gallery = gallery.with_formats(formats);
        }
        if let Some(style) = &file.style {
            gallery = gallery.with_style(at(text, style, Style::from_name(style.get_ref()))?);
        }
        if let Some(font) = &file.font {
            gallery = gallery.with_font(at(text, font, font.get_ref().parse::<Font>())?);
        }
        for path in file.scenes.iter().flatten() {
            let entry = at(text, path, scene_entry(&gallery, base, path.get_ref()))?;
            at(text, path, gallery.add_scene(entry))?;
        }
        Ok(gallery)
    }
}

/// A scene file read, named after its file, with the gallery's style and
/// font where it sets none.
fn scene_entry(gallery: &Gallery, base: &Path, path: &str) -> Result<SceneEntry> {
    let full = base.join(path);
    let text = read_text(&full, MAX_SCENE_BYTES, Input::Scene)?;
    let named = |e: Error| Error::invalid(Input::Scene, format!("{path}: {}", e.one_line()));
    let mut scene = SceneFile::from_toml(&text)
        .and_then(SceneFile::into_scene)
        .map_err(named)?;
    let keys = text
        .parse::<toml::Table>()
        .map_err(|e| named(Error::invalid(Input::Scene, e.to_string())))?;
    if let Some(style) = gallery.style
        && !keys.contains_key("style")
    {
        scene = scene.with_style(style);
    }
    if let Some(font) = gallery.font
        && !keys.contains_key("font")
    {
        scene = scene.with_font(font);
    }
    let name = Path::new(path)
        .file_stem()
        .and_then(|s| s.to_str())
        .filter(|s| !s.is_empty() && !s.starts_with('.'))
        .ok_or_else(|| {
            Error::invalid(
                Input::Scene,
                format!("{path}: a scene file needs a name to name its files"),
            )
        })?;
    // The name names the gallery's files and their anchor in its page: an
    // escape sequence in it would be a file name no terminal lists as it is.
    if let Some(why) = crate::error::text_fault(name) {
        return Err(Error::invalid(
            Input::Scene,
            format!(
                "{}: a scene file's name names its files in the gallery, and {why}",
                Error::printable(path)
            ),
        ));
    }
    Ok(SceneEntry {
        name: name.to_string(),
        file: path.to_string(),
        scene,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_manifest_chooses_figures_scenes_formats_style_and_font() {
        let base = Path::new(env!("CARGO_MANIFEST_DIR"));
        let g = Gallery::from_manifest(
            r#"
figures = ["fig-67-example"]
scenes = ["examples/offset-kisch.toml"]
formats = ["svg", "PDF"]
style = "handout"
font = "libertinus-serif"
"#,
            base,
        )
        .unwrap();
        assert_eq!(g.figures(), [FigureName::Fig67Example]);
        assert_eq!(g.formats(), [FileFormat::Svg, FileFormat::Pdf]);
        let names = g.file_names();
        assert!(names.contains(&"offset-kisch.pdf".to_string()), "{names:?}");
        assert_eq!(g.scenes[0].scene.style(), Style::Handout);
        assert_eq!(g.scenes[0].scene.font(), Font::LibertinusSerif);
    }

    #[test]
    fn errors_name_the_line_and_column() {
        let base = Path::new(env!("CARGO_MANIFEST_DIR"));
        for (text, expected) in [
            (
                "figures = [\"fig-99\"]",
                "line 1, column 12: unknown figure 'fig-99'",
            ),
            (
                "\nformats = [\"jpg\"]",
                "line 2, column 12: unknown format 'jpg'",
            ),
            ("colour = 1", "line 1, column 1: unknown field `colour`"),
            (
                "scenes = [\"missing.toml\"]",
                "line 1, column 11: cannot read scene file",
            ),
            (
                "scenes = [\"examples/overlay.toml\",\n \"examples/overlay.toml\"]",
                "line 2, column 2: two entries of the gallery are named overlay",
            ),
        ] {
            let err = Gallery::from_manifest(text, base).unwrap_err().to_string();
            assert!(err.starts_with(expected), "{text}: {err}");
        }
    }
}
