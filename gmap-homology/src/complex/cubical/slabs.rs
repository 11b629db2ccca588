//! The cubical chain complex of a set of any dimension, built and reduced slab by slab, so
//! that memory grows with a slab and with the reduced complex, not with the box.
//!
//! The cells are the points of the doubled grid ([`super::grid`]): `2L + 1` points per axis
//! (`2L` on a periodic axis). The box is read one layer of cubes across its slowest axis at a
//! time (`fill`, as in [`super::pass`]); the cells of doubled layers `2z`, `2z + 1`
//! and `2z + 2` that the closure of layer `z` adds are added to the complex. Every `slab`
//! layers the complex is reduced by pairs that keep the homology and need no arithmetic:
//!
//! * a **collapse** `(a, b)`: `b` is the only surviving coface of `a`. Allowed only when every
//!   coface `a` will ever have is known: `a` lies below the frontier layer `2z + 2` (and, on a
//!   periodic slowest axis, not in layer 0, whose cofaces include the last layer);
//! * a **coreduction** `(a, b)`: `a` is the only surviving face of `b`. Allowed anywhere, since
//!   the faces of a cell are present with it.
//!
//! After any sequence of such pairs the reduced complex is the restriction of the boundary
//! matrices to the surviving cells (`engine/morse.rs` gives the argument), so nothing but the
//! set of survivors is stored: the faces and cofaces of a cell come from its coordinates, and
//! a cell added later simply does not see the cells removed before. Layers the next slab
//! cannot change are moved from dense rows (one byte per point) into a hash set of the
//! surviving points.
//!
//! **Starting the coreductions.** A set without free faces left (a loop, a closed surface)
//! has no cell with a single face either. As in Mrozek and Batko's algorithm, a vertex `v` is
//! then set aside: the complex becomes the relative one `(X, V)`, whose coreductions sweep on.
//! Every vertex of a complete layer still alive after the slab's sweep is set aside, one at a
//! time; two of them may lie in the same component (joined only through later layers), so the
//! groups of X follow from those of `(X, V)` by `H_k(X) = H_k(X, V)` for `k ≥ 2`,
//! `b_1(X) = b_1(X, V) - |V| + c_V` and `b_0(X) = b_0(X, V) + c_V`, with `c_V` the components of
//! X meeting V (the sequence of the pair splits, V being discrete: torsion is unchanged). The
//! components of X are counted on the way by a union-find over two layers of cubes at a time
//! (cubes joined when they share any face), so `c_V = b_0(X) - b_0(X, V)`:
//! [`SlabComplex::absolute`] makes the correction.
//!
//! With `keep_subcomplex` only collapses are made and no vertex is set aside: the survivors
//! then form a subcomplex, whose cycles are cycles of the set (the generators' route).
//! Without it, coreductions reduce further but the survivors' cycles are those of a quotient.
//! A periodic box sets no vertex aside either (its components are not counted).
//!
//! Memory: `(2 · slab + 1)` rows of one byte per point of a doubled layer (two on a periodic
//! slowest axis), one layer of cubes, and about 24 bytes per surviving point of the layers
//! behind. Time: O(points · d) checks, each of O(d) lookups.
//!
//! ```
//! use gmap_homology::{cubical::slabs::cubical_complex_slabs, homology_z};
//! // a 3 × 3 × 3 block with its centre removed: a sphere, read one layer at a time
//! let mut bits = vec![1u8; 27];
//! bits[13] = 0;
//! let fill = |start: usize, out: &mut [u8]| out.copy_from_slice(&bits[start..start + out.len()]);
//! let c = cubical_complex_slabs(&[3, 3, 3], fill, false, 1, false).unwrap();
//! let h = c.absolute(homology_z(&c.complex.chain).unwrap()).unwrap();
//! assert_eq!(h.betti, vec![1, 0, 1, 0]);
//! ```

#![allow(clippy::needless_range_loop)] // axes index several arrays at once

use rustc_hash::{FxHashMap, FxHashSet};

use gmap_core::union_find::UnionFind;

