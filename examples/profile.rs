//! Stage timings of the cellular and simplicial homology of a map (a profiling aid):
//! `cargo run --release --example profile -- FILE.gmap|FILE.facets|gridK [simplicial]`
//! (`gridK`: the periodic `K³` cube grid, built in memory).
//! Times are CPU times of the main thread, except the two-thread precondition checks, the
//! border and the pipeline (wall).
use std::time::{Duration, Instant as WallInstant};

/// CPU time of the calling thread (from /proc/thread-self/schedstat), so timings hold on a
/// busy machine.
#[derive(Clone, Copy)]
struct Instant(u64);

impl Instant {
    fn now() -> Self {
        let s = std::fs::read_to_string(std::path::Path::new("/proc").join("thread-self").join("schedstat"))
            .unwrap_or_default();
        Instant(s.split_whitespace().next().and_then(|x| x.parse().ok()).unwrap_or(0))
    }
    fn elapsed(&self) -> Duration {
        Duration::from_nanos(Instant::now().0 - self.0)
    }
}

use gmap_homology::border::border_from_oriented;
use gmap_homology::precond::{check_c2, oriented_cells};
use gmap_homology::{homology_z, homology_zp, simplicial_complex};

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let path = std::path::Path::new(&args[1]);
    let t = Instant::now();
    let grid = args[1].strip_prefix("grid").and_then(|k| k.parse::<usize>().ok());
    let map = if let Some(k) = grid {
        gmap_ops::build::grid(&[k; 3], &[true; 3]).unwrap()
    } else if path.extension().is_some_and(|e| e == "facets") {
        gmap_ops::import::read_facets(path, None).unwrap()
    } else {
        gmap_core::io::read_gmap(path).unwrap()
    };
    eprintln!("load {:.3?} ({} darts)", t.elapsed(), map.dart_count());
    let t0 = Instant::now();
    let mut oriented = Vec::new();
    for i in 0..=map.dim() {
        let t = Instant::now();
        let c = oriented_cells(&map, i).unwrap();
        let t1 = t.elapsed();
        let t = Instant::now();
        check_c2(&map, &c).unwrap();
        eprintln!("cells {i}: {} oriented {t1:.3?} c2 {:.3?}", c.cells.len(), t.elapsed());
        oriented.push(c);
    }
    let t = WallInstant::now();
    let oriented2 = gmap_homology::check_by_dimension(&map).unwrap();
    eprintln!("check_by_dimension (two threads) {:.3?}", t.elapsed());
    drop(oriented2);
    let t = WallInstant::now();
    let oriented2 = gmap_homology::check_preconditions(&map).unwrap();
    eprintln!("check_preconditions (ring walks for 3-maps, two threads) {:.3?}", t.elapsed());
    drop(oriented2);
    let t = WallInstant::now();
    let c = border_from_oriented(&map, &oriented);
    eprintln!("border {:.3?}; build total {:.3?}", t.elapsed(), t0.elapsed());
    let t = Instant::now();
    let h = homology_z(&c.chain).unwrap();
    eprintln!("homology_z {:.3?}: {h}", t.elapsed());
    let t = Instant::now();
    let h = homology_zp(&c.chain, 2).unwrap();
    eprintln!("homology_z2 {:.3?}: {h}", t.elapsed());
    // with GMAP_THREADS=1 the CPU time of the main thread is that of the whole pipeline
    for _ in 0..3 {
        let t = WallInstant::now();
        let cpu = Instant::now();
        let c = gmap_homology::cellular_complex(&map).unwrap();
        let t1 = t.elapsed();
        let h = homology_z(&c.chain).unwrap();
        let (wall, cpu) = (t.elapsed(), cpu.elapsed());
        let per_dart = cpu.as_secs_f64() * 1e9 / map.dart_count() as f64;
        eprintln!(
            "pipeline wall: cells+border {t1:.3?}, total {wall:.3?}; main-thread CPU {cpu:.3?} ({per_dart:.1} ns/dart): {h}"
        );
    }
    if args.get(2).is_some_and(|a| a == "simplicial") {
        let t = Instant::now();
        let s = simplicial_complex(&map);
        eprintln!("simplicial build {:.3?} {:?}", t.elapsed(), s.counts());
        let t = Instant::now();
        let h = homology_z(&s).unwrap();
        eprintln!("simplicial homology_z {:.3?}: {h}", t.elapsed());
    }
}
