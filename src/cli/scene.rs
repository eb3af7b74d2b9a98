//! `slider-crank scene FILE.toml`: a figure described by a scene file.

use super::figure::{Encoding, destination, emit, not_an_input};
use super::output::Stdout;
use clap::Args;
use slider_crank::figure::Font;
use slider_crank::files::{MAX_SCENE_BYTES, read_text};
use slider_crank::{Error, FigureName, Input, Result, SceneFile, Unit};
use std::path::PathBuf;

/// Draw the figure a scene file describes: a mechanism figure, or one of
/// the named diagrams with the file's changes.
#[derive(Debug, Args)]
pub struct SceneArgs {
    /// The scene file (TOML; docs/scene-format.md, examples/*.toml)
    #[arg(value_name = "FILE.toml", required_unless_present = "print_default")]
    pub file: Option<PathBuf>,
    /// Print the scene file of the named figure instead of drawing one: every
    /// key it uses at the figure's own value, with comments, a starting
    /// point to edit (`scene` on it draws that figure). NAME is any name
    /// `figure` takes
    #[arg(
        long,
        value_name = "NAME",
        conflicts_with_all = ["file", "font", "length_unit", "force_unit", "out"]
    )]
    pub print_default: Option<FigureName>,
    /// Face of the text, over the file's `font` key: new-computer-modern
    /// (the look of LaTeX books) or libertinus-serif [default: the file's,
    /// else new-computer-modern]
    #[arg(long, value_name = "NAME")]
    pub font: Option<Font>,
    /// Name of the length unit, over the file's `[units] length` (a name
    /// only, no number is converted) [default: the file's, else its
    /// figure's, else ft]
    #[arg(long = "unit", value_name = "UNIT")]
    pub length_unit: Option<Unit>,
    /// Name of the force unit, over the file's `[units] force` [default:
    /// the one that goes with --unit (N for mm, cm, m; lbf for in, ft),
    /// else the file's, else its figure's, else lbf]
    #[arg(long = "force-unit", value_name = "FORCE")]
    pub force_unit: Option<Unit>,
    /// Write to FILE instead of printing SVG, in the format its extension
    /// names: .svg, .png (2 pixels per page unit), .pdf (vector, fonts
    /// embedded) or .tex (a TikZ picture whose letters LaTeX sets in the
    /// book's fonts; docs/tikz.md); SVG for a name without an extension,
    /// any other is refused; `-` prints SVG. A device or FIFO is written in place; a
    /// symbolic link is kept and its target replaced. The folder must
    /// exist (only `gallery` makes its folder)
    #[arg(long, value_name = "FILE", allow_hyphen_values = true)]
    pub out: Option<PathBuf>,
    /// With --out FILE.tex: a LaTeX document of its own around the TikZ
    /// picture, which pdflatex or lualatex compiles as it is
    #[arg(long)]
    pub tikz_standalone: bool,
}

/// Runs the subcommand.
pub fn run(args: &SceneArgs, out: &mut Stdout) -> Result<()> {
    let to = destination(args.out.as_ref())?;
    let encoding = Encoding {
        tikz_standalone: args.tikz_standalone,
        ..Encoding::default()
    };
    encoding.check(to)?;
    if let Some(name) = &args.print_default {
        return out.text(&name.scene_toml());
    }
    // cannot fail: clap requires FILE unless --print-default, which returned above.
    #[allow(clippy::expect_used)]
    let path = args
        .file
        .as_ref()
        .expect("clap requires FILE without --print-default");
    not_an_input(to, path, "the scene file")?;
    let text = read_text(path, MAX_SCENE_BYTES, Input::Scene)?;
    let file = SceneFile::from_toml(&text)
        .map_err(|e| Error::invalid(Input::Scene, format!("{}: {e}", path.display())))?;
    let font = args.font;
    let figure = match file {
        SceneFile::Mechanism(mut scene) => {
            if let Some(f) = font {
                scene = scene.with_font(f);
            }
            let units = scene
                .units()
                .clone()
                .asked(args.length_unit.as_ref(), args.force_unit.as_ref());
            scene = scene.with_units(units);
            scene.figure()?
        }
        SceneFile::Diagram(name, mut options) => {
            options.font = font.or(options.font);
            options.length_unit = args.length_unit.clone().or(options.length_unit);
            options.force_unit = args
                .force_unit
                .clone()
                .or_else(|| args.length_unit.as_ref().and_then(Unit::usual_force))
                .or(options.force_unit);
            name.figure(&options)?
        }
    };
    emit(&figure, to, encoding, out)
}
