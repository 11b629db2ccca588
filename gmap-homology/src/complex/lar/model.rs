//! The model of the module, apart from its re-exports (see the module docs).

use crate::engine::chain::ChainError;
use crate::engine::sparse::SparseMatrix;
use gmap_core::DenseMap;
use std::fmt::Write as _;
use thiserror::Error;

/// Why LAR data is malformed.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
#[non_exhaustive]
pub enum LarError {
    /// A vertex index is out of range.
    #[error("cell {cell} of dimension {dim} names vertex {vertex}, but there are {vertices} vertices")]
    VertexOutOfRange {
        /// dimension of the cell
        dim: usize,
        /// the cell
        cell: usize,
        /// the vertex
        vertex: u32,
        /// number of vertices
        vertices: usize,
    },
    /// A count does not fit (more than 2^63 entries).
    #[error("integer overflow in a sparse product")]
    Overflow,
    /// `p` is out of `1..=n`.
    #[error("no boundary of dimension {p} in a complex of dimension {n}")]
    NoSuchDimension {
        /// the dimension asked
        p: usize,
        /// the complex's dimension
        n: usize,
    },
    /// An edge does not have exactly two vertices, so it has no conventional orientation.
    #[error("edge {edge} has {count} vertices, an oriented edge needs 2")]
    EdgeVertices {
        /// the edge
        edge: usize,
        /// its number of vertices
        count: usize,
    },
    /// A p-cell (p >= 2) has no facet by the count rule.
    #[error("{dim}-cell {cell} has no ({}-dimensional) facet", .dim - 1)]
    NoFacet {
        /// dimension of the cell
        dim: usize,
        /// the cell
        cell: usize,
    },
    /// The facets of a p-cell are not a closed (p-1)-cycle: a (p-2)-cell of its boundary
    /// lies on `count != 2` of its facets.
    #[error("{dim}-cell {cell}: ({}-cell) {ridge} lies on {count} of its facets, a closed boundary needs 2", .dim - 2)]
    OpenBoundary {
        /// dimension of the cell
        dim: usize,
        /// the cell
        cell: usize,
        /// the (p-2)-cell
        ridge: usize,
        /// on how many facets of the cell it lies
        count: usize,
    },
    /// The boundary of a p-cell falls into several pieces, so orienting it from its first
    /// facet leaves a piece without orientation.
    #[error("{dim}-cell {cell}: its boundary is disconnected (facet {facet} is not reached from the first)")]
    DisconnectedBoundary {
        /// dimension of the cell
        dim: usize,
        /// the cell
        cell: usize,
        /// a facet not reached
        facet: usize,
    },
    /// The facets of a p-cell cannot be signed so that their boundaries cancel.
    #[error("{dim}-cell {cell}: its boundary is not orientable (conflict at ({}-cell) {ridge})", .dim - 2)]
    NonOrientable {
        /// dimension of the cell
        dim: usize,
        /// the cell
        cell: usize,
        /// the (p-2)-cell where two signs disagree
        ridge: usize,
    },
    /// A top cell has zero oriented area (2D) or volume (3D), so its sign is undefined.
    #[error("{dim}-cell {cell} has zero oriented measure")]
    ZeroMeasure {
        /// dimension of the cell
        dim: usize,
        /// the cell
        cell: usize,
    },
    /// The number of points does not match the number of vertices.
    #[error("{points} points given for {vertices} vertices")]
    PointCount {
        /// points given
        points: usize,
        /// vertices of the complex
        vertices: usize,
    },
    /// Two p-cells have the same vertex set, so the count rule cannot tell them apart
    /// (a G-map whose cells are not determined by their vertices, e.g. two edges glued at
    /// both ends only).
    #[error("{dim}-cells {first} and {second} have the same vertices")]
    SameVertices {
        /// dimension of the cells
        dim: usize,
        /// the first cell
        first: usize,
        /// the second cell, with the same vertex set
        second: usize,
    },
    /// The signed matrices fail to form a chain complex (kept for completeness: the
    /// conventional orientation always gives `∂∂ = 0`).
    #[error("the signed boundaries are not a chain complex: {0}")]
    Chain(#[from] ChainError),
}

/// The characteristic matrix of cells given by their vertex sets: row `i` has a 1 in the
/// columns of `rows[i]` (sorted and deduplicated here). Fails if a vertex is `>= vertices`.
/// O(nnz log + vertices).
pub fn characteristic_matrix(vertices: usize, rows: &[Vec<u32>]) -> Result<SparseMatrix, LarError> {
    // the transpose has the vertex sets as columns: build it, then turn it over
    let mut col_ptr = Vec::with_capacity(rows.len() + 1);
    col_ptr.push(0);
    let mut row_idx = Vec::new();
    for (i, r) in rows.iter().enumerate() {
        let mut r = r.clone();
        r.sort_unstable();
        r.dedup();
        if let Some(&v) = r.iter().find(|&&v| v as usize >= vertices) {
            return Err(LarError::VertexOutOfRange { dim: 0, cell: i, vertex: v, vertices });
        }
        row_idx.extend_from_slice(&r);
        col_ptr.push(row_idx.len());
    }
    let vals = vec![1; row_idx.len()];
    let t = SparseMatrix::try_from_csc(vertices, rows.len(), col_ptr, row_idx, vals)
        .expect("vertex sets are sorted, distinct and in range");
    Ok(t.transpose())
}

/// `a · b`, checked. The shapes agree by construction.
pub(super) fn mul(a: &SparseMatrix, b: &SparseMatrix) -> Result<SparseMatrix, LarError> {
    debug_assert_eq!(a.cols(), b.rows(), "shapes of a product");
    a.checked_mul(b).ok_or(LarError::Overflow)
}

/// The number of entries in each row of `m`. O(nnz + rows).
pub(super) fn row_lengths(m: &SparseMatrix) -> Vec<usize> {
    let mut len = vec![0usize; m.rows()];
    for (i, _, _) in m.iter() {
        len[i] += 1;
    }
    len
}

/// The 0/1 matrix of the non-zero entries of `m` off its diagonal. O(nnz).
pub(super) fn off_diagonal_support(m: &SparseMatrix) -> SparseMatrix {
    let columns: Vec<Vec<(u32, i64)>> =
        (0..m.cols()).map(|j| m.col(j).0.iter().filter(|&&i| i as usize != j).map(|&i| (i, 1)).collect()).collect();
    SparseMatrix::try_from_columns(m.rows(), &columns).expect("a subset of a valid matrix")
}

/// The nine incidence/adjacency operators of a 2-complex (LAR, Table 1).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum LarOp {
    /// vertices sharing an edge with a vertex: `M_1^T M_1`
    VV,
    /// edges on a vertex: `M_1^T`
    VE,
    /// faces on a vertex: `M_2^T`
    VF,
    /// vertices of an edge: `M_1`
    EV,
    /// edges sharing a vertex: `M_1 M_1^T`
    EE,
    /// faces on an edge (shared vertices): `M_1 M_2^T`
    EF,
    /// vertices of a face: `M_2`
    FV,
    /// edges of a face (shared vertices): `M_2 M_1^T`
    FE,
    /// faces sharing vertices: `M_2 M_2^T`
    FF,
}

