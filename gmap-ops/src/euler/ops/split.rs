//! Splits: an i-cell cut in two by a new (i-1)-cell ([`try_split_cell`], with
//! [`try_insert_vertex`] and [`try_insert_edge`] as its cases i = 1, 2).

use rustc_hash::{FxHashMap as HashMap, FxHashSet as HashSet};

use gmap_core::{AlphaSet, Attributes, DartId, GMap, Point};

use super::common::{debug_check, diff, edge_middle, live, local_counts, op_name, reconcile};
use super::EulerError;
use crate::euler::vector::{EpVector, EulerOp};

/// The darts on side A of a cut of an i-cell: the closure of `seeds` under `alpha_k`
/// for `k <= i - 3` and `k >= i + 1`.
fn cut_closure<A: Attributes>(g: &GMap<A>, seeds: &[DartId], i: usize) -> Vec<DartId> {
    let n = g.dim();
    let mut set = AlphaSet::EMPTY;
    for k in 0..=n {
        if k + 3 <= i || k > i {
            set = set.with(k);
        }
    }
    let mut seen: HashSet<DartId> = HashSet::default();
    let mut out = Vec::new();
    for &s in seeds {
        if seen.contains(&s) {
            continue;
        }
        for x in g.orbit(s, set) {
            if seen.insert(x) {
                out.push(x);
            }
        }
    }
    out
}

/// The `alpha_{i-2}` partner of a cut dart inside the new (i-1)-cell: walk from `x` by
/// `alpha_{i-2}`, then alternately `alpha_{i-1}`, `alpha_{i-2}`, until a dart of the cut.
fn cut_partner<A: Attributes>(
    g: &GMap<A>,
    x: DartId,
    i: usize,
    cut: &HashSet<DartId>,
    limit: usize,
) -> Result<DartId, EulerError> {
    let mut y = g.alpha(x, i - 2);
    for _ in 0..limit {
        if cut.contains(&y) {
            return if y == x { Err(EulerError::OpenCut(x)) } else { Ok(y) };
        }
        let z = g.alpha(y, i - 1);
        if z == y {
            return Err(EulerError::Free { dart: y, alpha: i - 1 });
        }
        let w = g.alpha(z, i - 2);
        if w == z {
            return Err(EulerError::Free { dart: z, alpha: i - 2 });
        }
        y = w;
    }
    Err(EulerError::OpenCut(x))
}

/// A checked cut, ready to be applied.
struct Cut {
    darts: Vec<DartId>,
    partner: HashMap<DartId, DartId>,
}

fn check_cut<A: Attributes>(g: &GMap<A>, seeds: &[DartId], i: usize) -> Result<Cut, EulerError> {
    let n = g.dim();
    if i == 0 || i > n {
        return Err(EulerError::BadDimension { what: "cell split", lo: 1, hi: n, got: i });
    }
    let Some(&first) = seeds.first() else {
        return Err(EulerError::BadDimension { what: "cell split (no dart given)", lo: 1, hi: n, got: i });
    };
    for &s in seeds {
        live(g, s)?;
    }
    let cell: HashSet<DartId> = g.cell(first, i).into_iter().collect();
    let darts = cut_closure(g, seeds, i);
    let set: HashSet<DartId> = darts.iter().copied().collect();
    for &x in &darts {
        if !cell.contains(&x) {
            return Err(EulerError::Misplaced { dart: x, what: "cell being split" });
        }
        let w = g.alpha(x, i - 1);
        if w == x {
            // an edge with a missing end (EO's boundary-incomplete edge): its darts are all
            // 0-free and form one side; the new vertex goes between that side and the open
            // end, so the far part keeps the missing end
            if i == 1 {
                continue;
            }
            return Err(EulerError::Free { dart: x, alpha: i - 1 });
        }
        if set.contains(&w) {
            return Err(EulerError::Misplaced { dart: w, what: "other side of the cut" });
        }
    }
    let mut partner = HashMap::default();
    if i >= 2 {
        for &x in &darts {
            let z = cut_partner(g, x, i, &set, cell.len() + 1)?;
            partner.insert(x, z);
        }
        for (&x, &z) in &partner {
            if partner.get(&z) != Some(&x) {
                return Err(EulerError::OpenCut(x));
            }
        }
    }
    // separation: from side A, moving inside the i-cell without crossing alpha_{i-1} at the
    // cut, the other side must stay out of reach
    let cellset = AlphaSet::cell(i, n);
    let mut reach: HashSet<DartId> = HashSet::default();
    let mut stack = vec![first];
    reach.insert(first);
    while let Some(x) = stack.pop() {
        for k in cellset.iter() {
            if k == i - 1 && set.contains(&x) {
                continue;
            }
            let y = g.alpha(x, k);
            if k == i - 1 && set.contains(&y) {
                continue;
            }
            if reach.insert(y) {
                stack.push(y);
            }
        }
    }
    for &x in &darts {
        let w = g.alpha(x, i - 1);
        if w != x && reach.contains(&w) {
            return Err(EulerError::NotSeparating(x));
        }
    }
    Ok(Cut { darts, partner })
}

