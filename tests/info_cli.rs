//! `gmap info` end to end (docs/FORMATS.md): exact JSON on good `.gmap` and `.moka` files, and
//! for every kind of bad input exit code 1 with one line `error: FILE:LINE: …` on stderr.

mod common;
use common::gmap;
use std::path::{Path, PathBuf};

use serde_json::json;

fn write(dir: &Path, name: &str, bytes: &[u8]) -> PathBuf {
    let p = dir.join(name);
    std::fs::write(&p, bytes).unwrap();
    p
}

fn info_json(path: &Path) -> serde_json::Value {
    let out = gmap(&["info", path.to_str().unwrap(), "--json"]);
    assert_eq!(out.status.code(), Some(0), "stderr: {}", String::from_utf8_lossy(&out.stderr));
    assert!(out.stderr.is_empty());
    serde_json::from_slice(&out.stdout).expect("one JSON object on stdout")
}

/// Runs `gmap info` on a file holding `bytes`; checks exit code 1 and a single stderr line
/// `error: PATH:LINE: …`; returns the message after the line number.
fn bad(name: &str, bytes: &[u8], line: usize) -> String {
    let dir = tempfile::tempdir().unwrap();
    let p = write(dir.path(), name, bytes);
    let out = gmap(&["info", p.to_str().unwrap(), "--json"]);
    let err = String::from_utf8(out.stderr).unwrap();
    assert_eq!(out.status.code(), Some(1), "stderr: {err}");
    assert!(out.stdout.is_empty(), "nothing on stdout on error");
    assert_eq!(err.lines().count(), 1, "one line: {err}");
    let prefix = format!("error: {}:{line}: ", p.display());
    assert!(err.starts_with(&prefix), "expected prefix {prefix:?}, got {err:?}");
    err[prefix.len()..].trim_end().to_string()
}

#[test]
fn good_gmap_exact_json() {
    let dir = tempfile::tempdir().unwrap();
    // BO Fig. 2, the cylinder: darts 1..8 of the paper are 0..7 here
    let text = "# the cylinder of BO Fig. 2\ngmap 2 8\n1 7 5\n0 2 4\n3 1 2\n2 4 3\n5 3 1\n4 6 0\n7 5 6\n6 0 7\n";
    let p = write(dir.path(), "cylinder.gmap", text.as_bytes());
    assert_eq!(
        info_json(&p),
        json!({"dimension": 2, "darts": 8, "cells": [2, 3, 1], "components": 1, "valid": true,
               "complete_boundaries": true, "orientable": true, "euler_characteristic": 0,
               "points": false, "labels": []})
    );
    // a segment: one edge, two vertices
    let p = write(dir.path(), "segment.gmap", b"gmap 1 2\n1 0\n0 1\n");
    assert_eq!(
        info_json(&p),
        json!({"dimension": 1, "darts": 2, "cells": [2, 1], "components": 1, "valid": true,
               "complete_boundaries": true, "orientable": true, "euler_characteristic": 1,
               "points": false, "labels": []})
    );
    // one 0-free dart: an edge with an incomplete boundary (BO Def. 6 fails)
    let p = write(dir.path(), "half.gmap", b"gmap 1 1\n0 0\n");
    assert_eq!(
        info_json(&p),
        json!({"dimension": 1, "darts": 1, "cells": [1, 1], "components": 1, "valid": true,
               "complete_boundaries": false, "orientable": true, "euler_characteristic": 0,
               "points": false, "labels": []})
    );
}

#[test]
fn good_moka_exact_json() {
    let dir = tempfile::tempdir().unwrap();
    // the Klein bottle of BO Fig. 4(b), embedded in dimension 3 (alpha_3 the identity)
    let text = "Moka file [ascii]\n0 0 0 0 0 0 0 0\n\
        1 7 5 0 0 0 0 0 1 0 0 0\n0 2 4 1 0 0 0 0 1 1 0 0\n3 1 6 2 0 0 0 0 0\n2 4 7 3 0 0 0 0 0\n\
        5 3 1 4 0 0 0 0 0\n4 6 0 5 0 0 0 0 0\n7 5 2 6 0 0 0 0 0\n6 0 3 7 0 0 0 0 0\n";
    let p = write(dir.path(), "klein.moka", text.as_bytes());
    assert_eq!(
        info_json(&p),
        json!({"dimension": 3, "darts": 8, "cells": [1, 2, 1, 1], "components": 1, "valid": true,
               "complete_boundaries": true, "orientable": false, "euler_characteristic": -1,
               "points": true, "labels": []})
    );
}

