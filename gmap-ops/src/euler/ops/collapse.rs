//! Removals and contractions of cells of degree 2 ([`try_remove_cell_keeping_homology`],
//! [`try_contract_cell_keeping_homology`]), which merge the two cells on either side, and the removal of a
//! dangling edge; each checks first that the space does not change.

use rustc_hash::{FxHashMap as HashMap, FxHashSet as HashSet};

use gmap_core::union_find::UnionFind;
use gmap_core::{AlphaSet, Attributes, DartId, GMap};

use super::common::{debug_check, diff, live, local_counts, op_name, reconcile};
use super::EulerError;
use crate::euler::vector::{EpVector, EulerOp};

/// A removal of an i-cell, which merges the two (i+1)-cells on its sides, or a contraction,
/// which merges the two (i-1)-cells at its ends.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Move {
    /// remove the cell
    Remove,
    /// contract the cell
    Contract,
}

impl Move {
    /// The dimension of the cells that an i-cell's move merges, `i + 1` or `i - 1`: the
    /// only involution of the cell's darts that leaves those cells.
    pub(crate) fn neighbour(self, i: usize) -> usize {
        match self {
            Move::Remove => i + 1,
            Move::Contract => i - 1,
        }
    }

    /// The next dimension beyond, `i + 2` or `i - 2`, if it is one of the n-map: the move
    /// needs `alpha_nb alpha_next` to be an involution on the cell (degree 2).
    pub(crate) fn beyond(self, i: usize, n: usize) -> Option<usize> {
        match self {
            Move::Remove => (i + 2 <= n).then_some(i + 2),
            Move::Contract => i.checked_sub(2),
        }
    }
}

/// How a removal or contraction will rewire the map.
enum Collapse {
    /// the cell separates two distinct cells of the next dimension (or, for contraction,
    /// of the previous one)
    Merge,
    /// an edge hanging from a vertex into a face (removal only)
    Dangling,
}

/// The check of [`is_removable_keeping_homology`] and [`is_contractible_keeping_homology`].
fn check_collapse<A: Attributes>(g: &GMap<A>, d: DartId, i: usize, kind: Move) -> Result<Collapse, EulerError> {
    let remove = kind == Move::Remove;
    live(g, d)?;
    let n = g.dim();
    let (what, lo, hi) = if remove { ("removal", 0, n.saturating_sub(1)) } else { ("contraction", 1, n) };
    if i < lo || i > hi || (remove && n == 0) {
        return Err(EulerError::BadDimension { what, lo, hi, got: i });
    }
    let cell = g.cell_darts(d, i);
    let nb = kind.neighbour(i);
    let nb2 = kind.beyond(i, n);
    if let Some(j) = nb2 {
        for &x in &cell {
            let a = g.alpha(g.alpha(x, nb), j);
            let b = g.alpha(g.alpha(x, j), nb);
            if a != b {
                return Err(EulerError::DegreeAboveTwo { dim: i, dart: x });
            }
        }
    }
    let mut sides: HashSet<DartId> = HashSet::default();
    let mut count = 0;
    let mut free = false;
    for &x in &cell {
        if g.is_free(x, nb) {
            free = true;
        }
        if !sides.contains(&x) {
            count += 1;
            sides.extend(g.cell_darts(x, nb));
        }
    }
    if free {
        return Err(EulerError::WouldChangeTopology { dim: i, dart: d, why: "lies on the boundary" });
    }
    if count == 2 {
        if sides.iter().all(|x| cell.contains(x)) {
            // the two cells are made of the cell's darts only (a vertex between two edges
            // that both miss their far end): the merged cell would keep no dart — a lone
            // open edge, which a G-map cannot carry
            return Err(EulerError::WouldChangeTopology {
                dim: i,
                dart: d,
                why: "would leave a merged cell without darts (both far ends are missing)",
            });
        }
        if remove {
            // two open cells (with darts free for an involution of the cell) re-linked
            // around the removed cell may fall into two cells, not one; and above edges,
            // an open side cell's count says nothing of the space (its pieces are not
            // balls), so both sides must be closed. Open edges (EO's incomplete edges,
            // missing an end) merge into one open edge.
            if i > 0 {
                if let Some(y) = sides.iter().copied().find(|&y| (0..nb).any(|j| g.is_free(y, j))) {
                    return Err(EulerError::WouldChangeTopology {
                        dim: i,
                        dart: y,
                        why: "merges cells that are not closed (a dart free inside a side cell)",
                    });
                }
            } else if !merges_into_one(g, &cell, &sides, i, nb) {
                return Err(EulerError::WouldChangeTopology {
                    dim: i,
                    dart: d,
                    why: "would split the merged edge in two (its sides are open edges)",
                });
            }
        }
        if !remove {
            // both end cells interior: no free dart in the cell or at its ends
            for &x in &cell {
                for y in g.cell_darts(x, nb) {
                    if (0..=n).any(|j| g.is_free(y, j)) {
                        return Err(EulerError::WouldChangeTopology {
                            dim: i,
                            dart: y,
                            why: "joins cells on the boundary (the space would be pinched)",
                        });
                    }
                }
            }
        }
        check_corners(g, &cell, i, nb)?;
        return Ok(Collapse::Merge);
    }
    if remove && i == 1 {
        // a dangling edge: at one of its ends the vertex is that end alone (alpha_1 keeps
        // the end), a vertex of degree one. Asking only that the vertex be made of the edge's
        // darts would take the loop of a one-vertex, one-edge map (L(1,0), L(2,1)) for one.
        // The other end must be a vertex with more than the edge at it: when both ends
        // are alone (an isolated edge, or an edge folded onto itself by alpha_2 whose two
        // ends make one vertex), removing the edge would remove its whole component.
        let above = AlphaSet::above(1, n);
        let alone = |x: DartId| g.cell_darts(x, 0).len() == g.orbit(x, above).len();
        for &x in &cell {
            // the end <alpha_2..alpha_n>(x) lies inside the vertex: equal sizes, equal sets
            if alone(x) && !alone(g.alpha(x, 0)) {
                return Ok(Collapse::Dangling);
            }
        }
    }
    Err(EulerError::WouldChangeTopology {
        dim: i,
        dart: d,
        why: if remove { "has the same cell on both sides" } else { "has the same cell at both ends" },
    })
}

