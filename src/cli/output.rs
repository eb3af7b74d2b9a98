//! Standard output, written so that every failure is seen.
//!
//! A closed standard output (`>&-`) would otherwise swallow everything
//! (the Rust runtime puts `/dev/null` in its place, and the standard
//! library takes EBADF on standard output for success); here it is an
//! error before any work, and a full device (`>/dev/full`) or a reader
//! that went away is an error when written or flushed. Output goes
//! through a duplicate of descriptor 1, so that every write error is
//! seen.

use slider_crank::{Error, Result};
use std::io::{BufWriter, ErrorKind, IsTerminal, Write};

/// The program's standard output, buffered.
pub struct Stdout {
    inner: BufWriter<Box<dyn Write>>,
    /// The kind of the first write error, if any.
    failed: Option<ErrorKind>,
}

impl Stdout {
    /// Takes hold of standard output; errors when it is closed.
    pub fn open() -> std::io::Result<Self> {
        Ok(Self {
            inner: BufWriter::with_capacity(1 << 16, raw()?),
            failed: None,
        })
    }

    /// Writes `text`; an error names standard output.
    pub fn text(&mut self, text: &str) -> Result<()> {
        self.bytes(text.as_bytes())
    }

    /// Writes `bytes`; an error names standard output.
    pub fn bytes(&mut self, bytes: &[u8]) -> Result<()> {
        let result = self.inner.write_all(bytes);
        self.check(result)
    }

    /// Flushes everything written; call once at the end.
    pub fn finish(&mut self) -> Result<()> {
        let result = self.inner.flush();
        self.check(result)
    }

    /// Whether writing failed because the reader closed the pipe.
    pub fn broken_pipe(&self) -> bool {
        self.failed == Some(ErrorKind::BrokenPipe)
    }

    fn check(&mut self, result: std::io::Result<()>) -> Result<()> {
        result.map_err(|e| {
            self.failed.get_or_insert(e.kind());
            Error::Io {
                message: format!("cannot write to standard output: {e}"),
                path: None,
                source: Some(std::sync::Arc::new(e)),
            }
        })
    }
}

#[cfg(unix)]
fn raw() -> std::io::Result<Box<dyn Write>> {
    use std::os::fd::AsFd;
    // A descriptor closed and never replaced (a runtime that leaves it
    // closed) cannot be duplicated: EBADF.
    let fd = match std::io::stdout().as_fd().try_clone_to_owned() {
        Ok(fd) => fd,
        Err(e) if e.raw_os_error() == Some(EBADF) => return Err(closed()),
        Err(e) => return Err(e),
    };
    // The null device, however it was opened (`>/dev/null`, `1<>/dev/null`,
    // Python's subprocess.DEVNULL, nohup, a service manager, or the
    // runtime's replacement of a closed descriptor before `main`), is a
    // sink: written to, and the output gone, as asked.
    Ok(Box::new(std::fs::File::from(fd)))
}

/// EBADF, the same number on every Unix.
#[cfg(unix)]
const EBADF: i32 = 9;

#[cfg(unix)]
fn closed() -> std::io::Error {
    std::io::Error::other("it was closed (>&-)")
}

#[cfg(not(unix))]
fn raw() -> std::io::Result<Box<dyn Write>> {
    Ok(Box::new(std::io::stdout()))
}

/// Writes `line` and a line break to standard error, the paths and names
/// in it as [`Error::printable`] shows them (an escape sequence in a
/// directory's name is not played on the terminal). A standard error
/// that cannot be written (full, closed) is ignored: the exit code still
/// tells the outcome, and a message is no reason to panic.
pub fn say(line: &str) {
    let _ = writeln!(std::io::stderr(), "{}", Error::printable(line));
}

/// The progress line on standard error: rewritten in place on a terminal,
/// one line per file otherwise.
pub struct Progress {
    what: &'static str,
    total: usize,
    terminal: bool,
}

impl Progress {
    /// A progress line for `total` steps, each line starting with `what:`.
    pub fn new(what: &'static str, total: usize) -> Self {
        Progress {
            what,
            total,
            terminal: std::io::stderr().is_terminal(),
        }
    }

    /// Shows step `done` of the total, on `name` (as [`Error::printable`]
    /// shows it).
    pub fn show(&mut self, done: usize, name: &str) {
        let name = Error::printable(name);
        let mut err = std::io::stderr().lock();
        // Progress is a courtesy: a standard error that cannot be written
        // does not stop the work.
        let _ = if self.terminal {
            write!(err, "\r\x1b[2K{}: {done}/{} {name}", self.what, self.total)
                .and_then(|()| err.flush())
        } else {
            writeln!(err, "{}: {done}/{} {name}", self.what, self.total)
        };
    }

    /// Ends the line on a terminal.
    pub fn finish(&mut self) {
        if self.terminal {
            let _ = writeln!(std::io::stderr());
        }
    }
}
