//! Small inputs that used to take minutes or gigabytes, rebuilt here: each run of `gmap`
//! exits 0 with the right groups or 1 with one `error:` line, quickly and within 2 GB of
//! address space. The full-size reproducers are `#[ignore]` tests (run with `--ignored`).

mod common;
use common::{p, stderr, stdout};

use std::path::Path;
use std::process::{Command, Output};
use std::time::{Duration, Instant};

use gmap_ops::rng::SplitMix64;

/// Runs `gmap ARGS` under `ulimit -v 2000000` (2 GB of address space), with its wall time.
fn gmap_2gb(args: &[&str]) -> (Output, Duration) {
    let quoted: Vec<String> = args.iter().map(|a| format!("'{a}'")).collect();
    let script = format!("ulimit -v 2000000 && exec '{}' {}", env!("CARGO_BIN_EXE_gmap"), quoted.join(" "));
    let t = Instant::now();
    let o = Command::new("sh").arg("-c").arg(script).output().expect("run sh");
    (o, t.elapsed())
}

/// A `.json` complex of `n` 1-regions and `n` 2-regions whose boundary matrix is the dense
/// `L · diag(d) · U`, `L` unit lower and `U` unit upper triangular with random entries in
/// `-1..=1`: its Smith form is `diag(d)` (made a divisibility chain), so `H_1` is
/// `⊕ Z/d_i` and `H_2 = 0`.
fn dense_json(dir: &Path, n: usize, d: &[i64], seed: u64) -> std::path::PathBuf {
    let mut rng = SplitMix64::new(seed);
    let mut tri = |lower: bool| -> Vec<Vec<i64>> {
        (0..n)
            .map(|i| {
                (0..n)
                    .map(|j| match (i == j, (j < i) == lower) {
                        (true, _) => 1,
                        (false, true) => rng.below(3) as i64 - 1,
                        (false, false) => 0,
                    })
                    .collect()
            })
            .collect()
    };
    let (l, u) = (tri(true), tri(false));
    let diag: Vec<i64> = (0..n).map(|k| if k + d.len() >= n { d[k + d.len() - n] } else { 1 }).collect();
    let mut text = String::from("{\"dimension\": 2, \"regions\": [");
    let regions: Vec<String> = (0..2 * n).map(|r| format!("{{\"id\": {r}, \"dim\": {}}}", 1 + r / n)).collect();
    text.push_str(&regions.join(", "));
    text.push_str("], \"incidence\": [");
    let mut entries = Vec::with_capacity(n * n);
    for i in 0..n {
        for j in 0..n {
            let a: i64 = (0..n).map(|k| l[i][k] * diag[k] * u[k][j]).sum();
            entries.push(format!("{{\"from\": {}, \"to\": {i}, \"weight\": {a}}}", n + j));
        }
    }
    text.push_str(&entries.join(",\n"));
    text.push_str("]}\n");
    let path = dir.join(format!("dense{n}.json"));
    std::fs::write(&path, text).unwrap();
    path
}

/// Asserts a run exits 0 within `secs` seconds and prints `expected` for `H_1`.
fn h1_is(path: &Path, expected: &str, secs: u64) {
    let (o, t) = gmap_2gb(&["homology", p(path)]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(t < Duration::from_secs(secs), "took {t:?}");
    let out = stdout(&o);
    assert!(out.contains(&format!("H_1 = {expected}\n")) && out.contains("H_2 = 0\n"), "{out}");
}

#[test]
fn dense_json_boundary_matrix() {
    let dir = tempfile::tempdir().unwrap();
    // 3 · 2^40 = 3298534883328
    let path = dense_json(dir.path(), 90, &[2, 6, 3 * (1 << 40)], 1);
    h1_is(&path, "Z/2 + Z/6 + Z/3298534883328", 20);
}

/// The reproducer: a dense 240 × 240 boundary matrix (over 200 s before).
#[test]
#[ignore]
fn dense_json_boundary_matrix_240() {
    let dir = tempfile::tempdir().unwrap();
    let path = dense_json(dir.path(), 240, &[4, 12, 7 * (1 << 50)], 2);
    h1_is(&path, "Z/4 + Z/12 + Z/7881299347898368", 60);
}
