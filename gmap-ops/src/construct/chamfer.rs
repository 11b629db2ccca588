//! Chamfers (Moka's chamfers of a vertex and of an edge), on surfaces (maps of dimension 2)
//! and on the boundary of a volume (maps of dimension 3, the darts around the chamfered
//! cell 3-free), made of Euler operators.
//!
//! **A vertex** `v` of degree k cut off and replaced by a k-gon:
//!
//! 1. a vertex `w_i` on every edge at `v`, at the fraction `t` of the way from `v` (`mve`,
//!    k of them);
//! 2. in every face at `v`, an edge `w_i w_{i+1}` cutting the corner off (`mef`, k);
//! 3. the k spokes `v w_i` removed (k - 1 `kef` merging the corner triangles into one face,
//!    then the last spoke, dangling, with `v`: `kev`).
//!
//! Δχ = (k - 1) - k + 1 = 0 (vertices, edges, faces; a volume stays one volume).
//!
//! **An edge** `uv` between two faces `f1`, `f2`, both ends of degree 3 (the third faces
//! `f3` at `u` and `f4` at `v`), replaced by a quadrangle, as when a cube's edge is
//! bevelled:
//!
//! 1. a vertex on each of the four other edges at `u` and `v`, at the fraction `t` of the
//!    way from `u` or `v` (`a`, `b` at `u` in `f1`, `f2`; `c`, `d` at `v`) (`mve`, 4);
//! 2. the edges `ac` across `f1` and `bd` across `f2` (`mef`, 2);
//! 3. the edge `uv` removed, the two strips it separated becoming one face (`kef`);
//! 4. `u` and `v`, now of degree 2, removed, their two edges merged into `ab` and `cd`
//!    (`kve`, 2).
//!
//! Δχ = (4 - 2) - (4 + 2 - 1 - 2) + (2 - 1) = 0.
//!
//! Points: the new vertices get theirs on the edges. Attributes follow the operators'
//! split and merge rules: the faces around keep theirs (each loses a strip or a corner to
//! the new face), the new face takes the attribute of the strip or corner cut from the face
//! of the dart given.

use gmap_core::{AlphaSet, Attributes, DartId, GMap};
use rustc_hash::FxHashSet as HashSet;

use super::ConstructError;
use crate::euler::ops::{try_insert_edge, try_insert_vertex_at, try_remove_cell_keeping_homology};

/// Checks the map's dimension (2, or 3 for a chamfer on a volume's boundary) and the
/// fraction `t`.
fn check_map<A: Attributes>(g: &GMap<A>, t: f64) -> Result<(), ConstructError> {
    if !(2..=3).contains(&g.dim()) {
        return Err(ConstructError::BadDimension { what: "a chamfer (on a surface)", lo: 2, hi: 3, got: g.dim() });
    }
    if !(t > 0.0 && t < 1.0) {
        return Err(ConstructError::BadParameter { what: "chamfer fraction", value: t });
    }
    Ok(())
}

/// The corners around the vertex of `d`, one dart `y` per corner (the corner is `y`,
/// `alpha_1(y)`, the next one starts at `alpha_2 alpha_1 (y)`), after checking the
/// chamfer's precondition.
fn check<A: Attributes>(g: &GMap<A>, d: DartId, t: f64) -> Result<Vec<DartId>, ConstructError> {
    if !g.contains(d) {
        return Err(ConstructError::NoSuchDart(d));
    }
    check_map(g, t)?;
    let vertex: HashSet<DartId> = g.orbit(d, AlphaSet::range(1, 2)).into_iter().collect();
    for &x in &vertex {
        for i in 0..=2 {
            if g.is_free(x, i) {
                return Err(ConstructError::NotFree { dart: x, alpha: i });
            }
        }
        if g.dim() == 3 && !g.is_free(x, 3) {
            return Err(ConstructError::BadShape { dart: x, what: "on the boundary of its volume (3-free)" });
        }
        let far = g.alpha(x, 0);
        if vertex.contains(&far) {
            return Err(ConstructError::BadShape { dart: x, what: "an edge with its other end elsewhere" });
        }
        if g.point(x).is_none() {
            return Err(ConstructError::NoPoint(x));
        }
        if g.point(far).is_none() {
            return Err(ConstructError::NoPoint(far));
        }
    }
    let mut corners = Vec::new();
    let mut faces: HashSet<DartId> = HashSet::default();
    let mut y = d;
    loop {
        // each face around the vertex meets it once
        let face = g.orbit(y, AlphaSet::range(0, 1));
        if face.iter().any(|x| faces.contains(x)) {
            return Err(ConstructError::BadShape { dart: y, what: "a vertex met once by each face around it" });
        }
        faces.extend(face);
        corners.push(y);
        y = g.alpha(g.alpha(y, 1), 2);
        if y == d {
            break;
        }
        if corners.len() > vertex.len() {
            return Err(ConstructError::BadShape { dart: d, what: "a disc around the vertex" });
        }
    }
    if corners.len() < 3 || 2 * corners.len() != vertex.len() {
        return Err(ConstructError::BadShape { dart: d, what: "a vertex of degree three or more, a disc around it" });
    }
    Ok(corners)
}

