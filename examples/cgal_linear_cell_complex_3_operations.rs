//! CGAL's `linear_cell_complex_3_operations` in this library: three hexahedra with points,
//! the second and the third 3-sewn to two adjacent faces of the first; an edge across the
//! face shared with the second and another across the opposite face of the first; then a
//! face along the closed path of four edges they make with two edges of the first
//! hexahedron, cutting it in two. Prints the characteristics, as the generalized-map run of
//! CGAL's example does (line 2 of `gmap/tests/data/cgal/linear_cell_complex_3_operations.out`;
//! line 1 is its run on a combinatorial map, outside this library).
//!
//! The darts are reached from the ones the constructors return by CGAL's words, written in
//! the involutions of a generalized map: `next` is `alpha_0` then `alpha_1`, `previous`
//! `alpha_1` then `alpha_0`, `opposite<2>` `alpha_0` then `alpha_2`, and `other_orientation`
//! `alpha_0`. [`GMap::make_hexahedron`] returns the flag CGAL's does, so each word names the
//! same cells as in CGAL's program.
//!
//! `cargo run --release --example cgal_linear_cell_complex_3_operations`

use std::error::Error;
use std::io::Write;

use gmap::core::GMap;
use gmap::ops::euler::ops::{try_insert_edge, try_split_cell};

/// CGAL's `next`, `previous`, `opposite<2>` and `other_orientation` as words.
const NEXT: [usize; 2] = [0, 1];
const PREVIOUS: [usize; 2] = [1, 0];
const OPPOSITE_2: [usize; 2] = [0, 2];
const OTHER_ORIENTATION: [usize; 1] = [0];

/// The concatenation of words, applied in order.
fn word(parts: &[&[usize]]) -> Vec<usize> {
    parts.concat()
}

/// Runs the example and writes its line to `out`.
pub fn run(out: &mut dyn Write) -> Result<(), Box<dyn Error>> {
    let mut g = GMap::new(3);
    let d1 = g.try_make_hexahedron([
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [1.0, 2.0, 0.0],
        [0.0, 2.0, 0.0],
        [0.0, 3.0, 4.0],
        [0.0, 0.0, 4.0],
        [6.0, 0.0, 4.0],
        [6.0, 3.0, 4.0],
    ])?;
    let d2 = g.try_make_hexahedron([
        [0.0, -5.0, 0.0],
        [2.0, -5.0, 0.0],
        [2.0, -2.0, 0.0],
        [0.0, -2.0, 0.0],
        [1.0, -1.0, 5.0],
        [1.0, -2.0, 5.0],
        [5.0, -2.0, 5.0],
        [5.0, -2.0, 5.0],
    ])?;
    let d3 = g.try_make_hexahedron([
        [1.0, 0.0, 5.0],
        [0.0, 0.0, 6.0],
        [0.0, 2.0, 5.0],
        [1.0, 2.0, 6.0],
        [1.0, 3.0, 8.0],
        [0.0, 0.0, 8.0],
        [5.0, 0.0, 9.0],
        [7.0, 3.0, 9.0],
    ])?;

    // the face of d1 against the face of the second hexahedron opposite d2's
    let e = g.alpha_word(d2, &word(&[&OPPOSITE_2, &NEXT, &NEXT, &OPPOSITE_2, &OTHER_ORIENTATION]));
    g.try_sew(d1, e, 3)?;
    // the face next to it against a face of the third hexahedron
    let f1 = g.alpha_word(d1, &word(&[&NEXT, &OPPOSITE_2]));
    let f3 = g.alpha_word(d3, &word(&[&PREVIOUS, &OPPOSITE_2, &OTHER_ORIENTATION]));
    g.try_sew(f1, f3, 3)?;

    // an edge across the face of d1 (shared with the second hexahedron: both sides split)
    let from = g.alpha_word(d1, &NEXT);
    let to = g.alpha_word(d1, &word(&[&PREVIOUS, &[1]]));
    try_insert_edge(&mut g, from, to)?;
    // an edge across the opposite face of the first hexahedron (3-free)
    let d2 = g.alpha_word(d1, &word(&[&OPPOSITE_2, &NEXT, &NEXT, &OPPOSITE_2]));
    let to = g.alpha_word(d2, &word(&[&NEXT, &NEXT, &[1]]));
    try_insert_edge(&mut g, d2, to)?;

    // a face along the two new edges and two edges of the hexahedron joining their ends
    let path = [
        g.alpha_word(d1, &NEXT),
        g.alpha_word(d1, &word(&[&PREVIOUS, &OPPOSITE_2, &NEXT])),
        g.alpha_word(d2, &PREVIOUS),
        g.alpha_word(d2, &word(&[&OPPOSITE_2, &NEXT])),
    ];
    try_split_cell(&mut g, &path, 3)?;

    writeln!(out, "{}", g.characteristics())?;
    Ok(())
}

fn main() -> Result<(), Box<dyn Error>> {
    run(&mut std::io::stdout().lock())
}
