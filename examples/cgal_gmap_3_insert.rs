//! CGAL's `gmap_3_insert` in this library: a hexahedron and a separate square; one edge
//! joins a corner of the square to a corner of a face of the hexahedron
//! (`insert_cell_1_between_two_cells_2`, CGAL 6), so the square becomes a hole in that
//! face. Prints the characteristics (one volume, six faces: the square's face and the
//! hexahedron's became one) and the number of 2-free darts, the 8 of the hole's border, as
//! CGAL's example does (`gmap/tests/data/cgal/gmap_3_insert.out`).
//!
//! `cargo run --release --example cgal_gmap_3_insert`

use std::error::Error;
use std::io::Write;

use gmap::core::GMap;
use gmap::ops::build;
use gmap::ops::euler::ops::{insert_cell_1_between_two_cells_2, is_insertable_cell_1_between_two_cells_2};

/// Runs the example and writes its two lines to `out`.
pub fn run(out: &mut dyn Write) -> Result<(), Box<dyn Error>> {
    let mut g = GMap::new(3);
    let hexahedron = g.try_append(&build::cube(3)?)?[0];
    let square = g.try_append(&build::polygon(4)?)?[0];
    if !is_insertable_cell_1_between_two_cells_2(&g, hexahedron, square) {
        return Err("the square cannot be hung from the hexahedron".into());
    }
    insert_cell_1_between_two_cells_2(&mut g, hexahedron, square)?;
    writeln!(out, "{}", g.characteristics())?;
    let free = g.darts().filter(|&d| g.is_free(d, 2)).count();
    writeln!(out, "Number of 2-free darts: {free}")?;
    Ok(())
}

fn main() -> Result<(), Box<dyn Error>> {
    run(&mut std::io::stdout().lock())
}
