//! Architectural complexes (AC §3): regions graded by dimension and a *partial* boundary
//! matrix, whose entries are either defined (an integer, zero allowed) or absent.
//!
//! An [`ArchComplex`] is a finite set of regions, each with a user id (`u64`) and a
//! dimension, and a list of defined entries `δ(from, to) = weight` where `from` is a region
//! of higher dimension than `to` (AC Def. 3.1). The entries are the edges of the underlying
//! weighted DAG, the *incidence graph* (AC Lemma 3.2). Construction validates the whole of
//! AC Def. 3.1 and names the offending entry ([`ArchError`]):
//! 1. entries go from a higher to a strictly lower dimension (so the graph is acyclic — a
//!    cycle is reported as such, before the dimension check);
//! 2. an entry across a dimension gap of two or more has weight 0;
//! 3. the partial product `δ²` (rules `a + undefined = a`, `a · undefined = undefined`) has
//!    only zero entries where it is defined.
//!
//! The topology of AC §3.2 is available through stars ([`ArchComplex::star`]: regions with a
//! path *to* a region), closures ([`ArchComplex::closure`]: regions reached *from* a region),
//! open and closed sets and the T0 separation of Axiom 3.6. Homology is that of the
//! *completion by zero* (AC Def. 3.8, 3.9): [`ArchComplex::boundary_entries`] lists its
//! non-zero entries between consecutive dimensions (entries across a gap are zero by
//! Def. 3.1), and [`crate::complex::arch::ArchComplex::euler_characteristic`] is the left side of the
//! Euler–Poincaré formula (AC Cor. 3.11).
//!
//! Algorithm 8.16 (turning a realisable complex into a cw-complex with the same
//! topological Betti numbers) for the constructive cases of AC Example 8.19 is
//! [`ArchComplex::topological`].
//!
//! ```
//! use gmap_homology::arch::{ArchComplex, Region};
//! // The left graph of AC Figure 2 / Table 1: a = Q - P, b = R - Q, c a loop at Q.
//! let (p, q, r, a, b, c) = (0, 1, 2, 3, 4, 5);
//! let regions = [(p, 0), (q, 0), (r, 0), (a, 1), (b, 1), (c, 1)].map(|(id, dim)| Region { id, dim });
//! let entries = vec![(a, p, -1), (a, q, 1), (b, q, -1), (b, r, 1), (c, q, 0)];
//! let x = ArchComplex::try_new(1, regions.to_vec(), entries).unwrap();
//! assert_eq!(x.region_counts(), vec![3, 3]);
//! assert_eq!(x.euler_characteristic(), 0);
//! // the defined zero keeps the loop attached to Q: Q is in the closure of c
//! let ci = x.index_of(c).unwrap();
//! assert_eq!(x.closure(ci), vec![x.index_of(q).unwrap(), ci]);
//! ```
//!
//! Complexities: construction O(R + E + Σ_b outdeg(b)·outdeg of its targets) for the δ²
//! check; stars and closures O(size of the result + its entries).

use std::collections::HashMap;
use std::fmt;

use gmap_core::{AlphaSet, CellDefect, DenseMap};
use thiserror::Error;

use crate::complex::ep::EpVector;
use crate::engine::chain::ChainComplex;
use crate::engine::homology::{homology_z, homology_zp, Homology, HomologyError};
use crate::engine::sparse::SparseMatrix;

/// A region: a user id and a dimension.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Region {
    /// the id, unique in the complex
    pub id: u64,
    /// the dimension
    pub dim: usize,
}

/// A defined entry of the partial boundary matrix, by region index (not id).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Entry {
    /// index of the region of higher dimension
    pub from: usize,
    /// index of the region of lower dimension, in the boundary of `from`
    pub to: usize,
    /// the value `δ(to, from)` (AC writes the lower region first)
    pub weight: i64,
}

