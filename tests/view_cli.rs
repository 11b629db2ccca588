//! `gmap view`: the page it writes for each kind of input, its flags and its refusals.

mod common;

use common::{gmap, p, stderr, stdout};

#[test]
fn view_writes_a_page_for_each_kind_of_input() {
    let dir = tempfile::tempdir().unwrap();
    let data = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data");
    for (file, generator) in [
        ("lutz/poincare.facets", "H3 #0 (Z)"),
        ("cubical/ring.cub", "H1 #0 (Z)"),
        ("arch/tetrahedron.json", "H0 #0 (Z)"),
        ("labelled_segment.gmap", "H0 #0 (Z)"),
    ] {
        let out = dir.path().join("page.html");
        let o = gmap(&["view", p(&data.join(file)), "-o", p(&out), "--generators"]);
        assert!(o.status.success(), "{file}: {}", stderr(&o));
        assert_eq!(stdout(&o), format!("wrote {}\n", out.display()));
        let page = std::fs::read_to_string(&out).unwrap();
        assert!(page.starts_with("<!DOCTYPE html>"), "{file}");
        assert!(page.contains(generator), "{file}: no {generator}");
        assert!(!page.contains("http://") && !page.contains("https://"), "{file}");
    }
}

#[test]
fn a_complex_without_a_gmap_is_drawn_by_its_faces() {
    // the dunce hat: ridges in three facets, so no G-map; its 8 vertices, 24 edges and 17
    // triangles are the page's cells, and it is contractible (one H0 generator, no other)
    let dir = tempfile::tempdir().unwrap();
    let data = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/lutz/dunce_hat.facets");
    let out = dir.path().join("hat.html");
    let o = gmap(&["view", p(&data), "-o", p(&out), "--generators"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let page = std::fs::read_to_string(&out).unwrap();
    assert!(page.contains("drawn by its faces"));
    assert!(page.contains("H0 #0 (Z)") && !page.contains("H1 #0"));
    let scene = gmap::view::scene(&gmap::open(&data).unwrap(), &gmap::ViewOptions::default()).unwrap();
    assert_eq!(scene.counts(), [8, 24, 17]);
}

#[test]
fn view_refuses_an_unknown_label_and_a_missing_file() {
    let dir = tempfile::tempdir().unwrap();
    let data = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data");
    let out = dir.path().join("x.html");
    let o = gmap(&["view", p(&data.join("lutz/poincare.facets")), "-o", p(&out), "--color-by", "room"]);
    assert_eq!(o.status.code(), Some(1));
    assert_eq!(stderr(&o), "error: no cell has a label named `room` (labels: none)\n");
    assert!(!out.exists());
    // a label that is there colours the cells
    let o = gmap(&["view", p(&data.join("labelled_segment.gmap")), "-o", p(&out), "--color-by", "hits"]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(std::fs::read_to_string(&out).unwrap().contains(r#""colorBy":"hits""#));
    std::fs::remove_file(&out).unwrap();
    let o = gmap(&["view", p(&dir.path().join("none.gmap")), "-o", p(&out)]);
    assert_eq!(o.status.code(), Some(1));
    assert!(!out.exists());
}
