//! Homology of classic objects and of the Benedetti–Lutz library by both methods, and the
//! `gmap homology` command line (docs/FORMATS.md).

use std::path::{Path, PathBuf};
use std::process::Command;

use gmap_core::{Dart, DenseMap};
use gmap_homology::{cellular_complex, homology_z, homology_zp, simplicial_complex, Homology, PreconditionError};
use gmap_ops::build;

/// Homology by both methods, checked equal; over Z/2 and Z/3 too.
fn both(map: &DenseMap) -> Homology {
    let c = homology_z(&cellular_complex(map).expect("C1 and C2 hold").chain).unwrap();
    let s = homology_z(&simplicial_complex(map)).unwrap();
    assert_eq!(c, s, "cellular = simplicial");
    for p in [2, 3] {
        let cp = homology_zp(&cellular_complex(map).unwrap().chain, p).unwrap();
        let sp = homology_zp(&simplicial_complex(map), p).unwrap();
        assert_eq!(cp, sp);
    }
    c
}

#[test]
fn classic_objects_by_both_methods() {
    let cases: Vec<(DenseMap, &str)> = vec![
        (build::schema("a A").unwrap(), "(Z, 0, Z)"),
        (build::schema("a b A B").unwrap(), "(Z, Z^2, Z)"),
        (build::schema("a b a B").unwrap(), "(Z, Z + Z/2, 0)"),
        (build::schema("a a").unwrap(), "(Z, Z/2, 0)"),
        (build::schema("a b A c").unwrap(), "(Z, Z, 0)"),
        (build::schema("a b a c").unwrap(), "(Z, Z, 0)"),
        (build::schema(&build::orientable_surface_word(2)).unwrap(), "(Z, Z^4, Z)"),
        (build::cube(3).unwrap(), "(Z, 0, 0, 0)"),
        (build::simplex(3).unwrap(), "(Z, 0, 0, 0)"),
        (build::solid_torus(3).unwrap(), "(Z, Z, 0, 0)"),
        (build::grid(&[2, 2, 2], &[true; 3]).unwrap(), "(Z, Z^3, Z^3, Z)"),
        (build::lens_space(5, 2).unwrap(), "(Z, Z/5, 0, Z)"),
        (build::lens_space(7, 3).unwrap(), "(Z, Z/7, 0, Z)"),
        (build::lens_space(2, 1).unwrap(), "(Z, Z/2, 0, Z)"),
        (build::cube(4).unwrap(), "(Z, 0, 0, 0, 0)"),
        (build::grid(&[1; 4], &[true; 4]).unwrap(), "(Z, Z^4, Z^6, Z^4, Z)"),
    ];
    for (map, want) in cases {
        assert_eq!(both(&map).to_string(), want);
    }
}

/// A volume bounded by a torus: C2 fails, and only the simplicial method answers.
#[test]
fn volume_bounded_by_a_torus_is_refused() {
    let t = build::schema("a b A B").unwrap();
    let mut flat = Vec::new();
    for d in t.darts() {
        flat.extend_from_slice(t.row(d));
        flat.push(d.get());
    }
    let m = DenseMap::try_from_flat(3, flat).unwrap();
    match cellular_complex(&m) {
        Err(PreconditionError::C2 { dim: 3, dart, .. }) if dart == Dart::new(0) => {}
        other => panic!("expected C2 on the 3-cell of dart 0, got {other:?}"),
    }
    // the simplicial counterpart is the cone over the torus: contractible
    assert_eq!(homology_z(&simplicial_complex(&m)).unwrap().to_string(), "(Z, 0, 0, 0)");
}

/// `(Z,Z_2,Z^22,Z_5^3,0)` from the README table.
fn parse_groups(s: &str) -> Option<(Vec<usize>, Vec<Vec<u64>>)> {
    let inner = s.trim().strip_prefix('(')?.strip_suffix(')')?;
    let mut betti = Vec::new();
    let mut torsion = Vec::new();
    for g in inner.split(',') {
        let (mut b, mut t) = (0usize, Vec::new());
        for part in g.split('+') {
            let part = part.trim();
            if part == "0" {
                continue;
            }
            let (base, exp) = match part.split_once('^') {
                Some((x, e)) => (x, e.parse::<usize>().ok()?),
                None => (part, 1),
            };
            if base == "Z" {
                b += exp;
            } else {
                let p: u64 = base.strip_prefix("Z_")?.parse().ok()?;
                t.extend(std::iter::repeat_n(p, exp));
            }
        }
        betti.push(b);
        torsion.push(t);
    }
    Some((betti, torsion))
}

