//! `slider-crank gallery [--out DIR]`: every named figure as SVG, PNG and
//! PDF, every table, and an index.html, written into a directory.

use super::output::{Progress, Stdout, say};
use clap::Args;
use slider_crank::files::{MAX_SCENE_BYTES, read_bytes_from, read_text};
use slider_crank::gallery::{Gallery, leftovers, lock_directory};
use slider_crank::{Error, FigureName, Input, Result};
use std::io::ErrorKind;
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
    let mut gallery = match &args.manifest {
        Some(path) => {
            let text = read_text(path, MAX_SCENE_BYTES, Input::Manifest)?;
            let base = path.parent().unwrap_or(Path::new(""));
            Gallery::from_manifest(&text, base).map_err(|e| {
                Error::invalid(
                    Input::Manifest,
                    format!("{}: {}", path.display(), e.one_line()),
                )
            })?
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
        let _lock = lock_directory(dir, false)?;
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
    let (mut done, mut differ) = (0, 0);
    let result = gallery.build(|file| {
        done += 1;
        progress.show(done, &file.name);
        let path = dir.join(&file.name);
        let Some(verdict) = compare(&path, &file.bytes)? else {
            return Ok(());
        };
        differ += 1;
        let shown = Error::printable(&path.display().to_string());
        out.text(&format!("{shown} {verdict}\n"))
    });
    progress.finish();
    result?;
    for stale in leftovers(dir)? {
        differ += 1;
        out.text(&format!(
            "{} is left by an interrupted gallery (the next gallery removes it)\n",
            Error::printable(&stale.display().to_string())
        ))?;
    }
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

/// How the file at `path` differs from `bytes` (`None`: it holds them).
/// Only a regular file is read (never a link, a FIFO or a device), and no
/// more of it than `bytes` holds and one byte.
fn compare(path: &Path, bytes: &[u8]) -> Result<Option<&'static str>> {
    let unreadable = |e: std::io::Error| {
        let message = format!("cannot read {}: {e}", path.display());
        Error::io_at(message, path, e)
    };
    let meta = match std::fs::symlink_metadata(path) {
        Ok(m) => m,
        Err(e) if e.kind() == ErrorKind::NotFound => return Ok(Some("is missing")),
        Err(e) => return Err(unreadable(e)),
    };
    if !meta.is_file() {
        return Ok(Some("is not a regular file"));
    }
    if meta.len() != bytes.len() as u64 {
        return Ok(Some("differs"));
    }
    let file = open_regular(path).map_err(unreadable)?;
    let shown = path.display().to_string();
    // A file that grew since: more than `bytes` is a difference.
    match read_bytes_from(file, bytes.len() as u64, &shown) {
        Ok(read) if read == bytes => Ok(None),
        Ok(_) => Ok(Some("differs")),
        Err(Error::Io { source: None, .. }) => Ok(Some("differs")),
        Err(e) => Err(e),
    }
}

/// Opens `path` for reading without following a link or waiting for a
/// FIFO's writer (a file swapped for either since it was looked at).
#[cfg(unix)]
fn open_regular(path: &Path) -> std::io::Result<std::fs::File> {
    use std::os::unix::fs::OpenOptionsExt;
    std::fs::OpenOptions::new()
        .read(true)
        .custom_flags(libc::O_NOFOLLOW | libc::O_NONBLOCK)
        .open(path)
}

#[cfg(not(unix))]
fn open_regular(path: &Path) -> std::io::Result<std::fs::File> {
    std::fs::File::open(path)
}
