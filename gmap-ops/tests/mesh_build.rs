//! Cells made into maps: sewing face to face, the refusals (a face in three cells, a
//! non-conforming face, pinched points and edges, bad cells), the incremental builder and
//! `sew3_same_facets`, and hostile text for the three readers.

use gmap_core::{Characteristics, GMap, LabelValue};
use gmap_ops::build::{sew3_same_facets, IncrementalBuilder};
use gmap_ops::import::{parse_msh, parse_vtk, parse_vtu, read_vtk, ImportError};
use gmap_ops::mesh::{CellKind, DataArray, Mesh, MeshCell, MeshError};

fn cell(kind: CellKind, nodes: &[u32]) -> MeshCell {
    MeshCell { kind, nodes: nodes.to_vec(), faces: Vec::new() }
}

/// The (n+1)² × 2 points of a slab of n × n unit cubes; point (x, y, z) is
/// `x + (n+1) (y + (n+1) z)`.
fn slab(n: u32) -> (Vec<[f64; 3]>, impl Fn(u32, u32, u32) -> u32) {
    let pts =
        (0..2).flat_map(|z| (0..=n).flat_map(move |y| (0..=n).map(move |x| [x as f64, y as f64, z as f64]))).collect();
    (pts, move |x, y, z| x + (n + 1) * (y + (n + 1) * z))
}

fn hex(id: &impl Fn(u32, u32, u32) -> u32, x: u32, y: u32) -> MeshCell {
    cell(
        CellKind::Hexahedron,
        &[
            id(x, y, 0),
            id(x + 1, y, 0),
            id(x + 1, y + 1, 0),
            id(x, y + 1, 0),
            id(x, y, 1),
            id(x + 1, y, 1),
            id(x + 1, y + 1, 1),
            id(x, y + 1, 1),
        ],
    )
}

fn chars(m: &Mesh) -> Characteristics {
    let g = m.to_gmap(1 << 20).unwrap_or_else(|e| panic!("{e}"));
    Characteristics::of(&g.to_dense_map())
}

#[test]
fn neighbouring_hexahedra_are_sewn_and_the_boundary_left_free() {
    let (points, id) = slab(2);
    let cells = vec![hex(&id, 0, 0), hex(&id, 1, 0), hex(&id, 0, 1), hex(&id, 1, 1)];
    let m = Mesh { points, cells, ..Mesh::default() };
    let g = m.to_gmap(1 << 20).unwrap();
    let d = g.to_dense_map();
    let c = Characteristics::of(&d);
    assert_eq!(c.cells, vec![18, 33, 20, 4]);
    assert_eq!(c.components, 1);
    assert!(c.orientable);
    // 4 inner faces sewn (8 sides of 8 darts), the rest 3-free
    let free = (0..d.dart_count() as u32).filter(|&k| d.is_free(gmap_core::Dart::new(k), 3)).count();
    assert_eq!(free, 4 * 48 - 4 * 2 * 8);
    // the dart limit is checked before building
    assert!(matches!(m.to_gmap(100), Err(MeshError::TooManyDarts { darts: Some(192), limit: 100, .. })));
}

#[test]
fn an_inverted_cell_is_sewn_by_its_vertices() {
    let (points, id) = slab(2);
    let mut b = hex(&id, 1, 0);
    // the same hexahedron listed upside down (a negative volume)
    b.nodes = [&b.nodes[4..], &b.nodes[..4]].concat();
    let m = Mesh { points, cells: vec![hex(&id, 0, 0), b], ..Mesh::default() };
    let c = chars(&m);
    assert_eq!(c.cells, vec![12, 20, 11, 2]);
    assert!(c.orientable);
}

