//! The complex itself (AC Def. 3.1): regions, defined entries, validation, and the chain
//! complex of its completion by zero (AC Def. 3.8, 3.9).

use std::collections::HashMap;

use gmap_core::{LabelValue, Labels};

use crate::engine::chain::ChainComplex;
use crate::engine::homology::{homology_z, homology_zp, Homology, HomologyError};
use crate::engine::sparse::SparseMatrix;

/// The user's name of a region: the id given in the input file (or chosen by the
/// producer), unique in its complex. Distinct from a region's *index*, its position in
/// [`ArchComplex::regions`], which the methods taking `usize` expect.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct RegionId(pub u64);

impl std::fmt::Display for RegionId {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        self.0.fmt(f)
    }
}

impl From<u64> for RegionId {
    fn from(id: u64) -> Self {
        RegionId(id)
    }
}

/// A region: a user id and a dimension.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Region {
    /// the id, unique in the complex
    pub id: RegionId,
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

/// Why data is not an architectural complex (AC Def. 3.1). Regions are named by id; with
/// [`ArchError::named`], by the names of the file ([`RegionNames`](super::RegionNames)).
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum ArchError {
    /// A new region is needed but every `u64` id above the largest one is taken.
    IdsExhausted,
    /// Two regions share an id.
    DuplicateRegion {
        /// the id
        id: RegionId,
    },
    /// A region's dimension exceeds the complex's.
    RegionDimension {
        /// the region
        id: RegionId,
        /// its dimension
        dim: usize,
        /// the complex's dimension
        max: usize,
    },
    /// An entry names a region that does not exist.
    UnknownRegion {
        /// `from` of the entry
        from: RegionId,
        /// `to` of the entry
        to: RegionId,
        /// the id not found
        missing: RegionId,
    },
    /// The same pair appears twice.
    DuplicateEntry {
        /// `from`
        from: RegionId,
        /// `to`
        to: RegionId,
    },
    /// The incidence graph has a directed cycle (listed in order, first id repeated last).
    Cycle {
        /// the regions of the cycle
        cycle: Vec<RegionId>,
    },
    /// An entry does not go from a higher to a strictly lower dimension.
    DimensionNotDecreasing {
        /// `from`
        from: RegionId,
        /// `to`
        to: RegionId,
        /// dimension of `from`
        from_dim: usize,
        /// dimension of `to`
        to_dim: usize,
    },
    /// An entry across a dimension gap of two or more has a non-zero weight.
    WeightAcrossGap {
        /// `from`
        from: RegionId,
        /// `to`
        to: RegionId,
        /// dimension of `from`
        from_dim: usize,
        /// dimension of `to`
        to_dim: usize,
        /// the weight
        weight: i64,
    },
    /// `δ²` has a non-zero defined entry: the boundary of `from` has a non-zero boundary at `to`.
    SquareNotZero {
        /// the upper region
        from: RegionId,
        /// the region two steps down
        to: RegionId,
        /// the value of the entry of δ²
        value: i128,
    },
    /// An intermediate sum overflowed 128-bit integers (only with absurd weights).
    Overflow {
        /// the upper region
        from: RegionId,
    },
    /// Betti numbers given to a region that no topological region of its dimension has
    /// (AC Def. 8.1: connected, orientable, bounded by closed orientable manifolds).
    RegionBetti {
        /// the region
        id: RegionId,
        /// its dimension
        dim: usize,
        /// the Betti numbers given
        betti: Vec<usize>,
        /// what rules them out
        reason: &'static str,
    },
    /// Algorithm 8.16 cannot cellulate a region from what the complex and its Betti numbers
    /// tell: the topological Betti numbers would be guessed, so none are given.
    RegionTopologyUnknown {
        /// the region
        id: RegionId,
        /// its dimension
        dim: usize,
        /// its Betti numbers (given, or the default)
        betti: Vec<usize>,
        /// the components of its boundary in the complex (of `Γ_b`; 0 for no entry)
        boundary: usize,
        /// why
        reason: &'static str,
    },
    /// Incidence signs were left out and cannot be chosen: the boundary of the region is
    /// not a cycle for any choice of signs (or its points do not say which way it turns).
    CannotOrient {
        /// the region
        id: RegionId,
        /// its dimension
        dim: usize,
        /// why
        reason: String,
        /// the region where it fails, if one
        at: Option<RegionId>,
    },
    /// Incidence signs were left out and the boundary of a region is open: some
    /// (k-2)-regions lie on an odd number of its (k-1)-faces (a room missing a wall or its
    /// roof, a face missing an edge), so no choice of signs makes it a cycle.
    BoundaryOpen {
        /// the region
        id: RegionId,
        /// its dimension
        dim: usize,
        /// the (k-2)-regions where it is open, in index order
        at: Vec<RegionId>,
        /// another region of the same dimension open at one of the same places: the two
        /// miss the face between them (a party wall)
        with: Option<RegionId>,
    },
    /// A region label whose value is a real that is not finite.
    LabelNotFinite {
        /// the region
        id: RegionId,
        /// the label's name
        name: String,
    },
}

