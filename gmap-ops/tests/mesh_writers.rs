//! The mesh writers (`.vtk`, `.vtu`, `.msh`): cells of positive volume by an independent
//! computation, refusals of what a mesh file cannot hold (slits, digons), and a property
//! test over randomly edited maps that every output reads back with the same cells and
//! labels.

use gmap_core::{AlphaSet, Dart, DenseLabels, DenseMap, GMap, LabelValue, Labels, Point};
use gmap_ops::build;
use gmap_ops::euler::random::{random_steps, Operator};
use gmap_ops::export::{msh_bytes_with_labels, vtk_string_with_labels, vtu_bytes_with_labels, ExportError};
use gmap_ops::import::{parse_msh, parse_vtk, parse_vtu};
use gmap_ops::mesh::{CellKind, Mesh};
use gmap_ops::rng::SplitMix64;
use proptest::prelude::*;

fn no_labels(m: &DenseMap) -> DenseLabels {
    DenseLabels { of: (0..=m.dim()).map(|i| vec![Labels::new(); m.cells(i).len()]).collect() }
}

/// The outward faces of VTK's (and Gmsh's) linear volumes in their corner order, written
/// from VTK's reference cells (a positive volume where these faces point out).
fn reference_faces(kind: CellKind) -> &'static [&'static [usize]] {
    match kind {
        CellKind::Tetra => &[&[0, 2, 1], &[0, 1, 3], &[1, 2, 3], &[2, 0, 3]],
        CellKind::Pyramid => &[&[0, 3, 2, 1], &[0, 1, 4], &[1, 2, 4], &[2, 3, 4], &[3, 0, 4]],
        CellKind::Wedge => &[&[0, 2, 1], &[3, 4, 5], &[0, 1, 4, 3], &[1, 2, 5, 4], &[2, 0, 3, 5]],
        CellKind::Hexahedron => {
            &[&[0, 3, 2, 1], &[4, 5, 6, 7], &[0, 1, 5, 4], &[1, 2, 6, 5], &[2, 3, 7, 6], &[3, 0, 4, 7]]
        }
        _ => &[],
    }
}

/// The signed volume of a cell by the divergence theorem over its faces (fans from each
/// face's first corner), relative to the cell's centroid.
fn volume(faces: &[Vec<Point>]) -> f64 {
    let all: Vec<Point> = faces.iter().flatten().copied().collect();
    let c = [0, 1, 2].map(|a| all.iter().map(|p| p[a]).sum::<f64>() / all.len() as f64);
    let sub = |p: Point| [p[0] - c[0], p[1] - c[1], p[2] - c[2]];
    let mut v = 0.0;
    for f in faces {
        for k in 1..f.len() - 1 {
            let (a, b, d) = (sub(f[0]), sub(f[k]), sub(f[k + 1]));
            v += a[0] * (b[1] * d[2] - b[2] * d[1]) - a[1] * (b[0] * d[2] - b[2] * d[0])
                + a[2] * (b[0] * d[1] - b[1] * d[0]);
        }
    }
    v / 6.0
}

/// The volume of every volume cell of a mesh as read.
fn volumes(mesh: &Mesh) -> Vec<(CellKind, f64)> {
    mesh.cells
        .iter()
        .filter(|c| c.kind.dim() == 3)
        .map(|c| {
            let faces: Vec<Vec<Point>> = if c.kind == CellKind::Polyhedron {
                c.faces.iter().map(|f| f.iter().map(|&v| mesh.points[v as usize]).collect()).collect()
            } else {
                reference_faces(c.kind)
                    .iter()
                    .map(|f| f.iter().map(|&k| mesh.points[c.nodes[k] as usize]).collect())
                    .collect()
            };
            (c.kind, volume(&faces))
        })
        .collect()
}

/// `k` wedges: the extrusion of `k` triangles around the origin.
fn wedges(k: usize) -> DenseMap {
    let mut g = GMap::new(2);
    for j in 0..k {
        let a = std::f64::consts::TAU * j as f64 / k as f64;
        let b = std::f64::consts::TAU * (j + 1) as f64 / k as f64;
        g.make_polygon(&[[a.cos(), a.sin()], [2.0 * a.cos(), 2.0 * a.sin()], [2.0 * b.cos(), 2.0 * b.sin()]]);
    }
    build::extrude(&g.to_dense_map()).unwrap()
}

