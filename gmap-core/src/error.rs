//! Typed errors of the kernel. Each carries the offending darts and indices.

use thiserror::Error;

use crate::ids::Dart;

/// A violation of BO Def. 1 (the G-map axioms), as found by `validate`.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
#[non_exhaustive]
pub enum ValidityError {
    /// `alpha_i(d)` names a dart that does not exist.
    #[error(
        "dart {dart} is linked along alpha_{alpha} to dart {target}, which does not exist (the map has {darts} darts)"
    )]
    OutOfRange {
        /// the dart whose link is wrong
        dart: Dart,
        /// the involution index
        alpha: usize,
        /// the value found
        target: Dart,
        /// the number of darts
        darts: usize,
    },
    /// `alpha_i(alpha_i(d)) != d`.
    #[error("dart {dart} is linked along alpha_{alpha} to dart {image}, which is linked back to dart {back} instead")]
    NotInvolution {
        /// the dart
        dart: Dart,
        /// the involution index
        alpha: usize,
        /// `alpha_i(dart)`
        image: Dart,
        /// `alpha_i(image)`, which should be `dart`
        back: Dart,
    },
    /// `alpha_i alpha_j` is not an involution for some `j >= i + 2`.
    #[error("the links alpha_{i} and alpha_{j} do not commute at dart {dart}: alpha_{i}, alpha_{j}, alpha_{i}, alpha_{j} from it lead to dart {image}, not back to it")]
    NotCommuting {
        /// the dart
        dart: Dart,
        /// the lower index
        i: usize,
        /// the higher index (`j >= i + 2`)
        j: usize,
        /// where the square of the composition sends `dart`
        image: Dart,
    },
    /// A dimension larger than [`crate::MAX_DIM`].
    #[error("dimension {0} is larger than the supported maximum {max}", max = crate::MAX_DIM)]
    DimensionTooLarge(usize),
    /// More darts than a `u32` index can name.
    #[error("{0} darts is more than the supported maximum of 2^32 - 1")]
    TooManyDarts(usize),
    /// The memory for the darts cannot be had.
    #[error("{darts} darts need more memory than can be had")]
    OutOfMemory {
        /// the number of darts asked for
        darts: usize,
    },
    /// A flat involution array whose length is not a multiple of `dim + 1`.
    #[error("a flat array of {len} entries does not hold whole rows of {width} entries (dimension {})", .width - 1)]
    RaggedRows {
        /// the length of the array
        len: usize,
        /// the length of a row, `dim + 1`
        width: usize,
    },
}

/// Why an edit or a query of a [`crate::DenseMap`] was refused: the dart or the involution
/// index it names does not exist. The panicking forms ([`crate::DenseMap::alpha`],
/// [`crate::DenseMap::link`], …) panic with this message; the `try_` forms return it.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
#[non_exhaustive]
pub enum DartError {
    /// The dart is not one of the map's darts `0..darts`.
    #[error("dart {dart} does not exist (the map has {darts} darts)")]
    NoSuchDart {
        /// the dart asked for
        dart: Dart,
        /// the number of darts
        darts: usize,
    },
    /// `alpha_i` with `i` above the dimension.
    #[error("alpha_{alpha} does not exist in a map of dimension {dim} (asked at dart {dart})")]
    BadIndex {
        /// the dart the operation was asked at
        dart: Dart,
        /// the index asked for
        alpha: usize,
        /// the map's dimension
        dim: usize,
    },
    /// Adding darts would pass the largest number of darts a `u32` index can name.
    #[error("adding {adding} darts to {darts} would pass the maximum of {max} darts", max = u32::MAX - 1)]
    TooManyDarts {
        /// the darts the map has
        darts: usize,
        /// the darts asked for
        adding: usize,
    },
}

/// Why a map does not have cells with complete boundaries (BO Def. 6).
#[derive(Clone, Debug, PartialEq, Eq, Error)]
#[non_exhaustive]
pub enum BoundaryDefect {
    /// `alpha_i` has a fixed point for some `i < n`.
    #[error("the boundary is open at dart {dart}: it has no neighbour along alpha_{alpha} (Def. 6 of BO: only alpha_n may have free darts)")]
    Free {
        /// the free dart
        dart: Dart,
        /// the involution
        alpha: usize,
    },
    /// `<alpha_{i+1..n}>(d)` and `<alpha_{0..i-1}>(d)` share a dart other than `d`: the
    /// i-cell of `d` is folded onto itself.
    #[error("the {i}-cell of dart {cell} is folded onto itself: darts {dart} and {other} lie in the same <alpha_{}..alpha_n> orbit and the same <alpha_0..alpha_{}> orbit (Def. 6 of BO: no self-bending)", .i + 1, .i - 1)]
    SelfBending {
        /// the dart
        dart: Dart,
        /// the dimension `i` of the folded cell, where the orbits meet
        i: usize,
        /// another dart in both orbits
        other: Dart,
        /// the smallest dart of the folded i-cell
        cell: Dart,
    },
}

/// Why a map is not orientable as a whole (BO Def. 7).
#[derive(Clone, Debug, PartialEq, Eq, Error)]
#[error("the map is not orientable: dart {dart} and its alpha_{alpha} neighbour {other} get the same orientation (Def. 7 of BO)")]
pub struct OrientationConflict {
    /// a dart where the 2-colouring fails
    pub dart: Dart,
    /// the involution along which it fails
    pub alpha: usize,
    /// the neighbour with the same colour
    pub other: Dart,
}

/// Why a cell is not orientable as a compacted cell (condition C1 of docs/DESIGN.md).
#[derive(Clone, Debug, PartialEq, Eq, Error)]
#[non_exhaustive]
pub enum CellDefect {
    /// A dart of the i-cell is k-free for some `k < i`: the cell's boundary is incomplete.
    #[error("the {dim}-cell of dart {dart} has an open boundary: one of its darts has no neighbour along alpha_{alpha} (condition C1: cells with complete boundaries)")]
    IncompleteBoundary {
        /// dimension of the cell
        dim: usize,
        /// representative dart
        dart: Dart,
        /// the involution that has a fixed point
        alpha: usize,
    },
    /// The 2-colouring of the compacted cell fails: the cell is non-orientable or folded.
    #[error("the {dim}-cell of dart {dart} is glued to itself in a way that reverses its orientation, or is not orientable (at dart {at}, along alpha_{alpha}; condition C1: every cell orientable as a compacted cell)")]
    NotOrientable {
        /// dimension of the cell
        dim: usize,
        /// representative dart of the cell
        dart: Dart,
        /// the involution along which the colouring fails
        alpha: usize,
        /// the dart where it fails
        at: Dart,
    },
}