use super::grid::{self, Grid, Order, Placement};
use super::{mark_closure, CubicalComplex, CubicalError};
use crate::{ChainComplex, Homology, SparseMatrix};

const PRESENT: u8 = 1;
const ALIVE: u8 = 2;
const QUEUED: u8 = 4;

/// Bytes held per surviving point of the layers behind the slab (a hash-set slot and its
/// share of the table's spare room).
pub const BYTES_PER_SURVIVOR: u64 = 24;

/// The doubled grid and the cells alive in it.
struct Slabs {
    /// the whole box's doubled grid, axis 0 fastest (axis `d - 1`, the slowest, is the layer)
    grid: Grid,
    /// points of one doubled layer
    layer: usize,
    /// dense rows of the layers in the slab (and layer 0 of a periodic box), by layer
    rows: Vec<Option<Box<[u8]>>>,
    /// the surviving points of layers whose row was released
    behind: FxHashSet<usize>,
    /// the lowest layer a collapse may not start from (the frontier), `usize::MAX` for none
    frontier: usize,
    /// layer 0 is closed to collapses (a periodic slowest axis before the last layer)
    hold_zero: bool,
    coreductions: bool,
    /// cells to check
    queue: Vec<usize>,
    /// vertices set aside (the complex is relative to them)
    set_aside: u64,
}

impl Slabs {
    #[inline]
    fn layer_of(&self, p: usize) -> usize {
        p / self.layer
    }

    #[inline]
    fn state(&self, p: usize) -> u8 {
        let s = self.layer_of(p);
        match &self.rows[s] {
            Some(row) => row[p % self.layer],
            None => {
                if self.behind.contains(&p) {
                    PRESENT | ALIVE
                } else {
                    0
                }
            }
        }
    }

    #[inline]
    fn alive(&self, p: usize) -> bool {
        self.state(p) & ALIVE != 0
    }

    fn kill(&mut self, p: usize) {
        let s = self.layer_of(p);
        let layer = self.layer;
        match &mut self.rows[s] {
            Some(row) => row[p % layer] &= !ALIVE,
            None => {
                self.behind.remove(&p);
            }
        }
    }

    fn push(&mut self, p: usize) {
        let s = self.layer_of(p);
        let layer = self.layer;
        if let Some(row) = &mut self.rows[s] {
            let x = &mut row[p % layer];
            if *x & QUEUED != 0 {
                return;
            }
            *x |= QUEUED;
        }
        self.queue.push(p);
    }

    /// The two faces (`faces = true`, `c` odd) or cofaces (`c` even) of `p` along axis `a`,
    /// where `c` is `p`'s coordinate on it; none where the two are one point (a periodic
    /// axis of one cube: their entries cancel).
    #[inline]
    fn across(&self, p: usize, a: usize, c: usize, faces: bool) -> [Option<usize>; 2] {
        let [lo, hi] = if faces {
            let (lo, up) = self.grid.faces_along(p, a, c);
            [Some(lo), Some(up)]
        } else {
            self.grid.cofaces_along(p, a, c)
        };
        if lo.is_some() && lo == hi {
            return [None, None];
        }
        [lo, hi]
    }

    /// The alive faces (`faces = true`) or cofaces of `p`: their number, and one of them.
    fn neighbours(&self, p: usize, faces: bool) -> (usize, usize) {
        let (mut count, mut one) = (0, 0);
        for a in 0..self.grid.axes() {
            let c = self.grid.coord(p, a);
            if (c % 2 == 1) == faces {
                let pair = self.across(p, a, c, faces);
                for q in pair.into_iter().flatten() {
                    if self.alive(q) {
                        count += 1;
                        one = q;
                    }
                }
            }
        }
        (count, one)
    }

    /// Queues the alive faces (`faces = true`) or cofaces of `p`.
    fn push_neighbours(&mut self, p: usize, faces: bool) {
        for a in 0..self.grid.axes() {
            let c = self.grid.coord(p, a);
            if (c % 2 == 1) == faces {
                let pair = self.across(p, a, c, faces);
                for q in pair.into_iter().flatten() {
                    if self.alive(q) {
                        self.push(q);
                    }
                }
            }
        }
    }