/// Whether [`try_split_cell`] would succeed for `seeds` and `i`.
pub fn can_split_cell<A: Attributes>(g: &GMap<A>, seeds: &[DartId], i: usize) -> bool {
    check_cut(g, seeds, i).is_ok()
}

/// Splits an i-cell in two by inserting an (i-1)-cell along a closed cut (EO's
/// `ms^{n-1}s^n`, CGAL's `insert_cell_0_in_cell_1`, `insert_cell_1_in_cell_2`,
/// `insert_cell_2_in_cell_3` in one routine, for every `1 <= i <= n`).
///
/// The cut is given by darts of side A: the darts whose `alpha_{i-1}` link crosses the cut,
/// taken on one side. The set is closed under `alpha_k` for `k <= i-3` and `k > i`
/// automatically. For i = 1 it is one dart of the edge (the vertex goes between it and its
/// `alpha_0`); for i = 2 the two corners' darts (see [`try_insert_edge`]); for i = 3 one dart
/// per edge of a closed path on the volume's boundary, all in faces of one side.
///
/// ```text
///   before:  x ──alpha_{i-1}── w        after:  x ─ a(x) ═alpha_i═ b(x) ─ w
/// ```
/// Each crossing `x — w` gets two new darts, `a(x)` on side A and `b(x)` on side B,
/// `alpha_i`-linked: they are the two sides of the new (i-1)-cell.
///
/// Attributes ([`gmap_core::attr`]): the i-cell's attribute stays on side A and side B
/// gets a copy (the split hook of dimension i runs once); the new (i-1)-cell has none; the
/// new darts join the other cells they meet and take their attributes and points. For
/// i = 1 the new vertex is placed as [`try_insert_vertex`] places it.
///
/// Precondition ([`can_split_cell`]): `1 <= i <= n`; the darts lie in one i-cell; none is
/// `(i-1)`-free (except for `i = 1`: an edge with a missing end, whose darts are all 0-free,
/// is cut between its one end and the missing one) and none is linked to another cut dart;
/// the walk that turns around each (i-3)-cell of the cut closes up; the cut separates the
/// cell. Effect: one more (i-1)-cell and one more i-cell, homology unchanged. O(size of the
/// i-cell · n).
pub fn try_split_cell<A: Attributes>(g: &mut GMap<A>, seeds: &[DartId], i: usize) -> Result<EulerOp, EulerError> {
    let point = if i == 1 { seeds.first().filter(|&&d| g.contains(d)).and_then(|&d| edge_middle(g, d)) } else { None };
    split_counted(g, seeds, i, point).map(|(op, _)| op)
}

/// [`try_split_cell`] with the point of the new vertex when `i = 1` (ignored otherwise);
/// returns the operator and `a(seeds[0])`, a dart of the new (i-1)-cell on side A.
pub(super) fn split_counted<A: Attributes>(
    g: &mut GMap<A>,
    seeds: &[DartId],
    i: usize,
    point: Option<Point>,
) -> Result<(EulerOp, DartId), EulerError> {
    let cut = check_cut(g, seeds, i)?;
    let mut touched: Vec<DartId> = cut.darts.clone();
    touched.extend(cut.darts.iter().map(|&x| g.alpha(x, i - 1)));
    let before = local_counts(g, &touched);
    let new_darts = apply_cut(g, &cut, i, point);
    let first = new_darts[0];
    touched.extend(new_darts);
    let after = local_counts(g, &touched);
    debug_check(g);
    Ok((EulerOp::new(op_name('m', i - 1), EpVector::from_cells(&diff(&after, &before))), first))
}

