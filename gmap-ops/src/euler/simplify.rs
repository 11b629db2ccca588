//! Homology-preserving simplification by removals and contractions.
//!
//! A G-map whose cells are homology balls (conditions C1, C2 of DESIGN.md) is a
//! CW-structure on its space; its cellular homology is the space's homology. Removing an
//! i-cell of degree 2 that separates two *distinct* (i+1)-cells merges them into one
//! (i+1)-cell — a ball glued to a ball along a ball — and leaves the space untouched;
//! contracting an i-cell of dual degree 2 between two distinct (i-1)-cells is the dual
//! move, a homotopy equivalence. Both therefore keep the homology and keep the cells balls,
//! while the number of darts drops.
//!
//! Two more conditions keep every step a homotopy equivalence that the G-map can represent:
//! the cell's appearances in each k-cell it touches must join distinct *corners* (pieces of
//! the neighbouring cells around that k-cell) without closing a cycle — otherwise the
//! k-cell would fall apart, as a volume does when an edge it meets twice is contracted — and
//! a contraction never merges two cells that carry free darts (two boundary vertices joined
//! by an interior edge would pinch the space), with one exception: in a manifold with
//! boundary (every free dart free for `alpha_n` only), an edge that lies on the boundary
//! itself may be contracted. The links of its two vertices are then (n-1)-disks glued along
//! the edge's link, an (n-2)-disk on both their boundaries, so the merged vertex is one cell
//! and nothing is pinched; contracting an arc is a homotopy equivalence.
//!
//! # Order of the moves
//!
//! [`simplify`] scans the cells dimension by dimension (removals of (n-1)-cells, which merge
//! the n-cells along a spanning tree of the dual graph, then of (n-2)-cells, …, then the
//! contractions of 1-cells, which merge the vertices along a spanning tree, 2-cells, …) and
//! repeats until nothing applies. The order matters: after a removal of an i-cell, the
//! (i-1)-cells on its border have lost a neighbour and are re-examined *at once*, before the
//! scan goes on (a work stack; dually after a contraction for the (i+1)-cells). In a
//! 3-manifold an edge whose degree falls to 2 is thus removed while its two faces still
//! separate two distinct volumes, and the merged face is removed later in the scan: this
//! is the collapse of a free edge of discrete Morse theory. Removing all the faces of the
//! spanning tree first instead leaves such an edge with one face on both sides of the
//! single volume, where no removal or contraction applies any more.
//!
//! A few runs from fresh copies of the input (removals first, contractions first, with and
//! without re-examining the merged neighbour after each move, then seeded random orders of
//! the darts) keep the smallest result; see [`SimplifyOptions`].
//!
//! # Search past plateaus (3-maps)
//!
//! Removals and contractions stop where every remaining cell meets its neighbours more than
//! once: a ball with a knotted boundary ended at one vertex, one volume, 18 loops and 19
//! faces that all bound the volume on both sides (8.9 % of `triple_trefoil_arc`). The
//! inverse moves get out: splitting the volume by a new face along a closed path of its
//! boundary, or a face by a new edge, subdivides without changing the space, and a face
//! that bounded the volume on both sides may now separate the two halves and be removed.
//! Such a split-then-remove is a handle slide. The search ([`SimplifyOptions::search`])
//! applies random splits (up to a third of the darts' count, at most 40, at a time) to the
//! smallest map so far, checks that every cell is still a ball (C1 and χ = 2 per volume),
//! simplifies greedily again and keeps the result when it is no larger. Bigger groups of
//! splits escaped the plateaus where one to three did not: with 1–3 splits per round half of
//! the seeds left `triple_trefoil_arc` above 5 %, with up to 40 none of twelve did.
//!
//! # Results
//!
//! Darts before → after (cells after, per dimension), all with the homology stated in the
//! files of the Lutz library and accepted by the cellular method (C1/C2 hold throughout);
//! "greedy" is the result before the search:
//!
//! | input | darts | greedy | after | cells after | time |
//! |---|---|---|---|---|---|
//! | 40³ periodic grid (3-torus) | 3,072,000 | 48 | 48 | 1, 3, 3, 1 | 0.5–0.8 s |
//! | 40³ grid (3-ball) | 3,072,000 | 4 | 4 | 2, 1, 1, 1 | 0.4 s |
//! | `600_cell` (3-sphere) | 14,400 | 4 | 4 | 1, 1, 1, 1 | 21 ms |
//! | `knot` (3-ball) | 28,128 | 152 | 4 (0.01 %) | 1, 1, 2, 1 | 0.2 s |
//! | `bing` (3-ball, Bing's house inside) | 37,296 | 36 | 4 (0.01 %) | 1, 1, 2, 1 | 48 ms |
//! | `trefoil_arc` (3-ball) | 912 | 20 | 4 (0.44 %) | 1, 1, 2, 1 | 18 ms |
//! | `triple_trefoil_arc` (3-ball) | 2,328 | 208 (8.9 %) | 32 (1.37 %) | 1, 3, 4, 1 | 0.4 s |
//! | `rudin` (non-shellable 3-ball) | 984 | 12 | 4 | 1, 1, 2, 1 | 18 ms |
//! | `poincare` (homology sphere) | 2,160 | 60 | 52 (2.4 %) | 1, 3, 3, 1 | 0.5 s |
//! | `hyperbolic_dodecahedral_space` | 4,056 | 176 | 176 (4.3 %) | 1, 13, 13, 1 | 0.7 s |
//! | `Hom_C5_K4` (H_1 = Z/2) | 34,560 | 44 | 8 | 1, 1, 1, 1 | 70 ms |
//! | `nc_sphere` | 46,272 | 148 | 4 | 1, 1, 1, 1 | 79 ms |
//! | `Hom_n9_655_compl_K4` | 456,192 | 2,328 (0.5 %) | not searched | 1, 141, 141, 1 | |
//! | `RP4` | 18,000 | 16 | (4-map) | 1, 1, 1, 1, 1 | |
//! | `CP2` | 4,320 | 80 | (4-map) | 3, 3, 3, 1, 1 | |
//! | `K3_16` | 34,560 | 3,656 (10.6 %) | (4-map) | 11, 73, 107, 22, 1 | |
//!
//! The search depends on its seed: over twelve seeds `triple_trefoil_arc` ended at 4 darts
//! ten times and at 108 and 112 darts (4.6 %, 4.8 %) twice, in 0.05 to 2.2 s
//! (`tests/simplify_measure.rs`, `GMAP_SEED`). The previous version (fixed passes, all
//! faces of the spanning tree removed before any edge) stopped at 9 % (600-cell), 34 %
//! (poincaré), 25 % (`Hom_C5_K4`) and 45 % (K3).
//!
//! K3 (a 4-map: no search) stays above 5 %. Where it stops (measured on the result above):
//! one 4-cell, and
//! - all 22 3-cells bound that 4-cell on both sides (no removal merges anything);
//! - of the 107 faces, 82 lie in more than two 3-cells and 25 bound one 3-cell on both
//!   sides; of the 73 edges, 71 lie in more than two faces and 2 in one face twice; the 11
//!   vertices all have degree above 2 (no removal);
//! - 71 edges join two distinct vertices, but each meets some cell twice so that contracting
//!   it would close a cycle of corners (pinch that cell); the 2 others are loops; no face,
//!   3-cell or 4-cell has dual degree 2 (no contraction).
//!
//! No counting bound explains it — H_2 = Z^22 only forces 22 faces, a few hundred darts —
//! so it is a limit of the two moves and of the orders tried, not of the manifold; the
//! search by splits would need the ball check of 3-cells inside a 4-map (C2 by homology of
//! each compacted 3-cell) and splits of 4-cells, which are not implemented.
//!
//! # Cost
//!
//! Every dart carries, per dimension k, the number of its k-cell in the input; cells only
//! merge under the moves (the corner test forbids splits), so a union–find structure per
//! dimension names the current cells, and no partition is recomputed. A move costs
//! O(|c| n²) for the darts of the cell c it removes, plus the corners it has to compare
//! when c meets one k-cell twice; a scan costs O(N α(N)) on top of the moves, and a scan
//! changing nothing ends the reduction. Memory: O(N n) words. The n + 1 partitions of the
//! input (two threads) take about a third of the time, the moves the rest. A search round
//! costs O(N) per split tried on the current small map (every split is checked on the whole
//! map), plus a greedy reduction of the split map. On the 40³ periodic grid (3,072,000 darts,
//! release build, two shared cores) the greedy reduction takes 0.5–0.7 s and the search of
//! its 48-dart result (500 rounds without a gain) about 0.1 s, several times the direct
//! cellular homology of the grid (~0.1–0.2 s): simplification makes homology computations on
//! such grids slower, not faster; its use is the small map itself (and inputs whose direct
//! homology is expensive).