    fn may_collapse(&self, p: usize) -> bool {
        let s = self.layer_of(p);
        s < self.frontier && !(self.hold_zero && s == 0)
    }

    /// Pairs cells from the queue until it is empty.
    fn reduce(&mut self) {
        while let Some(p) = self.queue.pop() {
            let s = self.layer_of(p);
            let layer = self.layer;
            if let Some(row) = &mut self.rows[s] {
                row[p % layer] &= !QUEUED;
            }
            if !self.alive(p) {
                continue;
            }
            if self.coreductions {
                let (count, a) = self.neighbours(p, true);
                if count == 1 {
                    // coreduction: `a` is the only face of `p`
                    self.kill(p);
                    self.kill(a);
                    self.push_neighbours(a, false);
                    self.push_neighbours(a, true);
                    self.push_neighbours(p, false);
                    continue;
                }
            }
            if self.may_collapse(p) {
                let (count, b) = self.neighbours(p, false);
                if count == 1 {
                    // collapse: `b` is the only coface of `p`
                    self.kill(p);
                    self.kill(b);
                    self.push_neighbours(b, true);
                    self.push_neighbours(p, true);
                    self.push_neighbours(b, false);
                }
            }
        }
    }

    /// Adds the cells of `closed` (points of one doubled layer, non-zero: in the closure) to
    /// layer `s` that were never present there, and queues them.
    fn add(&mut self, s: usize, closed: &[u8]) {
        let layer = self.layer;
        let row = self.rows[s].get_or_insert_with(|| vec![0u8; layer].into_boxed_slice());
        let mut fresh = Vec::new();
        for (x, (&c, r)) in closed.iter().zip(row.iter_mut()).enumerate() {
            if c != 0 && *r & PRESENT == 0 {
                *r = PRESENT | ALIVE | QUEUED;
                fresh.push(s * layer + x);
            }
        }
        self.queue.extend(fresh);
    }

    /// Queues every alive cell of layer `s` (its collapses were held until now).
    fn queue_layer(&mut self, s: usize) {
        let layer = self.layer;
        if let Some(row) = &mut self.rows[s] {
            for (x, r) in row.iter_mut().enumerate() {
                if *r & ALIVE != 0 && *r & QUEUED == 0 {
                    *r |= QUEUED;
                    self.queue.push(s * layer + x);
                }
            }
        }
    }

    /// Sets aside each vertex of layer `s` still alive, one at a time, each followed by the
    /// coreductions it starts.
    fn seed_layer(&mut self, s: usize) {
        if s % 2 == 1 {
            return;
        }
        let layer = self.layer;
        for x in 0..layer {
            let p = s * layer + x;
            if self.alive(p) && (0..self.grid.axes() - 1).all(|a| self.grid.coord(p, a).is_multiple_of(2)) {
                self.kill(p);
                self.set_aside += 1;
                self.push_neighbours(p, false);
                self.reduce();
            }
        }
    }

    /// Moves the survivors of layer `s` into the hash set and frees its row.
    fn release(&mut self, s: usize) {
        let layer = self.layer;
        if let Some(row) = self.rows[s].take() {
            for (x, &r) in row.iter().enumerate() {
                if r & ALIVE != 0 {
                    self.behind.insert(s * layer + x);
                }
            }
        }
    }
}

/// The closure of one layer of cubes (of `shape`) in its doubled layer grid `g`: a byte per
/// point, non-zero where a cube of `bits` has the point as a face.
fn close_layer(shape: &[usize], g: &Grid, bits: &[u8], out: &mut [u8]) {
    out.fill(0);
    mark_closure(shape, g, bits, out);
}

