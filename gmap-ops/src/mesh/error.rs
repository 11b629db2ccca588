//! [`MeshError`]: why cells given by their vertices could not be made into a map.

use std::fmt;

use thiserror::Error;

/// Why cells given by their vertices (a mesh file's cells, or the facets and surfaces of an
/// [`crate::build::IncrementalBuilder`]) could not be made into a G-map. Cells are named by
/// their index: in a mesh file, the index of the cell in the file (from 0, in file order);
/// in the builder, the index of the surface (dimension 3) or of the facet (dimension 2).
#[derive(Clone, Debug, PartialEq, Error)]
#[non_exhaustive]
pub enum MeshError {
    /// A facet (a face of volumes, an edge of polygons, an end of lines) shared by three
    /// cells or more: the cells around it cannot all be sewn in a G-map.
    #[error("the {} with vertices {} lies in {} cells ({}): at most two cells may share it", facet_word(vertices.len(), *dim), list(vertices), cells.len(), list(cells))]
    FacetInManyCells {
        /// the dimension of the cells sharing the facet
        dim: usize,
        /// the vertices of the facet
        vertices: Vec<u64>,
        /// the cells that contain it
        cells: Vec<usize>,
    },
    /// Two facets with the same vertices joined in different cycles.
    #[error("cells {} and {} have faces on the same vertices {} joined in different orders ({} and {})", cells[0], cells[1], list(&sorted(first)), list(first), list(second))]
    FacetOrder {
        /// the two cells
        cells: [usize; 2],
        /// the face in the first cell, as a cycle
        first: Vec<u64>,
        /// the face in the second cell, as a cycle
        second: Vec<u64>,
    },
    /// A face of one cell covering part of a face of another (they share at least two edges
    /// without being the same face): the mesh is not conforming there.
    #[error("non-conforming faces: face {} of cell {} and face {} of cell {} share the edges {} without being one face", list(first), cells[0], list(second), cells[1], edges(shared))]
    NonConforming {
        /// the two cells
        cells: [usize; 2],
        /// the face in the first cell
        first: Vec<u64>,
        /// the face in the second cell
        second: Vec<u64>,
        /// the edges both faces contain
        shared: Vec<[u64; 2]>,
    },
    /// A cell that cannot be made: a vertex repeated, too few vertices, faces that do not
    /// close.
    #[error("cell {cell} ({kind}): {reason}")]
    BadCell {
        /// the cell
        cell: usize,
        /// its type
        kind: String,
        /// what is wrong
        reason: String,
    },
    /// A vertex index beyond the points given.
    #[error("cell {cell} uses vertex {vertex}, but there are {points} points")]
    NoSuchVertex {
        /// the cell
        cell: usize,
        /// the index used
        vertex: u64,
        /// the number of points
        points: usize,
    },
    /// A cell of lower dimension that is not a face, edge or vertex of the cells of the
    /// top dimension (the map would have to hold it apart, as a cell of its own).
    #[error("cell {cell} ({kind}) on vertices {} is not a {} of any {}-dimensional cell of the mesh", list(vertices), cell_word(vertices.len()), top)]
    LooseCell {
        /// the cell
        cell: usize,
        /// its type
        kind: String,
        /// its vertices
        vertices: Vec<u64>,
        /// the top dimension of the mesh
        top: usize,
    },
    /// Two lower cells on the same vertices (their labels would collide).
    #[error("cells {} and {} both lie on vertices {}", cells[0], cells[1], list(vertices))]
    RepeatedCell {
        /// the two cells
        cells: [usize; 2],
        /// their vertices
        vertices: Vec<u64>,
    },
    /// A point (or an edge) where the cells around it meet only there: the map, a
    /// quasi-manifold, would split it into several vertices (edges) and change the space.
    #[error("the cells around {what} {} form {pieces} separate fans: the mesh is not a quasi-manifold there (a G-map would split it)", list(vertices))]
    Pinched {
        /// `"point"` or `"edge"`
        what: &'static str,
        /// its vertices
        vertices: Vec<u64>,
        /// the number of separate pieces
        pieces: usize,
    },
    /// The map would have more darts than allowed.
    #[error("{cells} cells make {} darts, over the limit of {limit} darts", darts.map_or_else(|| "more than 2^64".to_string(), |d| d.to_string()))]
    TooManyDarts {
        /// the number of cells
        cells: usize,
        /// the number of darts, `None` past `u64`
        darts: Option<u64>,
        /// the limit in force
        limit: u64,
    },
    /// A call of the incremental builder out of order (a facet outside a surface…).
    #[error("builder: {0}")]
    Order(String),
    /// A map that [`crate::build::sew3_same_facets`] cannot work on.
    #[error("{0}")]
    Map(String),
}

