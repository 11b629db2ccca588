//! The metrical edit of a complex with points (TM §X–XI): the continuity conditions between
//! a cell and its boundary, and the non-intersection condition for every pair of cells.
//!
//! Cells are straight: an edge is the segment between its two ends' points, a face the plane
//! polygon (with holes) its edges bound. Continuity: an edge with a point at one end has one
//! at the other, a face's points lie in one plane and span it. Non-intersection, for every
//! pair of cells neither of which is in the other's boundary: two points are not the same
//! point, a point is not inside an edge or a face, two edges do not cross or coincide, an
//! edge does not lie in a face or pass through it, two faces do not coincide. A T-junction
//! (a wall ending on another wall's face) is a point inside an edge and an edge inside a
//! face; the same point given twice is two points at distance 0.
//!
//! Everything is decided within the tolerance [`Shape::tolerance`]: `1e-8 · max(1, L)` where
//! L is the largest extent of the points' bounding box. The pairs are those of cells whose
//! boxes (grown by the tolerance) meet in a uniform grid of cells of about the median edge
//! length ([`Shape::defects`]): O(n + pairs of neighbouring cells) for n cells, not all pairs.

use std::collections::HashMap;
use std::fmt;

use super::model::{ArchComplex, Region, RegionId};
use super::names::RegionNames;

type P = [f64; 3];

fn sub(a: P, b: P) -> P {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
fn dot(a: P, b: P) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
fn cross(a: P, b: P) -> P {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}
fn norm(a: P) -> f64 {
    dot(a, a).sqrt()
}
fn lerp(a: P, b: P, t: f64) -> P {
    [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])]
}

/// The distance from `p` to the segment `ab` and the parameter of the nearest point.
pub(super) fn point_segment(p: P, a: P, b: P) -> (f64, f64) {
    let d = sub(b, a);
    let l2 = dot(d, d);
    let t = if l2 > 0.0 { (dot(sub(p, a), d) / l2).clamp(0.0, 1.0) } else { 0.0 };
    (norm(sub(p, lerp(a, b, t))), t)
}

/// A failed metrical condition, cells by id. Displayed with names by [`MetricDefect::named`].
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum MetricDefect {
    /// Two points closer than the tolerance: the same point given twice.
    NearPoints {
        /// the first point
        a: RegionId,
        /// the second
        b: RegionId,
        /// their distance
        distance: f64,
    },
    /// A point inside an edge it is not an end of (a T-junction).
    VertexOnEdge {
        /// the point
        vertex: RegionId,
        /// the edge
        edge: RegionId,
    },
    /// A point inside a face it is not on the boundary of.
    VertexInFace {
        /// the point
        vertex: RegionId,
        /// the face
        face: RegionId,
    },
    /// Two edges crossing at a point inside both.
    EdgesCross {
        /// the first edge
        a: RegionId,
        /// the second
        b: RegionId,
    },
    /// Two edges with the same ends: the same segment twice.
    EdgesCoincide {
        /// the first edge
        a: RegionId,
        /// the second
        b: RegionId,
    },
    /// An edge lying inside a face it is not on the boundary of (a T-junction of walls).
    EdgeInFace {
        /// the edge
        edge: RegionId,
        /// the face
        face: RegionId,
    },
    /// An edge passing through a face.
    EdgeThroughFace {
        /// the edge
        edge: RegionId,
        /// the face
        face: RegionId,
    },
    /// Two faces with the same edges: the same polygon twice.
    FacesCoincide {
        /// the first face
        a: RegionId,
        /// the second
        b: RegionId,
    },
    /// Continuity: an edge with a point at one end and none at the other.
    EdgeEndWithoutPoint {
        /// the edge
        edge: RegionId,
        /// the end without a point
        vertex: RegionId,
    },
    /// Continuity: a face whose points are not in one plane, or all on one line.
    FaceNotPlanar {
        /// the face
        face: RegionId,
        /// its point farthest from the plane of the others (the face's first point when
        /// they are on one line)
        vertex: RegionId,
        /// that distance (0 when they are on one line)
        distance: f64,
    },
}

