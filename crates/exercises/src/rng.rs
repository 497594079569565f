//! A tiny deterministic pseudo-random generator: SplitMix64 (Steele, Lea and Flood, 2014).
//!
//! The same seed gives the same stream on every platform and in every build, which is what
//! makes `cagd generate --seed S` reproducible byte for byte. No external crate, no global
//! state.

/// SplitMix64: a 64-bit state advanced by the golden-ratio increment, then mixed.
#[derive(Debug, Clone)]
pub(crate) struct Rng(u64);

const GOLDEN: u64 = 0x9E37_79B9_7F4A_7C15;

/// The SplitMix64 finalizer: a bijection of u64 that spreads every input bit.
fn mix(mut z: u64) -> u64 {
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// FNV-1a of a string, to give each topic its own stream for the same seed.
fn fnv1a(s: &str) -> u64 {
    s.bytes().fold(0xCBF2_9CE4_8422_2325, |h, b| {
        (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01B3)
    })
}

impl Rng {
    /// A generator started at `seed`.
    #[cfg(test)]
    pub(crate) fn new(seed: u64) -> Self {
        Rng(seed)
    }

    /// The stream of problem `index` of `topic` for `seed`: independent of the count, so
    /// that the first problems of a longer set are the problems of a shorter one.
    pub(crate) fn for_problem(seed: u64, topic: &str, index: usize) -> Self {
        let base = mix(seed ^ mix(fnv1a(topic)));
        Rng(mix(
            base ^ mix((index as u64).wrapping_add(1).wrapping_mul(GOLDEN))
        ))
    }

    /// The next 64 random bits.
    pub(crate) fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(GOLDEN);
        mix(self.0)
    }

    /// A number in `0..n` (0 when `n` is 0), by Lemire's multiply-shift.
    pub(crate) fn below(&mut self, n: u64) -> u64 {
        ((u128::from(self.next_u64()) * u128::from(n)) >> 64) as u64
    }

    /// An integer in `lo..=hi` (`lo` when the range is empty).
    pub(crate) fn range(&mut self, lo: i64, hi: i64) -> i64 {
        if hi <= lo {
            return lo;
        }
        lo + self.below(hi.abs_diff(lo) + 1) as i64
    }

    /// True with probability `num / den`.
    pub(crate) fn chance(&mut self, num: u64, den: u64) -> bool {
        self.below(den) < num
    }

    /// One of the `N` items (`N >= 1`, checked when it is compiled).
    // The index is below N, and N >= 1 is a compile-time assertion: it cannot fail.
    #[allow(clippy::indexing_slicing)]
    pub(crate) fn pick<T: Clone, const N: usize>(&mut self, items: &[T; N]) -> T {
        const { assert!(N > 0, "pick needs at least one item") }
        let i = self.below(N as u64) as usize;
        items[i.min(N - 1)].clone()
    }

    /// An item of a slice, or `None` when it is empty.
    pub(crate) fn choose<'a, T>(&mut self, items: &'a [T]) -> Option<&'a T> {
        items.get(self.below(items.len() as u64) as usize)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn splitmix64_reference_values() {
        // Reference outputs of SplitMix64 seeded with 0 (Vigna's splitmix64.c).
        let mut r = Rng::new(0);
        assert_eq!(r.next_u64(), 0xE220_A839_7B1D_CDAF);
        assert_eq!(r.next_u64(), 0x6E78_9E6A_A1B9_65F4);
        assert_eq!(r.next_u64(), 0x06C4_5D18_8009_454F);
    }

    #[test]
    fn ranges_stay_inside_and_cover() {
        let mut r = Rng::new(42);
        let mut seen = [false; 7];
        for _ in 0..500 {
            let x = r.range(-3, 3);
            assert!((-3..=3).contains(&x));
            seen[(x + 3) as usize] = true;
        }
        assert!(
            seen.iter().all(|s| *s),
            "every value of -3..=3 drawn: {seen:?}"
        );
        assert_eq!(r.range(5, 5), 5);
        assert_eq!(r.below(0), 0);
        assert!(r.choose::<u8>(&[]).is_none());
    }

    #[test]
    fn problem_streams_differ_by_topic_seed_and_index() {
        let a = Rng::for_problem(1, "restrict", 0).next_u64();
        assert_eq!(a, Rng::for_problem(1, "restrict", 0).next_u64());
        assert_ne!(a, Rng::for_problem(2, "restrict", 0).next_u64());
        assert_ne!(a, Rng::for_problem(1, "elevate", 0).next_u64());
        assert_ne!(a, Rng::for_problem(1, "restrict", 1).next_u64());
    }
}
