//! Property tests of cell attributes and vertex points on the editable map.
//!
//! Random maps of dimension 2 and 3 (a few simplices) get an attribute on every cell of
//! every dimension and a point on every vertex; then random sews and unsews run. After each
//! edit: every cell has exactly one attribute and the values count exactly the cells
//! ([`GMap::check_attributes`]); the merge and split hooks ran exactly as many times as the
//! cell partitions, computed independently before and after from the dense snapshot, say
//! cells merged or split; a sew keeps the attributes and the point of the first dart's cells;
//! an unsew changes no dart's attribute value nor point. Then `.gmap` files: a map with
//! points and labels on every dimension (texts with spaces, quotes, newlines, any
//! character) is read back identical.

mod attr_common;

use attr_common::{attr, cells_by_dart, count, fill, merges_and_splits, Full, Hooks};
use gmap_core::examples::add_simplex;
use gmap_core::io::{format_labelled_gmap, parse_labelled_gmap};
use gmap_core::{DartId, LabelValue, LabelledGMap, Labels, Point};
use proptest::prelude::*;

/// The cell of each dart (by position in `darts`) for dimension `i`, from the snapshot.
fn partition(g: &Full, i: usize) -> Vec<u32> {
    g.to_dense_map().cells(i).of
}

/// A map of `pieces` simplices with a distinct value on every cell and a point per vertex.
fn attributed(n: usize, pieces: &[usize]) -> (Full, Vec<DartId>) {
    let mut g = Full::with_attributes(n);
    let mut darts = Vec::new();
    for &k in pieces {
        darts.extend(add_simplex(&mut g, k % (n + 1)));
    }
    fill(&mut g, &mut 0);
    (g, darts)
}

/// Runs the edits, checking every property after each; returns the number of edits that
/// changed the map.
fn run(n: usize, pieces: &[usize], edits: &[(bool, usize, usize, usize)]) -> Result<usize, TestCaseError> {
    let (mut g, darts) = attributed(n, pieces);
    let hooks = Hooks::default();
    hooks.install(&mut g);
    g.check_attributes().map_err(|e| TestCaseError::fail(e.to_string()))?;
    let mut changed = 0;
    for &(sew, a, b, i) in edits {
        let (d, e, i) = (darts[a % darts.len()], darts[b % darts.len()], i % (n + 1));
        let before: Vec<Vec<u32>> = (0..=n).map(|j| partition(&g, j)).collect();
        let values: Vec<Vec<Option<u64>>> = (0..=n).map(|j| darts.iter().map(|&x| attr(&g, x, j)).collect()).collect();
        let points: Vec<Option<Point>> = darts.iter().map(|&x| g.point(x)).collect();
        let (m0, s0) = hooks.counts();
        let done = if sew { g.try_sew(d, e, i).is_ok() } else { !g.is_free(d, i) && g.try_unsew(d, i).is_ok() };
        changed += done as usize;
        let (m1, s1) = hooks.counts();
        g.check_attributes().map_err(|e| TestCaseError::fail(e.to_string()))?;
        for j in 0..=n {
            let after = partition(&g, j);
            let (merges, splits) = merges_and_splits(&before[j], &after);
            prop_assert_eq!(m1[j] - m0[j], merges, "merges of {}-cells", j);
            prop_assert_eq!(s1[j] - s0[j], splits, "splits of {}-cells", j);
            // exactly one attribute per cell
            let cells = after.iter().copied().max().map_or(0, |m| m as usize + 1);
            prop_assert_eq!(count(&g, j), cells);
            for (k, &x) in darts.iter().enumerate() {
                prop_assert!(attr(&g, x, j).is_some());
                if !sew {
                    prop_assert_eq!(attr(&g, x, j), values[j][k], "unsew changed a value");
                }
            }
            if sew && done {
                // the merged cells keep the first dart's value (the counting hooks keep it)
                prop_assert_eq!(attr(&g, d, j), values[j][darts.iter().position(|&x| x == d).unwrap()]);
            }
        }
        for (k, &x) in darts.iter().enumerate() {
            prop_assert!(g.point(x).is_some(), "a vertex lost its point");
            if !sew {
                prop_assert_eq!(g.point(x), points[k]);
            }
        }
        if sew && done {
            // the vertex of d keeps its point; an i-sew with i >= 1 puts e in that vertex
            let kept = points[darts.iter().position(|&x| x == d).unwrap()];
            prop_assert_eq!(g.point(d), kept);
            if i >= 1 {
                prop_assert_eq!(g.point(e), kept);
            }
        }
    }
    Ok(changed)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 96, ..ProptestConfig::default() })]

    #[test]
    fn attributes_follow_sews_and_unsews_in_2d(
        pieces in prop::collection::vec(0usize..3, 1..5),
        edits in prop::collection::vec((any::<bool>(), any::<usize>(), any::<usize>(), 0usize..3), 0..30),
    ) {
        run(2, &pieces, &edits)?;
    }

    #[test]
    fn attributes_follow_sews_and_unsews_in_3d(
        pieces in prop::collection::vec(0usize..4, 1..4),
        edits in prop::collection::vec((any::<bool>(), any::<usize>(), any::<usize>(), 0usize..4), 0..30),
    ) {
        run(3, &pieces, &edits)?;
    }
}

