//! Property tests: on random surfaces glued from polygons (C1 and C2 hold: every edge glued
//! to a different edge or left free), the cellular homology equals the simplicial one over
//! Z and Z/2; on random maps with a folded edge or an open corner (C1 fails), the cellular
//! method refuses and names the cell while the simplicial method still answers.

use gmap_core::{Dart, DenseMap};
use gmap_homology::{cellular_complex, homology_z, homology_zp, simplicial_complex, PreconditionError};
use proptest::prelude::*;

/// Polygons with `sides[j]` edges; edge `e` of polygon `j` has darts `base + 2e`, `base + 2e + 1`.
fn polygons(sides: &[usize]) -> (DenseMap, Vec<(u32, u32)>) {
    let total: usize = sides.iter().map(|s| 2 * s).sum();
    let mut m = DenseMap::new(2, total);
    let mut edges = Vec::new();
    let mut base = 0u32;
    for &s in sides {
        let s = s as u32;
        for e in 0..s {
            m.link(Dart::new(base + 2 * e), Dart::new(base + 2 * e + 1), 0);
            m.link(Dart::new(base + 2 * e + 1), Dart::new(base + (2 * e + 2) % (2 * s)), 1);
            edges.push((base + 2 * e, base + 2 * e + 1));
        }
        base += 2 * s;
    }
    (m, edges)
}

/// Glues edges pairwise in the order given by `perm`, flipping by `flips`; pairs whose
/// `keep` bit is false stay free (boundary).
fn glue(m: &mut DenseMap, edges: &[(u32, u32)], perm: &[usize], flips: &[bool], keep: &[bool]) {
    for k in 0..edges.len() / 2 {
        if !keep[k % keep.len()] {
            continue;
        }
        let (a0, a1) = edges[perm[2 * k]];
        let (b0, b1) = edges[perm[2 * k + 1]];
        let (b0, b1) = if flips[k % flips.len()] { (b1, b0) } else { (b0, b1) };
        m.link(Dart::new(a0), Dart::new(b0), 2);
        m.link(Dart::new(a1), Dart::new(b1), 2);
    }
}

fn surface() -> impl Strategy<Value = DenseMap> {
    (
        prop::collection::vec(1usize..6, 1..5),
        prop::collection::vec(any::<bool>(), 8),
        prop::collection::vec(any::<bool>(), 8),
    )
        .prop_flat_map(|(sides, flips, keep)| {
            let n: usize = sides.iter().sum();
            (Just(sides), Just(flips), Just(keep), Just((0..n).collect::<Vec<_>>()).prop_shuffle())
        })
        .prop_map(|(sides, flips, mut keep, perm)| {
            keep[0] = true;
            let (mut m, edges) = polygons(&sides);
            glue(&mut m, &edges, &perm, &flips, &keep);
            m
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    #[test]
    fn cellular_equals_simplicial(m in surface()) {
        m.validate().unwrap();
        let c = cellular_complex(&m).expect("distinct edges glued: C1 and C2 hold");
        c.chain.check_dd().unwrap();
        let hc = homology_z(&c.chain).unwrap();
        let s = simplicial_complex(&m);
        let hs = homology_z(&s).unwrap();
        prop_assert_eq!(&hc, &hs);
        prop_assert_eq!(hc.euler_characteristic(), m.euler_characteristic());
        prop_assert_eq!(homology_zp(&c.chain, 2).unwrap(), homology_zp(&s, 2).unwrap());
    }

    #[test]
    fn violations_are_refused(m in surface(), which in any::<bool>(), pick in any::<prop::sample::Index>()) {
        let mut m = m;
        let d = Dart::new(pick.index(m.dart_count()) as u32);
        if which {
            // fold the edge of d onto itself
            let e = m.alpha(d, 0);
            for x in [d, e] {
                let y = m.alpha(x, 2);
                if y != x {
                    m.unlink(x, 2);
                }
            }
            m.link(d, e, 2);
        } else {
            // open the corner of d
            m.unlink(d, 1);
        }
        m.validate().unwrap();
        match cellular_complex(&m) {
            Err(PreconditionError::C1(_)) => {}
            other => prop_assert!(false, "expected a C1 failure, got {:?}", other.map(|c| c.chain.counts().to_vec())),
        }
        let h = homology_z(&simplicial_complex(&m)).unwrap();
        prop_assert_eq!(h.betti[0], m.component_count());
    }
}
