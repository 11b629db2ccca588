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
