//! Cubical sets through the `gmap` binary: `.cub` and `.pbm`, `--periodic`, refusals.

use std::path::PathBuf;
use std::process::Command;

fn data(name: &str) -> String {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/data/cubical").join(name).to_str().unwrap().to_string()
}

fn gmap(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_gmap")).args(args).output().unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// Betti numbers and torsion of `gmap homology FILE --json EXTRA…`.
fn betti(file: &str, extra: &[&str]) -> (Vec<u64>, serde_json::Value) {
    let mut args = vec!["homology", file, "--json"];
    args.extend_from_slice(extra);
    let (code, out, err) = gmap(&args);
    assert_eq!(code, 0, "{file}: {err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let b = v["betti"].as_array().unwrap().iter().map(|x| x.as_u64().unwrap()).collect();
    (b, v)
}

#[test]
fn exact_groups() {
    assert_eq!(betti(&data("square.cub"), &[]).0, vec![1, 0, 0]);
    // negative coordinates, comments, `dimension` lines, a duplicate cube
    assert_eq!(betti(&data("ring.cub"), &[]).0, vec![1, 1, 0]);
    // closed squares touching at a corner: one component
    assert_eq!(betti(&data("corner.cub"), &[]).0, vec![1, 0, 0]);
    let (b, v) = betti(&data("shell.cub"), &[]);
    assert_eq!(b, vec![1, 0, 1, 0]);
    assert_eq!(v["dimension"], 3);
    assert_eq!(v["euler_characteristic"], 2);
    assert_eq!(betti(&data("box.cub"), &[]).0, vec![1, 0, 0]);
    assert_eq!(betti(&data("box.cub"), &["--periodic"]).0, vec![1, 2, 1]);
    assert_eq!(betti(&data("shell.cub"), &["--field", "2"]).0, vec![1, 0, 1, 0]);
}

#[test]
fn pbm_p1_and_p4_agree() {
    let (a, va) = betti(&data("annulus_p1.pbm"), &[]);
    let (b, vb) = betti(&data("annulus_p4.pbm"), &[]);
    assert_eq!(a, vec![1, 1, 0]);
    assert_eq!(a, b);
    assert_eq!(va, vb);
    // the whole 5 x 4 image box glued into a torus
    let (p, _) = betti(&data("annulus_p1.pbm"), &["--periodic"]);
    let (q, _) = betti(&data("annulus_p4.pbm"), &["--periodic"]);
    assert_eq!(p, q);
}

#[test]
fn generators_name_cubical_cells() {
    let (code, out, err) = gmap(&["homology", &data("ring.cub"), "--generators"]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("H_1 = Z"), "{out}");
    assert!(out.contains("generator of H_1 (Z):"), "{out}");
    assert!(out.contains("x"), "{out}");
}

/// A 3-D set's generators by the command: the cavity of the hollow cube is its skin, the six
/// squares around the middle cube, oriented outwards of the cavity; the JSON says the same;
/// over Z/3 the coefficients are 1 and 2.
#[test]
fn generators_of_a_cavity() {
    let (code, out, err) = gmap(&["homology", &data("shell.cub"), "--generators"]);
    assert_eq!(code, 0, "{err}");
    let lines: Vec<&str> = out.lines().filter(|l| l.starts_with("generator")).collect();
    assert_eq!(
        lines,
        vec![
            "generator of H_0 (Z): +1 0x0x0",
            "generator of H_2 (Z): -1 [1,2]x[1,2]x1 +1 [1,2]x1x[1,2] -1 1x[1,2]x[1,2] +1 2x[1,2]x[1,2] -1 [1,2]x2x[1,2] +1 [1,2]x[1,2]x2",
        ]
    );
    let (code, out, err) = gmap(&["homology", &data("shell.cub"), "--generators", "--json"]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let skin = &v["generators"][1];
    assert_eq!((skin["dim"].as_u64(), skin["chain"].as_array().map(Vec::len)), (Some(2), Some(6)));
    assert_eq!(
        skin["chain"][0],
        serde_json::json!({"cell": {"cube": [1, 1, 1], "extent": [1, 1, 0]}, "coefficient": -1})
    );
    let (code, out, err) = gmap(&["homology", &data("shell.cub"), "--generators", "--field", "3"]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("generator of H_2 (Z/3): +2 [1,2]x[1,2]x1 +1 [1,2]x1x[1,2]"), "{out}");
}

#[test]
fn info_on_a_cubical_set() {
    let (code, out, err) = gmap(&["info", &data("shell.cub"), "--json"]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["kind"], "cubical set");
    assert_eq!(v["cubes"], 26);
    assert_eq!(v["cells"], serde_json::json!([64, 144, 108, 26]));
    assert_eq!(v["euler_characteristic"], 2);
    let (code, out, _) = gmap(&["info", &data("box.cub"), "--periodic"]);
    assert_eq!(code, 0);
    assert!(out.contains("euler characteristic  0"), "{out}");
}

#[test]
fn malformed_inputs_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    let long = "9".repeat(500);
    let cases: Vec<(&str, Vec<u8>, &str)> = vec![
        ("mixed.cub", b"(0,0)\n(1,2,3)\n".to_vec(), "line 2"),
        ("word.cub", b"(0,0)\n(1,x)\n".to_vec(), "line 2"),
        ("noparen.cub", b"0 0\n".to_vec(), "line 1"),
        ("long.cub", format!("(0,{long})\n").into_bytes(), "line 1"),
        ("empty.cub", b"; nothing\ndimension 2\n".to_vec(), "no cube"),
        ("huge.cub", b"(0,0,0)\n(100000,100000,100000)\n".to_vec(), "bounding box"),
        ("magic.pbm", b"P3\n1 1\n1\n".to_vec(), "magic"),
        ("short1.pbm", b"P1\n3 2\n1 0 1\n0\n".to_vec(), "too short"),
        ("short4.pbm", b"P4\n9 2\n\xff\xff\xff".to_vec(), "too short"),
        ("header.pbm", b"P1\n3 -2\n".to_vec(), "height"),
        ("pixel.pbm", b"P1\n2 1\n1 2\n".to_vec(), "pixel"),
    ];
    for (name, bytes, what) in cases {
        let p = dir.path().join(name);
        std::fs::write(&p, &bytes).unwrap();
        let p = p.to_str().unwrap();
        let (code, out, err) = gmap(&["homology", p]);
        assert_eq!(code, 1, "{name}: {err}");
        assert!(out.is_empty());
        assert!(err.starts_with("error: "), "{name}: {err}");
        assert!(err.contains(name), "{name}: {err}");
        assert!(err.contains(what), "{name}: {err}");
        assert!(err.len() < 300, "{name}: {err}");
    }
    // --periodic is for cubical sets only
    let p = dir.path().join("t.facets");
    std::fs::write(&p, "0 1 2\n").unwrap();
    let (code, _, err) = gmap(&["homology", p.to_str().unwrap(), "--periodic"]);
    assert_eq!(code, 1);
    assert!(err.contains("--periodic"), "{err}");
}

#[test]
fn periodic_takes_the_box_given_by_a_box_line_or_box() {
    let dir = tempfile::tempdir().unwrap();
    let row = dir.path().join("row.cub");
    std::fs::write(&row, "(0)\n(1)\n(2)\n").unwrap();
    let groups = |args: &[&str]| {
        let (code, out, err) = gmap(args);
        assert_eq!(code, 0, "{err}");
        out.lines().filter(|l| l.starts_with("H_")).collect::<Vec<_>>().join(" ")
    };
    let path = row.to_str().unwrap();
    // the bounding box: three cubes in a row close up into a circle
    assert_eq!(groups(&["homology", "--periodic", path]), "H_0 = Z H_1 = Z");
    // a box of six cubes: the row stays a segment in the circle
    assert_eq!(groups(&["homology", "--periodic", "--box", "(0) (5)", path]), "H_0 = Z H_1 = 0");
    let boxed = dir.path().join("boxed.cub");
    std::fs::write(&boxed, "box (0) (5)\n(0)\n(1)\n(2)\n").unwrap();
    assert_eq!(groups(&["homology", "--periodic", boxed.to_str().unwrap()]), "H_0 = Z H_1 = 0");
    let (code, _, err) = gmap(&["homology", "--box", "(1) (2)", path]);
    assert_eq!(code, 1);
    assert!(err.contains("does not hold the cubes: along axis 0 they run from 0 to 2"), "{err}");
}

#[test]
fn cubical_cell_complexes() {
    // CHomP's cell syntaxes: the square's four edges, the cube's six 2-faces, a mix
    assert_eq!(betti(&data("square_edges.cel"), &[]).0, vec![1, 1, 0]);
    assert_eq!(betti(&data("cube_faces.cel"), &[]).0, vec![1, 0, 1, 0]);
    let (b, v) = betti(&data("mixed.cub"), &[]);
    assert_eq!((b, v["euler_characteristic"].as_i64()), (vec![3, 1, 0], Some(2)));
    // the square's edges on a 1 x 1 periodic box: all four vertices one point, the edges two
    // circles of the torus
    assert_eq!(betti(&data("square_edges.cel"), &["--periodic"]).0, vec![1, 2, 0]);
    assert_eq!(betti(&data("square_edges.cel"), &["--periodic", "--box", "(0,0) (2,2)"]).0, vec![1, 1, 0]);
    let (code, out, err) = gmap(&["homology", &data("square_edges.cel"), "--generators"]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("generator of H_1 (Z): -1 [0,1]x0 +1 0x[0,1] -1 1x[0,1] +1 [0,1]x1"), "{out}");
    let (code, out, err) = gmap(&["info", &data("cube_faces.cel"), "--json"]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!((v["cubes"].as_u64(), v["lower_cells"].as_u64()), (Some(0), Some(6)));
    assert_eq!(v["cells"], serde_json::json!([8, 12, 6, 0]));
    // the face poset of every cell; .gmap and .vtk hold cubes only
    let dir = tempfile::tempdir().unwrap();
    for ext in ["json", "dot", "graphml"] {
        let out = dir.path().join(format!("m.{ext}"));
        let (code, _, err) = gmap(&["convert", &data("mixed.cub"), out.to_str().unwrap()]);
        assert_eq!(code, 0, "{ext}: {err}");
    }
    let back = dir.path().join("m.json");
    assert_eq!(betti(back.to_str().unwrap(), &[]).0, vec![3, 1, 0]);
    for ext in ["gmap", "vtk"] {
        let out = dir.path().join(format!("m.{ext}"));
        let (code, _, err) = gmap(&["convert", &data("mixed.cub"), out.to_str().unwrap()]);
        assert_eq!(code, 1, "{ext}");
        assert!(err.contains("6 cells of dimension below 2 on no 2-cube (the first: 0x[3,4])"), "{err}");
        assert!(!out.exists());
    }
    // the page draws cubes: refused, naming a cell; bench times the whole complex only
    let page = dir.path().join("m.html");
    let (code, _, err) = gmap(&["view", &data("mixed.cub"), "-o", page.to_str().unwrap()]);
    assert_eq!(code, 1);
    assert!(err.contains("(the first: 0x[3,4])"), "{err}");
    assert!(!page.exists());
    let (code, out, err) = gmap(&["bench", &data("mixed.cub"), "--json"]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let rows = v["rows"].as_array().unwrap();
    assert_eq!(rows.iter().map(|r| r["route"].as_str().unwrap()).collect::<Vec<_>>(), ["cubical"], "{v}");
    assert_eq!(rows[0]["betti"], serde_json::json!([3, 1, 0]), "{v}");
    // a complex whose lower cells all lie on its cubes is the full set: .gmap keeps it
    let faces = dir.path().join("faces.cel");
    std::fs::write(&faces, "[0,1]x[0,1]\n[0]x[0,1]\n[(0,0) (1,0)]\n").unwrap();
    let out = dir.path().join("faces.gmap");
    let (code, _, err) = gmap(&["convert", faces.to_str().unwrap(), out.to_str().unwrap()]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(betti(out.to_str().unwrap(), &[]).0, vec![1, 0, 0]);
    // errors name the file and the line
    let cases: [(&str, &str, &str); 4] = [
        ("interval.cel", "[0,1]x[0]\n; ok\n[0,2]x[1]\n", "line 3: bad interval [0,2]"),
        ("mixed.cel", "[0,1]x[0]\n[0]x[0]x[0]\n", "line 2: mixed dimensions"),
        ("far.cel", "[(0,0) (2,1)]\n", "line 1: the vertices of the cell '[(0,0) (2,1)]' differ by 2 along axis 0"),
        ("overflow.cel", "[0,1]x[99999999999999999999]\n", "line 1: '99999999999999999999' is not an integer"),
    ];
    for (name, text, what) in cases {
        let p = dir.path().join(name);
        std::fs::write(&p, text).unwrap();
        let (code, _, err) = gmap(&["info", p.to_str().unwrap()]);
        assert_eq!(code, 1, "{name}");
        assert!(err.contains(name) && err.contains(what), "{name}: {err}");
    }
}

#[test]
fn info_takes_a_box() {
    let dir = tempfile::tempdir().unwrap();
    let row = dir.path().join("row.cub");
    std::fs::write(&row, "(0)\n(1)\n(2)\n").unwrap();
    let path = row.to_str().unwrap();
    let json = |args: &[&str]| {
        let (code, out, err) = gmap(args);
        assert_eq!(code, 0, "{err}");
        serde_json::from_str::<serde_json::Value>(&out).unwrap()
    };
    let v = json(&["info", path, "--json", "--box", "(-1) (5)"]);
    assert_eq!((v["box_min"].clone(), v["box_shape"].clone()), (serde_json::json!([-1]), serde_json::json!([7])));
    assert_eq!(v["cells"], serde_json::json!([4, 3]));
    // periodic on the box of seven: the row stays a segment; on its own box it closes up
    let v = json(&["info", path, "--json", "--box", "(-1) (5)", "--periodic"]);
    assert_eq!((v["cells"].clone(), v["periodic"].clone()), (serde_json::json!([4, 3]), serde_json::json!(true)));
    let v = json(&["info", path, "--json", "--periodic"]);
    assert_eq!(v["cells"], serde_json::json!([3, 3]));
    let (code, out, _) = gmap(&["info", path, "--box", "(0) (5)"]);
    assert_eq!(code, 0);
    assert!(out.contains("box shape             6"), "{out}");
    let (code, _, err) = gmap(&["info", path, "--box", "(1) (2)"]);
    assert_eq!(code, 1);
    assert!(err.contains("--box: the box from [1] to [2] does not hold the cubes"), "{err}");
    let facets = dir.path().join("t.facets");
    std::fs::write(&facets, "0 1 2\n").unwrap();
    let (code, _, err) = gmap(&["info", facets.to_str().unwrap(), "--box", "(0) (1)"]);
    assert_eq!(code, 1);
    assert!(err.contains("--box applies to cubical sets"), "{err}");
}
