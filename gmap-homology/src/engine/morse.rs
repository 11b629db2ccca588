//! Fill-free reductions: collapses and coreductions over the whole complex at once.
//!
//! ## Why they cost nothing
//!
//! Eliminating a pair `(a, b)` — `a` a (k-1)-cell, `b` a k-cell, `∂_k[a, b]` a unit — leaves
//! a complex with the same homology whose matrix `∂_k` changes by `c ↦ c - (∂[a, c] / ∂[a, b]) ∂b`
//! on the other k-cells `c` (see [`crate::engine::reduce`]). Two kinds of pairs make that update
//! vanish on the surviving cells:
//!
//! * a **collapse**: `b` is the only surviving coface of `a`, so `∂[a, c] = 0` for every other
//!   `c` (an elementary collapse through the free face `a`);
//! * a **coreduction**: `a` is the only surviving face of `b`, so `∂b` restricted to the
//!   survivors is `±a`, and `c - λ ∂b` only loses its entry in row `a`.
//!
//! Hence after any sequence of such pairs the reduced complex is simply the **restriction of
//! the original matrices to the surviving cells**: no arithmetic, no fill, only counters. The
//! pass keeps, per cell, the number of surviving faces and cofaces with a non-zero entry,
//! and a work queue of cells where either count is 1; it is O(entries) in all.
//!
//! ## How a closed complex starts
//!
//! A closed manifold has no free face and no cell with a single face. The pass therefore
//! first sets aside one vertex per connected component of the 1-skeleton: with `∂_1` made of
//! columns `v - w` (or empty), `H(X) = H(X, {v_1..v_c}) ⊕ Z^c` in degree 0, and the relative
//! complex is the restriction to the other cells. The set-aside vertices stay in the output
//! as isolated cells (each gives its `Z` in `H_0`). From there the edges at those vertices
//! become coreducible, and coreductions sweep the complex like a spanning tree in each
//! dimension in turn — Mrozek and Batko's coreduction algorithm. Waiting cells are taken
//! lowest number first (lowest dimension, then order of smallest dart), so the sweep walks
//! the arrays nearly in order. On manifolds, cube grids and the simplicial counterparts of
//! G-maps what survives is a handful of cells.
//!
//! ## Memory
//!
//! The faces of a cell are read from the input's boundary matrices. Besides them the pass
//! keeps 16 bytes per cell (its two counts, the head of its list of cofaces, its state and
//! whether it has entries in critical rows), 8 bytes per entry (the lists of cofaces,
//! threaded through the entries in one pass over the matrices), a bit per cell for the
//! waiting cells, and the log of pairs.

use std::borrow::Cow;

use gmap_core::union_find::UnionFind;
use rustc_hash::FxHashMap;

use crate::engine::chain::ChainComplex;
use crate::engine::ring::{Euclid, Ring};
use crate::engine::sparse::SparseMatrix;

/// What the sweep knows of a cell: one byte per cell.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(u8)]
enum State {
    /// not paired yet: counts among its neighbours' surviving faces and cofaces
    Alive,
    /// eliminated together with its partner (a pair of the log)
    Paired,
    /// a vertex set aside for `H_0`: survives, but takes part in no entry
    SetAside,
    /// a critical cell: survives, with the fill of later coreductions in its row
    Critical,
}

/// Cells and entries are numbered in 32 bits: a complex with more of either is handed on
/// as it is.
const LIMIT: usize = u32::MAX as usize;

/// The counts of a cell that is no longer alive: decreasing them never reaches 1 before
/// far more than a cell's neighbours are gone, so the releases need not look at the state
/// of the cell (and a wrapped count would only queue a cell that the sweep then skips).
const GONE: u32 = 1 << 31;

/// The complex left by [`prereduce`]: the surviving cells and the boundary between them.
#[derive(Debug)]
pub(crate) struct Restricted {
    /// the reduced complex (renumbered cells)
    pub chain: ChainComplex,
    /// `ids[k][j]`: the input's number of surviving k-cell `j`
    pub ids: Vec<Vec<u32>>,
    /// the pairs `(a, b)` eliminated, in order, as global cell numbers (`off[k] + j`)
    pub log: Vec<(u32, u32)>,
    /// `off[k]`: global number of the first k-cell; `off[n + 1]` the number of cells
    pub off: Vec<u32>,
}

impl Restricted {
    /// The eliminated pairs `(a, b)` per dimension of `b` (what a lifting walks over).
    pub(crate) fn pairs_per_dimension(&self) -> Vec<usize> {
        let mut n = vec![0usize; self.off.len().max(1)];
        for &(_, b) in &self.log {
            n[self.dim_of(b)] += 1;
        }
        n
    }

