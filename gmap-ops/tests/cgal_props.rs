//! Property tests of CGAL's removal, contraction and insertions on random maps: random
//! sequences of operations on maps made of builder objects keep the map valid, and each
//! changes the cells as CGAL's documentation of the operation says.
//!
//! * `remove_cell<i>` (CGAL: "the i-cell is removed; for i < n the two (i+1)-cells
//!   incident to it are merged") and `contract_cell<i>`: the predicate and the `try_` form
//!   agree, the map stays valid, exactly one i-cell less (only `alpha_i` is re-linked, so
//!   the other i-cells stay), the darts of the cell deleted.
//! * Where the homology-keeping predicate holds, CGAL's does too, CGAL's operation gives
//!   the same map as the homology-keeping one, the two (i±1)-cells on its sides become one
//!   and the homology-keeping operator's Euler–Poincaré vector is the change of cells, with
//!   the Euler characteristic unchanged — also on maps left degenerate by CGAL's
//!   space-changing removals (open faces and volumes, whose merge the homology-keeping
//!   predicate refuses: seeds 19bab745 and a4a0f1c1 in the regressions file).
//! * `insert_cell_0_in_cell_1`: one vertex more and, on an edge with both ends, one edge
//!   more (χ unchanged); `insert_cell_1_in_cell_2`: one edge and one face more.

use gmap_core::{DartId, GMap};
use gmap_ops::build;
use gmap_ops::euler::ops;
use gmap_ops::iso::are_isomorphic;
use proptest::prelude::*;

#[derive(Clone, Debug)]
enum Step {
    Remove(usize, usize),
    Contract(usize, usize),
    Vertex(usize),
    Edge(usize),
}

fn step_strategy() -> impl Strategy<Value = Step> {
    let p = any::<usize>();
    prop_oneof![
        3 => (p, 0usize..4).prop_map(|(a, i)| Step::Remove(a, i)),
        3 => (p, 0usize..4).prop_map(|(a, i)| Step::Contract(a, i)),
        1 => p.prop_map(Step::Vertex),
        1 => p.prop_map(Step::Edge),
    ]
}

/// Number of distinct j-cells meeting the darts of `cell`.
fn meeting(g: &GMap, cell: &[DartId], j: usize) -> usize {
    let mut seen = std::collections::HashSet::new();
    let mut count = 0;
    for &x in cell {
        if seen.insert(x) {
            count += 1;
            seen.extend(g.cell_darts(x, j));
        }
    }
    count
}

/// A removal (`remove`) or a contraction of the i-cell of `d`, checked against CGAL's
/// documented effect and against the homology-keeping operator where that applies.
fn collapse(g: &mut GMap, d: DartId, i: usize, remove: bool) -> Result<(), TestCaseError> {
    let n = g.dim();
    let allowed = if remove { ops::is_removable(g, d, i) } else { ops::is_contractible(g, d, i) };
    let keeps = if remove {
        ops::is_removable_keeping_homology(g, d, i)
    } else {
        ops::is_contractible_keeping_homology(g, d, i)
    };
    prop_assert!(!keeps || allowed, "the homology-keeping predicate is the stricter");
    let before = g.cell_counts();
    let cell = g.cell_darts(d, i);
    let other = if remove { (i < n).then_some(i + 1) } else { i.checked_sub(1) };
    let two_sides = other.is_some_and(|j| meeting(g, &cell, j) == 2);
    let mut twin = g.clone();
    let darts = g.dart_count();
    let done = if remove { ops::try_remove_cell(g, d, i) } else { ops::try_contract_cell(g, d, i) };
    prop_assert_eq!(done.is_ok(), allowed, "predicate and operation disagree");
    let Ok(k) = done else { return Ok(()) };
    prop_assert_eq!((k, darts - g.dart_count()), (cell.len(), cell.len()));
    g.validate().map_err(|e| TestCaseError::fail(format!("invalid after the operation: {e}")))?;
    let after = g.cell_counts();
    prop_assert_eq!(after[i], before[i] - 1, "one {}-cell less", i);
    if keeps {
        // two distinct cells on its sides (at its ends) merge; else it was a dangling edge
        if let (Some(j), true) = (other, two_sides) {
            prop_assert_eq!(after[j], before[j] - 1, "the two {}-cells around became one", j);
        }
        let op = if remove {
            ops::try_remove_cell_keeping_homology(&mut twin, d, i)
        } else {
            ops::try_contract_cell_keeping_homology(&mut twin, d, i)
        };
        let op = op.map_err(|e| TestCaseError::fail(format!("the homology-keeping move refused: {e}")))?;
        prop_assert!(are_isomorphic(&twin.to_dense_map(), &g.to_dense_map()), "CGAL's and ours differ");
        let change: Vec<i64> = after.iter().zip(&before).map(|(&a, &b)| a as i64 - b as i64).collect();
        prop_assert_eq!(op.vector.dx(), &change[..], "the Euler–Poincaré vector is the change of cells");
        let chi: i64 = change.iter().enumerate().map(|(k, &c)| if k % 2 == 0 { c } else { -c }).sum();
        prop_assert_eq!(chi, 0, "the homology-keeping move keeps the Euler characteristic");
    }
    Ok(())
}

