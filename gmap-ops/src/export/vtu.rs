//! XML VTK unstructured grids (`.vtu`; docs/FORMATS.md). The reader is
//! [`crate::import::vtu`].
//!
//! The cells, their order and orientation, the labelled lower cells and the label columns
//! are those of the legacy writer ([`super::vtk`], [`super::cells`]); every array is binary
//! appended data (`encoding="raw"`), compressed by `vtkZLibDataCompressor` in blocks of
//! 32 KiB with `UInt64` headers, little-endian: `Points` as `Float64`, `connectivity`,
//! `offsets` (`Int64`) and `types` (`UInt8`), and for polyhedra `faces` and `faceoffsets`
//! (`Int64`, VTK's face streams, `-1` for the other cells); the cell data `dim` (`Int32`)
//! and one array per label column (`Int32`, `Int64`, `Float64`, texts as `Int32` ranks), the
//! tables of texts as `UInt8` arrays of the grid's `FieldData`. No `String` array is written
//! (meshio reads none). The output is read back before it is written and refused when it
//! would not give the same map and labels.

use std::io::Write as _;
use std::path::Path;

use flate2::write::ZlibEncoder;
use flate2::Compression;
use gmap_core::{DenseLabels, DenseMap, LabelValue};

use super::cells::{mesh_out, text_table, text_table_name, Column, MeshOut, VTK_POLYHEDRON};
use super::error::{write_atomic, ExportError};
use super::readback::Labelling;

/// The uncompressed size of a block.
const BLOCK: usize = 32 * 1024;

/// The appended data being built and the XML that points into it.
struct Appended {
    xml: String,
    data: Vec<u8>,
}

/// XML's escapes for an attribute value.
fn attr(s: &str) -> String {
    s.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;").replace('"', "&quot;")
}

impl Appended {
    /// Adds one array: its `DataArray` element (`extra` attributes) and its compressed
    /// bytes (a header `[blocks, block size, last block size, compressed sizes…]`, then one
    /// zlib stream per block).
    fn array(&mut self, indent: &str, ty: &str, name: &str, extra: &str, raw: &[u8]) {
        let offset = self.data.len();
        self.xml.push_str(&format!(
            "{indent}<DataArray type=\"{ty}\" Name=\"{}\"{extra} format=\"appended\" offset=\"{offset}\"/>\n",
            attr(name)
        ));
        let blocks: Vec<&[u8]> = raw.chunks(BLOCK).collect();
        let last = blocks.last().map_or(0, |b| if b.len() == BLOCK { 0 } else { b.len() });
        let compressed: Vec<Vec<u8>> = blocks
            .iter()
            .map(|b| {
                let mut z = ZlibEncoder::new(Vec::new(), Compression::default());
                z.write_all(b).expect("writing to memory");
                z.finish().expect("writing to memory")
            })
            .collect();
        for w in [blocks.len(), BLOCK, last].into_iter().chain(compressed.iter().map(Vec::len)) {
            self.data.extend_from_slice(&(w as u64).to_le_bytes());
        }
        for c in compressed {
            self.data.extend_from_slice(&c);
        }
    }
}

fn le_i64(v: impl Iterator<Item = i64>) -> Vec<u8> {
    v.flat_map(i64::to_le_bytes).collect()
}

fn le_i32(v: impl Iterator<Item = i32>) -> Vec<u8> {
    v.flat_map(i32::to_le_bytes).collect()
}

/// The cell arrays: connectivity, offsets, types, and for polyhedra faces and faceoffsets.
fn cell_arrays(a: &mut Appended, m: &MeshOut) {
    let ind = "        ";
    let mut end = 0i64;
    let offsets: Vec<i64> = m
        .cells
        .iter()
        .map(|c| {
            end += c.conn.len() as i64;
            end
        })
        .collect();
    a.array(ind, "Int64", "connectivity", "", &le_i64(m.cells.iter().flat_map(|c| c.conn.iter().map(|&v| v as i64))));
    a.array(ind, "Int64", "offsets", "", &le_i64(offsets.into_iter()));
    a.array(ind, "UInt8", "types", "", &m.cells.iter().map(|c| c.kind).collect::<Vec<u8>>());
    if m.cells.iter().any(|c| c.kind == VTK_POLYHEDRON) {
        let mut faces: Vec<i64> = Vec::new();
        let mut fo: Vec<i64> = Vec::with_capacity(m.cells.len());
        for c in &m.cells {
            if c.kind == VTK_POLYHEDRON {
                faces.extend(c.legacy().into_iter().map(i64::from));
                fo.push(faces.len() as i64);
            } else {
                fo.push(-1);
            }
        }
        a.array(ind, "Int64", "faces", "", &le_i64(faces.into_iter()));
        a.array(ind, "Int64", "faceoffsets", "", &le_i64(fo.into_iter()));
    }
}

