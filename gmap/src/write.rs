//! The writers of the format registry ([`crate::formats::FORMATS`]): one function per
//! format and kind of value, each writing a whole file through a temporary file and a
//! rename (a failure leaves no partial output). [`crate::save`] chooses among them.

use std::path::Path;

use gmap_core::{DenseMap, LabelledGMap};
use gmap_homology::arch::ArchComplex;
use gmap_homology::lar::Lar;
use gmap_ops::import::{CubicalSet, Image, SimplicialComplex};

use crate::error::{err, Error, ErrorKind, Result};

/// Writes a map.
pub(crate) type MapFn = fn(&DenseMap, &Path) -> Result<()>;
/// Writes a map with its points and the labels of its cells.
pub(crate) type LabelledFn = fn(&LabelledGMap, &Path) -> Result<()>;
/// Writes a full cubical set's cubes as they are.
pub(crate) type CubesFn = fn(&CubicalSet, &Path) -> Result<()>;
/// Writes a simplicial complex's facets as they are.
pub(crate) type FacetsFn = fn(&SimplicialComplex, &Path) -> Result<()>;
/// The text of an incidence graph.
pub(crate) type GraphFn = fn(&ArchComplex) -> String;
/// Writes an image.
pub(crate) type ImageFn = fn(&Image, &Path) -> Result<()>;

/// The refusal of a writer that failed, naming the output.
pub(crate) fn cannot_write<E: std::error::Error + Send + Sync + 'static>(output: &Path, e: E) -> Error {
    Error::from_source(ErrorKind::Write, e).context(format!("{}: cannot write", output.display()))
}

/// Writes `text` to `path` atomically.
pub(crate) fn text(path: &Path, text: &str) -> Result<()> {
    gmap_core::io::write_atomic(path, text.as_bytes()).map_err(|e| cannot_write(path, e))
}

/// `.gmap`.
pub(crate) fn gmap(m: &DenseMap, output: &Path) -> Result<()> {
    Ok(gmap_core::io::write_gmap(m, output)?)
}

/// `.gmap` with points and labels.
pub(crate) fn labelled_gmap(g: &LabelledGMap, output: &Path) -> Result<()> {
    Ok(gmap_core::io::write_labelled_gmap(g, output)?)
}

/// `.moka`: a map of dimension at most 3 (Moka's 3G-maps); a higher one is refused before
/// anything is written.
pub(crate) fn moka(m: &DenseMap, output: &Path) -> Result<()> {
    if m.dim() > 3 {
        return Err(err!(
            Unsupported,
            "{}: .moka holds maps of dimension at most 3, this map has dimension {}; write .gmap",
            output.display(),
            m.dim()
        )
        .with_path(output));
    }
    Ok(gmap_core::io::write_moka(m, output)?)
}

/// `.off` of a 2-map; a 3-map is refused with the flag that writes its boundary.
pub(crate) fn off(m: &DenseMap, output: &Path) -> Result<()> {
    if m.dim() == 3 {
        return Err(err!(
            Unsupported,
            "{}: .off holds 2-maps (surfaces), this map has dimension 3; gmap convert --boundary writes its boundary surface",
            output.display()
        ));
    }
    gmap_ops::export::write_off(m, output).map_err(|e| cannot_write(output, e))
}

/// `.off` of the boundary surface of a 3-map.
pub(crate) fn boundary_off(m: &DenseMap, output: &Path) -> Result<()> {
    gmap_ops::export::write_boundary_off(m, output).map_err(|e| cannot_write(output, e))
}

/// `.facets`: the barycentric subdivision, one simplex per dart.
pub(crate) fn facets(m: &DenseMap, output: &Path) -> Result<()> {
    Ok(gmap_ops::export::write_barycentric_facets(m, output)?)
}

/// `.facets` of a simplicial complex: its facets, one a line, their vertex labels as given.
pub(crate) fn complex_facets(sc: &SimplicialComplex, output: &Path) -> Result<()> {
    let mut s = String::new();
    let mut digits = itoa::Buffer::new();
    for f in sc.facets() {
        for (i, &v) in f.iter().enumerate() {
            if i > 0 {
                s.push(' ');
            }
            s.push_str(digits.format(v));
        }
        s.push('\n');
    }
    text(output, &s)
}

/// `.cub` (CHomP's cubical sets): `dimension d`, then a cube a line by its minimal vertex,
/// `(x_0,x_1,…)`. A cubical cell complex with cells on no cube is refused (the format holds
/// cubes only), naming the first of them.
pub(crate) fn cub(set: &CubicalSet, output: &Path) -> Result<()> {
    set.require_full("a .cub of cubes")
        .map_err(|e| err!(Unsupported, "{e}; write .json, .dot or .graphml (every cell)").with_path(output))?;
    let mut s = format!("dimension {}\n", set.dim());
    let mut digits = itoa::Buffer::new();
    for c in set.cubes() {
        s.push('(');
        for (a, &x) in c.iter().enumerate() {
            if a > 0 {
                s.push(',');
            }
            s.push_str(digits.format(x));
        }
        s.push_str(")\n");
    }
    text(output, &s)
}