    /// The dimension of global cell `x`.
    fn dim_of(&self, x: u32) -> usize {
        self.off.partition_point(|&o| o <= x) - 1
    }
}

/// Collapses and coreductions to exhaustion (entries judged over `ring`: an entry that is zero
/// in the ring is no entry; only unit entries are paired). With `freeze`, a stuck pass makes
/// a cell of the lowest dimension left **critical** and goes on: the cell stays in the output
/// and the later coreductions add fill in its row only (the frozen rows of
/// [`crate::engine::reduce`]), so the output is the restriction of the input plus those rows.
/// `None` when the fill overflows.
///
/// O(entries + cells + fill in the critical rows); for the memory it touches besides the
/// input, see the module documentation.
pub(crate) fn prereduce<R: Euclid>(ring: &R, c: &ChainComplex, freeze: bool) -> Option<Restricted> {
    let counts = c.counts();
    let total: usize = counts.iter().sum();
    let nnz: usize = c.boundaries().iter().map(SparseMatrix::nnz).sum();
    if total >= LIMIT || nnz >= LIMIT {
        // beyond 32-bit numbers: hand the complex on as it is
        let ids = counts.iter().map(|&m| (0..m as u32).collect()).collect();
        return Some(Restricted { chain: c.clone(), ids, log: Vec::new(), off: Vec::new() });
    }
    let c = nonzero_part(ring, c);
    let mut sweep = Sweep::new(ring, &c, nnz);
    sweep.set_aside_base_vertices();
    sweep.queue_ready();
    sweep.run(freeze)?;
    sweep.restricted(freeze)
}

/// Collapses and coreductions of the cells that `keep(k, j)` does not name, the named ones
/// being critical from the start (never paired; they take the fill of the coreductions in
/// their rows); a stuck pass makes the lowest alive cell critical and goes on. No vertex is
/// set aside, so the output is an algebraic reduction of `c` itself: a piece of a larger
/// complex whose kept cells are the ones it shares with the other pieces reduces to a piece
/// that glues to the same homology. The kept cells must be closed under faces. `None` when
/// the fill overflows. O(entries + cells + fill in the critical rows).
pub(crate) fn prereduce_keeping<R: Euclid>(
    ring: &R,
    c: &ChainComplex,
    keep: impl Fn(usize, usize) -> bool,
) -> Option<Restricted> {
    let counts = c.counts();
    let total: usize = counts.iter().sum();
    let nnz: usize = c.boundaries().iter().map(SparseMatrix::nnz).sum();
    if total >= LIMIT || nnz >= LIMIT {
        return None;
    }
    let c = nonzero_part(ring, c);
    let mut sweep = Sweep::new(ring, &c, nnz);
    // lowest dimension first: the faces of a kept cell are kept, hence critical already
    for (k, &m) in counts.iter().enumerate() {
        for j in 0..m {
            if keep(k, j) {
                let x = sweep.off[k] + j;
                sweep.make_cell_critical(k, x);
            }
        }
    }
    sweep.queue_ready();
    sweep.run(true)?;
    sweep.restricted(true)
}

/// `c` without its entries that are zero in `ring` (`c` itself when it has none, always the
/// case over `Z`). O(entries).
fn nonzero_part<'c, R: Ring>(ring: &R, c: &'c ChainComplex) -> Cow<'c, ChainComplex> {
    let zero = |v: i64| ring.is_zero(&ring.of_i64(v));
    let has_zero = |m: &SparseMatrix| (0..m.cols()).any(|j| m.col(j).1.iter().any(|&v| zero(v)));
    if ring.keeps_nonzero_integers() || !c.boundaries().iter().any(has_zero) {
        return Cow::Borrowed(c);
    }
    let mats = c
        .boundaries()
        .iter()
        .map(|m| {
            let cols: Vec<Vec<(u32, i64)>> = (0..m.cols())
                .map(|j| {
                    let (ri, rv) = m.col(j);
                    ri.iter().zip(rv).filter(|&(_, &v)| !zero(v)).map(|(&r, &v)| (r, v)).collect()
                })
                .collect();
            SparseMatrix::try_from_columns(m.rows(), &cols).expect("the entries of a valid matrix stay valid")
        })
        .collect();
    Cow::Owned(ChainComplex::try_new_unchecked_dd(c.counts().to_vec(), mats).expect("the shapes are kept"))
}

