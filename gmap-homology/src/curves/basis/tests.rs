use gmap_core::DenseMap;
use gmap_ops::build::{grid, lens_space, schema, solid_torus};
use proptest::prelude::*;

use super::*;
use crate::engine::sparse::SparseMatrix;
use crate::{cellular_complex, homology_zp};

fn lengths(map: &DenseMap) -> Vec<f64> {
    let c = cellular_complex(map).unwrap().chain;
    let w = vec![1.0; c.count(1)];
    shortest_basis(&c, &w).unwrap().iter().map(|x| x.length).collect()
}

/// β₁ over Z/2 of `c` with a 2-cell added on each cycle: 0 when the cycles span H_1.
fn rank_left(c: &ChainComplex, cycles: &[BasisCycle]) -> usize {
    let counts = c.counts().to_vec();
    let n2 = counts.get(2).copied().unwrap_or(0);
    let mut cols: Vec<Vec<(u32, i64)>> = (0..n2)
        .map(|j| {
            let (r, v) = c.boundary(2).col(j);
            r.iter().copied().zip(v.iter().copied()).collect()
        })
        .collect();
    for z in cycles {
        let mut edges = z.edges.clone();
        edges.sort_unstable();
        let mut col: Vec<(u32, i64)> = Vec::new();
        for e in edges {
            match col.last_mut() {
                Some((x, v)) if *x == e => *v += 1,
                _ => col.push((e, 1)),
            }
        }
        col.retain(|(_, v)| v % 2 != 0);
        cols.push(col);
    }
    let mut new_counts = counts.clone();
    if new_counts.len() < 3 {
        new_counts.push(0);
    }
    new_counts[2] = cols.len();
    let mut mats = vec![c.boundary(1).clone(), SparseMatrix::try_from_columns(counts[1], &cols).unwrap()];
    for k in 3..counts.len() {
        let b = c.boundary(k);
        let (rows, cols_k) = (new_counts[k - 1], b.cols());
        let entries: Vec<(u32, u32, i64)> = b.iter().map(|(i, j, v)| (i as u32, j as u32, v)).collect();
        mats.push(SparseMatrix::try_from_entries(rows, cols_k, &entries).unwrap());
    }
    // over Z/2 the boundaries of the added cells need ∂∂ = 0 only modulo 2: check there
    let cc = ChainComplex::try_new_unchecked_dd(new_counts, mats).unwrap();
    homology_zp(&cc, 2).unwrap().betti[1]
}

fn check_basis(c: &ChainComplex, w: &[f64]) -> Vec<BasisCycle> {
    let b = shortest_basis(c, w).unwrap();
    let beta = homology_zp(c, 2).unwrap().betti.get(1).copied().unwrap_or(0);
    assert_eq!(b.len(), beta);
    assert_eq!(rank_left(c, &b), 0, "the cycles span H_1(Z/2)");
    let ends = edge_ends(c).unwrap();
    for z in &b {
        // a closed walk: every vertex met an even number of times
        let mut deg = std::collections::HashMap::new();
        for &e in &z.edges {
            let (a, bb) = ends[e as usize];
            if a != NONE {
                *deg.entry(a).or_insert(0) += 1;
                *deg.entry(bb).or_insert(0) += 1;
            }
        }
        assert!(deg.values().all(|d| d % 2 == 0), "{z:?} is not a cycle");
        let sum: f64 = z.edges.iter().map(|&e| w[e as usize]).sum();
        assert_eq!(sum, z.length);
    }
    assert!(b.windows(2).all(|p| p[0].length <= p[1].length));
    b
}

#[test]
fn tori_and_surfaces() {
    assert_eq!(lengths(&gmap_core::examples::torus()), vec![1.0, 1.0]);
    assert_eq!(lengths(&grid(&[6, 3], &[true, true]).unwrap()), vec![3.0, 6.0]);
    assert_eq!(lengths(&grid(&[4, 4], &[true, true]).unwrap()), vec![4.0, 4.0]);
    assert_eq!(lengths(&gmap_core::examples::klein_bottle()).len(), 2);
    assert_eq!(lengths(&schema("a a").unwrap()), vec![1.0]);
    assert_eq!(lengths(&schema("a A").unwrap()), Vec::<f64>::new());
    // an annulus: its core
    assert_eq!(lengths(&grid(&[5, 2], &[true, false]).unwrap()), vec![5.0]);
}

#[test]
fn maps_of_dimension_three() {
    assert_eq!(lengths(&grid(&[3, 4, 5], &[true, true, true]).unwrap()), vec![3.0, 4.0, 5.0]);
    assert_eq!(lengths(&grid(&[3, 2, 2], &[true, false, false]).unwrap()), vec![3.0]);
    let st = solid_torus(5).unwrap();
    assert_eq!(lengths(&st).len(), 1);
    // L(4,1): H_1 = Z/4, so H_1(Z/2) has rank 1; L(3,1) has none over Z/2
    assert_eq!(lengths(&lens_space(4, 1).unwrap()).len(), 1);
    assert_eq!(lengths(&lens_space(3, 1).unwrap()).len(), 0);
    for m in [grid(&[3, 3, 2], &[true, true, false]).unwrap(), st, lens_space(6, 1).unwrap()] {
        let c = cellular_complex(&m).unwrap().chain;
        check_basis(&c, &vec![1.0; c.count(1)]);
    }
}

