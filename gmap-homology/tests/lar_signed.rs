//! LAR, signed: the conventional orientation, the signed boundary and coboundary, the nine
//! operators of Table 1 entry by entry, Table 2's cardinalities, and agreement with our
//! border operator (BO Def. 10) on the same complexes.

use gmap_core::{examples, DenseMap};
use gmap_homology::lar::{characteristic_matrix, Lar, LarError, LarOp};
use gmap_homology::{cellular_complex, homology_z, SparseMatrix};
use gmap_ops::build::grid;
use gmap_ops::import::off::PolygonMesh;
use gmap_ops::import::CubicalSet;
use proptest::prelude::*;

/// A LAR complex from vertex lists: `cells[p - 1]` lists the p-cells.
fn lar(vertices: usize, cells: &[&[&[u32]]]) -> Lar {
    let ms = cells
        .iter()
        .map(|c| characteristic_matrix(vertices, &c.iter().map(|r| r.to_vec()).collect::<Vec<_>>()).unwrap())
        .collect();
    Lar::from_cells(vertices, ms).unwrap()
}

/// The unit square cut by its diagonal 0-2: vertices 0 (0,0), 1 (1,0), 2 (1,1), 3 (0,1);
/// edges e0 = {0,1}, e1 = {1,2}, e2 = {2,3}, e3 = {0,3}, e4 = {0,2}; faces f0 = {0,1,2},
/// f1 = {0,2,3}.
fn cut_square() -> Lar {
    lar(4, &[&[&[0, 1], &[1, 2], &[2, 3], &[0, 3], &[0, 2]], &[&[0, 1, 2], &[0, 2, 3]]])
}

#[test]
fn the_nine_operators_entry_by_entry() {
    let l = cut_square();
    let op = |o| l.operator(o).unwrap().to_dense();
    // EV = M_1: the vertices of each edge
    let m1 = vec![vec![1, 1, 0, 0], vec![0, 1, 1, 0], vec![0, 0, 1, 1], vec![1, 0, 0, 1], vec![1, 0, 1, 0]];
    assert_eq!(op(LarOp::EV), m1);
    // FV = M_2: the vertices of each face
    assert_eq!(op(LarOp::FV), vec![vec![1, 1, 1, 0], vec![1, 0, 1, 1]]);
    // VE = M_1^T: the edges on each vertex (vertex 0 is on e0, e3, e4)
    assert_eq!(op(LarOp::VE), vec![vec![1, 0, 0, 1, 1], vec![1, 1, 0, 0, 0], vec![0, 1, 1, 0, 1], vec![0, 0, 1, 1, 0]]);
    // VF = M_2^T: the faces on each vertex (0 and 2 are on both)
    assert_eq!(op(LarOp::VF), vec![vec![1, 1], vec![1, 0], vec![1, 1], vec![0, 1]]);
    // VV = M_1^T M_1: degrees on the diagonal (3, 2, 3, 2), 1 for the ends of an edge
    assert_eq!(op(LarOp::VV), vec![vec![3, 1, 1, 1], vec![1, 2, 1, 0], vec![1, 1, 3, 1], vec![1, 0, 1, 2]]);
    // EE = M_1 M_1^T: common vertices of two edges (2 on the diagonal)
    assert_eq!(
        op(LarOp::EE),
        vec![vec![2, 1, 0, 1, 1], vec![1, 2, 1, 0, 1], vec![0, 1, 2, 1, 1], vec![1, 0, 1, 2, 1], vec![1, 1, 1, 1, 2],]
    );
    // EF = M_1 M_2^T: common vertices of an edge and a face (2: the edge is on the face)
    assert_eq!(op(LarOp::EF), vec![vec![2, 1], vec![2, 1], vec![1, 2], vec![1, 2], vec![2, 2]]);
    // FE = M_2 M_1^T
    assert_eq!(op(LarOp::FE), vec![vec![2, 2, 1, 1, 2], vec![1, 1, 2, 2, 2]]);
    // FF = M_2 M_2^T: three vertices each, two in common
    assert_eq!(op(LarOp::FF), vec![vec![3, 2], vec![2, 3]]);
    // the unsigned boundary by the count rule: M_{1,2} = M_1 M_2^T = EF, kept where it is 2
    assert_eq!(l.incidence(2).unwrap().to_dense(), op(LarOp::EF));
    assert_eq!(
        l.unsigned_boundary(2).unwrap().to_dense(),
        vec![vec![1, 0], vec![1, 0], vec![0, 1], vec![0, 1], vec![1, 1]]
    );
    assert_eq!(l.unsigned_boundary(1).unwrap(), l.operator(LarOp::VE).unwrap());
    // the relations behind Table 2
    let rel = |o| l.relation(o).unwrap().to_dense();
    assert_eq!(rel(LarOp::VV), vec![vec![0, 1, 1, 1], vec![1, 0, 1, 0], vec![1, 1, 0, 1], vec![1, 0, 1, 0]]);
    assert_eq!(rel(LarOp::EF), vec![vec![1, 0], vec![1, 0], vec![0, 1], vec![0, 1], vec![1, 1]]);
    assert_eq!(rel(LarOp::FE), vec![vec![1, 1, 0, 0, 1], vec![0, 0, 1, 1, 1]]);
    assert_eq!(rel(LarOp::FF), vec![vec![0, 1], vec![1, 0]]);
    assert_eq!(rel(LarOp::EE)[4], vec![1, 1, 1, 1, 0]);
    assert_eq!(l.cardinality(LarOp::EE).unwrap(), 3 * 2 + 2 + 3 * 2 + 2);
}

