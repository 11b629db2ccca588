//! Extrusions: an i-cell swept into an (i + 1)-cell along a vector, or along a path of edges
//! one step per edge (Moka's extrusions by an offset and along a path). A face becomes a
//! volume (a prism), an edge a face (a quadrangle), a vertex an edge.
//!
//! The new cell is the product `c × [0, 1]` of the i-cell `c` of `d` with an edge, made of
//! new darts (the product block the revolution shares, laid out as
//! [`crate::build::extrude`]) and `alpha_{i+1}`-sewn to `c` along its bottom copy; the
//! top copy is `c` moved by the vector. Every j-cell of `c` gives a new j-cell (its moved
//! copy) and a new (j + 1)-cell (its sweep), so the Euler characteristic does not change
//! (Δχ = 0, asserted in the tests): the map gains a cell collapsible onto `c`, and its
//! homology is unchanged.
//!
//! Attributes: the sew keeps every attribute and point of `c` (the bottom copy's cells
//! merge into `c`'s); the new cells carry no attribute; every new vertex gets the point of
//! the vertex below it moved by the vector (vertices of `c` without a point give vertices
//! without a point).

use gmap_core::{Attributes, DartId, GMap, Point};

use super::product::{make_slab, place_copy, Profile};
use super::ConstructError;

/// What an extrusion made.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Extruded {
    /// The dart of the new (i + 1)-cell sewn to the dart given (its bottom copy's dart).
    pub cell: DartId,
    /// The dart over the dart given in the moved copy of the cell (the top of the new
    /// cell, `alpha_{i+1}`-free): where a further extrusion starts.
    pub top: DartId,
    /// The change of the Euler characteristic: always 0.
    pub euler_change: i64,
}

/// The checked profile of an extrusion of the i-cell of `d`.
fn check<A: Attributes>(g: &GMap<A>, d: DartId, i: usize) -> Result<Profile, ConstructError> {
    if !g.contains(d) {
        return Err(ConstructError::NoSuchDart(d));
    }
    let n = g.dim();
    if i + 1 > n {
        return Err(ConstructError::BadDimension { what: "an extrusion", lo: 0, hi: n.saturating_sub(1), got: i });
    }
    let prof = Profile::new(g, d, i, i);
    // the sew orbit of alpha_{i+1} is <alpha_0..alpha_{i-1}, alpha_{i+3}..alpha_n>: the
    // cell's darts must be free for alpha_{i+1} and for alpha_{i+3}.. so that the bottom
    // copy pairs with them
    for &x in &prof.darts {
        for j in std::iter::once(i + 1).chain(i + 3..=n) {
            if !g.is_free(x, j) {
                return Err(ConstructError::NotFree { dart: x, alpha: j });
            }
        }
    }
    Ok(prof)
}

/// Whether [`try_extrude_cell`] would succeed: `d` is live, `i < n`, and every dart of the
/// i-cell of `d` (its orbit under `alpha_0..alpha_{i-1}`) is free for `alpha_{i+1}` and
/// for every `alpha_j`, `j >= i + 3` (the cell lies on the boundary, where the new cell
/// attaches). O(cell size · n).
pub fn can_extrude_cell<A: Attributes>(g: &GMap<A>, d: DartId, i: usize) -> bool {
    check(g, d, i).is_ok()
}

/// Extrudes the i-cell of `d` into an (i + 1)-cell along the vector `v`: a new cell
/// `c × [0, 1]` sewn to the cell `c` by `alpha_{i+1}`, its far side `c` moved by `v` (see
/// the [module docs](self)). Precondition: [`can_extrude_cell`] and `v` finite. Δχ = 0.
/// O(s · n²) for a cell of s darts, plus the attribute repair of the sew.
pub fn try_extrude_cell<A: Attributes>(
    g: &mut GMap<A>,
    d: DartId,
    i: usize,
    v: [f64; 3],
) -> Result<Extruded, ConstructError> {
    if let Some(&bad) = v.iter().find(|x| !x.is_finite()) {
        return Err(ConstructError::BadParameter { what: "extrusion vector coordinate", value: bad });
    }
    let prof = check(g, d, i)?;
    Ok(extrude_checked(g, &prof, move |p| [p[0] + v[0], p[1] + v[1], p[2] + v[2]]))
}

/// The extrusion of a checked profile (a cell), its top placed by `f`.
fn extrude_checked<A: Attributes>(g: &mut GMap<A>, prof: &Profile, f: impl Fn(Point) -> Point) -> Extruded {
    let i = prof.p;
    let slab = make_slab(g, prof, false);
    let (d, bottom) = (prof.darts[0], slab[prof.at(0, i + 1, 0)]);
    g.sew(d, bottom, i + 1);
    place_copy(g, prof, &slab, 1, f);
    debug_check(g);
    Extruded { cell: bottom, top: slab[prof.at(0, i + 1, 1)], euler_change: 0 }
}

/// Like [`try_extrude_cell`], panicking when the precondition fails.
#[track_caller]
pub fn extrude_cell<A: Attributes>(g: &mut GMap<A>, d: DartId, i: usize, v: [f64; 3]) -> Extruded {
    try_extrude_cell(g, d, i, v).unwrap_or_else(|e| panic!("extrude_cell: {e}"))
}

/// Whether [`try_extrude_face`] would succeed ([`can_extrude_cell`] with `i = 2`).
pub fn can_extrude_face<A: Attributes>(g: &GMap<A>, d: DartId) -> bool {
    can_extrude_cell(g, d, 2)
}

/// Extrudes the face of `d` into a volume (a prism) along `v` (Moka's extrusion of a face
/// by an offset): [`try_extrude_cell`] with `i = 2`. The face must be 3-free. Δχ = 0.
pub fn try_extrude_face<A: Attributes>(g: &mut GMap<A>, d: DartId, v: [f64; 3]) -> Result<Extruded, ConstructError> {
    try_extrude_cell(g, d, 2, v)
}

