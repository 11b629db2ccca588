//! Homology of random full cubical sets (`.cub`): reading plus homology, as `gmap homology
//! FILE` does it, on 48³ and 96³ boxes at densities 0.25, 0.5 and 0.7 (each cube in the set
//! with that probability, seeded SplitMix64), against GUDHI's CubicalComplex (bitmap +
//! persistence over Z/2, timed in-process by `benches/anchors/gudhi_cubical_file.py`) when
//! `python3 -c "import gudhi"` works; the ratio GUDHI / gmap is printed per input.
//!
//! Inputs are written once to `target/bench-data/cubical{k}_{density}.cub` (under
//! `$CARGO_TARGET_DIR` when set).
//!
//! `cargo bench --bench cubical`

use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

use criterion::{criterion_group, criterion_main, Criterion};
use gmap_homology::cubical::cubical_complex;
use gmap_homology::{homology_z, Homology};
use gmap_ops::rng::SplitMix64;

mod common;

/// The random set `k³` at `percent`%, written when missing.
fn input(k: usize, percent: u64) -> Option<PathBuf> {
    let path = common::bench_data_dir().join(format!("cubical{k}_{percent}.cub"));
    if path.exists() {
        return Some(path);
    }
    let mut rng = SplitMix64::new(1000 * k as u64 + percent);
    let mut text = String::from("; random cubical set\ndimension 3\n");
    for z in 0..k {
        for y in 0..k {
            for x in 0..k {
                if rng.next_u64() % 100 < percent {
                    text.push_str(&format!("({x},{y},{z})\n"));
                }
            }
        }
    }
    std::fs::create_dir_all(path.parent()?).ok()?;
    let tmp = path.with_extension("tmp");
    std::fs::write(&tmp, text).ok()?;
    std::fs::rename(&tmp, &path).ok()?;
    Some(path)
}

/// Reading and homology over Z, as `gmap homology FILE`.
fn run(path: &Path) -> Homology {
    let set = gmap_ops::import::read_cub(path).expect("read");
    let c = cubical_complex(set.shape(), set.bits(), false).expect("complex");
    homology_z(&c.chain).expect("homology")
}

/// GUDHI's seconds and Betti numbers, `None` without python3 and gudhi.
fn gudhi(path: &Path) -> Option<(f64, Vec<u64>)> {
    let out = Command::new("python3").arg(common::anchor("gudhi_cubical_file.py")).arg(path).output().ok()?;
    if !out.status.success() {
        return None;
    }
    let s = String::from_utf8_lossy(&out.stdout);
    let mut it = s.split_whitespace();
    let t = it.next()?.parse().ok()?;
    Some((t, it.filter_map(|x| x.parse().ok()).collect()))
}

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("cubical");
    g.sample_size(10);
    for k in [48, 96] {
        for percent in [25, 50, 70] {
            let Some(path) = input(k, percent) else {
                eprintln!("bench: cannot write the {k}^3 set at {percent}%");
                continue;
            };
            let best = (0..3)
                .map(|_| {
                    let t = Instant::now();
                    let h = run(&path);
                    (t.elapsed().as_secs_f64(), h)
                })
                .min_by(|a, b| a.0.total_cmp(&b.0))
                .unwrap();
            let line = format!("cubical {k}^3 at 0.{percent}: gmap {:.3} s, betti {:?}", best.0, best.1.betti);
            match gudhi(&path) {
                Some((t, b)) => eprintln!("{line}; GUDHI {t:.3} s, betti {b:?}; GUDHI / gmap = {:.2}", t / best.0),
                None => eprintln!("{line}; GUDHI not available"),
            }
            g.bench_function(format!("read+homology {k}^3 at 0.{percent}"), |b| b.iter(|| run(&path)));
        }
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
