//! `slider-crank handout`: a printable page that works one engine through
//! §35–37 and Ng (and its dynamics, given `--mass`); with `--exercise`, an exercise sheet and its answer key;
//! with `--class N`, a sheet and a key for each of N engines and a table
//! of every answer.

use super::args::{GivenMechanismArgs, LoadArgs, SpeedArgs, UnitArgs};
use super::output::{Progress, Stdout};
use clap::Args;
use slider_crank::handout::{Class, Handout, HandoutRequest, Paper};
use slider_crank::render::{no_link_at_derived, write_atomic_all};
use slider_crank::{Error, Input, Result};
use std::path::{Path, PathBuf};

/// Write a teaching handout, an exercise sheet with its key, or a class's
/// sheets.
#[derive(Debug, Args)]
pub struct HandoutArgs {
    #[command(flatten)]
    pub mechanism: GivenMechanismArgs,
    #[command(flatten)]
    pub speed: SpeedArgs,
    /// Crank angle θ in degrees of the pose worked through,
    /// counter-clockwise from +x, the direction from the crank centre
    /// towards the slider (0: outer dead centre)
    #[arg(
        long,
        default_value_t = 45.0,
        value_name = "DEG",
        allow_hyphen_values = true
    )]
    pub angle: f64,
    #[command(flatten)]
    pub units: UnitArgs,
    #[command(flatten)]
    pub load: LoadArgs,
    /// Work the engine's dynamics after the diagrams (on an exercise, the
    /// forces at the pose), for a reciprocating mass M (piston and
    /// cross-head) in the unit that makes mass × length/s² the force unit
    /// (slug with ft and lbf, kg with m and N): the inertia force from
    /// Klein's CG, the crank effort T = F·OM with the gas force of
    /// --gas-force or --indicator, else the example's steam indicator
    /// diagram (examples/indicator.csv, lbf/ft² on a 10 in bore: with ft
    /// and lbf only), the turning-moment diagram with its mean torque and
    /// ΔE, and the flywheel; three steps and their figures, about three
    /// more pages
    #[arg(
        long,
        value_name = "M",
        allow_negative_numbers = true,
        conflicts_with = "class"
    )]
    pub mass: Option<f64>,
    /// The coefficient of fluctuation of speed C_s = (ω_max − ω_min)/ω
    /// the flywheel of --mass is sized for
    #[arg(
        long,
        value_name = "CS",
        default_value_t = slider_crank::dynamics::DEFAULT_FLUCTUATION,
        allow_negative_numbers = true,
        requires = "mass"
    )]
    pub fluctuation: f64,
    /// A constant gas force on the piston for --mass, positive towards
    /// the crank centre, in the force unit
    #[arg(long, value_name = "F", allow_negative_numbers = true)]
    pub gas_force: Option<f64>,
    /// The engine's own indicator diagram for --mass: CSV with the
    /// columns fraction (of the stroke from the outer dead centre),
    /// expansion and compression (gauge pressures in force per length²;
    /// a unit declared in the header, "expansion (N/mm²)", must be that
    /// of the units); give --bore with it
    #[arg(long, value_name = "CSV")]
    pub indicator: Option<PathBuf>,
    /// The bore D of the cylinder of --indicator, in the length unit
    #[arg(long, value_name = "D", allow_negative_numbers = true)]
    pub bore: Option<f64>,
    /// The paper the page is printed on: a4 or letter (the CSS @page size;
    /// no figure or table is broken across two pages)
    #[arg(long, value_name = "PAPER", default_value = "a4")]
    pub paper: Paper,
    /// Write an exercise sheet instead: only the mechanism to scale on a
    /// faint grid, the data and empty answer fields; its answer key goes
    /// beside it, FILE-key.html
    #[arg(long)]
    pub exercise: bool,
    /// Write exercise sheets for a class of N different engines (in line,
    /// n = l/r from 3.5 to 6, angles clear of the dead centres and the
    /// quarter turns, 100 to 1500 rpm), drawn from --seed: FILE-01.html
    /// and FILE-01-key.html for each, and FILE-answers.html with every
    /// answer for the teacher. Implies --exercise. With --crank, --rod or
    /// --offset, the engines are variations of that engine instead (r
    /// ×0.8 to ×1.2, n ×0.9 to ×1.1, e/r kept, each assembling); the
    /// angles and speeds are the class's own, so --angle and the speed are
    /// not taken
    #[arg(
        long,
        value_name = "N",
        conflicts_with_all = ["angle", "rpm", "omega", "torque"]
    )]
    pub class: Option<usize>,
    /// The seed the class's engines are drawn from: the same seed gives
    /// the same engines on every machine and with every version
    #[arg(long, value_name = "S", default_value_t = 1, requires = "class")]
    pub seed: u64,
    /// The page to write, an .html file; an exercise's key and a class's
    /// files are named after it, in its folder, which must exist (only
    /// `gallery` makes its folder). Each file is written whole or not at all
    #[arg(long, value_name = "FILE.html", default_value = "handout.html")]
    pub out: PathBuf,
}

