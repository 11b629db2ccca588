//! CGAL's removal and contraction of cells ([`try_remove_cell`], [`try_contract_cell`]):
//! any i-cell of degree 2, on the boundary or not, whatever the cells on its sides, as
//! `Generalized_map::remove_cell<i>` and `contract_cell<i>` do.
//!
//! These change the map exactly as CGAL's do, and so may change the space: removing an edge
//! with the same face on both sides cuts that face, removing the last face of a component
//! leaves nothing of it, contracting a loop kills a circle. The operators that never change
//! the space, and so keep the homology, are [`try_remove_cell_keeping_homology`] and
//! [`try_contract_cell_keeping_homology`]; their predicates are stricter.
//!
//! | | CGAL's (here) | homology-keeping |
//! | --- | --- | --- |
//! | removal of an i-cell | [`is_removable`]: `i <= n`, and for `i <= n - 2` the cell has degree 2 (`alpha_{i+1} alpha_{i+2}` an involution on its darts) | [`is_removable_keeping_homology`]: `i < n`, degree 2, two distinct interior (i+1)-cells on its sides, no cell it touches falls apart — or a dangling edge |
//! | contraction of an i-cell | [`is_contractible`]: `1 <= i <= n`, and for `i >= 2` dual degree 2 (`alpha_{i-1} alpha_{i-2}` an involution) | [`is_contractible_keeping_homology`]: the same, and two distinct (i-1)-cells at its ends, none on the boundary, no cell it touches falls apart |
//! | returns | the number of darts deleted, as CGAL | an [`EulerOp`](crate::euler::EulerOp) with the Euler–Poincaré vector |

use rustc_hash::FxHashSet as HashSet;

use gmap_core::{Attributes, DartId, GMap};

use super::collapse::{collapse, Move};
use super::common::{debug_check, live, reconcile};
use super::EulerError;
#[cfg(doc)]
use super::{
    is_contractible_keeping_homology, is_removable_keeping_homology, try_contract_cell_keeping_homology,
    try_remove_cell_keeping_homology,
};

/// The precondition of [`try_remove_cell`] or [`try_contract_cell`], as CGAL states it.
fn check<A: Attributes>(g: &GMap<A>, d: DartId, i: usize, kind: Move) -> Result<(), EulerError> {
    live(g, d)?;
    let n = g.dim();
    let (what, lo) = match kind {
        Move::Remove => ("removal", 0),
        Move::Contract => ("contraction", 1),
    };
    if i < lo || i > n {
        return Err(EulerError::BadDimension { what, lo, hi: n, got: i });
    }
    let Some(j) = kind.beyond(i, n) else { return Ok(()) };
    let nb = kind.neighbour(i);
    for x in g.cell_darts(d, i) {
        if g.alpha(g.alpha(x, nb), j) != g.alpha(g.alpha(x, j), nb) {
            return Err(EulerError::DegreeAboveTwo { dim: i, dart: x });
        }
    }
    Ok(())
}

/// Whether [`try_remove_cell`] applies to the i-cell of `d` (CGAL's `is_removable<i>`):
/// `d` is live, `i <= n`, and for `i <= n - 2` every dart `x` of the cell has
/// `alpha_{i+1}(alpha_{i+2}(x)) = alpha_{i+2}(alpha_{i+1}(x))` (at most two (i+1)-cells
/// around it). O(cell size · n).
pub fn is_removable<A: Attributes>(g: &GMap<A>, d: DartId, i: usize) -> bool {
    check(g, d, i, Move::Remove).is_ok()
}

/// Whether [`try_contract_cell`] applies to the i-cell of `d` (CGAL's
/// `is_contractible<i>`): `d` is live, `1 <= i <= n`, and for `i >= 2` every dart `x` of
/// the cell has `alpha_{i-1}(alpha_{i-2}(x)) = alpha_{i-2}(alpha_{i-1}(x))`.
/// O(cell size · n).
pub fn is_contractible<A: Attributes>(g: &GMap<A>, d: DartId, i: usize) -> bool {
    check(g, d, i, Move::Contract).is_ok()
}

