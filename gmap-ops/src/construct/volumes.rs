//! Volumes merged across a face and split by a loop of edges (Moka's fusion and cut of
//! volumes), in a map of dimension 3 or more: the face removal and insertion of the Euler
//! operators under the names a modeller looks for. Each is a subdivision or its inverse:
//! Δχ = 0 (a face and a volume go or come together), asserted in the tests.

use gmap_core::{Attributes, DartId, GMap};

use super::ConstructError;
use crate::euler::ops::{
    insert_cell_2_in_cell_3, is_insertable_cell_2_in_cell_3, is_removable_keeping_homology,
    try_remove_cell_keeping_homology,
};

/// Checks that the map has volumes.
fn has_volumes<A: Attributes>(g: &GMap<A>, what: &'static str) -> Result<(), ConstructError> {
    if g.dim() < 3 {
        return Err(ConstructError::BadDimension { what, lo: 3, hi: g.dim(), got: 3 });
    }
    Ok(())
}

/// Whether [`try_merge_volumes`] would succeed: `n >= 3` and the face of `d` can be removed
/// ([`is_removable_keeping_homology`] with `i = 2`: it separates two distinct volumes, degree 2).
pub fn can_merge_volumes<A: Attributes>(g: &GMap<A>, d: DartId) -> bool {
    g.dim() >= 3 && g.contains(d) && is_removable_keeping_homology(g, d, 2)
}

/// Merges the two volumes on either side of the face of `d` into one by removing the face
/// (CGAL's `remove_cell<2>`). The merged volume keeps the attribute of the volume of `d`
/// (the merge hook runs when both had one). Δχ = 0 (-1 face, -1 volume). O(size of the
/// cells touched · n).
pub fn try_merge_volumes<A: Attributes>(g: &mut GMap<A>, d: DartId) -> Result<(), ConstructError> {
    has_volumes(g, "a merge of volumes")?;
    if !g.contains(d) {
        return Err(ConstructError::NoSuchDart(d));
    }
    try_remove_cell_keeping_homology(g, d, 2)?;
    Ok(())
}

/// Like [`try_merge_volumes`], panicking when the precondition fails.
#[track_caller]
pub fn merge_volumes<A: Attributes>(g: &mut GMap<A>, d: DartId) {
    try_merge_volumes(g, d).unwrap_or_else(|e| panic!("merge_volumes: {e}"))
}

/// Whether [`try_split_volume`] would succeed ([`is_insertable_cell_2_in_cell_3`]).
pub fn can_split_volume<A: Attributes>(g: &GMap<A>, path: &[DartId]) -> bool {
    is_insertable_cell_2_in_cell_3(g, path)
}

/// Splits a volume in two by a new face along a closed loop of edges (CGAL's
/// `insert_cell_2_in_cell_3`): `path` holds one dart per edge of the loop, all in faces
/// on one side of the new face. Returns a dart of the new face. The side holding
/// `path[0]` keeps the volume's attribute, the other gets a copy (split hook). Δχ = 0
/// (+1 face, +1 volume). O(volume size · n).
pub fn try_split_volume<A: Attributes>(g: &mut GMap<A>, path: &[DartId]) -> Result<DartId, ConstructError> {
    has_volumes(g, "a split of a volume")?;
    Ok(insert_cell_2_in_cell_3(g, path)?)
}

/// Like [`try_split_volume`], panicking when the precondition fails.
#[track_caller]
pub fn split_volume<A: Attributes>(g: &mut GMap<A>, path: &[DartId]) -> DartId {
    try_split_volume(g, path).unwrap_or_else(|e| panic!("split_volume: {e}"))
}
