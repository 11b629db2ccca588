//! Sparse elimination with unit pivots: the general stage of the homology
//! computation.
//!
//! ## The reduction step
//!
//! Let `u = ∂_k[a, b]` be a unit (±1 over `Z`, any non-zero value over `Z/p`), `a` a
//! (k-1)-cell and `b` a k-cell. Changing the basis of `C_k` by `c ↦ c - (∂_k[a, c] / u) b`
//! for every other k-cell `c`, and the basis of `C_{k-1}` by `a ↦ ∂_k(b) / u`, splits off the
//! acyclic pair `b ↦ ∂b` and leaves a complex with the same homology in which
//!
//! * column `b` and row `a` of `∂_k` are gone and every other column `c` with an entry in
//!   row `a` became `c - (∂_k[a, c] / u) b`;
//! * row `b` of `∂_{k+1}` is gone (its coefficient vanishes in the new basis, as `∂∂ = 0`);
//! * column `a` of `∂_{k-1}` is gone (the new basis vector `∂b / u` is a cycle).
//!
//! This is algebraic discrete Morse theory in matrix form. Two cases cost no fill at all:
//! a **row singleton** (`a` lies in the boundary of `b` only: an elementary collapse) and a
//! **column singleton** (the boundary of `b` is `±a`: a coreduction). The engine processes
//! those first from work queues. When neither exists it **freezes** a row: a frozen row is
//! never a pivot, so updates may create fill only in frozen rows, which play the role of
//! critical cells. A closed connected complex gets stuck at once (every vertex lies on two
//! edges or more), freezes one vertex and then peels the whole 1-skeleton by coreductions,
//! like a breadth-first spanning tree; the same happens one dimension up. On manifolds and
//! on the simplicial counterparts of G-maps the frozen rows are about as many as the Betti
//! numbers, so the whole stage is linear in the number of entries in practice.
//!
//! What remains is a complex on the surviving cells whose matrices are small; they are
//! reduced again with general unit pivots (fewest entries first, a Markowitz-like rule)
//! and then by dense Smith normal form ([`crate::engine::snf`]).

use std::cmp::Reverse;
use std::collections::BinaryHeap;

use crate::engine::ring::Ring;

/// State of a row during elimination.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum RowState {
    Active,
    Frozen,
    Eliminated,
}

/// What to do when no singleton pivot is left.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub(crate) enum Mode {
    /// freeze a row (stage 1, keeps fill in frozen rows)
    Freeze,
    /// take a general unit pivot with the fewest entries (stage 2, small matrices)
    General,
}

/// A sparse column: `(row, value)` pairs with strictly increasing rows.
pub(crate) type Col<E> = Vec<(u32, E)>;

/// The result of eliminating one matrix.
#[derive(Debug)]
pub(crate) struct Eliminated<E> {
    /// pivots `(row, col)` in the order taken
    pub pivots: Vec<(u32, u32)>,
    /// the columns that were not pivots, with their reduced entries (only in non-pivot rows)
    pub remaining: Vec<(u32, Col<E>)>,
}

/// An elimination in progress.
struct Engine<'r, R: Ring> {
    ring: &'r R,
    cols: Vec<Col<R::E>>,
    alive: Vec<bool>,
    state: Vec<RowState>,
    row_cols: Vec<Vec<u32>>,
    row_count: Vec<u32>,
    col_nf: Vec<u32>,
    col_q: Vec<u32>,
    row_q: Vec<u32>,
    heap: BinaryHeap<Reverse<(u32, u32)>>,
    pivots: Vec<(u32, u32)>,
}

/// Eliminates unit pivots from a `rows × cols.len()` matrix given by sorted columns.
/// Rows listed in `frozen` start frozen. Returns `None` on arithmetic overflow.
/// O(nnz + fill) heap and queue operations, each O(log cols).
pub(crate) fn eliminate<R: Ring>(ring: &R, rows: usize, cols: Vec<Col<R::E>>, mode: Mode) -> Option<Eliminated<R::E>> {
    let ncols = cols.len();
    let mut e = Engine {
        ring,
        alive: vec![true; ncols],
        state: vec![RowState::Active; rows],
        row_cols: vec![Vec::new(); rows],
        row_count: vec![0; rows],
        col_nf: vec![0; ncols],
        col_q: Vec::new(),
        row_q: Vec::new(),
        heap: BinaryHeap::with_capacity(ncols),
        pivots: Vec::new(),
        cols,
    };
    for (c, col) in e.cols.iter().enumerate() {
        for &(r, _) in col {
            e.row_cols[r as usize].push(c as u32);
            e.row_count[r as usize] += 1;
        }
        e.col_nf[c] = col.len() as u32;
    }
    for c in 0..ncols {
        if e.col_nf[c] == 1 {
            e.col_q.push(c as u32);
        }
        if e.col_nf[c] >= 1 {
            e.heap.push(Reverse((e.col_nf[c], c as u32)));
        }
    }
    for r in 0..rows {
        if e.row_count[r] == 1 {
            e.row_q.push(r as u32);
        }
    }
    e.run(mode)?;
    let Engine { cols, alive, pivots, .. } = e;
    let remaining = cols.into_iter().enumerate().filter(|(c, _)| alive[*c]).map(|(c, col)| (c as u32, col)).collect();
    Some(Eliminated { pivots, remaining })
}

