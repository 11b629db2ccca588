//! The facade calls the Python package makes instead of deciding itself: a cubical set
//! copied from borrowed cubes in the caller's axes, an image's pixels copied only when the
//! facade decides to, a map that keeps the complex it was made from to name its cells, and
//! the registry's writers of `.cub` and of a complex's own `.facets`.

use gmap::persistence::{image_persistence, Pixels};
use gmap::{CellName, CubesRef, HomologyOptions, Input, MapInput, PersistenceOptions, Sourced};

fn data(name: &str) -> std::path::PathBuf {
    std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../tests/data").join(name)
}

#[test]
fn a_c_ordered_array_becomes_a_set_in_its_own_axes() {
    // shape (2, 3), C order: element (i, j) at 3 i + j; cubes at (0, 2) and (1, 0)
    let c = [0u8, 0, 1, 1, 0, 0];
    let f = [0u8, 1, 0, 0, 1, 0]; // the same array in Fortran order: (i, j) at i + 2 j
    let from_c = CubesRef::new(&c, &[2, 3], &[3, 1]).unwrap().to_input(&[]).unwrap();
    let from_f = CubesRef::new(&f, &[2, 3], &[1, 2]).unwrap().to_input(&[10, 20]).unwrap();
    let (Input::Cubical(a), Input::Cubical(b)) = (&from_c, &from_f) else { panic!("not cubical sets") };
    assert_eq!(a.shape(), &[2, 3]);
    assert_eq!(a.bits(), b.bits());
    let mut cubes: Vec<Vec<i64>> = a.cubes().collect();
    cubes.sort();
    assert_eq!(cubes, vec![vec![0, 2], vec![1, 0]]);
    assert_eq!(b.min(), &[10, 20]);
    // a 3-D C-ordered box: every cube where it was
    let shape = [2usize, 3, 4];
    let bytes: Vec<u8> = (0..24).map(|k| u8::from(k % 5 == 0)).collect();
    let Input::Cubical(s) = CubesRef::new(&bytes, &shape, &[12, 4, 1]).unwrap().to_input(&[]).unwrap() else {
        panic!("not a cubical set")
    };
    let mut got: Vec<Vec<i64>> = s.cubes().collect();
    got.sort();
    let mut want: Vec<Vec<i64>> = (0..24).filter(|k| k % 5 == 0).map(|k| vec![k / 12, (k / 4) % 3, k % 4]).collect();
    want.sort();
    assert_eq!(got, want);
    assert!(CubesRef::new(&c, &[2, 3], &[3, 1]).unwrap().to_input(&[1]).is_err());
}

#[test]
fn a_conversion_is_refused_before_it_is_made() {
    assert!(CubesRef::check_conversion(&[3, 4]).is_ok());
    for bad in [&[][..], &[0, 3], &[2; 9], &[1 << 20, 1 << 20]] {
        assert!(CubesRef::check_conversion(bad).is_err(), "{bad:?}");
    }
    let e = CubesRef::check_conversion(&[1 << 20, 1 << 20]).unwrap_err();
    assert_eq!(e.kind(), gmap::ErrorKind::Limit);
}

#[test]
fn copied_pixels_are_copied_only_when_the_facade_decides() {
    let shape = [6usize, 7];
    let values: Vec<f64> = (0..42).map(|k| ((k * 7) % 11) as f64).collect();
    let o = PersistenceOptions::default();
    let whole = image_persistence(&shape, Pixels::Slice(&values), &o).unwrap();
    let fill = |out: &mut [f64]| out.copy_from_slice(&values);
    assert_eq!(image_persistence(&shape, Pixels::Copied(&fill), &o).unwrap().pairs, whole.pairs);
    // a view of 10^10 pixels: refused with the whole grid's estimate, nothing copied
    let never = |_: &mut [f64]| panic!("copied past the limit");
    let e = image_persistence(&[100_000, 100_000], Pixels::Copied(&never), &o).unwrap_err();
    assert_eq!(e.kind(), gmap::ErrorKind::Limit);
    assert!(e.to_string().contains("100000×100000 image would take an estimated"), "{e}");
}