/// A [`MetricDefect`] displayed with the file's names.
pub struct NamedDefect<'a> {
    defect: &'a MetricDefect,
    names: &'a RegionNames,
}

impl MetricDefect {
    /// The defect displayed with regions named by `names`.
    pub fn named<'a>(&'a self, names: &'a RegionNames) -> NamedDefect<'a> {
        NamedDefect { defect: self, names }
    }
}

impl fmt::Display for NamedDefect<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let n = |id: &RegionId| self.names.get(*id);
        match self.defect {
            MetricDefect::NearPoints { a, b, distance } => {
                write!(f, "points {} and {} are {distance:.2e} apart: the same point twice", n(a), n(b))
            }
            MetricDefect::VertexOnEdge { vertex, edge } => {
                write!(f, "point {} lies inside edge {} (a T-junction)", n(vertex), n(edge))
            }
            MetricDefect::VertexInFace { vertex, face } => {
                write!(f, "point {} lies inside face {}", n(vertex), n(face))
            }
            MetricDefect::EdgesCross { a, b } => write!(f, "edges {} and {} cross", n(a), n(b)),
            MetricDefect::EdgesCoincide { a, b } => {
                write!(f, "edges {} and {} have the same ends: the same segment twice", n(a), n(b))
            }
            MetricDefect::EdgeInFace { edge, face } => {
                write!(f, "edge {} lies inside face {} (a T-junction)", n(edge), n(face))
            }
            MetricDefect::EdgeThroughFace { edge, face } => {
                write!(f, "edge {} passes through face {}", n(edge), n(face))
            }
            MetricDefect::FacesCoincide { a, b } => {
                write!(f, "faces {} and {} have the same edges: the same polygon twice", n(a), n(b))
            }
            MetricDefect::EdgeEndWithoutPoint { edge, vertex } => {
                write!(f, "edge {} has its end {} without a point", n(edge), n(vertex))
            }
            MetricDefect::FaceNotPlanar { face, vertex, distance } if *distance == 0.0 => {
                write!(f, "face {} is flat: its points, {} and the others, are on one line", n(face), n(vertex))
            }
            MetricDefect::FaceNotPlanar { face, vertex, distance } => {
                write!(
                    f,
                    "face {} is not plane: its point {} is {distance:e} from the plane of the others",
                    n(face),
                    n(vertex)
                )
            }
        }
    }
}

impl fmt::Display for MetricDefect {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        self.named(&RegionNames::new()).fmt(f)
    }
}

/// A plane face: its edges, its points, and its plane.
struct Face {
    edges: Vec<usize>,
    /// its points' regions, sorted
    verts: Vec<usize>,
    origin: P,
    normal: P,
    /// the axis dropped to project it on a coordinate plane
    drop: usize,
}

/// The cells of a complex with points, for the metrical edit (module docs).
pub struct Shape {
    ids: Vec<RegionId>,
    points: Vec<Option<P>>,
    /// ends of each edge with points at both
    ends: Vec<Option<(usize, usize)>>,
    faces: Vec<Option<Face>>,
    dims: Vec<usize>,
    defects: Vec<MetricDefect>,
    tol: f64,
}

impl Shape {
    /// The shape of regions `regions` with the entries `(from, to)` (only those between
    /// consecutive dimensions are used) and the points of 0-regions. Unknown ids are left
    /// out. O(R + E).
    pub fn new(
        regions: &[Region],
        entries: impl Iterator<Item = (RegionId, RegionId)>,
        points: &HashMap<RegionId, P>,
    ) -> Self {
        let by_id: HashMap<RegionId, usize> = regions.iter().enumerate().map(|(k, r)| (r.id, k)).collect();
        let mut down = vec![Vec::new(); regions.len()];
        for (f, t) in entries {
            if let (Some(&a), Some(&b)) = (by_id.get(&f), by_id.get(&t)) {
                if regions[a].dim == regions[b].dim + 1 {
                    down[a].push(b);
                }
            }
        }
        let pts: Vec<Option<P>> = regions.iter().map(|r| points.get(&r.id).copied()).collect();
        Self::build(regions.iter().map(|r| (r.id, r.dim)).collect(), down, pts)
    }