/// Whether [`try_chamfer_vertex`] would succeed: a 2-map, or a 3-map with the darts of the
/// vertex 3-free (the vertex on the boundary of its volume); `0 < t < 1`; the vertex of `d`
/// is inside the surface (no 0-, 1- or 2-free dart around it), of degree k >= 3, each face around it
/// meeting it once, each edge at it having its other end elsewhere, and it and its
/// neighbours have points. O(size of the faces around the vertex).
pub fn can_chamfer_vertex<A: Attributes>(g: &GMap<A>, d: DartId, t: f64) -> bool {
    check(g, d, t).is_ok()
}

/// Cuts off the vertex of `d`, of degree k, replacing it by a k-gon whose corners lie on
/// its edges at the fraction `t` of their length from it (see the [module docs](self)).
/// Returns a dart of the new face. Δχ = 0 (asserted in the tests). O(k · size of the faces
/// around the vertex).
pub fn try_chamfer_vertex<A: Attributes>(g: &mut GMap<A>, d: DartId, t: f64) -> Result<DartId, ConstructError> {
    let corners = check(g, d, t)?;
    // 1. a vertex on every edge at v: corner y's dart is on the edge of y
    for &y in &corners {
        split_edge_at(g, y, t)?;
    }
    // 2. in every face, the corner cut off between the new vertices on its two edges
    let mut face = None;
    for &y in &corners {
        let (a, b) = (g.alpha(y, 0), g.alpha(g.alpha(y, 1), 0));
        try_insert_edge(g, a, b)?;
        // the new edge's dart on the corner triangle's side
        face.get_or_insert(g.alpha(a, 1));
    }
    // 3. the spokes removed: k - 1 merges, then the last one dangling, with v
    for &y in &corners {
        try_remove_cell_keeping_homology(g, y, 1)?;
    }
    Ok(face.expect("three corners or more"))
}

/// Like [`try_chamfer_vertex`], panicking when the precondition fails.
#[track_caller]
pub fn chamfer_vertex<A: Attributes>(g: &mut GMap<A>, d: DartId, t: f64) -> DartId {
    try_chamfer_vertex(g, d, t).unwrap_or_else(|e| panic!("chamfer_vertex: {e}"))
}

/// Inserts a vertex on the edge of `y` at the fraction `t` of the way from the vertex of
/// `y` (both ends have points: the caller checked); `alpha_0(y)` is then the new vertex's.
fn split_edge_at<A: Attributes>(g: &mut GMap<A>, y: DartId, t: f64) -> Result<(), ConstructError> {
    let p = g.point(y).expect("checked");
    let q = g.point(g.alpha(y, 0)).expect("checked");
    let w = [p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1]), p[2] + t * (q[2] - p[2])];
    try_insert_vertex_at(g, y, Some(w))?;
    Ok(())
}

/// The chamfer of the edge of `d` as planned by [`check_edge`]: the darts at its ends.
struct EdgePlan {
    /// at `u` in `f1` (the dart given), at `v` in `f1`, at `u` in `f2`, at `v` in `f2`
    ends: [DartId; 4],
}

