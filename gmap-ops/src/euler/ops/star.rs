//! Stellar subdivision: a new vertex inside an i-cell, joined to the whole boundary of the
//! cell ([`try_star_cell`]). For a face this is CGAL's `insert_cell_0_in_cell_2` (the face
//! becomes one triangle per side), for an edge its `insert_cell_0_in_cell_1`, for a volume
//! one pyramid per face; [`insert_point_in_cell`] is the linear-cell-complex form that
//! places the new vertex.
//!
//! See [`try_star_cell`] for the construction and how attributes follow it.

use rustc_hash::{FxHashMap as HashMap, FxHashSet as HashSet};

use gmap_core::{Attributes, DartId, GMap, MapView, Point};

use super::common::distinct_cells;
use super::EulerError;
use crate::euler::vector::{cell_letter, EpVector, EulerOp};

/// What [`try_star_cell`] did: where the new vertex is and the change of cells.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Starred {
    /// A dart of the new vertex, on the new edge that joins it to the vertex of the dart
    /// `d` given (CGAL's return value): `alpha_0(alpha_1(…alpha_{i-1}(d)))`, for a face
    /// `alpha_0(alpha_1(d))`.
    pub vertex: DartId,
    /// The operator's name (`star_e`, `star_f`, `star_s`, `star_c4`, …) and its
    /// Euler–Poincaré vector: one vertex, one k-cell per (k-1)-cell occurrence on the
    /// boundary for `1 <= k <= i`, minus the i-cell itself; homology unchanged.
    pub op: EulerOp,
}

/// `Ok` when [`try_star_cell`] applies: `d` is a live dart and `1 <= i <= n`.
fn check_star<A: Attributes>(g: &GMap<A>, d: DartId, i: usize) -> Result<(), EulerError> {
    if !g.contains(d) {
        return Err(EulerError::NoSuchDart(d));
    }
    let n = g.dim();
    if i == 0 || i > n {
        return Err(EulerError::BadDimension { what: "star of a cell", lo: 1, hi: n, got: i });
    }
    Ok(())
}

/// Whether [`try_star_cell`] would succeed: `d` is a live dart of `g` and `1 <= i <= n`.
/// O(1).
pub fn can_star_cell<A: Attributes>(g: &GMap<A>, d: DartId, i: usize) -> bool {
    check_star(g, d, i).is_ok()
}

/// The darts of one side of the face of `d` in CGAL's order: from `d` alternately across
/// `alpha_0` and `alpha_1` until the walk comes back to `d`; on an open face, to the free
/// end, then from `d` across `alpha_1` to the other end. O(face side).
fn face_ring<A: Attributes>(g: &GMap<A>, d: DartId) -> Vec<DartId> {
    let mut out = vec![d];
    let mut x = d;
    let mut j = 0;
    loop {
        let y = g.alpha(x, j);
        if y == d {
            return out;
        }
        if y == x {
            break;
        }
        out.push(y);
        x = y;
        j ^= 1;
    }
    let mut x = d;
    let mut j = 1;
    loop {
        let y = g.alpha(x, j);
        if y == x || y == d {
            return out;
        }
        out.push(y);
        x = y;
        j ^= 1;
    }
}

/// The darts of the i-cell of `d`, `d` first, in the order the cones are split off (see
/// [`try_star_cell`]): for a face, its ring from `d` and then the other sides; else
/// breadth-first from `d`. O(cell size · n).
fn split_order<A: Attributes>(g: &GMap<A>, d: DartId, i: usize) -> Vec<DartId> {
    if i != 2 {
        return g.cell(d, i);
    }
    let mut out = face_ring(g, d);
    let mut seen: HashSet<DartId> = out.iter().copied().collect();
    for x in g.cell(d, i) {
        if seen.insert(x) {
            out.push(x);
        }
    }
    out
}

