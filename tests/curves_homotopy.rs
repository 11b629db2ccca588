//! Homotopy tests of paths (`gmap::homotopy`): CGAL 5.5.1's `Surface_mesh_topology`
//! examples `path_homotopy_double_torus`, `open_path_homotopy` (on
//! `double-torus-example.off`, with the deterministic paths of
//! `tests/data/cgal/double-torus-paths.txt` in place of the examples' random ones) and
//! `path_homotopy_with_symbols` (its schema and paths), against the answers CGAL gave,
//! recorded in `tests/data/cgal/double-torus.homotopy.txt` by `homotopy.cpp` (how:
//! `tests/data/cgal/README.md`); then known answers on the torus, the cylinder, the Klein
//! bottle, and refusals of what is not a path.

use std::collections::HashMap;
use std::path::PathBuf;

use gmap::core::DenseMap;
use gmap::homotopy::{PathSpec, Paths};
use gmap::{Input, MapInput};

fn data(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/data/cgal").join(name)
}

fn paths_of(map: DenseMap) -> Paths {
    Paths::new(&Input::Map(MapInput::new(map))).unwrap()
}

/// The gmap vertex of each vertex of the .off (by its point).
fn off_vertices(text: &str, map: &DenseMap) -> Vec<u64> {
    let mut lines = text.lines().filter(|l| !l.trim().is_empty() && !l.starts_with('#')).skip(1);
    let nv: usize = lines.next().unwrap().split_whitespace().next().unwrap().parse().unwrap();
    let key = |p: [f64; 3]| p.map(|x| (x * 1e5).round() as i64);
    let v = map.cells(0);
    let mut by_point = HashMap::new();
    for (k, r) in v.reps.iter().enumerate() {
        by_point.insert(key(map.vertex_point(*r).unwrap()), k as u64);
    }
    (0..nv)
        .map(|_| {
            let c: Vec<f64> = lines.next().unwrap().split_whitespace().map(|x| x.parse().unwrap()).collect();
            by_point[&key([c[0], c[1], c[2]])]
        })
        .collect()
}

#[test]
fn cgal_double_torus_examples() {
    let input = gmap::open(data("double-torus-example.off")).unwrap();
    let map = input.to_map().unwrap().into_owned();
    let of = off_vertices(&std::fs::read_to_string(data("double-torus-example.off")).unwrap(), &map);
    let paths = paths_of(map);
    let text = std::fs::read_to_string(data("double-torus-paths.txt")).unwrap();
    let mut named: HashMap<String, PathSpec> = HashMap::new();
    for l in text.lines().filter(|l| l.starts_with("path ")) {
        let w: Vec<&str> = l.split_whitespace().collect();
        let vs: Vec<u64> = w[2..].iter().map(|x| of[x.parse::<usize>().unwrap()]).collect();
        named.insert(w[1].to_string(), PathSpec::Vertices(vs));
    }
    let rec = std::fs::read_to_string(data("double-torus.homotopy.txt")).unwrap();
    let mut checked = 0;
    for l in rec.lines().filter(|l| !l.starts_with("symbols")) {
        let w: Vec<&str> = l.split_whitespace().collect();
        let want = w[w.len() - 1] == "1";
        let got = match w[0] {
            "contractible" => paths.is_contractible(&named[w[1]]),
            "free" => paths.are_freely_homotopic(&named[w[1]], &named[w[2]]),
            "fixed" => paths.are_homotopic_with_fixed_endpoints(&named[w[1]], &named[w[2]]),
            other => panic!("unknown question {other}"),
        };
        assert_eq!(got.unwrap_or_else(|e| panic!("{l}: {e}")), want, "{l}");
        checked += 1;
    }
    assert_eq!(checked, 55);
}

