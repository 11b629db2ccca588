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
//! faces make one — corners in VTK's order, oriented as VTK expects when the volume is
//! orientable — and as polyhedra otherwise (`VTK_POLYHEDRON` 42, each cell the face stream
//! `nFaces, nPts, ids…, …`), so that readers without polyhedra (meshio's) read the usual
//! meshes; a 2-map's faces as triangles (`VTK_TRIANGLE` 5), quadrangles (`VTK_QUAD` 9) or
//! polygons (`VTK_POLYGON` 7) by their number of corners, a 1-map's edges as lines (`VTK_LINE` 3), a
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

use super::{write_atomic, ExportError};

const VTK_VERTEX: u8 = 1;
const VTK_LINE: u8 = 3;
const VTK_TRIANGLE: u8 = 5;
const VTK_POLYGON: u8 = 7;
const VTK_QUAD: u8 = 9;
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

/// Every volume of a 3-map as a VTK cell, in the order of `map.cells(3)`: its type and its
/// corners ([`standard_cell`]), or `VTK_POLYHEDRON` and its face stream
/// (`nFaces, nPts, ids…, …`).
fn polyhedra(map: &DenseMap, vert: &[u32], pts: &[Point]) -> Vec<(u8, Vec<u32>)> {
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
        out.push(match standard_cell(&polys) {
            Some((kind, conn)) => (kind, conn),
            None => {
                let mut stream = vec![polys.len() as u32];
                for p in polys {
                    stream.push(p.len() as u32);
                    stream.extend(p);
                }
                (VTK_POLYHEDRON, stream)
            }
        });
    }
    out
}