#[test]
fn every_volume_is_written_with_a_positive_volume() {
    let prism = |k| build::extrude(&build::polygon(k).unwrap()).unwrap();
    let grid = build::placed::grid_with_points(&[2, 2, 1], &[false; 3]).unwrap();
    let mut tet = GMap::new(3);
    tet.make_tetrahedron([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]);
    let cases = [
        (prism(3), CellKind::Wedge),
        (prism(4), CellKind::Hexahedron),
        (prism(6), CellKind::Polyhedron),
        (grid, CellKind::Hexahedron),
        (wedges(7), CellKind::Wedge),
        (tet.to_dense_map(), CellKind::Tetra),
    ];
    for (m, kind) in cases {
        let l = no_labels(&m);
        let vtk = parse_vtk(vtk_string_with_labels(&m, &l).unwrap().as_bytes()).unwrap();
        let vtu = parse_vtu(&vtu_bytes_with_labels(&m, &l).unwrap()).unwrap();
        let mut read = vec![vtk, vtu];
        if kind != CellKind::Polyhedron {
            let msh = msh_bytes_with_labels(&m, &l, false).unwrap();
            read.push(parse_msh(&msh).unwrap().mesh);
        }
        for mesh in read {
            let v = volumes(&mesh);
            assert_eq!(v.len(), m.cells(3).len());
            for (k, x) in v {
                assert_eq!(k, kind);
                assert!(x > 1e-9, "{kind:?}: volume {x}");
            }
        }
    }
}

/// The grid of 3×3×3 unit cubes with the face between the middle cube and its neighbour
/// in +x unsewn: every vertex and edge of that face stays shared, so the map has two faces
/// on the same four vertices and a cavity (H₂ = Z).
fn slit_box() -> DenseMap {
    let mut m = build::placed::grid_with_points(&[3, 3, 3], &[false; 3]).unwrap();
    let inside = |p: Point| (p[0] - 2.0).abs() < 1e-9 && (1.0..=2.0).contains(&p[1]) && (1.0..=2.0).contains(&p[2]);
    let darts: Vec<Dart> = m
        .darts()
        .filter(|&d| {
            !m.is_free(d, 3) && m.orbit(d, AlphaSet::of(&[0, 1])).iter().all(|&e| inside(m.vertex_point(e).unwrap()))
        })
        .collect();
    assert_eq!(darts.len(), 16);
    for d in darts {
        if !m.is_free(d, 3) {
            m.unlink(d, 3);
        }
    }
    assert_eq!(m.cell_counts(), vec![64, 144, 109, 27]);
    m
}

#[test]
fn a_slit_is_refused_by_every_writer() {
    let m = slit_box();
    let l = no_labels(&m);
    let why = |e: ExportError| {
        let s = e.to_string();
        assert!(s.contains("on the same vertices") && s.contains("slit"), "{s}");
    };
    why(vtk_string_with_labels(&m, &l).unwrap_err());
    why(vtu_bytes_with_labels(&m, &l).unwrap_err());
    why(msh_bytes_with_labels(&m, &l, false).unwrap_err());
}

/// A volume with two faces of two corners (the prism over a digon), as an edge contraction
/// leaves in a volume with a triangle: a mesh face needs three corners.
#[test]
fn a_digon_is_refused() {
    let m = build::extrude(&build::polygon(2).unwrap()).unwrap();
    assert_eq!(m.cell_counts(), vec![4, 6, 4, 1]);
    let l = no_labels(&m);
    for e in [
        vtk_string_with_labels(&m, &l).unwrap_err(),
        vtu_bytes_with_labels(&m, &l).unwrap_err(),
        msh_bytes_with_labels(&m, &l, false).unwrap_err(),
    ] {
        assert!(e.to_string().contains("a face of 2 corners"), "{e}");
    }
}

#[test]
fn names_are_integer_columns_with_a_table_of_texts() {
    let m = build::placed::grid_with_points(&[2, 1, 1], &[false; 3]).unwrap();
    let mut l = no_labels(&m);
    for (c, name) in [(0, "left"), (1, "right side")] {
        l.of[3][c].set("gmsh:physical", LabelValue::Int(7 + c as i64));
        l.of[3][c].set("gmsh:physical_name", LabelValue::Text(name.into()));
    }
    l.of[2][3].set("w", LabelValue::Real(0.25));
    let text = vtk_string_with_labels(&m, &l).unwrap();
    assert!(!text.contains(" string\n"), "{text}");
    assert!(text.contains("gmsh:physical_name 1 3 int\n0\n1\n-1\n"), "{text}");
    for bytes in [text.into_bytes(), vtu_bytes_with_labels(&m, &l).unwrap()] {
        let mesh = if bytes.starts_with(b"#") { parse_vtk(&bytes).unwrap() } else { parse_vtu(&bytes).unwrap() };
        let names = mesh.cell_data.iter().find(|a| a.name == "gmsh:physical_name").unwrap();
        assert_eq!(
            names.values,
            vec![Some(LabelValue::Text("left".into())), Some(LabelValue::Text("right side".into())), None]
        );
    }
    let msh = String::from_utf8(msh_bytes_with_labels(&m, &l, false).unwrap()).unwrap();
    assert!(msh.contains("$PhysicalNames\n2\n3 7 \"left\"\n3 8 \"right side\"\n$EndPhysicalNames\n"), "{msh}");
    let back = parse_msh(msh.as_bytes()).unwrap().mesh;
    let w = back.cell_data.iter().find(|a| a.name == "w").unwrap();
    assert_eq!(w.values.iter().flatten().collect::<Vec<_>>(), vec![&LabelValue::Real(0.25)]);
    // a text other than a physical name has no place in .msh
    l.of[2][3].set("w", LabelValue::Text("x".into()));
    assert!(msh_bytes_with_labels(&m, &l, false).unwrap_err().to_string().contains("physical names"));
}

