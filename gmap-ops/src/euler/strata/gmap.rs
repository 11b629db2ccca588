//! EO's operators on G-maps: the counterparts among [`crate::euler::ops`], the counts of
//! complete and incomplete cells, and the stratified object a G-map carries.

use gmap_core::union_find::UnionFind;
use gmap_core::{DartId, DenseMap, GMap};

use super::catalogue::{EoOperator, Scheme};
use super::object::{alt, StratifiedObject};
use crate::euler::ops::{self, EulerError};
use crate::euler::vector::EulerOp;

/// EO's split of the cells of a G-map into boundary-complete and boundary-incomplete
/// ones: an i-cell is incomplete when one of its darts is free for some `alpha_k`, `k < i`
/// (an edge with a missing end has 0-free darts). Returns `(complete, incomplete)` counts
/// per dimension. O(N n).
pub fn incomplete_cells(map: &DenseMap) -> (Vec<usize>, Vec<usize>) {
    let n = map.dim();
    let mut complete = vec![0usize; n + 1];
    let mut incomplete = vec![0usize; n + 1];
    for i in 0..=n {
        let (_, bad) = cell_states(map, i);
        for b in bad {
            if b {
                incomplete[i] += 1;
            } else {
                complete[i] += 1;
            }
        }
    }
    (complete, incomplete)
}

/// The number of i-cells and, for each, whether it is boundary-incomplete.
fn cell_states(map: &DenseMap, i: usize) -> (usize, Vec<bool>) {
    let p = map.cells(i);
    let mut bad = vec![false; p.len()];
    for d in map.darts() {
        if (0..i).any(|k| map.is_free(d, k)) {
            bad[p.of[d.index()] as usize] = true;
        }
    }
    (p.len(), bad)
}

/// The counts a [`StratifiedObject`] and a G-map carrying the same object share: complete
/// and incomplete cells per dimension (as `i64`, by [`incomplete_cells`]) and the Euler
/// characteristic. O(N n).
pub fn map_counts(map: &DenseMap) -> (Vec<i64>, Vec<i64>, i64) {
    let (c, i) = incomplete_cells(map);
    let to = |v: Vec<usize>| v.into_iter().map(|x| x as i64).collect();
    (to(c), to(i), map.euler_characteristic())
}

impl EoOperator {
    /// The operator of [`crate::euler::ops`] that does the same on a G-map, when there is
    /// one: the subdividers of balls (`mve`, `mve∞`, `mef`, `mfs`) and their coalescers
    /// (`kve`, `kve∞`, `kef`, `kfs`). The other operators attach or detach strata with holes,
    /// or change only a state, which a G-map's cells (balls, complete exactly when no dart
    /// is free below their dimension) do not express as one operator.
    pub fn gmap_counterpart(&self) -> Option<&'static str> {
        match (self.scheme, self.inverse, self.n, self.open) {
            (Scheme::Subdivide, false, 1, _) => Some("try_insert_vertex"),
            (Scheme::Subdivide, true, 1, _) => Some("try_remove_cell_keeping_homology(_, 0)"),
            (Scheme::Subdivide, false, 2, false) => Some("try_insert_edge"),
            (Scheme::Subdivide, true, 2, false) => Some("try_remove_cell_keeping_homology(_, 1)"),
            (Scheme::Subdivide, false, 3, false) => Some("try_split_cell(_, 3)"),
            (Scheme::Subdivide, true, 3, false) => Some("try_remove_cell_keeping_homology(_, 2)"),
            _ => None,
        }
    }
}

fn edge_open(g: &GMap, d: DartId) -> bool {
    g.cell_darts(d, 1).iter().any(|&x| g.is_free(x, 0))
}