fn list<T: fmt::Display>(xs: &[T]) -> String {
    let parts: Vec<String> = xs.iter().map(|x| x.to_string()).collect();
    format!("[{}]", parts.join(", "))
}

fn edges(es: &[[u64; 2]]) -> String {
    let parts: Vec<String> = es.iter().map(|[a, b]| format!("{a}-{b}")).collect();
    parts.join(", ")
}

fn sorted(xs: &[u64]) -> Vec<u64> {
    let mut v = xs.to_vec();
    v.sort_unstable();
    v
}

fn facet_word(vertices: usize, dim: usize) -> &'static str {
    match (dim, vertices) {
        (1, _) => "point",
        (2, _) => "edge",
        _ => "face",
    }
}

fn cell_word(vertices: usize) -> &'static str {
    match vertices {
        1 => "vertex",
        2 => "edge",
        _ => "face",
    }
}

impl MeshError {
    /// The same error with every cell index `c` replaced by `f(c)` (the builder numbers
    /// surfaces or facets; a reader gives back the index of the cell in the file).
    pub fn renumber(self, f: impl Fn(usize) -> usize) -> Self {
        match self {
            MeshError::FacetInManyCells { dim, vertices, cells } => {
                MeshError::FacetInManyCells { dim, vertices, cells: cells.into_iter().map(&f).collect() }
            }
            MeshError::FacetOrder { cells, first, second } => {
                MeshError::FacetOrder { cells: cells.map(&f), first, second }
            }
            MeshError::NonConforming { cells, first, second, shared } => {
                MeshError::NonConforming { cells: cells.map(&f), first, second, shared }
            }
            MeshError::BadCell { cell, kind, reason } => MeshError::BadCell { cell: f(cell), kind, reason },
            MeshError::NoSuchVertex { cell, vertex, points } => {
                MeshError::NoSuchVertex { cell: f(cell), vertex, points }
            }
            MeshError::LooseCell { cell, kind, vertices, top } => {
                MeshError::LooseCell { cell: f(cell), kind, vertices, top }
            }
            MeshError::RepeatedCell { cells, vertices } => MeshError::RepeatedCell { cells: cells.map(&f), vertices },
            other => other,
        }
    }

    /// The same error with every vertex `v` replaced by `f(v)` (a `.msh` file names its
    /// nodes by tags).
    pub fn renumber_vertices(self, f: impl Fn(u64) -> u64) -> Self {
        let map = |v: Vec<u64>| -> Vec<u64> { v.into_iter().map(&f).collect() };
        match self {
            MeshError::FacetInManyCells { dim, vertices, cells } => {
                MeshError::FacetInManyCells { dim, vertices: map(vertices), cells }
            }
            MeshError::FacetOrder { cells, first, second } => {
                MeshError::FacetOrder { cells, first: map(first), second: map(second) }
            }
            MeshError::NonConforming { cells, first, second, shared } => MeshError::NonConforming {
                cells,
                first: map(first),
                second: map(second),
                shared: shared.into_iter().map(|e| e.map(&f)).collect(),
            },
            MeshError::LooseCell { cell, kind, vertices, top } => {
                MeshError::LooseCell { cell, kind, vertices: map(vertices), top }
            }
            MeshError::RepeatedCell { cells, vertices } => MeshError::RepeatedCell { cells, vertices: map(vertices) },
            MeshError::Pinched { what, vertices, pieces } => {
                MeshError::Pinched { what, vertices: map(vertices), pieces }
            }
            other => other,
        }
    }
}