/// Stars the i-cell of `d` (stellar subdivision): a new vertex inside the cell, joined by
/// a cone to its whole boundary. On an edge it inserts a vertex (CGAL's
/// `insert_cell_0_in_cell_1`), on a face it makes one triangle per side
/// (`insert_cell_0_in_cell_2`), on a volume one pyramid per face, on an i-cell one cone per
/// (i-1)-cell of its boundary. The cell's darts across `alpha_{i+1}..alpha_n` are starred
/// with it, so a face shared by two volumes is subdivided on both sides.
///
/// ```text
///   ┌───────┐          ┌───────┐
///   │       │   star   │ \   / │
///   │   f   │  ─────>  │   w   │   one face becomes k triangles (here 4)
///   │       │          │ /   \ │
///   └───────┘          └───────┘
/// ```
///
/// ```
/// use gmap_core::{Cells, GMap, MapView};
/// use gmap_ops::{build, euler::ops::try_star_cell};
/// // a hexahedron whose volume carries a weight, split evenly on every split
/// let mut g: GMap<((), (), (), Cells<f64>)> = GMap::with_attributes(3);
/// let d = g.try_append(&build::cube(3).unwrap()).unwrap()[0];
/// g.set_attribute::<3>(d, 6.0);
/// g.set_on_split::<3>(|kept, copy| {
///     *kept /= 2.0;
///     *copy = *kept;
/// });
/// let star = try_star_cell(&mut g, d, 3, Some([0.5, 0.5, 0.5])).unwrap();
/// // six square pyramids around the centre: 8 + 1 vertices, 12 + 8 edges, 6 + 12 faces
/// assert_eq!(MapView::cell_counts(&g), vec![9, 20, 18, 6]);
/// assert_eq!(star.op.vector.dx(), &[1, 8, 12, 5]);
/// assert_eq!(g.point(star.vertex), Some([0.5, 0.5, 0.5]));
/// // five splits in turn: the pyramid of d kept 6 / 2^5
/// assert_eq!(g.attribute::<3>(d), Some(&(6.0 / 32.0)));
/// assert_eq!(g.attribute_count::<3>(), 6);
/// ```
///
/// `point` becomes the new vertex's point (`None`: no point). Attributes follow the rules
/// below: the cone of `d` keeps the cell's attribute, the split hook of dimension i runs
/// once per other cone, in CGAL's order; no other hook runs.
///
/// # Construction, flag by flag
///
/// A dart is a flag `(c_0, c_1, …, c_n)` of mutually incident cells. Starring the i-cell
/// `C` from a new vertex `w` replaces `C` by the cones `w * c_{i-1}` over its (i-1)-cells,
/// and adds the cones `w * c_k` over its lower cells. A flag of the new cells is an old
/// flag `x` of `C` with a *level* `s` in `0..=i`:
///
/// ```text
///   x_s = (c_0, …, c_{s-1},  w * c_{s-1}, …, w * c_{i-1},  c_{i+1}, …, c_n)
///          old cells below s  cones from level s on          cells above C
/// ```
///
/// (`w * c_{-1}` is `w` itself). Level `i` is the old dart itself, with `C` replaced by
/// the cone over its (i-1)-cell, so each old dart of `C` gets `i` new companions and the
/// i-cell grows from `|C|` to `(i + 1)|C|` darts. The involutions follow from the flags:
///
/// | `alpha_j(x_s)` | |
/// | --- | --- |
/// | `j < s - 1` | `(alpha_j x)_s` |
/// | `j = s - 1` | `x_{s-1}` |
/// | `j = s < i` | `x_{s+1}` |
/// | `s < j <= i` | `(alpha_{j-1} x)_s` |
/// | `j > i`, or `j = s = i` | `(alpha_j x)_s` (the old link) |
///
/// On the old darts only `alpha_{i-1}` changes. Nothing here asks more of `C` than being an
/// i-cell: a face with a repeated vertex or edge (a face glued to itself, the one face of a
/// torus), a face with a free boundary, a face shared by two volumes or lying in an n-map
/// with copies across `alpha_3..alpha_n` — the cone is taken over every flag of the cell,
/// so the new vertex is joined once to each *occurrence* of a boundary cell. The result is
/// a subdivision of the same space: homology unchanged.
///
/// # Attributes
///
/// The cells of dimension other than i are neither split nor merged (an old cell gains
/// darts, the new cones start without attributes, the new vertex gets the point given).
/// The i-cell is split into its cones as CGAL does it: the cone of the dart given keeps
/// the attribute, and each other cone in turn gets a copy after the split hook ran on
/// `(kept, copy)`, so a hook that halves the kept value leaves `v/2^k, v/2, v/4, …,
/// v/2^k` on `k + 1` cones. For a face the cones are taken in CGAL's order: around the
/// face from the dart given, first across `alpha_0`.
///
/// # Precondition and cost
///
/// Precondition ([`can_star_cell`]): `d` is a live dart and `1 <= i <= n`; `g` is a valid
/// G-map (BO Def. 1), which the result then is. The cell may have free darts and repeated
/// boundary cells (see above). Effect: `|C| · i` new darts for an i-cell of `|C|` darts;
/// one more vertex, for each `1 <= k <= i` one more k-cell per occurrence of a (k-1)-cell
/// on the boundary, one i-cell less; homology unchanged. O(|C| · i · n) for
/// the links, O(|C| · i² · n) for the count of cells in the returned vector.
pub fn try_star_cell<A: Attributes>(
    g: &mut GMap<A>,
    d: DartId,
    i: usize,
    point: Option<Point>,
) -> Result<Starred, EulerError> {
    check_star(g, d, i)?;
    let n = g.dim();
    let cell = split_order(g, d, i);
    let pos: HashMap<DartId, usize> = cell.iter().enumerate().map(|(k, &x)| (x, k)).collect();
    // the old involutions as positions in `cell` (alpha_j with j != i stays in the cell);
    // the entry for j = i is unused
    let old: Vec<usize> = cell
        .iter()
        .flat_map(|&x| (0..=n).map(move |j| (x, j)))
        .map(|(x, j)| if j == i { 0 } else { pos[&g.alpha(x, j)] })
        .collect();
    let fresh: Vec<DartId> = (0..cell.len() * i).map(|_| g.create_dart()).collect();
    // x_s of the k-th dart of the cell; level i is the old dart
    let at = |k: usize, s: usize| if s == i { cell[k] } else { fresh[k * i + s] };
    for k in 0..cell.len() {
        let nb = |j: usize| old[k * (n + 1) + j];
        for s in 0..i {
            let x = at(k, s);
            for j in 0..s.saturating_sub(1) {
                g.link(x, at(nb(j), s), j);
            }
            if s >= 1 {
                g.link(x, at(k, s - 1), s - 1);
            }
            // for s = i - 1 this replaces the old alpha_{i-1} of the old dart
            g.link(x, at(k, s + 1), s);
            for j in s + 1..=i {
                g.link(x, at(nb(j - 1), s), j);
            }
            for j in i + 1..=n {
                g.link(x, at(nb(j), s), j);
            }
        }
    }
    if g.needs_reconcile() {
        let mut touched = cell.clone();
        touched.extend_from_slice(&fresh);
        g.reconcile_attributes(&touched);
    }
    let vertex = at(0, 0);
    if point.is_some() {
        g.set_point(vertex, point);
    }
    // the new k-cells are the cones over the (k-1)-cells: x_{k-1} lies on one
    let mut dx = vec![0i64; n + 1];
    dx[0] = 1;
    for (k, slot) in dx.iter_mut().enumerate().take(i + 1).skip(1) {
        *slot = distinct_cells(g, (0..cell.len()).map(|c| at(c, k - 1)), k) as i64;
    }
    dx[i] -= 1;
    if cfg!(debug_assertions) {
        if let Err(e) = MapView::validate(g) {
            panic!("star of a cell broke validity: {e}");
        }
    }
    Ok(Starred { vertex, op: EulerOp::new(format!("star_{}", cell_letter(i)), EpVector::from_cells(&dx)) })
}

