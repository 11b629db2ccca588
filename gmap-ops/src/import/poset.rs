//! Regular cell complexes given by their face poset, made into G-maps by the flag
//! (cell-tuple) construction.
//!
//! The input is a [`FacePoset`]: cells numbered `0..m`, each with a dimension, and the
//! *covering* pairs `(higher, lower)` where `lower` is a face of `higher` of dimension one
//! less (only consecutive dimensions; deeper faces follow by transitivity). A dart is a
//! maximal chain `c_0 < c_1 < … < c_n` (a vertex, an edge on it, …, an n-cell), and
//! `alpha_i` replaces `c_i` by the other i-cell between `c_{i-1}` and `c_{i+1}`.
//!
//! This is a G-map exactly when the poset is *thin* (the diamond property): every edge has
//! exactly two vertices, every interval `c_{i-1} < · < c_{i+1}` holds exactly two i-cells,
//! and every (n-1)-cell lies in one or two n-cells. The complex must also be pure: every cell
//! lies in an n-cell. [`FacePoset::to_gmap`] checks all of it and says which cells fail.
//!
//! ```
//! use gmap_ops::import::FacePoset;
//! // a triangle: 3 vertices, 3 edges, 1 face
//! let mut p = FacePoset::new();
//! let v: Vec<usize> = (0..3).map(|_| p.add_cell(0)).collect();
//! let e: Vec<usize> = (0..3).map(|_| p.add_cell(1)).collect();
//! let f = p.add_cell(2);
//! for k in 0..3 {
//!     p.add_cover(e[k], v[k]);
//!     p.add_cover(e[k], v[(k + 1) % 3]);
//!     p.add_cover(f, e[k]);
//! }
//! let m = p.to_gmap(1_000).unwrap();
//! assert_eq!(m.dart_count(), 6);
//! assert_eq!(m.cell_counts(), vec![3, 3, 1]);
//! ```

use std::collections::HashMap;

use gmap_core::DenseMap;
use thiserror::Error;

/// Why a face poset is not that of a regular cell complex that a G-map can hold.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
#[non_exhaustive]
pub enum PosetError {
    /// The poset has no cell.
    #[error("the incidence graph has no cell")]
    Empty,
    /// A covering pair names a cell that does not exist.
    #[error("incidence ({higher}, {lower}) names a cell outside 0..{cells}")]
    NoSuchCell {
        /// the higher cell given
        higher: usize,
        /// the lower cell given
        lower: usize,
        /// the number of cells
        cells: usize,
    },
    /// A covering pair whose dimensions are not consecutive.
    #[error("cell {lower} (dimension {lower_dim}) is given as a face of cell {higher} (dimension {higher_dim}): dimensions must differ by one")]
    NotConsecutive {
        /// the higher cell
        higher: usize,
        /// its dimension
        higher_dim: usize,
        /// the lower cell
        lower: usize,
        /// its dimension
        lower_dim: usize,
    },
    /// The same covering pair twice.
    #[error("incidence ({higher}, {lower}) is given twice")]
    Duplicate {
        /// the higher cell
        higher: usize,
        /// the lower cell
        lower: usize,
    },
    /// An edge without exactly two vertices.
    #[error("edge {edge} has {vertices} vertices, not 2: not a regular complex")]
    EdgeVertices {
        /// the edge
        edge: usize,
        /// its number of vertices
        vertices: usize,
    },
    /// The diamond property fails: the interval between two cells does not hold exactly two cells.
    #[error("diamond property fails: {count} cells of dimension {dim} lie between cell {lower} and cell {upper} (2 expected)")]
    Diamond {
        /// the lower end of the interval
        lower: usize,
        /// the upper end
        upper: usize,
        /// the dimension of the cells between
        dim: usize,
        /// how many there are
        count: usize,
    },
    /// An (n-1)-cell in three or more n-cells.
    #[error("cell {cell} of dimension {dim} lies in {count} cells of dimension {} (at most 2)", .dim + 1)]
    TooManyCofaces {
        /// the (n-1)-cell
        cell: usize,
        /// its dimension
        dim: usize,
        /// the number of n-cells on it
        count: usize,
    },
    /// A cell that is in no cell of the top dimension, or a cell of positive dimension
    /// without faces.
    #[error("cell {cell} of dimension {dim} is not part of any {top}-cell: the complex is not pure")]
    NotPure {
        /// the cell
        cell: usize,
        /// its dimension
        dim: usize,
        /// the top dimension
        top: usize,
    },
    /// Too many flags.
    #[error("the incidence graph has more than {limit} flags (darts)")]
    TooManyDarts {
        /// the limit in force
        limit: u64,
    },
    /// The flags would take more than the memory limit (`--max-memory`).
    #[error(transparent)]
    MemoryLimit(#[from] gmap_core::resources::MemoryLimit),
}

/// The face poset of a cell complex: cells with dimensions and covering pairs (module docs).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct FacePoset {
    /// the dimension of each cell
    pub dims: Vec<usize>,
    /// the covering pairs `(higher, lower)`, `dims[higher] == dims[lower] + 1`
    pub covers: Vec<(usize, usize)>,
}