use gmap_core::parallel;
use gmap_core::union_find::UnionFind;
use gmap_core::{DartId, DenseMap, GMap};

use crate::euler::ops;
use crate::rng::SplitMix64;

const NONE: u32 = u32::MAX;

/// What [`simplify`] did.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SimplifyReport {
    /// darts before
    pub darts_before: usize,
    /// darts after
    pub darts_after: usize,
    /// cells per dimension before
    pub cells_before: Vec<usize>,
    /// cells per dimension after
    pub cells_after: Vec<usize>,
    /// number of i-cells removed, per i
    pub removed: Vec<usize>,
    /// number of i-cells contracted, per i
    pub contracted: Vec<usize>,
    /// rounds of scans run by the greedy stage, the last one changing nothing (`removed`,
    /// `contracted` and `rounds` describe that stage, which ends the reduction when there is
    /// no search)
    pub rounds: usize,
    /// rounds of the search made after the greedy stage (see [`SimplifyOptions::search`])
    pub search_rounds: usize,
    /// darts the search removed beyond the greedy stage's result
    pub search_gain: usize,
}

impl SimplifyReport {
    /// `darts_after / darts_before` (0 for an empty map).
    pub fn ratio(&self) -> f64 {
        if self.darts_before == 0 {
            0.0
        } else {
            self.darts_after as f64 / self.darts_before as f64
        }
    }
}

