//! [`GMap`]: the editable map, with stable dart handles.
//!
//! Darts live in a slot store (`DartStore`, one row of `u32` per dart: a version and the
//! slot number of each involution image, 20 bytes in a 3-map): a [`DartId`] (slot number
//! and version) stays valid while other darts are created and removed, and a removed
//! dart's handle is detected as stale rather than silently reused. Attributes, points and
//! marks are stored apart, by dart index, so the orbit walks of sews and attribute repairs
//! read only the links. Editing goes through `link`/`unlink` (low level, may break
//! validity) or `sew`/`unsew` (keep validity, CGAL's semantics).
//! [`GMap::to_dense_map`] freezes the map into a [`DenseMap`] for analysis in one linear
//! pass; [`GMap::from_dense`] thaws one back.
//!
//! A `GMap<A>` carries cell attributes described by `A` (see [`crate::attr`]) and a point
//! per vertex; `GMap` alone is `GMap<()>`, with no attribute and no per-dart cost for them.

use rustc_hash::FxHashMap as HashMap;
use smallvec::SmallVec;
use thiserror::Error;

use crate::alpha::{AlphaSet, MAX_DIM};
use crate::attr::{AttrId, AttributeAt, AttributeDefect, Attributes, Points, Topo};
pub use crate::darts::DartId;
use crate::darts::{dart_index, DartStore};
use crate::dense::{DenseMap, Partition};
use crate::error::{BoundaryDefect, OrientationConflict};
#[cfg(test)]
use crate::ids::Dart;
use crate::ids::Point;
use crate::map_view::MapView;
use crate::marks::{MarkId, Marks};
use bitvec::vec::BitVec;

/// The misuse of an editable [`GMap`]: why an edit (a sew, a link, a removal, a mark, an
/// attribute) or a query through a [`DartId`] was refused. The `try_` forms ([`GMap::try_sew`], [`GMap::try_link`], [`GMap::try_unsew`],
/// [`GMap::try_remove_dart`], [`GMap::try_mark`], …) return it, the panicking forms panic
/// with its message. The same misuse of a [`DenseMap`] (a dart out of range, an index above
/// the dimension) is a [`crate::DartError`], which names the dart by its number.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
#[non_exhaustive]
pub enum EditError {
    /// `i` is larger than the dimension.
    #[error("alpha_{alpha} does not exist in a map of dimension {dim}")]
    BadIndex {
        /// the index asked for
        alpha: usize,
        /// the map's dimension
        dim: usize,
    },
    /// A handle does not name a live dart.
    #[error("dart {0:?} does not exist (removed or from another map)")]
    NoSuchDart(DartId),
    /// A dart of the sewn orbits is not i-free.
    #[error("dart {dart:?} is not {alpha}-free")]
    NotFree {
        /// the dart already linked
        dart: DartId,
        /// the involution
        alpha: usize,
    },
    /// The two orbits are not isomorphic, or the pairing is not one-to-one.
    #[error("the orbits of {first:?} and {second:?} cannot be paired one-to-one by alpha_{alpha}-sewing (conflict at {at:?})")]
    NotIsomorphic {
        /// first dart given
        first: DartId,
        /// second dart given
        second: DartId,
        /// the involution
        alpha: usize,
        /// a dart where the pairing fails
        at: DartId,
    },
    /// The connected component of a dart has no orientation (BO Def. 7): `alpha` links
    /// `dart` to `other`, and both are reached from the starting dart with the same parity.
    #[error("the component is not orientable: alpha_{alpha} links darts {dart:?} and {other:?} of the same class")]
    NotOrientable {
        /// a dart where the 2-colouring fails
        dart: DartId,
        /// the involution along which it fails
        alpha: usize,
        /// its neighbour of the same class
        other: DartId,
    },
    /// An attribute of i-cells was asked of a map without i-cells (`i > n`).
    #[error("there are no {cell}-cells in a map of dimension {dim}")]
    NoSuchCells {
        /// the cell dimension asked for
        cell: usize,
        /// the map's dimension
        dim: usize,
    },
}