#[test]
fn a_map_made_from_facets_names_its_cells_by_their_labels() {
    let facets = vec![vec![10, 20, 30], vec![10, 30, 40], vec![10, 20, 40], vec![20, 30, 40]];
    let sc = gmap::ops::import::SimplicialComplex::from_facets(facets).unwrap();
    let m = MapInput::of_complex(std::sync::Arc::new(Sourced::new(sc))).unwrap();
    let mut o = HomologyOptions::default();
    o.generators = true;
    let r = gmap::homology(&Input::Map(m), &o).unwrap();
    assert_eq!((r.kind, r.route), ("map", None));
    assert_eq!(r.groups.betti, vec![1, 0, 1]);
    let top = r.generators.unwrap().into_iter().find(|g| g.dim == 2).unwrap();
    assert!(top.chain.iter().all(|(c, _)| matches!(c, CellName::Simplex(v) if v.len() == 3)));
    // a map that is not one refuses
    let ridge = gmap::ops::import::SimplicialComplex::from_facets(vec![vec![0, 1, 2], vec![0, 1, 3], vec![0, 1, 4]]);
    assert!(MapInput::of_complex(std::sync::Arc::new(Sourced::new(ridge.unwrap()))).is_err());
}

#[test]
fn cubes_and_facets_are_written_as_they_are() {
    let dir = tempfile::tempdir().unwrap();
    let ring = gmap::open(data("cubical/ring.cub")).unwrap();
    let out = dir.path().join("ring.cub");
    gmap::save(&ring, &out, &gmap::SaveOptions::default()).unwrap();
    let back = gmap::open(&out).unwrap();
    let (Input::Cubical(a), Input::Cubical(b)) = (&ring, &back) else { panic!("not cubical sets") };
    let cubes = |s: &gmap::ops::import::CubicalSet| {
        let mut v: Vec<Vec<i64>> = s.cubes().collect();
        v.sort();
        v
    };
    assert_eq!(cubes(a), cubes(b));
    // a cell complex with cells on no cube is refused, naming them
    let cells = gmap::open(data("cubical/mixed.cub")).unwrap();
    let e = gmap::save(&cells, dir.path().join("mixed.cub"), &gmap::SaveOptions::default()).unwrap_err();
    assert!(e.to_string().contains("on no 2-cube"), "{e}");
    // a map is not a cubical set
    let map = gmap::open(data("labelled_segment.gmap")).unwrap();
    let e = gmap::save(&map, dir.path().join("m.cub"), &gmap::SaveOptions::default()).unwrap_err();
    assert!(e.to_string().contains("holds cubical sets"), "{e}");
    assert!(gmap::save::dropped(&map, &dir.path().join("m.cub"), &gmap::SaveOptions::default()).is_empty());
    // a simplicial complex keeps its facets and labels, any complex
    let sc = gmap::open(data("rp2.facets")).unwrap();
    let out = dir.path().join("rp2.facets");
    gmap::save(&sc, &out, &gmap::SaveOptions::default()).unwrap();
    let (Input::Simplicial(a), Input::Simplicial(b)) = (&sc, &gmap::open(&out).unwrap()) else {
        panic!("not complexes")
    };
    assert_eq!(a.facets().collect::<Vec<_>>(), b.facets().collect::<Vec<_>>());
}

#[test]
fn a_builder_refuses_past_the_memory_limit() {
    // 3.2 × 10^9 darts of a 2-map (38 GB of involutions): under the dart index limit, over
    // a limit of 1 GiB (the other tests of this file take a few kilobytes)
    gmap::core::resources::set_max_memory(1 << 30);
    let e = gmap::ops::build::grid(&[20_000, 20_000], &[false, false]).unwrap_err();
    assert!(matches!(e, gmap::ops::build::BuildError::MemoryLimit(_)), "{e}");
    assert!(gmap::ops::build::grid(&[3, 4], &[false, true]).is_ok());
}

#[test]
fn a_missing_file_of_any_reader_is_an_io_error() {
    // the Python package makes these an OSError by Error::is_io, not by their text
    let dir = tempfile::tempdir().unwrap();
    for name in ["missing.gmap", "missing.facets", "missing.npy", "missing.pgm", "missing.json", "missing.off"] {
        let e = gmap::open(dir.path().join(name)).unwrap_err();
        assert!(e.is_io(), "{name}: {e:?}");
    }
    let bad = dir.path().join("bad.facets");
    std::fs::write(&bad, "1 2 x\n").unwrap();
    assert!(!gmap::open(&bad).unwrap_err().is_io());
}