/// The G-map of one polygon whose sides are glued by their labels (`a`, `-a`, …), as
/// CGAL's `Polygonal_schema`: side i has darts 2i (at corner i) and 2i + 1 (at corner
/// i + 1); and the darts of a word of labels.
fn schema(facet: &str) -> (DenseMap, impl Fn(&str) -> Vec<u64>) {
    let sides: Vec<(String, bool)> =
        facet.split_whitespace().map(|s| (s.trim_start_matches('-').to_string(), !s.starts_with('-'))).collect();
    let k = sides.len();
    let mut flat = vec![0u32; 2 * k * 3];
    for i in 0..k {
        let (s, e) = (2 * i, 2 * i + 1);
        flat[s * 3] = e as u32;
        flat[e * 3] = s as u32;
        let next = 2 * ((i + 1) % k);
        flat[e * 3 + 1] = next as u32;
        flat[next * 3 + 1] = e as u32;
        let j = (0..k).find(|&j| j != i && sides[j].0 == sides[i].0).unwrap();
        let same = sides[i].1 == sides[j].1;
        let (s2, e2) = if same { (2 * j, 2 * j + 1) } else { (2 * j + 1, 2 * j) };
        flat[s * 3 + 2] = s2 as u32;
        flat[e * 3 + 2] = e2 as u32;
    }
    let map = DenseMap::try_from_flat(2, flat).unwrap();
    let word = move |w: &str| {
        w.split_whitespace()
            .map(|l| {
                let (name, fwd) = (l.trim_start_matches('-'), !l.starts_with('-'));
                let i = sides
                    .iter()
                    .position(|(n, s)| n == name && *s)
                    .unwrap_or_else(|| sides.iter().position(|(n, _)| n == name).unwrap());
                let pos = sides[i].1;
                // dart 2i leaves the side's tail when the side is written +
                (2 * i + usize::from(fwd != pos)) as u64
            })
            .collect()
    };
    (map, word)
}

#[test]
fn cgal_path_homotopy_with_symbols() {
    let rec = std::fs::read_to_string(data("double-torus.homotopy.txt")).unwrap();
    let want = |k: &str| rec.lines().find(|l| l.starts_with(k)).unwrap().ends_with(" 1");
    let (map, word) = schema("a b -a -b c d -c -d");
    let paths = paths_of(map);
    let (p1, p2) = (PathSpec::Darts(word("a")), PathSpec::Darts(word("b c a -c -b")));
    assert_eq!(paths.are_freely_homotopic(&p1, &p2).unwrap(), want("symbols free"));
    assert_eq!(paths.are_homotopic_with_fixed_endpoints(&p1, &p2).unwrap(), want("symbols fixed"));
    // genus 2 and not contractible: not decided here, refused
    let e = paths.is_homotopic_to_simple_cycle(&p1).unwrap_err().to_string();
    assert!(e.contains("not decided here"), "{e}");
    // the relator is contractible, a b a⁻¹ b⁻¹ is not (it bounds the handle)
    assert!(paths.is_contractible(&PathSpec::Darts(word("a b -a -b c d -c -d"))).unwrap());
    assert!(!paths.is_contractible(&PathSpec::Darts(word("a b -a -b"))).unwrap());
    assert!(paths.is_contractible(&PathSpec::Darts(word("c d -c -d a b -a -b"))).unwrap());
}

/// A surface written as .off text (points `(i, j, 0)` or given), with the map's vertex
/// of each .off vertex.
fn mesh(points: &[[f64; 3]], faces: &[Vec<usize>]) -> (Paths, Vec<u64>) {
    let mut text = format!("OFF\n{} {} 0\n", points.len(), faces.len());
    for p in points {
        text += &format!("{} {} {}\n", p[0], p[1], p[2]);
    }
    for f in faces {
        let v: Vec<String> = f.iter().map(usize::to_string).collect();
        text += &format!("{} {}\n", f.len(), v.join(" "));
    }
    // written under the target directory (the .off reader reads files)
    static COUNT: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let n = COUNT.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let file =
        PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("curves_homotopy_{}_{n}.off", std::process::id()));
    std::fs::write(&file, &text).unwrap();
    let input = gmap::open(&file).unwrap();
    std::fs::remove_file(&file).unwrap();
    let map = input.to_map().unwrap().into_owned();
    let of = off_vertices(&text, &map);
    (paths_of(map), of)
}

/// The a × b grid of squares with vertex (i, j) numbered i + a j, i periodic; rows wrap
/// to row 0 as they are (`wrap = Some(false)`, a torus), flipped (`Some(true)`, a Klein
/// bottle) or not at all (a cylinder).
fn grid(a: usize, b: usize, wrap: Option<bool>) -> (Paths, Vec<u64>) {
    let points: Vec<[f64; 3]> = (0..a * b).map(|k| [(k % a) as f64, (k / a) as f64, 0.0]).collect();
    let id = |i: usize, j: usize| -> usize {
        if j < b {
            i % a + a * j
        } else if wrap == Some(true) {
            (a - i % a) % a
        } else {
            i % a
        }
    };
    let rows = if wrap.is_some() { b } else { b - 1 };
    let faces: Vec<Vec<usize>> = (0..rows)
        .flat_map(|j| (0..a).map(move |i| (i, j)))
        .map(|(i, j)| vec![id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)])
        .collect();
    mesh(&points, &faces)
}

