//! `slider-crank gallery [--out DIR]`: every named figure as SVG, PNG and
//! PDF, every table, and an index.html, written into a directory.

use super::output::{Progress, Stdout, say};
use clap::Args;
use slider_crank::gallery::{Gallery, GalleryRequest};
use slider_crank::{Error, Result};
use std::path::{Path, PathBuf};

/// Write the gallery: every figure at its source's parameters, every table,
/// and an index.html.
#[derive(Debug, Args)]
pub struct GalleryArgs {
    /// The directory to write into, created if missing; files of the same
    /// names are replaced (all at once when every one is made; a link of
    /// such a name is replaced, not followed), others left alone; one
    /// gallery is written into a directory at a time
    #[arg(long, value_name = "DIR", default_value = "gallery")]
    pub out: PathBuf,
    /// Rebuild the gallery in memory and compare it with the files in DIR,
    /// writing nothing: prints each file that differs or is missing, and
    /// exits 1 if any does, 0 if all match
    #[arg(long)]
    pub check: bool,
    /// A TOML manifest of what the gallery holds: `figures` (names),
    /// `scenes` (scene files, from the manifest's directory), `formats`
    /// (svg, png, pdf), `style` and `font` for every figure and for each
    /// scene file that sets none [default: every named figure in the three
    /// formats, each in its own style]
    #[arg(long, value_name = "FILE.toml")]
    pub manifest: Option<PathBuf>,
    /// Only these figures, comma-separated (the tables and the index are
    /// always made)
    #[arg(long, value_name = "LIST", hide = true, conflicts_with = "manifest")]
    pub only: Option<String>,
}

/// Runs the subcommand: the files written, a progress line on standard
/// error; with `--check`, the files compared instead (`false`: some
/// differ).
pub fn run(args: &GalleryArgs, out: &mut Stdout) -> Result<bool> {
    let mut request = GalleryRequest::default();
    request.manifest = args.manifest.clone();
    request.only = args.only.clone().map(|list| vec![list]);
    let gallery = request.gallery()?;
    let dir = &args.out;
    if args.check {
        return check(&gallery, dir, out);
    }
    let mut progress = Progress::new("gallery", gallery.file_names().len());
    let written = gallery.write_into(dir, args.manifest.as_deref(), |i, name| {
        progress.show(i, name)
    });
    progress.finish();
    written?;
    say(&format!(
        "gallery: {} files in {}",
        gallery.file_names().len(),
        dir.display()
    ));
    Ok(true)
}

/// `--check`: each file made in memory against the one on disk; a line on
/// standard output for each that differs or is missing.
fn check(gallery: &Gallery, dir: &Path, out: &mut Stdout) -> Result<bool> {
    let names = gallery.file_names();
    let mut progress = Progress::new("gallery", names.len());
    let differ = gallery.compare_with(
        dir,
        |i, name| progress.show(i, name),
        |path, difference| {
            let shown = Error::printable(&path.display().to_string());
            out.text(&format!("{shown} {}\n", difference.words()))
        },
    );
    progress.finish();
    let differ = differ?;
    if differ == 0 {
        say(&format!(
            "gallery: the {} files in {} are up to date",
            names.len(),
            dir.display()
        ));
    } else {
        say(&format!(
            "gallery: {differ} of {} files in {} differ from this build's or were left by an interrupted gallery",
            names.len(),
            dir.display()
        ));
    }
    Ok(differ == 0)
}
