//! `gmap bench` end to end: the JSON is one object whose groups are those of
//! `gmap homology`, the CSV has a header and one line per row, folders are expanded sorted,
//! an unreadable input is exit 1 and bad usage exit 2, and a route that does not apply is a
//! row that says so.

mod common;
use common::{gmap, lutz, p, stderr, stdout};
use std::path::PathBuf;

use serde_json::Value;

const FILES: [&str; 3] = ["Barnette_sphere.facets", "d2n12g6.facets", "B_3_9_18.facets"];

fn homology(file: &str, method: &str) -> Value {
    let o = gmap(&["homology", file, "--json", "--method", method]);
    assert!(o.status.success(), "{}", stderr(&o));
    serde_json::from_slice(&o.stdout).unwrap()
}

#[test]
fn json_groups_are_those_of_homology() {
    let files: Vec<String> = FILES.iter().map(|f| lutz(f)).collect();
    let mut args = vec!["bench", "--json"];
    args.extend(files.iter().map(String::as_str));
    let o = gmap(&args);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(o.stderr.is_empty(), "stderr is not a terminal: silent ({})", stderr(&o));
    let v: Value = serde_json::from_slice(&o.stdout).unwrap();
    let rows = v["rows"].as_array().unwrap();
    assert_eq!(rows.len(), 3 * files.len());
    for (k, f) in files.iter().enumerate() {
        for (j, route) in ["direct", "cellular", "simplicial"].iter().enumerate() {
            let r = &rows[3 * k + j];
            assert_eq!(r["input"], f.as_str());
            assert_eq!(r["route"], *route);
            let method = if *route == "simplicial" { "simplicial" } else { "cellular" };
            let h = homology(f, method);
            assert_eq!(r["betti"], h["betti"], "{f} {route}");
            assert_eq!(r["torsion"], h["torsion"], "{f} {route}");
            assert_eq!(r["agree"], true);
            let cells = r["cells"].as_array().unwrap();
            assert_eq!(cells.len(), h["betti"].as_array().unwrap().len());
            for key in ["read", "border", "reduction", "smith", "total"] {
                assert!(r["times_ms"][key].as_f64().unwrap() >= 0.0, "{key}");
            }
        }
    }
    // the direct route's cells and the G-map's cells of a .facets input are its simplices
    assert_eq!(rows[0]["cells"], serde_json::json!([8, 27, 38, 19]));
    assert_eq!(rows[1]["cells"], serde_json::json!([8, 27, 38, 19]));
    assert_eq!(rows[3]["groups"], "(Z, Z^12, Z)");
}

#[test]
fn csv_and_markdown_have_one_line_per_row() {
    let f = lutz("Barnette_sphere.facets");
    let o = gmap(&["bench", "--csv", &f]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = String::from_utf8(o.stdout).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len(), 4, "{text}");
    assert!(lines[0].starts_with("input,route,cells,read_ms,"), "{text}");
    assert!(lines[1].contains(",direct,8 27 38 19,"), "{text}");
    assert!(lines[2].contains(",cellular,8 27 38 19,"), "{text}");
    assert!(lines[2].contains("\"(Z, 0, 0, Z)\""), "{text}");
    assert!(lines[3].contains(",simplicial,"), "{text}");
    let o = gmap(&["bench", &f]);
    let text = String::from_utf8(o.stdout).unwrap();
    assert_eq!(text.lines().count(), 5, "{text}");
    assert!(text.starts_with("| input | route |"), "{text}");
    assert!(text.contains("(Z, 0, 0, Z)"), "{text}");
}