/// The cubical chain complex of the set of a box of `shape` cubes (axis 0 fastest, any
/// dimension ≥ 1), read one layer of the slowest axis at a time through `fill(start, out)`
/// (the presence bytes of cubes `start .. start + out.len()`), reduced every `slab` layers
/// (see the [module docs](self)). `periodic` identifies opposite faces of the box;
/// `keep_subcomplex` makes collapses only, so that the cycles of the result are cycles of the
/// set (for generators). The cells of the result are named by their doubled-grid points, as
/// those of [`super::cubical_complex`]; its homology, through
/// [`SlabComplex::absolute`], is theirs.
///
/// Refuses an empty shape, a grid past `u64`, or rows over the memory limit; the survivors
/// are checked against the limit as each slab is released.
pub fn cubical_complex_slabs(
    shape: &[usize],
    fill: impl Fn(usize, &mut [u8]),
    periodic: bool,
    slab: usize,
    keep_subcomplex: bool,
) -> Result<SlabComplex, CubicalError> {
    let d = shape.len();
    if d == 0 || shape.contains(&0) {
        return Err(CubicalError::BadShape(format!("shape {shape:?}")));
    }
    let placement = if periodic { Placement::Periodic } else { Placement::Cubes };
    let grid = Grid::of_box(shape, placement, Order::FirstFastest)
        .ok_or_else(|| CubicalError::TooLarge { points: grid::shown(shape, placement), limit: u64::MAX })?;
    let n = grid.points().to_vec();
    let layer = grid.strides()[d - 1];
    // the doubled grid of one layer: the box's first d - 1 axes
    let layer_grid = Grid::new(n[..d - 1].to_vec(), periodic, Order::FirstFastest).expect("a part of the grid");
    let cubes_per_layer: usize = shape[..d - 1].iter().product();
    let slab = slab.max(1);
    let rows_held = (2 * slab as u64 + 2) * layer as u64;
    gmap_core::resources::check_memory(
        "the rows of the slab-by-slab cubical complex",
        rows_held.checked_add(2 * layer as u64).and_then(|b| b.checked_add(cubes_per_layer as u64)),
    )?;
    let slow = shape[d - 1];
    let mut g = Slabs {
        grid,
        layer,
        rows: (0..n[d - 1]).map(|_| None).collect(),
        behind: FxHashSet::default(),
        frontier: 0,
        hold_zero: periodic,
        coreductions: !keep_subcomplex,
        queue: Vec::new(),
        set_aside: 0,
    };
    let seed = !keep_subcomplex && !periodic;
    let mut components = Components::new(&shape[..d - 1]);
    let mut bits = vec![0u8; cubes_per_layer];
    let mut closed = vec![0u8; layer];
    let top_of = |z: usize| if periodic && z + 1 == slow { 0 } else { 2 * z + 2 };
    // the first layer that has not been released to the hash set
    let mut kept_from = 0usize;
    for z in 0..slow {
        fill(z * cubes_per_layer, &mut bits);
        if seed {
            components.layer(&bits);
        }
        if d == 1 {
            closed[0] = bits[0];
        } else {
            close_layer(&shape[..d - 1], &layer_grid, &bits, &mut closed);
        }
        let top = top_of(z);
        g.frontier = 2 * z + 2;
        // the faces first, so that a queued cell finds its neighbours
        g.add(2 * z, &closed);
        g.add(top, &closed);
        g.add(2 * z + 1, &closed);
        let last = z + 1 == slow;
        if (z + 1) % slab == 0 || last {
            // layers below the frontier are complete now: their collapses may start
            for s in kept_from..2 * z + 2 {
                g.queue_layer(s);
            }
            if last {
                g.frontier = usize::MAX;
                g.hold_zero = false;
                g.queue_layer(top);
                if periodic {
                    g.queue_layer(0);
                }
            }
            g.reduce();
            if seed {
                let end = if last { n[d - 1] } else { 2 * z + 2 };
                for s in kept_from..end {
                    g.seed_layer(s);
                }
            }
            if !last {
                let start = if periodic { kept_from.max(1) } else { kept_from };
                for s in start..2 * z + 2 {
                    g.release(s);
                }
                kept_from = 2 * z + 2;
                gmap_core::resources::check_memory(
                    "the surviving cells of the slab-by-slab cubical complex",
                    (g.behind.len() as u64).checked_mul(BYTES_PER_SURVIVOR).and_then(|b| b.checked_add(rows_held)),
                )?;
            }
        }
    }
    let mut survivors: Vec<usize> = g.behind.iter().copied().collect();
    for (s, row) in g.rows.iter().enumerate() {
        if let Some(row) = row {
            survivors.extend(row.iter().enumerate().filter(|(_, &r)| r & ALIVE != 0).map(|(x, _)| s * layer + x));
        }
    }
    survivors.sort_unstable();
    let complex = build(&g, &survivors)?;
    let components = if seed { Some(components.finish()) } else { None };
    Ok(SlabComplex { complex, relative: Relative { set_aside: g.set_aside, components } })
}

