//! Condition C2 in dimensions 4 and 5: the check that shares one homology computation
//! among isomorphic compacted cells, and computes it on the cell's own cells, gives the
//! verdict of the cell-by-cell check (the simplicial homology of every compacted cell, in
//! order of smallest dart) and the groups of the Lutz headers (over Z); a 5-cell bounded by a
//! pinched suspension is refused, one bounded by a suspended homology sphere accepted.

use gmap_core::{CompactedCells, Dart, DenseMap};
use gmap_homology::{cellular_complex, check_preconditions, homology_z, simplicial_complex, PreconditionError};
use gmap_ops::import::{read_facets, SimplicialComplex};

fn lutz(name: &str) -> std::path::PathBuf {
    std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/lutz").join(name)
}

/// The first i-cell, `i >= 3`, lowest dimension first and then by smallest dart, whose
/// compacted cell is not a homology sphere, checked one cell at a time by the simplicial
/// method: `(i, smallest dart, homology found)`. C1 is assumed.
fn c2_cell_by_cell(map: &DenseMap) -> Option<(usize, Dart, String)> {
    for i in 3..=map.dim() {
        let b = CompactedCells::new(map, i);
        let cells = map.cells(i);
        let mut elems_of: Vec<Vec<u32>> = vec![Vec::new(); cells.len()];
        for e in 0..b.len() as u32 {
            elems_of[b.cell_of[e as usize] as usize].push(e);
        }
        let mut local = vec![u32::MAX; b.len()];
        for (elems, &rep) in elems_of.iter().zip(&cells.reps) {
            for (k, &e) in elems.iter().enumerate() {
                local[e as usize] = k as u32;
            }
            let (local, b) = (&local, &b);
            let flat = elems.iter().flat_map(|&e| (0..i).map(move |k| local[b.alpha(e, k) as usize])).collect();
            let sub = DenseMap::from_flat_unchecked(i - 1, flat).unwrap();
            let h = homology_z(&simplicial_complex(&sub)).unwrap();
            let m = i - 1;
            let sphere = h.torsion.iter().all(Vec::is_empty)
                && h.betti.iter().enumerate().all(|(k, &x)| x == usize::from(k == 0 || k == m));
            if !sphere {
                return Some((i, rep, h.to_string()));
            }
        }
    }
    None
}

/// The dimension, dart and homology named by a C2 refusal.
fn c2_of(e: &PreconditionError) -> (usize, Dart, String) {
    match e {
        PreconditionError::C2 { dim, dart, found } => {
            (*dim, *dart, found.strip_prefix("homology ").unwrap_or(found).to_string())
        }
        other => panic!("expected a C2 refusal, got {other}"),
    }
}

#[test]
fn lutz_four_and_five_manifolds_keep_verdicts_and_groups() {
    for (name, groups) in [
        ("CP2.facets", "(Z, 0, Z, 0, Z)"),
        ("RP4.facets", "(Z, Z/2, 0, Z/2, 0)"),
        ("K3_16.facets", "(Z, 0, Z^22, 0, Z)"),
        // the Wu manifold: its header gives the Betti numbers mod 2
        ("SU2_SO3.facets", "(Z, 0, Z/2, 0, 0, Z)"),
        ("non_PL.facets", "(Z, 0, 0, 0, 0, Z)"),
        ("RP5_24.facets", "(Z, Z/2, 0, Z/2, 0, Z)"),
    ] {
        let map = read_facets(&lutz(name), None).unwrap();
        assert_eq!(c2_cell_by_cell(&map), None, "{name}: every simplex bounds a sphere");
        let c = cellular_complex(&map).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert_eq!(homology_z(&c.chain).unwrap().to_string(), groups, "{name}");
        // the cells are the simplices: the face counts of the triangulation
        let sc = SimplicialComplex::parse_facets(&std::fs::read_to_string(lutz(name)).unwrap()).unwrap();
        assert_eq!(c.chain.counts()[map.dim()], sc.facet_count(), "{name}");
    }
}

/// The suspension (two apexes, `u64::MAX - 1` and `u64::MAX`) of the Lutz 3-manifold
/// `name`, as a 4-map, seen as a 5-map: one 5-cell bounded by the suspension.
fn five_cell_on_suspension(name: &str) -> DenseMap {
    let text = std::fs::read_to_string(lutz(name)).unwrap();
    let m = SimplicialComplex::parse_facets(&text).unwrap();
    let facets = m.all_facets().into_iter().flat_map(|t| {
        [u64::MAX - 1, u64::MAX].map(|apex| t.iter().copied().chain(std::iter::once(apex)).collect::<Vec<u64>>())
    });
    let suspension = SimplicialComplex::from_facets(facets).unwrap().to_gmap(10_000_000).unwrap();
    assert_eq!(suspension.dim(), 4);
    suspension.embedded(5).unwrap()
}

#[test]
fn a_five_cell_bounded_by_a_pinched_suspension_is_refused() {
    // the dodecahedral space has H_1 = (Z/5)^3, so its suspension has H_2 = (Z/5)^3: the
    // one 5-cell fails C2, named by its smallest dart 0
    let map = five_cell_on_suspension("hyperbolic_dodecahedral_space.facets");
    let want = c2_cell_by_cell(&map).expect("the cell-by-cell check refuses it");
    assert_eq!(want, (5, Dart::new(0), "(Z, 0, Z/5 + Z/5 + Z/5, 0, Z)".to_string()));
    let err = check_preconditions(&map).expect_err("C2 fails in dimension 5");
    assert_eq!(c2_of(&err), want);
    assert_eq!(
        err.to_string(),
        "the 5-cell of dart 0 is not bounded by a sphere: its boundary has homology (Z, 0, Z/5 + Z/5 + Z/5, 0, Z) \
         (condition C2: every cell bounded by a homology sphere)"
    );
    // the simplicial method still answers: a cone, contractible
    assert_eq!(homology_z(&simplicial_complex(&map)).unwrap().to_string(), "(Z, 0, 0, 0, 0, 0)");
}

#[test]
fn a_five_cell_bounded_by_a_suspended_homology_sphere_is_accepted() {
    // the suspension of the Poincaré sphere is not a manifold, but it has the homology of
    // the 4-sphere, which is all C2 asks
    let map = five_cell_on_suspension("poincare.facets");
    assert_eq!(c2_cell_by_cell(&map), None);
    let c = cellular_complex(&map).unwrap();
    assert_eq!(c.chain.counts()[5], 1);
    assert_eq!(homology_z(&c.chain).unwrap().to_string(), "(Z, 0, 0, 0, 0, 0)");
}
