//! Legacy VTK unstructured grids (`.vtk`; docs/FORMATS.md §2). The reader is
//! [`crate::import::vtk`].
//!
//! ```text
//! # vtk DataFile Version 3.0
//! gmap: a 3-map, 8 vertices, 1 top cells
//! ASCII
//! DATASET UNSTRUCTURED_GRID
//! POINTS 8 double
//! 0 0 0
//! …
//! CELLS 1 9
//! 8 0 2 3 1 4 6 7 5         a hexahedron (a polyhedron: 42 and its face stream)
//! CELL_TYPES 1
//! 12
//! CELL_DATA 1
//! SCALARS dim int 1
//! LOOKUP_TABLE default
//! 3
//! ```
//!
//! One point per 0-cell (numbered by the 0-cells' smallest darts), the point of a dart of the
//! vertex ([`DenseMap::vertex_point`]). The cells are the map's top cells: a 3-map's volumes
//! as tetrahedra (`VTK_TETRA` 10), pyramids (14), wedges (13) or hexahedra (12) when their
//! faces make one — corners in VTK's order and orientation, every cell of positive volume
//! ([`super::cells`]) — and as polyhedra otherwise (`VTK_POLYHEDRON` 42, each cell the
//! face stream `nFaces, nPts, ids…, …`, faces outward), so that readers without polyhedra
//! (meshio's) read the usual meshes; a 2-map's faces as triangles (`VTK_TRIANGLE` 5),
//! quadrangles (`VTK_QUAD` 9) or polygons (`VTK_POLYGON` 7) by their number of corners, a
//! 1-map's edges as lines (`VTK_LINE` 3), a 0-map's vertices as `VTK_VERTEX` 1. The corners
//! of a polygon follow `alpha_1 alpha_0` from a dart. `CELL_DATA` holds the cell dimension
//! (`dim`). Maps of dimension above 3, maps without points, points that are not finite,
//! faces of fewer than three distinct corners and slits (two faces on the same vertices) are
//! refused, and so is a text that would not read back as the same map and labels.
//!
//! With labels ([`vtk_string_with_labels`]), the lower cells that carry a label are written
//! after the top cells (2-cells as polygons, 1-cells as lines, 0-cells as vertices; a
//! viewer tells them apart by `dim`), and the cell data gains `FIELD labels K`: per label
//! name, in order of first appearance, an array over all written cells — `int` when every
//! value is an integer of 32 bits (missing: `-2147483648`), `long` for wider
//! integers (missing: `-9223372036854775808`), `double` when a value is real (missing:
//! `-1.7976931348623157e308`, as the legacy reader parses no NaN), and for texts an `int`
//! array of ranks (missing: `-1`) in the table of the column's distinct texts in byte order.
//! The tables are the dataset's field data, before the points (`FIELD FieldData K`): per
//! text column `name`, an `unsigned_char` array `gmap:texts:name` of the texts' UTF-8 bytes,
//! each text followed by a NUL byte. No `string` array is written, so that both VTK and
//! meshio read the file (meshio has no `string` type). Names are written with VTK's `%XX`
//! escape for bytes outside `!`..`~` and for `%`.

use std::fmt::Write as _;
use std::path::Path;

use gmap_core::{DenseLabels, DenseMap, LabelValue};

use super::cells::{mesh_out, text_table, text_table_name, Column, MeshOut};
use super::error::{write_atomic, ExportError};
use super::readback::Labelling;

/// A name or text as the legacy reader decodes it: every byte outside `!`..`~`, and `%`,
/// as `%XX` (so that a text is one word, or one line).
fn encode(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for b in s.bytes() {
        if b <= b' ' || b >= 0x7f || b == b'%' {
            let _ = write!(out, "%{b:02X}");
        } else {
            out.push(b as char);
        }
    }
    out
}

