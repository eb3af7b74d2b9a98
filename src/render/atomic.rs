//! Writing a file whole or not at all.

use crate::error::{Error, Field, Input, Result, Wording};
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use super::pending::make_pending;

/// Most symbolic links followed from one output path (as the kernel's
/// `ELOOP` limit).
const MAX_LINKS: usize = 40;

/// Where the bytes for an output path go.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum OutputTarget {
    /// A regular file (existing or not), replaced whole through a temporary
    /// file in its directory: the path after following every symbolic link,
    /// so that a link is kept and its target replaced.
    Replace(PathBuf),
    /// A device, FIFO, socket or a `/proc` descriptor link (`/dev/stdout`,
    /// `/dev/null`, a named pipe): opened and written in place, never
    /// replaced.
    Direct(PathBuf),
}

/// Decides how `path` is written: see [`OutputTarget`].
///
/// Errors: a directory, a write-protected regular file (no write
/// permission for anyone, mode 444: refused even for a user who could
/// replace it), a loop of links (more than 40), or a link that cannot be
/// read.
pub fn output_target(path: &Path) -> Result<OutputTarget> {
    let fail = |why: String, source: Option<std::io::Error>| Error::Io {
        message: format!("cannot write {}: {why}", path.display()),
        path: Some(path.to_path_buf()),
        source: source.map(Arc::new),
    };
    let mut current = path.to_path_buf();
    for _ in 0..MAX_LINKS {
        let meta = match std::fs::symlink_metadata(&current) {
            Ok(m) => m,
            // Not there yet: created, in a folder that must exist (a
            // single file's folder is never made: a typo there would make
            // one).
            Err(_) => {
                return missing_folder(&current).map_or(Ok(OutputTarget::Replace(current)), Err);
            }
        };
        let kind = meta.file_type();
        if kind.is_symlink() {
            let link = std::fs::read_link(&current).map_err(|e| fail(e.to_string(), Some(e)))?;
            // A descriptor link (/dev/stdout → /proc/self/fd/1 → pipe:[…])
            // names no file to replace: write through it.
            if link.starts_with("/proc") || link.starts_with("/dev/fd") {
                return Ok(OutputTarget::Direct(path.to_path_buf()));
            }
            current = match current.parent() {
                Some(dir) if link.is_relative() => dir.join(link),
                _ => link,
            };
        } else if kind.is_dir() {
            return Err(fail("it is a directory".into(), None));
        } else if kind.is_file() {
            if write_protected(&meta) {
                return Err(fail(
                    "it is write-protected (give another file, or make it writable)".into(),
                    None,
                ));
            }
            return Ok(OutputTarget::Replace(current));
        } else {
            return Ok(OutputTarget::Direct(path.to_path_buf()));
        }
    }
    Err(fail(format!("more than {MAX_LINKS} symbolic links"), None))
}

/// Whether a regular file grants nobody write permission (mode 444): it
/// is not replaced, not even by a user who could (the owner, root).
#[cfg(unix)]
pub fn write_protected(meta: &std::fs::Metadata) -> bool {
    use std::os::unix::fs::PermissionsExt;
    meta.permissions().mode() & 0o222 == 0
}

#[cfg(not(unix))]
pub fn write_protected(meta: &std::fs::Metadata) -> bool {
    meta.permissions().readonly()
}

/// Refuses a symbolic link at the name of a file derived from the one
/// written ([`Field::Out`]: an exercise's key, a class's sheets, keys and
/// answers): that one is written through a link as the user named it,
/// but a link planted at a
/// name the user did not give would have its target, anywhere, replaced.
/// Checked for every file before any is written; the command line's
/// handout and the Python package's `exercise` call it.
pub fn no_link_at_derived<P: AsRef<Path>>(files: &[P]) -> Result<()> {
    for path in files.iter().map(AsRef::as_ref) {
        if std::fs::symlink_metadata(path).is_ok_and(|m| m.file_type().is_symlink()) {
            return Err(Error::refused(
                Input::OutputFile,
                Wording::from(format!(
                    "cannot write {}: it is a symbolic link, and a file named after ",
                    path.display()
                ))
                .option(Field::Out)
                .then(" is never written through one (remove it or give another ")
                .option(Field::Out)
                .then(")"),
            ));
        }
    }
    Ok(())
}

