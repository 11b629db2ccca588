//! Cubes borrowed from memory (`gmap::CubesRef`, `gmap::homology_cubes`): the layouts taken
//! and refused, and the same groups and cycles as the cubical set holding the same cubes.

use gmap::ops::import::CubicalSet;
use gmap::{homology, homology_cubes, CubesRef, HomologyOptions, Input, Sourced};

/// A 3×4 picture (rows, columns) of an annulus-like ring with one hole, row-major (C order).
const RING: [u8; 12] = [1, 1, 1, 1, 1, 0, 0, 1, 1, 1, 1, 1];

#[test]
fn c_and_fortran_layouts_give_the_set_of_the_caller_axes() {
    // C order: element (i, j) at i * 4 + j
    let c = CubesRef::new(&RING, &[3, 4], &[4, 1]).unwrap();
    assert!(c.is_reversed());
    assert_eq!(c.shape(), vec![3, 4]);
    assert_eq!(c.storage_shape(), &[4, 3]);
    // the same bytes read as Fortran order: element (i, j) at i + 4 j of a 4×3 array
    let f = CubesRef::new(&RING, &[4, 3], &[1, 4]).unwrap();
    assert!(!f.is_reversed());
    assert_eq!(f.storage_shape(), &[4, 3]);
}

#[test]
fn other_layouts_are_refused_with_the_reason() {
    let strided = CubesRef::new(&RING, &[3, 4], &[8, 2]).unwrap_err();
    assert!(strided.to_string().contains("neither C- nor Fortran-contiguous"), "{strided}");
    let short = CubesRef::new(&RING[..11], &[3, 4], &[4, 1]).unwrap_err();
    assert!(short.to_string().contains("needs 12 bytes"), "{short}");
    assert!(CubesRef::new(&[], &[0], &[1]).is_err());
    assert!(CubesRef::new(&RING, &[], &[]).is_err());
}

#[test]
fn borrowed_cubes_have_the_groups_and_cycles_of_their_set() {
    let cubes = CubesRef::new(&RING, &[3, 4], &[4, 1]).unwrap();
    // the set of the same cubes, axis 0 fastest in storage: the transposed bytes
    let mut bits = vec![0u8; 12];
    for i in 0..3 {
        for j in 0..4 {
            bits[i + 3 * j] = RING[i * 4 + j];
        }
    }
    let set = Input::Cubical(Sourced::new(CubicalSet::new(vec![0, 0], vec![3, 4], bits).unwrap()));
    for generators in [false, true] {
        for field in [None, Some(3)] {
            let mut o = HomologyOptions::default();
            (o.generators, o.field) = (generators, field);
            let a = homology_cubes(&cubes, &o).unwrap();
            let b = homology(&set, &o).unwrap();
            assert_eq!(a.groups, b.groups);
            assert_eq!(a.groups.betti, vec![1, 1, 0]);
            // the same cycles, walked in the order of each one's storage: the same cells
            assert_eq!(cells(&a), cells(&b), "generators {generators}, field {field:?}");
        }
    }
    // the whole cubical complex (periodic: no one-pass route with generators)
    let mut o = HomologyOptions::default();
    (o.generators, o.periodic) = (true, true);
    let (a, b) = (homology_cubes(&cubes, &o).unwrap(), homology(&set, &o).unwrap());
    assert_eq!(a.groups, b.groups);
    // another basis of the torus's cycles, but its cells in the caller's box (3 rows, 4 columns)
    for g in a.generators.iter().flatten() {
        for (cell, _) in g.chain.iter() {
            let gmap::CellName::Cube { min, extent } = &cell else { panic!("{cell:?} is not a cube") };
            assert!(min[0] + i64::from(extent[0]) <= 3 && min[1] + i64::from(extent[1]) <= 4, "{cell:?}");
        }
    }
}

/// Each generator's dimension and its cells, sorted, in the caller's axes.
fn cells(r: &gmap::Report) -> Vec<(usize, Vec<String>)> {
    let mut out: Vec<(usize, Vec<String>)> = r
        .generators
        .iter()
        .flatten()
        .map(|g| {
            let mut c: Vec<String> = g.chain.iter().map(|(cell, _)| cell.to_text()).collect();
            c.sort();
            (g.dim, c)
        })
        .collect();
    out.sort();
    out
}

#[test]
fn options_that_do_not_fit_cubes_are_refused() {
    let cubes = CubesRef::new(&RING, &[3, 4], &[4, 1]).unwrap();
    let mut o = HomologyOptions::default();
    o.field = Some(4);
    assert_eq!(homology_cubes(&cubes, &o).unwrap_err().kind(), gmap::ErrorKind::Usage);
    let mut o = HomologyOptions::default();
    o.method = gmap::Method::Simplicial;
    assert_eq!(homology_cubes(&cubes, &o).unwrap_err().kind(), gmap::ErrorKind::Precondition);
}
