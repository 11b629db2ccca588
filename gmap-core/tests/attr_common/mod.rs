//! What the property tests of attributes share: a map type with a `u64` on the cells of
//! every dimension, counters of hook calls, filling every cell and vertex, and the
//! independent count of merges and splits between two partitions of the same darts. Used
//! by `attr_props.rs` here and by gmap-ops's `euler_attr_props.rs`.
#![allow(dead_code)]

use std::collections::{BTreeMap, BTreeSet, HashMap};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Arc;

use gmap_core::{Cells, DartId, GMap};

/// A map with a `u64` on the cells of dimensions 0 to 3.
pub type Full = GMap<(Cells<u64>, Cells<u64>, Cells<u64>, Cells<u64>)>;

/// Counters of hook calls, per dimension.
#[derive(Default)]
pub struct Hooks {
    merges: [Arc<AtomicUsize>; 4],
    splits: [Arc<AtomicUsize>; 4],
}

impl Hooks {
    /// Sets merge and split hooks on every dimension of `g` that count their calls here
    /// (and keep the values as the defaults do).
    pub fn install(&self, g: &mut Full) {
        macro_rules! on {
            ($i:literal) => {
                let m = self.merges[$i].clone();
                g.set_on_merge::<$i>(move |_, _| {
                    m.fetch_add(1, Ordering::Relaxed);
                });
                let s = self.splits[$i].clone();
                g.set_on_split::<$i>(move |_, _| {
                    s.fetch_add(1, Ordering::Relaxed);
                });
            };
        }
        on!(0);
        on!(1);
        on!(2);
        on!(3);
    }

    /// The calls so far: (merges, splits), each per dimension.
    pub fn counts(&self) -> ([usize; 4], [usize; 4]) {
        (
            self.merges.each_ref().map(|c| c.load(Ordering::Relaxed)),
            self.splits.each_ref().map(|c| c.load(Ordering::Relaxed)),
        )
    }
}

/// The i-cell number of every live dart, for every i, from the dense snapshot.
pub fn cells_by_dart(g: &Full) -> Vec<HashMap<DartId, u32>> {
    let (dense, ids) = g.to_dense_with_ids();
    (0..=g.dim()).map(|i| ids.iter().copied().zip(dense.cells(i).of).collect()).collect()
}

/// Merges and splits between two partitions of the same darts: a new cell meeting k old
/// cells is k - 1 merges; an old cell meeting k new cells is k - 1 splits.
pub fn merges_and_splits(old: &[u32], new: &[u32]) -> (usize, usize) {
    let mut olds_of_new: BTreeMap<u32, BTreeSet<u32>> = BTreeMap::new();
    let mut news_of_old: BTreeMap<u32, BTreeSet<u32>> = BTreeMap::new();
    for (&o, &n) in old.iter().zip(new) {
        olds_of_new.entry(n).or_default().insert(o);
        news_of_old.entry(o).or_default().insert(n);
    }
    (olds_of_new.values().map(|s| s.len() - 1).sum(), news_of_old.values().map(|s| s.len() - 1).sum())
}

/// The value on the i-cell of `d`.
pub fn attr(g: &Full, d: DartId, i: usize) -> Option<u64> {
    match i {
        0 => g.attribute::<0>(d).copied(),
        1 => g.attribute::<1>(d).copied(),
        2 => g.attribute::<2>(d).copied(),
        _ => g.attribute::<3>(d).copied(),
    }
}

/// The number of values on the i-cells.
pub fn count(g: &Full, i: usize) -> usize {
    [g.attribute_count::<0>(), g.attribute_count::<1>(), g.attribute_count::<2>(), g.attribute_count::<3>()][i]
}

/// Gives every cell without a value a fresh one and every vertex without a point a fresh
/// point, all distinct; `next` numbers them.
pub fn fill(g: &mut Full, next: &mut u64) {
    let darts: Vec<DartId> = g.darts().collect();
    for i in 0..=g.dim() {
        for &d in &darts {
            if attr(g, d, i).is_none() {
                *next += 1;
                match i {
                    0 => g.set_attribute::<0>(d, *next),
                    1 => g.set_attribute::<1>(d, *next),
                    2 => g.set_attribute::<2>(d, *next),
                    _ => g.set_attribute::<3>(d, *next),
                };
            }
        }
    }
    for &d in &darts {
        if g.point(d).is_none() {
            *next += 1;
            g.set_point(d, Some([*next as f64, 0.5, -1.0]));
        }
    }
}
