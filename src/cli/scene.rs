//! `slider-crank scene FILE.toml`: a figure described by a scene file.

use super::figure::{destination, emit};
use super::output::Stdout;
use clap::Args;
use slider_crank::figure::Font;
use slider_crank::input::{MAX_SCENE_BYTES, read_text};
use slider_crank::{Error, Result, Scene};
use std::path::PathBuf;

/// Draw the figure a scene file describes.
#[derive(Debug, Args)]
pub struct SceneArgs {
    /// The scene file (TOML; see examples/*.toml)
    #[arg(value_name = "FILE.toml")]
    pub file: PathBuf,
    /// Face of the text, over the file's `font` key: new-computer-modern
    /// (the look of LaTeX books) or libertinus-serif [default: the file's,
    /// else new-computer-modern]
    #[arg(long, value_name = "NAME")]
    pub font: Option<String>,
    /// Write to FILE instead of printing SVG, in the format its extension
    /// names: .svg, .png (2 pixels per page unit) or .pdf (vector, fonts
    /// embedded); SVG for a name without an extension, any other is
    /// refused; `-` prints SVG. A device or FIFO is written in place; a
    /// symbolic link is kept and its target replaced
    #[arg(long, value_name = "FILE", allow_hyphen_values = true)]
    pub out: Option<PathBuf>,
}

/// Runs the subcommand.
pub fn run(args: &SceneArgs, out: &mut Stdout) -> Result<()> {
    let to = destination(args.out.as_ref())?;
    let text = read_text(&args.file, MAX_SCENE_BYTES, "scene file")?;
    let mut scene = Scene::from_toml(&text)
        .map_err(|e| Error::Parse(format!("{}: {e}", args.file.display())))?;
    if let Some(name) = &args.font {
        scene = scene.with_font(name.parse::<Font>()?);
    }
    emit(&scene.figure(), to, out)
}
