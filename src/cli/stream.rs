//! Long outputs computed on every core and written in order: a sweep's
//! angles are cut into chunks, each chunk computed (and, for JSON,
//! serialised) by a thread of its own, and the chunks written one after
//! another, so that the bytes are those of one thread doing it all while
//! memory stays a few chunks whatever the number of angles.

use super::output::Stdout;
use slider_crank::table::{self, Format, Head};
use slider_crank::{Error, Result};

/// Angles a thread takes at a time: large enough that starting threads
/// costs nothing beside the work, small enough that the chunks held at
/// once (one a thread, about two kilobytes of JSON an angle) stay small.
const CHUNK: usize = 1024;

/// The threads to use: the machine's cores, asked once (at most 8).
fn threads() -> usize {
    static THREADS: std::sync::OnceLock<usize> = std::sync::OnceLock::new();
    *THREADS.get_or_init(|| std::thread::available_parallelism().map_or(1, |n| n.get().min(8)))
}

/// `work` applied to each chunk of `angles`, several chunks at once, each
/// writing into a buffer of its own (kept from chunk to chunk so that its
/// memory is not asked of the system again: `work` clears it), the
/// buffers handed to `take` in the order of the angles; stops at the
/// first error of `work` or `take` (the chunks before it taken).
fn in_chunks<T: Default + Send>(
    angles: impl Iterator<Item = f64>,
    work: impl Fn(&[f64], &mut T) -> Result<()> + Sync,
    mut take: impl FnMut(&T) -> Result<()>,
) -> Result<()> {
    let mut angles = angles.peekable();
    let mut buffers: Vec<(Vec<f64>, T)> = (0..threads())
        .map(|_| (Vec::with_capacity(CHUNK), T::default()))
        .collect();
    while angles.peek().is_some() {
        for (chunk, _) in &mut buffers {
            chunk.clear();
            chunk.extend(angles.by_ref().take(CHUNK));
        }
        let work = &work;
        let results: Vec<Result<()>> = std::thread::scope(|scope| {
            let mut jobs = buffers.iter_mut().filter(|(c, _)| !c.is_empty());
            let first = jobs.next();
            let others: Vec<_> = jobs
                .map(|(c, out)| scope.spawn(move || work(c, out)))
                .collect();
            let mut results = Vec::with_capacity(threads());
            results.extend(first.map(|(c, out)| work(c, out)));
            for handle in others {
                results.push(
                    handle
                        .join()
                        .unwrap_or_else(|e| std::panic::resume_unwind(e)),
                );
            }
            results
        });
        let filled = buffers.iter().filter(|(c, _)| !c.is_empty());
        for (r, (_, out)) in results.into_iter().zip(filled) {
            r?;
            take(out)?;
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
        |chunk, _: &mut ()| chunk.iter().try_for_each(|&d| compute(d).map(drop)),
        |_| Ok(()),
    )
}

/// Writes one pretty JSON array of `object(angle)` for every angle of
/// `angles` to `out`, byte for byte `serde_json::to_string_pretty` of the
/// whole array: each object is serialised as the one element of an array
/// (so indented as `to_string_pretty` indents an array's elements), the
/// elements joined by `,\n` between `[\n` and `\n]`. No angle: `[]`.
pub fn json_array<T: serde::Serialize>(
    angles: impl Iterator<Item = f64>,
    object: impl Fn(f64) -> Result<T> + Sync,
    out: &mut Stdout,
) -> Result<()> {
    let mut first = true;
    in_chunks(
        angles,
        |chunk, text: &mut Vec<u8>| {
            text.clear();
            // Each object as the one element of an array, "[\n" + its
            // lines indented + "\n]", kept without the brackets.
            let mut one = Vec::new();
            for (i, &d) in chunk.iter().enumerate() {
                one.clear();
                serde_json::to_writer_pretty(&mut one, &[object(d)?]).map_err(json_error)?;
                if i > 0 {
                    text.extend_from_slice(b",\n");
                }
                text.extend_from_slice(one.get(2..one.len().saturating_sub(2)).unwrap_or_default());
            }
            Ok(())
        },
        |elements| {
            out.text(if first { "[\n" } else { ",\n" })?;
            first = false;
            out.bytes(elements)
        },
    )?;
    out.text(if first { "[]" } else { "\n]" })
}

/// Writes a table of one row, `row(angle)`, for every angle `angles()`
/// gives, as [`table::render_rows`] writes it (the same bytes): a first
/// pass over the angles finds the columns' widths and any error (nothing is
/// written when a row fails), a second writes the rows; each pass on every
/// core, a chunk of rows a thread.
pub fn table<A: Iterator<Item = f64>>(
    format: Format,
    head: &Head,
    angles: impl Fn() -> A,
    row: impl Fn(f64) -> Result<Vec<String>> + Sync,
    out: &mut Stdout,
) -> Result<()> {
    let mut widths = table::header_widths(head);
    in_chunks(
        angles(),
        |chunk, chunk_widths: &mut Vec<usize>| {
            chunk_widths.clear();
            chunk_widths.resize(head.headers.len(), 0);
            for &d in chunk {
                table::widen(chunk_widths, &row(d)?);
            }
            Ok(())
        },
        |chunk_widths| {
            for (w, c) in widths.iter_mut().zip(chunk_widths) {
                *w = (*w).max(*c);
            }
            Ok(())
        },
    )?;
    out.text(&table::head_text(format, head, &widths))?;
    let widths = &widths;
    in_chunks(
        angles(),
        |chunk, text: &mut String| {
            text.clear();
            for &d in chunk {
                table::push_row(format, &row(d)?, widths, text);
            }
            Ok(())
        },
        |text| out.text(text),
    )?;
    out.text(&table::tail_text(format, head))
}

fn json_error(e: serde_json::Error) -> Error {
    Error::Io {
        message: e.to_string(),
        path: None,
        source: Some(std::sync::Arc::new(e.into())),
    }
}
