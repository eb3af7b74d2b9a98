//! `slider-crank figure NAME`: one of the seeds' figures as SVG or PNG.

use super::args::{SpeedArgs, UnitArgs};
use super::output::Stdout;
use clap::Args;
use slider_crank::catalogue::{FigureOptions, FigureRequest, Fit, Group};
use slider_crank::figure::{Font, PageLength, Title};
use slider_crank::files::{MAX_DATA_BYTES, read_text};
use slider_crank::render::{
    FileFormat, TikzOptions, same_file, to_svg, to_svg_with_fonts, to_tikz, write_atomic,
};
use slider_crank::{Error, Figure, FigureName, Input, Layer, Notation, Result, Style};
use std::path::{Path, PathBuf};

/// The help of a figure's NAME: `lead`, then the names of the figures of
/// each of `groups` after its heading, in the catalogue's order.
pub(super) fn names_help(groups: &[Group], lead: &str) -> String {
    let mut help = lead.to_string();
    for &group in groups {
        let names: Vec<&str> = FigureName::ALL
            .iter()
            .filter(|f| f.group() == group)
            .map(FigureName::name)
            .collect();
        let heading = group.heading();
        help.push_str(&format!(". {heading}: {}", names.join(", ")));
    }
    help
}

/// Draw a named figure: a mechanism figure of the seeds or a diagram.
#[derive(Debug, Args)]
pub struct FigureArgs {
    // The help lists every named figure by its group (`names_help`).
    #[arg(value_name = "NAME", help = names_help(&Group::ALL, "The figure"))]
    pub name: FigureName,
    #[command(flatten)]
    pub flags: FigureFlags,
    /// Write to FILE instead of printing SVG, in the format its extension
    /// names: .svg, .png (2 pixels per page unit), .pdf (vector, fonts
    /// embedded) or .tex (a TikZ picture whose letters LaTeX sets in the
    /// book's fonts; docs/tikz.md); SVG for a name without an extension,
    /// any other is refused; `-` prints SVG. A device or FIFO is written in place; a
    /// symbolic link is kept and its target replaced. The folder must
    /// exist (only `gallery` makes its folder)
    #[arg(long, value_name = "FILE", allow_hyphen_values = true)]
    pub out: Option<PathBuf>,
    /// Carry the face in the SVG: its regular and italic faces cut to the
    /// characters the figure draws, so that a browser shows the figure in
    /// the face it was measured in without it installed (adds about 20 to
    /// 60 kB; PNG and PDF always carry their faces)
    #[arg(long)]
    pub embed_fonts: bool,
    /// With --out FILE.tex: a LaTeX document of its own around the TikZ
    /// picture (an article whose page is the figure's), which pdflatex or
    /// lualatex compiles as it is; without it, the tikzpicture alone, for
    /// \input in a book that loads TikZ
    #[arg(long)]
    pub tikz_standalone: bool,
}