#[test]
fn refusals_name_the_cells() {
    let (points, id) = slab(2);
    let h = hex(&id, 0, 0);
    // a face in three cells: two wedges and a pyramid on the square 1-4-13-10 (x = 1 side)
    let side = [id(1, 0, 0), id(1, 1, 0), id(1, 1, 1), id(1, 0, 1)];
    let mut pts = points.clone();
    pts.push([1.5, 0.5, 0.5]);
    let apex = pts.len() as u32 - 1;
    let pyr = cell(CellKind::Pyramid, &[side[0], side[1], side[2], side[3], apex]);
    let m = Mesh { points: pts.clone(), cells: vec![h.clone(), hex(&id, 1, 0), pyr], ..Mesh::default() };
    assert_eq!(
        m.to_gmap(1 << 20).unwrap_err().to_string(),
        "the face with vertices [1, 4, 10, 13] lies in 3 cells ([0, 1, 2]): at most two cells may share it"
    );
    // a non-conforming face: a tetrahedron on half of the hexahedron's x = 1 side
    let tet = cell(CellKind::Tetra, &[side[0], side[1], side[2], apex]);
    let m = Mesh { points: pts.clone(), cells: vec![h.clone(), tet], ..Mesh::default() };
    assert_eq!(
        m.to_gmap(1 << 20).unwrap_err().to_string(),
        "non-conforming faces: face [1, 4, 13, 10] of cell 0 and face [1, 4, 13] of cell 1 share the edges 1-4, 4-13 without being one face"
    );
    // two hexahedra sharing one edge only: its points are pinched
    let m = Mesh { points: points.clone(), cells: vec![h.clone(), hex(&id, 1, 1)], ..Mesh::default() };
    assert_eq!(
        m.to_gmap(1 << 20).unwrap_err().to_string(),
        "the cells around point [4] form 2 separate fans: the mesh is not a quasi-manifold there (a G-map would split it)"
    );
    // the same in the middle layer of three, the layers above and below joining the stars
    // of its points: the edge alone is pinched
    let k = |x: u32, y: u32, z: u32| x + 3 * (y + 3 * z);
    let pts: Vec<[f64; 3]> =
        (0..4).flat_map(|z| (0..3).flat_map(move |y| (0..3).map(move |x| [x as f64, y as f64, z as f64]))).collect();
    let h3 = |x: u32, y: u32, z: u32| {
        cell(
            CellKind::Hexahedron,
            &[
                k(x, y, z),
                k(x + 1, y, z),
                k(x + 1, y + 1, z),
                k(x, y + 1, z),
                k(x, y, z + 1),
                k(x + 1, y, z + 1),
                k(x + 1, y + 1, z + 1),
                k(x, y + 1, z + 1),
            ],
        )
    };
    let cells =
        vec![h3(0, 0, 0), h3(1, 0, 0), h3(1, 1, 0), h3(0, 0, 1), h3(1, 1, 1), h3(0, 0, 2), h3(1, 0, 2), h3(1, 1, 2)];
    let m = Mesh { points: pts, cells, ..Mesh::default() };
    assert_eq!(
        m.to_gmap(1 << 20).unwrap_err().to_string(),
        format!("the cells around edge [{}, {}] form 2 separate fans: the mesh is not a quasi-manifold there (a G-map would split it)", k(1, 1, 1), k(1, 1, 2))
    );
    // two triangles sharing one point
    let tris = vec![cell(CellKind::Triangle, &[0, 1, 3]), cell(CellKind::Triangle, &[0, 2, 4])];
    let m = Mesh { points: points[..5].to_vec(), cells: tris, ..Mesh::default() };
    assert!(m.to_gmap(1 << 20).unwrap_err().to_string().starts_with("the cells around point [0] form 2 separate fans"));
    // bad cells
    let bad = |c: MeshCell| {
        Mesh { points: points.clone(), cells: vec![h.clone(), c], ..Mesh::default() }
            .to_gmap(1 << 20)
            .unwrap_err()
            .to_string()
    };
    assert_eq!(bad(cell(CellKind::Tetra, &[0, 1, 2, 1])), "cell 1 (tetrahedron): point 1 appears twice");
    assert_eq!(bad(cell(CellKind::Tetra, &[0, 1, 2])), "cell 1 (tetrahedron): 3 points, a tetrahedron has 4");
    assert_eq!(bad(cell(CellKind::Tetra, &[0, 1, 2, 99])), "cell 1 uses vertex 99, but there are 18 points");
    let open =
        MeshCell { kind: CellKind::Polyhedron, nodes: vec![0, 1, 3, 4], faces: vec![vec![0, 1, 3], vec![0, 1, 4]] };
    assert_eq!(bad(open), "cell 1 (polyhedron): its edge 0-3 lies in 1 of its faces (the faces must close: two each)");
    // a triangle that is no face of the hexahedra, and a repeated boundary triangle
    assert_eq!(
        bad(cell(CellKind::Triangle, &[0, 1, 4])),
        "cell 1 (triangle) on vertices [0, 1, 4] is not a face of any 3-dimensional cell of the mesh"
    );
    let quad = [id(0, 0, 0), id(1, 0, 0), id(1, 1, 0), id(0, 1, 0)];
    let m =
        Mesh { points, cells: vec![h, cell(CellKind::Quad, &quad), cell(CellKind::Quad, &quad)], ..Mesh::default() };
    assert_eq!(m.to_gmap(1 << 20).unwrap_err().to_string(), "cells 1 and 2 both lie on vertices [0, 1, 4, 3]");
}