/// Writes the dataset's field data: the table of texts of each text column (see
/// [`Column::Text`]), as `unsigned_char` arrays `gmap:texts:<name>`.
fn write_text_tables(out: &mut String, m: &MeshOut) {
    let tables: Vec<(String, Vec<u8>)> = m
        .columns
        .iter()
        .filter(|c| c.col == Column::Text)
        .map(|c| (text_table_name(&c.name), text_table(&c.text_ranks().0)))
        .collect();
    if tables.is_empty() {
        return;
    }
    let _ = writeln!(out, "FIELD FieldData {}", tables.len());
    for (name, bytes) in tables {
        let _ = writeln!(out, "{} 1 {} unsigned_char", encode(&name), bytes.len());
        for (k, b) in bytes.iter().enumerate() {
            let _ = write!(
                out,
                "{}{b}",
                if k % 20 == 0 {
                    if k == 0 {
                        ""
                    } else {
                        "\n"
                    }
                } else {
                    " "
                }
            );
        }
        out.push('\n');
    }
}

/// Writes the `FIELD labels` block of the cell data: one array per label column.
fn write_label_arrays(out: &mut String, m: &MeshOut) {
    if m.columns.is_empty() {
        return;
    }
    let n = m.cells.len();
    let _ = writeln!(out, "FIELD labels {}", m.columns.len());
    for c in &m.columns {
        let enc = encode(&c.name);
        match c.col {
            Column::Int | Column::Int64 => {
                let (ty, missing) =
                    if c.col == Column::Int { ("int", i64::from(i32::MIN)) } else { ("long", i64::MIN) };
                let _ = writeln!(out, "{enc} 1 {n} {ty}");
                for v in &c.values {
                    let v = match v {
                        Some(LabelValue::Int(i)) => *i,
                        _ => missing,
                    };
                    let _ = writeln!(out, "{v}");
                }
            }
            Column::Real => {
                let _ = writeln!(out, "{enc} 1 {n} double");
                for v in &c.values {
                    let v = match v {
                        Some(LabelValue::Int(i)) => *i as f64,
                        Some(LabelValue::Real(r)) => *r,
                        _ => f64::MIN,
                    };
                    let _ = writeln!(out, "{v:?}");
                }
            }
            Column::Text => {
                let _ = writeln!(out, "{enc} 1 {n} int");
                for id in c.text_ranks().1 {
                    let _ = writeln!(out, "{id}");
                }
            }
        }
    }
}

/// The legacy VTK text of a map of dimension at most 3 with points (see the module
/// documentation), without cell labels. O(N) plus the text.
pub fn vtk_string(map: &DenseMap) -> Result<String, ExportError> {
    vtk_string_with_labels(map, &DenseLabels::default())
}

/// The legacy VTK text of a map of dimension at most 3 with points and the labels of its
/// cells (`labels.get(i, c)`: those of `i`-cell `c` of [`DenseMap::cells`]`(i)`, as
/// [`gmap_core::to_dense_labels`] numbers them). Written cells: every top cell, then the
/// cells of each lower dimension (from the highest) that carry at least one label; the cell
/// data holds `dim` and one array per label name (see the module documentation). A map
/// without labels gives exactly [`vtk_string`]. The text is read back
/// ([`super::readback`]) and refused when it would not give the same map and labels.
/// O(N n) plus the text and its reading.
pub fn vtk_string_with_labels(map: &DenseMap, labels: &DenseLabels) -> Result<String, ExportError> {
    let m = mesh_out(map, labels, ".vtk")?;
    let out = legacy_text(&m);
    super::readback::check(map, labels, ".vtk", Labelling::Exact, || crate::import::parse_vtk(out.as_bytes()))?;
    Ok(out)
}