/// Removes random darts one at a time, reconciling with their former neighbours (the
/// editing pattern of the Euler operators): cells only split or vanish, the split hook runs
/// once per extra piece, every surviving cell keeps exactly one attribute.
fn run_removals(
    n: usize,
    pieces: &[usize],
    sews: &[(usize, usize, usize)],
    removals: &[usize],
) -> Result<(), TestCaseError> {
    let (mut g, darts) = attributed(n, pieces);
    for &(a, b, i) in sews {
        let _ = g.try_sew(darts[a % darts.len()], darts[b % darts.len()], i % (n + 1));
    }
    let hooks = Hooks::default();
    hooks.install(&mut g);
    for &r in removals {
        let live: Vec<DartId> = g.darts().collect();
        if live.is_empty() {
            break;
        }
        let d = live[r % live.len()];
        let before = cells_by_dart(&g);
        let neighbours: Vec<DartId> = (0..=n).map(|j| g.alpha(d, j)).filter(|&x| x != d).collect();
        let (m0, s0) = hooks.counts();
        g.remove_dart(d);
        g.reconcile_attributes(&neighbours);
        let (m1, s1) = hooks.counts();
        g.check_attributes().map_err(|e| TestCaseError::fail(e.to_string()))?;
        let after = cells_by_dart(&g);
        for j in 0..=n {
            let survivors: Vec<DartId> = g.darts().collect();
            let old: Vec<u32> = survivors.iter().map(|x| before[j][x]).collect();
            let new: Vec<u32> = survivors.iter().map(|x| after[j][x]).collect();
            let (merges, splits) = merges_and_splits(&old, &new);
            prop_assert_eq!(merges, 0);
            prop_assert_eq!(m1[j] - m0[j], 0);
            prop_assert_eq!(s1[j] - s0[j], splits, "splits of {}-cells", j);
            let cells = new.iter().collect::<std::collections::BTreeSet<_>>().len();
            prop_assert_eq!(count(&g, j), cells);
            for &x in &survivors {
                prop_assert!(attr(&g, x, j).is_some());
                prop_assert!(g.point(x).is_some());
            }
        }
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, ..ProptestConfig::default() })]

    #[test]
    fn attributes_follow_dart_removals(
        n in 1usize..4,
        pieces in prop::collection::vec(0usize..4, 1..4),
        sews in prop::collection::vec((any::<usize>(), any::<usize>(), 0usize..4), 0..10),
        removals in prop::collection::vec(any::<usize>(), 0..20),
    ) {
        run_removals(n, &pieces, &sews, &removals)?;
    }
}

fn label_value() -> impl Strategy<Value = LabelValue> {
    prop_oneof![
        any::<i64>().prop_map(LabelValue::Int),
        any::<f64>().prop_filter("finite", |v| v.is_finite()).prop_map(LabelValue::Real),
        any::<String>().prop_map(LabelValue::Text),
        "[ a-z\"\\\n\t#=]{0,8}".prop_map(LabelValue::Text),
    ]
}

