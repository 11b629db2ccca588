//! Euler operators on classic objects with exact counts, and property tests on random maps
//! and random operator sequences: validity kept, every Euler–Poincaré vector on the AC §4
//! hyperplane and equal to the recomputed change of cells.

mod euler_common;

use euler_common::{counts, cube_grid, cycle, find_cut, polygon, sphere_simplicial, thaw};
use gmap_core::{DartId, GMap};
use gmap_ops::euler::ops::*;
use gmap_ops::euler::random::{attempt_at, Operator};
use gmap_ops::euler::{EpVector, EulerError};
use proptest::prelude::*;

fn first_where(g: &GMap, f: impl Fn(&GMap, DartId) -> bool) -> DartId {
    g.darts().find(|&d| f(g, d)).expect("a dart with the property")
}

#[test]
fn one_dimensional_cycle() {
    let mut g = cycle(3);
    let d = g.darts().next().unwrap();
    let op = try_insert_vertex(&mut g, d).unwrap();
    assert_eq!((op.name.as_str(), op.vector.dx()), ("mve", &[1, 1][..]));
    assert_eq!(counts(&g), vec![4, 4]);
    // remove a vertex (kve) and contract an edge (kev)
    let v = first_where(&g, |g, d| is_removable_keeping_homology(g, d, 0));
    assert_eq!(try_remove_cell_keeping_homology(&mut g, v, 0).unwrap().vector.dx().to_vec(), vec![-1, -1]);
    assert_eq!(counts(&g), vec![3, 3]);
    let e = first_where(&g, |g, d| is_contractible_keeping_homology(g, d, 1));
    let op = try_contract_cell_keeping_homology(&mut g, e, 1).unwrap();
    assert_eq!((op.name.as_str(), op.basis_name()), ("kev", "-B0 - A1".to_string()));
    assert_eq!(counts(&g), vec![2, 2]);
    let e = first_where(&g, |g, d| is_contractible_keeping_homology(g, d, 1));
    try_contract_cell_keeping_homology(&mut g, e, 1).unwrap();
    assert_eq!(counts(&g), vec![1, 1]);
    // the last loop has the same vertex at both ends: contracting it would kill the circle
    let d = g.darts().next().unwrap();
    assert!(matches!(
        try_contract_cell_keeping_homology(&mut g, d, 1),
        Err(EulerError::WouldChangeTopology { dim: 1, .. })
    ));
}

#[test]
fn square_face() {
    let mut g = polygon(4);
    let ds: Vec<DartId> = g.darts().collect();
    // darts 2k, 2k+1 are the two darts of edge k; corner between 2k+1 and 2k+2
    let op = try_insert_edge(&mut g, ds[1], ds[5]).unwrap();
    assert_eq!((op.name.as_str(), op.vector.dx()), ("mef", &[0, 1, 1][..]));
    assert_eq!(op.basis_name(), "B1 + A2");
    assert_eq!(counts(&g), vec![4, 5, 2]);
    // the new edge separates the two faces: remove it again (kef)
    let new_edge = g.alpha(ds[1], 1);
    let op = try_remove_cell_keeping_homology(&mut g, new_edge, 1).unwrap();
    assert_eq!((op.name.as_str(), op.vector.dx()), ("kef", &[0, -1, -1][..]));
    assert_eq!(counts(&g), vec![4, 4, 1]);
    // a dangling edge, then its removal (kev)
    let op = try_insert_dangling_edge(&mut g, ds[3]).unwrap();
    assert_eq!((op.name.as_str(), op.vector.dx()), ("mev", &[1, 1, 0][..]));
    assert_eq!(counts(&g), vec![5, 5, 1]);
    let hang = g.alpha(ds[3], 1);
    let op = try_remove_cell_keeping_homology(&mut g, hang, 1).unwrap();
    assert_eq!((op.name.as_str(), op.vector.dx()), ("kev", &[-1, -1, 0][..]));
    assert_eq!(counts(&g), vec![4, 4, 1]);
    // a boundary edge of the square is not removable (it is 2-free)
    assert!(!is_removable_keeping_homology(&g, ds[0], 1));
    // same corner twice is refused
    assert!(matches!(try_insert_edge(&mut g, ds[1], ds[2]), Err(EulerError::Misplaced { .. })));
    // close(2) caps the square: one more face, a sphere
    let rep = try_close(&mut g, 2).unwrap();
    assert_eq!((rep.new_darts, rep.dx), (8, vec![0, 0, 1]));
    assert_eq!(counts(&g), vec![4, 4, 2]);
    assert!(g.darts().all(|d| !g.is_free(d, 2)));
}

