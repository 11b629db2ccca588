//! Curves on the cells: shortest cycles and homology bases.
//!
//! * [`surface`]: a 2-map as a graph with faces ([`Surface`]), edge weights ([`Weights`]:
//!   unit, edge lengths from the points, or given per edge), the radial graph.
//! * [`tree`]: weighted graphs and shortest-path trees.
//! * [`cycles`]: the shortest non-contractible cycle of a surface, through a vertex or
//!   overall, the edge width and the face width (Erickson–Har-Peled), on orientable and
//!   non-orientable surfaces, with or without boundary.
//! * [`basis`]: a shortest basis of `H_1` over `Z/2` of any chain complex whose 1-cells
//!   are edges (annotations, Horton candidates, greedy), in any dimension.
//! * [`homotopy`]: homotopy tests of paths ([`Homotopy`], [`SurfacePath`]) on the
//!   fundamental group's tree–cotree presentation, with [`words`]: free reduction, Dehn's
//!   algorithm.
//!
//! ```
//! use gmap_homology::curves::{edge_width, face_width};
//! // the torus of one square: a loop of one edge is not contractible
//! let t = gmap_core::examples::torus();
//! assert_eq!(edge_width(&t).unwrap().unwrap().edges.len(), 1);
//! assert_eq!(face_width(&t).unwrap().unwrap().width, 1);
//! ```

pub mod basis;
pub mod cycles;
pub mod error;
pub mod homotopy;
pub mod surface;
pub mod tree;
pub mod words;

pub use basis::{annotations, shortest_basis, Annotations, BasisCycle};
pub use cycles::{
    edge_width, face_width, shortest_non_contractible_cycle, shortest_non_contractible_cycle_through, Cycle, FaceWidth,
};
pub use error::CurveError;
pub use homotopy::{Homotopy, SurfaceKind, SurfacePath};
pub use surface::{Surface, Weights};
pub use tree::{Graph, Tree};
