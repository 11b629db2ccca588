//! # gmap: generalized maps, their construction and their homology
//!
//! The library side of the project: it pulls in the three crates below and nothing of the
//! command line (the `gmap` binary lives in the `gmap-cli` package).
//!
//! This facade re-exports the three crates of the workspace:
//!
//! * [`core`] (`gmap-core`): the kernel — darts, involutions, orbits, cells, marks,
//!   validity, orientation, compacted cells, face operators, the dual, file formats;
//! * [`ops`] (`gmap-ops`): making and changing maps — builders, importers, sewing,
//!   Euler operators;
//! * [`homology`] (`gmap-homology`): incidence numbers, the cellular border operator,
//!   homology over Z and Z/p, architectural complexes, LAR operators.
//!
//! ```
//! use gmap::core::{DenseMap, Dart};
//! let mut m = DenseMap::new(1, 2);
//! m.link(Dart::new(0), Dart::new(1), 0); // one edge with two free ends
//! assert_eq!(m.cell_counts(), vec![2, 1]);
//! ```

pub use gmap_core as core;
pub use gmap_homology as homology;
pub use gmap_ops as ops;
