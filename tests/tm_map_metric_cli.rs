//! `gmap tm check` on a G-map with points runs the metrical edit (TM §X) too: a surface whose
//! vertex lies inside another face, or with two vertices at one point, fails it with the
//! cells named as the topological check names them; the same surface with its points in
//! place passes.

mod common;
use common::{gmap, p, stdout};

/// Two triangles sharing the edge 0-2, their fourth vertex at `v3`.
fn square(dir: &std::path::Path, name: &str, v3: &str) -> std::path::PathBuf {
    let path = dir.join(name);
    std::fs::write(&path, format!("OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n{v3}\n3 0 1 2\n3 0 2 3\n")).unwrap();
    path
}

#[test]
fn a_surface_with_points_gets_the_metrical_edit() {
    let dir = tempfile::tempdir().unwrap();
    let o = gmap(&["tm", "check", p(&square(dir.path(), "ok.off", "0 1 0"))]);
    assert!(o.status.success());
    assert!(
        stdout(&o).ends_with("metrical edit (TM X, tolerance 1e-8): no defect\npasses the edit check\n"),
        "{}",
        stdout(&o)
    );

    let o = gmap(&["tm", "check", p(&square(dir.path(), "inside.off", "0.8 0.2 0"))]);
    assert_eq!(o.status.code(), Some(1));
    let out = stdout(&o);
    assert!(out.contains("metrical edit (TM X, tolerance 1e-8): 3 defects\n"), "{out}");
    assert!(out.contains("  point 0-cell 3 lies inside face 2-cell 9\n"), "{out}");
    assert!(out.contains("  edge 1-cell 7 lies inside face 2-cell 9 (a T-junction)\n"), "{out}");
    assert!(out.ends_with("fails the edit check\n"), "{out}");

    let o = gmap(&["tm", "check", p(&square(dir.path(), "twice.off", "1 0 0"))]);
    assert_eq!(o.status.code(), Some(1));
    assert!(
        stdout(&o).contains("  points 0-cell 1 and 0-cell 3 are 0.00e0 apart: the same point twice\n"),
        "{}",
        stdout(&o)
    );
}

#[test]
fn a_map_without_points_has_no_metrical_edit() {
    // the segment of tests/data/labelled_segment.gmap without its points
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("segment.gmap");
    std::fs::write(&path, "gmap 1 2\n1 0\n0 1\n").unwrap();
    let o = gmap(&["tm", "check", p(&path)]);
    assert!(o.status.success());
    assert!(stdout(&o).contains("passes the edit check"), "{}", stdout(&o));
    assert!(!stdout(&o).contains("metrical edit"), "{}", stdout(&o));
    let o = gmap(&[
        "tm",
        "check",
        p(&std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/labelled_segment.gmap")),
    ]);
    assert!(stdout(&o).contains("metrical edit (TM X, tolerance 3.5e-8): no defect\n"), "{}", stdout(&o));
}