/// Global cell numbers: `off[k]` is the number of the first k-cell, `off[n + 1]` the number
/// of cells.
fn offsets(counts: &[usize]) -> Vec<usize> {
    let mut off = Vec::with_capacity(counts.len() + 1);
    let mut acc = 0;
    for &m in counts {
        off.push(acc);
        acc += m;
    }
    off.push(acc);
    off
}

/// The cofaces of every cell, as a list per cell threaded through the entries of the
/// boundary matrices: one pass over the matrices builds it (a transposed copy would take a
/// counting pass more), and the lists hold the numbers of the cofaces among the cells of the
/// dimension above, decreasing. (The faces are read from the boundary matrices themselves.)
struct Cofaces {
    /// per entry, in the matrices' order: the next entry of the same face (or [`END`]) and
    /// the coface's number
    node: Vec<(u32, u32)>,
}

/// The end of a list of cofaces.
const END: u32 = u32::MAX;

impl Cofaces {
    /// The lists, their heads and the number of cofaces written into `cells` (which start
    /// with no coface). O(entries + cells).
    fn new(c: &ChainComplex, off: &[usize], nnz: usize, cells: &mut [Cell]) -> Self {
        let mut node = vec![(END, 0u32); nnz];
        let mut e = 0usize;
        for (m, &base) in c.boundaries().iter().zip(off) {
            let faces = &mut cells[base..base + m.rows()];
            for j in 0..m.cols() {
                for &r in m.col(j).0 {
                    let face = &mut faces[r as usize];
                    node[e] = (face.head, j as u32);
                    face.head = e as u32;
                    face.nc += 1;
                    e += 1;
                }
            }
        }
        Cofaces { node }
    }

    /// The cofaces of a cell whose list starts at `head`, numbered among the cells of the
    /// dimension above.
    #[inline(always)]
    fn of(&self, head: u32) -> Walk<'_> {
        Walk { node: &self.node, at: head }
    }
}

/// What the sweep keeps of a cell: its numbers of surviving faces (`nb`) and cofaces (`nc`),
/// the head of its list of cofaces in [`Cofaces`], its state, and whether it has entries in
/// the critical rows (so that most pairs look up no critical row at all).
#[derive(Clone, Copy)]
struct Cell {
    nb: u32,
    nc: u32,
    head: u32,
    state: State,
    filled: bool,
}

/// The cofaces of one cell ([`Cofaces::of`]).
struct Walk<'a> {
    node: &'a [(u32, u32)],
    at: u32,
}

impl Iterator for Walk<'_> {
    type Item = u32;

    #[inline(always)]
    fn next(&mut self) -> Option<u32> {
        let &(next, y) = self.node.get(self.at as usize)?;
        self.at = next;
        Some(y)
    }
}

/// The pass in progress: per cell its state and its numbers of surviving faces (`nb`) and
/// cofaces (`nc`), the cells waiting to be looked at, the pairs eliminated so far, and the
/// entries of the critical rows. Cells are named by global number (`off[k] + j`) in the
/// per-cell arrays, the log and the critical rows, and by dimension and number `(k, j)`
/// everywhere else.
struct Sweep<'a, R: Euclid> {
    ring: &'a R,
    c: &'a ChainComplex,
    off: Vec<usize>,
    co: Cofaces,
    cells: Vec<Cell>,
    /// entries of alive or critical cells in critical rows: (row, value), rows increasing
    extra: FxHashMap<u32, Vec<(u32, R::E)>>,
    /// a buffer for the updates of the critical rows
    scratch: Vec<(u32, R::E)>,
    log: Vec<(u32, u32)>,
    /// lowest cell number first: the sweep then moves through the complex in numbering
    /// order, which keeps its memory accesses close together (a stack gets stuck far
    /// earlier on closed manifolds)
    work: Ready,
    /// per dimension, the first cell that may still be alive (critical cells are taken in order)
    cursor: Vec<usize>,
    /// the cells set aside or made critical (global numbers): with `freeze`, the survivors
    kept: Vec<u32>,
}

