//! Stellar subdivision (`try_star_cell`, `try_star_face`, CGAL's `insert_cell_0_in_cell_2`,
//! `insert_point_in_cell`): exact cell counts on classic objects, faces shared by two
//! volumes, faces in 4-maps, degenerate faces; attributes and hooks counted; property
//! tests on random cells of random objects (validity, the returned vector equal to the
//! recounted change, the Euler characteristic kept).

use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Arc;

use gmap_core::{Cells, DartId, DenseMap, GMap};
use gmap_ops::build::{cube, grid, polygon, schema, simplex};
use gmap_ops::euler::ops::*;
use gmap_ops::euler::EulerError;
use proptest::prelude::*;

fn counts<A: gmap_core::Attributes>(g: &GMap<A>) -> Vec<usize> {
    g.cell_counts()
}

fn thaw(m: &DenseMap) -> GMap {
    GMap::from_dense(m).0
}

/// `after - before`, entry by entry.
fn change(before: &[usize], after: &[usize]) -> Vec<i64> {
    after.iter().zip(before).map(|(&a, &b)| a as i64 - b as i64).collect()
}

/// Stars the i-cell of `d` and checks validity, the dart count and that the returned
/// vector is the recounted change; returns the new counts.
fn star_checked<A: gmap_core::Attributes>(g: &mut GMap<A>, d: DartId, i: usize) -> Vec<usize> {
    let before = counts(g);
    let cell = g.cell_darts(d, i).len();
    let darts = g.dart_count();
    let s = try_star_cell(g, d, i, None).unwrap();
    let after = counts(g);
    assert_eq!(s.op.vector.dx(), &change(&before, &after)[..], "the vector is the change of cells");
    assert!(s.op.vector.dy().iter().all(|&y| y == 0));
    assert_eq!(g.dart_count(), darts + i * cell);
    g.validate().unwrap();
    g.check_attributes().unwrap();
    after
}

#[test]
fn a_square_becomes_four_triangles() {
    let mut g = thaw(&polygon(4).unwrap());
    let d = g.darts().next().unwrap();
    let s = try_star_face(&mut g, d, Some([0.0, 0.0, 0.0])).unwrap();
    assert_eq!((s.op.name.as_str(), s.op.vector.dx()), ("star_f", &[1, 4, 3][..]));
    assert_eq!(s.op.basis_name(), "B0 + A1 + 3B1 + 3A2");
    assert_eq!(counts(&g), vec![5, 8, 4]);
    assert_eq!(g.dart_count(), 24);
    // the vertex returned is the new one: four edges, four triangles around it
    assert_eq!(s.vertex, g.alpha(g.alpha(d, 1), 0));
    assert_eq!(g.point(s.vertex), Some([0.0, 0.0, 0.0]));
    assert_eq!(g.cell_darts(s.vertex, 0).len(), 8);
    assert_eq!(g.cell_darts(d, 2).len(), 6);
    // the corners keep their points; the square was built with points at its corners
    assert_eq!(g.point_count(), 5);
    g.validate().unwrap();
}

#[test]
fn an_edge_gets_a_vertex() {
    let mut g = thaw(&polygon(3).unwrap());
    let d = g.darts().next().unwrap();
    let s = try_star_cell(&mut g, d, 1, None).unwrap();
    assert_eq!((s.op.name.as_str(), s.op.vector.dx()), ("star_e", &[1, 1, 0][..]));
    assert_eq!(counts(&g), vec![4, 4, 1]);
    assert_eq!(g.alpha(d, 0), s.vertex);
    assert_eq!(g.point(s.vertex), None);
    // as an insertion in an edge with insert_point_in_cell: the point is set
    let v = insert_point_in_cell(&mut g, d, 1, [1.0, 2.0, 3.0]).unwrap();
    assert_eq!(g.point(v), Some([1.0, 2.0, 3.0]));
    assert_eq!(v, g.alpha(d, 0));
    assert_eq!(counts(&g), vec![5, 5, 1]);
}

