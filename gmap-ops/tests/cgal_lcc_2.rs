//! Our port of CGAL's `Linear_cell_complex/test/Linear_cell_complex/Linear_cell_complex_2_test.h`
//! (CGAL master, commit caf6d1b), the generalized-map flavour: a 2-dimensional linear
//! cell complex built from closed segments and triangles, with insertions of points and
//! barycentres, dangling edges, then every removal back to the empty map. Each check
//! cites the header's line: the map is valid, its cells and components are as CGAL
//! asserts, and there are as many vertex points as vertices (`number_of_vertex_attributes`).
//!
//! The plane graph of CGAL's `data/graph.txt` is rebuilt here from its description (a
//! 6 × 6 grid of points two apart, the centre of each square joined to its four corners,
//! and a square with a triangle on one side, apart). Not ported: the import of a Delaunay
//! triangulation of `data/points2D.txt` (its counts depend on CGAL's triangulation); the
//! orientation tests that follow are for combinatorial maps only (CGAL returns true for
//! generalized maps).
//!
//! Steps: 28.

mod cgal_common;

use cgal_common::{check, isomorphic, Steps};
use gmap_core::{Attributes, DartId, GMap};
use gmap_ops::euler::ops::{
    insert_barycenter_in_cell, insert_dangling_cell_1_in_cell_2, insert_point_in_cell, remove_cell,
};
use gmap_ops::import::plane_graph::import_from_plane_graph;

/// CGAL's `check_number_of_cells_2` for a linear cell complex: also one point per vertex.
#[track_caller]
fn check_lcc<A: Attributes>(s: &mut Steps, line: u32, g: &GMap<A>, want: &[usize]) {
    assert_eq!(g.point_count(), want[0], "Linear_cell_complex_2_test.h:{line}: one point per vertex");
    check(s, line, g, want);
}

/// Removes every edge at the vertex of `d` (CGAL's loop over `darts_of_cell<0,2>`, skipping
/// the darts already gone).
fn remove_edges_at(g: &mut GMap, d: DartId) {
    for x in g.cell_darts(d, 0) {
        if g.contains(x) {
            remove_cell(g, x, 1);
        }
    }
}

