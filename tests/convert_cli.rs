//! `gmap convert` and `gmap demo` end to end, through the binary.

mod common;
use common::{gmap, p, stderr};

use gmap_ops::iso;

const TORUS_FACETS: &str = "# Moebius' 7-vertex torus
1 2 4\n2 3 5\n3 4 6\n4 5 7\n5 6 1\n6 7 2\n7 1 3
1 3 4\n2 4 5\n3 5 6\n4 6 7\n5 7 1\n6 1 2\n7 2 3
";

#[test]
fn demo_prints_every_classic_object() {
    let o = gmap(&["demo"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let out = String::from_utf8(o.stdout).unwrap();
    for name in [
        "sphere",
        "torus",
        "Klein bottle",
        "projective plane",
        "cylinder",
        "Moebius band",
        "solid cube",
        "3-torus",
        "L(5,2)",
    ] {
        assert!(out.contains(name), "{name} missing from\n{out}");
    }
    let torus = out.lines().find(|l| l.starts_with("torus")).unwrap();
    let cols: Vec<&str> = torus.split_whitespace().collect();
    // name "torus (a b A B)" (5 words), dim, darts, 3 cell counts, chi, orientable
    assert_eq!(&cols[5..12], &["2", "8", "1", "2", "1", "0", "yes"]);
    let lens = out.lines().find(|l| l.contains("L(5,2)")).unwrap();
    assert!(lens.contains(" 20 ") && lens.contains("1 1 1 1"), "{lens}");
}

#[test]
fn facets_to_gmap_moka_and_barycentric() {
    let dir = tempfile::tempdir().unwrap();
    let src = dir.path().join("torus.facets");
    std::fs::write(&src, TORUS_FACETS).unwrap();
    let g = dir.path().join("torus.gmap");
    let o = gmap(&["convert", p(&src), p(&g)]);
    assert!(o.status.success(), "{}", stderr(&o));
    let m = gmap_core::io::read_gmap(&g).unwrap();
    assert_eq!(m.dart_count(), 14 * 6);
    assert_eq!(m.cell_counts(), vec![7, 21, 14]);
    let k = dir.path().join("torus.moka");
    assert!(gmap(&["convert", p(&g), p(&k)]).status.success());
    let back = gmap_core::io::read_moka(&k).unwrap();
    // Moka holds 3-maps; the file records dimension 2 and the torus comes back as a 2-map
    assert_eq!(back.cell_counts(), vec![7, 21, 14]);
    assert_eq!(back, m);
    let b = dir.path().join("torus-bary.facets");
    assert!(gmap(&["convert", p(&g), p(&b)]).status.success());
    let bary = gmap_ops::import::read_facets(&b, None).unwrap();
    assert_eq!(bary.cell_counts(), vec![42, 126, 84]);
}

#[test]
fn off_roundtrip_through_the_binary() {
    let dir = tempfile::tempdir().unwrap();
    let src = dir.path().join("strip.off");
    // a Moebius band of three quads, one of them reversed
    std::fs::write(&src, "OFF\n6 3 0\n0 0 0\n1 0 0\n2 0 0\n0 1 0\n1 1 0\n2 1 0\n4 0 1 4 3\n4 1 2 5 4\n4 2 3 0 5\n")
        .unwrap();
    let out = dir.path().join("again.off");
    let o = gmap(&["convert", p(&src), p(&out)]);
    assert!(o.status.success(), "{}", stderr(&o));
    let a = gmap_ops::import::read_off(&src).unwrap();
    let b = gmap_ops::import::read_off(&out).unwrap();
    assert!(!a.is_orientable());
    assert!(iso::are_isomorphic(&a, &b));
}

#[test]
fn lex_by_name() {
    let dir = tempfile::tempdir().unwrap();
    let src = dir.path().join("two.lex");
    std::fs::write(&src, "circle=[[1,2],[2,3],[1,3]]\nmanifold_2_4_#1=[[1,2,3],[1,2,4],\n[1,3,4],[2,3,4]]\n").unwrap();
    let out = dir.path().join("s.gmap");
    let arg = format!("{}#manifold_2_4_#1", p(&src));
    let o = gmap(&["convert", &arg, p(&out)]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(gmap_core::io::read_gmap(&out).unwrap().cell_counts(), vec![4, 6, 4]);
    assert!(gmap(&["convert", p(&src), p(&out)]).status.success());
    assert_eq!(gmap_core::io::read_gmap(&out).unwrap().cell_counts(), vec![3, 3]);
    let bad = format!("{}#nothing", p(&src));
    let o = gmap(&["convert", &bad, p(&out)]);
    assert_eq!(o.status.code(), Some(1));
    assert!(stderr(&o).contains("no complex named 'nothing'"), "{}", stderr(&o));
}

#[test]
fn bad_inputs_exit_1_naming_the_place_and_write_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out.gmap");
    let cases = [
        ("ridge.facets", "1 2 3\n1 2 4\n1 2 5\n", "ridge [1, 2] lies in 3 facets (lines [1, 2, 3])"),
        ("mixed.facets", "1 2 3\n# c\n4 5\n", "facet on line 3 has 2 vertices"),
        ("repeat.facets", "1 2 3\n1 1 4\n", "facet on line 2 repeats vertex 1"),
        ("word.facets", "1 2 x\n", "line 1: 'x' is not a vertex label"),
        (
            "fan.off",
            "OFF\n4 3 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n3 0 1 3\n3 1 0 2\n",
            "edge 0-1 lies in 3 polygons",
        ),
        ("short.off", "OFF\n3 1 0\n0 0 0\n", "line 2: expected 3 vertices"),
    ];
    for (name, text, expect) in cases {
        let src = dir.path().join(name);
        std::fs::write(&src, text).unwrap();
        let o = gmap(&["convert", p(&src), p(&out)]);
        assert_eq!(o.status.code(), Some(1), "{name}");
        let e = stderr(&o);
        assert!(e.starts_with("error: ") && e.contains(name) && e.contains(expect), "{name}: {e}");
        assert_eq!(e.lines().count(), 1, "{e}");
        assert!(!out.exists(), "{name}");
    }
    // too many darts, refused before allocating
    let src = dir.path().join("big.facets");
    std::fs::write(&src, "1 2 3 4 5 6 7 8 9 10 11 12 13 14\n").unwrap();
    let o = gmap(&["convert", p(&src), p(&out)]);
    assert_eq!(o.status.code(), Some(1));
    assert!(stderr(&o).contains("87178291200 darts"), "{}", stderr(&o));
    let o = gmap(&["convert", "--max-darts", "5", p(&dir.path().join("ridge.facets")), p(&out)]);
    assert!(stderr(&o).contains("over the limit of 5"), "{}", stderr(&o));
    // formats that cannot hold the map
    let src = dir.path().join("tet.facets");
    std::fs::write(&src, "1 2 3 4\n").unwrap();
    for bad in ["x.off", "x.xyz"] {
        let o = gmap(&["convert", p(&src), p(&dir.path().join(bad))]);
        assert_eq!(o.status.code(), Some(1), "{bad}");
        assert!(!dir.path().join(bad).exists());
    }
    let names: Vec<String> =
        std::fs::read_dir(dir.path()).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
    assert!(names.iter().all(|n| !n.contains("tmp")), "{names:?}");
}

/// `.gmap` to `.gmap` keeps the points and the labels of every dimension; `.gmap` to `.moka`
/// keeps the points.
#[test]
fn gmap_to_gmap_keeps_points_and_labels() {
    let dir = tempfile::tempdir().unwrap();
    let input = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/labelled_segment.gmap");
    let out = dir.path().join("copy.gmap");
    let o = gmap(&["convert", p(&input), p(&out)]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(&out).unwrap();
    assert_eq!(
        text,
        "gmap 1 2\n1 0\n0 1\npoints 2\n0 0.0 0.0 0.0\n1 2.5 0.0 -1.0\nlabels 0 1\n1 hits=3\nlabels 1 1\n0 name=\"main \\\"beam\\\"\" length=2.5\n"
    );
    // .moka keeps the points, not the labels: refused without --lossy
    let moka = dir.path().join("copy.moka");
    let o = gmap(&["convert", p(&out), p(&moka)]);
    assert!(stderr(&o).contains("copy.moka drops the labels of"), "{}", stderr(&o));
    let o = gmap(&["convert", "--lossy", p(&out), p(&moka)]);
    assert!(o.status.success(), "{}", stderr(&o));
    let back = gmap_core::io::read_moka(&moka).unwrap();
    assert_eq!(back.point(gmap_core::Dart::new(1)), Some([2.5, 0.0, -1.0]));
    // a malformed section is refused with the file and line
    let bad = dir.path().join("bad.gmap");
    std::fs::write(&bad, "gmap 1 2\n1 0\n0 1\nlabels 1 1\n0 name=\"open\n").unwrap();
    let o = gmap(&["convert", p(&bad), p(&dir.path().join("x.gmap"))]);
    assert!(!o.status.success());
    assert!(
        stderr(&o).contains("bad.gmap:5: labels of dart 0: column 8: the quoted text is not closed"),
        "{}",
        stderr(&o)
    );
}

/// `.off` → `.cgal.xml` → `.off` keeps the map (isomorphic) and its points; a labelled map is
/// refused without `--lossy`; an empty or truncated `.cgal.xml` is an error, not an empty map.
#[test]
fn cgal_xml_round_trip_through_the_binary() {
    let dir = tempfile::tempdir().unwrap();
    let data = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data");
    let src = data.join("cgal/3torus.off");
    let xml = dir.path().join("3torus.cgal.xml");
    let o = gmap(&["convert", p(&src), p(&xml)]);
    assert!(o.status.success(), "{}", stderr(&o));
    let back = dir.path().join("back.off");
    let o = gmap(&["convert", p(&xml), p(&back)]);
    assert!(o.status.success(), "{}", stderr(&o));
    let a = gmap_ops::import::read_off(&src).unwrap();
    let b = gmap_ops::import::read_cgal_xml(&xml, None).unwrap();
    assert_eq!((b.dart_count(), b.cell_counts()), (184, vec![19, 46, 23]));
    assert!(iso::are_isomorphic(&a, &b));
    assert!(iso::are_isomorphic(&a, &gmap_ops::import::read_off(&back).unwrap()));
    for d in a.darts() {
        assert_eq!(a.vertex_point(d), b.vertex_point(d), "dart {d:?}");
    }
    // labels: CGAL's XML holds none here, so the write is refused without --lossy
    let labelled = data.join("labelled_segment.gmap");
    let o = gmap(&["convert", p(&labelled), p(&dir.path().join("seg.cgal.xml"))]);
    assert!(!o.status.success());
    assert!(stderr(&o).contains("seg.cgal.xml drops the labels of"), "{}", stderr(&o));
    // empty and truncated files are refused
    let text = std::fs::read_to_string(&xml).unwrap();
    for (name, body) in [("empty.cgal.xml", ""), ("cut.cgal.xml", &text[..text.len() / 2])] {
        let f = dir.path().join(name);
        std::fs::write(&f, body).unwrap();
        let o = gmap(&["info", p(&f)]);
        assert!(!o.status.success(), "{name} was read");
        assert!(stderr(&o).contains(name), "{}", stderr(&o));
    }
}
