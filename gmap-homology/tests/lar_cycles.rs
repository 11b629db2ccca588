//! LAR cycle extraction: the worked example of the paper ("Extraction of a 2-cell", steps
//! (a)–(e)), the faces of planar arrangements against the same arrangements built as
//! 2-maps, and the refusals.

use gmap_core::{Dart, DenseMap};
use gmap_homology::lar::{ArrangementError, PlanarGraph, Stripe};
use gmap_homology::{cellular_complex, homology_z};
use gmap_ops::import::off::PolygonMesh;
use proptest::prelude::*;

/// The 1-complex of the paper's Figure 3 is only a picture; this plane graph reproduces
/// every value the worked example states: `δv12 = e10 + e11 + e12 + e13`,
/// `δv11 = e12 + e14 + e15 + e16 + e17`, the edges `e10 = v12 v15`, `e12 = v11 v12`,
/// `e17 = v11 v14`, `e7`, `e8` meeting at `v13`, and the cyclic orders that make the
/// stripes pick `e10`, `e17`, then `e7`, `e8`. The pentagon `v11 v12 v15 v13 v14` sits
/// in a square `v0 v1 v2 v3` cut into twelve faces in all.
fn figure3() -> (Vec<[i32; 2]>, Vec<[u32; 2]>) {
    let points = vec![
        [-3, -3], // v0
        [5, -3],  // v1
        [5, 5],   // v2
        [-3, 5],  // v3
        [1, 5],   // v4
        [-3, 0],  // v5
        [5, 0],   // v6
        [-2, 0],  // v7
        [-1, -2], // v8
        [2, -2],  // v9
        [4, 0],   // v10
        [0, 0],   // v11
        [2, 0],   // v12
        [1, 3],   // v13
        [-1, 2],  // v14
        [3, 2],   // v15
    ];
    let edges = vec![
        [0, 1],   // e0
        [1, 6],   // e1
        [2, 6],   // e2
        [2, 4],   // e3
        [3, 4],   // e4
        [3, 5],   // e5
        [0, 5],   // e6
        [13, 15], // e7
        [13, 14], // e8
        [4, 13],  // e9
        [12, 15], // e10
        [9, 12],  // e11
        [11, 12], // e12
        [10, 12], // e13
        [7, 11],  // e14
        [8, 11],  // e15
        [9, 11],  // e16
        [11, 14], // e17
        [7, 14],  // e18
        [10, 15], // e19
        [7, 8],   // e20
        [8, 9],   // e21
        [9, 10],  // e22
        [5, 7],   // e23
        [6, 10],  // e24
        [0, 8],   // e25
        [1, 9],   // e26
    ];
    (points, edges)
}

/// The twelve faces of [`figure3`], written down from the drawing (not extracted).
fn figure3_faces() -> Vec<Vec<u32>> {
    vec![
        vec![0, 8, 7, 5],
        vec![1, 6, 10, 9],
        vec![0, 1, 9, 8],
        vec![3, 5, 7, 14, 13, 4],
        vec![4, 13, 15, 10, 6, 2],
        vec![12, 10, 15],
        vec![11, 9, 12],
        vec![11, 8, 9],
        vec![11, 7, 8],
        vec![12, 9, 10],
        vec![11, 14, 7],
        vec![11, 12, 15, 13, 14],
    ]
}

/// A vertex cycle up to rotation and reversal: the smallest of its rotations and of the
/// rotations of its reverse.
fn normal(c: &[u32]) -> Vec<u32> {
    let rotations = |c: &[u32]| (0..c.len()).map(|k| [&c[k..], &c[..k]].concat()).collect::<Vec<_>>();
    let mut r: Vec<u32> = c.to_vec();
    r.reverse();
    rotations(c).into_iter().chain(rotations(&r)).min().expect("a cycle has a vertex")
}

fn normals(cs: &[Vec<u32>]) -> Vec<Vec<u32>> {
    let mut out: Vec<Vec<u32>> = cs.iter().map(|c| normal(c)).collect();
    out.sort();
    out
}

/// The 2-map of polygons over integer points (through the `.off` importer).
fn two_map(points: &[[i32; 2]], polygons: &[Vec<u32>]) -> DenseMap {
    let mesh = PolygonMesh {
        points: points.iter().map(|p| [f64::from(p[0]), f64::from(p[1]), 0.0]).collect(),
        polygons: polygons.to_vec(),
        lines: vec![0; polygons.len()],
    };
    mesh.to_gmap().expect("polygons of a plane arrangement import")
}

/// The vertex cycle of every face of a 2-map: from a dart, `alpha_0` then `alpha_1` until
/// back, reading each dart's point as a vertex number.
fn map_faces(m: &DenseMap, points: &[[i32; 2]]) -> Vec<Vec<u32>> {
    let vertex = |d: Dart| {
        let p = m.point(d).expect("imported darts carry points");
        points.iter().position(|q| f64::from(q[0]) == p[0] && f64::from(q[1]) == p[1]).expect("a known point") as u32
    };
    m.cells(2)
        .reps
        .iter()
        .map(|&start| {
            let mut cycle = Vec::new();
            let mut d = start;
            loop {
                cycle.push(vertex(d));
                d = m.alpha(m.alpha(d, 0), 1);
                if d == start {
                    break;
                }
            }
            cycle
        })
        .collect()
}

