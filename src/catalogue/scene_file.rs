//! What a scene file describes: a mechanism figure or a named diagram.

use super::{FigureName, FigureOptions, parse};
use crate::error::{Error, Input, Result};
use crate::figure::Figure;
use crate::scene::Scene;

/// What a scene file describes: a mechanism figure, drawn by a [`Scene`],
/// or one of the named diagrams with the changes the file asks for
/// (`figure = "fig-64-velocity-diagrams"`; its mechanism, speed, angle,
/// units, page, title, style and font).
#[derive(Debug, Clone, PartialEq)]
pub enum SceneFile {
    /// A mechanism figure: a named one changed by the file, or one made
    /// from scratch.
    Mechanism(Scene),
    /// A diagram of the catalogue, drawn by [`FigureName::figure`] with
    /// these options.
    Diagram(FigureName, FigureOptions),
}

impl SceneFile {
    /// Reads a scene file (TOML; see `examples/*.toml` and docs/design.md
    /// §4). Errors name the line and column of the bad key or value, in one
    /// line.
    pub fn from_toml(text: &str) -> Result<Self> {
        parse::parse(text).map_err(Error::one_line)
    }

    /// Every key a scene file may hold, read off the parser's own
    /// structs: the top-level keys (`angle`), and each table (`page`)
    /// followed by its keys as `table.key` (`page.width`). The reference,
    /// docs/scene-format.md, gives each with its type, default and range.
    pub fn keys() -> Vec<String> {
        parse::keys()
    }

    /// The version of scene files this program reads, the integer a file
    /// may give as `version` (newer or invalid versions are refused).
    pub const VERSION: i64 = parse::VERSION;

    /// The scene of a file that describes a mechanism figure; a file that
    /// starts from a diagram is refused with a message naming the
    /// mechanism figures.
    pub fn into_scene(self) -> Result<Scene> {
        match self {
            SceneFile::Mechanism(scene) => Ok(scene),
            SceneFile::Diagram(name, _) => Err(Error::invalid(
                Input::FigureName,
                format!(
                    "'{}' is a diagram; a scene starts from a mechanism figure ({})",
                    name.name(),
                    FigureName::SCENES.map(|s| s.name()).join(", ")
                ),
            )),
        }
    }

    /// The figure it describes.
    pub fn figure(&self) -> Result<Figure> {
        match self {
            SceneFile::Mechanism(scene) => scene.figure(),
            SceneFile::Diagram(name, options) => name.figure(options),
        }
    }
}
