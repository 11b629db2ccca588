//! Slabs of a cubical set reduced apart and glued give the groups of the whole set's
//! cubical complex, torsion included, in dimensions 1 to 4; the blocks' messages read back
//! to the same blocks; the one-pass blocks' messages too.

use gmap_homology::cubical::blocks::{block_complex, glue, BlockComplex};
use gmap_homology::cubical::cubical_complex;
use gmap_homology::cubical::pass::{block_pass, merge_blocks, BlockSummary};
use gmap_homology::{homology_z, Homology};
use proptest::prelude::*;

mod common;
use common::random_bits;

fn whole(shape: &[usize], bits: &[u8]) -> Homology {
    homology_z(&cubical_complex(shape, bits, false).unwrap().chain).unwrap()
}

/// The slabs ending at `ends` (increasing, the last one the box's last layer), each sent
/// through its message, glued.
fn in_slabs(shape: &[usize], bits: &[u8], ends: &[usize]) -> (Homology, Vec<usize>) {
    let fill = |s: usize, out: &mut [u8]| out.copy_from_slice(&bits[s..s + out.len()]);
    let mut start = 0;
    let mut blocks = Vec::new();
    for &e in ends {
        let b = block_complex(shape, start..e, &fill).unwrap();
        let back = BlockComplex::from_bytes(&b.to_bytes()).unwrap();
        assert_eq!((&back.keys, back.chain.counts()), (&b.keys, b.chain.counts()));
        blocks.push(back);
        start = e;
    }
    let sizes = blocks.iter().map(BlockComplex::cell_count).collect();
    (homology_z(&glue(shape, &blocks).unwrap()).unwrap(), sizes)
}

#[test]
fn known_sets() {
    // two nested shells in a 7³ box, cut in 1, 2 and 7 slabs
    let mut bits = vec![0u8; 343];
    for z in 0..7i32 {
        for y in 0..7i32 {
            for x in 0..7i32 {
                let m = [x, y, z].iter().map(|&c| (c - 3).abs()).max().unwrap();
                bits[(x + 7 * (y + 7 * z)) as usize] = (m == 3 || m == 1) as u8;
            }
        }
    }
    for ends in [vec![7], vec![3, 7], (1..=7).collect()] {
        let (h, _) = in_slabs(&[7, 7, 7], &bits, &ends);
        assert_eq!(h.betti, vec![2, 0, 2, 0]);
    }
    // the boundary of a 4-cube: a 3³ × 3 box of 4-cubes without its centre, cut in 3
    let mut bits = vec![1u8; 81];
    bits[40] = 0;
    let (h, sizes) = in_slabs(&[3, 3, 3, 3], &bits, &[1, 2, 3]);
    assert_eq!(h.betti, vec![1, 0, 0, 1, 0]);
    assert!(sizes.iter().all(|&s| s > 0));
    // a solid block: each slab keeps its cuts and about nothing inside
    let bits = vec![1u8; 4 * 4 * 12];
    let (h, sizes) = in_slabs(&[4, 4, 12], &bits, &[4, 8, 12]);
    assert_eq!(h.betti, vec![1, 0, 0, 0]);
    // the middle slab: two cuts of 9 × 9 points, 81 cells each, plus a cell or two
    assert!(sizes[1] <= 2 * 81 + 4, "{sizes:?}");
}

#[test]
fn one_pass_summaries_read_back() {
    let shape = [6, 5, 9];
    let bits = random_bits(270, 50, 7);
    let fill = |s: usize, out: &mut [u8]| out.copy_from_slice(&bits[s..s + out.len()]);
    let blocks: Vec<BlockSummary> = [(0..3, false), (2..6, true), (5..9, true)]
        .into_iter()
        .map(|(r, shared)| {
            let b = block_pass(&shape, r, shared, &fill).unwrap();
            let back = BlockSummary::from_bytes(&shape, &b.to_bytes()).unwrap();
            assert_eq!(back, b);
            back
        })
        .collect();
    let betti: Vec<usize> = merge_blocks(&shape, &blocks).betti.iter().map(|&b| b as usize).collect();
    assert_eq!(betti, whole(&shape, &bits).betti);
    // a message cut short or for another box is refused
    let bytes = blocks[1].to_bytes();
    for end in 0..bytes.len() {
        assert!(BlockSummary::from_bytes(&shape, &bytes[..end]).is_err());
    }
    assert!(BlockSummary::from_bytes(&[6, 5, 4], &bytes).is_err());
    let bytes = block_complex(&shape, 3..6, &fill).unwrap().to_bytes();
    for end in 0..bytes.len() {
        assert!(BlockComplex::from_bytes(&bytes[..end]).is_err());
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]
    /// Cut anywhere along the last axis, in dimensions 1 to 4: the whole set's groups.
    #[test]
    fn slabs_glue_to_the_whole(
        shape in prop::collection::vec(1usize..6, 1..5),
        extra in 1usize..6,
        cuts in prop::collection::vec(any::<prop::sample::Index>(), 0..4),
        density in 0u64..100,
        seed in any::<u64>(),
    ) {
        let mut shape = shape;
        let d = shape.len();
        if d == 4 {
            shape.iter_mut().for_each(|s| *s = (*s).min(3));
        }
        shape[d - 1] += extra;
        let n = shape[d - 1];
        let bits = random_bits(shape.iter().product(), density, seed);
        let mut ends: Vec<usize> = cuts.iter().map(|i| 1 + i.index(n - 1)).collect();
        ends.push(n);
        ends.sort();
        ends.dedup();
        let (h, _) = in_slabs(&shape, &bits, &ends);
        prop_assert_eq!(h, whole(&shape, &bits));
    }
}
