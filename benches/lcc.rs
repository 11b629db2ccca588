//! The 40³ hexahedral grid built the way a modelling kernel builds it, to compare side by
//! side with CGAL's `Linear_cell_complex_for_generalized_map<3>`
//! (`benches/anchors/cgal_lcc_grid.cpp`, the same steps): each of the 64,000 hexahedra made
//! on its own from its eight corners ([`GMap::make_hexahedron`], CGAL's `make_hexahedron`),
//! then every pair of neighbours 3-sewn (187,200 sews). Three variants:
//!
//! * `no_attributes`: combinatorial hexahedra in a `GMap`
//!   ([`GMap::make_combinatorial_hexahedron`]);
//! * `points`: hexahedra with their eight corner points (the sews merge the points that
//!   meet: 512,000 points made, 68,921 left);
//! * `points_and_labels`: the same with an integer label on every volume;
//! * `sew3_same_facets`: the hexahedra with points left unsewn, then
//!   [`build::sew3_same_facets`] finds the faces to sew by their points (CGAL's
//!   `sew3_same_facets`).
//!
//! Before the Criterion groups, each variant is timed (best of 5 interleaved rounds, building
//! and sewing apart) and, when CGAL's headers and g++ are installed, CGAL's harness is run in
//! the same sitting (`benches/anchors/run-cgal-lcc.sh 40 5`, best of 5 too); the ratios
//! ours / CGAL's are printed. Then each variant is built once more in a fresh process on
//! both sides (this bench with `LCC_ONLY=k`, the harness with the variant's name) for its
//! peak resident memory.
//!
//! `cargo bench --bench lcc`

use std::collections::VecDeque;
use std::process::Command;
use std::time::Instant;

use criterion::{criterion_group, criterion_main, Criterion};
use gmap_core::{Attributes, Cells, DartId, GMap};
use gmap_ops::build;

mod common;

const K: usize = 40;

/// A map whose volumes carry an integer label.
type Labelled = GMap<((), (), (), Cells<u32>)>;

/// A path of alpha indices from the dart a constructor returns to another dart of the same
/// hexahedron. Every hexahedron is laid out the same way, so a path found once on a
/// prototype (from its geometry) names the same dart in every hexahedron.
type Path = Vec<usize>;

/// CGAL's `make_hexahedron` order of the unit cube's corners (bits x, y, z): the bottom
/// face counterclockwise, then the top corners above p3, p0, p1, p2.
const CORNER_OF_ARG: [usize; 8] = [0b000, 0b001, 0b011, 0b010, 0b110, 0b100, 0b101, 0b111];

/// Makes the hexahedron `[x, x+1] × [y, y+1] × [z, z+1]` with its eight corner points, as
/// CGAL's harness does: 48 new darts, 8 new vertex points. Returns the dart
/// [`GMap::make_hexahedron`] returns.
fn hexahedron_at<A: Attributes>(g: &mut GMap<A>, at: [f64; 3]) -> DartId {
    let p =
        CORNER_OF_ARG.map(|c| [at[0] + (c & 1) as f64, at[1] + ((c >> 1) & 1) as f64, at[2] + ((c >> 2) & 1) as f64]);
    g.make_hexahedron(p)
}

/// For each axis, the paths to the darts of a hexahedron's upper face (coordinate 1 on the
/// axis) and lower face (coordinate 0) that meet when two neighbours along the axis are
/// 3-sewn: on the corner at the origin of the face, on its edge along the next axis.
struct SewPaths {
    upper: [Path; 3],
    lower: [Path; 3],
}

fn sew_paths() -> SewPaths {
    let mut proto = GMap::new(3);
    let d0 = hexahedron_at(&mut proto, [0.; 3]);
    // shortest alpha path from d0 to every dart of the hexahedron, breadth first
    let mut paths: Vec<(DartId, Path)> = vec![(d0, Vec::new())];
    let mut todo = VecDeque::from([0usize]);
    while let Some(k) = todo.pop_front() {
        let (d, path) = paths[k].clone();
        for i in 0..=2 {
            let e = proto.alpha(d, i);
            if paths.iter().all(|(x, _)| *x != e) {
                let mut p = path.clone();
                p.push(i);
                paths.push((e, p));
                todo.push_back(paths.len() - 1);
            }
        }
    }
    let point = |d: DartId| proto.point(d).expect("every corner has a point");
    let find = |axis: usize, side: f64| -> Path {
        let (next, third) = ((axis + 1) % 3, (axis + 2) % 3);
        let hit = paths.iter().find(|(d, _)| {
            let (a, b) = (point(*d), point(proto.alpha(*d, 0)));
            let c = point(proto.alpha_word(*d, &[0, 1, 0]));
            a[axis] == side
                && a[next] == 0.
                && a[third] == 0.
                && b[axis] == side
                && b[next] == 1.
                && b[third] == 0.
                && c[axis] == side
        });
        hit.map(|(_, p)| p.clone()).expect("a hexahedron has a dart on every corner, edge and face")
    };
    SewPaths { upper: [0, 1, 2].map(|a| find(a, 1.)), lower: [0, 1, 2].map(|a| find(a, 0.)) }
}

