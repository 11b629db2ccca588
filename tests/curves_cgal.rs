//! CGAL 5.5.1's `Surface_mesh_topology` cycle examples (`shortest_noncontractible_cycle`,
//! `edgewidth_surface_mesh`, `facewidth`) on their own inputs, against the answers CGAL
//! gave there, recorded in `tests/data/cgal/*.cycles.txt` by `tests/data/cgal/cycles.cpp`
//! (how: `tests/data/cgal/README.md`): the edge width, the shortest non-contractible
//! cycle's Euclidean length, the face width, and through every vertex the fewest edges and
//! the shortest length of a non-contractible cycle.

use std::path::PathBuf;

use gmap::curves::{self, Weights};

mod common;
use common::gmap;

fn data(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/data/cgal").join(name)
}

/// The recorded answers: `key value…` lines.
fn recorded(name: &str) -> Vec<(String, Vec<String>)> {
    let text = std::fs::read_to_string(data(name)).unwrap();
    text.lines()
        .map(|l| {
            let mut w = l.split_whitespace().map(str::to_string);
            (w.next().unwrap(), w.collect())
        })
        .collect()
}

fn value<'a>(rec: &'a [(String, Vec<String>)], key: &str) -> &'a [String] {
    &rec.iter().find(|(k, _)| k == key).unwrap_or_else(|| panic!("no {key}")).1
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-9 * (1.0 + a.abs())
}

fn check(off: &str) {
    let rec = recorded(&off.replace(".off", ".cycles.txt"));
    let input = gmap::open(data(off)).unwrap();
    let map = input.to_map().unwrap().into_owned();
    let n: Vec<usize> = value(&rec, "darts").iter().skip(2).step_by(2).map(|x| x.parse().unwrap()).collect();
    assert_eq!(&map.cell_counts(), &n[..3], "vertices, edges and faces as CGAL read them");
    let ew = curves::edge_width(&input).unwrap().unwrap();
    assert_eq!(ew.edges.len().to_string(), value(&rec, "edgewidth")[0]);
    let fw = curves::face_width(&input).unwrap().unwrap();
    assert_eq!(fw.width.to_string(), value(&rec, "facewidth_darts")[0]);
    let sw = curves::shortest_non_contractible_cycle(&input, &Weights::Length, None).unwrap().unwrap();
    let cgal: f64 = value(&rec, "shortest_euclidean")[1].parse().unwrap();
    assert!(close(sw.length, cgal), "{} against CGAL's {cgal}", sw.length);
    // through every vertex, found by its point
    let mut through = 0;
    for (k, v) in rec.iter().filter(|(k, _)| k == "through") {
        let _ = k;
        let p: Vec<f64> = v[..3].iter().map(|x| x.parse().unwrap()).collect();
        let dart = map
            .darts()
            .find(|&d| map.vertex_point(d).is_some_and(|q| (0..3).all(|i| close(q[i], p[i]))))
            .unwrap_or_else(|| panic!("no vertex at {p:?}"));
        let d = u64::from(dart.get());
        let unit = curves::shortest_non_contractible_cycle(&input, &Weights::Unit, Some(d)).unwrap().unwrap();
        assert_eq!(unit.edges.len().to_string(), v[4], "edges through {p:?}");
        let len = curves::shortest_non_contractible_cycle(&input, &Weights::Length, Some(d)).unwrap().unwrap();
        let cgal: f64 = v[6].parse().unwrap();
        assert!(close(len.length, cgal), "through {p:?}: {} against CGAL's {cgal}", len.length);
        assert_eq!(unit.vertices[0], unit.vertices[unit.vertices.len() - 1]);
        through += 1;
    }
    assert_eq!(through, n[0]);
}

#[test]
fn three_torus_as_cgal() {
    check("3torus.off");
}

#[test]
fn double_torus_as_cgal() {
    check("double-torus-example.off");
}

#[test]
fn the_command_prints_the_widths() {
    let f = data("3torus.off");
    let o = gmap(&["curves", "edge-width", f.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(String::from_utf8_lossy(&o.stdout).starts_with("length 3 (3 edges), darts "));
    let o = gmap(&["curves", "face-width", f.to_str().unwrap(), "--json"]);
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["width"], 3);
    let o = gmap(&["curves", "shortest", f.to_str().unwrap(), "--weights", "length", "--json"]);
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert!(close(v["length"].as_f64().unwrap(), 2.2718217464557178));
    // a base point that is no dart is refused, naming it
    let o = gmap(&["curves", "shortest", f.to_str().unwrap(), "--through", "5000"]);
    assert_eq!(o.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&o.stderr).contains("5000"), "{}", String::from_utf8_lossy(&o.stderr));
}

/// The lengths of the generators of H_1 in a JSON report (each cell of the chain an edge).
fn h1_lengths(out: &[u8]) -> Vec<usize> {
    let v: serde_json::Value = serde_json::from_slice(out).unwrap();
    let mut l: Vec<usize> = v["generators"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|g| g["dim"] == 1)
        .map(|g| g["chain"].as_array().unwrap().len())
        .collect();
    l.sort_unstable();
    l
}

#[test]
fn homology_gives_a_shortest_basis_no_longer_than_the_generators() {
    let f = data("double-torus-example.off");
    let f = f.to_str().unwrap();
    let o = gmap(&["homology", f, "--field", "2", "--generators", "shortest", "--json"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let shortest = h1_lengths(&o.stdout);
    let o = gmap(&["homology", f, "--field", "2", "--generators", "--json"]);
    let today = h1_lengths(&o.stdout);
    assert_eq!(shortest.len(), 4);
    assert_eq!(today.len(), 4);
    assert!(shortest.iter().zip(&today).all(|(s, t)| s <= t), "{shortest:?} against {today:?}");
    // the shortest is the edge width: on this surface a shortest non-separating cycle
    assert_eq!(shortest[0], 8);
    let o = gmap(&["homology", f, "--field", "2", "--generators", "shortest"]);
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(text.contains("generator of H_1 (Z/2): length 8: "), "{text}");
    // over Z the classes modulo 2 are not the classes: refused with the reason
    let o = gmap(&["homology", f, "--generators", "shortest"]);
    assert_eq!(o.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&o.stderr).contains("add --field 2"));
}

/// The kind of `--generators` is optional: the flag right before the file still reads the
/// file as the input, as it did before the kind existed, and the joined form names it.
#[test]
fn generators_before_the_file_keeps_the_file() {
    let f = data("double-torus-example.off");
    let f = f.to_str().unwrap();
    let o = gmap(&["homology", "--generators", f, "--json"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert_eq!(h1_lengths(&o.stdout).len(), 4);
    let o = gmap(&["homology", "--field", "2", "--generators=shortest", f, "--json"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert_eq!(h1_lengths(&o.stdout)[0], 8);
    let o = gmap(&["homology", "--field", "2", "--generators", "shortest", f]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
}