/// Labels a map as the tests do: volumes (or top cells) in two physical groups with names,
/// a real on some faces.
fn label(m: &DenseMap, seed: u64) -> DenseLabels {
    let mut l = no_labels(m);
    let n = m.dim();
    for c in 0..l.of[n].len() {
        let p = 1 + (c as u64 + seed) % 2;
        l.of[n][c].set("gmsh:physical", LabelValue::Int(p as i64));
        l.of[n][c].set("gmsh:physical_name", LabelValue::Text(format!("group {p}")));
    }
    if n >= 1 {
        for c in (0..l.of[n - 1].len()).step_by(3) {
            l.of[n - 1][c].set("w", LabelValue::Real(c as f64 + 0.5));
        }
    }
    l
}

/// The labels of each dimension as sorted lists, sorted (numbers as reals: `.msh`).
fn label_sets(m: &DenseMap, l: &DenseLabels, reals: bool, skip_geometrical: bool) -> Vec<Vec<Vec<String>>> {
    (0..=m.dim())
        .map(|i| {
            let mut v: Vec<Vec<String>> =
                l.of.get(i)
                    .map(|cells| {
                        cells
                            .iter()
                            .map(|x| {
                                let mut s: Vec<String> = x
                                    .iter()
                                    .filter(|(n, _)| !(skip_geometrical && *n == "gmsh:geometrical"))
                                    .map(|(n, v)| match v {
                                        LabelValue::Int(k) if reals && n == "w" => format!("{n}={:?}", *k as f64),
                                        v => format!("{n}={v:?}"),
                                    })
                                    .collect();
                                s.sort();
                                s
                            })
                            .filter(|s| !s.is_empty())
                            .collect()
                    })
                    .unwrap_or_default();
            v.sort();
            v
        })
        .collect()
}

/// Writes `m` in every format; each output that is written reads back with the same cells
/// and labels. Returns how many writes were refused.
fn every_writer_reads_back(m: &DenseMap, l: &DenseLabels) -> usize {
    let mut refused = 0;
    let outputs: Vec<(&str, Result<Mesh, ExportError>)> = vec![
        (".vtk", vtk_string_with_labels(m, l).map(|t| parse_vtk(t.as_bytes()).unwrap())),
        (".vtu", vtu_bytes_with_labels(m, l).map(|b| parse_vtu(&b).unwrap())),
        (".msh", msh_bytes_with_labels(m, l, false).map(|b| parse_msh(&b).unwrap().mesh)),
    ];
    for (format, out) in outputs {
        let mesh = match out {
            Ok(mesh) => mesh,
            Err(ExportError::MeshWrite { .. } | ExportError::VertexPoint { .. }) => {
                refused += 1;
                continue;
            }
            Err(e) => panic!("{format}: {e}"),
        };
        let g = mesh.to_gmap(u64::MAX).unwrap();
        let (back, back_labels, _) = gmap_core::to_dense_labels(&g);
        assert_eq!(back.cell_counts(), m.cell_counts(), "{format}");
        assert_eq!(back.dart_count(), m.dart_count(), "{format}");
        assert!(gmap_ops::iso::are_isomorphic(&back, m), "{format}");
        let msh = format == ".msh";
        assert_eq!(label_sets(&back, &back_labels, msh, msh), label_sets(m, l, msh, msh), "{format}");
    }
    refused
}

