//! Pages to look at in a browser: `examples/building.rs`'s building (rooms coloured by their
//! names) and a torus of revolution with its two H1 generators, written as self-contained
//! HTML files (`gmap_ops::export::html`) to a folder.
//!
//! `cargo run --release --example view [FOLDER]` (default: `gmap-view` in the system's
//! temporary folder), then open `FOLDER/building.html` or `FOLDER/torus.html`. An address
//! ending in `#view=cells&explode=35` opens the cells view with the rooms pushed apart.

#[path = "building.rs"]
#[allow(dead_code)]
mod building;

use std::error::Error;
use std::path::PathBuf;

use gmap::algebra::{cellular_complex, generators::generators};
use gmap::core::to_dense_labels;
use gmap::ops::export::html::{write_html, HtmlOptions, Scene, ViewGenerator};

fn main() -> Result<(), Box<dyn Error>> {
    let dir = std::env::args_os().nth(1).map(PathBuf::from).unwrap_or_else(|| std::env::temp_dir().join("gmap-view"));
    std::fs::create_dir_all(&dir)?;

    let g = building::building()?;
    let (m, labels, _) = to_dense_labels(&g);
    let scene = Scene::from_map(&m, Some(&labels), "building (examples/building.rs)");
    write_html(&scene, &HtmlOptions::default(), &dir.join("building.html"))?;

    // the torus and its H1 generators, their cells renumbered as the map's 1-cells
    let t = gmap::ops::build::placed::torus_with_points(24, 12, 2.0, 0.8)?;
    let c = cellular_complex(&t)?;
    let edges = t.cells(1);
    let mut scene = Scene::from_map(&t, None, "torus of 24 × 12 squares");
    for (k, x) in generators(&c.chain, None)?.iter().filter(|x| x.dim == 1).enumerate() {
        let cells = x.chain.iter().map(|&(j, _)| edges.of[c.reps[1][j as usize].index()]).collect();
        scene.add_generator(ViewGenerator { name: format!("H1 #{k} (Z)"), dim: 1, cells })?;
    }
    write_html(&scene, &HtmlOptions::default(), &dir.join("torus.html"))?;
    println!("wrote building.html and torus.html in {}", dir.display());
    Ok(())
}