#[test]
fn human_output_is_aligned_lines() {
    let dir = tempfile::tempdir().unwrap();
    let p = write(dir.path(), "c.gmap", b"gmap 1 2\n1 1\n0 0\n");
    let out = gmap(&["info", p.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(0));
    let text = String::from_utf8(out.stdout).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len(), 11);
    assert_eq!(lines[1], "dimension             1");
    assert_eq!(lines[2], "darts                 2");
    assert_eq!(lines[3], "cells (0..n)          1 1");
    assert_eq!(lines[6], "complete boundaries   yes");
    assert_eq!(lines[8], "euler characteristic  0");
    assert_eq!(lines[9], "points                no");
    assert_eq!(lines[10], "labels                none");
}

#[test]
fn wrong_header() {
    assert_eq!(bad("h.gmap", b"gmap2 3\n", 1), "bad header: expected `gmap <n> <number of darts>`, found `gmap2 3`");
    assert_eq!(bad("h.moka", b"Moka file\n", 1), "bad header: expected `Moka file [ascii]`, found `Moka file`");
}

#[test]
fn dart_count_mismatch() {
    assert_eq!(
        bad("few.gmap", b"gmap 1 3\n0 0\n1 1\n", 4),
        "truncated: the header announces 3 darts but the file ends after 2"
    );
    assert_eq!(bad("many.gmap", b"gmap 1 1\n0 0\n0 0\n", 3), "more dart lines than the 1 darts the header announces");
}

#[test]
fn index_out_of_range() {
    assert_eq!(
        bad("r.gmap", b"gmap 1 2\n0 0\n1 7\n", 3),
        "not a G-map (BO Def. 1): dart 1 is linked along alpha_1 to dart 7, which does not exist (the map has 2 darts)"
    );
    assert_eq!(
        bad("r.moka", b"Moka file [ascii]\n0 0 0 0 0 0 0 0\n0 0 0 9 0 0 0 0 0\n", 3),
        "not a G-map (BO Def. 1): dart 0 is linked along alpha_3 to dart 9, which does not exist (the map has 1 darts)"
    );
}

#[test]
fn not_an_involution() {
    assert_eq!(
        bad("i.gmap", b"gmap 0 3\n1\n2\n0\n", 2),
        "not a G-map (BO Def. 1): dart 0 is linked along alpha_0 to dart 1, which is linked back to dart 2 instead"
    );
}

#[test]
fn alpha_i_alpha_j_not_an_involution() {
    assert_eq!(
        bad("c.gmap", b"gmap 2 4\n1 0 0\n0 1 2\n3 2 1\n2 3 3\n", 2),
        "not a G-map (BO Def. 1): the links alpha_0 and alpha_2 do not commute at dart 0: alpha_0, alpha_2, alpha_0, alpha_2 from it lead to dart 3, not back to it"
    );
}

#[test]
fn huge_dimension() {
    assert_eq!(
        bad("d.gmap", b"gmap 4000000000 1\n0\n", 1),
        "dimension 4000000000 is larger than the supported maximum 30"
    );
    assert_eq!(
        bad("n.gmap", b"gmap 30 18446744073709551615\n", 1),
        "18446744073709551615 darts is more than a map can hold (at most 4294967294 darts)"
    );
}

#[test]
fn truncated() {
    assert_eq!(bad("t.gmap", b"gmap 2 2\n1 0 0\n0 1", 3), "dart 1: expected 3 values, found 2");
    assert_eq!(
        bad("t.moka", b"Moka file [ascii]\n0 0 0 0 0 0 0 0\n0 0 0 0 0 0 0 0 1 0.5 1", 3),
        "dart 0: expected 9 or 12 values, found 11"
    );
}

#[test]
fn empty() {
    assert_eq!(bad("e.gmap", b"", 1), "the file is empty: expected the header `gmap <n> <number of darts>`");
    assert_eq!(bad("e.moka", b"\n\n", 3), "the file is empty: expected the header `Moka file [ascii]`");
}

#[test]
fn not_utf8() {
    assert_eq!(bad("u.gmap", b"gmap 0 1\n\xfe\n", 2), "not UTF-8 text: invalid byte at offset 9");
}

