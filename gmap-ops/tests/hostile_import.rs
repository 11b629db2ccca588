//! Hostile inputs for the importers (`.off`, `.facets`, `.lex`, `.cub`, `.pbm`), from the hostile-input
//! audit: each reproducer is refused with an error naming the file and the line, without a
//! panic or an allocation the input does not justify; arbitrary and mutated bytes never make
//! a reader panic.

use std::path::{Path, PathBuf};

use gmap_ops::import::cubical::{parse_cub, parse_pbm, MAX_BOX_CUBES};
use gmap_ops::import::{
    read_cub, read_facets, read_lex, read_off, read_off_with, read_pbm, CubicalSet, ImportError, PolygonMesh,
    SimplicialComplex,
};
use proptest::prelude::*;

fn file(dir: &tempfile::TempDir, name: &str, bytes: &[u8]) -> PathBuf {
    let p = dir.path().join(name);
    std::fs::write(&p, bytes).unwrap();
    p
}

fn off_err(text: &str) -> String {
    let dir = tempfile::tempdir().unwrap();
    let p = file(&dir, "m.off", text.as_bytes());
    let e = read_off(&p).unwrap_err().to_string();
    let prefix = format!("{}: ", p.display());
    assert!(e.starts_with(&prefix), "{e}");
    e[prefix.len()..].to_string()
}

const SQUARE: &str = "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n";

#[test]
fn off_huge_polygon_size_is_an_error_not_a_panic() {
    let e = off_err(&format!("{SQUARE}18446744073709551615 0 1 2 3\n"));
    assert!(e.starts_with("line 7: "), "{e}");
    assert!(e.contains("darts") || e.contains("announces"), "{e}");
    // a size that fits the dart limit but not the line
    let e = off_err(&format!("{SQUARE}1000 0 1 2 3\n"));
    assert_eq!(e, "line 7: the polygon announces 1000 vertices but lists 4");
}

#[test]
fn off_non_finite_coordinates_are_refused() {
    for bad in ["NaN", "inf", "-inf", "infinity", "1e999"] {
        let e = off_err(&format!("OFF\n3 1 0\n0 0 0\n1 {bad} 0\n0 1 0\n3 0 1 2\n"));
        assert_eq!(e, format!("line 4: '{bad}' is not a finite coordinate"));
    }
}

#[test]
fn off_trailing_junk_is_refused() {
    let e = off_err(&format!("{SQUARE}4 0 1 2 3\n\n# fine\n3 0 1 2\n"));
    assert_eq!(e, "line 10: '3 0 1 2' after the 1 polygons the header announces: the counts are wrong");
    let e = off_err(&format!("{SQUARE}4 0 1 2 3\nsome junk\n"));
    assert!(e.starts_with("line 8: 'some junk' after"), "{e}");
}

#[test]
fn off_dart_limit_is_applied_before_building() {
    let dir = tempfile::tempdir().unwrap();
    let p = file(&dir, "m.off", format!("{SQUARE}4 0 1 2 3\n").as_bytes());
    assert_eq!(read_off_with(&p, Some(8)).unwrap().dart_count(), 8);
    let e = read_off_with(&p, Some(7)).unwrap_err();
    assert!(matches!(e.error, ImportError::TooManyDarts { darts: Some(8), limit: 7, .. }), "{e}");
    // announced polygons are counted before any is read: 10^9 polygons make 6·10^9 darts
    let q = file(&dir, "n.off", b"OFF\n3 1000000000 0\n");
    let e = read_off_with(&q, Some(1000)).unwrap_err();
    assert!(matches!(e.error, ImportError::TooManyDarts { darts: Some(6_000_000_000), .. }), "{e}");
}

