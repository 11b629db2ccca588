//! The Euler operators under CGAL's names, and the edge between two faces, with exact
//! counts and the darts they return; their refusals name the offending dart.

use gmap_core::{Cells, DartId, GMap};
use gmap_ops::build;
use gmap_ops::euler::ops::*;

/// A 3-map with a small label on its edges, faces and volumes.
type Labelled = GMap<((), Cells<u8>, Cells<u8>, Cells<u8>)>;

/// Darts, cells of every dimension, components and validity.
fn summary<A: gmap_core::Attributes>(g: &GMap<A>) -> (usize, Vec<usize>, usize, bool) {
    let c = g.characteristics();
    (c.darts, c.cells, c.components, c.valid)
}

#[test]
fn an_edge_between_two_faces_of_one_cube() {
    let mut g = GMap::new(3);
    let d = g.try_append(&build::cube(3).unwrap()).unwrap()[0];
    // the face opposite to d's: across the cube through the edge at d
    let opposite = g.alpha_word(d, &[1, 0, 1, 2]);
    assert!(!g.cell_darts(d, 2).contains(&opposite));
    assert!(can_insert_edge_between_faces(&g, d, opposite));
    let r = try_insert_edge_between_faces(&mut g, d, opposite).unwrap();
    assert_eq!(r.dx, vec![0, 1, -1, 0]);
    assert_eq!(g.alpha(r.dart, 1), d);
    assert_eq!(g.alpha(g.alpha(r.dart, 0), 1), opposite);
    assert_eq!(summary(&g), (52, vec![8, 13, 5, 1], 1, true));
    // the new edge has the one merged face on both sides: removing it is refused, as it
    // would cut that face in two
    assert!(!is_removable_keeping_homology(&g, r.dart, 1));
}

#[test]
fn an_edge_between_two_volumes_merges_them() {
    // two cubes 3-sewn along a face; an edge between outer faces of the two
    let mut g: Labelled = GMap::with_attributes(3);
    let a = g.try_append(&build::cube(3).unwrap()).unwrap()[0];
    let b = g.try_append(&build::cube(3).unwrap()).unwrap()[0];
    g.sew(a, b, 3);
    g.set_attribute::<3>(a, 1);
    g.set_attribute::<3>(b, 2);
    let (fa, fb) = (g.alpha_word(a, &[2]), g.alpha_word(b, &[2]));
    g.set_attribute::<2>(fa, 10);
    g.set_attribute::<2>(fb, 20);
    assert_eq!(summary(&g).1, vec![12, 20, 11, 2]);
    let r = try_insert_edge_between_faces(&mut g, fa, fb).unwrap();
    assert_eq!(r.dx, vec![0, 1, -1, -1]);
    assert_eq!(summary(&g), (100, vec![12, 21, 10, 1], 1, true));
    // the merged face and volume keep the values of the first dart's cells
    assert_eq!((g.attribute::<2>(fb), g.attribute::<3>(b)), (Some(&10), Some(&1)));
    assert_eq!((g.attribute_count::<2>(), g.attribute_count::<3>()), (1, 1));
}

#[test]
fn an_edge_between_two_inner_faces_pairs_their_copies() {
    // a row of three cubes: the faces 1|2 and 2|3 are both 3-sewn, so each corner has two
    // copies across alpha_3, and the parallel walk pairs them
    let mut g = GMap::new(3);
    let d = g.try_append(&build::grid(&[3, 1, 1], &[false; 3]).unwrap()).unwrap();
    let inner: Vec<DartId> = d.iter().copied().filter(|&x| !g.is_free(x, 3)).collect();
    // both corners in the middle cube: its copies lie in cubes 1 and 3, which merge
    let (d1, d2) = inner
        .iter()
        .find_map(|&x| {
            let (face, volume) = (g.cell_darts(x, 2), g.cell_darts(x, 3));
            inner.iter().find(|y| volume.contains(y) && !face.contains(y)).map(|&y| (x, y))
        })
        .unwrap();
    assert_eq!(summary(&g).1, vec![16, 28, 16, 3]);
    let r = try_insert_edge_between_faces(&mut g, d1, d2).unwrap();
    assert_eq!(r.dx, vec![0, 1, -1, -1]);
    assert_eq!(summary(&g), (144 + 8, vec![16, 29, 15, 2], 1, true));
    // the new edge has two copies, alpha_3-linked like the corners
    assert_eq!(g.cell_darts(r.dart, 1).len(), 8);
    assert!(!g.is_free(r.dart, 3));
}

#[test]
fn edges_between_faces_are_refused_with_the_dart() {
    let mut g = GMap::new(3);
    let d = g.try_append(&build::grid(&[2, 1, 1], &[false; 3]).unwrap()).unwrap();
    let inner = *d.iter().find(|&&x| !g.is_free(x, 3)).unwrap();
    let outer = *d.iter().find(|&&x| g.is_free(x, 3)).unwrap();
    // the same face
    let same = g.alpha_word(outer, &[0, 1]);
    assert_eq!(
        try_insert_edge_between_faces(&mut g, outer, same),
        Err(EulerError::Misplaced { dart: same, what: "a face other than the face of d1" })
    );
    // a corner with a copy across alpha_3 against one without
    assert!(matches!(
        try_insert_edge_between_faces(&mut g, inner, outer),
        Err(EulerError::Misplaced { dart, .. }) if dart == outer
    ));
    assert!(!is_insertable_cell_1_between_two_cells_2(&g, inner, outer));
    // a 1-free dart, a dimension below 2
    let lone = g.create_dart();
    assert_eq!(try_insert_edge_between_faces(&mut g, outer, lone), Err(EulerError::Free { dart: lone, alpha: 1 }));
    let mut line = GMap::new(1);
    let x = line.try_append(&build::simplex(1).unwrap()).unwrap();
    assert_eq!(
        try_insert_edge_between_faces(&mut line, x[0], x[1]),
        Err(EulerError::BadDimension { what: "edge between faces", lo: 2, hi: 1, got: 1 })
    );
    // nothing changed
    assert_eq!(summary(&g).0, 97);
}

