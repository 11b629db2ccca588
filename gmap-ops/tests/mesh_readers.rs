//! The `.vtk`, `.vtu` and `.msh` readers on the meshio-written fixtures of
//! tests/data/mesh (README there): cell counts, components, orientability, labels.

use std::path::PathBuf;

use gmap_core::{cell_labels, to_dense_labels, Characteristics, LabelValue, LabelledGMap};
use gmap_ops::import::read_mesh;

fn data(name: &str) -> PathBuf {
    PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/../tests/data/mesh")).join(name)
}

fn read(name: &str) -> LabelledGMap {
    let p = data(name);
    let r = read_mesh(&p, None).unwrap_or_else(|| panic!("{name}"));
    r.unwrap_or_else(|e| panic!("{e}"))
}

fn summary(g: &LabelledGMap) -> Characteristics {
    let d = g.to_dense_map();
    d.validate().unwrap();
    Characteristics::of(&d)
}

#[test]
fn the_hollow_hexahedral_block_in_every_vtk_form() {
    for name in ["hex_hollow.vtu", "hex_hollow_ascii.vtu", "hex_hollow.vtk", "hex_hollow_42.vtk"] {
        let g = read(name);
        let c = summary(&g);
        assert_eq!(c.darts, 26 * 48, "{name}");
        assert_eq!(c.cells, vec![64, 144, 108, 26], "{name}");
        assert_eq!(c.components, 1);
        assert!(c.orientable);
        // region = x + y + z of the cube's corner, temperature = x + y + z of the point
        let (dense, labels, _) = to_dense_labels(&g);
        let mut regions: Vec<i64> = labels.of[3]
            .iter()
            .map(|l| match l.get("region") {
                Some(LabelValue::Int(r)) => *r,
                other => panic!("{name}: {other:?}"),
            })
            .collect();
        regions.sort_unstable();
        assert_eq!(regions.iter().sum::<i64>(), 3 * 27 - 3, "{name}");
        for (k, l) in labels.of[0].iter().enumerate() {
            let p = dense.vertex_point(dense.cells(0).reps[k]).unwrap();
            assert_eq!(l.get("temperature"), Some(&LabelValue::Real(p[0] + p[1] + p[2])), "{name}");
        }
    }
}

#[test]
fn mixed_cells_are_sewn_face_to_face() {
    for name in ["mixed.vtu", "mixed.vtk", "mixed_42.vtk"] {
        let g = read(name);
        let c = summary(&g);
        // hexahedron 48 + pyramid 32 + wedge 36 + tetrahedron 24 darts
        assert_eq!(c.darts, 48 + 32 + 36 + 24, "{name}");
        // edges: 12 of the hexahedron, 4 to the apex, 5 of the wedge, 3 to the tip; χ = 1
        assert_eq!(c.cells, vec![12, 12 + 4 + 5 + 3, 6 + 4 + 4 + 3, 4], "{name}");
        assert_eq!(c.components, 1);
        let (_, labels, _) = to_dense_labels(&g);
        let mut kinds: Vec<&LabelValue> = labels.of[3].iter().map(|l| l.get("kind").unwrap()).collect();
        kinds.sort_by_key(|v| format!("{v}"));
        assert_eq!(kinds, [10, 12, 13, 14].map(LabelValue::Int).iter().collect::<Vec<_>>());
    }
}

#[test]
fn tetrahedra_with_their_boundary_triangles_as_labelled_faces() {
    for name in ["tet_cube.vtu", "tet_cube_42bin.vtk"] {
        let g = read(name);
        let c = summary(&g);
        assert_eq!(c.darts, 48 * 24, "{name}");
        assert_eq!(c.cells[0], 27);
        assert_eq!(c.cells[3], 48);
        assert_eq!(c.cells[0] as i64 - c.cells[1] as i64 + c.cells[2] as i64 - c.cells[3] as i64, 1);
        let (_, labels, _) = to_dense_labels(&g);
        let tagged = |dim: usize, v: i64| {
            labels.of[dim].iter().filter(|l| l.get("physical") == Some(&LabelValue::Int(v))).count()
        };
        assert_eq!(tagged(3, 1), 48, "{name}");
        assert_eq!(tagged(2, 2), 48, "{name}");
        let _ = cell_labels;
    }
}

#[test]
fn appended_raw_and_zlib_and_polyhedra() {
    for name in ["ring_raw.vtu", "ring_zlib.vtu"] {
        let g = read(name);
        let c = summary(&g);
        assert_eq!(c.cells, vec![32, 64, 40, 8], "{name}");
        let (_, labels, _) = to_dense_labels(&g);
        let mut ids: Vec<String> = labels.of[3].iter().map(|l| l.get("index").unwrap().to_string()).collect();
        ids.sort();
        assert_eq!(ids, (0..8).map(|k| k.to_string()).collect::<Vec<_>>());
    }
    let g = read("poly.vtu");
    let c = summary(&g);
    assert_eq!(c.cells, vec![12, 20, 11, 2]);
    assert_eq!(c.darts, 96);
}

#[test]
fn gmsh_files_with_physical_tags_and_names() {
    let g = read("tet_cube.msh");
    let c = summary(&g);
    assert_eq!((c.darts, c.cells[0], c.cells[3]), (48 * 24, 27, 48));
    let (_, labels, _) = to_dense_labels(&g);
    let with =
        |dim: usize, name: &str, v: LabelValue| labels.of[dim].iter().filter(|l| l.get(name) == Some(&v)).count();
    assert_eq!(with(3, "gmsh:physical", LabelValue::Int(1)), 48);
    assert_eq!(with(3, "gmsh:physical_name", LabelValue::Text("solid".into())), 48);
    assert_eq!(with(2, "gmsh:physical", LabelValue::Int(2)), 48);
    assert_eq!(with(2, "gmsh:physical_name", LabelValue::Text("boundary".into())), 48);
    // interior faces carry no label
    assert_eq!(labels.of[2].iter().filter(|l| l.is_empty()).count(), c.cells[2] - 48);

    let g = read("mixed.msh");
    let c = summary(&g);
    assert_eq!(c.cells, vec![12, 24, 17, 4]);
    let (_, labels, _) = to_dense_labels(&g);
    let mut tags: Vec<String> = labels.of[3].iter().map(|l| l.get("gmsh:physical").unwrap().to_string()).collect();
    tags.sort();
    assert_eq!(tags, ["1", "2", "3", "4"]);

    let c = summary(&read("ring.msh"));
    assert_eq!(c.cells, vec![32, 64, 40, 8]);
}
