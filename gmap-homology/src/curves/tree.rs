//! Graphs with weighted edges and their shortest-path trees (Dijkstra).

use std::cmp::Ordering;
use std::collections::BinaryHeap;

use crate::curves::error::CurveError;

/// No vertex or no edge.
pub const NONE: u32 = u32::MAX;

/// An undirected multigraph: `ends[e]` are the two ends of edge `e` (equal for a loop),
/// `weights[e]` its length, with each vertex's incident edges in a CSR table.
#[derive(Clone, Debug)]
pub struct Graph {
    vertices: usize,
    ends: Vec<(u32, u32)>,
    weights: Vec<f64>,
    start: Vec<usize>,
    incident: Vec<(u32, u32)>,
}

impl Graph {
    /// The graph of `vertices` vertices and edges `ends`, with one weight per edge, each
    /// finite and `≥ 0`. O(V + E).
    pub fn try_new(vertices: usize, ends: Vec<(u32, u32)>, weights: Vec<f64>) -> Result<Self, CurveError> {
        if weights.len() != ends.len() {
            return Err(CurveError::WeightCount { given: weights.len(), edges: ends.len() });
        }
        if let Some((e, &w)) = weights.iter().enumerate().find(|(_, w)| !(w.is_finite() && **w >= 0.0)) {
            return Err(CurveError::BadWeight { edge: e as u32, weight: w });
        }
        if let Some(&(a, b)) = ends.iter().find(|&&(a, b)| a as usize >= vertices || b as usize >= vertices) {
            return Err(CurveError::NoSuchVertex { vertex: a.max(b), vertices });
        }
        let mut start = vec![0usize; vertices + 1];
        for &(a, b) in &ends {
            start[a as usize + 1] += 1;
            if a != b {
                start[b as usize + 1] += 1;
            }
        }
        for v in 0..vertices {
            start[v + 1] += start[v];
        }
        let mut fill = start.clone();
        let mut incident = vec![(0u32, 0u32); start[vertices]];
        for (e, &(a, b)) in ends.iter().enumerate() {
            incident[fill[a as usize]] = (e as u32, b);
            fill[a as usize] += 1;
            if a != b {
                incident[fill[b as usize]] = (e as u32, a);
                fill[b as usize] += 1;
            }
        }
        Ok(Graph { vertices, ends, weights, start, incident })
    }

    /// The number of vertices.
    pub fn vertex_count(&self) -> usize {
        self.vertices
    }

    /// The number of edges.
    pub fn edge_count(&self) -> usize {
        self.ends.len()
    }

    /// The two ends of edge `e`.
    pub fn ends(&self, e: u32) -> (u32, u32) {
        self.ends[e as usize]
    }

    /// The length of edge `e`.
    pub fn weight(&self, e: u32) -> f64 {
        self.weights[e as usize]
    }

    /// The edges at `v` with their other ends (a loop once).
    pub fn incident(&self, v: u32) -> &[(u32, u32)] {
        &self.incident[self.start[v as usize]..self.start[v as usize + 1]]
    }

    /// The shortest-path tree from `root` (Dijkstra, ties broken by the smaller vertex, then
    /// the smaller edge: the same tree every time). O(E log V).
    pub fn shortest_path_tree(&self, root: u32) -> Tree {
        let n = self.vertices;
        let mut t = Tree { root, dist: vec![f64::INFINITY; n], parent: vec![NONE; n], order: Vec::with_capacity(n) };
        let mut done = vec![false; n];
        let mut heap = BinaryHeap::new();
        t.dist[root as usize] = 0.0;
        heap.push(Entry(0.0, root));
        while let Some(Entry(d, v)) = heap.pop() {
            if done[v as usize] {
                continue;
            }
            done[v as usize] = true;
            t.order.push(v);
            for &(e, u) in self.incident(v) {
                let nd = d + self.weights[e as usize];
                let better = nd < t.dist[u as usize]
                    || (nd == t.dist[u as usize] && !done[u as usize] && e < t.parent[u as usize]);
                if u != v && !done[u as usize] && better {
                    t.dist[u as usize] = nd;
                    t.parent[u as usize] = e;
                    heap.push(Entry(nd, u));
                }
            }
        }
        t
    }
}

/// A shortest-path tree: distances from the root (`INFINITY` where unreachable), the tree
/// edge to each vertex's parent ([`NONE`] at the root and where unreachable), and the
/// vertices in the order they were settled (each after its parent).
#[derive(Clone, Debug)]
pub struct Tree {
    /// the root
    pub root: u32,
    /// distance from the root
    pub dist: Vec<f64>,
    /// the edge to the parent
    pub parent: Vec<u32>,
    /// reached vertices, parents first
    pub order: Vec<u32>,
}

impl Tree {
    /// Whether edge `e` of `g` is a tree edge.
    pub fn has_edge(&self, g: &Graph, e: u32) -> bool {
        let (a, b) = g.ends(e);
        self.parent[a as usize] == e || self.parent[b as usize] == e
    }

    /// The tree edges from `v` up to the root, with the vertices passed (from `v`).
    pub fn up(&self, g: &Graph, mut v: u32) -> (Vec<u32>, Vec<u32>) {
        let (mut edges, mut vertices) = (Vec::new(), vec![v]);
        while self.parent[v as usize] != NONE {
            let e = self.parent[v as usize];
            let (a, b) = g.ends(e);
            v = if a == v { b } else { a };
            edges.push(e);
            vertices.push(v);
        }
        (edges, vertices)
    }

    /// The closed walk root → `a`, edge `e`, `b` → root, where `(a, b)` are the ends of
    /// `e`: its vertices (the root first and last) and edges, in order.
    pub fn loop_through(&self, g: &Graph, e: u32) -> (Vec<u32>, Vec<u32>) {
        let (a, b) = g.ends(e);
        let (mut ea, mut va) = self.up(g, a);
        ea.reverse();
        va.reverse();
        let (eb, vb) = self.up(g, b);
        ea.push(e);
        ea.extend(eb);
        va.extend(vb);
        (va, ea)
    }
}

/// A heap entry: the smallest distance first, then the smallest vertex.
#[derive(Clone, Copy, PartialEq)]
struct Entry(f64, u32);

impl Eq for Entry {}

impl Ord for Entry {
    fn cmp(&self, o: &Self) -> Ordering {
        o.0.total_cmp(&self.0).then(o.1.cmp(&self.1))
    }
}

impl PartialOrd for Entry {
    fn partial_cmp(&self, o: &Self) -> Option<Ordering> {
        Some(self.cmp(o))
    }
}
