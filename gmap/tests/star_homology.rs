//! Stellar subdivision against homology: starring any cell of an object (an edge, a face,
//! a volume, in maps of dimension 2 to 4, orientable or not, with torsion) leaves its
//! integer homology as it was, Betti numbers and torsion coefficients alike.

use gmap_core::{DenseMap, GMap};
use gmap_homology::{homology_z, simplicial_complex};
use gmap_ops::build::{cube, grid, lens_space, schema, simplex};
use gmap_ops::euler::ops::try_star_cell;
use proptest::prelude::*;

/// The integer homology of a map, as text: `(Z, Z + Z/2, 0)`.
fn homology(m: &DenseMap) -> String {
    homology_z(&simplicial_complex(m)).expect("homology").to_string()
}

/// The objects: a Klein bottle, a projective plane, a torus, a solid cube, a 3-torus of
/// cubes, the lens space L(3, 1), a tetrahedron's boundary and interior, a 4-cube.
fn object(kind: u8) -> DenseMap {
    match kind % 8 {
        0 => schema("a b a B").unwrap(),
        1 => schema("a b a b").unwrap(),
        2 => grid(&[2, 2], &[true, true]).unwrap(),
        3 => cube(3).unwrap(),
        4 => grid(&[1, 1, 2], &[true, true, true]).unwrap(),
        5 => lens_space(3, 1).unwrap(),
        6 => simplex(3).unwrap(),
        _ => cube(4).unwrap(),
    }
}

#[test]
fn the_objects_have_the_homology_we_expect() {
    let expected = [
        "(Z, Z + Z/2, 0)",
        "(Z, Z/2, 0)",
        "(Z, Z^2, Z)",
        "(Z, 0, 0, 0)",
        "(Z, Z^3, Z^3, Z)",
        "(Z, Z/3, 0, Z)",
        "(Z, 0, 0, 0)",
        "(Z, 0, 0, 0, 0)",
    ];
    for (kind, want) in expected.iter().enumerate() {
        assert_eq!(homology(&object(kind as u8)), *want, "object {kind}");
    }
}

#[test]
fn every_dimension_of_cell_on_the_lens_space() {
    let m = object(5);
    let before = homology(&m);
    for i in 1..=3 {
        let mut g = GMap::from_dense(&m).0;
        let d = g.darts().next().unwrap();
        try_star_cell(&mut g, d, i, None).unwrap();
        assert_eq!(homology(&g.to_dense_map()), before, "star of a {i}-cell");
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// Up to three stars at random places keep the homology and the map valid.
    #[test]
    fn stars_keep_the_homology(kind in 0u8..8, picks in prop::collection::vec((0usize..10_000, 1usize..5), 1..4)) {
        let m = object(kind);
        let before = homology(&m);
        let mut g = GMap::from_dense(&m).0;
        for (at, i) in picks {
            let i = 1 + (i - 1) % g.dim();
            let d = g.darts().nth(at % g.dart_count()).unwrap();
            try_star_cell(&mut g, d, i, None).unwrap();
        }
        prop_assert!(g.validate().is_ok());
        prop_assert_eq!(homology(&g.to_dense_map()), before);
    }
}