/// The edges of polygons, each once.
fn edges_of(polygons: &[Vec<u32>]) -> Vec<[u32; 2]> {
    let mut e: Vec<[u32; 2]> = polygons
        .iter()
        .flat_map(|p| (0..p.len()).map(move |j| [p[j].min(p[(j + 1) % p.len()]), p[j].max(p[(j + 1) % p.len()])]))
        .collect();
    e.sort_unstable();
    e.dedup();
    e
}

#[test]
fn paper_worked_example_step_by_step() {
    let (points, edges) = figure3();
    let g = PlanarGraph::try_new(points, edges).unwrap();
    // (b): the coboundaries of the two ends of e12
    let mut d12 = g.coboundary(12).unwrap();
    d12.sort();
    assert_eq!(d12, vec![10, 11, 12, 13]);
    let mut d11 = g.coboundary(11).unwrap();
    d11.sort();
    assert_eq!(d11, vec![12, 14, 15, 16, 17]);
    assert_eq!(g.coboundary(16), None);
    let steps = g.stripes(12, true).unwrap();
    assert_eq!(
        steps,
        vec![
            // (a) c = e12, ∂c = v12 - v11
            Stripe { chain: vec![(12, 1)], boundary: vec![(11, -1), (12, 1)] },
            // (c) c = e10 + e12 - e17, ∂c = v15 - v14
            Stripe { chain: vec![(10, 1), (12, 1), (17, -1)], boundary: vec![(14, -1), (15, 1)] },
            // (d)-(e) c = e10 + e12 - e17 - e7 + e8, ∂c = 0
            Stripe { chain: vec![(7, -1), (8, 1), (10, 1), (12, 1), (17, -1)], boundary: vec![] },
        ]
    );
    // the same 2-cell is a column of the extracted ∂2
    let a = g.extract();
    let d2 = a.boundary();
    let col: Vec<Vec<i64>> = (0..d2.cols()).map(|j| (0..d2.rows()).map(|e| d2.get(e, j)).collect()).collect();
    let mut want = vec![0i64; 27];
    for (e, s) in [(7, -1), (8, 1), (10, 1), (12, 1), (17, -1)] {
        want[e] = s;
    }
    assert_eq!(col.iter().filter(|c| **c == want).count(), 1);
}

#[test]
fn paper_example_faces_equal_the_two_map_faces() {
    let (points, edges) = figure3();
    let g = PlanarGraph::try_new(points.clone(), edges.clone()).unwrap();
    let a = g.extract();
    // V - E + F = 16 - 27 + 12 = 1 bounded faces plus the unbounded one
    assert_eq!(a.faces.len(), 12);
    assert!(a.faces.iter().all(|f| f.twice_area > 0));
    // the square of side 8, clockwise
    assert_eq!(a.outer.twice_area, -128);
    assert_eq!(a.faces.iter().map(|f| f.twice_area).sum::<i128>(), 128);
    let found: Vec<Vec<u32>> = a.faces.iter().map(|f| f.vertices.clone()).collect();
    assert_eq!(normals(&found), normals(&figure3_faces()));
    // the 2-map of the drawn faces has the same faces, and the edges of the drawing
    let m = two_map(&points, &figure3_faces());
    assert_eq!(m.cell_counts(), vec![16, 27, 12]);
    assert_eq!(normals(&map_faces(&m, &points)), normals(&found));
    assert_eq!(edges_of(&figure3_faces()), {
        let mut e = edges;
        e.sort_unstable();
        e
    });
    // and the same homology as the signed LAR chain complex: a disk
    let lar = a.lar();
    assert_eq!(lar.signed_boundary_planar(&points).unwrap(), a.boundary());
    let h_lar = homology_z(&lar.chain_complex().unwrap()).unwrap();
    let h_map = homology_z(&cellular_complex(&m).unwrap().chain).unwrap();
    assert_eq!(h_lar.betti, vec![1, 0, 0]);
    assert_eq!(h_lar, h_map);
}

#[test]
fn a_tree_has_only_the_unbounded_face() {
    let g = PlanarGraph::try_new(vec![[0, 0], [1, 0], [0, 1]], vec![[0, 1], [2, 0]]).unwrap();
    let a = g.extract();
    assert!(a.faces.is_empty());
    assert_eq!(a.outer.twice_area, 0);
    // each edge walked both ways cancels
    assert_eq!(a.outer.steps.len(), 4);
    assert_eq!(a.outer.chain(), vec![]);
}

