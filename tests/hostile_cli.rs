//! The `gmap` command on hostile inputs (the hostile-input audit), through the binary: every
//! failure is one `error:` line and exit code 1, never a wrong answer, a crash or a lost file.

mod common;
use common::{gmap, stderr, stdout};
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use gmap_core::{examples::add_simplex, DenseMap, GMap};
use proptest::prelude::*;

/// Runs `gmap ARGS` under `ulimit LIMIT` (a shell builtin) in `dir`.
fn gmap_limited(dir: &Path, limit: &str, args: &str) -> Output {
    let script = format!("ulimit {limit} && exec '{}' {args}", env!("CARGO_BIN_EXE_gmap"));
    Command::new("sh").arg("-c").arg(script).current_dir(dir).output().expect("run sh")
}

/// Asserts a refusal: exit code 1 and one `error:` line containing `needle`.
fn refused(o: &Output, needle: &str) {
    let err = stderr(o);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(err.starts_with("error: ") && err.lines().count() == 1, "{err}");
    assert!(err.contains(needle), "{err} should contain {needle}");
}

fn write(dir: &Path, name: &str, text: &[u8]) -> PathBuf {
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// The `betti` and `torsion` of `gmap homology --json` (None when it fails).
fn groups(args: &[&str]) -> Option<(serde_json::Value, serde_json::Value)> {
    let o = gmap(args);
    if !o.status.success() {
        return None;
    }
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    Some((v["betti"].clone(), v["torsion"].clone()))
}

#[test]
fn simplify_on_a_segment_keeps_its_homology() {
    let dir = tempfile::tempdir().unwrap();
    // two darts at one vertex, each an edge with an open end: H = (Z, 0)
    let seg = write(dir.path(), "seg.gmap", b"gmap 1 2\n0 1\n1 0\n");
    let plain = groups(&["homology", s(&seg), "--json", "--method", "simplicial"]).unwrap();
    assert_eq!(plain.0, serde_json::json!([1, 0]));
    let simp = groups(&["homology", s(&seg), "--json", "--method", "simplicial", "--simplify"]).unwrap();
    assert_eq!(simp, plain);
    // the cellular method does not apply, with or without --simplify
    let o = gmap(&["homology", s(&seg), "--simplify"]);
    refused(&o, "condition C1");
    assert_eq!(stderr(&o), stderr(&gmap(&["homology", s(&seg)])));
    // the error quotes its cause once
    assert_eq!(stderr(&o).matches("has an open boundary").count(), 1, "{}", stderr(&o));
}

#[test]
fn simplify_keeps_three_components() {
    let dir = tempfile::tempdir().unwrap();
    // a triangle of free darts and two loose edges: three components
    let m = write(dir.path(), "c3.gmap", b"gmap 2 6\n0 5 0\n2 1 1\n1 2 2\n4 3 3\n3 4 4\n5 0 5\n");
    let plain = groups(&["homology", s(&m), "--json", "--method", "simplicial"]).unwrap();
    assert_eq!(plain.0, serde_json::json!([3, 0, 0]));
    let simp = groups(&["homology", s(&m), "--json", "--method", "simplicial", "--simplify"]).unwrap();
    assert_eq!(simp, plain);
}

/// A random valid map: simplices of the given dimensions (mod n + 1), then sews that may fail.
fn build(n: usize, pieces: &[usize], sews: &[(usize, usize, usize)]) -> DenseMap {
    let mut g = GMap::new(n);
    let mut darts = Vec::new();
    for &k in pieces {
        let ids = add_simplex(&mut g, k % (n + 1));
        darts.extend(ids);
    }
    for &(a, b, i) in sews {
        let _ = g.try_sew(darts[a % darts.len()], darts[b % darts.len()], i % (n + 1));
    }
    g.to_dense_map()
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, ..ProptestConfig::default() })]

    /// `--simplify` never changes the groups nor whether a method applies.
    #[test]
    fn simplify_never_changes_the_groups(
        n in 1usize..=3,
        pieces in prop::collection::vec(0usize..4, 1..5),
        sews in prop::collection::vec((0usize..1000, 0usize..1000, 0usize..4), 0..30),
    ) {
        let m = build(n, &pieces, &sews);
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("m.gmap");
        gmap_core::io::write_gmap(&m, &p).unwrap();
        for method in ["cellular", "simplicial"] {
            let plain = groups(&["homology", s(&p), "--json", "--method", method]);
            let simp = groups(&["homology", s(&p), "--json", "--method", method, "--simplify"]);
            prop_assert_eq!(&simp, &plain, "{} {}", method, String::from_utf8_lossy(&gmap_core::io::format_gmap(&m)));
        }
    }
}

