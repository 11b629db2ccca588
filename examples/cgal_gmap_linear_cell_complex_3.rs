//! CGAL's `gmap_linear_cell_complex_3` in this library: two tetrahedra with points in a
//! 3-map, 3-sewn along a face (the vertices of that face keep the points of the first
//! tetrahedron), then the second tetrahedron translated by (3, 1, 1), which moves the shared
//! face for both. Prints every vertex point, the points of each volume before the sew, after
//! it and after the translation, and the characteristics, as CGAL's example does
//! (`gmap/tests/data/cgal/gmap_linear_cell_complex_3.out`).
//!
//! CGAL lists vertices in the order of its attribute container and of a traversal; those
//! orders mean nothing about the map, so the items of the `Vertices` and `Volume` lines are
//! printed sorted (the test compares them as sorted lists).
//!
//! `cargo run --release --example cgal_gmap_linear_cell_complex_3`

use std::error::Error;
use std::io::Write;

use gmap::core::{DartId, GMap, Point};

/// A point as CGAL prints it: the three coordinates separated by spaces.
fn show(p: Point) -> String {
    format!("{} {} {}", p[0], p[1], p[2])
}

/// `head` and the points of the vertices of the darts, sorted, each followed by `; `.
fn point_line(g: &GMap, head: &str, darts: impl Iterator<Item = DartId>) -> String {
    let mut items: Vec<String> = darts.filter_map(|d| g.point(d)).map(show).collect();
    items.sort();
    let mut line = head.to_string();
    for item in items {
        line.push_str(&item);
        line.push_str("; ");
    }
    line
}

/// One line per volume: its number (in the order of the volumes' first darts, so the first
/// tetrahedron made is volume 1) and the points of its vertices.
fn volumes(g: &GMap, out: &mut dyn Write) -> std::io::Result<()> {
    for (k, v) in g.one_dart_per_cell(3).enumerate() {
        writeln!(out, "{}", point_line(g, &format!("Volume {} : ", k + 1), g.one_dart_per_incident_cell(v, 3, 0)))?;
    }
    Ok(())
}

/// Runs the example and writes its lines to `out`.
pub fn run(out: &mut dyn Write) -> Result<(), Box<dyn Error>> {
    let mut g = GMap::new(3);
    let d1 = g.try_make_tetrahedron([[-1.0, 0.0, 0.0], [0.0, 2.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 2.0]])?;
    let d2 = g.try_make_tetrahedron([[0.0, 2.0, -1.0], [-1.0, 0.0, -1.0], [1.0, 0.0, -1.0], [1.0, 1.0, -3.0]])?;

    writeln!(out, "{}", point_line(&g, "Vertices: ", g.one_dart_per_cell(0)))?;
    volumes(&g, out)?;

    // the face of d2 takes the place of the face of d1: the points of d1's side stay
    g.try_sew(d1, d2, 3)?;
    volumes(&g, out)?;

    // every vertex of the second tetrahedron, the shared ones included
    g.translate_cell(d2, 3, [3.0, 1.0, 1.0]);
    volumes(&g, out)?;

    writeln!(out, "LCC characteristics: {}", g.characteristics())?;
    Ok(())
}

fn main() -> Result<(), Box<dyn Error>> {
    run(&mut std::io::stdout().lock())
}
