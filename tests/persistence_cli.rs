//! `gmap persistence`: the command's JSON equals GUDHI's recorded diagram of a sample image,
//! a valued `.facets` file is read, a composite field is refused.

use std::process::Command;

use serde_json::Value;

fn gmap(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_gmap")).args(args).output().unwrap()
}

fn sorted(pairs: &Value) -> Vec<String> {
    let mut v: Vec<String> = pairs.as_array().unwrap().iter().map(|p| p.to_string()).collect();
    v.sort();
    v
}

#[test]
fn coins_equals_gudhi_in_both_constructions() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/images");
    let rec: Value = serde_json::from_str(&std::fs::read_to_string(dir.join("coins.json")).unwrap()).unwrap();
    for (cons, key) in [("T", "T_sub_n_3"), ("V", "V_sub_n_3")] {
        let out = gmap(&[
            "persistence",
            dir.join("coins.pgm").to_str().unwrap(),
            "--construction",
            cons,
            "--field",
            "3",
            "--json",
        ]);
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
        let got: Value = serde_json::from_slice(&out.stdout).unwrap();
        assert_eq!(got["field"], 3);
        assert_eq!(sorted(&got["pairs"]), sorted(&rec["diagrams"][key]), "{cons}");
    }
}

#[test]
fn valued_facets_and_refusals() {
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("tet.facets");
    std::fs::write(&f, "# the boundary of a tetrahedron\n1 2 3 : 1\n2 3 4 : 2\n1 3 4 : 3\n1 2 4 : 4\n").unwrap();
    let out = gmap(&["persistence", f.to_str().unwrap()]);
    assert!(out.status.success());
    // one component from 1; the sphere closes at 4
    assert_eq!(String::from_utf8_lossy(&out.stdout), "0 1 inf\n2 4 inf\n");
    let out = gmap(&["persistence", f.to_str().unwrap(), "--field", "4"]);
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains("Z/4"));
}
