//! Reading input files with a bound on their size.
//!
//! Every file the program reads (scene files, manifests, a figure's data
//! CSV) goes through [`read_text`], and the files a gallery's check compares
//! through [`read_bytes_from`]: they read as the file streams and stop one
//! byte past the limit, so `/dev/zero` or a huge file costs at most the
//! limit in memory, and the message names the file and the limit.

use crate::error::{Error, Input, Result};
use std::io::Read;
use std::path::Path;
use std::sync::Arc;

/// Largest scene file read, in bytes (1 MiB: a scene is a few hundred).
pub const MAX_SCENE_BYTES: u64 = 1 << 20;

/// Largest data CSV file read (a figure's data, an indicator diagram), in bytes (4 MiB; the data reader also
/// stops at 100 000 rows).
pub const MAX_DATA_BYTES: u64 = 4 << 20;

/// Reads the UTF-8 text of `path`, at most `limit` bytes, a file of kind
/// `input`, which messages name (`scene file`, `data file`); text that is
/// not UTF-8 is an [`Error::Invalid`] about `input`.
///
/// Errors: the file cannot be opened or read (a directory, a missing
/// file), it holds more than `limit` bytes (only `limit + 1` are ever
/// read), or it is not UTF-8 text.
pub fn read_text(path: &Path, limit: u64, input: Input) -> Result<String> {
    let shown = path.display();
    let file = std::fs::File::open(path).map_err(|e| Error::Io {
        message: format!("cannot read {input} {shown}: {e}"),
        path: Some(path.to_path_buf()),
        source: Some(Arc::new(e)),
    })?;
    read_text_from(file, limit, input, &format!("{input} {shown}")).map_err(|e| match e {
        Error::Io {
            message, source, ..
        } => Error::Io {
            message,
            path: Some(path.to_path_buf()),
            source,
        },
        e => e,
    })
}

/// [`read_text`] for any reader (standard input, a pipe) of kind `input`;
/// `what` names the source in messages.
pub fn read_text_from(reader: impl Read, limit: u64, input: Input, what: &str) -> Result<String> {
    let bytes = read_bytes_from(reader, limit, what)?;
    String::from_utf8(bytes).map_err(|e| {
        Error::invalid(
            input,
            format!(
                "{what} is not UTF-8 text (byte {})",
                e.utf8_error().valid_up_to()
            ),
        )
    })
}

/// The bytes of `reader`, at most `limit` (only `limit + 1` are ever
/// read); `what` names the source in messages.
///
/// Errors: reading fails, or there are more than `limit` bytes.
pub fn read_bytes_from(reader: impl Read, limit: u64, what: &str) -> Result<Vec<u8>> {
    let mut bytes = Vec::new();
    reader
        .take(limit.saturating_add(1))
        .read_to_end(&mut bytes)
        .map_err(|e| Error::Io {
            message: format!("cannot read {what}: {e}"),
            path: None,
            source: Some(Arc::new(e)),
        })?;
    if bytes.len() as u64 > limit {
        return Err(Error::Io {
            message: format!(
                "{what} is larger than {} (the most this program reads)",
                size(limit)
            ),
            path: None,
            source: None,
        });
    }
    Ok(bytes)
}

/// A byte count as people read it: `1 MiB`, `4 MiB`, `512 bytes`.
fn size(bytes: u64) -> String {
    if bytes >= 1 << 20 && bytes.is_multiple_of(1 << 20) {
        format!("{} MiB", bytes >> 20)
    } else {
        format!("{bytes} bytes")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_missing_file_keeps_its_path_and_the_system_error() {
        let path = Path::new("/nonexistent/scene.toml");
        let e = read_text(path, 10, Input::Scene).unwrap_err();
        assert!(
            e.to_string()
                .starts_with("cannot read scene file /nonexistent/scene.toml: "),
            "{e}"
        );
        let Error::Io {
            path: Some(p),
            source: Some(os),
            ..
        } = &e
        else {
            panic!("{e:?}");
        };
        assert_eq!(p, path);
        assert_eq!(os.kind(), std::io::ErrorKind::NotFound);
        let source = std::error::Error::source(&e).expect("a source");
        assert_eq!(source.to_string(), os.to_string());
        assert_eq!(e.clone(), e);
    }

    #[test]
    fn stops_one_byte_past_the_limit() {
        let endless = std::io::repeat(0);
        let err = read_text_from(endless, 1 << 20, Input::Data, "data file z").unwrap_err();
        assert_eq!(
            err.to_string(),
            "data file z is larger than 1 MiB (the most this program reads)"
        );
        assert_eq!(
            read_text_from(&b"abc"[..], 3, Input::Data, "f").unwrap(),
            "abc"
        );
        assert!(read_text_from(&b"abcd"[..], 3, Input::Data, "f").is_err());
    }

    #[test]
    fn binary_and_missing_files_are_errors() {
        let err = read_text_from(&[0x61, 0xff][..], 10, Input::Scene, "scene file s").unwrap_err();
        assert_eq!(err.to_string(), "scene file s is not UTF-8 text (byte 1)");
        assert!(
            matches!(
                err,
                Error::Invalid {
                    input: Input::Scene,
                    ..
                }
            ),
            "{err:?}"
        );
        let err = read_text(Path::new("/nonexistent/x.toml"), 10, Input::Scene).unwrap_err();
        assert!(
            err.to_string()
                .starts_with("cannot read scene file /nonexistent/x.toml: ")
        );
    }
}
