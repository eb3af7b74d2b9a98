//! The `slider-crank` command line.
// As in the library: no `unwrap`, `expect`, index or slice without a
// proof it cannot fail (`tests/library/panic_free.rs`).
#![deny(clippy::unwrap_used, clippy::expect_used, clippy::indexing_slicing)]

mod cli;

use clap::{Parser, Subcommand};
use std::process::ExitCode;

/// Exact kinematics, statics and the classical graphical constructions of
/// the slider-crank mechanism, drawn as textbook figures (SVG, PNG or PDF).
///
/// Frame: crank centre C at the origin, line of stroke y = e (the offset),
/// slider A on the +x side; crank angle θ in degrees, counter-clockwise
/// from +x (0° is the outer dead centre); a positive speed turns the crank
/// counter-clockwise. Letters: C crank centre, B crank pin, A cross-head,
/// D instantaneous centre of the rod, E where the rod produced meets the
/// perpendicular to the stroke through C.
///
/// Units: lengths in any one unit (ft, mm, m) and forces in any one unit,
/// named by --unit and --force-unit wherever they are printed or drawn
/// (names only: no number is converted); crank speed in rpm or rad/s;
/// velocities come out in that length unit per second, accelerations per
/// second squared, torques in force·length, the rod's rates in rad/s and
/// rad/s². The defaults are the engine of the textbook's §35 (r = 0.5 ft,
/// l = 3 ft, 250 rpm) and the seeds' own units (ft and lbf for the
/// textbook's figures, mm and N for Ng's).
///
/// Errors go to standard error as one line, with exit code 2 and nothing on
/// standard output.
#[derive(Debug, Parser)]
#[command(name = "slider-crank", version)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Positions, velocities and accelerations at an angle: exact values and
    /// those read off the constructions (CE, CG, BD, FG); statics with --torque
    ///
    /// Lengths are in one unit, named by --unit (ft by default, the §35
    /// engine's); velocities in that unit per second, accelerations per
    /// second squared, the rod's angular velocity and acceleration in rad/s
    /// and rad/s² (signed: d x_A/dt, d² x_A/dt², dφ/dt, d²φ/dt² with sin φ
    /// = (r sin θ − e)/l). The JSON names them under `units`.
    Analyze(cli::analyze::AnalyzeArgs),
    /// Print a table of the seeds or a sweep: obliquity, acceleration-factor,
    /// kinematics, forces
    Table(Box<cli::table::TableArgs>),
    /// Sweep the whole turn and compare every construction with the
    /// analytic core; exits 1 if any difference exceeds the tolerance
    ///
    /// Differences are scaled (lengths and the slider's rates by r, the
    /// rod's rates per unit ω; docs/design.md §6), so no speed is needed.
    /// Exit code 0: every quantity within the tolerance; 1: some exceed it;
    /// 2: bad input.
    #[command(
        mut_arg("assembly", |a| a.hide(true)),
        mut_arg("inversion", |a| a.help(
            "Check the polygons with the Coriolis component of inversion 2 (the rotating block, Whitworth's quick return) or 3 (the crank and slotted lever) against the chain's exact link motion, instead of the engine's constructions"
        ))
    )]
    Check(cli::check::CheckArgs),
    /// Draw a named figure or diagram as SVG (or PNG or PDF with --out
    /// FILE.png, FILE.pdf)
    Figure(cli::figure::FigureArgs),
    /// Draw the figure a TOML scene file describes (a mechanism figure, or
    /// a named diagram with the file's changes)
    Scene(cli::scene::SceneArgs),
    /// Write every named figure as SVG, PNG and PDF, every table, and an
    /// index.html with a caption naming the seed and figure each reproduces
    ///
    /// The figures are drawn at the seeds' own parameters, as `figure NAME`
    /// draws them; the tables are those `table NAME` prints. A progress line
    /// goes to standard error. Each file is written whole or not at all.
    /// With --check nothing is written: exit code 0 when every file in the
    /// directory is what this build makes, 1 when some differ or are
    /// missing (each printed), 2 for an error.
    Gallery(cli::gallery::GalleryArgs),
    /// Write a printable teaching handout (HTML) that works one engine
    /// through §35–37 and Ng step by step; or an exercise sheet and its
    /// answer key (--exercise); or sheets for a whole class (--class)
    ///
    /// The page is one self-contained file: the figures inlined as SVG, no
    /// script, nothing fetched from the network. Every value read off a
    /// construction is set beside the exact value (the numbers `analyze`
    /// prints, also in each value's data-value attribute). Print rules for
    /// A4 or Letter keep every figure and table on one page. Each file is
    /// written whole or not at all; a failed run leaves none.
    #[command(mut_arg("length", |a| a.visible_alias("units")))]
    Handout(cli::handout::HandoutArgs),
    /// Animate a mechanism figure through one revolution of the crank: a
    /// self-playing SVG, or an HTML page with a slider and a play button
    ///
    /// Every frame is the figure `figure NAME --angle θ` draws, in one
    /// view held over the whole turn, so that only the mechanism and its
    /// constructions move. Progress goes to standard error when drawing
    /// takes more than a moment; the file is written whole or not at all.
    Animate(cli::animate::AnimateArgs),
    /// Serve the explorer on the loopback address: a page where a figure
    /// follows the crank pin as it is dragged, with the engine, layers and
    /// look as controls and the exact and graphical values beside it
    ///
    /// Listens on 127.0.0.1 and ::1 only, prints the address to open and
    /// serves until Ctrl-C. Each figure request is read as the flags of
    /// `figure` and checked as they are; nothing is read from or written
    /// to the file system (downloads are saved by the browser).
    #[cfg(feature = "explore")]
    Explore(cli::explore::ExploreArgs),
}