#[derive(Clone)]
struct Work {
    n: usize,
    w: usize,
    a: Vec<u32>,
    alive: Vec<bool>,
    /// `label[k][d]`: the input k-cell of dart d; `uf[k]` merges them.
    label: Vec<Vec<u32>>,
    uf: Vec<UnionFind>,
    /// `free[k][r]`: the k-cell of root r holds a free dart.
    free: Vec<Vec<bool>>,
    /// every free dart of the input is free for `alpha_n` only (a manifold with boundary, no
    /// incomplete cell): boundary edges may then be contracted
    top_free_only: bool,
    /// `exam[k][r]`: last scan that examined the k-cell of root r; `queued` likewise for
    /// the work stack.
    exam: Vec<Vec<u32>>,
    queued: Vec<Vec<u32>>,
    // scratch: membership of the current cell, appearances, corners
    stamp: Vec<u32>,
    tag: u32,
    seen: Vec<u32>,
    seen_tag: u32,
    cstamp: Vec<u32>,
    cid: Vec<u32>,
    ctag: u32,
    cell: Vec<u32>,
    stack: Vec<u32>,
    links: Vec<(u32, u32)>,
    apps: Vec<(u32, u32)>,
    work: Vec<(u8, bool, u32)>,
    moves: u32,
    /// also re-examine the merged neighbour cell after a move
    up: bool,
    removed: Vec<usize>,
    contracted: Vec<usize>,
}

/// Bumps a stamp counter, clearing the stamps when it would wrap.
fn bump(tag: &mut u32, stamps: &mut [u32]) -> u32 {
    if *tag == u32::MAX - 1 {
        stamps.iter_mut().for_each(|s| *s = 0);
        *tag = 0;
    }
    *tag += 1;
    *tag
}

