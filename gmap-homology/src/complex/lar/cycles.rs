//! Cycle extraction (LAR, "Extraction of a 2-cell"): the 2-cells of a planar arrangement
//! from its 1-skeleton, each as a signed 1-chain, i.e. a column of the unknown `[∂_2]`.
//!
//! Around each vertex `v` the coboundary `δv` (its edges) is ordered cyclically by angle:
//! that is the "cyclic subgroup on `δv`" of the paper. A 1-chain `c` grows by *stripes*:
//! `stripe(c) = c + next(c ∩ δ∂c)`: at the vertex where `c` ends (the `+` term of `∂c`) the
//! edge after the last one of `c` in the cyclic order is appended, at the vertex where it
//! starts (the `-` term) the edge before the first one is prepended, each oriented
//! coherently with `c`; this repeats until `∂c = 0`. Here "after" is *clockwise from the
//! edge we came in by*, which keeps the new 2-cell on the left of `c`: bounded faces come
//! out counter-clockwise (positive area, the sign of LAR's conventional orientation of a
//! d-cell) and the unbounded one clockwise.
//!
//! Edges are straight segments between integer points, so every geometric test (angle
//! order, crossing) is exact. The edge `{a, b}`, `a < b`, is oriented from `a` to `b`, as
//! in [`Lar::signed_boundaries`](super::Lar::signed_boundaries).
//!
//! ```
//! use gmap_homology::lar::PlanarGraph;
//! // a unit square with one diagonal: two triangles
//! let g = PlanarGraph::try_new(
//!     vec![[0, 0], [1, 0], [1, 1], [0, 1]],
//!     vec![[0, 1], [1, 2], [2, 3], [0, 3], [0, 2]],
//! ).unwrap();
//! let a = g.extract();
//! assert_eq!(a.faces.len(), 2);
//! assert_eq!(a.faces[0].vertices, vec![0, 1, 2]);
//! assert_eq!(a.faces[0].chain(), vec![(0, 1), (1, 1), (4, -1)]);
//! assert_eq!(a.outer.vertices, vec![1, 0, 3, 2]);
//! ```

use std::cmp::Ordering;

use gmap_core::union_find::UnionFind;
use thiserror::Error;

use super::{characteristic_matrix, Lar};
use crate::engine::sparse::SparseMatrix;

/// Why edges and points do not make a connected planar straight-line graph.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
#[non_exhaustive]
pub enum ArrangementError {
    /// There are no edges.
    #[error("an arrangement needs at least one edge")]
    Empty,
    /// An edge names a vertex that has no point.
    #[error("edge {edge} names vertex {vertex}, but there are {vertices} points")]
    VertexOutOfRange {
        /// the edge
        edge: usize,
        /// the vertex
        vertex: u32,
        /// number of points
        vertices: usize,
    },
    /// An edge joins a vertex to itself.
    #[error("edge {edge} joins vertex {vertex} to itself")]
    Loop {
        /// the edge
        edge: usize,
        /// the vertex
        vertex: u32,
    },
    /// Two edges join the same two vertices (two straight segments that coincide).
    #[error("edges {first} and {second} join the same two vertices")]
    DuplicateEdge {
        /// the first edge
        first: usize,
        /// the second edge
        second: usize,
    },
    /// Two vertices have the same point.
    #[error("vertices {a} and {b} have the same point")]
    CoincidentPoints {
        /// a vertex
        a: usize,
        /// another vertex at the same point
        b: usize,
    },
    /// Two edges cross at a point that is not a vertex of both: the drawing is not a plane
    /// graph (split the edges at the crossing first).
    #[error("edges {first} and {second} cross")]
    Crossing {
        /// an edge
        first: usize,
        /// the edge crossing it
        second: usize,
    },
    /// A vertex lies inside an edge it does not bound.
    #[error("vertex {vertex} lies inside edge {edge}")]
    VertexOnEdge {
        /// the vertex
        vertex: u32,
        /// the edge
        edge: usize,
    },
    /// An edge number asked for is out of range.
    #[error("there is no edge {edge}: the graph has {edges} edges")]
    NoSuchEdge {
        /// the edge asked
        edge: usize,
        /// number of edges
        edges: usize,
    },
    /// The graph is not connected (an isolated vertex included): the face holding another
    /// component would have a hole, which needs a containment test this extraction does not
    /// make.
    #[error("vertex {vertex} is not connected to vertex 0")]
    Disconnected {
        /// a vertex outside the component of vertex 0
        vertex: usize,
    },
}