fn lutz_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/lutz")
}

/// A library entry: file, darts, Betti numbers, torsion (prime powers).
type LutzCase = (String, u64, Vec<usize>, Vec<Vec<u64>>);

/// The pseudo-manifolds of the library with their darts and stated homology.
fn lutz_cases() -> Vec<LutzCase> {
    let readme = std::fs::read_to_string(lutz_dir().join("README.md")).expect("README of the Lutz library");
    let mut out = Vec::new();
    for line in readme.lines() {
        let cols: Vec<&str> = line.split('|').map(str::trim).collect();
        if cols.len() < 6 || !cols[1].ends_with(".facets") || cols[5].contains("not a pseudo") {
            continue;
        }
        let darts: u64 = match cols[4].replace(',', "").parse() {
            Ok(d) => d,
            Err(_) => continue,
        };
        if let Some((b, t)) = parse_groups(cols[5]) {
            out.push((cols[1].to_string(), darts, b, t));
        }
    }
    out
}

fn check_lutz(lo: u64, hi: u64) -> usize {
    let mut checked = 0;
    for (file, darts, betti, torsion) in lutz_cases() {
        if darts < lo || darts > hi {
            continue;
        }
        let map = gmap_ops::import::read_facets(&lutz_dir().join(&file), None).unwrap();
        let h = both(&map);
        if file == "SU2_SO3.facets" {
            // The file states (Z,0,Z,Z,0,Z), which are its Betti numbers over Z/2; over Z both
            // methods find the Wu manifold SU(3)/SO(3): (Z, 0, Z/2, 0, 0, Z).
            assert_eq!(h.to_string(), "(Z, 0, Z/2, 0, 0, Z)");
            let h2 = homology_zp(&simplicial_complex(&map), 2).unwrap();
            assert_eq!(h2.betti, betti, "{file} over Z/2");
            checked += 1;
            continue;
        }
        // torsion of the README is written in prime powers; compare as multisets of factors
        let mut got: Vec<Vec<u64>> =
            h.torsion.iter().map(|t| t.iter().map(|x| x.to_u64().unwrap()).collect()).collect();
        let mut want = torsion.clone();
        for v in got.iter_mut().chain(want.iter_mut()) {
            v.sort_unstable();
        }
        assert_eq!(h.betti, betti, "{file}");
        assert_eq!(got, want, "{file}");
        checked += 1;
    }
    checked
}

#[test]
fn lutz_library_small() {
    assert_eq!(check_lutz(0, 100_000), 30);
}

#[test]
#[ignore = "large inputs (up to 10^6 darts): run with --ignored in release mode"]
fn lutz_library_large() {
    assert_eq!(check_lutz(100_001, 1_000_000), 7);
}

fn gmap(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_gmap")).args(args).output().unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn cli_json_and_fields() {
    let f = lutz_dir().join("hyperbolic_dodecahedral_space.facets");
    let f = f.to_str().unwrap();
    let (code, out, _) = gmap(&["homology", f, "--json"]);
    assert_eq!(code, 0);
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["dimension"], 3);
    assert_eq!(v["method"], "cellular");
    assert_eq!(v["coefficients"], "Z");
    assert_eq!(v["betti"], serde_json::json!([1, 0, 0, 1]));
    assert_eq!(v["torsion"], serde_json::json!([[], [5, 5, 5], [], []]));
    assert_eq!(v["euler_characteristic"], 0);
    let (code, out, _) = gmap(&["homology", f, "--json", "--method", "simplicial", "--field", "5"]);
    assert_eq!(code, 0);
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["coefficients"], "Z/5");
    assert_eq!(v["method"], "simplicial");
    assert_eq!(v["betti"], serde_json::json!([1, 3, 3, 1]));
    assert_eq!(v["torsion"], serde_json::json!([[], [], [], []]));
    let (code, _, err) = gmap(&["homology", f, "--field", "4"]);
    assert_eq!(code, 1);
    assert!(err.starts_with("error: ") && err.contains("prime"), "{err}");
    let (code, out, _) = gmap(&["homology", f]);
    assert_eq!(code, 0);
    assert!(out.contains("H_1 = Z/5 + Z/5 + Z/5"), "{out}");
}