#[test]
fn the_star_of_an_edge_is_the_vertex_insertion() {
    for m in [polygon(3).unwrap(), cube(3).unwrap(), grid(&[2, 2], &[true, false]).unwrap()] {
        let mut a = thaw(&m);
        let mut b = thaw(&m);
        let (da, db) = (a.darts().nth(5).unwrap(), b.darts().nth(5).unwrap());
        let star = try_star_cell(&mut a, da, 1, None).unwrap();
        let mve = try_insert_vertex(&mut b, db).unwrap();
        assert_eq!(star.op.vector, mve.vector);
        assert!(gmap_ops::iso::are_isomorphic(&a.to_dense_map(), &b.to_dense_map()));
    }
}

#[test]
fn a_hexahedron_becomes_six_pyramids() {
    let mut g = thaw(&cube(3).unwrap());
    let d = g.darts().next().unwrap();
    let s = try_star_cell(&mut g, d, 3, None).unwrap();
    // 8 + 1 vertices, 12 + 8 edges, 6 + 12 faces, 6 volumes: chi = 9 - 20 + 18 - 6 = 1
    assert_eq!((s.op.name.as_str(), s.op.vector.dx()), ("star_s", &[1, 8, 12, 5][..]));
    assert_eq!(counts(&g), vec![9, 20, 18, 6]);
    assert_eq!(g.dart_count(), 4 * 48);
    // each volume is a square pyramid: 4 triangles and a square, 32 darts
    for v in g.one_dart_per_cell(3).collect::<Vec<_>>() {
        assert_eq!(g.cell_darts(v, 3).len(), 32);
    }
    assert_eq!(s.vertex, g.alpha(g.alpha(g.alpha(d, 2), 1), 0));
    // the new vertex meets every volume, edge and face made
    assert_eq!(g.cell_darts(s.vertex, 0).len(), 6 * 4 * 2);
    g.validate().unwrap();
}

#[test]
fn a_face_between_two_hexahedra_is_starred_on_both_sides() {
    let mut g = GMap::new(3);
    let a = g.try_append(&cube(3).unwrap()).unwrap()[0];
    let b = g.try_append(&cube(3).unwrap()).unwrap()[0];
    g.try_sew(a, b, 3).unwrap();
    assert_eq!(counts(&g), vec![12, 20, 11, 2]);
    let after = star_checked(&mut g, b, 2);
    // CGAL's gmap_3_with_colored_facets prints the same: 128 darts, 13, 24, 14, 2
    assert_eq!(after, vec![13, 24, 14, 2]);
    assert_eq!(g.dart_count(), 128);
    // both sides: every new triangle is 3-sewn
    let s = g.alpha(g.alpha(b, 1), 0);
    assert!(g.cell_darts(s, 0).iter().all(|&x| !g.is_free(x, 3)));
}

#[test]
fn faces_and_cells_of_a_tesseract() {
    // a square of the 4-cube lies in 3 cubes, its darts have copies across alpha_3, alpha_4
    let mut g = thaw(&cube(4).unwrap());
    assert_eq!(counts(&g), vec![16, 32, 24, 8, 1]);
    let d = g.darts().next().unwrap();
    assert_eq!(star_checked(&mut g, d, 2), vec![17, 36, 27, 8, 1]);
    // the whole 4-cell: a cone over every vertex, edge, face and cube of its boundary
    let mut g = thaw(&cube(4).unwrap());
    let d = g.darts().next().unwrap();
    let s = try_star_cell(&mut g, d, 4, None).unwrap();
    assert_eq!((s.op.name.as_str(), s.op.vector.dx()), ("star_c4", &[1, 16, 32, 24, 7][..]));
    assert_eq!(counts(&g), vec![17, 48, 56, 32, 8]);
}

