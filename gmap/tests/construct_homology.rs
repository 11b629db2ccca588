//! Homology of what the construction operations build ([`gmap::ops::construct`]), through
//! [`gmap::homology`]: the revolved square's boundary is the torus surface (Z, Z², Z), the
//! revolved square face the solid torus (Z, Z, 0, 0); and random sequences of extrusions,
//! triangulations, tetrahedralizations, merges, splits and chamfers of vertices and edges
//! from a hexahedron never change
//! the homology of the ball (Z, 0, 0, 0) — each is a subdivision, its inverse or a
//! collapse.

use gmap::algebra::gmap_homology;
use gmap::core::{DartId, GMap, Point};
use gmap::ops::construct::{self as c, Axis};
use proptest::prelude::*;

fn homology(g: &GMap) -> String {
    gmap_homology(g).expect("the cellular homology's preconditions hold").to_string()
}

const Z: Axis = Axis { origin: [0., 0., 0.], direction: [0., 0., 1.] };

fn square(g: &mut GMap) -> DartId {
    g.make_polygon(&[[2., 0., 0.], [3., 0., 0.], [3., 0., 1.], [2., 0., 1.]])
}

#[test]
fn the_revolved_square_boundary_is_the_torus_surface() {
    let mut g = GMap::new(2);
    let d = square(&mut g);
    c::revolve(&mut g, d, 1, &Z, 8);
    assert_eq!(homology(&g), "(Z, Z^2, Z)");
}

#[test]
fn the_revolved_square_face_is_the_solid_torus() {
    let mut g = GMap::new(3);
    let d = square(&mut g);
    c::revolve(&mut g, d, 2, &Z, 8);
    assert_eq!(homology(&g), "(Z, Z, 0, 0)");
}

const UNIT: [Point; 8] =
    [[0., 0., 0.], [1., 0., 0.], [1., 1., 0.], [0., 1., 0.], [0., 1., 1.], [0., 0., 1.], [1., 0., 1.], [1., 1., 1.]];

#[test]
fn a_hexahedron_extruded_along_a_path_is_still_a_ball() {
    let mut g = GMap::new(3);
    g.make_hexahedron(UNIT);
    let top = g
        .darts()
        .find(|&d| g.orbit(d, gmap::core::AlphaSet::range(0, 1)).iter().all(|&x| g.point(x).unwrap()[2] == 1.0))
        .unwrap();
    let path: Vec<DartId> = (1..5).map(|k| g.make_segment([[9., 9., k as f64], [9., 9., k as f64 + 1.]])).collect();
    c::extrude_cell_along_path(&mut g, top, 2, &path);
    // the path is read only: its segments removed, the five cubes stacked are a ball
    for d in path {
        let e = g.alpha(d, 0);
        g.remove_dart(d);
        g.remove_dart(e);
    }
    assert_eq!(g.characteristics().cells, vec![24, 44, 26, 5]);
    assert_eq!(homology(&g), "(Z, 0, 0, 0)");
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, ..ProptestConfig::default() })]

    #[test]
    fn random_constructions_keep_the_homology_of_the_ball(
        steps in proptest::collection::vec((0usize..7, any::<usize>(), 0usize..3), 1..8)
    ) {
        let mut g = GMap::new(3);
        g.make_hexahedron(UNIT);
        for (op, k, i) in steps {
            let darts: Vec<DartId> = g.darts().collect();
            let d = darts[k % darts.len()];
            let done = match op {
                0 => c::try_extrude_cell(&mut g, d, i, [0., 0., 1.]).is_ok(),
                1 => c::try_triangulate_face_fan(&mut g, d).is_ok(),
                2 => c::try_triangulate_face_barycentric(&mut g, d).is_ok(),
                3 => g.dart_count() < 1500 && c::try_tetrahedralize_volume(&mut g, d).is_ok(),
                4 => c::try_merge_volumes(&mut g, d).is_ok(),
                5 => c::try_chamfer_vertex(&mut g, d, 0.25 + 0.25 * i as f64).is_ok(),
                _ => c::try_chamfer_edge(&mut g, d, 0.25 + 0.25 * i as f64).is_ok(),
            };
            if done {
                prop_assert!(g.validate().is_ok());
                prop_assert_eq!(homology(&g), "(Z, 0, 0, 0)");
            }
        }
    }
}
