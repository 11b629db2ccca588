//! Euler operators, Euler–Poincaré bookkeeping, simplification and boundary-incomplete
//! objects.
//!
//! * [`vector`]: Euler–Poincaré vectors and their names in the basis of AC Prop. 5.2.
//! * [`ops`]: cell operators on the editable [`gmap_core::GMap`] in any dimension —
//!   split a cell (`mve`, also on an edge missing an end, `mef`, `mfs`, …), dangling edges, removal and contraction of
//!   cells of degree 2, closing a boundary, an edge between two faces — each with a
//!   predicate, a `try_` form with a typed error and its Euler–Poincaré vector; on maps
//!   with attributes of any kind, which follow every operator (merge and split hooks, vertex
//!   points); also under CGAL's names ([`ops::cgal`]).
//! * [`simplify`](mod@simplify): homology-preserving reduction of a
//!   [`gmap_core::DenseMap`] by removals and contractions ([`simplify()`],
//!   [`simplify_with`]), with a search past plateaus for 3-maps.
//! * [`strata`]: the stratified objects with incomplete boundaries of EO, the Euler
//!   characteristic of its Theorems 1–2, and the catalogue of its operators
//!   ([`strata::EoOperator`]: every operator the paper names, applied by name, refused
//!   unchanged when it would break an invariant), with their G-map counterparts; docs/EO.md
//!   maps the paper to code and tests.
//! * [`random`]: random sequences of Euler operators for tests and benches, each attempt
//!   checking that an operator's predicate agrees with its `try_` form.
//!
//! ```
//! use gmap_core::GMap;
//! use gmap_ops::euler::ops::{try_insert_vertex, try_remove_cell_keeping_homology};
//! // a 1-map: a triangle (three edges, three vertices)
//! let mut g = GMap::new(1);
//! let d: Vec<_> = (0..6).map(|_| g.create_dart()).collect();
//! for k in 0..3 {
//!     g.sew(d[2 * k], d[2 * k + 1], 0);
//!     g.sew(d[2 * k + 1], d[(2 * k + 2) % 6], 1);
//! }
//! let op = try_insert_vertex(&mut g, d[0]).unwrap();
//! assert_eq!((op.name.as_str(), op.vector.dx().to_vec()), ("mve", vec![1, 1]));
//! assert_eq!(op.basis_name(), "B0 + A1");
//! assert_eq!(g.to_dense_map().cell_counts(), vec![4, 4]);
//! // removing a vertex of degree 2 merges its two edges back
//! let op = try_remove_cell_keeping_homology(&mut g, d[1], 0).unwrap();
//! assert_eq!((op.name.as_str(), op.vector.dx().to_vec()), ("kve", vec![-1, -1]));
//! assert_eq!(g.to_dense_map().cell_counts(), vec![3, 3]);
//! ```

pub mod ops;
pub mod random;
pub mod simplify;
pub mod strata;
pub mod vector;

pub use ops::{CloseReport, EulerError};
pub use simplify::{simplify, simplify_with, SimplifyOptions, SimplifyReport};
pub use vector::{AbExpansion, EpVector, EulerOp};
