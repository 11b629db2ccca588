//! The slab-by-slab cubical complex has the homology of the whole one (torsion included) on
//! random images of every dimension 1 to 5, periodic or not, whatever the slab; with collapses
//! only its cells are a subcomplex, whose cycles are cycles of the set.

mod common;
use common::random_bits;

use gmap_homology::cubical::cubical_complex_with;
use gmap_homology::cubical::slabs::cubical_complex_slabs;
use gmap_homology::{homology_z, Homology};
use proptest::prelude::*;

fn whole(shape: &[usize], bits: &[u8], periodic: bool) -> Homology {
    homology_z(&cubical_complex_with(shape, bits, periodic, false).unwrap().chain).unwrap()
}

fn slabs(shape: &[usize], bits: &[u8], periodic: bool, slab: usize, keep: bool) -> Homology {
    let fill = |s: usize, out: &mut [u8]| out.copy_from_slice(&bits[s..s + out.len()]);
    let c = cubical_complex_slabs(shape, fill, periodic, slab, keep).unwrap();
    c.complex.chain.check_dd().unwrap();
    if keep || periodic {
        assert_eq!(c.set_aside(), 0);
    }
    c.absolute(homology_z(&c.complex.chain).unwrap()).unwrap()
}

#[test]
fn known_sets() {
    // a ring of 8 squares, a hollow cube, the full 2-torus and 3-torus of cubes
    let ring = [1, 1, 1, 1, 0, 1, 1, 1, 1];
    assert_eq!(slabs(&[3, 3], &ring, false, 1, false).betti, vec![1, 1, 0]);
    let mut shell = vec![1u8; 27];
    shell[13] = 0;
    assert_eq!(slabs(&[3, 3, 3], &shell, false, 2, true).betti, vec![1, 0, 1, 0]);
    assert_eq!(slabs(&[4, 4], &[1; 16], true, 1, false).betti, vec![1, 2, 1]);
    assert_eq!(slabs(&[2, 1, 3], &[1; 6], true, 1, false).betti, vec![1, 3, 3, 1]);
    assert_eq!(slabs(&[1, 1, 1, 1], &[1], true, 1, false).betti, vec![1, 4, 6, 4, 1]);
    assert_eq!(slabs(&[3, 2], &[0; 6], false, 1, false).betti, vec![0, 0, 0]);
    // a full 4-D box reduces to one vertex
    let c = cubical_complex_slabs(&[3, 3, 3, 3], |_, out: &mut [u8]| out.fill(1), false, 1, false).unwrap();
    assert_eq!((c.complex.chain.counts(), c.set_aside(), c.relative.components), (&[0, 0, 0, 0, 0][..], 1, Some(1)));
    // random 3-D images: far fewer cells than the collapses alone leave
    let bits = random_bits(20 * 20 * 20, 50, 7);
    let fill = |s: usize, out: &mut [u8]| out.copy_from_slice(&bits[s..s + out.len()]);
    let few = cubical_complex_slabs(&[20, 20, 20], fill, false, 2, false).unwrap();
    let collapsed = cubical_complex_slabs(&[20, 20, 20], fill, false, 2, true).unwrap();
    let size = |c: &gmap_homology::cubical::CubicalComplex| c.chain.counts().iter().sum::<usize>();
    assert!(
        size(&few.complex) * 4 < size(&collapsed.complex),
        "{:?} {:?}",
        few.complex.chain.counts(),
        collapsed.complex.chain.counts()
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]
    #[test]
    fn streaming_equals_the_whole_complex(
        shape in (1usize..=5).prop_flat_map(|d| prop::collection::vec(1usize..=4, d)),
        density in 0u64..=100,
        seed in any::<u64>(),
        periodic in any::<bool>(),
        slab in 1usize..=3,
        keep in any::<bool>(),
    ) {
        // 5-D boxes of up to 4^5 cubes are slow for the whole complex: at most 3 per axis
        let shape: Vec<usize> = shape.iter().map(|&l| if shape.len() == 5 { l.min(3) } else { l }).collect();
        let bits = random_bits(shape.iter().product(), density, seed);
        prop_assert_eq!(slabs(&shape, &bits, periodic, slab, keep), whole(&shape, &bits, periodic));
    }
}
