//! Loads a `.gmap` or `.moka` file and prints what the kernel computes on it, with timings.
//!
//! `cargo run --release -p gmap-core --example load -- FILE` (used to measure load time and
//! peak memory per dart, e.g. under `/usr/bin/time -v`).

use std::time::Instant;

fn main() {
    let Some(path) = std::env::args().nth(1) else {
        eprintln!("usage: load FILE");
        std::process::exit(2);
    };
    let t = Instant::now();
    let res = if path.ends_with(".moka") { gmap_core::io::read_moka(&path) } else { gmap_core::io::read_gmap(&path) };
    let map = match res {
        Ok(m) => m,
        Err(e) => {
            eprintln!("error: {e}");
            std::process::exit(1);
        }
    };
    println!("load (parse + validate): {:.3} s, {} darts", t.elapsed().as_secs_f64(), map.dart_count());
    let t = Instant::now();
    let (counts, comps) = map.cell_counts_and_components();
    println!("cells {:?} components {} : {:.3} s", counts, comps, t.elapsed().as_secs_f64());
    let t = Instant::now();
    let o = map.is_orientable();
    println!("orientable {} : {:.3} s", o, t.elapsed().as_secs_f64());
    let t = Instant::now();
    let v = map.validate().is_ok();
    println!("valid {} : {:.3} s", v, t.elapsed().as_secs_f64());
}
