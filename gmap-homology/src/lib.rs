//! # gmap-homology: homology on the cells of a generalized map
//!
//! The cells of a G-map (BO Def. 2) carry a chain complex of their own: the signed
//! incidence number between an i-cell and an (i-1)-cell (BO Def. 9) counts, with
//! orientation signs, the elements of the face-operator preimage that lie in the cell, and
//! the border operator (BO Def. 10) collects them into sparse integer matrices. Its
//! homology is the homology of the object whenever every cell is orientable as a compacted
//! cell (condition C1) and bounded by a homology sphere (C2); the crate checks both and
//! refuses otherwise, naming the cell. The simplicial counterpart (BO §6: one n-simplex per
//! dart) is always right and serves as the oracle.
//!
//! ## Model
//!
//! * [`SparseMatrix`]: CSC integer matrices with validated invariants.
//! * [`ChainComplex`]: cell counts per dimension and `∂_k : C_k → C_{k-1}`, `∂∂ = 0` checked.
//! * [`homology_z`] / [`homology_zp`]: [`Homology`] (Betti numbers and torsion invariant
//!   factors) in three stages: a fill-free pass of collapses and coreductions over the whole
//!   complex, making a cell critical where it gets stuck (`morse`, private: on manifolds and
//!   cube grids it leaves as many cells as the Betti numbers, in time linear in the
//!   entries); unit-pivot elimination of what is left (`reduce`, private too);
//!   Smith normal form of the non-unit remainder. Checked `i64`, big-integer fall-back.
//! * [`border::cellular_complex`]: the border operator of a map, after checking C1/C2 on two
//!   threads; `∂_1`, `∂_n` and `∂_2` of 3-maps by local formulas, the rest by orbit walks.
//! * [`generators::generators`]: a representative cycle per summand, found on the reduced
//!   complex and lifted back through the eliminated pairs.
//!
//! ## Example
//!
//! A triangle's boundary (a circle) by hand: three vertices, three edges.
//!
//! ```
//! use gmap_homology::{homology_z, ChainComplex, SparseMatrix};
//! let d1 = SparseMatrix::try_from_triplets(3, 3, &[
//!     (0, 0, -1), (1, 0, 1),   // edge 0: v0 -> v1
//!     (1, 1, -1), (2, 1, 1),   // edge 1: v1 -> v2
//!     (2, 2, -1), (0, 2, 1),   // edge 2: v2 -> v0
//! ]).unwrap();
//! let c = ChainComplex::try_new(vec![3, 3], vec![d1]).unwrap();
//! let h = homology_z(&c).unwrap();
//! assert_eq!(h.betti, vec![1, 1]);
//! assert_eq!(h.to_string(), "(Z, Z)");
//! ```

#![warn(missing_docs)]

pub mod arch;
pub mod border;
pub mod chain;
pub mod dot;
pub mod ep;
pub mod generators;
pub mod homology;
pub mod incidence;
pub mod json;
pub mod lar;
mod morse;
pub mod precond;
pub(crate) mod reduce;
pub(crate) mod ring;
pub mod simplicial;
pub(crate) mod snf;
pub mod sparse;
pub mod tm;

pub use border::{cellular_complex, CellularComplex};
pub use chain::{ChainComplex, ChainError};
pub use homology::{homology_z, homology_z_bigint, homology_zp, is_prime, Coefficients, Homology, HomologyError};
pub use incidence::Incidence;
pub use precond::{check_by_dimension, check_preconditions, oriented_cells, OrientedCells, PreconditionError};
pub use simplicial::{simplicial_complex, simplicial_complex_with_simplices, Simplex, SimplicialComplex};
pub use sparse::{SparseError, SparseMatrix};
