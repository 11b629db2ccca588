//! Euler operators on the editable [`GMap`], in any dimension.
//!
//! Every operator comes as a predicate (`can_…` / `is_…`) that tells whether its
//! precondition holds and a `try_…` form that checks it and returns a typed [`EulerError`];
//! splits, removals and contractions also have a plain form that panics when the
//! precondition fails. Each returns an [`EulerOp`]: the classical name and the Euler–Poincaré vector
//! (AC §4–5). The change of cells in the vector is *recounted* on the cells that meet the
//! modified darts (cells that do not meet them are unchanged), so it is exact even in
//! degenerate configurations; the change of homology follows from the operator's
//! precondition, which makes every operator here a subdivision, a coalescence or a
//! collapse of the underlying space (a homotopy equivalence), hence `dy = 0` — except
//! [`try_close`], whose homology change is global and is left to the caller.
//!
//! In debug builds every operator checks BO Def. 1 on the result (`debug_assert`).
//!
//! [`EulerOp`]: crate::euler::EulerOp
//!
//! The operators are grouped by what they do: splits and insertions (`split`), removals and
//! contractions of cells of degree 2 (`collapse`), closing a boundary (`close`); all are
//! re-exported here.

mod close;
mod collapse;
mod error;
mod split;
mod star;

use rustc_hash::FxHashSet as HashSet;

use gmap_core::{DartId, GMap};

use super::vector::cell_letter;

pub use close::{can_close, try_close, CloseReport};
pub(crate) use collapse::Move;
pub use collapse::{contract_cell, is_contractible, is_removable, remove_cell, try_contract_cell, try_remove_cell};
pub use error::EulerError;
pub use split::{
    can_insert_dangling_edge, can_insert_edge, can_insert_vertex, can_split_cell, split_cell, try_insert_dangling_edge,
    try_insert_edge, try_insert_vertex, try_split_cell,
};
pub(crate) use split::{insert_edge_quietly, split_cell_quietly};
pub use star::{
    can_star_cell, can_star_face, insert_cell_0_in_cell_2, insert_point_in_cell, is_insertable_cell_0_in_cell_2,
    star_cell, star_face, try_star_cell, try_star_face, Starred,
};

/// `Ok` when `d` is a live dart of `g`.
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

/// In debug builds, panics when `g` is not a valid G-map (BO Def. 1).
fn debug_check(g: &GMap) {
    if cfg!(debug_assertions) {
        let (m, _) = g.to_dense();
        if let Err(e) = m.validate() {
            panic!("Euler operator broke validity: {e}");
        }
    }
}

/// `after - before`, entry by entry.
fn diff(after: &[i64], before: &[i64]) -> Vec<i64> {
    after.iter().zip(before).map(|(a, b)| a - b).collect()
}

/// The classical name of an operator that makes (`prefix` `m`) or kills (`k`) a `low`-cell
/// and a `(low + 1)`-cell together: `mve`, `mef`, `mfs`, `kev`, …
fn op_name(prefix: char, low: usize) -> String {
    format!("{prefix}{}{}", cell_letter(low), cell_letter(low + 1))
}