/// Whether the darts of `sides` outside `cell`, with `alpha_i` re-linked around the cell as
/// [`collapse`] will re-link it, form one orbit of every involution but `alpha_nb`: the two
/// `nb`-cells become one. Two closed cells always do; open ones (darts free for an
/// involution of the cell) may fall apart. O(size of the sides · n).
fn merges_into_one<A: Attributes>(g: &GMap<A>, cell: &[DartId], sides: &HashSet<DartId>, i: usize, nb: usize) -> bool {
    let set: HashSet<DartId> = cell.iter().copied().collect();
    let mut relinked: HashMap<DartId, DartId> = HashMap::default();
    for &x in cell {
        let y = g.alpha(x, i);
        if set.contains(&y) {
            continue;
        }
        let target = relink_target(g, &set, x, i, nb);
        relinked.insert(y, target.unwrap_or(y));
    }
    let rest: Vec<DartId> = sides.iter().copied().filter(|x| !set.contains(x)).collect();
    let Some(&start) = rest.first() else { return true };
    let mut seen: HashSet<DartId> = HashSet::default();
    seen.insert(start);
    let mut stack = vec![start];
    while let Some(x) = stack.pop() {
        for j in (0..=g.dim()).filter(|&j| j != nb) {
            let y = if j == i { relinked.get(&x).copied().unwrap_or_else(|| g.alpha(x, i)) } else { g.alpha(x, j) };
            if !set.contains(&y) && seen.insert(y) {
                stack.push(y);
            }
        }
    }
    seen.len() == rest.len()
}

/// The dart outside `set` that `alpha_i` of `alpha_i(x)` reaches once the cell `set` is gone
/// (alternating `alpha_nb`, `alpha_i` from `x`), or `None` when the walk stays in the cell
/// (`alpha_i(x)` becomes i-free).
fn relink_target<A: Attributes>(g: &GMap<A>, set: &HashSet<DartId>, x: DartId, i: usize, nb: usize) -> Option<DartId> {
    let mut w = g.alpha(x, nb);
    let mut z = g.alpha(w, i);
    let mut steps = 0;
    while set.contains(&z) && z != w && steps <= set.len() {
        w = g.alpha(z, nb);
        z = g.alpha(w, i);
        steps += 1;
    }
    (!set.contains(&z)).then_some(z)
}