/// Why data is not an architectural complex (AC Def. 3.1). Regions are named by id.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
pub enum ArchError {
    /// Two regions share an id.
    #[error("duplicate region id {id}")]
    DuplicateRegion {
        /// the id
        id: u64,
    },
    /// A region's dimension exceeds the complex's.
    #[error("region {id} has dimension {dim}, above the complex's dimension {max}")]
    RegionDimension {
        /// the region
        id: u64,
        /// its dimension
        dim: usize,
        /// the complex's dimension
        max: usize,
    },
    /// An entry names a region that does not exist.
    #[error("incidence entry {from} -> {to} names the unknown region {missing}")]
    UnknownRegion {
        /// `from` of the entry
        from: u64,
        /// `to` of the entry
        to: u64,
        /// the id not found
        missing: u64,
    },
    /// The same pair appears twice.
    #[error("duplicate incidence entry {from} -> {to}")]
    DuplicateEntry {
        /// `from`
        from: u64,
        /// `to`
        to: u64,
    },
    /// The incidence graph has a directed cycle (listed in order, first id repeated last).
    #[error("the incidence graph has a cycle: {}", join(cycle))]
    Cycle {
        /// the regions of the cycle
        cycle: Vec<u64>,
    },
    /// An entry does not go from a higher to a strictly lower dimension.
    #[error(
        "incidence entry {from} -> {to} goes from dimension {from_dim} to dimension {to_dim}: dimension must decrease"
    )]
    DimensionNotDecreasing {
        /// `from`
        from: u64,
        /// `to`
        to: u64,
        /// dimension of `from`
        from_dim: usize,
        /// dimension of `to`
        to_dim: usize,
    },
    /// An entry across a dimension gap of two or more has a non-zero weight.
    #[error("incidence entry {from} -> {to} crosses from dimension {from_dim} to {to_dim} with weight {weight}: an entry across a gap must be 0")]
    WeightAcrossGap {
        /// `from`
        from: u64,
        /// `to`
        to: u64,
        /// dimension of `from`
        from_dim: usize,
        /// dimension of `to`
        to_dim: usize,
        /// the weight
        weight: i64,
    },
    /// `δ²` has a non-zero defined entry: the boundary of `from` has a non-zero boundary at `to`.
    #[error("the partial boundary matrix does not square to zero: δ² from region {from} to region {to} is {value}")]
    SquareNotZero {
        /// the upper region
        from: u64,
        /// the region two steps down
        to: u64,
        /// the value of the entry of δ²
        value: i128,
    },
    /// An intermediate sum overflowed 128-bit integers (only with absurd weights).
    #[error("integer overflow while checking δ² at region {from}")]
    Overflow {
        /// the upper region
        from: u64,
    },
}

fn join(ids: &[u64]) -> String {
    ids.iter().map(|i| i.to_string()).collect::<Vec<_>>().join(" -> ")
}

/// An architectural complex (AC Def. 3.1). Immutable once built; see the module docs.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ArchComplex {
    dim: usize,
    regions: Vec<Region>,
    by_id: HashMap<u64, usize>,
    /// entries sorted by (from, to)
    entries: Vec<Entry>,
    /// entries of region r are `entries[down_off[r]..down_off[r + 1]]`
    down_off: Vec<usize>,
    /// entry indices whose `to` is r: `up[up_off[r]..up_off[r + 1]]`
    up_off: Vec<usize>,
    up: Vec<u32>,
    /// position of each region among the regions of its dimension
    rank_in_dim: Vec<u32>,
    /// region indices per dimension
    per_dim: Vec<Vec<u32>>,
}

impl ArchComplex {
    /// Builds and validates a complex of dimension `dim` from regions and entries given as
    /// `(from id, to id, weight)`. Checks, in this order: duplicate ids, region dimensions,
    /// unknown ids, duplicate entries, cycles, decreasing dimension, zero weight across a
    /// gap, `δ² = 0`. Returns the first violation. See the module docs for complexity.
    pub fn try_new(dim: usize, regions: Vec<Region>, entries: Vec<(u64, u64, i64)>) -> Result<Self, ArchError> {
        let mut by_id = HashMap::with_capacity(regions.len());
        for (k, r) in regions.iter().enumerate() {
            if by_id.insert(r.id, k).is_some() {
                return Err(ArchError::DuplicateRegion { id: r.id });
            }
            if r.dim > dim {
                return Err(ArchError::RegionDimension { id: r.id, dim: r.dim, max: dim });
            }
        }
        let mut es = Vec::with_capacity(entries.len());
        for &(f, t, w) in &entries {
            let from = *by_id.get(&f).ok_or(ArchError::UnknownRegion { from: f, to: t, missing: f })?;
            let to = *by_id.get(&t).ok_or(ArchError::UnknownRegion { from: f, to: t, missing: t })?;
            es.push(Entry { from, to, weight: w });
        }
        es.sort_by_key(|e| (e.from, e.to));
        for w in es.windows(2) {
            if w[0].from == w[1].from && w[0].to == w[1].to {
                return Err(ArchError::DuplicateEntry { from: regions[w[0].from].id, to: regions[w[0].to].id });
            }
        }
        let x = Self::assemble(dim, regions, by_id, es);
        x.check_acyclic()?;
        x.check_dimensions()?;
        x.check_square()?;
        Ok(x)
    }

    fn assemble(dim: usize, regions: Vec<Region>, by_id: HashMap<u64, usize>, entries: Vec<Entry>) -> Self {
        let nr = regions.len();
        let mut down_off = vec![0usize; nr + 1];
        for e in &entries {
            down_off[e.from + 1] += 1;
        }
        for k in 0..nr {
            down_off[k + 1] += down_off[k];
        }
        let mut up_off = vec![0usize; nr + 1];
        for e in &entries {
            up_off[e.to + 1] += 1;
        }
        for k in 0..nr {
            up_off[k + 1] += up_off[k];
        }
        let mut fill = up_off.clone();
        let mut up = vec![0u32; entries.len()];
        for (k, e) in entries.iter().enumerate() {
            up[fill[e.to]] = k as u32;
            fill[e.to] += 1;
        }
        let mut per_dim: Vec<Vec<u32>> = vec![Vec::new(); dim + 1];
        let mut rank_in_dim = vec![0u32; nr];
        for (k, r) in regions.iter().enumerate() {
            rank_in_dim[k] = per_dim[r.dim].len() as u32;
            per_dim[r.dim].push(k as u32);
        }
        ArchComplex { dim, regions, by_id, entries, down_off, up_off, up, rank_in_dim, per_dim }
    }

