//! Kernel speed on the 40³ hexahedral grid (3,072,000 darts), to compare side by side with
//! CGAL's Generalized_map (`benches/anchors/run-cgal.sh FILE`):
//! loading the `.gmap` file, counting the cells of every dimension plus the connected
//! components, orientability (BO Def. 7) and validation (BO Def. 1).
//!
//! The grid is read from `$GMAP_GRID` when set, else from `target/bench-data/grid40.gmap`
//! (under `$CARGO_TARGET_DIR` when that is set); a missing file is written first by the
//! library itself (`gmap_ops::build::grid`, `gmap_core::io::write_gmap`). Give CGAL's harness
//! that same file. When the file can be neither read nor written the bench says so and
//! measures nothing.
//!
//! `cargo bench --bench cells`

use criterion::{criterion_group, criterion_main, Criterion};

mod common;

fn bench(c: &mut Criterion) {
    let Some(path) = common::grid_file("GMAP_GRID", 3, 40, false) else {
        eprintln!("cells bench: no grid file, nothing measured");
        return;
    };
    let map = gmap_core::io::read_gmap(&path).expect("read the grid");
    eprintln!("cells bench: {} darts, cells and components {:?}", map.dart_count(), map.cell_counts_and_components());
    let mut g = c.benchmark_group("grid40");
    g.sample_size(10);
    g.bench_function("load", |b| b.iter(|| gmap_core::io::read_gmap(&path).unwrap().dart_count()));
    g.bench_function("cell_counts_and_components", |b| b.iter(|| map.cell_counts_and_components()));
    g.bench_function("is_orientable", |b| b.iter(|| map.is_orientable()));
    g.bench_function("validate", |b| b.iter(|| map.validate().is_ok()));
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
