//! The generators of the one-pass route (`cubical::gens`) are a basis over Z of the homology of
//! the set: each is a cycle of the set's cubical complex, there are `b_k` of them in each
//! dimension, and coning them off kills all homology (torsion included), which holds exactly
//! when they generate `H_k` over Z.

mod common;
use common::random_bits;

use std::collections::HashMap;

use gmap_homology::cubical::cubical_complex_with;
use gmap_homology::cubical::gens::{
    cubical_generators, cubical_generators_pairing, cubical_generators_tunnels, CubicalGenerators,
};
use gmap_homology::{homology_z, ChainComplex, SparseMatrix};
use proptest::prelude::*;

/// Checks the generators against the whole cubical complex, those of every route in 3-D (the
/// one chosen, the sweep, the complement's); returns its Betti numbers.
fn check(shape: &[usize], bits: &[u8]) -> Vec<usize> {
    let betti = check_generators(shape, bits, cubical_generators(shape, bits).unwrap());
    if shape.len() == 3 {
        assert_eq!(check_pairing(shape, bits, usize::MAX), betti);
        assert_eq!(check_generators(shape, bits, cubical_generators_tunnels(shape, bits).unwrap()), betti);
    }
    betti
}

/// [`check`] with the 3-D sweep's eliminations above the vertices bounded by `pairs` (the
/// rest made critical and reduced by the general route).
fn check_pairing(shape: &[usize], bits: &[u8], pairs: usize) -> Vec<usize> {
    check_generators(shape, bits, cubical_generators_pairing(shape, bits, pairs).unwrap())
}

/// Checks `g`, the generators of the set, against its whole cubical complex.
fn check_generators(shape: &[usize], bits: &[u8], g: CubicalGenerators) -> Vec<usize> {
    let c = cubical_complex_with(shape, bits, false, false).unwrap();
    let h = homology_z(&c.chain).unwrap();
    assert!(h.torsion.iter().all(Vec::is_empty));
    assert_eq!(g.betti.iter().map(|&b| b as usize).collect::<Vec<_>>(), h.betti, "{shape:?} {bits:?}");
    assert_eq!(g.grid, c.grid);
    assert_eq!(g.euler_characteristic, c.chain.euler_characteristic());
    let index: HashMap<u64, (usize, u32)> = c
        .cells
        .iter()
        .enumerate()
        .flat_map(|(k, cells)| cells.iter().enumerate().map(move |(i, &p)| (p, (k, i as u32))))
        .collect();
    let n = shape.len();
    // the complex with a cone over each generator: a (k+1)-cell whose boundary is the cycle
    let mut cols: Vec<Vec<Vec<(u32, i64)>>> = (0..=n + 1).map(|_| Vec::new()).collect();
    let mut counts: Vec<usize> = (0..=n).map(|k| c.chain.count(k)).collect();
    counts.push(0);
    for (k, col) in cols.iter_mut().enumerate().take(n + 1).skip(1) {
        let m = c.chain.boundary(k);
        for j in 0..m.cols() {
            let (ri, rv) = m.col(j);
            col.push(ri.iter().copied().zip(rv.iter().copied()).collect());
        }
    }
    let mut previous = 0;
    for z in &g.generators {
        assert!(z.dim >= previous, "generators dimension by dimension");
        previous = z.dim;
        assert!(z.chain.windows(2).all(|w| w[0].0 < w[1].0), "cells increasing");
        let col: Vec<(u32, i64)> = z
            .chain
            .iter()
            .map(|&(p, coef)| {
                let (k, i) = index[&p];
                assert_eq!(k, z.dim, "a cell of the cycle's dimension");
                (i, coef)
            })
            .collect();
        // a cycle
        if z.dim > 0 {
            let m = c.chain.boundary(z.dim);
            let mut bd = vec![0i64; m.rows()];
            for &(j, v) in &col {
                let (ri, rv) = m.col(j as usize);
                for (&r, &x) in ri.iter().zip(rv) {
                    bd[r as usize] += x * v;
                }
            }
            assert!(bd.iter().all(|&x| x == 0), "not a cycle: {:?}", z.chain);
        }
        cols[z.dim + 1].push(col);
        counts[z.dim + 1] += 1;
    }
    let boundaries: Vec<SparseMatrix> =
        (1..=n + 1).map(|k| SparseMatrix::try_from_columns(counts[k - 1], &cols[k]).unwrap()).collect();
    let coned = ChainComplex::try_new(counts, boundaries).unwrap();
    let hc = homology_z(&coned).unwrap();
    assert!(hc.betti.iter().all(|&b| b == 0) && hc.torsion.iter().all(Vec::is_empty), "not a basis over Z: {hc:?}");
    h.betti
}

