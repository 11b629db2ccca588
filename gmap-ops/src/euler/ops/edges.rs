//! Edges hung at a corner: a dangling edge into a face ([`try_insert_dangling_edge`]) and
//! a bridge from a corner of one face to a corner of another
//! ([`try_insert_edge_between_faces`]), which makes the two faces one.
//!
//! Both add, for every copy `x` of the corner of `d` across `alpha_3 … alpha_n`, four darts
//! `p, q` (at the corner of `x`) and `p2, q2` (at the far end), with `alpha_0` along the
//! edge and `alpha_2` across it; they differ in where the far end goes: `p2, q2` are
//! `alpha_1`-linked to each other (a new vertex) or to a corner of the other face.

use rustc_hash::{FxHashMap as HashMap, FxHashSet as HashSet};

use gmap_core::{AlphaSet, Attributes, DartId, GMap, Point};

use super::common::{debug_check, diff, live, local_counts, reconcile};
use super::EulerError;
use crate::euler::vector::{EpVector, EulerOp};

/// The copies of the corner of `d` across `alpha_3 … alpha_n`, checked: `n >= 2`, none
/// 1-free, the corners (`x`, `alpha_1(x)`) pairwise disjoint. O(orbit size · n).
fn corner_copies<A: Attributes>(g: &GMap<A>, d: DartId, what: &'static str) -> Result<Vec<DartId>, EulerError> {
    live(g, d)?;
    let n = g.dim();
    if n < 2 {
        return Err(EulerError::BadDimension { what, lo: 2, hi: n, got: n });
    }
    let copies = g.orbit(d, AlphaSet::range(3, n));
    let mut seen: HashSet<DartId> = HashSet::default();
    for &x in &copies {
        let y = g.alpha(x, 1);
        if y == x {
            return Err(EulerError::Free { dart: x, alpha: 1 });
        }
        if !seen.insert(x) || !seen.insert(y) {
            return Err(EulerError::Misplaced { dart: x, what: "a corner met once by its alpha_3..alpha_n orbit" });
        }
    }
    Ok(copies)
}

/// Whether [`try_insert_dangling_edge`] (and [`try_insert_dangling_edge_at`]) would succeed.
pub fn can_insert_dangling_edge<A: Attributes>(g: &GMap<A>, d: DartId) -> bool {
    corner_copies(g, d, "dangling edge").is_ok()
}

/// Inserts a dangling edge in the face of `d`, hanging from the vertex of `d` between `d`
/// and `alpha_1(d)` (`mev`, CGAL's `insert_dangling_cell_1_in_cell_2`).
///
/// ```text
///   ┌───────┐          ┌───────┐
///   │       │   mev    │       │
///   │       │  ─────>  │   o   │   a new vertex o on a new edge, inside the face
///   │       │          │   |   │
///   └───────┘          └───┴───┘
/// ```
/// The new vertex `o` has no point ([`try_insert_dangling_edge_at`] takes one); the new
/// edge has no attribute; the new darts take the attributes of the face, the vertex of `d`
/// and the higher cells they join. No cell merges or splits: no hook runs.
///
/// Precondition ([`can_insert_dangling_edge`]): `n >= 2`, `d` is not 1-free, and the
/// corner of `d` meets each of its copies across `alpha_3 … alpha_n` once (true in every
/// valid map). Effect `X_0 + X_1` (`B0 + A1`). O(size of the cells touched · n).
pub fn try_insert_dangling_edge<A: Attributes>(g: &mut GMap<A>, d: DartId) -> Result<EulerOp, EulerError> {
    try_insert_dangling_edge_at(g, d, None)
}

/// [`try_insert_dangling_edge`] with the point of the new vertex: `Some(p)` places it at
/// `p`, `None` leaves it without one. Same precondition, effect and cost.
pub fn try_insert_dangling_edge_at<A: Attributes>(
    g: &mut GMap<A>,
    d: DartId,
    point: Option<Point>,
) -> Result<EulerOp, EulerError> {
    dangling_counted(g, d, point).map(|(op, _)| op)
}

