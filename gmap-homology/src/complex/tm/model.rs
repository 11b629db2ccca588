//! The model of the module, apart from its re-exports (see the module docs).

use super::signed::SignedSet;
use crate::complex::arch::{all_cell_incidences, ArchComplex, FromMapError};
use gmap_core::DenseMap;
use std::collections::BTreeMap;
use std::fmt;
use thiserror::Error;

/// Why a model cannot be built, annotated or closed.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
#[non_exhaustive]
pub enum TmError {
    /// A cell index (in an incidence or a query) is not below the number of cells.
    #[error("no cell {index}: the model has {len} cells")]
    NoSuchCell {
        /// the index
        index: usize,
        /// the number of cells
        len: usize,
    },
    /// A cell's dimension exceeds the model's.
    #[error("cell {id} has dimension {dim}, above the model's {max}")]
    DimensionAbove {
        /// the cell's id
        id: u64,
        /// its dimension
        dim: usize,
        /// the model's dimension
        max: usize,
    },
    /// Two cells share an id (ids are the entry keys of TM §XI).
    #[error("cells {first} and {second} share the id {id}")]
    DuplicateId {
        /// the id
        id: u64,
        /// the first cell with it (index)
        first: usize,
        /// the second (index)
        second: usize,
    },
    /// An incidence joins cells whose dimensions do not differ by one (TM (2:1) relates
    /// a k-cell to a (k+1)-cell only).
    #[error("incidence of {lower_dim}-cell {lower} on {upper_dim}-cell {upper}: dimensions must differ by one")]
    NotAdjacent {
        /// the upper cell's id
        upper: u64,
        /// its dimension
        upper_dim: usize,
        /// the lower cell's id
        lower: u64,
        /// its dimension
        lower_dim: usize,
    },
    /// A query needs a cell of another dimension.
    #[error("cell {id} has dimension {dim}, the query needs dimension {expected}")]
    WrongDimension {
        /// the cell's id
        id: u64,
        /// its dimension
        dim: usize,
        /// the dimension needed
        expected: usize,
    },
    /// An annotation needs at most one cell occurrence of each sign (TM (7:3), (7:4): "its
    /// pair of cobounding cells"), and the cell has more.
    #[error("{dim}-cell {id} is not annotated by a pair: +{plus}/-{minus} occurrences")]
    NotAPair {
        /// the cell's id
        id: u64,
        /// its dimension
        dim: usize,
        /// positive occurrences
        plus: u64,
        /// negative occurrences
        minus: u64,
    },
    /// The query has no meaning in a model of this dimension.
    #[error("a model of dimension 0 has no {what}")]
    Pointless {
        /// what was asked
        what: &'static str,
    },
    /// The exterior cell's id is already a cell's.
    #[error("the id {id} is already used by a cell")]
    IdInUse {
        /// the id
        id: u64,
    },
    /// An (n-1)-cell whose coboundary is unbalanced is not free (cobounded once): closing
    /// cannot pair it up with one exterior occurrence.
    #[error("{dim}-cell {id} is cobounded +{plus}/-{minus} times: not a free face, the exterior cannot close it")]
    NotFree {
        /// the cell's id
        id: u64,
        /// its dimension
        dim: usize,
        /// positive occurrences in its coboundary
        plus: u64,
        /// negative occurrences
        minus: u64,
    },
    /// Every (n-1)-cell already has its two sides: there is nothing to close.
    #[error("the model has no free {dim}-cell: nothing to close")]
    AlreadyClosed {
        /// the dimension of the free cells looked for (n - 1)
        dim: usize,
    },
}

/// A set of the structure (6:1): the k-cells `C^k`, the k-circuits `Z^k` or the
/// k-cocircuits `Y^k`. Displayed as in the paper: `C^2`, `Z^1`, `Y^3`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum TmSet {
    /// the k-cells
    C(usize),
    /// the k-circuits (here: the bounding ones, boundaries of (k+1)-cells)
    Z(usize),
    /// the k-cocircuits (here: the cobounding ones, coboundaries of (k-1)-cells)
    Y(usize),
}

