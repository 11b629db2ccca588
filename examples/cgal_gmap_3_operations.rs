//! CGAL's `gmap_3_operations` in this library: a hexahedron cut in two by a diagonal face.
//! An edge goes across one face and another across the opposite face, a face is inserted
//! along the closed path of four edges they make with two edges of the hexahedron, and the
//! characteristics are printed; then the face and the two edges are removed again and the
//! characteristics, back at the hexahedron, are printed, as CGAL's example does
//! (`gmap/tests/data/cgal/gmap_3_operations.out`).
//!
//! Darts are reached by words of involutions from the first one, as in CGAL's program: a
//! word's meaning does not depend on how a builder numbers darts, since every dart of a
//! hexahedron is like every other (its 48 flags are permuted transitively by its
//! symmetries).
//!
//! `cargo run --release --example cgal_gmap_3_operations`

use std::error::Error;
use std::io::Write;

use gmap::core::GMap;
use gmap::ops::build;
use gmap::ops::euler::ops::{try_insert_edge, try_remove_cell, try_split_cell};

/// Runs the example and writes its two lines to `out`.
pub fn run(out: &mut dyn Write) -> Result<(), Box<dyn Error>> {
    let mut g = GMap::new(3);
    let d1 = g.try_append(&build::cube(3)?)?[0];
    // a diagonal across the face of d1, from its corner to the opposite corner
    let far = g.alpha_word(d1, &[0, 1, 0]);
    try_insert_edge(&mut g, d1, far)?;
    // the same across the opposite face, from the corner above d1's
    let d2 = g.alpha_word(d1, &[2, 1, 0, 1, 2]);
    let far = g.alpha_word(d2, &[0, 1, 0]);
    try_insert_edge(&mut g, d2, far)?;
    // one dart per edge of the closed path: the two diagonals and the two edges joining
    // their ends, all in faces on the same side of the cut
    let path = [
        g.alpha_word(d1, &[1]),
        g.alpha_word(d1, &[1, 0, 1, 2, 1]),
        g.alpha_word(d2, &[1, 0]),
        g.alpha_word(d2, &[2, 1]),
    ];
    try_split_cell(&mut g, &path, 3)?;
    let d3 = g.alpha_word(path[0], &[2]);
    writeln!(out, "{}", g.characteristics())?;

    try_remove_cell(&mut g, d3, 2)?;
    let diagonal = g.alpha_word(d1, &[1]);
    try_remove_cell(&mut g, diagonal, 1)?;
    let diagonal = g.alpha_word(d2, &[1]);
    try_remove_cell(&mut g, diagonal, 1)?;
    writeln!(out, "{}", g.characteristics())?;
    Ok(())
}

fn main() -> Result<(), Box<dyn Error>> {
    run(&mut std::io::stdout().lock())
}
