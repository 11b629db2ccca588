//! CGAL's `import_from_plane_graph`: a graph embedded in the plane, as text — the number
//! of vertices and of edges, then `x y` per vertex, then the two vertex numbers (from 0) of
//! each edge — made into a closed 2-map with points: every edge has its two sides, the
//! edges around each vertex are ordered by angle, and every face of the plane embedding,
//! the outer face of each connected piece included, is a 2-cell (so a connected graph gives
//! a sphere: χ = 2 per component).
//!
//! ```
//! use gmap_ops::import::plane_graph::import_from_plane_graph;
//! // a square with one diagonal: 4 vertices, 5 edges, 2 inner faces and the outer one
//! let g = import_from_plane_graph("4 5\n0 0\n1 0\n1 1\n0 1\n0 1\n1 2\n2 3\n3 0\n0 2\n").unwrap();
//! assert_eq!(g.cell_counts(), vec![4, 5, 3]);
//! assert_eq!(g.euler_characteristic(), 2);
//! ```

use gmap_core::{DartId, GMap};

use super::common::ImportError;

/// The tokens of the text with their line numbers.
fn tokens(text: &str) -> impl Iterator<Item = (usize, &str)> + '_ {
    text.lines().enumerate().flat_map(|(k, l)| l.split_whitespace().map(move |t| (k + 1, t)))
}

fn syntax(line: usize, message: impl Into<String>) -> ImportError {
    ImportError::Syntax { line, message: message.into() }
}

/// The vertices' points and the edges of a plane graph.
type PlaneGraph = (Vec<[f64; 2]>, Vec<[usize; 2]>);

/// Parses CGAL's plane-graph text: the vertices' points and the edges.
fn parse(text: &str) -> Result<PlaneGraph, ImportError> {
    let mut it = tokens(text);
    let mut last = 1;
    let mut next = |what: &str| -> Result<(usize, String), ImportError> {
        match it.next() {
            Some((l, t)) => {
                last = l;
                Ok((l, t.to_string()))
            }
            None => Err(syntax(last, format!("the text ends where {what} was expected"))),
        }
    };
    let mut count = |what: &str| -> Result<usize, ImportError> {
        let (l, t) = next(what)?;
        t.parse().map_err(|_| syntax(l, format!("{what}: expected a count, found {t:?}")))
    };
    let (nv, ne) = (count("the number of vertices")?, count("the number of edges")?);
    if nv == 0 {
        return Err(ImportError::Empty);
    }
    let mut points = Vec::with_capacity(nv.min(1 << 20));
    for _ in 0..nv {
        let mut p = [0.0; 2];
        for c in &mut p {
            let (l, t) = next("a coordinate")?;
            *c = t
                .parse()
                .ok()
                .filter(|x: &f64| x.is_finite())
                .ok_or_else(|| syntax(l, format!("not a coordinate: {t:?}")))?;
        }
        points.push(p);
    }
    let mut edges = Vec::with_capacity(ne.min(1 << 20));
    for _ in 0..ne {
        let mut e = [0; 2];
        for v in &mut e {
            let (l, t) = next("a vertex number")?;
            *v = t
                .parse()
                .ok()
                .filter(|&k: &usize| k < nv)
                .ok_or_else(|| syntax(l, format!("not a vertex number below {nv}: {t:?}")))?;
        }
        if e[0] == e[1] {
            return Err(syntax(last, format!("edge {} {} is a loop", e[0], e[1])));
        }
        edges.push(e);
    }
    Ok((points, edges))
}

/// CGAL's `import_from_plane_graph` (see the module): the closed 2-map of the plane graph
/// in `text`, with the points of its vertices. Isolated vertices have no dart and are
/// left out, as in CGAL. Errors name the line of a bad token; a loop edge is refused.
/// O(E log E).
pub fn import_from_plane_graph(text: &str) -> Result<GMap, ImportError> {
    let (points, edges) = parse(text)?;
    let mut g = GMap::new(2);
    // darts of edge k: [at u on its left side, at v left, at u right, at v right]
    let mut darts: Vec<[DartId; 4]> = Vec::with_capacity(edges.len());
    let mut around: Vec<Vec<(f64, usize, bool)>> = vec![Vec::new(); points.len()];
    for (k, &[u, v]) in edges.iter().enumerate() {
        let d: [DartId; 4] = std::array::from_fn(|_| g.create_dart());
        g.link(d[0], d[1], 0);
        g.link(d[2], d[3], 0);
        g.link(d[0], d[2], 2);
        g.link(d[1], d[3], 2);
        darts.push(d);
        let (p, q) = (points[u], points[v]);
        around[u].push(((q[1] - p[1]).atan2(q[0] - p[0]), k, true));
        around[v].push(((p[1] - q[1]).atan2(p[0] - q[0]), k, false));
    }
    for (u, list) in around.iter_mut().enumerate() {
        list.sort_by(|a, b| a.0.total_cmp(&b.0));
        let m = list.len();
        for j in 0..m {
            let (_, k, from_u) = list[j];
            let (_, k2, from_u2) = list[(j + 1) % m];
            // the wedge from this edge to the next counter-clockwise one is a face: on the
            // left of this edge leaving u, on the right of the next
            let left = if from_u { darts[k][0] } else { darts[k][3] };
            let right = if from_u2 { darts[k2][2] } else { darts[k2][1] };
            g.link(left, right, 1);
        }
        if let Some(&(_, k, from_u)) = list.first() {
            let at = if from_u { darts[k][0] } else { darts[k][1] };
            let [x, y] = points[u];
            g.set_point(at, Some([x, y, 0.0]));
        }
    }
    Ok(g)
}