impl Work {
    fn new(map: &DenseMap) -> (Self, Vec<usize>) {
        let n = map.dim();
        let a = map.flat().to_vec();
        let nd = map.dart_count();
        // the n + 1 cell partitions, one task each
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
            work: Vec::new(),
            moves: 0,
            up: false,
            removed: vec![0; n + 1],
            contracted: vec![0; n + 1],
        };
        (work, counts)
    }

    #[inline]
    fn al(&self, d: u32, i: usize) -> u32 {
        self.a[d as usize * self.w + i]
    }

    #[inline]
    fn root(&mut self, k: usize, d: u32) -> u32 {
        let l = self.label[k][d as usize];
        self.uf[k].find(l)
    }

    /// Collects the i-cell of `x0` into `self.cell` (stamped with the returned tag) while
    /// testing the cheap conditions of the move; `None` when one fails. On success the two
    /// neighbour cells (roots in dimension `nb`) are returned.
    fn gather(&mut self, i: usize, remove: bool, x0: u32) -> Option<(u32, [u32; 2])> {
        let n = self.n;
        let nb = if remove { i + 1 } else { i - 1 };
        let nb2 = if remove { (i + 2 <= n).then_some(i + 2) } else { i.checked_sub(2) };
        let tag = bump(&mut self.tag, &mut self.stamp);
        self.cell.clear();
        self.stack.clear();
        self.stamp[x0 as usize] = tag;
        self.stack.push(x0);
        // with the degree condition, alpha_nb is the only involution of the cell that leaves
        // an nb-cell: the darts of the cell lie in the nb-cell of x0 and in that of its image
        let roots = [self.root(nb, x0), self.root(nb, self.al(x0, nb))];
        if roots[0] == roots[1] {
            return None;
        }
        // a contraction joining cells that carry free darts could pinch the space, except
        // for an edge on the boundary of a manifold with boundary: the links of its two
        // vertices are disks glued along the edge's link, an arc on both their boundaries,
        // so the merged vertex is one cell again
        let boundary_edge = !remove && i == 1 && self.top_free_only;
        let ends_free = !remove && (self.free[nb][roots[0] as usize] || self.free[nb][roots[1] as usize]);
        if ends_free && !boundary_edge {
            return None;
        }
        let mut on_boundary = false;
        while let Some(x) = self.stack.pop() {
            self.cell.push(x);
            let y = self.al(x, nb);
            if y == x {
                return None;
            }
            if !remove {
                for j in 0..=n {
                    if self.al(x, j) == x {
                        if boundary_edge && j == n {
                            on_boundary = true;
                        } else {
                            return None;
                        }
                    }
                }
            }
            if let Some(j) = nb2 {
                if self.al(y, j) != self.al(self.al(x, j), nb) {
                    return None;
                }
            }
            for j in 0..=n {
                if j == i {
                    continue;
                }
                let z = self.al(x, j);
                if self.stamp[z as usize] != tag {
                    self.stamp[z as usize] = tag;
                    self.stack.push(z);
                }
            }
        }
        if ends_free && !on_boundary {
            return None;
        }
        Some((tag, roots))
    }

    /// The corner of `x` around its k-cell: the orbit of every involution but `alpha_nb` and
    /// `alpha_k`, named by its smallest dart (cached for the current corner tag).
    fn corner(&mut self, x: u32, nb: usize, k: usize) -> u32 {
        if self.cstamp.is_empty() {
            self.cstamp = vec![0; self.alive.len()];
            self.cid = vec![0; self.alive.len()];
        }
        if self.cstamp[x as usize] == self.ctag {
            return self.cid[x as usize];
        }
        let t = self.ctag;
        let mut members: Vec<u32> = vec![x];
        self.cstamp[x as usize] = t;
        let mut q = 0;
        let mut least = x;
        while q < members.len() {
            let y = members[q];
            q += 1;
            least = least.min(y);
            for j in 0..=self.n {
                if j == nb || j == k {
                    continue;
                }
                let z = self.al(y, j);
                if self.cstamp[z as usize] != t {
                    self.cstamp[z as usize] = t;
                    members.push(z);
                }
            }
        }
        for &y in &members {
            self.cid[y as usize] = least;
        }
        least
    }

    /// For every k-cell (k not i, nb) that the cell in `self.cell` meets more than once, its
    /// appearances must join distinct corners along a forest.
    fn corners_ok(&mut self, i: usize, nb: usize) -> bool {
        let n = self.n;
        for k in 0..=n {
            if k == i || k == nb {
                continue;
            }
            self.apps.clear();
            // the involutions of an appearance, when there are two of them (n = 3)
            let mut pair = [0usize; 2];
            let mut m = 0;
            for j in (0..=n).filter(|&j| j != i && j != k) {
                if m < 2 {
                    pair[m] = j;
                }
                m += 1;
            }
            if m == 2 {
                let [p, q] = pair;
                if p + 2 <= q {
                    // an appearance is {x, a_p x, a_q x, a_p a_q x}: keep its smallest dart
                    for c in 0..self.cell.len() {
                        let x = self.cell[c];
                        let (y, z) = (self.al(x, p), self.al(x, q));
                        if x <= y && x <= z && x <= self.al(y, q) {
                            let r = self.root(k, x);
                            self.apps.push((r, x));
                        }
                    }
                    if !self.forest_of_appearances(nb, k) {
                        return false;
                    }
                    continue;
                }
            }
            let st = bump(&mut self.seen_tag, &mut self.seen);
            for c in 0..self.cell.len() {
                let x = self.cell[c];
                if self.seen[x as usize] == st {
                    continue;
                }
                self.seen[x as usize] = st;
                self.stack.clear();
                self.stack.push(x);
                while let Some(y) = self.stack.pop() {
                    for j in 0..=n {
                        if j == i || j == k {
                            continue;
                        }
                        let z = self.al(y, j);
                        if self.seen[z as usize] != st {
                            self.seen[z as usize] = st;
                            self.stack.push(z);
                        }
                    }
                }
                let r = self.root(k, x);
                self.apps.push((r, x));
            }
            if !self.forest_of_appearances(nb, k) {
                return false;
            }
        }
        true
    }

    /// The forest test on the appearances in `self.apps` (k-cell root, dart), grouped by
    /// k-cell.
    fn forest_of_appearances(&mut self, nb: usize, k: usize) -> bool {
        {
            if self.apps.len() < 2 {
                return true;
            }
            self.apps.sort_unstable();
            let mut s = 0;
            while s < self.apps.len() {
                let mut e = s + 1;
                while e < self.apps.len() && self.apps[e].0 == self.apps[s].0 {
                    e += 1;
                }
                if e - s >= 2 {
                    if self.cstamp.is_empty() {
                        self.cstamp = vec![0; self.alive.len()];
                        self.cid = vec![0; self.alive.len()];
                    }
                    bump(&mut self.ctag, &mut self.cstamp);
                    let mut joins: Vec<(u32, u32)> = Vec::with_capacity(e - s);
                    for t in s..e {
                        let x = self.apps[t].1;
                        let y = self.al(x, nb);
                        let (cx, cy) = (self.corner(x, nb, k), self.corner(y, nb, k));
                        if cx == cy {
                            return false;
                        }
                        joins.push((cx, cy));
                    }
                    if closes_cycle(&joins) {
                        return false;
                    }
                }
                s = e;
            }
        }
        true
    }

    /// Re-links `alpha_i` around the cell in `self.cell` and kills its darts.
    fn collapse(&mut self, i: usize, nb: usize, tag: u32, roots: [u32; 2]) {
        self.links.clear();
        for c in 0..self.cell.len() {
            let x = self.cell[c];
            let y = self.al(x, i);
            if self.stamp[y as usize] == tag {
                continue;
            }
            let mut z = self.al(x, nb);
            let mut t = self.al(z, i);
            let mut steps = 0;
            while self.stamp[t as usize] == tag && t != z && steps <= self.cell.len() {
                z = self.al(t, nb);
                t = self.al(z, i);
                steps += 1;
            }
            let target = if self.stamp[t as usize] == tag { y } else { t };
            self.links.push((y, target));
        }
        for c in 0..self.cell.len() {
            self.alive[self.cell[c] as usize] = false;
        }
        let w = self.w;
        for l in 0..self.links.len() {
            let (y, t) = self.links[l];
            self.a[y as usize * w + i] = t;
            self.a[t as usize * w + i] = y;
            if y == t {
                for k in 0..=self.n {
                    let r = self.root(k, y);
                    self.free[k][r as usize] = true;
                }
            }
        }
        // the merged cell holds a free dart if either did, and counts as examined in the
        // current scan if the cell across alpha_nb (root r1) did
        let (r0, r1) = (roots[0] as usize, roots[1] as usize);
        let r = self.uf[nb].link_roots(roots[0], roots[1]) as usize;
        self.free[nb][r] = self.free[nb][r0] || self.free[nb][r1];
        self.exam[nb][r] = self.exam[nb][r1];
        self.moves += 1;
    }

    /// Tries to remove (or contract) the i-cell of `x`; on success queues the cells whose
    /// degree the move lowered.
    fn try_move(&mut self, i: usize, remove: bool, x: u32) -> bool {
        if !self.alive[x as usize] {
            return false;
        }
        let Some((tag, roots)) = self.gather(i, remove, x) else {
            return false;
        };
        let nb = if remove { i + 1 } else { i - 1 };
        if !self.corners_ok(i, nb) {
            return false;
        }
        self.collapse(i, nb, tag, roots);
        if remove {
            self.removed[i] += 1;
        } else {
            self.contracted[i] += 1;
        }
        // removing an i-cell lowers the degree of the (i-1)-cells on its border; contracting
        // one lowers the dual degree of the (i+1)-cells around it
        let next = if remove { i.checked_sub(1) } else { (i < self.n).then_some(i + 1) };
        // and the merged nb-cell may now separate two distinct cells itself
        if self.up && ((remove && nb < self.n) || (!remove && nb >= 1)) {
            let y = self.links.first().map(|l| l.0);
            if let Some(y) = y {
                self.work.push((nb as u8, remove, y));
            }
        }
        if let Some(k) = next {
            let mv = self.moves;
            for l in 0..self.links.len() {
                let y = self.links[l].0;
                let r = self.root(k, y) as usize;
                if self.queued[k][r] != mv {
                    self.queued[k][r] = mv;
                    self.work.push((k as u8, remove, y));
                }
            }
        }
        true
    }

    /// Runs the work stack dry.
    fn drain(&mut self) {
        while let Some((k, remove, y)) = self.work.pop() {
            self.try_move(k as usize, remove, y);
        }
    }

    /// One scan of the i-cells, in the order of `order` (live darts); returns the number of
    /// moves made.
    fn scan(&mut self, i: usize, remove: bool, order: &[u32], scan_id: u32) -> u32 {
        let before = self.moves;
        for &d in order {
            if !self.alive[d as usize] {
                continue;
            }
            let r = self.root(i, d) as usize;
            if self.exam[i][r] == scan_id {
                continue;
            }
            self.exam[i][r] = scan_id;
            if self.try_move(i, remove, d) {
                self.drain();
            }
        }
        self.moves - before
    }

    /// Rounds of scans in the given order of moves until one changes nothing; returns the
    /// number of rounds.
    fn run(&mut self, steps: &[(usize, bool)], mut order: Vec<u32>) -> usize {
        let mut rounds = 0;
        let mut scan_id = 0;
        loop {
            rounds += 1;
            let mut changed = 0;
            for &(i, rem) in steps {
                scan_id += 1;
                changed += self.scan(i, rem, &order, scan_id);
            }
            if changed == 0 {
                return rounds;
            }
            order.retain(|&d| self.alive[d as usize]);
        }
    }

    fn compact(&self) -> DenseMap {
        let mut newid = vec![NONE; self.alive.len()];
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

/// Whether the edges `joins` (pairs of corner names) contain a cycle.
fn closes_cycle(joins: &[(u32, u32)]) -> bool {
    let mut ids: Vec<u32> = joins.iter().flat_map(|&(a, b)| [a, b]).collect();
    ids.sort_unstable();
    ids.dedup();
    let mut uf = UnionFind::new(ids.len());
    joins.iter().any(|&(a, b)| {
        let ia = ids.binary_search(&a).expect("listed") as u32;
        let ib = ids.binary_search(&b).expect("listed") as u32;
        !uf.union(ia, ib)
    })
}

/// How [`simplify_with`] searches.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SimplifyOptions {
    /// Number of runs, each from a fresh copy of the input; the smallest result is kept.
    /// Run 0 scans removals first and run 1 contractions first, both in dart order; later
    /// runs alternate the two in a random order of the darts drawn from `seed`.
    pub tries: usize,
    /// Seed of the random orders (a SplitMix64 generator: the result is deterministic).
    pub seed: u64,
    /// Rounds of search after the greedy runs, for 3-maps whose cells are balls (C1 and
    /// χ = 2 for every volume); 0 for none. A round splits one to three cells of the smallest
    /// map so far (a face across a volume, an edge across a face: subdivisions, which keep
    /// the space), checks that every cell is still a ball, simplifies the result again (two
    /// greedy runs) and keeps it when it has at most as many darts. The splits move cells
    /// past each other where removals and contractions alone are stuck. The search stops
    /// after `search` rounds or when the split maps it has simplified hold `256 · search` darts
    /// in all (chains and their ends: see the module documentation). Greedy results of more
    /// than 1,024 darts are not searched.
    pub search: usize,
}

