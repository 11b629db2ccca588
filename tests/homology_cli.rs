//! Homology of classic objects and of the Benedetti–Lutz library by both methods, and the
//! `gmap homology` command line (CONTRACT §1).

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
        flat.push(d.0);
    }
    let m = DenseMap::try_from_flat(3, flat).unwrap();
    match cellular_complex(&m) {
        Err(PreconditionError::C2 { dim: 3, dart: Dart(0), .. }) => {}
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
        let mut got: Vec<Vec<u64>> = h.torsion.clone();
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
    assert_eq!(g[0]["dimension"], 0);
    assert_eq!(g[1]["dimension"], 1);
    assert_eq!(g[1]["order"], 2);
    assert!(!g[1]["chain"].as_array().unwrap().is_empty());
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
