//! Unstructured meshes — points, cells given by their vertices, and data on both — made
//! into labelled G-maps. The readers of [`crate::import`] (`.vtk`, `.vtu`, `.msh`) parse a
//! file into a [`Mesh`]; [`Mesh::to_gmap`] builds the map.
//!
//! ## From cells to a map
//!
//! The map's dimension is the largest dimension of the cells (the *top* cells): volumes
//! (tetrahedra, hexahedra, wedges, pyramids, polyhedra given by their faces) make a 3-map,
//! polygons a 2-map, lines a 1-map, vertices a 0-map. Each top cell is made on its own —
//! a volume as a surface of polygons 2-sewn along their edges, through
//! [`crate::build::IncrementalBuilder`] — and top cells sharing a *facet* (a face of
//! volumes, an edge of polygons, an end of lines) are sewn along it by `alpha_n`, the darts
//! paired at equal vertices, whatever the cells' orientations; a facet of one cell stays
//! free (the boundary). Facets are found by their sorted vertex ids in a hash map, the
//! routine the builder and [`crate::build::sew3_same_facets`] share.
//!
//! Refused, naming the cells by their index in the file: a facet in three cells or more; two
//! faces on the same vertices in different cycles; two faces of different cells sharing
//! two edges or more without being one face (a non-conforming mesh: a triangle on half a
//! quadrangle; hanging vertices in the middle of an edge need the geometry and are not
//! seen); a cell with a vertex twice or, for a polyhedron, faces that do not close (every
//! edge in exactly two faces); a point or an edge where the cells around it meet only there
//! (two tetrahedra sharing one vertex): a G-map is a quasi-manifold and would split it, which
//! would change the space.
//!
//! Cells of a lower dimension are not cells of their own: each must be a face, an edge or a
//! vertex of the top cells, and its data labels that cell of the map (so a boundary
//! triangle of a tetrahedral mesh names the boundary face). Points used by no cell are not
//! part of the map.
//!
//! ## Data becoming labels
//!
//! Each data array is a label name: cell data labels the cells (top or lower), point data
//! labels the 0-cells. A value missing for a cell ([`DataArray::values`] `None`) gives no
//! label. The readers give integers as [`LabelValue::Int`], reals as [`LabelValue::Real`],
//! texts as [`LabelValue::Text`], an array of k > 1 components as the names `name.0` …
//! `name.{k-1}`.
//!
//! [`LabelValue::Int`]: gmap_core::LabelValue::Int
//! [`LabelValue::Real`]: gmap_core::LabelValue::Real
//! [`LabelValue::Text`]: gmap_core::LabelValue::Text

pub(crate) mod cells;
pub(crate) mod error;
pub(crate) mod matching;
pub(crate) mod texts;
pub(crate) mod to_map;
pub(crate) mod volumes;

pub use cells::{CellKind, DataArray, Mesh, MeshCell};
pub use error::MeshError;
