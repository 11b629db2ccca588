//! Why an Euler operator cannot be applied.

use gmap_core::DartId;
use thiserror::Error;

/// Why an Euler operator cannot be applied. Each variant names the offending dart.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
#[non_exhaustive]
pub enum EulerError {
    /// A handle does not name a live dart.
    #[error("dart {0:?} does not exist")]
    NoSuchDart(DartId),
    /// The cell dimension is out of range for the operator and the map.
    #[error("a {what} needs a cell dimension in {lo}..={hi}, got {got}")]
    BadDimension {
        /// the operator
        what: &'static str,
        /// lowest allowed
        lo: usize,
        /// highest allowed
        hi: usize,
        /// given
        got: usize,
    },
    /// A dart that must be linked by `alpha_i` is i-free (an incomplete boundary).
    #[error("dart {dart:?} is {alpha}-free")]
    Free {
        /// the dart
        dart: DartId,
        /// the involution
        alpha: usize,
    },
    /// The darts given do not lie in one i-cell, or lie on both sides of the cut.
    #[error("dart {dart:?} is not where the {what} needs it")]
    Misplaced {
        /// the dart
        dart: DartId,
        /// what was expected
        what: &'static str,
    },
    /// The cut does not close up: walking around it from this dart does not come back.
    #[error("the cut is not closed at dart {0:?}")]
    OpenCut(DartId),
    /// The cut does not separate the cell into two parts.
    #[error("the cut through dart {0:?} does not separate its cell")]
    NotSeparating(DartId),
    /// The cell's degree is not 2 (CGAL's condition: `alpha_{i+1} alpha_{i+2}` must be an
    /// involution on the cell for removal, `alpha_{i-1} alpha_{i-2}` for contraction).
    #[error("the {dim}-cell of dart {dart:?} has degree above 2")]
    DegreeAboveTwo {
        /// the cell dimension
        dim: usize,
        /// a dart where the condition fails
        dart: DartId,
    },
    /// Removing or contracting this cell would change the topology (the same cell lies on
    /// both sides, or the cell is on the boundary).
    #[error("the {dim}-cell of dart {dart:?} {why}")]
    WouldChangeTopology {
        /// the cell dimension
        dim: usize,
        /// a dart of the cell
        dart: DartId,
        /// the reason
        why: &'static str,
    },
    /// A vertex of the cell has no point, so the cell has no barycentre.
    #[error("the {dim}-cell of dart {dart:?} has a vertex without a point")]
    NoPoint {
        /// the cell dimension
        dim: usize,
        /// a dart of the cell
        dart: DartId,
    },
}
