//! The temporary files a write has made and not yet renamed into place,
//! so that an interrupted program can remove them.
//!
//! Every temporary file [`write_atomic`](super::write_atomic) and the
//! gallery make is registered here while it exists. A program that stops
//! on a signal (the command line does, on Ctrl-C) calls
//! [`remove_pending`] first: no `.slider-crank-…` file is left behind.
//! [`uninterrupted`] holds the removal off while a group of renames runs,
//! so that a directory is seen either before them all or after them all.

use std::path::{Path, PathBuf};
use std::sync::{Mutex, MutexGuard, PoisonError};

/// The temporary files in existence.
static PENDING: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

/// Held by [`uninterrupted`] and by [`remove_pending`].
static COMMIT: Mutex<()> = Mutex::new(());

fn lock<T>(m: &Mutex<T>) -> MutexGuard<'_, T> {
    // A panic elsewhere leaves the list as it was: still usable.
    m.lock().unwrap_or_else(PoisonError::into_inner)
}

/// A temporary file registered while it lives (for [`remove_pending`]):
/// dropped when the file has been renamed into place or removed. It does
/// not remove the file itself.
#[derive(Debug)]
pub struct Pending(PathBuf);

impl Pending {
    /// Registers `path` (a temporary file just made; a path registered
    /// twice is listed twice).
    pub fn new(path: &Path) -> Self {
        lock(&PENDING).push(path.to_path_buf());
        Pending(path.to_path_buf())
    }
}

impl Drop for Pending {
    fn drop(&mut self) {
        let mut list = lock(&PENDING);
        if let Some(i) = list.iter().position(|p| *p == self.0) {
            list.swap_remove(i);
        }
    }
}

/// Makes a temporary file with `make` and registers it, with
/// [`remove_pending`] held off meanwhile: a signal arriving between the
/// file's creation and its registration would otherwise leave it behind
/// (and once the removal has run, no temporary file is made at all: the
/// program is ending).
pub fn make_pending(
    make: impl FnOnce() -> std::io::Result<tempfile::NamedTempFile>,
) -> std::io::Result<(tempfile::NamedTempFile, Pending)> {
    let _guard = lock(&COMMIT);
    let file = make()?;
    let pending = Pending::new(file.path());
    Ok((file, pending))
}

/// Runs `f` (a group of renames) with [`remove_pending`] held off until
/// it returns.
pub fn uninterrupted<T>(f: impl FnOnce() -> T) -> T {
    let _guard = lock(&COMMIT);
    f()
}

/// Removes every temporary file that a write in progress has made, and
/// returns how many were removed. For a program about to stop on a signal;
/// it waits for an [`uninterrupted`] group of renames to end, and keeps
/// the commit lock so that none starts after it (the program is ending).
/// With no write in progress it removes nothing (0).
pub fn remove_pending() -> usize {
    let guard = lock(&COMMIT);
    std::mem::forget(guard);
    let list = std::mem::take(&mut *lock(&PENDING));
    list.iter()
        .filter(|p| std::fs::remove_file(p).is_ok())
        .count()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_registered_file_is_listed_until_dropped() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join(".slider-crank-x");
        std::fs::write(&path, "x").unwrap();
        let pending = Pending::new(&path);
        assert!(lock(&PENDING).contains(&path));
        drop(pending);
        assert!(!lock(&PENDING).contains(&path));
        assert!(path.exists(), "dropping does not remove the file");
    }
}