#[test]
fn torus_cylinder_klein_projective_plane() {
    let (t, of) = grid(4, 3, Some(false));
    let v = |of: &[u64], x: &[usize]| PathSpec::Vertices(x.iter().map(|&k| of[k]).collect());
    let round = v(&of, &[0, 1, 2, 3, 0]);
    let round_up = v(&of, &[4, 5, 6, 7, 4]);
    let other = v(&of, &[0, 4, 8, 0]);
    let kind = t.kind();
    assert!(kind.orientable && !kind.boundary && kind.euler == 0 && kind.generators == 2);
    assert!(!t.is_contractible(&round).unwrap());
    assert!(t.are_freely_homotopic(&round, &round_up).unwrap());
    assert!(!t.are_freely_homotopic(&round, &other).unwrap());
    assert!(!t.are_freely_homotopic(&round, &v(&of, &[0, 3, 2, 1, 0])).unwrap());
    assert!(t.is_homotopic_to_simple_cycle(&round).unwrap());
    assert!(!t.is_homotopic_to_simple_cycle(&v(&of, &[0, 1, 2, 3, 0, 1, 2, 3, 0])).unwrap());
    // (1, 1): simple
    assert!(t.is_homotopic_to_simple_cycle(&v(&of, &[0, 1, 2, 3, 0, 4, 8, 0])).unwrap());
    // a square is contractible
    assert!(t.is_contractible(&v(&of, &[0, 1, 5, 4, 0])).unwrap());
    // fixed ends: two ways from 0 to 2 round the ring differ, the same way pushed agrees
    assert!(!t.are_homotopic_with_fixed_endpoints(&v(&of, &[0, 1, 2]), &v(&of, &[0, 3, 2])).unwrap());
    assert!(t.are_homotopic_with_fixed_endpoints(&v(&of, &[0, 1, 2]), &v(&of, &[0, 4, 5, 1, 2])).unwrap());

    // a cylinder (annulus): free group on one generator
    let (c, of) = grid(4, 3, None);
    let kind = c.kind();
    assert!(kind.boundary && kind.orientable && kind.generators == 1);
    assert!(!c.is_contractible(&v(&of, &[0, 1, 2, 3, 0])).unwrap());
    assert!(c.are_freely_homotopic(&v(&of, &[0, 1, 2, 3, 0]), &v(&of, &[8, 9, 10, 11, 8])).unwrap());
    assert!(!c.are_freely_homotopic(&v(&of, &[0, 1, 2, 3, 0]), &v(&of, &[0, 3, 2, 1, 0])).unwrap());
    assert!(c.is_contractible(&v(&of, &[0, 1, 2, 3, 0, 3, 2, 1, 0])).unwrap());
    assert!(c.is_contractible(&v(&of, &[0, 1, 5, 4, 0])).unwrap());

    // the Klein bottle: a = the row (keeps the orientation), b = the column (reverses it),
    // b a b⁻¹ = a⁻¹
    let (k, of) = grid(4, 3, Some(true));
    let kind = k.kind();
    assert!(!kind.orientable && !kind.boundary && kind.euler == 0 && kind.generators == 2);
    let row = v(&of, &[0, 1, 2, 3, 0]);
    let column = v(&of, &[0, 4, 8, 0]);
    assert!(!k.is_contractible(&row).unwrap());
    assert!(!k.is_contractible(&column).unwrap());
    assert!(!k.is_contractible(&v(&of, &[0, 4, 8, 0, 4, 8, 0])).unwrap());
    assert!(k.is_contractible(&v(&of, &[0, 1, 5, 4, 0])).unwrap());
    // the row is freely homotopic to its reverse (across the column), and to the next row
    assert!(k.are_freely_homotopic(&row, &v(&of, &[0, 3, 2, 1, 0])).unwrap());
    assert!(k.are_freely_homotopic(&row, &v(&of, &[4, 5, 6, 7, 4])).unwrap());
    assert!(!k.are_freely_homotopic(&row, &v(&of, &[0, 1, 2, 3, 0, 1, 2, 3, 0])).unwrap());
    assert!(!k.are_freely_homotopic(&row, &column).unwrap());
    // fixed ends: the row and its reverse are not homotopic as loops at 0
    assert!(!k.are_homotopic_with_fixed_endpoints(&row, &v(&of, &[0, 3, 2, 1, 0])).unwrap());
    // two orientation-reversing loops of the Klein bottle: refused
    let e = k.are_freely_homotopic(&column, &v(&of, &[1, 5, 9, 3, 2, 1])).err().map(|e| e.to_string());
    assert!(e.is_some_and(|e| e.contains("Klein bottle")));

    // the projective plane of 6 vertices (half an icosahedron): a triangle that is not a
    // face is its non-contractible loop, contractible twice
    let faces: Vec<Vec<usize>> =
        [[0, 1, 2], [0, 2, 3], [0, 3, 4], [0, 4, 5], [0, 5, 1], [1, 2, 4], [2, 3, 5], [3, 4, 1], [4, 5, 2], [5, 1, 3]]
            .iter()
            .map(|f| f.to_vec())
            .collect();
    let points: Vec<[f64; 3]> = (0..6).map(|k| [k as f64, (k * k) as f64, 1.0]).collect();
    let (rp, of) = mesh(&points, &faces);
    let kind = rp.kind();
    assert!(!kind.orientable && !kind.boundary && kind.euler == 1);
    let line = v(&of, &[0, 1, 3, 0]);
    assert!(!rp.is_contractible(&line).unwrap());
    assert!(rp.is_contractible(&v(&of, &[0, 1, 3, 0, 1, 3, 0])).unwrap());
    assert!(rp.is_contractible(&v(&of, &[0, 1, 2, 0])).unwrap());
    assert!(rp.are_freely_homotopic(&line, &v(&of, &[1, 2, 5, 1])).unwrap());
    assert!(!rp.are_freely_homotopic(&line, &v(&of, &[0, 1, 2, 0])).unwrap());
    assert!(rp.is_homotopic_to_simple_cycle(&line).unwrap());
}