#[test]
fn solid_cube_cells() {
    let (mut g, _) = thaw(&cube_grid(3, 1, false));
    assert_eq!(counts(&g), vec![8, 12, 6, 1]);
    // faces are on the boundary: not removable; vertices have degree 3
    let d = g.darts().next().unwrap();
    assert!(matches!(
        try_remove_cell_keeping_homology(&mut g, d, 2),
        Err(EulerError::WouldChangeTopology { dim: 2, .. })
    ));
    assert!(matches!(try_remove_cell_keeping_homology(&mut g, d, 0), Err(EulerError::DegreeAboveTwo { dim: 0, .. })));
    // an edge between two boundary faces goes (kef)
    let op = try_remove_cell_keeping_homology(&mut g, d, 1).unwrap();
    assert_eq!(op.vector.dx().to_vec(), vec![0, -1, -1, 0]);
    assert_eq!(counts(&g), vec![8, 11, 5, 1]);
    // contraction would pinch boundary vertices together
    let e = g.darts().next().unwrap();
    assert!(!is_contractible_keeping_homology(&g, e, 1));
}

#[test]
fn split_volume_by_a_face() {
    // a solid cube: cut it by a square through the middle of four parallel edges
    let (mut g, _) = thaw(&cube_grid(3, 1, false));
    let d = g.darts().next().unwrap();
    // split the four edges of one direction: the edge of d and its three parallels
    let parallels: Vec<DartId> = {
        let mut out = vec![d];
        let mut x = d;
        for _ in 0..3 {
            // across the face: alpha_0 alpha_1 alpha_0 alpha_1 alpha_2 …: walk to the opposite edge
            x = g.alpha(g.alpha(g.alpha(x, 1), 0), 1);
            x = g.alpha(x, 2);
            out.push(x);
        }
        out
    };
    let mut cut = Vec::new();
    for &e in &parallels {
        let before = counts(&g);
        try_insert_vertex(&mut g, e).unwrap();
        assert_eq!(counts(&g)[0], before[0] + 1);
        cut.push(e);
    }
    assert_eq!(counts(&g), vec![12, 16, 6, 1]);
    // cut the four side faces by edges between the new vertices
    for k in 0..4 {
        let a = g.alpha(cut[k], 0);
        let target = first_where(&g, |g, x| {
            can_insert_edge(g, a, x) && g.cell_darts(x, 0).contains(&g.alpha(cut[(k + 1) % 4], 0))
        });
        try_insert_edge(&mut g, a, target).unwrap();
    }
    assert_eq!(counts(&g), vec![12, 20, 10, 1]);
    // the four new edges form a closed path around the cube: split the volume (mfs)
    let seeds = find_cut(&g);
    let op = try_split_cell(&mut g, &seeds, 3).unwrap();
    assert_eq!((op.name.as_str(), op.vector.dx()), ("mfs", &[0, 0, 1, 1][..]));
    assert_eq!(op.basis_name(), "B2 + A3");
    assert_eq!(counts(&g), vec![12, 20, 11, 2]);
    // and the new face separates two volumes: remove it (kfs)
    let f = g.alpha(seeds[0], 2);
    let op = try_remove_cell_keeping_homology(&mut g, f, 2).unwrap();
    assert_eq!((op.name.as_str(), op.vector.dx()), ("kfs", &[0, 0, -1, -1][..]));
    assert_eq!(counts(&g), vec![12, 20, 10, 1]);
}

