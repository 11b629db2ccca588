//! Euler operators against homology: on classic objects and random operator sequences,
//! each returned Euler–Poincaré vector equals the recomputed change of cells *and* of
//! Betti numbers (simplicial counterpart, BO §6), and lies on the AC §4 hyperplane.

use gmap_core::{DenseMap, GMap};
use gmap_homology::{homology_z, simplicial_complex};
use gmap_ops::build::{cube, grid, polygon, simplex};
use gmap_ops::euler::ops::*;
use gmap_ops::euler::random::{attempt_at, Operator};
use gmap_ops::euler::EpVector;
use proptest::prelude::*;

fn betti(m: &DenseMap) -> Vec<usize> {
    homology_z(&simplicial_complex(m)).expect("homology").betti
}

fn config(g: &GMap) -> (Vec<usize>, Vec<usize>) {
    let (m, _) = g.to_dense_with_ids();
    (m.cell_counts(), betti(&m))
}

fn base(kind: u8) -> GMap {
    let m = match kind % 6 {
        0 => polygon(5).unwrap(),
        1 => grid(&[3, 3], &[true, true]).unwrap(),
        2 => grid(&[2, 3], &[false, true]).unwrap(),
        3 => cube(3).unwrap(),
        4 => grid(&[2, 2, 2], &[true, true, true]).unwrap(),
        _ => simplex(3).unwrap(),
    };
    GMap::from_dense(&m).0
}

/// One operator of the six at a place given by numbers; its vector when it applied.
fn step(g: &mut GMap, op: u8, p1: usize, p2: usize, dim: usize) -> Option<EpVector> {
    let op = Operator::ALL[op as usize % Operator::ALL.len()];
    attempt_at(g, op, p1, p2, dim)?.result.ok().map(|o| o.vector)
}

#[test]
fn every_cell_kind_on_classic_objects() {
    // the 2-torus as a 3x3 grid: remove an edge (kef), contract an edge (kev)
    let mut g = base(1);
    let (c0, b0) = config(&g);
    assert_eq!((c0.clone(), b0.clone()), (vec![9, 18, 9], vec![1, 2, 1]));
    let d = g.darts().next().unwrap();
    let v = try_remove_cell_keeping_homology(&mut g, d, 1).unwrap().vector;
    let (c1, b1) = config(&g);
    assert_eq!(c1, vec![9, 17, 8]);
    assert_eq!(v, EpVector::between(&c0, &b0, &c1, &b1));
    let e = g.darts().find(|&x| is_contractible_keeping_homology(&g, x, 1)).unwrap();
    let v = try_contract_cell_keeping_homology(&mut g, e, 1).unwrap().vector;
    let (c2, b2) = config(&g);
    assert_eq!((c2.clone(), b2.clone()), (vec![8, 16, 8], vec![1, 2, 1]));
    assert_eq!(v, EpVector::between(&c1, &b1, &c2, &b2));
    // the 3-torus: remove a face (kfs)
    let mut g = base(4);
    let (c0, b0) = config(&g);
    assert_eq!(b0, vec![1, 3, 3, 1]);
    let d = g.darts().next().unwrap();
    let v = try_remove_cell_keeping_homology(&mut g, d, 2).unwrap().vector;
    let (c1, b1) = config(&g);
    assert_eq!(c1, vec![8, 24, 23, 7]);
    assert_eq!(v, EpVector::between(&c0, &b0, &c1, &b1));
}

#[test]
fn closing_a_disc_makes_a_sphere() {
    let mut g = GMap::from_dense(&polygon(6).unwrap()).0;
    let (c0, b0) = config(&g);
    let rep = try_close(&mut g, 2).unwrap();
    let (c1, b1) = config(&g);
    assert_eq!((c1.clone(), b1.clone()), (vec![6, 6, 2], vec![1, 0, 1]));
    let v = EpVector::between(&c0, &b0, &c1, &b1);
    assert_eq!(v.dx(), rep.dx.as_slice());
    assert_eq!(v.basis_name(), "B2"); // make a face and a 2-hole
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 32, .. ProptestConfig::default() })]

    #[test]
    fn vectors_match_homology(kind in 0u8..6,
                              ops in prop::collection::vec((0u8..6, 0usize..10_000, 0usize..10_000, 0usize..4), 1..8)) {
        let mut g = base(kind);
        let mut conf = config(&g);
        for (op, p1, p2, dim) in ops {
            if let Some(v) = step(&mut g, op, p1, p2, dim) {
                let (dense, _) = g.to_dense_with_ids();
                prop_assert!(dense.validate().is_ok());
                let next = (dense.cell_counts(), betti(&dense));
                prop_assert_eq!(&v, &EpVector::between(&conf.0, &conf.1, &next.0, &next.1));
                prop_assert!(v.is_on_hyperplane());
                conf = next;
            }
        }
    }
}
