//! LAR, the Linear Algebraic Representation of cell complexes (LAR lecture): every p-cell
//! is the set of its vertices, and the *characteristic matrix* `M_p` (one row per p-cell,
//! one column per vertex, 1 where the vertex belongs to the cell) is stored in CSR.
//! Topological queries are sparse products:
//! * `M_{p-1} M_p^T` counts the common vertices of a (p-1)-cell and a p-cell; the *count
//!   rule* keeps a 1 where the count equals the size of the (p-1)-cell: the unsigned
//!   boundary `[∂_p]` ([`Lar::unsigned_boundary`]);
//! * the nine incidence/adjacency operators `VV … FF` of a 2-complex ([`LarOp`]).
//!
//! From a G-map ([`Lar::from_map`]) a cell's vertex set is the set of 0-cells of its darts.
//! On maps without multi-incidence (every unsigned incidence number 0 or 1) the unsigned
//! boundary equals the unsigned incidence numbers of BO Def. 5. With multi-incidence the
//! vertex-set model loses information: on the one-vertex torus both edges and the face
//! have the vertex set `{v}`, so the two edges cannot be told apart and every incidence
//! (really 2, signed 0) reads 1.
//!
//! ```
//! use gmap_homology::lar::{Csr, Lar};
//! // a triangle: vertices 0, 1, 2; edges {0,1}, {1,2}, {0,2}; one face
//! let lar = Lar::from_cells(3, vec![
//!     Csr::from_rows(3, &[vec![0, 1], vec![1, 2], vec![0, 2]]).unwrap(),
//!     Csr::from_rows(3, &[vec![0, 1, 2]]).unwrap(),
//! ]).unwrap();
//! // the face's boundary is its three edges
//! assert_eq!(lar.unsigned_boundary(2).unwrap().to_dense(), vec![vec![1], vec![1], vec![1]]);
//! ```

use std::fmt::Write as _;

use gmap_core::DenseMap;
use thiserror::Error;

/// Why LAR data is malformed.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
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
}

/// A sparse integer matrix in compressed sparse row form: row `i` holds the column indices
/// `indices[offsets[i]..offsets[i + 1]]` (strictly increasing) with their values.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Csr {
    rows: usize,
    cols: usize,
    offsets: Vec<usize>,
    indices: Vec<u32>,
    values: Vec<i64>,
}

impl Csr {
    /// A 0/1 matrix from the column sets of its rows (sorted and deduplicated here).
    /// Fails if a column is `>= cols`. O(nnz log).
    pub fn from_rows(cols: usize, rows: &[Vec<u32>]) -> Result<Csr, LarError> {
        let mut offsets = Vec::with_capacity(rows.len() + 1);
        offsets.push(0);
        let mut indices = Vec::new();
        for (i, r) in rows.iter().enumerate() {
            let mut r = r.clone();
            r.sort_unstable();
            r.dedup();
            if let Some(&v) = r.iter().find(|&&v| v as usize >= cols) {
                return Err(LarError::VertexOutOfRange { dim: 0, cell: i, vertex: v, vertices: cols });
            }
            indices.extend_from_slice(&r);
            offsets.push(indices.len());
        }
        let values = vec![1; indices.len()];
        Ok(Csr { rows: rows.len(), cols, offsets, indices, values })
    }

    /// The `n × n` identity.
    pub fn identity(n: usize) -> Csr {
        Csr { rows: n, cols: n, offsets: (0..=n).collect(), indices: (0..n as u32).collect(), values: vec![1; n] }
    }

    /// Number of rows.
    pub fn rows(&self) -> usize {
        self.rows
    }

    /// Number of columns.
    pub fn cols(&self) -> usize {
        self.cols
    }

    /// Number of stored entries.
    pub fn nnz(&self) -> usize {
        self.indices.len()
    }

    /// Row `i`: its column indices and values.
    pub fn row(&self, i: usize) -> (&[u32], &[i64]) {
        let r = self.offsets[i]..self.offsets[i + 1];
        (&self.indices[r.clone()], &self.values[r])
    }

    /// The entry at `(i, j)` (0 if not stored). O(log row length).
    pub fn get(&self, i: usize, j: usize) -> i64 {
        let (c, v) = self.row(i);
        c.binary_search(&(j as u32)).map_or(0, |k| v[k])
    }

    /// The transpose. O(nnz + rows + cols).
    pub fn transpose(&self) -> Csr {
        let mut offsets = vec![0usize; self.cols + 1];
        for &j in &self.indices {
            offsets[j as usize + 1] += 1;
        }
        for k in 0..self.cols {
            offsets[k + 1] += offsets[k];
        }
        let mut fill = offsets.clone();
        let mut indices = vec![0u32; self.indices.len()];
        let mut values = vec![0i64; self.indices.len()];
        for i in 0..self.rows {
            let (c, v) = self.row(i);
            for (&j, &x) in c.iter().zip(v) {
                let p = fill[j as usize];
                indices[p] = i as u32;
                values[p] = x;
                fill[j as usize] += 1;
            }
        }
        Csr { rows: self.cols, cols: self.rows, offsets, indices, values }
    }