/// `.vtk` of a map with points.
pub(crate) fn vtk(m: &DenseMap, output: &Path) -> Result<()> {
    gmap_ops::export::write_vtk(m, output).map_err(|e| cannot_write(output, e))
}

/// `.vtk` of a map with points, the labels of its cells as cell data.
pub(crate) fn labelled_vtk(g: &LabelledGMap, output: &Path) -> Result<()> {
    let (m, labels, _) = gmap_core::to_dense_labels(g);
    gmap_ops::export::write_vtk_with_labels(&m, &labels, output).map_err(|e| cannot_write(output, e))
}

/// `.vtu` of a map with points (XML, binary appended, zlib).
pub(crate) fn vtu(m: &DenseMap, output: &Path) -> Result<()> {
    let labels = gmap_core::DenseLabels::default();
    gmap_ops::export::write_vtu_with_labels(m, &labels, output).map_err(|e| cannot_write(output, e))
}

/// `.vtu` of a map with points, the labels of its cells as cell data.
pub(crate) fn labelled_vtu(g: &LabelledGMap, output: &Path) -> Result<()> {
    let (m, labels, _) = gmap_core::to_dense_labels(g);
    gmap_ops::export::write_vtu_with_labels(&m, &labels, output).map_err(|e| cannot_write(output, e))
}

/// `.msh` (Gmsh 4.1, ASCII) of a map with points.
pub(crate) fn msh(m: &DenseMap, output: &Path) -> Result<()> {
    let labels = gmap_core::DenseLabels::default();
    gmap_ops::export::write_msh_with_labels(m, &labels, false, output).map_err(|e| cannot_write(output, e))
}

/// `.msh` (Gmsh 4.1, ASCII) of a map with points, the physical groups and names and the
/// other labels as element data.
pub(crate) fn labelled_msh(g: &LabelledGMap, output: &Path) -> Result<()> {
    let (m, labels, _) = gmap_core::to_dense_labels(g);
    gmap_ops::export::write_msh_with_labels(&m, &labels, false, output).map_err(|e| cannot_write(output, e))
}

/// `.msh` (Gmsh 4.1, binary) of a map with points.
pub(crate) fn msh_binary(m: &DenseMap, output: &Path) -> Result<()> {
    let labels = gmap_core::DenseLabels::default();
    gmap_ops::export::write_msh_with_labels(m, &labels, true, output).map_err(|e| cannot_write(output, e))
}

/// `.msh` (Gmsh 4.1, binary) of a map with points and its labels, as [`labelled_msh`].
pub(crate) fn labelled_msh_binary(g: &LabelledGMap, output: &Path) -> Result<()> {
    let (m, labels, _) = gmap_core::to_dense_labels(g);
    gmap_ops::export::write_msh_with_labels(&m, &labels, true, output).map_err(|e| cannot_write(output, e))
}

/// `.vtk` of a full cubical set: its cubes as voxels.
pub(crate) fn voxels_vtk(set: &CubicalSet, output: &Path) -> Result<()> {
    gmap_ops::export::write_cubical_vtk(set, output).map_err(|e| cannot_write(output, e))
}

/// `.lar.json`: LAR's characteristic matrices of a map.
pub(crate) fn lar(m: &DenseMap, output: &Path) -> Result<()> {
    let json = Lar::from_map(m).to_json().map_err(|e| Error::from_source(ErrorKind::Write, e))?;
    text(output, &json)
}

/// The `.json` of an incidence graph.
pub(crate) fn json_graph(x: &ArchComplex) -> String {
    gmap_homology::json::write_json(x)
}

/// The `.dot` of an incidence graph.
pub(crate) fn dot_graph(x: &ArchComplex) -> String {
    gmap_homology::dot::write_dot(x)
}

/// The GraphML of an incidence graph.
pub(crate) fn graphml_graph(x: &ArchComplex) -> String {
    gmap_homology::graphml::write_graphml(x)
}

/// `.npy`: an image as it is.
pub(crate) fn npy(img: &Image, output: &Path) -> Result<()> {
    img.write_npy(output).map_err(|e| err!(Write, "{}: {e}", output.display()).with_path(output))
}

/// DIPHA's `.complex`: an image's values as `f64`.
pub(crate) fn dipha(img: &Image, output: &Path) -> Result<()> {
    img.write_dipha(output).map_err(|e| err!(Write, "{}: {e}", output.display()).with_path(output))
}

/// `.cgal.xml`: darts, alpha links and vertex points as CGAL's `load_generalized_map` reads them.
pub(crate) fn cgal_xml(m: &DenseMap, output: &Path) -> Result<()> {
    text(output, &gmap_ops::import::format_cgal_xml(m))
}
