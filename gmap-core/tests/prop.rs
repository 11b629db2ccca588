//! Property tests on random valid G-maps of dimensions 1 to 4.
//!
//! A map is built from a few k-simplices (k ≤ n; the darts of a k-simplex are the
//! orderings of its k + 1 vertices, `alpha_i` swaps positions i and i + 1 for i < k, the
//! other involutions are free), then glued by random `GMap::try_sew` calls (failed sews are
//! skipped, so the map stays valid), then frozen. On it: validity, cells partitioning the
//! darts, the dual, orientation, the fast kernels against plain references, and the
//! `.gmap`/`.moka` round trips.

use gmap_core::examples::add_simplex;
use gmap_core::io::{format_gmap, format_moka, parse_gmap, parse_moka};
use gmap_core::{AlphaSet, Dart, DenseMap, GMap};
use proptest::prelude::*;

/// A random valid map: `pieces` simplex dimensions (reduced mod n + 1), then sews.
fn build(n: usize, pieces: &[usize], sews: &[(usize, usize, usize)]) -> DenseMap {
    let mut g = GMap::new(n);
    let mut darts = Vec::new();
    for &k in pieces {
        darts.extend(add_simplex(&mut g, k % (n + 1)));
    }
    for &(a, b, i) in sews {
        let (d, e) = (darts[a % darts.len()], darts[b % darts.len()]);
        let _ = g.try_sew(d, e, i % (n + 1));
    }
    g.to_dense().0
}

fn map_strategy(dims: std::ops::RangeInclusive<usize>) -> impl Strategy<Value = DenseMap> {
    (
        dims,
        prop::collection::vec(0usize..5, 1..5),
        prop::collection::vec((0usize..1000, 0usize..1000, 0usize..5), 0..40),
    )
        .prop_map(|(n, pieces, sews)| {
            // keep dimension 4 maps small: a 4-simplex alone has 120 darts
            let pieces: Vec<usize> = if n == 4 { pieces.into_iter().take(3).collect() } else { pieces };
            build(n, &pieces, &sews)
        })
}

/// Plain reference of BO Def. 1.
fn naive_valid(m: &DenseMap) -> bool {
    let n = m.dart_count() as u32;
    for d in m.darts() {
        for i in 0..=m.dim() {
            let e = m.row(d)[i];
            if e >= n || m.alpha(Dart::new(e), i) != d {
                return false;
            }
        }
    }
    for d in m.darts() {
        for i in 0..=m.dim() {
            for j in i + 2..=m.dim() {
                let x = m.alpha(m.alpha(m.alpha(m.alpha(d, i), j), i), j);
                if x != d {
                    return false;
                }
            }
        }
    }
    true
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 96, ..ProptestConfig::default() })]

    #[test]
    fn random_maps_are_valid(m in map_strategy(1..=4)) {
        prop_assert!(m.validate().is_ok());
        prop_assert!(naive_valid(&m));
    }

    #[test]
    fn cells_partition_the_darts(m in map_strategy(1..=4)) {
        let (counts, components) = m.cell_counts_and_components();
        prop_assert_eq!(components, m.components().len());
        for (i, &count) in counts.iter().enumerate() {
            let set = AlphaSet::cell(i, m.dim());
            let p = m.cells(i);
            prop_assert_eq!(p.len(), count);
            prop_assert_eq!(p.of.len(), m.dart_count());
            let (off, darts) = p.members();
            for k in 0..p.len() {
                let mut orbit: Vec<u32> = m.orbit(p.reps[k], set).iter().map(|d| d.get()).collect();
                orbit.sort_unstable();
                prop_assert_eq!(&orbit[..], &darts[off[k]..off[k + 1]]);
                prop_assert_eq!(orbit[0], p.reps[k].get());
            }
            prop_assert_eq!(off[p.len()], m.dart_count());
        }
        let chi: i64 = counts.iter().enumerate().map(|(i, &c)| if i % 2 == 0 { c as i64 } else { -(c as i64) }).sum();
        prop_assert_eq!(chi, m.euler_characteristic());
    }

    #[test]
    fn dual_reverses_counts_and_is_an_involution(m in map_strategy(1..=4)) {
        let d = m.dual();
        prop_assert!(d.validate().is_ok());
        let mut rev = m.cell_counts();
        rev.reverse();
        prop_assert_eq!(d.cell_counts(), rev);
        prop_assert_eq!(d.dual(), m.clone());
        prop_assert_eq!(d.is_orientable(), m.is_orientable());
    }

    #[test]
    fn orientation_is_a_proper_two_colouring(m in map_strategy(1..=4)) {
        prop_assert_eq!(m.is_orientable(), m.orientation().is_ok());
        if let Ok(pos) = m.orientation() {
            for d in m.darts() {
                for i in 0..=m.dim() {
                    let e = m.alpha(d, i);
                    if e != d {
                        prop_assert_ne!(pos[d.index()], pos[e.index()]);
                    }
                }
            }
        } else {
            // a conflict names an edge of the dart graph joining two darts of one class
            let c = m.orientation().unwrap_err();
            prop_assert_eq!(m.alpha(c.dart, c.alpha), c.other);
        }
    }

    #[test]
    fn fast_validation_agrees_with_the_definition(m in map_strategy(1..=4), a in 0usize..1000, b in 0usize..1000, i in 0usize..5) {
        let mut m = m;
        if m.dart_count() > 0 {
            let (d, e) = (Dart::new((a % m.dart_count()) as u32), Dart::new((b % m.dart_count()) as u32));
            m.link(d, e, i % (m.dim() + 1));
        }
        prop_assert_eq!(m.validate().is_ok(), naive_valid(&m));
    }

    #[test]
    fn gmap_round_trip(m in map_strategy(1..=4)) {
        let text = format_gmap(&m);
        prop_assert_eq!(parse_gmap(&text, "x.gmap").unwrap(), m);
    }

    #[test]
    fn moka_round_trip(m in map_strategy(1..=3), pts in prop::collection::vec((any::<u16>(), -1e6f64..1e6, -1e6f64..1e6, -1e6f64..1e6), 0..6)) {
        let mut m = m;
        for (k, x, y, z) in pts {
            let d = Dart::new((k as usize % m.dart_count()) as u32);
            m.set_point(d, Some([x, y, z]));
        }
        let text = format_moka(&m).unwrap();
        let back = parse_moka(&text, "x.moka").unwrap();
        prop_assert_eq!(back, m);
    }
}

#[test]
fn simplices_have_the_expected_cells() {
    // the boundary of nothing: one free 3-simplex has 4 vertices, 6 edges, 4 triangles, 1 tetrahedron
    let m = build(3, &[3], &[]);
    assert_eq!(m.dart_count(), 24);
    assert_eq!(m.cell_counts(), vec![4, 6, 4, 1]);
    assert!(m.is_orientable());
    // a 4-simplex: 5, 10, 10, 5, 1
    let m = build(4, &[4], &[]);
    assert_eq!(m.cell_counts(), vec![5, 10, 10, 5, 1]);
    // two triangles 2-sewn along an edge: 4 vertices, 5 edges, 2 faces
    let m = build(2, &[2, 2], &[(0, 6, 2)]);
    assert_eq!(m.cell_counts(), vec![4, 5, 2]);
    assert_eq!(m.euler_characteristic(), 1);
}
