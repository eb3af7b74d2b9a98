//! `slider-crank gallery [--out DIR]`: every named figure as SVG, PNG and
//! PDF, every table, and an index.html, written into a directory.

use super::output::{Progress, Stdout, say};
use clap::Args;
use slider_crank::gallery::{Gallery, GalleryFile};
use slider_crank::input::{MAX_SCENE_BYTES, read_bytes_from, read_text};
use slider_crank::render::{Pending, make_pending, uninterrupted, write_protected};
use slider_crank::{Error, FigureName, Input, Result};
use std::io::{ErrorKind, Write};
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
        let _lock = lock(dir, false)?;
        return check(&gallery, dir, out);
    }
    prepare(dir)?;
    let _lock = lock(dir, true)?;
    // Under the lock no other gallery writes here: a staged file is one a
    // killed gallery left behind.
    for stale in leftovers(dir)? {
        std::fs::remove_file(&stale).map_err(|e| {
            Error::io_at(
                format!(
                    "cannot remove {}, left by an interrupted gallery: {e}",
                    stale.display()
                ),
                &stale,
                e,
            )
        })?;
    }
    let names = gallery.file_names();
    for name in &names {
        writable(&dir.join(name))?;
        if let Some(manifest) = &args.manifest {
            not_the_manifest(&dir.join(name), manifest)?;
        }
    }
    let mut progress = Progress::new("gallery", names.len());
    let mut staged = Vec::new();
    let result = gallery.build(|file| {
        progress.show(staged.len() + 1, &file.name);
        staged.push(stage(dir, &file)?);
        Ok(())
    });
    progress.finish();
    if let Err(e) = result {
        // The file being made or written when the error came (a write
        // error is about that file and names it already).
        return Err(match names.get(staged.len()) {
            Some(name) if !is_about(&e, &dir.join(name)) => Error::io_about(
                format!("gallery: {name}: {}", e.one_line()),
                &dir.join(name),
            ),
            _ => e,
        });
    }
    commit(dir, staged)?;
    say(&format!(
        "gallery: {} files in {}",
        names.len(),
        dir.display()
    ));
    Ok(true)
}

/// A file of the gallery written under a temporary name in its directory,
/// and the name it takes when the whole gallery is made.
struct Staged {
    name: String,
    file: tempfile::TempPath,
    _pending: Pending,
}

/// The prefix of a gallery's staged files: a gallery's own, so that what
/// a killed gallery leaves is told from another command's file being
/// written in the same directory.
const STAGED_PREFIX: &str = ".slider-crank-gallery-";

/// The files a gallery staged in `dir` and never renamed (it was killed,
/// SIGKILL, before it could remove them), in name order.
fn leftovers(dir: &Path) -> Result<Vec<std::path::PathBuf>> {
    let entries = match std::fs::read_dir(dir) {
        Ok(e) => e,
        Err(e) if e.kind() == ErrorKind::NotFound => return Ok(Vec::new()),
        Err(e) => {
            let message = format!("cannot read the directory {}: {e}", dir.display());
            return Err(Error::io_at(message, dir, e));
        }
    };
    let mut found: Vec<_> = entries
        .filter_map(|e| e.ok())
        .filter(|e| e.file_name().to_string_lossy().starts_with(STAGED_PREFIX))
        .filter(|e| e.file_type().is_ok_and(|t| t.is_file()))
        .map(|e| e.path())
        .collect();
    found.sort();
    Ok(found)
}

