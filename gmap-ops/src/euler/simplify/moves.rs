//! One removal or contraction on the working copy: the test (degree 2, two distinct
//! neighbour cells, free darts, the corner test) and the re-linking of `alpha_i` around
//! the cell, with the bookkeeping of the merged cells and of the cells to re-examine.

use gmap_core::union_find::UnionFind;

use super::work::{bump, Work};
use crate::euler::ops::Move;

impl Work {
    /// Collects the i-cell of `x0` into `self.cell` (stamped with the returned tag) while
    /// testing the cheap conditions of the move; `None` when one fails. On success the two
    /// neighbour cells (roots in dimension `nb`) are returned.
    fn gather(&mut self, i: usize, kind: Move, x0: u32) -> Option<(u32, [u32; 2])> {
        let n = self.n;
        let contract = kind == Move::Contract;
        let nb = kind.neighbour(i);
        let nb2 = kind.beyond(i, n);
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
        let boundary_edge = contract && i == 1 && self.top_free_only;
        let ends_free = contract && (self.free[nb][roots[0] as usize] || self.free[nb][roots[1] as usize]);
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
            if contract {
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
    pub(super) fn try_move(&mut self, i: usize, kind: Move, x: u32) -> bool {
        if !self.alive[x as usize] {
            return false;
        }
        let Some((tag, roots)) = self.gather(i, kind, x) else {
            return false;
        };
        let nb = kind.neighbour(i);
        if !self.corners_ok(i, nb) {
            return false;
        }
        self.collapse(i, nb, tag, roots);
        match kind {
            Move::Remove => self.removed[i] += 1,
            Move::Contract => self.contracted[i] += 1,
        }
        // removing an i-cell lowers the degree of the (i-1)-cells on its border; contracting
        // one lowers the dual degree of the (i+1)-cells around it
        let next = match kind {
            Move::Remove => i.checked_sub(1),
            Move::Contract => (i < self.n).then_some(i + 1),
        };
        // and the merged nb-cell may now separate two distinct cells itself
        let nb_movable = match kind {
            Move::Remove => nb < self.n,
            Move::Contract => nb >= 1,
        };
        if self.up && nb_movable {
            let y = self.links.first().map(|l| l.0);
            if let Some(y) = y {
                self.pending.push((nb as u8, kind, y));
            }
        }
        if let Some(k) = next {
            let mv = self.moves;
            for l in 0..self.links.len() {
                let y = self.links[l].0;
                let r = self.root(k, y) as usize;
                if self.queued[k][r] != mv {
                    self.queued[k][r] = mv;
                    self.pending.push((k as u8, kind, y));
                }
            }
        }
        true
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