impl FacePoset {
    /// An empty poset.
    pub fn new() -> Self {
        Self::default()
    }

    /// Adds a cell of dimension `dim`; returns its number.
    pub fn add_cell(&mut self, dim: usize) -> usize {
        self.dims.push(dim);
        self.dims.len() - 1
    }

    /// Records that `lower` is a facet of `higher` (checked by [`FacePoset::to_gmap`]).
    pub fn add_cover(&mut self, higher: usize, lower: usize) {
        self.covers.push((higher, lower));
    }

    /// The top dimension n (the largest cell dimension), or `None` when empty.
    pub fn dim(&self) -> Option<usize> {
        self.dims.iter().copied().max()
    }

    /// Checks the poset (module docs) without building the map.
    pub fn check(&self) -> Result<(), PosetError> {
        self.flags(u64::MAX).map(|_| ())
    }

    /// The G-map of the flags (module docs), refusing more than `max_darts` flags. Darts are
    /// numbered in the order of a depth-first enumeration from the n-cells in increasing
    /// number. O(F n d) for F flags and faces of degree at most d.
    pub fn to_gmap(&self, max_darts: u64) -> Result<DenseMap, PosetError> {
        self.to_gmap_with_flags(max_darts).map(|(map, _)| map)
    }

    /// [`FacePoset::to_gmap`] with the flags: dart `k` is the flag
    /// `flags[k (n + 1)..(k + 1) (n + 1)]`, its cells of dimension 0 to n, so the `i`-cell of
    /// the map that holds dart `k` is the poset's cell `flags[k (n + 1) + i]`.
    pub fn to_gmap_with_flags(&self, max_darts: u64) -> Result<(DenseMap, Vec<u32>), PosetError> {
        let (n, flags, down, up) = self.flags(max_darts.min(u32::MAX as u64 - 1))?;
        let w = n + 1;
        let count = flags.len() / w;
        let mut index: HashMap<&[u32], u32> = HashMap::with_capacity(count);
        for k in 0..count {
            index.insert(&flags[k * w..(k + 1) * w], k as u32);
        }
        let mut alpha = vec![0u32; count * w];
        let mut tmp = vec![0u32; w];
        for k in 0..count {
            let flag = &flags[k * w..(k + 1) * w];
            for i in 0..w {
                let c = flag[i] as usize;
                // candidates: faces of c_{i+1} (or every n-cell, for i = n) that contain c_{i-1}
                let other = if i < n {
                    let above = flag[i + 1] as usize;
                    down[above]
                        .iter()
                        .copied()
                        .find(|&x| x != c && (i == 0 || down[x].contains(&(flag[i - 1] as usize))))
                } else if i > 0 {
                    up[flag[i - 1] as usize].iter().copied().find(|&x| x != c)
                } else {
                    None
                };
                alpha[k * w + i] = match other {
                    None => k as u32,
                    Some(x) => {
                        tmp.copy_from_slice(flag);
                        tmp[i] = x as u32;
                        index[tmp.as_slice()]
                    }
                };
            }
        }
        let map = DenseMap::from_flat_unchecked(n, alpha).map_err(|_| PosetError::TooManyDarts { limit: max_darts })?;
        debug_assert!(map.validate().is_ok());
        drop(index);
        Ok((map, flags))
    }

