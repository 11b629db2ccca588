//! CGAL's insertions where they differ from the subdividers of `split`: a vertex in an
//! edge with a free end (CGAL closes it there), and a face along a path of 2-free darts
//! (CGAL hangs the face on it instead of splitting a volume).

use rustc_hash::FxHashMap as HashMap;

use gmap_core::{AlphaSet, Attributes, DartId, GMap, Point};

use super::common::{debug_check, live, reconcile};
use super::split::split_counted;
use super::EulerError;

/// CGAL's vertex insertion in the edge of `d` (`n >= 1`): every dart `x` of the edge gets
/// a new dart `x'` with `alpha_0(x) = x'`; the new darts of two darts that were
/// `alpha_0`-linked are `alpha_1`-linked, and they copy the edge's other links (`alpha_j`,
/// `j >= 2`). A 0-free dart's new dart is the end the edge lacked. Returns
/// `alpha_0(d)`, a dart of the new vertex, which gets `point`.
pub(super) fn insert_vertex_as_cgal<A: Attributes>(
    g: &mut GMap<A>,
    d: DartId,
    point: Option<Point>,
) -> Result<DartId, EulerError> {
    live(g, d)?;
    let n = g.dim();
    if n < 1 {
        return Err(EulerError::BadDimension { what: "vertex insertion", lo: 1, hi: n, got: 1 });
    }
    let edge = g.orbit(d, AlphaSet::cell(1, n));
    let old: Vec<[DartId; 2]> = edge.iter().map(|&x| [g.alpha(x, 0), x]).collect();
    let mut new: HashMap<DartId, DartId> = HashMap::default();
    for &x in &edge {
        new.insert(x, g.create_dart());
    }
    for (k, &x) in edge.iter().enumerate() {
        let nx = new[&x];
        let p = old[k][0];
        if p != x {
            g.link(nx, new[&p], 1);
        }
        for j in 2..=n {
            let y = g.alpha(x, j);
            if y != x {
                g.link(nx, new[&y], j);
            }
        }
    }
    for &x in &edge {
        g.link(x, new[&x], 0);
    }
    if g.needs_reconcile() {
        let mut touched = edge.clone();
        touched.extend(edge.iter().map(|x| new[x]));
        reconcile(g, &touched);
    }
    let v = new[&d];
    if point.is_some() {
        g.set_point(v, point);
    }
    debug_check(g);
    Ok(v)
}

/// CGAL's `is_insertable_cell_2_in_cell_3`: `n >= 3`, a non-empty path of live darts, one
/// per edge, each not 0-free, where `alpha_0` of each dart and the next (the last and the
/// first) lie in one vertex of one volume (an orbit of `alpha_1`, `alpha_2`).
pub(super) fn is_cgal_path<A: Attributes>(g: &GMap<A>, path: &[DartId]) -> bool {
    if g.dim() < 3 || path.is_empty() || path.iter().any(|&x| !g.contains(x) || g.is_free(x, 0)) {
        return false;
    }
    let corner = AlphaSet::of(&[1, 2]);
    path.iter().enumerate().all(|(k, &x)| {
        let next = path.get(k + 1).copied().unwrap_or(path[0]);
        g.orbit(g.alpha(x, 0), corner).contains(&next)
    })
}

/// Whether the path is free for every `alpha_j`, `j >= 4` (always true in a 3-map): then
/// CGAL's construction needs no copy of the new face beyond `alpha_3`.
fn free_above_3<A: Attributes>(g: &GMap<A>, path: &[DartId]) -> bool {
    path.iter().all(|&x| (4..=g.dim()).all(|j| g.is_free(x, j) && g.is_free(g.alpha(x, 0), j)))
}