#[test]
fn cli_refuses_the_cellular_method_where_c1_fails() {
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("open.gmap");
    // two darts of one face whose corner is open: dart 0 is 1-free
    std::fs::write(&p, "gmap 2 2\n1 0 0\n0 1 1\n").unwrap();
    let p = p.to_str().unwrap();
    let (code, out, err) = gmap(&["homology", p]);
    assert_eq!(code, 1);
    assert!(out.is_empty());
    assert!(err.contains("C1") && err.contains("2-cell of dart 0"), "{err}");
    let (code, out, _) = gmap(&["homology", p, "--method", "simplicial", "--json"]);
    assert_eq!(code, 0);
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["betti"], serde_json::json!([1, 0, 0]));
}

#[test]
fn cli_generators() {
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("rp2.facets");
    // the 6-vertex projective plane
    std::fs::write(&p, "1 2 3\n1 3 4\n1 4 5\n1 5 6\n1 6 2\n2 3 5\n3 4 6\n4 5 2\n5 6 3\n6 2 4\n").unwrap();
    let (code, out, _) = gmap(&["homology", p.to_str().unwrap(), "--json", "--generators"]);
    assert_eq!(code, 0);
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["torsion"], serde_json::json!([[], [2], []]));
    let g = v["generators"].as_array().unwrap();
    assert_eq!(g.len(), 2);
    assert_eq!(g[0]["dim"], 0);
    assert_eq!(g[1]["dim"], 1);
    assert_eq!(g[1]["order"], 2);
    // cells are simplices named by their labels from the file, by both routes
    for via in ["direct", "gmap"] {
        let (code, out, _) = gmap(&["homology", p.to_str().unwrap(), "--json", "--generators", "--via", via]);
        assert_eq!(code, 0, "{via}");
        let v: serde_json::Value = serde_json::from_str(&out).unwrap();
        let g = v["generators"].as_array().unwrap();
        assert_eq!(g[0]["chain"].as_array().unwrap().len(), 1);
        let cell = &g[0]["chain"][0]["cell"];
        assert!(cell.as_array().is_some_and(|c| c.len() == 1), "{via}: {cell}");
        let chain = g[1]["chain"].as_array().unwrap();
        assert!(!chain.is_empty());
        // a cycle: every vertex of its edges is met by coefficients summing to zero
        let mut at = std::collections::BTreeMap::<u64, i64>::new();
        for t in chain {
            let e: Vec<u64> = t["cell"].as_array().unwrap().iter().map(|x| x.as_u64().unwrap()).collect();
            assert!(e.len() == 2 && e[0] < e[1] && (1..=6).contains(&e[0]) && e[1] <= 6, "{via}: {t}");
            let c = t["coefficient"].as_i64().unwrap();
            *at.entry(e[1]).or_default() += c;
            *at.entry(e[0]).or_default() -= c;
        }
        assert!(at.values().all(|&x| x == 0), "{via}: {chain:?}");
    }
    // a G-map's cells by dart
    let q = dir.path().join("rp2.gmap");
    let (code, _, _) = gmap(&["convert", p.to_str().unwrap(), q.to_str().unwrap()]);
    assert_eq!(code, 0);
    let (code, out, _) = gmap(&["homology", q.to_str().unwrap(), "--json", "--generators"]);
    assert_eq!(code, 0);
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let t = &v["generators"][1];
    assert_eq!((t["dim"].as_u64(), t["order"].as_u64()), (Some(1), Some(2)));
    assert!(t["chain"][0]["cell"]["dart"].is_u64(), "{t}");
    let (code, out, _) = gmap(&["homology", q.to_str().unwrap(), "--generators"]);
    assert_eq!(code, 0);
    assert!(out.contains("generator of H_1 (Z/2): ") && out.contains(" dart "), "{out}");
    // a map with points: the cell's dart and its point
    let off = dir.path().join("tet.off");
    std::fs::write(&off, "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n").unwrap();
    let (code, out, _) = gmap(&["homology", off.to_str().unwrap(), "--json", "--generators"]);
    assert_eq!(code, 0);
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let cell = &v["generators"][0]["chain"][0]["cell"];
    assert!(cell["dart"].is_u64() && cell["point"].as_array().is_some_and(|p| p.len() == 3), "{cell}");
    // the simplicial counterpart: a dart and the dimensions of the cells spanning the simplex
    let (code, out, _) = gmap(&["homology", p.to_str().unwrap(), "--json", "--generators", "--method", "simplicial"]);
    assert_eq!(code, 0);
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let cell = &v["generators"][1]["chain"][0]["cell"];
    assert_eq!(cell["simplex"].as_array().map(Vec::len), Some(2), "{cell}");
    assert_eq!(v["route"], "gmap");
}