/// The CPU time of the calling thread in seconds, from `/proc/thread-self/schedstat` (its
/// first field, nanoseconds on a CPU); `None` where that file does not exist. CGAL's
/// harness reads the same clock (`CLOCK_THREAD_CPUTIME_ID`).
fn thread_cpu() -> Option<f64> {
    let text = std::fs::read_to_string("/proc/thread-self/schedstat").ok()?;
    let ns: f64 = text.split_whitespace().next()?.parse().ok()?;
    Some(ns * 1e-9)
}

/// Seconds spent building and sewing one grid: `(build, sew)` in wall-clock time, and in
/// the thread's CPU time when it can be read (on a shared machine the time spent waiting
/// for a core is in the first and not in the second).
#[derive(Clone, Copy)]
struct Times {
    wall: (f64, f64),
    cpu: Option<(f64, f64)>,
}

/// Makes the `K³` hexahedra with `make` (given the cell's position and number), then 3-sews
/// every pair of neighbours. Returns the map and the time spent building and sewing.
fn grid<A: Attributes>(
    paths: &SewPaths,
    mut make: impl FnMut(&mut GMap<A>, [usize; 3], u32) -> DartId,
) -> (GMap<A>, Times) {
    let mut g = GMap::with_attributes(3);
    let c0 = thread_cpu();
    let t0 = Instant::now();
    let mut hex = Vec::with_capacity(K * K * K);
    for z in 0..K {
        for y in 0..K {
            for x in 0..K {
                let label = hex.len() as u32;
                hex.push(make(&mut g, [x, y, z], label));
            }
        }
    }
    let built = t0.elapsed().as_secs_f64();
    let c1 = thread_cpu();
    let t1 = Instant::now();
    let step = [1, K, K * K];
    for z in 0..K {
        for y in 0..K {
            for x in 0..K {
                let i = (z * K + y) * K + x;
                for (axis, c) in [x, y, z].into_iter().enumerate() {
                    if c + 1 < K {
                        let a = g.alpha_word(hex[i], &paths.upper[axis]);
                        let b = g.alpha_word(hex[i + step[axis]], &paths.lower[axis]);
                        g.sew(a, b, 3);
                    }
                }
            }
        }
    }
    let sewn = t1.elapsed().as_secs_f64();
    let c2 = thread_cpu();
    let cpu = c0.zip(c1).zip(c2).map(|((c0, c1), c2)| (c1 - c0, c2 - c1));
    (g, Times { wall: (built, sewn), cpu })
}

/// The sew paths, the same for every hexahedron.
struct Setup {
    paths: SewPaths,
}

fn plain(s: &Setup) -> (GMap, Times) {
    grid(&s.paths, |g, _, _| g.make_combinatorial_hexahedron())
}

fn with_points(s: &Setup) -> (GMap, Times) {
    grid(&s.paths, |g, [x, y, z], _| hexahedron_at(g, [x as f64, y as f64, z as f64]))
}

fn with_labels(s: &Setup) -> (Labelled, Times) {
    grid(&s.paths, |g, [x, y, z], label| {
        let d = hexahedron_at(g, [x as f64, y as f64, z as f64]);
        g.set_attribute::<3>(d, label);
        d
    })
}

/// The `K³` hexahedra with their points left unsewn, then [`build::sew3_same_facets`]
/// (faces found by their points, as CGAL's `sew3_same_facets`): "build" is making the
/// hexahedra, "sew" the call.
fn same_facets() -> (GMap, Times) {
    let mut g = GMap::new(3);
    let c0 = thread_cpu();
    let t0 = Instant::now();
    for z in 0..K {
        for y in 0..K {
            for x in 0..K {
                hexahedron_at(&mut g, [x as f64, y as f64, z as f64]);
            }
        }
    }
    let built = t0.elapsed().as_secs_f64();
    let c1 = thread_cpu();
    let t1 = Instant::now();
    let sewn = build::sew3_same_facets(&mut g).expect("the grid's faces pair up");
    let sewn_s = t1.elapsed().as_secs_f64();
    let c2 = thread_cpu();
    assert_eq!(sewn, 3 * K * K * (K - 1));
    let cpu = c0.zip(c1).zip(c2).map(|((c0, c1), c2)| (c1 - c0, c2 - c1));
    (g, Times { wall: (built, sewn_s), cpu })
}