#[test]
fn facets_repeated_facet_is_refused_naming_both_lines() {
    let e = SimplicialComplex::parse_facets("1 2 3\n1 2 3\n").unwrap_err();
    assert!(matches!(e, ImportError::RepeatedFacet { first: 1, second: 2 }), "{e}");
    assert_eq!(
        e.to_string(),
        "facet on line 2 repeats the facet on line 1 (a simplicial complex lists each facet once)"
    );
    // also in another order of the vertices, after other facets
    let e = SimplicialComplex::parse_facets("1 2 4\n3 2 1\n\n2,3,1\n").unwrap_err();
    assert!(matches!(e, ImportError::RepeatedFacet { first: 2, second: 4 }), "{e}");
    let e = SimplicialComplex::parse_lex("x=[[1,2],[2,3],[2,1]]", None).unwrap_err();
    assert!(matches!(e, ImportError::RepeatedFacet { first: 1, second: 1 }), "{e}");
}

#[test]
fn facets_one_big_facet_is_refused_before_allocating() {
    let dir = tempfile::tempdir().unwrap();
    // 23 bytes, 11! = 39,916,800 darts
    let p = file(&dir, "big.facets", b"0 1 2 3 4 5 6 7 8 9 10\n");
    assert_eq!(std::fs::metadata(&p).unwrap().len(), 23);
    let t = std::time::Instant::now();
    let e = read_facets(&p, Some(1_000_000)).unwrap_err();
    assert!(matches!(e.error, ImportError::TooManyDarts { darts: Some(39_916_800), limit: 1_000_000, .. }), "{e}");
    assert!(t.elapsed().as_secs() < 2);
    // the estimate counts the tables of orderings, not only the rows
    let sc = SimplicialComplex::parse_facets("0 1 2 3 4 5 6 7 8 9 10\n").unwrap();
    assert!(sc.memory_estimate().unwrap() > 5_000_000_000, "{:?}", sc.memory_estimate());
}

#[test]
fn long_tokens_are_quoted_short() {
    let long = "x".repeat(1 << 20);
    let dir = tempfile::tempdir().unwrap();
    type Read = Box<dyn Fn(&Path) -> String>;
    let cases: Vec<(PathBuf, Read)> = vec![
        (
            file(&dir, "a.off", format!("OFF\n3 1 0\n0 0 {long}\n").as_bytes()),
            Box::new(|p| read_off(p).unwrap_err().to_string()),
        ),
        (file(&dir, "b.off", format!("{long}\n").as_bytes()), Box::new(|p| read_off(p).unwrap_err().to_string())),
        (
            file(&dir, "c.off", format!("OFF\n{long} 1 0\n").as_bytes()),
            Box::new(|p| read_off(p).unwrap_err().to_string()),
        ),
        (
            file(&dir, "d.facets", format!("1 2 {long}\n").as_bytes()),
            Box::new(|p| read_facets(p, None).unwrap_err().to_string()),
        ),
        (
            file(&dir, "e.lex", format!("x=[[1,2,{}]]", "9".repeat(1 << 20)).as_bytes()),
            Box::new(|p| read_lex(p, None, None).unwrap_err().to_string()),
        ),
    ];
    for (p, read) in cases {
        let e = read(&p);
        assert!(e.len() < 300, "{}: {} bytes", p.display(), e.len());
        assert!(e.starts_with(&p.display().to_string()), "{e}");
    }
}

/// Valid inputs to mutate: an `.off` square, an octahedron's `.facets`, a `.lex` circle, a
/// `.cub` ring with negative coordinates and a duplicate, a P1 and a P4 bitmap.
const SEEDS: [&[u8]; 6] = [
    b"OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 3 2\n",
    b"1 2 3\n1 3 4\n1 4 5\n1 5 2\n6 2 3\n6 3 4\n6 4 5\n6 5 2\n",
    b"circle=[[1,2],[2,3],[3,1]]\nsphere=[[1,2,3],[1,2,4],[1,3,4],[2,3,4]]\n",
    b"; a ring\ndimension 2\n(-5, -7)\n(-5 -6)\n(-5,-5)\n(-4,-7)\n(-4,-5)\n(-3,-7)\n(-3,-6)\n(-3,-5)\n(-5 -7) ; again\n",
    b"P1\n# an annulus and a dot\n5 4\n1 1 1 1 0\n1 0 0 1 0\n1 1 1 1 0\n0 0 0 0 1\n",
    b"P4 5 4\n\xf0\x90\xf0\x08",
];

