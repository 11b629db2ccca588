//! `gmap convert` between every pair of mesh formats (`.msh`, `.vtk`, `.vtu`, and `.off` for
//! surfaces) keeps the cells, the groups and the labels: each file of `tests/data/mesh`
//! written as A, then as B, reads back as the map and labels of the file itself.

mod common;
use common::{gmap, p, stderr};

use std::path::{Path, PathBuf};

use gmap_core::{DenseLabels, DenseMap, LabelValue};

const MESH: [&str; 3] = ["vtk", "vtu", "msh"];

fn data(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/mesh").join(name)
}

fn convert(from: &Path, to: &Path) {
    let o = gmap(&["convert", p(from), p(to)]);
    assert!(o.status.success(), "{} -> {}: {}", from.display(), to.display(), stderr(&o));
}

/// The map and labels of a file, through `gmap convert FILE X.gmap`.
fn read(path: &Path, dir: &Path) -> (DenseMap, DenseLabels) {
    let g = dir.join("read.gmap");
    convert(path, &g);
    let lg = gmap_core::io::read_labelled_gmap(&g).unwrap();
    let (m, l, _) = gmap_core::to_dense_labels(&lg);
    (m, l)
}

/// The labels of each dimension as sorted lists, sorted; through `.msh` (`gmsh`), numbers
/// other than the Gmsh tags as reals, and `gmsh:geometrical` left out where the file had
/// none (each element of a `.msh` is on an entity).
fn label_sets(l: &DenseLabels, gmsh: bool, geometrical: bool) -> Vec<Vec<Vec<String>>> {
    l.of.iter()
        .map(|cells| {
            let mut v: Vec<Vec<String>> = cells
                .iter()
                .map(|x| {
                    let mut s: Vec<String> = x
                        .iter()
                        .filter(|(n, _)| geometrical || *n != "gmsh:geometrical")
                        .map(|(n, v)| match v {
                            LabelValue::Int(k) if gmsh && !n.starts_with("gmsh:") => {
                                format!("{n}={:?}", LabelValue::Real(*k as f64))
                            }
                            v => format!("{n}={v:?}"),
                        })
                        .collect();
                    s.sort();
                    s
                })
                .filter(|s| !s.is_empty())
                .collect();
            v.sort();
            v
        })
        .collect()
}

#[test]
fn every_pair_of_mesh_formats_keeps_cells_groups_and_labels() {
    let dir = tempfile::tempdir().unwrap();
    let mut pairs = 0;
    for name in ["tet_cube.msh", "mixed.msh", "ring.msh", "hex_hollow.vtu", "mixed.vtu", "tet_cube.vtu"] {
        let src = data(name);
        let (m, l) = read(&src, dir.path());
        let had_geometrical = l.of.iter().flatten().any(|x| x.get("gmsh:geometrical").is_some());
        for a in MESH {
            for b in MESH {
                let (x, y) = (dir.path().join(format!("a.{a}")), dir.path().join(format!("b.{b}")));
                convert(&src, &x);
                convert(&x, &y);
                let (m2, l2) = read(&y, dir.path());
                let what = format!("{name} -> .{a} -> .{b}");
                assert_eq!(m2.cell_counts(), m.cell_counts(), "{what}");
                assert!(gmap_ops::iso::are_isomorphic(&m, &m2), "{what}");
                let gmsh = a == "msh" || b == "msh";
                assert_eq!(
                    label_sets(&l2, gmsh, had_geometrical || !gmsh),
                    label_sets(&l, gmsh, had_geometrical || !gmsh),
                    "{what}"
                );
                pairs += 1;
            }
        }
    }
    assert_eq!(pairs, 6 * 9);
    // the physical groups and their names, through every format
    let (_, l) = read(&data("tet_cube.msh"), dir.path());
    let named = |l: &DenseLabels, dim: usize, name: &str| {
        l.of[dim].iter().filter(|x| x.get("gmsh:physical_name") == Some(&LabelValue::Text(name.into()))).count()
    };
    assert_eq!((named(&l, 3, "solid"), named(&l, 2, "boundary")), (48, 48));
}

