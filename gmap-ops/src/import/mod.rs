//! Importers: simplicial complexes (`.facets`, `.lex`), polygon meshes (`.off`), plane graphs
//! (CGAL's `import_from_plane_graph`) and face posets of regular cell complexes (the flag construction).
//!
//! Every reader returns a [`FileError`] that names the file, and inside it an
//! [`ImportError`] that names the line, the facet, the ridge or the edge at fault. Readers
//! never panic on user input. The simplicial importer computes the number of darts first,
//! with checked arithmetic, and refuses an input over the limit before allocating the map
//! (see [`default_max_darts`]).

pub mod cgal_xml;
mod common;
pub mod cubical;
pub mod high_order;
pub mod image;
pub mod msh;
pub mod off;
pub mod perseus;
pub mod plane_graph;
pub mod poset;
pub mod raster;
pub mod simplicial;
pub mod vtk;
pub mod vtu;

pub use cgal_xml::{format_cgal_xml, parse_cgal_xml, read_cgal_xml};
pub use common::{bytes_per_dart, default_max_darts, default_max_faces, FileError, ImportError};
pub use cubical::{parse_box, read_cub, read_pbm, CubicalSet};
pub use image::{Image, Level};
pub use msh::{parse_msh, read_msh, MshFile};
pub use off::{read_off, read_off_with, PolygonMesh};
pub use poset::{FacePoset, PosetError};
pub use simplicial::{
    parse_vertex_values, read_facets, read_facets_complex, read_lex, read_lex_complex, read_vertex_values,
    SimplicialComplex,
};
pub use vtk::{parse_vtk, read_vtk};
pub use vtu::{parse_vtu, read_vtu};

/// Reads a volume mesh chosen by the file's extension (any case): legacy `.vtk`, XML `.vtu`
/// or Gmsh `.msh`; `None` for any other extension.
pub fn read_mesh(path: &std::path::Path, max_darts: Option<u64>) -> Option<Result<gmap_core::LabelledGMap, FileError>> {
    let ext = path.extension()?.to_string_lossy().to_lowercase();
    Some(match ext.as_str() {
        "vtk" => read_vtk(path, max_darts),
        "vtu" => read_vtu(path, max_darts),
        "msh" => read_msh(path, max_darts),
        _ => return None,
    })
}