fn apply(g: &mut GMap, step: &Step) -> Result<(), TestCaseError> {
    let darts: Vec<DartId> = g.darts().collect();
    if darts.is_empty() {
        return Ok(());
    }
    let pick = |k: usize| darts[k % darts.len()];
    let n = g.dim();
    match *step {
        Step::Remove(a, i) => collapse(g, pick(a), i % (n + 1), true),
        Step::Contract(a, i) => collapse(g, pick(a), i % (n + 1), false),
        Step::Vertex(a) => {
            let d = pick(a);
            let (before, closed) = (g.cell_counts(), !g.is_free(d, 0));
            let folded = g.cell_darts(d, 1).len() != g.orbit(d, gmap_core::AlphaSet::above(1, n)).len() * 2;
            ops::insert_cell_0_in_cell_1(g, d).unwrap();
            g.validate().map_err(|e| TestCaseError::fail(format!("invalid after a vertex: {e}")))?;
            let after = g.cell_counts();
            prop_assert_eq!(after[0], before[0] + 1);
            if closed && !folded {
                prop_assert_eq!(after[1], before[1] + 1);
            }
            Ok(())
        }
        Step::Edge(a) => {
            let d = pick(a);
            if n < 2 || g.is_free(d, 0) || g.is_free(g.alpha(d, 0), 1) {
                return Ok(());
            }
            let far = g.alpha_word(d, &[0, 1, 0]);
            if !ops::is_insertable_cell_1_in_cell_2(g, d, far) {
                return Ok(());
            }
            let before = g.cell_counts();
            ops::insert_cell_1_in_cell_2(g, d, far).unwrap();
            g.validate().map_err(|e| TestCaseError::fail(format!("invalid after an edge: {e}")))?;
            let after = g.cell_counts();
            prop_assert_eq!((after[1], after[2]), (before[1] + 1, before[2] + 1));
            Ok(())
        }
    }
}

fn run(n: usize, pieces: &[usize], steps: &[Step]) -> Result<(), TestCaseError> {
    let mut g = GMap::new(n);
    for &k in pieces {
        let piece = match k % 5 {
            0 => build::simplex(n),
            1 => build::cube(n),
            2 => build::polygon(5),
            3 => build::grid(&vec![2; n], &vec![false; n]),
            _ => build::simplex(1),
        };
        g.try_append(&piece.expect("a small builder object")).expect("pieces fit in the map");
    }
    for step in steps {
        apply(&mut g, step).map_err(|e| TestCaseError::fail(format!("{step:?}: {e}")))?;
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, ..ProptestConfig::default() })]

    #[test]
    fn cgal_operations_in_2d(
        pieces in prop::collection::vec(0usize..5, 1..4),
        steps in prop::collection::vec(step_strategy(), 1..40),
    ) {
        run(2, &pieces, &steps)?;
    }

    #[test]
    fn cgal_operations_in_3d(
        pieces in prop::collection::vec(0usize..5, 1..4),
        steps in prop::collection::vec(step_strategy(), 1..40),
    ) {
        run(3, &pieces, &steps)?;
    }
}
