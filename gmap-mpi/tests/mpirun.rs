//! `gmap-mpi` under `mpirun -n 2` and `mpirun -n 4 --oversubscribe` (with
//! `--allow-run-as-root` when run as root): the groups of `gmap homology` on random 2-D, 3-D
//! and 4-D images and on the structured image of docs/PERFORMANCE.md (5 shells, 7 solid
//! tori, 6 balls); an error on one rank ends every rank with the same message.
//! Built only with `--features mpi` (needs Open MPI's `mpirun`).
#![cfg(feature = "mpi")]

use std::path::Path;
use std::process::{Command, Output};

use gmap_ops::import::image::{Image, Order};

/// `mpirun -n ranks gmap-mpi args…`, ended after two minutes at most (a hang fails).
fn mpirun(ranks: usize, args: &[&str]) -> Output {
    let mut c = Command::new("timeout");
    c.args(["120", "mpirun", "-n", &ranks.to_string()]);
    // more ranks than cores (Open MPI's slots) need leave
    if ranks > std::thread::available_parallelism().map_or(1, |n| n.get()) {
        c.arg("--oversubscribe");
    }
    let uid = Command::new("id").arg("-u").output().expect("id -u runs");
    if String::from_utf8_lossy(&uid.stdout).trim() == "0" {
        c.arg("--allow-run-as-root");
    }
    c.arg(env!("CARGO_BIN_EXE_gmap-mpi")).args(args);
    let out = c.output().expect("mpirun (Open MPI's openmpi-bin) is installed");
    assert_ne!(out.status.code(), Some(124), "mpirun -n {ranks} {args:?} did not end within 120 s");
    out
}

fn groups_json(ranks: usize, path: &Path) -> serde_json::Value {
    let out = mpirun(ranks, &[path.to_str().unwrap(), "--json"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    serde_json::from_slice(&out.stdout).expect("rank 0 prints one JSON object")
}

/// The groups of one process, `gmap homology`'s route, as `gmap homology --json` says them.
fn one_process(path: &Path) -> (serde_json::Value, serde_json::Value) {
    let r = gmap::homology_file(path, &gmap::HomologyOptions::default()).unwrap();
    let v = r.to_json();
    (v["betti"].clone(), v["torsion"].clone())
}

fn check(path: &Path) -> serde_json::Value {
    let (betti, torsion) = one_process(path);
    let mut last = serde_json::Value::Null;
    for ranks in [2, 4] {
        let v = groups_json(ranks, path);
        assert_eq!((&v["betti"], &v["torsion"]), (&betti, &torsion), "{} on {ranks} ranks", path.display());
        let per = v["mpi"]["ranks"].as_array().unwrap();
        assert_eq!(per.len(), ranks);
        for (r, x) in per.iter().enumerate() {
            assert_eq!(x["rank"], r);
            assert!(x["bytes_sent"].as_u64().unwrap() > 0);
            assert!(x["peak_rss_bytes"].as_u64().unwrap() > 0);
        }
        last = v;
    }
    last
}

/// `benches/anchors/make_images.py ARGS…` (python3 with numpy) writes an image.
fn make_image(args: &[&str]) {
    let script = concat!(env!("CARGO_MANIFEST_DIR"), "/../benches/anchors/make_images.py");
    let made = Command::new("python3").arg(script).args(args).status().expect("python3 (with numpy) runs");
    assert!(made.success(), "make_images.py {args:?}");
}

#[test]
fn random_images_in_2_3_and_4_dimensions() {
    let dir = tempfile::tempdir().unwrap();
    for (dim, size) in [("2", "64"), ("3", "24"), ("4", "7")] {
        for (density, seed) in [("0.35", "3"), ("0.6", "4")] {
            let path = dir.path().join(format!("r{dim}-{density}.npy"));
            make_image(&["random", path.to_str().unwrap(), size, dim, density, seed]);
            let v = check(&path);
            let route = if dim == "3" { "one-pass blocks" } else { "slab complexes" };
            assert_eq!(v["mpi"]["route"], route);
        }
    }
}

#[test]
fn the_structured_image() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("structured.npy");
    make_image(&["structured", path.to_str().unwrap(), "256"]);
    let v = check(&path);
    // 5 shells, 7 solid tori, 6 balls
    assert_eq!(v["betti"], serde_json::json!([18, 7, 5, 0]));
}

#[test]
fn an_error_on_one_rank_ends_every_rank_with_its_message() {
    let dir = tempfile::tempdir().unwrap();
    // a 5 × 2000 image in 2 slabs of 3 and 2 layers: only rank 0's grid (4001 × 7 points,
    // 252063 bytes) is over 200K, rank 1's (4001 × 5) is under
    let path = dir.path().join("wide.npy");
    Image::from_values(&[5, 2000], Order::C, vec![1u8; 10_000]).unwrap().write_npy(&path).unwrap();
    let out = mpirun(2, &[path.to_str().unwrap(), "--max-memory", "200K"]);
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    let lines: Vec<&str> = err.lines().filter(|l| l.starts_with("error: ")).collect();
    assert_eq!(lines.len(), 2, "{err}");
    assert_eq!(lines[0], lines[1]);
    assert!(lines[0].contains("rank 0: ") && lines[0].contains("over the memory limit of 204800 bytes"), "{err}");
    assert!(out.stdout.is_empty());
    // a file that is not there: every rank says so, with the same line
    let missing = dir.path().join("missing.npy");
    let out = mpirun(4, &[missing.to_str().unwrap()]);
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    let lines: Vec<&str> = err.lines().filter(|l| l.starts_with("error: ")).collect();
    assert_eq!(lines.len(), 4, "{err}");
    assert!(lines.iter().all(|l| *l == lines[0] && l.contains("missing.npy")), "{err}");
}