/// Applies the G-map counterpart of `op` ([`EoOperator::gmap_counterpart`]) at `darts`:
/// `[d]` for `mve`/`mve∞` (the edge of `d`) and for the coalescers (the cell of `d` that
/// goes), `[d1, d2]` for `mef` (the corners), the cut's darts for `mfs`. `None` when `op`
/// has no counterpart. The `∞` forms ask that the edge (for `kve∞`, one of the two edges)
/// miss an end, the plain forms that it not.
pub fn apply_on_gmap(op: EoOperator, g: &mut GMap, darts: &[DartId]) -> Option<Result<EulerOp, EulerError>> {
    op.gmap_counterpart()?;
    let &d = darts.first()?;
    if !g.contains(d) {
        return Some(Err(EulerError::NoSuchDart(d)));
    }
    let wrong = |what| Some(Err(EulerError::Misplaced { dart: d, what }));
    Some(match (op.inverse, op.n) {
        (false, 1) => {
            if edge_open(g, d) != op.open {
                return wrong(if op.open {
                    "an edge with a missing end (mve∞)"
                } else {
                    "an edge with both ends (mve)"
                });
            }
            ops::try_insert_vertex(g, d)
        }
        (true, 1) => {
            let open = g.cell_darts(d, 0).iter().any(|&x| edge_open(g, x));
            if open != op.open {
                return wrong(if op.open {
                    "a vertex next to an edge with a missing end (kve∞)"
                } else {
                    "a vertex between edges with both ends (kve)"
                });
            }
            ops::try_remove_cell_keeping_homology(g, d, 0)
        }
        (false, 2) => ops::try_insert_edge(g, d, *darts.get(1)?),
        (false, 3) => ops::try_split_cell(g, darts, 3),
        (true, i) => ops::try_remove_cell_keeping_homology(g, d, i - 1),
        _ => return None,
    })
}

impl StratifiedObject {
    /// The stratified object a G-map carries: one stratum per cell (a ball), boundary-
    /// complete as [`incomplete_cells`] says, bounded by the lower cells it meets; the
    /// complete cells form components by incidence, each incomplete cell is a stratum
    /// component of its own. The global holes of a complete component are read from its
    /// Euler characteristic χ: `1 - χ` 1-holes when χ <= 1, else `χ - 1` 2-holes (exact for
    /// graphs, discs, annuli and spheres; other surfaces get the right χ, not their Betti
    /// numbers). Returns the object and, per dimension i, the stratum of each i-cell
    /// (numbered as [`DenseMap::cells`]). O(N n²).
    pub fn from_map(map: &DenseMap) -> (StratifiedObject, Vec<Vec<usize>>) {
        let n = map.dim();
        let mut o = StratifiedObject::new();
        let parts: Vec<_> = (0..=n).map(|i| map.cells(i)).collect();
        let states: Vec<Vec<bool>> = (0..=n).map(|i| cell_states(map, i).1).collect();
        let mut ids: Vec<Vec<usize>> = Vec::new();
        for (i, st) in states.iter().enumerate() {
            ids.push(st.iter().map(|&bad| o.new_stratum(i, !bad, usize::MAX, &[])).collect());
        }
        // frontiers: the lower cells met by the darts of each cell
        for d in map.darts() {
            for i in 1..=n {
                let s = ids[i][parts[i].of[d.index()] as usize];
                for (j, part) in parts.iter().enumerate().take(i) {
                    let b = ids[j][part.of[d.index()] as usize];
                    if !o.strata[s].frontier.contains(&b) {
                        o.strata[s].frontier.push(b);
                    }
                }
            }
        }
        // components of the complete part, by incidence
        let total = o.strata.len();
        let mut uf = UnionFind::new(total);
        for s in 0..total {
            if o.strata[s].complete {
                for &b in &o.strata[s].frontier {
                    if o.strata[b].complete {
                        uf.union(s as u32, b as u32);
                    }
                }
            }
        }
        let mut comp_of_root: Vec<Option<usize>> = vec![None; total];
        for s in 0..total {
            let c = if o.strata[s].complete {
                let r = uf.find(s as u32) as usize;
                match comp_of_root[r] {
                    Some(c) => c,
                    None => {
                        let c = o.new_component(true);
                        comp_of_root[r] = Some(c);
                        c
                    }
                }
            } else {
                o.new_component(false)
            };
            o.strata[s].component = c;
        }
        for c in 0..o.components.len() {
            if !o.components[c].complete {
                continue;
            }
            let chi: i64 = o.strata_of(c).iter().map(|&s| super::object::sign(o.strata[s].dim)).sum();
            let holes = if chi <= 1 { vec![0, 1 - chi] } else { vec![0, 0, chi - 1] };
            debug_assert_eq!(alt(&holes), chi);
            o.components[c].holes = holes;
        }
        (o, ids)
    }
}