    fn check_acyclic(&self) -> Result<(), ArchError> {
        // Kahn's algorithm; leftovers contain a cycle, found by walking inside them.
        let nr = self.regions.len();
        let mut indeg: Vec<usize> = (0..nr).map(|r| self.up_off[r + 1] - self.up_off[r]).collect();
        let mut queue: Vec<usize> = (0..nr).filter(|&r| indeg[r] == 0).collect();
        let mut done = 0usize;
        while let Some(r) = queue.pop() {
            done += 1;
            for e in self.down(r) {
                indeg[e.to] -= 1;
                if indeg[e.to] == 0 {
                    queue.push(e.to);
                }
            }
        }
        if done == nr {
            return Ok(());
        }
        // every leftover region has a leftover predecessor; walk backwards until a repeat
        let start = (0..nr).find(|&r| indeg[r] > 0).expect("a leftover region");
        let mut pos: HashMap<usize, usize> = HashMap::new();
        let mut path = vec![start];
        let mut cur = start;
        loop {
            pos.insert(cur, path.len() - 1);
            let pred = self.up_of(cur).map(|e| e.from).find(|&f| indeg[f] > 0).expect("a leftover predecessor");
            if let Some(&p) = pos.get(&pred) {
                let mut cyc: Vec<u64> = path[p..].iter().rev().map(|&r| self.regions[r].id).collect();
                // start at the smallest id, for a stable message
                let m = (0..cyc.len()).min_by_key(|&k| cyc[k]).unwrap_or(0);
                cyc.rotate_left(m);
                cyc.push(cyc[0]);
                return Err(ArchError::Cycle { cycle: cyc });
            }
            path.push(pred);
            cur = pred;
        }
    }

    fn check_dimensions(&self) -> Result<(), ArchError> {
        for e in &self.entries {
            let (f, t) = (self.regions[e.from], self.regions[e.to]);
            if f.dim <= t.dim {
                return Err(ArchError::DimensionNotDecreasing { from: f.id, to: t.id, from_dim: f.dim, to_dim: t.dim });
            }
            if f.dim - t.dim >= 2 && e.weight != 0 {
                return Err(ArchError::WeightAcrossGap {
                    from: f.id,
                    to: t.id,
                    from_dim: f.dim,
                    to_dim: t.dim,
                    weight: e.weight,
                });
            }
        }
        Ok(())
    }

    fn check_square(&self) -> Result<(), ArchError> {
        let nr = self.regions.len();
        let mut acc = vec![0i128; nr];
        let mut touched: Vec<usize> = Vec::new();
        let mut defined = vec![false; nr];
        for c in 0..nr {
            let from = self.regions[c].id;
            for e1 in self.down(c) {
                for e2 in self.down(e1.to) {
                    if !defined[e2.to] {
                        defined[e2.to] = true;
                        touched.push(e2.to);
                    }
                    let p = e1.weight as i128 * e2.weight as i128;
                    acc[e2.to] = acc[e2.to].checked_add(p).ok_or(ArchError::Overflow { from })?;
                }
            }
            touched.sort_unstable();
            for &a in &touched {
                if acc[a] != 0 {
                    return Err(ArchError::SquareNotZero { from, to: self.regions[a].id, value: acc[a] });
                }
            }
            for &a in &touched {
                acc[a] = 0;
                defined[a] = false;
            }
            touched.clear();
        }
        Ok(())
    }

    /// The dimension n of the complex (regions have dimensions `0..=n`).
    pub fn dim(&self) -> usize {
        self.dim
    }

    /// The regions, in the order given (a region's *index* is its position here).
    pub fn regions(&self) -> &[Region] {
        &self.regions
    }

    /// The region of an index.
    pub fn region(&self, index: usize) -> Region {
        self.regions[index]
    }

    /// The index of the region with this id. O(1).
    pub fn index_of(&self, id: u64) -> Option<usize> {
        self.by_id.get(&id).copied()
    }

    /// Every defined entry, sorted by `(from, to)` index.
    pub fn entries(&self) -> &[Entry] {
        &self.entries
    }

    /// The defined value `δ(to, from)`, `None` where the partial matrix is undefined.
    /// O(log outdeg).
    pub fn weight(&self, from: usize, to: usize) -> Option<i64> {
        let d = self.down(from);
        d.binary_search_by_key(&to, |e| e.to).ok().map(|k| d[k].weight)
    }

    /// The entries from a region (its boundary, out-edges of the DAG), sorted by `to`.
    pub fn down(&self, r: usize) -> &[Entry] {
        &self.entries[self.down_off[r]..self.down_off[r + 1]]
    }