#[test]
fn known_sets() {
    // a ring of 8 squares: one loop, the boundary of its hole
    assert_eq!(check(&[3, 3], &[1, 1, 1, 1, 0, 1, 1, 1, 1]), vec![1, 1, 0]);
    // a hollow cube: one cavity; a solid torus (a ring one cube thick); two of them; a cube
    // with a tunnel and a cavity
    let mut shell = vec![1u8; 27];
    shell[13] = 0;
    assert_eq!(check(&[3, 3, 3], &shell), vec![1, 0, 1, 0]);
    let mut torus = vec![1u8; 9];
    torus[4] = 0;
    assert_eq!(check(&[3, 3, 1], &torus), vec![1, 1, 0, 0]);
    let two: Vec<u8> = (0..7 * 3 * 2)
        .map(|i| {
            let (x, y, z) = (i % 7, (i / 7) % 3, i / 21);
            u8::from(x != 3 && !(x % 4 == 1 && y == 1) && z == 1)
        })
        .collect();
    assert_eq!(check(&[7, 3, 2], &two), vec![2, 2, 0, 0]);
    let holed: Vec<u8> = (0..125)
        .map(|i| {
            let (x, y, z) = (i % 5, (i / 5) % 5, i / 25);
            u8::from(!((x, y) == (1, 1) || (x, y, z) == (3, 3, 2)))
        })
        .collect();
    assert_eq!(check(&[5, 5, 5], &holed), vec![1, 1, 1, 0]);
    // cavities of several cubes, filled for the sweep when their cubes and shared facets
    // make a tree (a row of two, an L of three) and not otherwise (a 2 × 2 square of four
    // around an edge that is not in the set, a ring of eight around a column of the set, whose
    // filling would lose the loop around the column)
    let solid_but = |n: [usize; 3], holes: &[[usize; 3]]| -> Vec<u8> {
        (0..n[0] * n[1] * n[2])
            .map(|i| {
                let c = [i % n[0], (i / n[0]) % n[1], i / (n[0] * n[1])];
                u8::from(!holes.contains(&c))
            })
            .collect()
    };
    let cavities = solid_but(
        [12, 5, 4],
        &[[1, 1, 1], [2, 1, 1], [4, 1, 1], [5, 1, 1], [5, 2, 1], [7, 1, 1], [8, 1, 1], [7, 2, 1], [8, 2, 1]],
    );
    assert_eq!(check(&[12, 5, 4], &cavities), vec![1, 0, 3, 0]);
    let ring: Vec<[usize; 3]> = (0..9).filter(|&i| i != 4).map(|i| [1 + i % 3, 1 + i / 3, 1]).collect();
    assert_eq!(check(&[5, 5, 3], &solid_but([5, 5, 3], &ring)), vec![1, 1, 1, 0]);
    // tunnels, whose loops the complement's route finds across the box's border: a corner cut
    // away (no loop: the edges it takes off the border tie its links), a tunnel 2 × 2 thick
    // (edges outside the set inside it), one bent from a face to the next
    assert_eq!(check(&[3, 3, 3], &solid_but([3, 3, 3], &[[0, 0, 0]])), vec![1, 0, 0, 0]);
    let thick: Vec<[usize; 3]> = (0..12).map(|i| [1 + i % 2, 1 + (i / 2) % 2, i / 4]).collect();
    assert_eq!(check(&[4, 4, 3], &solid_but([4, 4, 3], &thick)), vec![1, 1, 0, 0]);
    let bent = [[0, 1, 1], [1, 1, 1], [1, 2, 1], [1, 3, 1]];
    assert_eq!(check(&[3, 4, 3], &solid_but([3, 4, 3], &bent)), vec![1, 1, 0, 0]);
    assert_eq!(check(&[2, 3, 2], &[0; 12]), vec![0, 0, 0, 0]);
    assert_eq!(check(&[4, 3, 5], &[1; 60]), vec![1, 0, 0, 0]);
    // two rings side by side, and a ring inside a ring (the inner one in the outer's hole)
    let two: Vec<u8> = (0..7 * 3).map(|i| u8::from(i % 7 != 3 && !(i % 7 % 4 == 1 && i / 7 == 1))).collect();
    assert_eq!(check(&[7, 3], &two), vec![2, 2, 0]);
    let nested: Vec<u8> = (0..49usize)
        .map(|i| {
            let (x, y) = (i % 7, i / 7);
            let ring = |r: usize| x.abs_diff(3).max(y.abs_diff(3)) == r;
            u8::from(ring(3) || ring(1))
        })
        .collect();
    assert_eq!(check(&[7, 7], &nested), vec![2, 2, 0]);
    // a hole whose outline is not a plain square (an L), and one touching the border (none)
    let l: Vec<u8> = (0..25).map(|i| u8::from(![6, 7, 12].contains(&i))).collect();
    assert_eq!(check(&[5, 5], &l), vec![1, 1, 0]);
    assert_eq!(check(&[3, 3], &[1, 0, 1, 1, 0, 1, 1, 1, 1]), vec![1, 0, 0]);
    // two squares meeting at a corner, a row with gaps, nothing, everything
    assert_eq!(check(&[2, 2], &[1, 0, 0, 1]), vec![1, 0, 0]);
    assert_eq!(check(&[7], &[1, 1, 0, 1, 0, 0, 1]), vec![3, 0]);
    assert_eq!(check(&[2, 3], &[0; 6]), vec![0, 0, 0]);
    assert_eq!(check(&[4, 3], &[1; 12]), vec![1, 0, 0]);
}