/// The groups of a Lutz file's header (`homology H_*=(Z,Z_5^3,0,Z)`), `None` for `(?)`.
fn header_groups(path: &Path) -> Option<(Vec<usize>, Vec<Vec<u64>>)> {
    let text = std::fs::read_to_string(path).unwrap();
    let line = text.lines().take(3).find(|l| l.contains("H_*="))?;
    let groups = line.split("H_*=").nth(1)?.split(';').next()?;
    parse_groups(groups)
}

/// `gmap homology FILE --json` (the direct route) on every file of the library, mixed
/// dimensions and non-pseudo-manifolds included, gives the groups of its header.
#[test]
fn every_lutz_file_by_the_direct_route() {
    let mut files: Vec<PathBuf> = std::fs::read_dir(lutz_dir())
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "facets"))
        .collect();
    files.sort();
    assert_eq!(files.len(), 44);
    for f in &files {
        let name = f.file_name().unwrap().to_string_lossy().into_owned();
        let (code, out, err) = gmap(&["homology", f.to_str().unwrap(), "--json"]);
        assert_eq!(code, 0, "{name}: {err}");
        let v: serde_json::Value = serde_json::from_str(&out).unwrap();
        assert_eq!(v["route"], "direct", "{name}");
        let betti: Vec<usize> = serde_json::from_value(v["betti"].clone()).unwrap();
        let mut torsion: Vec<Vec<u64>> = serde_json::from_value(v["torsion"].clone()).unwrap();
        match (name.as_str(), header_groups(f)) {
            // two tetrahedra on a triangle, and a triangle's boundary on their vertex 5
            ("scTest.facets", None) => {
                assert_eq!((betti, torsion), (vec![1, 1, 0, 0], vec![vec![]; 4]));
            }
            // the header gives Betti numbers mod 2; over Z it is the Wu manifold
            ("SU2_SO3.facets", Some((b2, _))) => {
                assert_eq!(
                    (betti, torsion),
                    (vec![1, 0, 0, 0, 0, 1], vec![vec![], vec![], vec![2], vec![], vec![], vec![]])
                );
                let (code, out, _) = gmap(&["homology", f.to_str().unwrap(), "--json", "--field", "2"]);
                assert_eq!(code, 0);
                let v: serde_json::Value = serde_json::from_str(&out).unwrap();
                assert_eq!(v["betti"], serde_json::json!(b2));
            }
            (_, Some((b, mut t))) => {
                for x in torsion.iter_mut().chain(t.iter_mut()) {
                    x.sort_unstable();
                }
                assert_eq!((betti, torsion), (b, t), "{name}");
            }
            (_, None) => panic!("{name}: no homology in the header"),
        }
    }
}

/// Facets of a mod-k Moore space: a disk (an annulus of two rings of 3k vertices and a fan
/// around a centre) whose boundary ring wraps the triangle 0 1 2 k times.
fn moore_space(k: u64) -> String {
    let n = 3 * k;
    let b = |i: u64| i % 3;
    let c = |i: u64| 3 + (i % n);
    let z = 3 + n;
    let mut out = String::new();
    for i in 0..n {
        out += &format!("{} {} {}\n", b(i), b(i + 1), c(i));
        out += &format!("{} {} {}\n", b(i + 1), c(i), c(i + 1));
        out += &format!("{} {} {}\n", c(i), c(i + 1), z);
    }
    out
}

