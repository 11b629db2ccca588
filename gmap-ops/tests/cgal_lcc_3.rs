//! Our port of CGAL's `Linear_cell_complex/test/Linear_cell_complex/Linear_cell_complex_3_test.h`
//! (CGAL/cgal at commit 12328929b2dd8e457fd7ec4f0fcff87f1fe5d2a0), the generalized-map
//! flavour. Each check cites the header's line: the map is valid, its cells of every
//! dimension and its components are as CGAL asserts. This file holds the edge-contraction
//! sequence of the header (lines 275-323); the header's other sequences are ported in
//! Python (`python/tests/test_modelling.py`).
//!
//! Steps: 8.

mod cgal_common;

use cgal_common::{check, Steps};
use gmap_core::GMap;
use gmap_ops::euler::ops::{contract_cell, is_contractible};

#[test]
fn linear_cell_complex_3_edge_contractions() {
    let mut s = Steps::new("Linear_cell_complex_3_test.h");
    let mut lcc = GMap::new(3);
    // :275-278: a lone dart vanishes
    let d = lcc.create_dart();
    s.assert(276, is_contractible(&lcc, d, 1), "is_contractible<1> of a lone dart");
    contract_cell(&mut lcc, d, 1);
    check(&mut s, 278, &lcc, &[0, 0, 0, 0, 0]);
    // :286-290: an open segment
    let d = lcc.make_segment([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0]]);
    contract_cell(&mut lcc, d, 1);
    check(&mut s, 290, &lcc, &[0, 0, 0, 0, 0]);
    // :293-297: a segment 1-sewn to itself
    let d = lcc.make_segment([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0]]);
    lcc.sew(d, d, 1);
    contract_cell(&mut lcc, d, 1);
    check(&mut s, 297, &lcc, &[0, 0, 0, 0, 0]);
    // :300-304: a loop
    let d = lcc.make_segment([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0]]);
    let o = lcc.other_orientation(d);
    lcc.sew(d, o, 1);
    contract_cell(&mut lcc, d, 1);
    check(&mut s, 304, &lcc, &[0, 0, 0, 0, 0]);
    // :307-323: a triangle's edges, one by one
    let dh1 = lcc.make_triangle([[5.0, 5.0, 3.0], [7.0, 5.0, 3.0], [6.0, 6.0, 3.0]]);
    let dh2 = lcc.previous(dh1);
    let dh3 = lcc.next(dh1);
    contract_cell(&mut lcc, dh1, 1);
    check(&mut s, 311, &lcc, &[2, 2, 1, 1, 1]);
    contract_cell(&mut lcc, dh2, 1);
    check(&mut s, 317, &lcc, &[1, 1, 1, 1, 1]);
    contract_cell(&mut lcc, dh3, 1);
    check(&mut s, 323, &lcc, &[0, 0, 0, 0, 0]);
    assert_eq!(s.done(), 8);
}
