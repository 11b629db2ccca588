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

use std::collections::HashMap;

use gmap_core::union_find::UnionFind;

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

/// bit 31 of a link: the entry is a unit
const UNIT: u32 = 1 << 31;
/// cells and entries are numbered in 31 bits
const LIMIT: usize = 1 << 31;

/// The cell of a link (its global number, without the [`UNIT`] bit).
#[inline]
fn cell(link: u32) -> usize {
    (link & !UNIT) as usize
}

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
/// `None` when the fill overflows. O(entries + cells + fill in the critical rows).
pub(crate) fn prereduce<R: Euclid>(ring: &R, c: &ChainComplex, freeze: bool) -> Option<Restricted> {
    let counts = c.counts();
    let total: usize = counts.iter().sum();
    let nnz: usize = (1..counts.len()).map(|k| c.boundary(k).nnz()).sum();
    if total >= LIMIT || nnz >= LIMIT {
        // beyond 31-bit numbers: hand the complex on as it is
        let ids = counts.iter().map(|&m| (0..m as u32).collect()).collect();
        return Some(Restricted { chain: c.clone(), ids, log: Vec::new(), off: Vec::new() });
    }
    let mut sweep = Sweep::new(ring, c, Links::new(ring, c, nnz));
    sweep.set_aside_base_vertices();
    sweep.queue_ready();
    sweep.run(freeze)?;
    sweep.restricted()
}

/// Global cell numbers: `off[k]` is the number of the first k-cell, `off[n + 1]` the number
/// of cells.
fn offsets(counts: &[usize]) -> Vec<u32> {
    let mut off = Vec::with_capacity(counts.len() + 1);
    let mut acc = 0u32;
    for &m in counts {
        off.push(acc);
        acc += m as u32;
    }
    off.push(acc);
    off
}

/// The faces and cofaces of every cell through its ring-nonzero entries, as links (global
/// cell numbers, [`UNIT`] set for a unit entry): the boundary in compressed rows per cell,
/// and its transpose.
struct Links {
    /// `off[k]`: global number of the first k-cell
    off: Vec<u32>,
    fptr: Vec<u32>,
    faces: Vec<u32>,
    cptr: Vec<u32>,
    cofaces: Vec<u32>,
}

impl Links {
    fn new<R: Euclid>(ring: &R, c: &ChainComplex, nnz: usize) -> Self {
        let counts = c.counts();
        let off = offsets(counts);
        let total = off[counts.len()] as usize;
        let mut fptr: Vec<u32> = Vec::with_capacity(total + 1);
        let mut faces: Vec<u32> = Vec::with_capacity(nnz);
        fptr.extend(std::iter::repeat_n(0, counts.first().copied().unwrap_or(0) + 1));
        for k in 1..counts.len() {
            let m = c.boundary(k);
            let base = off[k - 1];
            for j in 0..m.cols() {
                let (ri, rv) = m.col(j);
                for (&r, &v) in ri.iter().zip(rv) {
                    let x = ring.of_i64(v);
                    if !ring.is_zero(&x) {
                        faces.push((base + r) | if ring.is_unit(&x) { UNIT } else { 0 });
                    }
                }
                fptr.push(faces.len() as u32);
            }
        }
        let mut cptr = vec![0u32; total + 1];
        for &r in &faces {
            cptr[cell(r) + 1] += 1;
        }
        for i in 0..total {
            cptr[i + 1] += cptr[i];
        }
        let mut cofaces = vec![0u32; faces.len()];
        let mut fill = cptr.clone();
        for col in 0..total {
            for &r in &faces[fptr[col] as usize..fptr[col + 1] as usize] {
                let slot = &mut fill[cell(r)];
                cofaces[*slot as usize] = col as u32 | (r & UNIT);
                *slot += 1;
            }
        }
        Links { off, fptr, faces, cptr, cofaces }
    }

    fn total(&self) -> usize {
        self.fptr.len() - 1
    }

