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
            convert(&x, &y);
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
