//! The linear cell complex: constructors with coordinates, barycentres, transforms and the
//! `.off` writers, checked as properties on random grids and random points.

use gmap::core::{Affine, GMap, Point};
use gmap::ops::build::placed::grid_with_points;
use gmap::ops::export::{gmap_off_string, gmap_two_skeleton_off_string};
use gmap::ops::import::PolygonMesh;
use proptest::prelude::*;

mod common;
use common::{gmap, p, stderr};

fn close(p: Point, q: Point) -> bool {
    (0..3).all(|k| (p[k] - q[k]).abs() <= 1e-9 * (1.0 + p[k].abs().max(q[k].abs())))
}

fn coord() -> impl Strategy<Value = f64> {
    (-1000i32..1000).prop_map(|x| f64::from(x) / 8.0)
}

fn point() -> impl Strategy<Value = [f64; 3]> {
    [coord(), coord(), coord()]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// The unit cubes of a grid have their centres as barycentres, and the mean of those is
    /// the centre of the box.
    #[test]
    fn grid_cells_are_centred_on_half_integers(sizes in prop::collection::vec(1usize..4, 1..=3)) {
        let d = sizes.len();
        let dense = grid_with_points(&sizes, &vec![false; d]).unwrap();
        let (g, _) = GMap::from_dense(&dense);
        let mut sum = [0.0; 3];
        let mut count = 0.0;
        for c in g.one_dart_per_cell(d) {
            let b = g.barycenter(c, d).unwrap();
            for k in 0..3 {
                let want_half = k < d;
                prop_assert_eq!((b[k] * 2.0) as i64 % 2 != 0, want_half, "{:?}", b);
                sum[k] += b[k];
            }
            count += 1.0;
        }
        let centre: Point = [0, 1, 2].map(|k| if k < d { sizes[k] as f64 / 2.0 } else { 0.0 });
        prop_assert_eq!(sum.map(|s| s / count), centre);
        prop_assert_eq!(g.bounding_box(), Some([[0.0; 3], [0, 1, 2].map(|k| if k < d { sizes[k] as f64 } else { 0.0 })]));
    }

    /// Translating a cell translates its barycentre; an affine map applied to the whole map
    /// moves every barycentre by the same map (barycentres are affine combinations).
    #[test]
    fn barycentres_follow_affine_maps(p in prop::array::uniform8(point()), v in point(), angle in -3.0f64..3.0, i in 0usize..=3) {
        let mut g = GMap::new(3);
        let d = g.make_hexahedron(p);
        let before = g.barycenter(d, i).unwrap();
        g.translate_cell(d, i, v);
        let moved = g.barycenter(d, i).unwrap();
        prop_assert!(close(moved, [before[0] + v[0], before[1] + v[1], before[2] + v[2]]), "{:?} {:?}", moved, before);
        let a = Affine::rotation_z(angle).then_after(&Affine::translation(v));
        let cells: Vec<Point> = (0..=3).map(|j| g.barycenter(d, j).unwrap()).collect();
        g.transform(|q| a.apply(q));
        for (j, b) in cells.into_iter().enumerate() {
            prop_assert!(close(g.barycenter(d, j).unwrap(), a.apply(b)));
        }
        g.validate().unwrap();
    }

    /// The `.off` of a planar grid reads back as a map with the same cells; the 2-skeleton of
    /// a 3D grid lists each of its faces once.
    #[test]
    fn off_texts_of_grids(a in 1usize..4, b in 1usize..4, c in 1usize..3) {
        let (g, _) = GMap::from_dense(&grid_with_points(&[a, b], &[false, false]).unwrap());
        let back = PolygonMesh::parse(&gmap_off_string(&g).unwrap()).unwrap().to_gmap().unwrap();
        prop_assert_eq!(back.cell_counts(), g.cell_counts()[..3].to_vec());
        let (h, _) = GMap::from_dense(&grid_with_points(&[a, b, c], &[false; 3]).unwrap());
        let text = gmap_two_skeleton_off_string(&h).unwrap();
        let counts = h.cell_counts();
        prop_assert_eq!(text.lines().nth(1).unwrap().to_string(), format!("{} {} 0", counts[0], counts[2]));
        prop_assert_eq!(text.lines().count(), 2 + counts[0] + counts[2]);
    }
}

/// A 3-map with points written as `.off` through `gmap convert` is refused, not flattened to
/// its faces (the 2-skeleton view is a library function, never a conversion); its faces are
/// still available as that view.
#[test]
fn convert_refuses_a_solid_to_off() {
    let dir = tempfile::tempdir().unwrap();
    let cube = gmap::ops::build::placed::cube_with_points(3).unwrap();
    let src = dir.path().join("cube.gmap");
    std::fs::write(&src, gmap::core::io::format_gmap(&cube)).unwrap();
    let out = dir.path().join("cube.off");
    let o = gmap(&["convert", p(&src), p(&out)]);
    assert!(!o.status.success());
    assert!(stderr(&o).contains("dimension 3"), "{}", stderr(&o));
    assert!(!out.exists());
    let (g, _) = GMap::from_dense(&cube);
    assert_eq!(gmap_two_skeleton_off_string(&g).unwrap().lines().nth(1), Some("8 6 0"));
}