/// A connected planar straight-line graph: integer points, edges between them, and for
/// each vertex its edges in counter-clockwise order.
///
/// A *half-edge* `h` is edge `h / 2` run from its lower vertex to its higher one when `h`
/// is even, the other way when `h` is odd.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PlanarGraph {
    points: Vec<[i32; 2]>,
    /// `edges[e] = [a, b]` with `a < b`
    edges: Vec<[u32; 2]>,
    /// the half-edges leaving each vertex, counter-clockwise by angle
    around: Vec<Vec<u32>>,
    /// the position of half-edge `h` in `around[tail(h)]`
    pos: Vec<u32>,
}

/// A closed walk around one face: its half-edges in order, with the face on the left.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Cycle {
    /// `(edge, ±1)` in walk order: `+1` where the walk runs along the edge's orientation
    pub steps: Vec<(u32, i64)>,
    /// the vertex each step starts from, in walk order
    pub vertices: Vec<u32>,
    /// twice the signed area enclosed (positive: counter-clockwise)
    pub twice_area: i128,
}

impl Cycle {
    /// The walk as a 1-chain: `(edge, coefficient)` sorted by edge, without zeros (an edge
    /// walked both ways, a bridge, cancels). O(k log k).
    pub fn chain(&self) -> Vec<(u32, i64)> {
        combine(self.steps.clone())
    }
}

/// A chain from its terms `(cell, coefficient)`: sorted by cell, the coefficients of a
/// cell added, zeros left out. O(k log k).
fn combine(mut terms: Vec<(u32, i64)>) -> Vec<(u32, i64)> {
    terms.sort_unstable();
    let mut out: Vec<(u32, i64)> = Vec::with_capacity(terms.len());
    for (c, s) in terms {
        match out.last_mut() {
            Some(last) if last.0 == c => last.1 += s,
            _ => out.push((c, s)),
        }
    }
    out.retain(|&(_, s)| s != 0);
    out
}

/// One state of the stripe iteration: the chain `c` and its boundary `∂c`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Stripe {
    /// `c`, as `(edge, ±1)` sorted by edge (an edge walked both ways left out)
    pub chain: Vec<(u32, i64)>,
    /// `∂c`, as `(vertex, coefficient)` sorted by vertex, zeros left out
    pub boundary: Vec<(u32, i64)>,
}

/// The faces of a planar arrangement found by [`PlanarGraph::extract`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Arrangement {
    /// the bounded faces (counter-clockwise), ordered by their lowest half-edge
    pub faces: Vec<Cycle>,
    /// the unbounded face's walk (clockwise; zero area when the graph is a tree)
    pub outer: Cycle,
    vertices: usize,
    edges: Vec<[u32; 2]>,
}

impl Arrangement {
    /// `[∂_2]`: rows edges, one column per bounded face, its [`Cycle::chain`]. O(nnz).
    pub fn boundary(&self) -> SparseMatrix {
        let columns: Vec<Vec<(u32, i64)>> = self.faces.iter().map(Cycle::chain).collect();
        SparseMatrix::try_from_columns(self.edges.len(), &columns).expect("chains are sorted, without zeros")
    }

    /// The arrangement in LAR form: `M_1` from the edges, `M_2` from the vertex sets of the
    /// bounded faces. O(size).
    pub fn lar(&self) -> Lar {
        let ev: Vec<Vec<u32>> = self.edges.iter().map(|e| e.to_vec()).collect();
        let fv: Vec<Vec<u32>> = self.faces.iter().map(|f| f.vertices.clone()).collect();
        let m1 = characteristic_matrix(self.vertices, &ev).expect("edges checked");
        let m2 = characteristic_matrix(self.vertices, &fv).expect("face vertices are edge ends");
        Lar { vertices: self.vertices, cells: vec![m1, m2] }
    }
}

