//! Cell attributes: user data attached to the i-cells of an editable [`GMap`].
//!
//! # Design
//!
//! An *i-attribute* is a value attached to an i-cell, not to a dart: every dart of the cell
//! reaches the same value in O(1), and the value lives as long as one dart of the cell
//! does (CGAL's `Generalized_map` attributes follow the same rules). This module is the
//! design document of how [`GMap`] stores them and keeps them consistent while the map is
//! edited.
//!
//! ## Which dimensions carry what: the type `A`
//!
//! [`GMap<A>`](crate::GMap) is generic over a tuple `A` of per-dimension *slots*: the k-th slot is
//! dimension k. A slot is `()` (nothing on that dimension) or [`Cells<T>`] (a `T` on the
//! k-cells, `T: Clone + 'static`). Tuples of one to six slots are [`Attributes`], and so is
//! `()` (no attribute at all); `GMap` alone means `GMap<()>`. Access is typed and static: the
//! dimension is a const parameter, `map.attribute::<2>(d)` returns an `Option<&T>` of the
//! slot's type, and asking for a dimension whose slot is `()` does not compile
//! ([`AttributeAt`] gives the type of slot `I`). No `Box<dyn Any>`, no lookup by name.
//! A slot beyond the map's dimension (a 4-tuple on a 2-map) is inert: nothing is ever stored
//! in it ([`GMap::try_set_attribute`] refuses it with [`EditError::NoSuchCells`]), so one
//! attribute layout serves maps of several dimensions ([`crate::LabelledGMap`]).
//!
//! ## Storage
//!
//! A [`Cells<T>`] holds a dense `Vec<u32>` of handles indexed by [`GMap::dart_index`]
//! (`u32::MAX`: no attribute) and a slab of entries, each with the value, the number of
//! darts that use it, a generation (so that a stale [`AttrId`] is detected) and one dart of
//! its cell. Freed entries go to a free list. The handle vector is allocated on the first
//! attribute set: a slot that is never used costs one empty `Vec` and one branch per edit,
//! and with `A = ()` ([`Attributes::EMPTY`]) the edits skip attribute work at compile time.
//!
//! The point of a vertex is a built-in 0-slot of [`Point`] with the same storage: it
//! exists on every `GMap` and costs nothing until a point is set ([`GMap::point`],
//! [`GMap::set_point`]).
//!
//! ## Consistency: one routine
//!
//! Every edit that merges or splits cells ends with [`GMap::reconcile_attributes`], given the
//! darts whose involutions changed (and the surviving neighbours of removed darts). For
//! each slot, it walks the i-cell of every such dart once and repairs it:
//!
//! 1. *split*: a handle found in two or more of the walked cells was one cell that is now
//!    several; the first cell (in the order of the darts given) keeps the value, every other
//!    one gets a clone, and the split hook runs on (kept, copy);
//! 2. *merge*: a cell holding two or more handles was several cells that are now one; the
//!    first handle met (walking from the first dart given) is kept, and the merge hook
//!    runs on (kept, other) for each other one, whose entry is then freed;
//! 3. darts of a cell without a handle inherit the cell's (a cell with an attribute that
//!    grew over darts without one: the attribute spreads, no hook runs).
//!
//! Hooks run exactly when two cells that both carry an attribute become one, and when one
//! cell that carries an attribute becomes two, as CGAL's `onmerge`/`onsplit` functors. The
//! defaults keep the first value on a merge and keep a plain clone on a split. The cost is
//! O(s · n) per slot in use, s the total size of the walked cells: proportional to the
//! cells the edit touched, never to the map.
//!
//! A sew reaches the same result, hooks included, from the pairs of darts it links rather
//! than by walking the merged cells: the cells of the sewn dimension do not change, the
//! others only merge, and the handles on the paired darts tell which cells merge. Two
//! cells that both carry a value cost a walk of the one whose value disappears; other
//! cases go through the routine above. An unsew skips the dimension it does not change.
//!
//! [`GMap::sew`] and [`GMap::unsew`] reconcile (a sew keeps the attributes of the first
//! dart's cells); [`GMap::link`] and [`GMap::unlink`] are low level and do not: a caller
//! that edits through them calls [`GMap::reconcile_attributes`] afterwards.
//! [`GMap::remove_dart`] drops the dart's handles (freeing a value no dart uses any more)
//! and does not reconcile either. [`GMap::check_attributes`] verifies the invariant: every
//! dart of a cell holds the same handle, and each live value's count is its number of darts.
//!
//! ```
//! use gmap_core::{Cells, GMap};
//! // a 1-map (a polygon) with a name on each edge
//! let mut m: GMap<((), Cells<String>)> = GMap::with_attributes(1);
//! let (a, b, c, d) = (m.create_dart(), m.create_dart(), m.create_dart(), m.create_dart());
//! m.sew(a, b, 0);
//! m.sew(c, d, 0);
//! m.set_attribute::<1>(a, "left".to_string());
//! m.set_attribute::<1>(c, "right".to_string());
//! assert_eq!(m.attribute::<1>(b).map(String::as_str), Some("left"));
//! // joining the two edges at a vertex keeps both (1-cells are not merged by alpha_1)
//! m.sew(b, c, 1);
//! assert_eq!(m.attribute_count::<1>(), 2);
//! m.check_attributes().unwrap();
//! ```
//!
//! [`GMap`]: crate::GMap
//! [`GMap::check_attributes`]: crate::GMap::check_attributes
//! [`GMap::dart_index`]: crate::GMap::dart_index
//! [`GMap::link`]: crate::GMap::link
//! [`GMap::point`]: crate::GMap::point
//! [`GMap::reconcile_attributes`]: crate::GMap::reconcile_attributes
//! [`GMap::remove_dart`]: crate::GMap::remove_dart
//! [`GMap::set_point`]: crate::GMap::set_point
//! [`GMap::sew`]: crate::GMap::sew
//! [`GMap::try_set_attribute`]: crate::GMap::try_set_attribute
//! [`GMap::unlink`]: crate::GMap::unlink
//! [`GMap::unsew`]: crate::GMap::unsew
//! [`EditError::NoSuchCells`]: crate::EditError::NoSuchCells

