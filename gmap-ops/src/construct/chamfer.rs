//! Chamfers on surfaces (maps of dimension 2): a vertex cut off and replaced by a face
//! (Moka's chamfer of a vertex), made of Euler operators:
//!
//! 1. a vertex `w_i` on every edge at the vertex `v`, at the fraction `t` of the way from
//!    `v` (`mve`, k of them for a vertex of degree k);
//! 2. in every face at `v`, an edge `w_i w_{i+1}` cutting the corner off (`mef`, k);
//! 3. the k spokes `v w_i` removed (k - 1 `kef` merging the corner triangles into one face,
//!    then the last spoke, dangling, with `v`: `kev`).
//!
//! The vertex becomes a k-gon: Δχ = (k - 1) - k + 1 = 0 (asserted in the tests). The
//! faces around `v` keep their attributes (each loses its corner to the new face, which
//! takes the attribute of the corner triangle of the dart given, through the operators'
//! split and merge rules); the new vertices get their points on the edges.

use gmap_core::{AlphaSet, Attributes, DartId, GMap};
use rustc_hash::FxHashSet as HashSet;

use super::ConstructError;
use crate::euler::ops::{try_insert_edge, try_insert_vertex_at, try_remove_cell};

/// The corners around the vertex of `d`, one dart `y` per corner (the corner is `y`,
/// `alpha_1(y)`, the next one starts at `alpha_2 alpha_1 (y)`), after checking the
/// chamfer's precondition.
fn check<A: Attributes>(g: &GMap<A>, d: DartId, t: f64) -> Result<Vec<DartId>, ConstructError> {
    if !g.contains(d) {
        return Err(ConstructError::NoSuchDart(d));
    }
    if g.dim() != 2 {
        return Err(ConstructError::BadDimension { what: "a chamfer (on a surface)", lo: 2, hi: 2, got: g.dim() });
    }
    if !(t > 0.0 && t < 1.0) {
        return Err(ConstructError::BadParameter { what: "chamfer fraction", value: t });
    }
    let vertex: HashSet<DartId> = g.orbit(d, AlphaSet::range(1, 2)).into_iter().collect();
    for &x in &vertex {
        for i in 0..=2 {
            if g.is_free(x, i) {
                return Err(ConstructError::NotFree { dart: x, alpha: i });
            }
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

/// Whether [`try_chamfer_vertex`] would succeed: a 2-map; `0 < t < 1`; the vertex of `d`
/// is inside the surface (no free dart around it), of degree k >= 3, each face around it
/// meeting it once, each edge at it having its other end elsewhere, and it and its
/// neighbours have points. O(size of the faces around the vertex).
pub fn can_chamfer_vertex<A: Attributes>(g: &GMap<A>, d: DartId, t: f64) -> bool {
    check(g, d, t).is_ok()
}

/// Cuts off the vertex of `d`, of degree k, replacing it by a k-gon whose corners lie on
/// its edges at the fraction `t` of their length from it (see the [module docs](self)).
/// Returns a dart of the new face. Δχ = 0. O(k · size of the faces around the vertex).
pub fn try_chamfer_vertex<A: Attributes>(g: &mut GMap<A>, d: DartId, t: f64) -> Result<DartId, ConstructError> {
    let corners = check(g, d, t)?;
    let p = g.point(d).expect("checked");
    // 1. a vertex on every edge at v: corner y's dart is on the edge of y
    for &y in &corners {
        let q = g.point(g.alpha(y, 0)).expect("checked");
        let w = [p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1]), p[2] + t * (q[2] - p[2])];
        try_insert_vertex_at(g, y, Some(w))?;
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
        try_remove_cell(g, y, 1)?;
    }
    Ok(face.expect("three corners or more"))
}

/// Like [`try_chamfer_vertex`], panicking when the precondition fails.
#[track_caller]
pub fn chamfer_vertex<A: Attributes>(g: &mut GMap<A>, d: DartId, t: f64) -> DartId {
    try_chamfer_vertex(g, d, t).unwrap_or_else(|e| panic!("chamfer_vertex: {e}"))
}