#[test]
fn a_surface_goes_through_off_and_every_mesh_format() {
    let dir = tempfile::tempdir().unwrap();
    let off = dir.path().join("cube.off");
    std::fs::write(
        &off,
        "OFF\n8 6 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n\
         4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n",
    )
    .unwrap();
    let (m, _) = read(&off, dir.path());
    assert_eq!(m.cell_counts(), vec![8, 12, 6]);
    for a in MESH {
        let x = dir.path().join(format!("s.{a}"));
        convert(&off, &x);
        for b in MESH.iter().chain(&["off"]) {
            let y = dir.path().join(format!("t.{b}"));
            if a == "msh" && *b == "off" {
                // every element of a .msh is on an entity (gmsh:geometrical), a label .off drops
                let o = gmap(&["convert", "--lossy", p(&x), p(&y)]);
                assert!(o.status.success() && stderr(&o).contains("drops the labels"), "{}", stderr(&o));
            } else {
                convert(&x, &y);
            }
            let (m2, _) = read(&y, dir.path());
            assert!(gmap_ops::iso::are_isomorphic(&m, &m2), ".off -> .{a} -> .{b}");
        }
    }
}

#[test]
fn a_polyhedron_is_refused_by_msh_with_the_reason() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("poly.msh");
    // two cubes given as polyhedra are hexahedra: written as such
    convert(&data("poly.vtu"), &out);
    // a pentagonal prism has no Gmsh element
    let g = dir.path().join("prism.gmap");
    let prism = gmap_ops::build::extrude(&gmap_ops::build::polygon(5).unwrap()).unwrap();
    gmap_core::io::write_gmap(&prism, &g).unwrap();
    let o = gmap(&["convert", p(&g), p(&out)]);
    assert_eq!(o.status.code(), Some(1));
    assert!(stderr(&o).contains("a polyhedron of 7 faces, which Gmsh has no element for"), "{}", stderr(&o));
    let vtu = dir.path().join("prism.vtu");
    convert(&g, &vtu);
}

/// The volumes of the cells of a `.vtk` as gmap reads it, by the divergence theorem over
/// VTK's outward faces of a wedge (the only type in the files below).
fn wedge_volumes(vtk: &Path) -> Vec<f64> {
    let mesh = gmap_ops::import::parse_vtk(&std::fs::read(vtk).unwrap()).unwrap();
    let faces: [&[usize]; 5] = [&[0, 2, 1], &[3, 4, 5], &[0, 1, 4, 3], &[1, 2, 5, 4], &[2, 0, 3, 5]];
    mesh.cells
        .iter()
        .filter(|c| c.kind == gmap_ops::mesh::CellKind::Wedge)
        .map(|c| {
            let pt = |k: usize| mesh.points[c.nodes[k] as usize];
            let mut v = 0.0;
            for f in faces {
                for k in 1..f.len() - 1 {
                    let (a, b, d) = (pt(f[0]), pt(f[k]), pt(f[k + 1]));
                    v += a[0] * (b[1] * d[2] - b[2] * d[1]) - a[1] * (b[0] * d[2] - b[2] * d[0])
                        + a[2] * (b[0] * d[1] - b[1] * d[0]);
                }
            }
            v / 6.0
        })
        .collect()
}

#[test]
fn wedges_are_written_with_a_positive_volume() {
    let dir = tempfile::tempdir().unwrap();
    let g = dir.path().join("prism.gmap");
    gmap_core::io::write_gmap(&gmap_ops::build::extrude(&gmap_ops::build::polygon(3).unwrap()).unwrap(), &g).unwrap();
    let vtk = dir.path().join("prism.vtk");
    convert(&g, &vtk);
    let v = wedge_volumes(&vtk);
    assert_eq!(v.len(), 1);
    // the prism over the triangle inscribed in the unit circle, of height 1
    assert!((v[0] - 3.0 * 3f64.sqrt() / 4.0).abs() < 1e-9, "{v:?}");
}