/// What [`cubical_complex_slabs`] gives: the reduced complex, relative to the vertices set
/// aside, and what [`SlabComplex::absolute`] needs to give the set's own groups.
#[derive(Clone, Debug)]
pub struct SlabComplex {
    /// the reduced complex (relative to the vertices set aside)
    pub complex: CubicalComplex,
    /// the vertices set aside and the components of the set
    pub relative: Relative,
}

impl SlabComplex {
    /// The groups of the set from those of [`Self::complex`]: [`Relative::absolute`].
    pub fn absolute(&self, h: Homology) -> Result<Homology, CubicalError> {
        self.relative.absolute(h)
    }

    /// The vertices set aside.
    pub fn set_aside(&self) -> u64 {
        self.relative.set_aside
    }
}

/// A complex relative to vertices set aside: how its groups become the set's.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Relative {
    /// the vertices set aside (`|V|`)
    pub set_aside: u64,
    /// the components of the set, where they were counted (vertices were set aside)
    pub components: Option<u64>,
}

impl Relative {
    /// The groups of the set from those of the complex relative to the vertices set aside
    /// (see the [module docs](self)): unchanged without vertices set aside; else `b_0` the
    /// components and `b_1 = b_1(X, V) - |V| + c_V`, over Z or a field alike. Refuses figures
    /// that do not fit the pair's sequence.
    pub fn absolute(&self, mut h: Homology) -> Result<Homology, CubicalError> {
        let Some(b0) = self.components.filter(|_| self.set_aside > 0) else {
            return Ok(h);
        };
        let relative = h.betti.clone();
        let bad = || {
            CubicalError::BadShape(format!(
                "internal: relative groups {relative:?} with {} vertices set aside and {b0} components",
                self.set_aside
            ))
        };
        let (rel0, rel1) = (h.betti[0] as u64, h.betti.get(1).copied().unwrap_or(0) as u64);
        let c_v = b0.checked_sub(rel0).ok_or_else(bad)?;
        let b1 = (rel1 + c_v).checked_sub(self.set_aside).ok_or_else(bad)?;
        h.betti[0] = usize::try_from(b0).map_err(|_| bad())?;
        if h.betti.len() > 1 {
            h.betti[1] = usize::try_from(b1).map_err(|_| bad())?;
        } else if b1 != 0 {
            return Err(bad());
        }
        Ok(h)
    }
}

/// The components of a set of cubes counted one layer at a time: a union-find over the
/// classes of the previous layer and the cubes of the current one, cubes joined when they
/// share any face. A class of the previous layer that reaches no cube of the current one is
/// finished. Memory: two layers of labels.
struct Components {
    shape: Vec<usize>,
    stride: Vec<usize>,
    /// the offsets of the `3^(d-1)` neighbours in a layer, per axis
    offsets: Vec<Vec<isize>>,
    /// per cube of the previous layer its class `0 .. classes`, or `u32::MAX`
    prev: Vec<u32>,
    classes: usize,
    finished: u64,
}

impl Components {
    fn new(shape: &[usize]) -> Self {
        let e = shape.len();
        let mut stride = vec![1usize; e];
        for a in 1..e {
            stride[a] = stride[a - 1] * shape[a - 1];
        }
        let mut offsets = vec![Vec::new()];
        for _ in 0..e {
            offsets = offsets
                .into_iter()
                .flat_map(|o: Vec<isize>| {
                    (-1..=1).map(move |t| {
                        let mut o = o.clone();
                        o.push(t);
                        o
                    })
                })
                .collect();
        }
        let len = shape.iter().product();
        Components { shape: shape.to_vec(), stride, offsets, prev: vec![u32::MAX; len], classes: 0, finished: 0 }
    }

