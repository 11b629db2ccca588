//! [`Surface`]: the vertices, edges and faces of a 2-map as a graph with faces, the input
//! of the cycle searches; and its radial graph (vertices and faces joined at corners), on
//! which the edge width is twice the face width.

use gmap_core::{AlphaSet, Dart, DenseMap, Partition};

use crate::curves::error::CurveError;
use crate::curves::tree::{Graph, NONE};

/// How the edges of a surface are weighted.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum Weights {
    /// every edge has length 1: lengths count edges
    Unit,
    /// the Euclidean distance between the points of the edge's ends (every vertex needs a
    /// point)
    Length,
    /// one weight per edge, in the order of the edges (their smallest darts)
    PerEdge(Vec<f64>),
}

/// A 2-map seen as a graph with faces. Vertices, edges and faces are numbered as the
/// orbit partitions of the map number them (by their smallest dart). Each face lists its
/// sides (an edge once per side: twice when the face runs along both sides of it); each
/// edge has one side (on the boundary) or two.
#[derive(Clone, Debug)]
pub struct Surface {
    /// the graph of vertices and edges, with weights
    pub graph: Graph,
    /// `face_start[f]..face_start[f + 1]` indexes the sides of face `f` in `face_sides`
    pub face_start: Vec<usize>,
    /// the edge of each side
    pub face_sides: Vec<u32>,
    /// the faces on the sides of each edge (`NONE` for the second side of a boundary edge)
    pub edge_faces: Vec<[u32; 2]>,
    /// a dart of each vertex, edge and face (the smallest)
    pub reps: [Vec<Dart>; 3],
}

impl Surface {
    /// The surface of a 2-map. Refuses maps of another dimension, invalid maps and maps
    /// with a dart free for `alpha_0` or `alpha_1` (naming it); `alpha_2`-free darts are
    /// the boundary. O(N).
    pub fn of_map(map: &DenseMap, weights: &Weights) -> Result<Self, CurveError> {
        check_surface(map)?;
        let v = map.cells(0);
        let e = map.cells(1);
        let f = map.cells(2);
        let ends: Vec<(u32, u32)> = e.reps.iter().map(|&r| (v.of[r.index()], v.of[map.alpha(r, 0).index()])).collect();
        let w = edge_weights(map, &e, &ends, weights)?;
        let graph = Graph::try_new(v.len(), ends, w)?;
        // one side per alpha_0-pair {d, alpha_0 d}, found at its smaller dart
        let mut edge_faces = vec![[NONE; 2]; e.len()];
        let mut per_face: Vec<Vec<u32>> = vec![Vec::new(); f.len()];
        for d in map.darts() {
            if map.alpha(d, 0) < d {
                continue;
            }
            let (edge, face) = (e.of[d.index()], f.of[d.index()]);
            let slot = &mut edge_faces[edge as usize];
            slot[usize::from(slot[0] != NONE)] = face;
            per_face[face as usize].push(edge);
        }
        let (face_start, face_sides) = csr(per_face);
        Ok(Surface { graph, face_start, face_sides, edge_faces, reps: [v.reps, e.reps, f.reps] })
    }

    /// The radial graph of a closed surface: a vertex per vertex (first) and per face
    /// (after them), an edge per corner (a vertex–face incidence, an `alpha_1`-pair of
    /// darts) of weight 1, a quadrilateral face per edge. A closed curve meeting k faces of
    /// the surface and no edge is homotopic to a cycle of 2k radial edges, and back.
    /// Refuses a surface with boundary, naming a boundary edge. O(N).
    pub fn radial(map: &DenseMap) -> Result<(Self, Partition), CurveError> {
        check_surface(map)?;
        if let Some(d) = map.darts().find(|&d| map.is_free(d, 2)) {
            let e = map.cells(1);
            let edge = e.of[d.index()];
            return Err(CurveError::Boundary { what: "the face width", edge, dart: e.reps[edge as usize].get() });
        }
        let v = map.cells(0);
        let f = map.cells(2);
        let corners = map.partition(AlphaSet::single(1));
        let nv = v.len() as u32;
        let ends: Vec<(u32, u32)> = corners.reps.iter().map(|&r| (v.of[r.index()], nv + f.of[r.index()])).collect();
        let unit = vec![1.0; ends.len()];
        let graph = Graph::try_new(v.len() + f.len(), ends, unit)?;
        let e = map.cells(1);
        let mut edge_faces = vec![[NONE; 2]; corners.len()];
        let mut per_face = Vec::with_capacity(e.len());
        for (q, &r) in e.reps.iter().enumerate() {
            let darts = [r, map.alpha(r, 0), map.alpha(map.alpha(r, 0), 2), map.alpha(r, 2)];
            let sides: Vec<u32> = darts.iter().map(|d| corners.of[d.index()]).collect();
            for &c in &sides {
                let slot = &mut edge_faces[c as usize];
                slot[usize::from(slot[0] != NONE)] = q as u32;
            }
            per_face.push(sides);
        }
        let (face_start, face_sides) = csr(per_face);
        let mut vreps = v.reps;
        vreps.extend(f.reps.iter().copied());
        let s = Surface { graph, face_start, face_sides, edge_faces, reps: [vreps, corners.reps.clone(), e.reps] };
        Ok((s, corners))
    }

    /// The number of faces.
    pub fn face_count(&self) -> usize {
        self.face_start.len() - 1
    }

    /// The edges on the sides of face `f`.
    pub fn sides(&self, f: u32) -> &[u32] {
        &self.face_sides[self.face_start[f as usize]..self.face_start[f as usize + 1]]
    }

    /// Whether edge `e` is on the boundary (one side only).
    pub fn is_boundary_edge(&self, e: u32) -> bool {
        self.edge_faces[e as usize][1] == NONE
    }
}

/// Refuses what is not a valid 2-map without `alpha_0`- or `alpha_1`-free darts.
pub fn check_surface(map: &DenseMap) -> Result<(), CurveError> {
    if map.dim() != 2 {
        return Err(CurveError::NotTwoMap { dim: map.dim() });
    }
    map.validate().map_err(|e| CurveError::Invalid { reason: e.to_string() })?;
    for d in map.darts() {
        for i in 0..2 {
            if map.is_free(d, i) {
                return Err(CurveError::OpenCell { dart: d.get(), i });
            }
        }
    }
    Ok(())
}

/// The weight of each edge.
fn edge_weights(map: &DenseMap, e: &Partition, ends: &[(u32, u32)], w: &Weights) -> Result<Vec<f64>, CurveError> {
    match w {
        Weights::Unit => Ok(vec![1.0; ends.len()]),
        Weights::PerEdge(v) => Ok(v.clone()),
        Weights::Length => e
            .reps
            .iter()
            .enumerate()
            .map(|(k, &r)| {
                let other = map.alpha(r, 0);
                let point = |d: Dart| map.vertex_point(d).ok_or(CurveError::NoPoint { edge: k as u32, dart: d.get() });
                let (p, q) = (point(r)?, point(other)?);
                Ok(((p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2) + (p[2] - q[2]).powi(2)).sqrt())
            })
            .collect(),
    }
}

/// Lists as a CSR table.
fn csr(lists: Vec<Vec<u32>>) -> (Vec<usize>, Vec<u32>) {
    let mut start = Vec::with_capacity(lists.len() + 1);
    start.push(0);
    let mut flat = Vec::new();
    for l in lists {
        flat.extend(l);
        start.push(flat.len());
    }
    (start, flat)
}