fn labels() -> impl Strategy<Value = Labels> {
    prop::collection::vec((prop_oneof!["[a-z_][a-z0-9_.-]{0,5}", any::<String>()], label_value()), 0..4)
        .prop_map(|v| v.into_iter().collect())
}

fn labels_of(g: &LabelledGMap, i: usize, d: DartId) -> Option<&Labels> {
    match i {
        0 => g.attribute::<0>(d),
        1 => g.attribute::<1>(d),
        2 => g.attribute::<2>(d),
        _ => g.attribute::<3>(d),
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, ..ProptestConfig::default() })]

    #[test]
    fn labelled_maps_read_back_identical(
        n in 1usize..4,
        pieces in prop::collection::vec(0usize..4, 1..4),
        sews in prop::collection::vec((any::<usize>(), any::<usize>(), 0usize..4), 0..8),
        marks in prop::collection::vec((any::<usize>(), 0usize..4, labels()), 0..12),
        points in prop::collection::vec((any::<usize>(), -1e9f64..1e9, -1e9f64..1e9, -1e9f64..1e9), 0..8),
    ) {
        let mut g = LabelledGMap::with_attributes(n);
        let mut darts = Vec::new();
        for &k in &pieces {
            darts.extend(add_simplex(&mut g, k % (n + 1)));
        }
        for &(a, b, i) in &sews {
            let _ = g.try_sew(darts[a % darts.len()], darts[b % darts.len()], i % (n + 1));
        }
        for (k, i, l) in marks {
            let d = darts[k % darts.len()];
            match i % (n + 1) {
                0 => g.set_attribute::<0>(d, l),
                1 => g.set_attribute::<1>(d, l),
                2 => g.set_attribute::<2>(d, l),
                _ => g.set_attribute::<3>(d, l),
            };
        }
        for (k, x, y, z) in points {
            g.set_point(darts[k % darts.len()], Some([x, y, z]));
        }
        let text = format_labelled_gmap(&g);
        let back = parse_labelled_gmap(&text, "x.gmap").map_err(|e| TestCaseError::fail(e.to_string()))?;
        let (dense, ids) = g.to_dense_with_ids();
        let (dense_back, ids_back) = back.to_dense_with_ids();
        prop_assert_eq!(&dense_back, &dense);
        back.check_attributes().map_err(|e| TestCaseError::fail(e.to_string()))?;
        for (&a, &b) in ids.iter().zip(&ids_back) {
            prop_assert_eq!(back.point(b), g.point(a));
            for i in 0..=n {
                prop_assert_eq!(labels_of(&back, i, b), labels_of(&g, i, a));
            }
        }
        prop_assert_eq!(format_labelled_gmap(&back), text);
    }
}

/// A fixed sequence that merges and splits in every dimension: the property test above
/// is not vacuous.
#[test]
fn a_known_sequence_merges_and_splits() {
    // two triangles (2-simplices) in a 2-map, glued along an edge by alpha_2, then unglued
    let (mut g, darts) = attributed(2, &[2, 2]);
    let hooks = Hooks::default();
    hooks.install(&mut g);
    assert_eq!([count(&g, 0), count(&g, 1), count(&g, 2)], [6, 6, 2]);
    // dart 0 of each triangle: vertex 0, edge 01, alpha_2 free
    let (d, e) = (darts[0], darts[6]);
    g.sew(d, e, 2);
    assert_eq!(hooks.counts(), ([2, 1, 0, 0], [0; 4]));
    assert_eq!([count(&g, 0), count(&g, 1), count(&g, 2)], [4, 5, 2]);
    assert_eq!(run(2, &[2, 2], &[(true, 0, 6, 2), (false, 0, 0, 2)]).unwrap(), 2);
    g.unsew(d, 2);
    assert_eq!(hooks.counts(), ([2, 1, 0, 0], [2, 1, 0, 0]));
    assert_eq!([count(&g, 0), count(&g, 1), count(&g, 2)], [6, 6, 2]);
    g.check_attributes().unwrap();
}
