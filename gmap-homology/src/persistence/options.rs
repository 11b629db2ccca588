//! The options of an image's filtration, and the order of its values: shared by the general
//! cubical route ([`super::image`]) and the lower-star fast path, which each read them.

use super::pairing::Zp;
use super::PersistenceError;

/// Where the array's values sit.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
#[non_exhaustive]
pub enum Construction {
    /// values on top cells, lower cells take the minimum of their cofaces (GUDHI's default)
    #[default]
    T,
    /// values on vertices, higher cells take the maximum of their vertices (CubicalRipser's)
    V,
}

impl std::str::FromStr for Construction {
    type Err = PersistenceError;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        match s {
            "T" | "t" | "top" | "top_dimensional_cells" => Ok(Construction::T),
            "V" | "v" | "vertex" | "vertices" => Ok(Construction::V),
            _ => Err(PersistenceError::BadOption(format!("construction {s:?} (want T or V)"))),
        }
    }
}

/// How to filter an image.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CubicalOptions {
    /// T- or V-construction
    pub construction: Construction,
    /// superlevel sets (values taken from the top down)
    pub superlevel: bool,
    /// identify opposite faces of the box (a torus)
    pub periodic: bool,
    /// coefficients `Z/p`, `p` a prime below `2^31`
    pub field: u32,
    /// return a representative cycle per pair
    pub cycles: bool,
}

impl Default for CubicalOptions {
    fn default() -> Self {
        CubicalOptions { construction: Construction::T, superlevel: false, periodic: false, field: 2, cycles: false }
    }
}

/// A total order on `f64` (finite values only reach here) as an unsigned key.
#[inline]
pub(crate) fn key(v: f64) -> u64 {
    let b = v.to_bits();
    if b >> 63 == 1 {
        !b
    } else {
        b | (1 << 63)
    }
}

/// The value of a [`key`].
#[inline]
pub(crate) fn unkey(k: u64) -> f64 {
    f64::from_bits(if k >> 63 == 1 { k & !(1 << 63) } else { !k })
}

pub(crate) fn check_field(p: u32) -> Result<Zp, PersistenceError> {
    if crate::Prime::new(u64::from(p)).is_none() {
        return Err(PersistenceError::BadOption(format!("field Z/{p}: want a prime below 2^31")));
    }
    Ok(Zp::new(p))
}
