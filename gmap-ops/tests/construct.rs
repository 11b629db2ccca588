//! The construction operations ([`gmap_ops::construct`]): exact cell counts, points and
//! Euler characteristic changes on small shapes; refusals with their typed errors; and a
//! property test on random sequences checking validity, the stated Δχ and the attributes
//! (the fixtures of `gmap-core/tests/attr_common`).

#[path = "../../gmap-core/tests/attr_common/mod.rs"]
mod attr_common;

use attr_common::{count, fill, Full};
use gmap_core::{Attributes, DartId, GMap, Point};
use gmap_ops::construct::{self as c, Axis, ConstructError};
use proptest::prelude::*;

fn chi<A: Attributes>(g: &GMap<A>) -> i64 {
    g.characteristics().cells.iter().enumerate().map(|(i, &n)| if i % 2 == 0 { n as i64 } else { -(n as i64) }).sum()
}

fn cells<A: Attributes>(g: &GMap<A>) -> Vec<usize> {
    let ch = g.characteristics();
    assert!(ch.valid, "{ch}");
    ch.cells
}

const UNIT: [Point; 8] =
    [[0., 0., 0.], [1., 0., 0.], [1., 1., 0.], [0., 1., 0.], [0., 1., 1.], [0., 0., 1.], [1., 0., 1.], [1., 1., 1.]];

/// A dart of the face of the hexahedron made by `make_hexahedron(UNIT)` at z = 1.
fn top_face<A: Attributes>(g: &GMap<A>) -> DartId {
    g.darts()
        .find(|&d| g.orbit(d, gmap_core::AlphaSet::range(0, 1)).iter().all(|&x| g.point(x).unwrap()[2] == 1.0))
        .expect("a face at z = 1")
}

#[test]
fn a_face_extruded_gives_a_second_hexahedron_on_top() {
    let mut g = GMap::new(3);
    g.make_hexahedron(UNIT);
    let before = chi(&g);
    let f = top_face(&g);
    assert!(c::can_extrude_face(&g, f));
    let e = c::extrude_face(&mut g, f, [0., 0., 2.]);
    assert_eq!(e.euler_change, 0);
    assert_eq!(chi(&g), before);
    assert_eq!(cells(&g), vec![12, 20, 11, 2]);
    assert_eq!(g.point_count(), 12);
    assert_eq!(g.barycenter(e.cell, 3), Some([0.5, 0.5, 2.0]));
    assert_eq!(g.barycenter(e.top, 2), Some([0.5, 0.5, 3.0]));
    assert_eq!(g.alpha(f, 3), e.cell);
    // the face is no longer free: a second extrusion from it is refused
    assert_eq!(c::try_extrude_face(&mut g, f, [0., 0., 1.]), Err(ConstructError::NotFree { dart: f, alpha: 3 }));
    g.validate().unwrap();
}

#[test]
fn an_edge_extruded_gives_a_quadrangle_and_a_vertex_an_edge() {
    let mut g = GMap::new(2);
    let d = g.make_polygon(&[[0., 0.], [1., 0.], [1., 1.], [0., 1.]]);
    let e = c::extrude_edge(&mut g, d, [0., -1., 0.]);
    assert_eq!((cells(&g), chi(&g), e.euler_change), (vec![6, 7, 2], 1, 0));
    assert_eq!(g.barycenter(e.cell, 2), Some([0.5, -0.5, 0.0]));
    let mut h = GMap::new(2);
    let s = h.make_segment([[0., 0.], [1., 0.]]);
    let v = c::extrude_vertex(&mut h, s, [-1., 0., 0.]);
    assert_eq!((cells(&h), chi(&h)), (vec![3, 2, 1], 2));
    assert_eq!(h.point(h.alpha(v.cell, 0)), Some([-1., 0., 0.]));
    // a vertex inside a polygon is not 1-free
    assert_eq!(c::try_extrude_vertex(&mut g, d, [1., 0., 0.]), Err(ConstructError::NotFree { dart: d, alpha: 1 }));
    // no cell of dimension n can be extruded
    assert!(matches!(c::try_extrude_cell(&mut g, d, 2, [0.; 3]), Err(ConstructError::BadDimension { got: 2, .. })));
    assert!(matches!(c::try_extrude_edge(&mut g, d, [f64::NAN, 0., 0.]), Err(ConstructError::BadParameter { .. })));
}