/// What [`GMap::validate`] finds wrong: the involutions, or the attributes.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
#[non_exhaustive]
pub enum MapDefect {
    /// BO Def. 1 fails (darts numbered as in [`GMap::to_dense_map`]).
    #[error(transparent)]
    Structure(#[from] crate::error::ValidityError),
    /// A cell's darts disagree on its attribute or point, or a count is wrong.
    #[error(transparent)]
    Attribute(#[from] AttributeDefect),
}

/// The dart pairs a sew links, in the order of the parallel traversal (the given pair first).
type Pairs = SmallVec<[(DartId, DartId); 16]>;

/// The same pairs by slot number, as the traversal finds them.
type SlotPairs = SmallVec<[(u32, u32); 16]>;

/// The pairing of two sew orbits while it is built, by slot number: the pairs in traversal
/// order, looked up by a linear scan while they are few (sew orbits of surfaces and volumes
/// have a few darts) and through two hash maps beyond [`Pairing::LINEAR`] pairs.
#[derive(Default)]
struct Pairing {
    pairs: SlotPairs,
    index: Option<(HashMap<u32, u32>, HashMap<u32, u32>)>,
}

impl Pairing {
    /// The number of pairs up to which lookups scan the list.
    const LINEAR: usize = 32;

    /// Adds the pair `(a, b)`.
    fn push(&mut self, a: u32, b: u32) {
        self.pairs.push((a, b));
        match &mut self.index {
            Some((fwd, bwd)) => {
                fwd.insert(a, b);
                bwd.insert(b, a);
            }
            None if self.pairs.len() > Self::LINEAR => {
                self.index =
                    Some((self.pairs.iter().copied().collect(), self.pairs.iter().map(|&(a, b)| (b, a)).collect()));
            }
            None => {}
        }
    }

    /// The partner of a first-side dart `a`.
    #[inline]
    fn forward(&self, a: u32) -> Option<u32> {
        match &self.index {
            Some((fwd, _)) => fwd.get(&a).copied(),
            None => self.pairs.iter().find(|p| p.0 == a).map(|p| p.1),
        }
    }

    /// The partner of a second-side dart `b`.
    #[inline]
    fn backward(&self, b: u32) -> Option<u32> {
        match &self.index {
            Some((_, bwd)) => bwd.get(&b).copied(),
            None => self.pairs.iter().find(|p| p.1 == b).map(|p| p.0),
        }
    }
}

/// The panic of the panicking forms, out of the hot paths.
#[cold]
#[inline(never)]
#[track_caller]
fn refuse(e: EditError) -> ! {
    panic!("{e}")
}

/// An editable n-dimensional generalized map (BO Def. 1) with stable dart handles.
///
/// ```
/// use gmap_core::GMap;
/// // A triangle as a 1-map: 6 darts, alpha_0 pairs the darts of an edge,
/// // alpha_1 the darts of a vertex.
/// let mut m = GMap::new(1);
/// let d: Vec<_> = (0..6).map(|_| m.create_dart()).collect();
/// for k in 0..3 {
///     m.sew(d[2 * k], d[2 * k + 1], 0);
///     m.sew(d[2 * k + 1], d[(2 * k + 2) % 6], 1);
/// }
/// let dense = m.to_dense_map();
/// assert_eq!(dense.cell_counts(), vec![3, 3]);
/// ```
///
/// `A` lists the attributes of each dimension ([`crate::attr`]); every map also has a point
/// per vertex ([`GMap::point`]).
#[derive(Clone, Debug)]
pub struct GMap<A: Attributes = ()> {
    dim: usize,
    darts: DartStore,
    marks: Marks,
    points: Points,
    attrs: A,
}

impl GMap {
    /// An empty map of dimension `dim`, without attributes. Panics if `dim > MAX_DIM`.
    /// [`GMap::with_attributes`] makes a map with attributes.
    pub fn new(dim: usize) -> Self {
        Self::with_attributes(dim)
    }

    /// Thaws a dense map: the handle of dense dart `k` is `ids[k]`. O(N n).
    /// [`GMap::from_dense_with_attributes`] makes a map with attributes.
    pub fn from_dense(m: &DenseMap) -> (GMap, Vec<DartId>) {
        Self::from_dense_with_attributes(m)
    }
}

impl<A: Attributes> GMap<A> {
    /// An empty map of dimension `dim` whose cells may carry the attributes `A` (none set
    /// yet). Panics if `dim > MAX_DIM`. Slots of `A` beyond `dim` stay empty.
    pub fn with_attributes(dim: usize) -> Self {
        assert!(dim <= MAX_DIM, "dimension {dim} exceeds MAX_DIM");
        GMap { dim, darts: DartStore::new(dim), marks: Marks::new(0), points: Points::default(), attrs: A::default() }
    }

    /// The dimension n.
    pub fn dim(&self) -> usize {
        self.dim
    }

    /// Number of live darts.
    pub fn dart_count(&self) -> usize {
        self.darts.len()
    }

    /// Whether the handle names a live dart.
    pub fn contains(&self, d: DartId) -> bool {
        self.darts.contains(d)
    }

    /// The live darts, in storage order.
    pub fn darts(&self) -> impl Iterator<Item = DartId> + '_ {
        self.darts.keys()
    }

    /// A dense index for a live dart, stable while the dart lives, below [`GMap::index_bound`].
    /// Marks are stored by this index.
    pub fn dart_index(&self, d: DartId) -> usize {
        dart_index(d)
    }

    /// An upper bound on [`GMap::dart_index`] of every live dart.
    pub fn index_bound(&self) -> usize {
        self.darts.bound()
    }

    /// Bytes an editable map of `darts` darts of dimension `dim` may take, with the frozen
    /// copy a query makes of it: the dart store (involutions, handles, marks), the cell
    /// attribute and point slots, and the dense map's involutions, ids and slot numbers. An
    /// estimate for the memory policy ([`crate::resources::check_memory`]), taken before a
    /// caller creates that many darts; `None` past `u64`.
    pub fn memory_estimate(dim: usize, darts: u64) -> Option<u64> {
        darts.checked_mul(12 * (dim as u64 + 1) + 96)
    }

    /// Creates a dart free for every involution.
    pub fn create_dart(&mut self) -> DartId {
        let d = self.darts.insert();
        let bound = self.dart_index(d) + 1;
        if self.marks.len() < bound {
            self.marks.resize(bound.max(self.marks.len() * 2));
        }
        d
    }

    /// Makes room for `n` more darts, so that creating them does not reallocate. O(N) when
    /// the storage grows.
    pub(crate) fn reserve_darts(&mut self, n: usize) {
        self.darts.reserve(n);
        let bound = self.index_bound();
        if self.marks.len() < bound {
            self.marks.resize(bound.max(self.marks.len() * 2));
        }
    }

    /// Creates `n` darts free for every involution in consecutive fresh slots (freed slots
    /// are not reused) and returns the index of the first: dart `first + k` is
    /// [`GMap::block_dart`]`(first + k)`, linked by [`GMap::link_block`]. O(n · dim).
    pub(crate) fn create_block(&mut self, n: usize) -> usize {
        let first = self.darts.insert_block(n);
        let bound = self.index_bound();
        if self.marks.len() < bound {
            self.marks.resize(bound.max(self.marks.len() * 2));
        }
        first
    }

    /// The handle of the dart at index `k` of a block from [`GMap::create_block`].
    #[inline]
    pub(crate) fn block_dart(&self, k: usize) -> DartId {
        self.darts.slot_id(k as u32)
    }

    /// `alpha_i` links the darts at indices `a` and `b` of a block from
    /// [`GMap::create_block`], both i-free (the caller's precondition). O(1).
    #[inline]
    pub(crate) fn link_block(&mut self, a: usize, b: usize, i: usize) {
        self.darts.link_slots(a, b, i);
    }

    /// Gives the point `p` to the vertex whose darts are exactly `vertex`, live darts none
    /// of which has a point (the caller's precondition: a vertex just made), without walking
    /// it. O(|vertex|).
    pub(crate) fn set_fresh_point(&mut self, vertex: &[DartId], p: Point) {
        let bound = self.index_bound();
        self.points.set_fresh(bound, vertex, p);
    }

    /// `alpha_i(d) = e`, `alpha_i(e) = d` for live darts `d`, `e` that are both i-free and
    /// `i <= n` (the caller's precondition): [`GMap::link`] without its checks. O(1).
    pub(crate) fn link_free(&mut self, d: DartId, e: DartId, i: usize) {
        self.darts.set_alpha(d, i, e);
        self.darts.set_alpha(e, i, d);
    }

    /// Removes a dart, first making its partners free. Other handles stay valid.
    /// May leave the map invalid (a hole in an orbit); callers re-sew or remove whole cells.
    /// The dart's attributes and point lose one user (a value no dart uses any more is
    /// freed); the cells are not reconciled: a caller that removes darts of a cell that
    /// stays calls [`GMap::reconcile_attributes`] with the former neighbours.
    ///
    /// # Panics
    /// If `d` is not a live dart (removed, or of another map); [`GMap::try_remove_dart`]
    /// returns the error.
    #[track_caller]
    pub fn remove_dart(&mut self, d: DartId) {
        if let Err(e) = self.try_remove_dart(d) {
            refuse(e)
        }
    }

    /// [`GMap::remove_dart`], or [`EditError::NoSuchDart`] (and no change) for a handle that
    /// does not name a live dart.
    pub fn try_remove_dart(&mut self, d: DartId) -> Result<(), EditError> {
        self.live(d)?;
        let topo = Topo { dim: self.dim, darts: &self.darts };
        self.points.drop_dart(&topo, 0, d);
        if !A::EMPTY {
            self.attrs.drop_dart_all(&topo, d);
        }
        for i in 0..=self.dim {
            self.unlink_unchecked(d, i);
        }
        let idx = self.dart_index(d);
        self.darts.remove(d);
        // marks are stored by slot index: clear them so a reused slot starts unmarked
        self.marks.clear_index(idx);
        Ok(())
    }

    /// Checks that `d` names a live dart (the handle's version is the slot's: a handle of a
    /// removed dart is refused even when a new dart reuses the slot).
    #[inline]
    fn live(&self, d: DartId) -> Result<(), EditError> {
        if self.darts.contains(d) {
            Ok(())
        } else {
            Err(EditError::NoSuchDart(d))
        }
    }

    /// Checks that `d` names a live dart and `i <= n`.
    #[inline]
    fn check_dart_index(&self, d: DartId, i: usize) -> Result<(), EditError> {
        if i > self.dim {
            return Err(EditError::BadIndex { alpha: i, dim: self.dim });
        }
        self.live(d)
    }

    /// `alpha_i(d)`.
    ///
    /// # Panics
    /// On a stale handle or `i > n`; [`GMap::try_alpha`] returns the error.
    #[inline]
    #[track_caller]
    pub fn alpha(&self, d: DartId, i: usize) -> DartId {
        match self.darts.get_alpha(d, i) {
            Some(e) => e,
            None => refuse(self.check_dart_index(d, i).expect_err("refused")),
        }
    }

    /// `alpha_i(d)`, or an error for a stale handle or `i > n`.
    pub fn try_alpha(&self, d: DartId, i: usize) -> Result<DartId, EditError> {
        self.check_dart_index(d, i)?;
        Ok(self.darts.alpha(d, i))
    }

    /// The dart reached from `d` by applying the involutions of `word` in order, first
    /// letter first: `alpha_word(d, &[0, 1])` is `alpha_1(alpha_0(d))` (CGAL's
    /// `alpha<0, 1>(d)`). O(|word|).
    ///
    /// # Panics
    /// Like [`GMap::alpha`]; [`GMap::try_alpha_word`] returns the error.
    #[track_caller]
    pub fn alpha_word(&self, d: DartId, word: &[usize]) -> DartId {
        word.iter().fold(d, |x, &i| self.alpha(x, i))
    }

    /// [`GMap::alpha_word`], or an error for a stale handle or a letter above n.
    pub fn try_alpha_word(&self, d: DartId, word: &[usize]) -> Result<DartId, EditError> {
        word.iter().try_fold(d, |x, &i| self.try_alpha(x, i))
    }

    /// Whether `d` is i-free.
    ///
    /// # Panics
    /// Like [`GMap::alpha`].
    #[track_caller]
    pub fn is_free(&self, d: DartId, i: usize) -> bool {
        self.alpha(d, i) == d
    }

    /// Low-level: `alpha_i(d) = e`, `alpha_i(e) = d`, freeing former partners. Keeps
    /// `alpha_i` an involution but may break the other conditions of BO Def. 1.
    /// Attributes and points are not reconciled: call [`GMap::reconcile_attributes`] with
    /// the darts whose links changed once the edit is complete.
    ///
    /// # Panics
    /// On a stale handle or `i > n` (nothing is changed then); [`GMap::try_link`] returns
    /// the error.
    #[track_caller]
    pub fn link(&mut self, d: DartId, e: DartId, i: usize) {
        if let Err(err) = self.try_link(d, e, i) {
            refuse(err)
        }
    }

    /// [`GMap::link`], or an error (and no change) for a stale handle or `i > n`.
    pub fn try_link(&mut self, d: DartId, e: DartId, i: usize) -> Result<(), EditError> {
        self.check_dart_index(d, i)?;
        self.check_dart_index(e, i)?;
        self.unlink_unchecked(d, i);
        self.unlink_unchecked(e, i);
        self.darts.set_alpha(d, i, e);
        self.darts.set_alpha(e, i, d);
        Ok(())
    }

    /// Low-level: makes `d` and its `alpha_i` partner i-free. May break validity.
    /// Attributes and points are not reconciled (see [`GMap::link`]).
    ///
    /// # Panics
    /// On a stale handle or `i > n`; [`GMap::try_unlink`] returns the error.
    #[track_caller]
    pub fn unlink(&mut self, d: DartId, i: usize) {
        if let Err(err) = self.try_unlink(d, i) {
            refuse(err)
        }
    }

    /// [`GMap::unlink`], or an error (and no change) for a stale handle or `i > n`.
    pub fn try_unlink(&mut self, d: DartId, i: usize) -> Result<(), EditError> {
        self.check_dart_index(d, i)?;
        self.unlink_unchecked(d, i);
        Ok(())
    }

    /// `unlink` for a live dart and an index checked by the caller.
    fn unlink_unchecked(&mut self, d: DartId, i: usize) {
        let e = self.darts.alpha(d, i);
        self.darts.set_alpha(d, i, d);
        if self.darts.contains(e) && self.darts.alpha(e, i) == d {
            self.darts.set_alpha(e, i, e);
        }
    }

    /// The point of the vertex (0-cell) of `d`, the same from every dart of the vertex. O(1).
    ///
    /// # Panics
    /// On a stale handle; [`GMap::try_point`] returns the error.
    #[track_caller]
    pub fn point(&self, d: DartId) -> Option<Point> {
        match self.try_point(d) {
            Ok(p) => p,
            Err(e) => refuse(e),
        }
    }

    /// [`GMap::point`], or [`EditError::NoSuchDart`] for a stale handle.
    pub fn try_point(&self, d: DartId) -> Result<Option<Point>, EditError> {
        self.live(d)?;
        Ok(self.points.get_at(dart_index(d)).copied())
    }

    /// Sets (`Some`) or removes (`None`) the point of the vertex of `d`, for every dart of
    /// the vertex. O(1) when the vertex has a point, O(vertex size · n) otherwise.
    ///
    /// A vertex keeps its point through edits: a sew joining two vertices keeps the point
    /// of the first dart's vertex, an unsew splitting a vertex gives both parts the point.
    ///
    /// # Panics
    /// On a stale handle; [`GMap::try_set_point`] returns the error.
    #[track_caller]
    pub fn set_point(&mut self, d: DartId, p: Option<Point>) {
        if let Err(e) = self.try_set_point(d, p) {
            refuse(e)
        }
    }

    /// [`GMap::set_point`], or [`EditError::NoSuchDart`] (and no change) for a stale handle.
    pub fn try_set_point(&mut self, d: DartId, p: Option<Point>) -> Result<(), EditError> {
        self.live(d)?;
        let topo = Topo { dim: self.dim, darts: &self.darts };
        match p {
            Some(p) => {
                self.points.set(&topo, 0, d, p);
            }
            None => {
                self.points.remove(&topo, 0, d);
            }
        }
        Ok(())
    }

    /// Whether some vertex has a point.
    pub fn has_points(&self) -> bool {
        !self.points.is_empty()
    }

    /// Number of vertices with a point.
    pub fn point_count(&self) -> usize {
        self.points.len()
    }

    /// The handle of the point of the vertex of a live dart `d` (one handle per vertex while
    /// the attributes are consistent), for the geometry routines. O(1).
    pub(crate) fn point_id(&self, d: DartId) -> Option<AttrId> {
        self.points.id_at(dart_index(d))
    }

    /// The point of a handle from [`GMap::point_id`], mutably. O(1).
    pub(crate) fn point_by_id_mut(&mut self, id: AttrId) -> Option<&mut Point> {
        self.points.get_id_mut(id)
    }

    /// Repairs the attributes and points after an edit (the consistency routine of
    /// [`crate::attr`]): for every slot in use, the cell of each dart of `touched` is
    /// walked once; a cell holding several attributes keeps the first one met (from the
    /// first dart of `touched`) and the merge hook folds the others into it; an attribute
    /// held by several cells stays with the first and the split hook runs on a copy for
    /// each other; darts without an attribute in a cell that has one inherit it.
    ///
    /// Precondition: `touched` holds every dart whose involutions changed since the last
    /// reconciliation, and the surviving neighbours of removed darts (removed darts in it are
    /// skipped). [`GMap::sew`] and [`GMap::unsew`] call it; edits through [`GMap::link`],
    /// [`GMap::unlink`] and [`GMap::remove_dart`] need it afterwards.
    ///
    /// O(s · n) per slot in use, s the total size of the walked cells; nothing at all when
    /// no point and no attribute was ever set.
    pub fn reconcile_attributes(&mut self, touched: &[DartId]) {
        let topo = Topo { dim: self.dim, darts: &self.darts };
        self.points.reconcile(&topo, 0, touched);
        if !A::EMPTY {
            self.attrs.reconcile_all(&topo, touched);
        }
    }

    /// Whether edits must call [`GMap::reconcile_attributes`]: `A` has a slot, or a point
    /// was set. When false, an editing routine may skip collecting the darts it touched.
    /// O(1).
    #[inline]
    pub fn needs_reconcile(&self) -> bool {
        !A::EMPTY || self.points.active()
    }

    /// Checks the whole map: BO Def. 1 ([`DenseMap::validate`] on the snapshot), then the
    /// attributes and points ([`GMap::check_attributes`]). O(N n²).
    pub fn validate(&self) -> Result<(), MapDefect> {
        self.to_dense_map().validate()?;
        self.check_attributes()?;
        Ok(())
    }

    /// Checks the attributes and points (see [`crate::attr`]): every two darts of one cell
    /// hold the same attribute (or both none), and every value's count of darts is exact.
    /// Reports the first defect with the darts and dimension. O(N n) per slot in use.
    pub fn check_attributes(&self) -> Result<(), AttributeDefect> {
        let darts: Vec<DartId> = self.darts.keys().collect();
        let topo = Topo { dim: self.dim, darts: &self.darts };
        self.points.check(&topo, 0, &darts).map_err(|e| match e {
            AttributeDefect::Disagree { dart, other, .. } => AttributeDefect::PointDisagree { dart, other },
            e => e,
        })?;
        self.attrs.check_all(&topo, &darts)
    }

    /// The orbit `<set>(d)` in breadth-first order from `d` (involutions above `dim()`
    /// ignored). O(orbit size × |set|).
    pub fn orbit(&self, d: DartId, set: AlphaSet) -> Vec<DartId> {
        let idx: Vec<usize> = set.iter().filter(|&i| i <= self.dim).collect();
        let mut seen: rustc_hash::FxHashSet<DartId> = rustc_hash::FxHashSet::default();
        seen.insert(d);
        let mut out = vec![d];
        let mut k = 0;
        while k < out.len() {
            let x = out[k];
            k += 1;
            for &i in &idx {
                let y = self.alpha(x, i);
                if seen.insert(y) {
                    out.push(y);
                }
            }
        }
        out
    }

    /// The darts of the i-cell of `d` (BO Def. 2).
    pub fn cell_darts(&self, d: DartId, i: usize) -> Vec<DartId> {
        self.orbit(d, AlphaSet::cell(i, self.dim))
    }

    /// The involutions whose orbits are paired by an i-sew:
    /// `<alpha_0..alpha_{i-2}, alpha_{i+2}..alpha_n>`.
    pub fn sew_set(&self, i: usize) -> AlphaSet {
        let mut s = AlphaSet::all(self.dim).without(i);
        if i >= 1 {
            s = s.without(i - 1);
        }
        s.without(i + 1)
    }

    /// Pairs the sew orbits of `d` and `e` by parallel traversal, checking that both
    /// are i-free throughout and that the pairing is one-to-one. O(s · n) for orbits of
    /// s darts up to [`Pairing::LINEAR`] (no allocation below 16 pairs), O(s · n) expected
    /// beyond.
    #[cfg(test)]
    fn sew_pairs(&self, d: DartId, e: DartId, i: usize) -> Result<Pairs, EditError> {
        let slots = self.sew_slots(d, e, i)?;
        Ok(slots.iter().map(|&(a, b)| (self.darts.slot_id(a), self.darts.slot_id(b))).collect())
    }

    /// [`GMap::sew_pairs`] by slot number: the traversal reads the rows of links only.
    fn sew_slots(&self, d: DartId, e: DartId, i: usize) -> Result<SlotPairs, EditError> {
        if i > self.dim {
            return Err(EditError::BadIndex { alpha: i, dim: self.dim });
        }
        for x in [d, e] {
            if !self.contains(x) {
                return Err(EditError::NoSuchDart(x));
            }
        }
        let store = &self.darts;
        let id = |k: u32| store.slot_id(k);
        if d == e && i == 1 {
            // CGAL's one exception: a 1-free dart 1-sewn to itself (a no-op that CGAL's
            // programs use to state that a lone dart is its own corner)
            let k = dart_index(d) as u32;
            if store.slot_alpha(k, 1) != k {
                return Err(EditError::NotFree { dart: d, alpha: 1 });
            }
            return Ok(std::iter::once((k, k)).collect());
        }
        let idx: SmallVec<[usize; 8]> = self.sew_set(i).iter().filter(|&k| k <= self.dim).collect();
        let conflict = |at: u32| EditError::NotIsomorphic { first: d, second: e, alpha: i, at: id(at) };
        let mut pairing = Pairing::default();
        pairing.push(dart_index(d) as u32, dart_index(e) as u32);
        let mut k = 0;
        while k < pairing.pairs.len() {
            let (a, b) = pairing.pairs[k];
            k += 1;
            if a == b {
                return Err(conflict(a));
            }
            for x in [a, b] {
                if store.slot_alpha(x, i) != x {
                    return Err(EditError::NotFree { dart: id(x), alpha: i });
                }
            }
            for &j in &idx {
                let (a2, b2) = (store.slot_alpha(a, j), store.slot_alpha(b, j));
                if (a2 == a) != (b2 == b) {
                    return Err(conflict(a));
                }
                match (pairing.forward(a2), pairing.backward(b2)) {
                    (Some(x), _) if x != b2 => return Err(conflict(a2)),
                    (_, Some(y)) if y != a2 => return Err(conflict(b2)),
                    (Some(_), Some(_)) => {}
                    (None, None) => pairing.push(a2, b2),
                    _ => return Err(conflict(a2)),
                }
            }
        }
        // a dart may appear on both sides (sewing an orbit to itself): then the pairing
        // must be symmetric, or alpha_i would not be an involution
        for &(a, b) in &pairing.pairs {
            if let Some(c) = pairing.forward(b) {
                if c != a {
                    return Err(conflict(b));
                }
            }
        }
        Ok(pairing.pairs)
    }

    /// Whether `d` and `e` can be i-sewn: both sew orbits (see [`GMap::sew_set`]) are
    /// i-free and pair one-to-one by a parallel traversal, and `d != e` — except, as in
    /// CGAL, `i = 1` and `d = e` 1-free (sewing a dart to itself, which changes nothing).
    /// Equivalent to `try_sew` succeeding.
    pub fn is_sewable(&self, d: DartId, e: DartId, i: usize) -> bool {
        self.sew_slots(d, e, i).is_ok()
    }

    /// i-sews `d` and `e` (CGAL's semantics): the sew orbits of `d` and `e` are paired
    /// one-to-one and each pair is linked by `alpha_i`. Keeps a valid map valid.
    /// Attributes and points follow ([`GMap::reconcile_attributes`]): cells that become one
    /// keep the attribute of the cell of `d` (the merge hook runs when both had one).
    /// O(orbit size · n), plus the reconciliation when attributes or points are in use.
    pub fn try_sew(&mut self, d: DartId, e: DartId, i: usize) -> Result<(), EditError> {
        let slots = self.sew_slots(d, e, i)?;
        for &(a, b) in &slots {
            self.darts.link_slots(a as usize, b as usize, i);
        }
        if self.needs_reconcile() {
            let pairs: Pairs = slots.iter().map(|&(a, b)| (self.darts.slot_id(a), self.darts.slot_id(b))).collect();
            // the same result as `reconcile_attributes` on the first sides then the second
            // sides of the pairs, from the pairing: the i-cells do not change, and the
            // other cells only merge
            let topo = Topo { dim: self.dim, darts: &self.darts };
            if i != 0 {
                self.points.reconcile_sewn(&topo, 0, &pairs);
            }
            if !A::EMPTY {
                self.attrs.reconcile_sewn_all(&topo, i, &pairs);
            }
        }
        Ok(())
    }

    /// Like [`GMap::try_sew`], panicking if the darts are not sewable.
    ///
    /// # Panics
    /// With the message of the [`EditError`] `try_sew` returns.
    #[track_caller]
    pub fn sew(&mut self, d: DartId, e: DartId, i: usize) {
        if let Err(err) = self.try_sew(d, e, i) {
            panic!("sew failed: {err}");
        }
    }

    /// i-unsews `d`: every dart of its sew orbit becomes i-free. Keeps a valid map valid.
    /// A no-op when `d` is already i-free. Attributes and points follow
    /// ([`GMap::reconcile_attributes`]): a cell cut in two keeps its attribute on the side of
    /// `d` and a copy on the other (the split hook runs on it); a vertex keeps its point on
    /// both sides.
    ///
    /// # Panics
    /// On a stale handle or `i > n`; [`GMap::try_unsew`] returns the error.
    #[track_caller]
    pub fn unsew(&mut self, d: DartId, i: usize) {
        if let Err(e) = self.try_unsew(d, i) {
            refuse(e)
        }
    }

    /// [`GMap::unsew`], or an error (and no change) for a stale handle or `i > n`.
    pub fn try_unsew(&mut self, d: DartId, i: usize) -> Result<(), EditError> {
        self.check_dart_index(d, i)?;
        if self.is_free(d, i) {
            return Ok(());
        }
        let orbit = self.orbit(d, self.sew_set(i));
        let partners: Vec<DartId> =
            if self.needs_reconcile() { orbit.iter().map(|&x| self.darts.alpha(x, i)).collect() } else { Vec::new() };
        for &x in &orbit {
            self.unlink_unchecked(x, i);
        }
        if self.needs_reconcile() {
            let mut touched = orbit;
            touched.extend(partners);
            // the i-cells do not change: only the other dimensions can split
            let topo = Topo { dim: self.dim, darts: &self.darts };
            if i != 0 {
                self.points.reconcile(&topo, 0, &touched);
            }
            if !A::EMPTY {
                self.attrs.reconcile_except_all(&topo, i, &touched);
            }
        }
        Ok(())
    }

    /// The dense snapshot of the map, for the whole-map kernels of [`DenseMap`]: darts
    /// renumbered `0..N` in storage order ([`GMap::darts`]), points kept. O(N n); when no dart
    /// was ever removed from the middle (the slots are contiguous) the numbering is the slot
    /// number and no table is built. [`GMap::to_dense_with_ids`] also gives each dense dart's
    /// handle.
    pub fn to_dense_map(&self) -> DenseMap {
        let first = self.darts.keys().next().map_or(0, dart_index);
        let contiguous = self.darts.keys().enumerate().all(|(k, d)| dart_index(d) == first + k);
        if !contiguous {
            return self.to_dense_with_ids().0;
        }
        let w = self.dim + 1;
        let mut flat = Vec::with_capacity(self.darts.len() * w);
        let first = first as u32;
        for (_, row) in self.darts.live_rows() {
            flat.extend(row.iter().map(|&x| x - first));
        }
        self.dense_with_points(flat, self.darts.keys())
    }

    /// The dense snapshot ([`GMap::to_dense_map`]) and the handle of each dense dart: dense
    /// dart `k` is `ids[k]`. O(N n).
    pub fn to_dense_with_ids(&self) -> (DenseMap, Vec<DartId>) {
        let ids: Vec<DartId> = self.darts.keys().collect();
        let first = ids.first().map_or(0, |&d| dart_index(d));
        if ids.iter().enumerate().all(|(k, &d)| dart_index(d) == first + k) {
            // consecutive slots: the rows shifted, no index map
            let first = first as u32;
            let mut flat = Vec::with_capacity(ids.len() * (self.dim + 1));
            for (_, row) in self.darts.live_rows() {
                flat.extend(row.iter().map(|&x| x - first));
            }
            let dense = self.dense_with_points(flat, ids.iter().copied());
            return (dense, ids);
        }
        let mut index: slotmap::SecondaryMap<DartId, u32> = slotmap::SecondaryMap::with_capacity(ids.len());
        for (k, &d) in ids.iter().enumerate() {
            index.insert(d, k as u32);
        }
        let w = self.dim + 1;
        let mut flat = Vec::with_capacity(ids.len() * w);
        for &d in &ids {
            for i in 0..w {
                flat.push(index[self.darts.alpha(d, i)]);
            }
        }
        let dense = self.dense_with_points(flat, ids.iter().copied());
        (dense, ids)
    }

    /// The dense map of rows `flat`, with the point of each dart of `ids` (dense order).
    fn dense_with_points(&self, flat: Vec<u32>, ids: impl Iterator<Item = DartId>) -> DenseMap {
        let mut dense = DenseMap::from_flat_unchecked(self.dim, flat).expect("sizes checked on creation");
        if self.points.active() {
            // one table entry per vertex value: the darts of a vertex share it
            let mut index = Vec::with_capacity(dense.dart_count());
            let mut table = Vec::with_capacity(self.points.len());
            let mut entry_of = vec![u32::MAX; self.points.slab_len()];
            for d in ids {
                let k = dart_index(d);
                index.push(match self.points.get_at(k) {
                    Some(&p) => {
                        let e = &mut entry_of[self.points.handle(k) as usize];
                        if *e == u32::MAX {
                            table.push(p);
                            *e = (table.len() - 1) as u32;
                        }
                        *e
                    }
                    None => u32::MAX,
                });
            }
            dense.set_point_table(index, table);
        }
        dense
    }

    /// Thaws a dense map into a map with attributes `A` (none set): the handle of dense dart
    /// `k` is `ids[k]`. A vertex takes the point of its first dart (in dense order) that has
    /// one. O(N n).
    pub fn from_dense_with_attributes(m: &DenseMap) -> (Self, Vec<DartId>) {
        let mut g = Self::with_attributes(m.dim());
        let ids: Vec<DartId> = (0..m.dart_count()).map(|_| g.create_dart()).collect();
        for d in m.darts() {
            let row = m.row(d);
            for (i, &e) in row.iter().enumerate() {
                g.darts.set_alpha(ids[d.index()], i, ids[e as usize]);
            }
        }
        if m.has_points() {
            for d in m.darts() {
                if let Some(p) = m.point(d) {
                    let x = ids[d.index()];
                    if g.points.get_at(dart_index(x)).is_none() {
                        g.set_point(x, Some(p));
                    }
                }
            }
        }
        (g, ids)
    }
}

/// The whole-map questions, with the names and answers of [`DenseMap`]'s: each runs the dense
/// kernel on one snapshot ([`GMap::to_dense_map`], O(N n)), so darts in the answers are
/// numbered as in [`GMap::darts`]. To ask several, take the snapshot once.
impl<A: Attributes> GMap<A> {
    /// The i-cells as a partition of the darts (see [`DenseMap::cells`]).
    pub fn cells(&self, i: usize) -> Partition {
        self.to_dense_map().cells(i)
    }

