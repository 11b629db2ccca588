//! Figures of the simplification (run by hand): `cargo test --release --test simplify_measure
//! -- --ignored --nocapture` prints darts and cells before and after, the ratio, the time and
//! whether the reduced map gives the homology stated in the file.

use std::path::{Path, PathBuf};
use std::time::Instant;

use gmap_homology::{cellular_complex, homology_z};
use gmap_ops::build::grid;
use gmap_ops::euler::simplify;
use gmap_ops::import::simplicial::read_facets;

fn lutz(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/lutz").join(name)
}

#[test]
#[ignore = "prints figures; run by hand in release"]
fn lutz_figures() {
    let names = std::env::var("GMAP_MEASURE").unwrap_or_else(|_| {
        "600_cell poincare Hom_C5_K4 K3_16 CP2 RP4 S_3_1000_2990 nc_sphere Barnette_sphere rudin".into()
    });
    for name in names.split_whitespace() {
        let map = read_facets(&lutz(&format!("{name}.facets")), None).expect("facets");
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

#[test]
#[ignore = "prints figures; run by hand in release"]
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

/// Greedy runs and search rounds against the result (`GMAP_MEASURE_ONE`, default
/// `triple_trefoil_arc`; `GMAP_SEED`). The figures measured are in docs/SIMPLIFY.md.
#[test]
#[ignore = "prints figures; run by hand in release"]
fn tries_figures() {
    use gmap_ops::euler::{simplify_with, SimplifyOptions};
    let name = std::env::var("GMAP_MEASURE_ONE").unwrap_or_else(|_| "triple_trefoil_arc".into());
    let map = read_facets(&lutz(&format!("{name}.facets")), None).expect("facets");
    for (tries, search) in [(8, 0), (32, 0), (128, 0), (512, 0), (8, 500), (8, 1000), (8, 2000), (8, 4000)] {
        let t = Instant::now();
        let (small, r) = simplify_with(
            &map,
            &SimplifyOptions {
                tries,
                search,
                seed: std::env::var("GMAP_SEED")
                    .ok()
                    .and_then(|s| s.parse().ok())
                    .unwrap_or(SimplifyOptions::for_map(&map).seed),
            },
        );
        println!(
            "{name} tries {tries} search {search}: {} darts ({:.2} %), cells {:?}, {:.1} ms",
            small.dart_count(),
            100.0 * r.ratio(),
            r.cells_after,
            t.elapsed().as_secs_f64() * 1e3
        );
    }
}