#[test]
fn a_folder_is_its_supported_files_sorted() {
    let dir = tempfile::tempdir().unwrap();
    for f in ["d2n12g6.facets", "Barnette_sphere.facets"] {
        std::fs::copy(lutz(f), dir.path().join(f)).unwrap();
    }
    std::fs::write(dir.path().join("notes.txt"), "not an input").unwrap();
    let m = gmap_ops::build::cube(3).unwrap();
    gmap_core::io::write_gmap(&m, dir.path().join("cube.gmap")).unwrap();
    let o = gmap(&["bench", "--json", dir.path().to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: Value = serde_json::from_slice(&o.stdout).unwrap();
    let inputs: Vec<PathBuf> =
        v["rows"].as_array().unwrap().iter().map(|r| PathBuf::from(r["input"].as_str().unwrap())).collect();
    let names: Vec<&str> = inputs.iter().map(|p| p.file_name().unwrap().to_str().unwrap()).collect();
    assert_eq!(
        names,
        [
            "Barnette_sphere.facets",
            "Barnette_sphere.facets",
            "Barnette_sphere.facets",
            "cube.gmap",
            "cube.gmap",
            "d2n12g6.facets",
            "d2n12g6.facets",
            "d2n12g6.facets"
        ]
    );
    let rows = v["rows"].as_array().unwrap();
    assert_eq!(rows[3]["groups"], "(Z, 0, 0, 0)");
    assert_eq!(rows[3]["cells"], serde_json::json!([8, 12, 6, 1]));
}

#[test]
fn a_route_that_does_not_apply_is_a_row() {
    // a segment with a free end: a 1-map whose 0-cell fails C1 or C2... use a loose dart pair
    let dir = tempfile::tempdir().unwrap();
    let mut m = gmap_core::DenseMap::new(2, 2);
    m.link(gmap_core::Dart::new(0), gmap_core::Dart::new(1), 1);
    let p = dir.path().join("odd.gmap");
    gmap_core::io::write_gmap(&m, &p).unwrap();
    let cell = gmap(&["homology", p.to_str().unwrap()]);
    let o = gmap(&["bench", "--json", p.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: Value = serde_json::from_slice(&o.stdout).unwrap();
    let rows = v["rows"].as_array().unwrap();
    assert_eq!(rows.len(), 2);
    if cell.status.success() {
        assert_eq!(rows[0]["error"], Value::Null);
    } else {
        assert!(rows[0]["error"].as_str().unwrap().starts_with("does not apply"), "{v}");
        assert_eq!(rows[0]["betti"], Value::Null);
    }
    assert_eq!(rows[1]["betti"], homology(p.to_str().unwrap(), "simplicial")["betti"]);
}

#[test]
fn errors_and_usage() {
    let dir = tempfile::tempdir().unwrap();
    let missing = dir.path().join("missing.facets");
    let o = gmap(&["bench", missing.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(1));
    assert!(o.stdout.is_empty());
    assert!(stderr(&o).starts_with("error: "), "{}", stderr(&o));
    let bad = dir.path().join("bad.facets");
    std::fs::write(&bad, "1 2 x\n").unwrap();
    let o = gmap(&["bench", "--json", &lutz("Barnette_sphere.facets"), bad.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(1));
    assert!(o.stdout.is_empty());
    // in a folder, the unreadable file is a row and the others are run
    let folder = tempfile::tempdir().unwrap();
    std::fs::copy(&bad, folder.path().join("bad.facets")).unwrap();
    std::fs::copy(lutz("Barnette_sphere.facets"), folder.path().join("a.facets")).unwrap();
    let o = gmap(&["bench", "--json", folder.path().to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: Value = serde_json::from_slice(&o.stdout).unwrap();
    let rows = v["rows"].as_array().unwrap();
    assert_eq!(rows.len(), 4);
    assert_eq!(rows[3]["route"], "read");
    assert!(rows[3]["error"].as_str().unwrap().starts_with("cannot read: "), "{v}");
    assert_eq!(rows[3]["betti"], Value::Null);
    let empty = tempfile::tempdir().unwrap();
    let o = gmap(&["bench", empty.path().to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(1));
    assert_eq!(gmap(&["bench"]).status.code(), Some(2));
    assert_eq!(gmap(&["bench", "--json", "--csv", &lutz("Barnette_sphere.facets")]).status.code(), Some(2));
    assert_eq!(gmap(&["bench", "--max-darts", "x", &lutz("Barnette_sphere.facets")]).status.code(), Some(2));
    // the direct route's faces have their own limit
    let o = gmap(&["bench", "--max-cells", "10", &lutz("Barnette_sphere.facets")]);
    assert_eq!(o.status.code(), Some(1));
    assert!(stderr(&o).contains("over the limit of 10; raise the limit with --max-cells N"), "{}", stderr(&o));
    // a periodic box: the cubical route of the torus
    let dir = tempfile::tempdir().unwrap();
    let ring = dir.path().join("row.cub");
    std::fs::write(&ring, "(0)\n(1)\n(2)\n").unwrap();
    let o = gmap(&["bench", "--json", "--periodic", p(&ring)]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stdout(&o).contains(r#""betti":[1,1]"#), "{}", stdout(&o));
}

#[test]
fn rows_hold_our_figures_only() {
    // the GUDHI column lives with the Python package and benches/anchors, not in the binary
    let o = gmap(&["bench", "--json", &lutz("Barnette_sphere.facets")]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: Value = serde_json::from_slice(&o.stdout).unwrap();
    let keys: Vec<&String> = v["rows"][0].as_object().unwrap().keys().collect();
    assert_eq!(
        keys,
        ["agree", "betti", "cells", "error", "groups", "input", "peak_rss_bytes", "route", "times_ms", "torsion"]
    );
    assert_eq!(gmap(&["bench", "--no-gudhi", &lutz("Barnette_sphere.facets")]).status.code(), Some(2));
}

#[test]
fn a_route_over_the_memory_policy_is_skipped_with_its_reason() {
    // Barnette's sphere as a 3-map has 456 darts (11 kB of involutions); its simplicial
    // counterpart is estimated at 2^4 (456 + 4) simplices of 72 bytes, 530 kB: over 100 kB
    let f = lutz("Barnette_sphere.facets");
    let o = gmap(&["bench", "--json", "--max-memory", "100K", &f]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: Value = serde_json::from_slice(&o.stdout).unwrap();
    let rows = v["rows"].as_array().unwrap();
    assert_eq!(rows.len(), 3, "{v}");
    assert_eq!(rows[0]["route"], "direct");
    assert_eq!(rows[1]["route"], "cellular");
    assert_eq!(rows[1]["groups"], "(Z, 0, 0, Z)");
    assert_eq!(rows[2]["route"], "simplicial");
    assert_eq!(rows[2]["betti"], Value::Null);
    assert_eq!(rows[2]["cells"], serde_json::json!([]));
    let why = rows[2]["error"].as_str().unwrap();
    assert!(why.starts_with("skipped: "), "{why}");
    assert!(why.contains("over the memory limit of 102400 bytes"), "{why}");
    // the skipped route takes no part in the agreement
    assert_eq!(rows[0]["agree"], true);
    // with the default policy the same route runs
    let o = gmap(&["bench", "--json", &f]);
    let v: Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["rows"][2]["groups"], "(Z, 0, 0, Z)");
}

#[test]
fn a_complex_without_a_gmap_has_a_direct_row() {
    // the dunce hat: a ridge in three facets, so no G-map; the direct route gives its groups
    let f = lutz("dunce_hat.facets");
    let o = gmap(&["bench", "--json", &f]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: Value = serde_json::from_slice(&o.stdout).unwrap();
    let rows = v["rows"].as_array().unwrap();
    assert_eq!(rows.len(), 3, "{v}");
    assert_eq!(rows[0]["route"], "direct");
    assert_eq!(rows[0]["cells"], serde_json::json!([8, 24, 17]));
    assert_eq!(rows[0]["groups"], "(Z, 0, 0)");
    assert_eq!(rows[0]["agree"], true);
    for r in &rows[1..] {
        assert_eq!(r["betti"], Value::Null);
        let why = r["error"].as_str().unwrap();
        assert!(why.starts_with("does not apply: ") && why.contains("not a pseudo-manifold"), "{why}");
    }
}

#[test]
fn every_row_has_its_peak_memory_and_a_cubical_set_its_one_pass_row() {
    let f = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/cubical/shell.cub");
    let f = f.to_str().unwrap();
    let o = gmap(&["bench", "--json", f, &lutz("Barnette_sphere.facets")]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: Value = serde_json::from_slice(&o.stdout).unwrap();
    let rows = v["rows"].as_array().unwrap();
    let routes: Vec<&str> = rows.iter().map(|r| r["route"].as_str().unwrap()).collect();
    assert_eq!(routes, ["one-pass", "slabs", "cubical", "direct", "cellular", "simplicial"], "{v}");
    // a hollow cube: H0 = Z, H2 = Z, by both routes
    assert_eq!(rows[0]["betti"], serde_json::json!([1, 0, 1, 0]));
    assert_eq!(rows[0]["betti"], rows[1]["betti"]);
    assert_eq!(rows[0]["betti"], rows[2]["betti"]);
    assert_eq!(rows[0]["agree"], true);
    // the high-water mark is reset per row on Linux; it counts at least the program itself
    if gmap_core::resources::reset_peak_rss() {
        for r in rows {
            let peak = r["peak_rss_bytes"].as_u64().unwrap_or_else(|| panic!("{r}"));
            assert!(peak > 1 << 20 && peak < 1 << 30, "{r}");
        }
    }
    let o = gmap(&["bench", "--csv", f]);
    let text = String::from_utf8(o.stdout).unwrap();
    assert!(text.lines().next().unwrap().ends_with(",agree,peak_rss_bytes"), "{text}");
    let o = gmap(&["bench", f]);
    let text = String::from_utf8(o.stdout).unwrap();
    assert!(text.lines().next().unwrap().ends_with("| agree | peak RSS MB |"), "{text}");
}