#[test]
fn cells_are_numbered_as_the_maps_partitions() {
    let m = grid(&[3, 2], &[true, true]).unwrap();
    let c = cellular_complex(&m).unwrap();
    assert_eq!(c.reps[1], m.cells(1).reps);
    assert_eq!(c.reps[0], m.cells(0).reps);
}

#[test]
fn refusals() {
    let c = cellular_complex(&grid(&[3, 3], &[true, true]).unwrap()).unwrap().chain;
    assert_eq!(shortest_basis(&c, &[1.0; 3]).unwrap_err(), CurveError::WeightCount { given: 3, edges: 18 });
    // an edge with one end
    let d1 = SparseMatrix::try_from_triplets(2, 1, &[(0, 0, 1)]).unwrap();
    let one = ChainComplex::try_new(vec![2, 1], vec![d1]).unwrap();
    assert_eq!(shortest_basis(&one, &[1.0]).unwrap_err(), CurveError::NotAGraph { edge: 0, ends: 1 });
}

/// The lengths of a basis of `H_1(Z/2)` found today, by [`crate::generators::generators`].
fn todays_lengths(c: &ChainComplex, w: &[f64]) -> Vec<f64> {
    let g = crate::generators::generators(c, Some(2)).unwrap();
    let mut l: Vec<f64> =
        g.iter().filter(|x| x.dim == 1).map(|x| x.chain.iter().map(|&(e, _)| w[e as usize]).sum()).collect();
    l.sort_by(f64::total_cmp);
    l
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    /// A basis, each k-th cycle no longer than the k-th of today's generators, on tori and
    /// 3-dimensional grids with random weights.
    #[test]
    fn shortest_bases_are_bases_and_no_longer(
        sizes in prop::collection::vec(2usize..5, 2..=3),
        periodic in prop::collection::vec(any::<bool>(), 3),
        seed in any::<u64>(),
    ) {
        let m = grid(&sizes, &periodic[..sizes.len()]).unwrap();
        let c = cellular_complex(&m).unwrap().chain;
        let mut x = seed | 1;
        let w: Vec<f64> = (0..c.count(1)).map(|_| { x ^= x << 13; x ^= x >> 7; x ^= x << 17; (x % 7 + 1) as f64 }).collect();
        let b = check_basis(&c, &w);
        let today = todays_lengths(&c, &w);
        prop_assert_eq!(b.len(), today.len());
        for (s, t) in b.iter().zip(&today) {
            prop_assert!(s.length <= *t, "{} > {}", s.length, t);
        }
    }

    /// Against brute force on the small torus: the greedy over every cycle of the 1-skeleton
    /// (all subsets of the 9 vertices' 18 edges that are cycles would be too many; the
    /// cycles through at most 6 edges are enough there, the longest of a shortest basis of
    /// a 3 x 3 torus with weights ≤ 2 being 6).
    #[test]
    fn matches_brute_force_on_the_3x3_torus(seed in any::<u64>()) {
        let m = grid(&[3, 3], &[true, true]).unwrap();
        let c = cellular_complex(&m).unwrap().chain;
        let mut x = seed | 1;
        let w: Vec<f64> = (0..18).map(|_| { x ^= x << 13; x ^= x >> 7; x ^= x << 17; (x % 2 + 1) as f64 }).collect();
        let b = check_basis(&c, &w);
        let ann = annotations(&c).unwrap();
        let ends = edge_ends(&c).unwrap();
        // every edge set of at most 6 edges that is a cycle, greedy by weight
        let mut cands: Vec<(Candidate, Vec<u64>)> = Vec::new();
        let mut subset = Vec::new();
        fn rec(k: u32, subset: &mut Vec<u32>, ends: &[(u32, u32)], w: &[f64], ann: &Annotations, out: &mut Vec<(Candidate, Vec<u64>)>) {
            if !subset.is_empty() {
                let mut deg = [0u8; 9];
                for &e in subset.iter() { deg[ends[e as usize].0 as usize] ^= 1; deg[ends[e as usize].1 as usize] ^= 1; }
                if deg.iter().all(|&d| d == 0) {
                    let len = subset.iter().map(|&e| w[e as usize]).sum();
                    out.push(((len, 0, 0), ann.class(subset)));
                }
            }
            if subset.len() == 6 { return; }
            for e in k..18 {
                subset.push(e);
                rec(e + 1, subset, ends, w, ann, out);
                subset.pop();
            }
        }
        rec(0, &mut subset, &ends, &w, &ann, &mut cands);
        let brute = greedy(cands, 2);
        prop_assert_eq!(brute.len(), 2);
        prop_assert_eq!(b[0].length, brute[0].0);
        prop_assert_eq!(b[1].length, brute[1].0);
    }
}