    /// Number of i-cells for `i = 0..=n` (see [`DenseMap::cell_counts`]).
    pub fn cell_counts(&self) -> Vec<usize> {
        self.to_dense_map().cell_counts()
    }

    /// The alternating sum of [`cell_counts`](GMap::cell_counts).
    pub fn euler_characteristic(&self) -> i64 {
        self.to_dense_map().euler_characteristic()
    }

    /// The connected components as a partition of the darts.
    pub fn components(&self) -> Partition {
        self.to_dense_map().components()
    }

    /// Number of connected components.
    pub fn component_count(&self) -> usize {
        self.to_dense_map().component_count()
    }

    /// An orientation (BO Def. 7): a bit per dart, or the first conflict (BO Def. 8).
    pub fn orientation(&self) -> Result<BitVec, OrientationConflict> {
        self.to_dense_map().orientation()
    }

    /// Whether the map is orientable (BO Def. 7).
    pub fn is_orientable(&self) -> bool {
        self.to_dense_map().is_orientable()
    }

    /// Checks BO Def. 6 (complete boundaries); see [`DenseMap::check_complete_boundaries`].
    pub fn check_complete_boundaries(&self) -> Result<(), BoundaryDefect> {
        self.to_dense_map().check_complete_boundaries()
    }

    /// Whether the map has cells with complete boundaries (BO Def. 6).
    pub fn has_complete_boundaries(&self) -> bool {
        self.check_complete_boundaries().is_ok()
    }

    /// Number of i-cells (see [`DenseMap::cell_count`]).
    pub fn cell_count(&self, i: usize) -> usize {
        self.to_dense_map().cell_count(i)
    }

    /// Whether [`GMap::validate`] succeeds (CGAL's `is_valid`).
    pub fn is_valid(&self) -> bool {
        self.validate().is_ok()
    }
}

impl<A: Attributes> MapView for GMap<A> {
    type Dart = DartId;

    fn dim(&self) -> usize {
        GMap::dim(self)
    }

    fn dart_count(&self) -> usize {
        GMap::dart_count(self)
    }

    fn dart_list(&self) -> Vec<DartId> {
        self.darts().collect()
    }

    fn alpha(&self, d: DartId, i: usize) -> DartId {
        GMap::alpha(self, d, i)
    }

    fn with_dense<R>(&self, f: impl FnOnce(&DenseMap) -> R) -> R {
        f(&self.to_dense_map())
    }
}

mod attributes;
mod bulk;
mod marking;

#[cfg(test)]
mod tests;
