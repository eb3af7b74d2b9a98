//! Long outputs computed on every core and written in order: a sweep's
//! angles are cut into chunks, each chunk computed (and, for JSON,
//! serialised) by a thread of its own, and the chunks written one after
//! another, so that the bytes are those of one thread doing it all while
//! memory stays a few chunks whatever the number of angles.

use super::output::Stdout;
use slider_crank::{Error, Result};

/// Angles a thread takes at a time: large enough that starting threads
/// costs nothing beside the work, small enough that the chunks held at
/// once (one a thread) stay a few megabytes of text.
const CHUNK: usize = 2048;

/// The threads to use: the machine's cores, asked once (at most 8).
fn threads() -> usize {
    static THREADS: std::sync::OnceLock<usize> = std::sync::OnceLock::new();
    *THREADS.get_or_init(|| std::thread::available_parallelism().map_or(1, |n| n.get().min(8)))
}

/// `work` applied to each chunk of `angles`, several chunks at once, the
/// results handed to `take` in the order of the angles; stops at the
/// first error of `work` or `take` (the chunks before it taken).
fn in_chunks<T: Send>(
    angles: impl Iterator<Item = f64>,
    work: impl Fn(&[f64]) -> Result<T> + Sync,
    mut take: impl FnMut(T) -> Result<()>,
) -> Result<()> {
    let mut angles = angles.peekable();
    while angles.peek().is_some() {
        let batch: Vec<Vec<f64>> = (0..threads())
            .map(|_| angles.by_ref().take(CHUNK).collect::<Vec<f64>>())
            .filter(|c| !c.is_empty())
            .collect();
        let work = &work;
        let results: Vec<Result<T>> = std::thread::scope(|scope| {
            let mut chunks = batch.iter();
            let first = chunks.next();
            let others: Vec<_> = chunks.map(|c| scope.spawn(move || work(c))).collect();
            let mut results = Vec::with_capacity(batch.len());
            results.extend(first.map(|c| work(c)));
            for handle in others {
                results.push(
                    handle
                        .join()
                        .unwrap_or_else(|e| std::panic::resume_unwind(e)),
                );
            }
            results
        });
        for r in results {
            take(r?)?;
        }
    }
    Ok(())
}

/// Checks that `compute` succeeds at every angle of `angles`, on every
/// core: the first error in the angles' order.
pub fn check_all<T>(
    angles: impl Iterator<Item = f64>,
    compute: impl Fn(f64) -> Result<T> + Sync,
) -> Result<()> {
    in_chunks(
        angles,
        |chunk| chunk.iter().try_for_each(|&d| compute(d).map(drop)),
        |()| Ok(()),
    )
}

/// Writes one pretty JSON array of `object(angle)` for every angle of
/// `angles` to `out`, byte for byte `serde_json::to_string_pretty` of the
/// whole array: each chunk is serialised as an array of its own and its
/// elements' lines (indented as in the whole) written between the
/// brackets. No angle: `[]`.
pub fn json_array<T: serde::Serialize>(
    angles: impl Iterator<Item = f64>,
    object: impl Fn(f64) -> Result<T> + Sync,
    out: &mut Stdout,
) -> Result<()> {
    let mut first = true;
    in_chunks(
        angles,
        |chunk| {
            let objects = chunk
                .iter()
                .map(|&d| object(d))
                .collect::<Result<Vec<T>>>()?;
            let text = serde_json::to_vec_pretty(&objects).map_err(json_error)?;
            // "[\n" + the elements + "\n]": the elements alone.
            Ok(text
                .get(2..text.len().saturating_sub(2))
                .unwrap_or_default()
                .to_vec())
        },
        |elements| {
            out.text(if first { "[\n" } else { ",\n" })?;
            first = false;
            out.bytes(&elements)
        },
    )?;
    out.text(if first { "[]" } else { "\n]" })
}

fn json_error(e: serde_json::Error) -> Error {
    Error::Io {
        message: e.to_string(),
        path: None,
        source: Some(std::sync::Arc::new(e.into())),
    }
}