impl LarOp {
    /// All nine, in table order.
    pub const ALL: [LarOp; 9] =
        [LarOp::VV, LarOp::VE, LarOp::VF, LarOp::EV, LarOp::EE, LarOp::EF, LarOp::FV, LarOp::FE, LarOp::FF];
}

/// A cell complex in LAR form: the number of vertices and the characteristic matrices
/// `M_1..M_n` (`M_0` is the identity).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Lar {
    pub(super) vertices: usize,
    pub(super) cells: Vec<SparseMatrix>,
}

impl Lar {
    /// From characteristic matrices `cells[p - 1] = M_p`; each must have `vertices` columns.
    pub fn from_cells(vertices: usize, cells: Vec<SparseMatrix>) -> Result<Lar, LarError> {
        for (p, m) in cells.iter().enumerate() {
            if m.cols() != vertices {
                return Err(LarError::VertexOutOfRange { dim: p + 1, cell: 0, vertex: m.cols() as u32, vertices });
            }
        }
        Ok(Lar { vertices, cells })
    }

    /// The vertex sets of the cells of a G-map: `M_p(c, v) = 1` when a dart of the p-cell
    /// `c` lies in the 0-cell `v` (cells numbered as in `DenseMap::cells`). O(N n log N).
    pub fn from_map(map: &DenseMap) -> Lar {
        let n = map.dim();
        let v = map.cells(0);
        let mut cells = Vec::with_capacity(n);
        for p in 1..=n {
            let c = map.cells(p);
            let mut rows: Vec<Vec<u32>> = vec![Vec::new(); c.len()];
            for d in map.darts() {
                rows[c.of[d.index()] as usize].push(v.of[d.index()]);
            }
            cells.push(characteristic_matrix(v.len(), &rows).expect("0-cell numbers are in range"));
        }
        Lar { vertices: v.len(), cells }
    }

