//! `slider-crank figure NAME`: one of the seeds' figures as SVG or PNG.

use super::args::SpeedArgs;
use clap::Args;
use slider_crank::render::{to_png, to_svg, write_atomic};
use slider_crank::{Angle, Error, Figure, FigureName, Layer, Result, SliderCrank, Style};
use std::path::PathBuf;

/// Draw a figure of the seeds.
#[derive(Debug, Args)]
pub struct FigureArgs {
    /// fig-62-displacement, fig-63-velocity, fig-65-klein, fig-66-kisch,
    /// fig-67-example, ng-fig-1-torque or ng-fig-a1-velocity
    #[arg(value_name = "NAME")]
    pub name: String,
    /// Crank radius r [default: the figure's, 0.5 ft or Ng's 25 mm]
    #[arg(long, value_name = "R")]
    pub crank: Option<f64>,
    /// Rod length l [default: the figure's, 3 ft or Ng's 72 mm]
    #[arg(long, value_name = "L")]
    pub rod: Option<f64>,
    /// Offset e of the line of stroke [default: 0]
    #[arg(long, value_name = "E", allow_hyphen_values = true)]
    pub offset: Option<f64>,
    /// Crank angle in degrees [default: the figure's]
    #[arg(long, value_name = "DEG", allow_hyphen_values = true)]
    pub angle: Option<f64>,
    #[command(flatten)]
    pub speed: SpeedArgs,
    /// Layers to draw, comma-separated: mechanism, dimensions, centrodes,
    /// coupler, virtual-centres, velocity, klein, kisch, torque, scales
    /// [default: the figure's]
    #[arg(long, value_name = "LIST")]
    pub layers: Option<String>,
    /// textbook (black ink) or handout (colour) [default: textbook]
    #[arg(long, value_name = "STYLE")]
    pub style: Option<String>,
    /// Write to FILE (PNG when it ends in .png, SVG otherwise) instead of
    /// printing SVG
    #[arg(long, value_name = "FILE")]
    pub out: Option<PathBuf>,
}

/// Writes the figure to `out` (PNG for `.png`) or returns its SVG text.
pub fn emit(figure: &Figure, out: Option<&PathBuf>) -> Result<String> {
    let svg = to_svg(figure);
    match out {
        None => Ok(svg),
        Some(path) => {
            let png = path
                .extension()
                .is_some_and(|e| e.eq_ignore_ascii_case("png"));
            let bytes = if png {
                to_png(&svg, 2.0)?
            } else {
                svg.into_bytes()
            };
            write_atomic(path, &bytes)?;
            Ok(String::new())
        }
    }
}

/// Runs the subcommand: the SVG text, or nothing when written to a file.
pub fn run(args: &FigureArgs) -> Result<String> {
    let mut scene = FigureName::from_name(&args.name)?.scene();
    if args.crank.is_some() || args.rod.is_some() || args.offset.is_some() {
        let m = scene.mechanism();
        let mechanism = SliderCrank::new(
            args.crank.unwrap_or(m.crank()),
            args.rod.unwrap_or(m.rod()),
            args.offset.unwrap_or(m.offset()),
        )?;
        scene = slider_crank::Scene::new(mechanism, scene.angles()[0])
            .named(scene.name())
            .with_layers(scene.layers().to_vec())
            .with_page(*scene.page())
            .with_style(scene.style())
            .with_notation(scene.notation())
            .mirrored(scene.is_mirrored())
            .with_unit(scene.unit())
            .with_force_unit(scene.force_unit())
            .with_torque(scene.torque())?
            .with_omega(scene.omega())?;
    }
    if let Some(a) = args.angle {
        scene = scene.with_angles(vec![Angle::from_degrees(a)?])?;
    }
    if args.speed.rpm.is_some() || args.speed.omega.is_some() {
        scene = scene.with_omega(args.speed.omega()?)?;
    }
    if let Some(list) = &args.layers {
        let layers = Layer::parse_list(list)?;
        if layers.is_empty() {
            return Err(Error::Parse("--layers names no layer".into()));
        }
        scene = scene.with_layers(layers);
    }
    if let Some(s) = &args.style {
        scene = scene.with_style(Style::from_name(s)?);
    }
    emit(&scene.figure(), args.out.as_ref())
}