#[test]
fn not_a_path_is_refused() {
    let (t, of) = grid(4, 3, Some(false));
    let e = t.is_contractible(&PathSpec::Vertices(vec![of[0], of[2]])).unwrap_err().to_string();
    assert!(e.contains("step 0") && e.contains("0 edges join vertex"), "{e}");
    let e = t.is_contractible(&PathSpec::Vertices(vec![of[0], of[1], of[2]])).unwrap_err().to_string();
    assert!(e.contains("a closed path is needed"), "{e}");
    let e = t.is_contractible(&PathSpec::Darts(vec![0, 0])).unwrap_err().to_string();
    assert!(e.contains("step 1: dart 0 does not start"), "{e}");
    let e = t.is_contractible(&PathSpec::Darts(vec![100_000])).unwrap_err().to_string();
    assert!(e.contains("is not a dart of the map"), "{e}");
    let e = t
        .are_homotopic_with_fixed_endpoints(
            &PathSpec::Vertices(vec![of[0], of[1]]),
            &PathSpec::Vertices(vec![of[0], of[4]]),
        )
        .unwrap_err()
        .to_string();
    assert!(e.contains("the same ends"), "{e}");
    // a 3-map is not a surface
    let cube = gmap::ops::build::cube(3).unwrap();
    assert!(Paths::new(&Input::Map(MapInput::new(cube))).is_err());
}

mod props {
    use super::*;
    use gmap::core::{Dart, GMap};
    use gmap::ops::euler::random::{random_steps, Operator};
    use gmap::ops::rng::SplitMix64;
    use proptest::prelude::*;

    /// A random dart at the vertex of `d`.
    fn at_vertex(map: &DenseMap, d: Dart, rng: &mut SplitMix64) -> Dart {
        let ds = map.cell_darts(d, 0);
        ds[(rng.next_u64() % ds.len() as u64) as usize]
    }

    /// A random walk of `len` steps from the vertex of `d`.
    fn walk(map: &DenseMap, d: Dart, len: usize, rng: &mut SplitMix64) -> Vec<Dart> {
        let mut w = Vec::new();
        let mut at = d;
        for _ in 0..len {
            let x = at_vertex(map, at, rng);
            w.push(x);
            at = map.alpha(x, 0);
        }
        w
    }

