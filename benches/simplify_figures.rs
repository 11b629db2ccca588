//! Figures of the simplification, printed rather than timed by criterion (docs/SIMPLIFY.md
//! holds them): darts and cells before and after, the ratio, the time and whether the reduced
//! map gives the homology stated in the file.
//!
//! `cargo bench --bench simplify_figures` runs the three measurements; name some of them to
//! run only those (`cargo bench --bench simplify_figures -- lutz tries`):
//!
//! * `lutz`: the Lutz files of `GMAP_MEASURE` (names without `.facets`, space-separated;
//!   default: a sample of ten), from `tests/data/lutz` or `$GMAP_LUTZ`;
//! * `grid`: the k³ grid, periodic and not (`GMAP_MEASURE_GRID` sets k, default 40),
//!   simplified then reduced against reduced directly;
//! * `tries`: greedy runs and search rounds against the result for one file
//!   (`GMAP_MEASURE_ONE`, default `triple_trefoil_arc`; `GMAP_SEED`).

use std::time::Instant;

use gmap_homology::{cellular_complex, homology_z};
use gmap_ops::build::grid;
use gmap_ops::euler::{simplify, simplify_with, SimplifyOptions};
use gmap_ops::import::simplicial::read_facets;

mod common;

fn read_lutz(name: &str) -> gmap_core::DenseMap {
    let path = common::lutz_dir().join(format!("{name}.facets"));
    read_facets(&path, None).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

fn lutz_figures() {
    let names = std::env::var("GMAP_MEASURE").unwrap_or_else(|_| {
        "600_cell poincare Hom_C5_K4 K3_16 CP2 RP4 S_3_1000_2990 nc_sphere Barnette_sphere rudin".into()
    });
    for name in names.split_whitespace() {
        let map = read_lutz(name);
        let t = Instant::now();
        let (small, r) = simplify(&map);
        let dt = t.elapsed();
        let h = cellular_complex(&small).map(|c| homology_z(&c.chain).expect("homology").to_string());
        println!(
            "{name}: {} -> {} darts ({:.2} %), cells {:?} -> {:?}, rounds {}, search {} rounds \
             (-{} darts), {:.1} ms, homology {:?}",
            r.darts_before,
            r.darts_after,
            100.0 * r.ratio(),
            r.cells_before,
            r.cells_after,
            r.rounds,
            r.search_rounds,
            r.search_gain,
            dt.as_secs_f64() * 1e3,
            h
        );
    }
}

fn grid_figures() {
    let k: usize = std::env::var("GMAP_MEASURE_GRID").ok().and_then(|s| s.parse().ok()).unwrap_or(40);
    for periodic in [true, false] {
        let map = grid(&[k, k, k], &[periodic; 3]).expect("grid");
        let t = Instant::now();
        let (small, r) = simplify(&map);
        let ts = t.elapsed().as_secs_f64();
        let t = Instant::now();
        let h = homology_z(&cellular_complex(&small).expect("C1/C2").chain).expect("homology");
        let th = t.elapsed().as_secs_f64();
        let t = Instant::now();
        let hd = homology_z(&cellular_complex(&map).expect("C1/C2").chain).expect("homology");
        let td = t.elapsed().as_secs_f64();
        println!(
            "grid {k}^3 periodic {periodic}: {} -> {} darts ({:.2} %), cells {:?}, simplify {:.1} ms, \
             homology after {:.1} ms, direct {:.1} ms, ratio (simplify+homology)/direct {:.3}",
            r.darts_before,
            r.darts_after,
            100.0 * r.ratio(),
            r.cells_after,
            ts * 1e3,
            th * 1e3,
            td * 1e3,
            (ts + th) / td
        );
        assert_eq!(h.betti, hd.betti);
    }
}

fn tries_figures() {
    let name = std::env::var("GMAP_MEASURE_ONE").unwrap_or_else(|_| "triple_trefoil_arc".into());
    let map = read_lutz(&name);
    let seed =
        std::env::var("GMAP_SEED").ok().and_then(|s| s.parse().ok()).unwrap_or(SimplifyOptions::for_map(&map).seed);
    for (tries, search) in [(8, 0), (32, 0), (128, 0), (512, 0), (8, 500), (8, 1000), (8, 2000), (8, 4000)] {
        let t = Instant::now();
        let (small, r) = simplify_with(&map, &SimplifyOptions { tries, search, seed });
        println!(
            "{name} tries {tries} search {search}: {} darts ({:.2} %), cells {:?}, {:.1} ms",
            small.dart_count(),
            100.0 * r.ratio(),
            r.cells_after,
            t.elapsed().as_secs_f64() * 1e3
        );
    }
}

fn main() {
    // cargo passes `--bench` (and criterion-style flags); the words are the measurements
    let asked: Vec<String> = std::env::args().skip(1).filter(|a| !a.starts_with('-')).collect();
    let runs: [(&str, fn()); 3] = [("lutz", lutz_figures), ("grid", grid_figures), ("tries", tries_figures)];
    if let Some(bad) = asked.iter().find(|a| !runs.iter().any(|(n, _)| n == a)) {
        eprintln!("simplify_figures: no measurement {bad:?} (lutz, grid, tries)");
        std::process::exit(2);
    }
    for (name, run) in runs {
        if asked.is_empty() || asked.iter().any(|a| a == name) {
            run();
        }
    }
}