#[test]
fn a_face_extruded_along_a_path_stacks_one_volume_per_edge() {
    let mut g = GMap::new(3);
    let f = g.make_quadrangle([[0., 0.], [1., 0.], [1., 1.], [0., 1.]]);
    // a polyline of three edges drawn apart: up, up, sideways
    let path: Vec<DartId> = [([5., 5., 0.], [5., 5., 1.]), ([5., 5., 1.], [5., 5., 3.]), ([5., 5., 3.], [6., 5., 3.])]
        .into_iter()
        .map(|(p, q)| g.make_segment([p, q]))
        .collect();
    let before = chi(&g);
    assert!(c::can_extrude_cell_along_path(&g, f, 2, &path));
    let steps = c::extrude_cell_along_path(&mut g, f, 2, &path);
    assert_eq!(steps.len(), 3);
    assert_eq!(chi(&g), before);
    let last = steps.last().unwrap();
    assert_eq!(g.barycenter(last.top, 2), Some([1.5, 0.5, 3.0]));
    assert_eq!(g.barycenter(steps[1].cell, 3), Some([0.5, 0.5, 2.0]));
    // quadrangle + 3 hexahedra stacked (4 + 3·4 vertices) + 3 segments (6 vertices)
    assert_eq!(cells(&g)[0], 16 + 6);
    assert_eq!(cells(&g)[3], 1 + 3 + 3);
    let lone = g.make_segment([[0., 0.], [1., 0.]]);
    g.unlink(lone, 0);
    assert_eq!(
        c::try_extrude_cell_along_path(&mut g, last.top, 2, &[lone]),
        Err(ConstructError::BadShape { dart: lone, what: "an edge with two ends" })
    );
}

/// The square `[2, 3] × {0} × [0, 1]` in the xz-plane, as a polygon of the map.
fn square<A: Attributes>(g: &mut GMap<A>) -> DartId {
    g.make_polygon(&[[2., 0., 0.], [3., 0., 0.], [3., 0., 1.], [2., 0., 1.]])
}

const Z: Axis = Axis { origin: [0., 0., 0.], direction: [0., 0., 1.] };

#[test]
fn the_boundary_of_a_square_revolved_is_a_torus() {
    let mut g = GMap::new(2);
    let d = square(&mut g);
    assert_eq!(chi(&g), 1);
    let r = c::revolve(&mut g, d, 1, &Z, 8);
    assert_eq!(r.euler_change, -1);
    let ch = g.characteristics();
    assert_eq!(ch.cells, vec![32, 64, 32]);
    assert!(ch.valid && ch.orientable && ch.components == 1, "{ch}");
    assert_eq!(chi(&g), 0);
    // closed: no free dart
    assert!(g.darts().all(|x| (0..=2).all(|i| !g.is_free(x, i))));
    assert_eq!(g.point_count(), 32);
    // the wall a quarter turn on lies in the yz-plane
    let q = g.point(r.walls[2]).unwrap();
    assert!(q[0].abs() < 1e-12 && (q[1] - 2.0).abs() < 1e-12, "{q:?}");
}

#[test]
fn the_square_face_revolved_is_a_solid_torus() {
    let mut g = GMap::new(3);
    let d = square(&mut g);
    assert_eq!(chi(&g), 0);
    let r = c::revolve(&mut g, d, 2, &Z, 6);
    assert_eq!(r.euler_change, 0);
    let ch = g.characteristics();
    assert_eq!(ch.cells, vec![24, 48, 30, 6]);
    assert!(ch.valid && ch.orientable && ch.components == 1, "{ch}");
    // the boundary (3-free darts) is the torus surface: 4 quads per step
    assert_eq!(g.darts().filter(|&x| g.is_free(x, 3)).count(), 6 * 4 * 8);
}