    /// The shape of an architectural complex. O(R + E).
    pub fn of(x: &ArchComplex) -> Self {
        let mut down = vec![Vec::new(); x.regions().len()];
        for e in x.entries() {
            if x.region(e.from).dim == x.region(e.to).dim + 1 {
                down[e.from].push(e.to);
            }
        }
        let pts = (0..x.regions().len()).map(|k| x.region_point(k)).collect();
        Self::build(x.regions().iter().map(|r| (r.id, r.dim)).collect(), down, pts)
    }

    fn build(cells: Vec<(RegionId, usize)>, down: Vec<Vec<usize>>, points: Vec<Option<P>>) -> Self {
        let n = cells.len();
        let mut ext = [f64::INFINITY, f64::NEG_INFINITY];
        for p in points.iter().flatten() {
            for c in p {
                ext = [ext[0].min(*c), ext[1].max(*c)];
            }
        }
        let extent = if ext[0].is_finite() { ext[1] - ext[0] } else { 0.0 };
        let mut s = Shape {
            ids: cells.iter().map(|c| c.0).collect(),
            dims: cells.iter().map(|c| c.1).collect(),
            points,
            ends: vec![None; n],
            faces: (0..n).map(|_| None).collect(),
            defects: Vec::new(),
            tol: 1e-8 * extent.max(1.0),
        };
        for (c, d) in down.iter().enumerate() {
            if s.dims[c] == 1 {
                s.ends[c] = s.edge_ends(c, d);
            }
        }
        for (c, d) in down.iter().enumerate() {
            if s.dims[c] == 2 {
                s.faces[c] = s.face(c, d);
            }
        }
        s
    }

    /// The tolerance of every decision (module docs).
    pub fn tolerance(&self) -> f64 {
        self.tol
    }

    /// The shape deciding the pairs of cells within `tol` instead (snapping).
    pub fn with_tolerance(mut self, tol: f64) -> Self {
        self.tol = tol;
        self
    }

    /// The region index of `id` in this shape (O(R)).
    pub(super) fn index(&self, id: RegionId) -> Option<usize> {
        self.ids.iter().position(|&i| i == id)
    }

    /// The point of region `v` (the origin without one).
    pub(super) fn point(&self, v: usize) -> P {
        self.pt(v)
    }

    /// The ends of edge `e`, when both have points.
    pub(super) fn ends_of(&self, e: usize) -> Option<(usize, usize)> {
        self.ends[e]
    }

    /// The edges, points and normal axis dropped of face `f`, when it is plane.
    pub(super) fn face_of(&self, f: usize) -> Option<(&[usize], usize)> {
        self.faces[f].as_ref().map(|x| (x.edges.as_slice(), x.drop))
    }

    /// The region id of index `k`.
    pub(super) fn id(&self, k: usize) -> RegionId {
        self.ids[k]
    }

    fn edge_ends(&mut self, e: usize, ends: &[usize]) -> Option<(usize, usize)> {
        let [a, b] = *ends else { return None };
        match (self.points[a], self.points[b]) {
            (Some(_), Some(_)) => Some((a, b)),
            (Some(_), None) | (None, Some(_)) => {
                let vertex = self.ids[if self.points[a].is_none() { a } else { b }];
                self.defects.push(MetricDefect::EdgeEndWithoutPoint { edge: self.ids[e], vertex });
                None
            }
            (None, None) => None,
        }
    }

