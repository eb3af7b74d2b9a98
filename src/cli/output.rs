//! Standard output, written so that every failure is seen.
//!
//! Rust's own `stdout()` treats a closed descriptor (`>&-`) as a sink that
//! swallows everything; here the descriptor is duplicated at start, so a
//! closed standard output is an error before any work, and a full device
//! (`>/dev/full`) or a reader that went away is an error when written.

use slider_crank::{Error, Result};
use std::io::{BufWriter, ErrorKind, Write};

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
            Error::Io(format!("cannot write to standard output: {e}"))
        })
    }
}

#[cfg(unix)]
fn raw() -> std::io::Result<Box<dyn Write>> {
    use std::os::fd::AsFd;
    // Duplicating fails with EBADF when descriptor 1 is closed.
    let fd = std::io::stdout().as_fd().try_clone_to_owned()?;
    Ok(Box::new(std::fs::File::from(fd)))
}

#[cfg(not(unix))]
fn raw() -> std::io::Result<Box<dyn Write>> {
    Ok(Box::new(std::io::stdout()))
}