/// Runs of each variant, ours and CGAL's: the machine is shared, so the best of several
/// runs is the steadier figure.
const REPS: usize = 5;

/// The smallest building and sewing times seen, wall clock and CPU apart.
#[derive(Clone, Copy)]
struct Best {
    wall: (f64, f64),
    cpu: Option<(f64, f64)>,
}

impl Best {
    fn new() -> Self {
        Best { wall: (f64::INFINITY, f64::INFINITY), cpu: Some((f64::INFINITY, f64::INFINITY)) }
    }

    /// Lowers each figure to the run's where it is smaller.
    fn keep(&mut self, t: Times) {
        let min = |a: (f64, f64), b: (f64, f64)| (a.0.min(b.0), a.1.min(b.1));
        self.wall = min(self.wall, t.wall);
        self.cpu = self.cpu.zip(t.cpu).map(|(a, b)| min(a, b));
    }
}

/// Checks the three grids of one round: the same complex (41³ vertices, 3·40·41² edges,
/// 3·40²·41 faces, 40³ volumes), every grid vertex with one point, every volume labelled.
fn check_grids(g0: &GMap, g1: &GMap, g2: &Labelled) {
    for ch in [g0.characteristics(), g1.characteristics(), g2.characteristics()] {
        assert_eq!(ch.cells, vec![68_921, 201_720, 196_800, 64_000], "{ch}");
        assert!(ch.valid && ch.components == 1, "{ch}");
    }
    assert_eq!((g1.point_count(), g2.point_count(), g2.attribute_count::<3>()), (68_921, 68_921, K * K * K));
    // the corner of the last cell, moved there with its cube
    assert!(g1.darts().any(|d| g1.point(d) == Some([K as f64; 3])));
}

/// The variants by name, as CGAL's harness takes them (its third argument).
const VARIANTS: [&str; 4] = ["plain", "lcc", "lcc_label", "same_facets"];

/// Builds variant `k` once and returns this process's peak resident memory in bytes: run in
/// a fresh process (`LCC_ONLY=k`), it is the memory that variant takes.
fn run_only(s: &Setup, k: usize) -> Option<u64> {
    let darts = match k {
        0 => plain(s).0.dart_count(),
        1 => with_points(s).0.dart_count(),
        2 => with_labels(s).0.dart_count(),
        _ => same_facets().0.dart_count(),
    };
    assert_eq!(darts, 48 * K * K * K);
    gmap_core::resources::peak_rss()
}

/// The peak resident memory in kB of each variant, ours and CGAL's, each built once in a
/// fresh process (this bench with `LCC_ONLY`, CGAL's harness with the variant's name): a
/// pair per variant, `None` where a run failed or CGAL is missing.
fn peaks() -> Vec<(Option<u64>, Option<u64>)> {
    let exe = std::env::current_exe().ok();
    (0..VARIANTS.len())
        .map(|k| {
            let ours = exe.as_ref().and_then(|exe| {
                let out = Command::new(exe).env("LCC_ONLY", k.to_string()).arg("--bench").output().ok()?;
                let text = String::from_utf8(out.stdout).ok()?;
                text.lines()
                    .find_map(|l| l.strip_prefix("peak_rss_bytes ")?.trim().parse::<u64>().ok())
                    .map(|b| b / 1024)
            });
            let cgal = cgal_run(&["1", VARIANTS[k]])
                .and_then(|text| text.lines().next().and_then(|l| serde_json::from_str::<serde_json::Value>(l).ok()))
                .and_then(|v| v["peak_rss_kb"].as_u64());
            (ours, cgal)
        })
        .collect()
}

/// The output of CGAL's harness on the 40³ grid with `args` after K, or `None` when CGAL
/// or g++ is missing or the harness fails.
fn cgal_run(args: &[&str]) -> Option<String> {
    if !std::path::Path::new("/usr/include/CGAL/Linear_cell_complex_for_generalized_map.h").exists() {
        return None;
    }
    let out =
        Command::new("bash").arg(common::anchor("run-cgal-lcc.sh")).arg(K.to_string()).args(args).output().ok()?;
    if !out.status.success() {
        eprintln!("lcc bench: CGAL anchor failed: {}", String::from_utf8_lossy(&out.stderr).trim());
        return None;
    }
    String::from_utf8(out.stdout).ok()
}

