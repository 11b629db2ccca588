//! Shortest non-contractible cycles on surfaces, the edge width and the face width
//! (Erickson–Har-Peled 2004, as CGAL's `Surface_mesh_topology` computes them).
//!
//! From a root `v`: the shortest-path tree `T` of `v`; then faces are peeled off one at a
//! time, a face whose sides are all deleted but one deleting that side's edge (its cycle
//! through `v` is the face's boundary times tree paths: contractible). The tree's edges
//! start deleted. The edges left, `E_nc`, are exactly those whose cycle `T(v,a) e T(b,v)`
//! is not contractible: a contractible one bounds a disc, whose faces the tree cuts into
//! a tree of faces hanging from `e` alone, peeled to the last; and a peeled edge's cycle
//! is contractible by construction. This holds on orientable and non-orientable surfaces,
//! closed or with boundary (a boundary side never blocks a peel). The shortest
//! non-contractible loop through `v` is the shortest of these cycles (Erickson and
//! Har-Peled, Lemma 5.2: a shortest one is two shortest paths and one edge), and the
//! shortest non-contractible cycle is the shortest over every root.
//!
//! Costs: O(E log V) through a given vertex; O(V E log V) for the shortest overall.

use gmap_core::{Dart, DenseMap};

use crate::curves::error::CurveError;
use crate::curves::surface::{Surface, Weights};
use crate::curves::tree::{Tree, NONE};

/// Past this many steps (vertices times edges) the search over every root is refused.
pub const CYCLE_WORK_LIMIT: u128 = 20_000_000_000;

/// A closed walk on a graph: `vertices` has one more entry than `edges` (the first vertex
/// again at the end) and edge `edges[k]` joins `vertices[k]` to `vertices[k + 1]`.
#[derive(Clone, Debug, PartialEq)]
pub struct Cycle {
    /// the sum of the weights of its edges
    pub length: f64,
    /// the vertices passed, the first again last
    pub vertices: Vec<u32>,
    /// the edges in order
    pub edges: Vec<u32>,
}

impl Cycle {
    /// The cycle as darts of `map` (the map of `surface`): for each step, the dart of the
    /// edge at the vertex it leaves (CGAL's paths of darts).
    pub fn darts(&self, surface: &Surface, map: &DenseMap) -> Vec<Dart> {
        self.edges
            .iter()
            .zip(&self.vertices)
            .map(|(&e, &x)| {
                let r = surface.reps[1][e as usize];
                if surface.graph.ends(e).0 == x {
                    r
                } else {
                    map.alpha(r, 0)
                }
            })
            .collect()
    }
}

/// The non-tree edges whose cycle through the tree's root is not contractible. O(E).
pub fn non_contractible_edges(s: &Surface, t: &Tree) -> Vec<bool> {
    let g = &s.graph;
    let m = g.edge_count();
    let mut deleted: Vec<bool> = (0..m as u32).map(|e| t.has_edge(g, e)).collect();
    let nf = s.face_count();
    let mut degree: Vec<u32> =
        (0..nf as u32).map(|f| s.sides(f).iter().filter(|&&e| !deleted[e as usize]).count() as u32).collect();
    let mut queue: Vec<u32> = (0..nf as u32).filter(|&f| degree[f as usize] == 1).collect();
    while let Some(f) = queue.pop() {
        if degree[f as usize] != 1 {
            continue;
        }
        let Some(&e) = s.sides(f).iter().find(|&&e| !deleted[e as usize]) else { continue };
        deleted[e as usize] = true;
        for &h in &s.edge_faces[e as usize] {
            if h != NONE {
                degree[h as usize] -= 1;
                if degree[h as usize] == 1 {
                    queue.push(h);
                }
            }
        }
    }
    deleted.iter().map(|&d| !d).collect()
}

/// The shortest non-contractible closed walk through vertex `v` (`None` if every closed
/// walk through `v` is contractible: a sphere, a disc). O(E log V).
pub fn shortest_non_contractible_cycle_through(s: &Surface, v: u32) -> Result<Option<Cycle>, CurveError> {
    let n = s.graph.vertex_count();
    if v as usize >= n {
        return Err(CurveError::NoSuchVertex { vertex: v, vertices: n });
    }
    let t = s.graph.shortest_path_tree(v);
    Ok(best_through(s, &t).map(|(_, e)| cycle_of(s, &t, e)))
}

