//! CGAL's `gmap_3_marks` in this library: two tetrahedra 3-sewn, the darts of the first
//! marked, then the face they share removed, which merges the two volumes into one. The
//! mark still tells which darts came from the first tetrahedron: 24 minus the 6 removed
//! with the face. Prints that count, as CGAL's example does
//! (`gmap/tests/data/cgal/gmap_3_marks.out`). Marks here have no fixed cap (CGAL's stop at 32
//! and throw), so reserving one cannot fail.
//!
//! `cargo run --release --example cgal_gmap_3_marks`

use std::error::Error;
use std::io::Write;

use gmap::core::GMap;
use gmap::ops::build;
use gmap::ops::euler::ops::try_remove_cell;

/// Runs the example and writes its line to `out`.
pub fn run(out: &mut dyn Write) -> Result<(), Box<dyn Error>> {
    let mut g = GMap::new(3);
    let first_tetrahedron = g.reserve_mark();
    let tetrahedron = build::simplex(3)?;
    let first = g.try_append(&tetrahedron)?[0];
    let second = g.try_append(&tetrahedron)?[0];
    g.try_sew(first, second, 3)?;
    for d in g.cell_darts(first, 3) {
        g.mark(first_tetrahedron, d);
    }
    // the shared face: removing it (a face between two volumes) merges them
    try_remove_cell(&mut g, first, 2)?;
    let kept = g.darts().filter(|&d| g.is_marked(first_tetrahedron, d)).count();
    writeln!(out, "Number of darts from the first tetrahedron: {kept}")?;
    g.free_mark(first_tetrahedron);
    Ok(())
}

fn main() -> Result<(), Box<dyn Error>> {
    run(&mut std::io::stdout().lock())
}