    /// The entries into a region (its coboundary, in-edges of the DAG).
    pub fn up_of(&self, r: usize) -> impl Iterator<Item = &Entry> + '_ {
        self.up[self.up_off[r]..self.up_off[r + 1]].iter().map(move |&k| &self.entries[k as usize])
    }

    /// Number of regions of each dimension `0..=n` (the `v_i` of AC Cor. 3.11).
    pub fn region_counts(&self) -> Vec<usize> {
        self.per_dim.iter().map(|v| v.len()).collect()
    }

    /// The indices of the regions of dimension k, in index order.
    pub fn regions_of_dim(&self, k: usize) -> &[u32] {
        &self.per_dim[k]
    }

    /// The position of a region among the regions of its dimension (its basis index in
    /// `C_k` of the completion by zero).
    pub fn rank_in_dim(&self, r: usize) -> usize {
        self.rank_in_dim[r] as usize
    }

    /// `Σ (-1)^i v_i`, the left side of the Euler–Poincaré formula (AC Cor. 3.11).
    pub fn euler_characteristic(&self) -> i64 {
        self.per_dim
            .iter()
            .enumerate()
            .map(|(i, v)| if i.is_multiple_of(2) { v.len() as i64 } else { -(v.len() as i64) })
            .sum()
    }

    /// The non-zero entries of `∂_k : C_k → C_{k-1}` of the completion by zero (AC Def. 3.8)
    /// as `(row, column, value)` with row the rank of the (k-1)-region and column the rank of
    /// the k-region in their dimensions. Entries across a gap are zero (Def. 3.1) and
    /// omitted. `1 <= k <= n`. O(E).
    pub fn boundary_entries(&self, k: usize) -> Vec<(u32, u32, i64)> {
        assert!(k >= 1 && k <= self.dim);
        let mut out = Vec::new();
        for &c in &self.per_dim[k] {
            for e in self.down(c as usize) {
                if self.regions[e.to].dim + 1 == k && e.weight != 0 {
                    out.push((self.rank_in_dim[e.to], self.rank_in_dim[c as usize], e.weight));
                }
            }
        }
        out
    }

    /// The chain complex associated to the complex (AC §3.3): the completion by zero of the
    /// partial boundary operator (Def. 3.8). Its homology is the complex's homology
    /// (Def. 3.9, Lemma 3.10). O(R + E).
    pub fn chain_complex(&self) -> ChainComplex {
        let counts = self.region_counts();
        let mut ds = Vec::with_capacity(self.dim);
        for k in 1..=self.dim {
            let t: Vec<(usize, usize, i64)> =
                self.boundary_entries(k).into_iter().map(|(r, c, v)| (r as usize, c as usize, v)).collect();
            let m = SparseMatrix::try_from_triplets(counts[k - 1], counts[k], &t)
                .expect("validated entries are in range and distinct");
            ds.push(m);
        }
        // δ² = 0 on defined entries (checked at construction) implies ∂² = 0 on the completion
        ChainComplex::try_new_unchecked_dd(counts, ds).expect("shapes agree with the region counts")
    }

    /// Homology over Z of the completion by zero (AC Def. 3.9).
    pub fn homology_z(&self) -> Result<Homology, HomologyError> {
        homology_z(&self.chain_complex())
    }

    /// Homology over `Z/p` of the completion by zero.
    pub fn homology_zp(&self, p: u64) -> Result<Homology, HomologyError> {
        homology_zp(&self.chain_complex(), p)
    }

    /// A topological order of the DAG: every region before the regions of its boundary
    /// (decreasing dimension, then index). O(R log R).
    pub fn topological_order(&self) -> Vec<usize> {
        let mut v: Vec<usize> = (0..self.regions.len()).collect();
        v.sort_by_key(|&r| (std::cmp::Reverse(self.regions[r].dim), r));
        v
    }

    fn reach(&self, seeds: &[usize], downward: bool) -> Vec<usize> {
        let mut seen = vec![false; self.regions.len()];
        let mut stack: Vec<usize> = Vec::new();
        for &s in seeds {
            if !seen[s] {
                seen[s] = true;
                stack.push(s);
            }
        }
        let mut out = Vec::new();
        while let Some(r) = stack.pop() {
            out.push(r);
            if downward {
                for e in self.down(r) {
                    if !seen[e.to] {
                        seen[e.to] = true;
                        stack.push(e.to);
                    }
                }
            } else {
                for e in self.up_of(r) {
                    if !seen[e.from] {
                        seen[e.from] = true;
                        stack.push(e.from);
                    }
                }
            }
        }
        out.sort_unstable();
        out
    }

    /// `Star(b)`: the regions with a path to `b` in the DAG, `b` included (AC §3.2); the
    /// smallest open set holding `b`. Sorted indices.
    pub fn star(&self, b: usize) -> Vec<usize> {
        self.reach(&[b], false)
    }

    /// The closure of `{b}` in the underlying topology: the regions reached from `b`, `b`
    /// included (those whose star holds `b`). Sorted indices.
    pub fn closure(&self, b: usize) -> Vec<usize> {
        self.reach(&[b], true)
    }

    /// The smallest open set holding a set of regions: the union of their stars.
    pub fn open_hull(&self, set: &[usize]) -> Vec<usize> {
        self.reach(set, false)
    }

    /// The closure of a set of regions: the union of their closures.
    pub fn closure_of(&self, set: &[usize]) -> Vec<usize> {
        self.reach(set, true)
    }

    /// Whether a set is open in the underlying topology (AC Def. 3.5): a union of stars,
    /// i.e. closed under going up the DAG. O(size + entries).
    pub fn is_open(&self, set: &[usize]) -> bool {
        let mut inside = vec![false; self.regions.len()];
        for &r in set {
            inside[r] = true;
        }
        set.iter().all(|&r| self.up_of(r).all(|e| inside[e.from]))
    }

    /// Whether a set is closed: its complement is open, i.e. it is closed under going down.
    pub fn is_closed(&self, set: &[usize]) -> bool {
        let mut inside = vec![false; self.regions.len()];
        for &r in set {
            inside[r] = true;
        }
        set.iter().all(|&r| self.down(r).iter().all(|e| inside[e.to]))
    }

    /// An open set holding exactly one of two distinct regions (the T0 axiom, AC Axiom 3.6):
    /// `Star(y)` if it misses `x`, else `Star(x)` (which then misses `y`, the DAG being
    /// acyclic). Panics if `x == y`.
    pub fn separating_open_set(&self, x: usize, y: usize) -> Vec<usize> {
        assert_ne!(x, y, "T0 separation needs two distinct regions");
        let sy = self.star(y);
        if sy.binary_search(&x).is_err() {
            sy
        } else {
            self.star(x)
        }
    }

    /// The connected components of a set of regions, linked by the entries between them
    /// (directions ignored). Each component sorted, components ordered by smallest index.
    pub fn components_of(&self, set: &[usize]) -> Vec<Vec<usize>> {
        let mut inside = vec![false; self.regions.len()];
        for &r in set {
            inside[r] = true;
        }
        let mut seen = vec![false; self.regions.len()];
        let mut sorted = set.to_vec();
        sorted.sort_unstable();
        let mut comps = Vec::new();
        for &s in &sorted {
            if seen[s] {
                continue;
            }
            seen[s] = true;
            let mut stack = vec![s];
            let mut comp = Vec::new();
            while let Some(r) = stack.pop() {
                comp.push(r);
                let nbrs = self.down(r).iter().map(|e| e.to).chain(self.up_of(r).map(|e| e.from)).collect::<Vec<_>>();
                for t in nbrs {
                    if inside[t] && !seen[t] {
                        seen[t] = true;
                        stack.push(t);
                    }
                }
            }
            comp.sort_unstable();
            comps.push(comp);
        }
        comps
    }

    /// Number of connected components of the incidence graph (directions ignored).
    /// O(R + E).
    pub fn component_count(&self) -> usize {
        let all: Vec<usize> = (0..self.regions.len()).collect();
        self.components_of(&all).len()
    }

    /// `Γ_b` of AC Example 8.19: the closure of `b` without `b` (its topological boundary
    /// as regions).
    pub fn boundary_regions(&self, b: usize) -> Vec<usize> {
        let mut c = self.closure(b);
        c.retain(|&r| r != b);
        c
    }

    /// The entries as `(from id, to id, weight)`.
    pub fn entry_ids(&self) -> Vec<(u64, u64, i64)> {
        self.entries.iter().map(|e| (self.regions[e.from].id, self.regions[e.to].id, e.weight)).collect()
    }

    /// The transposed complex of dimension n: region of dimension k becomes dimension
    /// `n - k`, every entry reversed. This is the incidence graph of the dual G-map (TM §IV,
    /// Poincaré duality) up to signs; Def. 3.1 may fail for it, hence the `Result`.
    pub fn transpose(&self) -> Result<ArchComplex, ArchError> {
        let regions = self.regions.iter().map(|r| Region { id: r.id, dim: self.dim - r.dim }).collect();
        let entries = self.entry_ids().into_iter().map(|(f, t, w)| (t, f, w)).collect();
        ArchComplex::try_new(self.dim, regions, entries)
    }
}