/// Whether `a` and `b` name the same existing file (through any links):
/// an output that would replace an input is refused with this.
#[cfg(unix)]
pub fn same_file(a: &Path, b: &Path) -> bool {
    use std::os::unix::fs::MetadataExt;
    match (std::fs::metadata(a), std::fs::metadata(b)) {
        (Ok(x), Ok(y)) => x.dev() == y.dev() && x.ino() == y.ino(),
        _ => false,
    }
}

/// Whether `a` and `b` name the same existing file (compared by their
/// canonical paths).
#[cfg(not(unix))]
pub fn same_file(a: &Path, b: &Path) -> bool {
    match (std::fs::canonicalize(a), std::fs::canonicalize(b)) {
        (Ok(x), Ok(y)) => x == y,
        _ => false,
    }
}

/// The error for a new file `path` whose folder does not exist, naming
/// the folder; `None` when it exists (or is the working directory).
fn missing_folder(path: &Path) -> Option<Error> {
    let dir = path.parent().filter(|d| !d.as_os_str().is_empty())?;
    if dir.is_dir() {
        return None;
    }
    Some(Error::Io {
        message: format!(
            "cannot write {}: the folder {} does not exist (create it first, or give another)",
            path.display(),
            dir.display()
        ),
        path: Some(path.to_path_buf()),
        source: None,
    })
}

/// Writes `bytes` to `path` as the kind of file there decides (a device
/// or FIFO in place, a symbolic link's target, a regular file whole).
///
/// A regular file is written through a temporary file in the same
/// directory, renamed over the target only when complete: a reader never
/// sees half a file, a failure leaves any old file as it was and no
/// temporary file behind, a symbolic link stays a link (its target is
/// replaced), and an existing file keeps its permissions (new files are
/// readable by all, 0644). A device or FIFO is written directly; a write
/// error there (`/dev/full`) is an error.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<()> {
    write_atomic_with(path, |sink| sink(bytes))
}

/// [`write_atomic`] of what `write` gives its sink a piece at a time (a
/// long animation, never held whole): the same kinds of file, the same
/// whole-or-nothing replacement. An error from `write` (its own, or the
/// sink's, which names `path`) leaves any old file as it was.
pub fn write_atomic_with(
    path: &Path,
    write: impl FnOnce(&mut dyn FnMut(&[u8]) -> Result<()>) -> Result<()>,
) -> Result<()> {
    let fail = |e: std::io::Error| Error::Io {
        message: format!("cannot write {}: {e}", path.display()),
        path: Some(path.to_path_buf()),
        source: Some(Arc::new(e)),
    };
    let fill = |file: &mut std::fs::File| -> Result<()> {
        let mut out = std::io::BufWriter::with_capacity(1 << 16, file);
        write(&mut |bytes| out.write_all(bytes).map_err(fail))?;
        out.flush().map_err(fail)
    };
    match output_target(path)? {
        OutputTarget::Direct(p) => {
            let mut file = std::fs::OpenOptions::new()
                .write(true)
                .open(&p)
                .map_err(fail)?;
            fill(&mut file)
        }
        OutputTarget::Replace(p) => replace(&p, fill, fail),
    }
}

