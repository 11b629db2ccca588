//! A map with points and cell labels as the cells of a mesh file (`.vtk`, `.vtu`, `.msh`):
//! one point per 0-cell, the top cells with VTK's types, corner orders and orientations,
//! then the labelled lower cells, and the label columns over the written cells. The
//! writers of [`super::vtk`], [`super::vtu`] and [`super::msh`] serialise this list.
//!
//! The corner orders are VTK's and Gmsh's (the same for the linear cells): a tetrahedron
//! `0 1 2 3` with `0 1 2` counterclockwise seen from `3`; a pyramid's base `0 1 2 3`
//! counterclockwise seen from the apex `4`; a wedge's triangle `0 1 2` counterclockwise seen
//! from the other triangle `3 4 5` (`k + 3` above `k`); a hexahedron's `0 1 2 3`
//! counterclockwise seen from `4 5 6 7` (`k + 4` above `k`). So every cell of an orientable
//! volume has a positive volume in VTK (`vtkCellSizeFilter`, `vtkMeshQuality`) and Gmsh.
//!
//! A mesh file glues cells by their vertices, so a map is refused here when it cannot be
//! written as cells on vertices at all: a face with fewer than three corners or a vertex
//! twice (a digon left by a contraction), and two distinct facets of the top cells on the
//! same vertices (a slit: faces unsewn inside the map, which any reader glues again).

use gmap_core::{AlphaSet, Dart, DenseLabels, DenseMap, LabelValue, Point};

use super::error::ExportError;

pub(crate) const VTK_VERTEX: u8 = 1;
pub(crate) const VTK_LINE: u8 = 3;
pub(crate) const VTK_TRIANGLE: u8 = 5;
pub(crate) const VTK_POLYGON: u8 = 7;
pub(crate) const VTK_QUAD: u8 = 9;
pub(crate) const VTK_TETRA: u8 = 10;
pub(crate) const VTK_HEXAHEDRON: u8 = 12;
pub(crate) const VTK_WEDGE: u8 = 13;
pub(crate) const VTK_PYRAMID: u8 = 14;
pub(crate) const VTK_POLYHEDRON: u8 = 42;

/// One cell as written: its VTK type, its corners (for a polyhedron its distinct points),
/// a polyhedron's faces (outward), and which cell of the map it is.
pub(crate) struct Written {
    pub(crate) kind: u8,
    pub(crate) conn: Vec<u32>,
    pub(crate) faces: Vec<Vec<u32>>,
    pub(crate) dim: usize,
    pub(crate) cell: usize,
}

impl Written {
    /// The legacy connectivity: the corners, or a polyhedron's face stream
    /// `nFaces, nPts, ids…, …`.
    pub(crate) fn legacy(&self) -> Vec<u32> {
        if self.kind != VTK_POLYHEDRON {
            return self.conn.clone();
        }
        let mut stream = vec![self.faces.len() as u32];
        for f in &self.faces {
            stream.push(f.len() as u32);
            stream.extend(f);
        }
        stream
    }
}

/// The type a label column is written with: the narrowest that holds all its values.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) enum Column {
    /// integers in the range of `i32`, missing `-2147483648`
    Int,
    /// integers beyond it, missing `-9223372036854775808`
    Int64,
    /// reals, or integers mixed with reals, missing `-1.7976931348623157e308`
    Real,
    /// texts (and numbers mixed with texts, in their text form): an `int` column of ranks in
    /// a table of the distinct texts in byte order (missing `-1`), the table written as
    /// dataset field data (see [`text_table`])
    Text,
}

/// A label column over the written cells.
pub(crate) struct LabelColumn {
    pub(crate) name: String,
    pub(crate) col: Column,
    pub(crate) values: Vec<Option<LabelValue>>,
}

impl LabelColumn {
    /// The distinct texts of a text column in byte order, and each cell's rank (`-1`:
    /// missing).
    pub(crate) fn text_ranks(&self) -> (Vec<String>, Vec<i64>) {
        let texts: Vec<Option<String>> = self.values.iter().map(|v| v.as_ref().map(text_of)).collect();
        let mut distinct: Vec<String> = texts.iter().flatten().cloned().collect();
        distinct.sort_unstable();
        distinct.dedup();
        let ranks = texts
            .iter()
            .map(|t| t.as_ref().map_or(-1, |t| distinct.binary_search(t).map_or(-1, |k| k as i64)))
            .collect();
        (distinct, ranks)
    }
}