/// Like [`try_star_cell`], panicking when the precondition fails.
#[track_caller]
pub fn star_cell<A: Attributes>(g: &mut GMap<A>, d: DartId, i: usize, point: Option<Point>) -> Starred {
    try_star_cell(g, d, i, point).unwrap_or_else(|e| panic!("star_cell: {e}"))
}

/// Whether [`try_star_face`] would succeed: `d` is a live dart and `n >= 2`. O(1).
pub fn can_star_face<A: Attributes>(g: &GMap<A>, d: DartId) -> bool {
    can_star_cell(g, d, 2)
}

/// Inserts a vertex in the face of `d` and joins it by an edge to every corner: a face of
/// k sides becomes k triangles, on both sides when it is shared by two volumes. The
/// triangle of `d` keeps the face's attribute; the others get copies through the split
/// hook, in order around the face from `d` across `alpha_0` (as CGAL's
/// `insert_cell_0_in_cell_2`). [`try_star_cell`] with `i = 2`: same precondition
/// ([`can_star_face`]: `n >= 2`) and cost.
pub fn try_star_face<A: Attributes>(g: &mut GMap<A>, d: DartId, point: Option<Point>) -> Result<Starred, EulerError> {
    try_star_cell(g, d, 2, point)
}

/// Like [`try_star_face`], panicking when the precondition fails.
#[track_caller]
pub fn star_face<A: Attributes>(g: &mut GMap<A>, d: DartId, point: Option<Point>) -> Starred {
    try_star_face(g, d, point).unwrap_or_else(|e| panic!("star_face: {e}"))
}