use std::fmt;
use std::sync::Arc;

use rustc_hash::FxHashMap;
use smallvec::SmallVec;
use thiserror::Error;

use crate::darts::{dart_index, DartId};
use crate::Point;

/// The handle value of a dart without an attribute.
pub(crate) const NONE: u32 = u32::MAX;

/// A handle to one attribute (one value of a [`Cells`] slot). Stays valid while a dart uses
/// the value; a handle to a freed value is detected ([`GMap::attribute_by_id`](crate::GMap::attribute_by_id) returns
/// `None`) even when the slab slot is reused.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct AttrId {
    index: u32,
    generation: u32,
}

impl AttrId {
    /// The slab index (below the slot's capacity; reused after the value is freed).
    pub fn index(self) -> usize {
        self.index as usize
    }
}

/// The merge hook of a slot: `(kept, other)`, called when two cells carrying an attribute
/// become one. `other` is the value that disappears.
pub type MergeHook<T> = Arc<dyn Fn(&mut T, T) + Send + Sync>;

/// The split hook of a slot: `(kept, copy)`, called when a cell carrying an attribute
/// becomes two; `copy` starts as a clone of `kept` and goes to the new cell.
pub type SplitHook<T> = Arc<dyn Fn(&mut T, &mut T) + Send + Sync>;

/// One slab entry.
#[derive(Clone, Debug)]
struct Entry<T> {
    value: Option<T>,
    refs: u32,
    generation: u32,
    dart: DartId,
}

/// The attributes of one dimension: a value of type `T` per i-cell that has one. See the
/// [module docs](self) for the storage and the consistency rules.
pub struct Cells<T> {
    handles: Vec<u32>,
    entries: Vec<Entry<T>>,
    /// bit `h` set when entry `h` holds a value: the liveness test of the sew's fast
    /// path reads this (64 entries a word) instead of the entries
    alive: Vec<u64>,
    free: Vec<u32>,
    live: usize,
    on_merge: Option<MergeHook<T>>,
    on_split: Option<SplitHook<T>>,
    /// scratch for cell walks: `stamp[k] == epoch` marks dart index `k` as visited
    stamp: Vec<u32>,
    epoch: u32,
    /// reusable list of darts for cell walks (kept between calls to avoid allocating)
    scratch: Vec<DartId>,
}

impl<T> Default for Cells<T> {
    fn default() -> Self {
        Cells {
            handles: Vec::new(),
            entries: Vec::new(),
            alive: Vec::new(),
            free: Vec::new(),
            live: 0,
            on_merge: None,
            on_split: None,
            stamp: Vec::new(),
            epoch: 0,
            scratch: Vec::new(),
        }
    }
}

impl<T: Clone> Clone for Cells<T> {
    fn clone(&self) -> Self {
        Cells {
            handles: self.handles.clone(),
            entries: self.entries.clone(),
            alive: self.alive.clone(),
            free: self.free.clone(),
            live: self.live,
            on_merge: self.on_merge.clone(),
            on_split: self.on_split.clone(),
            stamp: Vec::new(),
            epoch: 0,
            scratch: Vec::new(),
        }
    }
}

impl<T: fmt::Debug> fmt::Debug for Cells<T> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_map().entries(self.iter().map(|(id, v)| (id.index, v))).finish()
    }
}

impl<T> Cells<T> {
    /// Number of live values.
    pub fn len(&self) -> usize {
        self.live
    }

    /// Whether no value is stored.
    pub fn is_empty(&self) -> bool {
        self.live == 0
    }

    /// Whether a value was ever set (the per-dart handles are allocated).
    #[inline]
    pub(crate) fn active(&self) -> bool {
        !self.handles.is_empty()
    }