/// Writes every file of `files` (a path and its bytes) whole, or none of
/// them: a sheet and its answer key, a class's sheets. Each path is
/// written as [`write_atomic`] writes one (a link kept and its target
/// replaced, an existing file's permissions kept), and every refusal
/// [`write_atomic`] makes (a directory, a write-protected file, a missing
/// folder, a loop of links) comes before any file is touched.
///
/// The regular files are first written under unpredictable temporary
/// names (`.slider-crank-…`, made exclusively in each target's directory,
/// never following a link planted there), then renamed over their targets
/// one after another with an interruption held off until the last: a
/// failure while any is written (a full disk, an unwritable folder)
/// removes the temporary files and leaves every old file as it was. A
/// device or FIFO among them is written in place after the others are
/// staged and before any is renamed (what it received cannot be taken
/// back). Only a rename failing part way (the folder removed meanwhile)
/// leaves the files renamed before it.
///
/// `each` is told of each file (its number from 1, its path) as it is
/// written, for a progress line.
pub fn write_atomic_all<P: AsRef<Path>, B: AsRef<[u8]>>(
    files: &[(P, B)],
    mut each: impl FnMut(usize, &Path),
) -> Result<()> {
    let fail = |path: &Path| {
        let path = path.to_path_buf();
        move |e: std::io::Error| Error::Io {
            message: format!("cannot write {}: {e}", path.display()),
            path: Some(path.clone()),
            source: Some(Arc::new(e)),
        }
    };
    let targets = files
        .iter()
        .map(|(p, _)| output_target(p.as_ref()))
        .collect::<Result<Vec<_>>>()?;
    let mut staged = Vec::new();
    let mut direct = Vec::new();
    for (i, ((path, bytes), target)) in files.iter().zip(targets).enumerate() {
        let path = path.as_ref();
        each(i + 1, path);
        match target {
            OutputTarget::Replace(p) => {
                let (mut tmp, pending) = make_pending(|| temporary(&p)).map_err(fail(path))?;
                tmp.write_all(bytes.as_ref()).map_err(fail(path))?;
                staged.push((path, p, tmp, pending));
            }
            OutputTarget::Direct(p) => direct.push((path, p, bytes.as_ref())),
        }
    }
    for (path, p, bytes) in direct {
        std::fs::OpenOptions::new()
            .write(true)
            .open(&p)
            .and_then(|mut f| f.write_all(bytes))
            .map_err(fail(path))?;
    }
    super::pending::uninterrupted(|| {
        for (path, p, tmp, _pending) in staged {
            persist(&p, tmp).map_err(fail(path))?;
        }
        Ok(())
    })
}

/// Replaces the regular file `path` (or creates it) through a temporary
/// file in its directory, written by `fill`.
fn replace(
    path: &Path,
    fill: impl FnOnce(&mut std::fs::File) -> Result<()>,
    fail: impl Fn(std::io::Error) -> Error,
) -> Result<()> {
    let (mut tmp, _pending) = make_pending(|| temporary(path)).map_err(&fail)?;
    fill(tmp.as_file_mut())?;
    persist(path, tmp).map_err(fail)
}

/// An empty temporary file beside `path`.
fn temporary(path: &Path) -> std::io::Result<tempfile::NamedTempFile> {
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    tempfile::Builder::new()
        .prefix(".slider-crank-")
        .tempfile_in(dir)
}

