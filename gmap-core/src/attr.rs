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

    /// The number of slab entries: every handle is below it.
    #[inline]
    pub(crate) fn slab_len(&self) -> usize {
        self.entries.len()
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
    /// Values given in bulk ([`GMap::set_attributes_by_ids`](crate::GMap::set_attributes_by_ids),
    /// [`GMap::set_points_by_ids`](crate::GMap::set_points_by_ids)) that cannot be set as given.
    #[error("{dim}-cell values by dart: {reason}")]
    BadIds {
        /// the dimension
        dim: usize,
        /// what is wrong
        reason: String,
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

mod cells;
