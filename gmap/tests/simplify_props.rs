//! Property test of `simplify`: on random small maps (classic objects changed by random
//! Euler operators, lens spaces, grids), whenever the input's cells satisfy C1/C2 the reduced
//! map is valid, keeps the Euler characteristic, is accepted by the cellular method and has
//! the same integral homology; every seed and number of runs gives such a map.

use gmap_core::{DenseMap, GMap};
use gmap_homology::{cellular_complex, homology_z, Homology};
use gmap_ops::build::{cube, grid, lens_space, polygon, simplex, solid_torus};
use gmap_ops::euler::random::{attempt_at, Operator};
use gmap_ops::euler::{simplify, simplify_with, SimplifyOptions};
use gmap_ops::rng::SplitMix64;
use proptest::prelude::*;

fn base(kind: u8) -> DenseMap {
    match kind % 9 {
        0 => polygon(5).unwrap(),
        1 => grid(&[3, 3], &[true, true]).unwrap(),
        2 => grid(&[2, 3], &[false, true]).unwrap(),
        3 => cube(3).unwrap(),
        4 => grid(&[2, 2, 3], &[true, true, true]).unwrap(),
        5 => simplex(3).unwrap(),
        6 => lens_space(5, 2).unwrap(),
        7 => solid_torus(3).unwrap(),
        _ => grid(&[2, 3, 2], &[true, false, true]).unwrap(),
    }
}

/// The operators tried: every one but the dangling edge.
const OPERATORS: [Operator; 5] =
    [Operator::InsertVertex, Operator::InsertEdge, Operator::RemoveCell, Operator::ContractCell, Operator::SplitCell];

/// One operator at a place given by numbers (applied when it can be).
fn step(g: &mut GMap, op: u8, p1: usize, p2: usize, dim: usize) {
    attempt_at(g, OPERATORS[op as usize % OPERATORS.len()], p1, p2, dim);
}

fn cellular(m: &DenseMap) -> Option<Homology> {
    cellular_complex(m).ok().map(|c| homology_z(&c.chain).expect("homology"))
}

#[test]
fn lens_space_keeps_its_torsion() {
    let m = lens_space(7, 3).unwrap();
    let (small, r) = simplify(&m);
    let h = cellular(&small).expect("C1/C2 after simplify");
    assert_eq!(h.betti, vec![1, 0, 0, 1]);
    assert_eq!(h.torsion, vec![vec![], vec![7], vec![], vec![]]);
    // already one cell per dimension: nothing to remove
    assert_eq!((r.darts_before, r.darts_after, r.cells_after), (28, 28, vec![1, 1, 1, 1]));
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, .. ProptestConfig::default() })]

    #[test]
    fn simplify_keeps_validity_and_homology(
        kind in 0u8..9,
        ops in prop::collection::vec((0u8..5, 0usize..10_000, 0usize..10_000, 0usize..4), 0..6),
        tries in 1usize..4,
        seed in 0u64..1000,
    ) {
        let mut g = GMap::from_dense(&base(kind)).0;
        for (op, p1, p2, dim) in ops {
            step(&mut g, op, p1, p2, dim);
        }
        let (m, _) = g.to_dense_with_ids();
        prop_assume!(m.validate().is_ok());
        let Some(before) = cellular(&m) else { return Ok(()) };
        let (small, report) = simplify_with(&m, &SimplifyOptions { tries, seed, search: 40 });
        prop_assert!(small.validate().is_ok());
        prop_assert_eq!(small.euler_characteristic(), m.euler_characteristic());
        prop_assert_eq!(report.darts_after, small.dart_count());
        prop_assert!(report.darts_after <= report.darts_before);
        let after = cellular(&small);
        prop_assert!(after.is_some(), "reduced cells fail C1/C2");
        let after = after.unwrap();
        prop_assert_eq!((after.betti, after.torsion), (before.betti, before.torsion));
    }
}

/// The search of split cells (3-maps) on random 3-maps: whatever it does, the map stays
/// valid with its Euler characteristic and homology, and its cells stay balls. Forty fixed
/// cases; at least three quarters of them must reach the search (all 40 do), so the test
/// cannot pass vacuously.
#[test]
fn search_keeps_validity_and_homology() {
    let mut rng = SplitMix64::new(0x2545_f491_4f6c_dd1d);
    let mut next = move || rng.next_u64() as usize;
    let mut searched = 0;
    for case in 0..40u8 {
        let mut g = GMap::from_dense(&base(3 + case % 6)).0;
        for _ in 0..next() % 5 {
            step(&mut g, (next() % 5) as u8, next(), next(), next() % 4);
        }
        let (m, _) = g.to_dense_with_ids();
        if m.validate().is_err() || m.dim() != 3 {
            continue;
        }
        let Some(before) = cellular(&m) else { continue };
        let options = SimplifyOptions { tries: 2, seed: next() as u64, search: 200 };
        let (small, report) = simplify_with(&m, &options);
        assert!(small.validate().is_ok(), "case {case}");
        assert_eq!(small.euler_characteristic(), m.euler_characteristic(), "case {case}");
        assert_eq!(report.darts_after, small.dart_count());
        let after = cellular(&small).unwrap_or_else(|| panic!("case {case}: reduced cells fail C1/C2"));
        assert_eq!((after.betti, after.torsion), (before.betti, before.torsion), "case {case}");
        if report.search_rounds > 0 {
            searched += 1;
        }
    }
    assert!(searched >= 30, "only {searched} of 40 cases reached the search");
}
