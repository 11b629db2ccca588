//! Legacy VTK unstructured grids (`.vtk`, write only; docs/FORMATS.md §2).
//!
//! ```text
//! # vtk DataFile Version 3.0
//! gmap: a 3-map, 8 vertices, 1 volume
//! ASCII
//! DATASET UNSTRUCTURED_GRID
//! POINTS 8 double
//! 0 0 0
//! …
//! CELLS 1 31
//! 30 6 4 0 1 3 2 …          a polyhedron: its face stream
//! CELL_TYPES 1
//! 42
//! CELL_DATA 1
//! SCALARS dim int 1
//! LOOKUP_TABLE default
//! 3
//! ```
//!
//! One point per 0-cell (numbered by the 0-cells' smallest darts), the point of a dart of the
//! vertex ([`DenseMap::vertex_point`]). The cells are the map's top cells: a 3-map's volumes
//! as polyhedra (`VTK_POLYHEDRON` 42, each cell the face stream `nFaces, nPts, ids…, …`), a
//! 2-map's faces as polygons (`VTK_POLYGON` 7), a 1-map's edges as lines (`VTK_LINE` 3), a
//! 0-map's vertices as `VTK_VERTEX` 1. The corners of a polygon follow `alpha_1 alpha_0`
//! from a dart; the faces of a polyhedron are all walked from darts of one orientation class
//! of the volume and reversed together when the volume's signed volume is negative, so an
//! orientable volume has outward normals. `CELL_DATA` holds the cell dimension (`dim`).
//! Maps of dimension above 3, maps without points, and points that are not finite are
//! refused.
//!
//! With labels ([`vtk_string_with_labels`]), the lower cells that carry a label are written
//! after the top cells (2-cells as polygons, 1-cells as lines, 0-cells as vertices; a
//! viewer tells them apart by `dim`), and the cell data gains `FIELD labels K`: per label
//! name, in order of first appearance, an array over all written cells — `int` when every
//! value is an integer of 32 bits (missing: `-2147483648`), `vtktypeint64` for wider
//! integers (missing: `-9223372036854775808`), `double` when a value is real (missing:
//! `-1.7976931348623157e308`, as the legacy reader parses no NaN), and for texts a `string`
//! array (one text per line, missing: empty) followed by an `int` array `<name>.id`, the
//! rank of the text among the distinct texts of the column in byte order (missing: `-1`),
//! for colouring. Names and texts are written with VTK's `%XX` escape for bytes outside
//! `!`..`~` and for `%`.

use std::fmt::Write as _;
use std::path::Path;

use gmap_core::{AlphaSet, Dart, DenseLabels, DenseMap, LabelValue, Point};

use super::error::{write_atomic, ExportError};

const VTK_VERTEX: u8 = 1;
const VTK_LINE: u8 = 3;
const VTK_POLYGON: u8 = 7;
const VTK_POLYHEDRON: u8 = 42;

/// The corners (0-cell numbers) of the polygon walked by `alpha_1 alpha_0` from `d`.
fn polygon(map: &DenseMap, vert: &[u32], d: Dart) -> Vec<u32> {
    let mut corners = Vec::new();
    let mut x = d;
    loop {
        corners.push(vert[x.index()]);
        x = map.alpha(map.alpha(x, 0), 1);
        if x == d {
            return corners;
        }
    }
}

/// Six times the signed volume enclosed by the faces (each a fan of triangles).
fn signed_volume6(faces: &[Vec<u32>], pts: &[Point]) -> f64 {
    let mut v = 0.0;
    for f in faces {
        let a = pts[f[0] as usize];
        for k in 1..f.len().saturating_sub(1) {
            let (b, c) = (pts[f[k] as usize], pts[f[k + 1] as usize]);
            v += a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
                + a[2] * (b[0] * c[1] - b[1] * c[0]);
        }
    }
    v
}

/// One cell as written: its VTK type, its connectivity list (without the leading count),
/// and which cell of the map it is (dimension, number in [`DenseMap::cells`]).
struct Written {
    kind: u8,
    conn: Vec<u32>,
    dim: usize,
    cell: usize,
}

