//! Coefficient rings for the reduction: `Z` with checked `i64` arithmetic, `Z` with big
//! integers (the fall-back when `i64` overflows), and the prime fields `Z/p`.
//!
//! Every operation that can overflow returns `Option`; `None` means "redo this computation
//! with big integers", never a silently wrong value.

use std::cmp::Ordering;
use std::fmt::Debug;

use num_bigint::BigInt;

use crate::engine::natural::Natural;
use num_traits::{One, Signed, ToPrimitive, Zero};

/// The operations the sparse elimination needs from a coefficient ring.
pub(crate) trait Ring {
    /// An element.
    type E: Clone + PartialEq + Debug;
    /// The image of an integer.
    fn of_i64(&self, v: i64) -> Self::E;
    /// Whether `a` is zero.
    fn is_zero(&self, a: &Self::E) -> bool;
    /// Whether `a` is invertible.
    fn is_unit(&self, a: &Self::E) -> bool;
    /// `a / u` for a unit `u`.
    fn div_unit(&self, a: &Self::E, u: &Self::E) -> Option<Self::E>;
    /// `a - l * b`.
    fn sub_mul(&self, a: &Self::E, l: &Self::E, b: &Self::E) -> Option<Self::E>;
    /// Whether every non-zero integer stays non-zero in the ring (`Z`: yes; `Z/p`: no), so
    /// the stored entries of a matrix need no check for zero.
    fn keeps_nonzero_integers(&self) -> bool {
        false
    }
}

/// The operations dense Smith normal form needs in addition: a Euclidean ring (`Z` only).
pub(crate) trait Euclid: Ring {
    /// Quotient and remainder with `|r| < |b|`.
    fn div_rem(&self, a: &Self::E, b: &Self::E) -> Option<(Self::E, Self::E)>;
    /// Compares absolute values.
    fn abs_cmp(&self, a: &Self::E, b: &Self::E) -> Ordering;
    /// `a + b`.
    fn add(&self, a: &Self::E, b: &Self::E) -> Option<Self::E>;
    /// `a` as an `i64` (over `Z/p`: its representative in `0..p`), if it fits.
    fn to_i64(&self, a: &Self::E) -> Option<i64>;
    /// `|a|` exactly (over `Z/p`: the representative in `0..p`).
    fn abs_natural(&self, a: &Self::E) -> Natural;
}

/// `Z` with checked `i64` arithmetic.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Zi64;

impl Ring for Zi64 {
    type E = i64;
    fn of_i64(&self, v: i64) -> i64 {
        v
    }
    fn is_zero(&self, a: &i64) -> bool {
        *a == 0
    }
    fn is_unit(&self, a: &i64) -> bool {
        *a == 1 || *a == -1
    }
    fn div_unit(&self, a: &i64, u: &i64) -> Option<i64> {
        a.checked_mul(*u)
    }
    fn sub_mul(&self, a: &i64, l: &i64, b: &i64) -> Option<i64> {
        a.checked_sub(l.checked_mul(*b)?)
    }
    fn keeps_nonzero_integers(&self) -> bool {
        true
    }
}

impl Euclid for Zi64 {
    fn div_rem(&self, a: &i64, b: &i64) -> Option<(i64, i64)> {
        Some((a.checked_div(*b)?, a.checked_rem(*b)?))
    }
    fn abs_cmp(&self, a: &i64, b: &i64) -> Ordering {
        a.unsigned_abs().cmp(&b.unsigned_abs())
    }
    fn add(&self, a: &i64, b: &i64) -> Option<i64> {
        a.checked_add(*b)
    }
    fn to_i64(&self, a: &i64) -> Option<i64> {
        Some(*a)
    }
    fn abs_natural(&self, a: &i64) -> Natural {
        Natural::from(a.unsigned_abs())
    }
}

/// `Z` with arbitrary-precision integers.
#[derive(Clone, Copy, Debug)]
pub(crate) struct ZBig;