    /// The live values with their handles, in slab order. Lazy, O(capacity) in total.
    pub fn iter(&self) -> impl Iterator<Item = (AttrId, &T)> + '_ {
        self.entries
            .iter()
            .enumerate()
            .filter_map(|(k, e)| e.value.as_ref().map(|v| (AttrId { index: k as u32, generation: e.generation }, v)))
    }

    /// The handle held by dart index `k` (`NONE` when it has none).
    #[inline]
    pub(crate) fn handle(&self, k: usize) -> u32 {
        self.handles.get(k).copied().unwrap_or(NONE)
    }

    /// The id of a handle.
    fn id(&self, h: u32) -> AttrId {
        AttrId { index: h, generation: self.entries[h as usize].generation }
    }

    /// The id of the value held by dart index `k`.
    pub(crate) fn id_at(&self, k: usize) -> Option<AttrId> {
        match self.handle(k) {
            NONE => None,
            h => Some(self.id(h)),
        }
    }

    /// The value held by dart index `k`.
    #[inline]
    pub(crate) fn get_at(&self, k: usize) -> Option<&T> {
        match self.handle(k) {
            NONE => None,
            h => self.entries.get(h as usize).and_then(|e| e.value.as_ref()),
        }
    }

    /// The value held by dart index `k`, mutably.
    pub(crate) fn get_at_mut(&mut self, k: usize) -> Option<&mut T> {
        match self.handle(k) {
            NONE => None,
            h => self.entries.get_mut(h as usize).and_then(|e| e.value.as_mut()),
        }
    }

    /// The value of a handle, if it is live.
    pub(crate) fn get_id(&self, id: AttrId) -> Option<&T> {
        self.entries.get(id.index()).filter(|e| e.generation == id.generation).and_then(|e| e.value.as_ref())
    }

    /// The value of a handle, mutably, if it is live.
    pub(crate) fn get_id_mut(&mut self, id: AttrId) -> Option<&mut T> {
        self.entries.get_mut(id.index()).filter(|e| e.generation == id.generation).and_then(|e| e.value.as_mut())
    }

    /// The recorded dart of a live handle (a dart of its cell).
    pub(crate) fn dart_of(&self, id: AttrId) -> Option<DartId> {
        self.entries.get(id.index()).filter(|e| e.generation == id.generation && e.value.is_some()).map(|e| e.dart)
    }

    /// Sets the merge hook.
    pub(crate) fn set_on_merge(&mut self, f: MergeHook<T>) {
        self.on_merge = Some(f);
    }

    /// Sets the split hook.
    pub(crate) fn set_on_split(&mut self, f: SplitHook<T>) {
        self.on_split = Some(f);
    }

    /// A new entry with no dart counted yet.
    fn alloc(&mut self, value: T, dart: DartId) -> u32 {
        self.live += 1;
        let h = match self.free.pop() {
            Some(h) => {
                let e = &mut self.entries[h as usize];
                e.value = Some(value);
                e.refs = 0;
                e.dart = dart;
                h
            }
            None => {
                self.entries.push(Entry { value: Some(value), refs: 0, generation: 0, dart });
                if self.alive.len() * 64 < self.entries.len() {
                    self.alive.push(0);
                }
                (self.entries.len() - 1) as u32
            }
        };
        self.alive[h as usize / 64] |= 1 << (h % 64);
        h
    }

    /// Frees an entry, returning its value.
    fn release(&mut self, h: u32) -> Option<T> {
        let e = &mut self.entries[h as usize];
        let v = e.value.take();
        if v.is_some() {
            self.alive[h as usize / 64] &= !(1 << (h % 64));
            e.generation = e.generation.wrapping_add(1);
            e.refs = 0;
            self.live -= 1;
            self.free.push(h);
        }
        v
    }

    /// Makes the handle and stamp vectors cover `bound` dart indices.
    fn ensure(&mut self, bound: usize) {
        if self.handles.len() < bound {
            self.handles.resize(bound, NONE);
        }
    }

    /// Starts a new walk epoch (every dart unvisited).
    fn next_epoch(&mut self, bound: usize) {
        if self.stamp.len() < bound {
            self.stamp.resize(bound, 0);
        }
        self.epoch = self.epoch.wrapping_add(1);
        if self.epoch == 0 {
            self.stamp.fill(0);
            self.epoch = 1;
        }
    }

    /// Appends the darts of the i-cell of `d` not visited in this epoch to `out`, marking
    /// them. Breadth-first from `d`, so `d` comes first.
    fn walk(&mut self, topo: &Topo, i: usize, d: DartId, out: &mut Vec<DartId>) {
        let k = dart_index(d);
        if self.stamp[k] == self.epoch {
            return;
        }
        self.stamp[k] = self.epoch;
        let start = out.len();
        out.push(d);
        let mut q = start;
        while q < out.len() {
            let x = out[q];
            q += 1;
            for j in (0..=topo.dim).filter(|&j| j != i) {
                let y = topo.alpha(x, j);
                let ky = dart_index(y);
                if self.stamp[ky] != self.epoch {
                    self.stamp[ky] = self.epoch;
                    out.push(y);
                }
            }
        }
    }
}

impl<T: Clone> Cells<T> {
    /// Sets the value of the i-cell of `d`, replacing the cell's value if it has one, and
    /// returns its id. O(1) when the cell has a value, O(cell size · n) otherwise.
    pub(crate) fn set(&mut self, topo: &Topo, i: usize, d: DartId, value: T) -> AttrId {
        self.ensure(topo.bound());
        let k = dart_index(d);
        match self.handle(k) {
            NONE => {
                let h = self.alloc(value, d);
                self.next_epoch(topo.bound());
                let mut cell = std::mem::take(&mut self.scratch);
                cell.clear();
                self.walk(topo, i, d, &mut cell);
                for &x in &cell {
                    let old = self.handles[dart_index(x)];
                    if old != NONE {
                        // a cell whose darts disagree (edited without reconciling): the
                        // new value replaces every old one
                        self.unref(old);
                    }
                    self.handles[dart_index(x)] = h;
                }
                self.entries[h as usize].refs = cell.len() as u32;
                self.scratch = cell;
                self.id(h)
            }
            h => {
                self.entries[h as usize].value = Some(value);
                self.id(h)
            }
        }
    }

