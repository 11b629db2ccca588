//! Euler operators on the editable [`GMap`], in any dimension.
//!
//! Every operator comes in three forms: a predicate (`can_…` / `is_…`) that tells whether
//! its precondition holds, a `try_…` form that checks it and returns a typed
//! [`EulerError`], and (for the splitting operators) an unchecked-free convenience that
//! panics. Each returns an [`EulerOp`]: the classical name and the Euler–Poincaré vector
//! (AC §4–5). The change of cells in the vector is *recounted* on the cells that meet the
//! modified darts (cells that do not meet them are unchanged), so it is exact even in
//! degenerate configurations; the change of homology follows from the operator's
//! precondition, which makes every operator here a subdivision, a coalescence or a
//! collapse of the underlying space (a homotopy equivalence), hence `dy = 0` — except
//! [`try_close`], whose homology change is global and is left to the caller.
//!
//! In debug builds every operator checks BO Def. 1 on the result (`debug_assert`).

use rustc_hash::{FxHashMap as HashMap, FxHashSet as HashSet};

use gmap_core::{AlphaSet, DartId, GMap};
use thiserror::Error;

use super::vector::{cell_letter, EpVector, EulerOp};

/// Why an Euler operator cannot be applied. Each variant names the offending dart.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
pub enum EulerError {
    /// A handle does not name a live dart.
    #[error("dart {0:?} does not exist")]
    NoSuchDart(DartId),
    /// The cell dimension is out of range for the operator and the map.
    #[error("a {what} needs a cell dimension in {lo}..={hi}, got {got}")]
    BadDimension {
        /// the operator
        what: &'static str,
        /// lowest allowed
        lo: usize,
        /// highest allowed
        hi: usize,
        /// given
        got: usize,
    },
    /// A dart that must be linked by `alpha_i` is i-free (an incomplete boundary).
    #[error("dart {dart:?} is {alpha}-free")]
    Free {
        /// the dart
        dart: DartId,
        /// the involution
        alpha: usize,
    },
    /// The darts given do not lie in one i-cell, or lie on both sides of the cut.
    #[error("dart {dart:?} is not where the {what} needs it")]
    Misplaced {
        /// the dart
        dart: DartId,
        /// what was expected
        what: &'static str,
    },
    /// The cut does not close up: walking around it from this dart does not come back.
    #[error("the cut is not closed at dart {0:?}")]
    OpenCut(DartId),
    /// The cut does not separate the cell into two parts.
    #[error("the cut through dart {0:?} does not separate its cell")]
    NotSeparating(DartId),
    /// The cell's degree is not 2 (CGAL's condition: `alpha_{i+1} alpha_{i+2}` must be an
    /// involution on the cell for removal, `alpha_{i-1} alpha_{i-2}` for contraction).
    #[error("the {dim}-cell of dart {dart:?} has degree above 2")]
    DegreeAboveTwo {
        /// the cell dimension
        dim: usize,
        /// a dart where the condition fails
        dart: DartId,
    },
    /// Removing or contracting this cell would change the topology (the same cell lies on
    /// both sides, or the cell is on the boundary).
    #[error("the {dim}-cell of dart {dart:?} {why}")]
    WouldChangeTopology {
        /// the cell dimension
        dim: usize,
        /// a dart of the cell
        dart: DartId,
        /// the reason
        why: &'static str,
    },
}

fn live(g: &GMap, d: DartId) -> Result<(), EulerError> {
    if g.contains(d) {
        Ok(())
    } else {
        Err(EulerError::NoSuchDart(d))
    }
}

/// Number of distinct k-cells (every k) meeting a set of live darts. O(total size of
/// those cells · n).
fn local_counts(g: &GMap, darts: &[DartId]) -> Vec<i64> {
    let n = g.dim();
    let mut out = vec![0i64; n + 1];
    for (k, slot) in out.iter_mut().enumerate() {
        let mut seen: HashSet<DartId> = HashSet::default();
        for &d in darts {
            if !g.contains(d) || seen.contains(&d) {
                continue;
            }
            *slot += 1;
            seen.extend(g.cell(d, k));
        }
    }
    out
}

fn debug_check(g: &GMap) {
    if cfg!(debug_assertions) {
        let (m, _) = g.to_dense();
        if let Err(e) = m.validate() {
            panic!("Euler operator broke validity: {e}");
        }
    }
}