/// The coefficient of half-edge `h` on its edge: `+1` along the edge's orientation.
fn sign(h: u32) -> i64 {
    1 - 2 * i64::from(h & 1)
}

/// `b - a`, widened.
fn sub(a: [i32; 2], b: [i32; 2]) -> [i64; 2] {
    [i64::from(b[0]) - i64::from(a[0]), i64::from(b[1]) - i64::from(a[1])]
}

/// `u × v` (exact: each coordinate of `u`, `v` is below 2^33 in absolute value).
fn cross(u: [i64; 2], v: [i64; 2]) -> i128 {
    i128::from(u[0]) * i128::from(v[1]) - i128::from(u[1]) * i128::from(v[0])
}

/// `u · v`, exact as [`cross`].
fn dot(u: [i64; 2], v: [i64; 2]) -> i128 {
    i128::from(u[0]) * i128::from(v[0]) + i128::from(u[1]) * i128::from(v[1])
}

/// Orders non-zero directions counter-clockwise from the positive x axis.
fn by_angle(u: [i64; 2], v: [i64; 2]) -> Ordering {
    let upper = |w: [i64; 2]| w[1] > 0 || (w[1] == 0 && w[0] > 0);
    match (upper(u), upper(v)) {
        (true, false) => Ordering::Less,
        (false, true) => Ordering::Greater,
        _ => 0.cmp(&cross(u, v)),
    }
}

impl PlanarGraph {
    /// Checks and stores a plane drawing: `points[v]` is vertex `v`, `edges[e]` its two
    /// vertices (either order). Precondition (each failure is an [`ArrangementError`]
    /// naming the data): at least one edge; vertices in range; no loop, no two edges on
    /// the same two vertices, no two vertices at one point; edges meet only at common
    /// vertices (no crossing, no vertex inside an edge); connected, every vertex on an edge.
    /// O(V log V + E^2) (every pair of edges is tested for crossing).
    pub fn try_new(points: Vec<[i32; 2]>, edges: Vec<[u32; 2]>) -> Result<Self, ArrangementError> {
        if edges.is_empty() {
            return Err(ArrangementError::Empty);
        }
        let n = points.len();
        let mut sorted = Vec::with_capacity(edges.len());
        for (e, &[a, b]) in edges.iter().enumerate() {
            for v in [a, b] {
                if v as usize >= n {
                    return Err(ArrangementError::VertexOutOfRange { edge: e, vertex: v, vertices: n });
                }
            }
            if a == b {
                return Err(ArrangementError::Loop { edge: e, vertex: a });
            }
            sorted.push([a.min(b), a.max(b)]);
        }
        let mut keyed: Vec<([u32; 2], usize)> = sorted.iter().copied().zip(0..).collect();
        keyed.sort_unstable();
        if let Some(w) = keyed.windows(2).find(|w| w[0].0 == w[1].0) {
            return Err(ArrangementError::DuplicateEdge { first: w[0].1, second: w[1].1 });
        }
        let mut at: Vec<([i32; 2], usize)> = points.iter().copied().zip(0..).collect();
        at.sort_unstable();
        if let Some(w) = at.windows(2).find(|w| w[0].0 == w[1].0) {
            return Err(ArrangementError::CoincidentPoints { a: w[0].1, b: w[1].1 });
        }
        let mut uf = UnionFind::new(n);
        for &[a, b] in &sorted {
            uf.union(a, b);
        }
        if let Some(v) = (1..n).find(|&v| !uf.same(0, v as u32)) {
            return Err(ArrangementError::Disconnected { vertex: v });
        }
        check_plane(&points, &sorted)?;
        let mut around: Vec<Vec<u32>> = vec![Vec::new(); n];
        for (e, &[a, b]) in sorted.iter().enumerate() {
            around[a as usize].push(2 * e as u32);
            around[b as usize].push(2 * e as u32 + 1);
        }
        let mut g = PlanarGraph { points, edges: sorted, around, pos: vec![0; 2 * edges.len()] };
        for v in 0..n {
            let mut hs = std::mem::take(&mut g.around[v]);
            hs.sort_by(|&h, &k| by_angle(g.direction(h), g.direction(k)));
            for (i, &h) in hs.iter().enumerate() {
                g.pos[h as usize] = i as u32;
            }
            g.around[v] = hs;
        }
        Ok(g)
    }

