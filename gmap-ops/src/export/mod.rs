//! Exporters: `.off` polygon meshes (2-maps with points, [`off_string`], or an editable
//! [`GMap`] directly, [`gmap_off_string`]; the 2-cells of a map of any dimension as a view,
//! [`two_skeleton_off_string`]), `.facets` of the barycentric
//! subdivision (any map), legacy `.vtk` and XML `.vtu` unstructured grids and Gmsh `.msh`
//! meshes (maps of dimension ≤ 3 with points and labels, [`vtk_string`],
//! [`vtu_bytes_with_labels`], [`msh_bytes_with_labels`], each read back before it is
//! written, [`readback`]) and self-contained HTML pages to look at a map in a browser
//! ([`html`]). Every writer goes through a temporary file in the target's
//! directory and a rename, so a failure never leaves a partial file behind. The native
//! `.gmap` and Moka formats are written by `gmap_core::io`.

use std::fmt::Write as _;
use std::path::Path;

use gmap_core::{AlphaSet, Attributes, Dart, DenseMap, GMap, Partition};

mod cells;
mod error;
pub mod html;
mod msh;
pub mod readback;
mod voxels;
mod vtk;
mod vtu;

pub use error::{write_atomic, ExportError};
pub use msh::{msh_bytes_with_labels, write_msh_with_labels};
pub use voxels::{cubical_vtk_string, write_cubical_vtk};
pub use vtk::{vtk_string, vtk_string_with_labels, write_vtk, write_vtk_with_labels};
pub use vtu::{vtu_bytes_with_labels, write_vtu_with_labels};

/// The OFF text of a 2-map with points: one vertex per 0-cell (numbered by its smallest
/// dart), one polygon per 2-cell listing its corners in cycle order (walking
/// `alpha_0 alpha_1` from the face's smallest dart). Faces must be closed polygons (no 0- or
/// 1-free dart), every vertex must carry a finite point, and the text must read back as the
/// same map ([`ExportError::NotAMesh`] otherwise: a monogon or a digon, an edge from a vertex
/// to itself, two edges between the same two vertices). O(N log N).
pub fn off_string(map: &DenseMap) -> Result<String, ExportError> {
    if map.dim() != 2 {
        return Err(ExportError::Dimension { format: ".off", expected: 2, found: map.dim() });
    }
    let (out, order) = off_text(map, &map.cells(2))?;
    same_as_read_back(map, &out, &order)?;
    Ok(out)
}

/// The OFF text of the polygons `faces` (one per class, walked by `alpha_0 alpha_1` from its
/// representative) on the vertices of `map`, and the darts in the order the reader numbers
/// them: per face, per corner, the dart at the corner and its `alpha_0` image at the next
/// corner. Refuses a 0- or 1-free dart and a vertex without a finite point. O(N n).
fn off_text(map: &DenseMap, faces: &Partition) -> Result<(String, Vec<Dart>), ExportError> {
    for d in map.darts() {
        for i in 0..2 {
            if map.is_free(d, i) {
                return Err(ExportError::OpenFace { dart: d.get(), alpha: i });
            }
        }
    }
    let verts = map.cells(0);
    let mut out = String::new();
    let _ = writeln!(out, "OFF\n{} {} 0", verts.len(), faces.len());
    for r in verts.reps.iter().map(|d| d.get()) {
        let p = map.vertex_point(Dart::new(r)).ok_or(ExportError::NoPoint { dart: r })?;
        if !p.iter().all(|c| c.is_finite()) {
            return Err(ExportError::NonFinitePoint { dart: r });
        }
        let _ = writeln!(out, "{} {} {}", p[0], p[1], p[2]);
    }
    let mut order: Vec<Dart> = Vec::with_capacity(map.dart_count());
    for r in faces.reps.iter().map(|d| d.get()) {
        let mut corners = Vec::new();
        let mut d = Dart::new(r);
        loop {
            corners.push(verts.of[d.index()]);
            order.push(d);
            order.push(map.alpha(d, 0));
            d = map.alpha(map.alpha(d, 0), 1);
            if d.get() == r {
                break;
            }
            if corners.len() > map.dart_count() {
                // a face that is not one cycle of alpha_0 alpha_1 (an invalid map)
                return Err(ExportError::NotAMesh { reason: format!("the face of dart {r} is not a cycle") });
            }
        }
        let _ = write!(out, "{}", corners.len());
        for c in corners {
            let _ = write!(out, " {c}");
        }
        out.push('\n');
    }
    Ok((out, order))
}