impl TmSet {
    /// The Poincaré dual set in an n-dimensional model (TM §IV): `C^k` and `C^{n-k}`,
    /// `Z^k` and `Y^{n-k}`. Precondition: the index is at most `n` (else it is kept).
    pub fn dual(self, n: usize) -> TmSet {
        match self {
            TmSet::C(k) => TmSet::C(n.checked_sub(k).unwrap_or(k)),
            TmSet::Z(k) => TmSet::Y(n.checked_sub(k).unwrap_or(k)),
            TmSet::Y(k) => TmSet::Z(n.checked_sub(k).unwrap_or(k)),
        }
    }
}

impl fmt::Display for TmSet {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            TmSet::C(k) => write!(f, "C^{k}"),
            TmSet::Z(k) => write!(f, "Z^{k}"),
            TmSet::Y(k) => write!(f, "Y^{k}"),
        }
    }
}

/// Cells with dimensions and signed incidences with multiplicities: the structure (6:1).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TmModel {
    pub(super) dim: usize,
    pub(super) ids: Vec<u64>,
    pub(super) dims: Vec<usize>,
    pub(super) per_dim: Vec<Vec<usize>>,
    /// for each cell, its bounding circuit `B(c)`
    pub(super) bound: Vec<SignedSet>,
    /// for each cell, its cobounding cocircuit `G(c)`
    pub(super) cobound: Vec<SignedSet>,
}

impl TmModel {
    /// The model from checked cells and incidences.
    fn build(dim: usize, cells: &[(u64, usize)], incidences: &[(usize, usize, u64, u64)]) -> TmModel {
        let nr = cells.len();
        let mut per_dim = vec![Vec::new(); dim + 1];
        for (k, &(_, d)) in cells.iter().enumerate() {
            per_dim[d].push(k);
        }
        let mut bound = vec![SignedSet::new(); nr];
        let mut cobound = vec![SignedSet::new(); nr];
        for &(u, l, p, m) in incidences {
            bound[u].add(l, p, m);
            cobound[l].add(u, p, m);
        }
        TmModel {
            dim,
            ids: cells.iter().map(|c| c.0).collect(),
            dims: cells.iter().map(|c| c.1).collect(),
            per_dim,
            bound,
            cobound,
        }
    }

    /// A model from cells `(id, dim)` (their index is their position) and incidences
    /// `(upper index, lower index, positive, negative)`: the upper cell takes the lower one
    /// `positive` times with its orientation and `negative` times against it (repeated
    /// pairs add up). The circuit conditions are not checked: that is what
    /// [`TmModel::edit_check`] is for.
    ///
    /// Errors: [`TmError::DimensionAbove`] (a cell above `dim`), [`TmError::DuplicateId`],
    /// [`TmError::NoSuchCell`] (an incidence index out of range), [`TmError::NotAdjacent`]
    /// (an incidence whose dimensions do not differ by one). O(cells log cells +
    /// incidences).
    pub fn try_new(
        dim: usize,
        cells: Vec<(u64, usize)>,
        incidences: &[(usize, usize, u64, u64)],
    ) -> Result<TmModel, TmError> {
        let mut seen: BTreeMap<u64, usize> = BTreeMap::new();
        for (k, &(id, d)) in cells.iter().enumerate() {
            if d > dim {
                return Err(TmError::DimensionAbove { id, dim: d, max: dim });
            }
            if let Some(&first) = seen.get(&id) {
                return Err(TmError::DuplicateId { id, first, second: k });
            }
            seen.insert(id, k);
        }
        let len = cells.len();
        for &(u, l, _, _) in incidences {
            for index in [u, l] {
                if index >= len {
                    return Err(TmError::NoSuchCell { index, len });
                }
            }
            let (ud, ld) = (cells[u].1, cells[l].1);
            if ud != ld + 1 {
                return Err(TmError::NotAdjacent {
                    upper: cells[u].0,
                    upper_dim: ud,
                    lower: cells[l].0,
                    lower_dim: ld,
                });
            }
        }
        Ok(TmModel::build(dim, &cells, incidences))
    }

    /// [`TmModel::try_new`], panicking on its errors (for models written in code).
    pub fn new(dim: usize, cells: Vec<(u64, usize)>, incidences: &[(usize, usize, u64, u64)]) -> TmModel {
        TmModel::try_new(dim, cells, incidences).unwrap_or_else(|e| panic!("TmModel::new: {e}"))
    }