#[test]
fn revolutions_are_refused_with_the_reason() {
    let mut g = GMap::new(3);
    let d = square(&mut g);
    assert_eq!(c::try_revolve(&mut g, d, 2, &Z, 2), Err(ConstructError::TooFewSteps { min: 3, got: 2 }));
    let flat = Axis { origin: [0.; 3], direction: [0.; 3] };
    assert_eq!(c::try_revolve(&mut g, d, 2, &flat, 4), Err(ConstructError::BadAxis([0.; 3])));
    assert!(matches!(c::try_revolve(&mut g, d, 3, &Z, 4), Err(ConstructError::BadDimension { got: 3, .. })));
    let h = g.make_hexahedron(UNIT);
    // a face of a hexahedron is not a component of dimension 1
    assert!(matches!(c::try_revolve(&mut g, h, 1, &Z, 4), Err(ConstructError::NotFree { alpha: 2, .. })));
    let e = g.make_combinatorial_polygon(3);
    assert!(matches!(c::try_revolve(&mut g, e, 1, &Z, 4), Err(ConstructError::NoPoint(_))));
    assert_eq!(g.characteristics().cells, vec![4 + 8 + 3, 4 + 12 + 3, 1 + 6 + 1, 3]);
}

#[test]
fn faces_triangulated_by_a_fan_and_around_the_barycentre() {
    let hexagon: Vec<[f64; 2]> = (0..6)
        .map(|k| {
            let t = std::f64::consts::TAU * k as f64 / 6.0;
            [t.cos(), t.sin()]
        })
        .collect();
    let mut g = GMap::new(2);
    let d = g.make_polygon(&hexagon);
    assert_eq!(c::triangulate_face_fan(&mut g, d), 3);
    assert_eq!((cells(&g), chi(&g)), (vec![6, 9, 4], 1));
    assert!(g.darts().all(|x| g.orbit(x, gmap_core::AlphaSet::range(0, 1)).len() == 6));
    let mut h = GMap::new(2);
    let d = h.make_polygon(&hexagon);
    let v = c::triangulate_face_barycentric(&mut h, d);
    assert_eq!((cells(&h), chi(&h)), (vec![7, 12, 6], 1));
    let p = h.point(v).unwrap();
    assert!(p.iter().all(|x| x.abs() < 1e-12), "{p:?}");
    let mut s = GMap::new(2);
    let e = s.make_segment([[0., 0.], [1., 0.]]);
    assert!(!c::can_triangulate_face_fan(&s, e));
}

#[test]
fn a_hexahedron_tetrahedralized_is_twelve_tetrahedra() {
    let mut g = GMap::new(3);
    let d = g.make_hexahedron(UNIT);
    assert!(c::can_tetrahedralize_volume(&g, d));
    let v = c::tetrahedralize_volume(&mut g, d);
    assert_eq!(g.point(v), Some([0.5, 0.5, 0.5]));
    // 9 vertices; 12 + 6 diagonals + 8 spokes; 12 outer triangles + 18 inner; 12 tetrahedra
    assert_eq!((cells(&g), chi(&g)), (vec![9, 26, 30, 12], 1));
    assert!(g.darts().all(|x| g.orbit(x, gmap_core::AlphaSet::range(0, 2)).len() == 24));
}

#[test]
fn volumes_split_by_a_loop_and_merged_back() {
    let mut g = GMap::new(3);
    g.make_hexahedron(UNIT);
    let f = top_face(&g);
    // one dart per edge of the top face, all in the top face
    let path = [f, g.alpha_word(f, &[0, 1]), g.alpha_word(f, &[0, 1, 0, 1]), g.alpha_word(f, &[0, 1, 0, 1, 0, 1])];
    assert!(c::can_split_volume(&g, &path));
    let new = c::split_volume(&mut g, &path);
    assert_eq!((cells(&g), chi(&g)), (vec![8, 12, 7, 2], 1));
    assert!(c::can_merge_volumes(&g, new));
    c::merge_volumes(&mut g, new);
    assert_eq!((cells(&g), chi(&g)), (vec![8, 12, 6, 1], 1));
    // a boundary face separates nothing
    assert!(!c::can_merge_volumes(&g, f));
    assert!(matches!(c::try_merge_volumes(&mut g, f), Err(ConstructError::Euler(_))));
}