    fn face(&mut self, f: usize, edges: &[usize]) -> Option<Face> {
        let mut verts = Vec::with_capacity(2 * edges.len());
        for &e in edges {
            let (a, b) = self.ends[e]?;
            verts.extend([a, b]);
        }
        verts.sort_unstable();
        verts.dedup();
        let p = |k: usize| self.points[verts[k]].unwrap_or_default();
        let o = p(0);
        let far = (0..verts.len()).max_by(|&i, &j| norm(sub(p(i), o)).total_cmp(&norm(sub(p(j), o))))?;
        let u = sub(p(far), o);
        let side =
            (0..verts.len()).max_by(|&i, &j| norm(cross(u, sub(p(i), o))).total_cmp(&norm(cross(u, sub(p(j), o)))))?;
        let c = cross(u, sub(p(side), o));
        let len = norm(c);
        if len <= self.tol * norm(u) || norm(u) <= self.tol {
            self.defects.push(MetricDefect::FaceNotPlanar {
                face: self.ids[f],
                vertex: self.ids[verts[0]],
                distance: 0.0,
            });
            return None;
        }
        let normal = [c[0] / len, c[1] / len, c[2] / len];
        let (worst, d) = (0..verts.len())
            .map(|k| (k, dot(sub(p(k), o), normal).abs()))
            .max_by(|a, b| a.1.total_cmp(&b.1))
            .unwrap_or((0, 0.0));
        if d > self.tol {
            self.defects.push(MetricDefect::FaceNotPlanar {
                face: self.ids[f],
                vertex: self.ids[verts[worst]],
                distance: d,
            });
            return None;
        }
        let drop = (0..3).max_by(|&i, &j| normal[i].abs().total_cmp(&normal[j].abs())).unwrap_or(2);
        Some(Face { edges: edges.to_vec(), verts, origin: o, normal, drop })
    }

    fn pt(&self, v: usize) -> P {
        self.points[v].unwrap_or_default()
    }

    /// Whether `p` (in the face's plane) is inside face `f`, farther than the tolerance from
    /// its boundary: the parity of the crossings of a ray with its edges (holes included).
    fn inside(&self, f: &Face, p: P) -> bool {
        let (i, j) = match f.drop {
            0 => (1, 2),
            1 => (2, 0),
            _ => (0, 1),
        };
        let mut odd = false;
        for &e in &f.edges {
            let Some((a, b)) = self.ends[e] else { return false };
            let (a, b) = (self.pt(a), self.pt(b));
            if point_segment(p, a, b).0 <= self.tol {
                return false;
            }
            if (a[j] > p[j]) != (b[j] > p[j]) {
                let x = a[i] + (p[j] - a[j]) / (b[j] - a[j]) * (b[i] - a[i]);
                if x > p[i] {
                    odd = !odd;
                }
            }
        }
        odd
    }
}

/// What a cell is in the grid: a point, an edge or a face, by region index.
#[derive(Clone, Copy)]
enum Item {
    V(usize),
    E(usize),
    F(usize),
}

impl Shape {
    fn items(&self) -> Vec<(Item, [P; 2])> {
        let grow = |lo: P, hi: P| {
            let t = self.tol;
            [[lo[0] - t, lo[1] - t, lo[2] - t], [hi[0] + t, hi[1] + t, hi[2] + t]]
        };
        let mut out = Vec::new();
        for c in 0..self.ids.len() {
            let (item, pts): (Item, Vec<P>) = match self.dims[c] {
                0 => match self.points[c] {
                    Some(p) => (Item::V(c), vec![p]),
                    None => continue,
                },
                1 => match self.ends[c] {
                    Some((a, b)) => (Item::E(c), vec![self.pt(a), self.pt(b)]),
                    None => continue,
                },
                2 => match &self.faces[c] {
                    Some(f) => (Item::F(c), f.verts.iter().map(|&v| self.pt(v)).collect()),
                    None => continue,
                },
                _ => continue,
            };
            let mut lo = pts[0];
            let mut hi = pts[0];
            for p in &pts {
                for k in 0..3 {
                    lo[k] = lo[k].min(p[k]);
                    hi[k] = hi[k].max(p[k]);
                }
            }
            out.push((item, grow(lo, hi)));
        }
        out
    }

