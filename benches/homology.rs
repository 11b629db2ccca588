//! Homology speed, side by side in one run:
//!
//! * integer homology of the periodic 40³ cube grid (the 3-torus: 512,000 cells,
//!   3,072,000 darts) from the loaded map, by the cellular method (C1/C2 checks, border
//!   operator, reduction) — against GUDHI's Z/2 homology of the Freudenthal triangulation
//!   of the same grid, run in the same sitting by the anchor script
//!   (`python3 benches/anchors/gudhi_grid.py 3 40 --periodic`); the ratio is printed;
//! * the same map by the simplicial counterpart (BO §6), for the ratio simplicial / cellular
//!   (timed once, printed: it is too slow for criterion's repetitions);
//! * `Hom_n9_655_compl_K4` (456,192 darts) by both methods.
//!
//! Inputs: `$GMAP_GRID_PERIODIC` when set, else `target/bench-data/grid40p.gmap` (under
//! `$CARGO_TARGET_DIR` when set), written first by the library's grid builder when missing;
//! and `tests/data/lutz/Hom_n9_655_compl_K4.facets` (folder overridden by `$GMAP_LUTZ`). A
//! missing input is reported and skipped.
//!
//! `cargo bench --bench homology`

use std::process::Command;
use std::time::Instant;

use criterion::{criterion_group, criterion_main, Criterion};
use gmap_core::DenseMap;
use gmap_homology::{cellular_complex, homology_z, homology_zp, simplicial_complex};

mod common;

/// One timed run of each stage, printed before criterion's statistics.
fn stages(name: &str, map: &DenseMap) {
    let t = Instant::now();
    let c = cellular_complex(map).expect("cellular method applies");
    let t_build = t.elapsed();
    let t = Instant::now();
    let h = homology_z(&c.chain).expect("homology");
    let t_red = t.elapsed();
    let t = Instant::now();
    let s = simplicial_complex(map);
    let t_sbuild = t.elapsed();
    let t = Instant::now();
    let hs = homology_z(&s).expect("homology");
    let t_sred = t.elapsed();
    assert_eq!(h, hs, "cellular = simplicial");
    let cell = t_build + t_red;
    let simp = t_sbuild + t_sred;
    eprintln!(
        "homology bench {name}: {h}; cells {:?}: build {t_build:.2?} + reduce {t_red:.2?} = {cell:.2?}; \
         simplices {:?}: build {t_sbuild:.2?} + reduce {t_sred:.2?} = {simp:.2?}; ratio {:.1}x",
        c.chain.counts(),
        s.counts(),
        simp.as_secs_f64() / cell.as_secs_f64()
    );
}

/// GUDHI's Z/2 homology of the Freudenthal triangulation of the periodic 40³ grid, run by
/// the anchor script in this same sitting, three times: the medians `(build seconds,
/// homology seconds)`, or `None` when python3 or gudhi is missing.
fn gudhi_anchor() -> Option<(f64, f64)> {
    let script = common::anchor("gudhi_grid.py");
    let mut build = Vec::new();
    let mut hom = Vec::new();
    for _ in 0..3 {
        let out = Command::new("python3").arg(&script).args(["3", "40", "--periodic"]).output().ok()?;
        if !out.status.success() {
            eprintln!("homology bench: GUDHI anchor failed: {}", String::from_utf8_lossy(&out.stderr).trim());
            return None;
        }
        let v: serde_json::Value = serde_json::from_slice(&out.stdout).ok()?;
        build.push(v["build_s"].as_f64()?);
        hom.push(v["homology_s"].as_f64()?);
    }
    build.sort_by(f64::total_cmp);
    hom.sort_by(f64::total_cmp);
    Some((build[1], hom[1]))
}

/// Median wall time of `runs` calls.
fn median_secs(runs: usize, mut f: impl FnMut()) -> f64 {
    let mut t: Vec<f64> = (0..runs)
        .map(|_| {
            let s = Instant::now();
            f();
            s.elapsed().as_secs_f64()
        })
        .collect();
    t.sort_by(f64::total_cmp);
    t[runs / 2]
}

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("homology");
    g.sample_size(10);
    match common::grid_file("GMAP_GRID_PERIODIC", 3, 40, true).map(|p| gmap_core::io::read_gmap(&p)) {
        Some(Ok(map)) => {
            stages("grid40p", &map);
            let ours = median_secs(11, || {
                homology_z(&cellular_complex(&map).unwrap().chain).unwrap();
            });
            match gudhi_anchor() {
                Some((build, hom)) => eprintln!(
                    "homology bench grid40p: ours (Z, cells from the loaded map, median of 11) {ours:.3} s; \
                     GUDHI Z/2 homology (median of 3) {hom:.3} s (+ {build:.3} s building its simplex tree); GUDHI / ours = {:.1}x \
                     (homology only), {:.1}x (with its build)",
                    hom / ours,
                    (hom + build) / ours
                ),
                None => eprintln!("homology bench grid40p: ours {ours:.3} s; GUDHI anchor not run"),
            }
            g.bench_function("grid40p_cellular_z", |b| {
                b.iter(|| homology_z(&cellular_complex(&map).unwrap().chain).unwrap())
            });
            g.bench_function("grid40p_cellular_z2", |b| {
                b.iter(|| homology_zp(&cellular_complex(&map).unwrap().chain, 2).unwrap())
            });
        }
        Some(Err(e)) => eprintln!("homology bench: cannot read the grid: {e}"),
        None => eprintln!("homology bench: no grid file, grid not measured"),
    }
    let hom = common::lutz_dir().join("Hom_n9_655_compl_K4.facets");
    match gmap_ops::import::read_facets(&hom, None) {
        Ok(map) => {
            stages("Hom_n9_655_compl_K4", &map);
            g.bench_function("hom_n9_cellular_z", |b| {
                b.iter(|| homology_z(&cellular_complex(&map).unwrap().chain).unwrap())
            });
            g.bench_function("hom_n9_simplicial_z", |b| b.iter(|| homology_z(&simplicial_complex(&map)).unwrap()));
        }
        Err(e) => eprintln!("homology bench: {}: {e}", hom.display()),
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
