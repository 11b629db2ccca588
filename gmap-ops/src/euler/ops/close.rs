//! Closing a boundary ([`try_close`]): every i-free dart gets a new partner, and the new
//! darts bound new i-cells.

use rustc_hash::FxHashMap as HashMap;

use gmap_core::{Attributes, DartId, GMap};

use super::common::{debug_check, diff, reconcile};
use super::EulerError;

/// What [`try_close`] did: the darts added and the change of cells. The change of
/// homology depends on the whole boundary being closed (a disc closes to a sphere, an
/// annulus too); complete it with [`EpVector::between`](crate::euler::EpVector::between) and a homology engine.
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
pub fn can_close<A: Attributes>(g: &GMap<A>, i: usize) -> bool {
    close_plan(g, i).is_ok()
}

fn close_plan<A: Attributes>(g: &GMap<A>, i: usize) -> Result<Vec<(DartId, Option<DartId>)>, EulerError> {
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
/// per boundary component.
///
/// Attributes: the new i-cells have none; the new darts join the other cells of the
/// darts they close and take their attributes and points (for `i >= 1` every new dart
/// lies in the vertex of its partner; `close(0)` makes new vertices, without points).
/// Should closing join cells that were apart, they merge as in a sew (the merge hook
/// runs). O(N n).
pub fn try_close<A: Attributes>(g: &mut GMap<A>, i: usize) -> Result<CloseReport, EulerError> {
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
    if g.needs_reconcile() {
        let mut touched: Vec<DartId> = plan.iter().map(|&(d, _)| d).collect();
        touched.extend(plan.iter().map(|(d, _)| new[d]));
        reconcile(g, &touched);
    }
    let after = dense_counts(g);
    debug_check(g);
    Ok(CloseReport { new_darts: plan.len(), dx: diff(&after, &before) })
}

fn dense_counts<A: Attributes>(g: &GMap<A>) -> Vec<i64> {
    g.to_dense().0.cell_counts().into_iter().map(|c| c as i64).collect()
}