#[test]
fn the_one_face_of_a_torus_repeats_its_vertex_and_edges() {
    // a b A B: one vertex, two edges, one face, each seen several times from the face
    let mut g = thaw(&schema("a b A B").unwrap());
    assert_eq!(counts(&g), vec![1, 2, 1]);
    let d = g.darts().next().unwrap();
    // the new vertex is joined to the 4 corners, all the same old vertex
    assert_eq!(star_checked(&mut g, d, 2), vec![2, 6, 4]);
}

#[test]
fn a_face_with_a_dangling_edge() {
    // the dangling edge is seen twice from inside the face, its tip once
    let mut g = thaw(&polygon(4).unwrap());
    let d = g.darts().next().unwrap();
    try_insert_dangling_edge(&mut g, d).unwrap();
    assert_eq!(counts(&g), vec![5, 5, 1]);
    assert_eq!(g.cell_darts(d, 2).len(), 12);
    assert_eq!(star_checked(&mut g, d, 2), vec![6, 11, 6]);
}

#[test]
fn an_open_face_is_a_fan() {
    // a path of three edges as the boundary of a face whose ends are 1-free: the cone over
    // it is a fan of three triangles
    let mut g = GMap::new(2);
    let x: Vec<DartId> = (0..6).map(|_| g.create_dart()).collect();
    for k in 0..3 {
        g.sew(x[2 * k], x[2 * k + 1], 0);
    }
    g.sew(x[1], x[2], 1);
    g.sew(x[3], x[4], 1);
    assert_eq!(counts(&g), vec![4, 3, 1]);
    // from the middle of the path: the walk reaches one free end, then the other
    let s = try_star_face(&mut g, x[2], None).unwrap();
    assert_eq!(s.op.vector.dx(), &[1, 4, 2][..]);
    assert_eq!(counts(&g), vec![5, 7, 3]);
    g.validate().unwrap();
}

#[test]
fn refusals_name_the_dart_or_the_dimension() {
    let mut g = thaw(&cube(3).unwrap());
    let d = g.darts().next().unwrap();
    let bad = EulerError::BadDimension { what: "star of a cell", lo: 1, hi: 3, got: 0 };
    assert_eq!(try_star_cell(&mut g, d, 0, None), Err(bad));
    assert!(!can_star_cell(&g, d, 0));
    assert!(matches!(try_star_cell(&mut g, d, 4, None), Err(EulerError::BadDimension { got: 4, .. })));
    assert!(can_star_cell(&g, d, 3) && can_star_face(&g, d));
    let mut e = thaw(&polygon(3).unwrap());
    let gone = e.darts().next().unwrap();
    e.remove_dart(gone);
    assert_eq!(try_star_face(&mut e, gone, None), Err(EulerError::NoSuchDart(gone)));
    assert!(!can_star_face(&e, gone));
    // a 1-map has no face
    let mut c = GMap::new(1);
    let x = c.create_dart();
    assert!(matches!(insert_cell_0_in_cell_2(&mut c, x, None), Err(EulerError::BadDimension { hi: 1, got: 2, .. })));
    assert!(!is_insertable_cell_0_in_cell_2(&c, x));
    assert_eq!(c.dart_count(), 1);
    // nothing changed on refusal
    assert_eq!(counts(&g), vec![8, 12, 6, 1]);
}

/// A hook counter: (merges, splits).
fn counters() -> (Arc<AtomicUsize>, Arc<AtomicUsize>) {
    (Arc::new(AtomicUsize::new(0)), Arc::new(AtomicUsize::new(0)))
}