    /// The grid step: the median edge length, doubled until the boxes fill at most about
    /// eight grid cells each.
    fn step(&self, boxes: &[[P; 2]]) -> f64 {
        let mut lens: Vec<f64> =
            self.ends.iter().flatten().map(|&(a, b)| norm(sub(self.pt(a), self.pt(b)))).filter(|l| *l > 0.0).collect();
        lens.sort_by(f64::total_cmp);
        let mut h = lens.get(lens.len() / 2).copied().unwrap_or(1.0).max(self.tol * 4.0);
        let budget = 8 * boxes.len() as u128 + 100_000;
        loop {
            let cells: u128 =
                boxes.iter().map(|b| (0..3).map(|k| ((b[1][k] - b[0][k]) / h) as u128 + 2).product::<u128>()).sum();
            if cells <= budget {
                return h;
            }
            h *= 2.0;
        }
    }

    /// Every failed metrical condition (module docs): the continuity defects found when the
    /// shape was made, then the pairs of neighbouring cells, in a uniform grid. Each pair is
    /// tested once, in the grid cell of the low corner of the intersection of their boxes.
    pub fn defects(&self) -> Vec<MetricDefect> {
        let mut out = self.defects.clone();
        let items = self.items();
        let boxes: Vec<[P; 2]> = items.iter().map(|x| x.1).collect();
        let h = self.step(&boxes);
        let key = |p: P| [(p[0] / h).floor() as i64, (p[1] / h).floor() as i64, (p[2] / h).floor() as i64];
        let mut grid: HashMap<[i64; 3], Vec<u32>> = HashMap::new();
        for (k, b) in boxes.iter().enumerate() {
            let (lo, hi) = (key(b[0]), key(b[1]));
            for x in lo[0]..=hi[0] {
                for y in lo[1]..=hi[1] {
                    for z in lo[2]..=hi[2] {
                        grid.entry([x, y, z]).or_default().push(k as u32);
                    }
                }
            }
        }
        let mut cells: Vec<(&[i64; 3], &Vec<u32>)> = grid.iter().collect();
        cells.sort_unstable_by_key(|c| *c.0);
        for (cell, list) in cells {
            for (i, &a) in list.iter().enumerate() {
                for &b in &list[i + 1..] {
                    let (ba, bb) = (boxes[a as usize], boxes[b as usize]);
                    let lo = [ba[0][0].max(bb[0][0]), ba[0][1].max(bb[0][1]), ba[0][2].max(bb[0][2])];
                    let meet = (0..3).all(|k| lo[k] <= ba[1][k].min(bb[1][k]));
                    if meet && key(lo) == *cell {
                        self.test(items[a as usize].0, items[b as usize].0, &mut out);
                    }
                }
            }
        }
        self.coinciding_faces(&mut out);
        out
    }

    fn coinciding_faces(&self, out: &mut Vec<MetricDefect>) {
        let mut seen: HashMap<Vec<usize>, usize> = HashMap::new();
        for (c, f) in self.faces.iter().enumerate() {
            let Some(f) = f else { continue };
            let mut e = f.edges.clone();
            e.sort_unstable();
            if let Some(&d) = seen.get(&e) {
                out.push(MetricDefect::FacesCoincide { a: self.ids[d], b: self.ids[c] });
            } else {
                seen.insert(e, c);
            }
        }
    }

    fn test(&self, a: Item, b: Item, out: &mut Vec<MetricDefect>) {
        match (a, b) {
            (Item::V(u), Item::V(v)) => self.vertex_vertex(u, v, out),
            (Item::V(v), Item::E(e)) | (Item::E(e), Item::V(v)) => self.vertex_edge(v, e, out),
            (Item::V(v), Item::F(f)) | (Item::F(f), Item::V(v)) => self.vertex_face(v, f, out),
            (Item::E(d), Item::E(e)) => self.edge_edge(d, e, out),
            (Item::E(e), Item::F(f)) | (Item::F(f), Item::E(e)) => self.edge_face(e, f, out),
            (Item::F(_), Item::F(_)) => {}
        }
    }

    fn vertex_vertex(&self, u: usize, v: usize, out: &mut Vec<MetricDefect>) {
        let d = norm(sub(self.pt(u), self.pt(v)));
        if d <= self.tol {
            let (a, b) = if u < v { (u, v) } else { (v, u) };
            out.push(MetricDefect::NearPoints { a: self.ids[a], b: self.ids[b], distance: d });
        }
    }