    #[inline]
    fn faces(&self, x: usize) -> &[u32] {
        &self.faces[self.fptr[x] as usize..self.fptr[x + 1] as usize]
    }

    #[inline]
    fn cofaces(&self, x: usize) -> &[u32] {
        &self.cofaces[self.cptr[x] as usize..self.cptr[x + 1] as usize]
    }
}

/// The pass in progress: per cell its state and its numbers of surviving faces (`nb`) and
/// cofaces (`nc`), the cells waiting to be looked at, the pairs eliminated so far, and the
/// entries of the critical rows.
struct Sweep<'a, R: Euclid> {
    ring: &'a R,
    c: &'a ChainComplex,
    links: Links,
    state: Vec<State>,
    nb: Vec<u32>,
    nc: Vec<u32>,
    /// entries of alive or critical cells in critical rows: (row, value), rows increasing
    extra: HashMap<u32, Vec<(u32, R::E)>>,
    log: Vec<(u32, u32)>,
    /// lowest cell number first: the sweep then moves through the complex in numbering
    /// order, which keeps its memory accesses close together (a stack gets stuck far
    /// earlier on closed manifolds)
    work: Ready,
    /// per dimension, the first cell that may still be alive (critical cells are taken in order)
    cursor: Vec<usize>,
}

impl<'a, R: Euclid> Sweep<'a, R> {
    fn new(ring: &'a R, c: &'a ChainComplex, links: Links) -> Self {
        let total = links.total();
        let nb = links.fptr.windows(2).map(|w| w[1] - w[0]).collect();
        let nc = links.cptr.windows(2).map(|w| w[1] - w[0]).collect();
        let work = Ready::new(&links.off);
        let cursor = links.off[..c.counts().len()].iter().map(|&o| o as usize).collect();
        Sweep {
            ring,
            c,
            links,
            state: vec![State::Alive; total],
            nb,
            nc,
            extra: HashMap::new(),
            log: Vec::with_capacity(total / 2),
            work,
            cursor,
        }
    }

    /// `⟨∂x, y⟩` from the input, for a k-cell `x` and a (k-1)-cell `y` (global numbers).
    fn value(&self, x: usize, y: usize) -> R::E {
        let off = &self.links.off;
        let k = off.partition_point(|&o| o as usize <= x) - 1;
        self.ring.of_i64(self.c.boundary(k).get(y - off[k - 1] as usize, x - off[k] as usize))
    }

    /// When `∂_1` is made of `v - w` columns, sets aside the smallest vertex of each
    /// component of the 1-skeleton: `H(X) = H(X, {v_1..v_c}) ⊕ Z^c` in degree 0, and the
    /// relative complex is the restriction to the other cells.
    fn set_aside_base_vertices(&mut self) {
        let c = self.c;
        if c.counts().len() < 2 || !edges_are_differences(c.boundary(1)) {
            return;
        }
        let nv = c.count(0);
        let mut uf = UnionFind::new(nv);
        let m = c.boundary(1);
        for j in 0..m.cols() {
            let (ri, _) = m.col(j);
            if ri.len() == 2 {
                uf.union(ri[0], ri[1]);
            }
        }
        for v in 0..nv as u32 {
            if uf.find(v) == v {
                self.state[v as usize] = State::SetAside;
                for &e in self.links.cofaces(v as usize) {
                    self.nb[cell(e)] -= 1;
                }
            }
        }
    }

    /// Queues every alive cell with a single surviving face or coface.
    fn queue_ready(&mut self) {
        for x in 0..self.state.len() {
            if self.state[x] == State::Alive && (self.nb[x] == 1 || self.nc[x] == 1) {
                self.work.push(x as u32);
            }
        }
    }

