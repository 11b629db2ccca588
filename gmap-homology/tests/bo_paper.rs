//! BO items with the paper's own values that the unit tests of the crates do not already
//! cover: Property 2 and the argument of Property 4 (on the map of Fig. 1(b), the one
//! Fig. 5 orients), and §6: the chain map τ from the cellular chains (BO Def. 10) to the
//! chains of the simplicial counterpart, with `c∂ᶜτ = cτ∂ˢ` on the paper's figures
//! (Fig. 1(a), 1(b), 2, 4(b)) and the torus. Random maps are covered in `prop_random3d.rs`
//! (every map the cellular method accepts there is checked the same way).

use gmap_core::{examples, AlphaSet, CompactedCells, Dart, DenseMap};
use gmap_homology::{chain_map_tau, oriented_cells, ChainMapTau, SparseMatrix, TauError};

#[test]
fn property_2_compacted_involutions_have_no_fixed_point() {
    for (name, m) in [
        ("Fig. 1(a)", examples::fig1_curve()),
        ("Fig. 1(b)", examples::fig1_surface()),
        ("Fig. 2", examples::cylinder()),
        ("Fig. 4(b)", examples::klein_bottle()),
    ] {
        assert!(m.has_complete_boundaries(), "{name}");
        for i in 1..=m.dim() {
            let b = CompactedCells::new(&m, i);
            for e in 0..b.len() as u32 {
                for k in 0..i {
                    assert_ne!(b.alpha(e, k), e, "{name}: alpha^{i}_{k} fixes an element of B_{i}");
                }
            }
        }
    }
}

#[test]
fn property_4_the_two_paths_through_dart_2_cancel() {
    // BO's argument for ∂∂ = 0 on Fig. 5(a): from the face of dart 2 to its vertex
    // {2, 3, 9, 14}, the path through dart 2 (edge {1, 2}) and the path through
    // dart 3 = alpha_1(2) (edge {3, 4, 9, 10}) carry opposite signs
    let m = examples::fig1_surface();
    let o: Vec<_> = (0..=2).map(|i| oriented_cells(&m, i).unwrap()).collect();
    let path = |paper: u32| o[2].sign(paper - 1) * o[1].sign(paper - 1) * o[1].sign(paper - 1) * o[0].sign(paper - 1);
    assert_eq!(m.alpha(Dart::new(1), 1), Dart::new(2));
    assert_eq!(path(2), -path(3));
    assert_eq!(path(2).abs(), 1);
    // and the whole border of the border vanishes
    let c = gmap_homology::cellular_complex(&m).unwrap();
    assert!(c.chain.boundary(1).checked_mul(c.chain.boundary(2)).unwrap().iter().all(|e| e.2 == 0));
}

/// The entries of column `j` of `m`, as `(row, value)`, sorted.
fn column(m: &SparseMatrix, j: usize) -> Vec<(usize, i64)> {
    let mut c: Vec<(usize, i64)> = m.iter().filter(|e| e.1 == j).map(|e| (e.0, e.2)).collect();
    c.sort_unstable();
    c
}

/// The i-simplex on vertices `{0..i}` of the element of `B_i` holding paper dart `d`
/// (numbered from 1): its row in `tau[i]`.
fn simplex_of(m: &DenseMap, i: usize, paper_dart: u32) -> usize {
    m.partition(AlphaSet::above(i, m.dim())).of[paper_dart as usize - 1] as usize
}

/// The i-cell of paper dart `d`: its column in `tau[i]`.
fn cell_of(t: &ChainMapTau, m: &DenseMap, i: usize, paper_dart: u32) -> usize {
    let cells = m.cells(i);
    let rep = cells.reps[cells.of[paper_dart as usize - 1] as usize];
    t.cellular.reps[i].iter().position(|&r| r == rep).unwrap()
}

#[test]
fn tau_commutes_on_the_figures() {
    for (name, m) in [
        ("Fig. 1(a)", examples::fig1_curve()),
        ("Fig. 1(b)", examples::fig1_surface()),
        ("Fig. 2", examples::cylinder()),
        ("Fig. 4(b)", examples::klein_bottle()),
        ("torus", examples::torus()),
    ] {
        let t = chain_map_tau(&m).unwrap();
        assert_eq!(t.check_commutes(), Ok(()), "{name}");
        // τ_i has one entry per element of B_i, each ±1, and no two cells share a simplex
        for i in 0..=m.dim() {
            let b = m.partition(AlphaSet::above(i, m.dim())).len();
            assert_eq!(t.tau[i].nnz(), b, "{name}, τ_{i}");
            assert!(t.tau[i].iter().all(|e| e.2.abs() == 1), "{name}, τ_{i}");
            assert_eq!(t.tau[i].cols(), t.cellular.chain.count(i));
            assert_eq!(t.tau[i].rows(), t.simplicial.chain.count(i));
        }
    }
}