#[test]
fn negative_or_non_numeric_tokens() {
    assert_eq!(bad("m.gmap", b"gmap 1 2\n-1 0\n", 2), "dart 0, alpha_0: `-1` is negative");
    assert_eq!(bad("x.gmap", b"gmap 1 2\n1 0\n0 one\n", 3), "dart 1, alpha_1: `one` is not a non-negative integer");
    assert_eq!(bad("h.gmap", b"gmap two 2\n", 1), "header dimension: `two` is not a non-negative integer");
}

#[test]
fn missing_file_and_dart_limit() {
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("none.gmap");
    let out = gmap(&["info", p.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(1));
    let err = String::from_utf8(out.stderr).unwrap();
    assert!(err.starts_with(&format!("error: {}: cannot read the file", p.display())), "{err}");
    let p = write(dir.path(), "two.gmap", b"gmap 0 2\n1\n0\n");
    let out = gmap(&["info", p.to_str().unwrap(), "--max-darts", "1"]);
    assert_eq!(out.status.code(), Some(1));
}

#[test]
fn bad_usage_exits_2() {
    assert_eq!(gmap(&["info"]).status.code(), Some(2));
    assert_eq!(gmap(&["info", "x.gmap", "--no-such-flag"]).status.code(), Some(2));
}

/// A simplicial complex without a G-map (a ridge in three facets, mixed dimensions): `info`
/// prints its simplices, components and Euler characteristic, with `"gmap": null` and why.
#[test]
fn simplicial_complex_without_a_gmap() {
    let dir = tempfile::tempdir().unwrap();
    // a book of three triangles, a dangling edge, an isolated vertex
    let p = write(dir.path(), "book.facets", b"1 2 3\n1 2 4\n1 2 5\n5 6\n9\n");
    let v = info_json(&p);
    assert_eq!(v["dimension"], 2);
    assert_eq!(v["cells"], json!([7, 8, 3]));
    assert_eq!(v["components"], 2);
    assert_eq!(v["euler_characteristic"], 2);
    assert_eq!(v["darts"], 0);
    assert_eq!(v["valid"], true);
    assert!(v["gmap"].is_null() && v.as_object().unwrap().contains_key("gmap"));
    let why = v["why"].as_str().unwrap();
    // the first cause: the facets' mixed dimensions (the book's ridge in 3 facets comes after)
    assert!(why.contains("facet on line 4 has 2 vertices, but the largest facets have 3: mixed dimensions"), "{why}");
    let o = gmap(&["info", p.to_str().unwrap()]);
    assert!(o.status.success());
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(
        text.contains("simplices (0..n)      7 8 3") && text.contains("gmap  ") && text.contains("mixed dimensions"),
        "{text}"
    );
    // mixed dimensions only
    let p = write(dir.path(), "mixed.facets", b"1 2 3\n3 4\n");
    let v = info_json(&p);
    assert_eq!((v["cells"].clone(), v["components"].clone()), (json!([4, 4, 1]), json!(1)));
    assert!(v["why"].as_str().unwrap().contains("mixed dimensions"), "{v}");
    // the Lutz dunce hat, and a complex over the dart limit that is not pure
    let lutz = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/lutz");
    let v = info_json(&lutz.join("dunce_hat.facets"));
    assert_eq!((v["cells"].clone(), v["euler_characteristic"].clone()), (json!([8, 24, 17]), json!(1)));
    let v = info_json(&lutz.join("contractible_vertex-homogeneous.facets"));
    assert_eq!(v["dimension"], 11);
    assert_eq!(v["euler_characteristic"], 1);
    assert!(v["gmap"].is_null() && v["why"].as_str().unwrap().contains("mixed dimensions"), "{v}");
}

/// A quadratic mesh written by gmsh (tests/data/mesh/make.py): read as its corner cells,
/// and `info` says so, naming the label that keeps the other nodes.
#[test]
fn higher_order_mesh_is_said_to_be_read_as_its_corners() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let p = root.join("tests/data/mesh/cube_o2_41.msh");
    let out = gmap(&["info", p.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(0), "stderr: {}", String::from_utf8_lossy(&out.stderr));
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.contains("cells (0..n)          45 186 242 100\n"), "{text}");
    assert!(
        text.contains(
            "higher order          184 cells read as their corner cells; their other nodes are kept in the label high_order.nodes\n"
        ),
        "{text}"
    );
}
