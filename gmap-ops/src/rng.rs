//! A small seeded random generator: the random choices of the workspace (the orders and
//! splits of [`crate::euler::simplify()`], random Euler operators in tests and benches) come
//! from it, so a seed gives the same result on every machine and in every build.
//!
//! [`SplitMix64`] is Steele, Lea and Flood's SplitMix64: a 64-bit counter advanced by the
//! golden-ratio increment and mixed by two xor-shift-multiply rounds. It passes the usual
//! statistical batteries and costs a few cycles per number; it is not cryptographic.
//!
//! ```
//! use gmap_ops::rng::SplitMix64;
//! let mut a = SplitMix64::new(7);
//! let mut b = SplitMix64::new(7);
//! assert_eq!(a.next_u64(), b.next_u64()); // same seed, same numbers
//! let k = a.below(6);
//! assert!(k < 6);
//! let mut v: Vec<u32> = (0..10).collect();
//! a.shuffle(&mut v);
//! v.sort_unstable();
//! assert_eq!(v, (0..10).collect::<Vec<u32>>());
//! ```

/// SplitMix64: a seeded, deterministic generator of 64-bit numbers. See the
/// [module docs](self).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SplitMix64 {
    state: u64,
}

impl SplitMix64 {
    /// The generator started at `seed` (every seed, 0 included, is fine).
    pub fn new(seed: u64) -> Self {
        SplitMix64 { state: seed }
    }

    /// The next number, uniform over `u64`.
    pub fn next_u64(&mut self) -> u64 {
        self.state = self.state.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.state;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// A number in `0..n`, as the next number modulo `n` (the bias, below `n / 2^64`, does
    /// not matter for the sizes used here).
    ///
    /// # Panics
    /// If `n` is 0.
    pub fn below(&mut self, n: usize) -> usize {
        assert!(n > 0, "below(0): no number to choose");
        (self.next_u64() % n as u64) as usize
    }

    /// Shuffles `v` in place (Fisher–Yates, from the end). O(len).
    pub fn shuffle<T>(&mut self, v: &mut [T]) {
        for k in (1..v.len()).rev() {
            let j = self.below(k + 1);
            v.swap(k, j);
        }
    }
}