    /// Pairs cells until none is ready; with `freeze`, makes a cell critical each time it is
    /// stuck and goes on until every cell is paired, set aside or critical. `None` when the
    /// fill of the critical rows overflows.
    fn run(&mut self, freeze: bool) -> Option<()> {
        loop {
            let Some(x) = self.work.pop() else {
                if freeze && self.make_critical() {
                    continue;
                }
                return Some(());
            };
            let x = x as usize;
            if self.state[x] != State::Alive {
                continue;
            }
            if let Some((a, b, coreduction)) = self.pair_of(x) {
                self.eliminate(a, b, coreduction)?;
            }
        }
    }

    /// Makes the first alive cell of the lowest dimension critical; `false` when no cell is
    /// alive. The cell has no alive face, so only its cofaces change: their entries in its
    /// row move to the critical rows.
    fn make_critical(&mut self) -> bool {
        let off = &self.links.off;
        let mut pick = None;
        for k in 0..self.cursor.len() {
            let end = off[k + 1] as usize;
            while self.cursor[k] < end && self.state[self.cursor[k]] != State::Alive {
                self.cursor[k] += 1;
            }
            if self.cursor[k] < end {
                pick = Some(self.cursor[k]);
                break;
            }
        }
        let Some(x) = pick else { return false };
        self.state[x] = State::Critical;
        for &e in self.links.cofaces(x) {
            let y = cell(e);
            if self.state[y] == State::Alive {
                let v = self.value(y, x);
                let list = self.extra.entry(y as u32).or_default();
                let pos = list.partition_point(|(r, _)| (*r as usize) < x);
                list.insert(pos, (x as u32, v));
                self.nb[y] -= 1;
                if self.nb[y] == 1 {
                    self.work.push(y as u32);
                }
            }
        }
        true
    }

    /// The pair `(a, b, coreduction)` that alive cell `x` makes: with its only surviving face
    /// (a coreduction) or its only surviving coface (a collapse), through a unit entry.
    fn pair_of(&self, x: usize) -> Option<(usize, usize, bool)> {
        let alive = |e: &&u32| self.state[cell(**e)] == State::Alive;
        if self.nb[x] == 1 {
            if let Some(&e) = self.links.faces(x).iter().find(alive) {
                if e & UNIT != 0 {
                    return Some((cell(e), x, true));
                }
            }
        }
        if self.nc[x] == 1 {
            if let Some(&e) = self.links.cofaces(x).iter().find(alive) {
                if e & UNIT != 0 {
                    return Some((x, cell(e), false));
                }
            }
        }
        None
    }

    /// Eliminates the pair `(a, b)`: logs it, moves the critical-row entries of `b` onto the
    /// other cofaces of `a` after a coreduction (a collapse changes no other column), and
    /// updates the counts of the neighbours. `None` when the fill overflows.
    fn eliminate(&mut self, a: usize, b: usize, coreduction: bool) -> Option<()> {
        self.state[a] = State::Paired;
        self.state[b] = State::Paired;
        self.log.push((a as u32, b as u32));
        self.extra.remove(&(a as u32));
        if let Some(fill) = self.extra.remove(&(b as u32)) {
            if coreduction {
                let eps = self.value(b, a);
                for &e in self.links.cofaces(a) {
                    let y = cell(e);
                    if self.state[y] != State::Alive {
                        continue;
                    }
                    let lambda = self.ring.div_unit(&self.value(y, a), &eps)?;
                    let list = self.extra.entry(y as u32).or_default();
                    *list = axpy(self.ring, list, &lambda, &fill)?;
                    if list.is_empty() {
                        self.extra.remove(&(y as u32));
                    }
                }
            }
        }
        self.release(a);
        self.release(b);
        Some(())
    }

    /// A cell `z` leaves: its alive cofaces lose a face and its alive faces a coface; those
    /// left with one are queued.
    #[inline]
    fn release(&mut self, z: usize) {
        let Sweep { links, state, nb, nc, work, .. } = self;
        lose_one(links.cofaces(z), state, nb, work);
        lose_one(links.faces(z), state, nc, work);
    }

