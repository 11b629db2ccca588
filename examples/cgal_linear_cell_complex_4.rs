//! CGAL's `linear_cell_complex_4` in this library: two tetrahedra in a 4-map, 4-sewn; a
//! vertex inserted in an edge, then an edge across a face from the new vertex to the
//! opposite corner; both removed again and the 4-sew undone. Prints the characteristics
//! after each of the five steps, as CGAL's example does
//! (`gmap/tests/data/cgal/linear_cell_complex_4.out`).
//!
//! CGAL's program gives the tetrahedra points of R^5 and places the new vertex at the
//! middle of its edge; those points are not part of what it prints.
//!
//! `cargo run --release --example cgal_linear_cell_complex_4`

use std::error::Error;
use std::io::Write;

use gmap::core::GMap;
use gmap::ops::build;
use gmap::ops::euler::ops::{try_insert_edge, try_insert_vertex, try_remove_cell};

/// Runs the example and writes its five lines to `out`.
pub fn run(out: &mut dyn Write) -> Result<(), Box<dyn Error>> {
    let mut g = GMap::new(4);
    let tetrahedron = build::simplex(3)?;
    let d1 = g.try_append(&tetrahedron)?[0];
    let d2 = g.try_append(&tetrahedron)?[0];
    writeln!(out, "{}", g.characteristics())?;

    g.try_sew(d1, d2, 4)?;
    writeln!(out, "{}", g.characteristics())?;

    // a vertex in the edge of d1: it lies on alpha_0(d1), the dart the split puts there
    try_insert_vertex(&mut g, d1)?;
    let d3 = g.alpha(d1, 0);
    writeln!(out, "{}", g.characteristics())?;

    // an edge from the new vertex to the corner of d1's face opposite d1's edge; the new
    // edge's dart at d3's corner is alpha_1(d3)
    let corner = g.alpha_word(d1, &[1, 0, 1]);
    try_insert_edge(&mut g, d3, corner)?;
    let d4 = g.alpha(d3, 1);
    writeln!(out, "{}", g.characteristics())?;

    try_remove_cell(&mut g, d4, 1)?;
    try_remove_cell(&mut g, d3, 0)?;
    g.try_unsew(d1, 4)?;
    writeln!(out, "{}", g.characteristics())?;
    Ok(())
}

fn main() -> Result<(), Box<dyn Error>> {
    run(&mut std::io::stdout().lock())
}
