//! G-map → architectural complex → `.json` → read back: the same homology, for every demo
//! object and the Lutz corpus up to 10^5 darts; and `gmap` on `.json` files.

use std::path::{Path, PathBuf};
use std::process::Command;

use gmap_core::DenseMap;
use gmap_homology::arch::ArchComplex;
use gmap_homology::json::{read_json, write_json};
use gmap_homology::{cellular_complex, homology_z, Homology};

fn lutz_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/lutz")
}

fn round_trip(name: &str, m: &DenseMap) -> Option<Homology> {
    let cellular = cellular_complex(m);
    let x = match ArchComplex::from_map(m) {
        Ok(x) => x,
        Err(e) => {
            // only where the cellular method refuses too
            assert!(cellular.is_err(), "{name}: {e}");
            return None;
        }
    };
    let back = read_json(&write_json(&x)).unwrap_or_else(|e| panic!("{name}: {e}"));
    assert_eq!(back, x, "{name}");
    let h = back.homology_z().unwrap();
    if let Ok(c) = cellular {
        assert_eq!(h, homology_z(&c.chain).unwrap(), "{name}");
    }
    assert_eq!(x.region_counts(), m.cell_counts(), "{name}");
    Some(h)
}

#[test]
fn demo_objects_round_trip() {
    let mut done = 0;
    for (name, m) in gmap_ops::build::demo_objects() {
        if let Some(h) = round_trip(&name, &m) {
            done += 1;
            if name.starts_with("lens space L(5,2)") {
                assert_eq!(h.torsion[1], vec![5]);
            }
            if name.starts_with("Klein") {
                assert_eq!(h.to_string(), "(Z, Z + Z/2, 0)");
            }
        }
    }
    assert!(done >= 14, "only {done} demo objects went through");
}

#[test]
fn lutz_corpus_round_trip() {
    let dir = lutz_dir();
    assert!(dir.is_dir(), "{} is missing", dir.display());
    let mut files: Vec<PathBuf> = std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().path()).collect();
    files.sort();
    let mut done = Vec::new();
    for f in files.iter().filter(|f| f.extension().is_some_and(|e| e == "facets")) {
        let Ok(m) = gmap_ops::import::read_facets(f, Some(100_000)) else { continue };
        let name = f.file_stem().unwrap().to_string_lossy().to_string();
        let h = round_trip(&name, &m).unwrap_or_else(|| panic!("{name}: simplicial cells satisfy C1"));
        if name == "hyperbolic_dodecahedral_space" {
            assert_eq!(h.torsion[1], vec![5, 5, 5]);
        }
        if name == "d2n12g6" {
            assert_eq!(h.betti, vec![1, 12, 1]);
        }
        done.push(name);
    }
    assert!(done.len() >= 25, "only {} files: {done:?}", done.len());
}

fn gmap() -> Command {
    Command::new(env!("CARGO_BIN_EXE_gmap"))
}