    /// The number of vertices.
    pub fn vertices(&self) -> usize {
        self.points.len()
    }

    /// The edges, each as `[a, b]` with `a < b`.
    pub fn edges(&self) -> &[[u32; 2]] {
        &self.edges
    }

    /// The edges at vertex `v` (its coboundary `δv`) in counter-clockwise order from the
    /// positive x axis; `None` if `v >= vertices()`. O(degree).
    pub fn coboundary(&self, v: usize) -> Option<Vec<u32>> {
        Some(self.around.get(v)?.iter().map(|h| h / 2).collect())
    }

    /// The vertex half-edge `h` leaves.
    fn tail(&self, h: u32) -> u32 {
        self.edges[(h / 2) as usize][(h % 2) as usize]
    }

    /// The vertex half-edge `h` reaches.
    fn head(&self, h: u32) -> u32 {
        self.edges[(h / 2) as usize][1 - (h % 2) as usize]
    }

    /// The direction of half-edge `h`.
    fn direction(&self, h: u32) -> [i64; 2] {
        sub(self.points[self.tail(h) as usize], self.points[self.head(h) as usize])
    }

    /// The half-edge after `h` around the face on its left: at `head(h)`, the first edge
    /// clockwise from the way back.
    fn next(&self, h: u32) -> u32 {
        let back = h ^ 1;
        let ring = &self.around[self.head(h) as usize];
        ring[(self.pos[back as usize] as usize + ring.len() - 1) % ring.len()]
    }

    /// The half-edge before `h` around the face on its left (`next(prev(h)) == h`).
    fn prev(&self, h: u32) -> u32 {
        let ring = &self.around[self.tail(h) as usize];
        ring[(self.pos[h as usize] as usize + 1) % ring.len()] ^ 1
    }

    /// The 1-chain of a walk of half-edges, sorted by edge (an edge walked both ways cancels).
    fn chain_of(&self, hs: impl IntoIterator<Item = u32>) -> Vec<(u32, i64)> {
        combine(hs.into_iter().map(|h| (h / 2, sign(h))).collect())
    }

    /// `∂c` for a 1-chain `c`, sorted by vertex, zeros left out.
    fn boundary_of(&self, c: &[(u32, i64)]) -> Vec<(u32, i64)> {
        let mut b: Vec<(u32, i64)> = Vec::with_capacity(2 * c.len());
        for &(e, s) in c {
            let [lo, hi] = self.edges[e as usize];
            b.push((lo, -s));
            b.push((hi, s));
        }
        combine(b)
    }

    /// The stripe iteration of the paper from edge `edge` (run along its orientation when
    /// `forward`, against it otherwise): the chain and its boundary at the start and after
    /// each stripe, until `∂c = 0`. Each stripe adds the next edge at the end of `c` and the
    /// previous edge at its start, once when both are the same edge. The last state is the
    /// chain of the face on the left of the starting half-edge. Fails with
    /// [`ArrangementError::NoSuchEdge`] if `edge` is out of range. O(k) stripes of
    /// O(k log k) for a face of k edges.
    pub fn stripes(&self, edge: usize, forward: bool) -> Result<Vec<Stripe>, ArrangementError> {
        if edge >= self.edges.len() {
            return Err(ArrangementError::NoSuchEdge { edge, edges: self.edges.len() });
        }
        let start = 2 * edge as u32 + u32::from(!forward);
        // the walk so far is the contiguous run first ..= last of the face's cycle
        let mut walk = std::collections::VecDeque::from([start]);
        let state = |walk: &std::collections::VecDeque<u32>| {
            let chain = self.chain_of(walk.iter().copied());
            let boundary = self.boundary_of(&chain);
            Stripe { chain, boundary }
        };
        let mut out = vec![state(&walk)];
        loop {
            let (first, last) = (walk[0], walk[walk.len() - 1]);
            let after = self.next(last);
            if after == first {
                break;
            }
            walk.push_back(after);
            let before = self.prev(first);
            if before != after {
                walk.push_front(before);
            }
            out.push(state(&walk));
        }
        Ok(out)
    }