    /// The model of the cells of a G-map (cells indexed and identified as in
    /// [`ArchComplex::from_map`]: 0-cells first). Occurrences are the face-operator preimage
    /// elements counted by sign ([`crate::complex::arch::cell_incidences`]); needs condition
    /// C1. On an orientable map the n-cells are oriented coherently, by the map's
    /// orientation classes (BO Def. 7): every n-cell is its positive version in TM's sense
    /// for one and the same choice of outside, so each inner (n-1)-cell has its two n-cells
    /// on opposite sides and the edit check can pass. O(N n) plus the incidences.
    pub fn from_map(map: &DenseMap) -> Result<TmModel, FromMapError> {
        let n = map.dim();
        let counts = map.cell_counts();
        let mut offset = vec![0usize; n + 2];
        for k in 0..=n {
            offset[k + 1] = offset[k] + counts[k];
        }
        let mut cells: Vec<(u64, usize)> = Vec::with_capacity(offset[n + 1]);
        for (k, &c) in counts.iter().enumerate() {
            cells.extend((0..c).map(|j| ((offset[k] + j) as u64, k)));
        }
        let flip = Self::coherent_flips(map, n)?;
        let mut inc = Vec::new();
        for (k, list) in all_cell_incidences(map)?.into_iter().enumerate() {
            let i = k + 1;
            for c in list {
                let (mut p, mut m) = (u64::from(c.plus), u64::from(c.minus));
                if i == n && flip.get(c.upper as usize).copied().unwrap_or(false) {
                    std::mem::swap(&mut p, &mut m);
                }
                inc.push((offset[i] + c.upper as usize, offset[i - 1] + c.lower as usize, p, m));
            }
        }
        Ok(TmModel::build(n, &cells, &inc))
    }

    /// For each n-cell, whether its own orientation (its smallest dart positive) disagrees
    /// with the map's orientation classes; none on a non-orientable map.
    fn coherent_flips(map: &DenseMap, n: usize) -> Result<Vec<bool>, FromMapError> {
        let Ok(global) = map.orientation() else {
            return Ok(Vec::new());
        };
        let (parts, positive) = map.oriented_cells(n)?;
        let mut flip = vec![false; parts.reps.len()];
        for (c, rep) in parts.reps.iter().enumerate() {
            let d = rep.index();
            flip[c] = positive[d] != global[d];
        }
        Ok(flip)
    }

    /// The model of an architectural complex: a weight `w` becomes `w` positive occurrences
    /// (or `-w` negative ones); a defined zero becomes one occurrence of each sign (the
    /// smallest split of a cancelling adherence, as on a seam). Entries across a dimension
    /// gap are not incidences of TM and are dropped.
    pub fn from_arch(x: &ArchComplex) -> TmModel {
        let cells: Vec<(u64, usize)> = x.regions().iter().map(|r| (r.id.0, r.dim)).collect();
        let inc: Vec<(usize, usize, u64, u64)> = x
            .entries()
            .iter()
            .filter(|e| x.region(e.from).dim == x.region(e.to).dim + 1)
            .map(|e| match e.weight {
                0 => (e.from, e.to, 1, 1),
                w if w > 0 => (e.from, e.to, w.unsigned_abs(), 0),
                w => (e.from, e.to, 0, w.unsigned_abs()),
            })
            .collect();
        TmModel::build(x.dim(), &cells, &inc)
    }

    /// The dimension n.
    pub fn dim(&self) -> usize {
        self.dim
    }

    /// Number of cells.
    pub fn len(&self) -> usize {
        self.ids.len()
    }

    /// Whether there is no cell.
    pub fn is_empty(&self) -> bool {
        self.ids.is_empty()
    }

    /// Whether `c` is a cell index of the model (the precondition of every per-cell query).
    pub fn contains(&self, c: usize) -> bool {
        c < self.len()
    }

    /// The id of a cell. Panics if `c` is not a cell ([`TmModel::contains`]).
    pub fn id(&self, c: usize) -> u64 {
        self.ids[c]
    }

    /// The cell with this id, if any. O(cells).
    pub fn index_of(&self, id: u64) -> Option<usize> {
        self.ids.iter().position(|&x| x == id)
    }

    /// The dimension of a cell. Panics if `c` is not a cell.
    pub fn cell_dim(&self, c: usize) -> usize {
        self.dims[c]
    }

