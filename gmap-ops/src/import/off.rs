//! Polygon meshes (`.off`) as 2-maps.
//!
//! A polygon with k vertices `v_0 … v_{k-1}` becomes one face of `2k` darts: the darts
//! `2j` and `2j + 1` lie on its edge `j` (from `v_j` to `v_{j+1}`), at `v_j` and at
//! `v_{j+1}`; `alpha_0` swaps them, `alpha_1` joins dart `2j + 1` to dart `2j + 2` at the
//! corner `v_{j+1}`. An edge shared by two polygons is `alpha_2`-sewn dart by dart at equal
//! vertices, whatever the orientation of the two polygons (so a Möbius band or a Klein
//! bottle imports); an edge of one polygon stays 2-free (the boundary); an edge in three or
//! more polygons is refused. Each dart carries the point of its vertex.

use std::path::Path;

use gmap_core::{Dart, DenseMap, Point};

use gmap_core::io::shorten;

use super::common::{default_max_darts, FileError, ImportError};

/// A polygon mesh: points, and polygons as lists of point indices, each with its input line.
#[derive(Clone, Debug, PartialEq)]
pub struct PolygonMesh {
    /// the vertex positions
    pub points: Vec<Point>,
    /// the polygons, as indices into `points`
    pub polygons: Vec<Vec<u32>>,
    /// the 1-based input line of each polygon (0 when built in code)
    pub lines: Vec<usize>,
}

impl PolygonMesh {
    /// Parses the OFF format: a header `OFF` (optionally followed by the counts on the same
    /// line), the counts `vertices faces edges`, one vertex per line (`x y z`, finite numbers,
    /// extra values ignored), one polygon per line (`k i_1 … i_k`, extra values such as
    /// colours ignored), nothing but comments and blank lines after the last polygon. `#`
    /// starts a comment. Errors name the line and quote at most 40 characters of a token.
    /// O(size of the text). No dart limit: see [`PolygonMesh::parse_limited`].
    pub fn parse(text: &str) -> Result<Self, ImportError> {
        Self::parse_limited(text, u32::MAX as u64 - 1)
    }

    /// [`PolygonMesh::parse`], refusing as soon as the polygons read or announced make more
    /// than `max_darts` darts (two per polygon side; every polygon has at least three sides),
    /// before the polygons are stored.
    pub fn parse_limited(text: &str, max_darts: u64) -> Result<Self, ImportError> {
        let mut lines = text
            .lines()
            .enumerate()
            .map(|(k, l)| (k + 1, l.split('#').next().unwrap_or("").trim()))
            .filter(|(_, l)| !l.is_empty());
        let syntax = |line: usize, message: String| ImportError::Syntax { line, message };
        let q = |t: &str| shorten(t.as_bytes(), 40);
        let (hl, header) = lines.next().ok_or(ImportError::Empty)?;
        let mut toks: Vec<&str> = header.split_whitespace().take(8).collect();
        if toks.first() != Some(&"OFF") {
            return Err(syntax(hl, format!("expected the header 'OFF', found '{}'", q(header))));
        }
        toks.remove(0);
        let mut cl = hl;
        if toks.is_empty() {
            let (l, c) = lines.next().ok_or_else(|| syntax(hl, "missing the counts line".into()))?;
            cl = l;
            toks = c.split_whitespace().take(8).collect();
        }
        if toks.len() < 2 {
            return Err(syntax(cl, "expected 'vertices faces edges'".into()));
        }
        let count = |t: &str| t.parse::<u32>().map_err(|_| syntax(cl, format!("'{}' is not a count", q(t))));
        let (nv, nf) = (count(toks[0])?, count(toks[1])?);
        let limit = max_darts.min(u32::MAX as u64 - 1);
        let too_many = |facets: usize, darts: Option<u64>| ImportError::TooManyDarts { facets, dim: 2, darts, limit };
        // every polygon has at least three sides, two darts each
        if 6 * nf as u64 > limit {
            return Err(too_many(nf as usize, Some(6 * nf as u64)));
        }
        let mut points = Vec::new();
        for k in 0..nv {
            let (l, body) = lines.next().ok_or_else(|| syntax(cl, format!("expected {nv} vertices, found {k}")))?;
            let xs: Vec<&str> = body.split_whitespace().take(3).collect();
            if xs.len() < 3 {
                return Err(syntax(l, "a vertex needs three coordinates".into()));
            }
            let mut p = [0.0; 3];
            for (c, t) in p.iter_mut().zip(&xs) {
                *c = t
                    .parse::<f64>()
                    .ok()
                    .filter(|v| v.is_finite())
                    .ok_or_else(|| syntax(l, format!("'{}' is not a finite coordinate", q(t))))?;
            }
            points.push(p);
        }
        let mut polygons = Vec::new();
        let mut plines = Vec::new();
        let mut darts = 0u64;
        for k in 0..nf {
            let (l, body) = lines.next().ok_or_else(|| syntax(cl, format!("expected {nf} polygons, found {k}")))?;
            let mut xs = body.split_whitespace();
            let first = xs.next().unwrap_or("");
            let size =
                first.parse::<usize>().map_err(|_| syntax(l, format!("'{}' is not a vertex count", q(first))))?;
            let mut poly = Vec::with_capacity(size.min(body.len()));
            for t in xs.by_ref().take(size) {
                let v = t.parse::<u32>().map_err(|_| syntax(l, format!("'{}' is not a vertex index", q(t))))?;
                if v >= nv {
                    return Err(syntax(l, format!("vertex index {v} out of range (the mesh has {nv} vertices)")));
                }
                poly.push(v);
            }
            if poly.len() < size {
                return Err(syntax(l, format!("the polygon announces {size} vertices but lists {}", poly.len())));
            }
            darts = darts.saturating_add(2 * size as u64);
            if darts > limit {
                return Err(too_many(k as usize + 1, Some(darts)));
            }
            polygons.push(poly);
            plines.push(l);
        }
        if let Some((l, body)) = lines.next() {
            return Err(syntax(
                l,
                format!("'{}' after the {nf} polygons the header announces: the counts are wrong", q(body)),
            ));
        }
        Ok(PolygonMesh { points, polygons, lines: plines })
    }