#[test]
fn torsion_in_non_manifolds() {
    let dir = tempfile::tempdir().unwrap();
    for k in [3u64, 12] {
        let p = dir.path().join(format!("moore{k}.facets"));
        std::fs::write(&p, moore_space(k)).unwrap();
        let p = p.to_str().unwrap();
        let (code, out, err) = gmap(&["homology", p, "--json"]);
        assert_eq!(code, 0, "{err}");
        let v: serde_json::Value = serde_json::from_str(&out).unwrap();
        assert_eq!(v["betti"], serde_json::json!([1, 0, 0]), "k = {k}");
        assert_eq!(v["torsion"], serde_json::json!([[], [k], []]), "k = {k}");
        // over Z/3 the torsion of Z/3 and Z/12 gives one dimension in H_1 and one in H_2
        let (code, out, _) = gmap(&["homology", p, "--json", "--field", "3"]);
        assert_eq!(code, 0);
        let v: serde_json::Value = serde_json::from_str(&out).unwrap();
        assert_eq!(v["betti"], serde_json::json!([1, 1, 1]), "k = {k}");
        // a torsion generator: a cycle of edges along the triangle, order k
        let (code, out, _) = gmap(&["homology", p, "--json", "--generators"]);
        assert_eq!(code, 0);
        let v: serde_json::Value = serde_json::from_str(&out).unwrap();
        let t = v["generators"].as_array().unwrap().iter().find(|g| g["order"] == k).unwrap().clone();
        assert_eq!(t["dim"], 1);
        // the edges that wrap it are not pseudo-manifold ridges: the G-map route refuses
        let (code, _, err) = gmap(&["homology", p, "--via", "gmap"]);
        assert_eq!(code, 1);
        assert!(err.contains("lies in") && err.contains("facets"), "{err}");
    }
    let dunce = lutz_dir().join("dunce_hat.facets");
    let (code, out, _) = gmap(&["homology", dunce.to_str().unwrap()]);
    assert_eq!(code, 0);
    assert!(out.contains("H_0 = Z\nH_1 = 0\nH_2 = 0\n"), "{out}");
    // mixed dimensions, an isolated vertex, a book of three triangles, over Z/2 too
    let p = dir.path().join("mixed.facets");
    std::fs::write(&p, "1 2 3\n1 2 4\n1 2 5\n5 6\n6 7\n7 5\n9\n").unwrap();
    let (code, out, _) = gmap(&["homology", p.to_str().unwrap(), "--json", "--field", "2"]);
    assert_eq!(code, 0);
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["betti"], serde_json::json!([2, 1, 0]));
    assert_eq!(v["coefficients"], "Z/2");
    // a repeated vertex is refused, naming the line
    std::fs::write(&p, "1 2 3\n4 4 5\n").unwrap();
    let (code, _, err) = gmap(&["homology", p.to_str().unwrap()]);
    assert_eq!(code, 1);
    assert!(err.starts_with("error: ") && err.contains("line 2") && err.contains("repeats vertex 4"), "{err}");
    // too many faces: refused before enumerating, naming the estimate
    std::fs::write(&p, "1 2 3 4 5 6 7 8 9 10\n").unwrap();
    let (code, _, err) = gmap(&["homology", p.to_str().unwrap(), "--max-cells", "1000"]);
    assert_eq!(code, 1);
    assert!(err.contains("1023 faces") && err.contains("raise the limit with --max-cells N"), "{err}");
}

/// The direct route and the G-map route agree on every pseudo-manifold of the library
/// (within the dart range), over Z and Z/2.
fn direct_equals_gmap(lo: u64, hi: u64) -> usize {
    let mut checked = 0;
    for (file, darts, _, _) in lutz_cases() {
        if darts < lo || darts > hi {
            continue;
        }
        let path = lutz_dir().join(&file);
        let sc = gmap_ops::import::read_facets_complex(&path).unwrap();
        let direct = gmap_homology::simplices::face_complex(&sc.all_facets(), u64::MAX).unwrap().chain;
        let map = gmap_ops::import::read_facets(&path, None).unwrap();
        let cell = cellular_complex(&map).unwrap().chain;
        assert_eq!(homology_z(&direct).unwrap(), homology_z(&cell).unwrap(), "{file}");
        assert_eq!(homology_zp(&direct, 2).unwrap(), homology_zp(&cell, 2).unwrap(), "{file}");
        checked += 1;
    }
    checked
}

#[test]
fn direct_route_equals_gmap_route_on_lutz() {
    assert_eq!(direct_equals_gmap(0, 100_000), 30);
}

#[test]
#[ignore = "large inputs (up to 10^6 darts): run with --ignored in release mode"]
fn direct_route_equals_gmap_route_on_lutz_large() {
    assert_eq!(direct_equals_gmap(100_001, 1_000_000), 7);
}

