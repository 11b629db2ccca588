//! Unit tests of the editable map that reach its private parts (the sew pairing, links
//! without reconciliation), on the fixtures of `crate::examples`. A file of its own: the
//! fixtures are built on the map of `edit.rs`, and a child file that nothing imports keeps
//! them from closing an import circle with it (`tests/layout.rs`).

use std::sync::{Arc, Mutex};

use proptest::prelude::*;

use super::*;
use crate::attr::Cells;
use crate::examples::add_simplex;

type Full = GMap<(Cells<u64>, Cells<u64>, Cells<u64>, Cells<u64>)>;

#[test]
fn alpha_word_applies_its_letters_first_to_last() {
    let mut g: GMap = GMap::new(2);
    let d: Vec<DartId> = (0..3).map(|_| g.create_dart()).collect();
    g.sew(d[0], d[1], 0);
    g.sew(d[1], d[2], 1);
    assert_eq!(g.alpha_word(d[0], &[0, 1]), d[2]);
    assert_eq!(g.alpha_word(d[0], &[1, 0]), d[1]);
    assert_eq!(g.alpha_word(d[0], &[]), d[0]);
    assert_eq!(g.try_alpha_word(d[0], &[0, 1, 1]), Ok(d[1]));
    assert!(g.try_alpha_word(d[0], &[0, 3]).is_err());
}

/// Every hook call as `(merge?, dimension, kept, other)`, in order.
type Log = Arc<Mutex<Vec<(bool, usize, u64, u64)>>>;

fn log_hooks(g: &mut Full) -> Log {
    let log: Log = Arc::default();
    macro_rules! on {
        ($i:literal) => {
            let l = log.clone();
            g.set_on_merge::<$i>(move |kept, other| {
                l.lock().unwrap().push((true, $i, *kept, other));
                *kept = kept.wrapping_mul(31).wrapping_add(other);
            });
            let l = log.clone();
            g.set_on_split::<$i>(move |kept, copy| {
                l.lock().unwrap().push((false, $i, *kept, *copy));
                *copy = copy.wrapping_add(7);
            });
        };
    }
    on!(0);
    on!(1);
    on!(2);
    on!(3);
    log
}

/// The attribute (id and value) of each dimension and the point, of one dart.
type DartState = (Vec<Option<(AttrId, u64)>>, Option<Point>);

/// Everything the attributes and points of a map say, dart by dart.
fn state(g: &Full, darts: &[DartId]) -> Vec<DartState> {
    darts
        .iter()
        .map(|&d| {
            let a = vec![
                g.attribute_id::<0>(d).zip(g.attribute::<0>(d).copied()),
                g.attribute_id::<1>(d).zip(g.attribute::<1>(d).copied()),
                g.attribute_id::<2>(d).zip(g.attribute::<2>(d).copied()),
                g.attribute_id::<3>(d).zip(g.attribute::<3>(d).copied()),
            ];
            (a, g.point(d))
        })
        .collect()
}

/// A map of simplices with a value on the cells `keep` lets through (cell by cell, in
/// the order of the darts, dimension after dimension) and a point on some vertices.
fn attributed(n: usize, pieces: &[usize], keep: &[bool]) -> (Full, Vec<DartId>) {
    let mut g = Full::with_attributes(n);
    let darts: Vec<DartId> = pieces.iter().flat_map(|&k| add_simplex(&mut g, k % (n + 1))).collect();
    let mask = |k: usize| keep[k % keep.len()];
    for (k, &d) in darts.iter().enumerate() {
        let v = k as u64 + 1;
        if mask(k) && g.attribute::<0>(d).is_none() {
            g.set_attribute::<0>(d, v);
        }
        if mask(k + 1) && g.attribute::<1>(d).is_none() {
            g.set_attribute::<1>(d, 1000 + v);
        }
        if mask(k + 2) && g.attribute::<2>(d).is_none() {
            g.set_attribute::<2>(d, 2000 + v);
        }
        if n == 3 && mask(k + 3) && g.attribute::<3>(d).is_none() {
            g.set_attribute::<3>(d, 3000 + v);
        }
        if mask(k + 4) && g.point(d).is_none() {
            g.set_point(d, Some([k as f64, 0.0, 1.0]));
        }
    }
    (g, darts)
}

/// A k-gon face in a 3-map: 2k darts, `d[2j], d[2j+1]` one side.
fn polygon(g: &mut GMap, k: usize) -> Vec<DartId> {
    let d: Vec<DartId> = (0..2 * k).map(|_| g.create_dart()).collect();
    for j in 0..k {
        g.sew(d[2 * j], d[2 * j + 1], 0);
        g.sew(d[2 * j + 1], d[(2 * j + 2) % (2 * k)], 1);
    }
    d
}

#[test]
fn large_sew_orbits_pair_through_the_hash_maps() {
    // a 20-gon has a 3-sew orbit of 40 darts, beyond Pairing::LINEAR
    let mut g = GMap::new(3);
    let (a, b, c) = (polygon(&mut g, 20), polygon(&mut g, 20), polygon(&mut g, 21));
    assert!(a.len() > Pairing::LINEAR);
    assert_eq!(g.sew_pairs(a[0], b[0], 3).map(|p| p.len()), Ok(40));
    assert!(matches!(g.try_sew(a[0], c[0], 3), Err(EditError::NotIsomorphic { .. })));
    g.sew(a[0], b[0], 3);
    assert!(a.iter().zip(&b).all(|(&x, &y)| g.alpha(x, 3) == y));
    assert_eq!(g.try_sew(a[1], c[0], 3), Err(EditError::NotFree { dart: a[1], alpha: 3 }));
    // the two 20-gons are one face now, each still its own volume
    assert_eq!(g.cell_counts(), vec![41, 41, 2, 3]);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]
    /// A sew reconciles from its pairing exactly as `reconcile_attributes` does on the
    /// darts of the pairs (first sides, then second sides): same values, same ids, same
    /// hook calls in the same order.
    #[test]
    fn sew_reconciles_like_the_general_routine(
        n in 2usize..=3,
        pieces in proptest::collection::vec(0usize..4, 2..6),
        keep in proptest::collection::vec(prop::bool::weighted(0.85), 1..9),
        sews in proptest::collection::vec((0usize..200, 0usize..200, 0usize..4), 1..40),
    ) {
        let (mut g, darts) = attributed(n, &pieces, &keep);
        for (a, b, i) in sews {
            let (d, e, i) = (darts[a % darts.len()], darts[b % darts.len()], i % (n + 1));
            let Ok(pairs) = g.sew_pairs(d, e, i) else { continue };
            let mut h = g.clone();
            let (fast, general) = (log_hooks(&mut g), log_hooks(&mut h));
            g.sew(d, e, i);
            for &(x, y) in &pairs {
                h.link_free(x, y, i);
            }
            let touched: Vec<DartId> = pairs.iter().map(|p| p.0).chain(pairs.iter().map(|p| p.1)).collect();
            h.reconcile_attributes(&touched);
            prop_assert_eq!(state(&g, &darts), state(&h, &darts));
            prop_assert_eq!(&*fast.lock().unwrap(), &*general.lock().unwrap());
            prop_assert!(g.check_attributes().is_ok());
        }
    }
}