/// [`try_insert_dangling_edge_at`], also returning the dart of the new edge at the new
/// vertex, on the side of `d`.
pub(super) fn dangling_counted<A: Attributes>(
    g: &mut GMap<A>,
    d: DartId,
    point: Option<Point>,
) -> Result<(EulerOp, DartId), EulerError> {
    let near = corner_copies(g, d, "dangling edge")?;
    let mut touched: Vec<DartId> = near.clone();
    touched.extend(near.iter().map(|&x| g.alpha(x, 1)));
    let before = local_counts(g, &touched);
    let new = hang(g, &near, None);
    let tip = new[0][2];
    if point.is_some() {
        g.set_point(tip, point);
    }
    touched.extend(new.iter().flatten());
    let after = local_counts(g, &touched);
    debug_check(g);
    Ok((EulerOp::new("mev", EpVector::from_cells(&diff(&after, &before))), tip))
}

/// What [`try_insert_edge_between_faces`] did: a dart of the new edge and the change of
/// cells. The change of homology is not local (joining two components, or making a face
/// with a hole in one component) and is left to a homology engine
/// ([`EpVector::between`](crate::euler::EpVector::between)).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct BridgeReport {
    /// the new dart at the corner of `d1`, on the side of `d1` (CGAL returns a dart of the
    /// new edge too)
    pub dart: DartId,
    /// change of the number of cells of every dimension, recounted on the cells that meet
    /// the corners (`[0, 1, -1, …]`: one more edge, one face less, and one cell less in every
    /// dimension where the two faces lay in different cells)
    pub dx: Vec<i64>,
}

/// The corners of a bridge, checked: the copies of `d1`'s corner and, at the same
/// positions, the copies of `d2`'s corner they are paired with by a parallel walk of
/// `alpha_3 … alpha_n`.
fn bridge_plan<A: Attributes>(g: &GMap<A>, d1: DartId, d2: DartId) -> Result<(Vec<DartId>, Vec<DartId>), EulerError> {
    let near = corner_copies(g, d1, "edge between faces")?;
    let far_orbit = corner_copies(g, d2, "edge between faces")?;
    let n = g.dim();
    let face = g.orbit(d1, AlphaSet::cell(2, n));
    if face.contains(&d2) {
        return Err(EulerError::Misplaced { dart: d2, what: "a face other than the face of d1" });
    }
    let mut to: HashMap<DartId, DartId> = HashMap::default();
    let mut from: HashMap<DartId, DartId> = HashMap::default();
    to.insert(d1, d2);
    from.insert(d2, d1);
    let mut stack = vec![(d1, d2)];
    while let Some((x, z)) = stack.pop() {
        for k in 3..=n {
            let (x2, z2) = (g.alpha(x, k), g.alpha(z, k));
            if (x2 == x) != (z2 == z) {
                return Err(EulerError::Misplaced {
                    dart: z,
                    what: "a corner linked across alpha_3..alpha_n as d1's is",
                });
            }
            match (to.get(&x2), from.get(&z2)) {
                (Some(&a), Some(&b)) if a == z2 && b == x2 => {}
                (None, None) => {
                    to.insert(x2, z2);
                    from.insert(z2, x2);
                    stack.push((x2, z2));
                }
                _ => {
                    return Err(EulerError::Misplaced {
                        dart: z2,
                        what: "a corner linked across alpha_3..alpha_n as d1's is",
                    })
                }
            }
        }
    }
    if to.len() != near.len() || from.len() != far_orbit.len() {
        return Err(EulerError::Misplaced { dart: d2, what: "a corner with as many copies as d1's" });
    }
    let far = near.iter().map(|x| to[x]).collect();
    Ok((near, far))
}

/// Whether [`try_insert_edge_between_faces`] would succeed.
pub fn can_insert_edge_between_faces<A: Attributes>(g: &GMap<A>, d1: DartId, d2: DartId) -> bool {
    bridge_plan(g, d1, d2).is_ok()
}

