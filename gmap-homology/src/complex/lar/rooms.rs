//! Rooms from walls: the 3-cells of a 2-complex in space, found as minimal 2-cycles (LAR
//! Fig. 1, the 2-cell extraction of Figs. 2–3 one dimension up).
//!
//! The input is a set of faces in space ([`Faces`]): polygons, each one or more closed
//! loops of vertex indices (an outer boundary and holes), with the vertices' points. Two
//! faces meet only along whole edges or at vertices (an arrangement: no crossing, no
//! vertex inside an edge or a face). Around every edge the faces on it are ordered by angle
//! ([`Faces::around`]); the space between two consecutive faces belongs to one 3-cell,
//! which lies on a known side of each. So a *side* of a face, `(f, σ)` with `σ = +1` when
//! the cell sees the face's normal (right-hand rule of its loops) pointing out of it, has
//! one neighbour side across each of its edges.
//!
//! A 3-cell is extracted as LAR extracts a 2-cell: start with the chain `c = σ f`, then
//! repeat the δ∂ step — `∂c` (the edges where `c` is open), and for each of them the next
//! face around the edge, with the sign that cancels it — until `∂c = 0`
//! ([`Faces::extraction_steps`] records every step). Every side of every face lies in
//! exactly one cell. The cells' boundaries have outward normals, so the bounded cells have
//! positive volume and the *outer* cell, the unbounded one, negative volume
//! ([`Cells::outer`]). A face with one cell on both sides (a wall standing free in a room),
//! a face of zero area, two faces at one angle around an edge, and faces in separate shells
//! (whose nesting is not known from edges alone) are refused ([`RoomsError`]).
//!
//! O(E log E) for the orders around the edges (E the edge-face incidences), then linear.

use std::collections::{BTreeMap, HashMap};

use thiserror::Error;

use crate::complex::arch::{ArchComplex, ArchError, Region, RegionId};

type P = [f64; 3];

