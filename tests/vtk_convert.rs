//! `gmap convert X.gmap OUT.vtk` end to end: legacy VTK unstructured grids of maps with
//! points (VTK's volume types or polyhedra for 3-maps, quadrangles and polygons for 2-maps),
//! refusals of maps without points, and a read-back by meshio when python3 has it.

mod common;
use common::{gmap, p, stderr};
use std::path::Path;
use std::process::Command;

/// The values after the line that starts with `key` (`CELLS 2 64` gives `[2, 64]`).
fn header(text: &str, key: &str) -> Vec<String> {
    let line = text.lines().find(|l| l.starts_with(key)).unwrap_or_else(|| panic!("no {key} in {text}"));
    line[key.len()..].split_whitespace().map(str::to_string).collect()
}

#[test]
fn a_cube_is_one_hexahedron() {
    let dir = tempfile::tempdir().unwrap();
    let cube = gmap_ops::build::extrude(&gmap_ops::build::polygon(4).unwrap()).unwrap();
    let g = dir.path().join("cube.moka");
    gmap_core::io::write_moka(&cube, &g).unwrap();
    let out = dir.path().join("cube.vtk");
    let o = gmap(&["convert", p(&g), p(&out)]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(&out).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines[0], "# vtk DataFile Version 3.0");
    assert_eq!(lines[2..4], ["ASCII", "DATASET UNSTRUCTURED_GRID"]);
    assert_eq!(header(&text, "POINTS "), ["8", "double"]);
    // one hexahedron: its 8 corners
    assert_eq!(header(&text, "CELLS "), ["1", "9"]);
    assert_eq!(header(&text, "CELL_TYPES "), ["1"]);
    assert_eq!(header(&text, "CELL_DATA "), ["1"]);
    assert!(text.contains("\nCELL_TYPES 1\n12\n"), "{text}");
    assert!(text.ends_with("SCALARS dim int 1\nLOOKUP_TABLE default\n3\n"), "{text}");
    let corners: Vec<usize> = lines[lines.iter().position(|l| l.starts_with("CELLS ")).unwrap() + 1]
        .split(' ')
        .map(|x| x.parse().unwrap())
        .collect();
    assert_eq!(corners[0], 8);
    let mut sorted = corners[1..].to_vec();
    sorted.sort_unstable();
    assert_eq!(sorted, (0..8).collect::<Vec<_>>());
    meshio_reads(&out, 8, &[("hexahedron", 1)]);
}

#[test]
fn a_cube_surface_is_quadrangles() {
    let dir = tempfile::tempdir().unwrap();
    // the surface of a cube, from an .off
    let off = dir.path().join("box.off");
    std::fs::write(
        &off,
        "OFF\n8 6 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n\
         4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n",
    )
    .unwrap();
    let out = dir.path().join("box.vtk");
    let o = gmap(&["convert", p(&off), p(&out)]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(&out).unwrap();
    assert_eq!(header(&text, "POINTS "), ["8", "double"]);
    assert_eq!(header(&text, "CELLS "), ["6", "30"]);
    let types: Vec<&str> = text.split("CELL_TYPES 6\n").nth(1).unwrap().lines().take(6).collect();
    assert_eq!(types, ["9"; 6]);
    assert!(text.ends_with("LOOKUP_TABLE default\n2\n2\n2\n2\n2\n2\n"), "{text}");
    meshio_reads(&out, 8, &[("quad", 6)]);
}

#[test]
fn maps_without_points_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    let g = dir.path().join("cube.gmap");
    gmap_core::io::write_gmap(&gmap_ops::build::cube(3).unwrap(), &g).unwrap();
    let out = dir.path().join("cube.vtk");
    let o = gmap(&["convert", p(&g), p(&out)]);
    assert_eq!(o.status.code(), Some(1));
    assert!(stderr(&o).starts_with("error: "), "{}", stderr(&o));
    assert!(stderr(&o).contains("no points"), "{}", stderr(&o));
    assert!(!out.exists());
}