    /// The cells of dimension k: the set `C^k` of (6:1), the entry key of dimension k.
    /// Empty above the model's dimension.
    pub fn regions_of_dim(&self, k: usize) -> &[usize] {
        self.per_dim.get(k).map(Vec::as_slice).unwrap_or(&[])
    }

    /// The stored bounding circuit `B(c)` of a cell, a member of `Z_B^{k-1}` once the edit
    /// check passes. Panics if `c` is not a cell. O(1).
    pub fn bounding(&self, c: usize) -> &SignedSet {
        &self.bound[c]
    }

    /// The stored cobounding cocircuit `G(c)`, a member of `Y_G^{k+1}` once the edit check
    /// passes. Panics if `c` is not a cell. O(1).
    pub fn cobounding(&self, c: usize) -> &SignedSet {
        &self.cobound[c]
    }

    /// `Z_B^k`: the bounding k-circuits as stored, one per (k+1)-cell `c`, `(c, B(c))`.
    /// Empty for k >= n.
    pub fn bounding_circuits(&self, k: usize) -> impl Iterator<Item = (usize, &SignedSet)> + '_ {
        self.regions_of_dim(k + 1).iter().map(move |&c| (c, &self.bound[c]))
    }

    /// `Y_G^k`: the cobounding k-cocircuits as stored, one per (k-1)-cell `c`, `(c, G(c))`.
    /// Empty for k = 0 and k > n.
    pub fn cobounding_cocircuits(&self, k: usize) -> impl Iterator<Item = (usize, &SignedSet)> + '_ {
        let cells = match k.checked_sub(1) {
            Some(j) => self.regions_of_dim(j),
            None => &[],
        };
        cells.iter().map(move |&c| (c, &self.cobound[c]))
    }

    /// The file layout of TM §XI (Fig. 3 for n = 2, Fig. 4 for n = 3): one entry key `C^k`
    /// per dimension, with the set its records hold. Below the middle dimension a k-cell
    /// holds its cocircuit (`Y^{k+1}`), above it its circuit (`Z^{k-1}`), and the
    /// self-dual middle dimension of an even n holds both pairs (`Z^{k-1}`, `Y^{k+1}`).
    /// In 3D: `C^0: Y^1`, `C^1: Y^2`, `C^2: Z^1`, `C^3: Z^2` (four keys); in 2D:
    /// `C^0: Y^1`, `C^1: Z^0, Y^2`, `C^2: Z^1` (three). Dual keys hold dual sets.
    pub fn file_layout(&self) -> Vec<(TmSet, Vec<TmSet>)> {
        let n = self.dim;
        (0..=n)
            .map(|k| {
                let mut sets = Vec::new();
                if 2 * k >= n && k >= 1 {
                    sets.push(TmSet::Z(k - 1));
                }
                if 2 * k <= n && k < n {
                    sets.push(TmSet::Y(k + 1));
                }
                (TmSet::C(k), sets)
            })
            .collect()
    }

    /// The record of cell `c` in the file layout ([`TmModel::file_layout`]): each set its
    /// key holds with this cell's member of it (`Z^{k-1}`: `B(c)`, `Y^{k+1}`: `G(c)`).
    /// Panics if `c` is not a cell.
    pub fn record(&self, c: usize) -> Vec<(TmSet, &SignedSet)> {
        let k = self.dims[c];
        let (_, sets) = &self.file_layout()[k];
        sets.iter()
            .map(|&s| match s {
                TmSet::Z(_) => (s, &self.bound[c]),
                _ => (s, &self.cobound[c]),
            })
            .collect()
    }

    fn apply(&self, s: &SignedSet, adj: &[SignedSet]) -> SignedSet {
        let mut out = SignedSet::new();
        for (c, p, m) in s.iter() {
            for (t, ip, im) in adj[c].iter() {
                // a positive occurrence of c contributes the incidences as they are, a
                // negative one with signs swapped
                let plus = p.saturating_mul(ip).saturating_add(m.saturating_mul(im));
                let minus = p.saturating_mul(im).saturating_add(m.saturating_mul(ip));
                out.add(t, plus, minus);
            }
        }
        out
    }

    /// `B(S)`: the boundary, amalgamated with signs and multiplicities (TM §IV).
    /// Panics if `S` holds a non-cell. O(Σ boundary sizes).
    pub fn boundary(&self, s: &SignedSet) -> SignedSet {
        self.apply(s, &self.bound)
    }

    /// `G(S)`: the coboundary, dual of `B`.
    pub fn coboundary(&self, s: &SignedSet) -> SignedSet {
        self.apply(s, &self.cobound)
    }

    fn series(&self, s: &SignedSet, adj: &[SignedSet]) -> SignedSet {
        let mut total = s.clone();
        let mut cur = s.clone();
        for _ in 0..=self.dim {
            cur = self.apply(&cur, adj);
            if cur.is_empty() {
                break;
            }
            total = total.union(&cur);
        }
        total
    }

    /// The view `(1 - B)^{-1} S = S + BS + B²S + …` (TM (7:1)): truncated after n + 1
    /// terms, since dimensions drop at each step.
    pub fn view(&self, s: &SignedSet) -> SignedSet {
        self.series(s, &self.bound)
    }

    /// The section `(1 - G)^{-1} S` (TM (7:2)).
    pub fn section(&self, s: &SignedSet) -> SignedSet {
        self.series(s, &self.cobound)
    }

    /// Whether [`TmModel::try_close_with_exterior`] would succeed.
    pub fn can_close_with_exterior(&self, id: u64) -> bool {
        self.try_close_with_exterior(id).is_ok()
    }

    /// The model closed by one exterior n-cell with id `id` (the last index, returned with
    /// the model): the exterior takes every free (n-1)-cell, one cobounded by a single
    /// n-cell occurrence, with the opposite sign, so that it lies on the free side (the
    /// outside of a building becomes the cell on the far side of its outer walls' near
    /// sides, and conversely). Cells whose coboundary already balances are left alone. An
    /// open model whose cells pass the boundary conditions (7:5) then passes (7:6) too.
    ///
    /// Precondition ([`TmModel::can_close_with_exterior`]): `n >= 1`, `id` unused, at
    /// least one free (n-1)-cell, and every (n-1)-cell with an unbalanced coboundary free.
    /// Errors: [`TmError::Pointless`], [`TmError::IdInUse`], [`TmError::NotFree`] (naming
    /// the cell: a wall with two rooms on one side is a defect, not an opening),
    /// [`TmError::AlreadyClosed`]. O(cells + incidences).
    pub fn try_close_with_exterior(&self, id: u64) -> Result<(TmModel, usize), TmError> {
        let n = self.dim;
        let wall = n.checked_sub(1).ok_or(TmError::Pointless { what: "exterior cell" })?;
        if self.ids.contains(&id) {
            return Err(TmError::IdInUse { id });
        }
        let exterior = self.len();
        let mut closing = SignedSet::new();
        for &c in self.regions_of_dim(wall) {
            let (plus, minus) = self.cobound[c].totals();
            match (plus, minus) {
                (p, m) if p == m => {}
                (1, 0) => closing.add(c, 0, 1),
                (0, 1) => closing.add(c, 1, 0),
                (plus, minus) => return Err(TmError::NotFree { id: self.ids[c], dim: wall, plus, minus }),
            }
        }
        if closing.is_empty() {
            return Err(TmError::AlreadyClosed { dim: wall });
        }
        let mut out = self.clone();
        out.ids.push(id);
        out.dims.push(n);
        out.per_dim[n].push(exterior);
        out.bound.push(SignedSet::new());
        out.cobound.push(SignedSet::new());
        for (c, p, m) in closing.iter() {
            out.bound[exterior].add(c, p, m);
            out.cobound[c].add(exterior, p, m);
        }
        Ok((out, exterior))
    }

    /// The Poincaré dual (TM §IV): cell of dimension k becomes dimension `n - k`, boundary
    /// and coboundary swap (the incidence graph transposed).
    pub fn dual(&self) -> TmModel {
        let n = self.dim;
        let mut per_dim = vec![Vec::new(); n + 1];
        for (c, &d) in self.dims.iter().enumerate() {
            per_dim[n - d].push(c);
        }
        TmModel {
            dim: n,
            ids: self.ids.clone(),
            dims: self.dims.iter().map(|&d| n - d).collect(),
            per_dim,
            bound: self.cobound.clone(),
            cobound: self.bound.clone(),
        }
    }
}
