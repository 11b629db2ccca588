//! CGAL's `gmap_3_with_colored_facets` in this library: two hexahedra whose faces carry an
//! integer colour (7 on the first, 13 on the second), with a merge hook that adds the two
//! colours and a split hook that halves the kept colour and gives the half to the new face
//! too. The 3-sew along a face merges two colours into 20; a vertex inserted in that face
//! splits it in four triangles, three splits in turn: 20 → 10, 5, 2, leaving 2 on the
//! triangle of the dart given. Prints the colours after each step and the characteristics
//! at the end, as CGAL's example does (`gmap/tests/data/cgal/gmap_3_with_colored_facets.out`).
//!
//! CGAL lists the colours in the order of its attribute container, an artefact of how it
//! reuses freed slots; this port prints them sorted (the test compares both as sorted
//! lists).
//!
//! `cargo run --release --example cgal_gmap_3_with_colored_facets`

use std::error::Error;
use std::io::Write;

use gmap::core::{Cells, GMap};
use gmap::ops::build;
use gmap::ops::euler::ops::insert_cell_0_in_cell_2;

/// A 3-map with an `i32` on every face.
type Map = GMap<((), (), Cells<i32>, ())>;

/// The face colours, sorted, each followed by `"; "`.
fn colours(g: &Map) -> String {
    let mut values: Vec<i32> = g.attributes::<2>().map(|(_, &c)| c).collect();
    values.sort_unstable();
    values.iter().map(|c| format!("{c}; ")).collect()
}

/// Runs the example and writes its three lines to `out`.
pub fn run(out: &mut dyn Write) -> Result<(), Box<dyn Error>> {
    let mut g: Map = GMap::with_attributes(3);
    g.set_on_merge::<2>(|kept, other| *kept += other);
    g.set_on_split::<2>(|kept, copy| {
        *kept /= 2;
        *copy = *kept;
    });
    let hexahedron = build::cube(3)?;
    let first = g.try_append(&hexahedron)?[0];
    let second = g.try_append(&hexahedron)?[0];
    for (volume, colour) in [(first, 7), (second, 13)] {
        let faces: Vec<_> = g.one_dart_per_incident_cell(volume, 3, 2).collect();
        for f in faces {
            g.try_set_attribute::<2>(f, colour)?;
        }
    }
    g.try_sew(first, second, 3)?;
    writeln!(out, "{}", colours(&g))?;
    insert_cell_0_in_cell_2(&mut g, second, None)?;
    writeln!(out, "{}", colours(&g))?;
    writeln!(out, "{}", g.characteristics())?;
    Ok(())
}

fn main() -> Result<(), Box<dyn Error>> {
    run(&mut std::io::stdout().lock())
}