/// The written temporary file `tmp` renamed over `path`, with the
/// permissions of the file it replaces.
fn persist(path: &Path, tmp: tempfile::NamedTempFile) -> std::io::Result<()> {
    let old = std::fs::metadata(path).ok().map(|m| m.permissions());
    tmp.as_file().sync_all()?;
    // An ordinary file, readable by others (temporary files are private),
    // unless it replaces one with its own permissions.
    let permissions = match old {
        Some(p) => p,
        #[cfg(unix)]
        None => std::os::unix::fs::PermissionsExt::from_mode(0o644),
        #[cfg(not(unix))]
        None => tmp.as_file().metadata()?.permissions(),
    };
    std::fs::set_permissions(tmp.path(), permissions)?;
    tmp.persist(path).map_err(|e| e.error)?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn writes_whole_file_and_reports_bad_directory() {
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("f.svg");
        write_atomic(&p, b"<svg/>").unwrap();
        assert_eq!(std::fs::read(&p).unwrap(), b"<svg/>");
        let err = write_atomic(&dir.path().join("missing/f.svg"), b"x").unwrap_err();
        let folder = dir.path().join("missing");
        assert!(
            err.to_string().ends_with(&format!(
                "the folder {} does not exist (create it first, or give another)",
                folder.display()
            )),
            "{err}"
        );
        assert!(!folder.exists());
        // No temporary file is left behind.
        assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 1);
    }

    #[cfg(unix)]
    #[test]
    fn a_link_is_kept_and_its_target_replaced() {
        let dir = tempfile::tempdir().unwrap();
        let target = dir.path().join("real.svg");
        std::fs::write(&target, b"old").unwrap();
        let link = dir.path().join("link.svg");
        std::os::unix::fs::symlink("real.svg", &link).unwrap();
        write_atomic(&link, b"new").unwrap();
        assert!(
            std::fs::symlink_metadata(&link)
                .unwrap()
                .file_type()
                .is_symlink()
        );
        assert_eq!(std::fs::read(&target).unwrap(), b"new");
        // A dangling link creates its target.
        let dangling = dir.path().join("dangling.svg");
        std::os::unix::fs::symlink("made.svg", &dangling).unwrap();
        write_atomic(&dangling, b"x").unwrap();
        assert_eq!(std::fs::read(dir.path().join("made.svg")).unwrap(), b"x");
    }

    #[cfg(unix)]
    #[test]
    fn devices_are_written_in_place_and_their_errors_reported() {
        assert_eq!(
            output_target(Path::new("/dev/null")).unwrap(),
            OutputTarget::Direct("/dev/null".into())
        );
        write_atomic(Path::new("/dev/null"), b"x").unwrap();
        if Path::new("/dev/full").exists() {
            let err = write_atomic(Path::new("/dev/full"), b"x").unwrap_err();
            assert!(
                err.to_string().starts_with("cannot write /dev/full: "),
                "{err}"
            );
        }
        let err = write_atomic(Path::new("/tmp"), b"x").unwrap_err();
        assert_eq!(err.to_string(), "cannot write /tmp: it is a directory");
    }

    #[cfg(unix)]
    #[test]
    fn several_files_are_written_all_or_none() {
        let dir = tempfile::tempdir().unwrap();
        let sheet = dir.path().join("sheet.html");
        let key = dir.path().join("sheet-key.html");
        let names = || {
            let mut n: Vec<_> = std::fs::read_dir(dir.path())
                .unwrap()
                .map(|e| e.unwrap().file_name().into_string().unwrap())
                .collect();
            n.sort();
            n
        };
        // The key's name is a folder: refused before the sheet is made.
        std::fs::create_dir(&key).unwrap();
        let files = [(&sheet, "sheet"), (&key, "key")];
        let err = write_atomic_all(&files, |_, _| ()).unwrap_err();
        assert!(err.to_string().ends_with("it is a directory"), "{err}");
        assert_eq!(names(), ["sheet-key.html"]);
        // An old sheet is kept when its key is write-protected.
        std::fs::remove_dir(&key).unwrap();
        std::fs::write(&sheet, "old sheet").unwrap();
        std::fs::write(&key, "old key").unwrap();
        let protected = std::os::unix::fs::PermissionsExt::from_mode(0o444);
        std::fs::set_permissions(&key, protected).unwrap();
        assert!(write_atomic_all(&files, |_, _| ()).is_err());
        assert_eq!(std::fs::read_to_string(&sheet).unwrap(), "old sheet");
        assert_eq!(names(), ["sheet-key.html", "sheet.html"]);
        // Both written, each told in turn; a link at a target is kept.
        let writable = std::os::unix::fs::PermissionsExt::from_mode(0o644);
        std::fs::set_permissions(&key, writable).unwrap();
        std::fs::remove_file(&sheet).unwrap();
        std::os::unix::fs::symlink("real.html", &sheet).unwrap();
        let mut told = Vec::new();
        write_atomic_all(&files, |i, p| told.push((i, p.to_path_buf()))).unwrap();
        assert_eq!(told, [(1, sheet.clone()), (2, key.clone())]);
        assert!(sheet.symlink_metadata().unwrap().file_type().is_symlink());
        assert_eq!(
            std::fs::read_to_string(dir.path().join("real.html")).unwrap(),
            "sheet"
        );
        assert_eq!(std::fs::read_to_string(&key).unwrap(), "key");
        assert_eq!(names(), ["real.html", "sheet-key.html", "sheet.html"]);
    }
}
