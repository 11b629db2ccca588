//! `.moka` keeps a map's dimension (docs/FORMATS.md, `.moka`): Moka holds 3-maps, and a map
//! of lower dimension is written with its dimension recorded in the last mark mask, which
//! the reader restores. Conversions through `.moka` keep the dimension and the homology.

mod common;
use common::{gmap, p};
use std::path::Path;

fn homology_json(file: &Path) -> serde_json::Value {
    let o = gmap(&["homology", p(file), "--json"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    serde_json::from_slice(&o.stdout).unwrap()
}

/// The surface of a cube: 8 vertices, 6 quadrilaterals.
const CUBE_OFF: &str = "OFF
8 6 12
0 0 0
1 0 0
1 1 0
0 1 0
0 0 1
1 0 1
1 1 1
0 1 1
4 0 3 2 1
4 4 5 6 7
4 0 1 5 4
4 1 2 6 5
4 2 3 7 6
4 3 0 4 7
";

#[test]
fn a_cube_surface_through_moka_keeps_its_homology() {
    let dir = tempfile::tempdir().unwrap();
    let off = dir.path().join("cube.off");
    std::fs::write(&off, CUBE_OFF).unwrap();
    let moka = dir.path().join("cube.moka");
    let o = gmap(&["convert", p(&off), p(&moka)]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let a = homology_json(&off);
    let b = homology_json(&moka);
    assert_eq!(b["dimension"], 2);
    assert_eq!(b["betti"], serde_json::json!([1, 0, 1]));
    assert_eq!(a["betti"], b["betti"]);
    assert_eq!(a["torsion"], b["torsion"]);
    let text = String::from_utf8(gmap(&["homology", p(&moka)]).stdout).unwrap();
    assert!(text.contains("H_2 = Z"), "{text}");
    // the same 2-map as read from the .off, points included
    let orig = gmap_ops::import::read_off(&off).unwrap();
    assert_eq!(gmap_core::io::read_moka(&moka).unwrap(), orig);
    // and on to .gmap (which keeps no points): the same darts and involutions
    let back = dir.path().join("back.gmap");
    assert!(gmap(&["convert", p(&moka), p(&back)]).status.success());
    let m = gmap_core::io::read_gmap(&back).unwrap();
    assert_eq!((m.dim(), m.flat()), (2, orig.flat()));
}

#[test]
fn three_maps_round_trip_unchanged() {
    let dir = tempfile::tempdir().unwrap();
    for (k, m) in
        [gmap_ops::build::cube(3).unwrap(), gmap_ops::build::grid(&[2, 1, 1], &[true; 3]).unwrap()].iter().enumerate()
    {
        let g = dir.path().join(format!("m{k}.gmap"));
        gmap_core::io::write_gmap(m, &g).unwrap();
        let moka = dir.path().join(format!("m{k}.moka"));
        assert!(gmap(&["convert", p(&g), p(&moka)]).status.success());
        let text = std::fs::read_to_string(&moka).unwrap();
        assert!(text.starts_with("Moka file [ascii]\n0 0 0 0 0 0 0 0\n"), "{text}");
        assert_eq!(&gmap_core::io::read_moka(&moka).unwrap(), m);
        assert_eq!(homology_json(&g)["betti"], homology_json(&moka)["betti"]);
    }
}

#[test]
fn every_lower_dimension_round_trips() {
    let dir = tempfile::tempdir().unwrap();
    for m in [gmap_core::examples::cylinder(), gmap_core::examples::fig1_surface()] {
        let moka = dir.path().join("x.moka");
        gmap_core::io::write_moka(&m, &moka).unwrap();
        assert_eq!(gmap_core::io::read_moka(&moka).unwrap(), m);
    }
}
