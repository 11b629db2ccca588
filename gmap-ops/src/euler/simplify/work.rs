//! The working copy of the map during a greedy run: the involutions as one flat array, the
//! live darts, and per dimension k the input k-cell of every dart with a union–find
//! structure that merges them as the moves go (so the current k-cells are named by roots
//! and no partition is recomputed), plus the stamps and scratch space of the moves.

use gmap_core::parallel;
use gmap_core::union_find::UnionFind;
use gmap_core::DenseMap;

use crate::euler::ops::Move;

/// The working copy of a map under removals and contractions. See the [module docs](self).
#[derive(Clone)]
pub(super) struct Work {
    /// the dimension
    pub(super) n: usize,
    /// `n + 1`, the width of a row of `a`
    pub(super) w: usize,
    /// `a[d * w + i]`: `alpha_i(d)`, kept up to date for the live darts
    pub(super) a: Vec<u32>,
    pub(super) alive: Vec<bool>,
    /// `label[k][d]`: the input k-cell of dart d; `uf[k]` merges them.
    pub(super) label: Vec<Vec<u32>>,
    pub(super) uf: Vec<UnionFind>,
    /// `free[k][r]`: the k-cell of root r holds a free dart.
    pub(super) free: Vec<Vec<bool>>,
    /// every free dart of the input is free for `alpha_n` only (a manifold with boundary, no
    /// incomplete cell): boundary edges may then be contracted
    pub(super) top_free_only: bool,
    /// `exam[k][r]`: last scan that examined the k-cell of root r; `queued` likewise for
    /// the work stack.
    pub(super) exam: Vec<Vec<u32>>,
    pub(super) queued: Vec<Vec<u32>>,
    // scratch: membership of the current cell (`stamp[d] == tag`), appearances (`seen`),
    // corner names (`cid`, valid where `cstamp == ctag`; allocated at the first corner test)
    pub(super) stamp: Vec<u32>,
    pub(super) tag: u32,
    pub(super) seen: Vec<u32>,
    pub(super) seen_tag: u32,
    pub(super) cstamp: Vec<u32>,
    pub(super) cid: Vec<u32>,
    pub(super) ctag: u32,
    pub(super) cell: Vec<u32>,
    pub(super) stack: Vec<u32>,
    pub(super) links: Vec<(u32, u32)>,
    pub(super) apps: Vec<(u32, u32)>,
    /// the work stack: cells to examine at once, as (dimension, move, dart)
    pub(super) pending: Vec<(u8, Move, u32)>,
    /// moves made so far
    pub(super) moves: u32,
    /// also re-examine the merged neighbour cell after a move
    pub(super) up: bool,
    /// cells removed and contracted, per dimension
    pub(super) removed: Vec<usize>,
    pub(super) contracted: Vec<usize>,
}

/// Bumps a stamp counter, clearing the stamps when it would wrap.
pub(super) fn bump(tag: &mut u32, stamps: &mut [u32]) -> u32 {
    if *tag == u32::MAX - 1 {
        stamps.iter_mut().for_each(|s| *s = 0);
        *tag = 0;
    }
    *tag += 1;
    *tag
}

impl Work {
    /// The working copy of `map`, and its numbers of cells per dimension. The n + 1 cell
    /// partitions are computed one task each on the threads of `gmap_core::parallel`.
    pub(super) fn new(map: &DenseMap) -> (Self, Vec<usize>) {
        let n = map.dim();
        let a = map.flat().to_vec();
        let nd = map.dart_count();
        let parts = parallel::map_tasks(n + 1, nd, |k| map.cells(k));
        let counts: Vec<usize> = parts.iter().map(|p| p.len()).collect();
        let label: Vec<Vec<u32>> = parts.into_iter().map(|p| p.of).collect();
        let mut free: Vec<Vec<bool>> = counts.iter().map(|&c| vec![false; c]).collect();
        let w = n + 1;
        let top_free_only = n >= 2 && (0..nd).all(|d| (0..n).all(|j| a[d * w + j] as usize != d));
        for d in 0..nd {
            if a[d * w..d * w + w].iter().any(|&y| y as usize == d) {
                for k in 0..=n {
                    free[k][label[k][d] as usize] = true;
                }
            }
        }
        let work = Work {
            n,
            w,
            a,
            alive: vec![true; nd],
            label,
            uf: counts.iter().map(|&c| UnionFind::new(c)).collect(),
            free,
            top_free_only,
            exam: counts.iter().map(|&c| vec![0; c]).collect(),
            queued: counts.iter().map(|&c| vec![0; c]).collect(),
            stamp: vec![0; nd],
            tag: 0,
            seen: vec![0; nd],
            seen_tag: 0,
            cstamp: Vec::new(),
            cid: Vec::new(),
            ctag: 0,
            cell: Vec::new(),
            stack: Vec::new(),
            links: Vec::new(),
            apps: Vec::new(),
            pending: Vec::new(),
            moves: 0,
            up: false,
            removed: vec![0; n + 1],
            contracted: vec![0; n + 1],
        };
        (work, counts)
    }

    /// `alpha_i(d)`.
    #[inline]
    pub(super) fn al(&self, d: u32, i: usize) -> u32 {
        self.a[d as usize * self.w + i]
    }

    /// The root naming the current k-cell of `d`.
    #[inline]
    pub(super) fn root(&mut self, k: usize, d: u32) -> u32 {
        let l = self.label[k][d as usize];
        self.uf[k].find(l)
    }

    /// Number of live darts.
    pub(super) fn live(&self) -> usize {
        self.alive.iter().filter(|&&x| x).count()
    }

    /// The live darts as a map, renumbered in order.
    pub(super) fn compact(&self) -> DenseMap {
        let mut newid = vec![u32::MAX; self.alive.len()];
        let mut k = 0u32;
        for (d, &al) in self.alive.iter().enumerate() {
            if al {
                newid[d] = k;
                k += 1;
            }
        }
        let mut flat = Vec::with_capacity(k as usize * self.w);
        for (d, &al) in self.alive.iter().enumerate() {
            if al {
                for i in 0..self.w {
                    flat.push(newid[self.a[d * self.w + i] as usize]);
                }
            }
        }
        DenseMap::from_flat_unchecked(self.n, flat).expect("fewer darts than the input")
    }
}
