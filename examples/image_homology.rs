//! The groups of a binary image (`.npy` or DIPHA `.complex`) by the one-pass route, with the
//! reading and computing stages timed apart and the peak memory; a JSON line on stdout.
//!
//! ```text
//! cargo run --release --example image_homology -- IMAGE.npy [--level T] [--json]
//! ```
//! (the JSON line is always printed; `--json` is accepted for the command line of
//! `gmap homology`).

use std::time::Instant;

use gmap::algebra::cubical::pass::betti_one_pass;
use gmap::ops::import::image::{Image, Level};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut args = std::env::args().skip(1);
    let (mut path, mut level) = (None, Level::Nonzero);
    while let Some(a) = args.next() {
        match a.as_str() {
            "--level" => level = Level::AtMost(args.next().ok_or("--level needs a value")?.parse()?),
            "--json" => {}
            _ => path = Some(a),
        }
    }
    let path = path.ok_or("usage: image_homology IMAGE [--level T] [--json]")?;
    let t0 = Instant::now();
    let img = Image::read(std::path::Path::new(&path))?;
    let read = t0.elapsed().as_secs_f64();
    let t1 = Instant::now();
    let r = betti_one_pass(&img.memory_shape(), |start, out| img.presence(level, start, out))?;
    let pass = t1.elapsed().as_secs_f64();
    println!(
        "{{\"file\": {:?}, \"shape\": {:?}, \"betti\": {:?}, \"cubes\": {}, \"euler_characteristic\": {}, \"read_s\": {:.4}, \"homology_s\": {:.4}, \"peak_rss\": {}}}",
        path,
        img.shape(),
        r.betti,
        r.cubes,
        r.euler_characteristic,
        read,
        pass,
        gmap::core::resources::peak_rss().unwrap_or(0)
    );
    Ok(())
}