impl SimplifyOptions {
    /// The choice of [`simplify`]: eight runs for maps of at most 2^16 darts, two (removals
    /// first, contractions first) up to 2^18, one beyond; 4000 rounds of search for 3-maps
    /// (its cost follows the size of the reduced map, not of the input). The first run does the work in
    /// near-linear time; the others pay off on small, hard inputs (triangulated manifolds with
    /// torsion, 4-manifolds), where they cost a few milliseconds.
    pub fn for_map(map: &DenseMap) -> Self {
        let n = map.dart_count();
        let tries = if n <= 1 << 16 {
            8
        } else if n <= 1 << 18 {
            2
        } else {
            1
        };
        SimplifyOptions { tries, seed: 0x5eed_9a3a, search: if map.dim() == 3 { 4000 } else { 0 } }
    }
}

/// Reduces `map` by removals and contractions of cells (see the module documentation) and
/// returns the reduced map with a report. The reduced map has the same homology as `map`
/// whenever the cells of `map` are homology balls (C1, C2 of DESIGN.md), and its cells are
/// again homology balls, so the cellular method applies to it. Points are dropped.
/// Equivalent to [`simplify_with`] and [`SimplifyOptions::for_map`].
///
/// Precondition: `map` is valid (BO Def. 1). Cells on a boundary (free darts) are left in
/// place. O(T · R · N n² α(N)) time for T tries of R rounds of scans (R is two or three in
/// practice), O(N n) extra memory.
///
/// ```
/// use gmap_core::GMap;
/// use gmap_ops::euler::simplify;
/// // a hexagon as a 1-map: six vertices, six edges, a circle
/// let mut g = GMap::new(1);
/// let d: Vec<_> = (0..12).map(|_| g.create_dart()).collect();
/// for k in 0..6 {
///     g.sew(d[2 * k], d[2 * k + 1], 0);
///     g.sew(d[2 * k + 1], d[(2 * k + 2) % 12], 1);
/// }
/// let (small, report) = simplify(&g.to_dense().0);
/// assert_eq!(small.cell_counts(), vec![1, 1]); // one vertex, one loop
/// assert_eq!((report.darts_before, report.darts_after), (12, 2));
/// ```
pub fn simplify(map: &DenseMap) -> (DenseMap, SimplifyReport) {
    simplify_with(map, &SimplifyOptions::for_map(map))
}

