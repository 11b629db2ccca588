//! Disjoint sets over dense `u32` indices: the one union-find of the workspace.
//!
//! Whole-map scans (orbit counts, orientability, the cells of 3-maps, vertex classes of
//! complexes, contraction bookkeeping) all merge classes of numbered items. Two forms:
//!
//! * [`UnionFind`]: plain classes. [`UnionFind::find`] halves the path it walks;
//!   [`UnionFind::union`] makes the smaller root the root of the merged class, so the root
//!   of a class is its smallest member and results do not depend on the order of merges.
//! * [`ParityUnionFind`]: classes whose members carry a parity (a colour `±1`) relative to
//!   their root; [`ParityUnionFind::join`] demands a given parity difference between two
//!   items and reports a conflict. Orientability (BO Def. 7) and the orientation of cells
//!   are this problem: every link demands opposite colours on its two darts.
//!
//! Both can be split into disjoint ranges ([`UnionFind::split_at_mut`],
//! [`ParityUnionFind::split_at_mut`]) scanned on separate threads, each range holding items
//! `base..base + len` and linking only inside itself; the links across the cut are then
//! joined on the whole.
//!
//! Costs: `find` and `join` run in amortised near-constant time (path halving with union by
//! smaller index; in the scans of this workspace the trees stay shallow because items are
//! merged in increasing order). Memory: one `u32` per item, plus one `bool` with parities.
//!
//! ```
//! use gmap_core::union_find::{ParityUnionFind, UnionFind};
//! let mut uf = UnionFind::new(5);
//! assert!(uf.union(3, 1));
//! assert!(uf.union(1, 4));
//! assert!(!uf.union(4, 3));
//! assert_eq!(uf.find(4), 1); // the smallest member is the root
//! assert_eq!(uf.class_count(), 3);
//!
//! // a triangle of "opposite colour" demands is odd: the third one conflicts
//! let mut p = ParityUnionFind::new(3);
//! assert!(p.join(0, 1, true));
//! assert!(p.join(1, 2, true));
//! assert!(!p.join(2, 0, true));
//! ```

/// Plain disjoint sets over `0..len`. See the [module docs](self).
#[derive(Clone, Debug, Default)]
pub struct UnionFind {
    parent: Vec<u32>,
}

impl UnionFind {
    /// `len` singleton classes. O(len).
    ///
    /// # Panics
    /// If `len` exceeds `u32::MAX` (items are numbered by `u32`).
    pub fn new(len: usize) -> Self {
        let len = u32::try_from(len).expect("union-find items are numbered by u32");
        UnionFind { parent: (0..len).collect() }
    }

    /// Number of items.
    pub fn len(&self) -> usize {
        self.parent.len()
    }

    /// Whether there is no item.
    pub fn is_empty(&self) -> bool {
        self.parent.is_empty()
    }

    /// Adds a singleton class and returns its item.
    pub fn push(&mut self) -> u32 {
        let x = self.parent.len() as u32;
        self.parent.push(x);
        x
    }

    /// The root of the class of `x`.
    #[inline]
    pub fn find(&mut self, x: u32) -> u32 {
        self.view().find(x)
    }

    /// Merges the classes of `a` and `b`; `true` if they were distinct.
    #[inline]
    pub fn union(&mut self, a: u32, b: u32) -> bool {
        self.view().union(a, b)
    }

    /// Merges two classes given by their roots and returns the new root (the smaller).
    /// Precondition: `a` and `b` are distinct roots.
    #[inline]
    pub fn link_roots(&mut self, a: u32, b: u32) -> u32 {
        self.view().link_roots(a, b)
    }

    /// Makes `p` the parent of `x`, whatever `x`'s class was: the streaming scans reuse one
    /// forest layer after layer, re-seeding its items from labels. Precondition: `p ≤ x` and
    /// `p` a root or pointing down to one (then every path still ends in a root; the classes of
    /// other items that went through `x` are not updated, so re-seed whole ranges at once).
    #[inline]
    pub fn set_parent(&mut self, x: u32, p: u32) {
        debug_assert!(p <= x);
        self.parent[x as usize] = p;
    }