/// The corner test: in every k-cell (k other than i and nb) that the cell meets, its
/// appearances (orbits of the cell without alpha_i and alpha_k) must each join two distinct
/// corners (orbits of every involution but alpha_nb and alpha_k), and these joins must
/// form a forest; otherwise the k-cell would fall apart.
fn check_corners<A: Attributes>(g: &GMap<A>, cell: &[DartId], i: usize, nb: usize) -> Result<(), EulerError> {
    let n = g.dim();
    for k in (0..=n).filter(|&k| k != i && k != nb) {
        let app_set = AlphaSet::all(n).without(i).without(k);
        let corner_set = AlphaSet::all(n).without(nb).without(k);
        let mut corner_of: HashMap<DartId, u32> = HashMap::default();
        let mut corners = UnionFind::new(0);
        let mut seen: HashSet<DartId> = HashSet::default();
        for &x in cell {
            if seen.contains(&x) {
                continue;
            }
            let app = g.orbit(x, app_set);
            seen.extend(app.iter().copied());
            let mut sides: Vec<u32> = Vec::new();
            for &y in &app {
                let id = match corner_of.get(&y) {
                    Some(&id) => id,
                    None => {
                        let id = corners.push();
                        for z in g.orbit(y, corner_set) {
                            corner_of.insert(z, id);
                        }
                        id
                    }
                };
                if !sides.contains(&id) {
                    sides.push(id);
                }
            }
            if sides.len() != 2 {
                return Err(EulerError::WouldChangeTopology {
                    dim: i,
                    dart: x,
                    why: "meets a lower or higher cell in a way that would split it",
                });
            }
            if !corners.union(sides[0], sides[1]) {
                return Err(EulerError::WouldChangeTopology {
                    dim: i,
                    dart: x,
                    why: "appears twice between the same corners of a cell it touches",
                });
            }
        }
    }
    Ok(())
}

/// Whether the i-cell of `d` can be removed by [`try_remove_cell_keeping_homology`].
pub fn is_removable_keeping_homology<A: Attributes>(g: &GMap<A>, d: DartId, i: usize) -> bool {
    check_collapse(g, d, i, Move::Remove).is_ok()
}

/// Whether the i-cell of `d` can be contracted by [`try_contract_cell_keeping_homology`].
pub fn is_contractible_keeping_homology<A: Attributes>(g: &GMap<A>, d: DartId, i: usize) -> bool {
    check_collapse(g, d, i, Move::Contract).is_ok()
}

/// Deletes the darts of `cell` after re-linking `alpha_i` around it: a dart `y` outside
/// the cell linked to `x` inside gets the first dart outside reached by alternating
/// `alpha_nb`, `alpha_i` from `x` (or becomes i-free). Then reconciles the attributes from
/// the re-linked darts, `alpha_i(cell[0])` first: the merged cells keep the attributes of
/// its cells.
pub(super) fn collapse<A: Attributes>(g: &mut GMap<A>, cell: &[DartId], i: usize, nb: usize) {
    let set: HashSet<DartId> = cell.iter().copied().collect();
    let mut links: Vec<(DartId, DartId)> = Vec::new();
    for &x in cell {
        let y = g.alpha(x, i);
        if set.contains(&y) {
            continue;
        }
        let target = relink_target(g, &set, x, i, nb);
        links.push((y, target.unwrap_or(y)));
    }
    for &x in cell {
        g.remove_dart(x);
    }
    for &(y, z) in &links {
        if y == z {
            g.unlink(y, i);
        } else {
            g.link(y, z, i);
        }
    }
    if g.needs_reconcile() {
        let touched: Vec<DartId> = links.iter().flat_map(|&(y, z)| [y, z]).collect();
        reconcile(g, &touched);
    }
}

/// Applies a checked removal or contraction of the i-cell of `d` ([`collapse`]) and returns
/// the change of cells, recounted on the cells around it.
fn collapse_counted<A: Attributes>(g: &mut GMap<A>, d: DartId, i: usize, kind: Move) -> Vec<i64> {
    let cell = g.cell_darts(d, i);
    let mut touched: Vec<DartId> = cell.clone();
    touched.extend(cell.iter().map(|&x| g.alpha(x, i)));
    let before = local_counts(g, &touched);
    collapse(g, &cell, i, kind.neighbour(i));
    let after = local_counts(g, &touched);
    debug_check(g);
    diff(&after, &before)
}

