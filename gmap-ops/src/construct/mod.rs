//! Construction operations on the editable [`GMap`](gmap_core::GMap): what a modeller
//! (Moka, CGAL's linear cell complex) builds shapes with, carrying points and attributes.
//!
//! | family | operations | Δχ |
//! |---|---|---|
//! | [`extrude`] | a face into a volume, an edge into a face, a vertex into an edge, along a vector ([`try_extrude_cell`]) or a path of edges ([`try_extrude_cell_along_path`]) | 0 |
//! | [`revolve`](mod@revolve) | a profile about an axis in k steps, closing the loop ([`try_revolve`]) | `-χ(profile)` |
//! | [`triangulate`] | a face by a fan or around its barycentre, a convex volume into tetrahedra | 0 |
//! | [`volumes`] | two volumes merged across a face, a volume split by a loop of edges | 0 |
//! | [`chamfer`] | a vertex or an edge of a surface or of a volume's boundary replaced by a face | 0 |
//!
//! Each operation comes as a predicate (`can_…`), a `try_…` form returning a typed
//! [`ConstructError`] (nothing changed on error) and a plain form that panics. Like the
//! Euler operators ([`crate::euler::ops`]) they are generic over the attributes
//! `A: Attributes` and end with the map's repair routine
//! ([`GMap::reconcile_attributes`](gmap_core::GMap::reconcile_attributes)), directly or
//! through the sews and Euler operators they are made of: every cell keeps one attribute,
//! new cells made of new darts have none, and every new vertex gets a point computed from
//! the vertices it comes from. The Euler characteristic change of each is stated in its
//! docs and checked by the tests (`gmap-ops/tests/construct.rs`, and with homology in
//! `gmap/tests/construct_homology.rs`).
//!
//! The extrusions and the revolution share one building block, the product of a profile
//! with an edge made inside the map (`product`, [`crate::build::extrude`]'s layout).

pub mod chamfer;
mod error;
pub mod extrude;
mod product;
pub mod revolve;
pub mod triangulate;
pub mod volumes;

pub use chamfer::{
    can_chamfer_edge, can_chamfer_vertex, chamfer_edge, chamfer_vertex, try_chamfer_edge, try_chamfer_vertex,
};
pub use error::ConstructError;
pub use extrude::{
    can_extrude_cell, can_extrude_cell_along_path, can_extrude_edge, can_extrude_face, can_extrude_vertex,
    extrude_cell, extrude_cell_along_path, extrude_edge, extrude_face, extrude_vertex, try_extrude_cell,
    try_extrude_cell_along_path, try_extrude_edge, try_extrude_face, try_extrude_vertex, Extruded,
};
pub use revolve::{can_revolve, revolve, try_revolve, Axis, Revolved, MIN_STEPS};
pub use triangulate::{
    can_tetrahedralize_volume, can_triangulate_face_barycentric, can_triangulate_face_fan, tetrahedralize_volume,
    triangulate_face_barycentric, triangulate_face_fan, try_tetrahedralize_volume, try_triangulate_face_barycentric,
    try_triangulate_face_fan,
};
pub use volumes::{
    can_merge_volumes, can_split_volume, merge_volumes, split_volume, try_merge_volumes, try_split_volume,
};