/// Random pure pseudo-manifolds: facets drawn at random on few vertices, kept while no
/// ridge lies in three of them, and only where every face's star is connected through
/// ridges (so that the G-map glues exactly what the labels glue). Both routes agree.
fn random_pseudo_manifold(dim: usize, verts: u64, draws: &[Vec<u64>]) -> Vec<Vec<u64>> {
    use std::collections::{BTreeMap, BTreeSet};
    let mut facets: Vec<Vec<u64>> = Vec::new();
    let mut ridges: BTreeMap<Vec<u64>, usize> = BTreeMap::new();
    let mut seen = BTreeSet::new();
    for d in draws {
        let mut f: Vec<u64> = d.iter().map(|x| x % verts).collect();
        f.sort_unstable();
        f.dedup();
        if f.len() != dim + 1 || !seen.insert(f.clone()) {
            continue;
        }
        let rs: Vec<Vec<u64>> = (0..=dim).map(|i| [&f[..i], &f[i + 1..]].concat()).collect();
        if rs.iter().any(|r| ridges.get(r).copied().unwrap_or(0) >= 2) {
            continue;
        }
        for r in rs {
            *ridges.entry(r).or_default() += 1;
        }
        facets.push(f);
    }
    facets
}

/// Whether the facets containing each face are connected through ridges containing it.
fn stars_connected(facets: &[Vec<u64>]) -> bool {
    use std::collections::BTreeSet;
    let mut faces = BTreeSet::new();
    for f in facets {
        for mask in 1u32..(1 << f.len()) {
            faces.insert((0..f.len()).filter(|i| mask & (1 << i) != 0).map(|i| f[i]).collect::<Vec<u64>>());
        }
    }
    faces.iter().all(|s| {
        let star: Vec<&Vec<u64>> = facets.iter().filter(|f| s.iter().all(|v| f.contains(v))).collect();
        let mut reached = vec![false; star.len()];
        let mut stack = vec![0];
        reached[0] = true;
        while let Some(a) = stack.pop() {
            for b in 0..star.len() {
                let shared = star[a].iter().filter(|v| star[b].contains(v)).count();
                if !reached[b] && shared + 1 == star[a].len() {
                    reached[b] = true;
                    stack.push(b);
                }
            }
        }
        reached.iter().all(|&r| r)
    })
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(64))]
    #[test]
    fn direct_route_equals_gmap_route_on_random_pseudo_manifolds(
        dim in 1usize..4,
        verts in 4u64..9,
        draws in proptest::collection::vec(proptest::collection::vec(0u64..64, 4), 1..40),
    ) {
        let draws: Vec<Vec<u64>> = draws.into_iter().map(|d| d[..dim + 1].to_vec()).collect();
        let facets = random_pseudo_manifold(dim, verts, &draws);
        proptest::prop_assume!(!facets.is_empty() && stars_connected(&facets));
        let direct = gmap_homology::simplices::face_complex(&facets, u64::MAX).unwrap().chain;
        let sc = gmap_ops::import::SimplicialComplex::from_facets(facets.clone()).unwrap();
        let map = sc.to_gmap(1 << 20).unwrap();
        let by_map = simplicial_complex(&map);
        proptest::prop_assert_eq!(homology_z(&direct).unwrap(), homology_z(&by_map).unwrap(), "{:?}", facets);
        proptest::prop_assert_eq!(homology_zp(&direct, 2).unwrap(), homology_zp(&by_map, 2).unwrap());
        if let Ok(c) = cellular_complex(&map) {
            proptest::prop_assert_eq!(homology_z(&direct).unwrap(), homology_z(&c.chain).unwrap());
        }
    }
}

#[test]
fn output_cut_short_by_the_reader_is_not_a_crash() {
    // generators of a 16^3 torus grid print about 120 kB, more than a pipe holds; the reader stops early
    use std::io::Read;
    use std::process::Stdio;
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("grid.gmap");
    gmap_core::io::write_gmap(&build::grid(&[16, 16, 16], &[true; 3]).unwrap(), &path).unwrap();
    let mut child = Command::new(env!("CARGO_BIN_EXE_gmap"))
        .args(["homology", path.to_str().unwrap(), "--generators"])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut head = [0u8; 16];
    child.stdout.take().unwrap().read_exact(&mut head).unwrap();
    // dropping the pipe's read end closes it
    let out = child.wait_with_output().unwrap();
    assert_eq!(&head, b"dimension 3, met");
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success() && !err.contains("panicked"), "{:?} {err}", out.status);
}