/// Whether [`insert_cell_0_in_cell_2`] would succeed ([`can_star_face`]). O(1).
pub fn is_insertable_cell_0_in_cell_2<A: Attributes>(g: &GMap<A>, d: DartId) -> bool {
    can_star_face(g, d)
}

/// CGAL's `insert_cell_0_in_cell_2`: [`try_star_face`] on the face of `d`, the new vertex
/// at `point`, returning CGAL's dart: [`Starred::vertex`], a dart of the new vertex.
/// Precondition ([`is_insertable_cell_0_in_cell_2`]) and cost of [`try_star_face`].
pub fn insert_cell_0_in_cell_2<A: Attributes>(
    g: &mut GMap<A>,
    d: DartId,
    point: Option<Point>,
) -> Result<DartId, EulerError> {
    try_star_face(g, d, point).map(|s| s.vertex)
}

/// The linear-cell-complex form of [`try_star_cell`] (CGAL's `insert_point_in_cell`): a
/// vertex at `p` inserted in the i-cell of `d`, for every `1 <= i <= n` (an edge, a face, a
/// volume, …), returning [`Starred::vertex`], a dart of the new vertex. Precondition
/// ([`can_star_cell`]) and cost of [`try_star_cell`].
pub fn insert_point_in_cell<A: Attributes>(
    g: &mut GMap<A>,
    d: DartId,
    i: usize,
    p: Point,
) -> Result<DartId, EulerError> {
    try_star_cell(g, d, i, Some(p)).map(|s| s.vertex)
}

/// Whether [`insert_barycenter_in_cell`] would succeed: the i-cell of `d` can be starred
/// ([`can_star_cell`]) and every vertex of it has a point. O(size of the cell · n).
pub fn is_insertable_barycenter_in_cell<A: Attributes>(g: &GMap<A>, d: DartId, i: usize) -> bool {
    can_star_cell(g, d, i) && g.barycenter(d, i).is_some()
}

/// CGAL's `insert_barycenter_in_cell`: [`insert_point_in_cell`] at the barycentre of the
/// i-cell of `d` ([`GMap::barycenter`], the mean of its distinct vertex points), returning a
/// dart of the new vertex. Refused with [`EulerError::NoPoint`] when a vertex of the cell
/// has no point, and as [`try_star_cell`] otherwise. O(size of the cell · n) on top of the
/// star.
pub fn insert_barycenter_in_cell<A: Attributes>(g: &mut GMap<A>, d: DartId, i: usize) -> Result<DartId, EulerError> {
    if !can_star_cell(g, d, i) {
        return try_star_cell(g, d, i, None).map(|s| s.vertex);
    }
    let p = g.barycenter(d, i).ok_or(EulerError::NoPoint { dim: i, dart: d })?;
    insert_point_in_cell(g, d, i, p)
}
