//! The characteristic of a field of coefficients, validated once: [`Prime`] is a prime
//! below 2^31 (so that a product of two residues fits in 64 bits), and every computation
//! over `Z/p` (homology, generators, persistence) and the facade take their `p` through it.

/// Whether `p` is a prime. O(sqrt p).
pub fn is_prime(p: u64) -> bool {
    if p < 2 {
        return false;
    }
    let mut d = 2u64;
    while d.saturating_mul(d) <= p {
        if p.is_multiple_of(d) {
            return false;
        }
        d += 1;
    }
    true
}

/// A prime below 2^31: the characteristic of a field `Z/p` of coefficients.
///
/// ```
/// use gmap_homology::Prime;
/// assert_eq!(Prime::new(3).map(Prime::get), Some(3));
/// assert!(Prime::new(4).is_none());
/// assert!(Prime::new((1 << 31) + 11).is_none()); // a prime, but too large
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Prime(u32);

impl Prime {
    /// Every valid characteristic is below this bound.
    pub const BOUND: u64 = 1 << 31;

    /// `p` as a field's characteristic, `None` when it is not a prime below
    /// [`Prime::BOUND`]. O(sqrt p).
    pub fn new(p: u64) -> Option<Prime> {
        (p < Prime::BOUND && is_prime(p)).then_some(Prime(p as u32))
    }

    /// The prime.
    pub fn get(self) -> u64 {
        u64::from(self.0)
    }
}

impl std::fmt::Display for Prime {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        self.0.fmt(f)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn primes_below_the_bound() {
        let small: Vec<u64> = (0..30).filter(|&p| Prime::new(p).is_some()).collect();
        assert_eq!(small, [2, 3, 5, 7, 11, 13, 17, 19, 23, 29]);
        assert_eq!(Prime::new(2_147_483_647).map(Prime::get), Some(2_147_483_647)); // 2^31 - 1
        assert!(Prime::new(1 << 31).is_none());
        assert!(Prime::new(u64::MAX).is_none());
    }
}
