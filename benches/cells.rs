//! Kernel speed on the 40³ hexahedral grid (3,072,000 darts), to compare side by side with
//! CGAL's Generalized_map (`../shared/anchors/run-cgal.sh FILE`):
//! loading the `.gmap` file, counting the cells of every dimension plus the connected
//! components, orientability (BO Def. 7) and validation (BO Def. 1).
//!
//! The grid is read from `$GMAP_GRID` (default `/work/grid40.gmap`); when missing it is made
//! with `python3 ../shared/anchors/gmapgen.py cubegrid 3 40`. Without the file or the script
//! the bench says so and measures nothing.
//!
//! `cargo bench --bench cells`

use std::path::{Path, PathBuf};
use std::process::Command;

use criterion::{criterion_group, criterion_main, Criterion};

fn grid_path() -> Option<PathBuf> {
    let path = PathBuf::from(std::env::var("GMAP_GRID").unwrap_or_else(|_| "/work/grid40.gmap".into()));
    if path.exists() {
        return Some(path);
    }
    let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/anchors/gmapgen.py");
    eprintln!("cells bench: generating {} with {}", path.display(), script.display());
    let out = Command::new("python3").arg(&script).args(["cubegrid", "3", "40"]).output().ok()?;
    if !out.status.success() {
        eprintln!("cells bench: generator failed: {}", String::from_utf8_lossy(&out.stderr));
        return None;
    }
    std::fs::write(&path, out.stdout).ok()?;
    Some(path)
}

fn bench(c: &mut Criterion) {
    let Some(path) = grid_path() else {
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