/// Checks that the `.off` reader makes `text` into `map` again: the reader numbers the darts
/// as `order` lists them and builds `alpha_0` and `alpha_1` from the polygons as the writer
/// walked them, so the map is reproduced exactly when the reader accepts the text (polygons
/// of three corners or more, no edge from a vertex to itself, no edge in three polygons) and
/// glues by `alpha_2` the darts the map glues. Refuses otherwise (a monogon, a digon, two
/// edges between the same two vertices), so the writer never writes a file its reader
/// refuses or reads as another space. O(N log N).
fn same_as_read_back(map: &DenseMap, text: &str, order: &[Dart]) -> Result<(), ExportError> {
    let not_a_mesh = |reason: String| ExportError::NotAMesh { reason };
    let back = crate::import::PolygonMesh::parse(text)
        .and_then(|m| m.to_gmap())
        .map_err(|e| not_a_mesh(format!("its .off would read as: {e}")))?;
    if back.dart_count() != order.len() || order.len() != map.dart_count() {
        return Err(not_a_mesh("its .off would read back with another number of darts".into()));
    }
    let mut new_of = vec![u32::MAX; map.dart_count()];
    for (k, d) in order.iter().enumerate() {
        new_of[d.index()] = k as u32;
    }
    for (k, &d) in order.iter().enumerate() {
        for i in 0..=2 {
            if back.alpha(Dart::new(k as u32), i).get() != new_of[map.alpha(d, i).index()] {
                return Err(not_a_mesh(format!(
                    "its .off would read back glued otherwise along alpha_{i} at dart {d} (two edges \
                     between the same vertices, or an edge of a vertex to itself)"
                )));
            }
        }
    }
    Ok(())
}

/// Writes a 2-map with points as `.off` (see [`off_string`]).
pub fn write_off(map: &DenseMap, path: &Path) -> Result<(), ExportError> {
    write_atomic(path, off_string(map)?.as_bytes())
}

/// The boundary of an n-map (n ≥ 1) as an (n-1)-map: the darts whose `alpha_n` is free, with
/// `alpha_0 … alpha_{n-2}` kept and `alpha_{n-1}` the next boundary dart around the
/// (n-2)-cell (walk `alpha_{n-1} alpha_n` until a free dart), each dart with the point of
/// its vertex. A closed map has an empty boundary. The boundary surface of a 3-map is what
/// `gmap convert --boundary` writes as `.off`. O(N n) plus the walks, O(N · the largest
/// number of n-cells around an (n-2)-cell).
pub fn boundary_map(map: &DenseMap) -> DenseMap {
    let n = map.dim();
    assert!(n >= 1, "the boundary of a 0-map");
    let kept: Vec<Dart> = map.darts().filter(|&d| map.is_free(d, n)).collect();
    let mut new_of = vec![u32::MAX; map.dart_count()];
    for (k, d) in kept.iter().enumerate() {
        new_of[d.index()] = k as u32;
    }
    let mut alpha = Vec::with_capacity(kept.len() * n);
    for &d in &kept {
        for i in 0..n - 1 {
            alpha.push(new_of[map.alpha(d, i).index()]);
        }
        let mut e = map.alpha(d, n - 1);
        while !map.is_free(e, n) {
            e = map.alpha(map.alpha(e, n), n - 1);
        }
        alpha.push(new_of[e.index()]);
    }
    let mut b = DenseMap::from_flat_unchecked(n - 1, alpha).expect("the boundary of a valid map is a valid map");
    if map.has_points() {
        for (k, &d) in kept.iter().enumerate() {
            b.set_point(Dart::new(k as u32), map.vertex_point(d));
        }
    }
    b
}

