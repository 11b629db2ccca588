//! Small inputs that used to take minutes or gigabytes, rebuilt here: each run of `gmap`
//! exits 0 with the right groups or 1 with one `error:` line, quickly and within 2 GB of
//! address space. The full-size reproducers are `#[ignore]` tests (run with `--ignored`).

mod common;
use common::{p, stderr, stdout};

use std::path::Path;
use std::process::{Command, Output};
use std::time::{Duration, Instant};

use gmap_ops::rng::SplitMix64;

/// Runs `gmap ARGS` under `ulimit -v 2000000` (2 GB of address space), with its wall time.
fn gmap_2gb(args: &[&str]) -> (Output, Duration) {
    let quoted: Vec<String> = args.iter().map(|a| format!("'{a}'")).collect();
    let script = format!("ulimit -v 2000000 && exec '{}' {}", env!("CARGO_BIN_EXE_gmap"), quoted.join(" "));
    let t = Instant::now();
    let o = Command::new("sh").arg("-c").arg(script).output().expect("run sh");
    (o, t.elapsed())
}

/// A `.json` complex of `n` 1-regions and `n` 2-regions whose boundary matrix is the dense
/// `L · diag(d) · U`, `L` unit lower and `U` unit upper triangular with random entries in
/// `-1..=1`: its Smith form is `diag(d)` (made a divisibility chain), so `H_1` is
/// `⊕ Z/d_i` and `H_2 = 0`.
fn dense_json(dir: &Path, n: usize, d: &[i64], seed: u64) -> std::path::PathBuf {
    let mut rng = SplitMix64::new(seed);
    let mut tri = |lower: bool| -> Vec<Vec<i64>> {
        (0..n)
            .map(|i| {
                (0..n)
                    .map(|j| match (i == j, (j < i) == lower) {
                        (true, _) => 1,
                        (false, true) => rng.below(3) as i64 - 1,
                        (false, false) => 0,
                    })
                    .collect()
            })
            .collect()
    };
    let (l, u) = (tri(true), tri(false));
    let diag: Vec<i64> = (0..n).map(|k| if k + d.len() >= n { d[k + d.len() - n] } else { 1 }).collect();
    let mut text = String::from("{\"dimension\": 2, \"regions\": [");
    let regions: Vec<String> = (0..2 * n).map(|r| format!("{{\"id\": {r}, \"dim\": {}}}", 1 + r / n)).collect();
    text.push_str(&regions.join(", "));
    text.push_str("], \"incidence\": [");
    let mut entries = Vec::with_capacity(n * n);
    for (i, li) in l.iter().enumerate() {
        for j in 0..n {
            let a: i64 = li.iter().zip(&diag).zip(&u).map(|((x, d), uk)| x * d * uk[j]).sum();
            entries.push(format!("{{\"from\": {}, \"to\": {i}, \"weight\": {a}}}", n + j));
        }
    }
    text.push_str(&entries.join(",\n"));
    text.push_str("]}\n");
    let path = dir.join(format!("dense{n}.json"));
    std::fs::write(&path, text).unwrap();
    path
}