/// The text form of a value in a text column.
fn text_of(v: &LabelValue) -> String {
    match v {
        LabelValue::Text(s) => s.clone(),
        LabelValue::Int(i) => i.to_string(),
        LabelValue::Real(r) => format!("{r:?}"),
    }
}

/// The name of the field-data array holding the texts of the text column `name`.
pub(crate) fn text_table_name(name: &str) -> String {
    format!("gmap:texts:{name}")
}

/// The bytes of a text table: each text followed by a NUL byte.
pub(crate) fn text_table(texts: &[String]) -> Vec<u8> {
    let mut out = Vec::with_capacity(texts.iter().map(|t| t.len() + 1).sum());
    for t in texts {
        out.extend_from_slice(t.as_bytes());
        out.push(0);
    }
    out
}

/// A map as mesh cells: the points and the cells, the label columns over them.
pub(crate) struct MeshOut {
    pub(crate) dim: usize,
    pub(crate) points: Vec<Point>,
    pub(crate) cells: Vec<Written>,
    /// the number of top cells (they come first)
    pub(crate) top: usize,
    pub(crate) columns: Vec<LabelColumn>,
}

/// The corners (0-cell numbers) of the polygon walked by `alpha_1 alpha_0` from `d`.
fn polygon(map: &DenseMap, vert: &[u32], d: Dart) -> Vec<u32> {
    let mut corners = Vec::new();
    let mut x = d;
    loop {
        corners.push(vert[x.index()]);
        x = map.alpha(map.alpha(x, 0), 1);
        if x == d || corners.len() > map.dart_count() {
            return corners;
        }
    }
}

/// Six times the signed volume enclosed by the faces (each a fan of triangles).
pub(crate) fn signed_volume6(faces: &[Vec<u32>], pts: &[Point]) -> f64 {
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

/// Refuses a face with fewer than three corners or a corner twice, naming the cell.
fn check_face(corners: &[u32], format: &'static str, what: &dyn Fn() -> String) -> Result<(), ExportError> {
    let mut s = corners.to_vec();
    s.sort_unstable();
    s.dedup();
    if corners.len() < 3 || s.len() != corners.len() {
        return Err(ExportError::MeshWrite {
            format,
            reason: format!(
                "{} has a face of {} corners on {} vertices ({:?}); a mesh face needs three distinct corners or more \
                 (a digon or a pinched face, as an edge contraction leaves: remove or contract that face first)",
                what(),
                corners.len(),
                s.len(),
                corners
            ),
        });
    }
    Ok(())
}

/// Every volume of a 3-map as a cell, in the order of `map.cells(3)`: a standard type
/// ([`standard_cell`]) or a polyhedron of outward faces. The faces of a volume are walked
/// from darts of one orientation class and reversed together when its signed volume is
/// negative.
fn volumes(map: &DenseMap, vert: &[u32], pts: &[Point], format: &'static str) -> Result<Vec<Written>, ExportError> {
    let vols = map.cells(3);
    let faces = map.partition(AlphaSet::of(&[0, 1]));
    let mut parity = vec![u8::MAX; map.dart_count()];
    let mut face_done = vec![false; faces.len()];
    let mut out = Vec::with_capacity(vols.len());
    for (c, &r) in vols.reps.iter().enumerate() {
        let mut stack = vec![r];
        parity[r.index()] = 0;
        let mut polys: Vec<Vec<u32>> = Vec::new();
        while let Some(d) = stack.pop() {
            let f = faces.of[d.index()] as usize;
            if parity[d.index()] == 0 && !face_done[f] {
                face_done[f] = true;
                let p = polygon(map, vert, d);
                check_face(&p, format, &|| format!("volume {c}"))?;
                polys.push(p);
            }
            for i in 0..3 {
                let e = map.alpha(d, i);
                if parity[e.index()] == u8::MAX {
                    parity[e.index()] = 1 - parity[d.index()];
                    stack.push(e);
                }
            }
        }
        if signed_volume6(&polys, pts) < 0.0 {
            for p in &mut polys {
                p.reverse();
            }
        }
        out.push(match standard_cell(&polys) {
            Some((kind, conn)) => Written { kind, conn, faces: Vec::new(), dim: 3, cell: c },
            None => {
                let mut conn: Vec<u32> = polys.iter().flatten().copied().collect();
                conn.sort_unstable();
                conn.dedup();
                Written { kind: VTK_POLYHEDRON, conn, faces: polys, dim: 3, cell: c }
            }
        });
    }
    Ok(out)
}

/// The VTK type and corners of a volume whose outward faces make a tetrahedron, a pyramid,
/// a wedge or a hexahedron (checked on the vertex sets of all its faces), in the corner
/// orders of the module documentation. `None` for any other volume. O(faces²).
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
    let faces_are = |want: Vec<Vec<u32>>| -> bool {
        let mut have: Vec<Vec<u32>> = polys.iter().map(|p| set(p)).collect();
        let mut want: Vec<Vec<u32>> = want.iter().map(|w| set(w)).collect();
        have.sort();
        want.sort();
        have == want
    };
    // an outward face turns clockwise seen from the rest of the cell: VTK's base is its
    // reverse
    match (polys.len(), tris.len(), quads.len(), verts.len()) {
        (4, 4, 0, 4) => {
            let (a, b, c) = (tris[0][0], tris[0][1], tris[0][2]);
            let d = *verts.iter().find(|v| !tris[0].contains(v))?;
            faces_are(vec![vec![a, b, c], vec![a, b, d], vec![b, c, d], vec![c, a, d]])
                .then(|| (VTK_TETRA, vec![a, c, b, d]))
        }
        (5, 4, 1, 5) => {
            let q = quads[0];
            let e = *verts.iter().find(|v| !q.contains(v))?;
            let sides = (0..4).map(|j| vec![q[j], q[(j + 1) % 4], e]);
            faces_are(sides.chain([q.clone()]).collect()).then(|| (VTK_PYRAMID, vec![q[0], q[3], q[2], q[1], e]))
        }
        (5, 2, 3, 6) => {
            let t = tris[0];
            let p: Vec<u32> = t.iter().map(|&x| partner(x, t)).collect::<Option<_>>()?;
            let sides = (0..3).map(|j| vec![t[j], t[(j + 1) % 3], p[(j + 1) % 3], p[j]]);
            faces_are(sides.chain([t.clone(), p.clone()]).collect())
                .then(|| (VTK_WEDGE, vec![t[0], t[2], t[1], p[0], p[2], p[1]]))
        }
        (6, 0, 6, 8) => {
            let q = quads[0];
            let p: Vec<u32> = q.iter().map(|&x| partner(x, q)).collect::<Option<_>>()?;
            let sides = (0..4).map(|j| vec![q[j], q[(j + 1) % 4], p[(j + 1) % 4], p[j]]);
            faces_are(sides.chain([q.clone(), p.clone()]).collect())
                .then(|| (VTK_HEXAHEDRON, vec![q[0], q[3], q[2], q[1], p[0], p[3], p[2], p[1]]))
        }
        _ => None,
    }
}