/// The OFF text of the boundary surface of a 3-map with points ([`boundary_map`], then
/// [`off_string`]: a closed surface that reads back as the same 2-map).
pub fn boundary_off_string(map: &DenseMap) -> Result<String, ExportError> {
    if map.dim() != 3 {
        return Err(ExportError::Dimension { format: ".off of the boundary", expected: 3, found: map.dim() });
    }
    let b = boundary_map(map);
    if b.dart_count() == 0 {
        return Err(ExportError::NotAMesh { reason: "the 3-map is closed: its boundary is empty".into() });
    }
    off_string(&b)
}

/// Writes [`boundary_off_string`] to `path`.
pub fn write_boundary_off(map: &DenseMap, path: &Path) -> Result<(), ExportError> {
    write_atomic(path, boundary_off_string(map)?.as_bytes())
}

/// Checks that every vertex of an editable map has a finite point, naming a dart of the
/// first one that has not. O(N).
fn check_gmap_points<A: Attributes>(g: &GMap<A>) -> Result<(), ExportError> {
    for d in g.darts() {
        match g.point(d) {
            None => return Err(ExportError::VertexOfDart { dart: d, what: "no point" }),
            Some(p) if !p.iter().all(|c| c.is_finite()) => {
                return Err(ExportError::VertexOfDart { dart: d, what: "a point that is not finite" })
            }
            Some(_) => {}
        }
    }
    Ok(())
}

/// The OFF text of an editable 2-map with points: [`off_string`] of its snapshot
/// ([`GMap::to_dense_map`]), with the same checks, the read-back included. A vertex without a
/// finite point is refused with [`ExportError::VertexOfDart`], naming a dart of the map;
/// other errors name snapshot darts (dart `k` is the `k`-th of [`GMap::darts`]).
/// O(N log N).
///
/// ```
/// use gmap_core::GMap;
/// let mut g = GMap::new(2);
/// g.make_quadrangle([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]);
/// let text = gmap_ops::export::gmap_off_string(&g).unwrap();
/// assert_eq!(text.lines().nth(1), Some("4 1 0"));
/// ```
pub fn gmap_off_string<A: Attributes>(g: &GMap<A>) -> Result<String, ExportError> {
    if g.dim() != 2 {
        return Err(ExportError::Dimension { format: ".off", expected: 2, found: g.dim() });
    }
    check_gmap_points(g)?;
    off_string(&g.to_dense_map())
}

/// Writes an editable 2-map with points as `.off` (see [`gmap_off_string`]).
pub fn write_gmap_off<A: Attributes>(g: &GMap<A>, path: &Path) -> Result<(), ExportError> {
    write_atomic(path, gmap_off_string(g)?.as_bytes())
}

/// A *view* of a map of dimension `n >= 2` as a polygon soup, not a conversion: the OFF text
/// of its 2-skeleton, one vertex per 0-cell and one polygon per 2-cell (whatever the
/// dimension, inner faces of a 3-map included, each once), its corners in the cycle order of
/// `alpha_0 alpha_1` from the face's smallest dart. Reading it back gives a surface, which in
/// general has neither the dimension nor the homology of the map: this is for looking at the
/// faces, and `gmap convert` never uses it. For a 2-map it is the text of [`off_string`]
/// without the read-back check.
///
/// Errors: dimension below 2 ([`ExportError::DimensionBelow`]), a 0- or 1-free dart
/// ([`ExportError::OpenFace`]), a vertex without a finite point ([`ExportError::NoPoint`],
/// [`ExportError::NonFinitePoint`]), a face that is not one cycle (only in an invalid map,
/// [`ExportError::NotAMesh`]). O(N n).
pub fn two_skeleton_off_string(map: &DenseMap) -> Result<String, ExportError> {
    if map.dim() < 2 {
        return Err(ExportError::DimensionBelow { format: ".off of the 2-skeleton", min: 2, found: map.dim() });
    }
    Ok(off_text(map, &map.partition(AlphaSet::cell(2, map.dim())))?.0)
}