/// The length and edge of the shortest non-contractible cycle of the tree's root.
fn best_through(s: &Surface, t: &Tree) -> Option<(f64, u32)> {
    let g = &s.graph;
    let keep = non_contractible_edges(s, t);
    let mut best: Option<(f64, u32)> = None;
    for e in (0..g.edge_count() as u32).filter(|&e| keep[e as usize]) {
        let (a, b) = g.ends(e);
        let len = t.dist[a as usize] + g.weight(e) + t.dist[b as usize];
        if len.is_finite() && best.is_none_or(|(l, _)| len < l) {
            best = Some((len, e));
        }
    }
    best
}

/// The cycle root → a, e, b → root.
fn cycle_of(s: &Surface, t: &Tree, e: u32) -> Cycle {
    let (vertices, edges) = t.loop_through(&s.graph, e);
    let length = edges.iter().map(|&x| s.graph.weight(x)).sum();
    Cycle { length, vertices, edges }
}

/// The shortest non-contractible cycle of the surface (`None` on spheres and discs): the
/// shortest over every vertex of [`shortest_non_contractible_cycle_through`]. O(V E log V);
/// refused past [`CYCLE_WORK_LIMIT`] steps.
pub fn shortest_non_contractible_cycle(s: &Surface) -> Result<Option<Cycle>, CurveError> {
    let (n, m) = (s.graph.vertex_count(), s.graph.edge_count());
    let work = n as u128 * m as u128;
    if work > CYCLE_WORK_LIMIT {
        return Err(CurveError::TooLarge {
            what: "the shortest non-contractible cycle",
            work,
            limit: CYCLE_WORK_LIMIT,
        });
    }
    let mut best: Option<(f64, u32, u32)> = None;
    for v in 0..n as u32 {
        let t = s.graph.shortest_path_tree(v);
        if let Some((len, e)) = best_through(s, &t) {
            if best.is_none_or(|(l, _, _)| len < l) {
                best = Some((len, v, e));
            }
        }
    }
    Ok(best.map(|(_, v, e)| cycle_of(s, &s.graph.shortest_path_tree(v), e)))
}

/// The edge width of a 2-map: the fewest edges of a non-contractible cycle, with one
/// (`None` on spheres and discs). O(V E log V).
pub fn edge_width(map: &DenseMap) -> Result<Option<Cycle>, CurveError> {
    shortest_non_contractible_cycle(&Surface::of_map(map, &Weights::Unit)?)
}

/// The face width of a closed surface: the fewest faces a non-contractible closed curve
/// meets when it meets the graph at vertices only.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FaceWidth {
    /// the number of faces (and of vertices) the curve passes
    pub width: usize,
    /// the faces passed, in order
    pub faces: Vec<u32>,
    /// the vertices passed, in order: the curve goes `vertices[k]`, `faces[k]`,
    /// `vertices[k + 1]`, …, back to `vertices[0]`
    pub vertices: Vec<u32>,
}

/// The face width of a closed 2-map (`None` on a sphere): half the edge width of its
/// radial graph (CGAL's method), with a curve realising it. Refuses surfaces with
/// boundary. O(N² log N).
pub fn face_width(map: &DenseMap) -> Result<Option<FaceWidth>, CurveError> {
    let (radial, _) = Surface::radial(map)?;
    let nv = map.cell_count(0) as u32;
    let Some(c) = shortest_non_contractible_cycle(&radial)? else { return Ok(None) };
    let mut w = FaceWidth { width: c.edges.len() / 2, faces: Vec::new(), vertices: Vec::new() };
    // radial cycles alternate vertices and faces; start on a vertex
    let skip = usize::from(c.vertices[0] >= nv);
    for &x in c.vertices[..c.vertices.len() - 1].iter().cycle().skip(skip).take(c.edges.len()) {
        if x < nv {
            w.vertices.push(x);
        } else {
            w.faces.push(x - nv);
        }
    }
    Ok(Some(w))
}

#[cfg(test)]
mod tests;