/// The path without its `.html` (or `.htm`) extension, to which `-key`,
/// `-01` and `-answers` are added; an error for any other extension.
fn stem(path: &Path) -> Result<String> {
    let text = path.to_string_lossy().into_owned();
    match path.extension().and_then(|e| e.to_str()) {
        Some("html") => Ok(text[..text.len() - 5].to_string()),
        Some("htm") => Ok(text[..text.len() - 4].to_string()),
        None if !text.is_empty() && !text.ends_with('/') => Ok(text),
        _ => Err(Error::invalid(
            Input::OutputFile,
            format!(
                "cannot write {}: a handout is an HTML page, give a file ending in .html",
                path.display()
            ),
        )),
    }
}

/// Writes every file whole, or none of them (the library's
/// [`write_atomic_all`]): a sheet is never left without its key, nor a
/// class without its answers.
fn write_all(files: &[(PathBuf, String)], progress: Option<&mut Progress>) -> Result<()> {
    let mut progress = progress;
    write_atomic_all(files, |i, path| {
        if let Some(p) = progress.as_deref_mut() {
            p.show(i, &path.display().to_string());
        }
    })
}

/// The request the flags make ([`HandoutRequest`]): each as given,
/// `--fluctuation` only with `--mass` and `--friction` only with
/// `--torque` (their defaults the request's own).
fn request(args: &HandoutArgs) -> HandoutRequest {
    let m = &args.mechanism;
    let mut r = HandoutRequest::default();
    (r.crank, r.rod, r.offset) = (m.crank, m.rod, m.offset);
    r.angle = Some(args.angle);
    (r.rpm, r.omega) = (args.speed.rpm, args.speed.omega);
    (r.unit, r.force_unit) = (args.units.length.clone(), args.units.force.clone());
    r.torque = args.load.torque;
    r.friction = (r.torque.and(Some(args.load.friction.unwrap_or(0.0)))).or(args.load.friction);
    r.mass = args.mass;
    r.fluctuation = args.mass.and(Some(args.fluctuation));
    (r.gas_force, r.indicator, r.bore) = (args.gas_force, args.indicator.clone(), args.bore);
    r.paper = Some(args.paper);
    r
}

/// The handout the flags ask for (of one engine; the exercise and the
/// class are drawn from it).
pub fn template(args: &HandoutArgs) -> Result<Handout> {
    request(args).handout()
}

/// Runs the subcommand: the files written; nothing on standard output.
pub fn run(args: &HandoutArgs, _out: &mut Stdout) -> Result<()> {
    let stem = stem(&args.out)?;
    let template = template(args)?;
    let path = |suffix: &str| PathBuf::from(format!("{stem}{suffix}.html"));
    if let Some(count) = args.class {
        let class = if args.mechanism.given() {
            Class::around(count, args.seed, &template)?
        } else {
            Class::draw(count, args.seed, &template)?
        };
        let width = count.to_string().len().max(2);
        let mut files = Vec::with_capacity(2 * count + 1);
        for (i, h) in class.handouts().iter().enumerate() {
            let no = format!("-{:0width$}", i + 1);
            files.push((path(&no), h.exercise()?));
            files.push((path(&format!("{no}-key")), h.key()?));
        }
        files.push((path("-answers"), class.answers()?));
        let derived: Vec<PathBuf> = files.iter().map(|(p, _)| p.clone()).collect();
        no_link_at_derived(&derived)?;
        let mut progress = Progress::new("handout", files.len());
        let result = write_all(&files, Some(&mut progress));
        progress.finish();
        result?;
        super::output::say(&format!(
            "handout: {count} exercises, their keys and the answers, {}",
            path("-answers").display()
        ));
        return Ok(());
    }
    if args.exercise {
        no_link_at_derived(&[path("-key")])?;
        let files = [
            (args.out.clone(), template.exercise()?),
            (path("-key"), template.key()?),
        ];
        return write_all(&files, None);
    }
    write_all(&[(args.out.clone(), template.page()?)], None)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn files_are_named_after_the_page() {
        assert_eq!(stem(Path::new("a/b.html")).unwrap(), "a/b");
        assert_eq!(stem(Path::new("sheet")).unwrap(), "sheet");
        assert!(stem(Path::new("x.pdf")).is_err());
    }
}