    /// Gives a new value to the i-cell whose darts are exactly `cell`, none of them holding a
    /// value (the caller's precondition: a cell just made), without walking it. `bound` is
    /// [`Topo::bound`]. O(|cell|).
    pub(crate) fn set_fresh(&mut self, bound: usize, cell: &[DartId], value: T) -> AttrId {
        self.ensure(bound);
        let h = self.alloc(value, cell[0]);
        for &x in cell {
            self.handles[dart_index(x)] = h;
        }
        self.entries[h as usize].refs = cell.len() as u32;
        self.id(h)
    }

    /// Drops one use of a handle, freeing it when no dart uses it.
    fn unref(&mut self, h: u32) {
        if let Some(e) = self.entries.get_mut(h as usize) {
            if e.value.is_some() {
                e.refs = e.refs.saturating_sub(1);
                if e.refs == 0 {
                    self.release(h);
                }
            }
        }
    }

    /// Removes the value of the i-cell of `d` and returns it. O(cell size · n).
    pub(crate) fn remove(&mut self, topo: &Topo, i: usize, d: DartId) -> Option<T> {
        let h = self.handle(dart_index(d));
        if h == NONE {
            return None;
        }
        self.next_epoch(topo.bound());
        let mut cell = std::mem::take(&mut self.scratch);
        cell.clear();
        self.walk(topo, i, d, &mut cell);
        for &x in &cell {
            let k = dart_index(x);
            if self.handles[k] == h {
                self.handles[k] = NONE;
            }
        }
        self.scratch = cell;
        self.release(h)
    }

    /// Forgets dart `d` (about to be removed): drops its use of its value, and moves the
    /// value's recorded dart to a neighbour of `d` in the same cell when `d` was it.
    pub(crate) fn drop_dart(&mut self, topo: &Topo, i: usize, d: DartId) {
        let k = dart_index(d);
        let h = self.handle(k);
        if h == NONE {
            return;
        }
        self.handles[k] = NONE;
        if self.entries[h as usize].dart == d {
            let other = (0..=topo.dim)
                .filter(|&j| j != i)
                .map(|j| topo.alpha(d, j))
                .find(|&y| y != d && self.handle(dart_index(y)) == h);
            if let Some(y) = other {
                self.entries[h as usize].dart = y;
            }
        }
        self.unref(h);
    }

    /// The consistency routine of the [module docs](self) for dimension `i`.
    pub(crate) fn reconcile(&mut self, topo: &Topo, i: usize, touched: &[DartId]) {
        if !self.active() {
            return;
        }
        self.ensure(topo.bound());
        self.next_epoch(topo.bound());
        let mut darts = std::mem::take(&mut self.scratch);
        darts.clear();
        let mut starts: SmallVec<[usize; 16]> = SmallVec::new();
        for &t in touched {
            if topo.live(t) {
                let before = darts.len();
                self.walk(topo, i, t, &mut darts);
                if darts.len() > before {
                    starts.push(before);
                }
            }
        }
        starts.push(darts.len());
        let cells = starts.len() - 1;
        // the distinct live handles of each walked cell, in the order met
        let mut held: Vec<SmallVec<[u32; 2]>> = Vec::with_capacity(cells);
        for c in 0..cells {
            let mut hs: SmallVec<[u32; 2]> = SmallVec::new();
            for &x in &darts[starts[c]..starts[c + 1]] {
                let h = self.handles[dart_index(x)];
                if h != NONE && self.entries[h as usize].value.is_some() && !hs.contains(&h) {
                    hs.push(h);
                }
            }
            held.push(hs);
        }
        // 1. splits: a handle held by several cells stays with the first, the others get copies
        let mut owner: FxHashMap<u32, usize> = FxHashMap::default();
        for (c, hs) in held.iter_mut().enumerate() {
            for h in hs.iter_mut() {
                match owner.get(h) {
                    Some(&first) if first != c => {
                        let mut copy = self.entries[*h as usize].value.clone().expect("live handle");
                        if let Some(f) = self.on_split.clone() {
                            let kept = self.entries[*h as usize].value.as_mut().expect("live handle");
                            f(kept, &mut copy);
                        }
                        *h = self.alloc(copy, darts[starts[c]]);
                    }
                    Some(_) => {}
                    None => {
                        owner.insert(*h, c);
                    }
                }
            }
        }
        // relabel every walked dart with its cell's first handle, counting uses exactly
        for (c, hs) in held.iter().enumerate() {
            let keep = hs.first().copied().unwrap_or(NONE);
            for &x in &darts[starts[c]..starts[c + 1]] {
                let k = dart_index(x);
                let old = self.handles[k];
                if old != keep {
                    if old != NONE {
                        if let Some(e) = self.entries.get_mut(old as usize) {
                            e.refs = e.refs.saturating_sub(1);
                        }
                    }
                    if keep != NONE {
                        self.entries[keep as usize].refs += 1;
                    }
                    self.handles[k] = keep;
                }
            }
            if keep != NONE {
                self.entries[keep as usize].dart = darts[starts[c]];
            }
        }
        // 2. merges: the other handles of a cell fold into its first
        for hs in &held {
            for &other in hs.iter().skip(1) {
                let v = if self.entries[other as usize].refs == 0 {
                    self.release(other).expect("live handle")
                } else {
                    self.entries[other as usize].value.clone().expect("live handle")
                };
                let kept = self.entries[hs[0] as usize].value.as_mut().expect("live handle");
                if let Some(f) = &self.on_merge {
                    f(kept, v);
                }
            }
        }
        self.scratch = darts;
    }