/// [`simplify`] with an explicit number of runs and seed (at least one run is made).
pub fn simplify_with(map: &DenseMap, options: &SimplifyOptions) -> (DenseMap, SimplifyReport) {
    let n = map.dim();
    let nd = map.dart_count();
    let (base, cells_before) = Work::new(map);
    let mut base = Some(base);
    let tries = options.tries.max(1);
    let removals: Vec<(usize, bool)> = (0..n).rev().map(|i| (i, true)).collect();
    let contractions: Vec<(usize, bool)> = (1..=n).map(|i| (i, false)).collect();
    let mut rng = SplitMix64::new(options.seed);
    let mut best: Option<(Work, usize)> = None;
    for t in 0..tries {
        let steps: Vec<(usize, bool)> = if t % 2 == 0 {
            removals.iter().chain(&contractions).copied().collect()
        } else {
            contractions.iter().chain(&removals).copied().collect()
        };
        let mut order: Vec<u32> = (0..nd as u32).collect();
        if t >= 4 {
            rng.shuffle(&mut order);
        }
        let mut work =
            if t + 1 == tries { base.take().expect("kept for the last run") } else { base.clone().expect("kept") };
        work.up = (t / 2) % 2 == 1;
        let rounds = work.run(&steps, order);
        let live = work.alive.iter().filter(|&&x| x).count();
        let better = match &best {
            None => true,
            Some((b, _)) => live < b.alive.iter().filter(|&&x| x).count(),
        };
        if better {
            best = Some((work, rounds));
        }
    }
    let (work, rounds) = best.expect("at least one run");
    let out = work.compact();
    debug_assert!(out.validate().is_ok(), "simplify broke validity");
    let greedy = out.dart_count();
    let (out, search_rounds) = search(out, options, &mut rng);
    let report = SimplifyReport {
        darts_before: nd,
        darts_after: out.dart_count(),
        cells_before,
        cells_after: out.cell_counts(),
        removed: work.removed,
        contracted: work.contracted,
        rounds,
        search_rounds,
        search_gain: greedy - out.dart_count(),
    };
    (out, report)
}

