//! The map of a mesh whose top cells are volumes of the fixed kinds (tetrahedra, hexahedra,
//! wedges, pyramids), written directly: the darts of every cell laid out by its kind's
//! template, faces matched by sorting their keys, and the points given in bulk.
//!
//! Inside a cell of a fixed kind, `alpha_0`, `alpha_1` and `alpha_2` follow a pattern that
//! depends on the kind alone: the [`Template`], made once per kind from
//! [`CellKind::faces`] as [`crate::build::IncrementalBuilder`] makes a surface (face `f`
//! of `k` corners takes `2k` consecutive darts, dart `2j` at corner `j` towards corner
//! `j + 1`, dart `2j + 1` at corner `j + 1` towards corner `j`; faces in the kind's order).
//! A cell's darts are its template's, shifted: the same darts, in the same order, as the
//! builder's, so the map is the one the builder makes, dart for dart.
//!
//! Faces across cells are matched by one sort of their keys (the sorted vertex ids, padded
//! to four, with the face's cell and number), then one scan of the runs of equal keys: a
//! face alone is on the boundary, two are 3-sewn at equal vertices (whatever their
//! orientations), three or more are refused. The refusals are those the builder's hash
//! map gives, and the first of them in the builder's order (cells in order, faces in the
//! kind's order) is the one reported: the error of a run arises at its second face (two
//! cycles on the same vertices that are not the same cycle) or at its third. Then the
//! involutions are checked for pinched points and edges on the dense rows, become the
//! darts of the map in one pass ([`gmap_core::GMap::from_dense_rows`]), and the points
//! are set by one id per dart ([`gmap_core::GMap::set_points_by_ids`]).
//!
//! Memory beyond the map: the dense rows (16 bytes a dart), the vertex of every dart (4),
//! the face keys (24 bytes a face, 4 bytes a dart for tetrahedra) and the partitions of the
//! pinch check (4 bytes a dart, one at a time). Time: linear in the darts but for the sort
//! of the faces (O(F log F)).

use std::sync::OnceLock;

use gmap_core::{DenseMap, LabelledGMap};
use smallvec::SmallVec;

use super::cells::{check_pinched, CellKind, Mesh};
use super::error::MeshError;
use super::matching::{align, check_conforming_faces, FaceRecord};

/// The darts of one cell of a fixed kind, by their number in the cell.
pub(crate) struct Template {
    /// `alpha_0`, `alpha_1`, `alpha_2` of each dart, inside the cell
    pub alpha: Vec<[u8; 3]>,
    /// the corner of each dart
    pub corner: Vec<u8>,
    /// each face: its first dart and its corners in the kind's order
    pub faces: Vec<(u8, SmallVec<[u8; 4]>)>,
}

impl Template {
    fn of(kind: CellKind) -> Template {
        let faces = kind.faces();
        let mut alpha: Vec<[u8; 3]> = Vec::new();
        let mut corner: Vec<u8> = Vec::new();
        let mut out = Vec::new();
        // the corner of each dart and the other end of its edge, to pair darts by alpha_2
        let mut ends: Vec<(u8, u8)> = Vec::new();
        for f in faces {
            let k = f.len();
            let o = alpha.len();
            out.push((o as u8, f.iter().map(|&c| c as u8).collect()));
            for j in 0..2 * k {
                let (a0, a1) = if j % 2 == 0 { (j + 1, (j + 2 * k - 1) % (2 * k)) } else { (j - 1, (j + 1) % (2 * k)) };
                alpha.push([(o + a0) as u8, (o + a1) as u8, 0]);
                let here = f[j.div_ceil(2) % k];
                let there = if j % 2 == 0 { f[(j / 2 + 1) % k] } else { f[j / 2] };
                corner.push(here as u8);
                ends.push((here as u8, there as u8));
            }
        }
        for d in 0..alpha.len() {
            let e = (0..alpha.len()).find(|&e| e != d && ends[e] == ends[d]).expect("every edge lies in two faces");
            alpha[d][2] = e as u8;
        }
        Template { alpha, corner, faces: out }
    }

    /// The template of a fixed volume kind (made once), `None` for other kinds.
    pub(crate) fn get(kind: CellKind) -> Option<&'static Template> {
        static T: [OnceLock<Template>; 4] = [OnceLock::new(), OnceLock::new(), OnceLock::new(), OnceLock::new()];
        let k = match kind {
            CellKind::Tetra => 0,
            CellKind::Hexahedron => 1,
            CellKind::Wedge => 2,
            CellKind::Pyramid => 3,
            _ => return None,
        };
        Some(T[k].get_or_init(|| Template::of(kind)))
    }
}