impl<'a, R: Euclid> Sweep<'a, R> {
    fn new(ring: &'a R, c: &'a ChainComplex, nnz: usize) -> Self {
        let off = offsets(c.counts());
        let total = off[off.len() - 1];
        let mut cells = Vec::with_capacity(total);
        let fresh = |nb: usize| Cell { nb: nb as u32, nc: 0, head: END, state: State::Alive, filled: false };
        cells.resize(c.count(0), fresh(0));
        for m in c.boundaries() {
            cells.extend(m.col_ptr().windows(2).map(|w| fresh(w[1] - w[0])));
        }
        let co = Cofaces::new(c, &off, nnz, &mut cells);
        let work = Ready::new(c.counts());
        let cursor = off[..c.counts().len()].to_vec();
        Sweep {
            ring,
            c,
            off,
            co,
            cells,
            extra: FxHashMap::default(),
            scratch: Vec::new(),
            log: Vec::with_capacity(total / 2),
            work,
            cursor,
            kept: Vec::new(),
        }
    }

    /// `∂_k`, for `k >= 1`.
    #[inline]
    fn bd(&self, k: usize) -> &'a SparseMatrix {
        &self.c.boundaries()[k - 1]
    }

    /// `⟨∂x, y⟩` from the input, for k-cell `x` and (k-1)-cell `y`.
    fn value(&self, k: usize, x: u32, y: u32) -> R::E {
        self.ring.of_i64(self.bd(k).get(y as usize, x as usize))
    }

    /// When `∂_1` is made of `v - w` columns, sets aside the smallest vertex of each
    /// component of the 1-skeleton: `H(X) = H(X, {v_1..v_c}) ⊕ Z^c` in degree 0, and the
    /// relative complex is the restriction to the other cells.
    ///
    /// When every vertex but the first has an edge to a smaller one, the 1-skeleton is
    /// connected (each vertex reaches vertex 0 through smaller ones) and vertex 0 is the
    /// only one set aside; otherwise a union-find of the edges finds the components.
    fn set_aside_base_vertices(&mut self) {
        let c = self.c;
        if c.counts().len() < 2 {
            return;
        }
        let nv = c.count(0);
        let m = c.boundary(1);
        let mut smaller_neighbour = vec![false; nv];
        for j in 0..m.cols() {
            match m.col(j) {
                // rows increase: `v < w`
                (&[_, w], &[x, y]) if x.unsigned_abs() == 1 && y == -x => smaller_neighbour[w as usize] = true,
                (&[], _) => {}
                // an edge that is not `v - w`: no vertex is set aside
                _ => return,
            }
        }
        let roots: Vec<u32> = if smaller_neighbour.iter().skip(1).all(|&s| s) {
            (0..nv.min(1) as u32).collect()
        } else {
            let mut uf = UnionFind::new(nv);
            for j in 0..m.cols() {
                if let (&[v, w], _) = m.col(j) {
                    uf.union(v, w);
                }
            }
            (0..nv as u32).filter(|&v| uf.find(v) == v).collect()
        };
        let edges = self.off[1];
        for v in roots {
            let head = self.cells[v as usize].head;
            self.leave(v as usize, State::SetAside);
            self.kept.push(v);
            for e in self.co.of(head) {
                self.cells[edges + e as usize].nb -= 1;
            }
        }
    }

    /// Global cell `x` is no longer alive: it takes `state` and its counts are [`GONE`].
    #[inline(always)]
    fn leave(&mut self, x: usize, state: State) {
        let cell = &mut self.cells[x];
        cell.state = state;
        cell.nb = GONE;
        cell.nc = GONE;
    }

    /// Queues every alive cell with a single surviving face or coface.
    fn queue_ready(&mut self) {
        for k in 0..self.c.counts().len() {
            for (j, cell) in self.cells[self.off[k]..self.off[k + 1]].iter().enumerate() {
                // only the set-aside vertices are not alive, and their counts are GONE
                if cell.nb == 1 || cell.nc == 1 {
                    self.work.push(k, j as u32);
                }
            }
        }
    }

    /// Pairs cells until none is ready; with `freeze`, makes a cell critical each time it is
    /// stuck and goes on until every cell is paired, set aside or critical. `None` when the
    /// fill of the critical rows overflows.
    fn run(&mut self, freeze: bool) -> Option<()> {
        loop {
            let Some((k, j, x)) = self.work.pop() else {
                if freeze && self.make_critical() {
                    continue;
                }
                return Some(());
            };
            let cell = self.cells[x];
            if cell.state != State::Alive {
                continue;
            }
            if let Some((k, a, b, coreduction)) = self.pair_of(k, j, cell) {
                self.eliminate(k, a, b, coreduction)?;
            }
        }
    }

    /// Makes the first alive cell of the lowest dimension critical; `false` when no cell is
    /// alive. The cell has no alive face, so only its cofaces change: their entries in its
    /// row move to the critical rows.
    fn make_critical(&mut self) -> bool {
        let mut pick = None;
        for k in 0..self.cursor.len() {
            let end = self.off[k + 1];
            while self.cursor[k] < end && self.cells[self.cursor[k]].state != State::Alive {
                self.cursor[k] += 1;
            }
            if self.cursor[k] < end {
                pick = Some((k, self.cursor[k]));
                break;
            }
        }
        let Some((k, x)) = pick else { return false };
        self.make_cell_critical(k, x);
        true
    }

    /// Makes alive cell `x` (global number, of dimension `k`) critical. Its faces must be
    /// paired, set aside or critical already; its alive cofaces take its entries into their
    /// critical rows.
    fn make_cell_critical(&mut self, k: usize, x: usize) {
        let mut at = self.cells[x].head;
        self.leave(x, State::Critical);
        self.kept.push(x as u32);
        let j = (x - self.off[k]) as u32;
        let above = self.off[k + 1];
        while let Some(&(next, y)) = self.co.node.get(at as usize) {
            at = next;
            let gy = above + y as usize;
            if self.cells[gy].state == State::Alive {
                let v = self.value(k + 1, y, j);
                let list = self.extra.entry(gy as u32).or_default();
                let pos = list.partition_point(|(r, _)| (*r as usize) < x);
                list.insert(pos, (x as u32, v));
                let coface = &mut self.cells[gy];
                coface.filled = true;
                coface.nb -= 1;
                if coface.nb == 1 {
                    self.work.push(k + 1, y);
                }
            }
        }
    }

    /// The pair `(k, a, b, coreduction)` — `a` a (k-1)-cell, `b` a k-cell — that alive
    /// cell `j` of dimension `k0` makes: with its only surviving face (a coreduction) or its
    /// only surviving coface (a collapse), through a unit entry.
    fn pair_of(&self, k0: usize, j: u32, cell: Cell) -> Option<(usize, u32, u32, bool)> {
        if cell.nb == 1 {
            // a cell with a face is of dimension 1 or more
            let base = self.off[k0 - 1];
            let (ri, rv) = self.bd(k0).col(j as usize);
            if let Some(p) = ri.iter().position(|&r| self.cells[base + r as usize].state == State::Alive) {
                if self.ring.is_unit(&self.ring.of_i64(rv[p])) {
                    return Some((k0, ri[p], j, true));
                }
            }
        }
        if cell.nc == 1 {
            let base = self.off[k0 + 1];
            if let Some(y) = self.co.of(cell.head).find(|&y| self.cells[base + y as usize].state == State::Alive) {
                if self.ring.is_unit(&self.value(k0 + 1, y, j)) {
                    return Some((k0 + 1, j, y, false));
                }
            }
        }
        None
    }

    /// Eliminates the pair of (k-1)-cell `a` and k-cell `b`: logs it, moves the
    /// critical-row entries of `b` onto the other cofaces of `a` after a coreduction (a
    /// collapse changes no other column), and updates the counts of the neighbours. `None`
    /// when the fill overflows.
    fn eliminate(&mut self, k: usize, a: u32, b: u32, coreduction: bool) -> Option<()> {
        let ga = self.off[k - 1] + a as usize;
        let gb = self.off[k] + b as usize;
        let (head_a, filled_a) = (self.cells[ga].head, self.cells[ga].filled);
        let (head_b, filled_b) = (self.cells[gb].head, self.cells[gb].filled);
        self.leave(ga, State::Paired);
        self.leave(gb, State::Paired);
        self.log.push((ga as u32, gb as u32));
        if filled_a {
            self.extra.remove(&(ga as u32));
        }
        if filled_b {
            if let Some(fill) = self.extra.remove(&(gb as u32)) {
                if coreduction {
                    self.move_fill(k, a, b, head_a, &fill)?;
                }
            }
        }
        // the neighbours of the pair lose it; the other faces of `b` after a coreduction,
        // and the other cofaces of `a` after a collapse, are not alive
        if coreduction {
            self.release_cofaces(k, head_a);
        } else {
            self.release_faces(k, b);
        }
        if k >= 2 {
            self.release_faces(k - 1, a);
        }
        self.release_cofaces(k + 1, head_b);
        Some(())
    }

    /// After the coreduction of (k-1)-cell `a` with k-cell `b`, whose critical rows hold
    /// `fill`: each other alive coface `y` of `a` (whose list of cofaces starts at `head`)
    /// becomes `y - (⟨∂y, a⟩ / ⟨∂b, a⟩) b` in those rows. `None` on overflow.
    fn move_fill(&mut self, k: usize, a: u32, b: u32, head: u32, fill: &[(u32, R::E)]) -> Option<()> {
        let eps = self.value(k, b, a);
        let base = self.off[k];
        let mut at = head;
        while let Some(&(next, y)) = self.co.node.get(at as usize) {
            at = next;
            let gy = (base + y as usize) as u32;
            if self.cells[gy as usize].state != State::Alive {
                continue;
            }
            let lambda = self.ring.div_unit(&self.value(k, y, a), &eps)?;
            let list = self.extra.entry(gy).or_default();
            axpy(self.ring, list, &lambda, fill, &mut self.scratch)?;
            // the updated row takes the buffer, and the old row becomes the buffer
            std::mem::swap(list, &mut self.scratch);
            let empty = list.is_empty();
            if empty {
                self.extra.remove(&gy);
            }
            self.cells[gy as usize].filled = !empty;
        }
        Some(())
    }

    /// A cell whose cofaces, of dimension `k`, are listed from `head` leaves: its alive
    /// cofaces lose a face; those left with one are queued.
    #[inline(always)]
    fn release_cofaces(&mut self, k: usize, head: u32) {
        let Sweep { off, co, cells, work, .. } = self;
        lose_one(co.of(head), k, off[k], cells, |c| &mut c.nb, work);
    }

    /// k-cell `z` (k >= 1) leaves: its alive faces lose a coface; those left with one are
    /// queued.
    #[inline(always)]
    fn release_faces(&mut self, k: usize, z: u32) {
        let Sweep { c, off, cells, work, .. } = self;
        let faces = c.boundaries()[k - 1].col(z as usize).0;
        lose_one(faces.iter().copied(), k - 1, off[k - 1], cells, |c| &mut c.nc, work);
    }

    /// The survivors: the input restricted to alive rows, plus the entries of the critical
    /// rows. With `freeze` the survivors are the cells set aside or made critical, and the
    /// cost is in their number and their entries only. `None` when an entry of a critical
    /// row does not fit `i64`.
    fn restricted(self, freeze: bool) -> Option<Restricted> {
        let Sweep { ring, c, off, mut cells, extra, log, mut kept, .. } = self;
        let counts = c.counts();
        let n1 = counts.len();
        let mut ids: Vec<Vec<u32>> = vec![Vec::new(); n1];
        if freeze {
            // no cell is left alive
            kept.sort_unstable();
            let mut k = 0;
            for &g in &kept {
                while g as usize >= off[k + 1] {
                    k += 1;
                }
                ids[k].push((g as usize - off[k]) as u32);
            }
        } else {
            for (k, v) in ids.iter_mut().enumerate() {
                v.extend((0..counts[k] as u32).filter(|&j| cells[off[k] + j as usize].state != State::Paired));
            }
        }
        // the number of a survivor among the survivors of its dimension, in the place of
        // its count of faces (no longer needed)
        for (k, v) in ids.iter().enumerate() {
            for (i, &j) in v.iter().enumerate() {
                cells[off[k] + j as usize].nb = i as u32;
            }
        }
        let mut mats = Vec::with_capacity(n1.saturating_sub(1));
        let mut col: Vec<(u32, i64)> = Vec::new();
        for k in 1..n1 {
            let m = c.boundary(k);
            let mut col_ptr = Vec::with_capacity(ids[k].len() + 1);
            col_ptr.push(0usize);
            let mut rows = Vec::new();
            let mut vals = Vec::new();
            for &j in &ids[k] {
                col.clear();
                if !freeze {
                    let (ri, rv) = m.col(j as usize);
                    for (&r, &v) in ri.iter().zip(rv) {
                        let g = off[k - 1] + r as usize;
                        if cells[g].state == State::Alive {
                            col.push((cells[g].nb, v));
                        }
                    }
                }
                if let Some(list) = extra.get(&((off[k] + j as usize) as u32)) {
                    for (r, v) in list {
                        col.push((cells[*r as usize].nb, ring.to_i64(v)?));
                    }
                    col.sort_unstable_by_key(|e| e.0);
                }
                for &(r, v) in &col {
                    rows.push(r);
                    vals.push(v);
                }
                col_ptr.push(rows.len());
            }
            let sm = SparseMatrix::try_from_csc(ids[k - 1].len(), ids[k].len(), col_ptr, rows, vals)
                .expect("survivors keep rows sorted and in range");
            mats.push(sm);
        }
        let new_counts = ids.iter().map(Vec::len).collect();
        let chain = ChainComplex::try_new_unchecked_dd(new_counts, mats).expect("shapes follow the survivors");
        let off = off.iter().map(|&o| o as u32).collect();
        Some(Restricted { chain, ids, log, off })
    }
}