fn write(dir: &Path, name: &str, text: &str) -> PathBuf {
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

const HEAD: &str = r#"{"dimension": 2, "regions": [{"id": 0, "dim": 0}, {"id": 1, "dim": 1}, {"id": 2, "dim": 1}, {"id": 3, "dim": 2}], "incidence": "#;

fn fails_with(text: &str, needle: &str) {
    let dir = tempfile::tempdir().unwrap();
    let p = write(dir.path(), "bad.json", text);
    for sub in ["info", "homology"] {
        let out = gmap().arg(sub).arg(&p).output().unwrap();
        assert_eq!(out.status.code(), Some(1), "{sub} {text}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.starts_with("error: "), "{err}");
        assert!(err.contains("bad.json"), "{err}");
        assert!(err.contains(needle), "{sub}: {err} should mention {needle}");
        assert_eq!(err.lines().count(), 1);
    }
}

#[test]
fn bad_json_cycle() {
    fails_with(
        &format!("{HEAD}[{{\"from\": 1, \"to\": 2, \"weight\": 0}}, {{\"from\": 2, \"to\": 1, \"weight\": 0}}]}}"),
        "cycle",
    );
}

#[test]
fn bad_json_dimension_not_decreasing() {
    fails_with(&format!("{HEAD}[{{\"from\": 0, \"to\": 1, \"weight\": 1}}]}}"), "dimension must decrease");
}

#[test]
fn bad_json_weight_across_gap() {
    fails_with(&format!("{HEAD}[{{\"from\": 3, \"to\": 0, \"weight\": 2}}]}}"), "across a gap must be 0");
}

#[test]
fn bad_json_duplicate_id() {
    fails_with(r#"{"regions": [{"id": 4, "dim": 0}, {"id": 4, "dim": 1}], "incidence": []}"#, "duplicate region id 4");
}

#[test]
fn bad_json_duplicate_entry() {
    fails_with(
        &format!("{HEAD}[{{\"from\": 1, \"to\": 0, \"weight\": 1}}, {{\"from\": 1, \"to\": 0, \"weight\": 1}}]}}"),
        "duplicate incidence entry 1 -> 0",
    );
}

#[test]
fn bad_json_square_not_zero() {
    fails_with(
        &format!("{HEAD}[{{\"from\": 1, \"to\": 0, \"weight\": 1}}, {{\"from\": 3, \"to\": 1, \"weight\": 1}}]}}"),
        "does not square to zero",
    );
}

#[test]
fn bad_json_syntax() {
    fails_with("{\"regions\": [}", "line 1");
}

/// The ring of AC Example 8.21 through the command line.
const RING: &str = r#"{"dimension": 2, "regions": [{"id": 0, "dim": 1}, {"id": 1, "dim": 1}, {"id": 2, "dim": 2}],
 "incidence": [{"from": 2, "to": 0, "weight": 1}, {"from": 2, "to": 1, "weight": 0}]}"#;

#[test]
fn homology_and_info_of_a_json_complex() {
    let dir = tempfile::tempdir().unwrap();
    let p = write(dir.path(), "ring.json", RING);
    let out = gmap().args(["homology", "--json"]).arg(&p).output().unwrap();
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["betti"], serde_json::json!([0, 1, 0]));
    assert_eq!(v["euler_characteristic"], -1);
    let out = gmap().args(["homology", "--json", "--topological"]).arg(&p).output().unwrap();
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["betti"], serde_json::json!([1, 1, 0]));
    let out = gmap().args(["info", "--json"]).arg(&p).output().unwrap();
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["dimension"], 2);
    assert_eq!(v["cells"], serde_json::json!([0, 2, 1]));
    assert_eq!(v["euler_characteristic"], -1);
}

/// A torus region (AC Def. 8.1) through the command line: with its Betti numbers,
/// `--topological` gives (1, 2, 1); a solid torus, which Algorithm 8.16 cannot cellulate
/// from its numbers, is refused with the region named; never the sphere's (1, 0, 1).
#[test]
fn topological_homology_of_regions_with_their_own_betti_numbers() {
    let dir = tempfile::tempdir().unwrap();
    let torus =
        write(dir.path(), "torus.json", r#"{"regions": [{"id": 7, "dim": 2, "betti": [1, 2, 1]}], "incidence": []}"#);
    let out = gmap().args(["homology", "--json", "--topological"]).arg(&torus).output().unwrap();
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["betti"], serde_json::json!([1, 2, 1]));
    // without --topological: the complex itself, one closed region
    let out = gmap().args(["homology", "--json"]).arg(&torus).output().unwrap();
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["betti"], serde_json::json!([0, 0, 1]));
    let solid = write(
        dir.path(),
        "solid.json",
        r#"{"regions": [{"id": 9, "dim": 3, "betti": [1, 1, 0, 0]}], "incidence": []}"#,
    );
    let out = gmap().args(["homology", "--topological"]).arg(&solid).output().unwrap();
    assert_eq!(out.status.code(), Some(1));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("Algorithm 8.16") && err.contains("region 9 (3-region with Betti numbers (1, 1, 0, 0)"),
        "{err}"
    );
    let bad =
        write(dir.path(), "bad.json", r#"{"regions": [{"id": 7, "dim": 2, "betti": [1, 1, 1]}], "incidence": []}"#);
    let out = gmap().args(["info"]).arg(&bad).output().unwrap();
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr)
        .contains("region 7 of dimension 2 cannot have the Betti numbers (1, 1, 1)"));
}

#[test]
fn convert_gmap_to_json_dot_and_lar() {
    let dir = tempfile::tempdir().unwrap();
    let torus = gmap_ops::build::schema("a b A B").unwrap();
    let src = dir.path().join("torus.gmap");
    gmap_core::io::write_gmap(&torus, &src).unwrap();
    for ext in ["json", "dot", "lar.json"] {
        let dst = dir.path().join(format!("torus.{ext}"));
        let out = gmap().arg("convert").arg(&src).arg(&dst).output().unwrap();
        assert_eq!(out.status.code(), Some(0), "{ext}: {}", String::from_utf8_lossy(&out.stderr));
        assert!(dst.is_file());
    }
    let back = read_json(&std::fs::read_to_string(dir.path().join("torus.json")).unwrap()).unwrap();
    assert_eq!(back.homology_z().unwrap().betti, vec![1, 2, 1]);
    let dot = std::fs::read_to_string(dir.path().join("torus.dot")).unwrap();
    assert!(dot.starts_with("digraph"));
    let lar: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.path().join("torus.lar.json")).unwrap()).unwrap();
    assert_eq!(lar["dimension"], 2);
    // .json → homology through the CLI equals the G-map's
    let out = gmap().args(["homology", "--json"]).arg(dir.path().join("torus.json")).output().unwrap();
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["betti"], serde_json::json!([1, 2, 1]));
}