/// The face stream of every volume of a 3-map (`nFaces, nPts, ids…, …`), in the order of
/// `map.cells(3)`.
fn polyhedra(map: &DenseMap, vert: &[u32], pts: &[Point]) -> Vec<Vec<u32>> {
    // orientation classes: parity of the number of involutions from the volume's smallest
    // dart (BFS over alpha_0, alpha_1, alpha_2)
    let vols = map.cells(3);
    let faces = map.partition(AlphaSet::of(&[0, 1]));
    let mut parity = vec![u8::MAX; map.dart_count()];
    let mut face_done = vec![false; faces.len()];
    let mut out = Vec::with_capacity(vols.len());
    for &r in &vols.reps {
        let mut stack = vec![r];
        parity[r.index()] = 0;
        let mut polys: Vec<Vec<u32>> = Vec::new();
        while let Some(d) = stack.pop() {
            let f = faces.of[d.index()] as usize;
            if parity[d.index()] == 0 && !face_done[f] {
                face_done[f] = true;
                polys.push(polygon(map, vert, d));
            }
            for i in 0..3 {
                let e = map.alpha(d, i);
                if parity[e.index()] == u8::MAX {
                    parity[e.index()] = 1 - parity[d.index()];
                    stack.push(e);
                }
            }
        }
        // outward normals for an orientable volume (its faces are walked consistently)
        if signed_volume6(&polys, pts) < 0.0 {
            for p in &mut polys {
                p.reverse();
            }
        }
        let mut stream = vec![polys.len() as u32];
        for p in polys {
            stream.push(p.len() as u32);
            stream.extend(p);
        }
        out.push(stream);
    }
    out
}

/// The `k`-cells whose number satisfies `keep`, as VTK cells (`k <= 2`; volumes go through
/// [`polyhedra`]).
fn low_cells(map: &DenseMap, vert: &[u32], k: usize, keep: impl Fn(usize) -> bool) -> Vec<Written> {
    let reps = if k == 0 { Vec::new() } else { map.cells(k).reps };
    let count = if k == 0 { vert.iter().map(|&v| v as usize + 1).max().unwrap_or(0) } else { reps.len() };
    (0..count)
        .filter(|&c| keep(c))
        .map(|c| match k {
            0 => Written { kind: VTK_VERTEX, conn: vec![c as u32], dim: 0, cell: c },
            1 => {
                let d = reps[c];
                Written { kind: VTK_LINE, conn: vec![vert[d.index()], vert[map.alpha(d, 0).index()]], dim: 1, cell: c }
            }
            _ => Written { kind: VTK_POLYGON, conn: polygon(map, vert, reps[c]), dim: 2, cell: c },
        })
        .collect()
}

/// The type a label column is written with: the narrowest that holds all its values.
#[derive(Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
enum Column {
    /// integers in the range of `i32`: `int`, missing `-2147483648`
    Int,
    /// integers beyond it: `vtktypeint64`, missing `-9223372036854775808`
    Int64,
    /// reals, or integers mixed with reals: `double`, missing `-1.7976931348623157e308`
    Real,
    /// texts (and numbers mixed with texts, in their text form): a `string` array (missing:
    /// the empty text) and an `int` array `<name>.id` (the rank of the text among the
    /// column's distinct texts in byte order, missing `-1`)
    Text,
}

fn column_of(v: &LabelValue) -> Column {
    match v {
        LabelValue::Int(i) if i32::try_from(*i).is_ok() => Column::Int,
        LabelValue::Int(_) => Column::Int64,
        LabelValue::Real(_) => Column::Real,
        LabelValue::Text(_) => Column::Text,
    }
}

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