    /// Whether `a` and `b` are in one class.
    pub fn same(&mut self, a: u32, b: u32) -> bool {
        self.find(a) == self.find(b)
    }

    /// Number of classes. O(len).
    pub fn class_count(&self) -> usize {
        self.parent.iter().enumerate().filter(|&(x, &p)| x as u32 == p).count()
    }

    /// The whole as one range starting at item 0.
    pub fn view(&mut self) -> Sets<'_> {
        Sets { parent: &mut self.parent, base: 0 }
    }

    /// Two disjoint ranges, items `0..mid` and `mid..len`, for scans on two threads.
    pub fn split_at_mut(&mut self, mid: usize) -> (Sets<'_>, Sets<'_>) {
        let (a, b) = self.parent.split_at_mut(mid);
        (Sets { parent: a, base: 0 }, Sets { parent: b, base: mid as u32 })
    }

    /// The parent array, given back for its memory (a scan done with the classes reuses it
    /// for a `u32` per item).
    pub fn into_parents(self) -> Vec<u32> {
        self.parent
    }

    /// Class labels `0..k` in order of each class's smallest item, and `k`. O(len).
    pub fn labels(&mut self) -> (Vec<u32>, usize) {
        let n = self.parent.len();
        let mut label = vec![u32::MAX; n];
        let mut k = 0u32;
        for x in 0..n as u32 {
            let r = self.find(x) as usize;
            if label[r] == u32::MAX {
                label[r] = k;
                k += 1;
            }
            label[x as usize] = label[r];
        }
        (label, k as usize)
    }
}

/// A range `base..base + len` of a [`UnionFind`], borrowed for a scan (possibly on its own
/// thread). Items outside the range must not be named.
#[derive(Debug)]
pub struct Sets<'a> {
    parent: &'a mut [u32],
    base: u32,
}

impl Sets<'_> {
    /// The root of the class of `x`, halving the path on the way.
    #[inline]
    pub fn find(&mut self, mut x: u32) -> u32 {
        let b = self.base;
        loop {
            let p = self.parent[(x - b) as usize];
            if p == x {
                return x;
            }
            let g = self.parent[(p - b) as usize];
            self.parent[(x - b) as usize] = g;
            x = g;
        }
    }

    /// Merges the classes of `a` and `b`; `true` if they were distinct.
    #[inline]
    pub fn union(&mut self, a: u32, b: u32) -> bool {
        let (ra, rb) = (self.find(a), self.find(b));
        if ra == rb {
            return false;
        }
        self.link_roots(ra, rb);
        true
    }

    /// Merges two classes given by their distinct roots; the smaller becomes the root.
    #[inline]
    pub fn link_roots(&mut self, a: u32, b: u32) -> u32 {
        debug_assert_ne!(a, b);
        let (lo, hi) = if a < b { (a, b) } else { (b, a) };
        self.parent[(hi - self.base) as usize] = lo;
        lo
    }
}

/// Disjoint sets over `0..len` whose items carry a parity relative to their root. See the
/// [module docs](self).
#[derive(Clone, Debug, Default)]
pub struct ParityUnionFind {
    parent: Vec<u32>,
    flip: Vec<bool>,
}

impl ParityUnionFind {
    /// `len` singleton classes, each of parity `false`. O(len).
    ///
    /// # Panics
    /// If `len` exceeds `u32::MAX`.
    pub fn new(len: usize) -> Self {
        let n = u32::try_from(len).expect("union-find items are numbered by u32");
        ParityUnionFind { parent: (0..n).collect(), flip: vec![false; len] }
    }

    /// An empty structure with room for `cap` items.
    pub fn with_capacity(cap: usize) -> Self {
        ParityUnionFind { parent: Vec::with_capacity(cap), flip: Vec::with_capacity(cap) }
    }

    /// Number of items.
    pub fn len(&self) -> usize {
        self.parent.len()
    }

    /// Whether there is no item.
    pub fn is_empty(&self) -> bool {
        self.parent.is_empty()
    }

    /// Adds a singleton class and returns its item.
    pub fn push(&mut self) -> u32 {
        let x = self.parent.len() as u32;
        self.parent.push(x);
        self.flip.push(false);
        x
    }