impl<R: Ring> Engine<'_, R> {
    fn run(&mut self, mode: Mode) -> Option<()> {
        loop {
            if let Some(c) = self.col_q.pop() {
                let c = c as usize;
                if !self.alive[c] || self.col_nf[c] != 1 {
                    continue;
                }
                let pos = self.cols[c].iter().position(|(r, _)| self.state[*r as usize] == RowState::Active);
                if let Some(p) = pos {
                    if self.ring.is_unit(&self.cols[c][p].1) {
                        let r = self.cols[c][p].0;
                        self.pivot(r as usize, c)?;
                    }
                }
                continue;
            }
            if let Some(r) = self.row_q.pop() {
                let r = r as usize;
                if self.state[r] != RowState::Active || self.row_count[r] != 1 {
                    continue;
                }
                if let Some((c, unit)) = self.row_entry(r) {
                    if unit {
                        self.pivot(r, c)?;
                    }
                }
                continue;
            }
            // stuck: the alive column with the fewest active entries
            let c = loop {
                match self.heap.pop() {
                    None => return Some(()),
                    Some(Reverse((k, c))) => {
                        let c = c as usize;
                        if self.alive[c] && self.col_nf[c] == k && k >= 1 {
                            break c;
                        }
                    }
                }
            };
            match mode {
                Mode::Freeze if self.col_nf[c] == 2 && self.contract(c)? => {}
                Mode::Freeze => {
                    // freeze a non-unit row if any, else the active row in most columns
                    let mut best: Option<(bool, u32, u32)> = None;
                    for (r, v) in &self.cols[c] {
                        if self.state[*r as usize] != RowState::Active {
                            continue;
                        }
                        let key = (!self.ring.is_unit(v), self.row_count[*r as usize], *r);
                        if best.is_none_or(|b| key > b) {
                            best = Some(key);
                        }
                    }
                    let r = best.map(|b| b.2).expect("col_nf >= 1 implies an active row");
                    self.freeze(r as usize);
                }
                Mode::General => {
                    // a unit entry in the row with the fewest columns; else freeze the column's rows
                    let mut best: Option<(u32, u32)> = None;
                    for (r, v) in &self.cols[c] {
                        if self.state[*r as usize] == RowState::Active && self.ring.is_unit(v) {
                            let key = (self.row_count[*r as usize], *r);
                            if best.is_none_or(|b| key < b) {
                                best = Some(key);
                            }
                        }
                    }
                    match best {
                        Some((_, r)) => self.pivot(r as usize, c)?,
                        None => {
                            let rs: Vec<u32> = self.cols[c]
                                .iter()
                                .filter(|(r, _)| self.state[*r as usize] == RowState::Active)
                                .map(|(r, _)| *r)
                                .collect();
                            for r in rs {
                                self.freeze(r as usize);
                            }
                        }
                    }
                }
            }
        }
    }

    /// A column with two active entries, both units: pivots on the one whose row is in the
    /// fewest columns (an edge contraction: other columns keep their number of active
    /// entries). Returns `Some(false)` when an entry is not a unit.
    fn contract(&mut self, c: usize) -> Option<bool> {
        let mut best: Option<(u32, u32)> = None;
        for (r, v) in &self.cols[c] {
            if self.state[*r as usize] != RowState::Active {
                continue;
            }
            if !self.ring.is_unit(v) {
                return Some(false);
            }
            let key = (self.row_count[*r as usize], *r);
            if best.is_none_or(|b| key < b) {
                best = Some(key);
            }
        }
        match best {
            Some((_, r)) => {
                self.pivot(r as usize, c)?;
                Some(true)
            }
            None => Some(false),
        }
    }

    /// The alive column holding the only entry of row `r`, and whether that entry is a unit.
    fn row_entry(&mut self, r: usize) -> Option<(usize, bool)> {
        let mut list = std::mem::take(&mut self.row_cols[r]);
        list.sort_unstable();
        list.dedup();
        let mut found = None;
        let mut kept = Vec::with_capacity(2);
        for &c in &list {
            let cu = c as usize;
            if !self.alive[cu] {
                continue;
            }
            if let Ok(p) = self.cols[cu].binary_search_by_key(&(r as u32), |x| x.0) {
                kept.push(c);
                found = Some((cu, self.ring.is_unit(&self.cols[cu][p].1)));
            }
        }
        self.row_cols[r] = kept;
        found
    }

    fn freeze(&mut self, r: usize) {
        self.state[r] = RowState::Frozen;
        let mut list = std::mem::take(&mut self.row_cols[r]);
        list.sort_unstable();
        list.dedup();
        let mut kept = Vec::with_capacity(list.len());
        for &c in &list {
            let cu = c as usize;
            if !self.alive[cu] || self.cols[cu].binary_search_by_key(&(r as u32), |x| x.0).is_err() {
                continue;
            }
            kept.push(c);
            self.col_nf[cu] -= 1;
            if self.col_nf[cu] == 1 {
                self.col_q.push(c);
            }
            if self.col_nf[cu] >= 1 {
                self.heap.push(Reverse((self.col_nf[cu], c)));
            }
        }
        self.row_cols[r] = kept;
    }

    /// Pivots on the unit entry at row `y`, column `b`.
    fn pivot(&mut self, y: usize, b: usize) -> Option<()> {
        let bcol = std::mem::take(&mut self.cols[b]);
        let p = bcol.binary_search_by_key(&(y as u32), |x| x.0).expect("pivot entry present");
        let u = bcol[p].1.clone();
        self.alive[b] = false;
        self.state[y] = RowState::Eliminated;
        self.pivots.push((y as u32, b as u32));
        for &(r, _) in &bcol {
            let r = r as usize;
            self.row_count[r] -= 1;
            if self.state[r] == RowState::Active && self.row_count[r] == 1 {
                self.row_q.push(r as u32);
            }
        }
        let list = std::mem::take(&mut self.row_cols[y]);
        let mut merged: Col<R::E> = Vec::new();
        for &c in &list {
            let cu = c as usize;
            if !self.alive[cu] {
                continue;
            }
            let v = match self.cols[cu].binary_search_by_key(&(y as u32), |x| x.0) {
                Ok(q) => self.cols[cu][q].1.clone(),
                Err(_) => continue,
            };
            let lambda = self.ring.div_unit(&v, &u)?;
            // merge c - lambda * b
            let old = std::mem::take(&mut self.cols[cu]);
            merged.clear();
            merged.reserve(old.len() + bcol.len());
            let (mut i, mut j) = (0, 0);
            let mut nf = 0u32;
            while i < old.len() || j < bcol.len() {
                let take_old = j == bcol.len() || (i < old.len() && old[i].0 < bcol[j].0);
                let take_b = i == old.len() || (j < bcol.len() && bcol[j].0 < old[i].0);
                if take_old {
                    let (r, ref x) = old[i];
                    if self.state[r as usize] == RowState::Active {
                        nf += 1;
                    }
                    merged.push((r, x.clone()));
                    i += 1;
                } else if take_b {
                    let (r, ref x) = bcol[j];
                    let zero = self.ring.of_i64(0);
                    let nv = self.ring.sub_mul(&zero, &lambda, x)?;
                    let ru = r as usize;
                    self.row_count[ru] += 1;
                    self.row_cols[ru].push(c);
                    if self.state[ru] == RowState::Active {
                        nf += 1;
                    }
                    merged.push((r, nv));
                    j += 1;
                } else {
                    let (r, ref x) = old[i];
                    let nv = self.ring.sub_mul(x, &lambda, &bcol[j].1)?;
                    i += 1;
                    j += 1;
                    let ru = r as usize;
                    if self.ring.is_zero(&nv) {
                        self.row_count[ru] -= 1;
                        if self.state[ru] == RowState::Active && self.row_count[ru] == 1 {
                            self.row_q.push(r);
                        }
                    } else {
                        if self.state[ru] == RowState::Active {
                            nf += 1;
                        }
                        merged.push((r, nv));
                    }
                }
            }
            self.cols[cu] = std::mem::replace(&mut merged, old);
            self.col_nf[cu] = nf;
            if nf == 1 {
                self.col_q.push(c);
            }
            if nf >= 1 {
                self.heap.push(Reverse((nf, c)));
            }
        }
        Some(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::engine::ring::{Zi64, Zp};

    fn col(v: &[(u32, i64)]) -> Col<i64> {
        v.to_vec()
    }

    #[test]
    fn triangle_boundary_has_rank_two() {
        // d1 of a triangle: edges (0,1), (1,2), (0,2)
        let cols = vec![col(&[(0, -1), (1, 1)]), col(&[(1, -1), (2, 1)]), col(&[(0, -1), (2, 1)])];
        let r = eliminate(&Zi64, 3, cols, Mode::Freeze).unwrap();
        assert_eq!(r.pivots.len(), 2);
        assert_eq!(r.remaining.len(), 1);
        assert!(r.remaining[0].1.iter().all(|(_, v)| *v == 0) || r.remaining[0].1.is_empty());
    }

    #[test]
    fn non_unit_entry_is_left() {
        let cols = vec![col(&[(0, 2)])];
        let r = eliminate(&Zi64, 1, cols.clone(), Mode::General).unwrap();
        assert!(r.pivots.is_empty());
        assert_eq!(r.remaining, vec![(0, vec![(0, 2)])]);
        let f = Zp { p: 3 };
        let r = eliminate(&f, 1, vec![vec![(0, 2u64)]], Mode::General).unwrap();
        assert_eq!(r.pivots, vec![(0, 0)]);
    }
}
