//! # gmap-core: the generalized-map kernel
//!
//! A *generalized map* of dimension n (an nG-map, BO Def. 1) is a finite set of
//! **darts** with n+1 involutions `alpha_0, …, alpha_n` such that `alpha_i alpha_j` is an
//! involution whenever `j >= i + 2`. A dart is a flag: one vertex, one edge, …, one
//! n-cell, mutually incident; `alpha_i` swaps the i-cell of the flag and keeps the
//! others. A dart fixed by `alpha_i` is **i-free**: the object has a boundary there.
//! Cells are not stored: the **i-cell** of a dart is its orbit under every involution
//! but `alpha_i` (BO Def. 2), and every topological query is an orbit traversal.
//!
//! ## Two representations
//!
//! * [`GMap`] is the editable map. Darts live in versioned slots (a row of `u32` links per
//!   dart), so a [`DartId`] survives the removal of other darts; [`GMap::sew`]/[`GMap::unsew`] follow CGAL's semantics and keep
//!   the map valid, [`GMap::link`]/[`GMap::unlink`] are the low-level operations that may
//!   not. Marks are reserved without a cap ([`Marks`]). A `GMap<A>` carries typed attributes
//!   on the cells of each dimension and a point per vertex, kept consistent through every
//!   sew and unsew, with merge and split hooks ([`attr`]).
//! * [`DenseMap`] is the read-only snapshot for analysis: darts `0..N`, involutions in one
//!   flat `Vec<u32>`. Readers produce it directly (a file of millions of darts loads in one
//!   pass), and whole-map algorithms run on it: [`DenseMap::validate`], orbit partitions
//!   ([`DenseMap::partition`]), cell counts, components, orientation (BO Def. 7, 8),
//!   complete boundaries (BO Def. 6), orientability of every compacted cell (condition C1),
//!   compacted cells and face operators ([`CompactedCells`], [`FaceOperator`], BO Def. 3, 4)
//!   and the dual.
//!
//! The split follows the measurement that drove it: orbit traversals over a flat `u32`
//! array touch one cache line per dart, while a handle lookup adds a version check. [`GMap::to_dense_map`] and [`GMap::from_dense`] convert in one linear pass.
//!
//! Whole-map counts and checks avoid traversals where a sequential scan does: orbit counts
//! ([`DenseMap::cell_counts_and_components`]) and orientability use union-find over the
//! rows in order, validation checks `alpha_i alpha_j = alpha_j alpha_i` from the rows of a
//! dart's neighbours in one fused pass, and maps of more than 65,536 darts use two threads.
//! The oriented cells of a 3-map ([`DenseMap::oriented_cells_3d`]) come from rings walked
//! inside volumes next to a sequential scan and glued across `alpha_3` by a union-find with
//! parities, not from traversals that jump between volumes at every step.
//! On the 40³ hexahedral grid (3,072,000 darts) this loads, counts and checks faster than
//! CGAL's `Generalized_map` (see `benches/cells.rs` of the workspace).
//!
//! ## Files and fixtures
//!
//! [`io`] reads and writes the native `.gmap` format (with vertex points and, through
//! [`LabelledGMap`], named [`Labels`] on cells of every dimension) and Moka's `.moka`, with
//! errors naming the file and line; [`walk`] iterates lazily over orbits and cells of a
//! [`GMap`]; [`points`] makes the linear cell complex of a [`GMap`] with points (CGAL's
//! constructors with coordinates, barycentres of cells, affine transformations);
//! [`examples`] rebuilds the small maps drawn in the border-operator
//! paper (BO Fig. 1, 2, 4(b)) for tests and documentation.
//!
//! ## Example
//!
//! A square as a 2-map: one face with 8 darts, each edge 2 darts, each vertex 2 darts.
//!
//! ```
//! use gmap_core::{DenseMap, Dart};
//! let mut m = DenseMap::new(2, 8);
//! for k in 0..4u32 {
//!     m.link(Dart::new(2 * k), Dart::new(2 * k + 1), 0);            // the two darts of an edge side
//!     m.link(Dart::new(2 * k + 1), Dart::new((2 * k + 2) % 8), 1);  // the two darts of a corner
//! }
//! m.validate().unwrap();
//! assert_eq!(m.cell_counts(), vec![4, 4, 1]);
//! assert_eq!(m.euler_characteristic(), 1);      // a disc
//! assert!(m.is_orientable());
//! // its darts are free for alpha_2 only (2 = n): the boundaries are complete
//! assert!(m.has_complete_boundaries());
//! // the dual swaps vertices and faces
//! assert_eq!(m.dual().cell_counts(), vec![1, 4, 4]);
//! ```

#![warn(missing_docs)]

pub mod alpha;
mod append;
pub mod attr;
mod cells3;
pub mod characteristics;
pub mod compacted;
mod darts;
pub mod dense;
pub mod edit;
pub mod ep_vector;
pub mod error;
pub mod examples;
pub mod fastdiv;
pub mod generic_map;
pub mod ids;
pub mod io;
mod kernels;
pub mod labels;
pub mod map_view;
pub mod marks;
pub mod normals;
pub mod parallel;
pub mod points;
pub mod resources;
mod text;
pub mod union_find;
pub mod walk;

pub use alpha::{AlphaSet, MAX_DIM};
pub use attr::{AttrId, AttributeAt, AttributeDefect, Attributes, Cells, Slot};
pub use characteristics::Characteristics;
pub use compacted::{CompactedCells, FaceOperator};
pub use dense::{DenseMap, OrientedCells3d, Partition};
pub use edit::{DartId, EditError, GMap, MapDefect};
pub use error::{BoundaryDefect, CellDefect, DartError, OrientationConflict, ValidityError};
pub use ids::{CellId, Dart, Point};
pub use labels::{LabelValue, LabelledGMap, Labels};
pub use map_view::MapView;
pub use marks::{MarkId, Marks};
pub use points::{Affine, IntoPoint, MakeError};

// labels numbered like the cells of a dense map
pub use labels::{cell_labels, labels_by_dimension, to_dense_labels, DenseLabels};