#[test]
fn three_torus_cells() {
    let (mut g, _) = thaw(&cube_grid(3, 2, true));
    assert_eq!(counts(&g), vec![8, 24, 24, 8]);
    let d = g.darts().next().unwrap();
    let op = try_remove_cell_keeping_homology(&mut g, d, 2).unwrap();
    assert_eq!((op.name.as_str(), op.vector.dx()), ("kfs", &[0, 0, -1, -1][..]));
    assert_eq!(counts(&g), vec![8, 24, 23, 7]);
    let e = first_where(&g, |g, x| is_contractible_keeping_homology(g, x, 1));
    let op = try_contract_cell_keeping_homology(&mut g, e, 1).unwrap();
    assert_eq!(op.vector.dx().to_vec(), vec![-1, -1, 0, 0]);
    assert_eq!(counts(&g), vec![7, 23, 23, 7]);
    // squares are not 2-gons: no face contraction; edges have degree 4: no removal
    let f = g.darts().next().unwrap();
    assert!(matches!(try_contract_cell_keeping_homology(&mut g, f, 2), Err(EulerError::DegreeAboveTwo { dim: 2, .. })));
}

#[test]
fn four_torus_cells() {
    let (mut g, _) = thaw(&cube_grid(4, 2, true));
    assert_eq!(counts(&g), vec![16, 64, 96, 64, 16]);
    let d = g.darts().next().unwrap();
    let op = try_remove_cell_keeping_homology(&mut g, d, 3).unwrap();
    assert_eq!((op.name.as_str(), op.vector.dx()), ("ksc4", &[0, 0, 0, -1, -1][..]));
    assert_eq!(counts(&g), vec![16, 64, 96, 63, 15]);
    let e = first_where(&g, |g, x| is_contractible_keeping_homology(g, x, 1));
    let op = try_contract_cell_keeping_homology(&mut g, e, 1).unwrap();
    assert_eq!(op.vector.dx().to_vec(), vec![-1, -1, 0, 0, 0]);
    assert_eq!(counts(&g), vec![15, 63, 96, 63, 15]);
}

#[test]
fn tetrahedron_surface_contractions() {
    let (mut g, _) = thaw(&sphere_simplicial(2));
    assert_eq!(counts(&g), vec![4, 6, 4]);
    let d = g.darts().next().unwrap();
    try_contract_cell_keeping_homology(&mut g, d, 1).unwrap();
    assert_eq!(counts(&g), vec![3, 5, 4]);
    // two triangles became 2-gons: contract one onto an edge (kef)
    let f = first_where(&g, |g, x| is_contractible_keeping_homology(g, x, 2));
    let op = try_contract_cell_keeping_homology(&mut g, f, 2).unwrap();
    assert_eq!((op.name.as_str(), op.vector.dx()), ("kef", &[0, -1, -1][..]));
    assert_eq!(counts(&g), vec![3, 4, 3]);
    // remove an edge between two distinct faces
    let e = first_where(&g, |g, x| is_removable_keeping_homology(g, x, 1));
    try_remove_cell_keeping_homology(&mut g, e, 1).unwrap();
    assert_eq!(counts(&g), vec![3, 3, 2]);
}