#[test]
fn malformed_arrangements_are_refused() {
    let sq = vec![[0, 0], [2, 0], [2, 2], [0, 2]];
    let try_new = |p: &[[i32; 2]], e: &[[u32; 2]]| PlanarGraph::try_new(p.to_vec(), e.to_vec()).unwrap_err();
    assert_eq!(try_new(&sq, &[]), ArrangementError::Empty);
    assert_eq!(try_new(&sq, &[[0, 1], [1, 7]]), ArrangementError::VertexOutOfRange { edge: 1, vertex: 7, vertices: 4 });
    assert_eq!(try_new(&sq, &[[0, 1], [2, 2]]), ArrangementError::Loop { edge: 1, vertex: 2 });
    assert_eq!(try_new(&sq, &[[0, 1], [1, 2], [1, 0]]), ArrangementError::DuplicateEdge { first: 0, second: 2 });
    assert_eq!(
        try_new(&[[0, 0], [1, 0], [0, 0]], &[[0, 1], [1, 2]]),
        ArrangementError::CoincidentPoints { a: 0, b: 2 }
    );
    // the two diagonals of the square cross at (1, 1), which is no vertex
    assert_eq!(
        try_new(&sq, &[[0, 1], [1, 2], [2, 3], [0, 3], [0, 2], [1, 3]]),
        ArrangementError::Crossing { first: 4, second: 5 }
    );
    // vertex 4 = (1, 0) inside the edge 0-1
    let mut p5 = sq.clone();
    p5.push([1, 0]);
    assert_eq!(
        try_new(&p5, &[[0, 1], [1, 2], [2, 3], [0, 3], [4, 2]]),
        ArrangementError::VertexOnEdge { vertex: 4, edge: 0 }
    );
    // two edges from vertex 0 along the same ray overlap
    assert_eq!(try_new(&p5, &[[0, 1], [0, 4], [1, 2], [2, 3]]), ArrangementError::VertexOnEdge { vertex: 4, edge: 0 });
    // an isolated vertex, and two components
    assert_eq!(try_new(&p5, &[[0, 1], [1, 2], [2, 3], [0, 3]]), ArrangementError::Disconnected { vertex: 4 });
    assert_eq!(
        try_new(&[[0, 0], [1, 0], [5, 5], [6, 5]], &[[0, 1], [2, 3]]),
        ArrangementError::Disconnected { vertex: 2 }
    );
    let g = PlanarGraph::try_new(sq, vec![[0, 1], [1, 2], [2, 3], [0, 3]]).unwrap();
    assert_eq!(g.stripes(4, true), Err(ArrangementError::NoSuchEdge { edge: 4, edges: 4 }));
    assert_eq!(g.stripes(0, false).unwrap().last().unwrap().chain, vec![(0, -1), (1, -1), (2, -1), (3, 1)]);
}

/// A `w × h` grid of unit squares, square `k` left whole (`0`) or cut by its diagonal from
/// lower left (`1`) or lower right (`2`): the points and the faces.
fn cut_grid(w: u32, h: u32, cuts: &[u8]) -> (Vec<[i32; 2]>, Vec<Vec<u32>>) {
    let at = |i: u32, j: u32| j * (w + 1) + i;
    let points = (0..=h).flat_map(|j| (0..=w).map(move |i| [i as i32, j as i32])).collect();
    let mut faces = Vec::new();
    for j in 0..h {
        for i in 0..w {
            let (a, b, c, d) = (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
            match cuts[(j * w + i) as usize % cuts.len()] {
                0 => faces.push(vec![a, b, c, d]),
                1 => faces.extend([vec![a, b, c], vec![a, c, d]]),
                _ => faces.extend([vec![a, b, d], vec![b, c, d]]),
            }
        }
    }
    (points, faces)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    /// Cycle extraction from the edges alone finds the faces the grid was drawn with, the
    /// same as the 2-map built from those faces, with the same homology (a disk).
    #[test]
    fn extracted_faces_equal_the_two_map_faces(w in 1u32..5, h in 1u32..5, cuts in prop::collection::vec(0u8..3, 1..16), flip in any::<bool>()) {
        let (points, faces) = cut_grid(w, h, &cuts);
        let mut edges = edges_of(&faces);
        if flip {
            edges.reverse();
            for e in &mut edges {
                e.reverse();
            }
        }
        let g = PlanarGraph::try_new(points.clone(), edges.clone()).unwrap();
        let a = g.extract();
        let found: Vec<Vec<u32>> = a.faces.iter().map(|f| f.vertices.clone()).collect();
        prop_assert_eq!(normals(&found), normals(&faces));
        prop_assert!(a.faces.iter().all(|f| f.twice_area > 0));
        prop_assert_eq!(a.outer.twice_area, -2 * i128::from(w * h));
        let m = two_map(&points, &faces);
        prop_assert_eq!(normals(&map_faces(&m, &points)), normals(&found));
        let lar = a.lar();
        prop_assert_eq!(lar.signed_boundary_planar(&points).unwrap(), a.boundary());
        let h_lar = homology_z(&lar.chain_complex().unwrap()).unwrap();
        prop_assert_eq!(&h_lar.betti, &vec![1, 0, 0]);
        prop_assert_eq!(h_lar, homology_z(&cellular_complex(&m).unwrap().chain).unwrap());
    }
}