/// Inserts an edge from the corner of `d1` (between `d1` and `alpha_1(d1)`) to the corner
/// of `d2` in another face (CGAL 6's `insert_cell_1_between_two_cells_2`): the two faces
/// become one, whose boundary runs around the first face, along the new edge, around the
/// second face and back. A square hung this way from a face of a hexahedron becomes a
/// hole in that face.
///
/// ```text
///   ┌─────────┐             ┌─────────┐
///   │  ┌──┐   │             │  ┌──┐   │
///   │  │f2│   │   bridge    │  │  │   │   f1 and f2 become one face, with a hole
///   │  └──┘   │  ───────>   │  └──┘   │
///   │ f1      │             │   \     │
///   └─────────┘             └────\────┘
/// ```
/// The new darts `p` (at `d1`) and `p2` (at `d2`) are `alpha_0`-linked, as are the darts
/// at `alpha_1(d1)` and `alpha_1(d2)`. Attributes: the two faces merge, keeping the
/// 2-attribute of `d1`'s face (the merge hook runs when both had one); so do the cells of
/// every higher dimension that differ between the two sides; the new edge has no
/// attribute; vertices keep theirs and their points (no vertex is made).
///
/// Precondition ([`can_insert_edge_between_faces`]): `n >= 2`; `d1`, `d2` live, not
/// 1-free, in different 2-cells; their corners have matching copies across
/// `alpha_3 … alpha_n` (a parallel walk pairs them one to one, free where the other is
/// free: both faces 3-free in a 3-map, for instance). Effect: see [`BridgeReport::dx`].
/// O(size of the cells touched · n).
pub fn try_insert_edge_between_faces<A: Attributes>(
    g: &mut GMap<A>,
    d1: DartId,
    d2: DartId,
) -> Result<BridgeReport, EulerError> {
    let (near, far) = bridge_plan(g, d1, d2)?;
    let mut touched: Vec<DartId> = near.clone();
    touched.extend(near.iter().map(|&x| g.alpha(x, 1)));
    touched.extend(far.iter().copied());
    touched.extend(far.iter().map(|&x| g.alpha(x, 1)));
    let before = local_counts(g, &touched);
    let new = hang(g, &near, Some(&far));
    touched.extend(new.iter().flatten());
    let after = local_counts(g, &touched);
    debug_check(g);
    Ok(BridgeReport { dart: new[0][0], dx: diff(&after, &before) })
}

/// Adds the edge darts `[p, q, p2, q2]` for every corner copy `near[k]` (see the module
/// docs), the far end on `far[k]` when given, else a new vertex; reconciles the attributes
/// (the side of `near[0]` first). Returns the new darts by copy, in the order of `near`.
fn hang<A: Attributes>(g: &mut GMap<A>, near: &[DartId], far: Option<&[DartId]>) -> Vec<[DartId; 4]> {
    let n = g.dim();
    let index: HashMap<DartId, usize> = near.iter().enumerate().map(|(k, &x)| (x, k)).collect();
    let near_other: Vec<DartId> = near.iter().map(|&x| g.alpha(x, 1)).collect();
    let far_other: Vec<DartId> = far.map(|f| f.iter().map(|&z| g.alpha(z, 1)).collect()).unwrap_or_default();
    let new: Vec<[DartId; 4]> =
        near.iter().map(|_| [g.create_dart(), g.create_dart(), g.create_dart(), g.create_dart()]).collect();
    for (k, &x) in near.iter().enumerate() {
        let [p, q, p2, q2] = new[k];
        g.link(x, p, 1);
        g.link(near_other[k], q, 1);
        g.link(p, p2, 0);
        g.link(q, q2, 0);
        g.link(p, q, 2);
        g.link(p2, q2, 2);
        match far {
            Some(f) => {
                g.link(f[k], p2, 1);
                g.link(far_other[k], q2, 1);
            }
            None => g.link(p2, q2, 1),
        }
        for j in 3..=n {
            let z = g.alpha(x, j);
            if z != x {
                let other = new[index[&z]];
                for t in 0..4 {
                    g.link(new[k][t], other[t], j);
                }
            }
        }
    }
    let mut touched: Vec<DartId> = near.to_vec();
    touched.extend(&near_other);
    if let Some(f) = far {
        touched.extend(f);
        touched.extend(&far_other);
    }
    touched.extend(new.iter().flatten());
    reconcile(g, &touched);
    new
}
