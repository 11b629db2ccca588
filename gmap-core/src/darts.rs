//! The storage of an editable map's darts: the stable handle [`DartId`] and what each dart
//! holds. Shared by the map ([`crate::edit`]) and its attributes ([`crate::attr`]); it
//! imports nothing of the crate.

use slotmap::{new_key_type, Key};
use smallvec::SmallVec;

new_key_type! {
    /// A stable handle to a dart of a [`GMap`](crate::GMap).
    pub struct DartId;
}

/// Per-dart storage: the involution images.
#[derive(Clone, Debug)]
pub(crate) struct DartData {
    pub(crate) alpha: SmallVec<[DartId; 5]>,
}

/// The dense index of a dart handle: its slot number (see [`GMap::dart_index`](crate::GMap::dart_index)).
#[inline]
pub(crate) fn dart_index(d: DartId) -> usize {
    (d.data().as_ffi() & 0xffff_ffff) as usize
}