#[test]
fn lower_cells_and_point_data_become_labels() {
    let (points, id) = slab(1);
    let quad = cell(CellKind::Quad, &[id(0, 0, 0), id(1, 0, 0), id(1, 1, 0), id(0, 1, 0)]);
    let line = cell(CellKind::Line, &[id(0, 0, 0), id(0, 0, 1)]);
    let vertex = cell(CellKind::Vertex, &[id(1, 1, 1)]);
    let n = points.len();
    let m = Mesh {
        points,
        cells: vec![hex(&id, 0, 0), quad, line, vertex],
        point_data: vec![DataArray {
            name: "t".into(),
            values: (0..n).map(|k| Some(LabelValue::Int(k as i64))).collect(),
        }],
        cell_data: vec![
            DataArray { name: "tag".into(), values: (0..4).map(|k| Some(LabelValue::Int(10 + k))).collect() },
            // the writer's own dim column is not a label
            DataArray { name: "dim".into(), values: [3, 2, 1, 0].map(|k| Some(LabelValue::Int(k))).to_vec() },
        ],
    };
    let g = m.to_gmap(1 << 20).unwrap();
    let (_, labels, _) = gmap_core::to_dense_labels(&g);
    let tags = |dim: usize| -> Vec<String> {
        labels.of[dim].iter().filter(|l| !l.is_empty()).map(|l| l.to_string()).collect()
    };
    assert_eq!(tags(3), ["tag=10"]);
    assert_eq!(tags(2), ["tag=11"]);
    assert_eq!(tags(1), ["tag=12"]);
    let mut v = tags(0);
    v.sort();
    assert_eq!(v.len(), 8);
    assert!(v.contains(&"tag=13 t=7".to_string()), "{v:?}");
}

#[test]
fn lines_and_vertices_make_1_and_0_maps() {
    let pts = vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]];
    let square: Vec<MeshCell> = (0..4).map(|k| cell(CellKind::Line, &[k, (k + 1) % 4])).collect();
    let c = chars(&Mesh { points: pts.clone(), cells: square.clone(), ..Mesh::default() });
    assert_eq!((c.cells.clone(), c.components, c.darts), (vec![4, 4], 1, 8));
    let mut star = square.clone();
    star.push(cell(CellKind::Line, &[0, 2]));
    assert_eq!(
        Mesh { points: pts.clone(), cells: star, ..Mesh::default() }.to_gmap(99).unwrap_err().to_string(),
        "the point with vertices [0] lies in 3 cells ([0, 3, 4]): at most two cells may share it"
    );
    let c = chars(&Mesh {
        points: pts.clone(),
        cells: (0..4).map(|k| cell(CellKind::Vertex, &[k])).collect(),
        ..Mesh::default()
    });
    assert_eq!((c.cells, c.components), (vec![4], 4));
}