/// The changes to a named figure that `figure` and `animate` take: the
/// mechanism, pose, speed, layers, look, units, page and title.
#[derive(Debug, Args)]
pub struct FigureFlags {
    /// Crank radius r, in the length unit (--unit) [default: the figure's
    /// own, 0.5 ft for the §35 engine, 25 mm for Ng's rig]
    #[arg(long, value_name = "R", allow_hyphen_values = true)]
    pub crank: Option<f64>,
    /// Rod length l, in the unit of r [default: the figure's own, 3 ft for
    /// the §35 engine, 72 mm for Ng's rig]
    #[arg(long, value_name = "L", allow_hyphen_values = true)]
    pub rod: Option<f64>,
    /// Offset e of the line of stroke, in the unit of r [default: 0]
    #[arg(long, value_name = "E", allow_hyphen_values = true)]
    pub offset: Option<f64>,
    /// Crank angle in degrees of the pose drawn [default: the figure's];
    /// for ng-fig-2-incline, the tilt of the plane
    #[arg(long, value_name = "DEG", allow_hyphen_values = true)]
    pub angle: Option<f64>,
    #[command(flatten)]
    pub speed: SpeedArgs,
    /// Layers of a mechanism figure, comma-separated: mechanism, angles,
    /// dimensions, centrodes, coupler, polar (Fig. 64's polar diagram as
    /// far as the crank has turned), virtual-centres, velocity, klein,
    /// kisch, ritterhaus, bennett, torque, motion, polygons (the velocity
    /// and acceleration polygons), scales [default: the figure's]
    #[arg(long, value_name = "LIST")]
    pub layers: Option<String>,
    /// Drawing style: textbook (black ink) or handout (colour) [default:
    /// textbook]
    #[arg(long, value_name = "STYLE")]
    pub style: Option<Style>,
    /// Face of the text, bundled (no system fonts needed):
    /// new-computer-modern (the look of LaTeX books) or libertinus-serif
    /// [default: new-computer-modern]
    #[arg(long, value_name = "NAME")]
    pub font: Option<Font>,
    /// Measured data, CSV with a header line: ng-fig-8-forces (columns
    /// angle, force; default examples/ng-experiment.csv, Ng's F'),
    /// turning-moment, flywheel and crank-pin-loads (an indicator diagram: fraction,
    /// expansion, compression, gauge pressures in force/length², a unit
    /// declared in a header such as "expansion (N/mm²)" checked against
    /// the units; give --bore; default examples/indicator.csv, lbf/ft²),
    /// ng-fig-7-calibration (force, strain; default Ng's Table 1),
    /// curve-benchmark (default docs/curve-benchmarks.csv)
    #[arg(long, value_name = "FILE")]
    pub data: Option<PathBuf>,
    /// Calibration line of ng-fig-7-calibration: origin (Ng's trendline
    /// through zero), intercept (ordinary least squares) or both
    /// [default: both]
    #[arg(long, value_name = "FIT")]
    pub fit: Option<Fit>,
    /// Reciprocating mass m of the engine dynamics figures
    /// (turning-moment, inertia-force, primary-secondary,
    /// direct-reverse-cranks, flywheel, crank-pin-loads), in the unit that makes mass × length/s² the
    /// force unit (slug with ft and lbf, kg with m and N) [default: 10]
    #[arg(long, value_name = "M", allow_hyphen_values = true)]
    pub mass: Option<f64>,
    /// Coefficient of fluctuation of speed C_s = (ω_max − ω_min)/ω of the
    /// flywheel figure, which draws the flywheel I = ΔE/(ω² C_s) it needs
    /// [default: 0.02]
    #[arg(long, value_name = "CS", allow_hyphen_values = true)]
    pub fluctuation: Option<f64>,
    /// The bore D of the cylinder of turning-moment, flywheel and crank-pin-loads, on which
    /// the indicator diagram of --data acts, in the length unit [default:
    /// the example's 10 in, with ft and lbf only]
    #[arg(long, value_name = "D", allow_hyphen_values = true)]
    pub bore: Option<f64>,
    /// A constant gas force on the piston of turning-moment, flywheel and crank-pin-loads,
    /// positive towards the crank centre, in the force unit, in place of
    /// an indicator diagram
    #[arg(long, value_name = "F", allow_hyphen_values = true)]
    pub gas_force: Option<f64>,
    #[command(flatten)]
    pub units: UnitArgs,
    /// Letters of a mechanism figure: textbook (C, B, A, D, E) or ng (O,
    /// C, P, I, M) [default: the figure's]
    #[arg(long, value_name = "LETTERS")]
    pub notation: Option<Notation>,
    /// Draw the mechanism mirrored, the cylinder on the left, as the
    /// textbook's figures are by default (mechanism figures,
    /// fig-61-centrodes, fig-64-velocity-diagrams, coupler-curves)
    #[arg(long, conflicts_with = "no_mirror")]
    pub mirror: bool,
    /// Draw the mechanism unmirrored, the cylinder on the right, as Ng's
    /// figures are by default
    #[arg(long)]
    pub no_mirror: bool,
    /// Page width: page units (px, 96 to the inch) like 800, or a size in
    /// mm, cm, in or pt like 120mm, 12cm or 4.5in, after which the SVG gives its width
    /// and height in that unit (its viewBox stays in page units) for a book
    /// to place it at that size [default: the figure's own, narrowed to a
    /// mechanism drawing that takes less than 85 % of it, to no less than
    /// 420]
    #[arg(long, value_name = "LENGTH", allow_hyphen_values = true)]
    pub width: Option<PageLength>,
    /// Page height, as --width; a mechanism figure ends within it (it may
    /// end shorter) and is refused, naming the height it needs, where its
    /// enlarged detail and notes do not fit [default: the figure's own,
    /// which grows for a detail]
    #[arg(long, value_name = "LENGTH", allow_hyphen_values = true)]
    pub height: Option<PageLength>,
    /// A title, set centred below the figure (the page grows by a line)
    /// and written as the SVG's <title>; *A* sets A in italic, V_p a
    /// subscript
    #[arg(long, value_name = "TEXT", allow_hyphen_values = true)]
    pub title: Option<Title>,
    /// The point Q of a mechanism figure's rod, T along it from A (0) to
    /// B (1) and, after a comma, H rod lengths off its line (to the left
    /// of A to B where positive, |H| at most 100): its path in the
    /// coupler layer, its images in the polygons layer; off the line the
    /// rod is drawn as the plate ABQ [default: 0.5, the rod's middle]
    #[arg(long, value_name = "T[,H]", allow_hyphen_values = true)]
    pub coupler: Option<CouplerArg>,
    /// The connecting rod's mass of crank-pin-loads, in the mass unit; 0
    /// for a massless rod [default: 0.6 times the reciprocating mass]
    #[arg(long, value_name = "MR", allow_hyphen_values = true)]
    pub rod_mass: Option<f64>,
    /// The distance of the rod's centre of mass from the crank pin, of
    /// crank-pin-loads, 0 to the rod's length [default: l/3]
    #[arg(long, value_name = "BG", allow_hyphen_values = true)]
    pub rod_cg: Option<f64>,
    /// The rod's radius of gyration about its centre of mass, of
    /// crank-pin-loads [default: 0.3 l]
    #[arg(long, value_name = "K", allow_hyphen_values = true)]
    pub rod_gyration: Option<f64>,
    /// The cranks of inline-balance, each cylinder's in degrees ahead of
    /// the first's, comma-separated [default: 0,120,240]
    #[arg(long, value_name = "LIST", allow_hyphen_values = true)]
    pub cranks: Option<String>,
    /// The planes of inline-balance's cylinders, each line of stroke's
    /// distance from the reference plane in pitches, one for each crank,
    /// comma-separated [default: a pitch of 1 about the engine's middle]
    #[arg(long, value_name = "LIST", allow_hyphen_values = true)]
    pub planes: Option<String>,
    /// A vertical engine of turning-moment, flywheel and crank-pin-loads:
    /// gravity along the line of stroke towards-crank (the cylinder above
    /// the crank) or away-from-crank (below it), standard gravity in the
    /// length unit [default: none]
    #[arg(long, value_name = "DIRECTION")]
    pub gravity: Option<slider_crank::dynamics::Gravity>,
    /// The slider's coefficient of friction μ in its guides, of
    /// turning-moment, flywheel and crank-pin-loads: μ|N| against the
    /// slider's motion (refused where it would self-lock, μ |tan φ| ≥ 1)
    /// [default: 0]
    #[arg(long, value_name = "MU", allow_hyphen_values = true)]
    pub friction: Option<f64>,
}

