//! LAR's extraction of 3-cells (Fig. 1, the 2-cell algorithm one dimension up): the δ∂
//! steps on two cubes sharing a face, as docs/LAR.md shows them.

use gmap_homology::lar::{ExtractionStep, Faces};

/// Two unit cubes side by side along x: vertices `0..12` at `(x, y, z)`, x ∈ {0, 1, 2};
/// faces: 0 the common square x = 1, then the other faces of the left cube (1..=5) and of
/// the right one (6..=10).
fn two_cubes() -> Faces {
    let v = |x: u32, y: u32, z: u32| x + 3 * (y + 2 * z);
    let mut points = Vec::new();
    for z in 0..2 {
        for y in 0..2 {
            for x in 0..3 {
                points.push([f64::from(x), f64::from(y), f64::from(z)]);
            }
        }
    }
    let sq = |a, b, c, d| vec![vec![a, b, c, d]];
    let faces = vec![
        sq(v(1, 0, 0), v(1, 1, 0), v(1, 1, 1), v(1, 0, 1)),
        sq(v(0, 0, 0), v(0, 1, 0), v(0, 1, 1), v(0, 0, 1)),
        sq(v(0, 0, 0), v(1, 0, 0), v(1, 1, 0), v(0, 1, 0)),
        sq(v(0, 0, 1), v(1, 0, 1), v(1, 1, 1), v(0, 1, 1)),
        sq(v(0, 0, 0), v(1, 0, 0), v(1, 0, 1), v(0, 0, 1)),
        sq(v(0, 1, 0), v(1, 1, 0), v(1, 1, 1), v(0, 1, 1)),
        sq(v(2, 0, 0), v(2, 1, 0), v(2, 1, 1), v(2, 0, 1)),
        sq(v(1, 0, 0), v(2, 0, 0), v(2, 1, 0), v(1, 1, 0)),
        sq(v(1, 0, 1), v(2, 0, 1), v(2, 1, 1), v(1, 1, 1)),
        sq(v(1, 0, 0), v(2, 0, 0), v(2, 0, 1), v(1, 0, 1)),
        sq(v(1, 1, 0), v(2, 1, 0), v(2, 1, 1), v(1, 1, 1)),
    ];
    Faces::try_new(points, faces).unwrap()
}

fn faces_of(s: &ExtractionStep) -> Vec<(usize, i64)> {
    s.chain.clone()
}

#[test]
fn delta_boundary_steps_on_two_cubes() {
    let f = two_cubes();
    assert_eq!(f.edges().len(), 20);
    // the common square's normal is +x: with σ = +1 it points out of the cell, the cell on
    // its -x side, the left cube
    let steps = f.extraction_steps(0, 1);
    assert_eq!(steps.len(), 3);
    assert_eq!(faces_of(&steps[0]), vec![(0, 1)]);
    assert_eq!(steps[0].boundary.len(), 4);
    // one δ∂ step: the four faces of the left cube on the common square's edges
    assert_eq!(faces_of(&steps[1]).iter().map(|x| x.0).collect::<Vec<_>>(), vec![0, 2, 3, 4, 5]);
    assert_eq!(steps[1].boundary.len(), 4);
    // the second closes the cube with the square x = 0: ∂c = 0
    assert_eq!(faces_of(&steps[2]).iter().map(|x| x.0).collect::<Vec<_>>(), vec![0, 1, 2, 3, 4, 5]);
    assert!(steps[2].boundary.is_empty());
    // exactly, with edges numbered as met: ∂c after each step
    assert_eq!(steps[0].boundary, vec![(0, 1), (1, 1), (2, -1), (3, -1)]);
    assert_eq!(steps[1].chain, vec![(0, 1), (2, -1), (3, 1), (4, 1), (5, -1)]);
    assert_eq!(steps[1].boundary, vec![(4, 1), (5, 1), (6, -1), (7, -1)]);
    assert_eq!(steps[2].chain, vec![(0, 1), (1, -1), (2, -1), (3, 1), (4, 1), (5, -1)]);
    let cells = f.cells().unwrap();
    assert_eq!(cells.cells.len(), 3);
    let mut volumes: Vec<f64> = cells.volumes6.iter().map(|v| v / 6.0).collect();
    volumes.sort_by(f64::total_cmp);
    assert_eq!(volumes, vec![-2.0, 1.0, 1.0]);
    assert_eq!(cells.cells[cells.outer].len(), 10);
    // around an edge of the common square, three faces, in angular order
    let e = f.face_edges(0)[0].0;
    assert_eq!(f.around(e).len(), 3);
}