#[test]
fn errors_name_the_dart() {
    let mut g = polygon(3);
    let d = g.darts().next().unwrap();
    let gone = g.create_dart();
    g.remove_dart(gone);
    assert_eq!(try_insert_vertex(&mut g, gone), Err(EulerError::NoSuchDart(gone)));
    assert!(matches!(try_remove_cell_keeping_homology(&mut g, d, 2), Err(EulerError::BadDimension { got: 2, .. })));
    assert!(matches!(try_contract_cell_keeping_homology(&mut g, d, 0), Err(EulerError::BadDimension { got: 0, .. })));
    // a lone dart is a vertex with an edge missing its far end: mve on it is accepted (EO's
    // mve applies to boundary-incomplete edges) and leaves a complete edge and an open one
    let mut line = GMap::new(1);
    let a = line.create_dart();
    let op = try_insert_vertex(&mut line, a).unwrap();
    assert_eq!((op.name.as_str(), op.vector.dx()), ("mve", &[1, 1][..]));
    assert_eq!(line.to_dense_map().cell_counts(), vec![2, 2]);
}

// ---------- property tests ----------

fn base(kind: u8, size: usize) -> GMap {
    match kind % 7 {
        0 => cycle(size + 2),
        1 => polygon(size + 2),
        2 => thaw(&cube_grid(2, size, true)).0,
        3 => thaw(&cube_grid(2, size, false)).0,
        4 => thaw(&sphere_simplicial(2)).0,
        5 => thaw(&cube_grid(3, 2, true)).0,
        _ => thaw(&sphere_simplicial(3)).0,
    }
}

/// One operator of the six at a place given by numbers; every predicate must agree with its
/// `try_` form.
fn apply(g: &mut GMap, op: u8, pick: usize, pick2: usize, dim: usize) -> Option<EpVector> {
    let op = Operator::ALL[op as usize % Operator::ALL.len()];
    let tried = attempt_at(g, op, pick, pick2, dim)?;
    assert!(tried.consistent(), "{op:?}: predicate {} but {:?}", tried.allowed, tried.result);
    tried.result.ok().map(|o| o.vector)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, .. ProptestConfig::default() })]

    #[test]
    fn random_operator_sequences(kind in 0u8..7, size in 1usize..4,
                                 ops in prop::collection::vec((0u8..6, 0usize..10_000, 0usize..10_000, 0usize..5), 1..12)) {
        let mut g = base(kind, size);
        for (op, p1, p2, dim) in ops {
            let before = counts(&g);
            if let Some(v) = apply(&mut g, op, p1, p2, dim) {
                let (dense, _) = g.to_dense_with_ids();
                prop_assert!(dense.validate().is_ok());
                let after = dense.cell_counts();
                let recount: Vec<i64> = after.iter().zip(&before).map(|(&a, &b)| a as i64 - b as i64).collect();
                prop_assert_eq!(v.dx(), recount.as_slice());
                prop_assert!(v.is_on_hyperplane(), "vector {} off the hyperplane", v);
                prop_assert!(v.basis().is_some());
            }
        }
    }
}

#[test]
fn an_edge_alone_at_both_ends_is_not_a_dangling_edge() {
    // a segment in a 2-map folded onto itself by alpha_2: its two ends make one vertex, a
    // circle (Z, Z); removing the edge would leave nothing (found by euler_attr_props)
    let mut g = GMap::new(2);
    let (a, b) = (g.create_dart(), g.create_dart());
    g.sew(a, b, 0);
    g.sew(a, b, 2);
    assert!(!is_removable_keeping_homology(&g, a, 1));
    assert!(matches!(
        try_remove_cell_keeping_homology(&mut g, a, 1),
        Err(EulerError::WouldChangeTopology { dim: 1, .. })
    ));
    assert_eq!(g.dart_count(), 2);
    // an edge doubled by alpha_2 with both ends free of anything else: a whole component
    let mut g = GMap::new(2);
    let d: Vec<DartId> = (0..4).map(|_| g.create_dart()).collect();
    g.sew(d[0], d[1], 0);
    g.sew(d[2], d[3], 0);
    g.sew(d[0], d[2], 2);
    assert!(!is_removable_keeping_homology(&g, d[0], 1));
    assert!(try_remove_cell_keeping_homology(&mut g, d[0], 1).is_err());
    assert_eq!(g.dart_count(), 4);
}
