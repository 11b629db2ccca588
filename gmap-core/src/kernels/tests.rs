//! Unit tests of the flat-array kernels: the union-find counters against traversals, the
//! two-thread paths, the generic widths, on the fixtures of `crate::examples`. A file of its
//! own: the fixtures are dense maps, whose file uses these kernels, and a child file that
//! nothing imports keeps them from closing an import circle with it (`tests/layout.rs`).

use super::*;

#[test]
fn bits() {
    let mut b = Bits::new(130);
    assert_eq!(b.next_clear(0, 130), Some(0));
    for i in 0..129 {
        b.set(i);
    }
    assert_eq!(b.next_clear(0, 130), Some(129));
    assert!(!b.test_and_set(129));
    assert!(b.test_and_set(129));
    assert_eq!(b.next_clear(0, 130), None);
    assert!(b.get(64));
}

#[test]
fn union_find_and_traversal_agree() {
    for m in [crate::examples::fig1_surface(), crate::examples::klein_bottle(), crate::examples::cylinder()] {
        let rows: &[[u32; 3]] = m.flat().as_chunks::<3>().0;
        for mask in 0..8u32 {
            assert_eq!(count_rows_uf(rows, mask), count_rows(rows, mask), "mask {mask:b}");
        }
        assert_eq!(orientable_rows(rows), orient_rows(rows).is_ok());
    }
    let k = crate::examples::klein_bottle();
    assert!(!orientable_rows(k.flat().as_chunks::<3>().0));
}

/// A ring of `n` squares (8 darts each) glued side to side, the last to the first with or
/// without a half twist: an annulus or a Möbius band.
fn ring_of_squares(n: u32, twist: bool) -> crate::DenseMap {
    use crate::Dart;
    let mut m = crate::DenseMap::new(2, 8 * n as usize);
    for k in 0..n {
        let b = 8 * k;
        for j in 0..4 {
            m.link(Dart::new(b + 2 * j), Dart::new(b + 2 * j + 1), 0);
            m.link(Dart::new(b + 2 * j + 1), Dart::new(b + (2 * j + 2) % 8), 1);
        }
        let c = 8 * ((k + 1) % n);
        let flip = twist && k + 1 == n;
        let (x, y) = if flip { (c + 6, c + 7) } else { (c + 7, c + 6) };
        m.link(Dart::new(b + 2), Dart::new(x), 2);
        m.link(Dart::new(b + 3), Dart::new(y), 2);
    }
    m
}

#[test]
fn big_maps_take_the_two_thread_paths() {
    for twist in [false, true] {
        let m = ring_of_squares(10_000, twist);
        assert!(m.dart_count() >= parallel::PARALLEL_FROM);
        m.validate().unwrap();
        assert_eq!(m.cell_counts_and_components(), (vec![20_000, 30_000, 10_000], 1));
        assert_eq!(m.is_orientable(), !twist);
        assert_eq!(m.orientation().is_ok(), !twist);
    }
    // a conflict inside the second half only
    let mut m = ring_of_squares(10_000, false);
    let base = m.dart_count() as u32;
    let k = crate::examples::klein_bottle();
    m.add_darts(8);
    for d in 0..8u32 {
        for i in 0..3 {
            m.link(crate::Dart::new(base + d), crate::Dart::new(base + k.row(crate::Dart::new(d))[i]), i);
        }
    }
    m.validate().unwrap();
    assert!(!m.is_orientable());
    assert_eq!(m.cell_counts_and_components(), (vec![20_001, 30_002, 10_001], 2));
}

#[test]
fn generic_and_specialised_paths_agree() {
    // a 9-map (width 10, generic path) made of two darts swapped by every involution
    let a: Vec<u32> = [vec![1u32; 10], vec![0u32; 10]].concat();
    assert_eq!(count_orbits(&a, 10, 0b1), 1);
    assert_eq!(count_orbits(&a, 10, 0), 2);
    assert!(is_valid(&a, 10));
    assert_eq!(orientation(&a, 10), Ok(vec![1, 2]));
    let b: Vec<u32> = [vec![1u32; 4], vec![0u32; 4]].concat();
    assert_eq!(count_orbits(&b, 4, 0b1), 1);
    assert!(is_valid(&b, 4));
    assert_eq!(orientation(&b, 4), Ok(vec![1, 2]));
    // out of range and a non-involution are caught on both paths
    assert!(!is_valid(&[1, 2], 1));
    assert!(!is_valid(&[1; 20], 10));
}
