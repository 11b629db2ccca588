//! The primitive ids every other module speaks in: [`Dart`], [`CellId`] and [`Point`].
//!
//! This module is a leaf: it imports nothing of the crate, so every module may use it
//! without making an import circle. The ids are opaque newtypes over `u32`, as petgraph's
//! `NodeIndex`: build one with `new`, read it with `index` (as `usize`, to index arrays) or
//! `get` (as the stored `u32`). `Debug` prints `Dart(7)`, `Display` prints `7`.

use std::fmt;

/// A dart of a [`DenseMap`](crate::DenseMap): an index `0..N`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Dart(u32);

impl Dart {
    /// The dart numbered `i`.
    #[inline]
    pub const fn new(i: u32) -> Self {
        Dart(i)
    }

    /// The index as `usize`, to index per-dart arrays.
    #[inline]
    pub const fn index(self) -> usize {
        self.0 as usize
    }

    /// The index as the stored `u32`.
    #[inline]
    pub const fn get(self) -> u32 {
        self.0
    }
}

impl fmt::Display for Dart {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        self.0.fmt(f)
    }
}

impl From<u32> for Dart {
    #[inline]
    fn from(i: u32) -> Self {
        Dart(i)
    }
}

impl From<Dart> for u32 {
    #[inline]
    fn from(d: Dart) -> u32 {
        d.0
    }
}

impl From<Dart> for usize {
    #[inline]
    fn from(d: Dart) -> usize {
        d.0 as usize
    }
}

impl TryFrom<usize> for Dart {
    type Error = std::num::TryFromIntError;

    /// The dart numbered `i`, or an error when `i` does not fit in `u32`.
    #[inline]
    fn try_from(i: usize) -> Result<Self, Self::Error> {
        u32::try_from(i).map(Dart)
    }
}

/// The number of a cell (an orbit) in a [`Partition`](crate::Partition): `0..len`, in the
/// order of the cells' smallest darts. `Partition::of` holds these numbers as bare `u32` for
/// the whole-map loops that index arrays by them.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct CellId(u32);

impl CellId {
    /// The cell numbered `i`.
    #[inline]
    pub const fn new(i: u32) -> Self {
        CellId(i)
    }

    /// The number as `usize`, to index per-cell arrays.
    #[inline]
    pub const fn index(self) -> usize {
        self.0 as usize
    }

    /// The number as the stored `u32`.
    #[inline]
    pub const fn get(self) -> u32 {
        self.0
    }
}

impl fmt::Display for CellId {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        self.0.fmt(f)
    }
}

impl From<u32> for CellId {
    #[inline]
    fn from(i: u32) -> Self {
        CellId(i)
    }
}

impl From<CellId> for u32 {
    #[inline]
    fn from(c: CellId) -> u32 {
        c.0
    }
}

impl From<CellId> for usize {
    #[inline]
    fn from(c: CellId) -> usize {
        c.0 as usize
    }
}

impl TryFrom<usize> for CellId {
    type Error = std::num::TryFromIntError;

    /// The cell numbered `i`, or an error when `i` does not fit in `u32`.
    #[inline]
    fn try_from(i: usize) -> Result<Self, Self::Error> {
        u32::try_from(i).map(CellId)
    }
}

/// A point in space, attached to a dart to embed the 0-cell it belongs to.
pub type Point = [f64; 3];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ids_round_trip_and_print_their_number() {
        let d = Dart::new(7);
        assert_eq!((d.index(), d.get(), u32::from(d), usize::from(d)), (7, 7, 7, 7));
        assert_eq!(Dart::try_from(7usize), Ok(d));
        assert_eq!(format!("{d} {d:?}"), "7 Dart(7)");
        let c = CellId::from(3);
        assert_eq!((c.index(), c.get()), (3, 3));
        assert_eq!(format!("{c} {c:?}"), "3 CellId(3)");
        #[cfg(target_pointer_width = "64")]
        assert!(Dart::try_from(1usize << 32).is_err());
    }
}
