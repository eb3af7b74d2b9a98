//! A gallery compared with the files of a directory, writing nothing:
//! which file differs from the one this build makes, is missing, or was
//! left by an interrupted gallery.

use super::Gallery;
use super::write::{leftovers, lock_directory};
use crate::error::{Error, Result};
use crate::files::read_bytes_from;
use std::io::ErrorKind;
use std::path::Path;

/// How a file of a directory differs from the gallery's.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Difference {
    /// No file of the gallery's name.
    Missing,
    /// The name is a link, a directory, a FIFO or a device, not a
    /// regular file.
    NotRegular,
    /// A regular file with other bytes (or more of them).
    Differs,
    /// A file a gallery staged and never renamed (it was killed); the
    /// next gallery written into the directory removes it.
    Leftover,
}

impl Difference {
    /// The difference as the command line words it after the file's
    /// path (`is missing`, `differs`).
    pub fn words(self) -> &'static str {
        match self {
            Difference::Missing => "is missing",
            Difference::NotRegular => "is not a regular file",
            Difference::Differs => "differs",
            Difference::Leftover => {
                "is left by an interrupted gallery (the next gallery removes it)"
            }
        }
    }
}

impl Gallery {
    /// Makes every file of [`Gallery::file_names`] in memory and compares
    /// it with the file of its name in `dir`, writing nothing: `each` is
    /// handed the path and the difference of each file that differs, in
    /// the order of the names, then each file an interrupted gallery left
    /// ([`leftovers`]). `progress` is told each file's number (from 1)
    /// and name as it is made. The directory is locked against a gallery
    /// writing into it meanwhile ([`lock_directory`], shared). Returns the
    /// number of differences (0: the directory holds the gallery; a
    /// missing directory differs in every file).
    ///
    /// Only regular files are read (never through a link, or a FIFO
    /// waited on), and no more of each than the gallery's file holds and
    /// one byte. Errors: a file that cannot be read, or what
    /// [`Gallery::build`] and `each` return.
    pub fn compare_with(
        &self,
        dir: &Path,
        mut progress: impl FnMut(usize, &str),
        mut each: impl FnMut(&Path, Difference) -> Result<()>,
    ) -> Result<usize> {
        let _lock = lock_directory(dir, false)?;
        let (mut done, mut differ) = (0, 0);
        self.build(|file| {
            done += 1;
            progress(done, &file.name);
            let path = dir.join(&file.name);
            let Some(difference) = compare(&path, &file.bytes)? else {
                return Ok(());
            };
            differ += 1;
            each(&path, difference)
        })?;
        for stale in leftovers(dir)? {
            differ += 1;
            each(&stale, Difference::Leftover)?;
        }
        Ok(differ)
    }
}

/// How the file at `path` differs from `bytes` (`None`: it holds them).
fn compare(path: &Path, bytes: &[u8]) -> Result<Option<Difference>> {
    let unreadable = |e: std::io::Error| {
        let message = format!("cannot read {}: {e}", path.display());
        Error::io_at(message, path, e)
    };
    let meta = match std::fs::symlink_metadata(path) {
        Ok(m) => m,
        Err(e) if e.kind() == ErrorKind::NotFound => return Ok(Some(Difference::Missing)),
        Err(e) => return Err(unreadable(e)),
    };
    if !meta.is_file() {
        return Ok(Some(Difference::NotRegular));
    }
    if meta.len() != bytes.len() as u64 {
        return Ok(Some(Difference::Differs));
    }
    let file = open_regular(path).map_err(unreadable)?;
    let shown = path.display().to_string();
    // A file that grew since: more than `bytes` is a difference.
    match read_bytes_from(file, bytes.len() as u64, &shown) {
        Ok(read) if read == bytes => Ok(None),
        Ok(_) => Ok(Some(Difference::Differs)),
        Err(Error::Io { source: None, .. }) => Ok(Some(Difference::Differs)),
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