#[test]
fn a_corner_of_a_cube_surface_chamfered_becomes_a_triangle() {
    // the surface of a cube as a 2-map: a hexahedron in dimension 2
    let mut g = GMap::new(2);
    let d = g.make_hexahedron(UNIT);
    assert_eq!(cells(&g), vec![8, 12, 6]);
    assert!(c::can_chamfer_vertex(&g, d, 0.25));
    let f = c::chamfer_vertex(&mut g, d, 0.25);
    assert_eq!((cells(&g), chi(&g)), (vec![10, 15, 7], 2));
    // the new face is a triangle with its corners a quarter along the cube's edges
    let face = g.orbit(f, gmap_core::AlphaSet::range(0, 1));
    assert_eq!(face.len(), 6);
    let mut corners: Vec<Point> = face.iter().map(|&x| g.point(x).unwrap()).collect();
    corners.sort_by(|a, b| a.partial_cmp(b).unwrap());
    corners.dedup();
    assert_eq!(corners, vec![[0., 0., 0.25], [0., 0.25, 0.], [0.25, 0., 0.]]);
    g.validate().unwrap();
    assert_eq!(
        c::try_chamfer_vertex(&mut g, f, 1.5),
        Err(ConstructError::BadParameter { what: "chamfer fraction", value: 1.5 })
    );
    // chamfers work on surfaces and on the boundary of volumes, not in dimension 4
    let mut h = GMap::new(4);
    let e = h.make_hexahedron(UNIT);
    assert!(matches!(c::try_chamfer_vertex(&mut h, e, 0.5), Err(ConstructError::BadDimension { .. })));
}

/// The corners of the face of `f`, sorted, without repeats.
fn face_points<A: Attributes>(g: &GMap<A>, f: DartId) -> Vec<Point> {
    let mut corners: Vec<Point> =
        g.orbit(f, gmap_core::AlphaSet::range(0, 1)).iter().map(|&x| g.point(x).unwrap()).collect();
    corners.sort_by(|a, b| a.partial_cmp(b).unwrap());
    corners.dedup();
    corners
}

#[test]
fn an_edge_of_a_cube_chamfered_becomes_a_quadrangle() {
    // the surface (dimension 2) and the solid (dimension 3): the same bevel, Δχ = 0
    for (dim, before, after) in [(2, vec![8, 12, 6], vec![10, 15, 7]), (3, vec![8, 12, 6, 1], vec![10, 15, 7, 1])] {
        let mut g = GMap::new(dim);
        // the dart at (0,0,0) on the edge to (0,0,1)
        let d = g.make_hexahedron(UNIT);
        assert_eq!(cells(&g), before);
        let chi0 = chi(&g);
        assert!(c::can_chamfer_edge(&g, d, 0.25));
        let f = c::chamfer_edge(&mut g, d, 0.25);
        assert_eq!((cells(&g), chi(&g)), (after, chi0));
        g.validate().unwrap();
        // the new face: a quadrangle with its corners a quarter along the four other edges
        assert_eq!(g.orbit(f, gmap_core::AlphaSet::range(0, 1)).len(), 8);
        assert_eq!(face_points(&g, f), vec![[0., 0.25, 0.], [0., 0.25, 1.], [0.25, 0., 0.], [0.25, 0., 1.]]);
        // an edge of the new face ends at vertices of degree 3: chamfered in turn
        assert!(c::can_chamfer_edge(&g, f, 0.5));
        c::chamfer_edge(&mut g, f, 0.5);
        assert_eq!(chi(&g), chi0);
        g.validate().unwrap();
    }
}