/// Asserts a run exits 0 within `secs` seconds and prints `expected` for `H_1`.
fn h1_is(path: &Path, expected: &str, secs: u64) {
    let (o, t) = gmap_2gb(&["homology", p(path)]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(t < Duration::from_secs(secs), "took {t:?}");
    let out = stdout(&o);
    assert!(out.contains(&format!("H_1 = {expected}\n")) && out.contains("H_2 = 0\n"), "{out}");
}

#[test]
fn dense_json_boundary_matrix() {
    let dir = tempfile::tempdir().unwrap();
    // 3 · 2^40 = 3298534883328
    let path = dense_json(dir.path(), 90, &[2, 6, 3 * (1 << 40)], 1);
    h1_is(&path, "Z/2 + Z/6 + Z/3298534883328", 20);
}

/// The reproducer: a dense 240 × 240 boundary matrix (over 200 s before).
#[test]
#[ignore]
fn dense_json_boundary_matrix_240() {
    let dir = tempfile::tempdir().unwrap();
    let path = dense_json(dir.path(), 240, &[4, 12, 7 * (1 << 50)], 2);
    // diag(4, 12, 7 · 2^50) has the invariant factors 4, 4, 21 · 2^50
    h1_is(&path, "Z/4 + Z/4 + Z/23643898043695104", 60);
}

/// Asserts exit code 1, one `error:` line containing each of `needles`, within 60 s.
fn refused_in_time((o, t): (Output, Duration), needles: &[&str]) {
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(err.starts_with("error: ") && err.lines().count() == 1, "{err}");
    for n in needles {
        assert!(err.contains(n), "{err} should contain {n}");
    }
    assert!(t < Duration::from_secs(60), "took {t:?}");
}

/// One 11-vertex facet (23 bytes): its G-map has 11! darts and its tables of orderings as
/// many again (6.4 GB); refused at once under 2 GB, while its homology by the direct route
/// (2047 faces) is that of a point.
#[test]
fn one_eleven_vertex_facet() {
    let dir = tempfile::tempdir().unwrap();
    let one = dir.path().join("one.facets");
    std::fs::write(&one, "0 1 2 3 4 5 6 7 8 9 10\n").unwrap();
    assert_eq!(std::fs::metadata(&one).unwrap().len(), 23);
    let needles = ["one.facets", "the G-map of the facets would take an estimated 6426605196 bytes", "--max-memory"];
    refused_in_time(gmap_2gb(&["info", p(&one)]), &needles);
    refused_in_time(gmap_2gb(&["convert", p(&one), p(&dir.path().join("one.gmap"))]), &needles);
    let (o, _) = gmap_2gb(&["homology", p(&one)]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stdout(&o).contains("H_0 = Z\n") && stdout(&o).contains("euler characteristic 1"), "{}", stdout(&o));
    // seven of them, on disjoint vertices
    let seven = dir.path().join("seven.facets");
    let lines: Vec<String> =
        (0..7).map(|f| (0..11).map(|v| (11 * f + v).to_string()).collect::<Vec<_>>().join(" ")).collect();
    std::fs::write(&seven, lines.join("\n")).unwrap();
    refused_in_time(gmap_2gb(&["info", p(&seven)]), &["seven.facets", "the G-map of the facets would take"]);
    // an explicit limit below: the same refusal whatever the machine
    let o = common::gmap(&["info", p(&one), "--max-memory", "100M"]);
    refused_in_time((o, Duration::ZERO), &["over the memory limit of 104857600 bytes"]);
}

/// The face poset of the 10-simplex (2047 cells, 11! flags) as a `.json` complex: its
/// homology is computed on the cells; converting it to a G-map is refused before the flags
/// are listed.
#[test]
fn face_poset_of_a_ten_simplex() {
    let dir = tempfile::tempdir().unwrap();
    let faces: Vec<u32> = (1u32..1 << 11).collect();
    let index = |f: u32| faces.binary_search(&f).unwrap();
    let mut text = String::from("{\"regions\": [");
    let regions: Vec<String> =
        faces.iter().enumerate().map(|(i, f)| format!("{{\"id\": {i}, \"dim\": {}}}", f.count_ones() - 1)).collect();
    text.push_str(&regions.join(", "));
    text.push_str("], \"incidence\": [");
    let mut entries = Vec::new();
    for (i, &f) in faces.iter().enumerate() {
        if f.count_ones() < 2 {
            continue;
        }
        for (k, v) in (0..11).filter(|v| f & (1 << v) != 0).enumerate() {
            let sign = if k % 2 == 0 { 1 } else { -1 };
            entries.push(format!("{{\"from\": {i}, \"to\": {}, \"weight\": {sign}}}", index(f & !(1 << v))));
        }
    }
    text.push_str(&entries.join(",\n"));
    text.push_str("]}\n");
    let poset = dir.path().join("simplex10.json");
    std::fs::write(&poset, text).unwrap();
    let (o, t) = gmap_2gb(&["homology", p(&poset)]);
    assert!(o.status.success() && t < Duration::from_secs(60), "{}", stderr(&o));
    assert!(stdout(&o).contains("H_0 = Z\nH_1 = 0\n"), "{}", stdout(&o));
    let out = dir.path().join("simplex10.gmap");
    refused_in_time(gmap_2gb(&["convert", p(&poset), p(&out)]), &["simplex10.gmap", "flags", "--max-memory"]);
    assert!(!out.exists());
    let o = common::gmap(&["convert", p(&poset), p(&out), "--max-darts", "100000000", "--max-memory", "1G"]);
    refused_in_time(
        (o, Duration::ZERO),
        &["the flags of the face poset would take an estimated 4790016000 bytes, over the memory limit of 1073741824"],
    );
}

/// The simplicial counterpart is estimated before it is built, and files before they are
/// read; `--max-memory` takes sizes with suffixes and refuses anything else as bad usage.
#[test]
fn estimates_before_allocations() {
    let dir = tempfile::tempdir().unwrap();
    let one_dart = dir.path().join("one.gmap");
    std::fs::write(&one_dart, format!("gmap 12 1\n{}\n", ["0"; 13].join(" "))).unwrap();
    let o = common::gmap(&["homology", p(&one_dart), "--method", "simplicial", "--max-memory", "1M"]);
    refused_in_time((o, Duration::ZERO), &["one.gmap", "the simplicial counterpart would take an estimated"]);
    let o = common::gmap(&["info", p(&one_dart), "--max-memory", "16"]);
    refused_in_time((o, Duration::ZERO), &["one.gmap", "the file and its map would take an estimated 108 bytes"]);
    assert!(common::gmap(&["info", p(&one_dart), "--max-memory", "1k"]).status.success());
    for bad in ["0", "2X", "1.5G", "-1"] {
        let o = common::gmap(&["info", p(&one_dart), "--max-memory", bad]);
        assert_eq!(o.status.code(), Some(2), "{bad}: {}", stderr(&o));
    }
}

/// Tiny `.cub` and `.pbm` files whose bounding box is huge: refused from the box, before the
/// bitmap is allocated, with the estimate (one byte a box cube and 9 per point of the doubled
/// grid) named; `--periodic` and `--max-memory` take the same route.
#[test]
fn cubical_bounding_boxes_are_estimated_before_allocation() {
    let dir = tempfile::tempdir().unwrap();
    let cases: [(&str, &str, &str); 4] = [
        // 2^30 cubes on a line: 2^30 + 9 (2^31 + 1) bytes
        ("line.cub", "(0)\n(1073741823)\n", "the bounding box 1073741824 would take an estimated 20401094665 bytes"),
        (
            "corners.cub",
            "(0,0)\n(32767,32767)",
            "the bounding box 32768 × 32768 would take an estimated 39729627145 bytes",
        ),
        ("header.pbm", "P4 99999 99999\n", "the bounding box 99999 × 99999 would take an estimated 369996200010 bytes"),
        ("header1.pbm", "P1 40000 40000\n", "the bounding box 40000 × 40000 would take an estimated 59201440009 bytes"),
    ];
    for (name, text, estimate) in cases {
        let path = dir.path().join(name);
        std::fs::write(&path, text).unwrap();
        for args in [vec!["info", p(&path)], vec!["homology", p(&path)], vec!["homology", p(&path), "--periodic"]] {
            refused_in_time(gmap_2gb(&args), &[name, estimate, "--max-memory"]);
        }
    }
    assert_eq!(std::fs::metadata(dir.path().join("line.cub")).unwrap().len(), 17);
    // a 3000 × 3000 box holding two cubes: 9 000 000 + 9 · 6001² bytes
    let two = dir.path().join("two.cub");
    std::fs::write(&two, "(0,0)\n(2999,2999)\n").unwrap();
    let o = common::gmap(&["homology", p(&two), "--max-memory", "300M"]);
    refused_in_time(
        (o, Duration::ZERO),
        &["would take an estimated 333108009 bytes, over the memory limit of 314572800"],
    );
    let (o, _) = gmap_2gb(&["homology", p(&two)]);
    assert!(stdout(&o).contains("H_0 = Z^2\nH_1 = 0\n"), "{}", stderr(&o));
    // on the torus the two cubes meet at a corner
    let (o, _) = gmap_2gb(&["homology", p(&two), "--periodic"]);
    assert!(stdout(&o).contains("H_0 = Z\nH_1 = 0\n"), "{}", stderr(&o));
}

/// `--simplify` on the periodic G-map of a set of 20 cubes (960 darts, every cell meeting
/// itself): the search past plateaus tried up to 400 splits per round, each checked on the
/// whole map, for up to 4000 rounds (seconds); its work is now bounded by `2304 · search`
/// darts plus one round, and the groups are kept.
#[test]
fn simplify_of_a_periodic_cube_set_is_bounded() {
    let cubes = [
        [0, 0, 0],
        [1, 0, 0],
        [2, 0, 0],
        [0, 1, 0],
        [1, 1, 0],
        [1, 2, 0],
        [2, 2, 0],
        [0, 0, 1],
        [2, 0, 1],
        [1, 1, 1],
        [2, 1, 1],
        [2, 2, 1],
        [0, 0, 2],
        [1, 0, 2],
        [2, 0, 2],
        [1, 1, 2],
        [2, 1, 2],
        [0, 2, 2],
        [1, 2, 2],
        [2, 2, 2],
    ];
    let text: String = cubes.iter().map(|c| format!("({},{},{})\n", c[0], c[1], c[2])).collect();
    let map = gmap_ops::import::cubical::parse_cub(text.as_bytes()).unwrap().gmap(true).unwrap();
    assert_eq!(map.dart_count(), 960);
    let groups = |m: &gmap_core::DenseMap| {
        gmap_homology::homology_z(&gmap_homology::cellular_complex(m).unwrap().chain).unwrap().to_string()
    };
    let before = groups(&map);
    assert_eq!(before, "(Z, Z^3, Z, 0)");
    let options = gmap_ops::euler::SimplifyOptions::for_map(&map);
    let (small, report) = gmap_ops::euler::simplify_with(&map, &options);
    assert_eq!(groups(&small), before);
    assert!(small.dart_count() < 100, "{}", small.dart_count());
    // 2304 · 4000 darts, plus one round of at most 400 tries on a map of at most 1100 darts
    assert!(report.search_work <= 2304 * 4000 + 400 * 1100 + 1100, "{}", report.search_work);
    assert!(report.search_rounds < 4000, "{}", report.search_rounds);
    // the same map from the command line
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("cubes20.gmap");
    gmap_core::io::write_gmap(&map, &path).unwrap();
    let (plain, _) = gmap_2gb(&["homology", p(&path)]);
    let (o, t) = gmap_2gb(&["homology", p(&path), "--simplify"]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(t < Duration::from_secs(30), "took {t:?}");
    let groups_of = |s: String| s.lines().filter(|l| l.starts_with("H_")).collect::<Vec<_>>().join("\n");
    assert_eq!(groups_of(stdout(&o)), groups_of(stdout(&plain)));
    assert_eq!(groups_of(stdout(&o)), "H_0 = Z\nH_1 = Z^3\nH_2 = Z\nH_3 = 0");
}

/// The map of `base` (a `k`-map) lifted to a 14-map: its darts `base × {0,1}^(14-k)`, each
/// `alpha_j`, `j > k`, swapping the two copies that differ in bit `j - k - 1` (the iterated
/// suspension of `base`, cells of dimension above `k` in pairs), or free where `flip` says
/// no. `2^(14-k)` times the darts of `base`.
fn lifted_to_14(base: &gmap_core::DenseMap, flip: &[bool]) -> gmap_core::DenseMap {
    let (k, b) = (base.dim(), base.dart_count());
    let m = 14 - k;
    let mut flat = Vec::with_capacity((b << m) * 15);
    for c in 0..1usize << m {
        for d in 0..b {
            flat.extend(base.flat()[d * (k + 1)..(d + 1) * (k + 1)].iter().map(|&x| (c * b) as u32 + x));
            flat.extend((0..m).map(|j| if flip[j] { ((c ^ (1 << j)) * b + d) as u32 } else { (c * b + d) as u32 }));
        }
    }
    gmap_core::DenseMap::try_from_flat(14, flat).unwrap()
}

/// 14-maps of 2.8 MB and more (25,000 to 40,000 darts): the 14-sphere of two cells in every
/// dimension (32,768 darts, the size of the reproducer), the suspensions of a triangle and of
/// a torus, a lens space lifted with some involutions free, and a polygon of 30,000 darts
/// (long orbits) with every other involution free. Each run answers with the right groups or
/// refuses with `error:` (C1 or C2 failing), well within 60 s under 2 GB.
#[test]
fn fourteen_dimensional_maps() {
    let dir = tempfile::tempdir().unwrap();
    let polygon = |sides: u32| {
        let n = 2 * sides;
        let flat = (0..n).flat_map(|d| [d ^ 1, if d % 2 == 1 { (d + 1) % n } else { (d + n - 1) % n }]).collect();
        gmap_core::DenseMap::try_from_flat(1, flat).unwrap()
    };
    let globe = lifted_to_14(&polygon(2), &[true; 13]);
    let triangle = lifted_to_14(&polygon(3), &[true; 13]);
    let torus = lifted_to_14(&gmap_core::examples::torus(), &[true; 12]);
    let mut some = [true; 11];
    some[4] = false;
    let lens = lifted_to_14(&gmap_ops::build::lens_space(5, 1).unwrap(), &some);
    let long = {
        let p = polygon(15_000);
        let flat: Vec<u32> = (0..30_000u32)
            .flat_map(|d| p.flat()[2 * d as usize..2 * d as usize + 2].iter().copied().chain([d; 13]))
            .collect();
        gmap_core::DenseMap::try_from_flat(14, flat).unwrap()
    };
    assert_eq!(
        [globe.dart_count(), triangle.dart_count(), torus.dart_count(), lens.dart_count(), long.dart_count()],
        [32_768, 49_152, 32_768, 40_960, 30_000]
    );
    let sphere = "H_0 = Z\n".to_string() + &(1..14).map(|k| format!("H_{k} = 0\n")).collect::<String>() + "H_14 = Z\n";
    let cases: [(&str, &gmap_core::DenseMap, Result<&str, &str>); 5] = [
        ("globe", &globe, Ok(&sphere)),
        ("triangle", &triangle, Ok(&sphere)),
        ("torus", &torus, Err("the 3-cell of dart 0 is not bounded by a sphere")),
        (
            "lens",
            &lens,
            Err("the 4-cell of dart 0 is not bounded by a sphere: its boundary has homology (Z, Z/5, 0, Z)"),
        ),
        ("long", &long, Err("has no neighbour along alpha_2")),
    ];
    for (name, map, expected) in cases {
        let path = dir.path().join(format!("{name}.gmap"));
        gmap_core::io::write_gmap(map, &path).unwrap();
        if name == "globe" {
            assert_eq!(std::fs::metadata(&path).unwrap().len(), 2_782_484);
        }
        let (o, t) = gmap_2gb(&["info", p(&path)]);
        assert!(o.status.success() && t < Duration::from_secs(30), "{name}: {} {t:?}", stderr(&o));
        for extra in [None, Some("--simplify"), Some("--generators")] {
            let mut args = vec!["homology", p(&path)];
            args.extend(extra);
            let (o, t) = gmap_2gb(&args);
            match expected {
                Ok(groups) => {
                    assert!(o.status.success(), "{name} {extra:?}: {}", stderr(&o));
                    assert!(stdout(&o).contains(groups), "{name} {extra:?}: {}", stdout(&o));
                    assert!(t < Duration::from_secs(30), "{name} {extra:?} took {t:?}");
                }
                Err(why) => refused_in_time((o, t), &[name, why]),
            }
        }
    }
}

/// Whatever the memory limit, one 11-vertex facet (23 bytes) is refused at once: the default
/// dart limit of the facets import is also what `2^30` dart visits can analyse
/// (`gmap_core::resources::max_darts_for_work`: 8,873,899 darts in dimension 10, against
/// 11! = 39,916,800); an explicit `--max-darts` is the way past it.
#[test]
fn eleven_vertex_facet_under_a_large_memory_limit() {
    let dir = tempfile::tempdir().unwrap();
    let one = dir.path().join("one.facets");
    std::fs::write(&one, "0 1 2 3 4 5 6 7 8 9 10\n").unwrap();
    assert_eq!(gmap_core::resources::max_darts_for_work(10), 8_873_899);
    for cmd in ["info", "convert"] {
        let out = dir.path().join("one.gmap");
        let mut args = vec![cmd, p(&one)];
        if cmd == "convert" {
            args.push(p(&out));
        }
        args.extend(["--max-memory", "1T"]);
        let t = Instant::now();
        let o = common::gmap(&args);
        refused_in_time(
            (o, t.elapsed()),
            &["one.facets", "1 facets of dimension 10 make 39916800 darts", "--max-darts"],
        );
        assert!(t.elapsed() < Duration::from_secs(10), "{:?}", t.elapsed());
        assert!(!out.exists());
    }
}

/// The simplicial counterpart of a one-dart n-map is the full simplex on n + 1 vertices
/// after subdivision: `2^(n+1) (n + 2)` simplices whose reduction costs about `(n + 1)^2`
/// each. Held to the work limit of 2^30: n = 17 (1,613,758,464 steps, half a minute and more
/// before) is refused at once, whatever the memory limit; n = 12 is answered.
#[test]
fn one_dart_maps_by_the_simplicial_method() {
    let dir = tempfile::tempdir().unwrap();
    let one = |n: usize| {
        let path = dir.path().join(format!("one{n}.gmap"));
        std::fs::write(&path, format!("gmap {n} 1\n{}\n", vec!["0"; n + 1].join(" "))).unwrap();
        path
    };
    let p17 = one(17);
    let t = Instant::now();
    let o = common::gmap(&["homology", p(&p17), "--method", "simplicial", "--max-memory", "1T"]);
    refused_in_time(
        (o, t.elapsed()),
        &["one17.gmap", "an estimated 1613758464 steps, over the work limit of 1073741824"],
    );
    assert!(t.elapsed() < Duration::from_secs(5));
    let (o, t) = gmap_2gb(&["homology", p(&one(12)), "--method", "simplicial"]);
    assert!(o.status.success() && t < Duration::from_secs(30), "{} {t:?}", stderr(&o));
    assert!(
        stdout(&o).contains("H_0 = Z\nH_1 = 0\n") && stdout(&o).contains("euler characteristic 1"),
        "{}",
        stdout(&o)
    );
}

/// A sparse 1 TB `.npy` (a header declaring 10000³ = 10^12 `u1` voxels, then a hole): every
/// command refuses it at once with its estimate and the file's name, before reading a
/// value — `info`, `view` and `homology --generators` with the whole cubical set's (what
/// they build), `homology` with the layers its one pass over the file would hold.
#[test]
fn a_sparse_terabyte_npy_is_refused_with_an_estimate() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("huge.npy");
    let dict = "{'descr': '|u1', 'fortran_order': False, 'shape': (10000, 10000, 10000), }";
    let mut header = format!("{dict}{}\n", " ".repeat((64 - (10 + dict.len() + 1) % 64) % 64)).into_bytes();
    let mut bytes = b"\x93NUMPY\x01\x00".to_vec();
    bytes.extend_from_slice(&(header.len() as u16).to_le_bytes());
    bytes.append(&mut header);
    std::fs::write(&path, &bytes).unwrap();
    let f = std::fs::OpenOptions::new().write(true).open(&path).unwrap();
    f.set_len(bytes.len() as u64 + 1_000_000_000_000).unwrap();
    drop(f);
    let limit = ", over the memory limit of 8589934592 bytes (--max-memory)";
    let whole = format!(
        "error: {}: the cubical set on the bounding box 10000 × 10000 × 10000 would take an estimated 73010800540009 bytes{limit}",
        path.display()
    );
    let layers = format!(
        "error: {}: the layers of the one-pass cubical homology would take an estimated 14405760576 bytes{limit}",
        path.display()
    );
    for (args, want) in [
        (vec!["info"], &whole),
        (vec!["view"], &whole),
        (vec!["homology", "--generators"], &whole),
        (vec!["homology"], &layers),
        (vec!["homology", "--level", "0"], &layers),
    ] {
        let mut cmd = args.clone();
        cmd.extend_from_slice(&[p(&path), "--max-memory", "8G"]);
        let t = Instant::now();
        let o = common::gmap(&cmd);
        assert_eq!(o.status.code(), Some(1), "{args:?}: {}", stderr(&o));
        assert_eq!(stderr(&o).trim_end(), want.as_str(), "{args:?}");
        assert!(t.elapsed() < Duration::from_secs(60), "{args:?} took {:?}", t.elapsed());
    }
}