/// An architectural complex (AC Def. 3.1). Immutable once built; see the module docs.
///
/// Two complexes are equal when their regions, entries, given Betti numbers and region
/// labels are equal.
#[derive(Clone, Debug, PartialEq)]
pub struct ArchComplex {
    pub(super) dim: usize,
    pub(super) regions: Vec<Region>,
    pub(super) by_id: HashMap<RegionId, usize>,
    /// entries sorted by (from, to)
    pub(super) entries: Vec<Entry>,
    /// entries of region r are `entries[down_off[r]..down_off[r + 1]]`
    pub(super) down_off: Vec<usize>,
    /// entry indices whose `to` is r: `up[up_off[r]..up_off[r + 1]]`
    pub(super) up_off: Vec<usize>,
    pub(super) up: Vec<u32>,
    /// position of each region among the regions of its dimension
    pub(super) rank_in_dim: Vec<u32>,
    /// region indices per dimension
    pub(super) per_dim: Vec<Vec<u32>>,
    /// the Betti numbers given to each region (`None`: the default, see
    /// [`ArchComplex::region_betti`])
    pub(super) betti: Vec<Option<Vec<usize>>>,
    /// the labels of each region (empty: none), e.g. a room's name
    pub(super) labels: Vec<Labels>,
    /// the string id the file gave each region (`None`: its number is its id)
    pub(super) keys: Vec<Option<String>>,
    /// the point of each region (0-regions of a file with coordinates)
    pub(super) points: Vec<Option<[f64; 3]>>,
}

/// Equality is an equivalence: the only reals a complex holds are region labels and points,
/// which [`ArchComplex::with_region_labels`] and [`ArchComplex::with_region_point`] refuse
/// when not finite (NaN among them).
impl Eq for ArchComplex {}

