use gmap_core::DenseMap;
use gmap_ops::build::{grid, polygon, schema};
use proptest::prelude::*;

use super::*;
use crate::curves::basis::shortest_basis;
use crate::curves::error::CurveError;

fn unit(map: &DenseMap) -> Surface {
    Surface::of_map(map, &Weights::Unit).unwrap()
}

fn width(map: &DenseMap) -> Option<usize> {
    edge_width(map).unwrap().map(|c| c.edges.len())
}

/// A cycle is a closed walk of the surface's edges with the length of its weights.
fn check_walk(s: &Surface, c: &Cycle) {
    assert_eq!(c.vertices.len(), c.edges.len() + 1);
    assert_eq!(c.vertices.first(), c.vertices.last());
    for (k, &e) in c.edges.iter().enumerate() {
        let (a, b) = s.graph.ends(e);
        let (x, y) = (c.vertices[k], c.vertices[k + 1]);
        assert!((a, b) == (x, y) || (b, a) == (x, y), "edge {e} does not join {x} and {y}");
    }
    let sum: f64 = c.edges.iter().map(|&e| s.graph.weight(e)).sum();
    assert_eq!(sum, c.length);
}

#[test]
fn widths_of_torus_grids_are_the_shorter_side() {
    for (a, b) in [(3, 3), (4, 3), (5, 2), (7, 4)] {
        let t = grid(&[a, b], &[true, true]).unwrap();
        assert_eq!(width(&t), Some(a.min(b)), "{a} x {b}");
        assert_eq!(face_width(&t).unwrap().unwrap().width, a.min(b), "{a} x {b}");
        let c = shortest_non_contractible_cycle(&unit(&t)).unwrap().unwrap();
        check_walk(&unit(&t), &c);
    }
}

#[test]
fn spheres_and_discs_have_no_non_contractible_cycle() {
    assert_eq!(width(&schema("a A").unwrap()), None);
    assert_eq!(width(&schema("a b B A").unwrap()), None);
    assert_eq!(width(&polygon(5).unwrap()), None);
    assert_eq!(width(&grid(&[3, 3], &[false, false]).unwrap()), None);
    assert_eq!(face_width(&schema("a b B A").unwrap()).unwrap(), None);
}

#[test]
fn non_orientable_and_bounded_surfaces() {
    // projective plane and Klein bottle: one vertex, every loop edge essential
    assert_eq!(width(&schema("a a").unwrap()), Some(1));
    assert_eq!(width(&gmap_core::examples::klein_bottle()), Some(1));
    // an annulus of 5 x 2 squares: the core goes round in 5 edges
    assert_eq!(width(&grid(&[5, 2], &[true, false]).unwrap()), Some(5));
    // the Möbius band of one square `a b a c`: two vertices, no loop; a then b goes round
    assert_eq!(width(&schema("a b a c").unwrap()), Some(2));
    assert!(matches!(face_width(&grid(&[5, 2], &[true, false]).unwrap()), Err(CurveError::Boundary { .. })));
}

#[test]
fn double_torus_one_face() {
    let m = schema(&gmap_ops::build::orientable_surface_word(2)).unwrap();
    assert_eq!(width(&m), Some(1));
    assert_eq!(face_width(&m).unwrap().unwrap().width, 1);
}

#[test]
fn refusals_name_the_offence() {
    let solid = grid(&[2, 2, 2], &[false; 3]).unwrap();
    assert_eq!(Surface::of_map(&solid, &Weights::Unit).unwrap_err(), CurveError::NotTwoMap { dim: 3 });
    let t = grid(&[3, 3], &[true, true]).unwrap();
    let e = t.cell_count(1);
    let err = Surface::of_map(&t, &Weights::PerEdge(vec![1.0; e - 1])).unwrap_err();
    assert_eq!(err, CurveError::WeightCount { given: e - 1, edges: e });
    let mut w = vec![1.0; e];
    w[4] = -1.0;
    assert_eq!(Surface::of_map(&t, &Weights::PerEdge(w)).unwrap_err(), CurveError::BadWeight { edge: 4, weight: -1.0 });
    assert!(matches!(Surface::of_map(&t, &Weights::Length), Err(CurveError::NoPoint { .. })));
    let s = unit(&t);
    assert_eq!(
        shortest_non_contractible_cycle_through(&s, 99).unwrap_err(),
        CurveError::NoSuchVertex { vertex: 99, vertices: 9 }
    );
    let mut open = DenseMap::new(2, 2);
    open.link(gmap_core::Dart::new(0), gmap_core::Dart::new(1), 0);
    assert_eq!(Surface::of_map(&open, &Weights::Unit).unwrap_err(), CurveError::OpenCell { dart: 0, i: 1 });
}

#[test]
fn lengths_from_points() {
    let t = gmap_ops::build::placed::torus_with_points(8, 4, 3.0, 1.0).unwrap();
    let s = Surface::of_map(&t, &Weights::Length).unwrap();
    let c = shortest_non_contractible_cycle(&s).unwrap().unwrap();
    check_walk(&s, &c);
    // the inner meridian-free loop: 4 edges of the small circle, each 2 sin(π/4)
    let small = 4.0 * 2.0 * (std::f64::consts::PI / 4.0).sin();
    assert!((c.length - small).abs() < 1e-9, "{}", c.length);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// On a torus every non-contractible simple cycle is non-separating, so the shortest
    /// one is the shortest cycle of non-zero class in H_1(Z/2): the two modules agree.
    #[test]
    fn torus_shortest_agrees_with_the_shortest_basis(a in 2usize..6, b in 2usize..6, seed in any::<u64>()) {
        let t = grid(&[a, b], &[true, true]).unwrap();
        let e = t.cell_count(1);
        let mut x = seed | 1;
        let w: Vec<f64> = (0..e).map(|_| { x ^= x << 13; x ^= x >> 7; x ^= x << 17; (x % 9 + 1) as f64 }).collect();
        let s = Surface::of_map(&t, &Weights::PerEdge(w.clone())).unwrap();
        let c = shortest_non_contractible_cycle(&s).unwrap().unwrap();
        check_walk(&s, &c);
        let cc = crate::cellular_complex(&t).unwrap();
        let basis = shortest_basis(&cc.chain, &w).unwrap();
        prop_assert_eq!(c.length, basis[0].length);
        // the overall shortest is the shortest through some vertex, and no root beats it
        let through: Vec<f64> = (0..s.graph.vertex_count() as u32)
            .map(|v| shortest_non_contractible_cycle_through(&s, v).unwrap().unwrap().length)
            .collect();
        prop_assert_eq!(through.iter().cloned().fold(f64::INFINITY, f64::min), c.length);
    }
}