#[test]
fn tau_of_the_cylinder_of_fig_2() {
    let m = examples::cylinder();
    let t = chain_map_tau(&m).unwrap();
    assert_eq!(t.cellular.chain.counts(), &[2, 3, 1]);
    // vertices 0: <alpha_1, alpha_2> (2), 1: <alpha_0, alpha_2> (3), 2: <alpha_0, alpha_1> (1);
    // edges {0,1}: <alpha_2> (6), {0,2}: <alpha_1> (4), {1,2}: <alpha_0> (4); 8 triangles
    assert_eq!(t.simplicial.chain.counts(), &[6, 14, 8]);
    // a vertex is the one simplex {0} of its one element of B_0
    assert_eq!(column(&t.tau[0], cell_of(&t, &m, 0, 1)), vec![(simplex_of(&m, 0, 1), 1)]);
    // edge {1, 2, 5, 6}: its elements <alpha_2>(1) = {1, 6} (positive, the smallest dart) and
    // <alpha_2>(2) = {2, 5} (negative), each simplex {0, 1} taken as (1, 0): sign -1
    let mut want = vec![(simplex_of(&m, 1, 1), -1), (simplex_of(&m, 1, 2), 1)];
    want.sort_unstable();
    assert_eq!(column(&t.tau[1], cell_of(&t, &m, 1, 1)), want);
    // the face: its 8 triangles, (2, 1, 0) is (-1)^3 (0, 1, 2); odd paper darts positive
    let mut want: Vec<(usize, i64)> =
        (1..=8).map(|d| (simplex_of(&m, 2, d), if d % 2 == 1 { -1 } else { 1 })).collect();
    want.sort_unstable();
    assert_eq!(column(&t.tau[2], 0), want);
    // the boundary circle {7, 8} is a cellular cycle (its vertex twice, opposite signs); its
    // image is a simplicial cycle (BO §6: z∂ = 0 ⇒ zτ∂ˢ = 0)
    let e78 = cell_of(&t, &m, 1, 7);
    let mut z = vec![0i64; 3];
    z[e78] = 1;
    assert!(column(t.cellular.chain.boundary(1), e78).is_empty());
    let zt = t.image(1, &z).unwrap();
    assert_eq!(zt.iter().filter(|&&x| x != 0).count(), 2); // <alpha_2>(7) = {7}, <alpha_2>(8) = {8}
    let d1 = t.simplicial.chain.boundary(1);
    let mut bz = vec![0i64; d1.rows()];
    for (r, c, v) in d1.iter() {
        bz[r] += v * zt[c];
    }
    assert!(bz.iter().all(|&x| x == 0), "τ of a cellular cycle is a simplicial cycle");
    assert_eq!(t.image(1, &[1, 0]), None, "a chain with one entry per cell");
    assert_eq!(t.image(3, &[]), None, "no 3-cells in a 2-map");
}

#[test]
fn fig_5_numbering_of_the_counterpart() {
    // BO §6 on Fig. 5: the triangles of darts 4 and 5, linked by alpha_1, share the edge
    // {0, 2}, the <alpha_1>-orbit {4, 5}
    let m = examples::fig1_surface();
    let s = gmap_homology::simplicial_complex_with_simplices(&m);
    let edge02 = s.simplices[1].iter().find(|x| x.labels == 0b101 && x.dart == Dart::new(3)).unwrap();
    assert_eq!(m.orbit(edge02.dart, AlphaSet::of(&[1])), vec![Dart::new(3), Dart::new(4)]);
}

#[test]
fn a_wrong_sign_is_caught() {
    // τ with the simplices in increasing vertex order (no (-1)^(i(i+1)/2)) on the edges:
    // c∂ᶜτ = -cτ∂ˢ on every edge, and the first one with two distinct ends, edge {1, 2, 5, 6}
    // of the cylinder (dart 0), is named
    let m = examples::cylinder();
    let mut t = chain_map_tau(&m).unwrap();
    let flipped: Vec<(u32, u32, i64)> = t.tau[1].iter().map(|(r, c, v)| (r as u32, c as u32, -v)).collect();
    t.tau[1] = SparseMatrix::try_from_entries(t.tau[1].rows(), t.tau[1].cols(), &flipped).unwrap();
    assert_eq!(t.check_commutes(), Err(TauError::NotCommuting { dim: 1, dart: Dart::new(0) }));
}

#[test]
fn tau_needs_the_cellular_method() {
    // a square with an edge sewn to itself reversed: C1 fails on that edge, so τ is refused
    let mut m = gmap_ops::build::polygon(4).unwrap();
    m.link(Dart::new(0), Dart::new(1), 2);
    let e = chain_map_tau(&m).unwrap_err().to_string();
    assert!(e.starts_with("the 1-cell of dart 0"), "{e}");
}
