//! What every importer shares: the errors, reading a file, and the memory limits.

use std::fmt;
use std::path::{Path, PathBuf};

use thiserror::Error;

/// Why an input could not be made into a G-map. Line numbers are 1-based.
#[derive(Debug, Error)]
#[non_exhaustive]
pub enum ImportError {
    /// The file could not be read.
    #[error("{0}")]
    Io(#[from] std::io::Error),
    /// A token or line that does not fit the format.
    #[error("line {line}: {message}")]
    Syntax {
        /// the offending line
        line: usize,
        /// what was expected
        message: String,
    },
    /// The input holds no facet or no polygon.
    #[error("no facet or polygon found")]
    Empty,
    /// A facet with fewer vertices than the largest facets (the complex is not pure).
    #[error("facet on line {line} has {found} vertices, but the largest facets have {expected}: mixed dimensions")]
    MixedDimension {
        /// line of the facet
        line: usize,
        /// vertices of the largest facets
        expected: usize,
        /// vertices of this facet
        found: usize,
    },
    /// A facet listing a vertex twice.
    #[error("facet on line {line} repeats vertex {vertex}")]
    RepeatedVertex {
        /// line of the facet
        line: usize,
        /// the repeated label
        vertex: u64,
    },
    /// A ridge (a facet minus one vertex) shared by three or more facets.
    #[error("ridge {} lies in {} facets (lines {}): not a pseudo-manifold", fmt_list(ridge), lines.len(), fmt_list(lines))]
    RidgeInManyFacets {
        /// the vertices of the ridge
        ridge: Vec<u64>,
        /// lines of the facets that contain it
        lines: Vec<usize>,
    },
    /// The G-map would have more darts than allowed.
    #[error("{facets} facets of dimension {dim} make {} darts, over the limit of {limit} darts{}",
        darts.map_or_else(|| "more than 2^64".to_string(), |d| d.to_string()),
        if *limit >= u32::MAX as u64 - 1 { " (the most a G-map indexes: no limit raises it)" } else { "" })]
    TooManyDarts {
        /// the number of facets (or polygons, or flags found so far)
        facets: usize,
        /// the dimension
        dim: usize,
        /// the number of darts, `None` past `u64`
        darts: Option<u64>,
        /// the limit in force
        limit: u64,
    },
    /// An edge shared by three or more polygons of a mesh.
    #[error("edge {u}-{v} lies in {} polygons (lines {}): not a surface", lines.len(), fmt_list(lines))]
    EdgeInManyPolygons {
        /// one end (the smaller vertex index)
        u: u32,
        /// the other end
        v: u32,
        /// lines of the polygons
        lines: Vec<usize>,
    },
    /// A polygon with an edge from a vertex to itself, or with fewer than three vertices.
    #[error("polygon on line {line} is degenerate: {reason}")]
    DegeneratePolygon {
        /// line of the polygon
        line: usize,
        /// what is wrong
        reason: String,
    },
    /// Memory for the input or the map could not be had.
    #[error("cannot allocate {bytes} bytes for {what}")]
    OutOfMemory {
        /// what the memory was for
        what: String,
        /// the estimate
        bytes: u64,
    },
    /// An estimated cost over the memory limit (`--max-memory`).
    #[error(transparent)]
    MemoryLimit(#[from] gmap_core::resources::MemoryLimit),
    /// The same facet listed twice: a simplicial complex is a set of simplices.
    #[error("facet on line {second} repeats the facet on line {first} (a simplicial complex lists each facet once)")]
    RepeatedFacet {
        /// line of the first occurrence
        first: usize,
        /// line of the repetition
        second: usize,
    },
    /// A `.lex` file without a complex of the requested name.
    #[error("no complex named '{0}' in the file")]
    NoSuchName(String),
    /// Cells that cannot be made into a map (a face in three cells, a non-conforming face…).
    #[error(transparent)]
    Mesh(#[from] crate::mesh::MeshError),
    /// A file that ends before a section its format requires (`$Elements`, `CELLS`,
    /// `<Piece>`…), or whose sections hold no cell: an empty or truncated mesh is not an
    /// empty map.
    #[error("{}", if *empty { format!("{section} holds no cell: an empty mesh is not read") } else { format!("the file ends before the {section} section it needs") })]
    MissingSection {
        /// the section, as the format names it
        section: String,
        /// `true` when the section is there but holds no cell
        empty: bool,
    },
    /// A file that does not fit its format as a whole (a `.pbm` header, a bounding box too big).
    #[error("{0}")]
    Format(String),
}

/// An [`ImportError`] with the file it came from. Displays as `FILE: message`.
#[derive(Debug, Error)]
pub struct FileError {
    /// the file read
    pub path: PathBuf,
    /// what went wrong (its message is part of this error's, so it is not a `source`)
    pub error: ImportError,
}

impl fmt::Display for FileError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.path.display(), self.error)
    }
}

