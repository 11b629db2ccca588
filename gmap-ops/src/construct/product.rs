//! The product of a profile with an edge, made inside an editable map: the one building
//! block of every extrusion ([`super::extrude`]) and of the revolution ([`super::revolve`]).
//!
//! The layout is [`crate::build::extrude`]'s: a profile dart `x` of dimension `p` gives
//! `2 (p + 1)` darts `(x, k, s)`, `1 <= k <= p + 1`, `s ∈ {0, 1}`, dart `(x, k, s)` being the
//! flag `c_0 × s < … < c_{k-1} × s < c_{k-1} × I < … < c_p × I` over the flag of `x`. The
//! darts `(x, p + 1, s)` are the copy `P × {s}` and are `alpha_{p+1}`-free: an extrusion
//! sews the bottom copy to the profile, a revolution chains the copies.

use rustc_hash::FxHashMap as HashMap;

use gmap_core::{AlphaSet, Attributes, DartId, GMap, Point};

/// The darts of a profile and their links inside it.
pub(super) struct Profile {
    /// the darts, breadth first from the dart given
    pub(super) darts: Vec<DartId>,
    /// the profile's dimension p
    pub(super) p: usize,
    /// `p + 1` entries per dart: the profile index of `alpha_j(x)`, `j <= p`; `x`'s own index
    /// when `x` is j-free or the link leaves the profile
    rows: Vec<u32>,
}

impl Profile {
    /// The orbit of `d` under `alpha_0..alpha_{inside - 1}` as a profile of dimension `p`
    /// (`inside` is `p` for a cell, whose `alpha_p` links go to other cells, and `p + 1` for
    /// a component). O(size · p).
    pub(super) fn new<A: Attributes>(g: &GMap<A>, d: DartId, p: usize, inside: usize) -> Profile {
        let set = if inside == 0 { AlphaSet::EMPTY } else { AlphaSet::range(0, inside - 1) };
        let darts = g.orbit(d, set);
        let index: HashMap<DartId, u32> = darts.iter().enumerate().map(|(k, &x)| (x, k as u32)).collect();
        let mut rows = Vec::with_capacity(darts.len() * (p + 1));
        for (k, &x) in darts.iter().enumerate() {
            for j in 0..=p {
                let y = if j < inside { g.alpha(x, j) } else { x };
                rows.push(index.get(&y).copied().unwrap_or(k as u32));
            }
        }
        Profile { darts, p, rows }
    }

    /// The number of darts a slab over the profile holds.
    pub(super) fn slab_len(&self) -> usize {
        self.darts.len() * 2 * (self.p + 1)
    }

    /// Position of dart `(x, k, s)` in a slab.
    #[inline]
    pub(super) fn at(&self, x: usize, k: usize, s: usize) -> usize {
        x * 2 * (self.p + 1) + 2 * (k - 1) + s
    }

    fn row(&self, x: usize, j: usize) -> usize {
        self.rows[x * (self.p + 1) + j] as usize
    }
}

/// Makes the darts of `P × I` in `g` and links them as the product does, inside the slab
/// only (the copies `P × {0}` and `P × {1}` stay `alpha_{p+1}`-free). With `reuse`, the
/// profile's own darts play the bottom copy `(x, p + 1, 0)`: their `alpha_0..alpha_{p-1}`
/// stay, their `alpha_p` moves to the slab's side darts (the profile's `alpha_p` links move
/// to the side darts' `alpha_{p+1}`). Returns the slab's darts by [`Profile::at`].
/// Attributes are not reconciled. O(size · p²).
pub(super) fn make_slab<A: Attributes>(g: &mut GMap<A>, prof: &Profile, reuse: bool) -> Vec<DartId> {
    let p = prof.p;
    let mut slab = Vec::with_capacity(prof.slab_len());
    for (x, &px) in prof.darts.iter().enumerate() {
        for k in 1..=p + 1 {
            for s in 0..2 {
                let reused = reuse && k == p + 1 && s == 0;
                debug_assert_eq!(slab.len(), prof.at(x, k, s));
                slab.push(if reused { px } else { g.create_dart() });
            }
        }
    }
    for x in 0..prof.darts.len() {
        for k in 1..=p + 1 {
            for s in 0..2 {
                let me = prof.at(x, k, s);
                for j in 0..=p + 1 {
                    let target = if j + 1 < k {
                        prof.at(prof.row(x, j), k, s)
                    } else if j + 1 == k {
                        if k >= 2 {
                            prof.at(x, k - 1, s)
                        } else {
                            prof.at(x, 1, 1 - s)
                        }
                    } else if j == k {
                        if k <= p {
                            prof.at(x, k + 1, s)
                        } else {
                            me
                        }
                    } else {
                        prof.at(prof.row(x, j - 1), k, s)
                    };
                    let (a, b) = (slab[me], slab[target]);
                    if g.alpha(a, j) == b {
                        continue;
                    }
                    if target == me {
                        g.unlink(a, j);
                    } else if target > me {
                        g.link(a, b, j);
                    }
                }
            }
        }
    }
    slab
}

/// Gives every vertex of the copy `P × {s}` of `slab` that has no point the image by `f` of
/// the point of the profile dart below it; vertices whose profile dart has no point stay
/// without. Returns the first dart whose vertex could not be placed, if any. O(size · p)
/// plus the vertices walked once.
pub(super) fn place_copy<A: Attributes>(
    g: &mut GMap<A>,
    prof: &Profile,
    slab: &[DartId],
    s: usize,
    f: impl Fn(Point) -> Point,
) -> Option<DartId> {
    let mut missing = None;
    for (x, &px) in prof.darts.iter().enumerate() {
        let y = slab[prof.at(x, prof.p + 1, s)];
        if g.point(y).is_some() {
            continue;
        }
        match g.point(px) {
            Some(q) => g.set_point(y, Some(f(q))),
            None => {
                missing.get_or_insert(px);
            }
        }
    }
    missing
}

/// The distinct i-cells met by `darts`, for every `i <= n`: the cell counts of a part of the
/// map. O(total size of those cells · n).
pub(super) fn cell_counts<A: Attributes>(g: &GMap<A>, darts: &[DartId]) -> Vec<usize> {
    (0..=g.dim())
        .map(|i| {
            let mut seen: rustc_hash::FxHashSet<DartId> = rustc_hash::FxHashSet::default();
            let mut count = 0;
            for &x in darts {
                if g.contains(x) && !seen.contains(&x) {
                    count += 1;
                    seen.extend(g.cell_darts(x, i));
                }
            }
            count
        })
        .collect()
}

/// The alternating sum of cell counts.
pub(super) fn chi(counts: &[usize]) -> i64 {
    counts.iter().enumerate().map(|(i, &c)| if i % 2 == 0 { c as i64 } else { -(c as i64) }).sum()
}
