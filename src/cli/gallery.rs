//! `slider-crank gallery [--out DIR]`: every named figure as SVG, PNG and
//! PDF, every table, and an index.html, written into a directory.

use super::output::{Progress, Stdout};
use clap::Args;
use slider_crank::gallery::Gallery;
use slider_crank::input::{MAX_SCENE_BYTES, read_text};
use slider_crank::render::write_atomic;
use slider_crank::{Error, FigureName, Result};
use std::path::{Path, PathBuf};

/// Write the gallery: every figure at its source's parameters, every table,
/// and an index.html.
#[derive(Debug, Args)]
pub struct GalleryArgs {
    /// The directory to write into, created if missing; files of the same
    /// names are replaced (each whole), others left alone
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
    let mut gallery = match &args.manifest {
        Some(path) => {
            let text = read_text(path, MAX_SCENE_BYTES, "manifest")?;
            let base = path.parent().unwrap_or(Path::new(""));
            Gallery::from_manifest(&text, base)
                .map_err(|e| Error::Parse(format!("{}: {}", path.display(), e.one_line())))?
        }
        None => Gallery::new(),
    };
    if let Some(list) = &args.only {
        let figures = list
            .split(',')
            .map(|n| FigureName::from_name(n.trim()))
            .collect::<Result<Vec<_>>>()?;
        gallery = gallery.with_figures(figures);
    }
    gallery.can_build()?;
    let dir = &args.out;
    if args.check {
        return check(&gallery, dir, out);
    }
    prepare(dir)?;
    let names = gallery.file_names();
    let mut progress = Progress::new("gallery", names.len());
    let mut made = 0;
    let result = gallery.build(|file| {
        progress.show(made + 1, &file.name);
        write_atomic(&dir.join(&file.name), &file.bytes)?;
        made += 1;
        Ok(())
    });
    progress.finish();
    match result {
        // The file being made or written when the error came (a write
        // error names it already).
        Err(e) => Err(match names.get(made) {
            Some(name) if !e.to_string().contains(name.as_str()) => Error::io_about(
                format!("gallery: {name}: {}", e.one_line()),
                &dir.join(name),
            ),
            _ => e,
        }),
        Ok(()) => {
            eprintln!("gallery: {} files in {}", names.len(), dir.display());
            Ok(true)
        }
    }
}

/// `--check`: each file made in memory against the one on disk; a line on
/// standard output for each that differs or is missing.
fn check(gallery: &Gallery, dir: &Path, out: &mut Stdout) -> Result<bool> {
    let names = gallery.file_names();
    let mut progress = Progress::new("gallery", names.len());
    let (mut done, mut differ) = (0, 0);
    let result = gallery.build(|file| {
        done += 1;
        progress.show(done, &file.name);
        let path = dir.join(&file.name);
        let verdict = match std::fs::read(&path) {
            Ok(bytes) if bytes == file.bytes => return Ok(()),
            Ok(_) => "differs",
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => "is missing",
            Err(e) => {
                let message = format!("cannot read {}: {e}", path.display());
                return Err(Error::io_at(message, &path, e));
            }
        };
        differ += 1;
        out.text(&format!("{} {verdict}\n", path.display()))
    });
    progress.finish();
    result?;
    if differ == 0 {
        eprintln!(
            "gallery: the {} files in {} are up to date",
            names.len(),
            dir.display()
        );
    } else {
        eprintln!(
            "gallery: {differ} of {} files in {} differ from this build's",
            names.len(),
            dir.display()
        );
    }
    Ok(differ == 0)
}

/// Checks the output directory: an existing directory (or a link to one)
/// is used, a missing one created, anything else refused.
fn prepare(dir: &Path) -> Result<()> {
    match std::fs::metadata(dir) {
        Ok(m) if m.is_dir() => Ok(()),
        Ok(_) => Err(Error::io_about(
            format!(
                "cannot write the gallery into {}: it exists and is not a directory",
                dir.display()
            ),
            dir,
        )),
        Err(_) => std::fs::create_dir_all(dir).map_err(|e| {
            let message = format!(
                "cannot create the gallery's directory {}: {e}",
                dir.display()
            );
            Error::io_at(message, dir, e)
        }),
    }
}
