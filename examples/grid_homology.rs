//! The periodic `K³` cube grid (48 K³ darts, a 3-torus) built in memory, or a `.gmap` file
//! read, and its integer homology by the cellular route, stage by stage: for each stage the
//! wall time, the CPU time of every thread, how evenly the threads of the stages' pool
//! shared it, and the peak resident memory beyond the map's own storage (the high-water
//! mark is reset between stages, `gmap_core::resources::reset_peak_rss`).
//!
//! `cargo run --release --example grid_homology -- 130 [/tmp/grid130.gmap]` builds the grid
//! (and writes it when a path is given); `… -- --read /tmp/grid130.gmap` reads the file
//! instead, the reading being the first stage.
use std::time::{Duration, Instant};

use gmap_core::resources::{current_rss, peak_rss, reset_peak_rss};

/// CPU seconds (user + system) of each thread, by thread name.
type ThreadCpu = Vec<(String, f64)>;

/// CPU seconds (user + system) of each thread of this process, by thread name.
fn thread_cpu() -> ThreadCpu {
    let mut out = Vec::new();
    let Ok(dir) = std::fs::read_dir("/proc/self/task") else { return out };
    for t in dir.flatten() {
        let Ok(stat) = std::fs::read_to_string(t.path().join("stat")) else { continue };
        // the name is in parentheses and may hold spaces: the fields follow the last ')'
        let (Some(open), Some(close)) = (stat.find('('), stat.rfind(')')) else { continue };
        let name = stat[open + 1..close].to_string();
        let f: Vec<&str> = stat[close + 2..].split(' ').collect();
        let ticks = |i: usize| f.get(i).and_then(|x| x.parse::<f64>().ok()).unwrap_or(0.0);
        // fields 14 and 15 of stat (utime, stime) are 11 and 12 after the name
        out.push((name, (ticks(11) + ticks(12)) / 100.0));
    }
    out
}

/// The stages of one pipeline, measured against the map's resident size `base`: each
/// [`Stages::start`] closes the stage open (and reports it) and opens the next.
struct Stages {
    base: u64,
    darts: usize,
    worst: u64,
    /// the stage open: its name, the threads' CPU and the time at its start
    open: Option<(&'static str, ThreadCpu, Instant)>,
}

impl Stages {
    fn start(&mut self, name: &'static str) {
        self.finish();
        reset_peak_rss();
        self.open = Some((name, thread_cpu(), Instant::now()));
    }

    fn finish(&mut self) {
        let Some((name, before, t)) = self.open.take() else { return };
        let wall = t.elapsed();
        let peak = peak_rss().unwrap_or(0);
        let beyond = peak.saturating_sub(self.base);
        self.worst = self.worst.max(beyond);
        eprintln!(
            "{name}: wall {wall:.2?}, {}; peak beyond the map {:.1} MB, {:.1} bytes per dart",
            cpu_since(&before),
            beyond as f64 / 1e6,
            beyond as f64 / self.darts.max(1) as f64
        );
    }
}

/// The CPU time of each thread since `before`, their sum, and how evenly the threads of the
/// stages' pool shared it: their sum over (threads × the busiest one's), or "serial".
fn cpu_since(before: &[(String, f64)]) -> String {
    let used: Vec<(String, f64)> = thread_cpu()
        .into_iter()
        .map(|(n, c)| {
            let b = before.iter().find(|(m, _)| *m == n).map_or(0.0, |b| b.1);
            (n, c - b)
        })
        .collect();
    let total: f64 = used.iter().map(|u| u.1).sum();
    let pool: Vec<f64> = used.iter().filter(|u| u.0.starts_with("gmap-")).map(|u| u.1).collect();
    let busiest = pool.iter().copied().fold(0.0, f64::max);
    let spread = if busiest > 0.0 {
        let share = 100.0 * pool.iter().sum::<f64>() / (pool.len() as f64 * busiest);
        format!("{share:.0}% over {} pool threads", pool.len())
    } else {
        "serial".to_string()
    };
    let threads: Vec<String> = used.iter().filter(|u| u.1 > 0.0).map(|u| format!("{} {:.2}", u.0, u.1)).collect();
    format!("CPU {total:.2} s ({}; {spread})", threads.join(", "))
}

fn fail(e: impl std::fmt::Display) -> ! {
    eprintln!("error: {e}");
    std::process::exit(1)
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let start = Instant::now();
    let map = match (args.get(1).map(String::as_str), args.get(2)) {
        (Some("--read"), Some(path)) => {
            reset_peak_rss();
            let (before, t) = (thread_cpu(), Instant::now());
            let map = gmap_core::io::read_gmap(path).unwrap_or_else(|e| fail(e));
            let beyond = peak_rss().unwrap_or(0).saturating_sub(current_rss().unwrap_or(0));
            eprintln!(
                "read: wall {:.2?}, {}; peak beyond the map read {:.1} MB, {:.1} bytes per dart",
                t.elapsed(),
                cpu_since(&before),
                beyond as f64 / 1e6,
                beyond as f64 / map.dart_count().max(1) as f64
            );
            map
        }
        (Some(k), _) if k.parse::<usize>().is_ok() => {
            let k: usize = k.parse().unwrap_or(0);
            let map = gmap_ops::build::grid(&[k; 3], &[true; 3]).unwrap_or_else(|e| fail(e));
            if let Some(out) = args.get(2) {
                let t = Instant::now();
                gmap_core::io::write_gmap(&map, out).unwrap_or_else(|e| fail(e));
                eprintln!("wrote {out} in {:.3?}", t.elapsed());
            }
            map
        }
        _ => {
            eprintln!("usage: grid_homology K [OUT.gmap] | grid_homology --read FILE.gmap");
            std::process::exit(2);
        }
    };
    let darts = map.dart_count();
    let base = current_rss().unwrap_or(0);
    eprintln!(
        "{darts} darts after {:.3?}; the map's storage {:.1} MB ({:.1} bytes per dart), resident {:.1} MB",
        start.elapsed(),
        (map.flat().len() * 4) as f64 / 1e6,
        (map.flat().len() * 4) as f64 / darts as f64,
        base as f64 / 1e6
    );
    let mut s = Stages { base, darts, worst: 0, open: None };
    let t = Instant::now();
    let c = gmap_homology::cellular::checked::cellular_complex_staged(&map, &mut |name| s.start(name))
        .unwrap_or_else(|e| fail(e));
    s.start("reduction");
    let h = gmap_homology::homology_z(&c.chain).unwrap_or_else(|e| fail(e));
    s.finish();
    let wall: Duration = t.elapsed();
    println!(
        "{h}: {wall:.3?}; peak {:.1} bytes per dart beyond the map's resident {:.1} MB",
        s.worst as f64 / darts as f64,
        base as f64 / 1e6
    );
}