/// Whether every cell of a 3-map is a ball as the cellular method demands: C1 in every
/// dimension and a boundary of Euler characteristic 2 for every volume (faces and edges are
/// then balls by themselves). O(N).
fn cells_are_balls(map: &DenseMap) -> bool {
    map.oriented_cells_3d().is_some_and(|c| c.euler.iter().all(|&x| x == 2))
}

/// Splits up to `count` random cells of `g` (faces across volumes with seven chances in
/// ten, else edges across faces), trying at most 400 random placements; the number made.
fn split_random_cells(g: &mut GMap, count: usize, rng: &mut SplitMix64) -> usize {
    let mut made = 0;
    let mut darts: Vec<DartId> = g.darts().collect();
    for _ in 0..400 {
        if made == count {
            break;
        }
        if made > 0 && darts.len() != g.dart_count() {
            darts = g.darts().collect();
        }
        let darts = &darts;
        let pick = |rng: &mut SplitMix64| darts[rng.below(darts.len())];
        if rng.below(10) < 7 {
            // a face across a volume along the closed path of one to three edge sides
            let k = 1 + rng.below(3);
            let seeds: Vec<DartId> = (0..k).map(|_| pick(rng)).collect();
            if ops::split_cell_quietly(g, &seeds, 3) {
                made += 1;
            }
        } else {
            // an edge across the face of d1, to a corner of that face
            let d1 = pick(rng);
            let mut ring = vec![d1];
            let mut x = d1;
            loop {
                let y = g.alpha(x, 0);
                ring.push(y);
                x = g.alpha(y, 1);
                if x == d1 || x == y || ring.len() > darts.len() {
                    break;
                }
                ring.push(x);
            }
            let d2 = ring[rng.below(ring.len())];
            if ops::insert_edge_quietly(g, d1, d2) {
                made += 1;
            }
        }
    }
    made
}