#[test]
fn signed_boundary_and_coboundary_by_hand() {
    let l = cut_square();
    let d1 = l.signed_boundary(1).unwrap();
    // each edge from its lower vertex to its higher one
    assert_eq!(
        d1.to_dense(),
        vec![vec![-1, 0, 0, -1, -1], vec![1, -1, 0, 0, 0], vec![0, 1, -1, 0, 1], vec![0, 0, 1, 1, 0]]
    );
    let d2 = l.signed_boundary(2).unwrap();
    // f0 follows e0: 0 -> 1 -> 2 -> 0 = e0 + e1 - e4; f1 follows e2: 2 -> 3 -> 0 -> 2 = e2 - e3 + e4
    assert_eq!(d2.to_dense(), vec![vec![1, 0], vec![1, 0], vec![0, 1], vec![0, -1], vec![-1, 1]]);
    assert!(d1.checked_mul(&d2).unwrap().is_zero());
    assert_eq!(l.signed_coboundary(0).unwrap(), d1.transpose());
    assert_eq!(l.signed_coboundary(1).unwrap(), d2.transpose());
    // both faces already run counter-clockwise
    let square = [[0, 0], [1, 0], [1, 1], [0, 1]];
    assert_eq!(l.signed_boundary_planar(&square).unwrap(), d2);
    // the triangle 0 (0,0), 1 (0,1), 2 (1,0): its first edge 0 -> 1 turns clockwise, so the
    // area sign turns it over
    let t = lar(3, &[&[&[0, 1], &[1, 2], &[0, 2]], &[&[0, 1, 2]]]);
    assert_eq!(t.signed_boundary(2).unwrap().to_dense(), vec![vec![1], vec![1], vec![-1]]);
    assert_eq!(
        t.signed_boundary_planar(&[[0, 0], [0, 1], [1, 0]]).unwrap().to_dense(),
        vec![vec![-1], vec![-1], vec![1]]
    );
    assert_eq!(homology_z(&l.chain_complex().unwrap()).unwrap().betti, vec![1, 0, 0]);
    assert_eq!(l.signed_boundary(3), Err(LarError::NoSuchDimension { p: 3, n: 2 }));
    assert_eq!(l.signed_boundary_planar(&square[..3]), Err(LarError::PointCount { points: 3, vertices: 4 }));
    assert_eq!(t.signed_boundary_planar(&[[0, 0], [1, 1], [2, 2]]), Err(LarError::ZeroMeasure { dim: 2, cell: 0 }));
}