/// Removes the i-cell of `d`, `i < n`, merging the two (i+1)-cells on its sides (`kve`,
/// `kef`, `kfs`, …), or removes a dangling edge with its free end
/// vertex (`kev`).
///
/// ```text
///   ┌───┬───┐          ┌───────┐
///   │ a │ b │   kef    │  a∪b  │   the middle edge goes, the faces merge
///   └───┴───┘          └───────┘
/// ```
/// Precondition ([`is_removable_keeping_homology`]): `i < n`; the cell has degree 2 (CGAL's condition:
/// `alpha_{i+1} alpha_{i+2}` is an involution on its darts); no dart is (i+1)-free; its
/// darts meet exactly two distinct (i+1)-cells, closed (no dart of theirs free for
/// `alpha_0` … `alpha_i`) for `i > 0`, and for a vertex two edges that make one edge once
/// re-linked (open edges, missing an end, may), and in every other cell it touches its
/// appearances join distinct corners without a cycle (else that cell would fall apart) —
/// or, for `i = 1`, the edge is dangling. This
/// is stricter than CGAL's [`remove_cell`](super::try_remove_cell), which also removes
/// cells with the same (i+1)-cell on both sides, on the boundary, and of dimension n: that
/// may change the space, and then no local rule gives the homology change.
/// Effect: `-X_i - X_{i+1}` (space unchanged) or `-X_0 - X_1` (a whisker collapsed).
///
/// Attributes: the two (i+1)-cells merge into the one of `d`, keeping its attribute (the
/// merge hook of dimension i + 1 runs when both had one, as CGAL's `remove_cell` calls
/// `on_merge`); the attribute of the removed cell goes with it, and so does the point of
/// the free end of a removed dangling edge; every other cell keeps its attribute and every
/// other vertex its point. O(size of the cells touched · n).
pub fn try_remove_cell_keeping_homology<A: Attributes>(
    g: &mut GMap<A>,
    d: DartId,
    i: usize,
) -> Result<EulerOp, EulerError> {
    let kind = check_collapse(g, d, i, Move::Remove)?;
    let dx = collapse_counted(g, d, i, Move::Remove);
    let name = match kind {
        Collapse::Dangling => "kev".to_string(),
        Collapse::Merge => op_name('k', i),
    };
    Ok(EulerOp::new(name, EpVector::from_cells(&dx)))
}

/// Like [`try_remove_cell_keeping_homology`], panicking when the precondition fails.
pub fn remove_cell_keeping_homology<A: Attributes>(g: &mut GMap<A>, d: DartId, i: usize) -> EulerOp {
    try_remove_cell_keeping_homology(g, d, i).unwrap_or_else(|e| panic!("remove_cell_keeping_homology: {e}"))
}

/// Contracts the i-cell of `d`, `i >= 1`, to an (i-1)-cell, merging the two (i-1)-cells
/// at its ends: the dual of [`try_remove_cell_keeping_homology`].
///
/// ```text
///   u ──── e ──── v ── …     kev     w ── …    the edge shrinks, u and v become w
/// ```
/// Precondition ([`is_contractible_keeping_homology`]): `1 <= i <= n`; dual degree 2
/// (`alpha_{i-1} alpha_{i-2}` an involution on the cell, vacuous for edges); no dart
/// free; its darts meet exactly two distinct (i-1)-cells, neither with a free dart; its
/// appearances in the other cells it touches join distinct corners without a cycle.
/// Effect `-X_{i-1} - X_i`,
/// homology unchanged.
///
/// Attributes: the two (i-1)-cells at its ends merge, keeping the attribute of the one
/// holding `d` (the merge hook of dimension i - 1 runs when both had one); for an edge,
/// the merged vertex keeps the point of `d`'s vertex. The contracted cell's attribute goes
/// with it. O(size of the cells touched · n).
pub fn try_contract_cell_keeping_homology<A: Attributes>(
    g: &mut GMap<A>,
    d: DartId,
    i: usize,
) -> Result<EulerOp, EulerError> {
    check_collapse(g, d, i, Move::Contract)?;
    let dx = collapse_counted(g, d, i, Move::Contract);
    // an edge contracted is the classical kev (kill edge and vertex), as its dual removal is kve
    let name = if i == 1 { "kev".to_string() } else { op_name('k', i - 1) };
    Ok(EulerOp::new(name, EpVector::from_cells(&dx)))
}

/// Like [`try_contract_cell_keeping_homology`], panicking when the precondition fails.
pub fn contract_cell_keeping_homology<A: Attributes>(g: &mut GMap<A>, d: DartId, i: usize) -> EulerOp {
    try_contract_cell_keeping_homology(g, d, i).unwrap_or_else(|e| panic!("contract_cell_keeping_homology: {e}"))
}
