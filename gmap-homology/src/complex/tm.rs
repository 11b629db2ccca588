//! The boundary/coboundary model of TM ("topological models for architectural and
//! engineering projects").
//!
//! Cells are joined by incidences; each incidence of a (k-1)-cell on a k-cell occurs a
//! number of times with each orientation (on a G-map: the elements of the face-operator
//! preimage, counted by sign; the cylinder's seam occurs once with each sign). The model
//! works on [`SignedSet`]s: sets of cells where positive and negative occurrences are
//! kept apart, each with a multiplicity (TM §IV):
//! * the boundary `B` and the coboundary `G` ([`TmModel::boundary`], [`TmModel::coboundary`]);
//! * the *view* `(1 - B)^{-1} c = c + Bc + B²c + …` (a cell with its complete boundary) and
//!   the *section* `(1 - G)^{-1} c` (a cell with everything above it), TM (7:1), (7:2);
//! * circuits (every bounding cell occurs as often with each orientation; for 0-cells the
//!   coefficients sum to zero, TM §VI) and, dually, cocircuits;
//! * the topological edit check (TM §XI, (7:5), (7:6)): the boundary of every cell is a
//!   circuit and the coboundary of every cell a cocircuit; the first offending cell is
//!   named ([`TmDefect`]).
//!
//! Poincaré duality: [`TmModel::dual`] swaps dimensions k and n - k and swaps `B` with
//! `G` (the incidence graph transposed); on a G-map it is the model of the dual map
//! (`DenseMap::dual`), as the tests check.
//!
//! ```
//! use gmap_core::{Dart, DenseMap};
//! use gmap_homology::tm::{SignedSet, TmModel};
//! // a square: 4 vertices, 4 edges, 1 face
//! let mut m = DenseMap::new(2, 8);
//! for k in 0..4u32 {
//!     m.link(Dart(2 * k), Dart(2 * k + 1), 0);
//!     m.link(Dart(2 * k + 1), Dart((2 * k + 2) % 8), 1);
//! }
//! let t = TmModel::from_map(&m).unwrap();
//! let face = t.regions_of_dim(2)[0];
//! let view = t.view(&SignedSet::cell(face));
//! assert_eq!(view.len(), 9); // the face, its 4 edges, its 4 vertices
//! // the boundary of the face is a circuit; the disc's free edges are not cocircuits
//! assert!(t.is_circuit(&t.boundary(&SignedSet::cell(face)), 1));
//! assert!(t.edit_check().is_err());
//! ```

use std::collections::BTreeMap;

use gmap_core::DenseMap;
use thiserror::Error;

use crate::complex::arch::{all_cell_incidences, ArchComplex, FromMapError};

/// A set of cells with signed multiplicities: for each cell, the number of positive and of
/// negative occurrences, kept apart (TM §IV). Cells are region indices of a [`TmModel`].
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct SignedSet {
    occ: BTreeMap<usize, (u64, u64)>,
}

impl SignedSet {
    /// The empty set.
    pub fn new() -> Self {
        SignedSet::default()
    }

    /// One positive occurrence of a cell.
    pub fn cell(c: usize) -> Self {
        let mut s = SignedSet::new();
        s.add(c, 1, 0);
        s
    }

    /// Adds `plus` positive and `minus` negative occurrences of `c` (saturating: counts
    /// beyond 2^64 are not meaningful for a model).
    pub fn add(&mut self, c: usize, plus: u64, minus: u64) {
        if plus == 0 && minus == 0 {
            return;
        }
        let e = self.occ.entry(c).or_insert((0, 0));
        e.0 = e.0.saturating_add(plus);
        e.1 = e.1.saturating_add(minus);
    }

    /// `(positive, negative)` occurrences of `c`.
    pub fn get(&self, c: usize) -> (u64, u64) {
        self.occ.get(&c).copied().unwrap_or((0, 0))
    }

    /// The net coefficient of `c` as a chain: positive minus negative occurrences.
    pub fn net(&self, c: usize) -> i128 {
        let (p, m) = self.get(c);
        p as i128 - m as i128
    }

    /// The cells present, increasing, with their occurrences.
    pub fn iter(&self) -> impl Iterator<Item = (usize, u64, u64)> + '_ {
        self.occ.iter().map(|(&c, &(p, m))| (c, p, m))
    }

    /// Number of distinct cells.
    pub fn len(&self) -> usize {
        self.occ.len()
    }

    /// Whether no cell occurs.
    pub fn is_empty(&self) -> bool {
        self.occ.is_empty()
    }

    /// The union with multiplicities added (TM's amalgamation of boundary sets).
    pub fn union(&self, other: &SignedSet) -> SignedSet {
        let mut s = self.clone();
        for (c, p, m) in other.iter() {
            s.add(c, p, m);
        }
        s
    }
}

