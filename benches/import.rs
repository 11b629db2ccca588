//! Import speed: the Lutz file `S2xpoincare.facets` (3,600 5-simplices, 2,592,000 darts;
//! target < 2 s) and the Freudenthal triangulation of the 40³ grid (384,000 tetrahedra,
//! 9,216,000 darts; target < 3 s), each from its file to a [`gmap_core::DenseMap`].
//!
//! `GMAP_LUTZ` names the folder of the Lutz files (default: the workspace's `tests/data/lutz`);
//! the grid's facets are written by this bench into a temporary folder (the same facets as
//! `benches/anchors/gudhi_grid.py 3 40 --facets`). A missing Lutz file skips that benchmark.

use std::fmt::Write as _;
use std::time::Duration;

use criterion::{criterion_group, criterion_main, Criterion};
use gmap_ops::import::read_facets;

mod common;

/// The Freudenthal (Kuhn) triangulation of a k³ grid of unit cubes: each cube splits into
/// 6 tetrahedra, one per ordering of the axes, walking from its lowest to its highest
/// corner; vertex `(x, y, z)` is labelled `x + (k+1) y + (k+1)² z`.
fn freudenthal_facets(k: usize) -> String {
    let s = k + 1;
    let id = |p: [usize; 3]| p[0] + s * p[1] + s * s * p[2];
    let orders = [[0, 1, 2], [0, 2, 1], [1, 0, 2], [1, 2, 0], [2, 0, 1], [2, 1, 0]];
    let mut out = String::with_capacity(6 * k * k * k * 24);
    for z in 0..k {
        for y in 0..k {
            for x in 0..k {
                for ord in &orders {
                    let mut p = [x, y, z];
                    let _ = write!(out, "{}", id(p));
                    for &a in ord {
                        p[a] += 1;
                        let _ = write!(out, " {}", id(p));
                    }
                    out.push('\n');
                }
            }
        }
    }
    out
}

fn bench_import(c: &mut Criterion) {
    let mut g = c.benchmark_group("import");
    g.sample_size(10).warm_up_time(Duration::from_secs(1)).measurement_time(Duration::from_secs(15));
    let s2p = common::lutz_dir().join("S2xpoincare.facets");
    if s2p.exists() {
        g.bench_function("S2xpoincare", |b| {
            b.iter(|| {
                let m = read_facets(&s2p, None).unwrap();
                assert_eq!(m.dart_count(), 2_592_000);
                m
            })
        });
    } else {
        eprintln!("skipping S2xpoincare: {} not found", s2p.display());
    }
    let dir = tempfile::tempdir().expect("temporary folder");
    let grid = dir.path().join("freud40.facets");
    std::fs::write(&grid, freudenthal_facets(40)).expect("write the grid's facets");
    g.bench_function("freudenthal40", |b| {
        b.iter(|| {
            let m = read_facets(&grid, None).unwrap();
            assert_eq!(m.dart_count(), 9_216_000);
            m
        })
    });
    g.finish();
}

criterion_group!(benches, bench_import);
criterion_main!(benches);
