//! LAR, the Linear Algebraic Representation of cell complexes (LAR lecture): every p-cell
//! is the set of its vertices, and the *characteristic matrix* `M_p` (one row per p-cell,
//! one column per vertex, 1 where the vertex belongs to the cell) is a [`SparseMatrix`](crate::SparseMatrix), the
//! engine's own.
//! Topological queries are sparse products:
//! * `M_{p-1} M_p^T` counts the common vertices of a (p-1)-cell and a p-cell; the *count
//!   rule* keeps a 1 where the count equals the size of the (p-1)-cell: the unsigned
//!   boundary `[∂_p]` ([`Lar::unsigned_boundary`]);
//! * the nine incidence/adjacency operators `VV … FF` of a 2-complex ([`LarOp`],
//!   [`Lar::operator`]) and the relations they stand for, whose sizes are LAR Table 2
//!   ([`Lar::relation`], [`Lar::cardinality`]);
//! * the signed boundary and coboundary with the conventional orientation
//!   ([`Lar::signed_boundaries`], [`Lar::signed_coboundary`], [`Lar::chain_complex`]; the
//!   top cells by the sign of their area or volume: [`Lar::signed_boundary_planar`],
//!   [`Lar::signed_boundary_solid`]);
//! * cycle extraction: the 2-cells of a planar arrangement from its edges
//!   ([`PlanarGraph::extract`], the paper's stripes: [`PlanarGraph::stripes`]); one
//!   dimension up, the 3-cells of faces in space, rooms from walls ([`Faces::cells`], the
//!   δ∂ steps: [`Faces::extraction_steps`]).
//!
//! The item-by-item map of the lecture to this code and its tests is `docs/LAR.md`.
//!
//! From a G-map ([`Lar::from_map`]) a cell's vertex set is the set of 0-cells of its darts.
//! On maps without multi-incidence (every unsigned incidence number 0 or 1) the unsigned
//! boundary equals the unsigned incidence numbers of BO Def. 5. With multi-incidence the
//! vertex-set model loses information: on the one-vertex torus both edges and the face
//! have the vertex set `{v}`, so the two edges cannot be told apart and every incidence
//! (really 2, signed 0) reads 1.
//!
//! ```
//! use gmap_homology::lar::{characteristic_matrix, Lar};
//! // a triangle: vertices 0, 1, 2; edges {0,1}, {1,2}, {0,2}; one face
//! let lar = Lar::from_cells(3, vec![
//!     characteristic_matrix(3, &[vec![0, 1], vec![1, 2], vec![0, 2]]).unwrap(),
//!     characteristic_matrix(3, &[vec![0, 1, 2]]).unwrap(),
//! ]).unwrap();
//! // the face's boundary is its three edges
//! assert_eq!(lar.unsigned_boundary(2).unwrap().to_dense(), vec![vec![1], vec![1], vec![1]]);
//! ```

mod cycles;
mod rooms;
mod signed;

pub use cycles::{Arrangement, ArrangementError, Cycle, PlanarGraph, Stripe};
pub use rooms::{Cells, ExtractionStep, Faces, RoomsError};

mod model;
pub use model::{characteristic_matrix, Lar, LarError, LarOp};
