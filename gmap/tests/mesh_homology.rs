//! Volume meshes written by meshio (tests/data/mesh, README there) read into maps: their
//! integer homology by the cellular method, with the cell counts, components and
//! orientability, across the `.vtk`, `.vtu` and `.msh` forms of each mesh.

use std::path::PathBuf;

use gmap::algebra::{cellular_complex, homology_z};
use gmap::core::{Characteristics, LabelledGMap};
use gmap::ops::import::read_mesh;

fn read(name: &str) -> LabelledGMap {
    let p = PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/../tests/data/mesh")).join(name);
    let r = read_mesh(&p, None).unwrap_or_else(|| panic!("{name}"));
    r.unwrap_or_else(|e| panic!("{e}"))
}

/// (cells per dimension, components, orientable, Betti numbers); the torsion must be empty.
fn analyse(name: &str) -> (Vec<usize>, usize, bool, Vec<usize>) {
    let dense = read(name).to_dense_map();
    let c = Characteristics::of(&dense);
    assert!(c.valid, "{name}");
    let cx = cellular_complex(&dense).unwrap_or_else(|e| panic!("{name}: {e}"));
    let h = homology_z(&cx.chain).unwrap();
    assert!(h.torsion.iter().all(Vec::is_empty), "{name}: {:?}", h.torsion);
    (c.cells, c.components, c.orientable, h.betti)
}

#[test]
fn a_hexahedral_block_with_a_cavity_is_a_ball_minus_a_ball() {
    for name in ["hex_hollow.vtu", "hex_hollow_ascii.vtu", "hex_hollow.vtk", "hex_hollow_42.vtk"] {
        assert_eq!(analyse(name), (vec![64, 144, 108, 26], 1, true, vec![1, 0, 1, 0]), "{name}");
    }
}

#[test]
fn a_tetrahedral_cube_is_a_ball() {
    for name in ["tet_cube.msh", "tet_cube.vtu", "tet_cube_42bin.vtk"] {
        let (cells, comps, orientable, betti) = analyse(name);
        assert_eq!((cells[0], cells[3], comps, orientable), (27, 48, 1, true), "{name}");
        assert_eq!(betti, vec![1, 0, 0, 0], "{name}");
    }
}

#[test]
fn a_mixed_mesh_is_a_ball() {
    for name in ["mixed.vtu", "mixed.vtk", "mixed_42.vtk", "mixed.msh"] {
        assert_eq!(analyse(name), (vec![12, 24, 17, 4], 1, true, vec![1, 0, 0, 0]), "{name}");
    }
    assert_eq!(analyse("poly.vtu"), (vec![12, 20, 11, 2], 1, true, vec![1, 0, 0, 0]));
}

#[test]
fn a_ring_of_hexahedra_is_a_solid_torus() {
    for name in ["ring.msh", "ring_raw.vtu", "ring_zlib.vtu"] {
        assert_eq!(analyse(name), (vec![32, 64, 40, 8], 1, true, vec![1, 1, 0, 0]), "{name}");
    }
}

#[test]
fn the_facade_opens_meshes_with_their_labels() {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/../tests/data/mesh/");
    for (name, betti) in
        [("hex_hollow.vtu", vec![1, 0, 1, 0]), ("ring.msh", vec![1, 1, 0, 0]), ("mixed.vtk", vec![1, 0, 0, 0])]
    {
        let input = gmap::open(format!("{dir}{name}")).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!((input.kind(), input.dim()), ("map", 3), "{name}");
        let report = gmap::homology(&input, &gmap::HomologyOptions::default()).unwrap();
        assert_eq!(report.groups.betti, betti, "{name}");
        let gmap::Input::Map(m) = &input else { panic!("{name}") };
        let (dense, labels) = m.dense_labels().expect("meshes keep their labels").unwrap();
        assert_eq!(&dense, m.map(), "{name}");
        assert!(!labels.is_empty() || name == "ring.msh", "{name}");
    }
    let e = gmap::open(format!("{dir}hex_hollow.vtu").as_str().replace("hex_hollow", "no_such_file")).unwrap_err();
    assert!(e.to_string().contains("no_such_file.vtu"), "{e}");
}
