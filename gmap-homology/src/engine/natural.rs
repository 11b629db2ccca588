//! [`Natural`]: an exact non-negative integer of any size, the type of a torsion
//! coefficient.
//!
//! Almost every torsion coefficient met in practice fits in a machine word, so a value is
//! kept as a `u64` when it fits and as a big integer only when it does not: comparisons,
//! printing and serialisation of small values cost what a `u64`'s do. The representation is
//! normalised (a value below 2^64 is never held as a big integer), so equality and order are
//! those of the integers.

use std::cmp::Ordering;
use std::fmt;
use std::str::FromStr;

use num_bigint::{BigInt, BigUint};
use num_traits::{Signed, ToPrimitive};
use serde::{Serialize, Serializer};

/// An exact non-negative integer of any size (a torsion coefficient `t` of `Z/t`).
///
/// Displayed and serialised as its decimal digits: in JSON a number token of any length
/// (`[2]`, `[340282366920938463463374607431768211457]`), never a string or a float.
///
/// ```
/// use gmap_homology::homology::Natural;
/// let t = Natural::from(6u64);
/// assert_eq!(t, 6);
/// assert_eq!(t.to_u64(), Some(6));
/// let big: Natural = "18446744073709551617".parse().unwrap(); // 2^64 + 1
/// assert_eq!(big.to_u64(), None);
/// assert!(big > t);
/// assert_eq!(big.to_string(), "18446744073709551617");
/// assert_eq!(serde_json::to_string(&vec![big]).unwrap(), "[18446744073709551617]");
/// ```
#[derive(Clone, PartialEq, Eq, Hash)]
pub struct Natural(Repr);

/// Normalised: `Big` holds only values above `u64::MAX`, so the derived order (every
/// `Small` before every `Big`) is the order of the integers.
#[derive(Clone, PartialEq, Eq, PartialOrd, Ord, Hash)]
enum Repr {
    Small(u64),
    Big(BigUint),
}

impl Natural {
    /// The value as a `u64`, if it fits.
    pub fn to_u64(&self) -> Option<u64> {
        match &self.0 {
            Repr::Small(v) => Some(*v),
            Repr::Big(_) => None,
        }
    }

    /// The value as a big integer.
    pub fn to_biguint(&self) -> BigUint {
        match &self.0 {
            Repr::Small(v) => BigUint::from(*v),
            Repr::Big(b) => b.clone(),
        }
    }

    /// The absolute value of a big integer.
    pub(crate) fn abs_of(x: &BigInt) -> Natural {
        Natural::from(x.abs().to_biguint().unwrap_or_default())
    }

    /// Whether `p` divides the value. O(size of the value).
    pub fn is_multiple_of(&self, p: u64) -> bool {
        match &self.0 {
            Repr::Small(v) => v.checked_rem(p).is_some_and(|r| r == 0),
            Repr::Big(b) => p != 0 && (b % p).to_u64() == Some(0),
        }
    }
}

impl From<u64> for Natural {
    fn from(v: u64) -> Natural {
        Natural(Repr::Small(v))
    }
}

impl From<BigUint> for Natural {
    fn from(b: BigUint) -> Natural {
        match b.to_u64() {
            Some(v) => Natural(Repr::Small(v)),
            None => Natural(Repr::Big(b)),
        }
    }
}

impl FromStr for Natural {
    type Err = num_bigint::ParseBigIntError;
    /// Decimal digits.
    fn from_str(s: &str) -> Result<Natural, Self::Err> {
        Ok(Natural::from(s.parse::<BigUint>()?))
    }
}

impl PartialEq<u64> for Natural {
    fn eq(&self, other: &u64) -> bool {
        self.0 == Repr::Small(*other)
    }
}

impl PartialEq<Natural> for u64 {
    fn eq(&self, other: &Natural) -> bool {
        other == self
    }
}

impl PartialOrd for Natural {
    fn partial_cmp(&self, other: &Natural) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Natural {
    fn cmp(&self, other: &Natural) -> Ordering {
        self.0.cmp(&other.0)
    }
}

impl fmt::Display for Natural {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.0 {
            Repr::Small(v) => v.fmt(f),
            Repr::Big(b) => b.fmt(f),
        }
    }
}

impl fmt::Debug for Natural {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(self, f)
    }
}

impl Serialize for Natural {
    /// A JSON number of any length: a `u64` as itself, a larger value as a number token
    /// holding its exact digits (serde_json's `arbitrary_precision`).
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        match &self.0 {
            Repr::Small(v) => s.serialize_u64(*v),
            Repr::Big(b) => match serde_json::Number::from_str(&b.to_string()) {
                Ok(n) => n.serialize(s),
                Err(e) => Err(serde::ser::Error::custom(e)),
            },
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn normalised_order_and_digits() {
        let two64: Natural = "18446744073709551616".parse().unwrap();
        let max = Natural::from(u64::MAX);
        assert!(max < two64);
        assert_eq!(Natural::from(BigUint::from(7u64)), 7);
        assert_eq!(Natural::from(two64.to_biguint() - 1u32), max);
        assert!(two64.is_multiple_of(1 << 32) && !two64.is_multiple_of(3));
        let v = serde_json::json!({"torsion": [[], [Natural::from(2)], [two64]]});
        assert_eq!(v.to_string(), r#"{"torsion":[[],[2],[18446744073709551616]]}"#);
        assert_eq!(Natural::abs_of(&BigInt::from(-12)), 12);
    }
}