#[test]
fn the_builder_sews_cgal_s_cube_and_pyramid_and_refuses_out_of_order_calls() {
    let mut g = GMap::new(3);
    let mut b = IncrementalBuilder::new(&mut g).unwrap();
    assert_eq!(b.begin_facet().unwrap_err().to_string(), "builder: begin_facet outside a surface");
    for p in
        [[0., 0., 0.], [1., 0., 0.], [1., 1., 0.], [0., 1., 0.], [0., 1., 1.], [0., 0., 1.], [1., 0., 1.], [1., 1., 1.]]
    {
        b.add_vertex(p);
    }
    b.begin_surface().unwrap();
    for f in [[0, 1, 2, 3], [1, 0, 5, 6], [2, 1, 6, 7], [3, 2, 7, 4], [0, 3, 4, 5], [5, 4, 7, 6]] {
        b.add_facet(&f).unwrap();
    }
    assert_eq!(b.add_facet(&[0, 1, 9]).unwrap_err().to_string(), "cell 0 uses vertex 9, but there are 8 points");
    assert_eq!(b.add_facet(&[0, 1, 0]).unwrap_err().to_string(), "cell 0 (facet): vertex 0 appears twice");
    b.end_surface().unwrap();
    assert!(b.face_dart(&[3, 0, 5, 4]).is_some());
    b.add_vertex([-1., 0.5, 0.5]);
    b.begin_surface().unwrap();
    for f in [&[3, 0, 5, 4][..], &[0, 3, 8], &[3, 4, 8], &[4, 5, 8], &[5, 0, 8]] {
        b.add_facet(f).unwrap();
    }
    b.end_surface().unwrap();
    // a third volume on the shared face is refused
    b.begin_surface().unwrap();
    b.add_facet(&[0, 3, 4, 5]).unwrap();
    assert_eq!(
        b.end_surface().unwrap_err().to_string(),
        "the face with vertices [0, 3, 4, 5] lies in 3 cells ([0, 1, 2]): at most two cells may share it"
    );
    let c = Characteristics::of(&g.to_dense_map());
    assert_eq!(c.components, 2, "the third surface stays, unsewn");
    assert!(g.validate().is_ok());
}

#[test]
fn sew3_same_facets_sews_cubes_made_apart() {
    let mut g = GMap::new(3);
    let p = |x: f64, y: f64, z: f64| [x, y, z];
    for k in 0..3 {
        let x = k as f64;
        g.make_hexahedron([
            p(x, 0., 0.),
            p(x + 1., 0., 0.),
            p(x + 1., 1., 0.),
            p(x, 1., 0.),
            p(x, 1., 1.),
            p(x, 0., 1.),
            p(x + 1., 0., 1.),
            p(x + 1., 1., 1.),
        ]);
    }
    assert_eq!(Characteristics::of(&g.to_dense_map()).components, 3);
    assert_eq!(sew3_same_facets(&mut g).unwrap(), 2);
    let c = Characteristics::of(&g.to_dense_map());
    assert_eq!((c.cells.clone(), c.components), (vec![16, 28, 16, 3], 1));
    assert!(g.validate().is_ok());
    assert_eq!(sew3_same_facets(&mut g).unwrap(), 0);
    assert!(sew3_same_facets(&mut GMap::new(2)).is_err());
}