    /// Checks everything and enumerates the flags (flat, `n + 1` cells each).
    #[allow(clippy::type_complexity)]
    fn flags(&self, limit: u64) -> Result<(usize, Vec<u32>, Vec<Vec<usize>>, Vec<Vec<usize>>), PosetError> {
        let n = self.dim().ok_or(PosetError::Empty)?;
        let m = self.dims.len();
        let mut down: Vec<Vec<usize>> = vec![Vec::new(); m];
        let mut up: Vec<Vec<usize>> = vec![Vec::new(); m];
        for &(h, l) in &self.covers {
            if h >= m || l >= m {
                return Err(PosetError::NoSuchCell { higher: h, lower: l, cells: m });
            }
            if self.dims[h] != self.dims[l] + 1 {
                return Err(PosetError::NotConsecutive {
                    higher: h,
                    higher_dim: self.dims[h],
                    lower: l,
                    lower_dim: self.dims[l],
                });
            }
            if down[h].contains(&l) {
                return Err(PosetError::Duplicate { higher: h, lower: l });
            }
            down[h].push(l);
            up[l].push(h);
        }
        for c in 0..m {
            let d = self.dims[c];
            if d == 1 && down[c].len() != 2 {
                return Err(PosetError::EdgeVertices { edge: c, vertices: down[c].len() });
            }
            if d > 0 && down[c].is_empty() {
                return Err(PosetError::NotPure { cell: c, dim: d, top: n });
            }
            if d < n && up[c].is_empty() {
                return Err(PosetError::NotPure { cell: c, dim: d, top: n });
            }
            if d + 1 == n && up[c].len() > 2 {
                return Err(PosetError::TooManyCofaces { cell: c, dim: d, count: up[c].len() });
            }
        }
        // diamonds: for every pair a < b with dims d-1, d+1, exactly two cells between
        for b in 0..m {
            let db = self.dims[b];
            if db < 2 {
                continue;
            }
            let mut between: HashMap<usize, usize> = HashMap::new();
            for &c in &down[b] {
                for &a in &down[c] {
                    *between.entry(a).or_insert(0) += 1;
                }
            }
            let mut bad: Vec<(usize, usize)> = between.into_iter().filter(|&(_, k)| k != 2).collect();
            bad.sort_unstable();
            if let Some(&(a, count)) = bad.first() {
                return Err(PosetError::Diamond { lower: a, upper: b, dim: db - 1, count });
            }
        }
        // the maximal chains counted before they are listed: chains[c] is the number of chains
        // from c down to a vertex (in increasing dimension, saturating), O(covers)
        let mut by_dim: Vec<usize> = (0..m).collect();
        by_dim.sort_by_key(|&c| self.dims[c]);
        let mut chains = vec![0u64; m];
        for &c in &by_dim {
            chains[c] =
                if self.dims[c] == 0 { 1 } else { down[c].iter().fold(0u64, |acc, &f| acc.saturating_add(chains[f])) };
        }
        let total = (0..m).filter(|&c| self.dims[c] == n).fold(0u64, |acc, c| acc.saturating_add(chains[c]));
        if total > limit {
            return Err(PosetError::TooManyDarts { limit });
        }
        // the flags, their index and the involutions: 4 (n + 1) bytes each, plus the index
        let per_flag = 8 * (n as u64 + 1) + 32;
        gmap_core::resources::check_memory("the flags of the face poset", total.checked_mul(per_flag))?;
        // depth-first enumeration of the maximal chains, from the top down
        let w = n + 1;
        let mut flags: Vec<u32> = Vec::new();
        let mut chain = vec![0u32; w];
        let mut stack: Vec<(usize, usize)> = Vec::new(); // (level, cell)
        for top in (0..m).filter(|&c| self.dims[c] == n) {
            stack.push((n, top));
            while let Some((lvl, c)) = stack.pop() {
                chain[lvl] = c as u32;
                if lvl == 0 {
                    if (flags.len() / w) as u64 >= limit {
                        return Err(PosetError::TooManyDarts { limit });
                    }
                    flags.extend_from_slice(&chain);
                } else {
                    for &f in down[c].iter().rev() {
                        stack.push((lvl - 1, f));
                    }
                }
            }
        }
        Ok((n, flags, down, up))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The boundary of a square, as a poset of dimension 1, plus optionally its face.
    fn square(with_face: bool) -> FacePoset {
        let mut p = FacePoset::new();
        let v: Vec<usize> = (0..4).map(|_| p.add_cell(0)).collect();
        let e: Vec<usize> = (0..4).map(|_| p.add_cell(1)).collect();
        for k in 0..4 {
            p.add_cover(e[k], v[k]);
            p.add_cover(e[k], v[(k + 1) % 4]);
        }
        if with_face {
            let f = p.add_cell(2);
            for &x in &e {
                p.add_cover(f, x);
            }
        }
        p
    }

    #[test]
    fn square_and_its_boundary() {
        let m = square(false).to_gmap(100).unwrap();
        m.validate().unwrap();
        assert_eq!(m.cell_counts(), vec![4, 4]);
        let m = square(true).to_gmap(100).unwrap();
        m.validate().unwrap();
        assert_eq!(m.dart_count(), 8);
        assert_eq!(m.cell_counts(), vec![4, 4, 1]);
        assert_eq!(square(true).to_gmap(7).unwrap_err(), PosetError::TooManyDarts { limit: 7 });
    }

    #[test]
    fn refusals_say_why() {
        let mut p = square(true);
        let extra = p.add_cell(1);
        p.add_cover(extra, 0);
        assert_eq!(p.check().unwrap_err(), PosetError::EdgeVertices { edge: extra, vertices: 1 });
        let mut p = square(true);
        p.add_cover(8, 0);
        assert!(matches!(p.check().unwrap_err(), PosetError::NotConsecutive { higher: 8, lower: 0, .. }));
        // a second face missing one of the edges: vertex 0 lies on only one of its edges
        let mut p = square(true);
        let f = p.add_cell(2);
        for x in 4..7 {
            p.add_cover(f, x);
        }
        let e = p.check().unwrap_err();
        assert_eq!(e, PosetError::Diamond { lower: 0, upper: 9, dim: 1, count: 1 });
        // three faces on one edge
        let mut p = square(true);
        for _ in 0..2 {
            let f = p.add_cell(2);
            for x in 4..8 {
                p.add_cover(f, x);
            }
        }
        assert_eq!(p.check().unwrap_err(), PosetError::TooManyCofaces { cell: 4, dim: 1, count: 3 });
        let mut p = square(true);
        p.add_cell(0);
        assert_eq!(p.check().unwrap_err(), PosetError::NotPure { cell: 9, dim: 0, top: 2 });
    }
}
