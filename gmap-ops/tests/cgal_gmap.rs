//! Our port of CGAL's generalized-map test suite: every step of
//! `Generalized_map/test/Generalized_map/Generalized_map_{2,3,4}_test.h` (CGAL master,
//! commits 7611a0b for the 3- and 4-map headers, e3934f1 for the 2-map one), replayed with
//! gmap's API under CGAL's names. Each check cites the CGAL file and line of the assertion
//! it ports: the cell counts `count_all_cells` gives (vertices, edges, …, components) after
//! `is_valid`, the isomorphisms and the shape tests. The insertion header
//! (`GMap_test_insertions.h`) is in `cgal_insertions.rs`.
//!
//! Steps: 15 (2-map) + 15 (3-map) + 18 (4-map) = 48 here.

mod cgal_common;

use cgal_common::{check, isomorphic, Steps};
use gmap_core::GMap;
use gmap_ops::euler::ops::{contract_cell, remove_cell, try_close};

#[test]
fn generalized_map_2_test() {
    let mut s = Steps::new("Generalized_map_2_test.h");
    let mut g = GMap::new(2);
    let dh1 = g.make_edge();
    let dh2 = g.make_edge();
    let dh3 = g.make_edge();
    check(&mut s, 114, &g, &[6, 3, 3, 3]);
    g.sew(dh1, dh2, 1);
    g.sew(g.alpha(dh2, 0), dh3, 1);
    check(&mut s, 120, &g, &[4, 3, 1, 1]);
    let mut dh5 = g.make_combinatorial_polygon(3);
    let mut dh6 = g.make_combinatorial_polygon(3);
    check(&mut s, 126, &g, &[10, 9, 3, 3]);
    g.sew(dh5, dh6, 2);
    check(&mut s, 131, &g, &[8, 8, 3, 2]);
    dh5 = g.alpha(dh5, 1);
    dh6 = g.alpha(dh6, 1);
    let at = g.alpha(dh5, 1);
    contract_cell(&mut g, at, 1);
    check(&mut s, 138, &g, &[8, 7, 3, 3]);
    contract_cell(&mut g, dh6, 2);
    check(&mut s, 143, &g, &[6, 5, 2, 2]);
    let at = g.alpha(dh5, 1);
    contract_cell(&mut g, at, 1);
    check(&mut s, 148, &g, &[5, 4, 2, 2]);
    contract_cell(&mut g, dh5, 1);
    check(&mut s, 153, &g, &[4, 3, 1, 1]);
    contract_cell(&mut g, dh2, 1);
    check(&mut s, 158, &g, &[3, 2, 1, 1]);
    contract_cell(&mut g, dh1, 1);
    check(&mut s, 163, &g, &[2, 1, 1, 1]);
    contract_cell(&mut g, dh3, 1);
    check(&mut s, 168, &g, &[0, 0, 0, 0]);
    let dh7 = g.make_combinatorial_hexahedron();
    let dh8 = g.alpha_word(dh7, &[2, 1, 0, 1, 2]);
    let dh9 = g.alpha(dh7, 2);
    remove_cell(&mut g, dh7, 2);
    check(&mut s, 177, &g, &[8, 12, 5, 1]);
    remove_cell(&mut g, dh8, 2);
    check(&mut s, 182, &g, &[8, 12, 4, 1]);
    try_close(&mut g, 2).unwrap();
    check(&mut s, 187, &g, &[8, 12, 6, 1]);
    s.assert(189, g.is_volume_combinatorial_hexahedron(dh9), "is_volume_combinatorial_hexahedron");
    assert_eq!(s.done(), 15);
}

/// The steps the 3- and 4-map headers share before the dimension-specific ones: three
/// edges, a path, two triangles sewn, then a hexahedron with two faces removed. Returns
/// `dh9`, CGAL's dart of the face next to the first one removed.
/// In a 4-map CGAL's counts have one entry more, the 4-cells, here as many as the volumes.
fn shared_opening(s: &mut Steps, g: &mut GMap, lines: [u32; 6]) -> gmap_core::DartId {
    let four = g.dim() == 4;
    let with = |head: &[usize]| -> Vec<usize> {
        let mut v = head.to_vec();
        if four {
            v.insert(4, head[3]);
        }
        v
    };
    let dh1 = g.make_edge();
    let dh2 = g.make_edge();
    let dh3 = g.make_edge();
    check(s, lines[0], g, &with(&[6, 3, 3, 3, 3]));
    g.sew(dh1, dh2, 1);
    g.sew(g.alpha(dh2, 0), dh3, 1);
    check(s, lines[1], g, &with(&[4, 3, 1, 1, 1]));
    let dh5 = g.make_combinatorial_polygon(3);
    let dh6 = g.make_combinatorial_polygon(3);
    check(s, lines[2], g, &with(&[10, 9, 3, 3, 3]));
    g.sew(dh5, dh6, 2);
    check(s, lines[3], g, &with(&[8, 8, 3, 2, 2]));
    g.clear();
    let dh7 = g.make_combinatorial_hexahedron();
    let dh8 = g.alpha_word(dh7, &[2, 1, 0, 1, 2]);
    let dh9 = g.alpha(dh7, 2);
    remove_cell(g, dh7, 2);
    check(s, lines[4], g, &with(&[8, 12, 5, 1, 1]));
    remove_cell(g, dh8, 2);
    check(s, lines[5], g, &with(&[8, 12, 4, 1, 1]));
    dh9
}