/// One face of a top cell in the sorted table.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) struct Face {
    /// its sorted vertex ids, `u32::MAX` after the last
    pub key: [u32; 4],
    /// the top cell (its number among the top cells)
    pub cell: u32,
    /// the face's number in its cell's kind
    pub face: u32,
}

/// What [`build`] makes: the map and what labelling it needs.
pub(crate) struct Built {
    /// the map, with its points
    pub map: LabelledGMap,
    /// the vertex of each dart, by dart index (`u32::MAX` at index 0)
    pub vertex: Vec<u32>,
    /// the index of the first dart of each top cell
    pub first: Vec<u32>,
    /// the faces of the top cells, sorted by key
    pub faces: Vec<Face>,
}

/// The face of the top cells on these vertices (any order): its cycle and the index of
/// its dart at corner 0 towards corner 1. O(log F).
pub(crate) fn face(
    mesh: &Mesh,
    tops: &[usize],
    first: &[u32],
    faces: &[Face],
    vertices: &[u32],
) -> Option<(SmallVec<[u32; 4]>, usize)> {
    let key = key_of(vertices)?;
    let at = faces.partition_point(|f| f.key < key);
    let f = faces.get(at).filter(|f| f.key == key)?;
    let t = Template::get(mesh.cells[tops[f.cell as usize]].kind)?;
    Some((cycle(mesh, tops, f), first[f.cell as usize] as usize + t.faces[f.face as usize].0 as usize))
}

/// The key of a face of 3 or 4 vertices, `None` for other sizes.
fn key_of(vertices: &[u32]) -> Option<[u32; 4]> {
    if !(3..=4).contains(&vertices.len()) {
        return None;
    }
    let mut key = [u32::MAX; 4];
    key[..vertices.len()].copy_from_slice(vertices);
    key.sort_unstable();
    Some(key)
}

fn cycle(mesh: &Mesh, tops: &[usize], f: &Face) -> SmallVec<[u32; 4]> {
    let c = &mesh.cells[tops[f.cell as usize]];
    let t = Template::get(c.kind).expect("a fixed kind");
    t.faces[f.face as usize].1.iter().map(|&k| c.nodes[k as usize]).collect()
}

/// Whether every top cell (`tops`, volumes) is of a fixed kind.
pub(crate) fn applies(mesh: &Mesh, tops: &[usize]) -> bool {
    tops.iter().all(|&i| Template::get(mesh.cells[i].kind).is_some())
}