#[test]
fn a_slit_box_is_refused_not_closed() {
    // 3×3×3 unit cubes, the face between the middle cube and its +x neighbour unsewn: a
    // cavity (H₂ = Z) whose two faces lie on the same vertices
    let mut m = gmap_ops::build::placed::grid_with_points(&[3, 3, 3], &[false; 3]).unwrap();
    let inside =
        |p: gmap_core::Point| (p[0] - 2.0).abs() < 1e-9 && (1.0..=2.0).contains(&p[1]) && (1.0..=2.0).contains(&p[2]);
    let face: Vec<gmap_core::Dart> = m
        .darts()
        .filter(|&d| m.orbit(d, gmap_core::AlphaSet::of(&[0, 1])).iter().all(|&e| inside(m.vertex_point(e).unwrap())))
        .collect();
    for d in face {
        if !m.is_free(d, 3) {
            m.unlink(d, 3);
        }
    }
    let dir = tempfile::tempdir().unwrap();
    let g = dir.path().join("slit.gmap");
    gmap_core::io::write_gmap(&m, &g).unwrap();
    let o = gmap(&["homology", p(&g)]);
    assert!(String::from_utf8_lossy(&o.stdout).contains("H_2 = Z\n"), "{}", String::from_utf8_lossy(&o.stdout));
    for ext in MESH {
        let out = dir.path().join(format!("slit.{ext}"));
        let o = gmap(&["convert", p(&g), p(&out)]);
        assert_eq!(o.status.code(), Some(1), ".{ext}: {}", stderr(&o));
        assert!(stderr(&o).contains("on the same vertices") && stderr(&o).contains("slit"), "{}", stderr(&o));
        assert!(!out.exists());
    }
}

#[test]
fn a_digon_face_is_refused_not_written() {
    let dir = tempfile::tempdir().unwrap();
    let g = dir.path().join("digon.gmap");
    gmap_core::io::write_gmap(&gmap_ops::build::extrude(&gmap_ops::build::polygon(2).unwrap()).unwrap(), &g).unwrap();
    for ext in MESH {
        let out = dir.path().join(format!("digon.{ext}"));
        let o = gmap(&["convert", p(&g), p(&out)]);
        assert_eq!(o.status.code(), Some(1), ".{ext}: {}", stderr(&o));
        assert!(stderr(&o).contains("a face of 2 corners"), "{}", stderr(&o));
    }
}

#[test]
fn convert_binary_writes_a_binary_msh_that_reads_back_the_same() {
    let dir = tempfile::tempdir().unwrap();
    for name in ["tet_cube.msh", "mixed.vtu", "hex_hollow.vtu"] {
        let src = data(name);
        let (m, l) = read(&src, dir.path());
        let (text, bin) = (dir.path().join("a.msh"), dir.path().join("b.msh"));
        convert(&src, &text);
        let o = gmap(&["convert", "--binary", p(&src), p(&bin)]);
        assert!(o.status.success(), "{name}: {}", stderr(&o));
        let bytes = std::fs::read(&bin).unwrap();
        // Gmsh's binary header: version 4.1, file type 1, data size 8, then the binary 1
        assert!(bytes.starts_with(b"$MeshFormat\n4.1 1 8\n\x01\0\0\0"), "{name}: {:?}", &bytes[..24.min(bytes.len())]);
        assert!(std::str::from_utf8(&bytes).is_err(), "{name}: binary data");
        assert_ne!(bytes, std::fs::read(&text).unwrap());
        let (m2, l2) = read(&bin, dir.path());
        assert_eq!(m2.cell_counts(), m.cell_counts(), "{name}");
        assert!(gmap_ops::iso::are_isomorphic(&m, &m2), "{name}");
        let had_geometrical = l.of.iter().flatten().any(|x| x.get("gmsh:geometrical").is_some());
        assert_eq!(label_sets(&l2, true, had_geometrical), label_sets(&l, true, had_geometrical), "{name}");
        // the binary file is the text file's mesh: both read back as the same labels
        let (_, l3) = read(&text, dir.path());
        assert_eq!(label_sets(&l2, true, true), label_sets(&l3, true, true), "{name}");
    }
    // other formats have no binary form here: refused, nothing written
    let out = dir.path().join("c.vtu");
    let o = gmap(&["convert", "--binary", p(&data("tet_cube.msh")), p(&out)]);
    assert!(!o.status.success());
    assert!(stderr(&o).contains("--binary writes .msh only, not '.vtu'"), "{}", stderr(&o));
    assert!(!out.exists());
}
