//! Cell attributes and vertex points on the editable map, case by case: setting, reading,
//! replacing and removing values; stale darts and inert slots refused; the merge and split
//! hooks on sew and unsew; a cell without a value taking its neighbour's; points kept
//! through edits and dense snapshots; `check_attributes` and `validate` naming what
//! disagrees. `attr_props.rs` checks the same rules on random maps.

use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Arc;

use gmap_core::{AttributeDefect, Attributes, Cells, Dart, DartId, EditError, GMap, MapDefect};

type Full2 = (Cells<u32>, Cells<u32>, Cells<u32>);

/// A square face of a 2-map: 8 darts, `d[2k], d[2k+1]` one side, `d[2k+1], d[2k+2]` a
/// corner.
fn square<A: Attributes>(m: &mut GMap<A>) -> Vec<DartId> {
    let d: Vec<DartId> = (0..8).map(|_| m.create_dart()).collect();
    for k in 0..4 {
        m.sew(d[2 * k], d[2 * k + 1], 0);
        m.sew(d[2 * k + 1], d[(2 * k + 2) % 8], 1);
    }
    d
}

#[test]
fn set_read_replace_remove_iterate() {
    let mut m: GMap<Full2> = GMap::with_attributes(2);
    let d = square(&mut m);
    assert_eq!(m.attribute::<2>(d[0]), None);
    let id = m.set_attribute::<2>(d[0], 7);
    for &x in &d {
        assert_eq!(m.attribute::<2>(x), Some(&7));
        assert_eq!(m.attribute_id::<2>(x), Some(id));
    }
    // replacing keeps the id
    assert_eq!(m.set_attribute::<2>(d[5], 8), id);
    assert_eq!(m.attribute::<2>(d[0]), Some(&8));
    *m.attribute_mut::<2>(d[3]).unwrap() += 1;
    assert_eq!(m.attribute_by_id::<2>(id), Some(&9));
    assert!(d.contains(&m.attribute_dart::<2>(id).unwrap()));
    // one value per edge: 4 edges, each of 2 darts
    for k in 0..4 {
        m.set_attribute::<1>(d[2 * k], k as u32);
    }
    assert_eq!(m.attribute_count::<1>(), 4);
    assert_eq!(m.attribute::<1>(d[7]), Some(&3));
    let mut values: Vec<u32> = m.attributes::<1>().map(|(_, &v)| v).collect();
    values.sort_unstable();
    assert_eq!(values, vec![0, 1, 2, 3]);
    m.check_attributes().unwrap();
    assert_eq!(m.remove_attribute::<2>(d[1]), Some(9));
    assert_eq!(m.remove_attribute::<2>(d[1]), None);
    assert_eq!(m.attribute_by_id::<2>(id), None);
    assert_eq!(m.attribute_dart::<2>(id), None);
    // a freed slab entry is reused under a new id; the old id stays stale
    let id2 = m.set_attribute::<2>(d[0], 1);
    assert_eq!(id2.index(), id.index());
    assert_ne!(id2, id);
    assert_eq!(m.attribute_by_id::<2>(id), None);
    m.check_attributes().unwrap();
}

#[test]
fn stale_darts_and_missing_cells_are_refused() {
    let mut m: GMap<((), (), (), Cells<u8>)> = GMap::with_attributes(2);
    let a = m.create_dart();
    assert_eq!(m.try_set_attribute::<3>(a, 1), Err(EditError::NoSuchCells { cell: 3, dim: 2 }));
    assert_eq!(m.try_remove_attribute::<3>(a), Ok(None));
    m.remove_dart(a);
    assert_eq!(m.try_attribute::<3>(a), Err(EditError::NoSuchDart(a)));
    assert_eq!(m.try_point(a), Err(EditError::NoSuchDart(a)));
    assert_eq!(m.try_set_point(a, Some([0.0; 3])), Err(EditError::NoSuchDart(a)));
}