/// The `k`-cells whose number satisfies `keep`, as cells (`k <= 2`; volumes go through
/// [`volumes`]).
fn low_cells(
    map: &DenseMap,
    vert: &[u32],
    k: usize,
    format: &'static str,
    keep: impl Fn(usize) -> bool,
) -> Result<Vec<Written>, ExportError> {
    let reps = if k == 0 { Vec::new() } else { map.cells(k).reps };
    let count = if k == 0 { vert.iter().map(|&v| v as usize + 1).max().unwrap_or(0) } else { reps.len() };
    let mut out = Vec::new();
    for c in (0..count).filter(|&c| keep(c)) {
        out.push(match k {
            0 => Written { kind: VTK_VERTEX, conn: vec![c as u32], faces: Vec::new(), dim: 0, cell: c },
            1 => {
                let d = reps[c];
                let conn = vec![vert[d.index()], vert[map.alpha(d, 0).index()]];
                Written { kind: VTK_LINE, conn, faces: Vec::new(), dim: 1, cell: c }
            }
            _ => {
                let conn = polygon(map, vert, reps[c]);
                check_face(&conn, format, &|| format!("face {c}"))?;
                let kind = match conn.len() {
                    3 => VTK_TRIANGLE,
                    4 => VTK_QUAD,
                    _ => VTK_POLYGON,
                };
                Written { kind, conn, faces: Vec::new(), dim: 2, cell: c }
            }
        });
    }
    Ok(out)
}