/// [`two_skeleton_off_string`] of an editable map: its snapshot's, a vertex without a finite
/// point refused with [`ExportError::VertexOfDart`] naming a dart of the map. O(N n).
///
/// ```
/// use gmap_core::GMap;
/// let mut g = GMap::new(3);
/// let p = [[0., 0., 0.], [1., 0., 0.], [1., 1., 0.], [0., 1., 0.],
///          [0., 1., 1.], [0., 0., 1.], [1., 0., 1.], [1., 1., 1.]];
/// g.make_hexahedron(p);
/// let text = gmap_ops::export::gmap_two_skeleton_off_string(&g).unwrap();
/// assert_eq!(text.lines().nth(1), Some("8 6 0"));
/// ```
pub fn gmap_two_skeleton_off_string<A: Attributes>(g: &GMap<A>) -> Result<String, ExportError> {
    if g.dim() < 2 {
        return Err(ExportError::DimensionBelow { format: ".off of the 2-skeleton", min: 2, found: g.dim() });
    }
    check_gmap_points(g)?;
    two_skeleton_off_string(&g.to_dense_map())
}

/// Writes the 2-skeleton of a map as `.off` (see [`two_skeleton_off_string`]).
pub fn write_two_skeleton_off(map: &DenseMap, path: &Path) -> Result<(), ExportError> {
    write_atomic(path, two_skeleton_off_string(map)?.as_bytes())
}

/// The largest dimension [`barycentric_facets_string`] handles: its check visits the
/// `2^(n+1)` faces of a flag, and a read-back of an n-simplex takes `(n + 1)!` darts.
pub const MAX_FACETS_DIM: usize = 8;

/// The faces of the simplices of the barycentric subdivision spanned by the vertices of the
/// dimensions in `s` (bit `i` for the i-cell; `s` nonempty): the face of dart `d`'s simplex
/// is the orbit of `d` under the involutions not in `s`.
fn faces_of(map: &DenseMap, s: usize) -> Partition {
    let n = map.dim();
    map.partition(AlphaSet::of(&(0..=n).filter(|&i| s & (1 << i) == 0).collect::<Vec<_>>()))
}

/// [`faces_of`] for every subset, indexed by subset (entry 0 empty).
fn faces(map: &DenseMap) -> Vec<Partition> {
    let all = (1usize << (map.dim() + 1)) - 1;
    (0..=all).map(|s| if s == 0 { Partition { of: Vec::new(), reps: Vec::new() } } else { faces_of(map, s) }).collect()
}

/// Whether the barycentric subdivision (one simplex per dart, vertex i of dart `d` its
/// i-cell) is a simplicial complex: every face, of every dimension, is the only one with its
/// vertex labels. Fails on maps whose cells are not embedded (a loop edge, a monogon, a torus
/// of one square, a lens space): two darts or two faces with the same cells.
/// The faces are computed one subset at a time (the cells are `cells[i]`), so the check takes
/// O(N) memory whatever the dimension.
fn first_subdivision_is_simplicial(map: &DenseMap, cells: &[Partition]) -> bool {
    let n = map.dim();
    for s in 1..(1usize << (n + 1)) {
        let dims: Vec<usize> = (0..=n).filter(|&i| s & (1 << i) != 0).collect();
        if dims.len() == 1 {
            continue;
        }
        let part = faces_of(map, s);
        let mut keys: Vec<Vec<u32>> =
            part.reps.iter().map(|&d| dims.iter().map(|&i| cells[i].of[d.index()]).collect()).collect();
        keys.sort_unstable();
        if keys.windows(2).any(|w| w[0] == w[1]) {
            return false;
        }
    }
    true
}