#[test]
fn a_corner_of_a_solid_cube_chamfered_becomes_a_triangle() {
    let mut g = GMap::new(3);
    let d = g.make_hexahedron(UNIT);
    assert!(c::can_chamfer_vertex(&g, d, 0.25));
    let f = c::chamfer_vertex(&mut g, d, 0.25);
    assert_eq!((cells(&g), chi(&g)), (vec![10, 15, 7, 1], 1));
    assert_eq!(face_points(&g, f), vec![[0., 0., 0.25], [0., 0.25, 0.], [0.25, 0., 0.]]);
    g.validate().unwrap();
}

#[test]
fn chamfers_refuse_with_the_reason() {
    // two cubes sewn: the shared face's vertices are not on the boundary of one volume
    let mut g = GMap::new(3);
    let a = g.make_hexahedron(UNIT);
    let b = g.make_hexahedron(UNIT.map(|p| [p[0], p[1], p[2] + 1.]));
    let top = top_face(&g);
    let bottom = g
        .darts()
        .find(|&x| {
            g.orbit(x, gmap_core::AlphaSet::range(0, 2)).contains(&b)
                && g.orbit(x, gmap_core::AlphaSet::range(0, 1)).iter().all(|&y| g.point(y).unwrap()[2] == 1.0)
        })
        .unwrap();
    let (p, q) = (g.point(top).unwrap(), g.point(g.alpha(top, 0)).unwrap());
    let partner = g
        .orbit(bottom, gmap_core::AlphaSet::range(0, 1))
        .into_iter()
        .find(|&y| g.point(y) == Some(p) && g.point(g.alpha(y, 0)) == Some(q))
        .unwrap();
    g.sew(top, partner, 3);
    let before = cells(&g);
    assert!(!c::can_chamfer_vertex(&g, top, 0.25));
    assert!(matches!(c::try_chamfer_vertex(&mut g, top, 0.25), Err(ConstructError::BadShape { .. })));
    assert!(matches!(c::try_chamfer_edge(&mut g, top, 0.25), Err(ConstructError::BadShape { .. })));
    assert_eq!(
        c::try_chamfer_edge(&mut g, a, 0.0),
        Err(ConstructError::BadParameter { what: "chamfer fraction", value: 0.0 })
    );
    assert_eq!(cells(&g), before);
    // an edge whose end has degree 4: the centre of a face triangulated around it
    let mut s = GMap::new(2);
    s.make_hexahedron(UNIT);
    let top = top_face(&s);
    let centre = c::triangulate_face_barycentric(&mut s, top);
    assert!(!c::can_chamfer_edge(&s, centre, 0.25));
    assert!(matches!(c::try_chamfer_edge(&mut s, centre, 0.25), Err(ConstructError::BadShape { .. })));
    let mut line = GMap::new(1);
    let e = line.make_segment([[0., 0., 0.], [1., 0., 0.]]);
    assert!(matches!(c::try_chamfer_edge(&mut line, e, 0.5), Err(ConstructError::BadDimension { .. })));
}

#[test]
fn only_convex_volumes_are_tetrahedralized() {
    // a frustum: convex, with its top smaller
    let mut g = GMap::new(3);
    let frustum = UNIT.map(|p| if p[2] == 1. { [0.25 + 0.5 * p[0], 0.25 + 0.5 * p[1], 1.] } else { p });
    let d = g.make_hexahedron(frustum);
    assert!(c::can_tetrahedralize_volume(&g, d));
    c::tetrahedralize_volume(&mut g, d);
    assert_eq!((cells(&g), chi(&g)), (vec![9, 26, 30, 12], 1));
    // the corner (1,1,1) pushed in to (0.6,0.6,0.6): not convex, refused naming the volume
    let mut h = GMap::new(3);
    let dented = UNIT.map(|p| if p == [1., 1., 1.] { [0.6, 0.6, 0.6] } else { p });
    let v = h.make_hexahedron(dented);
    assert!(!c::can_tetrahedralize_volume(&h, v));
    match c::try_tetrahedralize_volume(&mut h, v) {
        Err(ConstructError::NotConvex { volume, .. }) => assert_eq!(volume, v),
        other => panic!("{other:?}"),
    }
    assert_eq!(cells(&h), vec![8, 12, 6, 1]);
    // a flat hexahedron (every corner at z = 0) is not a convex volume either
    let mut k = GMap::new(3);
    let w = k.make_hexahedron(UNIT.map(|p| [p[0] + p[2], p[1], 0.]));
    assert!(matches!(c::try_tetrahedralize_volume(&mut k, w), Err(ConstructError::NotConvex { .. })));
}