    /// The consistency routine for dimension `i` after a sew of index `s != i` that linked
    /// the darts of each pair of `pairs` by `alpha_s`, on a map whose i-cells were consistent
    /// before. Gives the result of [`Cells::reconcile`] on the darts of the pairs (first
    /// sides, then second sides), with the same hook calls in the same order, but uses the
    /// known pairing: a sew only merges cells, and every old cell of a merged cell holds a
    /// dart of the pairs, so the handles on the pairs tell which cells merge without walking
    /// them. When each merged cell joins at most two cells that both carry an attribute,
    /// only the darts of the cell whose value disappears are relabelled; other cases (a
    /// cell without attribute meeting one with, three or more cells becoming one) go to
    /// [`Cells::reconcile`]. O(p²) for p pairs plus O(r · n) for the r darts relabelled.
    pub(crate) fn reconcile_sewn(&mut self, topo: &Topo, i: usize, pairs: &[(DartId, DartId)]) {
        if !self.active() {
            return;
        }
        self.ensure(topo.bound());
        match self.sew_merges(pairs) {
            Some(merges) => {
                for (kept, other, from) in merges {
                    self.fold(topo, i, kept, other, from);
                }
            }
            None => {
                let touched: Vec<DartId> = pairs.iter().map(|p| p.0).chain(pairs.iter().map(|p| p.1)).collect();
                self.reconcile(topo, i, &touched);
            }
        }
    }

    /// Whether `h` names a live value.
    #[inline]
    fn is_live(&self, h: u32) -> bool {
        h != NONE && self.alive.get(h as usize / 64).is_some_and(|w| w & (1 << (h % 64)) != 0)
    }

    /// The merges a sew of `pairs` causes, as `(kept, other, a dart holding other)` in the
    /// order [`Cells::reconcile`] runs their hooks, or `None` when the sew is not the simple
    /// case of [`Cells::reconcile_sewn`].
    ///
    /// Every paired dart holding a live handle, the handles are the nodes of a graph whose
    /// edges are the pairs with different handles; a connected set of nodes is one merged
    /// cell. The general routine keeps the handle of the first paired dart (first sides
    /// come first) of each merged cell and runs the hooks cell by cell in that order. The
    /// simple case: every merged cell joins two cells, the kept one holding the first side
    /// of the pair that joins them, and the merges come in the order of their first pairs.
    fn sew_merges(&self, pairs: &[(DartId, DartId)]) -> Option<SmallVec<[(u32, u32, DartId); 4]>> {
        // the handles of the first sides in order of first appearance: a merged cell's
        // first paired dart is always a first side (its partner is in the same cell)
        let mut order: SmallVec<[u32; 16]> = SmallVec::new();
        for &(a, _) in pairs {
            let h = self.handle(dart_index(a));
            if !self.is_live(h) {
                return None;
            }
            if !order.contains(&h) {
                order.push(h);
            }
        }
        let rank = |h: u32| order.iter().position(|&x| x == h).unwrap_or(usize::MAX);
        let mut merges: SmallVec<[(u32, u32, DartId); 4]> = SmallVec::new();
        for &(a, b) in pairs {
            let (ha, hb) = (self.handle(dart_index(a)), self.handle(dart_index(b)));
            if !self.is_live(hb) {
                return None;
            }
            if ha == hb || merges.iter().any(|m| (m.0, m.1) == (ha, hb)) {
                continue;
            }
            let simple = rank(ha) < rank(hb)
                && merges.iter().all(|m| m.0 != ha && m.1 != ha && m.0 != hb && m.1 != hb)
                && merges.last().is_none_or(|m| rank(m.0) < rank(ha));
            if !simple {
                // the second side's value kept, three or more cells becoming one, or hooks
                // out of the order of the pairs
                return None;
            }
            merges.push((ha, hb, b));
        }
        Some(merges)
    }