/// The legacy text of mesh cells.
fn legacy_text(m: &MeshOut) -> String {
    let (n, top) = (m.dim, m.top);
    let conns: Vec<Vec<u32>> = m.cells.iter().map(|c| c.legacy()).collect();
    let mut out = String::with_capacity(64 + m.points.len() * 24 + conns.iter().map(|c| c.len() * 6).sum::<usize>());
    let _ = writeln!(out, "# vtk DataFile Version 3.0");
    let _ = write!(out, "gmap: a {n}-map, {} vertices, {top} top cells", m.points.len());
    if m.cells.len() > top {
        let _ = write!(out, ", {} labelled lower cells", m.cells.len() - top);
    }
    let _ = writeln!(out, "\nASCII\nDATASET UNSTRUCTURED_GRID");
    write_text_tables(&mut out, m);
    let _ = writeln!(out, "POINTS {} double", m.points.len());
    for p in &m.points {
        let _ = writeln!(out, "{} {} {}", p[0], p[1], p[2]);
    }
    let size: usize = conns.iter().map(|c| c.len() + 1).sum();
    let _ = writeln!(out, "CELLS {} {size}", m.cells.len());
    for c in &conns {
        let _ = write!(out, "{}", c.len());
        for v in c {
            let _ = write!(out, " {v}");
        }
        out.push('\n');
    }
    let _ = writeln!(out, "CELL_TYPES {}", m.cells.len());
    for c in &m.cells {
        let _ = writeln!(out, "{}", c.kind);
    }
    let _ = writeln!(out, "CELL_DATA {}", m.cells.len());
    let _ = writeln!(out, "SCALARS dim int 1\nLOOKUP_TABLE default");
    for c in &m.cells {
        let _ = writeln!(out, "{}", c.dim);
    }
    write_label_arrays(&mut out, m);
    out
}

/// Writes a map as legacy VTK (see [`vtk_string`]); nothing is written when it is refused.
pub fn write_vtk(map: &DenseMap, path: &Path) -> Result<(), ExportError> {
    write_atomic(path, vtk_string(map)?.as_bytes())
}

/// Writes a map and the labels of its cells as legacy VTK (see [`vtk_string_with_labels`]);
/// nothing is written when it is refused.
pub fn write_vtk_with_labels(map: &DenseMap, labels: &DenseLabels, path: &Path) -> Result<(), ExportError> {
    write_atomic(path, vtk_string_with_labels(map, labels)?.as_bytes())
}

#[cfg(test)]
mod tests {
    use super::super::cells::signed_volume6;
    use super::*;
    use crate::build;
    use gmap_core::{Dart, Labels, Point};

    fn prism(k: usize) -> DenseMap {
        build::extrude(&build::polygon(k).unwrap()).unwrap()
    }

    /// The corners of the one cell of `text` and the points.
    fn one_cell(text: &str) -> (u8, Vec<u32>, Vec<Point>) {
        let lines: Vec<&str> = text.lines().collect();
        let np: usize = lines[4].split(' ').nth(1).unwrap().parse().unwrap();
        let pts: Vec<Point> = lines[5..5 + np]
            .iter()
            .map(|l| {
                let v: Vec<f64> = l.split(' ').map(|x| x.parse().unwrap()).collect();
                [v[0], v[1], v[2]]
            })
            .collect();
        assert!(lines[5 + np].starts_with("CELLS 1 "));
        let cell: Vec<u32> = lines[6 + np].split(' ').map(|x| x.parse().unwrap()).collect();
        assert_eq!(cell[0] as usize, cell.len() - 1);
        assert_eq!(lines[7 + np], "CELL_TYPES 1");
        (lines[8 + np].parse().unwrap(), cell[1..].to_vec(), pts)
    }