/// A violation of the topological edit check (TM §XI), naming the cell.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
pub enum TmDefect {
    /// The boundary of a k-cell is not a (k-1)-circuit: `at` occurs `plus` times positively
    /// and `minus` times negatively in the boundary of that boundary (for k = 1: `at` is
    /// the cell itself and plus/minus are the summed coefficients of its end vertices).
    #[error(
        "the boundary of {dim}-cell {cell} is not a circuit: cell {at} occurs +{plus}/-{minus} times in its boundary"
    )]
    BoundaryNotCircuit {
        /// the cell (region id)
        cell: u64,
        /// its dimension
        dim: usize,
        /// where the circuit condition fails (region id)
        at: u64,
        /// positive occurrences
        plus: u64,
        /// negative occurrences
        minus: u64,
    },
    /// The coboundary of a k-cell is not a (k+1)-cocircuit (dual of the above; for
    /// k = n - 1 the n-cells cobounding it do not pair up with opposite orientations).
    #[error("the coboundary of {dim}-cell {cell} is not a cocircuit: cell {at} occurs +{plus}/-{minus} times in its coboundary")]
    CoboundaryNotCocircuit {
        /// the cell (region id)
        cell: u64,
        /// its dimension
        dim: usize,
        /// where the cocircuit condition fails (region id)
        at: u64,
        /// positive occurrences
        plus: u64,
        /// negative occurrences
        minus: u64,
    },
}

/// Cells with dimensions and signed incidences with multiplicities.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TmModel {
    dim: usize,
    ids: Vec<u64>,
    dims: Vec<usize>,
    per_dim: Vec<Vec<usize>>,
    /// for each cell, its boundary: (lower cell, positive, negative occurrences)
    down: Vec<Vec<(usize, u64, u64)>>,
    /// for each cell, its coboundary: (upper cell, positive, negative occurrences)
    up: Vec<Vec<(usize, u64, u64)>>,
}

impl TmModel {
    /// A model from cells `(id, dim)` (their index is their position) and incidences
    /// `(upper index, lower index, positive, negative)`. No condition is checked: that is
    /// what [`TmModel::edit_check`] is for. Panics if an index is out of range or a cell's
    /// dimension exceeds `dim`.
    pub fn new(dim: usize, cells: Vec<(u64, usize)>, incidences: &[(usize, usize, u64, u64)]) -> TmModel {
        let nr = cells.len();
        let mut per_dim = vec![Vec::new(); dim + 1];
        for (k, &(_, d)) in cells.iter().enumerate() {
            assert!(d <= dim, "cell {k} has dimension {d} above {dim}");
            per_dim[d].push(k);
        }
        let mut down = vec![Vec::new(); nr];
        let mut up = vec![Vec::new(); nr];
        for &(u, l, p, m) in incidences {
            down[u].push((l, p, m));
            up[l].push((u, p, m));
        }
        TmModel {
            dim,
            ids: cells.iter().map(|c| c.0).collect(),
            dims: cells.iter().map(|c| c.1).collect(),
            per_dim,
            down,
            up,
        }
    }