    /// The dimension n.
    pub fn dim(&self) -> usize {
        self.cells.len()
    }

    /// The number of vertices.
    pub fn vertices(&self) -> usize {
        self.vertices
    }

    /// `M_p` (the identity for p = 0). Panics if `p > n`; [`Lar::try_characteristic`] is
    /// the fallible form.
    #[track_caller]
    pub fn characteristic(&self, p: usize) -> SparseMatrix {
        self.try_characteristic(p).unwrap_or_else(|e| panic!("Lar::characteristic: {e}"))
    }

    /// `M_p` (the identity for p = 0), or [`LarError::NoSuchDimension`] when `p > n`.
    /// O(nnz of `M_p`) for the copy.
    pub fn try_characteristic(&self, p: usize) -> Result<SparseMatrix, LarError> {
        match p {
            0 => Ok(SparseMatrix::identity(self.vertices)),
            _ => self.cells.get(p - 1).cloned().ok_or(LarError::NoSuchDimension { p, n: self.dim() }),
        }
    }

    /// `M_{p-1,p} = M_{p-1} M_p^T`: entry (i, j) is the number of common vertices of the
    /// (p-1)-cell i and the p-cell j. `1 <= p <= n`.
    pub fn incidence(&self, p: usize) -> Result<SparseMatrix, LarError> {
        if p == 0 || p > self.dim() {
            return Err(LarError::NoSuchDimension { p, n: self.dim() });
        }
        mul(&self.characteristic(p - 1), &self.characteristic(p).transpose())
    }

    /// The unsigned boundary `[∂_p]` by the count rule: 1 where the p-cell holds every
    /// vertex of the (p-1)-cell, i.e. `M_{p-1,p}(i, j) = #μ_i`. Rows: (p-1)-cells;
    /// columns: p-cells. O(cost of the product).
    pub fn unsigned_boundary(&self, p: usize) -> Result<SparseMatrix, LarError> {
        let m = self.incidence(p)?;
        let size = row_lengths(&self.characteristic(p - 1));
        let mut col_ptr = vec![0usize];
        let mut row_idx = Vec::new();
        for j in 0..m.cols() {
            let (r, v) = m.col(j);
            row_idx.extend(r.iter().zip(v).filter(|&(&i, &x)| x == size[i as usize] as i64).map(|(&i, _)| i));
            col_ptr.push(row_idx.len());
        }
        let vals = vec![1; row_idx.len()];
        Ok(SparseMatrix::try_from_csc(m.rows(), m.cols(), col_ptr, row_idx, vals).expect("a subset of a valid matrix"))
    }