/// What every accepted cubical set satisfies: a non-empty box within the limit, a 0/1 bitmap
/// of its volume, the count of its ones.
fn check_set(s: &CubicalSet) {
    assert!(s.dim() >= 1 && s.min().len() == s.dim());
    let volume = s.shape().iter().try_fold(1u64, |v, &l| v.checked_mul(l as u64)).unwrap();
    assert!((1..=MAX_BOX_CUBES).contains(&volume));
    assert_eq!(s.bits().len() as u64, volume);
    assert!(s.bits().iter().all(|&b| b <= 1));
    assert_eq!(s.cube_count(), s.bits().iter().filter(|&&b| b == 1).count());
}

/// The cubes of a set as `.cub` lines.
fn cub_text(s: &CubicalSet) -> String {
    s.cubes().map(|c| format!("({})\n", c.iter().map(|x| x.to_string()).collect::<Vec<_>>().join(","))).collect()
}

/// Reads `bytes` with every importer; none may panic, every error names the file.
fn check_all(bytes: &[u8]) {
    let dir = tempfile::tempdir().unwrap();
    let limit = Some(100_000);
    for (name, read) in [
        ("f.off", &(|p: &Path| read_off_with(p, limit).map(|_| ())) as &dyn Fn(&Path) -> Result<(), _>),
        ("f.facets", &|p: &Path| read_facets(p, limit).map(|_| ())),
        ("f.lex", &|p: &Path| read_lex(p, None, limit).map(|_| ())),
        ("f.cub", &|p: &Path| read_cub(p).map(|_| ())),
        ("f.pbm", &|p: &Path| read_pbm(p).map(|_| ())),
    ] {
        let p = file(&dir, name, bytes);
        if let Err(e) = read(&p) {
            let text = e.to_string();
            assert!(text.starts_with(&p.display().to_string()), "{text}");
            assert!(text.chars().count() < 500, "{text}");
        }
    }
    if let Ok(text) = std::str::from_utf8(bytes) {
        if let Ok(mesh) = PolygonMesh::parse_limited(text, 100_000) {
            let _ = mesh.to_gmap();
        }
    }
    if let Ok(s) = parse_cub(bytes) {
        check_set(&s);
        assert!(s.cube_count() >= 1);
        if s.bits().len() <= 1 << 16 {
            assert_eq!(parse_cub(cub_text(&s).as_bytes()).unwrap(), s);
        }
    }
    if let Ok(s) = parse_pbm(bytes) {
        check_set(&s);
        assert_eq!((s.dim(), s.min()), (2, &[0i64, 0][..]));
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn arbitrary_bytes_never_panic(bytes in proptest::collection::vec(any::<u8>(), 0..200)) {
        check_all(&bytes);
    }

    #[test]
    fn arbitrary_text_never_panics(text in "[0-9 ,\\[\\]=#\\n.eE+-OFnaif]{0,120}") {
        check_all(text.as_bytes());
    }

    #[test]
    fn arbitrary_cubes_never_panic(text in "(dimension|[0-9 ,()\\-;\\r\\n]){0,80}") {
        check_all(text.as_bytes());
    }

    #[test]
    fn arbitrary_bitmaps_never_panic(magic in "P[14]", text in "[0-9 #\\n\\t]{0,60}", tail in proptest::collection::vec(any::<u8>(), 0..16)) {
        let mut bytes = format!("{magic}{text}").into_bytes();
        bytes.extend_from_slice(&tail);
        check_all(&bytes);
    }

    #[test]
    fn mutated_valid_files_never_panic(
        which in 0..SEEDS.len(),
        edits in proptest::collection::vec((any::<prop::sample::Index>(), any::<u8>(), 0u8..3), 1..6),
    ) {
        let mut bytes = SEEDS[which].to_vec();
        for (at, byte, kind) in edits {
            if bytes.is_empty() {
                bytes.push(byte);
                continue;
            }
            let k = at.index(bytes.len());
            match kind {
                0 => bytes[k] = byte,
                1 => bytes.insert(k, byte),
                _ => {
                    bytes.remove(k);
                }
            }
        }
        check_all(&bytes);
    }
}