/// The VTK type and corners of a volume whose outward faces make a tetrahedron, a pyramid,
/// a wedge or a hexahedron (checked on the vertex sets of all its faces), in VTK's corner
/// order and orientation: the tetrahedron's `0 1 2` and the pyramid's and hexahedron's
/// `0 1 2 3` turn counterclockwise seen from the other corners, the wedge's `0 1 2` faces
/// out. `None` for any other volume. O(faces²).
fn standard_cell(polys: &[Vec<u32>]) -> Option<(u8, Vec<u32>)> {
    let tris: Vec<&Vec<u32>> = polys.iter().filter(|p| p.len() == 3).collect();
    let quads: Vec<&Vec<u32>> = polys.iter().filter(|p| p.len() == 4).collect();
    let mut verts: Vec<u32> = polys.iter().flatten().copied().collect();
    verts.sort_unstable();
    verts.dedup();
    // the neighbour of x along an edge of some face that is not in `base`
    let partner = |x: u32, base: &[u32]| -> Option<u32> {
        let mut found: Vec<u32> = Vec::new();
        for p in polys {
            for (j, &v) in p.iter().enumerate() {
                if v == x {
                    for w in [p[(j + 1) % p.len()], p[(j + p.len() - 1) % p.len()]] {
                        if !base.contains(&w) && !found.contains(&w) {
                            found.push(w);
                        }
                    }
                }
            }
        }
        (found.len() == 1).then(|| found[0])
    };
    let set = |xs: &[u32]| -> Vec<u32> {
        let mut v = xs.to_vec();
        v.sort_unstable();
        v
    };
    // every face of the volume is one of `want` (as vertex sets), and they are all there
    let faces_are = |want: Vec<Vec<u32>>| -> bool {
        let mut have: Vec<Vec<u32>> = polys.iter().map(|p| set(p)).collect();
        let mut want: Vec<Vec<u32>> = want.iter().map(|w| set(w)).collect();
        have.sort();
        want.sort();
        have == want
    };
    match (polys.len(), tris.len(), quads.len(), verts.len()) {
        (4, 4, 0, 4) => {
            let (a, b, c) = (tris[0][0], tris[0][1], tris[0][2]);
            let d = *verts.iter().find(|v| !tris[0].contains(v))?;
            faces_are(vec![vec![a, b, c], vec![a, b, d], vec![b, c, d], vec![c, a, d]]).then(|| (10, vec![a, c, b, d]))
        }
        (5, 4, 1, 5) => {
            let q = quads[0];
            let e = *verts.iter().find(|v| !q.contains(v))?;
            let sides = (0..4).map(|j| vec![q[j], q[(j + 1) % 4], e]);
            faces_are(sides.chain([q.clone()]).collect()).then(|| (14, vec![q[0], q[3], q[2], q[1], e]))
        }
        (5, 2, 3, 6) => {
            let t = tris[0];
            let p: Vec<u32> = t.iter().map(|&x| partner(x, t)).collect::<Option<_>>()?;
            let sides = (0..3).map(|j| vec![t[j], t[(j + 1) % 3], p[(j + 1) % 3], p[j]]);
            faces_are(sides.chain([t.clone(), p.clone()]).collect())
                .then(|| (13, vec![t[0], t[1], t[2], p[0], p[1], p[2]]))
        }
        (6, 0, 6, 8) => {
            let q = quads[0];
            let p: Vec<u32> = q.iter().map(|&x| partner(x, q)).collect::<Option<_>>()?;
            let sides = (0..4).map(|j| vec![q[j], q[(j + 1) % 4], p[(j + 1) % 4], p[j]]);
            faces_are(sides.chain([q.clone(), p.clone()]).collect())
                .then(|| (12, vec![q[0], q[3], q[2], q[1], p[0], p[3], p[2], p[1]]))
        }
        _ => None,
    }
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
            _ => {
                let conn = polygon(map, vert, reps[c]);
                let kind = match conn.len() {
                    3 => VTK_TRIANGLE,
                    4 => VTK_QUAD,
                    _ => VTK_POLYGON,
                };
                Written { kind, conn, dim: 2, cell: c }
            }
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
fn write_label_arrays(out: &mut String, written: &[Written], labels: &DenseLabels) -> Result<(), ExportError> {
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
        return Ok(());
    }
    if names.iter().any(|(n, _)| n.is_empty()) {
        return Err(ExportError::EmptyLabelName { format: ".vtk" });
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
    Ok(())
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
    for &Dart(r) in &verts.reps {
        let p =
            map.vertex_point(Dart(r)).ok_or(ExportError::VertexPoint { format: ".vtk", dart: r, what: "no point" })?;
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
            .map(|(c, (kind, conn))| Written { kind, conn, dim: 3, cell: c })
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
    write_label_arrays(&mut out, &cells, labels)?;
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
        // the triangular prism: a wedge whose 0 1 2 faces out, 3 4 5 above it
        let (kind, c, p) = one_cell(&vtk_string(&prism(3)).unwrap());
        assert_eq!((kind, c.len()), (13, 6));
        let at = |k: usize| p[c[k] as usize];
        assert!(det(at(0), at(1), at(2), at(3)) < 0.0);
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
            tet.set_point(Dart(d), Some([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]][v]));
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
        half.set_point(Dart(0), None);
        half.set_point(Dart(7), None);
        half.set_point(Dart(4), Some([f64::NAN, 0.0, 0.0]));
        assert_eq!(
            vtk_string(&half).unwrap_err().to_string(),
            "the vertex of dart 0 has no point: .vtk needs finite coordinates for every vertex"
        );
        // a 1-map: the square's boundary
        let mut c = DenseMap::new(1, 4);
        for (a, b) in [(0, 1), (2, 3)] {
            c.link(Dart(a), Dart(b), 0);
        }
        c.link(Dart(1), Dart(2), 1);
        c.link(Dart(3), Dart(0), 1);
        for d in 0..4 {
            c.set_point(Dart(d), Some([d as f64, 0.0, 0.0]));
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
        assert!(text.contains(&format!("CELLS 3 10\n4 0 1 2 3\n2 {a} {b}\n1 1\nCELL_TYPES 3\n9\n3\n1\n")), "{text}");
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