    /// Whether the mesh can become a 2-map: every polygon has at least 3 vertices and no
    /// edge from a vertex to itself, and no edge lies in three or more polygons.
    pub fn check(&self) -> Result<(), ImportError> {
        self.edge_pairs().map(|_| ())
    }

    /// The 2-map of the mesh (module docs), with points. O(E log E) for E polygon edges.
    pub fn to_gmap(&self) -> Result<DenseMap, ImportError> {
        let pairs = self.edge_pairs()?;
        let mut offsets = Vec::with_capacity(self.polygons.len() + 1);
        let mut total = 0usize;
        for p in &self.polygons {
            offsets.push(total);
            total =
                total.checked_add(2 * p.len()).filter(|&t| t < u32::MAX as usize).ok_or(ImportError::TooManyDarts {
                    facets: self.polygons.len(),
                    dim: 2,
                    darts: None,
                    limit: u32::MAX as u64 - 1,
                })?;
        }
        if total == 0 {
            return Err(ImportError::Empty);
        }
        let mut m = DenseMap::try_new(2, total).map_err(|_| ImportError::OutOfMemory {
            what: format!("a map of {total} darts"),
            bytes: total as u64 * 12,
        })?;
        for (f, p) in self.polygons.iter().enumerate() {
            let k = p.len();
            let o = offsets[f];
            for j in 0..k {
                let a = Dart::new((o + 2 * j) as u32);
                let b = Dart::new((o + 2 * j + 1) as u32);
                m.link(a, b, 0);
                m.link(b, Dart::new((o + (2 * j + 2) % (2 * k)) as u32), 1);
                m.set_point(a, Some(self.points[p[j] as usize]));
                m.set_point(b, Some(self.points[p[(j + 1) % k] as usize]));
            }
        }
        // dart of polygon f's edge j at vertex v
        let at = |f: usize, j: usize, v: u32| {
            let p = &self.polygons[f];
            let o = offsets[f] + 2 * j;
            Dart::new(if p[j] == v { o } else { o + 1 } as u32)
        };
        for ((f, j), (g, k)) in pairs {
            let p = &self.polygons[f];
            let (u, v) = (p[j], p[(j + 1) % p.len()]);
            m.link(at(f, j, u), at(g, k, u), 2);
            m.link(at(f, j, v), at(g, k, v), 2);
        }
        Ok(m)
    }

