//! CGAL's `gmap_4_simple_example` in this library: two tetrahedra in a 4-map (their darts
//! 4-free), 4-sewn along their whole boundary-free side, which makes one component of two
//! 4-cells. Prints the map's characteristics, as CGAL's example does
//! (`gmap/tests/data/cgal/gmap_4_simple_example.out`).
//!
//! `cargo run --release --example cgal_gmap_4_simple_example`

use std::error::Error;
use std::io::Write;

use gmap::core::GMap;
use gmap::ops::build;

/// Builds and sews the two tetrahedra and writes the characteristics line to `out`.
pub fn run(out: &mut dyn Write) -> Result<(), Box<dyn Error>> {
    let mut g = GMap::new(4);
    let tetrahedron = build::simplex(3)?;
    let first = g.try_append(&tetrahedron)?[0];
    let second = g.try_append(&tetrahedron)?[0];
    // 4-sewing pairs the <α0, α1, α2> orbits: the two whole tetrahedra
    g.try_sew(first, second, 4)?;
    writeln!(out, "{}", g.characteristics())?;
    Ok(())
}

fn main() -> Result<(), Box<dyn Error>> {
    run(&mut std::io::stdout().lock())
}