/// Why the cells of a G-map do not give an architectural complex.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
pub enum FromMapError {
    /// a cell is not orientable as a compacted cell (condition C1): no signed incidences
    #[error(transparent)]
    Cell(#[from] CellDefect),
    /// the incidences violate AC Def. 3.1 (δ² ≠ 0: a cell whose boundary is not a cycle)
    #[error(transparent)]
    Arch(#[from] ArchError),
}

/// Signed incidences of the i-cells on the (i-1)-cells of a G-map, split by sign: for
/// each adherent pair (an i-cell and an (i-1)-cell sharing a dart), the number of elements
/// of the face-operator preimage of one fixed element of the (i-1)-cell (BO Def. 4) that lie
/// in the i-cell with sign +1 and with sign -1 (BO Def. 5, 9: `plus + minus` is the
/// unsigned incidence number, `plus - minus` the signed one).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct CellIncidence {
    /// the i-cell (numbered as in `DenseMap::cells(i)`)
    pub upper: u32,
    /// the (i-1)-cell (numbered as in `DenseMap::cells(i - 1)`)
    pub lower: u32,
    /// elements with sign +1
    pub plus: u32,
    /// elements with sign -1
    pub minus: u32,
}

impl CellIncidence {
    /// The signed incidence number (BO Def. 9).
    pub fn signed(&self) -> i64 {
        self.plus as i64 - self.minus as i64
    }