    fn det(a: Point, b: Point, c: Point, d: Point) -> f64 {
        let (u, v, w) = (
            [b[0] - a[0], b[1] - a[1], b[2] - a[2]],
            [c[0] - a[0], c[1] - a[1], c[2] - a[2]],
            [d[0] - a[0], d[1] - a[1], d[2] - a[2]],
        );
        u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0])
    }

    #[test]
    fn standard_volumes_get_their_vtk_types_and_orientation() {
        // the cube: a hexahedron whose bottom turns counterclockwise seen from the top
        let text = vtk_string(&prism(4)).unwrap();
        assert!(text.ends_with("CELL_DATA 1\nSCALARS dim int 1\nLOOKUP_TABLE default\n3\n"));
        let (kind, c, p) = one_cell(&text);
        assert_eq!((kind, c.len()), (12, 8));
        let mut sorted = c.clone();
        sorted.sort_unstable();
        assert_eq!(sorted, (0..8).collect::<Vec<u32>>());
        let at = |k: usize| p[c[k] as usize];
        assert!(det(at(0), at(1), at(3), at(4)) > 0.0);
        // VTK's twelve edges are edges of the prism: sides of length √2, verticals of 1
        let len = |a: Point, b: Point| ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt();
        let edge = |l: f64| (l - 1.0).abs() < 1e-9 || (l - 2f64.sqrt()).abs() < 1e-9;
        for k in 0..4 {
            assert!(edge(len(at(k), at((k + 1) % 4))) && edge(len(at(k + 4), at((k + 1) % 4 + 4))));
            assert!(edge(len(at(k), at(k + 4))));
        }
        // the triangular prism: a wedge whose 0 1 2 turns counterclockwise seen from 3 4 5
        // (VTK's vtkCellSizeFilter gives it a positive volume)
        let (kind, c, p) = one_cell(&vtk_string(&prism(3)).unwrap());
        assert_eq!((kind, c.len()), (13, 6));
        let at = |k: usize| p[c[k] as usize];
        assert!(det(at(0), at(1), at(2), at(3)) > 0.0);
        let edge = |l: f64| (l - 1.0).abs() < 1e-9 || (l - 3f64.sqrt()).abs() < 1e-9;
        for k in 0..3 {
            assert!(edge(len(at(k), at((k + 1) % 3))) && edge(len(at(k + 3), at((k + 1) % 3 + 3))));
            assert!(edge(len(at(k), at(k + 3))));
        }
        // the simplex: a tetrahedron with 0 1 2 counterclockwise seen from 3
        let mut tet = build::simplex(3).unwrap();
        for (d, q) in (0..tet.dart_count() as u32).zip(0..) {
            let _ = q;
            let v = tet.cells(0).of[d as usize] as usize;
            tet.set_point(Dart::new(d), Some([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]][v]));
        }
        let (kind, c, p) = one_cell(&vtk_string(&tet).unwrap());
        assert_eq!((kind, c.len()), (10, 4));
        assert!(det(p[c[0] as usize], p[c[1] as usize], p[c[2] as usize], p[c[3] as usize]) > 0.0);
    }

    #[test]
    fn other_volumes_are_polyhedra_with_outward_faces() {
        // the pentagonal prism: 7 faces, 10 points
        let m = prism(5);
        let (kind, stream, pts) = one_cell(&vtk_string(&m).unwrap());
        assert_eq!(kind, 42);
        assert_eq!(stream[0], 7);
        let mut faces = Vec::new();
        let mut k = 1;
        while k < stream.len() {
            let n = stream[k] as usize;
            faces.push(stream[k + 1..k + 1 + n].to_vec());
            k += 1 + n;
        }
        assert_eq!(faces.len(), 7);
        for v in 0..10 {
            assert_eq!(faces.iter().filter(|f| f.contains(&v)).count(), 3);
        }
        assert!(signed_volume6(&faces, &pts) > 0.0);
        // each edge is used once in each direction (consistently oriented faces)
        let mut dir_edges = Vec::new();
        for f in &faces {
            for j in 0..f.len() {
                dir_edges.push((f[j], f[(j + 1) % f.len()]));
            }
        }
        for &(a, b) in &dir_edges {
            assert!(dir_edges.contains(&(b, a)));
            assert_eq!(dir_edges.iter().filter(|&&e| e == (a, b)).count(), 1);
        }
    }

    #[test]
    fn polygons_lines_and_refusals() {
        let sq = build::polygon(4).unwrap();
        let text = vtk_string(&sq).unwrap();
        assert!(text.contains("POINTS 4 double\n"));
        assert!(text.contains("CELLS 1 5\n4 0 1 2 3\n") || text.contains("CELLS 1 5\n4 0 3 2 1\n"), "{text}");
        assert!(text.contains("CELL_TYPES 1\n9\n"));
        assert!(text.ends_with("SCALARS dim int 1\nLOOKUP_TABLE default\n2\n"));
        let e = vtk_string(&build::cube(3).unwrap()).unwrap_err();
        assert_eq!(e.to_string(), "the map has no points: .vtk needs coordinates for every vertex");
        assert!(matches!(vtk_string(&DenseMap::new(4, 1)), Err(ExportError::DimensionAbove { .. })));
        let mut half = sq.clone();
        half.set_point(Dart::new(0), None);
        half.set_point(Dart::new(7), None);
        half.set_point(Dart::new(4), Some([f64::NAN, 0.0, 0.0]));
        assert_eq!(
            vtk_string(&half).unwrap_err().to_string(),
            "the vertex of dart 0 has no point: .vtk needs finite coordinates for every vertex"
        );
        // a 1-map: the square's boundary
        let mut c = DenseMap::new(1, 4);
        for (a, b) in [(0, 1), (2, 3)] {
            c.link(Dart::new(a), Dart::new(b), 0);
        }
        c.link(Dart::new(1), Dart::new(2), 1);
        c.link(Dart::new(3), Dart::new(0), 1);
        for d in 0..4 {
            c.set_point(Dart::new(d), Some([d as f64, 0.0, 0.0]));
        }
        let text = vtk_string(&c).unwrap();
        assert!(text.contains("POINTS 2 double\n"), "{text}");
        assert!(text.contains("CELLS 2 6\n2 0 1\n2 1 0\nCELL_TYPES 2\n3\n3\n"), "{text}");
    }

    #[test]
    fn labels_become_cell_data_over_the_labelled_cells() {
        let sq = build::polygon(4).unwrap();
        // face 0 named, edge 2 with a wide integer and a real, vertex 1 with a mixed column
        let mut labels = DenseLabels { of: vec![vec![Labels::new(); 4], vec![Labels::new(); 4], vec![Labels::new()]] };
        labels.of[2][0].set("name", LabelValue::Text("a 100% \"square\"".into()));
        labels.of[1][2].set("big", LabelValue::Int(1 << 40));
        labels.of[1][2].set("w", LabelValue::Real(2.0));
        labels.of[0][1].set("w", LabelValue::Real(0.5));
        labels.of[0][1].set("name", LabelValue::Text("3".into()));
        let text = vtk_string_with_labels(&sq, &labels).unwrap();
        let vert = sq.cells(0).of;
        let e = sq.cells(1).reps[2];
        let (a, b) = (vert[e.index()], vert[sq.alpha(e, 0).index()]);
        assert!(text.contains(&format!("CELLS 3 10\n4 0 1 2 3\n2 {a} {b}\n1 1\nCELL_TYPES 3\n9\n3\n1\n")), "{text}");
        // the texts "3" and "a 100% \"square\"" in byte order, each ended by NUL
        let mut table = b"3\0a 100% \"square\"\0".iter().map(|b| b.to_string()).collect::<Vec<_>>().join(" ");
        table.insert(0, '\n');
        assert!(
            text.contains(&format!(
                "DATASET UNSTRUCTURED_GRID\nFIELD FieldData 1\ngmap:texts:name 1 18 unsigned_char{table}\nPOINTS"
            )),
            "{text}"
        );
        let data = text.split("CELL_DATA 3\n").nth(1).unwrap();
        assert_eq!(
            data,
            "SCALARS dim int 1\nLOOKUP_TABLE default\n2\n1\n0\n\
             FIELD labels 3\n\
             name 1 3 int\n1\n-1\n0\n\
             big 1 3 long\n-9223372036854775808\n1099511627776\n-9223372036854775808\n\
             w 1 3 double\n-1.7976931348623157e308\n2.0\n0.5\n"
        );
        // no label: the text of `vtk_string`
        let none = DenseLabels { of: vec![vec![Labels::new(); 4]] };
        assert_eq!(vtk_string_with_labels(&sq, &none).unwrap(), vtk_string(&sq).unwrap());
        assert_eq!(encode("é\t%"), "%C3%A9%09%25");
        // a column of integers and reals would read back as reals: refused
        labels.of[1][2].set("w", LabelValue::Int(2));
        let e = vtk_string_with_labels(&sq, &labels).unwrap_err().to_string();
        assert!(e.contains("would read back with other labels") && e.contains("Int(2)"), "{e}");
    }
}
