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

use crate::engine::chain::ChainComplex;
use crate::engine::ring::{Euclid, Ring};
use crate::engine::sparse::SparseMatrix;

const ALIVE: u8 = 0;
const PAIRED: u8 = 1;
/// a vertex set aside for `H_0`: survives, but takes part in no entry
const SET_ASIDE: u8 = 2;
/// a critical cell: survives, with the fill of later coreductions in its row
const CRITICAL: u8 = 3;
/// bit 31 of an entry: its value is a unit
const UNIT: u32 = 1 << 31;
/// cells and entries are numbered in 31 bits
const LIMIT: usize = 1 << 31;

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
    let n1 = counts.len();
    let total: usize = counts.iter().sum();
    let nnz: usize = (1..n1).map(|k| c.boundary(k).nnz()).sum();
    if total >= LIMIT || nnz >= LIMIT {
        // beyond u32 indices: hand the complex on as it is
        let ids = counts.iter().map(|&m| (0..m as u32).collect()).collect();
        return Some(Restricted { chain: c.clone(), ids, log: Vec::new(), off: Vec::new() });
    }
    let mut off = Vec::with_capacity(n1 + 1);
    let mut acc = 0u32;
    for &m in counts {
        off.push(acc);
        acc += m as u32;
    }
    off.push(acc);
    let dim_of = |x: usize| off.partition_point(|&o| o as usize <= x) - 1;
    // ⟨∂x, y⟩ from the input, for a k-cell x and a (k-1)-cell y (global numbers)
    let value = |x: usize, y: usize| -> R::E {
        let k = dim_of(x);
        ring.of_i64(c.boundary(k).get(y - off[k - 1] as usize, x - off[k] as usize))
    };
    // faces of every cell (global ids, bit 31 set for a unit entry), ring-nonzero entries only
    let mut fptr: Vec<u32> = Vec::with_capacity(total + 1);
    let mut faces: Vec<u32> = Vec::with_capacity(nnz);
    fptr.extend(std::iter::repeat_n(0, counts.first().copied().unwrap_or(0) + 1));
    for k in 1..n1 {
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
    // cofaces: the transpose
    let mut cptr = vec![0u32; total + 1];
    for &r in &faces {
        cptr[(r & !UNIT) as usize + 1] += 1;
    }
    for i in 0..total {
        cptr[i + 1] += cptr[i];
    }
    let mut cofaces = vec![0u32; faces.len()];
    {
        let mut fill = cptr.clone();
        for col in 0..total {
            for &r in &faces[fptr[col] as usize..fptr[col + 1] as usize] {
                let slot = &mut fill[(r & !UNIT) as usize];
                cofaces[*slot as usize] = col as u32 | (r & UNIT);
                *slot += 1;
            }
        }
    }
    let mut nb: Vec<u32> = fptr.windows(2).map(|w| w[1] - w[0]).collect();
    let mut nc: Vec<u32> = cptr.windows(2).map(|w| w[1] - w[0]).collect();
    let mut state = vec![ALIVE; total];

    // set aside one vertex per component of the 1-skeleton when ∂_1 is made of `v - w` columns
    if n1 >= 2 && edges_are_differences(c.boundary(1)) {
        let nv = counts[0];
        let mut parent: Vec<u32> = (0..nv as u32).collect();
        let m = c.boundary(1);
        for j in 0..m.cols() {
            let (ri, _) = m.col(j);
            if ri.len() == 2 {
                let (x, y) = (find(&mut parent, ri[0]), find(&mut parent, ri[1]));
                if x != y {
                    parent[x.max(y) as usize] = x.min(y);
                }
            }
        }
        for v in 0..nv as u32 {
            if find(&mut parent, v) == v {
                state[v as usize] = SET_ASIDE;
                for &e in &cofaces[cptr[v as usize] as usize..cptr[v as usize + 1] as usize] {
                    nb[(e & !UNIT) as usize] -= 1;
                }
            }
        }
    }

    // entries of alive or critical cells in critical rows: (row, value), rows increasing
    let mut extra: HashMap<u32, Vec<(u32, R::E)>> = HashMap::new();
    let mut log: Vec<(u32, u32)> = Vec::with_capacity(total / 2);
    // lowest cell number first: the sweep moves through the complex in numbering order, which
    // keeps its accesses close together (2.5x faster than first in, first out on the 40³
    // grid, with the same survivors); a stack gets stuck far earlier on closed manifolds
    let mut work = Ready::new(&off);
    for x in 0..total {
        if state[x] == ALIVE && (nb[x] == 1 || nc[x] == 1) {
            work.push(x as u32);
        }
    }
    // per dimension, the first cell that may still be alive (critical cells are taken in order)
    let mut cursor: Vec<usize> = off[..n1].iter().map(|&o| o as usize).collect();
    loop {
        let Some(x) = work.pop() else {
            if !freeze {
                break;
            }
            // stuck: the first alive cell of the lowest dimension becomes critical; it has no
            // alive face, so only its cofaces change
            let mut pick = None;
            for k in 0..n1 {
                while cursor[k] < off[k + 1] as usize && state[cursor[k]] != ALIVE {
                    cursor[k] += 1;
                }
                if cursor[k] < off[k + 1] as usize {
                    pick = Some(cursor[k]);
                    break;
                }
            }
            let Some(x) = pick else { break };
            state[x] = CRITICAL;
            for &e in &cofaces[cptr[x] as usize..cptr[x + 1] as usize] {
                let y = (e & !UNIT) as usize;
                if state[y] == ALIVE {
                    let v = value(y, x);
                    let list = extra.entry(y as u32).or_default();
                    let pos = list.partition_point(|(r, _)| (*r as usize) < x);
                    list.insert(pos, (x as u32, v));
                    nb[y] -= 1;
                    if nb[y] == 1 {
                        work.push(y as u32);
                    }
                }
            }
            continue;
        };
        let x = x as usize;
        if state[x] != ALIVE {
            continue;
        }
        let mut pair = None;
        let mut coreduction = false;
        if nb[x] == 1 {
            // coreduction: the only surviving face of x
            let f =
                faces[fptr[x] as usize..fptr[x + 1] as usize].iter().find(|&&e| state[(e & !UNIT) as usize] == ALIVE);
            if let Some(&e) = f {
                if e & UNIT != 0 {
                    pair = Some(((e & !UNIT) as usize, x));
                    coreduction = true;
                }
            }
        }
        if pair.is_none() && nc[x] == 1 {
            // collapse: the only surviving coface of x
            let f =
                cofaces[cptr[x] as usize..cptr[x + 1] as usize].iter().find(|&&e| state[(e & !UNIT) as usize] == ALIVE);
            if let Some(&e) = f {
                if e & UNIT != 0 {
                    pair = Some((x, (e & !UNIT) as usize));
                }
            }
        }
        let Some((a, b)) = pair else { continue };
        state[a] = PAIRED;
        state[b] = PAIRED;
        log.push((a as u32, b as u32));
        extra.remove(&(a as u32));
        // a collapse changes no other column; a coreduction of a column with entries in
        // critical rows adds them to the other columns meeting row a
        if let Some(fill) = extra.remove(&(b as u32)) {
            if coreduction {
                let eps = value(b, a);
                for &e in &cofaces[cptr[a] as usize..cptr[a + 1] as usize] {
                    let y = (e & !UNIT) as usize;
                    if state[y] != ALIVE {
                        continue;
                    }
                    let lambda = ring.div_unit(&value(y, a), &eps)?;
                    let list = extra.entry(y as u32).or_default();
                    *list = axpy(ring, list, &lambda, &fill)?;
                    if list.is_empty() {
                        extra.remove(&(y as u32));
                    }
                }
            }
        }
        for z in [a, b] {
            for &e in &cofaces[cptr[z] as usize..cptr[z + 1] as usize] {
                let y = (e & !UNIT) as usize;
                if state[y] == ALIVE {
                    nb[y] -= 1;
                    if nb[y] == 1 {
                        work.push(y as u32);
                    }
                }
            }
            for &e in &faces[fptr[z] as usize..fptr[z + 1] as usize] {
                let y = (e & !UNIT) as usize;
                if state[y] == ALIVE {
                    nc[y] -= 1;
                    if nc[y] == 1 {
                        work.push(y as u32);
                    }
                }
            }
        }
    }

    // the survivors: restricted entries in alive rows, tracked entries in critical rows
    let mut ids: Vec<Vec<u32>> = Vec::with_capacity(n1);
    let mut local = vec![u32::MAX; total];
    for k in 0..n1 {
        let mut v = Vec::new();
        for j in 0..counts[k] {
            let g = off[k] as usize + j;
            if state[g] != PAIRED {
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
                if state[g] == ALIVE && !ring.is_zero(&ring.of_i64(v)) {
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

/// The cells waiting to be looked at, taken lowest number first (lowest dimension, then
/// order of smallest dart): a bit per cell and, per dimension, a count and the first word
/// that may hold a bit. Taking cells in numbering order keeps the sweep's memory accesses
/// close together; on the Lutz library it leaves as few cells as a first-in-first-out queue
/// did, give or take a few (fewer on bing and knot, more on non_4_2_colorable).
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

fn find(parent: &mut [u32], mut x: u32) -> u32 {
    while parent[x as usize] != x {
        let p = parent[parent[x as usize] as usize];
        parent[x as usize] = p;
        x = p;
    }
    x
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