/// Refuses two distinct facets of the top cells on the same vertices: a reader would glue
/// them (the facets of a 3-map are its faces, of a 2-map its edges). O(N log N).
fn check_no_slit(map: &DenseMap, vert: &[u32], format: &'static str) -> Result<(), ExportError> {
    let n = map.dim();
    if n < 2 {
        return Ok(());
    }
    let facets = map.cells(n - 1);
    let mut keys: Vec<(Vec<u32>, usize)> = facets
        .reps
        .iter()
        .enumerate()
        .map(|(k, &d)| {
            let mut v: Vec<u32> =
                if n == 3 { polygon(map, vert, d) } else { vec![vert[d.index()], vert[map.alpha(d, 0).index()]] };
            v.sort_unstable();
            v.dedup();
            (v, k)
        })
        .collect();
    keys.sort();
    for w in keys.windows(2) {
        if w[0].0 == w[1].0 {
            let what = if n == 3 { "faces" } else { "edges" };
            return Err(ExportError::MeshWrite {
                format,
                reason: format!(
                    "{what} {} and {} are distinct {}-cells on the same vertices {:?} (a slit: cells unsewn inside \
                     the map); a mesh file glues cells by their vertices, so any reader would glue them again \
                     and lose the slit; write .gmap, which keeps the map as it is",
                    w[0].1,
                    w[1].1,
                    n - 1,
                    w[0].0
                ),
            });
        }
    }
    Ok(())
}

/// The points of the 0-cells, refusing a vertex without a finite point.
fn vertex_points(map: &DenseMap, format: &'static str) -> Result<(Vec<Point>, Vec<u32>), ExportError> {
    let verts = map.cells(0);
    let mut pts: Vec<Point> = Vec::with_capacity(verts.len());
    for r in verts.reps.iter().map(|d| d.get()) {
        let p = map.vertex_point(Dart::new(r)).ok_or(ExportError::VertexPoint { format, dart: r, what: "no point" })?;
        if !p.iter().all(|c| c.is_finite()) {
            return Err(ExportError::VertexPoint { format, dart: r, what: "a point that is not finite" });
        }
        pts.push(p);
    }
    Ok((pts, verts.of))
}

fn column_of(v: &LabelValue) -> Column {
    match v {
        LabelValue::Int(i) if i32::try_from(*i).is_ok() => Column::Int,
        LabelValue::Int(_) => Column::Int64,
        LabelValue::Real(_) => Column::Real,
        LabelValue::Text(_) => Column::Text,
    }
}

/// One column per label name over the written cells, names in order of first appearance.
fn columns(written: &[Written], labels: &DenseLabels, format: &'static str) -> Result<Vec<LabelColumn>, ExportError> {
    let mut names: Vec<(String, Column)> = Vec::new();
    for w in written {
        for (name, v) in labels.get(w.dim, w.cell).iter() {
            let c = column_of(v);
            match names.iter_mut().find(|(n, _)| n == name) {
                Some((_, col)) => *col = (*col).max(c),
                None => names.push((name.to_string(), c)),
            }
        }
    }
    if names.iter().any(|(n, _)| n.is_empty()) {
        return Err(ExportError::EmptyLabelName { format });
    }
    Ok(names
        .into_iter()
        .map(|(name, col)| {
            let values = written.iter().map(|w| labels.get(w.dim, w.cell).get(&name).cloned()).collect();
            LabelColumn { name, col, values }
        })
        .collect())
}

/// A map of dimension at most 3 with points and the labels of its cells as mesh cells (see
/// the module documentation): every top cell, then the cells of each lower dimension (from
/// the highest) that carry a label. O(N log N) plus the cells' faces.
pub(crate) fn mesh_out(map: &DenseMap, labels: &DenseLabels, format: &'static str) -> Result<MeshOut, ExportError> {
    let n = map.dim();
    if n > 3 {
        return Err(ExportError::DimensionAbove { format, max: 3, found: n });
    }
    if map.dart_count() > 0 && !map.has_points() {
        return Err(ExportError::NoPoints { format });
    }
    let (points, vert) = vertex_points(map, format)?;
    let mut cells =
        if n == 3 { volumes(map, &vert, &points, format)? } else { low_cells(map, &vert, n, format, |_| true)? };
    check_no_slit(map, &vert, format)?;
    let top = cells.len();
    for k in (0..n).rev() {
        if labels.of.get(k).is_some_and(|v| v.iter().any(|l| !l.is_empty())) {
            cells.extend(low_cells(map, &vert, k, format, |c| !labels.get(k, c).is_empty())?);
        }
    }
    let columns = columns(&cells, labels, format)?;
    Ok(MeshOut { dim: n, points, cells, top, columns })
}