fn sub(a: P, b: P) -> P {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn cross(a: P, b: P) -> P {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

fn dot(a: P, b: P) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// Why faces in space do not bound 3-cells as [`Faces::cells`] finds them.
#[derive(Clone, Debug, PartialEq, Error)]
#[non_exhaustive]
pub enum RoomsError {
    /// A face names a vertex that does not exist, or has a loop of fewer than 3 vertices.
    #[error("face {face}: {problem}")]
    BadFace {
        /// the face
        face: usize,
        /// what is wrong
        problem: String,
    },
    /// A face whose loops enclose no area (all its points on a line).
    #[error("face {face} has no area: its points lie on a line")]
    Flat {
        /// the face
        face: usize,
    },
    /// Two faces on one edge at the same angle (they overlap).
    #[error("faces {a} and {b} overlap along the edge {u}-{v}")]
    Overlap {
        /// one face
        a: usize,
        /// the other
        b: usize,
        /// the edge's ends (vertex indices)
        u: u32,
        /// the other end
        v: u32,
    },
    /// A face with the same 3-cell on both sides.
    #[error("face {face} has the same 3-cell on both sides (a wall standing free in a room)")]
    BothSides {
        /// the face
        face: usize,
    },
    /// The faces form several shells (closed surfaces not joined by edges): which one lies
    /// inside which is not known from the edges.
    #[error("the faces form {shells} separate shells; give each building alone")]
    Shells {
        /// how many unbounded cells were found
        shells: usize,
    },
}

/// Faces in space: points and polygons with holes (module docs).
#[derive(Clone, Debug, PartialEq)]
pub struct Faces {
    points: Vec<P>,
    /// each face's loops, as vertex indices
    faces: Vec<Vec<Vec<u32>>>,
    /// each face's edges: (edge, +1 when the face runs it from its lower to its higher vertex)
    face_edges: Vec<Vec<(usize, i64)>>,
    /// the edges as (lower, higher) vertex index
    edges: Vec<(u32, u32)>,
    /// the normal of each face (Newell's, twice the vector area)
    normals: Vec<P>,
    /// for each edge, its faces in the order of the angle around it
    around: Vec<Vec<usize>>,
    /// the side across each edge: (face, σ, edge) -> (face, σ)
    next: HashMap<(usize, i64, usize), (usize, i64)>,
}

/// One δ∂ step of an extraction: the chain so far and its boundary.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ExtractionStep {
    /// the chain: (face, ±1)
    pub chain: Vec<(usize, i64)>,
    /// its boundary: (edge, coefficient), empty at the last step
    pub boundary: Vec<(usize, i64)>,
}

/// The 3-cells of [`Faces`]: each a 2-cycle of faces with outward signs.
#[derive(Clone, Debug, PartialEq)]
pub struct Cells {
    /// each cell's boundary: (face, ±1), the face's normal pointing out of the cell for +1
    pub cells: Vec<Vec<(usize, i64)>>,
    /// six times each cell's volume (negative for the outer cell)
    pub volumes6: Vec<f64>,
    /// the index of the outer (unbounded) cell
    pub outer: usize,
}

impl Faces {
    /// Faces from points and polygons (each face a list of loops of vertex indices, the
    /// first its outer boundary). Orders the faces around every edge. Errors:
    /// [`RoomsError::BadFace`], [`RoomsError::Flat`], [`RoomsError::Overlap`].
    pub fn try_new(points: Vec<P>, faces: Vec<Vec<Vec<u32>>>) -> Result<Self, RoomsError> {
        let mut edge_of: BTreeMap<(u32, u32), usize> = BTreeMap::new();
        let mut edges = Vec::new();
        let mut face_edges = Vec::with_capacity(faces.len());
        let mut normals = Vec::with_capacity(faces.len());
        for (f, loops) in faces.iter().enumerate() {
            let mut fe = Vec::new();
            let mut n = [0.0; 3];
            for lp in loops {
                if lp.len() < 3 {
                    return Err(RoomsError::BadFace { face: f, problem: format!("a loop of {} vertices", lp.len()) });
                }
                for (j, &a) in lp.iter().enumerate() {
                    let b = lp[(j + 1) % lp.len()];
                    let (Some(&pa), Some(&pb)) = (points.get(a as usize), points.get(b as usize)) else {
                        return Err(RoomsError::BadFace {
                            face: f,
                            problem: format!("vertex {} does not exist", a.max(b)),
                        });
                    };
                    if a == b {
                        return Err(RoomsError::BadFace { face: f, problem: format!("vertex {a} twice in a row") });
                    }
                    let c = cross(pa, pb);
                    n = [n[0] + c[0], n[1] + c[1], n[2] + c[2]];
                    let key = (a.min(b), a.max(b));
                    let e = *edge_of.entry(key).or_insert_with(|| {
                        edges.push(key);
                        edges.len() - 1
                    });
                    fe.push((e, if a < b { 1 } else { -1 }));
                }
            }
            if dot(n, n) == 0.0 {
                return Err(RoomsError::Flat { face: f });
            }
            face_edges.push(fe);
            normals.push(n);
        }
        let mut on: Vec<Vec<(usize, i64)>> = vec![Vec::new(); edges.len()];
        for (f, fe) in face_edges.iter().enumerate() {
            for &(e, t) in fe {
                on[e].push((f, t));
            }
        }
        let mut around = Vec::with_capacity(edges.len());
        let mut next = HashMap::new();
        for (e, list) in on.iter().enumerate() {
            let (u, v) = edges[e];
            let d = sub(points[v as usize], points[u as usize]);
            // the direction from the edge into each face: n × (t d)
            let into: Vec<P> = list
                .iter()
                .map(|&(f, t)| cross(normals[f], [t as f64 * d[0], t as f64 * d[1], t as f64 * d[2]]))
                .collect();
            let e1 = into[0];
            let e2 = cross(d, e1);
            let mut order: Vec<(f64, usize)> =
                into.iter().enumerate().map(|(j, w)| (dot(*w, e2).atan2(dot(*w, e1)), j)).collect();
            order.sort_by(|a, b| a.0.total_cmp(&b.0));
            for w in order.windows(2) {
                if w[0].0 == w[1].0 {
                    return Err(RoomsError::Overlap { a: list[w[0].1].0, b: list[w[1].1].0, u, v });
                }
            }
            let k = order.len();
            for i in 0..k {
                let (fi, ti) = list[order[i].1];
                let (fj, tj) = list[order[(i + 1) % k].1];
                // the wedge from fi to the next face: the cell on side σ = -t of fi and σ = t of fj
                next.insert((fi, -ti, e), (fj, tj));
                next.insert((fj, tj, e), (fi, -ti));
            }
            around.push(order.iter().map(|&(_, j)| list[j].0).collect());
        }
        Ok(Faces { points, faces, face_edges, edges, normals, around, next })
    }

    /// The edges, as (lower, higher) vertex index.
    pub fn edges(&self) -> &[(u32, u32)] {
        &self.edges
    }

    /// The edges of face `f`: (edge, +1 when the face runs it from its lower vertex).
    pub fn face_edges(&self, f: usize) -> &[(usize, i64)] {
        &self.face_edges[f]
    }

    /// The faces on edge `e`, in the order of the angle around it.
    pub fn around(&self, e: usize) -> &[usize] {
        &self.around[e]
    }

    /// The number of faces.
    pub fn len(&self) -> usize {
        self.faces.len()
    }

    /// Whether there is no face.
    pub fn is_empty(&self) -> bool {
        self.faces.is_empty()
    }

    /// The points.
    pub fn points(&self) -> &[P] {
        &self.points
    }

    /// The boundary of a chain of faces: (edge, coefficient), zero coefficients left out.
    pub fn boundary(&self, chain: &[(usize, i64)]) -> Vec<(usize, i64)> {
        let mut b: BTreeMap<usize, i64> = BTreeMap::new();
        for &(f, s) in chain {
            for &(e, t) in &self.face_edges[f] {
                *b.entry(e).or_insert(0) += s * t;
            }
        }
        b.into_iter().filter(|&(_, v)| v != 0).collect()
    }

    /// The δ∂ steps extracting the cell on side `sigma` of face `f` (module docs): the
    /// chain after each step and its boundary; the last boundary is empty.
    pub fn extraction_steps(&self, f: usize, sigma: i64) -> Vec<ExtractionStep> {
        let mut chain: BTreeMap<usize, i64> = BTreeMap::from([(f, sigma)]);
        let mut steps = Vec::new();
        loop {
            let c: Vec<(usize, i64)> = chain.iter().map(|(&f, &s)| (f, s)).collect();
            let boundary = self.boundary(&c);
            let done = boundary.is_empty();
            steps.push(ExtractionStep { chain: c.clone(), boundary: boundary.clone() });
            if done {
                return steps;
            }
            let mut added = false;
            for &(e, _) in &boundary {
                for &(g, s) in &c {
                    if let Some(&(h, t)) = self.next.get(&(g, s, e)) {
                        if let std::collections::btree_map::Entry::Vacant(v) = chain.entry(h) {
                            v.insert(t);
                            added = true;
                        }
                    }
                }
            }
            if !added {
                // only where a face has one cell on both sides: reported by `cells`
                return steps;
            }
        }
    }

    /// Six times the volume bounded by a chain with outward signs.
    fn volume6(&self, chain: &[(usize, i64)]) -> f64 {
        let mut v = 0.0;
        for &(f, s) in chain {
            for lp in &self.faces[f] {
                let n = lp.len() as f64;
                let c = lp.iter().fold([0.0; 3], |c, &i| {
                    let p = self.points[i as usize];
                    [c[0] + p[0] / n, c[1] + p[1] / n, c[2] + p[2] / n]
                });
                for (j, &a) in lp.iter().enumerate() {
                    let b = lp[(j + 1) % lp.len()];
                    v += s as f64 * dot(c, cross(self.points[a as usize], self.points[b as usize]));
                }
            }
        }
        v
    }

    /// Every 3-cell (module docs), in the order of the first side of a face each holds.
    pub fn cells(&self) -> Result<Cells, RoomsError> {
        let mut cell_of: HashMap<(usize, i64), usize> = HashMap::new();
        let mut cells = Vec::new();
        for f in 0..self.faces.len() {
            for sigma in [1, -1] {
                if cell_of.contains_key(&(f, sigma)) {
                    continue;
                }
                let steps = self.extraction_steps(f, sigma);
                let last = steps.last().map(|s| s.chain.clone()).unwrap_or_default();
                let k = cells.len();
                let mut members = Vec::with_capacity(last.len());
                for (g, s) in last {
                    if cell_of.insert((g, s), k).is_some() {
                        return Err(RoomsError::BothSides { face: g });
                    }
                    members.push((g, s));
                }
                if !steps.last().is_some_and(|s| s.boundary.is_empty()) {
                    return Err(RoomsError::BothSides { face: f });
                }
                cells.push(members);
            }
        }
        let volumes6: Vec<f64> = cells.iter().map(|c| self.volume6(c)).collect();
        let outer: Vec<usize> = (0..cells.len()).filter(|&k| volumes6[k] < 0.0).collect();
        if outer.len() != 1 {
            return Err(RoomsError::Shells { shells: outer.len() });
        }
        Ok(Cells { cells, volumes6, outer: outer[0] })
    }
}

impl Cells {
    /// The bounded cells (the rooms), in order.
    pub fn rooms(&self) -> impl Iterator<Item = &[(usize, i64)]> + '_ {
        self.cells.iter().enumerate().filter(move |&(k, _)| k != self.outer).map(|(_, c)| c.as_slice())
    }

    /// The 3-complex of the faces and their rooms (the outer cell left out): regions
    /// numbered vertices, edges, faces, rooms, with the string ids `v0`, `e0`, `f0`, `room 1`
    /// (in the order of [`Cells::rooms`]) and the vertices' points; an edge runs from its
    /// lower vertex, a face takes its edges as its loops run them, a room its faces with
    /// outward normals. O(size).
    pub fn to_arch(&self, faces: &Faces) -> Result<ArchComplex, ArchError> {
        let (nv, ne, nf) = (faces.points.len(), faces.edges.len(), faces.len());
        let mut regions = Vec::new();
        let mut keys = Vec::new();
        let mut push = |dim: usize, key: String, regions: &mut Vec<Region>| {
            regions.push(Region { id: RegionId(regions.len() as u64), dim });
            keys.push(key);
        };
        (0..nv).for_each(|i| push(0, format!("v{i}"), &mut regions));
        (0..ne).for_each(|i| push(1, format!("e{i}"), &mut regions));
        (0..nf).for_each(|i| push(2, format!("f{i}"), &mut regions));
        let rooms: Vec<&[(usize, i64)]> = self.rooms().collect();
        (0..rooms.len()).for_each(|i| push(3, format!("room {}", i + 1), &mut regions));
        let id = |k: usize| RegionId(k as u64);
        let mut entries = Vec::new();
        for (e, &(u, v)) in faces.edges.iter().enumerate() {
            entries.push((id(nv + e), id(u as usize), -1));
            entries.push((id(nv + e), id(v as usize), 1));
        }
        for (f, fe) in faces.face_edges.iter().enumerate() {
            let mut sum: BTreeMap<usize, i64> = BTreeMap::new();
            for &(e, t) in fe {
                *sum.entry(e).or_insert(0) += t;
            }
            entries.extend(sum.into_iter().map(|(e, t)| (id(nv + ne + f), id(nv + e), t)));
        }
        for (r, cell) in rooms.iter().enumerate() {
            entries.extend(cell.iter().map(|&(f, s)| (id(nv + ne + nf + r), id(nv + ne + f), s)));
        }
        let mut x = ArchComplex::try_new(3, regions, entries)?;
        for (k, key) in keys.into_iter().enumerate() {
            x = x.with_region_key(id(k), key)?;
        }
        for (i, &p) in faces.points.iter().enumerate() {
            x = x.with_region_point(id(i), p)?;
        }
        Ok(x)
    }
}