#[test]
fn linear_cell_complex_2_test() {
    let mut s = Steps::new("Linear_cell_complex_2_test.h");
    let mut lcc = GMap::new(2);
    let dh1 = lcc.make_segment_closed([[0.0, 0.0], [1.0, 0.0]]);
    let dh2 = lcc.make_segment_closed([[2.0, 0.0], [2.0, 1.0]]);
    let dh3 = lcc.make_segment_closed([[2.0, 2.0], [3.0, 1.0]]);
    check_lcc(&mut s, 226, &lcc, &[6, 3, 6, 3]);
    {
        let mut lcc2 = GMap::new(2);
        std::mem::swap(&mut lcc2, &mut lcc);
        check_lcc(&mut s, 232, &lcc, &[0, 0, 0, 0]);
        check_lcc(&mut s, 234, &lcc2, &[6, 3, 6, 3]);
        std::mem::swap(&mut lcc, &mut lcc2);
        check_lcc(&mut s, 238, &lcc2, &[0, 0, 0, 0]);
        check_lcc(&mut s, 240, &lcc, &[6, 3, 6, 3]);
        let lcc3 = lcc.clone();
        check_lcc(&mut s, 246, &lcc3, &[6, 3, 6, 3]);
        s.assert(248, isomorphic(&lcc, &lcc3), "is_isomorphic_to (operator=)");
    }
    let vh = lcc.point_attribute(dh1).unwrap();
    s.assert(253, lcc.is_point_used(vh), "is_attribute_used<0>");
    lcc.sew(dh1, dh2, 1);
    lcc.sew(lcc.other_orientation(dh2), dh3, 1);
    check_lcc(&mut s, 258, &lcc, &[4, 3, 4, 1]);
    let dh5 = lcc.make_triangle([[5.0, 5.0], [7.0, 5.0], [6.0, 6.0]]);
    let dh6 = lcc.make_triangle([[5.0, 4.0], [7.0, 4.0], [6.0, 3.0]]);
    check_lcc(&mut s, 264, &lcc, &[10, 9, 6, 3]);
    lcc.sew(dh5, dh6, 2);
    check_lcc(&mut s, 269, &lcc, &[8, 8, 6, 2]);
    let dh7 = insert_barycenter_in_cell(&mut lcc, dh1, 1).unwrap();
    check_lcc(&mut s, 274, &lcc, &[9, 9, 6, 2]);
    let dh8 = insert_barycenter_in_cell(&mut lcc, dh5, 2).unwrap();
    check_lcc(&mut s, 279, &lcc, &[10, 12, 8, 2]);
    let dh9 = insert_point_in_cell(&mut lcc, dh2, 1, [1.0, 0.0, 0.0]).unwrap();
    check_lcc(&mut s, 284, &lcc, &[11, 13, 8, 2]);
    let dh10 = insert_point_in_cell(&mut lcc, dh6, 2, [6.0, 5.0, 0.0]).unwrap();
    check_lcc(&mut s, 289, &lcc, &[12, 16, 10, 2]);
    let dh11 = insert_dangling_cell_1_in_cell_2(&mut lcc, dh8, Some([6.0, 5.2, 0.0])).unwrap();
    check_lcc(&mut s, 294, &lcc, &[13, 17, 10, 2]);
    remove_cell(&mut lcc, dh11, 1);
    check_lcc(&mut s, 300, &lcc, &[12, 16, 10, 2]);
    remove_edges_at(&mut lcc, dh10);
    check_lcc(&mut s, 317, &lcc, &[11, 13, 8, 2]);
    remove_cell(&mut lcc, dh9, 0);
    check_lcc(&mut s, 322, &lcc, &[10, 12, 8, 2]);
    remove_edges_at(&mut lcc, dh8);
    check_lcc(&mut s, 338, &lcc, &[9, 9, 6, 2]);
    remove_cell(&mut lcc, dh7, 0);
    check_lcc(&mut s, 343, &lcc, &[8, 8, 6, 2]);
    lcc.unsew(dh5, 2);
    check_lcc(&mut s, 348, &lcc, &[10, 9, 6, 3]);
    remove_cell(&mut lcc, dh6, 2);
    remove_cell(&mut lcc, dh5, 2);
    check_lcc(&mut s, 354, &lcc, &[4, 3, 4, 1]);
    lcc.unsew(dh1, 1);
    check_lcc(&mut s, 359, &lcc, &[5, 3, 5, 2]);
    let at = lcc.other_orientation(dh2);
    lcc.unsew(at, 1);
    check_lcc(&mut s, 364, &lcc, &[6, 3, 6, 3]);
    for d in [dh1, dh2, dh3] {
        remove_cell(&mut lcc, d, 1);
    }
    check_lcc(&mut s, 371, &lcc, &[0, 0, 0, 0]);
    s.assert(374, !lcc.is_point_used(vh), "!is_attribute_used<0> once its vertex is gone");
    let graph = import_from_plane_graph(&graph_txt()).unwrap();
    check_lcc(&mut s, 385, &graph, &[66, 166, 104, 2]);
    assert_eq!(s.done(), 28);
}

/// The plane graph of CGAL's `data/graph.txt`: 66 vertices, 166 edges.
fn graph_txt() -> String {
    let mut points: Vec<(f64, f64)> = Vec::new();
    let mut edges: Vec<(usize, usize)> = Vec::new();
    // the grid corners, column by column, x and y in -5, -3, …, 5
    let corner = |i: usize, j: usize| 6 * i + j;
    for i in 0..6 {
        for j in 0..6 {
            points.push((2.0 * i as f64 - 5.0, 2.0 * j as f64 - 5.0));
        }
    }
    for i in 0..6 {
        for j in 0..6 {
            if j + 1 < 6 {
                edges.push((corner(i, j), corner(i, j + 1)));
            }
            if i + 1 < 6 {
                edges.push((corner(i, j), corner(i + 1, j)));
            }
        }
    }
    // the centre of every square, joined to its four corners
    for i in 0..5 {
        for j in 0..5 {
            let c = points.len();
            points.push((2.0 * i as f64 - 4.0, 2.0 * j as f64 - 4.0));
            for (a, b) in [(i, j), (i + 1, j), (i, j + 1), (i + 1, j + 1)] {
                edges.push((corner(a, b), c));
            }
        }
    }
    // apart: a square with a triangle on its top side
    let base = points.len();
    points.extend([(10.0, 10.0), (15.0, 10.0), (10.0, 15.0), (15.0, 15.0), (12.5, 17.5)]);
    for (a, b) in [(0, 1), (0, 2), (1, 3), (2, 3), (2, 4), (3, 4)] {
        edges.push((base + a, base + b));
    }
    let mut text = format!("{} {}\n", points.len(), edges.len());
    for (x, y) in points {
        text += &format!("{x} {y}\n");
    }
    for (a, b) in edges {
        text += &format!("{a} {b}\n");
    }
    text
}