/// The boundary of a unit cube, of a tetrahedron and of an octahedron as 2-maps (through
/// the `.off` importer), and the 3 × 3 torus.
fn closed_surfaces() -> Vec<(&'static str, DenseMap)> {
    let mesh = |points: Vec<[f64; 3]>, polygons: Vec<Vec<u32>>| {
        let n = polygons.len();
        PolygonMesh { points, polygons, lines: vec![0; n] }.to_gmap().unwrap()
    };
    let cube = mesh(
        (0..8).map(|i| [f64::from(i & 1), f64::from((i >> 1) & 1), f64::from(i >> 2)]).collect(),
        vec![
            vec![0, 2, 3, 1],
            vec![4, 5, 7, 6],
            vec![0, 1, 5, 4],
            vec![2, 6, 7, 3],
            vec![0, 4, 6, 2],
            vec![1, 3, 7, 5],
        ],
    );
    let tetra = mesh(
        vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
        vec![vec![0, 2, 1], vec![0, 1, 3], vec![1, 2, 3], vec![0, 3, 2]],
    );
    // vertices ±x (0, 1), ±y (2, 3), ±z (4, 5)
    let octa = mesh(
        vec![[1.0, 0.0, 0.0], [-1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, -1.0, 0.0], [0.0, 0.0, 1.0], [0.0, 0.0, -1.0]],
        [4, 5].iter().flat_map(|&z| [[0, 2], [2, 1], [1, 3], [3, 0]].map(|[a, b]| vec![a, b, z])).collect(),
    );
    vec![("cube", cube), ("tetrahedron", tetra), ("octahedron", octa), ("torus", grid(&[3, 3], &[true, true]).unwrap())]
}

#[test]
fn table_2_cardinalities() {
    // (V, E, F, Σ deg(deg - 1), β)
    let want = [
        ("cube", (8, 12, 6, 8 * 3 * 2, vec![1, 0, 1])),
        ("tetrahedron", (4, 6, 4, 4 * 3 * 2, vec![1, 0, 1])),
        ("octahedron", (6, 12, 8, 6 * 4 * 3, vec![1, 0, 1])),
        ("torus", (9, 18, 9, 9 * 4 * 3, vec![1, 2, 1])),
    ];
    for ((name, m), (wname, (v, e, f, ee, betti))) in closed_surfaces().into_iter().zip(want) {
        assert_eq!(name, wname);
        assert_eq!(m.cell_counts(), vec![v, e, f], "{name}");
        let l = Lar::from_map(&m);
        for op in LarOp::ALL {
            let n = l.cardinality(op).unwrap();
            if op == LarOp::EE {
                assert_eq!(n, ee, "{name} EE");
                assert!(n >= 4 * e, "{name}: |EE| >= 4|E|");
            } else {
                assert_eq!(n, 2 * e, "{name} {op:?}: 2|E|");
            }
        }
        let h = homology_z(&l.chain_complex().unwrap()).unwrap();
        assert_eq!(h.betti, betti, "{name}");
        assert_eq!(h, homology_z(&cellular_complex(&m).unwrap().chain).unwrap(), "{name}");
    }
}

/// `lar[p-1] = D_{p-1} bo[p-1] D_p` for diagonal sign matrices with `D_0 = I` (both
/// conventions keep vertices positive): the two boundaries differ only by the orientation
/// chosen for each cell. Returns the first dimension where no such signs exist.
fn sign_equivalent(lar: &[SparseMatrix], bo: &[SparseMatrix]) -> Result<(), usize> {
    let mut lower = vec![1i64; lar.first().map_or(0, SparseMatrix::rows)];
    for (p, (a, b)) in lar.iter().zip(bo).enumerate() {
        if a.rows() != b.rows() || a.cols() != b.cols() {
            return Err(p + 1);
        }
        let mut signs = Vec::with_capacity(a.cols());
        for j in 0..a.cols() {
            let ((ra, va), (rb, vb)) = (a.col(j), b.col(j));
            if ra != rb || ra.is_empty() {
                return Err(p + 1);
            }
            let s = va[0] * vb[0] * lower[ra[0] as usize];
            if ra.iter().zip(va.iter().zip(vb)).any(|(&i, (&x, &y))| x != s * lower[i as usize] * y) {
                return Err(p + 1);
            }
            signs.push(s);
        }
        lower = signs;
    }
    Ok(())
}

/// The LAR of `m` against its border operator: same cells, same matrices up to the sign of
/// each cell, same homology. Returns the homology's Betti numbers.
fn agrees_with_border_operator(m: &DenseMap) -> Vec<usize> {
    let bo = cellular_complex(m).unwrap();
    for k in 0..=m.dim() {
        assert_eq!(bo.reps[k], m.cells(k).reps, "cell order of dimension {k}");
    }
    let l = Lar::from_map(m);
    let signed = l.signed_boundaries().unwrap();
    assert_eq!(sign_equivalent(&signed, bo.chain.boundaries()), Ok(()));
    let h = homology_z(&l.chain_complex().unwrap()).unwrap();
    assert_eq!(h, homology_z(&bo.chain).unwrap());
    h.betti
}

