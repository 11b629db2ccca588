//! The local formulas of the border operator (`border_from_oriented`) agree with the orbit
//! walks of BO Def. 9 (`border_by_walks`) on 3- and 4-dimensional maps, and the ring walks
//! of 3-maps (`check_preconditions`) with the per-dimension traversals
//! (`check_by_dimension`), darts in file order or shuffled.

use gmap_core::DenseMap;
use gmap_homology::border::{border_by_walks, border_from_oriented};
use gmap_homology::{check_by_dimension, check_preconditions};
use gmap_ops::build;

fn agree(name: &str, m: &DenseMap) {
    let oriented = check_preconditions(m).unwrap_or_else(|e| panic!("{name}: {e}"));
    assert_eq!(Ok(&oriented), check_by_dimension(m).as_ref(), "{name}");
    if m.dim() == 3 {
        assert!(m.oriented_cells_3d().is_some(), "{name}: ring walks apply");
    }
    // a shuffled numbering: rings no longer next to the scan, cells numbered otherwise
    let n = m.dart_count() as u64;
    let perm: Vec<u32> = (0..n).map(|d| ((d * 7919 + 13) % n) as u32).collect();
    if !n.is_multiple_of(7919) {
        let p = m.permuted(&perm);
        assert_eq!(check_preconditions(&p), check_by_dimension(&p), "{name} shuffled");
    }
    let fast = border_from_oriented(m, &oriented);
    let slow = border_by_walks(m, &oriented);
    assert_eq!(fast.chain, slow.chain, "{name}");
    fast.chain.check_dd().unwrap();
}

#[test]
fn three_and_four_dimensional_objects() {
    agree("3-torus 3x4x2", &build::grid(&[3, 4, 2], &[true; 3]).unwrap());
    agree("open grid 2x2x3", &build::grid(&[2, 2, 3], &[false, true, false]).unwrap());
    agree("4-torus 2^4", &build::grid(&[2, 2, 2, 2], &[true; 4]).unwrap());
    agree("4-cube grid", &build::grid(&[2, 1, 2, 1], &[false; 4]).unwrap());
    agree("solid torus", &build::solid_torus(5).unwrap());
    for (p, q) in [(5, 2), (7, 3), (2, 1)] {
        agree("lens space", &build::lens_space(p, q).unwrap());
    }
    for name in ["poincare.facets", "RP4.facets", "B_3_9_18.facets"] {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../tests/data/lutz").join(name);
        agree(name, &gmap_ops::import::read_facets(&path, None).unwrap());
    }
}