    /// The unsigned incidence number (BO Def. 5).
    pub fn unsigned(&self) -> u32 {
        self.plus + self.minus
    }
}

/// Every adherent pair of i-cells and (i-1)-cells of a valid G-map with its incidence
/// counts, sorted by `(upper, lower)`. Needs every i-cell and (i-1)-cell orientable as a
/// compacted cell (condition C1), else returns the defect naming the cell. `1 <= i <= n`.
/// O(N (n + log N)).
pub fn cell_incidences(map: &DenseMap, i: usize) -> Result<Vec<CellIncidence>, CellDefect> {
    assert!(i >= 1 && i <= map.dim(), "incidences need 1 <= i <= n");
    Ok(incidences_between(&DimData::new(map, i)?, &DimData::new(map, i - 1)?))
}

/// [`cell_incidences`] for every `i = 1..=n` (`result[i - 1]`), computing the cells, the
/// elements of `B_i` and the orientation of each dimension once. O(N n (n + log N)).
pub fn all_cell_incidences(map: &DenseMap) -> Result<Vec<Vec<CellIncidence>>, CellDefect> {
    let mut out = Vec::with_capacity(map.dim());
    let mut lo = DimData::new(map, 0)?;
    for i in 1..=map.dim() {
        let hi = DimData::new(map, i)?;
        out.push(incidences_between(&hi, &lo));
        lo = hi;
    }
    Ok(out)
}

/// What the incidences need of one dimension k: the k-cells, the elements of `B_k`
/// (`<alpha_{k+1..n}>`-orbits) and the orientation of every k-cell (C1).
struct DimData {
    pos: bitvec::vec::BitVec,
    cells: gmap_core::Partition,
    b: gmap_core::Partition,
}

impl DimData {
    fn new(map: &DenseMap, k: usize) -> Result<DimData, CellDefect> {
        Ok(DimData {
            pos: map.cell_orientation(k)?,
            cells: map.cells(k),
            b: map.partition(AlphaSet::above(k, map.dim())),
        })
    }
}

fn incidences_between(hi: &DimData, lo: &DimData) -> Vec<CellIncidence> {
    // the fixed element of B_{i-1} of each (i-1)-cell: the one holding its smallest dart
    let chosen: Vec<u32> = lo.cells.reps.iter().map(|&r| lo.b.of[r as usize]).collect();
    // both cells are unions of B_i elements, so one dart per element gives every pair
    let mut pairs: Vec<(u32, u32)> =
        hi.b.reps.iter().map(|&r| (hi.cells.of[r as usize], lo.cells.of[r as usize])).collect();
    pairs.sort_unstable();
    pairs.dedup();
    let mut out: Vec<CellIncidence> =
        pairs.iter().map(|&(upper, lower)| CellIncidence { upper, lower, plus: 0, minus: 0 }).collect();
    for &r in &hi.b.reps {
        let d = r as usize;
        let f = lo.cells.of[d];
        if lo.b.of[d] != chosen[f as usize] {
            continue;
        }
        let c = hi.cells.of[d];
        let k = pairs.binary_search(&(c, f)).expect("a dart's own pair is adherent");
        if hi.pos[d] == lo.pos[d] {
            out[k].plus += 1;
        } else {
            out[k].minus += 1;
        }
    }
    out
}

impl ArchComplex {
    /// The architectural complex of the cells of a G-map (AC Remark 3.3): one region per
    /// cell (ids: the 0-cells first, numbered as in `DenseMap::cells`, then the 1-cells, …),
    /// and one entry for each adherent pair of consecutive dimensions, weighted by the
    /// signed incidence number — kept when it is 0 (the cylinder's seam). Needs condition
    /// C1 for every dimension (see [`cell_incidences`]). O(N n (n + log N)).
    pub fn from_map(map: &DenseMap) -> Result<ArchComplex, FromMapError> {
        let n = map.dim();
        let counts = map.cell_counts();
        let mut offset = vec![0u64; n + 2];
        for k in 0..=n {
            offset[k + 1] = offset[k] + counts[k] as u64;
        }
        let mut regions = Vec::with_capacity(offset[n + 1] as usize);
        for (k, &c) in counts.iter().enumerate() {
            regions.extend((0..c as u64).map(|j| Region { id: offset[k] + j, dim: k }));
        }
        let mut entries = Vec::new();
        for (k, list) in all_cell_incidences(map)?.into_iter().enumerate() {
            let i = k + 1;
            for ci in list {
                entries.push((offset[i] + ci.upper as u64, offset[i - 1] + ci.lower as u64, ci.signed()));
            }
        }
        Ok(ArchComplex::try_new(n, regions, entries)?)
    }
}

/// How Algorithm 8.16 treats a region of dimension i > 0 with an empty boundary whose only
/// cobounding entries have weight 0 (AC Example 8.19, case α = 0).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum ZeroWeightRule {
    /// Treat it as a closed region (a loop, a sphere — AC Remark 8.2) like the case α ≠ 0:
    /// attach a base vertex with a zero entry (`X_0 + Y_0`). No Betti number decreases
    /// (Remark 8.18 asks this of the cellulation steps); the ring of AC Example 8.21 gets
    /// the stated `b_0 = b_1 = 1`.
    #[default]
    Closed,
    /// The paper's literal case α = 0: the region is an open ball whose boundary was not
    /// recorded; complete it with a new (i-1)-region of weight 1 and a base vertex
    /// (`(X_0 + Y_0) + (X_{i-1} - Y_i)`), or for i = 1 with two end vertices
    /// (`(X_0 + Y_0) + (X_0 - Y_1)`). Reproduces the operator `3X_0 + 2Y_0 - Y_1` printed
    /// in AC Example 8.21.
    Seam,
}

