//! # gmap-ops: making and changing generalized maps
//!
//! The construction side of the workspace. Every map its functions return passes
//! [`gmap_core::DenseMap::validate`] (BO Def. 1). Its modules:
//!
//! * [`build`]: the classic objects — n-simplex, n-cube, k-gon, the product with an edge
//!   (extrusion), cube grids in any dimension with any axes periodic (d-tori), surfaces
//!   from polygonal schema words, the solid torus, lens spaces L(p, q); and in
//!   [`build::placed`], the grid, the cube, the simplex and the torus with the points of
//!   their vertices;
//! * [`import`]: pure simplicial complexes (`.facets`, `.lex`; one dart per flag of each
//!   facet), polygon meshes (`.off`), CGAL's plane graphs and face posets of regular cell complexes (the flag
//!   construction), each refusing what is not a G-map with an error that says where;
//! * [`export`]: `.off` polygon meshes and the `.facets` of the barycentric subdivision,
//!   written through a temporary file and a rename;
//! * [`iso`]: isomorphism of maps (canonical breadth-first codes), for round-trip tests;
//! * [`euler`]: Euler operators on the editable [`gmap_core::GMap`] (split, remove,
//!   contract, close) with their Euler–Poincaré vectors — removal and contraction both as
//!   CGAL's (any cell, which may change the space) and homology-keeping —, simplification,
//!   stratified objects with incomplete boundaries, and random operator sequences for tests;
//! * [`rng`]: the seeded SplitMix64 generator behind every random choice of the crate.
//!
//! ```
//! use gmap_ops::{build, import::SimplicialComplex, iso};
//! // the boundary of a tetrahedron, imported from its facets: a sphere
//! let sc = SimplicialComplex::parse_facets("1 2 3\n1 2 4\n1 3 4\n2 3 4\n").unwrap();
//! let sphere = sc.to_gmap(1_000).unwrap();
//! assert_eq!(sphere.dart_count(), 4 * 6);
//! assert_eq!(sphere.cell_counts(), vec![4, 6, 4]);
//! assert_eq!(sphere.euler_characteristic(), 2);
//! // the same surface as two triangles glued along their boundary has other cells
//! let pillow = build::schema("a b c, C B A").unwrap();
//! assert_eq!(pillow.euler_characteristic(), 2);
//! assert!(!iso::are_isomorphic(&sphere, &pillow));
//! ```

#![warn(missing_docs)]

pub mod build;
pub mod construct;
pub mod euler;
pub mod export;
pub mod import;
pub mod iso;
pub mod mesh;
mod perm;
pub mod rng;
