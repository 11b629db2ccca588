//! Shapes built with the construction operations ([`gmap::ops::construct`]) and written to
//! `.vtk` (open them in ParaView):
//!
//! * `torus_surface.vtk`: the boundary of a square revolved about the z axis in 16 steps,
//!   the torus surface, homology (Z, Z², Z);
//! * `solid_torus.vtk`: the square face revolved the same way, the solid torus, homology
//!   (Z, Z, 0, 0);
//! * `extruded.vtk`: a hexagon extruded into a prism, its top face extruded along a bent
//!   path of three edges, the last block cut into tetrahedra: a ball, homology (Z, 0, 0, 0).
//!
//! `cargo run --release --example construct_shapes [FOLDER]` (default: `gmap-construct` in
//! the system's temporary folder). Prints the cells and homology of each shape.

use std::error::Error;
use std::path::PathBuf;

use gmap::algebra::gmap_homology;
use gmap::core::{AlphaSet, DartId, GMap};
use gmap::ops::construct::{self as c, Axis};
use gmap::ops::export;

fn write(g: &GMap, name: &str, folder: &std::path::Path) -> Result<(), Box<dyn Error>> {
    let path = folder.join(name);
    export::write_vtk(&g.to_dense_map(), &path)?;
    println!("{name}: {}, homology {}", g.characteristics(), gmap_homology(g)?);
    Ok(())
}

fn main() -> Result<(), Box<dyn Error>> {
    let folder =
        std::env::args().nth(1).map(PathBuf::from).unwrap_or_else(|| std::env::temp_dir().join("gmap-construct"));
    std::fs::create_dir_all(&folder)?;
    let z = Axis::new([0., 0., 0.], [0., 0., 1.]);
    let square = [[2., 0., 0.], [3., 0., 0.], [3., 0., 1.], [2., 0., 1.]];

    // a loop of four edges in a 2-map, revolved: the torus surface
    let mut torus = GMap::new(2);
    let d = torus.make_polygon(&square);
    c::try_revolve(&mut torus, d, 1, &z, 16)?;
    write(&torus, "torus_surface.vtk", &folder)?;

    // the square face in a 3-map, revolved: the solid torus
    let mut solid = GMap::new(3);
    let d = solid.make_polygon(&square);
    c::try_revolve(&mut solid, d, 2, &z, 16)?;
    write(&solid, "solid_torus.vtk", &folder)?;

    // a hexagonal prism, then its top extruded along a bent path, the last block in tetrahedra
    let mut g = GMap::new(3);
    let hexagon: Vec<[f64; 2]> = (0..6)
        .map(|k| {
            let t = std::f64::consts::TAU * k as f64 / 6.0;
            [t.cos(), t.sin()]
        })
        .collect();
    let base = g.make_polygon(&hexagon);
    let prism = c::try_extrude_face(&mut g, base, [0., 0., 1.])?;
    let corners = [[6., 0., 1.], [6., 0., 2.], [6.5, 0., 3.], [7.5, 0., 3.5]];
    let path: Vec<DartId> = corners.windows(2).map(|w| g.make_segment([w[0], w[1]])).collect();
    let steps = c::try_extrude_cell_along_path(&mut g, prism.top, 2, &path)?;
    let last = steps.last().expect("three steps").cell;
    c::try_tetrahedralize_volume(&mut g, last)?;
    // the path was only read: remove it, and the flat hexagon the prism was swept from
    for d in path {
        let e = g.alpha(d, 0);
        g.remove_dart(d);
        g.remove_dart(e);
    }
    for d in g.orbit(base, AlphaSet::range(0, 1)) {
        g.unlink(d, 3);
        g.remove_dart(d);
    }
    g.reconcile_attributes(&g.darts().collect::<Vec<_>>());
    write(&g, "extruded.vtk", &folder)?;
    println!("written to {}", folder.display());
    Ok(())
}