/// Which step of Algorithm 8.16 applied an operator.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Step {
    /// a region with empty boundary, hit with non-zero weight or not at all: base vertex
    BaseVertex,
    /// a region with empty boundary hit only with weight 0, [`ZeroWeightRule::Seam`]
    CompleteSeam,
    /// a region whose boundary `Γ_b` had several components: a connecting edge
    ConnectBoundary,
}

/// One Euler–Poincaré operator applied by Algorithm 8.16.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct AppliedOperator {
    /// the step
    pub step: Step,
    /// the region it was applied to (id)
    pub region: u64,
    /// the regions it created (ids)
    pub created: Vec<u64>,
    /// the operator `(ΔX; ΔY)`
    pub vector: EpVector,
}

impl fmt::Display for AppliedOperator {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{:?} on region {}: {}", self.step, self.region, self.vector)
    }
}

/// The output of Algorithm 8.16: the cw-complex and the operators applied, in order.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Topological {
    /// the resulting complex `cw(C)`
    pub complex: ArchComplex,
    /// every operator applied
    pub operators: Vec<AppliedOperator>,
}

impl Topological {
    /// The sum of all operators applied, or `None` on overflow.
    pub fn total(&self) -> Option<EpVector> {
        let mut t = EpVector::zero(self.complex.dim());
        for o in &self.operators {
            t = t.try_add(&o.vector).ok()?;
        }
        Some(t)
    }
}

struct Growing {
    dim: usize,
    regions: Vec<Region>,
    entries: Vec<(u64, u64, i64)>,
    next_id: u64,
}

impl Growing {
    fn fresh(&mut self, dim: usize) -> u64 {
        let id = self.next_id;
        self.next_id += 1;
        self.regions.push(Region { id, dim });
        id
    }
}

