//! Our port of CGAL's `Generalized_map/test/Generalized_map/GMap_test_insertions.h` (CGAL
//! master, commit 7cf2a92): vertex, edge, dangling-edge and face insertions on degenerate
//! and ordinary cells, with the counts CGAL asserts after each (vertices, edges, faces,
//! volumes, components), then the degrees and codegrees of two sewn hexahedra. CGAL runs
//! the header on a 3-map (from `Generalized_map_3_test.h`) and on a 4-map (from
//! `Generalized_map_4_test.h`, with the same counts, the 4-cells being the components);
//! so do we. Each check cites the header's line.
//!
//! Steps: 12 vertex + 9 edge + 4 face insertions, 1 isomorphism, 6 degrees = 32 per
//! dimension, 64 in all.

mod cgal_common;

use cgal_common::{check, isomorphic, Steps};
use gmap_core::{DartId, GMap};
use gmap_ops::euler::ops::{
    insert_cell_0_in_cell_1, insert_cell_1_in_cell_2, insert_cell_2_in_cell_3, insert_dangling_cell_1_in_cell_2,
    remove_cell,
};

const FILE: &str = "GMap_test_insertions.h";

/// CGAL's `check_number_of_cells_3` on an n-map: in a 4-map the 4-cells come before the
/// components and are as many (no dart is 4-sewn here).
#[track_caller]
fn check3(s: &mut Steps, line: u32, g: &mut GMap, want: [usize; 5]) {
    let mut w = want.to_vec();
    if g.dim() == 4 {
        w.insert(4, want[4]);
    }
    check(s, line, g, &w);
    g.clear();
}

fn vertex(g: &mut GMap, d: DartId) {
    insert_cell_0_in_cell_1(g, d).unwrap();
}

fn test_vertex_insertion(s: &mut Steps, g: &mut GMap) {
    let d1 = g.create_dart();
    vertex(g, d1);
    check3(s, 30, g, [2, 1, 1, 1, 1]);
    let d1 = g.create_dart();
    g.sew(d1, d1, 1);
    vertex(g, d1);
    check3(s, 37, g, [2, 1, 1, 1, 1]);
    let d1 = g.make_edge();
    vertex(g, d1);
    check3(s, 44, g, [3, 2, 1, 1, 1]);
    let d1 = g.make_edge();
    g.sew(d1, g.alpha(d1, 0), 1);
    vertex(g, d1);
    check3(s, 52, g, [2, 2, 1, 1, 1]);
    let (d1, d2) = (g.make_edge(), g.make_edge());
    g.sew(d1, d2, 2);
    vertex(g, d1);
    check3(s, 61, g, [3, 2, 2, 1, 1]);
    let (d1, d2) = (g.make_edge(), g.make_edge());
    g.sew(d1, d2, 2);
    g.sew(d1, g.alpha(d1, 0), 1);
    vertex(g, d1);
    check3(s, 71, g, [2, 2, 2, 1, 1]);
    let (d1, d2) = (g.make_edge(), g.make_edge());
    g.sew(d1, d2, 2);
    g.sew(d1, g.alpha(d1, 0), 1);
    g.sew(d2, g.alpha(d2, 0), 1);
    vertex(g, d1);
    check3(s, 82, g, [2, 2, 2, 1, 1]);
    let d1 = g.make_combinatorial_polygon(3);
    let (d2, d3) = (g.alpha_word(d1, &[0, 1]), g.alpha(d1, 1));
    for d in [d1, d2, d3] {
        vertex(g, d);
    }
    check3(s, 93, g, [6, 6, 1, 1, 1]);
    let (d1, d2) = (g.make_combinatorial_polygon(3), g.make_combinatorial_polygon(3));
    g.sew(d1, d2, 3);
    let (d2, d3) = (g.alpha_word(d1, &[0, 1]), g.alpha(d1, 1));
    for d in [d1, d2, d3] {
        vertex(g, d);
    }
    check3(s, 106, g, [6, 6, 1, 2, 1]);
    let (d1, d2) = (g.make_combinatorial_polygon(3), g.make_combinatorial_polygon(3));
    g.sew(d1, d2, 2);
    vertex(g, d1);
    check3(s, 115, g, [5, 6, 2, 1, 1]);
    let (d1, d2) = (g.make_combinatorial_polygon(3), g.make_combinatorial_polygon(3));
    g.sew(d1, d2, 2);
    for d in [g.alpha_word(d1, &[0, 1]), g.alpha(d1, 1), d1] {
        vertex(g, d);
    }
    check3(s, 126, g, [7, 8, 2, 1, 1]);
    let (d1, d2) = (g.make_combinatorial_hexahedron(), g.make_combinatorial_hexahedron());
    g.sew(d1, d2, 3);
    for d in [g.alpha_word(d1, &[0, 1, 0, 1]), g.alpha_word(d1, &[0, 1]), g.alpha(d1, 1), d1] {
        vertex(g, d);
    }
    check3(s, 138, g, [16, 24, 11, 2, 1]);
}