/// Writes `file` under a temporary name in `dir` (a
/// [`STAGED_PREFIX`] file, removed if the program stops before
/// [`commit`], and by the next gallery if it is killed).
fn stage(dir: &Path, file: &GalleryFile) -> Result<Staged> {
    let path = dir.join(&file.name);
    let fail =
        |e: std::io::Error| Error::io_at(format!("cannot write {}: {e}", path.display()), &path, e);
    let (mut tmp, pending) = make_pending(|| {
        tempfile::Builder::new()
            .prefix(STAGED_PREFIX)
            .tempfile_in(dir)
    })
    .map_err(fail)?;
    tmp.write_all(&file.bytes)
        .and_then(|()| tmp.as_file().sync_all())
        .map_err(fail)?;
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        let readable = std::fs::Permissions::from_mode(0o644);
        tmp.as_file().set_permissions(readable).map_err(fail)?;
    }
    Ok(Staged {
        name: file.name.clone(),
        file: tmp.into_temp_path(),
        _pending: pending,
    })
}

/// Whether `e` is a reading or writing error about the file `path`.
fn is_about(e: &Error, path: &Path) -> bool {
    matches!(e, Error::Io { path: Some(p), .. } if p == path)
}

/// Renames every staged file over its name, with an interruption held off
/// until all are renamed: the directory holds the old gallery or the new
/// one. A name that is a symbolic link is replaced by the file (the link
/// is not followed out of the directory).
fn commit(dir: &Path, staged: Vec<Staged>) -> Result<()> {
    uninterrupted(|| {
        for s in staged {
            let path = dir.join(&s.name);
            s.file.persist(&path).map_err(|e| {
                let message = format!("cannot write {}: {}", path.display(), e.error);
                Error::io_at(message, &path, e.error)
            })?;
        }
        Ok(())
    })
}

/// Refuses a file of the gallery that is its own manifest (through any
/// link): the gallery would write over the input it was made from.
fn not_the_manifest(path: &Path, manifest: &Path) -> Result<()> {
    let is_file = |p: &Path| std::fs::metadata(p).is_ok_and(|m| m.is_file());
    if is_file(path) && slider_crank::render::same_file(path, manifest) {
        return Err(Error::io_about(
            format!(
                "cannot write {}: it is the gallery's manifest {}, read to make the gallery (give another --out, or keep the manifest elsewhere)",
                path.display(),
                manifest.display()
            ),
            path,
        ));
    }
    Ok(())
}

/// Refuses, before anything is made, a name of the gallery that is a
/// directory or a write-protected file. Anything else there (a file, a
/// link, a FIFO) is replaced.
fn writable(path: &Path) -> Result<()> {
    let Ok(meta) = std::fs::symlink_metadata(path) else {
        return Ok(());
    };
    let why = if meta.is_dir() {
        "it is a directory"
    } else if meta.is_file() && write_protected(&meta) {
        "it is write-protected (make it writable, or write the gallery elsewhere)"
    } else {
        return Ok(());
    };
    Err(Error::io_about(
        format!("cannot write {}: {why}", path.display()),
        path,
    ))
}

/// Locks the gallery's directory for this process: `exclusive` to write
/// it, shared to compare it. Another slider-crank writing it is an error
/// (two galleries written at once would mix their files); the lock ends
/// with the returned file. A file system without locks is written
/// unlocked.
fn lock(dir: &Path, exclusive: bool) -> Result<Option<std::fs::File>> {
    let Ok(handle) = std::fs::File::open(dir) else {
        // A missing directory (for --check): nothing to lock.
        return Ok(None);
    };
    let locked = if exclusive {
        handle.try_lock()
    } else {
        handle.try_lock_shared()
    };
    match locked {
        Ok(()) => Ok(Some(handle)),
        Err(std::fs::TryLockError::WouldBlock) => Err(Error::io_about(
            format!(
                "another slider-crank is writing the gallery in {}: run again when it has finished",
                dir.display()
            ),
            dir,
        )),
        Err(std::fs::TryLockError::Error(e)) if e.kind() == ErrorKind::Unsupported => Ok(None),
        Err(std::fs::TryLockError::Error(e)) => {
            let message = format!("cannot lock the gallery's directory {}: {e}", dir.display());
            Err(Error::io_at(message, dir, e))
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