/// Removes the i-cell of `d`, `0 <= i <= n`, as CGAL's `remove_cell<i>`; returns the
/// number of darts deleted.
///
/// For `i < n`, every dart outside the cell that was `alpha_i`-linked into it is linked to
/// the first dart outside reached by alternating `alpha_{i+1}`, `alpha_i` (or becomes
/// i-free): the (i+1)-cells on both sides merge when they are two, a cell with the same
/// (i+1)-cell on both sides is cut out of it, a cell on the boundary leaves a boundary. For
/// `i = n`, the darts around the n-cell become n-free and the n-cell goes. A cell that is
/// its whole component (an isolated segment, a lone dart) leaves nothing.
///
/// ```
/// use gmap_core::GMap;
/// use gmap_ops::euler::ops::{is_removable, try_remove_cell};
/// // CGAL's Generalized_map_2_test: the faces of a combinatorial hexahedron (a 2-map)
/// let mut g = GMap::new(2);
/// let d = g.make_combinatorial_hexahedron();
/// assert!(is_removable(&g, d, 2));
/// assert_eq!(try_remove_cell(&mut g, d, 2), Ok(8));
/// assert_eq!(g.cell_counts(), vec![8, 12, 5]);
/// // an isolated segment removed as a vertex, then as an edge: nothing left
/// let mut s = GMap::new(1);
/// let e = s.make_edge();
/// assert_eq!(try_remove_cell(&mut s, e, 1), Ok(2));
/// assert_eq!(s.dart_count(), 0);
/// ```
///
/// Precondition: [`is_removable`]. Attributes and points: the (i+1)-cells that merge keep
/// the attribute of the one met first from `alpha_i` of the cell (the merge hook runs when
/// both had one); a cell that falls in two keeps its attribute on one part and a copy on
/// the other (the split hook runs); the removed cell's attributes go with its darts, and
/// every vertex that keeps darts keeps its point ([`GMap::reconcile_attributes`]). The map
/// stays valid. O(size of the cells touched · n).
///
/// [`GMap::reconcile_attributes`]: gmap_core::GMap::reconcile_attributes
pub fn try_remove_cell<A: Attributes>(g: &mut GMap<A>, d: DartId, i: usize) -> Result<usize, EulerError> {
    check(g, d, i, Move::Remove)?;
    let cell = g.cell_darts(d, i);
    if i == g.dim() {
        drop_top_cell(g, &cell);
    } else {
        collapse(g, &cell, i, Move::Remove.neighbour(i));
    }
    debug_check(g);
    Ok(cell.len())
}

/// Like [`try_remove_cell`], panicking when the precondition fails (CGAL asserts it).
pub fn remove_cell<A: Attributes>(g: &mut GMap<A>, d: DartId, i: usize) -> usize {
    try_remove_cell(g, d, i).unwrap_or_else(|e| panic!("remove_cell: {e}"))
}

/// Contracts the i-cell of `d`, `1 <= i <= n`, as CGAL's `contract_cell<i>`; returns the
/// number of darts deleted: the dual of [`try_remove_cell`], walking `alpha_{i-1}`,
/// `alpha_i` around the cell. The two (i-1)-cells at its ends merge when they are two;
/// a loop, a lone dart or a cell that is its whole component leaves nothing of itself.
///
/// ```
/// use gmap_core::GMap;
/// use gmap_ops::euler::ops::try_contract_cell;
/// // an open path of three edges (a 1-map): contracting the middle edge
/// let mut g = GMap::new(1);
/// let (a, b, c) = (g.make_edge(), g.make_edge(), g.make_edge());
/// g.sew(g.alpha(a, 0), b, 1);
/// g.sew(g.alpha(b, 0), c, 1);
/// assert_eq!(try_contract_cell(&mut g, b, 1), Ok(2));
/// assert_eq!(g.cell_counts(), vec![3, 2]);
/// // the last edges go too, one after the other
/// try_contract_cell(&mut g, a, 1).unwrap();
/// try_contract_cell(&mut g, c, 1).unwrap();
/// assert_eq!(g.dart_count(), 0);
/// ```
///
/// Precondition: [`is_contractible`]. Attributes and points as for [`try_remove_cell`],
/// with the (i-1)-cells at the ends merging (for an edge, the merged vertex keeps the
/// point of `d`'s vertex side met first). O(size of the cells touched · n).
pub fn try_contract_cell<A: Attributes>(g: &mut GMap<A>, d: DartId, i: usize) -> Result<usize, EulerError> {
    check(g, d, i, Move::Contract)?;
    let cell = g.cell_darts(d, i);
    collapse(g, &cell, i, Move::Contract.neighbour(i));
    debug_check(g);
    Ok(cell.len())
}

/// Like [`try_contract_cell`], panicking when the precondition fails (CGAL asserts it).
pub fn contract_cell<A: Attributes>(g: &mut GMap<A>, d: DartId, i: usize) -> usize {
    try_contract_cell(g, d, i).unwrap_or_else(|e| panic!("contract_cell: {e}"))
}

/// Removes the n-cell made of `cell`: its neighbours across `alpha_n` become n-free, then
/// its darts go; the cells of the neighbours that fall apart are repaired.
fn drop_top_cell<A: Attributes>(g: &mut GMap<A>, cell: &[DartId]) {
    let n = g.dim();
    let set: HashSet<DartId> = cell.iter().copied().collect();
    let outside: Vec<DartId> = cell.iter().map(|&x| g.alpha(x, n)).filter(|y| !set.contains(y)).collect();
    for &x in cell {
        g.remove_dart(x);
    }
    if g.needs_reconcile() && !outside.is_empty() {
        reconcile(g, &outside);
    }
}