/// Greedy results above this many darts are not searched: every split is checked on the
/// whole map, so a round costs O(N) per attempt, and such results are already far below
/// the input (`Hom_n9_655_compl_K4`: 2,328 of 456,192 darts; searching it takes 11 s for
/// 0.29 % instead of 0.51 %).
const SEARCH_MAX_DARTS: usize = 1 << 10;

/// The search of [`SimplifyOptions::search`] from the greedy result `map`; the smallest map
/// found and the rounds made.
///
/// Chains of rounds start from `map`; a chain keeps a split-and-simplify round when the map
/// has at most as many darts, and ends after `search / 8` rounds without fewer darts. A new
/// chain starts (at most four) while the last one improved on the best map so far: chains
/// that find their way down usually do so within a few hundred rounds, and one that does
/// not sits on a plateau that more random splits rarely leave. Splits grow with the map:
/// up to a third of its darts' count, between 3 and 40.
fn search(map: DenseMap, options: &SimplifyOptions, rng: &mut SplitMix64) -> (DenseMap, usize) {
    if map.dim() != 3
        || options.search == 0
        || map.dart_count() == 0
        || map.dart_count() > SEARCH_MAX_DARTS
        || !cells_are_balls(&map)
    {
        return (map, 0);
    }
    let inner = SimplifyOptions { tries: 2, seed: 0, search: 0 };
    let budget = options.search.saturating_mul(256);
    let patience = options.search.div_ceil(8);
    let mut best = map.clone();
    let (mut spent, mut rounds) = (0usize, 0);
    for _chain in 0..4 {
        let mut cur = map.clone();
        let mut since = 0;
        while rounds < options.search && since < patience && spent < budget {
            rounds += 1;
            since += 1;
            let (mut g, _) = GMap::from_dense(&cur);
            let most = (cur.dart_count() / 3).clamp(3, 40);
            let kicks = 1 + rng.below(most);
            if split_random_cells(&mut g, kicks, rng) == 0 {
                continue;
            }
            let split = g.to_dense().0;
            spent += split.dart_count();
            if !cells_are_balls(&split) {
                continue;
            }
            let (small, _) = simplify_with(&split, &SimplifyOptions { seed: rng.next_u64(), ..inner });
            if small.dart_count() <= cur.dart_count() && cells_are_balls(&small) {
                if small.dart_count() < cur.dart_count() {
                    since = 0;
                }
                cur = small;
            }
        }
        if cur.dart_count() >= best.dart_count() {
            break;
        }
        best = cur;
    }
    (best, rounds)
}
