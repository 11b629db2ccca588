//! `simplify`: homology of the 3-torus grid (and a Lutz 3-manifold) computed directly by
//! the cellular method against simplify-then-cellular.
//!
//! Run with `cargo bench --bench simplify`; `GMAP_BENCH_GRID=40` (default 20) sets the grid
//! size k of the k³ periodic hexahedral grid (6·8·k³ darts).

use criterion::{criterion_group, criterion_main, Criterion};
use gmap_homology::{cellular_complex, homology_z};
use gmap_ops::build::grid;
use gmap_ops::euler::simplify;
use gmap_ops::import::simplicial::read_facets;

fn direct(map: &gmap_core::DenseMap) -> Vec<usize> {
    let c = cellular_complex(map).expect("C1/C2");
    homology_z(&c.chain).expect("homology").betti
}

fn reduced(map: &gmap_core::DenseMap) -> Vec<usize> {
    let (small, _) = simplify(map);
    direct(&small)
}

fn bench(c: &mut Criterion) {
    let k: usize = std::env::var("GMAP_BENCH_GRID").ok().and_then(|s| s.parse().ok()).unwrap_or(20);
    let torus = grid(&[k, k, k], &[true; 3]).expect("grid");
    let (small, report) = simplify(&torus);
    eprintln!(
        "simplify: {k}^3 torus grid {} darts -> {} darts ({:.2} %), cells {:?} -> {:?}",
        report.darts_before,
        report.darts_after,
        100.0 * report.ratio(),
        report.cells_before,
        report.cells_after
    );
    assert_eq!(direct(&small), vec![1, 3, 3, 1]);
    let mut g = c.benchmark_group("simplify");
    g.sample_size(10);
    g.bench_function(format!("torus{k}/direct_cellular"), |b| b.iter(|| direct(&torus)));
    g.bench_function(format!("torus{k}/simplify_then_cellular"), |b| b.iter(|| reduced(&torus)));
    g.bench_function(format!("torus{k}/simplify_only"), |b| b.iter(|| simplify(&torus)));
    let lutz = std::path::Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../shared/data/lutz/S_3_100_4850.facets"));
    if let Ok(m) = read_facets(lutz, None) {
        g.bench_function("S_3_100_4850/direct_cellular", |b| b.iter(|| direct(&m)));
        g.bench_function("S_3_100_4850/simplify_then_cellular", |b| b.iter(|| reduced(&m)));
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
