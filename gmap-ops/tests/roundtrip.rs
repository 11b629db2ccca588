//! Round trips: `.facets` → map → barycentric `.facets` → map keeps χ; `.off` → map →
//! `.off` → map is isomorphic; `.gmap` and `.moka` likewise.

use gmap_core::DenseMap;
use gmap_ops::export::{barycentric_facets_string, off_string, write_barycentric_facets, write_off};
use gmap_ops::import::{read_facets, read_off, PolygonMesh, SimplicialComplex};
use gmap_ops::{build, iso};

fn lutz(name: &str) -> String {
    let dir = std::env::var("GMAP_LUTZ")
        .unwrap_or_else(|_| concat!(env!("CARGO_MANIFEST_DIR"), "/../tests/data/lutz").to_string());
    std::fs::read_to_string(format!("{dir}/{name}.facets")).unwrap()
}

fn barycentric_roundtrip(m: &DenseMap) -> DenseMap {
    let text = barycentric_facets_string(m).unwrap();
    let sc = SimplicialComplex::parse_facets(&text).unwrap();
    assert_eq!(sc.facet_count(), m.dart_count());
    sc.to_gmap(u64::MAX).unwrap()
}

#[test]
fn barycentric_keeps_euler_characteristic() {
    for (name, chi) in [("poincare", 0), ("d2n12g6", -10), ("regular_2_21_23_1", -28), ("rudin", 1), ("RP4", 1)] {
        let sc = SimplicialComplex::parse_facets(&lutz(name)).unwrap();
        let m = sc.to_gmap(u64::MAX).unwrap();
        assert_eq!(m.euler_characteristic(), chi, "{name}");
        if m.dart_count() > 5_000 {
            continue;
        }
        let b = barycentric_roundtrip(&m);
        b.validate().unwrap();
        assert_eq!(b.dart_count(), m.dart_count() * (1..=m.dim() + 1).product::<usize>());
        assert_eq!(b.euler_characteristic(), chi, "{name}");
        assert_eq!(b.is_orientable(), m.is_orientable(), "{name}");
    }
    // builders whose cells are regular: the simplex and the cube
    for m in [build::simplex(3).unwrap(), build::cube(3).unwrap(), build::cube(2).unwrap()] {
        let b = barycentric_roundtrip(&m);
        assert_eq!(b.euler_characteristic(), 1);
        assert_eq!(b.cell_counts()[0], m.cell_counts().iter().sum::<usize>());
    }
}

#[test]
fn barycentric_file_roundtrip() {
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("b.facets");
    let m = build::grid(&[2, 2], &[false, false]).unwrap();
    write_barycentric_facets(&m, &p).unwrap();
    let b = read_facets(&p, None).unwrap();
    assert_eq!(b.cell_counts(), vec![25, 56, 32]);
    assert_eq!(b.euler_characteristic(), 1);
}

const MOEBIUS: &str = "OFF
# a Moebius band of 4 quads: the last quad is glued with a twist
8 4 0
0 0 0
1 0 0
2 0 0
3 0 0
0 1 0
1 1 0
2 1 0
3 1 0
4 0 1 5 4
4 1 2 6 5
4 2 3 7 6
4 3 4 0 7
";

const OCTAHEDRON: &str = "OFF
6 8 12
1 0 0
-1 0 0
0 1 0
0 -1 0
0 0 1
0 0 -1
3 0 2 4
3 2 1 4
3 1 3 4
3 3 0 4
3 2 0 5
3 1 2 5
3 3 1 5
3 0 3 5
";

#[test]
fn off_roundtrip_is_isomorphic() {
    let dir = tempfile::tempdir().unwrap();
    for (name, text, cells, orientable) in
        [("moebius", MOEBIUS, vec![8, 12, 4], false), ("octahedron", OCTAHEDRON, vec![6, 12, 8], true)]
    {
        let m = PolygonMesh::parse(text).unwrap().to_gmap().unwrap();
        m.validate().unwrap();
        assert_eq!(m.cell_counts(), cells, "{name}");
        assert_eq!(m.is_orientable(), orientable, "{name}");
        let p = dir.path().join(format!("{name}.off"));
        write_off(&m, &p).unwrap();
        let back = read_off(&p).unwrap();
        assert!(iso::are_isomorphic(&m, &back), "{name}");
        // and the text is stable from then on
        assert_eq!(off_string(&back).unwrap(), std::fs::read_to_string(&p).unwrap());
    }
    // builders with points: a prism's top and bottom faces are not a surface, but a polygon is
    let pentagon = build::polygon(5).unwrap();
    let back = PolygonMesh::parse(&off_string(&pentagon).unwrap()).unwrap().to_gmap().unwrap();
    assert!(iso::are_isomorphic(&pentagon, &back));
    assert_eq!(back.vertex_point(gmap_core::Dart::new(0)), Some([1.0, 0.0, 0.0]));
}

#[test]
fn gmap_and_moka_roundtrips_are_isomorphic() {
    let dir = tempfile::tempdir().unwrap();
    let objects = [
        build::schema("a b a B").unwrap(),
        build::cube(3).unwrap(),
        build::lens_space(5, 2).unwrap(),
        build::grid(&[2, 2, 2, 1], &[true, false, true, false]).unwrap(),
        build::extrude(&build::polygon(4).unwrap()).unwrap(),
    ];
    for (k, m) in objects.iter().enumerate() {
        let p = dir.path().join(format!("m{k}.gmap"));
        gmap_core::io::write_gmap(m, &p).unwrap();
        let back = gmap_core::io::read_gmap(&p).unwrap();
        assert!(iso::are_isomorphic(m, &back), "gmap {k}");
        if m.dim() == 3 {
            let p = dir.path().join(format!("m{k}.moka"));
            gmap_core::io::write_moka(m, &p).unwrap();
            let back = gmap_core::io::read_moka(&p).unwrap();
            assert!(iso::are_isomorphic(m, &back), "moka {k}");
        }
    }
}