    /// Whether `v` lies inside edge `e` (farther than the tolerance from its ends).
    pub(super) fn on_edge(&self, v: usize, e: usize) -> Option<f64> {
        let (a, b) = self.ends[e]?;
        if v == a || v == b {
            return None;
        }
        let (p, pa, pb) = (self.pt(v), self.pt(a), self.pt(b));
        let (d, t) = point_segment(p, pa, pb);
        let inside = d <= self.tol && norm(sub(p, pa)) > self.tol && norm(sub(p, pb)) > self.tol;
        inside.then_some(t)
    }

    fn vertex_edge(&self, v: usize, e: usize, out: &mut Vec<MetricDefect>) {
        if self.on_edge(v, e).is_some() {
            out.push(MetricDefect::VertexOnEdge { vertex: self.ids[v], edge: self.ids[e] });
        }
    }

    fn vertex_face(&self, v: usize, f: usize, out: &mut Vec<MetricDefect>) {
        let Some(face) = &self.faces[f] else { return };
        let p = self.pt(v);
        if face.verts.binary_search(&v).is_err()
            && dot(sub(p, face.origin), face.normal).abs() <= self.tol
            && self.inside(face, p)
        {
            out.push(MetricDefect::VertexInFace { vertex: self.ids[v], face: self.ids[f] });
        }
    }

    fn edge_edge(&self, d: usize, e: usize, out: &mut Vec<MetricDefect>) {
        let (Some((a, b)), Some((c, k))) = (self.ends[d], self.ends[e]) else { return };
        let (x, y) = if d < e { (d, e) } else { (e, d) };
        if (a == c && b == k) || (a == k && b == c) {
            out.push(MetricDefect::EdgesCoincide { a: self.ids[x], b: self.ids[y] });
            return;
        }
        if a == c || a == k || b == c || b == k {
            return;
        }
        let (p, q, r, s) = (self.pt(a), self.pt(b), self.pt(c), self.pt(k));
        let (u, w) = (sub(q, p), sub(s, r));
        let n = cross(u, w);
        if norm(n) <= 1e-12 * norm(u) * norm(w) {
            return; // parallel: an overlap has an end inside the other edge
        }
        // the nearest points p + t u and r + s w of the two lines
        let rp = sub(r, p);
        let nn = dot(n, n);
        let t = dot(cross(rp, w), n) / nn;
        let sp = dot(cross(rp, u), n) / nn;
        if !(0.0..=1.0).contains(&t) || !(0.0..=1.0).contains(&sp) {
            return;
        }
        let (m1, m2) = (lerp(p, q, t), lerp(r, s, sp));
        let far = |m: P| [p, q, r, s].iter().all(|&z| norm(sub(m, z)) > self.tol);
        if norm(sub(m1, m2)) <= self.tol && far(m1) && far(m2) {
            out.push(MetricDefect::EdgesCross { a: self.ids[x], b: self.ids[y] });
        }
    }

    fn edge_face(&self, e: usize, f: usize, out: &mut Vec<MetricDefect>) {
        let (Some((a, b)), Some(face)) = (self.ends[e], &self.faces[f]) else { return };
        if face.edges.contains(&e) {
            return;
        }
        let (p, q) = (self.pt(a), self.pt(b));
        let (da, db) = (dot(sub(p, face.origin), face.normal), dot(sub(q, face.origin), face.normal));
        if da.abs() <= self.tol && db.abs() <= self.tol {
            if self.inside(face, lerp(p, q, 0.5)) {
                out.push(MetricDefect::EdgeInFace { edge: self.ids[e], face: self.ids[f] });
            }
        } else if da.abs() > self.tol && db.abs() > self.tol && (da < 0.0) != (db < 0.0) {
            let x = lerp(p, q, da / (da - db));
            if self.inside(face, x) {
                out.push(MetricDefect::EdgeThroughFace { edge: self.ids[e], face: self.ids[f] });
            }
        }
    }
}
