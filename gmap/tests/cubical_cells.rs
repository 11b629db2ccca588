//! Cubical cell complexes (CHomP's cell syntax): the groups of known complexes, and the cell
//! reading of the closure of random full cubes against their full-cube reading.

use gmap::{homology, InfoOptions, Input, Sourced};
use gmap_homology::cubical::{cubical_cell_complex_with, cubical_complex_with};
use gmap_homology::homology_z;
use gmap_ops::import::cubical::{parse_cub, CubicalSet};
use proptest::prelude::*;

fn groups(set: &CubicalSet, periodic: bool) -> (Vec<usize>, usize) {
    let mut o = gmap::HomologyOptions::default();
    o.periodic = periodic;
    o.generators = true;
    let r = homology(&Input::Cubical(Sourced::new(set.clone())), &o).unwrap();
    (r.groups.betti, r.groups.torsion.iter().map(Vec::len).sum())
}

fn betti(text: &str) -> Vec<usize> {
    groups(&parse_cub(text.as_bytes()).unwrap(), false).0
}

#[test]
fn known_complexes() {
    // the four edges of a square: a circle
    assert_eq!(betti("[0,1]x[0]\n[0,1]x[1]\n[0]x[0,1]\n[1]x[0,1]\n"), vec![1, 1, 0]);
    // the six 2-faces of a cube: a sphere
    let sphere =
        "[0,1]x[0,1]x[0]\n[0,1]x[0,1]x[1]\n[0,1]x[0]x[0,1]\n[0,1]x[1]x[0,1]\n[0]x[0,1]x[0,1]\n[1]x[0,1]x[0,1]\n";
    assert_eq!(betti(sphere), vec![1, 0, 1, 0]);
    // the twelve edges of a cube: a graph of 8 vertices and 12 edges, H_1 = Z^5
    let mut edges = String::new();
    for (a, b) in [(0, 1), (0, 2), (1, 2)] {
        for u in 0..2 {
            for v in 0..2 {
                let mut iv = [String::new(), String::new(), String::new()];
                let c = 3 - a - b;
                iv[c] = "[0,1]".into();
                iv[a] = format!("[{u}]");
                iv[b] = format!("[{v}]");
                edges.push_str(&format!("{}\n", iv.join("x")));
            }
        }
    }
    assert_eq!(betti(&edges), vec![1, 5, 0, 0]);
    // full cubes and lower cells: two squares with a hanging edge, a loop of edges apart, a
    // lone point
    let mixed = "(0,0)\n(1,0)\n[2,3]x[0]\n[0,1]x[3]\n[1]x[3,4]\n[0,1]x[4]\n[0]x[3,4]\n[5]x[5]\n";
    let set = parse_cub(mixed.as_bytes()).unwrap();
    assert_eq!((set.cube_count(), set.lower_cell_count()), (2, 6));
    assert_eq!(groups(&set, false).0, vec![3, 1, 0]);
    let info = gmap::info(&Input::Cubical(Sourced::new(set)), &InfoOptions::default()).unwrap();
    let gmap::Info::Cubical(i) = info else { panic!("{info:?}") };
    assert_eq!((i.cells, i.euler_characteristic), (vec![12, 12, 2], 2));
}

#[test]
fn periodic_cells_wrap() {
    // a row of edges across a 3-wide periodic box closes into a circle, a column of
    // points does not
    let row = parse_cub(b"[0,1]x[0]\n[1,2]x[0]\n[2,3]x[0]\n").unwrap();
    assert_eq!(groups(&row, false).0, vec![1, 0, 0]);
    let boxed = row.with_box(&[0, 0], &[2, 2]).unwrap();
    assert_eq!(groups(&boxed, true).0, vec![1, 1, 0]);
    // the two edges 0x[0,1] and 0x[1,2] on a box of height 2: a circle around the torus
    let col = parse_cub(b"box (0,0) (1,1)\n[0]x[0,1]\n[0]x[1,2]\n").unwrap();
    assert_eq!(groups(&col, true).0, vec![1, 1, 0]);
    assert_eq!(groups(&col, false).0, vec![1, 0, 0]);
}

#[test]
fn cubes_only_routes_refuse_lower_cells() {
    let set = parse_cub(b"(0,0)\n[5]x[5]\n").unwrap();
    let e = set.gmap_of_union(false).unwrap_err().to_string();
    assert!(e.contains("1 cells of dimension below 2 on no 2-cube (the first: 5x5)"), "{e}");
    assert!(gmap_ops::export::cubical_vtk_string(&set).is_err());
    let p = gmap::persistence(&Input::Cubical(Sourced::new(set)), &Default::default()).unwrap_err();
    assert!(p.to_string().contains("first: 5x5"), "{p}");
}

