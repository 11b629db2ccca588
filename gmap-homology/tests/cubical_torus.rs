//! The periodic one-pass groups (torsion included) of cubical sets of dimension 1 to 3 equal
//! the periodic chain complex's, on known sets of the torus and on random images.

use gmap_homology::cubical::cubical_complex;
use gmap_homology::cubical::torus::betti_one_pass_periodic;
use gmap_homology::homology_z;
use proptest::prelude::*;

mod common;
use common::random_bits;

/// Betti numbers and torsion (invariant factors) per dimension.
type Groups = (Vec<u64>, Vec<Vec<u64>>);

fn one_pass(shape: &[usize], bits: &[u8]) -> (Groups, i64) {
    let r = betti_one_pass_periodic(shape, |s, out| out.copy_from_slice(&bits[s..s + out.len()])).unwrap();
    ((r.betti, r.torsion), r.euler_characteristic)
}

fn general(shape: &[usize], bits: &[u8]) -> Groups {
    let c = cubical_complex(shape, bits, true).unwrap();
    let h = homology_z(&c.chain).unwrap();
    let torsion = h.torsion.iter().map(|t| t.iter().map(|x| x.to_string().parse().unwrap()).collect()).collect();
    (h.betti.iter().map(|&b| b as u64).collect(), torsion)
}

fn free(betti: &[u64]) -> Groups {
    (betti.to_vec(), vec![Vec::new(); betti.len()])
}

/// A box of `shape` (3-D) with the cubes `keep` picks.
fn image(shape: [usize; 3], keep: impl Fn(usize, usize, usize) -> bool) -> Vec<u8> {
    let mut bits = Vec::with_capacity(shape.iter().product());
    for z in 0..shape[2] {
        for y in 0..shape[1] {
            for x in 0..shape[0] {
                bits.push(keep(x, y, z) as u8);
            }
        }
    }
    bits
}

fn check(shape: &[usize], bits: &[u8], want: Groups, chi: i64) {
    assert_eq!(one_pass(shape, bits), (want.clone(), chi), "one pass, {shape:?}");
    assert_eq!(general(shape, bits), want, "chain complex, {shape:?}");
}

#[test]
fn known_sets_of_the_torus() {
    // the empty set and the whole torus, in every dimension
    for shape in [vec![4], vec![3, 4], vec![3, 4, 2]] {
        let n: usize = shape.iter().product();
        check(&shape, &vec![0; n], free(&vec![0; shape.len() + 1]), 0);
        let torus = match shape.len() {
            1 => vec![1, 1],
            2 => vec![1, 2, 1],
            _ => vec![1, 3, 3, 1],
        };
        check(&shape, &vec![1; n], free(&torus), 0);
    }
    // arcs of a circle; a band around a 2-torus; a 2-torus minus a square
    check(&[6], &[1, 0, 1, 1, 0, 1], free(&[2, 0]), 2);
    check(&[4, 3], &[0, 0, 0, 0, 1, 1, 1, 1, 0, 0, 0, 0], free(&[1, 1, 0]), 0);
    let mut punctured = vec![1u8; 9];
    punctured[4] = 0;
    check(&[3, 3], &punctured, free(&[1, 2, 0]), -1);
    // a slab layer of T³: T² × I
    let slab = image([4, 3, 5], |_, _, z| z == 2);
    check(&[4, 3, 5], &slab, free(&[1, 2, 1, 0]), 0);
    // a tube winding (1, 1, 0): a circle
    let tube = image([4, 4, 3], |x, y, z| x == y && z == 1);
    check(&[4, 4, 3], &tube, free(&[1, 1, 0, 0]), 0);
    // the torus minus one cube: T³ minus a ball
    let holed = image([3, 4, 3], |x, y, z| (x, y, z) != (1, 2, 1));
    check(&[3, 4, 3], &holed, free(&[1, 3, 3, 0]), 1);
}

/// The complement a thin tube whose core winds twice around the x axis (a double helix
/// around a square of the y-z plane): `H_1` has the torsion `Z/2`.
#[test]
fn a_complement_winding_twice_gives_torsion() {
    let ring = [(1, 1), (1, 2), (1, 3), (2, 3), (3, 3), (3, 2), (3, 1), (2, 1)];
    let (nx, n) = (8usize, 5usize);
    let mut bits = vec![1u8; nx * n * n];
    let mut put = |x: usize, (y, z): (usize, usize)| bits[x + nx * (y + n * z)] = 0;
    // step t: x = t mod 8 on ring position t / 2; twice around x for once around the ring
    for t in 0..2 * nx {
        put(t % nx, ring[t / 2 % 8]);
        put(t % nx, ring[t.div_ceil(2) % 8]);
    }
    let want = (vec![1, 3, 2, 0], vec![vec![], vec![2], vec![], vec![]]);
    let ((betti, torsion), chi) = one_pass(&[nx, n, n], &bits);
    assert_eq!((betti.clone(), torsion.clone()), want);
    assert_eq!(chi, 0);
    assert_eq!(general(&[nx, n, n], &bits), want);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1000))]
    #[test]
    fn random_periodic_images_agree_with_the_chain_complex(
        shape in prop::collection::vec(1usize..9, 1..4),
        density in 0u64..100,
        seed in any::<u64>(),
    ) {
        let bits = random_bits(shape.iter().product(), density, seed);
        let ((b, t), chi) = one_pass(&shape, &bits);
        let g = general(&shape, &bits);
        prop_assert_eq!(&(b, t), &g);
        let alt: i64 = g.0.iter().enumerate().map(|(k, &x)| if k % 2 == 0 { x as i64 } else { -(x as i64) }).sum();
        prop_assert_eq!(chi, alt);
    }
}
