//! Euler operators on the editable [`GMap`], in any dimension.
//!
//! Every operator comes as a predicate (`can_…` / `is_…`) that tells whether its
//! precondition holds and a `try_…` form that checks it and returns a typed [`EulerError`];
//! splits, removals and contractions also have a plain form that panics when the
//! precondition fails. Each returns an [`EulerOp`]: the classical name and the Euler–Poincaré vector
//! (AC §4–5). The change of cells in the vector is *recounted* on the cells that meet the
//! modified darts (cells that do not meet them are unchanged), so it is exact even in
//! degenerate configurations; the change of homology follows from the operator's
//! precondition, which makes every operator here a subdivision, a coalescence or a
//! collapse of the underlying space (a homotopy equivalence), hence `dy = 0` — except
//! [`try_close`], whose homology change is global and is left to the caller.
//!
//! In debug builds every operator checks BO Def. 1 on the result (`debug_assert`).
//!
//! [`EulerOp`]: crate::euler::EulerOp
//! [`GMap`]: gmap_core::GMap
//! [`GMap::reconcile_attributes`]: gmap_core::GMap::reconcile_attributes
//!
//! # Attributes and points
//!
//! Every operator works on a [`GMap<A>`](gmap_core::GMap) with any attributes `A` (a plain `GMap` needs
//! no annotation) and ends with the map's one repair routine,
//! [`GMap::reconcile_attributes`], given the darts it re-linked: the merge hooks run
//! exactly when cells carrying attributes become one (a removal, a contraction, an edge
//! between two faces), the split hooks exactly when one becomes two (a split, an
//! insertion), each cell holds one attribute afterwards, and every vertex that is not
//! merged keeps its point. A new cell made of new darts only (the new edge of `mef`, the
//! new face of `mfs`) has no attribute. An operator that makes a vertex gives it a point:
//! [`try_insert_vertex`] the middle of the split edge when both ends have points,
//! [`try_insert_vertex_at`] and [`try_insert_dangling_edge_at`] the point they are given.
//! Each operator's doc says which cell keeps the original attribute.
//!
//! # CGAL's names
//!
//! The operators are also available under CGAL's names (`insert_cell_0_in_cell_1`,
//! `insert_cell_1_in_cell_2`, `insert_dangling_cell_1_in_cell_2`,
//! `insert_cell_1_between_two_cells_2`, `insert_cell_2_in_cell_3`, `remove_cell`,
//! `contract_cell`), returning a dart of the new cell as CGAL's do; the table in [`cgal`]
//! maps each CGAL operation to ours with its precondition and predicate.
//!
//! # Removal and contraction: CGAL's and the homology-keeping ones
//!
//! [`try_remove_cell`] and [`try_contract_cell`] (with [`is_removable`],
//! [`is_contractible`]) are CGAL's `remove_cell<i>` and `contract_cell<i>`: any i-cell of
//! degree 2, `0 <= i <= n`, on the boundary or not; they may change the space (cut a face,
//! kill a circle, remove a whole component) and return the number of darts deleted.
//! [`try_remove_cell_keeping_homology`] and [`try_contract_cell_keeping_homology`] (with
//! [`is_removable_keeping_homology`], [`is_contractible_keeping_homology`]) accept only
//! the moves that keep the space (two distinct interior cells merge, nothing falls apart)
//! and return the Euler–Poincaré vector; simplification, the EO counterparts and the
//! constructions use them. The table in the `removal` module compares both predicates.
//!
//! The operators are grouped by what they do: splits and insertions (`split`), edges hung
//! at a corner (`edges`: dangling edges, edges between two faces), CGAL's removals and
//! contractions (`removal`), the homology-keeping ones (`collapse`), closing a boundary
//! (`close`), CGAL's names ([`cgal`]); all are re-exported here.

pub mod cgal;
mod cgal_insert;
mod close;
mod collapse;
mod common;
mod edges;
mod error;
mod removal;
mod split;
mod star;

pub use cgal::{
    insert_cell_0_in_cell_1, insert_cell_1_between_two_cells_2, insert_cell_1_in_cell_2, insert_cell_2_in_cell_3,
    insert_dangling_cell_1_in_cell_2, is_insertable_cell_0_in_cell_1, is_insertable_cell_1_between_two_cells_2,
    is_insertable_cell_1_in_cell_2, is_insertable_cell_2_in_cell_3, is_insertable_dangling_cell_1_in_cell_2,
};
pub use close::{can_close, try_close, CloseReport};
pub(crate) use collapse::Move;
pub use collapse::{
    contract_cell_keeping_homology, is_contractible_keeping_homology, is_removable_keeping_homology,
    remove_cell_keeping_homology, try_contract_cell_keeping_homology, try_remove_cell_keeping_homology,
};
pub use edges::{
    can_insert_dangling_edge, can_insert_edge_between_faces, try_insert_dangling_edge, try_insert_dangling_edge_at,
    try_insert_edge_between_faces, BridgeReport,
};
pub use error::EulerError;
pub use removal::{contract_cell, is_contractible, is_removable, remove_cell, try_contract_cell, try_remove_cell};
pub use split::{
    can_insert_edge, can_insert_vertex, can_split_cell, split_cell, try_insert_edge, try_insert_vertex,
    try_insert_vertex_at, try_split_cell,
};
pub(crate) use split::{insert_edge_quietly, split_cell_quietly};
pub use star::{
    can_star_cell, can_star_face, insert_barycenter_in_cell, insert_cell_0_in_cell_2, insert_point_in_cell,
    is_insertable_barycenter_in_cell, is_insertable_cell_0_in_cell_2, star_cell, star_face, try_star_cell,
    try_star_face, Starred,
};