/// One random construction step; the numbers pick darts among the live ones.
#[derive(Clone, Debug)]
enum Step {
    Extrude(usize, usize, [i8; 3]),
    Fan(usize),
    Barycentric(usize),
    Tetrahedralize(usize),
    Merge(usize),
    Split(usize),
    ChamferVertex(usize, u8),
    ChamferEdge(usize, u8),
}

fn step() -> impl Strategy<Value = Step> {
    let p = any::<usize>();
    let v = [-2i8..=2, -2i8..=2, -2i8..=2];
    prop_oneof![
        3 => (p, 0usize..3, v).prop_map(|(a, i, v)| Step::Extrude(a, i, v)),
        2 => p.prop_map(Step::Fan),
        2 => p.prop_map(Step::Barycentric),
        1 => p.prop_map(Step::Tetrahedralize),
        2 => p.prop_map(Step::Merge),
        1 => p.prop_map(Step::Split),
        2 => (p, 1u8..9).prop_map(|(a, t)| Step::ChamferVertex(a, t)),
        2 => (p, 1u8..9).prop_map(|(a, t)| Step::ChamferEdge(a, t)),
    ]
}

/// Applies a step when its predicate allows it, checking that predicate and `try_` agree;
/// returns the stated Δχ of an applied step.
fn apply(g: &mut Full, s: &Step) -> Option<i64> {
    let darts: Vec<DartId> = g.darts().collect();
    let pick = |k: usize| darts[k % darts.len()];
    match *s {
        Step::Extrude(a, i, v) => {
            let d = pick(a);
            let ok = c::can_extrude_cell(g, d, i);
            let r = c::try_extrude_cell(g, d, i, v.map(f64::from));
            assert_eq!(ok, r.is_ok(), "{r:?}");
            r.ok().map(|e| e.euler_change)
        }
        Step::Fan(a) => {
            let d = pick(a);
            let ok = c::can_triangulate_face_fan(g, d);
            // a polygon with a repeated corner may pass the predicate and be refused by an
            // edge insertion, before any change
            let r = c::try_triangulate_face_fan(g, d);
            assert!(ok || r.is_err());
            r.ok().map(|_| 0)
        }
        Step::Barycentric(a) => {
            let d = pick(a);
            let ok = c::can_triangulate_face_barycentric(g, d);
            let r = c::try_triangulate_face_barycentric(g, d);
            assert_eq!(ok, r.is_ok(), "{r:?}");
            r.ok().map(|_| 0)
        }
        Step::Tetrahedralize(a) => {
            let d = pick(a);
            if !c::can_tetrahedralize_volume(g, d) || g.dart_count() > 2000 {
                return None;
            }
            c::try_tetrahedralize_volume(g, d).ok().map(|_| 0)
        }
        Step::Merge(a) => {
            let d = pick(a);
            let ok = c::can_merge_volumes(g, d);
            let r = c::try_merge_volumes(g, d);
            assert_eq!(ok, r.is_ok(), "{r:?}");
            r.ok().map(|_| 0)
        }
        Step::ChamferVertex(a, t) => {
            let (d, t) = (pick(a), f64::from(t) / 10.0);
            let ok = c::can_chamfer_vertex(g, d, t);
            let r = c::try_chamfer_vertex(g, d, t);
            assert_eq!(ok, r.is_ok(), "{r:?}");
            r.ok().map(|_| 0)
        }
        Step::ChamferEdge(a, t) => {
            let (d, t) = (pick(a), f64::from(t) / 10.0);
            let ok = c::can_chamfer_edge(g, d, t);
            let r = c::try_chamfer_edge(g, d, t);
            assert_eq!(ok, r.is_ok(), "{r:?}");
            r.ok().map(|_| 0)
        }
        Step::Split(a) => {
            // the loop around a face of a volume
            let f = pick(a);
            let path = face_loop(g, f)?;
            let ok = c::can_split_volume(g, &path);
            let r = c::try_split_volume(g, &path);
            assert_eq!(ok, r.is_ok(), "{r:?}");
            r.ok().map(|_| 0)
        }
    }
}

