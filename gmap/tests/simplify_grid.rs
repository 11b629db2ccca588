//! Simplification of hexahedral grids (a 3-ball) and periodic grids (a 3-torus): the
//! reduced map keeps the homology, passes C1/C2, and has at most 5 % of the darts.

use gmap_homology::{cellular_complex, homology_z, Homology};
use gmap_ops::build::grid;
use gmap_ops::euler::simplify;

fn reduced_homology(k: usize, periodic: bool) -> (Homology, f64, Vec<usize>) {
    let map = grid(&[k, k, k], &[periodic; 3]).expect("grid");
    let (small, report) = simplify(&map);
    assert!(small.validate().is_ok());
    assert_eq!(small.euler_characteristic(), map.euler_characteristic());
    let chain = cellular_complex(&small).expect("reduced cells satisfy C1/C2");
    (homology_z(&chain.chain).expect("homology"), report.ratio(), report.cells_after)
}

#[test]
fn small_grids_exact() {
    // 4^3 torus: one vertex and one volume remain
    let (h, _, cells) = reduced_homology(4, true);
    assert_eq!(h.betti, vec![1, 3, 3, 1]);
    assert_eq!((cells[0], cells[3]), (1, 1));
    let (h, _, cells) = reduced_homology(4, false);
    assert_eq!(h.betti, vec![1, 0, 0, 0]);
    assert!(h.torsion.iter().all(|t| t.is_empty()));
    assert_eq!(cells[3], 1);
}

/// The k³ grid and the k³ torus reduce to at most 5 % of their darts with their homology.
fn below_five_percent(k: usize) {
    for periodic in [false, true] {
        let (h, ratio, _) = reduced_homology(k, periodic);
        let want = if periodic { vec![1, 3, 3, 1] } else { vec![1, 0, 0, 0] };
        assert_eq!(h.betti, want);
        assert!(ratio <= 0.05, "k {k}, periodic {periodic}: {ratio}");
    }
}

#[test]
fn grid_20_below_five_percent() {
    below_five_percent(20);
}

#[test]
#[ignore = "3,072,000 darts: run with --ignored --release"]
fn grid_40_below_five_percent() {
    below_five_percent(40);
}
