//! Writing a gallery into its directory, all its files or none: each
//! staged under a gallery's own temporary name and renamed over its name
//! once every one is made, the directory locked against a second gallery.
//! The command line (`slider-crank gallery`) and the Python package's
//! `gallery()` both write through [`Gallery::write_into`].

use super::{Gallery, GalleryFile};
use crate::error::{Error, Result};
use crate::render::{Pending, make_pending, same_file, uninterrupted, write_protected};
use std::io::{ErrorKind, Write};
use std::path::{Path, PathBuf};

/// The prefix of a gallery's staged files: a gallery's own, so that what
/// a killed gallery leaves is told from another command's file being
/// written in the same directory.
pub const STAGED_PREFIX: &str = ".slider-crank-gallery-";

impl Gallery {
    /// Writes every file of [`Gallery::file_names`] into `dir` (created if
    /// missing), all or none: each is made and staged under a
    /// [`STAGED_PREFIX`] name in `dir`, and only when every one is staged
    /// are they renamed over their names (a symbolic link of such a name
    /// is replaced, not followed). Before anything is made, the directory
    /// is locked against another gallery ([`lock_directory`]), the files a
    /// killed gallery left are removed ([`leftovers`]), and a name that is
    /// a directory, a write-protected file or `manifest` (the file the
    /// gallery was read from) is refused. `progress` is told each file's
    /// number (from 1) and name as it is made. On an error no file of the
    /// gallery is changed and no staged file is left.
    pub fn write_into(
        &self,
        dir: &Path,
        manifest: Option<&Path>,
        mut progress: impl FnMut(usize, &str),
    ) -> Result<()> {
        self.can_build()?;
        prepare(dir)?;
        let _lock = lock_directory(dir, true)?;
        // Under the lock no other gallery writes here: a staged file is one
        // a killed gallery left behind.
        for stale in leftovers(dir)? {
            std::fs::remove_file(&stale).map_err(|e| {
                let message = format!(
                    "cannot remove {}, left by an interrupted gallery: {e}",
                    stale.display()
                );
                Error::io_at(message, &stale, e)
            })?;
        }
        let names = self.file_names();
        for name in &names {
            writable(&dir.join(name))?;
            if let Some(manifest) = manifest {
                not_the_manifest(&dir.join(name), manifest)?;
            }
        }
        let mut staged = Vec::new();
        let result = self.build(|file| {
            progress(staged.len() + 1, &file.name);
            staged.push(stage(dir, &file)?);
            Ok(())
        });
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
        commit(dir, staged)
    }
}

/// A file of the gallery written under a temporary name in its directory,
/// and the name it takes when the whole gallery is made.
struct Staged {
    name: String,
    file: tempfile::TempPath,
    _pending: Pending,
}

/// The files a gallery staged in `dir` and never renamed (it was killed,
/// SIGKILL, before it could remove them), in name order; none when `dir`
/// does not exist.
pub fn leftovers(dir: &Path) -> Result<Vec<PathBuf>> {
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

/// Writes `file` under a temporary name in `dir` (a [`STAGED_PREFIX`]
/// file, removed if the program stops before [`commit`], and by the next
/// gallery if it is killed).
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
    if is_file(path) && same_file(path, manifest) {
        return Err(Error::io_about(
            format!(
                "cannot write {}: it is the gallery's manifest {}, read to make the gallery (write the gallery to another directory, or keep the manifest elsewhere)",
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
/// it, shared to compare it. Another process writing it is an error (two
/// galleries written at once would mix their files); the lock ends with
/// the returned file. A missing directory or a file system without locks
/// gives no lock (`None`).
pub fn lock_directory(dir: &Path, exclusive: bool) -> Result<Option<std::fs::File>> {
    let Ok(handle) = std::fs::File::open(dir) else {
        // A missing directory (for a comparison): nothing to lock.
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::catalogue::FigureName;
    use crate::render::FileFormat;

    fn small() -> Gallery {
        Gallery::new()
            .with_figures([FigureName::Fig63Velocity])
            .with_formats([FileFormat::Svg])
    }

    #[test]
    fn a_gallery_that_cannot_be_written_whole_changes_nothing() {
        let dir = tempfile::tempdir().unwrap();
        let g = small();
        let names = g.file_names();
        for name in &names {
            std::fs::write(dir.path().join(name), "old").unwrap();
        }
        // The last file's name a directory: refused before any is made.
        let last = dir.path().join(names.last().unwrap());
        std::fs::remove_file(&last).unwrap();
        std::fs::create_dir(&last).unwrap();
        let mut made = 0;
        let e = g
            .write_into(dir.path(), None, |_, _| made += 1)
            .unwrap_err();
        assert!(e.to_string().contains("it is a directory"), "{e}");
        assert_eq!(made, 0);
        for name in &names[..names.len() - 1] {
            assert_eq!(std::fs::read(dir.path().join(name)).unwrap(), b"old");
        }
        assert!(leftovers(dir.path()).unwrap().is_empty());
        // Made whole once the name is free, every file in place.
        std::fs::remove_dir(&last).unwrap();
        g.write_into(dir.path(), None, |_, _| made += 1).unwrap();
        assert_eq!(made, names.len());
        for name in &names {
            assert_ne!(std::fs::read(dir.path().join(name)).unwrap(), b"old");
        }
    }

    #[cfg(unix)]
    #[test]
    fn a_link_at_a_gallery_name_is_replaced_and_its_target_kept() {
        let dir = tempfile::tempdir().unwrap();
        let elsewhere = dir.path().join("elsewhere.svg");
        std::fs::write(&elsewhere, "kept").unwrap();
        let out = dir.path().join("g");
        std::fs::create_dir(&out).unwrap();
        let name = out.join("fig-63-velocity.svg");
        std::os::unix::fs::symlink(&elsewhere, &name).unwrap();
        small().write_into(&out, None, |_, _| ()).unwrap();
        assert_eq!(std::fs::read(&elsewhere).unwrap(), b"kept");
        let meta = std::fs::symlink_metadata(&name).unwrap();
        assert!(meta.is_file(), "the link is replaced by the file");
    }
}