#[test]
fn generalized_map_3_test() {
    let mut s = Steps::new("Generalized_map_3_test.h");
    let mut g = GMap::new(3);
    let dh9 = shared_opening(&mut s, &mut g, [67, 73, 79, 84, 94, 99]);
    let dh10 = g.make_combinatorial_hexahedron();
    g.sew(dh9, dh10, 3);
    check(&mut s, 105, &g, &[12, 20, 9, 2, 1]);
    let g2 = g.clone();
    check(&mut s, 111, &g2, &[12, 20, 9, 2, 1]);
    s.assert(113, isomorphic(&g, &g2), "is_isomorphic_to (after copy)");
    try_close(&mut g, 2).unwrap();
    check(&mut s, 122, &g, &[12, 20, 11, 2, 1]);
    s.assert(124, g.is_volume_combinatorial_hexahedron(dh9), "is_volume_combinatorial_hexahedron");
    try_close(&mut g, 3).unwrap();
    check(&mut s, 133, &g, &[12, 20, 11, 3, 1]);
    let at = g.alpha_word(dh9, &[2, 3]);
    remove_cell(&mut g, at, 3);
    check(&mut s, 138, &g, &[12, 20, 11, 2, 1]);
    let at = g.alpha(dh9, 2);
    remove_cell(&mut g, at, 2);
    let at = g.alpha_word(dh9, &[1, 0, 1, 2]);
    remove_cell(&mut g, at, 2);
    check(&mut s, 144, &g, &[12, 20, 9, 2, 1]);
    s.assert(146, isomorphic(&g, &g2), "is_isomorphic_to (after close and removals)");
    assert_eq!(s.done(), 15);
}

#[test]
fn generalized_map_4_test() {
    let mut s = Steps::new("Generalized_map_4_test.h");
    let mut g = GMap::new(4);
    let dh9 = shared_opening(&mut s, &mut g, [62, 68, 74, 79, 89, 94]);
    let dh10 = g.make_combinatorial_hexahedron();
    g.sew(dh9, dh10, 3);
    check(&mut s, 100, &g, &[12, 20, 9, 2, 1, 1]);
    let dh11 = g.make_combinatorial_hexahedron();
    g.sew(dh10, dh11, 4);
    check(&mut s, 106, &g, &[12, 20, 9, 2, 2, 1]);
    let g2 = g.clone();
    check(&mut s, 112, &g2, &[12, 20, 9, 2, 2, 1]);
    s.assert(114, isomorphic(&g, &g2), "is_isomorphic_to (after copy)");
    try_close(&mut g, 2).unwrap();
    check(&mut s, 123, &g, &[12, 20, 11, 2, 2, 1]);
    s.assert(125, g.is_volume_combinatorial_hexahedron(dh9), "is_volume_combinatorial_hexahedron");
    try_close(&mut g, 3).unwrap();
    check(&mut s, 134, &g, &[12, 20, 11, 4, 2, 1]);
    try_close(&mut g, 4).unwrap();
    check(&mut s, 139, &g, &[12, 20, 11, 4, 3, 1]);
    let at = g.alpha_word(dh9, &[2, 3, 4]);
    remove_cell(&mut g, at, 4);
    check(&mut s, 144, &g, &[12, 20, 11, 4, 2, 1]);
    let at = g.alpha_word(dh9, &[2, 3]);
    remove_cell(&mut g, at, 3);
    let at = g.alpha_word(dh10, &[2, 4, 3]);
    remove_cell(&mut g, at, 3);
    check(&mut s, 150, &g, &[12, 20, 11, 2, 2, 1]);
    let at = g.alpha(dh9, 2);
    remove_cell(&mut g, at, 2);
    let at = g.alpha_word(dh9, &[1, 0, 1, 2]);
    remove_cell(&mut g, at, 2);
    check(&mut s, 156, &g, &[12, 20, 9, 2, 2, 1]);
    s.assert(159, isomorphic(&g, &g2), "is_isomorphic_to (after close and removals)");
    assert_eq!(s.done(), 18);
}