#[test]
fn equal_to_the_border_operator_on_known_maps() {
    assert_eq!(agrees_with_border_operator(&examples::fig1_surface()), vec![1, 0, 0]);
    assert_eq!(agrees_with_border_operator(&examples::fig1_curve()), vec![1, 1]);
    assert_eq!(agrees_with_border_operator(&grid(&[3, 2], &[false, false]).unwrap()), vec![1, 0, 0]);
    assert_eq!(agrees_with_border_operator(&grid(&[3, 4], &[true, false]).unwrap()), vec![1, 1, 0]);
    assert_eq!(agrees_with_border_operator(&grid(&[2, 2, 1], &[false; 3]).unwrap()), vec![1, 0, 0, 0]);
    assert_eq!(agrees_with_border_operator(&grid(&[3, 3, 3], &[true; 3]).unwrap()), vec![1, 3, 3, 1]);
    // a 3 × 3 × 3 box without its centre cube: a hollow ball, H_2 = Z
    let mut bits = vec![1u8; 27];
    bits[13] = 0;
    let shell = CubicalSet::new(vec![0; 3], vec![3; 3], bits).unwrap().gmap(false).unwrap();
    assert_eq!(agrees_with_border_operator(&shell), vec![1, 0, 1, 0]);
}

/// The cuboidal grid of `a × b × c` unit cubes in LAR form, built from coordinates alone
/// (vertex `(x, y, z)` is `x + (a+1)(y + (b+1) z)`), with its points.
fn cuboid(a: u32, b: u32, c: u32) -> (Lar, Vec<[i32; 3]>) {
    let size = [a, b, c];
    let id = |x: [u32; 3]| x[0] + (a + 1) * (x[1] + (b + 1) * x[2]);
    let mut points = Vec::new();
    for z in 0..=c {
        for y in 0..=b {
            for x in 0..=a {
                points.push([x as i32, y as i32, z as i32]);
            }
        }
    }
    // the k-cells spanned from each lattice point along each set of k axes
    let mut cells: Vec<Vec<Vec<u32>>> = vec![Vec::new(); 3];
    for base in &points {
        let base = base.map(|t| t as u32);
        for axes in 1u32..8 {
            let k = axes.count_ones() as usize;
            if (0..3).any(|i| axes >> i & 1 == 1 && base[i] >= size[i]) {
                continue;
            }
            let mut verts: Vec<u32> = (0u32..8)
                .filter(|corner| corner & !axes == 0)
                .map(|corner| id([0, 1, 2].map(|i| base[i] + (corner >> i & 1))))
                .collect();
            verts.sort_unstable();
            cells[k - 1].push(verts);
        }
    }
    let ms = cells.iter().map(|c| characteristic_matrix(points.len(), c).unwrap()).collect();
    (Lar::from_cells(points.len(), ms).unwrap(), points)
}

/// The vertices of cell `j` of dimension `p`.
fn vertices_of(l: &Lar, p: usize, j: usize) -> Vec<u32> {
    l.characteristic(p).transpose().col(j).0.to_vec()
}