/// Each cell among `linked` (cells `j` of dimension `k`, global numbers `base + j`) has one
/// neighbour less in its `count` (`nb` or `nc`); those left with one are queued. The counts
/// of cells no longer alive start at [`GONE`], so they are never queued.
#[inline(always)]
fn lose_one(
    linked: impl Iterator<Item = u32>,
    k: usize,
    base: usize,
    cells: &mut [Cell],
    count: impl Fn(&mut Cell) -> &mut u32,
    work: &mut Ready,
) {
    for j in linked {
        let n = count(&mut cells[base + j as usize]);
        *n = n.wrapping_sub(1);
        if *n == 1 {
            work.push(k, j);
        }
    }
}

/// The cells waiting to be looked at, taken lowest number first (lowest dimension, then
/// order of smallest dart): per dimension a bit per cell, a count, and the first word that
/// may hold a bit; and the lowest dimension that may hold one. Taking cells in numbering
/// order keeps the sweep's memory accesses close together.
///
/// A push below a dimension's cursor moves the cursor back, so the next pops may have to
/// step over many empty words again; a second level (a bit per word of `bits`, set while
/// that word holds a bit) makes each such step cover 64 words, so a pop costs
/// O(1 + gap / 4096) words read, where gap is the number of cells between the cursor and the
/// cell found. Push is O(1).
struct Ready {
    /// a bit per cell; each dimension starts a new word
    bits: Vec<u64>,
    /// a bit per word of `bits`: set exactly when that word is not zero
    words: Vec<u64>,
    /// per dimension: where its bits are, and how many are set
    dims: Vec<Queue>,
    /// no dimension below it holds a bit
    low: usize,
}

