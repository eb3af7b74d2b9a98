//! The longest run along a line clear of what stands on it: where a
//! bar's letter goes (the Coriolis mechanism's d and b, the inversions'
//! turning bar d).

/// The longest run of `(from, to)` (along a bar, page units from its
/// start) clear of every `taken` stretch; `None` where none is longer
/// than nothing (an empty run between two stretches that meet gives no
/// room for a letter).
pub(super) fn longest_clear_run(
    taken: &[(f64, f64)],
    (from, to): (f64, f64),
) -> Option<(f64, f64)> {
    let mut cuts: Vec<f64> = vec![from, to];
    cuts.extend(taken.iter().flat_map(|(lo, hi)| [*lo, *hi]));
    let mut cuts: Vec<f64> = cuts.into_iter().map(|x| x.clamp(from, to)).collect();
    cuts.sort_by(f64::total_cmp);
    let free = |x: f64| taken.iter().all(|(lo, hi)| x < *lo || x > *hi);
    (cuts.iter().copied())
        .zip(cuts.iter().copied().skip(1))
        .filter(|(lo, hi)| hi > lo && free(0.5 * (lo + hi)))
        .max_by(|x, y| (x.1 - x.0).total_cmp(&(y.1 - y.0)))
}

#[cfg(test)]
mod tests {
    use super::longest_clear_run;

    #[test]
    fn the_longest_free_run_is_found_and_an_empty_one_never() {
        // Free: 0–2, 5–6, 8–10; the longest of equal ones is the last.
        let taken = [(2.0, 5.0), (6.0, 8.0)];
        assert_eq!(longest_clear_run(&taken, (0.0, 10.0)), Some((8.0, 10.0)));
        let taken = [(-1.0, 3.0), (4.0, 11.0)];
        assert_eq!(longest_clear_run(&taken, (0.0, 10.0)), Some((3.0, 4.0)));
        // Two stretches that meet, covering the bar: no room at all,
        // not the empty run where they meet.
        let taken = [(-1.0, 5.0), (5.0, 11.0)];
        assert_eq!(longest_clear_run(&taken, (0.0, 10.0)), None);
        assert_eq!(longest_clear_run(&[], (0.0, 10.0)), Some((0.0, 10.0)));
    }
}