#[test]
fn a_halving_split_hook_runs_once_per_new_triangle_in_cgals_order() {
    // CGAL's gmap_3_with_colored_facets: faces of 7 and 13, merged to 20 by the 3-sew, the
    // shared face starred from a dart of the second hexahedron
    type Map = GMap<((), (), Cells<i32>, ())>;
    let mut g: Map = GMap::with_attributes(3);
    let (merges, splits) = counters();
    let (m, s) = (merges.clone(), splits.clone());
    g.set_on_merge::<2>(move |kept, other| {
        m.fetch_add(1, Ordering::Relaxed);
        *kept += other;
    });
    g.set_on_split::<2>(move |kept, copy| {
        s.fetch_add(1, Ordering::Relaxed);
        *kept /= 2;
        *copy = *kept;
    });
    let a = g.try_append(&cube(3).unwrap()).unwrap()[0];
    let b = g.try_append(&cube(3).unwrap()).unwrap()[0];
    for (dart, value) in [(a, 7), (b, 13)] {
        for f in g.one_dart_per_incident_cell(dart, 3, 2).collect::<Vec<_>>() {
            g.set_attribute::<2>(f, value);
        }
    }
    g.try_sew(a, b, 3).unwrap();
    assert_eq!((merges.load(Ordering::Relaxed), splits.load(Ordering::Relaxed)), (1, 0));
    assert_eq!(g.attribute::<2>(b), Some(&20));
    // one dart per side of the square, around it from b across alpha_0
    let mut sides = vec![b];
    for _ in 0..3 {
        let last = *sides.last().unwrap();
        sides.push(g.alpha(g.alpha(last, 0), 1));
    }
    assert!(is_insertable_cell_0_in_cell_2(&g, b));
    let v = insert_cell_0_in_cell_2(&mut g, b, None).unwrap();
    assert_eq!((merges.load(Ordering::Relaxed), splits.load(Ordering::Relaxed)), (1, 3));
    // the triangle of b kept 20 / 2 / 2 / 2; the others in order: 10, 5, 2
    let values: Vec<i32> = sides.iter().map(|&x| *g.attribute::<2>(x).unwrap()).collect();
    assert_eq!(values, vec![2, 10, 5, 2]);
    // the last one is across the new edge at b's corner, the one CGAL's example removes
    assert!(g.cell_darts(g.alpha(v, 2), 2).contains(&sides[3]));
    assert_eq!(g.attribute_count::<2>(), 14);
    assert_eq!(counts(&g)[2], 14);
    g.validate().unwrap();
}

/// A map with a `u32` on every cell of every dimension up to 4 and a point per vertex.
type Full = GMap<(Cells<u32>, Cells<u32>, Cells<u32>, Cells<u32>, Cells<u32>)>;

/// A copy of `m` with every cell labelled, every vertex given a point, and hooks that count
/// the splits of each dimension and the merges of all.
struct Labelled {
    g: Full,
    splits: Vec<Arc<AtomicUsize>>,
    merges: Arc<AtomicUsize>,
}

impl Labelled {
    // the label of slot 0 compares `0 <= n`, always true
    #[allow(unused_comparisons)]
    fn new(m: &DenseMap) -> Self {
        let mut g: Full = GMap::from_dense_with_attributes(m).0;
        let splits: Vec<Arc<AtomicUsize>> = (0..5).map(|_| Arc::new(AtomicUsize::new(0))).collect();
        let merges = Arc::new(AtomicUsize::new(0));
        macro_rules! label {
            ($($k:literal)+) => {$(
                let s = splits[$k].clone();
                g.set_on_split::<$k>(move |_, _| {
                    s.fetch_add(1, Ordering::Relaxed);
                });
                let c = merges.clone();
                g.set_on_merge::<$k>(move |_, _| {
                    c.fetch_add(1, Ordering::Relaxed);
                });
                if $k <= g.dim() {
                    for (n, x) in g.one_dart_per_cell($k).collect::<Vec<_>>().into_iter().enumerate() {
                        g.set_attribute::<$k>(x, n as u32);
                    }
                }
            )+};
        }
        label!(0 1 2 3 4);
        for (n, x) in g.one_dart_per_cell(0).collect::<Vec<_>>().into_iter().enumerate() {
            g.set_point(x, Some([n as f64, 0.0, 0.0]));
        }
        Labelled { g, splits, merges }
    }

    /// Split hook calls per dimension up to n.
    fn splits(&self) -> Vec<usize> {
        self.splits[..=self.g.dim()].iter().map(|s| s.load(Ordering::Relaxed)).collect()
    }

