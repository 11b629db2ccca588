//! One vocabulary on both maps: the editable `GMap` and its `DenseMap` snapshot answer the
//! same whole-map questions under the same names, with the same answers, and the same
//! darts through `MapView`.

use gmap_core::{Dart, DartId, DenseMap, GMap, MapView};

fn two_hexahedra_and_a_loose_tetrahedron() -> GMap {
    let mut g = GMap::new(3);
    let a = g.make_combinatorial_hexahedron();
    let b = g.make_combinatorial_hexahedron();
    g.make_combinatorial_tetrahedron();
    g.sew(a, b, 3);
    g
}

#[test]
fn the_same_questions_have_the_same_answers() {
    let g = two_hexahedra_and_a_loose_tetrahedron();
    let d = g.to_dense_map();
    assert_eq!(g.dart_count(), d.dart_count());
    assert_eq!(g.cell_counts(), d.cell_counts());
    assert_eq!(g.cell_counts(), vec![16, 26, 15, 3]);
    for i in 0..=3 {
        assert_eq!(g.cell_count(i), d.cell_count(i));
        assert_eq!(g.cells(i).len(), d.cells(i).len());
    }
    assert_eq!(g.euler_characteristic(), d.euler_characteristic());
    assert_eq!((g.component_count(), d.component_count()), (2, 2));
    assert_eq!(g.components().len(), d.components().len());
    assert_eq!(g.is_orientable(), d.is_orientable());
    assert_eq!(g.orientation().is_ok(), d.orientation().is_ok());
    assert_eq!(g.is_valid(), d.is_valid());
    assert!(g.validate().is_ok() && d.validate().is_ok());
    assert_eq!(g.has_complete_boundaries(), d.has_complete_boundaries());
    let first = g.darts().next().unwrap();
    assert_eq!(g.cell_darts(first, 2).len(), d.cell_darts(Dart::new(0), 2).len());
}

/// The same questions asked of both representations give the same answers.
fn agree(m: &DenseMap) {
    let (g, ids) = GMap::from_dense(m);
    assert_eq!(g.cell_counts(), m.cell_counts());
    assert_eq!(g.euler_characteristic(), m.euler_characteristic());
    assert_eq!(g.component_count(), m.component_count());
    assert_eq!(g.components(), m.components());
    assert_eq!(g.is_orientable(), m.is_orientable());
    assert_eq!(g.orientation(), m.orientation());
    assert_eq!(g.validate().map_err(|e| e.to_string()), m.validate().map_err(|e| e.to_string()));
    assert_eq!(g.check_complete_boundaries(), m.check_complete_boundaries());
    assert_eq!(g.dart_list(), ids);
    for d in m.darts() {
        for i in 0..=m.dim() {
            assert_eq!(g.cells(i), m.cells(i));
            let a: Vec<DartId> = g.cell_darts(ids[d.index()], i);
            let b: Vec<Dart> = m.cell_darts(d, i);
            assert_eq!(a.len(), b.len());
            assert_eq!(g.is_free(ids[d.index()], i), m.is_free(d, i));
        }
    }
}

#[test]
fn editable_and_dense_agree_on_the_examples() {
    use gmap_core::examples::*;
    for m in [fig1_curve(), fig1_surface(), cylinder(), klein_bottle(), torus()] {
        agree(&m);
    }
}
