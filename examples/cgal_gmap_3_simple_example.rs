//! CGAL's `gmap_3_simple_example` in this library: two tetrahedra in a 3-map, the map's
//! characteristics, and the sizes of two orbits walked lazily — the `<α0, α1, α2>` orbit of
//! a dart of the first tetrahedron (in a 3-map, its volume) and the `<α0, α1>` orbit of a
//! dart of the second (a face seen from one volume). Prints what CGAL's example prints
//! (`gmap/tests/data/cgal/gmap_3_simple_example.out`).
//!
//! `cargo run --release --example cgal_gmap_3_simple_example`

use std::error::Error;
use std::io::Write;

use gmap::core::{AlphaSet, GMap};
use gmap::ops::build;

/// Builds the two tetrahedra and writes the three lines to `out`.
pub fn run(out: &mut dyn Write) -> Result<(), Box<dyn Error>> {
    let mut g = GMap::new(3);
    // the tetrahedron of the builder (24 darts, its faces 3-free), twice
    let tetrahedron = build::simplex(3)?;
    let first = g.try_append(&tetrahedron)?[0];
    let second = g.try_append(&tetrahedron)?[0];
    writeln!(out, "{}", g.characteristics())?;
    let volume = g.orbit_iter(first, AlphaSet::of(&[0, 1, 2])).count();
    writeln!(out, "Number of darts of the first tetrahedron: {volume}")?;
    let face = g.orbit_iter(second, AlphaSet::of(&[0, 1])).count();
    writeln!(out, "Number of darts of the face incident to dh2: {face}")?;
    Ok(())
}

fn main() -> Result<(), Box<dyn Error>> {
    run(&mut std::io::stdout().lock())
}