/// The `.facets` text of a map's space as a simplicial complex, or why it has none.
///
/// The barycentric subdivision of a map has one n-simplex per dart, whose vertices are the
/// dart's 0-cell, 1-cell, …, n-cell, labelled by cell (`offset_i + k` for the k-th i-cell,
/// `offset_i` the number of cells of lower dimension). It is a simplicial complex of the same
/// space only when no two of its faces have the same vertices: true of a regular complex (a
/// cube, anything imported from `.facets`), false of a monogon, a torus of one square or a
/// lens space, where two darts can have the same cells. This is checked on every face; where
/// it fails, the text is the *second* barycentric subdivision, which is always a simplicial
/// complex: one facet per dart and ordering of `0..=n`, whose vertices are the faces of the
/// dart's simplex along the chain (the face spanned by the cells of the first k dimensions of
/// the ordering, `k = 1..=n+1`), labelled by face. So reading the text back gives a map of the
/// same space (the homology of the map's simplicial counterpart, BO §6), `(n + 1)!` times
/// bigger when the second subdivision is needed.
///
/// A first comment line says which subdivision was written. Errors: a dimension above
/// [`MAX_FACETS_DIM`] ([`ExportError::Dimension`]), a map without darts
/// ([`ExportError::Empty`]). O(2^(n+1) N n) for the check, plus the output.
pub fn barycentric_facets_string(map: &DenseMap) -> Result<String, ExportError> {
    let n = map.dim();
    if n > MAX_FACETS_DIM {
        return Err(ExportError::DimensionAbove { format: ".facets", max: MAX_FACETS_DIM, found: n });
    }
    if map.is_empty() {
        return Err(ExportError::Empty);
    }
    let cells: Vec<Partition> = (0..=n).map(|i| faces_of(map, 1 << i)).collect();
    if first_subdivision_is_simplicial(map, &cells) {
        let mut offsets = vec![0u64; n + 1];
        for i in 1..=n {
            offsets[i] = offsets[i - 1] + cells[i - 1].len() as u64;
        }
        let mut out = String::with_capacity(map.dart_count() * (n + 1) * 6);
        let _ = writeln!(
            out,
            "# barycentric subdivision of a {n}-map: one simplex per dart, vertex = (dimension offset) + cell"
        );
        for d in 0..map.dart_count() {
            for i in 0..=n {
                if i > 0 {
                    out.push(' ');
                }
                let _ = write!(out, "{}", offsets[i] + cells[i].of[d] as u64);
            }
            out.push('\n');
        }
        return Ok(out);
    }
    // the second subdivision: vertices are the faces (subset s, orbit), numbered by subset
    drop(cells);
    let faces = faces(map);
    let mut offsets = vec![0u64; faces.len()];
    for s in 1..faces.len() {
        offsets[s] = offsets[s - 1] + faces[s - 1].len() as u64;
    }
    let orderings = crate::perm::PermTable::try_new(n + 1).ok_or(ExportError::TooLarge { facets: usize::MAX })?;
    let lines = map.dart_count().saturating_mul(orderings.len());
    let mut out = String::new();
    out.try_reserve(lines.saturating_mul((n + 1) * 6)).map_err(|_| ExportError::TooLarge { facets: lines })?;
    let _ = writeln!(
        out,
        "# second barycentric subdivision of a {n}-map (the first is not a simplicial complex): \
         one simplex per dart and ordering of its cells"
    );
    for d in 0..map.dart_count() {
        for p in 0..orderings.len() {
            let mut s = 0usize;
            for (k, &i) in orderings.perm(p).iter().enumerate() {
                s |= 1 << i;
                if k > 0 {
                    out.push(' ');
                }
                let _ = write!(out, "{}", offsets[s] + faces[s].of[d] as u64);
            }
            out.push('\n');
        }
    }
    Ok(out)
}