#[test]
fn json_back_to_a_gmap_by_the_flag_construction() {
    let dir = tempfile::tempdir().unwrap();
    let cube = gmap_ops::build::cube(3).unwrap();
    let src = dir.path().join("cube.gmap");
    gmap_core::io::write_gmap(&cube, &src).unwrap();
    let js = dir.path().join("cube.json");
    let back = dir.path().join("back.gmap");
    for (a, b) in [(&src, &js), (&js, &back)] {
        let out = gmap().arg("convert").arg(a).arg(b).output().unwrap();
        assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    }
    let m = gmap_core::io::read_gmap(&back).unwrap();
    assert!(gmap_ops::iso::are_isomorphic(&m, &cube));
    // the one-vertex torus is not a regular complex (an edge meets its one vertex twice):
    // refused, no output file
    let torus = gmap_ops::build::schema("a b A B").unwrap();
    let t = dir.path().join("torus.gmap");
    gmap_core::io::write_gmap(&torus, &t).unwrap();
    let tj = dir.path().join("torus.json");
    let out = gmap().arg("convert").arg(&t).arg(&tj).output().unwrap();
    assert_eq!(out.status.code(), Some(0));
    let tb = dir.path().join("torus_back.gmap");
    let out = gmap().arg("convert").arg(&tj).arg(&tb).output().unwrap();
    assert_eq!(out.status.code(), Some(1));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("region 1: its entry to region 0 has weight 0"), "{err}");
    assert!(!tb.exists());
}

#[test]
fn convert_keeps_the_cell_labels_of_a_gmap_in_json_and_dot() {
    let dir = tempfile::tempdir().unwrap();
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/labelled_segment.gmap");
    let json = dir.path().join("segment.json");
    let dot = dir.path().join("segment.dot");
    for dst in [&json, &dot] {
        // an incidence graph keeps the labels, not the points: said, and written with --lossy
        let out = gmap().arg("convert").arg(&src).arg(dst).output().unwrap();
        assert_eq!(out.status.code(), Some(1));
        assert!(String::from_utf8_lossy(&out.stderr).contains("drops the points"));
        let out = gmap().arg("convert").arg(&src).arg(dst).arg("--lossy").output().unwrap();
        assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    }
    let text = std::fs::read_to_string(&json).unwrap();
    assert_eq!(
        text,
        "{\"dimension\": 1,\n \"regions\": [{\"id\": 0, \"dim\": 0},\n  \
         {\"id\": 1, \"dim\": 0, \"labels\": {\"hits\": 3}},\n  \
         {\"id\": 2, \"dim\": 1, \"labels\": {\"name\": \"main \\\"beam\\\"\", \"length\": 2.5}}],\n \
         \"incidence\": [{\"from\": 2, \"to\": 0, \"weight\": 1},\n  {\"from\": 2, \"to\": 1, \"weight\": -1}]}\n"
    );
    // read back by the CLI and written again: the same text
    let again = dir.path().join("again.json");
    let out = gmap().arg("convert").arg(&json).arg(&again).output().unwrap();
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    assert_eq!(std::fs::read_to_string(&again).unwrap(), text);
    let d = std::fs::read_to_string(&dot).unwrap();
    assert!(d.contains("  r1 [label=\"0\", \"hits\"=\"3\"];\n"), "{d}");
    assert!(d.contains("  r2 [label=\"main \\\"beam\\\"\\n1\", \"length\"=\"2.5\"];\n"), "{d}");
    // a label of a kind JSON labels cannot hold is refused, naming it
    let bad = write(
        dir.path(),
        "bad.json",
        r#"{"regions": [{"id": 0, "dim": 0, "labels": {"ok": false}}], "incidence": []}"#,
    );
    let out = gmap().arg("info").arg(&bad).output().unwrap();
    assert_eq!(out.status.code(), Some(1));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("regions[0].labels.ok: expected an integer, a real or a text, found false"), "{err}");
}