/// `--coupler T[,H]`: a point along the rod and off its line.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CouplerArg(pub f64, pub f64);

impl std::str::FromStr for CouplerArg {
    type Err = String;

    /// `T` (H = 0) or `T,H`, each a number.
    fn from_str(text: &str) -> std::result::Result<Self, String> {
        let number = |s: &str| {
            s.trim()
                .parse::<f64>()
                .map_err(|_| format!("'{text}' is not T or T,H (two numbers)"))
        };
        match text.split_once(',') {
            Some((t, h)) => Ok(CouplerArg(number(t)?, number(h)?)),
            None => Ok(CouplerArg(number(text)?, 0.0)),
        }
    }
}

/// Where `--out` sends a figure: a file and the format its extension
/// names, or standard output (`None`: no `--out`, or `-`). Called before
/// any work, so that an unknown extension is refused at once.
pub fn destination(path: Option<&PathBuf>) -> Result<Option<(&Path, FileFormat)>> {
    match path {
        Some(path) if path.as_os_str() != "-" => Ok(Some((path, FileFormat::from_path(path)?))),
        _ => Ok(None),
    }
}

/// Refuses an output file that is one of the inputs (`what`: "the scene
/// file"), the same file through any link: the figure drawn from it would
/// replace it. Standard output, a file not there yet and a device (which
/// is written in place, not replaced) are never refused.
pub fn not_an_input(to: Option<(&Path, FileFormat)>, input: &Path, what: &str) -> Result<()> {
    let regular = |p: &Path| std::fs::metadata(p).is_ok_and(|m| m.is_file());
    match to {
        Some((path, _)) if regular(path) && same_file(path, input) => Err(Error::io_about(
            format!(
                "cannot write {}: it is {what} {}, read to draw the figure (give another --out)",
                path.display(),
                input.display()
            ),
            path,
        )),
        _ => Ok(()),
    }
}

/// How `emit` writes a figure beyond its format: the SVG with its faces
/// ([`to_svg_with_fonts`]), the TikZ as a document of its own.
#[derive(Debug, Clone, Copy, Default)]
pub struct Encoding {
    /// The SVG carries its faces.
    pub embed_fonts: bool,
    /// The TikZ is a standalone document.
    pub tikz_standalone: bool,
}