/// [`try_split_cell`] without the Euler–Poincaré bookkeeping, for searches that split many
/// cells and only keep the map: `false` (and `g` unchanged) when the precondition fails.
/// Attributes and points follow as in [`try_split_cell`]. O(size of the i-cell · n).
pub(crate) fn split_cell_quietly<A: Attributes>(g: &mut GMap<A>, seeds: &[DartId], i: usize) -> bool {
    match check_cut(g, seeds, i) {
        Ok(cut) => {
            let point = if i == 1 { edge_middle(g, cut.darts[0]) } else { None };
            apply_cut(g, &cut, i, point);
            true
        }
        Err(_) => false,
    }
}

/// [`try_insert_edge`] without the Euler–Poincaré bookkeeping (see [`split_cell_quietly`]).
pub(crate) fn insert_edge_quietly<A: Attributes>(g: &mut GMap<A>, d1: DartId, d2: DartId) -> bool {
    edge_cut(g, d1, d2).is_ok_and(|c| split_cell_quietly(g, &c, 2))
}

/// Links the two new darts of every crossing of a checked cut (see [`try_split_cell`]),
/// reconciles the attributes and, for i = 1, gives the new vertex `point`. Returns the new
/// darts: `a(x)` then `b(x)` for each cut dart `x` in the order of `cut.darts`.
fn apply_cut<A: Attributes>(g: &mut GMap<A>, cut: &Cut, i: usize, point: Option<Point>) -> Vec<DartId> {
    let n = g.dim();
    let mut a: HashMap<DartId, DartId> = HashMap::default();
    let mut b: HashMap<DartId, DartId> = HashMap::default();
    let mut new = Vec::with_capacity(2 * cut.darts.len());
    for &x in &cut.darts {
        let (ax, bx) = (g.create_dart(), g.create_dart());
        a.insert(x, ax);
        b.insert(x, bx);
        new.push(ax);
        new.push(bx);
    }
    // side A first, so that the split i-cell keeps its attribute there (collected only
    // when the map has attributes or points to repair)
    let repair = g.needs_reconcile();
    let mut touched: Vec<DartId> = if repair { cut.darts.clone() } else { Vec::new() };
    for &x in &cut.darts {
        let (ax, bx) = (a[&x], b[&x]);
        let w = g.alpha(x, i - 1);
        g.link(x, ax, i - 1);
        if w != x {
            g.link(w, bx, i - 1);
            if repair {
                touched.push(w);
            }
        }
        g.link(ax, bx, i);
        for k in 0..=n {
            if k + 3 <= i || k > i {
                let y = g.alpha(x, k);
                if y != x {
                    g.link(ax, a[&y], k);
                    g.link(bx, b[&y], k);
                }
            }
        }
        if i >= 2 {
            let z = cut.partner[&x];
            g.link(ax, a[&z], i - 2);
            g.link(bx, b[&z], i - 2);
        }
    }
    if repair {
        touched.extend(new.iter().copied());
        reconcile(g, &touched);
    }
    if i == 1 && point.is_some() {
        g.set_point(new[0], point);
    }
    new
}

/// Like [`try_split_cell`], panicking when the precondition fails.
pub fn split_cell<A: Attributes>(g: &mut GMap<A>, seeds: &[DartId], i: usize) -> EulerOp {
    try_split_cell(g, seeds, i).unwrap_or_else(|e| panic!("split_cell: {e}"))
}

/// Whether [`try_insert_vertex`] (and [`try_insert_vertex_at`]) would succeed.
pub fn can_insert_vertex<A: Attributes>(g: &GMap<A>, d: DartId) -> bool {
    g.contains(d) && g.dim() >= 1 && can_split_cell(g, &[d], 1)
}

