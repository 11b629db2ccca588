//! The `.json` architectural complex on hostile inputs, through the `gmap` binary: a key
//! repeated in an object is refused with the key and its line, and a map that fails the
//! cellular condition C2 is not converted to `.json` (its complex would have other groups).

mod common;
use common::{gmap, p, stderr};

use std::path::Path;
use std::process::Output;

/// Asserts exit code 1 and one `error:` line containing each of `needles`.
fn refused(o: &Output, needles: &[&str]) {
    let err = stderr(o);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(err.starts_with("error: ") && err.lines().count() == 1, "{err}");
    for n in needles {
        assert!(err.contains(n), "{err} should contain {n}");
    }
}

fn write(dir: &Path, name: &str, text: &str) -> std::path::PathBuf {
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path
}

#[test]
fn repeated_keys_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    let regions_twice = write(
        dir.path(),
        "regions.json",
        "{\"dimension\": 0,\n \"regions\": [{\"id\": 0, \"dim\": 0}],\n \"regions\": [],\n \"incidence\": []}\n",
    );
    let dim_twice =
        write(dir.path(), "dim.json", "{\"regions\": [{\"id\":0,\"dim\":0,\"dim\":1}], \"incidence\": []}\n");
    let unknown_twice = write(
        dir.path(),
        "note.json",
        "{\"regions\": [{\"id\": 0, \"dim\": 0}], \"incidence\": [], \"note\": 1, \"note\": 2}\n",
    );
    for cmd in ["info", "homology"] {
        refused(&gmap(&[cmd, p(&regions_twice)]), &["regions.json", "line 3", "\"regions\" appears twice"]);
        refused(&gmap(&[cmd, p(&dim_twice)]), &["dim.json", "line 1", "\"dim\" appears twice"]);
        refused(&gmap(&[cmd, p(&unknown_twice)]), &["note.json", "\"note\" appears twice"]);
    }
    let out = dir.path().join("out.dot");
    refused(&gmap(&["convert", p(&dim_twice), p(&out)]), &["\"dim\" appears twice"]);
    assert!(!out.exists());
    // the same objects without the repetition are read
    let fine = write(dir.path(), "fine.json", "{\"regions\": [{\"id\":0,\"dim\":0}], \"incidence\": []}\n");
    let o = gmap(&["homology", p(&fine), "--json"]);
    assert!(o.status.success(), "{}", stderr(&o));
}

/// The torus (one vertex, two edges, one square) as the boundary of one 3-cell: every
/// dart 3-free. Its cells satisfy C1 but the 3-cell is not bounded by a sphere (C2).
fn torus_bounded_cell() -> String {
    let torus = gmap_core::examples::torus();
    let mut text = format!("gmap 3 {}\n", torus.dart_count());
    for d in torus.darts() {
        let row: Vec<String> = torus.row(d).iter().map(u32::to_string).collect();
        text.push_str(&format!("{} {}\n", row.join(" "), d.index()));
    }
    text
}

#[test]
fn a_map_failing_c2_is_not_converted_to_json() {
    let dir = tempfile::tempdir().unwrap();
    let map = write(dir.path(), "solid.gmap", &torus_bounded_cell());
    let out = dir.path().join("solid.json");
    refused(&gmap(&["convert", p(&map), p(&out)]), &["solid.json", "the 3-cell of dart 0", "condition C2"]);
    assert!(!out.exists());
    // the cellular method refuses the same cell; the map itself is read
    refused(&gmap(&["homology", p(&map)]), &["the 3-cell of dart 0", "condition C2"]);
    assert!(gmap(&["info", p(&map)]).status.success());
    // the torus alone (C2 holds below dimension 3) converts and keeps its groups
    let torus = dir.path().join("torus.gmap");
    gmap_core::io::write_gmap(&gmap_core::examples::torus(), &torus).unwrap();
    let json = dir.path().join("torus.json");
    let o = gmap(&["convert", p(&torus), p(&json)]);
    assert!(o.status.success(), "{}", stderr(&o));
    // the same groups; the .json report adds which space it computed
    let o = common::stdout(&gmap(&["homology", p(&json)]));
    let (groups, space) = o.split_at(o.find("space: the region complex").expect("the space stated"));
    assert_eq!(groups, common::stdout(&gmap(&["homology", p(&torus)])));
    assert_eq!(space.lines().count(), 1, "a torus of cells: no hint");
}