    /// Folds the cell holding `other` (reached from its dart `from`) into the value `kept`:
    /// relabels its darts, moves the counts, frees `other` once no dart holds it and runs the
    /// merge hook on (kept, other). The darts holding `other` are connected by links that
    /// a sew leaves in place, so the walk from `from` through them finds them all. O(r · n)
    /// for the r darts relabelled.
    fn fold(&mut self, topo: &Topo, i: usize, kept: u32, other: u32, from: DartId) {
        // by slot number: the walk reads the rows of links and the handles only
        let mut stack: SmallVec<[u32; 64]> = SmallVec::new();
        let start = dart_index(from);
        self.handles[start] = kept;
        stack.push(start as u32);
        let mut moved: u32 = 1;
        while let Some(x) = stack.pop() {
            for j in (0..=topo.dim).filter(|&j| j != i) {
                let y = topo.darts.slot_alpha(x, j);
                let k = y as usize;
                if self.handles[k] == other {
                    self.handles[k] = kept;
                    moved += 1;
                    stack.push(y);
                }
            }
        }
        self.entries[kept as usize].refs += moved;
        let e = &mut self.entries[other as usize];
        e.refs = e.refs.saturating_sub(moved);
        let v =
            if e.refs == 0 { self.release(other).expect("live handle") } else { e.value.clone().expect("live handle") };
        let kept = self.entries[kept as usize].value.as_mut().expect("live handle");
        if let Some(f) = &self.on_merge {
            f(kept, v);
        }
    }

    /// Checks the invariant of dimension `i` on every live dart: neighbours in the cell hold
    /// the same handle, handles name live values, counts match, no value is held by two
    /// cells. O(N n).
    pub(crate) fn check(&self, topo: &Topo, i: usize, darts: &[DartId]) -> Result<(), AttributeDefect> {
        if !self.active() {
            return Ok(());
        }
        let mut counts = vec![0u32; self.entries.len()];
        for &d in darts {
            let h = self.handle(dart_index(d));
            if h != NONE {
                if self.entries.get(h as usize).is_none_or(|e| e.value.is_none()) {
                    return Err(AttributeDefect::Dangling { dim: i, dart: d });
                }
                counts[h as usize] += 1;
            }
            for j in (0..=topo.dim).filter(|&j| j != i) {
                let y = topo.alpha(d, j);
                if self.handle(dart_index(y)) != h {
                    return Err(AttributeDefect::Disagree {
                        dim: i,
                        dart: d,
                        other: y,
                        dart_attr: self.id_at(dart_index(d)),
                        other_attr: self.id_at(dart_index(y)),
                    });
                }
            }
        }
        for (k, e) in self.entries.iter().enumerate() {
            if e.value.is_some() && e.refs != counts[k] {
                return Err(AttributeDefect::Count {
                    dim: i,
                    attr: self.id(k as u32),
                    stored: e.refs,
                    found: counts[k],
                });
            }
        }
        // one cell per value (the cells are uniform by now): the first dart met holding a
        // value claims it for its cell; a dart of another cell holding it is a defect
        let mut visited = bitvec::vec::BitVec::<usize>::repeat(false, topo.bound());
        let mut owner: Vec<Option<DartId>> = vec![None; self.entries.len()];
        let mut stack = Vec::new();
        for &d in darts {
            let h = self.handle(dart_index(d));
            if h == NONE || visited[dart_index(d)] {
                continue;
            }
            if let Some(other) = owner[h as usize] {
                return Err(AttributeDefect::Shared { dim: i, attr: self.id(h), dart: d, other });
            }
            owner[h as usize] = Some(d);
            visited.set(dart_index(d), true);
            stack.push(d);
            while let Some(x) = stack.pop() {
                for j in (0..=topo.dim).filter(|&j| j != i) {
                    let y = topo.alpha(x, j);
                    if !visited[dart_index(y)] {
                        visited.set(dart_index(y), true);
                        stack.push(y);
                    }
                }
            }
        }
        Ok(())
    }
}

/// A cell whose darts disagree on their attribute, or a broken count: what
/// [`GMap::check_attributes`](crate::GMap::check_attributes) reports.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
#[non_exhaustive]
pub enum AttributeDefect {
    /// Two darts of one i-cell, neighbours by some `alpha_j` (`j != i`), hold different
    /// attributes (or one holds none).
    #[error(
        "darts {dart:?} and {other:?} of one {dim}-cell disagree on its attribute ({dart_attr:?} and {other_attr:?})"
    )]
    Disagree {
        /// the dimension of the cell
        dim: usize,
        /// a dart of the cell
        dart: DartId,
        /// a neighbour of `dart` in the same cell
        other: DartId,
        /// the attribute `dart` holds
        dart_attr: Option<AttrId>,
        /// the attribute `other` holds
        other_attr: Option<AttrId>,
    },
    /// Two darts of one vertex, neighbours by some `alpha_j` (`j >= 1`), hold different points.
    #[error("darts {dart:?} and {other:?} of one vertex disagree on its point")]
    PointDisagree {
        /// a dart of the vertex
        dart: DartId,
        /// a neighbour of `dart` in the same vertex
        other: DartId,
    },
    /// Two different cells hold the same value (a cell was cut without reconciling).
    #[error("{dim}-attribute {attr:?} is held by dart {dart:?} and by dart {other:?} of another {dim}-cell")]
    Shared {
        /// the dimension
        dim: usize,
        /// the attribute
        attr: AttrId,
        /// a dart of one cell
        dart: DartId,
        /// a dart of another cell holding it
        other: DartId,
    },
    /// A dart holds a handle to a freed value.
    #[error("dart {dart:?} holds a freed {dim}-attribute")]
    Dangling {
        /// the dimension
        dim: usize,
        /// the dart
        dart: DartId,
    },
    /// A value's count of darts is not the number of darts holding it.
    #[error("{dim}-attribute {attr:?} counts {stored} darts but {found} hold it")]
    Count {
        /// the dimension
        dim: usize,
        /// the attribute
        attr: AttrId,
        /// the stored count
        stored: u32,
        /// the darts found holding it
        found: u32,
    },
}

