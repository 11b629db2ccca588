//! `gmap homology --simplify`: same groups as without, on a file with torsion.

use std::process::Command;

fn homology(args: &[&str]) -> String {
    let out = Command::new(env!("CARGO_BIN_EXE_gmap")).arg("homology").args(args).output().expect("run gmap");
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    String::from_utf8(out.stdout).expect("utf-8")
}

#[test]
fn simplify_keeps_the_groups() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/lutz/Hom_C5_K4.facets");
    let file = path.to_str().expect("utf-8 path");
    // --simplify works on the G-map: compare with the G-map route (the output names the route)
    let plain = homology(&[file, "--json", "--via", "gmap"]);
    let reduced = homology(&[file, "--json", "--simplify"]);
    assert_eq!(plain, reduced);
    let direct = homology(&[file, "--json"]);
    assert_eq!(direct.replace("\"route\":\"direct\"", "\"route\":\"gmap\""), reduced);
    assert!(reduced.contains("\"torsion\":[[],[2],[],[]]"), "{reduced}");
    assert!(reduced.contains("\"betti\":[1,0,0,1]"), "{reduced}");
}