#[test]
fn sew_merges_with_the_hook_and_keeps_the_first() {
    // two squares glued along a side: their edges d[0]d[1] and e[0]e[1] become one
    let mut m: GMap<((), Cells<u32>)> = GMap::with_attributes(2);
    let merges = Arc::new(AtomicUsize::new(0));
    let seen = merges.clone();
    m.set_on_merge::<1>(move |kept, other| {
        seen.fetch_add(1, Ordering::Relaxed);
        *kept += 100 * other;
    });
    let d = square(&mut m);
    let e = square(&mut m);
    for k in 0..4 {
        m.set_attribute::<1>(d[2 * k], k as u32 + 1);
        m.set_attribute::<1>(e[2 * k], k as u32 + 5);
    }
    m.sew(d[0], e[1], 2);
    assert_eq!(merges.load(Ordering::Relaxed), 1);
    assert_eq!(m.attribute_count::<1>(), 7);
    // the first dart's edge is kept, the other folded in by the hook
    for x in [d[0], d[1], e[0], e[1]] {
        assert_eq!(m.attribute::<1>(x), Some(&(1 + 100 * 5)));
    }
    m.check_attributes().unwrap();
    // unsewing splits the edge: the default split clones
    m.unsew(d[0], 2);
    assert_eq!(m.attribute_count::<1>(), 8);
    assert_eq!(m.attribute::<1>(e[0]), Some(&501));
    assert_ne!(m.attribute_id::<1>(e[0]), m.attribute_id::<1>(d[0]));
    m.check_attributes().unwrap();
}

#[test]
fn a_cell_without_attribute_takes_the_other_without_hooks() {
    let mut m: GMap<((), Cells<u32>)> = GMap::with_attributes(2);
    let calls = Arc::new(AtomicUsize::new(0));
    let (c1, c2) = (calls.clone(), calls.clone());
    m.set_on_merge::<1>(move |_, _| {
        c1.fetch_add(1, Ordering::Relaxed);
    });
    m.set_on_split::<1>(move |_, _| {
        c2.fetch_add(1, Ordering::Relaxed);
    });
    let d = square(&mut m);
    let e = square(&mut m);
    m.set_attribute::<1>(e[0], 3);
    m.sew(d[0], e[1], 2);
    assert_eq!(m.attribute::<1>(d[1]), Some(&3));
    assert_eq!(m.attribute_count::<1>(), 1);
    assert_eq!(calls.load(Ordering::Relaxed), 0);
    m.unsew(e[1], 2);
    // the split: one hook call, both edges carry 3
    assert_eq!(calls.load(Ordering::Relaxed), 1);
    assert_eq!(m.attribute::<1>(d[1]), Some(&3));
    assert_eq!(m.attribute::<1>(e[0]), Some(&3));
    assert_eq!(m.attribute_count::<1>(), 2);
    m.check_attributes().unwrap();
}

#[test]
fn split_hook_sees_both_values() {
    let mut m: GMap<((), (), Cells<Vec<u32>>)> = GMap::with_attributes(1);
    // slot 2 is inert on a 1-map: nothing stored, nothing reconciled
    let a = m.create_dart();
    assert_eq!(m.try_set_attribute::<2>(a, vec![]), Err(EditError::NoSuchCells { cell: 2, dim: 1 }));
    let mut m: GMap<(Cells<Vec<u32>>,)> = GMap::with_attributes(1);
    m.set_on_split::<0>(|kept, copy| {
        kept.push(1);
        copy.push(2);
    });
    let (a, b) = (m.create_dart(), m.create_dart());
    m.sew(a, b, 1);
    m.set_attribute::<0>(a, vec![0]);
    m.unsew(b, 1);
    // the first dart of the unsew keeps the original
    assert_eq!(m.attribute::<0>(b), Some(&vec![0, 1]));
    assert_eq!(m.attribute::<0>(a), Some(&vec![0, 2]));
}