/// Exit code of a refused run (bad input, unwritable output).
const REFUSED: u8 = 2;

fn main() -> ExitCode {
    // Checked before anything opens a file, which could otherwise take the
    // number of a closed standard output.
    let mut out = match cli::output::Stdout::open() {
        Ok(out) => out,
        Err(e) => {
            cli::output::say(&format!(
                "slider-crank: error: cannot write to standard output: {e}"
            ));
            return ExitCode::from(REFUSED);
        }
    };
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => return parse_error(e),
    };
    stop_cleanly_on_signals();
    let result = match &cli.command {
        Command::Analyze(args) => cli::analyze::run(args, &mut out).map(|()| true),
        Command::Table(args) => cli::table::run(args, &mut out).map(|()| true),
        Command::Check(args) => cli::check::run(args, &mut out),
        Command::Figure(args) => cli::figure::run(args, &mut out).map(|()| true),
        Command::Scene(args) => cli::scene::run(args, &mut out).map(|()| true),
        Command::Gallery(args) => cli::gallery::run(args, &mut out),
        Command::Handout(args) => cli::handout::run(args, &mut out).map(|()| true),
        Command::Animate(args) => cli::animate::run(args, &mut out).map(|()| true),
        #[cfg(feature = "explore")]
        Command::Explore(args) => cli::explore::run(args, &mut out).map(|()| true),
    }
    .and_then(|ok| out.finish().map(|()| ok));
    match result {
        Ok(true) => ExitCode::SUCCESS,
        Ok(false) => ExitCode::from(1),
        // The reader went away (`| head`): nothing to say, but not a success.
        Err(_) if out.broken_pipe() => ExitCode::from(REFUSED),
        Err(e) => {
            cli::output::say(&format!("slider-crank: error: {}", cli::flags::said(e)));
            ExitCode::from(REFUSED)
        }
    }
}

/// On Ctrl-C (SIGINT), SIGTERM or SIGHUP: the temporary files of the
/// writes in progress removed (after a gallery's renames, if they have
/// begun), then the program ends as the signal would have ended it. A
/// program that cannot watch for signals runs unwatched (they end it as
/// before, leaving its temporary files).
#[cfg(unix)]
fn stop_cleanly_on_signals() {
    use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
    let Ok(mut signals) = signal_hook::iterator::Signals::new([SIGINT, SIGTERM, SIGHUP]) else {
        return;
    };
    let watch = move || {
        if let Some(signal) = signals.forever().next() {
            slider_crank::render::remove_pending();
            let _ = signal_hook::low_level::emulate_default_handler(signal);
            // A signal whose default is not to end the program (none of
            // these three): end it as the shell would report the signal.
            std::process::exit(128 + signal);
        }
    };
    let _ = std::thread::Builder::new()
        .name("signals".into())
        .spawn(watch);
}

#[cfg(not(unix))]
fn stop_cleanly_on_signals() {}

/// Help and version print with exit 0; anything else (no subcommand, an
/// unknown flag) is one line on standard error and exit 2.
fn parse_error(e: clap::Error) -> ExitCode {
    use clap::error::{ContextKind, ContextValue, ErrorKind};
    if matches!(e.kind(), ErrorKind::DisplayHelp | ErrorKind::DisplayVersion) {
        // Flushed here, where an error can still be told: a full device
        // or a reader gone is not a success.
        use std::io::Write;
        return match e.print().and_then(|()| std::io::stdout().flush()) {
            Ok(()) => ExitCode::SUCCESS,
            Err(err) if err.kind() == std::io::ErrorKind::BrokenPipe => ExitCode::from(REFUSED),
            Err(err) => {
                cli::output::say(&format!(
                    "slider-crank: error: cannot write to standard output: {err}"
                ));
                ExitCode::from(REFUSED)
            }
        };
    }
    if e.kind() == ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand {
        cli::output::say(
            "slider-crank: a subcommand is required: gallery, handout, analyze, table, check, figure, scene, animate or explore (see --help)",
        );
        return ExitCode::from(REFUSED);
    }
    // One line: clap's first paragraph names the problem (and, for a
    // missing argument, lists it on the lines after the first), then its
    // tips (the subcommand or flag nearest a misspelt one); the value it
    // quotes is shown escaped and cut (a carriage return, a bidi override
    // or 100 KB are not echoed as given).
    let mut text = e.render().to_string();
    for kind in [ContextKind::InvalidValue, ContextKind::InvalidArg] {
        if let Some(ContextValue::String(raw)) = e.get(kind) {
            let shown = format!("'{}'", slider_crank::Error::show(raw));
            text = text.replace(&format!("'{raw}'"), &shown);
        }
    }
    let first: Vec<&str> = text
        .lines()
        .take_while(|l| !l.trim().is_empty())
        .map(str::trim)
        .collect();
    let mut first = if first.is_empty() {
        "invalid arguments".to_string()
    } else {
        first.join(" ")
    };
    for tip in text
        .lines()
        .map(str::trim)
        .filter(|l| l.starts_with("tip:"))
    {
        first.push_str("; ");
        first.push_str(tip);
    }
    let first = slider_crank::Error::invalid(slider_crank::Input::CommandLine, first).one_line();
    cli::output::say(&format!("slider-crank: {first} (see --help)"));
    ExitCode::from(REFUSED)
}