/// The bits of one dimension in [`Ready`].
#[derive(Clone, Copy)]
struct Queue {
    /// the first word
    lo: usize,
    /// the first word that may hold a bit
    cursor: usize,
    /// the number of bits set
    count: u32,
    /// the global number of the first cell
    start: usize,
}

impl Ready {
    fn new(counts: &[usize]) -> Self {
        let mut dims = Vec::with_capacity(counts.len());
        let (mut words, mut start) = (0, 0);
        for &m in counts {
            dims.push(Queue { lo: words, cursor: words, count: 0, start });
            words += m.div_ceil(64);
            start += m;
        }
        Ready { bits: vec![0; words], words: vec![0; words.div_ceil(64)], dims, low: counts.len() }
    }

    /// Queues cell `j` of dimension `k` (once, however often it is pushed before it is popped).
    #[inline(always)]
    fn push(&mut self, k: usize, j: u32) {
        let q = &mut self.dims[k];
        let w = q.lo + j as usize / 64;
        let b = 1u64 << (j % 64);
        let word = &mut self.bits[w];
        if *word & b == 0 {
            if *word == 0 {
                self.words[w / 64] |= 1u64 << (w % 64);
            }
            *word |= b;
            q.count += 1;
            q.cursor = q.cursor.min(w);
            self.low = self.low.min(k);
        }
    }