/// CGAL's face insertion along a path ([`is_cgal_path`]): a face of two darts per path edge,
/// `alpha_2`-linked to the path; when a path dart was not 2-free, a second copy of the
/// face, `alpha_3`-linked to the first, takes its old `alpha_2` partner. Returns
/// `alpha_0` of the face's first dart, CGAL's result. A path that is not CGAL's (darts in
/// any order), or one with `alpha_j` links for `j >= 4`, goes to the volume split of
/// [`super::try_split_cell`] with its precondition.
pub(super) fn insert_face_as_cgal<A: Attributes>(g: &mut GMap<A>, path: &[DartId]) -> Result<DartId, EulerError> {
    if !is_cgal_path(g, path) || !free_above_3(g, path) {
        return split_counted(g, path, 3, None).map(|(_, f)| f);
    }
    let twin = path.iter().any(|&x| !g.is_free(x, 2));
    let mut touched: Vec<DartId> = Vec::new();
    let mut faces: Vec<[DartId; 4]> = Vec::with_capacity(path.len());
    for &x in path {
        let (a, b) = (g.create_dart(), g.create_dart());
        g.link(a, b, 0);
        let (y, x0) = (g.alpha(x, 2), g.alpha(x, 0));
        let y0 = g.alpha(y, 0);
        g.link(x, a, 2);
        g.link(x0, b, 2);
        let (mut a3, mut b3) = (a, b);
        if twin {
            (a3, b3) = (g.create_dart(), g.create_dart());
            g.link(a3, b3, 0);
            g.link(a, a3, 3);
            g.link(b, b3, 3);
            if y != x {
                g.link(y, a3, 2);
                g.link(y0, b3, 2);
            }
        }
        touched.extend([x, x0, y, y0, a, b, a3, b3]);
        faces.push([a, b, a3, b3]);
    }
    for k in 0..faces.len() {
        let next = faces[(k + 1) % faces.len()];
        g.link(faces[k][1], next[0], 1);
        if twin {
            g.link(faces[k][3], next[2], 1);
        }
    }
    reconcile(g, &touched);
    debug_check(g);
    Ok(faces[0][1])
}

/// CGAL's dangling edge at a 1-free dart `d` (`n >= 2`): every dart `x` of the orbit of `d`
/// under `alpha_3 … alpha_n` gets a new edge of two darts `a_x`, `b_x` (`alpha_0`-linked),
/// `a_x` `alpha_1`-linked to `x`, the copies linked across `alpha_3 … alpha_n` as the `x`
/// are. A lone dart becomes a corner with a dangling edge: two vertices, two edges (CGAL's
/// `GMap_test_insertions.h`). Returns `b_d`, the dart of the new vertex.
pub(super) fn dangling_at_free_dart<A: Attributes>(
    g: &mut GMap<A>,
    d: DartId,
    point: Option<Point>,
) -> Result<DartId, EulerError> {
    live(g, d)?;
    let n = g.dim();
    if n < 2 {
        return Err(EulerError::BadDimension { what: "dangling edge", lo: 2, hi: n, got: n });
    }
    if !g.is_free(d, 1) {
        return Err(EulerError::Misplaced { dart: d, what: "a 1-free dart" });
    }
    let copies = g.orbit(d, AlphaSet::range(3, n));
    let mut new: HashMap<DartId, (DartId, DartId)> = HashMap::default();
    for &x in &copies {
        let (a, b) = (g.create_dart(), g.create_dart());
        g.link(a, b, 0);
        g.link(x, a, 1);
        new.insert(x, (a, b));
    }
    for &x in &copies {
        for k in 3..=n {
            let y = g.alpha(x, k);
            if y != x {
                let ((a, b), (ay, by)) = (new[&x], new[&y]);
                g.link(a, ay, k);
                g.link(b, by, k);
            }
        }
    }
    let mut touched = copies.clone();
    touched.extend(new.values().flat_map(|&(a, b)| [a, b]));
    reconcile(g, &touched);
    let tip = new[&d].1;
    if point.is_some() {
        g.set_point(tip, point);
    }
    debug_check(g);
    Ok(tip)
}