    /// The walk around the face on the left of half-edge `h`, marking its half-edges.
    fn walk(&self, h: u32, seen: &mut [bool]) -> Cycle {
        let mut steps = Vec::new();
        let mut vertices = Vec::new();
        let mut twice_area = 0i128;
        let mut k = h;
        loop {
            seen[k as usize] = true;
            steps.push((k / 2, sign(k)));
            let (a, b) = (self.points[self.tail(k) as usize], self.points[self.head(k) as usize]);
            vertices.push(self.tail(k));
            // each term is below 2^63 in absolute value and there are fewer than 2^33 of them
            twice_area += cross([a[0].into(), a[1].into()], [b[0].into(), b[1].into()]);
            k = self.next(k);
            if k == h {
                break;
            }
        }
        Cycle { steps, vertices, twice_area }
    }

    /// All faces: every half-edge lies on exactly one walk; the walk with the least area
    /// (the only one with area <= 0) is the unbounded face, the others are the bounded
    /// faces, each a 2-cell whose signed boundary is its chain. Euler: `V - E + F = 2`
    /// counting the unbounded face. O(E log E).
    pub fn extract(&self) -> Arrangement {
        let mut seen = vec![false; 2 * self.edges.len()];
        let mut walks = Vec::new();
        for h in 0..seen.len() {
            if !seen[h] {
                walks.push(self.walk(h as u32, &mut seen));
            }
        }
        let outer_at =
            walks.iter().enumerate().min_by_key(|(_, w)| w.twice_area).map(|(i, _)| i).expect("at least one edge");
        let outer = walks.remove(outer_at);
        Arrangement { faces: walks, outer, vertices: self.points.len(), edges: self.edges.clone() }
    }
}

/// Every pair of edges meets at most at a common vertex. O(E^2).
fn check_plane(points: &[[i32; 2]], edges: &[[u32; 2]]) -> Result<(), ArrangementError> {
    let p = |v: u32| points[v as usize];
    // whether c lies on the closed segment ab
    let on = |a: [i32; 2], b: [i32; 2], c: [i32; 2]| cross(sub(a, b), sub(a, c)) == 0 && dot(sub(c, a), sub(c, b)) <= 0;
    for (e, &[a, b]) in edges.iter().enumerate() {
        for (f, &[c, d]) in edges.iter().enumerate().skip(e + 1) {
            let shared = [a, b].into_iter().find(|v| *v == c || *v == d);
            if let Some(s) = shared {
                // two edges from one vertex overlap when they leave it the same way
                let x = if s == a { b } else { a };
                let y = if s == c { d } else { c };
                let (u, w) = (sub(p(s), p(x)), sub(p(s), p(y)));
                if cross(u, w) == 0 && dot(u, w) > 0 {
                    return Err(if on(p(s), p(x), p(y)) {
                        ArrangementError::VertexOnEdge { vertex: y, edge: e }
                    } else {
                        ArrangementError::VertexOnEdge { vertex: x, edge: f }
                    });
                }
                continue;
            }
            for (v, (s, t), g) in [(c, (a, b), e), (d, (a, b), e), (a, (c, d), f), (b, (c, d), f)] {
                if on(p(s), p(t), p(v)) {
                    return Err(ArrangementError::VertexOnEdge { vertex: v, edge: g });
                }
            }
            let side = |s: u32, t: u32, v: u32| cross(sub(p(s), p(t)), sub(p(s), p(v))).signum();
            if side(a, b, c) * side(a, b, d) < 0 && side(c, d, a) * side(c, d, b) < 0 {
                return Err(ArrangementError::Crossing { first: e, second: f });
            }
        }
    }
    Ok(())
}