#[test]
fn refusals() {
    assert!(cubical_generators(&[2, 2, 2, 2], &[1; 16]).is_err());

    assert!(cubical_generators(&[3, 3], &[1; 8]).is_err());
    assert!(cubical_generators(&[0, 3], &[]).is_err());
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(160))]
    /// Random sets of dimension 1 to 3 at densities from sparse to nearly full.
    #[test]
    fn random_sets(
        shape in prop::collection::vec(1usize..8, 1..=3),
        density in 10u64..95,
        seed in any::<u64>(),
    ) {
        let n: usize = shape.iter().product();
        check(&shape, &random_bits(n, density, seed));
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]
    /// The 3-D sweep stopped early: the cells left are made critical, and the cycles of the
    /// critical edges, lifted, are a basis all the same.
    #[test]
    fn stopped_sweeps(
        shape in prop::collection::vec(2usize..6, 3),
        density in 30u64..90,
        seed in any::<u64>(),
        pairs in 0usize..60,
    ) {
        let n: usize = shape.iter().product();
        check_pairing(&shape, &random_bits(n, density, seed), pairs);
    }
}

#[test]
fn larger_random_boxes() {
    for (seed, density) in [(1, 30), (2, 50), (3, 70), (4, 85)] {
        check(&[40, 37], &random_bits(1480, density, seed));
        check(&[11, 9, 10], &random_bits(990, density, seed));
        check(&[300], &random_bits(300, density, seed));
    }
}
