//! The periodic `K³` cube grid (48 K³ darts, a 3-torus) built in memory, its integer homology
//! by the cellular route, and the map written as `.gmap` when a path is given, for measuring
//! memory per dart (`/usr/bin/time -v`) against `gmap homology FILE.gmap` on the written file:
//! `cargo run --release --example grid_homology -- 130 [/tmp/grid130.gmap]`.
fn main() {
    let args: Vec<String> = std::env::args().collect();
    let Some(k) = args.get(1).and_then(|k| k.parse::<usize>().ok()) else {
        eprintln!("usage: grid_homology K [OUT.gmap]");
        std::process::exit(2);
    };
    let t = std::time::Instant::now();
    let map = gmap_ops::build::grid(&[k; 3], &[true; 3]).unwrap_or_else(|e| {
        eprintln!("error: {e}");
        std::process::exit(1)
    });
    let darts = map.dart_count();
    let base = gmap_core::resources::current_rss().unwrap_or(0);
    eprintln!("built {darts} darts in {:.3?}; resident {:.1} MB", t.elapsed(), base as f64 / 1e6);
    if let Some(out) = args.get(2) {
        let t = std::time::Instant::now();
        gmap_core::io::write_gmap(&map, out).unwrap_or_else(|e| {
            eprintln!("error: {e}");
            std::process::exit(1)
        });
        eprintln!("wrote {out} in {:.3?}", t.elapsed());
    }
    gmap_core::resources::reset_peak_rss();
    let t = std::time::Instant::now();
    let h = gmap_homology::cellular_complex(&map).map(|c| gmap_homology::homology_z(&c.chain));
    let wall = t.elapsed();
    let peak = gmap_core::resources::peak_rss().unwrap_or(0);
    match h {
        Ok(Ok(h)) => println!(
            "{h}: {wall:.3?}; peak {:.1} MB, {:.1} bytes per dart beyond the map's {:.1} MB",
            peak as f64 / 1e6,
            peak.saturating_sub(base) as f64 / darts as f64,
            base as f64 / 1e6
        ),
        Ok(Err(e)) => eprintln!("error: {e}"),
        Err(e) => eprintln!("error: {e}"),
    }
}
