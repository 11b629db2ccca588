//! The steps every Euler operation shares: liveness, local counts, the debug check and the
//! reconciliation of attributes.

use rustc_hash::FxHashSet as HashSet;

use gmap_core::{Attributes, DartId, GMap, Point};

use super::error::EulerError;
use crate::euler::vector::cell_letter;

/// `Ok` when `d` is a live dart of `g`.
pub(super) fn live<A: Attributes>(g: &GMap<A>, d: DartId) -> Result<(), EulerError> {
    if g.contains(d) {
        Ok(())
    } else {
        Err(EulerError::NoSuchDart(d))
    }
}

/// Number of distinct k-cells (every k) meeting a set of darts (dead ones skipped).
/// O(total size of those cells · n).
pub(super) fn local_counts<A: Attributes>(g: &GMap<A>, darts: &[DartId]) -> Vec<i64> {
    (0..=g.dim()).map(|k| distinct_cells(g, darts.iter().copied(), k) as i64).collect()
}

/// Number of distinct k-cells meeting `darts` (dead ones skipped). O(total size of those
/// cells · n).
pub(super) fn distinct_cells<A: Attributes>(g: &GMap<A>, darts: impl Iterator<Item = DartId>, k: usize) -> usize {
    let mut seen: HashSet<DartId> = HashSet::default();
    let mut count = 0;
    for x in darts {
        if g.contains(x) && seen.insert(x) {
            count += 1;
            seen.extend(g.cell(x, k));
        }
    }
    count
}

/// In debug builds, panics when `g` is not a valid G-map (BO Def. 1) or when a cell's darts
/// disagree on an attribute or a point ([`GMap::check_attributes`]).
pub(super) fn debug_check<A: Attributes>(g: &GMap<A>) {
    if cfg!(debug_assertions) {
        let (m, _) = g.to_dense();
        if let Err(e) = m.validate() {
            panic!("Euler operator broke validity: {e}");
        }
        if let Err(e) = g.check_attributes() {
            panic!("Euler operator broke the attributes: {e}");
        }
    }
}

/// Repairs attributes and points after an operator's edit ([`GMap::reconcile_attributes`]),
/// when the map uses any: `touched` lists the darts whose links changed, those of the
/// side that keeps the original attributes first. O(size of the cells touched · n) per
/// slot in use, nothing when none is.
pub(super) fn reconcile<A: Attributes>(g: &mut GMap<A>, touched: &[DartId]) {
    if g.needs_reconcile() {
        g.reconcile_attributes(touched);
    }
}

/// The middle of the points of the vertices of `d` and `alpha_0(d)`, when `d` is not 0-free
/// and both have one: where [`try_insert_vertex`] puts the vertex it makes. O(1).
pub(super) fn edge_middle<A: Attributes>(g: &GMap<A>, d: DartId) -> Option<Point> {
    let e = g.alpha(d, 0);
    if e == d {
        return None;
    }
    let (p, q) = (g.point(d)?, g.point(e)?);
    Some([0.5 * (p[0] + q[0]), 0.5 * (p[1] + q[1]), 0.5 * (p[2] + q[2])])
}

/// `after - before`, entry by entry.
pub(super) fn diff(after: &[i64], before: &[i64]) -> Vec<i64> {
    after.iter().zip(before).map(|(a, b)| a - b).collect()
}

/// The classical name of an operator that makes (`prefix` `m`) or kills (`k`) a `low`-cell
/// and a `(low + 1)`-cell together: `mve`, `mef`, `mfs`, `kev`, …
pub(super) fn op_name(prefix: char, low: usize) -> String {
    format!("{prefix}{}{}", cell_letter(low), cell_letter(low + 1))
}
