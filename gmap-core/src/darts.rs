//! The storage of an editable map's darts: the stable handle [`DartId`] and what each dart
//! holds. Shared by the map ([`crate::edit`]) and its attributes ([`crate::attr`]); it
//! imports nothing of the crate.

use slotmap::{new_key_type, Key, KeyData};

new_key_type! {
    /// A stable handle to a dart of a [`GMap`](crate::GMap).
    pub struct DartId;
}

/// The dense index of a dart handle: its slot number (see [`GMap::dart_index`](crate::GMap::dart_index)).
#[inline]
pub(crate) fn dart_index(d: DartId) -> usize {
    (d.data().as_ffi() & 0xffff_ffff) as usize
}

/// The darts of an editable map, one row of `u32` per slot: the slot's version, then the
/// slot number of each involution image (`alpha_0 .. alpha_n`). A [`DartId`] is a slot
/// number and a version (odd while the slot is live, even once it is freed), as in a
/// slotmap, so the handle of a removed dart is recognised as stale even when its slot is
/// reused; freed slots are reused last freed first.
///
/// Rows of `n + 2` words (20 bytes in a 3-map, against 48 for a slotmap entry holding
/// `DartId` images) keep a dart and its images in one cache line, and `alpha_i(d)` reads
/// the version of the image in the image's own row, the row an orbit walk reads next.
/// Slot 0 is a sentinel that is never live, so dart indices start at 1.
#[derive(Clone, Debug)]
pub(crate) struct DartStore {
    /// words per row: `dim + 2`
    stride: usize,
    rows: Vec<u32>,
    /// freed slots, the last freed on top
    free: Vec<u32>,
    live: usize,
}

impl DartStore {
    /// An empty store for darts with `dim + 1` involutions.
    pub(crate) fn new(dim: usize) -> Self {
        let stride = dim + 2;
        DartStore { stride, rows: vec![0; stride], free: Vec::new(), live: 0 }
    }

    /// Number of live darts.
    #[inline]
    pub(crate) fn len(&self) -> usize {
        self.live
    }

    /// Number of slots (the sentinel included): a strict upper bound on the dart indices.
    #[inline]
    pub(crate) fn bound(&self) -> usize {
        self.rows.len() / self.stride
    }

    #[inline]
    fn key(idx: u32, version: u32) -> DartId {
        DartId::from(KeyData::from_ffi((u64::from(version) << 32) | u64::from(idx)))
    }

    #[inline]
    fn version_of(d: DartId) -> u32 {
        (d.data().as_ffi() >> 32) as u32
    }

    /// Whether `d` names a live dart of this store.
    #[inline]
    pub(crate) fn contains(&self, d: DartId) -> bool {
        let k = dart_index(d);
        k < self.bound() && self.rows[k * self.stride] == Self::version_of(d)
    }

    /// The handle of the live dart in slot `k`. Precondition: the slot is live.
    #[inline]
    pub(crate) fn slot_id(&self, k: u32) -> DartId {
        Self::key(k, self.rows[k as usize * self.stride])
    }

    /// `alpha_i` of the live dart in slot `k`, as a slot number, for `i <= n`.
    #[inline]
    pub(crate) fn slot_alpha(&self, k: u32, i: usize) -> u32 {
        self.rows[k as usize * self.stride + 1 + i]
    }

    /// `alpha_i(d)` for a live dart `d` and `i <= n` (the caller's precondition).
    #[inline]
    pub(crate) fn alpha(&self, d: DartId, i: usize) -> DartId {
        self.slot_id(self.rows[dart_index(d) * self.stride + 1 + i])
    }

    /// `alpha_i(d)`, or `None` when `d` is not live or `i > n`.
    #[inline]
    pub(crate) fn get_alpha(&self, d: DartId, i: usize) -> Option<DartId> {
        (i + 2 <= self.stride && self.contains(d)).then(|| self.alpha(d, i))
    }

    /// Sets `alpha_i(d) = e` (one side only) for live darts and `i <= n`.
    #[inline]
    pub(crate) fn set_alpha(&mut self, d: DartId, i: usize, e: DartId) {
        self.rows[dart_index(d) * self.stride + 1 + i] = dart_index(e) as u32;
    }

    /// A new dart, free for every involution.
    pub(crate) fn insert(&mut self) -> DartId {
        let k = match self.free.pop() {
            Some(k) => {
                let at = k as usize * self.stride;
                self.rows[at] = self.rows[at].wrapping_add(1) | 1;
                self.rows[at + 1..at + self.stride].fill(k);
                k
            }
            None => {
                let k = u32::try_from(self.bound()).expect("fewer than 2^32 dart slots");
                self.rows.push(1);
                self.rows.extend(std::iter::repeat_n(k, self.stride - 1));
                k
            }
        };
        self.live += 1;
        self.slot_id(k)
    }

    /// `n` new darts in fresh consecutive slots (the free slots are left for later),
    /// free for every involution: the index of the first. O(n), one write per word.
    pub(crate) fn insert_block(&mut self, n: usize) -> usize {
        let first = self.bound();
        assert!(first + n <= u32::MAX as usize, "fewer than 2^32 dart slots");
        self.rows.reserve(n * self.stride);
        for k in first as u32..(first + n) as u32 {
            self.rows.push(1);
            self.rows.extend(std::iter::repeat_n(k, self.stride - 1));
        }
        self.live += n;
        first
    }

    /// Whether slot `k` (below [`DartStore::bound`]) holds a live dart.
    #[inline]
    pub(crate) fn slot_live(&self, k: usize) -> bool {
        self.rows[k * self.stride] & 1 == 1
    }

    /// Sets `alpha_i` of slot `k` to slot `e` (one side only), by slot number.
    #[inline]
    pub(crate) fn set_slot_alpha(&mut self, k: usize, i: usize, e: usize) {
        self.rows[k * self.stride + 1 + i] = e as u32;
    }

    /// Links slots `a` and `b` by `alpha_i` (both sides), by slot number.
    #[inline]
    pub(crate) fn link_slots(&mut self, a: usize, b: usize, i: usize) {
        self.rows[a * self.stride + 1 + i] = b as u32;
        self.rows[b * self.stride + 1 + i] = a as u32;
    }

    /// Room for `n` more darts without reallocating.
    pub(crate) fn reserve(&mut self, n: usize) {
        self.rows.reserve(n * self.stride);
    }

    /// Frees the slot of a live dart `d` (its links are left as they are: the caller
    /// unlinks first).
    pub(crate) fn remove(&mut self, d: DartId) {
        let k = dart_index(d);
        let at = k * self.stride;
        self.rows[at] = self.rows[at].wrapping_add(1);
        self.free.push(k as u32);
        self.live -= 1;
    }

    /// The live darts, in slot order.
    pub(crate) fn keys(&self) -> impl Iterator<Item = DartId> + '_ {
        (1..self.bound() as u32).filter(|&k| self.rows[k as usize * self.stride] & 1 == 1).map(|k| self.slot_id(k))
    }

    /// The live slots with their rows of images, in slot order.
    pub(crate) fn live_rows(&self) -> impl Iterator<Item = (usize, &[u32])> + '_ {
        self.rows
            .chunks_exact(self.stride)
            .enumerate()
            .skip(1)
            .filter(|(_, r)| r[0] & 1 == 1)
            .map(|(k, r)| (k, &r[1..]))
    }
}