/// Checks the precondition of [`try_chamfer_edge`].
fn check_edge<A: Attributes>(g: &GMap<A>, d: DartId, t: f64) -> Result<EdgePlan, ConstructError> {
    if !g.contains(d) {
        return Err(ConstructError::NoSuchDart(d));
    }
    check_map(g, t)?;
    let (du, dv) = (d, g.alpha(d, 0));
    if du == dv {
        return Err(ConstructError::NotFree { dart: d, alpha: 0 });
    }
    let (eu, ev) = (g.alpha(du, 2), g.alpha(dv, 2));
    // both ends: inside the surface, each face around met once, points, degree 3
    for end in [du, dv] {
        let corners = check(g, end, t)?;
        if corners.len() != 3 {
            return Err(ConstructError::BadShape {
                dart: end,
                what: "a vertex of degree 3 (an end of a chamfered edge)",
            });
        }
    }
    let vertex_u: HashSet<DartId> = g.orbit(du, AlphaSet::range(1, 2)).into_iter().collect();
    if vertex_u.contains(&dv) {
        return Err(ConstructError::BadShape { dart: d, what: "an edge with two distinct ends" });
    }
    let f1: HashSet<DartId> = g.orbit(du, AlphaSet::range(0, 1)).into_iter().collect();
    if f1.contains(&eu) {
        return Err(ConstructError::BadShape { dart: d, what: "an edge between two distinct faces" });
    }
    for f in [du, eu] {
        if g.orbit(f, AlphaSet::range(0, 1)).len() < 6 {
            return Err(ConstructError::BadShape { dart: f, what: "a face of three sides or more" });
        }
    }
    Ok(EdgePlan { ends: [du, dv, eu, ev] })
}

/// Whether [`try_chamfer_edge`] would succeed: a 2-map, or a 3-map with the darts around
/// the edge's ends 3-free; `0 < t < 1`; the edge of `d` has two distinct ends, each inside
/// the surface, of degree 3, each face around it met once, and it and its neighbours have
/// points; the edge separates two distinct faces of three sides or more. O(size of the
/// faces around the edge).
pub fn can_chamfer_edge<A: Attributes>(g: &GMap<A>, d: DartId, t: f64) -> bool {
    check_edge(g, d, t).is_ok()
}

/// Replaces the edge of `d` by a quadrangle whose corners lie on the four other edges at its
/// ends, at the fraction `t` of their length from the ends (see the [module docs](self)).
/// Returns the dart of the new face at the corner on the edge `alpha_1(d)`. Δχ = 0
/// (asserted in the tests). O(size of the faces around the edge).
pub fn try_chamfer_edge<A: Attributes>(g: &mut GMap<A>, d: DartId, t: f64) -> Result<DartId, ConstructError> {
    let EdgePlan { ends: [du, dv, eu, ev] } = check_edge(g, d, t)?;
    // the darts at u and v on the four other edges: they survive until their vertex goes
    let sides = [du, dv, eu, ev].map(|x| g.alpha(x, 1));
    // 1. a vertex on each: alpha_0 of the side dart is then at the new vertex
    for &y in &sides {
        split_edge_at(g, y, t)?;
    }
    let [a, c, b, e] = sides.map(|y| g.alpha(y, 0));
    // 2. the strips cut off the two faces along the edge
    try_insert_edge(g, a, c)?;
    try_insert_edge(g, b, e)?;
    // 3. the edge removed: the two strips become one face
    try_remove_cell_keeping_homology(g, du, 1)?;
    // 4. its ends removed, each now on two edges
    try_remove_cell_keeping_homology(g, sides[0], 0)?;
    try_remove_cell_keeping_homology(g, sides[1], 0)?;
    Ok(a)
}

/// Like [`try_chamfer_edge`], panicking when the precondition fails.
#[track_caller]
pub fn chamfer_edge<A: Attributes>(g: &mut GMap<A>, d: DartId, t: f64) -> DartId {
    try_chamfer_edge(g, d, t).unwrap_or_else(|e| panic!("chamfer_edge: {e}"))
}
