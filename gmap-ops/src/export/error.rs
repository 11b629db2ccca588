//! What every export shares: the error and the atomic write.

use std::path::{Path, PathBuf};

use gmap_core::DartId;
use thiserror::Error;

/// Why a map could not be exported.
#[derive(Debug, Error)]
#[non_exhaustive]
pub enum ExportError {
    /// The format holds only maps of one dimension.
    #[error("{format} holds {expected}-maps, this map has dimension {found}")]
    Dimension {
        /// the format
        format: &'static str,
        /// the dimension it needs
        expected: usize,
        /// the map's dimension
        found: usize,
    },
    /// The writer handles maps up to a dimension.
    #[error("{format} is written for maps of dimension at most {max}, this map has dimension {found}")]
    DimensionAbove {
        /// the format
        format: &'static str,
        /// the largest dimension written
        max: usize,
        /// the map's dimension
        found: usize,
    },
    /// A vertex without a point (`.off` needs coordinates).
    #[error("the vertex of dart {dart} has no point: .off needs coordinates")]
    NoPoint {
        /// a dart of that vertex
        dart: u32,
    },
    /// A face that is not a closed polygon (a 0- or 1-free dart).
    #[error("the face of dart {dart} is not a closed polygon (dart {dart} is {alpha}-free)")]
    OpenFace {
        /// the dart
        dart: u32,
        /// the involution with a fixed point
        alpha: usize,
    },
    /// A label whose name is empty: the format names every array.
    #[error("a label has an empty name: {format} names every data array")]
    EmptyLabelName {
        /// the format
        format: &'static str,
    },
    /// The format needs coordinates and the map has no points at all.
    #[error("the map has no points: {format} needs coordinates for every vertex")]
    NoPoints {
        /// the format
        format: &'static str,
    },
    /// A vertex without a finite point, for a format other than `.off` that needs them.
    #[error("the vertex of dart {dart} has {what}: {format} needs finite coordinates for every vertex")]
    VertexPoint {
        /// the format
        format: &'static str,
        /// a dart of that vertex
        dart: u32,
        /// `no point` or `a point that is not finite`
        what: &'static str,
    },
    /// A map without darts has no simplicial complex to write.
    #[error("the map has no dart: there is no facet to write")]
    Empty,
    /// The output would not fit in memory.
    #[error("the output of {facets} facets cannot be held in memory")]
    TooLarge {
        /// the number of facets
        facets: usize,
    },
    /// The `.off` text would not read back as the same map.
    #[error("the map is not a polygon mesh that .off can describe: {reason}")]
    NotAMesh {
        /// what the reader makes of the text
        reason: String,
    },
    /// A vertex whose point is not finite.
    #[error("the vertex of dart {dart} has a point that is not finite: .off needs finite coordinates")]
    NonFinitePoint {
        /// a dart of that vertex
        dart: u32,
    },
    /// A vertex of an editable map without a finite point (`.off` needs coordinates).
    #[error("the vertex of dart {dart:?} has {what}: .off needs finite coordinates for every vertex")]
    VertexOfDart {
        /// a dart of that vertex
        dart: DartId,
        /// `no point` or `a point that is not finite`
        what: &'static str,
    },
    /// The format needs maps of at least a dimension.
    #[error("{format} needs a map of dimension at least {min}, this map has dimension {found}")]
    DimensionBelow {
        /// the format
        format: &'static str,
        /// the smallest dimension written
        min: usize,
        /// the map's dimension
        found: usize,
    },
    /// A map that a mesh format (`.vtk`, `.vtu`, `.msh`) cannot hold as it is, or whose
    /// output would not read back as the same map and labels.
    #[error("{format} cannot hold this map as it is: {reason}")]
    MeshWrite {
        /// the format
        format: &'static str,
        /// which cells and why
        reason: String,
    },
    /// A cubical cell complex with lower cells on no cube, for a format of cubes only.
    #[error("{reason}")]
    LowerCells {
        /// which cells and why the format drops them
        reason: String,
    },
    /// Writing failed.
    #[error("{path}: {source}")]
    Io {
        /// the file
        path: PathBuf,
        /// the cause
        source: std::io::Error,
    },
    /// A cell of a scene that cannot be added (see [`super::html::Scene`]).
    #[error("the scene has no room for {reason}")]
    SceneCell {
        /// what was refused
        reason: String,
    },
    /// A generator names a cell the scene does not have.
    #[error("generator {name}: {dim}-cell {cell} is not among the scene's {count} cells of dimension {dim}")]
    GeneratorCell {
        /// the generator's name
        name: String,
        /// its dimension
        dim: usize,
        /// the first cell that is not there
        cell: u32,
        /// how many cells of that dimension the scene has
        count: usize,
    },
    /// A page is to be coloured by a label that no cell has.
    #[error("no cell has a label named `{name}` (labels: {})", if known.is_empty() { "none".to_string() } else { known.join(", ") })]
    UnknownLabel {
        /// the label asked for
        name: String,
        /// the labels the scene has
        known: Vec<String>,
    },
}

/// Writes `contents` to `path` with [`gmap_core::io::write_atomic`] (never a partial file).
pub fn write_atomic(path: &Path, contents: &[u8]) -> Result<(), ExportError> {
    gmap_core::io::write_atomic(path, contents).map_err(|source| ExportError::Io { path: path.to_path_buf(), source })
}