/// Like [`try_extrude_face`], panicking when the precondition fails.
#[track_caller]
pub fn extrude_face<A: Attributes>(g: &mut GMap<A>, d: DartId, v: [f64; 3]) -> Extruded {
    try_extrude_face(g, d, v).unwrap_or_else(|e| panic!("extrude_face: {e}"))
}

/// Whether [`try_extrude_edge`] would succeed ([`can_extrude_cell`] with `i = 1`).
pub fn can_extrude_edge<A: Attributes>(g: &GMap<A>, d: DartId) -> bool {
    can_extrude_cell(g, d, 1)
}

/// Extrudes the edge of `d` into a face (a quadrangle) along `v`: [`try_extrude_cell`]
/// with `i = 1`. The edge's darts must be 2-free (a boundary edge). Δχ = 0.
pub fn try_extrude_edge<A: Attributes>(g: &mut GMap<A>, d: DartId, v: [f64; 3]) -> Result<Extruded, ConstructError> {
    try_extrude_cell(g, d, 1, v)
}

/// Like [`try_extrude_edge`], panicking when the precondition fails.
#[track_caller]
pub fn extrude_edge<A: Attributes>(g: &mut GMap<A>, d: DartId, v: [f64; 3]) -> Extruded {
    try_extrude_edge(g, d, v).unwrap_or_else(|e| panic!("extrude_edge: {e}"))
}

/// Whether [`try_extrude_vertex`] would succeed ([`can_extrude_cell`] with `i = 0`).
pub fn can_extrude_vertex<A: Attributes>(g: &GMap<A>, d: DartId) -> bool {
    can_extrude_cell(g, d, 0)
}

/// Extrudes the vertex of `d` into an edge along `v` (a new edge hung at the corner of
/// `d`, its far end at the vertex's point plus `v`): [`try_extrude_cell`] with `i = 0`.
/// `d` must be 1-free. Δχ = 0.
pub fn try_extrude_vertex<A: Attributes>(g: &mut GMap<A>, d: DartId, v: [f64; 3]) -> Result<Extruded, ConstructError> {
    try_extrude_cell(g, d, 0, v)
}

/// Like [`try_extrude_vertex`], panicking when the precondition fails.
#[track_caller]
pub fn extrude_vertex<A: Attributes>(g: &mut GMap<A>, d: DartId, v: [f64; 3]) -> Extruded {
    try_extrude_vertex(g, d, v).unwrap_or_else(|e| panic!("extrude_vertex: {e}"))
}

/// The steps of a path of edges: for each dart, the vector from its vertex to the vertex
/// of `alpha_0` of it.
fn path_steps<A: Attributes>(g: &GMap<A>, path: &[DartId]) -> Result<Vec<[f64; 3]>, ConstructError> {
    path.iter()
        .map(|&e| {
            if !g.contains(e) {
                return Err(ConstructError::NoSuchDart(e));
            }
            let f = g.alpha(e, 0);
            if f == e {
                return Err(ConstructError::BadShape { dart: e, what: "an edge with two ends" });
            }
            let (p, q) = (g.point(e).ok_or(ConstructError::NoPoint(e))?, g.point(f).ok_or(ConstructError::NoPoint(f))?);
            Ok([q[0] - p[0], q[1] - p[1], q[2] - p[2]])
        })
        .collect()
}

/// Whether [`try_extrude_cell_along_path`] would succeed: [`can_extrude_cell`], and every
/// dart of `path` is live, not 0-free, and its edge's two ends have points.
pub fn can_extrude_cell_along_path<A: Attributes>(g: &GMap<A>, d: DartId, i: usize, path: &[DartId]) -> bool {
    can_extrude_cell(g, d, i) && path_steps(g, path).is_ok()
}

/// Extrudes the i-cell of `d` along a path of edges (Moka's extrusion along a path): one
/// (i + 1)-cell per edge of `path` (one dart per edge, in order), each the previous top
/// moved by the edge's vector (from the vertex of the dart to that of its `alpha_0`), the
/// cells stacked by `alpha_{i+1}`. The path is read, not changed; it may lie anywhere in
/// the map (a polyline drawn apart, or edges of the object). Returns one [`Extruded`] per
/// edge. Δχ = 0 per step. O(|path| · s · n²).
pub fn try_extrude_cell_along_path<A: Attributes>(
    g: &mut GMap<A>,
    d: DartId,
    i: usize,
    path: &[DartId],
) -> Result<Vec<Extruded>, ConstructError> {
    let steps = path_steps(g, path)?;
    check(g, d, i)?;
    let mut out = Vec::with_capacity(steps.len());
    let mut at = d;
    for v in steps {
        // the top of a fresh prism is free and has the cell's shape: the check passes
        let e = try_extrude_cell(g, at, i, v)?;
        at = e.top;
        out.push(e);
    }
    Ok(out)
}

/// Like [`try_extrude_cell_along_path`], panicking when the precondition fails.
#[track_caller]
pub fn extrude_cell_along_path<A: Attributes>(g: &mut GMap<A>, d: DartId, i: usize, path: &[DartId]) -> Vec<Extruded> {
    try_extrude_cell_along_path(g, d, i, path).unwrap_or_else(|e| panic!("extrude_cell_along_path: {e}"))
}

/// In debug builds, panics when `g` is not valid or its attributes disagree.
pub(super) fn debug_check<A: Attributes>(g: &GMap<A>) {
    if cfg!(debug_assertions) {
        if let Err(e) = g.validate() {
            panic!("construction broke the map: {e}");
        }
    }
}
