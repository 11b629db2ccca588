//! Simplification of the Lutz library's manifolds (3- and 4-dimensional, closed or with
//! boundary): the reduced map keeps the homology stated in each file's header, its cells
//! satisfy C1/C2 (the cellular method accepts it), and it is smaller.

use std::path::PathBuf;

use gmap_homology::{cellular_complex, homology_z};
use gmap_ops::euler::simplify;
use gmap_ops::import::simplicial::read_facets;

fn lutz(name: &str) -> PathBuf {
    PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/../shared/data/lutz")).join(name)
}

/// The homology in the header, normalised: `(Z,Z_2,0,Z)` → `(Z,Z/2,0,Z)`.
fn stated_homology(name: &str) -> String {
    let text = std::fs::read_to_string(lutz(name)).expect("fixture");
    let line = text.lines().nth(1).expect("header line");
    let start = line.find("H_*=").expect("homology in header") + 4;
    let end = line[start..].find(';').map(|k| start + k).unwrap_or(line.len());
    line[start..end].replace("Z_", "Z/").replace(' ', "")
}

/// Simplifies, checks the homology against the header, returns the dart ratio.
fn check(name: &str) -> f64 {
    let map = read_facets(&lutz(name), None).expect("pseudo-manifold");
    let (small, report) = simplify(&map);
    assert!(small.validate().is_ok());
    assert_eq!(report.darts_before, map.dart_count());
    let chain = cellular_complex(&small).unwrap_or_else(|e| panic!("{name}: reduced cells fail C1/C2: {e}"));
    let h = homology_z(&chain.chain).expect("homology");
    assert_eq!(h.to_string().replace(' ', ""), stated_homology(name), "{name}");
    report.ratio()
}

#[test]
fn three_spheres_and_balls() {
    for name in
        ["Barnette_sphere.facets", "B_3_9_18.facets", "S_3_50_1033.facets", "rudin.facets", "trefoil_arc.facets"]
    {
        check(name);
    }
}

#[test]
fn closed_three_manifolds() {
    // closed 3-manifolds with torsion and with big Betti numbers. The greedy reduction stops
    // at a one-vertex, one-volume map whose edges mostly have degree 3: far from the 5 %
    // reached on hexahedral grids. The ratios are exact for this algorithm.
    for (name, cells, darts) in [
        ("600_cell.facets", [1, 99, 99, 1], 1312),
        ("Hom_C5_K4.facets", [1, 681, 681, 1], 8708),
        ("poincare.facets", [1, 60, 60, 1], 724),
    ] {
        let map = read_facets(&lutz(name), None).expect("pseudo-manifold");
        let (small, report) = simplify(&map);
        assert_eq!((small.cell_counts(), small.dart_count()), (cells.to_vec(), darts), "{name}");
        assert_eq!(report.cells_after, cells.to_vec());
        check(name);
    }
    for name in ["S_3_1000_2990.facets", "nc_sphere.facets"] {
        assert!(check(name) < 0.2);
    }
}

#[test]
fn four_manifolds() {
    for name in ["CP2.facets", "RP4.facets", "K3_16.facets"] {
        check(name);
    }
}

#[test]
#[ignore = "456,192 darts: run with --ignored (a few seconds in release)"]
fn big_three_manifold() {
    // 456,192 darts -> 115,268 (25 %): homology (Z, Z^13, Z^13, Z) kept
    let r = check("Hom_n9_655_compl_K4.facets");
    assert!(r < 0.26, "{r}");
}