fn diff(after: &[i64], before: &[i64]) -> Vec<i64> {
    after.iter().zip(before).map(|(a, b)| a - b).collect()
}

/// The darts on side A of a cut of an i-cell: the closure of `seeds` under `alpha_k`
/// for `k <= i - 3` and `k >= i + 1`.
fn cut_closure(g: &GMap, seeds: &[DartId], i: usize) -> Vec<DartId> {
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
fn cut_partner(g: &GMap, x: DartId, i: usize, cut: &HashSet<DartId>, limit: usize) -> Result<DartId, EulerError> {
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

fn check_cut(g: &GMap, seeds: &[DartId], i: usize) -> Result<Cut, EulerError> {
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
        if reach.contains(&g.alpha(x, i - 1)) {
            return Err(EulerError::NotSeparating(x));
        }
    }
    Ok(Cut { darts, partner })
}

/// Whether [`try_split_cell`] would succeed for `seeds` and `i`.
pub fn can_split_cell(g: &GMap, seeds: &[DartId], i: usize) -> bool {
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
/// Precondition ([`can_split_cell`]): `1 <= i <= n`; the darts lie in one i-cell; none is
/// `(i-1)`-free and none is linked to another cut dart; the walk that turns around each
/// (i-3)-cell of the cut closes up; the cut separates the cell. Effect: one more
/// (i-1)-cell and one more i-cell, homology unchanged. O(size of the i-cell · n).
pub fn try_split_cell(g: &mut GMap, seeds: &[DartId], i: usize) -> Result<EulerOp, EulerError> {
    let cut = check_cut(g, seeds, i)?;
    let mut touched: Vec<DartId> = cut.darts.clone();
    touched.extend(cut.darts.iter().map(|&x| g.alpha(x, i - 1)));
    let before = local_counts(g, &touched);
    let new_darts = apply_cut(g, &cut, i);
    touched.extend(new_darts);
    let after = local_counts(g, &touched);
    debug_check(g);
    let name = match i {
        1 => "mve".to_string(),
        2 => "mef".to_string(),
        3 => "mfs".to_string(),
        _ => format!("m{}{}", cell_letter(i - 1), cell_letter(i)),
    };
    Ok(EulerOp::new(name, EpVector::from_cells(&diff(&after, &before))))
}

/// [`try_split_cell`] without the Euler–Poincaré bookkeeping, for searches that split many
/// cells and only keep the map: `false` (and `g` unchanged) when the precondition fails.
/// O(size of the i-cell · n).
pub(crate) fn split_cell_quietly(g: &mut GMap, seeds: &[DartId], i: usize) -> bool {
    match check_cut(g, seeds, i) {
        Ok(cut) => {
            apply_cut(g, &cut, i);
            true
        }
        Err(_) => false,
    }
}

/// [`try_insert_edge`] without the Euler–Poincaré bookkeeping (see [`split_cell_quietly`]).
pub(crate) fn insert_edge_quietly(g: &mut GMap, d1: DartId, d2: DartId) -> bool {
    edge_cut(g, d1, d2).is_ok_and(|c| split_cell_quietly(g, &c, 2))
}

/// Links the two new darts of every crossing of a checked cut (see [`try_split_cell`]);
/// returns the new darts.
fn apply_cut(g: &mut GMap, cut: &Cut, i: usize) -> Vec<DartId> {
    let n = g.dim();
    let mut a: HashMap<DartId, DartId> = HashMap::default();
    let mut b: HashMap<DartId, DartId> = HashMap::default();
    for &x in &cut.darts {
        a.insert(x, g.create_dart());
        b.insert(x, g.create_dart());
    }
    for &x in &cut.darts {
        let (ax, bx) = (a[&x], b[&x]);
        let w = g.alpha(x, i - 1);
        g.link(x, ax, i - 1);
        g.link(w, bx, i - 1);
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
    a.into_values().chain(b.into_values()).collect()
}

/// Like [`try_split_cell`], panicking when the precondition fails.
pub fn split_cell(g: &mut GMap, seeds: &[DartId], i: usize) -> EulerOp {
    try_split_cell(g, seeds, i).unwrap_or_else(|e| panic!("split_cell: {e}"))
}

/// Whether [`try_insert_vertex`] would succeed.
pub fn can_insert_vertex(g: &GMap, d: DartId) -> bool {
    g.contains(d) && g.dim() >= 1 && can_split_cell(g, &[d], 1)
}

/// Inserts a vertex in the edge of `d` (`mve`, CGAL's `insert_cell_0_in_cell_1`).
///
/// ```text
///   u ─────────── v      becomes      u ───── w ───── v
/// ```
/// Precondition ([`can_insert_vertex`]): `n >= 1`, the edge has both ends (no 0-free dart)
/// and is not folded onto itself. Effect `X_0 + X_1` (`B0 + A1`). O(edge size · n).
pub fn try_insert_vertex(g: &mut GMap, d: DartId) -> Result<EulerOp, EulerError> {
    live(g, d)?;
    try_split_cell(g, &[d], 1)
}

/// The two corner darts that define an edge inserted between the vertices of `d1` and
/// `d2` in their face: `d1`, and whichever of `d2`, `alpha_1(d2)` the face boundary
/// reaches first walking from `d1` by `alpha_0`, `alpha_1`, ….
fn edge_cut(g: &GMap, d1: DartId, d2: DartId) -> Result<[DartId; 2], EulerError> {
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
pub fn can_insert_edge(g: &GMap, d1: DartId, d2: DartId) -> bool {
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
/// Precondition ([`can_insert_edge`]): `n >= 2`; `d2` lies on the boundary of the face of
/// `d1` at another corner; the face boundary between them has no free dart. Effect
/// `X_1 + X_2` (`B1 + A2`). O(face size · n).
pub fn try_insert_edge(g: &mut GMap, d1: DartId, d2: DartId) -> Result<EulerOp, EulerError> {
    let cut = edge_cut(g, d1, d2)?;
    try_split_cell(g, &cut, 2)
}

/// Whether [`try_insert_dangling_edge`] would succeed.
pub fn can_insert_dangling_edge(g: &GMap, d: DartId) -> bool {
    g.contains(d) && g.dim() >= 2 && !g.is_free(d, 1)
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
/// Precondition ([`can_insert_dangling_edge`]): `n >= 2` and `d` is not 1-free. Effect
/// `X_0 + X_1` (`B0 + A1`). O(size of the cells touched · n).
pub fn try_insert_dangling_edge(g: &mut GMap, d: DartId) -> Result<EulerOp, EulerError> {
    live(g, d)?;
    let n = g.dim();
    if n < 2 {
        return Err(EulerError::BadDimension { what: "dangling edge", lo: 2, hi: n, got: n });
    }
    if g.is_free(d, 1) {
        return Err(EulerError::Free { dart: d, alpha: 1 });
    }
    // copies of the corner across alpha_3..alpha_n
    let corners = g.orbit(d, AlphaSet::range(3, n));
    let mut touched: Vec<DartId> = corners.clone();
    touched.extend(corners.iter().map(|&x| g.alpha(x, 1)));
    let before = local_counts(g, &touched);
    // per corner copy: p (next to x), q (next to alpha_1 x), p2, q2 at the far end
    let mut new: HashMap<DartId, [DartId; 4]> = HashMap::default();
    for &x in &corners {
        let ds = [g.create_dart(), g.create_dart(), g.create_dart(), g.create_dart()];
        new.insert(x, ds);
    }
    for &x in &corners {
        let [p, q, p2, q2] = new[&x];
        let y = g.alpha(x, 1);
        g.link(x, p, 1);
        g.link(y, q, 1);
        g.link(p, p2, 0);
        g.link(q, q2, 0);
        g.link(p, q, 2);
        g.link(p2, q2, 2);
        g.link(p2, q2, 1);
        for k in 3..=n {
            let z = g.alpha(x, k);
            if z != x {
                let o = new[&z];
                for t in 0..4 {
                    g.link(new[&x][t], o[t], k);
                }
            }
        }
    }
    touched.extend(new.values().flatten());
    let after = local_counts(g, &touched);
    debug_check(g);
    Ok(EulerOp::new("mev", EpVector::from_cells(&diff(&after, &before))))
}

/// How a removal or contraction will rewire the map.
enum Collapse {
    /// the cell separates two distinct cells of the next dimension (or, for contraction,
    /// of the previous one)
    Merge,
    /// an edge hanging from a vertex into a face (removal only)
    Dangling,
}

/// Shared check of [`is_removable`] (`dir = +1`) and [`is_contractible`] (`dir = -1`).
fn check_collapse(g: &GMap, d: DartId, i: usize, remove: bool) -> Result<Collapse, EulerError> {
    live(g, d)?;
    let n = g.dim();
    let (what, lo, hi) = if remove { ("removal", 0, n.saturating_sub(1)) } else { ("contraction", 1, n) };
    if i < lo || i > hi || (remove && n == 0) {
        return Err(EulerError::BadDimension { what, lo, hi, got: i });
    }
    let cell = g.cell(d, i);
    // the neighbour involution (i+1 or i-1) and the next one (i+2 or i-2)
    let nb = if remove { i + 1 } else { i - 1 };
    let nb2 = if remove { (i + 2 <= n).then_some(i + 2) } else { i.checked_sub(2) };
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
            sides.extend(g.cell(x, nb));
        }
    }
    if free {
        return Err(EulerError::WouldChangeTopology { dim: i, dart: d, why: "lies on the boundary" });
    }
    if count == 2 {
        if !remove {
            // both end cells interior: no free dart in the cell or at its ends
            for &x in &cell {
                for y in g.cell(x, nb) {
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
        let above = AlphaSet::above(1, n);
        for &x in &cell {
            // the end <alpha_2..alpha_n>(x) lies inside the vertex: equal sizes, equal sets
            if g.cell(x, 0).len() == g.orbit(x, above).len() {
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

/// The corner test: in every k-cell (k other than i and nb) that the cell meets, its
/// appearances (orbits of the cell without alpha_i and alpha_k) must each join two distinct
/// corners (orbits of every involution but alpha_nb and alpha_k), and these joins must
/// form a forest; otherwise the k-cell would fall apart.
fn check_corners(g: &GMap, cell: &[DartId], i: usize, nb: usize) -> Result<(), EulerError> {
    let n = g.dim();
    for k in (0..=n).filter(|&k| k != i && k != nb) {
        let app_set = AlphaSet::all(n).without(i).without(k);
        let corner_set = AlphaSet::all(n).without(nb).without(k);
        let mut corner_of: HashMap<DartId, usize> = HashMap::default();
        let mut parent: Vec<usize> = Vec::new();
        let mut seen: HashSet<DartId> = HashSet::default();
        for &x in cell {
            if seen.contains(&x) {
                continue;
            }
            let app = g.orbit(x, app_set);
            seen.extend(app.iter().copied());
            let mut sides: Vec<usize> = Vec::new();
            for &y in &app {
                let id = match corner_of.get(&y) {
                    Some(&id) => id,
                    None => {
                        let id = parent.len();
                        parent.push(id);
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
            let find = |p: &Vec<usize>, mut v: usize| {
                while p[v] != v {
                    v = p[v];
                }
                v
            };
            let (a, b) = (find(&parent, sides[0]), find(&parent, sides[1]));
            if a == b {
                return Err(EulerError::WouldChangeTopology {
                    dim: i,
                    dart: x,
                    why: "appears twice between the same corners of a cell it touches",
                });
            }
            parent[a] = b;
        }
    }
    Ok(())
}

/// Whether the i-cell of `d` can be removed by [`try_remove_cell`].
pub fn is_removable(g: &GMap, d: DartId, i: usize) -> bool {
    check_collapse(g, d, i, true).is_ok()
}

/// Whether the i-cell of `d` can be contracted by [`try_contract_cell`].
pub fn is_contractible(g: &GMap, d: DartId, i: usize) -> bool {
    check_collapse(g, d, i, false).is_ok()
}

/// Deletes the darts of `cell` after re-linking `alpha_i` around it: a dart `y` outside
/// the cell linked to `x` inside gets the first dart outside reached by alternating
/// `alpha_nb`, `alpha_i` from `x` (or becomes i-free).
fn collapse(g: &mut GMap, cell: &[DartId], i: usize, nb: usize) {
    let set: HashSet<DartId> = cell.iter().copied().collect();
    let mut links: Vec<(DartId, DartId)> = Vec::new();
    for &x in cell {
        let y = g.alpha(x, i);
        if set.contains(&y) {
            continue;
        }
        let mut w = g.alpha(x, nb);
        let mut z = g.alpha(w, i);
        let mut steps = 0;
        while set.contains(&z) && z != w && steps <= cell.len() {
            w = g.alpha(z, nb);
            z = g.alpha(w, i);
            steps += 1;
        }
        let target = if set.contains(&z) { y } else { z };
        links.push((y, target));
    }
    for &x in cell {
        g.remove_dart(x);
    }
    for (y, z) in links {
        if y == z {
            g.unlink(y, i);
        } else {
            g.link(y, z, i);
        }
    }
}

/// Removes the i-cell of `d`, `i < n`, merging the two (i+1)-cells on its sides (`kve`,
/// `kef`, `kfs`, …; CGAL's `remove_cell<i>`), or removes a dangling edge with its free end
/// vertex (`kev`).
///
/// ```text
///   ┌───┬───┐          ┌───────┐
///   │ a │ b │   kef    │  a∪b  │   the middle edge goes, the faces merge
///   └───┴───┘          └───────┘
/// ```
/// Precondition ([`is_removable`]): `i < n`; the cell has degree 2 (CGAL's condition:
/// `alpha_{i+1} alpha_{i+2}` is an involution on its darts); no dart is (i+1)-free; its
/// darts meet exactly two distinct (i+1)-cells, and in every other cell it touches its
/// appearances join distinct corners without a cycle (else that cell would fall apart) —
/// or, for `i = 1`, the edge is dangling. This
/// is stricter than CGAL, which also removes cells with the same (i+1)-cell on both
/// sides: that changes the space, and then no local rule gives the homology change.
/// Effect: `-X_i - X_{i+1}` (space unchanged) or `-X_0 - X_1` (a whisker collapsed).
/// O(size of the cells touched · n).
pub fn try_remove_cell(g: &mut GMap, d: DartId, i: usize) -> Result<EulerOp, EulerError> {
    let kind = check_collapse(g, d, i, true)?;
    let cell = g.cell(d, i);
    let mut touched: Vec<DartId> = cell.clone();
    touched.extend(cell.iter().map(|&x| g.alpha(x, i)));
    let before = local_counts(g, &touched);
    collapse(g, &cell, i, i + 1);
    let after = local_counts(g, &touched);
    debug_check(g);
    let name = match (kind, i) {
        (Collapse::Dangling, _) => "kev".to_string(),
        (Collapse::Merge, 0) => "kve".to_string(),
        (Collapse::Merge, 1) => "kef".to_string(),
        (Collapse::Merge, 2) => "kfs".to_string(),
        (Collapse::Merge, _) => format!("k{}{}", cell_letter(i), cell_letter(i + 1)),
    };
    Ok(EulerOp::new(name, EpVector::from_cells(&diff(&after, &before))))
}

/// Like [`try_remove_cell`], panicking when the precondition fails.
pub fn remove_cell(g: &mut GMap, d: DartId, i: usize) -> EulerOp {
    try_remove_cell(g, d, i).unwrap_or_else(|e| panic!("remove_cell: {e}"))
}

/// Contracts the i-cell of `d`, `i >= 1`, to an (i-1)-cell, merging the two (i-1)-cells
/// at its ends (CGAL's `contract_cell<i>`): the dual of [`try_remove_cell`].
///
/// ```text
///   u ──── e ──── v ── …     kev     w ── …    the edge shrinks, u and v become w
/// ```
/// Precondition ([`is_contractible`]): `1 <= i <= n`; dual degree 2
/// (`alpha_{i-1} alpha_{i-2}` an involution on the cell, vacuous for edges); no dart
/// free; its darts meet exactly two distinct (i-1)-cells, neither with a free dart; its
/// appearances in the other cells it touches join distinct corners without a cycle.
/// Effect `-X_{i-1} - X_i`,
/// homology unchanged. O(size of the cells touched · n).
pub fn try_contract_cell(g: &mut GMap, d: DartId, i: usize) -> Result<EulerOp, EulerError> {
    check_collapse(g, d, i, false)?;
    let cell = g.cell(d, i);
    let mut touched: Vec<DartId> = cell.clone();
    touched.extend(cell.iter().map(|&x| g.alpha(x, i)));
    let before = local_counts(g, &touched);
    collapse(g, &cell, i, i - 1);
    let after = local_counts(g, &touched);
    debug_check(g);
    let name = match i {
        1 => "kev".to_string(),
        2 => "kef".to_string(),
        3 => "kfs".to_string(),
        _ => format!("k{}{}", cell_letter(i - 1), cell_letter(i)),
    };
    Ok(EulerOp::new(name, EpVector::from_cells(&diff(&after, &before))))
}

/// Like [`try_contract_cell`], panicking when the precondition fails.
pub fn contract_cell(g: &mut GMap, d: DartId, i: usize) -> EulerOp {
    try_contract_cell(g, d, i).unwrap_or_else(|e| panic!("contract_cell: {e}"))
}

/// What [`try_close`] did: the darts added and the change of cells. The change of
/// homology depends on the whole boundary being closed (a disc closes to a sphere, an
/// annulus too); complete it with [`EpVector::between`] and a homology engine.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CloseReport {
    /// number of darts created
    pub new_darts: usize,
    /// change of the number of cells of every dimension
    pub dx: Vec<i64>,
}

/// Whether [`try_close`] would succeed: `i <= n`, and around every i-free dart the walk
/// alternating `alpha_{i-1}` and `alpha_i` reaches another i-free dart without meeting an
/// (i-1)-free one.
pub fn can_close(g: &GMap, i: usize) -> bool {
    close_plan(g, i).is_ok()
}

fn close_plan(g: &GMap, i: usize) -> Result<Vec<(DartId, Option<DartId>)>, EulerError> {
    let n = g.dim();
    if i > n {
        return Err(EulerError::BadDimension { what: "close", lo: 0, hi: n, got: i });
    }
    let free: Vec<DartId> = g.darts().filter(|&d| g.is_free(d, i)).collect();
    let mut plan = Vec::with_capacity(free.len());
    for &d in &free {
        if i == 0 {
            plan.push((d, None));
            continue;
        }
        let mut e = g.alpha(d, i - 1);
        let mut steps = 0;
        loop {
            if g.is_free(e, i) {
                break;
            }
            let f = g.alpha(e, i);
            let h = g.alpha(f, i - 1);
            if h == f {
                return Err(EulerError::Free { dart: f, alpha: i - 1 });
            }
            e = h;
            steps += 1;
            if steps > g.dart_count() {
                return Err(EulerError::OpenCut(d));
            }
        }
        plan.push((d, Some(e)));
    }
    Ok(plan)
}

/// Closes the i-boundary (CGAL's `close<i>`): every i-free dart `d` gets a new dart `d'` as
/// `alpha_i(d)`; the new darts copy the links of the old ones for `alpha_k`, `|k - i| >= 2`,
/// and are `alpha_{i-1}`-linked around the old boundary so that they bound new i-cells.
/// They are (i+1)-free.
///
/// ```text
///   an open disc (the boundary cycle is 2-free)   close(2)   a sphere: a new face caps it
/// ```
/// Precondition ([`can_close`]). Effect on cells: recounted over the whole map
/// ([`CloseReport::dx`]); `close(n)` on a map with complete lower boundaries adds one n-cell
/// per boundary component. O(N n).
pub fn try_close(g: &mut GMap, i: usize) -> Result<CloseReport, EulerError> {
    let plan = close_plan(g, i)?;
    let n = g.dim();
    let before = dense_counts(g);
    let mut new: HashMap<DartId, DartId> = HashMap::default();
    for &(d, _) in &plan {
        new.insert(d, g.create_dart());
    }
    for &(d, e) in &plan {
        let nd = new[&d];
        g.link(d, nd, i);
        if let Some(e) = e {
            g.link(nd, new[&e], i - 1);
        }
        for k in 0..=n {
            if k + 2 <= i || k >= i + 2 {
                let y = g.alpha(d, k);
                if y != d {
                    g.link(nd, new[&y], k);
                }
            }
        }
    }
    let after = dense_counts(g);
    debug_check(g);
    Ok(CloseReport { new_darts: plan.len(), dx: diff(&after, &before) })
}

fn dense_counts(g: &GMap) -> Vec<i64> {
    g.to_dense().0.cell_counts().into_iter().map(|c| c as i64).collect()
}