    /// The root of `x` and the parity of `x` relative to it.
    #[inline]
    pub fn find(&mut self, x: u32) -> (u32, bool) {
        self.view().find(x)
    }

    /// Demands that the parities of `x` and `y` differ by `flip` (`true`: opposite),
    /// merging their classes; `false` on a conflict with earlier demands.
    #[inline]
    pub fn join(&mut self, x: u32, y: u32, flip: bool) -> bool {
        self.view().join(x, y, flip)
    }

    /// The whole as one range starting at item 0.
    pub fn view(&mut self) -> ParitySets<'_> {
        ParitySets { parent: &mut self.parent, flip: &mut self.flip, base: 0 }
    }

    /// Two disjoint ranges, items `0..mid` and `mid..len`, for scans on two threads.
    pub fn split_at_mut(&mut self, mid: usize) -> (ParitySets<'_>, ParitySets<'_>) {
        let (pa, pb) = self.parent.split_at_mut(mid);
        let (fa, fb) = self.flip.split_at_mut(mid);
        (ParitySets { parent: pa, flip: fa, base: 0 }, ParitySets { parent: pb, flip: fb, base: mid as u32 })
    }

    /// Disjoint consecutive ranges covering all items, of the given lengths (which must add
    /// up to [`len`](Self::len)), for scans on as many threads.
    pub fn split_mut(&mut self, lens: &[usize]) -> Vec<ParitySets<'_>> {
        assert_eq!(lens.iter().sum::<usize>(), self.parent.len(), "range lengths must cover the items");
        let (mut parent, mut flip) = (&mut self.parent[..], &mut self.flip[..]);
        let mut base = 0u32;
        let mut out = Vec::with_capacity(lens.len());
        for &l in lens {
            let (pa, pr) = std::mem::take(&mut parent).split_at_mut(l);
            let (fa, fr) = std::mem::take(&mut flip).split_at_mut(l);
            out.push(ParitySets { parent: pa, flip: fa, base });
            (parent, flip) = (pr, fr);
            base += l as u32;
        }
        out
    }
}

/// A range `base..base + len` of a [`ParityUnionFind`], borrowed for a scan.
#[derive(Debug)]
pub struct ParitySets<'a> {
    parent: &'a mut [u32],
    flip: &'a mut [bool],
    base: u32,
}