    /// The model of the cells of a G-map (cells indexed and identified as in
    /// [`ArchComplex::from_map`]: 0-cells first). Occurrences are the face-operator preimage
    /// elements counted by sign ([`crate::complex::arch::cell_incidences`]); needs condition C1.
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
        let mut inc = Vec::new();
        for (k, list) in all_cell_incidences(map)?.into_iter().enumerate() {
            let i = k + 1;
            for c in list {
                inc.push((
                    offset[i] + c.upper as usize,
                    offset[i - 1] + c.lower as usize,
                    c.plus as u64,
                    c.minus as u64,
                ));
            }
        }
        Ok(TmModel::new(n, cells, &inc))
    }

    /// The model of an architectural complex: a weight `w` becomes `w` positive occurrences
    /// (or `-w` negative ones); a defined zero becomes one occurrence of each sign (the
    /// smallest split of a cancelling adherence, as on a seam). Entries across a dimension
    /// gap are not incidences of TM and are dropped.
    pub fn from_arch(x: &ArchComplex) -> TmModel {
        let cells = x.regions().iter().map(|r| (r.id.0, r.dim)).collect();
        let inc: Vec<(usize, usize, u64, u64)> = x
            .entries()
            .iter()
            .filter(|e| x.region(e.from).dim == x.region(e.to).dim + 1)
            .map(|e| match e.weight {
                0 => (e.from, e.to, 1, 1),
                w if w > 0 => (e.from, e.to, w as u64, 0),
                w => (e.from, e.to, 0, w.unsigned_abs()),
            })
            .collect();
        TmModel::new(x.dim(), cells, &inc)
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

    /// The id of a cell.
    pub fn id(&self, c: usize) -> u64 {
        self.ids[c]
    }

    /// The dimension of a cell.
    pub fn cell_dim(&self, c: usize) -> usize {
        self.dims[c]
    }

    /// The cells of dimension k.
    pub fn regions_of_dim(&self, k: usize) -> &[usize] {
        &self.per_dim[k]
    }

    fn apply(&self, s: &SignedSet, adj: &[Vec<(usize, u64, u64)>]) -> SignedSet {
        let mut out = SignedSet::new();
        for (c, p, m) in s.iter() {
            for &(t, ip, im) in &adj[c] {
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
    /// O(Σ boundary sizes).
    pub fn boundary(&self, s: &SignedSet) -> SignedSet {
        self.apply(s, &self.down)
    }

    /// `G(S)`: the coboundary, dual of `B`.
    pub fn coboundary(&self, s: &SignedSet) -> SignedSet {
        self.apply(s, &self.up)
    }

    fn series(&self, s: &SignedSet, adj: &[Vec<(usize, u64, u64)>]) -> SignedSet {
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
        self.series(s, &self.down)
    }

    /// The section `(1 - G)^{-1} S` (TM (7:2)).
    pub fn section(&self, s: &SignedSet) -> SignedSet {
        self.series(s, &self.up)
    }

    fn zero_sum(s: &SignedSet) -> (u64, u64) {
        s.iter().fold((0u64, 0u64), |(a, b), (_, p, m)| (a.saturating_add(p), b.saturating_add(m)))
    }

    /// Whether a set of k-cells is a k-circuit (TM §VI): every (k-1)-cell occurs in its
    /// boundary as often positively as negatively; for k = 0, the coefficients sum to zero.
    pub fn is_circuit(&self, s: &SignedSet, k: usize) -> bool {
        if k == 0 {
            let (p, m) = Self::zero_sum(s);
            return p == m;
        }
        self.boundary(s).iter().all(|(_, p, m)| p == m)
    }

    /// Whether a set of k-cells is a k-cocircuit: every (k+1)-cell occurs in its coboundary
    /// as often with each sign; for k = n, the coefficients sum to zero.
    pub fn is_cocircuit(&self, s: &SignedSet, k: usize) -> bool {
        if k == self.dim {
            let (p, m) = Self::zero_sum(s);
            return p == m;
        }
        self.coboundary(s).iter().all(|(_, p, m)| p == m)
    }

    /// The topological edit check (TM §XI): for every cell c of dimension k, `B(c)` is a
    /// (k-1)-circuit (k >= 1) and `G(c)` a (k+1)-cocircuit (k < n). Boundaries are checked
    /// first, then coboundaries; returns the first cell that fails, in index order, with the
    /// place where it fails. For k = n - 1 the cocircuit condition asks the n-cells on each
    /// (n-1)-cell to pair up with opposite orientations: free faces (a boundary) and
    /// twisted gluings (non-orientable objects) fail it. O(Σ |B²(c)| + |G²(c)|).
    pub fn edit_check(&self) -> Result<(), TmDefect> {
        for c in 0..self.len() {
            let k = self.dims[c];
            if k == 0 {
                continue;
            }
            if let Some((at, plus, minus)) = self.unbalanced(c, k == 1, |x| self.boundary(x)) {
                return Err(TmDefect::BoundaryNotCircuit { cell: self.ids[c], dim: k, at: self.ids[at], plus, minus });
            }
        }
        for c in 0..self.len() {
            let k = self.dims[c];
            if k >= self.dim {
                continue;
            }
            if let Some((at, plus, minus)) = self.unbalanced(c, k + 1 == self.dim, |x| self.coboundary(x)) {
                return Err(TmDefect::CoboundaryNotCocircuit {
                    cell: self.ids[c],
                    dim: k,
                    at: self.ids[at],
                    plus,
                    minus,
                });
            }
        }
        Ok(())
    }

    /// Where the image of cell `c` under `step` is not a circuit: with `ends`, the image is
    /// a set of end cells whose coefficients must cancel (reported at `c` itself); else the
    /// first cell occurring unequally often with each sign in the image of the image.
    fn unbalanced(&self, c: usize, ends: bool, step: impl Fn(&SignedSet) -> SignedSet) -> Option<(usize, u64, u64)> {
        let image = step(&SignedSet::cell(c));
        if ends {
            let (p, m) = Self::zero_sum(&image);
            (p != m).then_some((c, p, m))
        } else {
            step(&image).iter().find(|&(_, p, m)| p != m)
        }
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
            down: self.up.clone(),
            up: self.down.clone(),
        }
    }
}
