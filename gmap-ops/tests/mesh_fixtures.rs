//! The readers on meshes written by gmsh's and VTK's own writers (tests/data/mesh/make.py,
//! README there): the unit cube of 100 tetrahedra in Gmsh 2.2 and 4.1, ASCII and binary of
//! both byte orders, `.vtu` compressed by zlib, LZMA and LZ4, and of orders 2 and 3 (read
//! as their corner tetrahedra, the other nodes kept in the label `high_order.nodes`).

use std::path::PathBuf;

use gmap_core::{to_dense_labels, Characteristics, LabelValue, LabelledGMap};
use gmap_ops::import::high_order::HIGH_ORDER_LABEL;
use gmap_ops::import::read_mesh;

fn read(name: &str) -> LabelledGMap {
    let p = PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/../tests/data/mesh")).join(name);
    read_mesh(&p, None).unwrap_or_else(|| panic!("{name}")).unwrap_or_else(|e| panic!("{e}"))
}

/// The cube's 100 tetrahedra on 45 corners: χ = 45 − 186 + 242 − 100 = 1; its 84 boundary
/// triangles.
fn check_cube(name: &str, g: &LabelledGMap) {
    let d = g.to_dense_map();
    d.validate().unwrap();
    let c = Characteristics::of(&d);
    assert_eq!(c.darts, 100 * 24, "{name}");
    assert_eq!(c.cells, vec![45, 186, 242, 100], "{name}");
    assert_eq!(c.components, 1, "{name}");
    assert!(c.orientable, "{name}");
}

/// How many `dim`-cells carry `label` = `value`.
fn count(g: &LabelledGMap, dim: usize, label: &str, value: &LabelValue) -> usize {
    let (_, labels, _) = to_dense_labels(g);
    labels.of[dim].iter().filter(|l| l.get(label) == Some(value)).count()
}

fn with_label(g: &LabelledGMap, dim: usize, label: &str) -> usize {
    let (_, labels, _) = to_dense_labels(g);
    labels.of[dim].iter().filter(|l| l.get(label).is_some()).count()
}

#[test]
fn gmsh_written_cubes_in_every_version_encoding_and_order() {
    for (name, higher) in [
        ("cube_22.msh", false),
        ("cube_22_bin.msh", false),
        ("cube_41_bin.msh", false),
        ("cube_41_bin_be.msh", false),
        ("cube_o2_41.msh", true),
        ("cube_o2_22_bin.msh", true),
        ("cube_o3_41_bin.msh", true),
    ] {
        let g = read(name);
        check_cube(name, &g);
        assert_eq!(count(&g, 3, "gmsh:physical", &LabelValue::Int(1)), 100, "{name}");
        assert_eq!(count(&g, 3, "gmsh:physical_name", &LabelValue::Text("solid".into())), 100, "{name}");
        assert_eq!(count(&g, 2, "gmsh:physical", &LabelValue::Int(2)), 84, "{name}");
        assert_eq!(count(&g, 2, "gmsh:physical_name", &LabelValue::Text("skin".into())), 84, "{name}");
        let (tets, faces) = if higher { (100, 84) } else { (0, 0) };
        assert_eq!(with_label(&g, 3, HIGH_ORDER_LABEL), tets, "{name}");
        assert_eq!(with_label(&g, 2, HIGH_ORDER_LABEL), faces, "{name}");
    }
}

#[test]
fn the_other_nodes_of_a_quadratic_tetrahedron_are_its_edge_midpoints() {
    // order 2: six nodes, each the middle of an edge of the straight-sided cube mesh
    let g = read("cube_o2_41.msh");
    let (d, labels, _) = to_dense_labels(&g);
    for (k, l) in labels.of[3].iter().enumerate() {
        let Some(LabelValue::Text(t)) = l.get(HIGH_ORDER_LABEL) else { panic!("tetrahedron {k}: {l:?}") };
        let nodes: Vec<[f64; 3]> = t
            .split(", ")
            .map(|p| {
                let v: Vec<f64> = p.split(' ').map(|x| x.parse().unwrap()).collect();
                [v[0], v[1], v[2]]
            })
            .collect();
        assert_eq!(nodes.len(), 6, "tetrahedron {k}");
        // the corners of this tetrahedron
        let dart = d.cells(3).reps[k];
        let mut corners: Vec<[f64; 3]> = Vec::new();
        for e in d.orbit(dart, gmap_core::AlphaSet::range(0, 2)) {
            let p = d.vertex_point(e).unwrap();
            if !corners.contains(&p) {
                corners.push(p);
            }
        }
        assert_eq!(corners.len(), 4);
        for n in &nodes {
            let mid = corners.iter().enumerate().any(|(i, a)| {
                corners[i + 1..].iter().any(|b| (0..3).all(|j| ((a[j] + b[j]) / 2.0 - n[j]).abs() < 1e-9))
            });
            assert!(mid, "tetrahedron {k}: {n:?} is not the middle of an edge of {corners:?}");
        }
    }
}

#[test]
fn vtk_written_cubes_with_every_compressor_and_order() {
    for (name, higher) in [
        ("cube_zlib.vtu", false),
        ("cube_lzma.vtu", false),
        ("cube_lz4.vtu", false),
        ("cube_o2_zlib.vtu", true),
        ("cube_o2_lagrange.vtu", true),
        ("cube_o2.vtk", true),
    ] {
        let g = read(name);
        check_cube(name, &g);
        assert_eq!(count(&g, 3, "physical", &LabelValue::Int(1)), 100, "{name}");
        assert_eq!(with_label(&g, 0, "x"), 45, "{name}");
        assert_eq!(with_label(&g, 3, HIGH_ORDER_LABEL), if higher { 100 } else { 0 }, "{name}");
    }
}