    fn layer(&mut self, bits: &[u8]) {
        let (m, e) = (self.classes, self.shape.len());
        let mut uf = UnionFind::new(m + bits.len());
        let mut x = vec![0usize; e];
        for i in 0..bits.len() {
            if bits[i] != 0 {
                'offsets: for o in &self.offsets {
                    let mut j = i as isize;
                    for a in 0..e {
                        let y = x[a] as isize + o[a];
                        if y < 0 || y >= self.shape[a] as isize {
                            continue 'offsets;
                        }
                        j += o[a] * self.stride[a] as isize;
                    }
                    let j = j as usize;
                    if self.prev[j] != u32::MAX {
                        uf.union((m + i) as u32, self.prev[j]);
                    }
                    if j < i && bits[j] != 0 {
                        uf.union((m + i) as u32, (m + j) as u32);
                    }
                }
            }
            for a in 0..e {
                x[a] += 1;
                if x[a] < self.shape[a] {
                    break;
                }
                x[a] = 0;
            }
        }
        // classes of the previous layer that no cube of this one reached are finished
        let mut label = vec![u32::MAX; m + bits.len()];
        let mut reached = vec![false; m + bits.len()];
        for i in 0..bits.len() {
            if bits[i] != 0 {
                let r = uf.find((m + i) as u32) as usize;
                reached[r] = true;
            }
        }
        for c in 0..m {
            let r = uf.find(c as u32) as usize;
            if !reached[r] {
                reached[r] = true;
                self.finished += 1;
            }
        }
        let mut classes = 0u32;
        for i in 0..bits.len() {
            self.prev[i] = if bits[i] != 0 {
                let r = uf.find((m + i) as u32) as usize;
                if label[r] == u32::MAX {
                    label[r] = classes;
                    classes += 1;
                }
                label[r]
            } else {
                u32::MAX
            };
        }
        self.classes = classes as usize;
    }

    fn finish(self) -> u64 {
        self.finished + self.classes as u64
    }
}

/// The chain complex of the surviving points: the boundary restricted to them.
fn build(g: &Slabs, survivors: &[usize]) -> Result<CubicalComplex, CubicalError> {
    let d = g.grid.axes();
    let mut cells: Vec<Vec<u64>> = vec![Vec::new(); d + 1];
    let mut index: FxHashMap<usize, u32> = FxHashMap::default();
    for &p in survivors {
        let k = g.grid.dim(p);
        let i = u32::try_from(cells[k].len()).map_err(|_| CubicalError::TooLarge {
            points: format!("{} surviving {k}-cells", cells[k].len()),
            limit: u32::MAX as u64,
        })?;
        index.insert(p, i);
        cells[k].push(p as u64);
    }
    let mut boundaries = Vec::with_capacity(d);
    for k in 1..=d {
        let mut columns: Vec<Vec<(u32, i64)>> = Vec::with_capacity(cells[k].len());
        for &p in &cells[k] {
            let mut col = Vec::with_capacity(2 * k);
            g.grid.for_each_face(p as usize, |lo, up, sign| {
                // a periodic axis of one cube: the two faces are one, their entries cancel
                if lo != up {
                    if let Some(&r) = index.get(&lo) {
                        col.push((r, -sign));
                    }
                    if let Some(&r) = index.get(&up) {
                        col.push((r, sign));
                    }
                }
            });
            col.sort_unstable_by_key(|e| e.0);
            columns.push(col);
        }
        let m = SparseMatrix::try_from_columns(cells[k - 1].len(), &columns)
            .map_err(|e| CubicalError::BadShape(format!("internal: {e}")))?;
        boundaries.push(m);
    }
    let counts = cells.iter().map(Vec::len).collect();
    let chain = ChainComplex::try_new_unchecked_dd(counts, boundaries)
        .map_err(|e| CubicalError::BadShape(format!("internal: {e}")))?;
    Ok(CubicalComplex { chain, cells, grid: g.grid.points().to_vec() })
}
