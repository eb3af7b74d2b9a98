//! Standard output, written so that every failure is seen.
//!
//! A closed standard output (`>&-`) would otherwise swallow everything
//! (the Rust runtime puts `/dev/null` in its place); here it is an error
//! before any work, and a full device (`>/dev/full`) or a reader that went
//! away is an error when written.

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
    if closed_at_start() {
        return Err(std::io::Error::other("it was closed (>&-)"));
    }
    let fd = std::io::stdout().as_fd().try_clone_to_owned()?;
    Ok(Box::new(std::fs::File::from(fd)))
}

/// Whether descriptor 1 was closed when the program started. The Rust
/// runtime opens `/dev/null` read-write on a closed standard descriptor
/// before `main`; a shell's `>/dev/null` opens it write-only, so the two
/// can be told apart (Linux: `/proc/self/fdinfo`).
#[cfg(unix)]
fn closed_at_start() -> bool {
    if !cfg!(target_os = "linux") {
        return false;
    }
    let null =
        std::fs::read_link("/proc/self/fd/1").is_ok_and(|p| p == std::path::Path::new("/dev/null"));
    let flags = std::fs::read_to_string("/proc/self/fdinfo/1")
        .ok()
        .and_then(|info| {
            let line = info.lines().find(|l| l.starts_with("flags:"))?;
            u32::from_str_radix(line["flags:".len()..].trim(), 8).ok()
        });
    // O_ACCMODE = 3, O_RDWR = 2.
    null && flags.is_some_and(|f| f & 3 == 2)
}

#[cfg(not(unix))]
fn raw() -> std::io::Result<Box<dyn Write>> {
    Ok(Box::new(std::io::stdout()))
}