/// The cell data: `dim` and one array per label column.
fn cell_data(a: &mut Appended, m: &MeshOut) {
    let ind = "        ";
    a.array(ind, "Int32", "dim", "", &le_i32(m.cells.iter().map(|c| c.dim as i32)));
    for c in &m.columns {
        match c.col {
            Column::Int => a.array(
                ind,
                "Int32",
                &c.name,
                "",
                &le_i32(c.values.iter().map(|v| match v {
                    Some(LabelValue::Int(i)) => *i as i32,
                    _ => i32::MIN,
                })),
            ),
            Column::Int64 => a.array(
                ind,
                "Int64",
                &c.name,
                "",
                &le_i64(c.values.iter().map(|v| match v {
                    Some(LabelValue::Int(i)) => *i,
                    _ => i64::MIN,
                })),
            ),
            Column::Real => {
                let bytes: Vec<u8> = c
                    .values
                    .iter()
                    .flat_map(|v| {
                        match v {
                            Some(LabelValue::Int(i)) => *i as f64,
                            Some(LabelValue::Real(r)) => *r,
                            _ => f64::NAN,
                        }
                        .to_le_bytes()
                    })
                    .collect();
                a.array(ind, "Float64", &c.name, "", &bytes);
            }
            Column::Text => a.array(ind, "Int32", &c.name, "", &le_i32(c.text_ranks().1.into_iter().map(|r| r as i32))),
        }
    }
}

/// The bytes of the `.vtu` of mesh cells.
fn vtu_bytes(m: &MeshOut) -> Vec<u8> {
    let mut a = Appended { xml: String::new(), data: Vec::new() };
    let tables: Vec<_> = m.columns.iter().filter(|c| c.col == Column::Text).collect();
    if !tables.is_empty() {
        a.xml.push_str("    <FieldData>\n");
        for c in tables {
            let bytes = text_table(&c.text_ranks().0);
            let extra = format!(" NumberOfTuples=\"{}\"", bytes.len());
            a.array("      ", "UInt8", &text_table_name(&c.name), &extra, &bytes);
        }
        a.xml.push_str("    </FieldData>\n");
    }
    a.xml.push_str(&format!("    <Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n", m.points.len(), m.cells.len()));
    a.xml.push_str("      <Points>\n");
    let pts: Vec<u8> = m.points.iter().flatten().flat_map(|x| x.to_le_bytes()).collect();
    a.array("        ", "Float64", "Points", " NumberOfComponents=\"3\"", &pts);
    a.xml.push_str("      </Points>\n      <Cells>\n");
    cell_arrays(&mut a, m);
    a.xml.push_str("      </Cells>\n      <CellData>\n");
    cell_data(&mut a, m);
    a.xml.push_str("      </CellData>\n    </Piece>\n");
    let mut out = Vec::with_capacity(a.xml.len() + a.data.len() + 400);
    out.extend_from_slice(
        b"<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" \
          header_type=\"UInt64\" compressor=\"vtkZLibDataCompressor\">\n  <UnstructuredGrid>\n",
    );
    out.extend_from_slice(a.xml.as_bytes());
    out.extend_from_slice(b"  </UnstructuredGrid>\n  <AppendedData encoding=\"raw\">\n   _");
    out.extend_from_slice(&a.data);
    out.extend_from_slice(b"\n  </AppendedData>\n</VTKFile>\n");
    out
}

/// The `.vtu` bytes of a map of dimension at most 3 with points and the labels of its cells
/// (see the module documentation and [`super::vtk_string_with_labels`]), read back before
/// they are returned. O(N n) plus the data and its reading.
pub fn vtu_bytes_with_labels(map: &DenseMap, labels: &DenseLabels) -> Result<Vec<u8>, ExportError> {
    let m = mesh_out(map, labels, ".vtu")?;
    let out = vtu_bytes(&m);
    super::readback::check(map, labels, ".vtu", Labelling::Exact, || crate::import::parse_vtu(&out))?;
    Ok(out)
}

/// Writes a map and the labels of its cells as `.vtu` (see [`vtu_bytes_with_labels`]);
/// nothing is written when it is refused.
pub fn write_vtu_with_labels(map: &DenseMap, labels: &DenseLabels, path: &Path) -> Result<(), ExportError> {
    write_atomic(path, &vtu_bytes_with_labels(map, labels)?)
}
