//! `slider-crank animate NAME --out FILE`: one revolution of a mechanism
//! figure, as a self-playing SVG or an HTML page with a slider.

use super::figure::{FigureFlags, names_help, unread};
use super::output::Stdout;
use clap::Args;
use slider_crank::animate::{AnimateRequest, AnimationFormat, DEFAULT_FRAMES, DEFAULT_PERIOD};
use slider_crank::catalogue::Group;
use slider_crank::render::write_atomic_with;
use slider_crank::{FigureName, Result};
use std::io::{IsTerminal, Write};
use std::path::PathBuf;
use std::time::{Duration, Instant};

/// Animate a mechanism figure through one revolution of the crank.
#[derive(Debug, Args)]
#[command(
    mut_arg("angle", |a| a.help(
        "Crank angle in degrees of the first frame; the others follow at equal steps \
         counter-clockwise round the turn [default: the figure's]"
    )),
    // The options of the diagrams, which are not animated: taken and
    // refused (the mechanism figures use none of them), not listed.
    mut_arg("data", |a| a.hide(true)),
    mut_arg("fit", |a| a.hide(true)),
    mut_arg("bore", |a| a.hide(true)),
    mut_arg("gas_force", |a| a.hide(true)),
    mut_arg("mass", |a| a.hide(true)),
    mut_arg("fluctuation", |a| a.hide(true)),
    mut_arg("rod_mass", |a| a.hide(true)),
    mut_arg("rod_cg", |a| a.hide(true)),
    mut_arg("rod_gyration", |a| a.hide(true)),
    mut_arg("cranks", |a| a.hide(true)),
    mut_arg("planes", |a| a.hide(true)),
    mut_arg("gravity", |a| a.hide(true)),
    mut_arg("friction", |a| a.hide(true))
)]
pub struct AnimateArgs {
    // The help lists the mechanism figures (the diagrams are not animated).
    #[arg(
        value_name = "NAME",
        help = names_help(&[Group::Mechanisms], "The mechanism figure (the diagrams are not animated)")
    )]
    pub name: FigureName,
    #[command(flatten)]
    pub flags: FigureFlags,
    /// Frames per revolution, 2 to 3600 (72: one every 5°), written as
    /// they are drawn; their curves are bounded in all (a frame whose
    /// curves take the curve engine's whole budget allows few frames)
    #[arg(long, value_name = "N", allow_hyphen_values = true, default_value_t = DEFAULT_FRAMES)]
    pub frames: usize,
    /// Seconds per revolution, more than 0 and at most 3600
    #[arg(long, value_name = "S", allow_hyphen_values = true, default_value_t = DEFAULT_PERIOD)]
    pub period: f64,
    /// For a projector or a large screen: the frames without the enlarged
    /// detail of the constructions about the crank (the page, shown the
    /// screen's size, is itself the enlargement), so that the mechanism
    /// fills the width of a landscape screen; the page of an .html file
    /// fills the window on any screen
    #[arg(long)]
    pub projector: bool,
    /// The file to write, in the format its extension names: .svg (plays
    /// by itself in a browser) or .html (a page with a slider for the
    /// crank angle and a play/pause button); both self-contained. `-`
    /// prints the SVG. Written whole or not at all, in a folder that must
    /// exist (only `gallery` makes its folder)
    #[arg(long, value_name = "FILE", allow_hyphen_values = true)]
    pub out: PathBuf,
}

/// The request the flags make ([`AnimateRequest`]): the figure's as
/// `figure` makes it, the frames, the period and the projector's view.
fn request(args: &AnimateArgs) -> Result<AnimateRequest> {
    let mut r = AnimateRequest::default();
    r.figure = unread(&args.flags)?;
    // The request refuses data whatever the file holds: it is not read.
    r.figure.data = args.flags.data.as_ref().map(|_| String::new());
    (r.frames, r.period) = (Some(args.frames), Some(args.period));
    r.projector = Some(args.projector);
    Ok(r)
}

/// Runs the subcommand: the file written, progress on standard error when
/// the frames take more than a moment.
pub fn run(args: &AnimateArgs, out: &mut Stdout) -> Result<()> {
    let to_stdout = args.out.as_os_str() == "-";
    let format = if to_stdout {
        AnimationFormat::Svg
    } else {
        AnimationFormat::from_path(&args.out)?
    };
    let request = request(args)?;
    let name = args.name;
    let mut progress = Progress::new();
    let mut show = |done, total| progress.show(done, total);
    let written = if to_stdout {
        request.write(name, format, &mut |s| out.text(s), &mut show)
    } else {
        write_atomic_with(&args.out, |sink| {
            request.write(name, format, &mut |s| sink(s.as_bytes()), &mut show)
        })
    };
    progress.finish();
    written
}

/// The progress line on standard error, once drawing has taken more than
/// a moment: rewritten in place on a terminal, a line a second otherwise.
struct Progress {
    start: Instant,
    last: Option<Instant>,
    terminal: bool,
}

impl Progress {
    /// How long drawing goes on before progress is shown.
    const MOMENT: Duration = Duration::from_millis(700);

    fn new() -> Self {
        Self {
            start: Instant::now(),
            last: None,
            terminal: std::io::stderr().is_terminal(),
        }
    }

    fn show(&mut self, done: usize, total: usize) {
        let now = Instant::now();
        let every = if self.terminal {
            Duration::from_millis(100)
        } else {
            Duration::from_secs(1)
        };
        let due = self.last.map_or(Self::MOMENT, |_| every);
        if now - self.last.unwrap_or(self.start) < due && done < total {
            return;
        }
        if self.last.is_none() && done == total {
            return; // done within the moment: nothing to show
        }
        self.last = Some(now);
        let mut err = std::io::stderr().lock();
        // A courtesy: a standard error that cannot be written stops nothing.
        let _ = if self.terminal {
            write!(err, "\r\x1b[2Kanimate: frame {done}/{total}").and_then(|()| err.flush())
        } else {
            writeln!(err, "animate: frame {done}/{total}")
        };
    }

    fn finish(&mut self) {
        if self.terminal && self.last.is_some() {
            let _ = writeln!(std::io::stderr());
        }
    }
}
