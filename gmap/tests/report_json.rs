//! `Report::from_json` reads back what `Report::to_json` writes: for a map, a simplicial
//! complex (both routes), a cubical set (the one-pass route, the sweep's grid of cells and
//! the cubical complex's named cubes) and an architectural complex (its space, regions that
//! are not balls included), over Z and Z/p, with and without generators.

use gmap::{HomologyOptions, Method, Report, Via};

fn data(name: &str) -> std::path::PathBuf {
    std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../tests/data").join(name)
}

/// Every option set the round trip is checked under.
fn options() -> Vec<HomologyOptions> {
    let mut all = Vec::new();
    for field in [None, Some(2), Some(3)] {
        for generators in [false, true] {
            let mut o = HomologyOptions::default();
            (o.field, o.generators) = (field, generators);
            all.push(o);
        }
    }
    all
}

/// The report read back from its JSON text is the same report: the same JSON, route, field
/// and groups (the kind is checked by the callers: the JSON says it only through a route, a
/// space or the generators' cells).
fn round_trip(r: &Report) -> Report {
    let text = r.to_json().to_string();
    let v: serde_json::Value = serde_json::from_str(&text).unwrap();
    let back = Report::from_json(&v).unwrap_or_else(|| panic!("not read back: {text}"));
    assert_eq!(back.to_json(), r.to_json());
    assert_eq!(back.to_json_string(), r.to_json_string());
    assert_eq!((back.route, back.field, back.method), (r.route, r.field, r.method));
    assert_eq!(back.groups, r.groups);
    assert_eq!(back.generators.as_ref().map(Vec::len), r.generators.as_ref().map(Vec::len));
    back
}

#[test]
fn every_kind_of_report_round_trips() {
    let files = [
        ("labelled_segment.gmap", "map"),
        ("rp2.facets", "simplicial complex"),
        ("lutz/poincare.facets", "simplicial complex"),
        ("cubical/ring.cub", "cubical set"),
        ("cubical/shell.cub", "cubical set"),
        ("cubical/cube_faces.cel", "cubical set"),
        ("arch/tetrahedron.json", "architectural complex"),
        ("arch/court.json", "architectural complex"),
        ("arch/floor_court.json", "architectural complex"),
    ];
    for (file, kind) in files {
        let input = gmap::open(data(file)).unwrap();
        for o in options() {
            let r = gmap::homology(&input, &o).unwrap();
            assert_eq!(r.kind, kind, "{file}");
            let back = round_trip(&r);
            // a cubical set's JSON names cubes only in its generators; without them it reads
            // back as a map's (the same object, the same groups)
            let said = o.generators || kind != "cubical set";
            assert_eq!(back.kind, if said { kind } else { "map" }, "{file}");
        }
    }
}

#[test]
fn routes_methods_and_spaces_are_kept() {
    let sc = gmap::open(data("rp2.facets")).unwrap();
    let mut o = HomologyOptions::default();
    o.via = Some(Via::Gmap);
    o.generators = true;
    let r = gmap::homology(&sc, &o).unwrap();
    assert_eq!(round_trip(&r).route, Some(Via::Gmap));
    let mut o = HomologyOptions::default();
    o.method = Method::Simplicial;
    let map = gmap::open(data("labelled_segment.gmap")).unwrap();
    assert_eq!(round_trip(&gmap::homology(&map, &o).unwrap()).method, Method::Simplicial);
    // an architectural complex's space, with the regions that are not balls when it has some
    let mut seen_not_balls = false;
    for file in ["arch/court.json", "arch/floor_court.json", "arch/window.json", "arch/rooms_door_window.json"] {
        let x = gmap::open(data(file)).unwrap();
        for topological in [false, true] {
            let mut o = HomologyOptions::default();
            o.topological = topological;
            let Ok(r) = gmap::homology(&x, &o) else { continue };
            let back = round_trip(&r);
            let (want, got) = (r.space.as_ref().unwrap(), back.space.as_ref().unwrap());
            assert_eq!(got.topological, want.topological);
            assert_eq!(back.kind, "architectural complex");
            // the regions that are not balls are written (and read) for the region complex
            if !topological {
                let ids =
                    |s: &gmap::ArchSpace| s.not_balls.iter().map(|(_, id, b)| (*id, b.clone())).collect::<Vec<_>>();
                assert_eq!(ids(got), ids(want));
                seen_not_balls |= !want.not_balls.is_empty();
            }
        }
    }
    assert!(seen_not_balls, "no file with a region that is not a ball");
}

#[test]
fn a_large_torsion_coefficient_is_read_exactly() {
    // a Z/t with t past u64, written as a number of its exact digits
    let text = r#"{"betti":[1,0],"coefficients":"Z","dimension":1,"euler_characteristic":1,"method":"cellular","torsion":[[],[123456789012345678901234567890]]}"#;
    let r = Report::from_json(&serde_json::from_str(text).unwrap()).unwrap();
    assert_eq!(r.groups.torsion[1][0].to_string(), "123456789012345678901234567890");
    assert_eq!(r.to_json().to_string(), text);
}

#[test]
fn objects_that_are_not_reports_are_refused() {
    for text in [
        "{}",
        "[1, 2]",
        r#"{"betti":[1],"coefficients":"Q","dimension":0,"method":"cellular","torsion":[[]]}"#,
        r#"{"betti":[1],"coefficients":"Z","dimension":0,"method":"magic","torsion":[[]]}"#,
        r#"{"betti":[1, 0],"coefficients":"Z","dimension":1,"method":"cellular","torsion":[[]]}"#,
        r#"{"betti":[1],"coefficients":"Z","dimension":0,"method":"cellular","torsion":[[]],"route":"sideways"}"#,
        r#"{"betti":[1],"coefficients":"Z","dimension":0,"method":"cellular","torsion":[[]],"generators":[{"dim":0,"order":0,"chain":[{"cell":{"cube":[0],"extent":[2]},"coefficient":1}]}]}"#,
        r#"{"betti":[-1],"coefficients":"Z","dimension":0,"method":"cellular","torsion":[[]]}"#,
    ] {
        let v: serde_json::Value = serde_json::from_str(text).unwrap();
        assert!(Report::from_json(&v).is_none(), "{text}");
    }
}