#[test]
fn standard_maps_are_written_by_every_writer() {
    for m in [
        build::placed::grid_with_points(&[2, 2, 2], &[false; 3]).unwrap(),
        build::extrude(&build::polygon(3).unwrap()).unwrap(),
        build::placed::grid_with_points(&[3, 2], &[false; 2]).unwrap(),
        wedges(5),
    ] {
        assert_eq!(every_writer_reads_back(&m, &label(&m, 0)), 0);
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, ..ProptestConfig::default() })]

    /// Random Euler operators, unsewing and contraction on a grid or an extruded polygon:
    /// every write either reads back the same or is refused with its reason.
    #[test]
    fn random_edited_maps_read_back_or_are_refused(seed in 0u64..10_000, base in 0usize..3, steps in 0usize..6, unsew in any::<bool>()) {
        let start = match base {
            0 => build::placed::grid_with_points(&[2, 2, 1], &[false; 3]).unwrap(),
            1 => build::extrude(&build::polygon(3 + (seed % 4) as usize).unwrap()).unwrap(),
            _ => build::placed::grid_with_points(&[3, 2], &[false; 2]).unwrap(),
        };
        let (mut g, _) = GMap::from_dense(&start);
        let mut rng = SplitMix64::new(seed);
        let ops = [Operator::InsertVertex, Operator::InsertEdge, Operator::SplitCell, Operator::ContractCell, Operator::RemoveCell];
        random_steps(&mut g, steps, &ops, &mut rng);
        let mut m: DenseMap = g.to_dense_map();
        if unsew && m.dart_count() > 0 {
            let n = m.dim();
            let sewn: Vec<Dart> = m.darts().filter(|&d| !m.is_free(d, n)).collect();
            if !sewn.is_empty() {
                let d = sewn[(seed as usize) % sewn.len()];
                let facet: Vec<usize> = (0..n - 1).collect();
                for e in m.orbit(d, AlphaSet::of(&facet)) {
                    if !m.is_free(e, n) {
                        m.unlink(e, n);
                    }
                }
            }
        }
        prop_assume!(m.validate().is_ok());
        let l = label(&m, seed);
        every_writer_reads_back(&m, &l);
    }
}

/// The cell blocks and point count meshio reads from `bytes` written to a file named
/// `name`, `None` where python3 has no meshio.
fn meshio_cells(bytes: &[u8], name: &str) -> Option<String> {
    let has = std::process::Command::new("python3").args(["-c", "import meshio"]).output();
    if !has.is_ok_and(|o| o.status.success()) {
        eprintln!("meshio is not installed: the comparison with meshio is skipped");
        return None;
    }
    let dir = std::env::temp_dir().join(format!("gmap-mesh-writers-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, bytes).unwrap();
    let script = "import sys, meshio\nm = meshio.read(sys.argv[1])\n\
                  print(len(m.points), ' '.join(f'{c.type}:{len(c.data)}' for c in m.cells), \
                  sorted((k, v.tolist()) for k, v in m.field_data.items() if not k.startswith('gmap:')))";
    let o = std::process::Command::new("python3").args(["-c", script, path.to_str().unwrap()]).output().unwrap();
    std::fs::remove_dir_all(&dir).unwrap();
    assert!(o.status.success(), "meshio: {}", String::from_utf8_lossy(&o.stderr));
    Some(String::from_utf8(o.stdout).unwrap().trim().to_string())
}

#[test]
fn meshio_reads_the_binary_and_ascii_msh_alike() {
    let m = build::placed::grid_with_points(&[2, 1, 1], &[false; 3]).unwrap();
    let mut l = label(&m, 0);
    // meshio's Gmsh reader wants a physical group on every entity: the labelled faces too
    for c in (0..l.of[2].len()).step_by(3) {
        l.of[2][c].set("gmsh:physical", LabelValue::Int(3));
    }
    let ascii = msh_bytes_with_labels(&m, &l, false).unwrap();
    let binary = msh_bytes_with_labels(&m, &l, true).unwrap();
    assert!(binary.starts_with(b"$MeshFormat\n4.1 1 8\n\x01\0\0\0\n$EndMeshFormat\n"));
    let (Some(a), Some(b)) = (meshio_cells(&ascii, "a.msh"), meshio_cells(&binary, "b.msh")) else { return };
    assert_eq!(a, b);
    assert_eq!(a, "12 hexahedron:1 hexahedron:1 quad:4 [('group 1', [1, 3]), ('group 2', [2, 3])]");
    for (bytes, name) in [
        (vtk_string_with_labels(&m, &l).unwrap().into_bytes(), "a.vtk"),
        (vtu_bytes_with_labels(&m, &l).unwrap(), "a.vtu"),
    ] {
        let got = meshio_cells(&bytes, name).unwrap();
        assert!(got.starts_with("12 hexahedron:2 "), "{name}: {got}");
    }
}
