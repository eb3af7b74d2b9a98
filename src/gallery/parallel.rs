//! Work done on several threads and taken in order: the gallery's
//! figures are made on every core, its files written (and its progress
//! shown) in the order of the catalogue.

use crate::error::Result;
use std::collections::BTreeMap;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::mpsc;

/// Runs `make` on every job on `threads` threads (at least one), and
/// `take` on each result on the calling thread in the order of `jobs`, as
/// soon as it and those before it are ready. Stops at the first error, of
/// `make` or `take`, in that order: no job after it is taken, and no new
/// job is started (the ones running finish and are dropped). With no
/// jobs, does nothing.
pub(super) fn in_order<J: Sync, T: Send>(
    jobs: &[J],
    threads: usize,
    make: impl Fn(&J) -> Result<T> + Sync,
    mut take: impl FnMut(T) -> Result<()>,
) -> Result<()> {
    let next = AtomicUsize::new(0);
    let stop = AtomicBool::new(false);
    std::thread::scope(|scope| {
        let (send, receive) = mpsc::channel();
        for _ in 0..threads.max(1).min(jobs.len()) {
            let send = send.clone();
            let (next, stop, make) = (&next, &stop, &make);
            scope.spawn(move || {
                while !stop.load(Ordering::Relaxed) {
                    let i = next.fetch_add(1, Ordering::Relaxed);
                    let Some(job) = jobs.get(i) else { break };
                    // The receiver is gone only after an error: then
                    // nothing more is wanted.
                    if send.send((i, make(job))).is_err() {
                        break;
                    }
                }
            });
        }
        drop(send);
        let result = take_in_order(jobs.len(), &receive, &mut take);
        stop.store(true, Ordering::Relaxed);
        result
    })
}

/// Receives the `count` results and takes them in order.
fn take_in_order<T>(
    count: usize,
    receive: &mpsc::Receiver<(usize, Result<T>)>,
    take: &mut impl FnMut(T) -> Result<()>,
) -> Result<()> {
    let mut waiting = BTreeMap::new();
    for i in 0..count {
        let result = loop {
            if let Some(r) = waiting.remove(&i) {
                break r;
            }
            // Every sender gone with results missing: a worker panicked,
            // and the scope passes its panic on when it ends.
            let Ok((j, r)) = receive.recv() else {
                return Ok(());
            };
            waiting.insert(j, r);
        };
        take(result?)?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::error::Error;

    #[test]
    fn results_are_taken_in_the_order_of_the_jobs_whatever_the_threads() {
        let jobs: Vec<u64> = (0..40).collect();
        for threads in [1, 2, 3, 8] {
            let mut taken = Vec::new();
            in_order(
                &jobs,
                threads,
                |&j| {
                    // Later jobs finish first.
                    std::thread::sleep(std::time::Duration::from_micros(40 - j));
                    Ok(j * j)
                },
                |r| {
                    taken.push(r);
                    Ok(())
                },
            )
            .unwrap();
            assert_eq!(taken, jobs.iter().map(|j| j * j).collect::<Vec<_>>());
        }
    }

    #[test]
    fn the_first_error_in_order_stops_the_work() {
        let jobs: Vec<u32> = (0..100).collect();
        let mut taken = Vec::new();
        let err = in_order(
            &jobs,
            2,
            |&j| {
                if j == 5 || j == 7 {
                    Err(Error::invalid(
                        crate::error::Input::Options,
                        format!("job {j}"),
                    ))
                } else {
                    Ok(j)
                }
            },
            |r| {
                taken.push(r);
                Ok(())
            },
        )
        .unwrap_err();
        assert_eq!(err.to_string(), "job 5");
        assert_eq!(taken, [0, 1, 2, 3, 4]);
        let err = in_order(
            &jobs,
            3,
            |&j| Ok(j),
            |r| match r {
                3 => Err(Error::invalid(
                    crate::error::Input::Options,
                    "taking 3".into(),
                )),
                _ => Ok(()),
            },
        )
        .unwrap_err();
        assert_eq!(err.to_string(), "taking 3");
        assert!(in_order(&[] as &[u32], 4, |_| Ok(()), |()| Ok(())).is_ok());
    }
}