    /// The survivors: the input restricted to alive rows, plus the entries of the critical
    /// rows. `None` when an entry of a critical row does not fit `i64`.
    fn restricted(self) -> Option<Restricted> {
        let Sweep { ring, c, links, state, extra, log, .. } = self;
        let off = links.off;
        let counts = c.counts();
        let n1 = counts.len();
        let mut ids: Vec<Vec<u32>> = Vec::with_capacity(n1);
        let mut local = vec![u32::MAX; state.len()];
        for k in 0..n1 {
            let mut v = Vec::new();
            for j in 0..counts[k] {
                let g = off[k] as usize + j;
                if state[g] != State::Paired {
                    local[g] = v.len() as u32;
                    v.push(j as u32);
                }
            }
            ids.push(v);
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
                let (ri, rv) = m.col(j as usize);
                for (&r, &v) in ri.iter().zip(rv) {
                    let g = (off[k - 1] + r) as usize;
                    if state[g] == State::Alive && !ring.is_zero(&ring.of_i64(v)) {
                        col.push((local[g], v));
                    }
                }
                if let Some(list) = extra.get(&(off[k] + j)) {
                    for (r, v) in list {
                        col.push((local[*r as usize], ring.to_i64(v)?));
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
        Some(Restricted { chain, ids, log, off })
    }
}

/// Each alive cell of `linked` has one neighbour less in `count`; those left with one are
/// queued.
#[inline]
fn lose_one(linked: &[u32], state: &[State], count: &mut [u32], work: &mut Ready) {
    for &e in linked {
        let y = cell(e);
        if state[y] == State::Alive {
            count[y] -= 1;
            if count[y] == 1 {
                work.push(y as u32);
            }
        }
    }
}

/// The cells waiting to be looked at, taken lowest number first (lowest dimension, then
/// order of smallest dart): a bit per cell and, per dimension, a count and the first word
/// that may hold a bit. Taking cells in numbering order keeps the sweep's memory accesses
/// close together.
struct Ready {
    /// a bit per cell; each dimension starts a new word
    bits: Vec<u64>,
    /// per dimension: its first word, its past-the-end word, the first word that may hold
    /// a bit, the number of bits set, and its first global cell number
    lo: Vec<usize>,
    hi: Vec<usize>,
    cursor: Vec<usize>,
    count: Vec<usize>,
    start: Vec<u32>,
}

impl Ready {
    fn new(off: &[u32]) -> Self {
        let dims = off.len() - 1;
        let mut lo = Vec::with_capacity(dims);
        let mut hi = Vec::with_capacity(dims);
        let mut start = Vec::with_capacity(dims);
        let mut words = 0;
        for k in 0..dims {
            let m = (off[k + 1] - off[k]) as usize;
            lo.push(words);
            start.push(off[k]);
            words += m.div_ceil(64);
            hi.push(words);
        }
        Ready { bits: vec![0; words], cursor: lo.clone(), lo, hi, count: vec![0; dims], start }
    }

    #[inline]
    fn push(&mut self, x: u32) {
        let k = self.start.partition_point(|&s| s <= x) - 1;
        let i = (x - self.start[k]) as usize;
        let w = self.lo[k] + i / 64;
        let b = 1u64 << (i % 64);
        if self.bits[w] & b == 0 {
            self.bits[w] |= b;
            self.count[k] += 1;
            self.cursor[k] = self.cursor[k].min(w);
        }
    }

    #[inline]
    fn pop(&mut self) -> Option<u32> {
        let k = self.count.iter().position(|&c| c > 0)?;
        let mut w = self.cursor[k];
        while self.bits[w] == 0 {
            w += 1;
        }
        debug_assert!(w < self.hi[k]);
        self.cursor[k] = w;
        let b = self.bits[w].trailing_zeros();
        self.bits[w] &= self.bits[w] - 1;
        self.count[k] -= 1;
        Some(self.start[k] + ((w - self.lo[k]) * 64) as u32 + b)
    }
}

/// `list - lambda * fill` for sorted sparse rows; zeros dropped.
fn axpy<R: Ring>(ring: &R, list: &[(u32, R::E)], lambda: &R::E, fill: &[(u32, R::E)]) -> Option<Vec<(u32, R::E)>> {
    let zero = ring.of_i64(0);
    let mut out = Vec::with_capacity(list.len() + fill.len());
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
    Some(out)
}

/// Lifts a k-chain of the reduced complex (numbered as in `pre.chain`) to a k-chain of the
/// input `c` through the eliminated pairs, last first: each pair `(a, b)` with `b` a k-cell
/// subtracts `(⟨∂z, a⟩ / ⟨∂b, a⟩) b`, which is the chain map of the reduction. A cycle lifts
/// to a cycle in the same homology class. `None` on overflow.
/// O(log length + entries of the k-cells met).
pub(crate) fn lift<R: Ring>(
    ring: &R,
    c: &ChainComplex,
    pre: &Restricted,
    k: usize,
    chain: &[(u32, R::E)],
) -> Option<Vec<(u32, R::E)>> {
    let zero = ring.of_i64(0);
    let mut z: Vec<R::E> = vec![zero.clone(); c.count(k)];
    for (j, v) in chain {
        z[pre.ids[k][*j as usize] as usize] = v.clone();
    }
    if k == 0 || pre.log.is_empty() {
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

/// Whether every column of `∂_1` is empty or `v - w` (entries `1` and `-1`).
fn edges_are_differences(m: &SparseMatrix) -> bool {
    (0..m.cols()).all(|j| {
        let (_, v) = m.col(j);
        v.is_empty() || (v.len() == 2 && v[0] + v[1] == 0 && v[0].abs() == 1)
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::engine::homology::homology_z;
    use crate::engine::homology::tests::complex;
    use crate::engine::ring::{Zi64, Zp};

    #[test]
    fn a_filled_triangle_reduces_to_one_vertex() {
        // vertices 0 1 2, edges 01 12 02, one face 01 + 12 - 02
        let c = complex(
            vec![3, 3, 1],
            vec![
                vec![(0, 0, -1), (1, 0, 1), (1, 1, -1), (2, 1, 1), (0, 2, -1), (2, 2, 1)],
                vec![(0, 0, 1), (1, 0, 1), (2, 0, -1)],
            ],
        );
        let r = prereduce(&Zi64, &c, true).unwrap();
        assert_eq!(r.chain.counts(), &[1, 0, 0]);
        assert_eq!(r.ids[0], vec![0]);
    }

    #[test]
    fn a_circle_keeps_one_edge() {
        let c = complex(vec![3, 3], vec![vec![(0, 0, -1), (1, 0, 1), (1, 1, -1), (2, 1, 1), (0, 2, 1), (2, 2, -1)]]);
        let r = prereduce(&Zi64, &c, true).unwrap();
        assert_eq!(r.chain.counts(), &[1, 1]);
        assert!(r.chain.boundary(1).is_zero());
    }

    #[test]
    fn non_unit_entries_are_not_paired() {
        // the projective plane: one vertex, one edge (a loop), one face with ∂ = 2a
        let c = complex(vec![1, 1, 1], vec![vec![], vec![(0, 0, 2)]]);
        let r = prereduce(&Zi64, &c, true).unwrap();
        assert_eq!(r.chain.counts(), &[1, 1, 1]);
        assert_eq!(homology_z(&r.chain).unwrap().torsion[1], vec![2]);
        // over Z/3 the entry 2 is a unit: the edge and the face go
        let r = prereduce(&Zp { p: 3 }, &c, true).unwrap();
        assert_eq!(r.chain.counts(), &[1, 0, 0]);
        // over Z/2 it is zero: nothing to pair
        let r = prereduce(&Zp { p: 2 }, &c, true).unwrap();
        assert_eq!(r.chain.counts(), &[1, 1, 1]);
        assert!(r.chain.boundary(2).is_zero());
    }
}