#[test]
fn vertex_points_survive_sew_and_unsew() {
    let mut m = GMap::new(2);
    let d = square(&mut m);
    assert!(!m.has_points());
    for k in 0..4 {
        m.set_point(d[2 * k + 1], Some([k as f64, 0.0, 0.0]));
    }
    // every dart of a vertex sees its point
    assert_eq!(m.point(d[0]), Some([3.0, 0.0, 0.0]));
    assert_eq!(m.point(d[2]), Some([0.0, 0.0, 0.0]));
    assert_eq!(m.point_count(), 4);
    let e = square(&mut m);
    for k in 0..4 {
        m.set_point(e[2 * k + 1], Some([k as f64, 10.0, 0.0]));
    }
    // gluing d[0]d[1] to e[1]e[0]: the vertices of d win
    m.sew(d[0], e[1], 2);
    assert_eq!(m.point_count(), 6);
    assert_eq!(m.point(e[1]), Some([3.0, 0.0, 0.0]));
    assert_eq!(m.point(e[0]), Some([0.0, 0.0, 0.0]));
    m.check_attributes().unwrap();
    m.unsew(d[0], 2);
    assert_eq!(m.point_count(), 8);
    assert_eq!(m.point(e[1]), Some([3.0, 0.0, 0.0]));
    assert_eq!(m.point(d[0]), Some([3.0, 0.0, 0.0]));
    m.set_point(e[1], None);
    assert_eq!(m.point(e[2]), None);
    assert_eq!(m.point(d[0]), Some([3.0, 0.0, 0.0]));
    m.check_attributes().unwrap();
    // to_dense writes a vertex's point on each of its darts, from_dense reads it back
    let (dense, ids) = m.to_dense_with_ids();
    let k = ids.iter().position(|&x| x == d[0]).unwrap();
    assert_eq!(dense.point(Dart::new(k as u32)), Some([3.0, 0.0, 0.0]));
    let (back, bids) = GMap::from_dense(&dense);
    assert_eq!(back.point(bids[k]), Some([3.0, 0.0, 0.0]));
    assert_eq!(back.point_count(), 7);
    back.check_attributes().unwrap();
}

#[test]
fn removing_darts_frees_unused_values_and_check_reports_disagreement() {
    let mut m: GMap<((), Cells<u32>)> = GMap::with_attributes(1);
    let (a, b, c) = (m.create_dart(), m.create_dart(), m.create_dart());
    m.sew(a, b, 0);
    let id = m.set_attribute::<1>(a, 4);
    m.set_point(c, Some([1.0, 2.0, 3.0]));
    // linking without reconciling leaves the edge of a/c disagreeing
    m.unlink(a, 0);
    m.link(a, c, 0);
    let e = m.check_attributes().unwrap_err();
    assert!(
        matches!(e, AttributeDefect::Disagree { dim: 1, dart, other, .. } if (dart, other) == (a, c) || (dart, other) == (c, a)),
        "{e:?}"
    );
    assert!(e.to_string().contains("disagree"));
    // the count of the edge is now 2 but only a holds it after b is reconciled away
    m.reconcile_attributes(&[a, c, b]);
    m.check_attributes().unwrap();
    assert_eq!(m.attribute::<1>(c), Some(&4));
    assert_eq!(m.attribute::<1>(b), Some(&4));
    assert_eq!(m.attribute_count::<1>(), 2);
    m.remove_dart(b);
    m.remove_dart(a);
    assert_eq!(m.attribute_dart::<1>(id), Some(c));
    m.remove_dart(c);
    assert_eq!(m.attribute_by_id::<1>(id), None);
    assert_eq!(m.attribute_count::<1>(), 0);
    assert_eq!(m.point_count(), 0);
}

#[test]
fn check_covers_structure_and_attributes() {
    let mut m: GMap<((), Cells<u8>)> = GMap::with_attributes(1);
    let (a, b) = (m.create_dart(), m.create_dart());
    assert!(m.needs_reconcile());
    m.sew(a, b, 0);
    m.set_attribute::<1>(a, 1);
    assert_eq!(m.validate(), Ok(()));
    m.unlink(a, 0);
    m.link(a, a, 0);
    assert_eq!(
        m.validate(),
        Err(MapDefect::Attribute(AttributeDefect::Shared {
            dim: 1,
            attr: m.attribute_id::<1>(a).unwrap(),
            dart: b,
            other: a
        }))
    );
    m.reconcile_attributes(&[a, b]);
    assert_eq!(m.validate(), Ok(()));
    assert_eq!(m.attribute_count::<1>(), 2);
    assert!(!GMap::new(1).needs_reconcile());
}

#[test]
fn check_names_the_point_disagreement() {
    let mut m = GMap::new(1);
    let (a, b) = (m.create_dart(), m.create_dart());
    m.set_point(a, Some([0.0; 3]));
    m.link(a, b, 1);
    assert_eq!(m.check_attributes(), Err(AttributeDefect::PointDisagree { dart: a, other: b }));
}