impl ArchComplex {
    /// Builds and validates a complex of dimension `dim` from regions and entries given as
    /// `(from id, to id, weight)`. Checks, in this order: duplicate ids, region dimensions,
    /// unknown ids, duplicate entries, cycles, decreasing dimension, zero weight across a
    /// gap, `δ² = 0`. Returns the first violation. See the module docs for complexity.
    pub fn try_new<I: Into<RegionId> + Copy>(
        dim: usize,
        regions: Vec<Region>,
        entries: Vec<(I, I, i64)>,
    ) -> Result<Self, ArchError> {
        let entries: Vec<(RegionId, RegionId, i64)> =
            entries.into_iter().map(|(f, t, w)| (f.into(), t.into(), w)).collect();
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

    fn assemble(dim: usize, regions: Vec<Region>, by_id: HashMap<RegionId, usize>, entries: Vec<Entry>) -> Self {
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
        let betti = vec![None; nr];
        let labels = vec![Labels::new(); nr];
        let (keys, points) = (vec![None; nr], vec![None; nr]);
        ArchComplex {
            dim,
            regions,
            by_id,
            entries,
            down_off,
            up_off,
            up,
            rank_in_dim,
            per_dim,
            betti,
            labels,
            keys,
            points,
        }
    }

    /// The complex with region `id` given its own topology: the Betti numbers
    /// `(b_0, …, b_dim)` of the region as a compact manifold with boundary (AC Def. 8.1), for
    /// Algorithm 8.16 ([`ArchComplex::topological`]). A torus 2-region is `[1, 2, 1]`, an
    /// annulus `[1, 1, 0]`, a solid torus `[1, 1, 0, 0]`. Fails with
    /// [`ArchError::UnknownRegion`] (naming `id` as both ends) for an unknown id and with
    /// [`ArchError::RegionBetti`] where [`ArchComplex::check_region_betti`] does. O(dim).
    ///
    /// ```
    /// use gmap_homology::arch::{ArchComplex, RegionId, ZeroWeightRule};
    /// // a torus region, alone: by default a sphere, (1, 0, 1); as a torus, (1, 2, 1)
    /// let x = ArchComplex::try_from_ids(2, &[(7, 2)], &[]).unwrap();
    /// assert_eq!(x.region_betti(0), vec![1, 0, 1]);
    /// let t = x.with_region_betti(RegionId(7), vec![1, 2, 1]).unwrap();
    /// let cw = t.topological(ZeroWeightRule::Closed).unwrap().complex;
    /// assert_eq!(cw.homology_z().unwrap().betti, vec![1, 2, 1]);
    /// ```
    pub fn with_region_betti(mut self, id: RegionId, betti: Vec<usize>) -> Result<Self, ArchError> {
        let r = self.index_of(id).ok_or(ArchError::UnknownRegion { from: id, to: id, missing: id })?;
        let dim = self.regions[r].dim;
        Self::check_region_betti(dim, &betti).map_err(|reason| ArchError::RegionBetti {
            id,
            dim,
            betti: betti.clone(),
            reason,
        })?;
        self.betti[r] = Some(betti);
        Ok(self)
    }

    /// The complex with region `id` given `labels` (its name, kind, material, …), replacing
    /// any it had. Labels take no part in the topology; they travel with the region through
    /// the `.json` and `.dot` writers. Fails with [`ArchError::UnknownRegion`] (naming `id`
    /// as both ends) for an unknown id and with [`ArchError::LabelNotFinite`] for a real
    /// value that is not finite. O(number of labels).
    ///
    /// ```
    /// use gmap_core::{LabelValue, Labels};
    /// use gmap_homology::arch::{ArchComplex, RegionId};
    /// let x = ArchComplex::try_from_ids(0, &[(7, 0)], &[]).unwrap();
    /// let room: Labels = [("name", LabelValue::Text("kitchen".into()))].into_iter().collect();
    /// let x = x.with_region_labels(RegionId(7), room.clone()).unwrap();
    /// assert_eq!(x.region_labels(0), &room);
    /// assert!(x.with_region_labels(RegionId(8), room).is_err());
    /// ```
    pub fn with_region_labels(mut self, id: RegionId, labels: Labels) -> Result<Self, ArchError> {
        let r = self.index_of(id).ok_or(ArchError::UnknownRegion { from: id, to: id, missing: id })?;
        if let Some((name, _)) = labels.iter().find(|(_, v)| matches!(v, LabelValue::Real(x) if !x.is_finite())) {
            return Err(ArchError::LabelNotFinite { id, name: name.to_string() });
        }
        self.labels[r] = labels;
        Ok(self)
    }

    /// The complex with region `id` known by the string `key` in its file (`.json` ids may
    /// be strings; the region keeps its number inside). Fails with
    /// [`ArchError::UnknownRegion`] for an unknown id. O(1).
    pub fn with_region_key(mut self, id: RegionId, key: String) -> Result<Self, ArchError> {
        let r = self.index_of(id).ok_or(ArchError::UnknownRegion { from: id, to: id, missing: id })?;
        self.keys[r] = Some(key);
        Ok(self)
    }

    /// The string id of region `index` in its file, if it had one. O(1).
    pub fn region_key(&self, index: usize) -> Option<&str> {
        self.keys[index].as_deref()
    }

    /// The complex with region `id` at the point `p` (a vertex's coordinates). Fails with
    /// [`ArchError::UnknownRegion`] for an unknown id and [`ArchError::LabelNotFinite`]
    /// (label `point`) for a coordinate that is not finite. O(1).
    pub fn with_region_point(mut self, id: RegionId, p: [f64; 3]) -> Result<Self, ArchError> {
        let r = self.index_of(id).ok_or(ArchError::UnknownRegion { from: id, to: id, missing: id })?;
        if p.iter().any(|x| !x.is_finite()) {
            return Err(ArchError::LabelNotFinite { id, name: "point".into() });
        }
        self.points[r] = Some(p);
        Ok(self)
    }

    /// The point of region `index`, if it has one. O(1).
    pub fn region_point(&self, index: usize) -> Option<[f64; 3]> {
        self.points[index]
    }

    /// The labels of region `index` (empty when it has none). O(1).
    pub fn region_labels(&self, index: usize) -> &Labels {
        &self.labels[index]
    }

    /// Whether `betti` can be the Betti numbers of a topological region of dimension `dim`
    /// (AC Def. 8.1), as far as Betti numbers tell: one number per dimension `0..=dim`,
    /// `b_0 = 1` (connected), `b_dim` 0 (a boundary) or 1 (closed), a closed region's
    /// numbers symmetric (Poincaré duality) with an even middle number in dimensions
    /// `4k + 2` (a closed surface has `b_1 = 2g`), a 1-region a segment `[1, 0]` or a loop
    /// `[1, 1]`, a point `[1]`. Returns the reason otherwise. O(dim).
    pub fn check_region_betti(dim: usize, betti: &[usize]) -> Result<(), &'static str> {
        if betti.len() != dim + 1 {
            return Err("one Betti number per dimension 0..=dim is needed");
        }
        if betti[0] != 1 {
            return Err("a region is connected: b_0 = 1");
        }
        if dim == 0 {
            return Ok(());
        }
        match betti[dim] {
            0 => {}
            1 => {
                if (0..=dim).any(|k| betti[k] != betti[dim - k]) {
                    return Err("a closed orientable manifold has symmetric Betti numbers (Poincaré duality)");
                }
                if dim % 4 == 2 && betti[dim / 2] % 2 == 1 {
                    return Err("a closed orientable manifold of dimension 4k + 2 has an even middle Betti number (a closed surface: b_1 = 2g)");
                }
            }
            _ => return Err("a connected region has b_dim = 1 when closed, 0 otherwise"),
        }
        Ok(())
    }