#[test]
fn cgal_names_return_a_dart_of_the_new_cell() {
    let mut g: Labelled = GMap::with_attributes(3);
    let d1 = g.try_append(&build::cube(3).unwrap()).unwrap()[0];
    g.set_attribute::<3>(d1, 7);
    // CGAL's gmap_3_operations: two diagonals in opposite faces, a face along the path
    assert!(is_insertable_cell_1_in_cell_2(&g, d1, g.alpha_word(d1, &[0, 1, 0])));
    let far = g.alpha_word(d1, &[0, 1, 0]);
    let e1 = insert_cell_1_in_cell_2(&mut g, d1, far).unwrap();
    assert_eq!((g.alpha(e1, 1), g.cell_darts(e1, 1).len(), g.attribute::<1>(e1)), (d1, 4, None));
    let d2 = g.alpha_word(d1, &[2, 1, 0, 1, 2]);
    let far = g.alpha_word(d2, &[0, 1, 0]);
    insert_cell_1_in_cell_2(&mut g, d2, far).unwrap();
    let path = [
        g.alpha_word(d1, &[1]),
        g.alpha_word(d1, &[1, 0, 1, 2, 1]),
        g.alpha_word(d2, &[1, 0]),
        g.alpha_word(d2, &[2, 1]),
    ];
    assert!(is_insertable_cell_2_in_cell_3(&g, &path));
    let f = insert_cell_2_in_cell_3(&mut g, &path).unwrap();
    // CGAL returns alpha_0 of the new face's dart at path[0]
    assert_eq!(g.alpha(f, 2), g.alpha(path[0], 0));
    assert_eq!((g.cell_darts(f, 2).len(), g.attribute::<2>(f)), (16, None));
    assert_eq!(summary(&g), (72, vec![8, 14, 9, 2], 1, true));
    // the volume split: both halves carry 7
    assert_eq!((g.attribute_count::<3>(), g.attribute::<3>(g.alpha_word(f, &[3]))), (2, Some(&7)));
    // a vertex in an edge, a dangling edge with its point
    assert!(is_insertable_cell_0_in_cell_1(&g, d1));
    let v = insert_cell_0_in_cell_1(&mut g, d1).unwrap();
    assert_eq!((g.alpha(v, 0), g.cell_darts(v, 0).len()), (d1, 4));
    assert!(is_insertable_dangling_cell_1_in_cell_2(&g, v));
    let tip = insert_dangling_cell_1_in_cell_2(&mut g, v, Some([1.0, 2.0, 3.0])).unwrap();
    assert_eq!((g.point(tip), g.cell_darts(tip, 0).len()), (Some([1.0, 2.0, 3.0]), 2));
    assert_eq!(g.alpha(g.alpha_word(tip, &[0]), 1), v);
    assert_eq!(summary(&g), (72 + 4 + 4, vec![10, 16, 9, 2], 1, true));
    // the homology-keeping removals (the homology-keeping contraction refuses here: the
    // cube's boundary is 3-free, and contracting an edge on a boundary would pinch it;
    // CGAL's contract_cell accepts it)
    remove_cell_keeping_homology(&mut g, tip, 1);
    assert!(!is_contractible_keeping_homology(&g, v, 1));
    assert!(is_contractible(&g, v, 1));
    remove_cell_keeping_homology(&mut g, v, 0);
    assert_eq!(summary(&g), (72, vec![8, 14, 9, 2], 1, true));
    // refusals are errors, not panics
    assert_eq!(
        insert_cell_2_in_cell_3(&mut g, &[]).unwrap_err().to_string(),
        "a cell split (no dart given) needs a cell dimension in 1..=3, got 3"
    );
}

#[test]
fn a_vertex_in_an_edge_with_points_is_placed_at_its_middle() {
    let mut g = GMap::new(2);
    let d = g.try_append(&build::polygon(4).unwrap()).unwrap();
    // the polygon's corners carry points: dart 0 at corner 0, dart 1 at corner 1
    let (p, q) = (g.point(d[0]).unwrap(), g.point(d[1]).unwrap());
    try_insert_vertex(&mut g, d[0]).unwrap();
    let w = g.alpha(d[0], 0);
    let mid = [0.5 * (p[0] + q[0]), 0.5 * (p[1] + q[1]), 0.5 * (p[2] + q[2])];
    assert_eq!(g.point(w), Some(mid));
    // without points, no point; with one given, that one
    let mut h = GMap::new(2);
    let e = h.try_append(&build::cube(2).unwrap()).unwrap();
    try_insert_vertex(&mut h, e[0]).unwrap();
    assert_eq!(h.point(h.alpha(e[0], 0)), None);
    try_insert_vertex_at(&mut h, e[2], Some([0.0, 5.0, 0.0])).unwrap();
    assert_eq!(h.point(h.alpha(e[2], 0)), Some([0.0, 5.0, 0.0]));
    assert_eq!(h.point_count(), 1);
    h.validate().unwrap();
}