    /// The walk back: each step reversed, last first.
    fn reverse(map: &DenseMap, w: &[Dart]) -> Vec<Dart> {
        w.iter().rev().map(|&x| map.alpha(x, 0)).collect()
    }

    /// h ∂f h⁻¹ from the vertex of `d`: a walk, the boundary of a face at its end, back.
    fn lasso(map: &DenseMap, d: Dart, len: usize, rng: &mut SplitMix64) -> Vec<Dart> {
        let h = walk(map, d, len, rng);
        let end = h.last().map_or(d, |&x| map.alpha(x, 0));
        let y0 = at_vertex(map, end, rng);
        let mut l = h.clone();
        let mut y = y0;
        loop {
            l.push(y);
            y = map.alpha(map.alpha(y, 0), 1);
            if y == y0 {
                break;
            }
        }
        l.extend(reverse(map, &h));
        l
    }

    fn ids(w: &[Dart]) -> PathSpec {
        PathSpec::Darts(w.iter().map(|d| u64::from(d.get())).collect())
    }

    /// The surfaces: a torus, a Klein bottle, CGAL's double torus, each after `steps`
    /// random Euler operators that keep the surface (vertex and edge insertions, removals
    /// and contractions keeping homology).
    fn surface(which: usize, steps: usize, seed: u64) -> DenseMap {
        let base = match which {
            0 => gmap::ops::build::grid(&[5, 4], &[true, true]).unwrap(),
            1 => gmap::core::examples::klein_bottle(),
            _ => gmap::open(data("double-torus-example.off")).unwrap().to_map().unwrap().into_owned(),
        };
        let (mut g, _) = GMap::from_dense(&base);
        let mut rng = SplitMix64::new(seed);
        let ops = [Operator::InsertVertex, Operator::InsertEdge, Operator::RemoveCell, Operator::ContractCell];
        random_steps(&mut g, steps, &ops, &mut rng);
        g.to_dense_with_ids().0
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 48, ..ProptestConfig::default() })]

        /// The shortest non-contractible cycle c is not contractible; c times a lasso is
        /// homotopic to c with fixed ends and not contractible; a lasso, twice, and a walk
        /// there and back are contractible; c rotated is never found not freely homotopic
        /// to c (it is, or the answer is refused).
        #[test]
        fn homotopic_paths_found_so(which in 0usize..3, steps in 0usize..30, seed in any::<u64>(), len in 0usize..12) {
            let map = surface(which, steps, seed);
            let Ok(paths) = Paths::new(&Input::Map(MapInput::new(map.clone()))) else {
                return Err(TestCaseError::reject("not a surface after the operators"));
            };
            let s = gmap::algebra::curves::Surface::of_map(&map, &gmap::algebra::curves::Weights::Unit).unwrap();
            let c = gmap::algebra::curves::shortest_non_contractible_cycle(&s).unwrap().unwrap();
            let c = c.darts(&s, &map);
            let mut rng = SplitMix64::new(seed ^ 0x48);
            prop_assert!(!paths.is_contractible(&ids(&c)).unwrap());
            let l = lasso(&map, c[0], len, &mut rng);
            prop_assert!(paths.is_contractible(&ids(&l)).unwrap());
            let mut ll = l.clone();
            ll.extend_from_slice(&l);
            prop_assert!(paths.is_contractible(&ids(&ll)).unwrap());
            let mut cl = c.clone();
            cl.extend_from_slice(&l);
            prop_assert!(!paths.is_contractible(&ids(&cl)).unwrap());
            prop_assert!(paths.are_homotopic_with_fixed_endpoints(&ids(&cl), &ids(&c)).unwrap());
            let w = walk(&map, c[0], len + 1, &mut rng);
            let mut back = w.clone();
            back.extend(reverse(&map, &w));
            prop_assert!(paths.is_contractible(&ids(&back)).unwrap());
            let k = (seed as usize) % c.len();
            let mut rot = c[k..].to_vec();
            rot.extend_from_slice(&c[..k]);
            prop_assert!(paths.are_freely_homotopic(&ids(&c), &ids(&rot)).unwrap_or(true));
            prop_assert!(paths.are_freely_homotopic(&ids(&cl), &ids(&c)).unwrap_or(true));
        }
    }
}