    /// The product `self · other`, checked (Gustavson's row-by-row algorithm). Zeros are
    /// not stored. O(flops + rows + cols).
    pub fn mul(&self, other: &Csr) -> Result<Csr, LarError> {
        assert_eq!(self.cols, other.rows, "shapes do not agree for a product");
        let mut acc = vec![0i64; other.cols];
        let mut mark = vec![false; other.cols];
        let mut touched: Vec<u32> = Vec::new();
        let mut offsets = Vec::with_capacity(self.rows + 1);
        offsets.push(0);
        let (mut indices, mut values) = (Vec::new(), Vec::new());
        for i in 0..self.rows {
            let (c, v) = self.row(i);
            for (&h, &a) in c.iter().zip(v) {
                let (c2, v2) = other.row(h as usize);
                for (&j, &b) in c2.iter().zip(v2) {
                    let p = a.checked_mul(b).ok_or(LarError::Overflow)?;
                    acc[j as usize] = acc[j as usize].checked_add(p).ok_or(LarError::Overflow)?;
                    if !mark[j as usize] {
                        mark[j as usize] = true;
                        touched.push(j);
                    }
                }
            }
            touched.sort_unstable();
            for &j in &touched {
                if acc[j as usize] != 0 {
                    indices.push(j);
                    values.push(acc[j as usize]);
                }
                acc[j as usize] = 0;
                mark[j as usize] = false;
            }
            touched.clear();
            offsets.push(indices.len());
        }
        Ok(Csr { rows: self.rows, cols: other.cols, offsets, indices, values })
    }

    /// The dense form, row by row (for tests and small matrices).
    pub fn to_dense(&self) -> Vec<Vec<i64>> {
        (0..self.rows).map(|i| (0..self.cols).map(|j| self.get(i, j)).collect()).collect()
    }
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
    vertices: usize,
    cells: Vec<Csr>,
}

impl Lar {
    /// From characteristic matrices `cells[p - 1] = M_p`; each must have `vertices` columns.
    pub fn from_cells(vertices: usize, cells: Vec<Csr>) -> Result<Lar, LarError> {
        for (p, m) in cells.iter().enumerate() {
            if m.cols != vertices {
                return Err(LarError::VertexOutOfRange { dim: p + 1, cell: 0, vertex: m.cols as u32, vertices });
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
            cells.push(Csr::from_rows(v.len(), &rows).expect("0-cell numbers are in range"));
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

    /// `M_p` (the identity for p = 0). Panics if `p > n`.
    pub fn characteristic(&self, p: usize) -> Csr {
        if p == 0 {
            Csr::identity(self.vertices)
        } else {
            self.cells[p - 1].clone()
        }
    }

    /// `M_{p-1,p} = M_{p-1} M_p^T`: entry (i, j) is the number of common vertices of the
    /// (p-1)-cell i and the p-cell j. `1 <= p <= n`.
    pub fn incidence(&self, p: usize) -> Result<Csr, LarError> {
        if p == 0 || p > self.dim() {
            return Err(LarError::NoSuchDimension { p, n: self.dim() });
        }
        self.characteristic(p - 1).mul(&self.characteristic(p).transpose())
    }

    /// The unsigned boundary `[∂_p]` by the count rule: 1 where the p-cell holds every
    /// vertex of the (p-1)-cell, i.e. `M_{p-1,p}(i, j) = #μ_i`. Rows: (p-1)-cells;
    /// columns: p-cells. O(cost of the product).
    pub fn unsigned_boundary(&self, p: usize) -> Result<Csr, LarError> {
        let m = self.incidence(p)?;
        let lower = self.characteristic(p - 1);
        let mut offsets = vec![0usize];
        let (mut indices, mut values) = (Vec::new(), Vec::new());
        for i in 0..m.rows {
            let size = lower.row(i).0.len() as i64;
            let (c, v) = m.row(i);
            for (&j, &x) in c.iter().zip(v) {
                if x == size {
                    indices.push(j);
                    values.push(1);
                }
            }
            offsets.push(indices.len());
        }
        Ok(Csr { rows: m.rows, cols: m.cols, offsets, indices, values })
    }

    /// One of the nine operators of LAR Table 1 (needs n >= 2; `M_2` is the 2-cells).
    pub fn operator(&self, op: LarOp) -> Result<Csr, LarError> {
        if self.dim() < 2 {
            return Err(LarError::NoSuchDimension { p: 2, n: self.dim() });
        }
        let m1 = &self.cells[0];
        let m2 = &self.cells[1];
        Ok(match op {
            LarOp::VV => m1.transpose().mul(m1)?,
            LarOp::VE => m1.transpose(),
            LarOp::VF => m2.transpose(),
            LarOp::EV => m1.clone(),
            LarOp::EE => m1.mul(&m1.transpose())?,
            LarOp::EF => m1.mul(&m2.transpose())?,
            LarOp::FV => m2.clone(),
            LarOp::FE => m2.mul(&m1.transpose())?,
            LarOp::FF => m2.mul(&m2.transpose())?,
        })
    }

    /// The `.lar.json` text: `{"dimension": n, "vertices": k0, "cells": [CV_1, …, CV_n],
    /// "boundary": [∂_1, …, ∂_n]}` where `CV_p` lists the vertex set of every p-cell and
    /// `∂_p` lists, for every p-cell, the (p-1)-cells of its unsigned boundary.
    pub fn to_json(&self) -> Result<String, LarError> {
        let mut s = format!("{{\"dimension\": {}, \"vertices\": {},\n \"cells\": [", self.dim(), self.vertices);
        let list = |s: &mut String, m: &Csr| {
            s.push('[');
            for i in 0..m.rows {
                if i > 0 {
                    s.push_str(", ");
                }
                let (c, _) = m.row(i);
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
            list(&mut s, m);
        }
        s.push_str("],\n \"boundary\": [");
        for p in 1..=self.dim() {
            if p > 1 {
                s.push_str(",\n  ");
            }
            list(&mut s, &self.unsigned_boundary(p)?.transpose());
        }
        s.push_str("]}\n");
        Ok(s)
    }
}
