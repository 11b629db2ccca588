//! The one-pass groups of cubical sets of dimension 1 to 3 equal the chain complex's, on
//! known sets and random images of every density.

use gmap_homology::cubical::cubical_complex;
use gmap_homology::cubical::pass::betti_one_pass;
use gmap_homology::homology_z;
use proptest::prelude::*;

mod common;
use common::random_bits;

fn one_pass(shape: &[usize], bits: &[u8]) -> (Vec<u64>, i64) {
    let r = betti_one_pass(shape, |s, out| out.copy_from_slice(&bits[s..s + out.len()])).unwrap();
    (r.betti, r.euler_characteristic)
}

fn general(shape: &[usize], bits: &[u8]) -> Vec<u64> {
    let c = cubical_complex(shape, bits, false).unwrap();
    let h = homology_z(&c.chain).unwrap();
    assert!(h.torsion.iter().all(|t| t.is_empty()));
    h.betti.iter().map(|&b| b as u64).collect()
}

#[test]
fn known_sets() {
    assert_eq!(one_pass(&[3, 3], &[1, 1, 1, 1, 0, 1, 1, 1, 1]).0, vec![1, 1, 0]);
    assert_eq!(one_pass(&[2, 2], &[1, 0, 0, 1]).0, vec![1, 0, 0]);
    assert_eq!(one_pass(&[5], &[1, 0, 1, 1, 0]).0, vec![2, 0]);
    assert_eq!(one_pass(&[3, 2], &[0; 6]).0, vec![0, 0, 0]);
    // a solid torus: a 3 × 3 ring of cubes, two layers thick
    let ring = [1, 1, 1, 1, 0, 1, 1, 1, 1];
    let torus: Vec<u8> = ring.iter().chain(ring.iter()).copied().collect();
    assert_eq!(one_pass(&[3, 3, 1], &ring), (vec![1, 1, 0, 0], 0));
    assert_eq!(one_pass(&[3, 3, 2], &torus), (vec![1, 1, 0, 0], 0));
    // two nested shells in a 7³ box
    let mut bits = vec![0u8; 343];
    for z in 0..7 {
        for y in 0..7 {
            for x in 0..7 {
                let m = [x, y, z].iter().map(|&c: &i32| (c - 3).abs()).max().unwrap();
                bits[(x + 7 * (y + 7 * z)) as usize] = (m == 3 || m == 1) as u8;
            }
        }
    }
    assert_eq!(one_pass(&[7, 7, 7], &bits), (vec![2, 0, 2, 0], 4));
    assert_eq!(general(&[7, 7, 7], &bits), vec![2, 0, 2, 0]);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(500))]
    #[test]
    fn random_images_agree_with_the_chain_complex(
        shape in prop::collection::vec(1usize..9, 1..4),
        density in 0u64..100,
        seed in any::<u64>(),
    ) {
        let bits = random_bits(shape.iter().product(), density, seed);
        let (b, chi) = one_pass(&shape, &bits);
        let g = general(&shape, &bits);
        prop_assert_eq!(&b, &g);
        let alt: i64 = g.iter().enumerate().map(|(k, &x)| if k % 2 == 0 { x as i64 } else { -(x as i64) }).sum();
        prop_assert_eq!(chi, alt);
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]
    /// Cut into blocks anywhere, computed apart and merged: the same groups as one block.
    #[test]
    fn blocks_merge_to_the_whole(
        shape in prop::collection::vec(1usize..7, 3..4),
        extra in 1usize..9,
        cuts in prop::collection::vec(any::<prop::sample::Index>(), 0..4),
        density in 0u64..100,
        seed in any::<u64>(),
    ) {
        use gmap_homology::cubical::pass::{block_pass, merge_blocks};
        let mut shape = shape;
        shape[2] += extra;
        let bits = random_bits(shape.iter().product(), density, seed);
        let mut ends: Vec<usize> = cuts.iter().map(|i| 1 + i.index(shape[2] - 1)).collect();
        ends.push(shape[2]);
        ends.sort();
        ends.dedup();
        let fill = |s: usize, out: &mut [u8]| out.copy_from_slice(&bits[s..s + out.len()]);
        let mut blocks = Vec::new();
        let mut start = 0;
        for (i, &e) in ends.iter().enumerate() {
            let from = if i == 0 { 0 } else { start - 1 };
            blocks.push(block_pass(&shape, from..e, i > 0, &fill).unwrap());
            start = e;
        }
        let merged = merge_blocks(&shape, &blocks);
        prop_assert_eq!(merged.blocks, ends.len());
        prop_assert_eq!(&merged.betti, &general(&shape, &bits));
    }
}
