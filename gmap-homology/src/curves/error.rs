//! [`CurveError`]: why a curve, a weight or a surface is refused.

use thiserror::Error;

/// Why a computation on curves is refused, with the offending data.
#[derive(Clone, Debug, PartialEq, Error)]
#[non_exhaustive]
pub enum CurveError {
    /// Curves on surfaces need a 2-map.
    #[error("the map is of dimension {dim}: curves on surfaces need a 2-map")]
    NotTwoMap {
        /// the map's dimension
        dim: usize,
    },
    /// The map breaks an involution or commutation rule.
    #[error("the map is not valid: {reason}")]
    Invalid {
        /// what the validation found
        reason: String,
    },
    /// A dart free for `alpha_0` or `alpha_1`: an edge without two ends or a face that is
    /// not closed, so the map is not a surface.
    #[error("dart {dart} is {i}-free: {}, so the map is not a surface", if *.i == 0 { "an edge has one end" } else { "a face is not closed" })]
    OpenCell {
        /// the free dart
        dart: u32,
        /// 0 or 1
        i: usize,
    },
    /// A surface with boundary where a closed one is needed.
    #[error("{what} is defined here on closed surfaces; edge {edge} (dart {dart}) is on the boundary")]
    Boundary {
        /// the refused computation
        what: &'static str,
        /// a boundary edge
        edge: u32,
        /// its smallest dart
        dart: u32,
    },
    /// Not one weight per edge.
    #[error("{given} weights for {edges} edges")]
    WeightCount {
        /// weights given
        given: usize,
        /// edges of the map or complex
        edges: usize,
    },
    /// A weight that is negative, infinite or not a number.
    #[error("edge {edge}: weight {weight} is not a finite number ≥ 0")]
    BadWeight {
        /// the edge
        edge: u32,
        /// its weight
        weight: f64,
    },
    /// A vertex without a point where edge lengths are asked for.
    #[error("edge {edge}: a vertex (dart {dart}) has no point, so the edge has no length")]
    NoPoint {
        /// the edge
        edge: u32,
        /// a dart of the vertex
        dart: u32,
    },
    /// A vertex index past the vertices.
    #[error("vertex {vertex} does not exist: the map has {vertices} vertices")]
    NoSuchVertex {
        /// the index given
        vertex: u32,
        /// the number of vertices
        vertices: usize,
    },
    /// A 1-cell whose boundary modulo 2 is not two vertices or none (a complex that is not
    /// a graph in dimension 1, such as a relative complex).
    #[error(
        "edge {edge}: its boundary has {ends} vertices of odd coefficient; an edge has two ends (or none, a loop)"
    )]
    NotAGraph {
        /// the edge
        edge: u32,
        /// vertices of odd coefficient in its boundary
        ends: usize,
    },
    /// The work asked for is past the limit.
    #[error("{what}: about {work} steps, past the limit of {limit}")]
    TooLarge {
        /// the computation
        what: &'static str,
        /// its estimated steps (or bytes)
        work: u128,
        /// the limit
        limit: u128,
    },
    /// A sequence of darts that is not a path of the map, named at the step that breaks.
    #[error("step {step}: dart {dart} {reason}")]
    NotAPath {
        /// the index of the step in the sequence
        step: usize,
        /// the dart there
        dart: u32,
        /// why it does not follow
        reason: &'static str,
    },
    /// A map of several components (or none) where one connected surface is needed.
    #[error("the map has {components} components: homotopy tests need one connected surface")]
    Disconnected {
        /// the number of components
        components: usize,
    },
    /// A path that does not come back to its start where a closed path is needed.
    #[error(
        "the path starts at vertex {start} and ends at vertex {end} (by their smallest darts): a closed path is needed"
    )]
    NotClosed {
        /// the start vertex's smallest dart
        start: u32,
        /// the end vertex's smallest dart
        end: u32,
    },
    /// Two paths whose ends differ, compared with their ends fixed.
    #[error("the paths run from vertex {} to {} and from {} to {} (by their smallest darts): homotopy with fixed ends needs the same ends", p[0], p[1], q[0], q[1])]
    EndsDiffer {
        /// the first path's start and end vertices
        p: [u32; 2],
        /// the second path's
        q: [u32; 2],
    },
    /// Two vertices of a path joined by no edge or by several.
    #[error("step {step}: {edges} edges join vertex {from} to vertex {to}; a step by vertices needs exactly one (give darts)")]
    NoEdge {
        /// the index of the step
        step: usize,
        /// its start vertex (index)
        from: u32,
        /// its end vertex (index)
        to: u32,
        /// the number of edges joining them
        edges: usize,
    },
    /// A question this implementation cannot settle on this input, refused rather than
    /// guessed.
    #[error("{what}: not decided here ({reason})")]
    Undecided {
        /// the question
        what: &'static str,
        /// why
        reason: String,
    },
    /// The fundamental group's presentation came out other than the surface's topology
    /// says (a defect, reported rather than used).
    #[error("the presentation of the fundamental group is inconsistent: {reason}")]
    Presentation {
        /// what was found
        reason: String,
    },
}