/// Reads the file with meshio when python3 has it (nothing otherwise): the point count and
/// the cell blocks (meshio names VTK type 9 `quad`, 12 `hexahedron`).
fn meshio_reads(path: &Path, points: usize, blocks: &[(&str, usize)]) {
    let has = Command::new("python3").args(["-c", "import meshio"]).output().is_ok_and(|o| o.status.success());
    if !has {
        return;
    }
    let script = "import sys, meshio\nm = meshio.read(sys.argv[1])\nprint(len(m.points))\n\
                  print(' '.join(f'{c.type}:{len(c.data)}' for c in m.cells))";
    let o = Command::new("python3").args(["-c", script, p(path)]).output().unwrap();
    assert!(o.status.success(), "meshio: {}", stderr(&o));
    let text = String::from_utf8(o.stdout).unwrap();
    let mut lines = text.lines();
    assert_eq!(lines.next().unwrap(), points.to_string());
    let got = lines.next().unwrap_or("");
    for (kind, count) in blocks {
        assert!(got.split(' ').any(|b| b.starts_with(kind) && b.ends_with(&format!(":{count}"))), "{got}");
    }
}

#[test]
fn the_labels_of_a_gmap_become_cell_data() {
    let dir = tempfile::tempdir().unwrap();
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/labelled_segment.gmap");
    let out = dir.path().join("segment.vtk");
    let o = gmap(&["convert", p(&src), p(&out)]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(&out).unwrap();
    // the edge (the top cell), then vertex 1, the only labelled lower cell
    assert_eq!(header(&text, "CELLS "), ["2", "5"]);
    assert!(text.contains("\nCELLS 2 5\n2 0 1\n1 1\nCELL_TYPES 2\n3\n1\n"), "{text}");
    let data = text.split("CELL_DATA 2\n").nth(1).unwrap();
    assert_eq!(
        data,
        "SCALARS dim int 1\nLOOKUP_TABLE default\n1\n0\nFIELD labels 3\n\
         name 1 2 int\n0\n-1\n\
         length 1 2 double\n2.5\n-1.7976931348623157e308\n\
         hits 1 2 int\n-2147483648\n3\n"
    );
    // the name's text in the table of the dataset's field data: `main "beam"` and a NUL
    assert!(
        text.contains(
            "DATASET UNSTRUCTURED_GRID\nFIELD FieldData 1\ngmap:texts:name 1 12 unsigned_char\n\
             109 97 105 110 32 34 98 101 97 109 34 0\nPOINTS "
        ),
        "{text}"
    );
    // meshio reads it (no string array): the line and the vertex
    meshio_reads(&out, 2, &[("line", 1), ("vertex", 1)]);
}

#[test]
fn a_vtk_file_is_read_back_as_a_mesh() {
    let dir = tempfile::tempdir().unwrap();
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/labelled_segment.gmap");
    let vtk = dir.path().join("segment.vtk");
    assert!(gmap(&["convert", p(&src), p(&vtk)]).status.success());
    let o = gmap(&["info", p(&vtk), "--json"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let out = String::from_utf8(o.stdout).unwrap();
    assert!(out.contains("\"cells\":[2,1]"), "{out}");
    // the labels come back: .vtk → .gmap keeps them
    let back = dir.path().join("back.gmap");
    assert!(gmap(&["convert", p(&vtk), p(&back)]).status.success());
    let g = gmap_core::io::read_labelled_gmap(&back).unwrap();
    let (_, labels, _) = gmap_core::to_dense_labels(&g);
    let edge: Vec<String> = labels.of[1].iter().map(|l| l.to_string()).collect();
    assert_eq!(edge, [r#"name="main \"beam\"" length=2.5"#]);
    // a .dot is still a view only
    let dot = dir.path().join("segment.dot");
    assert!(gmap(&["convert", p(&src), p(&dot), "--lossy"]).status.success());
    let o = gmap(&["info", p(&dot)]);
    assert_eq!(o.status.code(), Some(1));
    assert!(stderr(&o).contains("unsupported input format '.dot': it is written only, as a view"), "{}", stderr(&o));
}