/// One dart per edge of the face of `f`, on the side of `f`, when it is a closed polygon.
fn face_loop(g: &Full, f: DartId) -> Option<Vec<DartId>> {
    let mut out = vec![f];
    let mut x = f;
    loop {
        let y = g.alpha(x, 0);
        let z = g.alpha(y, 1);
        if y == x || z == y || out.len() > 64 {
            return None;
        }
        if z == f {
            return Some(out);
        }
        out.push(z);
        x = z;
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, ..ProptestConfig::default() })]

    /// Random construction sequences from a hexahedron with an attribute on every cell and
    /// a point on every vertex: every step keeps the map valid with one attribute per cell
    /// and one point per vertex, and changes χ by what it states (0 for these).
    #[test]
    fn random_constructions_keep_the_map_and_its_attributes(steps in proptest::collection::vec(step(), 1..10)) {
        let mut g = Full::with_attributes(3);
        g.make_hexahedron(UNIT);
        let mut next = 0;
        fill(&mut g, &mut next);
        for s in &steps {
            let before = chi(&g);
            if let Some(dchi) = apply(&mut g, s) {
                prop_assert!(g.validate().is_ok(), "{s:?}: {:?}", g.validate());
                prop_assert_eq!(chi(&g) - before, dchi, "{:?}", s);
                // every vertex has a point: the constructions place every vertex they make
                prop_assert!(g.darts().all(|x| g.point(x).is_some()), "{:?}", s);
                fill(&mut g, &mut next);
                let ch = g.characteristics();
                for i in 0..=3 {
                    prop_assert_eq!(count(&g, i), ch.cells[i]);
                }
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, ..ProptestConfig::default() })]

    /// Random chamfers (of vertices and edges) and triangulations of the cube's surface (a 2-map with an attribute
    /// on every cell and a point on every vertex): valid, χ = 2 throughout, one attribute
    /// per cell and one point per vertex.
    #[test]
    fn random_chamfers_keep_the_sphere_and_its_attributes(
        steps in proptest::collection::vec((0usize..4, any::<usize>(), 1u8..9), 1..8)
    ) {
        let mut g = Full::with_attributes(2);
        g.make_hexahedron(UNIT);
        let mut next = 0;
        fill(&mut g, &mut next);
        for (op, k, t) in steps {
            let darts: Vec<DartId> = g.darts().collect();
            let d = darts[k % darts.len()];
            let done = match op {
                0 => {
                    let t = f64::from(t) / 10.0;
                    let ok = c::can_chamfer_vertex(&g, d, t);
                    let r = c::try_chamfer_vertex(&mut g, d, t);
                    prop_assert_eq!(ok, r.is_ok(), "{:?}", r);
                    ok
                }
                1 => {
                    let t = f64::from(t) / 10.0;
                    let ok = c::can_chamfer_edge(&g, d, t);
                    let r = c::try_chamfer_edge(&mut g, d, t);
                    prop_assert_eq!(ok, r.is_ok(), "{:?}", r);
                    ok
                }
                2 => c::try_triangulate_face_fan(&mut g, d).is_ok(),
                _ => c::try_triangulate_face_barycentric(&mut g, d).is_ok(),
            };
            if done {
                prop_assert!(g.validate().is_ok(), "{:?}", g.validate());
                prop_assert_eq!(chi(&g), 2);
                prop_assert!(g.darts().all(|x| g.point(x).is_some()));
                fill(&mut g, &mut next);
                let ch = g.characteristics();
                for i in 0..=2 {
                    prop_assert_eq!(count(&g, i), ch.cells[i]);
                }
            }
        }
    }
}
