//! CGAL's `gmap_2_moebius` in this library: a square whose two opposite sides are glued
//! with a half twist is a Möbius strip. Prints the map's characteristics, as CGAL's example
//! does (`gmap/tests/data/cgal/gmap_2_moebius.out`).
//!
//! `cargo run --release --example cgal_gmap_2_moebius`

use std::error::Error;
use std::io::Write;

use gmap::core::GMap;
use gmap::ops::build;

/// Builds the strip and writes its characteristics line to `out`.
pub fn run(out: &mut dyn Write) -> Result<(), Box<dyn Error>> {
    // the square: dart 0 starts side 0 at corner 0, the darts go round the border
    let (mut g, darts) = GMap::from_dense(&build::polygon(4)?);
    let d = darts[0];
    // alpha_1 alpha_0 alpha_1 alpha_0 walks back round the corner of d to the far end of the
    // opposite side: sewing there glues corner 0 to corner 2 and corner 1 to corner 3
    let opposite = g.alpha_word(d, &[1, 0, 1, 0]);
    g.try_sew(d, opposite, 2)?;
    writeln!(out, "{}", g.characteristics())?;
    Ok(())
}

fn main() -> Result<(), Box<dyn Error>> {
    run(&mut std::io::stdout().lock())
}