fn test_edge_insertion(s: &mut Steps, g: &mut GMap) {
    let edge = |g: &mut GMap, d1: DartId| {
        let d2 = g.alpha_word(d1, &[0, 1, 0]);
        insert_cell_1_in_cell_2(g, d1, d2).unwrap();
    };
    let dangling = |g: &mut GMap, d1: DartId| {
        insert_dangling_cell_1_in_cell_2(g, d1, None).unwrap();
    };
    let d1 = g.make_combinatorial_polygon(4);
    edge(g, d1);
    check3(s, 153, g, [4, 5, 2, 1, 1]);
    let (d1, d2) = (g.make_combinatorial_polygon(4), g.make_combinatorial_polygon(4));
    g.sew(d1, d2, 3);
    edge(g, d1);
    check3(s, 162, g, [4, 5, 2, 2, 1]);
    let (d1, d2) = (g.make_combinatorial_polygon(4), g.make_combinatorial_polygon(4));
    g.sew(d1, d2, 2);
    edge(g, d1);
    check3(s, 171, g, [6, 8, 3, 1, 1]);
    let d1 = g.create_dart();
    dangling(g, d1);
    check3(s, 178, g, [2, 2, 1, 1, 1]);
    let d1 = g.make_edge();
    g.sew(d1, g.alpha(d1, 0), 1);
    dangling(g, d1);
    check3(s, 186, g, [2, 2, 1, 1, 1]);
    let (d1, d2) = (g.make_edge(), g.make_edge());
    g.sew(d1, d2, 3);
    g.sew(d1, g.alpha(d1, 0), 1);
    dangling(g, d1);
    check3(s, 196, g, [2, 2, 1, 2, 1]);
    let d1 = g.make_combinatorial_polygon(4);
    dangling(g, d1);
    check3(s, 203, g, [5, 5, 1, 1, 1]);
    let (d1, d2) = (g.make_combinatorial_polygon(4), g.make_combinatorial_polygon(4));
    g.sew(d1, d2, 3);
    dangling(g, d1);
    check3(s, 212, g, [5, 5, 1, 2, 1]);
    let (d1, d2) = (g.make_combinatorial_polygon(4), g.make_combinatorial_polygon(4));
    g.sew(d1, d2, 2);
    dangling(g, d1);
    check3(s, 221, g, [7, 8, 2, 1, 1]);
}

/// CGAL's path: `v[k+1] = alpha_word(v[k], step)`, `len` darts from `start`.
fn path(g: &GMap, start: DartId, step: &[usize], len: usize) -> Vec<DartId> {
    let mut v = vec![start];
    while v.len() < len {
        let last = *v.last().unwrap();
        v.push(g.alpha_word(last, step));
    }
    v
}

fn test_face_insertion(s: &mut Steps, g: &mut GMap) {
    let d1 = g.make_combinatorial_polygon(4);
    let v = path(g, d1, &[0, 1], 4);
    insert_cell_2_in_cell_3(g, &v).unwrap();
    check3(s, 241, g, [4, 4, 2, 1, 1]);
    let (d1, d2) = (g.make_combinatorial_polygon(3), g.make_combinatorial_polygon(3));
    g.sew(d1, d2, 2);
    let v = path(g, d1, &[0, 1], 3);
    insert_cell_2_in_cell_3(g, &v).unwrap();
    check3(s, 253, g, [4, 5, 3, 2, 1]);
    let d1 = g.make_combinatorial_hexahedron();
    let v = path(g, g.alpha(d1, 2), &[0, 1, 2, 1], 4);
    insert_cell_2_in_cell_3(g, &v).unwrap();
    check3(s, 265, g, [8, 12, 7, 2, 1]);
    let (d1, d2) = (g.make_combinatorial_hexahedron(), g.make_combinatorial_hexahedron());
    g.sew(d1, d2, 3);
    let d3 = g.alpha(d1, 2);
    remove_cell(g, d1, 2);
    let v = path(g, d3, &[0, 1, 2, 1], 4);
    insert_cell_2_in_cell_3(g, &v).unwrap();
    let mut w = vec![12, 20, 11, 2];
    w.extend(if g.dim() == 4 { vec![1, 1] } else { vec![1] });
    check(s, 280, g, &w);
    let mut g2 = GMap::new(g.dim());
    let (d1, d2) = (g2.make_combinatorial_hexahedron(), g2.make_combinatorial_hexahedron());
    g2.sew(d1, d2, 3);
    s.assert(287, isomorphic(g, &g2), "is_isomorphic_to (after insertion/removal)");
    s.equal(294, g2.degree(d1, 0), 4, "degree<0>");
    s.equal(301, g2.degree(d1, 1), 3, "degree<1>");
    s.equal(308, g2.degree(d1, 2), 2, "degree<2>");
    s.equal(315, g2.codegree(d1, 1), 2, "codegree<1>");
    s.equal(322, g2.codegree(d1, 2), 4, "codegree<2>");
    s.equal(329, g2.codegree(d1, 3), 6, "codegree<3>");
    g.clear();
}

fn run(dim: usize) -> usize {
    let mut s = Steps::new(FILE);
    let mut g = GMap::new(dim);
    test_vertex_insertion(&mut s, &mut g);
    test_edge_insertion(&mut s, &mut g);
    test_face_insertion(&mut s, &mut g);
    s.done()
}

#[test]
fn insertions_in_a_3_map() {
    assert_eq!(run(3), 32);
}

#[test]
fn insertions_in_a_4_map() {
    assert_eq!(run(4), 32);
}