/// Writes the `FIELD labels` block of the cell data: one array per label name (see
/// [`Column`]), the names in order of first appearance over the written cells.
fn write_label_arrays(out: &mut String, written: &[Written], labels: &DenseLabels) {
    let mut names: Vec<(&str, Column)> = Vec::new();
    for w in written {
        for (name, v) in labels.get(w.dim, w.cell).iter() {
            let c = column_of(v);
            match names.iter_mut().find(|(n, _)| *n == name) {
                Some((_, col)) => *col = (*col).max(c),
                None => names.push((name, c)),
            }
        }
    }
    if names.is_empty() {
        return;
    }
    let arrays = names.len() + names.iter().filter(|(_, c)| *c == Column::Text).count();
    let n = written.len();
    let _ = writeln!(out, "FIELD labels {arrays}");
    for &(name, col) in &names {
        let value = |w: &Written| labels.get(w.dim, w.cell).get(name);
        let enc = encode(name);
        match col {
            Column::Int | Column::Int64 => {
                let (ty, missing) =
                    if col == Column::Int { ("int", i64::from(i32::MIN)) } else { ("vtktypeint64", i64::MIN) };
                let _ = writeln!(out, "{enc} 1 {n} {ty}");
                for w in written {
                    let v = match value(w) {
                        Some(LabelValue::Int(i)) => *i,
                        _ => missing,
                    };
                    let _ = writeln!(out, "{v}");
                }
            }
            Column::Real => {
                let _ = writeln!(out, "{enc} 1 {n} double");
                for w in written {
                    let v = match value(w) {
                        Some(LabelValue::Int(i)) => *i as f64,
                        Some(LabelValue::Real(r)) => *r,
                        _ => f64::MIN,
                    };
                    let _ = writeln!(out, "{v:?}");
                }
            }
            Column::Text => {
                let text = |v: &LabelValue| match v {
                    LabelValue::Text(s) => s.clone(),
                    LabelValue::Int(i) => i.to_string(),
                    LabelValue::Real(r) => format!("{r:?}"),
                };
                let texts: Vec<Option<String>> = written.iter().map(|w| value(w).map(text)).collect();
                let mut distinct: Vec<&str> = texts.iter().flatten().map(String::as_str).collect();
                distinct.sort_unstable();
                distinct.dedup();
                let _ = writeln!(out, "{enc} 1 {n} string");
                for t in &texts {
                    let _ = writeln!(out, "{}", encode(t.as_deref().unwrap_or("")));
                }
                let _ = writeln!(out, "{enc}.id 1 {n} int");
                for t in &texts {
                    let id = match t {
                        Some(t) => distinct.binary_search(&t.as_str()).map_or(-1, |k| k as i64),
                        None => -1,
                    };
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
/// without labels gives exactly [`vtk_string`]. O(N n) plus the text.
pub fn vtk_string_with_labels(map: &DenseMap, labels: &DenseLabels) -> Result<String, ExportError> {
    let n = map.dim();
    if n > 3 {
        return Err(ExportError::DimensionAbove { format: ".vtk", max: 3, found: n });
    }
    if map.dart_count() > 0 && !map.has_points() {
        return Err(ExportError::NoPoints { format: ".vtk" });
    }
    let verts = map.cells(0);
    let mut pts: Vec<Point> = Vec::with_capacity(verts.len());
    for r in verts.reps.iter().map(|d| d.get()) {
        let p = map.vertex_point(Dart::new(r)).ok_or(ExportError::VertexPoint {
            format: ".vtk",
            dart: r,
            what: "no point",
        })?;
        if !p.iter().all(|c| c.is_finite()) {
            return Err(ExportError::VertexPoint { format: ".vtk", dart: r, what: "a point that is not finite" });
        }
        pts.push(p);
    }
    let vert = &verts.of;
    let mut cells: Vec<Written> = if n == 3 {
        polyhedra(map, vert, &pts)
            .into_iter()
            .enumerate()
            .map(|(c, conn)| Written { kind: VTK_POLYHEDRON, conn, dim: 3, cell: c })
            .collect()
    } else {
        low_cells(map, vert, n, |_| true)
    };
    let top = cells.len();
    for k in (0..n).rev() {
        if labels.of.get(k).is_some_and(|v| v.iter().any(|l| !l.is_empty())) {
            cells.extend(low_cells(map, vert, k, |c| !labels.get(k, c).is_empty()));
        }
    }
    let mut out = String::with_capacity(64 + pts.len() * 24 + cells.iter().map(|c| c.conn.len() * 6).sum::<usize>());
    let _ = writeln!(out, "# vtk DataFile Version 3.0");
    let _ = write!(out, "gmap: a {n}-map, {} vertices, {top} top cells", pts.len());
    if cells.len() > top {
        let _ = write!(out, ", {} labelled lower cells", cells.len() - top);
    }
    let _ = writeln!(out, "\nASCII\nDATASET UNSTRUCTURED_GRID");
    let _ = writeln!(out, "POINTS {} double", pts.len());
    for p in &pts {
        let _ = writeln!(out, "{} {} {}", p[0], p[1], p[2]);
    }
    let size: usize = cells.iter().map(|c| c.conn.len() + 1).sum();
    let _ = writeln!(out, "CELLS {} {size}", cells.len());
    for c in &cells {
        let _ = write!(out, "{}", c.conn.len());
        for v in &c.conn {
            let _ = write!(out, " {v}");
        }
        out.push('\n');
    }
    let _ = writeln!(out, "CELL_TYPES {}", cells.len());
    for c in &cells {
        let _ = writeln!(out, "{}", c.kind);
    }
    let _ = writeln!(out, "CELL_DATA {}", cells.len());
    let _ = writeln!(out, "SCALARS dim int 1\nLOOKUP_TABLE default");
    for c in &cells {
        let _ = writeln!(out, "{}", c.dim);
    }
    write_label_arrays(&mut out, &cells, labels);
    Ok(out)
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
    use super::*;
    use crate::build;
    use gmap_core::Labels;

    fn prism(k: usize) -> DenseMap {
        build::extrude(&build::polygon(k).unwrap()).unwrap()
    }

    #[test]
    fn a_cube_is_one_hexahedral_polyhedron_with_outward_faces() {
        let m = prism(4);
        assert_eq!(m.dim(), 3);
        let text = vtk_string(&m).unwrap();
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(lines[0], "# vtk DataFile Version 3.0");
        assert_eq!(lines[2], "ASCII");
        assert_eq!(lines[3], "DATASET UNSTRUCTURED_GRID");
        assert_eq!(lines[4], "POINTS 8 double");
        assert_eq!(lines[13], "CELLS 1 32");
        let cell: Vec<u32> = lines[14].split(' ').map(|x| x.parse().unwrap()).collect();
        assert_eq!(cell[0], 31);
        assert_eq!(cell[1], 6);
        assert_eq!(&lines[15..17], &["CELL_TYPES 1", "42"]);
        assert_eq!(&lines[17..], &["CELL_DATA 1", "SCALARS dim int 1", "LOOKUP_TABLE default", "3"]);
        // six quadrilaterals, every point used by three of them, positive volume
        let pts: Vec<Point> = lines[5..13]
            .iter()
            .map(|l| {
                let v: Vec<f64> = l.split(' ').map(|x| x.parse().unwrap()).collect();
                [v[0], v[1], v[2]]
            })
            .collect();
        let mut faces = Vec::new();
        let mut k = 2;
        for _ in 0..6 {
            assert_eq!(cell[k], 4);
            faces.push(cell[k + 1..k + 5].to_vec());
            k += 5;
        }
        for v in 0..8 {
            assert_eq!(faces.iter().filter(|f| f.contains(&v)).count(), 3);
        }
        // the unit-circle square extruded by 1 has area 2 and volume 2
        assert!((signed_volume6(&faces, &pts) / 6.0 - 2.0).abs() < 1e-9);
        // each edge is used once in each direction (consistently oriented faces)
        let mut dir_edges = Vec::new();
        for f in &faces {
            for j in 0..4 {
                dir_edges.push((f[j], f[(j + 1) % 4]));
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
        assert!(text.contains("CELL_TYPES 1\n7\n"));
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
        labels.of[1][2].set("w", LabelValue::Int(2));
        labels.of[0][1].set("w", LabelValue::Real(0.5));
        labels.of[0][1].set("name", LabelValue::Int(3));
        let text = vtk_string_with_labels(&sq, &labels).unwrap();
        let vert = sq.cells(0).of;
        let e = sq.cells(1).reps[2];
        let (a, b) = (vert[e.index()], vert[sq.alpha(e, 0).index()]);
        assert!(text.contains(&format!("CELLS 3 10\n4 0 1 2 3\n2 {a} {b}\n1 1\nCELL_TYPES 3\n7\n3\n1\n")), "{text}");
        let data = text.split("CELL_DATA 3\n").nth(1).unwrap();
        assert_eq!(
            data,
            "SCALARS dim int 1\nLOOKUP_TABLE default\n2\n1\n0\n\
             FIELD labels 4\n\
             name 1 3 string\na%20100%25%20\"square\"\n\n3\n\
             name.id 1 3 int\n1\n-1\n0\n\
             big 1 3 vtktypeint64\n-9223372036854775808\n1099511627776\n-9223372036854775808\n\
             w 1 3 double\n-1.7976931348623157e308\n2.0\n0.5\n"
        );
        // no label: the text of `vtk_string`
        let none = DenseLabels { of: vec![vec![Labels::new(); 4]] };
        assert_eq!(vtk_string_with_labels(&sq, &none).unwrap(), vtk_string(&sq).unwrap());
        assert_eq!(encode("é\t%"), "%C3%A9%09%25");
    }
}