mod sealed {
    use super::AttributeDefect;
    use crate::darts::{DartId, DartStore};

    /// The topology an attribute slot walks: the map's dimension and darts. Built by [`GMap`](crate::GMap)
    /// for the duration of one call.
    pub struct Topo<'a> {
        pub(crate) dim: usize,
        pub(crate) darts: &'a DartStore,
    }

    impl Topo<'_> {
        /// `alpha_j(d)` of a live dart.
        #[inline]
        pub(crate) fn alpha(&self, d: DartId, j: usize) -> DartId {
            self.darts.alpha(d, j)
        }

        #[inline]
        pub(crate) fn live(&self, d: DartId) -> bool {
            self.darts.contains(d)
        }

        /// A strict upper bound on the dart indices.
        #[inline]
        pub(crate) fn bound(&self) -> usize {
            self.darts.bound()
        }
    }

    /// The per-slot operations, hidden from users: only `()` and `Cells<T>` are slots.
    pub trait SlotOps {
        const PRESENT: bool;
        fn reconcile_slot(&mut self, topo: &Topo, i: usize, touched: &[DartId]);
        fn reconcile_sewn_slot(&mut self, topo: &Topo, i: usize, pairs: &[(DartId, DartId)]);
        fn drop_dart_slot(&mut self, topo: &Topo, i: usize, d: DartId);
        fn check_slot(&self, topo: &Topo, i: usize, darts: &[DartId]) -> Result<(), AttributeDefect>;
    }

    /// The whole-tuple operations, hidden from users.
    pub trait AttributesOps {
        fn reconcile_all(&mut self, topo: &Topo, touched: &[DartId]);
        /// Reconciles every slot but `skip` (the index of the involution that changed: the
        /// cells of that dimension do not change).
        fn reconcile_except_all(&mut self, topo: &Topo, skip: usize, touched: &[DartId]);
        /// Reconciles every slot but `s` after an `s`-sew of `pairs`.
        fn reconcile_sewn_all(&mut self, topo: &Topo, s: usize, pairs: &[(DartId, DartId)]);
        fn drop_dart_all(&mut self, topo: &Topo, d: DartId);
        fn check_all(&self, topo: &Topo, darts: &[DartId]) -> Result<(), AttributeDefect>;
    }
}

use sealed::SlotOps;
pub(crate) use sealed::{AttributesOps, Topo};

/// What may stand at position i of an [`Attributes`] tuple: `()` (no attribute on the
/// i-cells) or [`Cells<T>`]. Sealed.
pub trait Slot: SlotOps + Default {}

impl SlotOps for () {
    const PRESENT: bool = false;
    fn reconcile_slot(&mut self, _: &Topo, _: usize, _: &[DartId]) {}
    fn reconcile_sewn_slot(&mut self, _: &Topo, _: usize, _: &[(DartId, DartId)]) {}
    fn drop_dart_slot(&mut self, _: &Topo, _: usize, _: DartId) {}
    fn check_slot(&self, _: &Topo, _: usize, _: &[DartId]) -> Result<(), AttributeDefect> {
        Ok(())
    }
}
impl Slot for () {}

impl<T: Clone + 'static> SlotOps for Cells<T> {
    const PRESENT: bool = true;
    fn reconcile_slot(&mut self, topo: &Topo, i: usize, touched: &[DartId]) {
        self.reconcile(topo, i, touched)
    }
    fn reconcile_sewn_slot(&mut self, topo: &Topo, i: usize, pairs: &[(DartId, DartId)]) {
        self.reconcile_sewn(topo, i, pairs)
    }
    fn drop_dart_slot(&mut self, topo: &Topo, i: usize, d: DartId) {
        self.drop_dart(topo, i, d)
    }
    fn check_slot(&self, topo: &Topo, i: usize, darts: &[DartId]) -> Result<(), AttributeDefect> {
        self.check(topo, i, darts)
    }
}
impl<T: Clone + 'static> Slot for Cells<T> {}

/// The attribute layout of a [`GMap`](crate::GMap): `()` (none) or a tuple of one to six [`Slot`]s, the
/// k-th for dimension k. Sealed: implemented for those types only.
pub trait Attributes: AttributesOps + Default {
    /// Whether no slot stores anything (`()` or a tuple of `()`): the edits then skip
    /// attribute work entirely.
    const EMPTY: bool;
}

impl AttributesOps for () {
    fn reconcile_all(&mut self, _: &Topo, _: &[DartId]) {}
    fn reconcile_except_all(&mut self, _: &Topo, _: usize, _: &[DartId]) {}
    fn reconcile_sewn_all(&mut self, _: &Topo, _: usize, _: &[(DartId, DartId)]) {}
    fn drop_dart_all(&mut self, _: &Topo, _: DartId) {}
    fn check_all(&self, _: &Topo, _: &[DartId]) -> Result<(), AttributeDefect> {
        Ok(())
    }
}
impl Attributes for () {
    const EMPTY: bool = true;
}

