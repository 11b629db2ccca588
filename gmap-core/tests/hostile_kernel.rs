//! Hostile uses of the kernel's editing and query API (the hostile-input audit): an index
//! above the dimension, a dart that does not exist, a removed dart's handle, more darts than
//! a `u32` names, a ragged flat array. Each is refused with a typed error by the `try_`
//! form, and the panicking form panics with the same message instead of corrupting the map.

use std::panic::{catch_unwind, AssertUnwindSafe};

use gmap_core::{Dart, DartError, DenseMap, EditError, GMap, ValidityError};

/// The panic message of `f`, which must panic.
fn panic_message(f: impl FnOnce()) -> String {
    let e = catch_unwind(AssertUnwindSafe(f)).expect_err("expected a panic");
    e.downcast_ref::<String>().cloned().or_else(|| e.downcast_ref::<&str>().map(|s| s.to_string())).unwrap_or_default()
}

/// A segment as a 2-map's single triangle: `gmap 2 2` with darts 0 and 1 joined by alpha_0.
fn two_darts() -> DenseMap {
    let mut m = DenseMap::new(2, 2);
    m.link(Dart::new(0), Dart::new(1), 0);
    m
}

#[test]
fn dense_alpha_above_the_dimension_is_refused() {
    let m = two_darts();
    // alpha(0, 3) on a 2-map used to read dart 1's alpha_0
    assert_eq!(m.try_alpha(Dart::new(0), 3), Err(DartError::BadIndex { dart: Dart::new(0), alpha: 3, dim: 2 }));
    assert_eq!(m.try_alpha(Dart::new(2), 0), Err(DartError::NoSuchDart { dart: Dart::new(2), darts: 2 }));
    assert_eq!(m.try_alpha(Dart::new(0), 0), Ok(Dart::new(1)));
    let msg = panic_message(|| {
        m.alpha(Dart::new(0), 3);
    });
    assert_eq!(msg, "alpha_3 does not exist in a map of dimension 2 (asked at dart 0)");
    let msg = panic_message(|| {
        m.is_free(Dart::new(7), 0);
    });
    assert_eq!(msg, "dart 7 does not exist (the map has 2 darts)");
}

#[test]
fn dense_link_above_the_dimension_changes_nothing() {
    let mut m = two_darts();
    let before = m.clone();
    // link(0, 2, 3) on a 2-map used to overwrite alpha_0 of other darts
    assert_eq!(
        m.try_link(Dart::new(0), Dart::new(2), 3),
        Err(DartError::BadIndex { dart: Dart::new(0), alpha: 3, dim: 2 })
    );
    assert_eq!(m.try_link(Dart::new(0), Dart::new(2), 1), Err(DartError::NoSuchDart { dart: Dart::new(2), darts: 2 }));
    assert_eq!(m.try_unlink(Dart::new(1), 3), Err(DartError::BadIndex { dart: Dart::new(1), alpha: 3, dim: 2 }));
    assert_eq!(m, before);
    let msg = panic_message(|| m.clone().link(Dart::new(0), Dart::new(2), 3));
    assert!(msg.contains("alpha_3 does not exist"), "{msg}");
    let msg = panic_message(|| m.clone().unlink(Dart::new(5), 0));
    assert_eq!(msg, "dart 5 does not exist (the map has 2 darts)");
    m.validate().unwrap();
}

#[test]
fn dense_add_darts_past_u32_is_refused() {
    let mut m = DenseMap::new(1, 3);
    let e = m.try_add_darts(1 << 32).unwrap_err();
    assert_eq!(e, DartError::TooManyDarts { darts: 3, adding: 1 << 32 });
    assert_eq!(e.to_string(), "adding 4294967296 darts to 3 would pass the maximum of 4294967294 darts");
    assert_eq!(m.try_add_darts(u32::MAX as usize - 3), Err(DartError::TooManyDarts { darts: 3, adding: 4294967292 }));
    assert_eq!(m.try_add_darts(usize::MAX), Err(DartError::TooManyDarts { darts: 3, adding: usize::MAX }));
    assert_eq!(m.dart_count(), 3);
    assert_eq!(m.try_add_darts(2), Ok(Dart::new(3)));
    assert_eq!(m.dart_count(), 5);
    m.validate().unwrap();
    let msg = panic_message(|| {
        m.clone().add_darts(1 << 32);
    });
    assert!(msg.starts_with("adding 4294967296 darts"), "{msg}");
}

#[test]
fn dense_ragged_flat_array_is_an_error() {
    // 5 entries are not whole rows of 3
    let e = DenseMap::try_from_flat(2, vec![0, 0, 0, 1, 1]).unwrap_err();
    assert_eq!(e, ValidityError::RaggedRows { len: 5, width: 3 });
    assert_eq!(e.to_string(), "a flat array of 5 entries does not hold whole rows of 3 entries (dimension 2)");
    assert!(DenseMap::from_flat_unchecked(1, vec![0]).is_err());
    assert!(DenseMap::try_from_flat(1, vec![0, 0]).is_ok());
}

#[test]
fn gmap_unsew_and_remove_of_a_removed_dart_are_errors() {
    let mut g = GMap::new(2);
    let a = g.create_dart();
    let b = g.create_dart();
    g.sew(a, b, 0);
    g.remove_dart(a);
    assert_eq!(g.try_unsew(a, 0), Err(EditError::NoSuchDart(a)));
    assert_eq!(g.try_remove_dart(a), Err(EditError::NoSuchDart(a)));
    assert_eq!(g.try_unsew(b, 3), Err(EditError::BadIndex { alpha: 3, dim: 2 }));
    assert_eq!(g.try_link(a, b, 1), Err(EditError::NoSuchDart(a)));
    assert_eq!(g.try_unlink(b, 9), Err(EditError::BadIndex { alpha: 9, dim: 2 }));
    assert_eq!(g.try_alpha(a, 0), Err(EditError::NoSuchDart(a)));
    assert_eq!(g.try_sew(a, b, 0), Err(EditError::NoSuchDart(a)));
    assert!(g.is_free(b, 0));
    let msg = panic_message(|| g.clone().unsew(a, 0));
    assert!(msg.starts_with("dart ") && msg.contains("does not exist"), "{msg}");
    let msg = panic_message(|| g.clone().remove_dart(a));
    assert!(msg.contains("does not exist"), "{msg}");
    g.try_unsew(b, 0).unwrap();
    g.try_remove_dart(b).unwrap();
    assert_eq!(g.dart_count(), 0);
}

#[test]
fn gmap_stale_handle_does_not_mark_the_dart_reusing_its_slot() {
    let mut g = GMap::new(1);
    let old = g.create_dart();
    g.remove_dart(old);
    let new = g.create_dart();
    // the slot is reused, with a new version
    assert_eq!(g.dart_index(old), g.dart_index(new));
    let m = g.reserve_mark();
    assert_eq!(g.try_mark(m, old), Err(EditError::NoSuchDart(old)));
    assert!(!g.is_marked(m, new));
    let msg = panic_message(|| {
        g.clone().mark(m, old);
    });
    assert!(msg.contains("does not exist"), "{msg}");
    assert!(catch_unwind(AssertUnwindSafe(|| g.is_marked(m, old))).is_err());
    assert_eq!(g.try_mark(m, new), Ok(false));
    assert!(g.is_marked(m, new));
}
