//! The `slider-crank` command line.

mod cli;

use clap::{Parser, Subcommand};
use std::io::Write;
use std::process::ExitCode;

/// Exact kinematics, statics and the classical graphical constructions of
/// the slider-crank mechanism.
///
/// World frame: crank centre C at the origin, line of stroke y = offset,
/// slider on the +x side, crank angle counter-clockwise from +x (0° is the
/// outer dead centre). Lengths are in any one unit; the defaults are the
/// engine of the textbook's §35 (r = 0.5 ft, l = 3 ft, 250 rpm).
#[derive(Debug, Parser)]
#[command(name = "slider-crank", version, about, long_about = None)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Positions, velocities and accelerations at an angle: exact values and
    /// those read off the constructions (CE, CG, BD, FG); statics with --torque
    Analyze(cli::analyze::AnalyzeArgs),
    /// Print a table: obliquity, acceleration-factor, kinematics, forces
    Table(cli::table::TableArgs),
    /// Sweep the whole turn and compare every construction with the
    /// analytic core; exits 1 if any difference exceeds the tolerance
    Check(cli::check::CheckArgs),
    /// Draw a named figure or diagram as SVG (or PNG with --out FILE.png)
    Figure(cli::figure::FigureArgs),
    /// Draw the figure a TOML scene file describes
    Scene(cli::scene::SceneArgs),
}

fn print(text: &str) -> ExitCode {
    let mut out = std::io::stdout().lock();
    match out.write_all(text.as_bytes()).and_then(|_| out.flush()) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("slider-crank: error: cannot write output: {e}");
            ExitCode::from(2)
        }
    }
}

fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => {
            use clap::error::ErrorKind;
            if matches!(
                e.kind(),
                ErrorKind::DisplayHelp
                    | ErrorKind::DisplayVersion
                    | ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand
            ) {
                let _ = e.print();
                return ExitCode::SUCCESS;
            }
            // One line: clap's first line names the problem.
            let text = e.render().to_string();
            let first = text.lines().next().unwrap_or("invalid arguments");
            eprintln!("slider-crank: {first} (see --help)");
            return ExitCode::from(2);
        }
    };
    let result = match &cli.command {
        Command::Analyze(args) => cli::analyze::run(args).map(|s| (s, true)),
        Command::Table(args) => cli::table::run(args).map(|s| (s, true)),
        Command::Check(args) => cli::check::run(args),
        Command::Figure(args) => cli::figure::run(args).map(|s| (s, true)),
        Command::Scene(args) => cli::scene::run(args).map(|s| (s, true)),
    };
    match result {
        Ok((text, ok)) => {
            let code = print(&text);
            if ok { code } else { ExitCode::from(1) }
        }
        Err(e) => {
            eprintln!("slider-crank: error: {e}");
            ExitCode::from(2)
        }
    }
}