/// Writes the `.facets` of a map (see [`barycentric_facets_string`]); nothing is written
/// when the map is refused.
pub fn write_barycentric_facets(map: &DenseMap, path: &Path) -> Result<(), ExportError> {
    write_atomic(path, barycentric_facets_string(map)?.as_bytes())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::build;

    #[test]
    fn off_of_a_square() {
        let sq = build::polygon(4).unwrap();
        let text = off_string(&sq).unwrap();
        assert!(text.starts_with("OFF\n4 1 0\n1 0 0\n"), "{text}");
        assert!(text.ends_with("4 0 1 2 3\n"), "{text}");
        let square = crate::build::placed::grid_with_points(&[1, 1], &[false, false]).unwrap();
        assert_eq!(off_string(&square).unwrap().lines().nth(1), Some("4 1 0"));
        let torus = build::schema("a b A B").unwrap();
        assert!(matches!(off_string(&torus), Err(ExportError::NoPoint { dart: 0 })));
        assert!(matches!(off_string(&build::cube(3).unwrap()), Err(ExportError::Dimension { .. })));
    }

    #[test]
    fn off_of_an_editable_map() {
        let mut g = GMap::new(2);
        let d = g.make_polygon(&[[0.0, 0.0], [2.0, 0.0], [1.0, 1.0]]);
        let text = gmap_off_string(&g).unwrap();
        assert_eq!(text, "OFF\n3 1 0\n0 0 0\n2 0 0\n1 1 0\n3 0 1 2\n");
        assert_eq!(text, off_string(&g.to_dense_map()).unwrap());
        // a vertex without a point is named by its dart
        g.set_point(d, None);
        assert!(matches!(gmap_off_string(&g), Err(ExportError::VertexOfDart { dart, what: "no point" }) if dart == d));
        g.set_point(d, Some([f64::NAN, 0.0, 0.0]));
        assert!(matches!(gmap_off_string(&g), Err(ExportError::VertexOfDart { dart, .. }) if dart == d));
        // a 3-map is not a 2-map
        let mut h = GMap::new(3);
        h.make_combinatorial_tetrahedron();
        assert!(matches!(gmap_off_string(&h), Err(ExportError::Dimension { expected: 2, found: 3, .. })));
    }

    #[test]
    fn the_two_skeleton_lists_every_face_once() {
        // two unit cubes sharing a face
        let (g, _) = GMap::from_dense(&crate::build::placed::grid_with_points(&[2, 1, 1], &[false; 3]).unwrap());
        assert_eq!(g.characteristics().cells, vec![12, 20, 11, 2]);
        let text = gmap_two_skeleton_off_string(&g).unwrap();
        let mut lines = text.lines();
        assert_eq!(lines.nth(1), Some("12 11 0"));
        let polygons: Vec<&str> = text.lines().skip(2 + 12).collect();
        assert_eq!(polygons.len(), 11);
        assert!(polygons.iter().all(|l| l.starts_with("4 ")));
        // the points are the twelve corners of the two cubes, each once
        let mut pts: Vec<&str> = text.lines().skip(2).take(12).collect();
        pts.sort();
        pts.dedup();
        assert_eq!(pts.len(), 12);
        // the same as the text of the 2-map writer on a 2-map
        let sq = build::polygon(4).unwrap();
        assert_eq!(two_skeleton_off_string(&sq).unwrap(), off_string(&sq).unwrap());
        assert!(matches!(
            two_skeleton_off_string(&build::simplex(1).unwrap()),
            Err(ExportError::DimensionBelow { min: 2, found: 1, .. })
        ));
        assert!(matches!(two_skeleton_off_string(&build::cube(3).unwrap()), Err(ExportError::NoPoint { .. })));
        let mut h = GMap::new(3);
        let t = h.make_combinatorial_tetrahedron();
        assert!(matches!(gmap_two_skeleton_off_string(&h), Err(ExportError::VertexOfDart { .. })));
        assert!(h.contains(t));
    }

    #[test]
    fn barycentric_of_an_edge() {
        let e = build::simplex(1).unwrap();
        assert_eq!(barycentric_facets_string(&e).unwrap().lines().skip(1).collect::<Vec<_>>(), vec!["0 2", "1 2"]);
    }

    #[test]
    fn atomic_write_leaves_no_temporary() {
        let dir = std::env::temp_dir().join(format!("gmap-ops-export-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let p = dir.join("x.facets");
        write_barycentric_facets(&build::simplex(2).unwrap(), &p).unwrap();
        let names: Vec<_> = std::fs::read_dir(&dir).unwrap().map(|e| e.unwrap().file_name()).collect();
        assert_eq!(names.len(), 1);
        assert_eq!(std::fs::read_to_string(&p).unwrap().lines().count(), 7);
        assert!(write_atomic(&dir.join("no/such/dir/x"), b"x").is_err());
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
