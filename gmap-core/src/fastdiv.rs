//! Division by a divisor fixed in advance, with a multiplication: the cubical routes turn
//! grid points into coordinates millions of times (a cell's neighbours, the names of the
//! cells of a cycle), and a hardware division costs several times a multiplication.
//!
//! The method is Lemire, Kaser and Kurz's ("Faster remainder by direct computation",
//! Software: Practice and Experience, 2019): for a 32-bit divisor `d`, `m = ⌊(2^64 − 1) / d⌋
//! + 1` and `n / d = ⌊m · n / 2^64⌋` for every 32-bit `n`.
//!
//! ```
//! use gmap_core::fastdiv::Divider;
//! let by_7 = Divider::new(7).unwrap();
//! assert_eq!(by_7.quotient(100), 14);
//! assert_eq!(by_7.remainder(100), 2);
//! ```

/// Division of numbers below `2^32` by a fixed divisor in `1..2^32`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Divider {
    d: u64,
    /// `⌊(2^64 − 1) / d⌋ + 1`, 0 for `d = 1`
    m: u64,
}

impl Divider {
    /// The divider by `d`; `None` for 0 or a divisor past `u32`.
    pub fn new(d: usize) -> Option<Self> {
        let d = u32::try_from(d).ok().filter(|&d| d > 0)? as u64;
        Some(Divider { d, m: (u64::MAX / d).wrapping_add(1) })
    }

    /// The divisor.
    pub fn divisor(self) -> usize {
        self.d as usize
    }

    /// `n / d`. Precondition: `n < 2^32` (debug builds check it).
    #[inline]
    pub fn quotient(self, n: usize) -> usize {
        debug_assert!(n <= u32::MAX as usize, "{n} is past u32");
        if self.m == 0 {
            n
        } else {
            ((u128::from(self.m) * n as u128) >> 64) as usize
        }
    }

    /// `n % d`, with the precondition of [`Divider::quotient`].
    #[inline]
    pub fn remainder(self, n: usize) -> usize {
        n - self.quotient(n) * self.d as usize
    }
}

#[cfg(test)]
mod tests {
    use super::Divider;

    /// The multiplication gives the quotient of every `u32` by the divisors a grid has,
    /// checked at the ends of the range and around the multiples.
    #[test]
    fn divider_equals_division() {
        for d in [1usize, 2, 3, 7, 255, 257, 513, 1025, 65_535, 263_169, 16_581_375, u32::MAX as usize] {
            let div = Divider::new(d).unwrap();
            let mut ns = vec![0usize, 1, u32::MAX as usize - 1, u32::MAX as usize];
            for k in [1usize, 2, 3, 1000, (u32::MAX as usize) / d] {
                let m = k * d;
                ns.extend([m.saturating_sub(1), m, m + 1].into_iter().filter(|&n| n <= u32::MAX as usize));
            }
            for n in ns {
                assert_eq!((div.quotient(n), div.remainder(n)), (n / d, n % d), "{n} / {d}");
            }
        }
        assert!(Divider::new(0).is_none());
        assert!(Divider::new(u32::MAX as usize + 1).is_none());
    }
}