    /// The first word at or after `from` that holds a bit.
    #[inline(always)]
    fn next_word(&self, from: usize) -> Option<usize> {
        let s = from / 64;
        let here = *self.words.get(s)? & (!0u64 << (from % 64));
        if here != 0 {
            return Some(s * 64 + here.trailing_zeros() as usize);
        }
        let t = s + 1 + self.words[s + 1..].iter().position(|&x| x != 0)?;
        Some(t * 64 + self.words[t].trailing_zeros() as usize)
    }

    /// The waiting cell of the lowest dimension and, in it, the lowest number, as `(k, j,
    /// global number)`.
    #[inline(always)]
    fn pop(&mut self) -> Option<(usize, u32, usize)> {
        while self.dims.get(self.low)?.count == 0 {
            self.low += 1;
        }
        let k = self.low;
        // a set bit lies at or after the cursor, as the count says, and the first one lies
        // in this dimension's words (the next dimension's words come after them)
        let w = self.next_word(self.dims[k].cursor)?;
        let q = &mut self.dims[k];
        q.cursor = w;
        let word = &mut self.bits[w];
        let b = word.trailing_zeros();
        *word &= *word - 1;
        if *word == 0 {
            self.words[w / 64] &= !(1u64 << (w % 64));
        }
        q.count -= 1;
        let j = ((w - q.lo) * 64) as u32 + b;
        Some((k, j, q.start + j as usize))
    }
}