/// Builds the map of the top cells `tops` of `mesh` (volumes of fixed kinds, checked by
/// [`Mesh::check_cells`]; at most `u32::MAX - 1` darts, checked by the caller), see the
/// module documentation. Errors name the cells by their index among `tops`.
pub(crate) fn build(mesh: &Mesh, tops: &[usize]) -> Result<Built, MeshError> {
    let templates: Vec<&Template> =
        tops.iter().map(|&i| Template::get(mesh.cells[i].kind).expect("checked by applies")).collect();
    let mut first = Vec::with_capacity(tops.len());
    let mut n = 0usize;
    let mut face_count = 0usize;
    for t in &templates {
        first.push(1 + n as u32);
        n += t.alpha.len();
        face_count += t.faces.len();
    }
    // the dense rows (dart `d` of the map is dense dart `d - 1`) and the vertex of each dart
    let mut alpha: Vec<u32> = Vec::with_capacity(4 * n);
    let mut vertex: Vec<u32> = Vec::with_capacity(n + 1);
    vertex.push(u32::MAX);
    let mut faces: Vec<Face> = Vec::with_capacity(face_count);
    for (c, (&i, t)) in tops.iter().zip(&templates).enumerate() {
        let nodes = &mesh.cells[i].nodes;
        let o = first[c] - 1;
        for (l, a) in t.alpha.iter().enumerate() {
            alpha.extend([o + a[0] as u32, o + a[1] as u32, o + a[2] as u32, o + l as u32]);
            vertex.push(nodes[t.corner[l] as usize]);
        }
        for (f, (_, corners)) in t.faces.iter().enumerate() {
            let mut key = [u32::MAX; 4];
            for (k, &x) in key.iter_mut().zip(corners) {
                *k = nodes[x as usize];
            }
            key.sort_unstable();
            faces.push(Face { key, cell: c as u32, face: f as u32 });
        }
    }
    faces.sort_unstable();
    // the darts of a face: at corner j, towards j + 1 (fwd) and towards j - 1 (back)
    let fwd = |f: &Face, j: usize| -> u32 {
        let (o, ref corners) = templates[f.cell as usize].faces[f.face as usize];
        let _ = corners;
        first[f.cell as usize] - 1 + o as u32 + 2 * j as u32
    };
    let back = |f: &Face, j: usize| -> u32 {
        let (o, ref corners) = templates[f.cell as usize].faces[f.face as usize];
        let k = corners.len();
        first[f.cell as usize] - 1 + o as u32 + ((2 * j + 2 * k - 1) % (2 * k)) as u32
    };
    // the first refusal in the builder's order: (the face where it arises, the error)
    let mut refusal: Option<((u32, u32), MeshError)> = None;
    let mut keep = |at: (u32, u32), e: MeshError| {
        if refusal.as_ref().is_none_or(|(r, _)| at < *r) {
            refusal = Some((at, e));
        }
    };
    let mut s = 0;
    while s < faces.len() {
        let mut e = s + 1;
        while e < faces.len() && faces[e].key == faces[s].key {
            e += 1;
        }
        if e - s >= 2 {
            let (a, b) = (&faces[s], &faces[s + 1]);
            let (ca, cb) = (cycle(mesh, tops, a), cycle(mesh, tops, b));
            match align(&ca, &cb) {
                None => keep(
                    (b.cell, b.face),
                    MeshError::FacetOrder {
                        cells: [a.cell as usize, b.cell as usize],
                        first: ca.iter().map(|&v| v as u64).collect(),
                        second: cb.iter().map(|&v| v as u64).collect(),
                    },
                ),
                Some(_) if e - s >= 3 => {
                    let c = &faces[s + 2];
                    keep(
                        (c.cell, c.face),
                        MeshError::FacetInManyCells {
                            dim: 3,
                            vertices: a.key.iter().filter(|&&v| v != u32::MAX).map(|&v| v as u64).collect(),
                            cells: vec![a.cell as usize, b.cell as usize, c.cell as usize],
                        },
                    )
                }
                Some((r, reversed)) => {
                    let k = ca.len();
                    for j in 0..k {
                        let p = if reversed { (r + k - j) % k } else { (r + j) % k };
                        let (x, y) = if reversed { (back(b, p), fwd(b, p)) } else { (fwd(b, p), back(b, p)) };
                        for (u, v) in [(fwd(a, j), x), (back(a, j), y)] {
                            alpha[4 * u as usize + 3] = v;
                            alpha[4 * v as usize + 3] = u;
                        }
                    }
                }
            }
        }
        s = e;
    }
    if let Some((_, e)) = refusal {
        return Err(e);
    }
    if faces.iter().any(|f| f.key[3] != u32::MAX) {
        let mut records: Vec<FaceRecord> = Vec::new();
        let mut s = 0;
        while s < faces.len() {
            let second = faces.get(s + 1).filter(|g| g.key == faces[s].key);
            records.push(FaceRecord {
                cycle: cycle(mesh, tops, &faces[s]),
                owner: faces[s].cell as usize,
                second: second.map(|g| g.cell as usize),
            });
            s += if second.is_some() { 2 } else { 1 };
        }
        check_conforming_faces(&records)?;
    }
    let dense = DenseMap::from_flat_unchecked(3, alpha).map_err(|e| MeshError::Map(e.to_string()))?;
    check_pinched(&dense, &vertex[1..], 3)?;
    let mut map = LabelledGMap::from_dense_rows(&dense);
    drop(dense);
    map.set_points_by_ids(&vertex, &mesh.points).map_err(|e| MeshError::Map(e.to_string()))?;
    Ok(Built { map, vertex, first, faces })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn templates_are_closed_surfaces() {
        // every dart has three distinct partners, alpha_0 alpha_2 is an involution, and the
        // numbers of darts are 2 x (sum of the face sizes)
        for (kind, darts) in
            [(CellKind::Tetra, 24), (CellKind::Hexahedron, 48), (CellKind::Wedge, 36), (CellKind::Pyramid, 32)]
        {
            let t = Template::get(kind).unwrap();
            assert_eq!(t.alpha.len(), darts, "{kind}");
            for d in 0..darts {
                for i in 0..3 {
                    let e = t.alpha[d][i] as usize;
                    assert_ne!(e, d);
                    assert_eq!(t.alpha[e][i] as usize, d);
                }
                let x = t.alpha[t.alpha[d][0] as usize][2] as usize;
                assert_eq!(t.alpha[t.alpha[x][0] as usize][2] as usize, d, "{kind}: alpha_0 alpha_2 at {d}");
                // alpha_1 and alpha_2 keep the corner, alpha_0 changes it
                assert_eq!(t.corner[t.alpha[d][1] as usize], t.corner[d]);
                assert_eq!(t.corner[t.alpha[d][2] as usize], t.corner[d]);
                assert_ne!(t.corner[t.alpha[d][0] as usize], t.corner[d]);
            }
        }
        assert!(Template::get(CellKind::Polyhedron).is_none());
        assert_eq!(key_of(&[5, 2, 9]), Some([2, 5, 9, u32::MAX]));
        assert_eq!(key_of(&[5, 2]), None);
    }
}