/// Every cell of the closure of the cubes of `set`, as `[a,a+1]` and `[a]` products, one a
/// line, and in doubled coordinates relative to the box.
fn closure_cells(set: &CubicalSet) -> (String, Vec<usize>) {
    let d = set.dim();
    let mut seen = std::collections::BTreeSet::new();
    for c in set.cubes() {
        for mask in 0u32..3u32.pow(d as u32) {
            // per axis: 0 the interval, 1 the lower point, 2 the upper point
            let mut m = mask;
            let cell: Vec<i64> = (0..d)
                .map(|a| {
                    let t = m % 3;
                    m /= 3;
                    match t {
                        0 => 2 * c[a] + 1,
                        1 => 2 * c[a],
                        _ => 2 * c[a] + 2,
                    }
                })
                .collect();
            seen.insert(cell);
        }
    }
    let mut text = String::new();
    let mut rel = Vec::new();
    for cell in &seen {
        let parts: Vec<String> = cell
            .iter()
            .map(|&x| if x % 2 != 0 { format!("[{},{}]", (x - 1) / 2, (x + 1) / 2) } else { format!("[{}]", x / 2) })
            .collect();
        text.push_str(&parts.join(" x "));
        text.push('\n');
        rel.extend(cell.iter().enumerate().map(|(a, &x)| (x - 2 * set.min()[a]) as usize));
    }
    (text, rel)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]
    #[test]
    fn closure_of_random_cubes_read_as_cells(
        three in any::<bool>(),
        seed in any::<u64>(),
        periodic in any::<bool>(),
    ) {
        let dims: &[i64] = if three { &[3, 3, 2] } else { &[4, 3] };
        let mut s = seed | 1;
        let mut text = String::new();
        let count: i64 = dims.iter().product();
        for i in 0..count {
            s = s.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            if (s >> 33) % 100 < 55 || i == 0 {
                let mut r = i;
                let c: Vec<String> = dims.iter().map(|&l| { let x = r % l - 1; r /= l; x.to_string() }).collect();
                text.push_str(&format!("({})\n", c.join(",")));
            }
        }
        let cubes = parse_cub(text.as_bytes()).unwrap();
        let (cell_text, rel) = closure_cells(&cubes);
        let cells = parse_cub(cell_text.as_bytes()).unwrap();
        // the same set, and the same groups through the facade
        prop_assert_eq!(&cells, &cubes);
        prop_assert!(cells.is_full());
        prop_assert_eq!(groups(&cells, periodic), groups(&cubes, periodic));
        // the closure given as cells alone (no cube bit) builds the same complex
        let zeros = vec![0u8; cubes.bits().len()];
        let by_cells = cubical_cell_complex_with(cubes.shape(), &zeros, &rel, periodic, false).unwrap().chain;
        let by_cubes = cubical_complex_with(cubes.shape(), cubes.bits(), periodic, false).unwrap().chain;
        by_cells.check_dd().unwrap();
        prop_assert_eq!(by_cells.counts(), by_cubes.counts());
        prop_assert_eq!(homology_z(&by_cells).unwrap(), homology_z(&by_cubes).unwrap());
    }
}

#[test]
fn a_gmap_of_cubes_pinched_at_a_cell_is_refused() {
    // two squares at a corner, two cubes along an edge
    for (text, cell) in [("(0,0)\n(1,1)\n", "1x1"), ("(0,0,0)\n(1,1,0)\n", "1x1x0")] {
        let set = parse_cub(text.as_bytes()).unwrap();
        let e = set.gmap_of_union(false).unwrap_err().to_string();
        assert!(e.contains(&format!("the cubes around the cell {cell} fall into 2 groups")), "{e}");
    }
    // joined below through three more cubes at the vertex (1,1,0), still pinched along the
    // edge above it
    let set = parse_cub(b"(0,0,0)\n(1,1,0)\n(0,0,-1)\n(1,0,-1)\n(1,1,-1)\n").unwrap();
    assert_eq!(set.pinched_cell(false), Some(("1x1x[0,1]".to_string(), 2)));
    // apart in their box, pinched across its wrap-around
    let set = parse_cub(b"box (0,0) (2,2)\n(0,0)\n(2,2)\n").unwrap();
    assert_eq!(set.pinched_cell(false), None);
    assert!(set.gmap_of_union(false).is_ok());
    assert_eq!(set.pinched_cell(true), Some(("0x0".to_string(), 2)));
    // an L of three squares is not pinched
    assert_eq!(parse_cub(b"(0,0)\n(1,1)\n(0,1)\n").unwrap().pinched_cell(false), None);
    // the facade says so and names the input
    let dir = tempfile::tempdir().unwrap();
    let src = dir.path().join("corner.cub");
    std::fs::write(&src, "(0,0)\n(1,1)\n").unwrap();
    let out = dir.path().join("corner.gmap");
    let e = gmap::save_file(&src, &out, &gmap::SaveOptions::default()).unwrap_err().to_string();
    assert!(e.contains(&src.display().to_string()) && e.contains("cell 1x1"), "{e}");
    assert!(!out.exists());
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, ..ProptestConfig::default() })]

    /// Random 2-D and 3-D sets, periodic or not: the G-map of the cubes is refused exactly
    /// when a cell is pinched, and when it is made its groups are the cubical set's.
    #[test]
    fn a_gmap_of_cubes_keeps_the_space_or_is_refused(
        d in 2usize..4,
        periodic in any::<bool>(),
        bits in prop::collection::vec(any::<bool>(), 27),
    ) {
        let n = 3usize.pow(d as u32);
        let shape = vec![3usize; d];
        let set = CubicalSet::new(vec![0; d], shape, bits[..n].iter().map(|&b| b as u8).collect()).unwrap();
        prop_assume!(set.cube_count() > 0);
        let pinched = set.pinched_cell(periodic);
        match set.gmap_of_union(periodic) {
            Err(e) => prop_assert!(pinched.is_some(), "{e}"),
            Ok(m) => {
                prop_assert!(pinched.is_none());
                let r = homology(&Input::Map(gmap::MapInput::new(m)), &gmap::HomologyOptions::default()).unwrap();
                let (betti, torsion) = groups(&set, periodic);
                prop_assert_eq!(r.groups.betti, betti);
                prop_assert_eq!(r.groups.torsion.iter().map(Vec::len).sum::<usize>(), torsion);
            }
        }
    }
}