/// [`Lar::signed_boundary_solid`] on [`cuboid`]`(a, b, c)`: every face of a cube, with its
/// sign, has its normal (from its oriented edge cycle) pointing away from the cube's centre,
/// and in the sum of all cubes the interior faces cancel, leaving the `2(ab + bc + ca)`
/// squares of the box's surface with coefficient ±1.
fn check_outward(l: &Lar, points: &[[i32; 3]], (a, b, c): (usize, usize, usize)) {
    let d = l.signed_boundaries().unwrap();
    let d3 = l.signed_boundary_solid(points).unwrap();
    let p = |v: u32| points[v as usize].map(i64::from);
    // the sum of the corners of a cell: 2^k times its centre
    let corner_sum = |vs: &[u32]| [0, 1, 2].map(|i| vs.iter().map(|&v| p(v)[i]).sum::<i64>());
    for cube in 0..d3.cols() {
        let (faces, signs) = d3.col(cube);
        assert_eq!(faces.len(), 6);
        let c8 = corner_sum(&vertices_of(l, 3, cube));
        for (&f, &s) in faces.iter().zip(signs) {
            let (edges, t) = d[1].col(f as usize);
            // Σ t_e (a × b) over the face's edges is twice its area times its normal
            let mut n = [0i64; 3];
            for (&e, &te) in edges.iter().zip(t) {
                let ends = d[0].col(e as usize).0;
                let (a, b) = (p(ends[0]), p(ends[1]));
                let x = [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
                for i in 0..3 {
                    n[i] += s * te * x[i];
                }
            }
            let f4 = corner_sum(&vertices_of(l, 2, f as usize));
            // 8 (face centre - cube centre) · normal
            let out: i64 = (0..3).map(|i| (2 * f4[i] - c8[i]) * n[i]).sum();
            assert!(out > 0, "cube {cube}, face {f} points inward");
        }
    }
    let ones = SparseMatrix::try_from_columns(d3.cols(), &[(0..d3.cols() as u32).map(|j| (j, 1)).collect()]).unwrap();
    let total = d3.checked_mul(&ones).unwrap();
    assert!(total.iter().all(|(_, _, v)| v == 1 || v == -1));
    assert_eq!(total.nnz(), 2 * (a * b + b * c + c * a));
}

#[test]
fn cuboid_grids_from_coordinates() {
    let (l, points) = cuboid(2, 1, 1);
    // 12 vertices, 20 edges, 11 squares, 2 cubes
    assert_eq!((1..=3).map(|p| l.characteristic(p).rows()).collect::<Vec<_>>(), vec![20, 11, 2]);
    assert_eq!(l.vertices(), 12);
    check_outward(&l, &points, (2, 1, 1));
    let h = homology_z(&l.chain_complex().unwrap()).unwrap();
    assert_eq!(h.betti, vec![1, 0, 0, 0]);
    assert!(h.torsion.iter().all(Vec::is_empty));
    let d3 = l.signed_boundary_solid(&points).unwrap();
    let ones = SparseMatrix::try_from_columns(2, &[vec![(0, 1), (1, 1)]]).unwrap();
    // the shared square cancels: 10 boundary squares remain
    assert_eq!(d3.checked_mul(&ones).unwrap().nnz(), 10);
}

#[test]
fn malformed_complexes_are_refused() {
    // an edge with three vertices
    let l = lar(3, &[&[&[0, 1, 2]]]);
    assert_eq!(l.signed_boundaries(), Err(LarError::EdgeVertices { edge: 0, count: 3 }));
    assert!(!l.is_orientable());
    // the one-vertex torus: each edge has the vertex set {v}
    assert_eq!(
        Lar::from_map(&examples::torus()).signed_boundaries(),
        Err(LarError::EdgeVertices { edge: 0, count: 1 })
    );
    // two edges on the same two vertices
    let twin = lar(3, &[&[&[0, 1], &[1, 2], &[0, 1]]]);
    assert_eq!(twin.signed_boundaries(), Err(LarError::SameVertices { dim: 1, first: 0, second: 2 }));
    // the ring of eight cubes where cubes (1,0,0) and (1,1,1) meet along an edge only: the
    // map keeps two copies of that edge, with the same two vertices
    let mut bits = vec![0u8; 27];
    for i in [0, 1, 2, 5, 9, 12, 13, 14] {
        bits[i] = 1;
    }
    let ring = CubicalSet::new(vec![0; 3], vec![3; 3], bits).unwrap().gmap(false).unwrap();
    assert!(matches!(Lar::from_map(&ring).signed_boundaries(), Err(LarError::SameVertices { dim: 1, .. })));
    assert_eq!(homology_z(&cellular_complex(&ring).unwrap().chain).unwrap().betti, vec![1, 1, 0, 0]);
    // a face missing the edge {0, 2}: vertex 0 lies on one of its edges only
    let open = lar(3, &[&[&[0, 1], &[1, 2]], &[&[0, 1, 2]]]);
    assert_eq!(open.signed_boundaries(), Err(LarError::OpenBoundary { dim: 2, cell: 0, ridge: 0, count: 1 }));
    // a face holding no edge
    let bare = lar(4, &[&[&[0, 1]], &[&[1, 2, 3]]]);
    assert_eq!(bare.signed_boundaries(), Err(LarError::NoFacet { dim: 2, cell: 0 }));
    // a "face" on two disjoint triangles
    let two = lar(6, &[&[&[0, 1], &[1, 2], &[0, 2], &[3, 4], &[4, 5], &[3, 5]], &[&[0, 1, 2, 3, 4, 5]]]);
    assert_eq!(two.signed_boundaries(), Err(LarError::DisconnectedBoundary { dim: 2, cell: 0, facet: 3 }));
    // a 3-cell bounded by the six-vertex projective plane
    let rp2: Vec<Vec<u32>> =
        [[1, 2, 3], [1, 3, 4], [1, 4, 5], [1, 5, 6], [1, 6, 2], [2, 3, 5], [3, 4, 6], [4, 5, 2], [5, 6, 3], [6, 2, 4]]
            .iter()
            .map(|t| t.iter().map(|v| v - 1).collect())
            .collect();
    let k6: Vec<Vec<u32>> = (0..6).flat_map(|a| (a + 1..6).map(move |b| vec![a, b])).collect();
    let m1 = characteristic_matrix(6, &k6).unwrap();
    let m2 = characteristic_matrix(6, &rp2).unwrap();
    let surface = Lar::from_cells(6, vec![m1.clone(), m2.clone()]).unwrap();
    // as a 2-complex it is fine: H = (Z, Z/2, 0)
    assert_eq!(homology_z(&surface.chain_complex().unwrap()).unwrap().to_string(), "(Z, Z/2, 0)");
    let m3 = characteristic_matrix(6, &[vec![0, 1, 2, 3, 4, 5]]).unwrap();
    let solid = Lar::from_cells(6, vec![m1, m2, m3]).unwrap();
    assert!(matches!(solid.signed_boundaries(), Err(LarError::NonOrientable { dim: 3, cell: 0, .. })));
    // the wrong number of columns in a characteristic matrix
    assert!(matches!(
        Lar::from_cells(4, vec![characteristic_matrix(3, &[vec![0, 1]]).unwrap()]),
        Err(LarError::VertexOutOfRange { dim: 1, .. })
    ));
    assert_eq!(
        characteristic_matrix(2, &[vec![0, 1], vec![0, 5]]),
        Err(LarError::VertexOutOfRange { dim: 0, cell: 1, vertex: 5, vertices: 2 })
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    /// Random planar and cuboidal grids, periodic or not, and random cubical sets: the
    /// signed LAR boundaries are our border operator up to cell signs, with the same
    /// homology.
    #[test]
    fn random_grids_agree_with_the_border_operator(sizes in prop::collection::vec(1usize..4, 2..4), periodic in any::<bool>()) {
        // a periodic axis needs 3 cells for its cells to have distinct vertex sets
        let flags: Vec<bool> = sizes.iter().map(|&s| periodic && s >= 3).collect();
        let m = grid(&sizes, &flags).unwrap();
        let betti = agrees_with_border_operator(&m);
        let wrapped = flags.iter().filter(|&&f| f).count();
        prop_assert_eq!(betti[1], wrapped);
    }

    #[test]
    fn random_cubical_sets_agree_with_the_border_operator(bits in prop::collection::vec(0u8..2, 27)) {
        prop_assume!(bits.contains(&1));
        let m = CubicalSet::new(vec![0; 3], vec![3; 3], bits).unwrap().gmap(false).unwrap();
        // cubes meeting along an edge only keep two copies of that edge in the map, with
        // the same two vertices when a ring of cubes joins them: LAR must refuse those
        let l = Lar::from_map(&m);
        let twins = (1..=m.dim()).find_map(|p| l.check_distinct(p).err());
        match twins {
            None => {
                agrees_with_border_operator(&m);
            }
            Some(e) => {
                prop_assert!(matches!(e, LarError::SameVertices { .. }), "{:?}", e);
                prop_assert_eq!(l.signed_boundaries().unwrap_err(), e);
            }
        }
    }

    #[test]
    fn random_cuboids_are_oriented_outward(a in 1u32..4, b in 1u32..4, c in 1u32..3) {
        let (l, points) = cuboid(a, b, c);
        check_outward(&l, &points, (a as usize, b as usize, c as usize));
        prop_assert_eq!(homology_z(&l.chain_complex().unwrap()).unwrap().betti, vec![1, 0, 0, 0]);
    }
}