    /// Whether the i-cell of `d` carries an attribute.
    fn has_attribute(&self, d: DartId, i: usize) -> bool {
        let g = &self.g;
        match i {
            0 => g.attribute::<0>(d).is_some(),
            1 => g.attribute::<1>(d).is_some(),
            2 => g.attribute::<2>(d).is_some(),
            3 => g.attribute::<3>(d).is_some(),
            _ => g.attribute::<4>(d).is_some(),
        }
    }

    /// Number of attributes per dimension up to n.
    fn attribute_counts(&self) -> Vec<usize> {
        let g = &self.g;
        let all = [
            g.attribute_count::<0>(),
            g.attribute_count::<1>(),
            g.attribute_count::<2>(),
            g.attribute_count::<3>(),
            g.attribute_count::<4>(),
        ];
        all[..=g.dim()].to_vec()
    }
}

#[test]
fn attributes_on_every_dimension_stay_one_per_cell() {
    let mut l = Labelled::new(&cube(3).unwrap());
    let d = l.g.darts().next().unwrap();
    let points: Vec<(DartId, Option<[f64; 3]>)> = l.g.darts().map(|x| (x, l.g.point(x))).collect();
    let st = try_star_cell(&mut l.g, d, 3, Some([0.5, 0.5, 0.5])).unwrap();
    assert_eq!(l.splits(), vec![0, 0, 0, 5]);
    assert_eq!(l.merges.load(Ordering::Relaxed), 0);
    // old cells keep theirs, the six pyramids have one each, the new cones none
    assert_eq!(l.attribute_counts(), vec![8, 12, 6, 6]);
    let g = &l.g;
    assert_eq!(g.attribute::<0>(st.vertex), None);
    assert_eq!(g.attribute::<1>(st.vertex), None);
    assert_eq!(g.attribute::<3>(st.vertex), g.attribute::<3>(d));
    // every old dart sees the point it saw, the new vertex has its own
    assert!(points.iter().all(|&(x, p)| g.point(x) == p));
    assert_eq!(g.point_count(), 9);
    assert_eq!(g.point(st.vertex), Some([0.5, 0.5, 0.5]));
    g.validate().unwrap();
}

#[test]
fn a_map_without_attributes_and_one_with_them_get_the_same_links() {
    let m = simplex(3).unwrap();
    let mut plain = GMap::new(3);
    let p = plain.append(&m);
    let mut rich: GMap<((), Cells<u8>, Cells<u8>)> = GMap::with_attributes(3);
    let r = rich.append(&m);
    rich.set_attribute::<2>(r[0], 1);
    rich.set_attribute::<1>(r[0], 1);
    try_star_face(&mut plain, p[0], None).unwrap();
    try_star_face(&mut rich, r[0], None).unwrap();
    assert_eq!(plain.to_dense_map().flat(), rich.to_dense_map().flat());
    rich.validate().unwrap();
}