#[test]
fn hostile_text_is_refused_with_the_line() {
    let bad_vtk: &[(&str, &str)] = &[
        ("", "line 1: expected '# vtk DataFile Version x.y'"),
        ("# vtk DataFile Version 3.0\nx\nASCII\nDATASET POLYDATA\n", "line 4: DATASET POLYDATA is not read: only UNSTRUCTURED_GRID"),
        ("# vtk DataFile Version 3.0\nx\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 99999999999 double\n", "line 5: POINTS: 299999999997 values announced, the rest of the file cannot hold them"),
        ("# vtk DataFile Version 3.0\nx\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 1 double\n0 0 nan\n", "line 5: POINTS: coordinate 2 (point 0) is not a finite number"),
        ("# vtk DataFile Version 3.0\nx\nBINARY\nDATASET UNSTRUCTURED_GRID\nPOINTS 2 float\n\0\0", "line 5: POINTS: 6 values of 4 bytes do not fit in the rest of the file"),
        ("# vtk DataFile Version 3.0\nx\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 1 double\n0 0 0\nCELLS 1 2\n1 0\nCELL_TYPES 1\n11\n", "line 9: cell 0: cell type 11 is not read (vertex 1, line 3, triangle 5, polygon 7, quad 9, tetra 10, hexahedron 12, wedge 13, pyramid 14, polyhedron 42, and the higher-order 21 to 37 and 68 to 81 as their corners)"),
        ("# vtk DataFile Version 3.0\nx\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 1 double\n0 0 0\nCELLS 1 3\n5 0 0\nCELL_TYPES 1\n1\n", "line 7: cell 0: 5 values announced past the end of the list"),
        ("# vtk DataFile Version 3.0\nx\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 1 double\n0 0 0\nCELLS 1 2\n1 0\nCELL_TYPES 1\n1\nCELL_DATA 1\nSCALARS a int\nLOOKUP_TABLE default\nx\n", "line 14: a: value 0 'x' is not a number of type Int(4)"),
    ];
    for (text, want) in bad_vtk {
        assert_eq!(parse_vtk(text.as_bytes()).unwrap_err().to_string(), *want, "{text:?}");
    }
    let bad_vtu: &[(&str, &str)] = &[
        ("<VTKFile type=\"PolyData\"/>", "line 1: type 'PolyData' is not read: only UnstructuredGrid"),
        ("<VTKFile type=\"UnstructuredGrid\"><UnstructuredGrid><Piece NumberOfPoints=\"1\" NumberOfCells=\"0\"><Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"binary\">AAAA</DataArray></Points></Piece></UnstructuredGrid></VTKFile>", "line 1: DataArray '': the block header is cut short"),
        ("<VTKFile type=\"UnstructuredGrid\" compressor=\"vtkBZip2DataCompressor\"/>", "line 1: compressor 'vtkBZip2DataCompressor' is not read (vtkZLibDataCompressor, vtkLZMADataCompressor, vtkLZ4DataCompressor)"),
        ("<VTKFile type=\"UnstructuredGrid\"><Unstr", "line 1: XML: the root node was opened but never closed"),
        ("<VTKFile type=\"UnstructuredGrid\">\n<UnstructuredGrid><Piece NumberOfPoints=\"1\" NumberOfCells=\"0\"><Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">0 0</DataArray></Points></Piece></UnstructuredGrid></VTKFile>", "line 3: DataArray '': 2 values, 3 expected"),
    ];
    for (text, want) in bad_vtu {
        assert_eq!(parse_vtu(text.as_bytes()).unwrap_err().to_string(), *want, "{text:?}");
    }
    let bad_msh: &[(&str, &str)] = &[
        ("$MeshFormat\n3.0 0 8\n$EndMeshFormat\n", "line 2: version 3.0 is not read: only 2.2 and 4.1"),
        ("$MeshFormat\n4.1 1 4\n$EndMeshFormat\n", "line 2: binary .msh of data size 4 is not read: only 8"),
        ("$Nodes\n", "line 1: the file does not start with $MeshFormat"),
        (
            "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 1 1 1\n3 1 0 1\n1\n0 0 x\n$EndNodes\n",
            "line 8: z 'x' is not a valid number",
        ),
        (
            "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Elements\n1 1 1 1\n3 1 35 1\n1 1 2 3 4\n$EndElements\n",
            "line 6: element type 35 (a polyhedron) is not read: its faces are not listed",
        ),
        (
            "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Elements\n1 1 1 1\n3 1 4 1\n1 1 2 3 4\n$EndElements\n",
            "line 7: element 1: no node with tag 1",
        ),
    ];
    for (text, want) in bad_msh {
        assert_eq!(parse_msh(text.as_bytes()).err().unwrap().to_string(), *want, "{text:?}");
    }
    // the file is named
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("bad.vtk");
    std::fs::write(&f, "# vtk DataFile Version 3.0\nx\nASCII\nDATASET POLYDATA\n").unwrap();
    let e = read_vtk(&f, None).unwrap_err();
    assert_eq!(e.to_string(), format!("{}: line 4: DATASET POLYDATA is not read: only UNSTRUCTURED_GRID", f.display()));
    assert!(matches!(e.error, ImportError::Syntax { line: 4, .. }));
}
