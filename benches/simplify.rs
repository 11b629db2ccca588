//! `simplify`: integral homology computed directly by the cellular method (BO Def. 9–10 on
//! every cell of the input) against simplify-then-cellular (removals and contractions of
//! cells first, `gmap_ops::euler::simplify`, then the cellular method on the reduced map),
//! and the reduction alone.
//!
//! Inputs: the k³ periodic hexahedral grid (a 3-torus, 48·k³ darts, reduced to 48 darts:
//! one vertex, three edges, three faces, one volume) and the Lutz 3-sphere `S_3_100_4850`
//! (116,400 darts, reduced to 4; from `tests/data/lutz`, or `$GMAP_LUTZ`). Before the measurements the bench prints the darts and
//! cells before and after each reduction.
//!
//! Run with `cargo bench --bench simplify`; `GMAP_BENCH_GRID=40` (default 20) sets k (the
//! 40³ grid has 3,072,000 darts). The ratio of `simplify_then_cellular` to
//! `direct_cellular` is the speed-up (below 1) or slow-down (above 1) that simplification
//! brings to a homology computation; `simplify_only` shows how much of it is the reduction.

use criterion::{criterion_group, criterion_main, Criterion};
use gmap_homology::{cellular_complex, homology_z};
use gmap_ops::build::grid;
use gmap_ops::euler::simplify;
use gmap_ops::import::simplicial::read_facets;

mod common;

fn direct(map: &gmap_core::DenseMap) -> Vec<usize> {
    let c = cellular_complex(map).expect("C1/C2");
    homology_z(&c.chain).expect("homology").betti
}

fn reduced(map: &gmap_core::DenseMap) -> Vec<usize> {
    let (small, _) = simplify(map);
    direct(&small)
}

fn describe(name: &str, map: &gmap_core::DenseMap) {
    let (small, report) = simplify(map);
    eprintln!(
        "simplify: {name} {} darts -> {} darts ({:.3} %), cells {:?} -> {:?}, betti {:?}",
        report.darts_before,
        report.darts_after,
        100.0 * report.ratio(),
        report.cells_before,
        report.cells_after,
        direct(&small)
    );
}

fn bench(c: &mut Criterion) {
    let k: usize = std::env::var("GMAP_BENCH_GRID").ok().and_then(|s| s.parse().ok()).unwrap_or(20);
    let torus = grid(&[k, k, k], &[true; 3]).expect("grid");
    describe(&format!("{k}^3 torus grid"), &torus);
    assert_eq!(reduced(&torus), vec![1, 3, 3, 1]);
    let mut g = c.benchmark_group("simplify");
    g.sample_size(10);
    g.bench_function(format!("torus{k}/direct_cellular"), |b| b.iter(|| direct(&torus)));
    g.bench_function(format!("torus{k}/simplify_then_cellular"), |b| b.iter(|| reduced(&torus)));
    g.bench_function(format!("torus{k}/simplify_only"), |b| b.iter(|| simplify(&torus)));
    let lutz = common::lutz_dir().join("S_3_100_4850.facets");
    if let Ok(m) = read_facets(&lutz, None) {
        describe("S_3_100_4850", &m);
        g.bench_function("S_3_100_4850/direct_cellular", |b| b.iter(|| direct(&m)));
        g.bench_function("S_3_100_4850/simplify_then_cellular", |b| b.iter(|| reduced(&m)));
        g.bench_function("S_3_100_4850/simplify_only", |b| b.iter(|| simplify(&m)));
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