/// CGAL's times for the three variants, from the anchor run in this sitting, or `None` when
/// CGAL or g++ is missing or the harness fails.
fn cgal_anchor() -> Option<Vec<Best>> {
    let text = cgal_run(&[&REPS.to_string()])?;
    text.lines()
        .map(|l| {
            let v: serde_json::Value = serde_json::from_str(l).ok()?;
            let cpu = v["cpu_build_s"].as_f64().zip(v["cpu_sew_s"].as_f64());
            Some(Best { wall: (v["build_s"].as_f64()?, v["sew_s"].as_f64()?), cpu })
        })
        .collect()
}

fn bench(c: &mut Criterion) {
    let s = Setup { paths: sew_paths() };
    if let Some(k) = std::env::var("LCC_ONLY").ok().and_then(|v| v.parse::<usize>().ok()) {
        // a child of `peaks`: one variant, then its peak memory
        if let Some(bytes) = run_only(&s, k.min(VARIANTS.len() - 1)) {
            println!("peak_rss_bytes {bytes}");
        }
        std::process::exit(0);
    }
    // REPS rounds of the three variants, interleaved so that a change in the machine's
    // load weighs on all three alike; the first round's grids are checked
    let mut best = [Best::new(); 4];
    for round in 0..REPS {
        let (g0, t) = plain(&s);
        best[0].keep(t);
        let (g1, t) = with_points(&s);
        best[1].keep(t);
        let (g2, t) = with_labels(&s);
        best[2].keep(t);
        let (g3, t) = same_facets();
        best[3].keep(t);
        if round == 0 {
            check_grids(&g0, &g1, &g2);
            check_grids(&g0, &g3, &g2);
        }
    }
    let anchor = cgal_anchor();
    let names = ["no attributes", "points", "points and labels", "points, sew3_same_facets"];
    for (k, (name, ours)) in names.iter().zip(best).enumerate() {
        let (b, s) = ours.wall;
        match anchor.as_ref().and_then(|a| a.get(k)) {
            Some(cgal) => {
                let (cb, cs) = cgal.wall;
                eprintln!(
                    "lcc bench grid{K}, {name}: wall: ours build {b:.3} s + sew {s:.3} s = {:.3} s; \
                     CGAL {cb:.3} + {cs:.3} = {:.3} s; ours / CGAL = {:.2}",
                    b + s,
                    cb + cs,
                    (b + s) / (cb + cs)
                );
                if let (Some((b, s)), Some((cb, cs))) = (ours.cpu, cgal.cpu) {
                    eprintln!(
                        "lcc bench grid{K}, {name}: CPU: ours build {b:.3} s + sew {s:.3} s = {:.3} s; \
                         CGAL {cb:.3} + {cs:.3} = {:.3} s; ours / CGAL = {:.2} (build {:.2}, sew {:.2})",
                        b + s,
                        cb + cs,
                        (b + s) / (cb + cs),
                        b / cb,
                        s / cs
                    );
                }
            }
            None => eprintln!("lcc bench grid{K}, {name}: ours build {b:.3} s + sew {s:.3} s; CGAL anchor not run"),
        }
    }
    for (name, (ours, cgal)) in names.iter().zip(peaks()) {
        let show = |kb: Option<u64>| kb.map_or("?".to_string(), |kb| format!("{:.0} MB", kb as f64 / 1024.0));
        let ratio =
            ours.zip(cgal).map_or(String::new(), |(o, c)| format!("; ours / CGAL = {:.2}", o as f64 / c as f64));
        eprintln!("lcc bench grid{K}, {name}: peak memory: ours {}, CGAL {}{ratio}", show(ours), show(cgal));
    }
    let mut group = c.benchmark_group(format!("lcc{K}"));
    group.sample_size(10);
    group.bench_function("no_attributes", |b| b.iter(|| plain(&s).0.dart_count()));
    group.bench_function("points", |b| b.iter(|| with_points(&s).0.dart_count()));
    group.bench_function("points_and_labels", |b| b.iter(|| with_labels(&s).0.dart_count()));
    group.bench_function("sew3_same_facets", |b| b.iter(|| same_facets().0.dart_count()));
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
