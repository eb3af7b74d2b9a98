//! The random numbers that choose a class's engines: SplitMix64.
//!
//! A class made from a seed S must be the same class on every machine and
//! with every future build of the program, so that a teacher can make the
//! sheets again from the seed alone. A random-number crate promises no
//! such thing across its versions (`rand`'s `StdRng` says its stream may
//! change in any release), so the generator is written out here:
//! SplitMix64 (Steele, Lea and Flood, "Fast splittable pseudorandom number
//! generators", OOPSLA 2014; the constants are those of Java's
//! `SplittableRandom` and of Vigna's reference C code). Its stream is
//! fixed by these few lines, which a test pins to published values.

/// The SplitMix64 generator: a 64-bit state advanced by a fixed odd
/// constant and mixed into each output.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SplitMix64 {
    state: u64,
}

impl SplitMix64 {
    /// The generator seeded with `seed` (every seed is valid, 0 included).
    pub fn new(seed: u64) -> Self {
        Self { state: seed }
    }

    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.state = self.state.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.state;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// A whole number in `0..n`, each equally likely (Lemire's multiply
    /// and reject, so that no value is favoured); `n` must be positive.
    pub fn below(&mut self, n: u64) -> u64 {
        assert!(n > 0, "below(0) has no value to give");
        let threshold = n.wrapping_neg() % n;
        loop {
            let m = u128::from(self.next_u64()) * u128::from(n);
            if (m as u64) >= threshold {
                return (m >> 64) as u64;
            }
        }
    }

    /// One of `items`, each equally likely; `items` must not be empty.
    // cannot fail: `below(n)` is less than n, and for an empty `items` its
    // assertion stops first (the class draws from non-empty lists).
    #[allow(clippy::indexing_slicing)]
    pub fn pick<T: Copy>(&mut self, items: &[T]) -> T {
        items[self.below(items.len() as u64) as usize]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_stream_is_the_reference_one() {
        // Vigna's splitmix64.c seeded with 1234567.
        let mut g = SplitMix64::new(1234567);
        let first: Vec<u64> = (0..5).map(|_| g.next_u64()).collect();
        assert_eq!(
            first,
            [
                6457827717110365317,
                3203168211198807973,
                9817491932198370423,
                4593380528125082431,
                16408922859458223821,
            ]
        );
    }

    #[test]
    fn below_stays_below_and_reaches_every_value() {
        let mut g = SplitMix64::new(7);
        let mut seen = [false; 7];
        for _ in 0..1000 {
            let v = g.below(7) as usize;
            seen[v] = true;
        }
        assert!(seen.iter().all(|&s| s));
        assert_eq!(SplitMix64::new(3).pick(&[42]), 42);
    }
}
