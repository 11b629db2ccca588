//! `.vtk → .gmap → .vtk` keeps the cells and the data, and meshio (when python3 has it)
//! reads the `.vtk` we write with the cell types, counts and data it should.

use std::path::{Path, PathBuf};
use std::process::Command;

use gmap_core::io::{read_labelled_gmap, write_labelled_gmap};
use gmap_core::{to_dense_labels, DenseLabels, DenseMap, LabelledGMap};
use gmap_ops::export::write_vtk_with_labels;
use gmap_ops::import::{read_msh, read_vtk, read_vtu};

fn data(name: &str) -> PathBuf {
    PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/../tests/data/mesh")).join(name)
}

fn read(p: &Path) -> LabelledGMap {
    let r = match p.extension().and_then(|e| e.to_str()) {
        Some("vtk") => read_vtk(p, None),
        Some("vtu") => read_vtu(p, None),
        _ => read_msh(p, None),
    };
    r.unwrap_or_else(|e| panic!("{e}"))
}

/// The cell counts and, per dimension, the sorted texts of the labels.
fn content(g: &LabelledGMap) -> (Vec<usize>, Vec<Vec<String>>) {
    let (d, labels, _): (DenseMap, DenseLabels, _) = to_dense_labels(g);
    let texts = labels
        .of
        .iter()
        .map(|v| {
            let mut t: Vec<String> = v.iter().map(|l| l.to_string()).collect();
            t.sort();
            t
        })
        .collect();
    (d.cell_counts(), texts)
}

#[test]
fn vtk_to_gmap_to_vtk_keeps_cells_and_data() {
    let dir = tempfile::tempdir().unwrap();
    for name in ["hex_hollow_42.vtk", "tet_cube.msh", "mixed.vtu", "poly.vtu", "ring_zlib.vtu"] {
        let first = read(&data(name));
        let want = content(&first);
        let gmap = dir.path().join("m.gmap");
        write_labelled_gmap(&first, &gmap).unwrap();
        let again = read_labelled_gmap(&gmap).unwrap();
        assert_eq!(content(&again), want, "{name}: .gmap");
        let (d, labels, _) = to_dense_labels(&again);
        let vtk = dir.path().join("m.vtk");
        write_vtk_with_labels(&d, &labels, &vtk).unwrap();
        assert_eq!(content(&read(&vtk)), want, "{name}: .vtk");
    }
}

#[test]
fn meshio_reads_what_we_write() {
    let has = Command::new("python3").args(["-c", "import meshio"]).output().is_ok_and(|o| o.status.success());
    if !has {
        println!("meshio_reads_what_we_write: skipped, python3 has no meshio (pip install meshio)");
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    // (fixture, points, the cell blocks meshio must find, a cell data array); labelled
    // faces and vertices are cells of their own in the .vtk
    type Case<'a> = (&'a str, usize, &'a [(&'a str, usize)], &'a str);
    let cases: &[Case] = &[
        ("hex_hollow.vtu", 64, &[("hexahedron", 26), ("vertex", 64)], "region"),
        ("tet_cube.msh", 27, &[("tetra", 48), ("triangle", 48)], "gmsh:physical"),
        ("mixed.msh", 12, &[("hexahedron", 1), ("pyramid", 1), ("wedge", 1), ("tetra", 1)], "gmsh:geometrical"),
        ("ring_raw.vtu", 32, &[("hexahedron", 8)], "index"),
    ];
    for &(name, points, blocks, array) in cases {
        let g = read(&data(name));
        // texts included: they are integer ranks and a table, which meshio reads
        let (d, labels, _) = to_dense_labels(&g);
        let out = dir.path().join(format!("{name}.vtk"));
        write_vtk_with_labels(&d, &labels, &out).unwrap();
        let script = "import sys, meshio\nm = meshio.read(sys.argv[1])\nprint(len(m.points))\n\
                      print(' '.join(f'{c.type}:{len(c.data)}' for c in m.cells))\n\
                      print(' '.join(sorted(m.cell_data)))";
        let o = Command::new("python3").args(["-c", script, out.to_str().unwrap()]).output().unwrap();
        assert!(o.status.success(), "{name}: meshio: {}", String::from_utf8_lossy(&o.stderr));
        let text = String::from_utf8(o.stdout).unwrap();
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(lines[0], points.to_string(), "{name}");
        for (kind, count) in blocks {
            let total: usize = lines[1]
                .split(' ')
                .filter_map(|b| b.split_once(':'))
                .filter(|(k, _)| k == kind)
                .map(|(_, n)| n.parse::<usize>().unwrap())
                .sum();
            assert_eq!(total, *count, "{name}: {kind} in {}", lines[1]);
        }
        assert!(lines[2].split(' ').any(|a| a == array), "{name}: {}", lines[2]);
    }
}

/// Inputs the fuzz targets found (tests/data/mesh/fuzz): a `.vtu` array without a name
/// (refused by the reader; a label of empty name, which the legacy writer cannot name, is
/// refused by the writer, not written broken), and a `.msh` whose labels the writer orders
/// otherwise (the same labels come back).
#[test]
fn fuzz_findings() {
    let e = read_vtu(&data("fuzz/vtu_empty_name.vtu"), None).unwrap_err().to_string();
    assert!(e.ends_with("line 7: a DataArray of CellData without a Name: labels are named"), "{e}");
    let mesh = gmap_ops::mesh::Mesh {
        points: vec![[0.0; 3]],
        cells: vec![gmap_ops::mesh::MeshCell { kind: gmap_ops::mesh::CellKind::Vertex, nodes: vec![0], faces: vec![] }],
        point_data: vec![],
        cell_data: vec![gmap_ops::mesh::DataArray {
            name: String::new(),
            values: vec![Some(gmap_core::LabelValue::Int(1))],
        }],
    };
    let g = mesh.to_gmap(10).unwrap();
    let (d, labels, _) = to_dense_labels(&g);
    assert!(labels.of.iter().flatten().any(|l| l.get("").is_some()));
    assert_eq!(
        gmap_ops::export::vtk_string_with_labels(&d, &labels).unwrap_err().to_string(),
        "a label has an empty name: .vtk names every data array"
    );
    let dir = tempfile::tempdir().unwrap();
    let g = read_msh(&data("fuzz/msh_label_order.msh"), None).unwrap();
    let (d, labels, _) = to_dense_labels(&g);
    let vtk = dir.path().join("m.vtk");
    write_vtk_with_labels(&d, &labels, &vtk).unwrap();
    let sets = |g: &LabelledGMap| -> Vec<Vec<String>> {
        let (_, labels, _) = to_dense_labels(g);
        labels
            .of
            .iter()
            .map(|v| {
                let mut cells: Vec<String> = v
                    .iter()
                    .map(|l| {
                        let mut t: Vec<String> = l.iter().map(|(n, v)| format!("{n}={v}")).collect();
                        t.sort();
                        t.join(" ")
                    })
                    .collect();
                cells.sort();
                cells
            })
            .collect()
    };
    assert_eq!(sets(&read(&vtk)), sets(&g));
}
