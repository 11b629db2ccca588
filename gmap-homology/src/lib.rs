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
//! ## Two halves
//!
//! The crate has an **engine** that computes and a **front** that builds what it computes
//! on; dependencies run from the front to the engine, never back.
//!
//! * [`engine`]: homology of any chain complex, knowing nothing of where its cells came from.
//!   - [`sparse`]: [`SparseMatrix`], CSC integer matrices with validated invariants.
//!   - [`chain`]: [`ChainComplex`], cell counts per dimension and `∂_k : C_k → C_{k-1}`,
//!     `∂∂ = 0` checked.
//!   - [`homology`]: [`homology_z`] / [`homology_zp`] give [`Homology`] (Betti numbers and
//!     torsion invariant factors) in three stages: a fill-free pass of collapses and
//!     coreductions over the whole complex, making a cell critical where it gets stuck
//!     (`morse`, private: on manifolds and cube grids it leaves as many cells as the Betti
//!     numbers, in time linear in the entries); unit-pivot elimination of what is left
//!     (`reduce`, private); Smith normal form of the non-unit remainder (`snf`, private).
//!     Checked `i64` (`ring`, private), big-integer fall-back.
//!   - [`generators`]: a representative cycle per summand, found on the reduced complex and
//!     lifted back through the eliminated pairs.
//! * [`cellular`]: the chain complexes of a G-map.
//!   - [`incidence`]: incidence numbers pair by pair, [`Incidence`] (BO Def. 5, 9).
//!   - [`precond`]: the conditions C1 and C2, checked cell by cell, and the oriented cells.
//!   - [`border`]: [`cellular_complex`], the border operator of a map (BO Def. 10) after
//!     the C1/C2 checks, dimensions shared out over the threads `gmap_core::parallel` allows.
//!   - [`simplicial`]: [`simplicial_complex`], the simplicial counterpart (BO §6), the oracle.
//! * [`complex`]: complexes given by their incidences rather than by a map, and formats.
//!   - [`arch`]: architectural complexes (AC §3), their topology, the complex of a G-map and
//!     Algorithm 8.16.
//!   - [`ep`]: Euler–Poincaré operators and their polynomial view (AC §4–7).
//!   - [`lar`]: LAR's characteristic matrices, the signed boundary and coboundary, the nine
//!     operators and cycle extraction of a planar arrangement.
//!   - [`tm`]: TM's model in 2D and 3D: (6:1), views, sections, annotations, the edit check.
//!   - [`simplices`]: any finite simplicial complex by its facets, every face a cell.
//!   - [`json`]: the `.json` incidence-graph format; [`dot`]: Graphviz output.
//!   - [`cubical`]: sets of cubes on their doubled grid ([`cubical::grid`], the one naming
//!     of cubical cells and the one boundary formula): the complex of a set, and the routes
//!     that need none or build it piece by piece ([`cubical::pass`], [`cubical::torus`],
//!     [`cubical::gens`], [`cubical::slabs`], [`cubical::blocks`]).
//! * [`persistence`]: persistence diagrams of filtered complexes: images on the doubled
//!   grid ([`persistence::image`], [`persistence::gradient`]) and complexes given cell by
//!   cell ([`persistence::filtered`]).
//!
//! Every module stays reachable at the crate root (`gmap_homology::sparse`,
//! `gmap_homology::arch`, `gmap_homology::cubical`, …).
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

pub mod cellular;
pub mod complex;
pub mod curves;
pub mod engine;
pub mod persistence;
mod prefetch;

pub use cellular::{border, checked, incidence, oriented, precond, simplicial};
pub use complex::{arch, cubical, dot, ep, graphml, json, lar, simplices, tm};
pub use engine::{chain, generators, homology, sparse};

pub use border::CellularComplex;
pub use chain::{ChainComplex, ChainError};
pub use checked::{cellular_complex, chain_map_tau, gmap_homology, GMapHomologyError};
pub use homology::{
    homology_z, homology_z_bigint, homology_z_staged, homology_zp, is_prime, Coefficients, Homology, HomologyError,
    Natural, Prime, Stages,
};
pub use incidence::Incidence;
pub use precond::{
    check_by_dimension, check_preconditions, check_self_bending, oriented_cells, OrientedCells, PreconditionError,
};
pub use simplicial::{
    simplicial_complex, simplicial_complex_with_simplices, ChainMapTau, Simplex, SimplicialComplex, TauError,
};
pub use sparse::{SparseError, SparseMatrix};