    /// The Betti numbers of region `index`: those given by
    /// [`ArchComplex::with_region_betti`], or the default. The default is the region of the
    /// cw case, an open cell glued along its recorded boundary: with `r >= 1` boundary
    /// components (the components of `Γ_b`, as AC Example 8.22 counts them) the sphere with
    /// `r` holes, `(1, 0, …, 0, r - 1, 0)`, a ball for `r = 1`; with no entry, a closed
    /// region, the sphere `(1, 0, …, 0, 1)` (a loop for dimension 1), as
    /// [`super::ZeroWeightRule::Closed`] reads it. O(size of the closure of the region).
    pub fn region_betti(&self, index: usize) -> Vec<usize> {
        if let Some(b) = &self.betti[index] {
            return b.clone();
        }
        let dim = self.regions[index].dim;
        let mut b = vec![0usize; dim + 1];
        b[0] = 1;
        if dim == 0 {
            return b;
        }
        let r = self.boundary_component_count(index);
        if r == 0 {
            b[dim] += 1;
        } else {
            b[dim - 1] += r - 1;
        }
        b
    }

    /// Whether region `index` was given Betti numbers ([`ArchComplex::with_region_betti`]).
    pub fn has_region_betti(&self, index: usize) -> bool {
        self.betti[index].is_some()
    }

    /// The number of components of the boundary of region `index` as the complex records
    /// it: 0 without entries, else the components of `Γ_b` (the closure of the region
    /// without the region). O(size of the closure).
    pub fn boundary_component_count(&self, index: usize) -> usize {
        if self.down(index).is_empty() {
            0
        } else {
            self.components_of(&self.boundary_regions(index)).len()
        }
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
                let mut cyc: Vec<RegionId> = path[p..].iter().rev().map(|&r| self.regions[r].id).collect();
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

    /// [`ArchComplex::try_new`] from plain numbers: regions as `(id, dim)`, entries as
    /// `(from id, to id, weight)`.
    pub fn try_from_ids(dim: usize, regions: &[(u64, usize)], entries: &[(u64, u64, i64)]) -> Result<Self, ArchError> {
        let regions = regions.iter().map(|&(id, dim)| Region { id: RegionId(id), dim }).collect();
        let entries = entries.iter().map(|&(f, t, w)| (RegionId(f), RegionId(t), w)).collect();
        ArchComplex::try_new(dim, regions, entries)
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
    pub fn index_of(&self, id: RegionId) -> Option<usize> {
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

    /// The entries as `(from id, to id, weight)`.
    pub fn entry_ids(&self) -> Vec<(RegionId, RegionId, i64)> {
        self.entries.iter().map(|e| (self.regions[e.from].id, self.regions[e.to].id, e.weight)).collect()
    }

    /// The transposed complex of dimension n: region of dimension k becomes dimension
    /// `n - k`, every entry reversed. This is the incidence graph of the dual G-map (TM §IV,
    /// Poincaré duality) up to signs; Def. 3.1 may fail for it, hence the `Result`. Betti
    /// numbers given to regions are not carried over (a dual region is another space).
    pub fn transpose(&self) -> Result<ArchComplex, ArchError> {
        let regions = self.regions.iter().map(|r| Region { id: r.id, dim: self.dim - r.dim }).collect();
        let entries = self.entry_ids().into_iter().map(|(f, t, w)| (t, f, w)).collect();
        ArchComplex::try_new(self.dim, regions, entries)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ids(v: &[u64]) -> Vec<RegionId> {
        v.iter().copied().map(RegionId).collect()
    }

    #[test]
    fn cycle_is_named() {
        let e = ArchComplex::try_from_ids(1, &[(1, 1), (2, 1)], &[(1, 2, 0), (2, 1, 0)]).unwrap_err();
        assert_eq!(e, ArchError::Cycle { cycle: ids(&[1, 2, 1]) });
        let e = ArchComplex::try_from_ids(1, &[(7, 1)], &[(7, 7, 0)]).unwrap_err();
        assert_eq!(e, ArchError::Cycle { cycle: ids(&[7, 7]) });
    }

    #[test]
    fn square_not_zero_is_named() {
        // a disc whose boundary edge has two distinct ends: δ² = ±1 at both vertices
        let e = ArchComplex::try_from_ids(2, &[(0, 0), (1, 0), (2, 1), (3, 2)], &[(2, 0, -1), (2, 1, 1), (3, 2, 1)])
            .unwrap_err();
        assert_eq!(e, ArchError::SquareNotZero { from: RegionId(3), to: RegionId(0), value: -1 });
    }
}