#[cfg(unix)]
#[test]
fn convert_refuses_to_overwrite_its_input() {
    let dir = tempfile::tempdir().unwrap();
    let text = b"1 2 3\n1 2 4\n1 3 4\n2 3 4\n";
    let x = write(dir.path(), "x.facets", text);
    std::os::unix::fs::symlink(&x, dir.path().join("link.facets")).unwrap();
    std::fs::hard_link(&x, dir.path().join("hard.facets")).unwrap();
    let run = |a: &str, b: &str| {
        Command::new(env!("CARGO_BIN_EXE_gmap")).args(["convert", a, b]).current_dir(dir.path()).output().unwrap()
    };
    for (a, b) in [
        ("x.facets", "x.facets"),
        ("x.facets", "./x.facets"),
        ("./x.facets", "../$DIR/x.facets"),
        ("link.facets", "x.facets"),
        ("x.facets", "link.facets"),
        ("hard.facets", "x.facets"),
    ] {
        let dname = dir.path().file_name().unwrap().to_str().unwrap();
        let b = b.replace("$DIR", dname);
        refused(&run(a, &b), "the output is the input file");
        assert_eq!(std::fs::read(&x).unwrap(), text);
    }
    // another file is fine
    let o = run("x.facets", "y.facets");
    assert!(o.status.success(), "{}", stderr(&o));
}

#[test]
fn a_hash_in_a_file_name_is_part_of_the_name() {
    let dir = tempfile::tempdir().unwrap();
    let p = write(dir.path(), "run#3.gmap", b"gmap 1 2\n1 1\n0 0\n");
    let o = gmap(&["info", s(&p)]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stdout(&o).contains("darts"), "{}", stdout(&o));
    let out = dir.path().join("out#1.moka");
    let o = gmap(&["convert", s(&p), s(&out)]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(std::fs::read_to_string(&out).unwrap().starts_with("Moka file [ascii]"));
    // FILE.lex#name still names a complex of a .lex file
    let lex = write(dir.path(), "k#2.lex", b"circle=[[1,2],[2,3],[3,1]]\nsphere=[[1,2,3],[1,2,4],[1,3,4],[2,3,4]]\n");
    let o = gmap(&["info", &format!("{}#sphere", s(&lex)), "--json"]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stdout(&o).contains("\"dimension\":2"), "{}", stdout(&o));
    let o = gmap(&["info", s(&lex), "--json"]);
    assert!(stdout(&o).contains("\"dimension\":1"), "{}", stdout(&o));
}

#[test]
fn max_darts_applies_to_off() {
    let dir = tempfile::tempdir().unwrap();
    let p = write(dir.path(), "sq.off", b"OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n");
    assert!(gmap(&["info", s(&p), "--max-darts", "8"]).status.success());
    refused(&gmap(&["info", s(&p), "--max-darts", "7"]), "raise the limit with --max-darts N");
}

#[cfg(unix)]
#[test]
fn a_file_size_limit_leaves_no_temporary_file() {
    let dir = tempfile::tempdir().unwrap();
    let big = gmap_ops::build::grid(&[6, 6, 6], &[true; 3]).unwrap();
    gmap_core::io::write_gmap(&big, dir.path().join("big.gmap")).unwrap();
    // 8 blocks (at most 8 KiB) for a .moka of about 300 KB
    let o = gmap_limited(dir.path(), "-f 8", "convert big.gmap out.moka");
    refused(&o, "out.moka");
    let names: Vec<String> =
        std::fs::read_dir(dir.path()).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
    assert_eq!(names, vec!["big.gmap".to_string()], "{names:?}");
}

#[cfg(unix)]
#[test]
fn memory_that_cannot_be_had_is_an_error_not_an_abort() {
    let dir = tempfile::tempdir().unwrap();
    // one 11-vertex facet: 11! darts, several GB
    write(dir.path(), "big.facets", b"0 1 2 3 4 5 6 7 8 9 10\n");
    let o = gmap_limited(dir.path(), "-v 1000000", "info big.facets");
    refused(&o, "big.facets");
    // a file larger than the address space left
    let f = std::fs::File::create(dir.path().join("huge.gmap")).unwrap();
    f.set_len(3 << 30).unwrap();
    let o = gmap_limited(dir.path(), "-v 1000000", "info huge.gmap");
    refused(&o, "huge.gmap");
}

#[test]
fn simplicial_counterpart_too_big_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    // the fuzzer's slow unit: an empty map of dimension 24 took 16 s (2^25 vertex sets, 25 times)
    let empty = write(dir.path(), "e24.gmap", b"gmap 24 0\n");
    let t = std::time::Instant::now();
    refused(&gmap(&["homology", s(&empty), "--method", "simplicial"]), "too many to build");
    assert!(t.elapsed().as_secs() < 5);
    // one dart of dimension 30: 2^31 simplices
    let one = write(dir.path(), "one.gmap", format!("gmap 30 1\n{}\n", vec!["0"; 31].join(" ")).as_bytes());
    refused(&gmap(&["homology", s(&one), "--method", "simplicial"]), "2^31 x 1 simplices");
    // the cellular method answers
    let o = gmap(&["homology", s(&empty), "--json"]);
    assert!(o.status.success(), "{}", stderr(&o));
    // small ones still go through
    let seg = write(dir.path(), "seg.gmap", b"gmap 1 2\n0 1\n1 0\n");
    assert!(gmap(&["homology", s(&seg), "--method", "simplicial"]).status.success());
}