impl Encoding {
    /// Refuses an option that the format of `to` does not take: the
    /// faces are for SVG, the standalone document for TikZ.
    pub fn check(&self, to: Option<(&Path, FileFormat)>) -> Result<()> {
        let format = to.map_or(FileFormat::Svg, |(_, f)| f);
        let file = || match to {
            Some((path, f)) => {
                let a = if f == FileFormat::Svg { "an" } else { "a" };
                format!("{} is {a} {} file", path.display(), f.label())
            }
            None => "the figure goes to standard output as SVG".into(),
        };
        if self.embed_fonts && format != FileFormat::Svg {
            let why = if format == FileFormat::Tikz {
                "whose letters LaTeX sets in the book's fonts"
            } else {
                "which carries its faces already"
            };
            return Err(Error::invalid(
                Input::Options,
                format!(
                    "--embed-fonts is for SVG output: {}, {why} (leave the option out)",
                    file()
                ),
            ));
        }
        if self.tikz_standalone && format != FileFormat::Tikz {
            return Err(Error::invalid(
                Input::Options,
                format!(
                    "--tikz-standalone is for TikZ output: {} (give --out FILE.tex, or leave the option out)",
                    file()
                ),
            ));
        }
        Ok(())
    }
}

/// Writes the figure to the file in its format (whole or not at all), or
/// its SVG text to standard output, as `encoding` asks.
pub fn emit(
    figure: &Figure,
    to: Option<(&Path, FileFormat)>,
    encoding: Encoding,
    out: &mut Stdout,
) -> Result<()> {
    if let Some((path, FileFormat::Tikz)) = to {
        let options = TikzOptions::default().standalone(encoding.tikz_standalone);
        return write_atomic(path, to_tikz(figure, &options).as_bytes());
    }
    let svg = if encoding.embed_fonts {
        to_svg_with_fonts(figure)
    } else {
        to_svg(figure)
    };
    match to {
        Some((path, format)) => write_atomic(path, &format.encode(figure, &svg)?),
        None => out.text(&svg),
    }
}

/// The options the flags ask for: the library's request filled from
/// them ([`request_of`]), validated there.
pub fn options(args: &FigureFlags, name: FigureName) -> Result<FigureOptions> {
    request_of(args)?.options(name)
}

/// The library's request the flags fill (the data file read, the lists
/// and the layers parsed).
pub fn request_of(args: &FigureFlags) -> Result<FigureRequest> {
    let mut request = unread(args)?;
    request.data = match &args.data {
        Some(path) => Some(read_text(path, MAX_DATA_BYTES, Input::Data)?),
        None => None,
    };
    Ok(request)
}

/// [`request_of`] without the data file: `data` not given.
pub fn unread(args: &FigureFlags) -> Result<FigureRequest> {
    let layers = args.layers.as_deref().map(Layer::parse_list).transpose()?;
    let mut request = FigureRequest::default();
    request.crank = args.crank;
    request.rod = args.rod;
    request.offset = args.offset;
    request.angle = args.angle;
    request.rpm = args.speed.rpm;
    request.omega = args.speed.omega;
    request.layers = layers;
    request.style = args.style;
    request.font = args.font;
    request.fit = args.fit;
    request.unit = args.units.length.clone();
    request.force_unit = args.units.force.clone();
    request.notation = args.notation;
    request.mass = args.mass;
    request.fluctuation = args.fluctuation;
    request.bore = args.bore;
    request.gas_force = args.gas_force;
    request.rod_mass = args.rod_mass;
    request.rod_cg = args.rod_cg;
    request.rod_gyration = args.rod_gyration;
    request.gravity = args.gravity;
    request.friction = args.friction;
    request.cranks = (args.cranks.as_deref())
        .map(|s| super::args::parse_list(s, "crank angle", false))
        .transpose()?;
    request.planes = (args.planes.as_deref())
        .map(|s| super::args::parse_list(s, "plane", false))
        .transpose()?;
    request.mirror = match (args.mirror, args.no_mirror) {
        (true, _) => Some(true),
        (_, true) => Some(false),
        _ => None,
    };
    request.width = args.width;
    request.height = args.height;
    request.title = args.title.clone();
    request.coupler = args.coupler.map(|c| (c.0, c.1));
    Ok(request)
}

/// Runs the subcommand: SVG on standard output, or the file written.
pub fn run(args: &FigureArgs, out: &mut Stdout) -> Result<()> {
    let name = args.name;
    let to = destination(args.out.as_ref())?;
    let encoding = Encoding {
        embed_fonts: args.embed_fonts,
        tikz_standalone: args.tikz_standalone,
    };
    encoding.check(to)?;
    if let Some(data) = &args.flags.data {
        not_an_input(to, data, "the data file")?;
    }
    let options = options(&args.flags, name)?;
    let figure = name.figure(&options).map_err(|e| match &args.flags.data {
        Some(path) => e.in_file(Input::Data, path),
        None => e,
    })?;
    emit(&figure, to, encoding, out)
}
