//! Why a construction operation cannot be applied.

use gmap_core::DartId;
use thiserror::Error;

use crate::euler::EulerError;

/// Why a construction operation ([`crate::construct`]) cannot be applied. Each variant
/// names the offending dart or argument; nothing is changed when one is returned.
#[derive(Clone, Debug, PartialEq, Error)]
#[non_exhaustive]
pub enum ConstructError {
    /// A handle does not name a live dart.
    #[error("dart {0:?} does not exist")]
    NoSuchDart(DartId),
    /// The cell dimension is out of range for the operation and the map.
    #[error("{what} needs a cell dimension in {lo}..={hi}, got {got}")]
    BadDimension {
        /// the operation
        what: &'static str,
        /// lowest allowed
        lo: usize,
        /// highest allowed
        hi: usize,
        /// given
        got: usize,
    },
    /// A dart of the cell or profile must be free for `alpha_{alpha}` and is not: the new
    /// cell would have nowhere to attach (extrusions), or the profile is not a component
    /// of dimension below the map's (revolution).
    #[error("dart {dart:?} is not {alpha}-free")]
    NotFree {
        /// the dart
        dart: DartId,
        /// the involution
        alpha: usize,
    },
    /// A vertex the operation places has no point.
    #[error("the vertex of dart {0:?} has no point")]
    NoPoint(DartId),
    /// A revolution needs at least three steps (the loop of copies closes).
    #[error("a revolution needs at least {min} steps, got {got}")]
    TooFewSteps {
        /// the smallest number accepted
        min: usize,
        /// given
        got: usize,
    },
    /// The axis of a revolution has no direction (a zero or non-finite vector).
    #[error("the axis direction {0:?} is zero or not finite")]
    BadAxis([f64; 3]),
    /// A vector or parameter is not finite (or, for a chamfer, not strictly between 0 and 1).
    #[error("the {what} {value} is out of range")]
    BadParameter {
        /// which argument
        what: &'static str,
        /// its value
        value: f64,
    },
    /// The cell is not of the shape the operation needs (a face of fewer than three
    /// sides for a triangulation, a path with a free dart, …).
    #[error("the cell of dart {dart:?} is not {what}")]
    BadShape {
        /// a dart of the cell
        dart: DartId,
        /// what was expected
        what: &'static str,
    },
    /// A volume that must be convex is not: a vertex of it lies outside the plane of one of
    /// its faces (on the other side from the volume's barycentre), or the barycentre is not
    /// strictly inside that plane (a flat volume, a face not planar).
    #[error("the volume of dart {volume:?} is not convex: the vertex of dart {vertex:?} is beyond the plane of the face of dart {face:?}")]
    NotConvex {
        /// the dart given, naming the volume
        volume: DartId,
        /// a dart of the face whose plane is crossed
        face: DartId,
        /// a dart of the vertex beyond it (a dart of the face itself when the barycentre is
        /// on the plane)
        vertex: DartId,
    },
    /// An Euler operator the construction is made of refused (its error says why).
    #[error(transparent)]
    Euler(#[from] EulerError),
}