/// `out = list - lambda * fill` for sorted sparse rows; zeros dropped.
fn axpy<R: Ring>(
    ring: &R,
    list: &[(u32, R::E)],
    lambda: &R::E,
    fill: &[(u32, R::E)],
    out: &mut Vec<(u32, R::E)>,
) -> Option<()> {
    let zero = ring.of_i64(0);
    out.clear();
    out.reserve(list.len() + fill.len());
    let (mut i, mut j) = (0, 0);
    while i < list.len() || j < fill.len() {
        if j == fill.len() || (i < list.len() && list[i].0 < fill[j].0) {
            out.push(list[i].clone());
            i += 1;
        } else if i == list.len() || fill[j].0 < list[i].0 {
            let v = ring.sub_mul(&zero, lambda, &fill[j].1)?;
            if !ring.is_zero(&v) {
                out.push((fill[j].0, v));
            }
            j += 1;
        } else {
            let v = ring.sub_mul(&list[i].1, lambda, &fill[j].1)?;
            if !ring.is_zero(&v) {
                out.push((list[i].0, v));
            }
            i += 1;
            j += 1;
        }
    }
    Some(())
}

/// Lifts a k-chain of the reduced complex (numbered as in `pre.chain`) to a k-chain of the
/// input `c` through the eliminated pairs, last first: each pair `(a, b)` with `b` a k-cell
/// subtracts `(⟨∂z, a⟩ / ⟨∂b, a⟩) b`, which is the chain map of the reduction. A cycle lifts
/// to a cycle in the same homology class. `pairs_k` is the number of pairs with `b` a k-cell
/// ([`Restricted::pairs_per_dimension`]): with none the chain is its own lift. `None` on
/// overflow. O(log length + entries of the k-cells met), O(chain) without pairs.
pub(crate) fn lift<R: Ring>(
    ring: &R,
    c: &ChainComplex,
    pre: &Restricted,
    k: usize,
    pairs_k: usize,
    chain: &[(u32, R::E)],
) -> Option<Vec<(u32, R::E)>> {
    if k == 0 || pairs_k == 0 {
        // no pair to walk back over: the cells themselves, in increasing order
        let mut z: Vec<(u32, R::E)> = chain.iter().map(|(j, v)| (pre.ids[k][*j as usize], v.clone())).collect();
        z.sort_unstable_by_key(|x| x.0);
        z.retain(|x| !ring.is_zero(&x.1));
        return Some(z);
    }
    let zero = ring.of_i64(0);
    let mut z: Vec<R::E> = vec![zero.clone(); c.count(k)];
    for (j, v) in chain {
        z[pre.ids[k][*j as usize] as usize] = v.clone();
    }
    if pre.log.is_empty() {
        return Some(z.into_iter().enumerate().filter(|(_, v)| !ring.is_zero(v)).map(|(i, v)| (i as u32, v)).collect());
    }
    let m = c.boundary(k);
    let mut bd: Vec<R::E> = vec![zero.clone(); c.count(k - 1)];
    for (j, v) in z.iter().enumerate() {
        if ring.is_zero(v) {
            continue;
        }
        let (ri, rv) = m.col(j);
        for (&r, &x) in ri.iter().zip(rv) {
            bd[r as usize] = ring.sub_mul(&bd[r as usize], &ring.of_i64(-x), v)?;
        }
    }
    let (ok, lo) = (pre.off[k], pre.off[k - 1]);
    for &(a, b) in pre.log.iter().rev() {
        if pre.dim_of(b) != k {
            continue;
        }
        let (a, b) = ((a - lo) as usize, (b - ok) as usize);
        if ring.is_zero(&bd[a]) {
            continue;
        }
        let eps = match m.get(a, b) {
            0 => return None,
            e => ring.of_i64(e),
        };
        let (ri, rv) = m.col(b);
        let lambda = ring.div_unit(&bd[a], &eps)?;
        z[b] = ring.sub_mul(&z[b], &lambda, &ring.of_i64(1))?;
        for (&r, &x) in ri.iter().zip(rv) {
            bd[r as usize] = ring.sub_mul(&bd[r as usize], &lambda, &ring.of_i64(x))?;
        }
    }
    Some(z.into_iter().enumerate().filter(|(_, v)| !ring.is_zero(v)).map(|(i, v)| (i as u32, v)).collect())
}

#[cfg(test)]
mod tests;
