//! The primitive ids every other module speaks in: [`Dart`], [`CellId`] and [`Point`].
//!
//! This module is a leaf: it imports nothing of the crate, so every module may use it
//! without making an import circle. The ids are opaque newtypes over `u32`, as petgraph's
//! `NodeIndex`: build one with `new`, read it with `index` (as `usize`, to index arrays) or
//! `get` (as the stored `u32`). `Debug` prints `Dart(7)`, `Display` prints `7`.

use std::fmt;

/// An opaque `u32` id: `new`, `index`, `get`, `Display` as the number, conversions from and
/// to `u32`, to `usize`, and from `usize` when it fits.
macro_rules! id_type {
    ($(#[$doc:meta])* $name:ident, $what:literal) => {
        $(#[$doc])*
        #[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
        pub struct $name(u32);

        impl $name {
            #[doc = concat!("The ", $what, " numbered `i`.")]
            #[inline]
            pub const fn new(i: u32) -> Self {
                $name(i)
            }

            #[doc = concat!("The number as `usize`, to index per-", $what, " arrays.")]
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

        impl fmt::Display for $name {
            fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                self.0.fmt(f)
            }
        }

        impl From<u32> for $name {
            #[inline]
            fn from(i: u32) -> Self {
                $name(i)
            }
        }

        impl From<$name> for u32 {
            #[inline]
            fn from(x: $name) -> u32 {
                x.0
            }
        }

        impl From<$name> for usize {
            #[inline]
            fn from(x: $name) -> usize {
                x.0 as usize
            }
        }

        impl TryFrom<usize> for $name {
            type Error = std::num::TryFromIntError;

            #[doc = concat!("The ", $what, " numbered `i`, or an error when `i` does not fit in `u32`.")]
            #[inline]
            fn try_from(i: usize) -> Result<Self, Self::Error> {
                u32::try_from(i).map($name)
            }
        }
    };
}

id_type!(
    /// A dart of a [`DenseMap`](crate::DenseMap): an index `0..N`.
    Dart,
    "dart"
);

id_type!(
    /// The number of a cell (an orbit) in a [`Partition`](crate::Partition): `0..len`, in the
    /// order of the cells' smallest darts. `Partition::of` holds these numbers as bare `u32`
    /// for the whole-map loops that index arrays by them.
    CellId,
    "cell"
);

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