/// A few objects: polygons, a torus and a Klein bottle of squares, a 3-torus of cubes,
/// simplices, a 4-cube.
fn object(kind: u8) -> DenseMap {
    match kind % 8 {
        0 => polygon(5).unwrap(),
        1 => grid(&[3, 3], &[true, true]).unwrap(),
        2 => schema("a b a B").unwrap(),
        3 => cube(3).unwrap(),
        4 => grid(&[2, 2, 2], &[true, true, true]).unwrap(),
        5 => simplex(3).unwrap(),
        6 => grid(&[2, 1, 1, 1], &[false, false, false, true]).unwrap(),
        _ => schema("a a b b").unwrap(),
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    /// Random cells of random objects, starred in sequence: the map stays valid, each
    /// vector is the recounted change, the Euler characteristic and orientability stay.
    #[test]
    fn stars_anywhere_are_subdivisions(kind in 0u8..8, picks in prop::collection::vec((0usize..10_000, 1usize..5), 1..4)) {
        let m = object(kind);
        let mut g = thaw(&m);
        let chi = m.euler_characteristic();
        let orientable = m.is_orientable();
        for (at, i) in picks {
            let i = 1 + (i - 1) % g.dim();
            let d = g.darts().nth(at % g.dart_count()).unwrap();
            star_checked(&mut g, d, i);
        }
        prop_assert_eq!(g.euler_characteristic(), chi);
        prop_assert_eq!(g.is_orientable(), orientable);
    }

    /// The same with an attribute on every cell and a point on every vertex: on a cell with
    /// an attribute the split hook of dimension i runs once per cone beyond the first and the
    /// i-cells gain as many attributes (a cell made by an earlier star has none: nothing to
    /// split); no other hook runs, the other dimensions gain no attribute, and every old
    /// dart keeps the point it had.
    #[test]
    fn stars_keep_one_attribute_per_cell(kind in 0u8..8, picks in prop::collection::vec((0usize..10_000, 1usize..5), 1..4)) {
        let mut l = Labelled::new(&object(kind));
        let n = l.g.dim();
        let mut splits = vec![0; n + 1];
        let mut attrs = l.attribute_counts();
        for (at, i) in picks {
            let i = 1 + (i - 1) % n;
            let d = l.g.darts().nth(at % l.g.dart_count()).unwrap();
            let points: Vec<(DartId, Option<[f64; 3]>)> = l.g.darts().map(|x| (x, l.g.point(x))).collect();
            let labelled = l.has_attribute(d, i);
            let st = try_star_cell(&mut l.g, d, i, Some([-1.0, 0.0, 0.0])).unwrap();
            if labelled {
                let more = st.op.vector.dx()[i] as usize;
                splits[i] += more;
                attrs[i] += more;
            }
            prop_assert_eq!(l.splits(), splits.clone());
            prop_assert_eq!(l.merges.load(Ordering::Relaxed), 0);
            prop_assert_eq!(l.attribute_counts(), attrs.clone());
            prop_assert!(points.iter().all(|&(x, p)| l.g.point(x) == p));
            prop_assert_eq!(l.g.point(st.vertex), Some([-1.0, 0.0, 0.0]));
            prop_assert_eq!(l.g.validate(), Ok(()));
        }
    }
}

#[test]
fn insert_barycenter_in_cell_places_the_vertex_at_the_mean_of_the_corners() {
    let mut g = GMap::new(3);
    let d = g.make_hexahedron([
        [0.0, 0.0, 0.0],
        [2.0, 0.0, 0.0],
        [2.0, 2.0, 0.0],
        [0.0, 2.0, 0.0],
        [0.0, 2.0, 2.0],
        [0.0, 0.0, 2.0],
        [2.0, 0.0, 2.0],
        [2.0, 2.0, 2.0],
    ]);
    assert!(is_insertable_barycenter_in_cell(&g, d, 3));
    let v = insert_barycenter_in_cell(&mut g, d, 3).unwrap();
    assert_eq!(g.point(v), Some([1.0, 1.0, 1.0]));
    let c = g.characteristics();
    assert_eq!((c.darts, c.cells.clone()), (192, vec![9, 20, 18, 6]));
    g.validate().unwrap();
    // a face of the starred cube: a triangle with a corner at the centre
    let f = insert_barycenter_in_cell(&mut g, v, 2).unwrap();
    let p = g.point(f).unwrap();
    assert!(p.iter().zip([1.0, 1.0, 1.0]).all(|(a, b)| (a - b).abs() < 1.0), "{p:?}");
    // a map without points has no barycentre
    let mut bare = GMap::new(3);
    let e = bare.make_combinatorial_hexahedron();
    assert!(!is_insertable_barycenter_in_cell(&bare, e, 3));
    assert_eq!(insert_barycenter_in_cell(&mut bare, e, 3), Err(EulerError::NoPoint { dim: 3, dart: e }));
    assert_eq!(bare.dart_count(), 48);
}