impl ArchComplex {
    /// Algorithm 8.16 for the constructive cases of AC Example 8.19, on a realisable complex:
    ///
    /// 1. *Empty boundary.* Every region of dimension i > 0 without entries gets a base
    ///    vertex with a zero entry (`X_0 + Y_0`, `mvmc`); with [`ZeroWeightRule::Seam`], a
    ///    region hit only by zero weights is completed as in the paper's case α = 0.
    /// 2. *Disconnected boundary.* For i = 2..n, every i-region `b` whose `Γ_b` (closure
    ///    minus `b`) has several components gets, for each component but the first, a new
    ///    edge from a vertex of the first to a vertex of that component (weights -1, +1),
    ///    recorded in `b`'s boundary with weight 0 (a seam). The operator is `X_1 - Y_0`
    ///    (`mekc`) when the two vertices were in different components of the whole complex's
    ///    1-skeleton, and `X_1 + Y_1` (`meml`) when they were already connected elsewhere
    ///    (the new edge then closes a loop: an extension of the paper, which assumes the
    ///    first case).
    ///
    /// New regions get ids above the largest existing id. Every intermediate complex
    /// satisfies Def. 3.1 (checked). O((R + E) · R) in the worst case (one closure per region).
    pub fn topological(&self, rule: ZeroWeightRule) -> Result<Topological, ArchError> {
        let n = self.dim;
        let mut g = Growing {
            dim: n,
            regions: self.regions.clone(),
            entries: self.entry_ids(),
            next_id: self.regions.iter().map(|r| r.id).max().map_or(0, |m| m + 1),
        };
        let mut ops = Vec::new();
        // step 1: regions with empty boundary
        for (r, reg) in self.regions.iter().enumerate() {
            if reg.dim == 0 || !self.down(r).is_empty() {
                continue;
            }
            let i = reg.dim;
            let mut hit = self.up_of(r).filter(|e| self.regions[e.from].dim == i + 1).peekable();
            let all_zero = hit.peek().is_some() && hit.all(|e| e.weight == 0);
            if rule == ZeroWeightRule::Seam && all_zero {
                let v = g.fresh(0);
                let mut vec = EpVector::x_unit(n, 0).try_add(&EpVector::y_unit(n, 0)).expect("small");
                if i > 1 {
                    let s = g.fresh(i - 1);
                    g.entries.push((reg.id, s, 1));
                    g.entries.push((s, v, 0));
                    vec = vec
                        .try_add(&EpVector::x_unit(n, i - 1))
                        .and_then(|x| x.try_add_scaled(-1, &EpVector::y_unit(n, i)))
                        .expect("small");
                    ops.push(AppliedOperator {
                        step: Step::CompleteSeam,
                        region: reg.id,
                        created: vec![s, v],
                        vector: vec,
                    });
                } else {
                    let w = g.fresh(0);
                    g.entries.push((reg.id, v, -1));
                    g.entries.push((reg.id, w, 1));
                    vec = vec
                        .try_add(&EpVector::x_unit(n, 0))
                        .and_then(|x| x.try_add_scaled(-1, &EpVector::y_unit(n, 1)))
                        .expect("small");
                    ops.push(AppliedOperator {
                        step: Step::CompleteSeam,
                        region: reg.id,
                        created: vec![v, w],
                        vector: vec,
                    });
                }
            } else {
                let v = g.fresh(0);
                g.entries.push((reg.id, v, 0));
                let vec = EpVector::b(n, 0);
                ops.push(AppliedOperator { step: Step::BaseVertex, region: reg.id, created: vec![v], vector: vec });
            }
        }
        let mut cur = ArchComplex::try_new(g.dim, g.regions.clone(), g.entries.clone())?;
        // step 2: disconnected boundaries, dimension by dimension
        for i in 2..=n {
            let targets: Vec<u64> = cur.per_dim[i].iter().map(|&r| cur.regions[r as usize].id).collect();
            for bid in targets {
                let b = cur.index_of(bid).expect("region kept");
                let comps = cur.components_of(&cur.boundary_regions(b));
                if comps.len() < 2 {
                    continue;
                }
                let vertex_of = |c: &Vec<usize>| c.iter().copied().find(|&r| cur.regions[r].dim == 0);
                let Some(v0) = vertex_of(&comps[0]) else { continue };
                let mut uf = cur.vertex_connectivity();
                let mut added = Vec::new();
                for comp in &comps[1..] {
                    let Some(v1) = vertex_of(comp) else { continue };
                    let e = g.fresh(1);
                    let (a, c) = (cur.regions[v0].id, cur.regions[v1].id);
                    g.entries.push((e, a, -1));
                    g.entries.push((e, c, 1));
                    g.entries.push((bid, e, 0));
                    let joined = uf.union(v0, v1);
                    let vector = if joined { EpVector::a(n, 1) } else { EpVector::b(n, 1) };
                    added.push(AppliedOperator { step: Step::ConnectBoundary, region: bid, created: vec![e], vector });
                }
                if !added.is_empty() {
                    ops.extend(added);
                    cur = ArchComplex::try_new(g.dim, g.regions.clone(), g.entries.clone())?;
                }
            }
        }
        Ok(Topological { complex: cur, operators: ops })
    }

    /// Union–find over the 0-regions, joined by 1-regions with non-zero weights to both.
    fn vertex_connectivity(&self) -> UnionFind {
        let mut uf = UnionFind::new(self.regions.len());
        for &e in &self.per_dim.get(1).cloned().unwrap_or_default() {
            let ends: Vec<usize> = self
                .down(e as usize)
                .iter()
                .filter(|x| x.weight != 0 && self.regions[x.to].dim == 0)
                .map(|x| x.to)
                .collect();
            for w in ends.windows(2) {
                uf.union(w[0], w[1]);
            }
        }
        uf
    }
}

struct UnionFind(Vec<usize>);

impl UnionFind {
    fn new(n: usize) -> Self {
        UnionFind((0..n).collect())
    }
    fn find(&mut self, mut x: usize) -> usize {
        while self.0[x] != x {
            self.0[x] = self.0[self.0[x]];
            x = self.0[x];
        }
        x
    }
    /// Joins the classes; true if they were distinct.
    fn union(&mut self, a: usize, b: usize) -> bool {
        let (ra, rb) = (self.find(a), self.find(b));
        if ra == rb {
            return false;
        }
        self.0[ra] = rb;
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn reg(v: &[(u64, usize)]) -> Vec<Region> {
        v.iter().map(|&(id, dim)| Region { id, dim }).collect()
    }

    #[test]
    fn cycle_is_named() {
        let e = ArchComplex::try_new(1, reg(&[(1, 1), (2, 1)]), vec![(1, 2, 0), (2, 1, 0)]).unwrap_err();
        assert_eq!(e, ArchError::Cycle { cycle: vec![1, 2, 1] });
        let e = ArchComplex::try_new(1, reg(&[(7, 1)]), vec![(7, 7, 0)]).unwrap_err();
        assert_eq!(e, ArchError::Cycle { cycle: vec![7, 7] });
    }

    #[test]
    fn square_not_zero_is_named() {
        // a disc whose boundary edge has two distinct ends: δ² = ±1 at both vertices
        let e = ArchComplex::try_new(2, reg(&[(0, 0), (1, 0), (2, 1), (3, 2)]), vec![(2, 0, -1), (2, 1, 1), (3, 2, 1)])
            .unwrap_err();
        assert_eq!(e, ArchError::SquareNotZero { from: 3, to: 0, value: -1 });
    }
}