impl Ring for ZBig {
    type E = BigInt;
    fn of_i64(&self, v: i64) -> BigInt {
        BigInt::from(v)
    }
    fn is_zero(&self, a: &BigInt) -> bool {
        a.is_zero()
    }
    fn is_unit(&self, a: &BigInt) -> bool {
        a.abs().is_one()
    }
    fn div_unit(&self, a: &BigInt, u: &BigInt) -> Option<BigInt> {
        Some(a * u)
    }
    fn sub_mul(&self, a: &BigInt, l: &BigInt, b: &BigInt) -> Option<BigInt> {
        Some(a - l * b)
    }
    fn keeps_nonzero_integers(&self) -> bool {
        true
    }
}

impl Euclid for ZBig {
    fn div_rem(&self, a: &BigInt, b: &BigInt) -> Option<(BigInt, BigInt)> {
        Some((a / b, a % b))
    }
    fn abs_cmp(&self, a: &BigInt, b: &BigInt) -> Ordering {
        a.abs().cmp(&b.abs())
    }
    fn add(&self, a: &BigInt, b: &BigInt) -> Option<BigInt> {
        Some(a + b)
    }
    fn to_i64(&self, a: &BigInt) -> Option<i64> {
        a.to_i64()
    }
    fn abs_natural(&self, a: &BigInt) -> Natural {
        Natural::abs_of(a)
    }
}

/// The prime field `Z/p` (elements `0..p`).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Zp {
    pub p: u64,
}

impl Zp {
    /// `a b mod p` (any modulus `p >= 1`).
    pub(crate) fn mul(&self, a: u64, b: u64) -> u64 {
        ((a as u128 * b as u128) % self.p as u128) as u64
    }
    /// The inverse of `a` (not a multiple of the prime `p`).
    pub(crate) fn inv(&self, a: u64) -> u64 {
        // Fermat: a^(p-2)
        let mut result = 1u64;
        let mut base = a % self.p;
        let mut e = self.p - 2;
        while e > 0 {
            if e & 1 == 1 {
                result = self.mul(result, base);
            }
            base = self.mul(base, base);
            e >>= 1;
        }
        result
    }
}

impl Ring for Zp {
    type E = u64;
    fn of_i64(&self, v: i64) -> u64 {
        v.rem_euclid(self.p as i64) as u64
    }
    fn is_zero(&self, a: &u64) -> bool {
        *a == 0
    }
    fn is_unit(&self, a: &u64) -> bool {
        *a != 0
    }
    fn div_unit(&self, a: &u64, u: &u64) -> Option<u64> {
        Some(self.mul(*a, self.inv(*u)))
    }
    fn sub_mul(&self, a: &u64, l: &u64, b: &u64) -> Option<u64> {
        let lb = self.mul(*l, *b);
        Some((*a + self.p - lb) % self.p)
    }
}

/// Over a field, division is exact: every non-zero element is a unit of the same "size".
impl Euclid for Zp {
    fn div_rem(&self, a: &u64, b: &u64) -> Option<(u64, u64)> {
        Some((self.mul(*a, self.inv(*b)), 0))
    }
    fn abs_cmp(&self, a: &u64, b: &u64) -> Ordering {
        (*a != 0).cmp(&(*b != 0))
    }
    fn add(&self, a: &u64, b: &u64) -> Option<u64> {
        Some((*a + *b) % self.p)
    }
    fn to_i64(&self, a: &u64) -> Option<i64> {
        i64::try_from(*a).ok()
    }
    fn abs_natural(&self, a: &u64) -> Natural {
        Natural::from(*a)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn field_inverse() {
        let f = Zp { p: 7 };
        for a in 1..7 {
            assert_eq!(f.mul(a, f.inv(a)), 1);
        }
        assert_eq!(f.of_i64(-1), 6);
        assert_eq!(f.sub_mul(&1, &2, &4), Some(0));
    }

    #[test]
    fn checked_overflow() {
        assert_eq!(Zi64.sub_mul(&i64::MIN, &1, &1), None);
        assert_eq!(Zi64.sub_mul(&5, &2, &3), Some(-1));
        assert_eq!(ZBig.abs_natural(&BigInt::from(-12)), 12);
    }
}