    /// The pairs of (polygon, edge index) sharing an edge; errors for degenerate polygons
    /// and edges in three or more polygons.
    #[allow(clippy::type_complexity)]
    fn edge_pairs(&self) -> Result<Vec<((usize, usize), (usize, usize))>, ImportError> {
        if self.polygons.is_empty() {
            return Err(ImportError::Empty);
        }
        let mut edges: Vec<(u32, u32, usize, usize)> = Vec::new();
        for (f, p) in self.polygons.iter().enumerate() {
            let line = self.lines.get(f).copied().unwrap_or(0);
            if p.len() < 3 {
                return Err(ImportError::DegeneratePolygon { line, reason: format!("{} vertices", p.len()) });
            }
            for j in 0..p.len() {
                let (u, v) = (p[j], p[(j + 1) % p.len()]);
                if u == v {
                    return Err(ImportError::DegeneratePolygon {
                        line,
                        reason: format!("edge from vertex {u} to itself"),
                    });
                }
                edges.push((u.min(v), u.max(v), f, j));
            }
        }
        edges.sort_unstable();
        let mut out = Vec::new();
        let mut s = 0;
        while s < edges.len() {
            let mut e = s + 1;
            while e < edges.len() && edges[e].0 == edges[s].0 && edges[e].1 == edges[s].1 {
                e += 1;
            }
            match e - s {
                1 => {}
                2 => out.push(((edges[s].2, edges[s].3), (edges[s + 1].2, edges[s + 1].3))),
                _ => {
                    let lines = edges[s..e].iter().map(|x| self.lines.get(x.2).copied().unwrap_or(0)).collect();
                    return Err(ImportError::EdgeInManyPolygons { u: edges[s].0, v: edges[s].1, lines });
                }
            }
            s = e;
        }
        Ok(out)
    }
}

/// Reads an `.off` file into a 2-map with points, with the default dart limit
/// ([`default_max_darts`]); see [`read_off_with`].
pub fn read_off(path: &Path) -> Result<DenseMap, FileError> {
    read_off_with(path, None)
}

/// Reads an `.off` file into a 2-map with points, refusing more than `max_darts` darts
/// (default: [`default_max_darts`]) while the polygons are read, before the map is built.
pub fn read_off_with(path: &Path, max_darts: Option<u64>) -> Result<DenseMap, FileError> {
    let text = super::common::read_text(path)?;
    let limit = max_darts.unwrap_or_else(|| default_max_darts(2));
    PolygonMesh::parse_limited(&text, limit).and_then(|m| m.to_gmap()).map_err(|e| FileError::new(path, e))
}

/// CGAL's `import_from_polyhedron_3` for a polyhedron read from `.off` text: the 2-map of
/// its faces, 2-sewn along their shared edges, each vertex with its point, as an editable
/// [`gmap_core::GMap`] ([`PolygonMesh::parse`] then [`PolygonMesh::to_gmap`], with their
/// errors).
///
/// ```
/// use gmap_ops::import::off::import_from_polyhedron_3;
/// let off = "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n";
/// let g = import_from_polyhedron_3(off).unwrap();
/// assert_eq!((g.cell_counts(), g.point_count()), (vec![4, 6, 4], 4));
/// assert!(g.is_face_combinatorial_polygon(g.darts().next().unwrap(), 3));
/// ```
pub fn import_from_polyhedron_3(text: &str) -> Result<gmap_core::GMap, ImportError> {
    let mesh = PolygonMesh::parse(text)?;
    Ok(gmap_core::GMap::from_dense(&mesh.to_gmap()?).0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn two_triangles_make_a_square() {
        let text = "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 3 2 # reversed\n";
        let mesh = PolygonMesh::parse(text).unwrap();
        let m = mesh.to_gmap().unwrap();
        m.validate().unwrap();
        assert_eq!(m.dart_count(), 12);
        assert_eq!(m.cell_counts(), vec![4, 5, 2]);
        assert!(m.is_orientable());
        assert_eq!(m.vertex_point(Dart::new(0)), Some([0.0, 0.0, 0.0]));
    }

    #[test]
    fn errors() {
        let e = PolygonMesh::parse("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n").unwrap_err();
        assert!(matches!(e, ImportError::Syntax { line: 6, .. }));
        let fan = "OFF 4 3 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n3 0 1 3\n3 1 0 2\n";
        let mesh = PolygonMesh::parse(fan).unwrap();
        match mesh.to_gmap().unwrap_err() {
            ImportError::EdgeInManyPolygons { u, v, lines } => assert_eq!((u, v, lines), (0, 1, vec![6, 7, 8])),
            e => panic!("{e}"),
        }
        let e = PolygonMesh::parse("OFF 2 1 0\n0 0 0\n1 0 0\n3 0 1 1\n").unwrap().to_gmap().unwrap_err();
        assert!(matches!(e, ImportError::DegeneratePolygon { line: 4, .. }));
        assert!(matches!(PolygonMesh::parse("PLY\n"), Err(ImportError::Syntax { line: 1, .. })));
    }
}