impl ParitySets<'_> {
    /// The root of `x` and the parity of `x` relative to it, halving the path.
    #[inline]
    pub fn find(&mut self, mut x: u32) -> (u32, bool) {
        let b = self.base;
        let mut acc = false;
        loop {
            let p = self.parent[(x - b) as usize];
            if p == x {
                return (x, acc);
            }
            let g = self.parent[(p - b) as usize];
            if g == p {
                return (p, acc ^ self.flip[(x - b) as usize]);
            }
            // x skips to its grandparent, carrying the parity of both steps
            let f = self.flip[(x - b) as usize] ^ self.flip[(p - b) as usize];
            self.parent[(x - b) as usize] = g;
            self.flip[(x - b) as usize] = f;
            acc ^= f;
            x = g;
        }
    }

    /// Demands that the parities of `x` and `y` differ by `flip`; `false` on a conflict.
    #[inline]
    pub fn join(&mut self, x: u32, y: u32, flip: bool) -> bool {
        let (a, fa) = self.find(x);
        let (b, fb) = self.find(y);
        if a == b {
            return fa ^ fb == flip;
        }
        self.link_roots(a, b, fa ^ fb ^ flip, false);
        true
    }

    /// Merges the classes of the distinct roots `a` and `b`, whose parities must differ by
    /// `flip`; the smaller root becomes the root. Returns the new root and the parity to it
    /// of an item that had parity `f` to `a` (so a scan can keep its current item's root
    /// without another [`find`](Self::find)).
    #[inline]
    pub fn link_roots(&mut self, a: u32, b: u32, flip: bool, f: bool) -> (u32, bool) {
        debug_assert_ne!(a, b, "link_roots takes two distinct roots");
        let (lo, hi) = if a < b { (a, b) } else { (b, a) };
        self.parent[(hi - self.base) as usize] = lo;
        self.flip[(hi - self.base) as usize] = flip;
        (lo, if a == lo { f } else { f ^ flip })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// Reference classes by relabelling a label vector on every union.
    fn naive(n: usize, pairs: &[(u32, u32)]) -> Vec<usize> {
        let mut label: Vec<usize> = (0..n).collect();
        for &(a, b) in pairs {
            let (la, lb) = (label[a as usize], label[b as usize]);
            for l in label.iter_mut() {
                if *l == lb {
                    *l = la;
                }
            }
        }
        label
    }

    proptest! {
        #[test]
        fn plain_matches_naive(n in 1usize..40, raw in prop::collection::vec((0u32..40, 0u32..40), 0..60)) {
            let pairs: Vec<(u32, u32)> = raw.into_iter().map(|(a, b)| (a % n as u32, b % n as u32)).collect();
            let mut uf = UnionFind::new(n);
            for &(a, b) in &pairs {
                uf.union(a, b);
            }
            let label = naive(n, &pairs);
            for x in 0..n as u32 {
                for y in 0..n as u32 {
                    prop_assert_eq!(uf.same(x, y), label[x as usize] == label[y as usize]);
                }
                // the root is the smallest member of the class
                let r = uf.find(x);
                prop_assert_eq!(r, (0..n as u32).find(|&z| label[z as usize] == label[x as usize]).unwrap());
            }
            let distinct: std::collections::BTreeSet<usize> = label.iter().copied().collect();
            prop_assert_eq!(uf.class_count(), distinct.len());
            prop_assert_eq!(uf.labels().1, distinct.len());
        }

        #[test]
        fn parity_matches_two_colouring(n in 1usize..30, raw in prop::collection::vec((0u32..30, 0u32..30, any::<bool>()), 0..50)) {
            // reference: a colouring by breadth-first search over the accepted demands
            let mut p = ParityUnionFind::new(n);
            let mut accepted: Vec<(u32, u32, bool)> = Vec::new();
            for (a, b, f) in raw {
                let (a, b) = (a % n as u32, b % n as u32);
                let ok = p.join(a, b, f);
                // a conflict means the demands so far plus this one have no colouring
                let mut trial = accepted.clone();
                trial.push((a, b, f));
                prop_assert_eq!(ok, colourable(n, &trial));
                if ok {
                    accepted.push((a, b, f));
                }
            }
            for &(a, b, f) in &accepted {
                let ((ra, pa), (rb, pb)) = (p.find(a), p.find(b));
                prop_assert_eq!(ra, rb);
                prop_assert_eq!(pa ^ pb, f);
            }
        }
    }

    fn colourable(n: usize, demands: &[(u32, u32, bool)]) -> bool {
        let mut colour: Vec<Option<bool>> = vec![None; n];
        for s in 0..n {
            if colour[s].is_some() {
                continue;
            }
            colour[s] = Some(false);
            let mut stack = vec![s];
            while let Some(x) = stack.pop() {
                let cx = colour[x].unwrap();
                for &(a, b, f) in demands {
                    let (a, b) = (a as usize, b as usize);
                    for (u, v) in [(a, b), (b, a)] {
                        if u == x {
                            match colour[v] {
                                None => {
                                    colour[v] = Some(cx ^ f);
                                    stack.push(v);
                                }
                                Some(cv) if cv != cx ^ f => return false,
                                _ => {}
                            }
                        }
                    }
                }
            }
        }
        true
    }

    #[test]
    fn split_ranges_then_join_across() {
        let mut p = ParityUnionFind::new(6);
        {
            let (mut lo, mut hi) = p.split_at_mut(3);
            assert!(lo.join(0, 1, true));
            assert!(lo.join(1, 2, true));
            assert!(hi.join(3, 4, true));
            assert!(hi.join(4, 5, false));
        }
        assert!(p.join(2, 3, true));
        // colours 0:+ 1:- 2:+ 3:- 4:+ 5:+
        assert_eq!(p.find(5), (0, false));
        assert_eq!(p.find(3), (0, true));
        assert!(!p.join(0, 5, true));
    }
}