/// Inserts a vertex in the edge of `d` (`mve`, CGAL's `insert_cell_0_in_cell_1`), whether
/// or not the edge's boundary is complete (EO §3.2: the subdivider `ms^{n-1}s^n` applies to
/// boundary-incomplete strata too).
///
/// ```text
///   u ─────────── v      becomes      u ───── w ───── v
///   u ─────────── ∘      becomes      u ───── w ───── ∘     (∘: the missing end)
/// ```
/// An edge with a missing end has 0-free darts (one side only); the new vertex `w` splits it
/// into a boundary-complete edge `u w` (the darts of `d`'s side and their new `alpha_0`
/// partners) and a boundary-incomplete edge from `w` to the missing end (new 0-free darts):
/// EO's `mve` on `e∞`, one more vertex, one more complete edge, the same number of
/// incomplete ones.
///
/// The point of `w`: the middle of the points of `u` and `v` when both have one (CGAL's
/// `insert_barycenter_in_cell<1>`), else none; [`try_insert_vertex_at`] takes it instead.
/// The edge's 1-attribute stays on the part `u w` and a copy goes to `w v` (the split hook
/// runs once).
///
/// Precondition ([`can_insert_vertex`]): `n >= 1` and the edge is not folded onto itself.
/// Effect `X_0 + X_1` (`B0 + A1`). O(edge size · n).
pub fn try_insert_vertex<A: Attributes>(g: &mut GMap<A>, d: DartId) -> Result<EulerOp, EulerError> {
    live(g, d)?;
    try_split_cell(g, &[d], 1)
}

/// [`try_insert_vertex`] with the point of the new vertex given: `Some(p)` places it at
/// `p`, `None` leaves it without a point. Same precondition ([`can_insert_vertex`]), effect
/// and cost.
pub fn try_insert_vertex_at<A: Attributes>(
    g: &mut GMap<A>,
    d: DartId,
    point: Option<Point>,
) -> Result<EulerOp, EulerError> {
    live(g, d)?;
    split_counted(g, &[d], 1, point).map(|(op, _)| op)
}

/// The two corner darts that define an edge inserted between the vertices of `d1` and
/// `d2` in their face: `d1`, and whichever of `d2`, `alpha_1(d2)` the face boundary
/// reaches first walking from `d1` by `alpha_0`, `alpha_1`, ….
pub(super) fn edge_cut<A: Attributes>(g: &GMap<A>, d1: DartId, d2: DartId) -> Result<[DartId; 2], EulerError> {
    live(g, d1)?;
    live(g, d2)?;
    if g.dim() < 2 {
        return Err(EulerError::BadDimension { what: "edge insertion", lo: 2, hi: g.dim(), got: g.dim() });
    }
    let corner = [d2, g.alpha(d2, 1)];
    if corner.contains(&d1) || corner.contains(&g.alpha(d1, 1)) {
        return Err(EulerError::Misplaced { dart: d2, what: "a corner other than d1's" });
    }
    let mut x = d1;
    let limit = g.cell(d1, 2).len() + 2;
    for _ in 0..limit {
        let y = g.alpha(x, 0);
        if y == x {
            return Err(EulerError::Free { dart: x, alpha: 0 });
        }
        if corner.contains(&y) {
            return Ok([d1, y]);
        }
        let z = g.alpha(y, 1);
        if z == y {
            return Err(EulerError::Free { dart: y, alpha: 1 });
        }
        if z == d1 {
            break;
        }
        if corner.contains(&z) {
            return Ok([d1, z]);
        }
        x = z;
    }
    Err(EulerError::Misplaced { dart: d2, what: "the face of d1" })
}

/// Whether [`try_insert_edge`] would succeed.
pub fn can_insert_edge<A: Attributes>(g: &GMap<A>, d1: DartId, d2: DartId) -> bool {
    edge_cut(g, d1, d2).map(|c| can_split_cell(g, &c, 2)).unwrap_or(false)
}

/// Inserts an edge across the face of `d1`, from the corner of `d1` (between `d1` and
/// `alpha_1(d1)`) to the corner of `d2` (`mef`, CGAL's `insert_cell_1_in_cell_2`).
///
/// ```text
///   ┌───────┐          ┌───────┐
///   │       │   mef    │      /│
///   │   f   │  ─────>  │  f1 / │   one face becomes two
///   │       │          │   / f2│
///   └───────┘          └───────┘
/// ```
/// The face's 2-attribute stays on the part holding `d1` and a copy goes to the other part
/// (the split hook runs once); the new edge has no 1-attribute.
///
/// Precondition ([`can_insert_edge`]): `n >= 2`; `d2` lies on the boundary of the face of
/// `d1` at another corner; the face boundary between them has no free dart. Effect
/// `X_1 + X_2` (`B1 + A2`). O(face size · n).
pub fn try_insert_edge<A: Attributes>(g: &mut GMap<A>, d1: DartId, d2: DartId) -> Result<EulerOp, EulerError> {
    let cut = edge_cut(g, d1, d2)?;
    try_split_cell(g, &cut, 2)
}