    /// One of the nine operators of LAR Table 1 (needs n >= 2; `M_2` is the 2-cells).
    pub fn operator(&self, op: LarOp) -> Result<SparseMatrix, LarError> {
        if self.dim() < 2 {
            return Err(LarError::NoSuchDimension { p: 2, n: self.dim() });
        }
        let m1 = &self.cells[0];
        let m2 = &self.cells[1];
        Ok(match op {
            LarOp::VV => mul(&m1.transpose(), m1)?,
            LarOp::VE => m1.transpose(),
            LarOp::VF => m2.transpose(),
            LarOp::EV => m1.clone(),
            LarOp::EE => mul(m1, &m1.transpose())?,
            LarOp::EF => mul(m1, &m2.transpose())?,
            LarOp::FV => m2.clone(),
            LarOp::FE => mul(m2, &m1.transpose())?,
            LarOp::FF => mul(m2, &m2.transpose())?,
        })
    }

    /// The incidence or adjacency *relation* named by `op`, as a 0/1 matrix with the same
    /// rows and columns as [`Lar::operator`] (LAR Tables 1 and 2):
    /// * `VE`, `VF`, `EV`, `FV`: the characteristic matrices (a vertex of a cell);
    /// * `EF`, `FE`: an edge on the boundary of a face, by the count rule
    ///   ([`Lar::unsigned_boundary`]`(2)` and its transpose);
    /// * `VV`: two distinct vertices of one edge (off-diagonal support of `M_1^T M_1`);
    /// * `EE`: two distinct edges with a common vertex (off-diagonal support of `M_1 M_1^T`);
    /// * `FF`: two distinct faces with a common boundary edge (off-diagonal support of
    ///   `[∂_2]^T [∂_2]`, unsigned).
    ///
    /// On a closed polyhedral surface whose faces are polygons without repeated vertices,
    /// two of them sharing at most one edge, the number
    /// of entries ([`Lar::cardinality`]) is `2|E|` for all but `EE`, which has
    /// `Σ_v deg v (deg v - 1) >= 4|E|` when every vertex has degree at least 3 (Table 2).
    /// Needs `n >= 2`. O(cost of the product).
    pub fn relation(&self, op: LarOp) -> Result<SparseMatrix, LarError> {
        let m = self.operator(op)?;
        Ok(match op {
            LarOp::VE | LarOp::VF | LarOp::EV | LarOp::FV => m,
            LarOp::EF => self.unsigned_boundary(2)?,
            LarOp::FE => self.unsigned_boundary(2)?.transpose(),
            LarOp::VV | LarOp::EE => off_diagonal_support(&m),
            LarOp::FF => {
                let b = self.unsigned_boundary(2)?;
                off_diagonal_support(&mul(&b.transpose(), &b)?)
            }
        })
    }

    /// The number of pairs in [`Lar::relation`]`(op)`.
    pub fn cardinality(&self, op: LarOp) -> Result<usize, LarError> {
        Ok(self.relation(op)?.nnz())
    }

    /// The `.lar.json` text: `{"dimension": n, "vertices": k0, "cells": [CV_1, …, CV_n],
    /// "boundary": [∂_1, …, ∂_n]}` where `CV_p` lists the vertex set of every p-cell and
    /// `∂_p` lists, for every p-cell, the (p-1)-cells of its unsigned boundary.
    pub fn to_json(&self) -> Result<String, LarError> {
        let mut s = format!("{{\"dimension\": {}, \"vertices\": {},\n \"cells\": [", self.dim(), self.vertices);
        // one list per column of `m`
        let list = |s: &mut String, m: &SparseMatrix| {
            s.push('[');
            for i in 0..m.cols() {
                if i > 0 {
                    s.push_str(", ");
                }
                let (c, _) = m.col(i);
                s.push('[');
                for (k, j) in c.iter().enumerate() {
                    let _ = write!(s, "{}{j}", if k == 0 { "" } else { ", " });
                }
                s.push(']');
            }
            s.push(']');
        };
        for (p, m) in self.cells.iter().enumerate() {
            if p > 0 {
                s.push_str(",\n  ");
            }
            list(&mut s, &m.transpose());
        }
        s.push_str("],\n \"boundary\": [");
        for p in 1..=self.dim() {
            if p > 1 {
                s.push_str(",\n  ");
            }
            list(&mut s, &self.unsigned_boundary(p)?);
        }
        s.push_str("]}\n");
        Ok(s)
    }
}