macro_rules! tuple_attributes {
    ($($S:ident $k:tt),+) => {
        // slot 0 compares `0 <= dim`, always true
        #[allow(unused_comparisons)]
        impl<$($S: Slot),+> AttributesOps for ($($S,)+) {
            fn reconcile_all(&mut self, topo: &Topo, touched: &[DartId]) {
                $(if $S::PRESENT && $k <= topo.dim {
                    self.$k.reconcile_slot(topo, $k, touched);
                })+
            }
            fn reconcile_except_all(&mut self, topo: &Topo, skip: usize, touched: &[DartId]) {
                $(if $S::PRESENT && $k <= topo.dim && $k != skip {
                    self.$k.reconcile_slot(topo, $k, touched);
                })+
            }
            fn reconcile_sewn_all(&mut self, topo: &Topo, s: usize, pairs: &[(DartId, DartId)]) {
                $(if $S::PRESENT && $k <= topo.dim && $k != s {
                    self.$k.reconcile_sewn_slot(topo, $k, pairs);
                })+
            }
            fn drop_dart_all(&mut self, topo: &Topo, d: DartId) {
                $(if $S::PRESENT && $k <= topo.dim {
                    self.$k.drop_dart_slot(topo, $k, d);
                })+
            }
            fn check_all(
                &self,
                topo: &Topo,
                darts: &[DartId],
            ) -> Result<(), AttributeDefect> {
                $(if $S::PRESENT && $k <= topo.dim {
                    self.$k.check_slot(topo, $k, darts)?;
                })+
                Ok(())
            }
        }
        impl<$($S: Slot),+> Attributes for ($($S,)+) {
            const EMPTY: bool = $(!$S::PRESENT &&)+ true;
        }
    };
}

tuple_attributes!(S0 0);
tuple_attributes!(S0 0, S1 1);
tuple_attributes!(S0 0, S1 1, S2 2);
tuple_attributes!(S0 0, S1 1, S2 2, S3 3);
tuple_attributes!(S0 0, S1 1, S2 2, S3 3, S4 4);
tuple_attributes!(S0 0, S1 1, S2 2, S3 3, S4 4, S5 5);

/// The slot of dimension `I` of an [`Attributes`] tuple, when it is a [`Cells<T>`]: gives
/// `T` and the storage. Implemented for every tuple position holding a `Cells`; asking for
/// a position holding `()` does not compile.
pub trait AttributeAt<const I: usize>: Attributes {
    /// The type of the values on the I-cells.
    type Value: Clone + 'static;
    /// The slot.
    fn cells(&self) -> &Cells<Self::Value>;
    /// The slot, mutably.
    fn cells_mut(&mut self) -> &mut Cells<Self::Value>;
}

macro_rules! attribute_at {
    ($I:tt, [$($G:ident),*], $tuple:ty) => {
        impl<T: Clone + 'static, $($G: Slot),*> AttributeAt<$I> for $tuple {
            type Value = T;
            fn cells(&self) -> &Cells<T> {
                &self.$I
            }
            fn cells_mut(&mut self) -> &mut Cells<T> {
                &mut self.$I
            }
        }
    };
}

attribute_at!(0, [], (Cells<T>,));
attribute_at!(0, [S1], (Cells<T>, S1));
attribute_at!(1, [S0], (S0, Cells<T>));
attribute_at!(0, [S1, S2], (Cells<T>, S1, S2));
attribute_at!(1, [S0, S2], (S0, Cells<T>, S2));
attribute_at!(2, [S0, S1], (S0, S1, Cells<T>));
attribute_at!(0, [S1, S2, S3], (Cells<T>, S1, S2, S3));
attribute_at!(1, [S0, S2, S3], (S0, Cells<T>, S2, S3));
attribute_at!(2, [S0, S1, S3], (S0, S1, Cells<T>, S3));
attribute_at!(3, [S0, S1, S2], (S0, S1, S2, Cells<T>));
attribute_at!(0, [S1, S2, S3, S4], (Cells<T>, S1, S2, S3, S4));
attribute_at!(1, [S0, S2, S3, S4], (S0, Cells<T>, S2, S3, S4));
attribute_at!(2, [S0, S1, S3, S4], (S0, S1, Cells<T>, S3, S4));
attribute_at!(3, [S0, S1, S2, S4], (S0, S1, S2, Cells<T>, S4));
attribute_at!(4, [S0, S1, S2, S3], (S0, S1, S2, S3, Cells<T>));
attribute_at!(0, [S1, S2, S3, S4, S5], (Cells<T>, S1, S2, S3, S4, S5));
attribute_at!(1, [S0, S2, S3, S4, S5], (S0, Cells<T>, S2, S3, S4, S5));
attribute_at!(2, [S0, S1, S3, S4, S5], (S0, S1, Cells<T>, S3, S4, S5));
attribute_at!(3, [S0, S1, S2, S4, S5], (S0, S1, S2, Cells<T>, S4, S5));
attribute_at!(4, [S0, S1, S2, S3, S5], (S0, S1, S2, S3, Cells<T>, S5));
attribute_at!(5, [S0, S1, S2, S3, S4], (S0, S1, S2, S3, S4, Cells<T>));

/// The built-in vertex points share the slot machinery with the user's attributes.
pub(crate) type Points = Cells<Point>;