impl FileError {
    /// Attaches a path to an error.
    pub fn new(path: &Path, error: ImportError) -> Self {
        FileError { path: path.to_path_buf(), error }
    }
}

pub(super) fn fmt_list<T: fmt::Display>(xs: &[T]) -> String {
    let parts: Vec<String> = xs.iter().map(|x| x.to_string()).collect();
    format!("[{}]", parts.join(", "))
}

/// Reads a whole file into a buffer reserved fallibly: a file larger than the memory to be
/// had is an error naming its size, not an abort.
pub(crate) fn read_bytes(path: &Path) -> Result<Vec<u8>, FileError> {
    use std::io::Read as _;
    let mut f = std::fs::File::open(path).map_err(|e| FileError::new(path, e.into()))?;
    let size = f.metadata().map(|m| m.len()).unwrap_or(0);
    gmap_core::resources::check_memory("the file", Some(size)).map_err(|e| FileError::new(path, e.into()))?;
    let mut bytes = Vec::new();
    if bytes.try_reserve_exact(usize::try_from(size).unwrap_or(usize::MAX)).is_err() {
        return Err(FileError::new(path, ImportError::OutOfMemory { what: "the file".into(), bytes: size }));
    }
    f.read_to_end(&mut bytes).map_err(|e| FileError::new(path, e.into()))?;
    Ok(bytes)
}

/// Reads a whole text file: the buffer is reserved fallibly (a file larger than the memory to
/// be had is an error naming its size, not an abort), and bytes that are not UTF-8 are an
/// error naming the line.
pub(crate) fn read_text(path: &Path) -> Result<String, FileError> {
    let bytes = read_bytes(path)?;
    String::from_utf8(bytes).map_err(|e| {
        let at = e.utf8_error().valid_up_to();
        let line = 1 + e.as_bytes()[..at].iter().filter(|&&b| b == b'\n').count();
        FileError::new(
            path,
            ImportError::Syntax { line, message: format!("not UTF-8 text: invalid byte at offset {at}") },
        )
    })
}

/// The default dart limit for a map of dimension `dim`: what fits in the memory budget
/// ([`gmap_core::resources::memory_budget`]) at `bytes_per_dart(dim)` bytes each, and what
/// the default work limit can analyse ([`gmap_core::resources::max_darts_for_work`]: one
/// 11-vertex facet, 11! darts in dimension 10, is over it), capped at `u32::MAX - 1` (the
/// largest dart index).
pub fn default_max_darts(dim: usize) -> u64 {
    let cap = (u32::MAX as u64 - 1).min(gmap_core::resources::max_darts_for_work(dim));
    match available_memory() {
        Some(bytes) => (bytes / bytes_per_dart(dim)).min(cap),
        None => cap,
    }
}

/// The default limit on the faces of a simplicial complex taken straight to its chain
/// complex (counted with repetition, `2^(d+1) - 1` per d-facet): what fits in the memory
/// budget at about `40 (dim + 2)` bytes a face (its key, its vertex list, its
/// boundary entries, the sort), capped at `u32::MAX - 1` (the largest cell index).
pub fn default_max_faces(dim: usize) -> u64 {
    let cap = u32::MAX as u64 - 1;
    match available_memory() {
        Some(bytes) => (bytes / (40 * (dim as u64 + 2))).min(cap),
        None => cap,
    }
}

/// The bytes an import may take: the workspace's memory budget
/// ([`gmap_core::resources::memory_budget`]: the `--max-memory` limit, at most the memory
/// available now).
pub(crate) fn available_memory() -> Option<u64> {
    Some(gmap_core::resources::memory_budget())
}

/// Bytes counted per dart when importing an n-dimensional complex: the involution row
/// (`4 (n + 1)`) plus half as much again for the importer's tables (at most `9 (n + 1)`
/// bytes per ordering of a facet, shared by all facets) and a first analysis pass.
pub fn bytes_per_dart(dim: usize) -> u64 {
    6 * (dim as u64 + 1)
}
