//! Refusals of the command found by the hostile-user audit (issue 47), end to end: a
//! conversion that would change the space, a `.npy` of a format version numpy does not
//! write, an empty array (one message whatever the command), a picture that cannot be
//! written (named), a 4-map as `.moka`.

mod common;
use common::{gmap, p, stderr};

fn npy(dir: &std::path::Path, name: &str, version: (u8, u8), shape: &str, data: &[u8]) -> std::path::PathBuf {
    let dict = format!("{{'descr': '|u1', 'fortran_order': False, 'shape': {shape}, }}");
    let mut header = dict.into_bytes();
    while (10 + header.len() + 1) % 64 != 0 {
        header.push(b' ');
    }
    header.push(b'\n');
    let mut bytes = b"\x93NUMPY".to_vec();
    bytes.extend_from_slice(&[version.0, version.1]);
    bytes.extend_from_slice(&(header.len() as u16).to_le_bytes());
    bytes.extend_from_slice(&header);
    bytes.extend_from_slice(data);
    let path = dir.join(name);
    std::fs::write(&path, bytes).unwrap();
    path
}

#[test]
fn convert_refuses_a_bowtie_naming_its_vertex_and_lossy_says_what_changes() {
    let dir = tempfile::tempdir().unwrap();
    let bowtie = dir.path().join("bowtie.facets");
    std::fs::write(&bowtie, "0 1 2\n0 3 4\n").unwrap();
    let out = dir.path().join("b.gmap");
    let o = gmap(&["convert", p(&bowtie), p(&out)]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    let err = stderr(&o);
    assert!(err.contains("b.gmap is another space than"), "{err}");
    assert!(err.contains("the facets around the vertex 0 fall into 2 groups that share no ridge there"), "{err}");
    assert!(err.contains(".facets, .json, .dot, .graphml keep it; convert with --lossy to write it anyway"), "{err}");
    assert!(!out.exists());
    let o = gmap(&["convert", "--lossy", p(&bowtie), p(&out)]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(stderr(&o).starts_with("gmap convert: "), "{}", stderr(&o));
    assert!(stderr(&o).contains("so the vertex 0 becomes 2 cells"), "{}", stderr(&o));
    let h = gmap(&["homology", p(&out)]);
    assert!(common::stdout(&h).contains("H_0 = Z^2"), "{}", common::stdout(&h));
}

#[test]
fn an_npy_of_another_format_version_is_refused_by_every_command() {
    let dir = tempfile::tempdir().unwrap();
    for (v, name) in [((1, 32), "v1_32.npy"), ((2, 1), "v2_1.npy"), ((4, 0), "v4_0.npy")] {
        let f = npy(dir.path(), name, v, "(2, 2)", &[1, 0, 0, 1]);
        for cmd in ["info", "homology", "persistence"] {
            let o = gmap(&[cmd, p(&f)]);
            assert_eq!(o.status.code(), Some(1), "{cmd} {name}: {}", stderr(&o));
            let want = format!(".npy format version {}.{}: versions 1.0, 2.0 and 3.0 are read", v.0, v.1);
            assert!(stderr(&o).contains(&want), "{cmd} {name}: {}", stderr(&o));
        }
    }
    // 1.0 is read
    let f = npy(dir.path(), "v1_0.npy", (1, 0), "(2, 2)", &[1, 0, 0, 1]);
    assert_eq!(gmap(&["homology", p(&f)]).status.code(), Some(0));
}

#[test]
fn an_empty_array_gets_one_message_whatever_the_command() {
    let dir = tempfile::tempdir().unwrap();
    for (shape, text, axis) in [("(0, 3)", "0 × 3", 0), ("(3, 0, 2)", "3 × 0 × 2", 1)] {
        let f = npy(dir.path(), "empty.npy", (1, 0), shape, &[]);
        let want = format!("an empty image: the shape {text} has no pixels (size 0 along axis {axis})");
        for cmd in ["info", "homology", "persistence"] {
            let o = gmap(&[cmd, p(&f)]);
            assert_eq!(o.status.code(), Some(1), "{cmd}: {}", stderr(&o));
            assert_eq!(stderr(&o).trim_end(), format!("error: {}: {want}", f.display()), "{cmd}");
        }
    }
}

#[test]
fn a_plot_that_cannot_be_written_names_its_file() {
    let dir = tempfile::tempdir().unwrap();
    let f = npy(dir.path(), "grey.npy", (1, 0), "(3, 3)", &[0, 1, 2, 3, 4, 5, 6, 7, 8]);
    let missing = dir.path().join("no/such/folder/p.svg");
    let o = gmap(&["persistence", p(&f), "--plot", p(&missing)]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert!(stderr(&o).contains(&format!("{}: cannot write", missing.display())), "{}", stderr(&o));
}

#[test]
fn a_4_map_is_refused_as_moka_before_anything_is_written() {
    let dir = tempfile::tempdir().unwrap();
    let simplex = dir.path().join("s4.facets");
    std::fs::write(&simplex, "0 1 2 3 4\n").unwrap();
    let out = dir.path().join("s4.moka");
    let o = gmap(&["convert", p(&simplex), p(&out)]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert!(stderr(&o).contains(".moka holds maps of dimension at most 3, this map has dimension 4"), "{}", stderr(&o));
    assert!(!out.exists());
}

#[test]
fn homology_through_the_gmap_of_a_pinched_complex_is_refused_naming_the_cell() {
    // the bowtie: two triangles sharing the vertex 0 only, H_0 = Z; its G-map splits the
    // vertex (H_0 = Z^2), so every route through the G-map must refuse, naming the vertex
    let dir = tempfile::tempdir().unwrap();
    let bowtie = dir.path().join("bowtie.facets");
    std::fs::write(&bowtie, "0 1 2\n0 3 4\n").unwrap();
    let direct = gmap(&["homology", p(&bowtie)]);
    assert_eq!(direct.status.code(), Some(0), "{}", stderr(&direct));
    assert!(common::stdout(&direct).contains("H_0 = Z\n"), "{}", common::stdout(&direct));
    for args in
        [&["--via", "gmap"][..], &["--method", "simplicial"], &["--simplify"], &["--via", "gmap", "--generators"]]
    {
        let mut cmd = vec!["homology", p(&bowtie)];
        cmd.extend_from_slice(args);
        let o = gmap(&cmd);
        assert_eq!(o.status.code(), Some(1), "{args:?}: {}", stderr(&o));
        assert!(common::stdout(&o).is_empty(), "{args:?}: {}", common::stdout(&o));
        let err = stderr(&o);
        assert!(err.contains("bowtie.facets: the G-map of this complex is another space"), "{args:?}: {err}");
        assert!(
            err.contains("the facets around the vertex 0 fall into 2 groups that share no ridge there"),
            "{args:?}: {err}"
        );
        assert!(err.contains("so the vertex 0 becomes 2 cells"), "{args:?}: {err}");
        assert!(err.contains("--via direct computes those"), "{args:?}: {err}");
    }
    // two tetrahedra sharing an edge: pinched along the edge, named before its vertices
    let edge = dir.path().join("edge.facets");
    std::fs::write(&edge, "0 1 2 3\n0 1 4 5\n").unwrap();
    let o = gmap(&["homology", p(&edge), "--via", "gmap"]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert!(stderr(&o).contains("the facets around the edge {0, 1} fall into 2 groups"), "{}", stderr(&o));
    // a complex whose G-map keeps every face goes through as before: the octahedron
    let octa = dir.path().join("octa.facets");
    std::fs::write(&octa, "0 2 4\n0 2 5\n0 3 4\n0 3 5\n1 2 4\n1 2 5\n1 3 4\n1 3 5\n").unwrap();
    let o = gmap(&["homology", p(&octa), "--via", "gmap"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(common::stdout(&o).contains("H_2 = Z"), "{}", common::stdout(&o));
}

#[test]
fn bench_gives_no_gmap_groups_for_a_pinched_complex() {
    let dir = tempfile::tempdir().unwrap();
    let bowtie = dir.path().join("bowtie.facets");
    std::fs::write(&bowtie, "0 1 2\n0 3 4\n").unwrap();
    let o = gmap(&["bench", p(&bowtie), "--json"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let out: serde_json::Value = serde_json::from_str(&common::stdout(&o)).unwrap();
    let rows = out["rows"].as_array().unwrap();
    // the direct route answers the complex's groups; the G-map's two routes do not apply
    let direct: Vec<_> = rows.iter().filter(|r| r["route"] == "direct").collect();
    assert_eq!(direct.len(), 1, "{out}");
    assert_eq!(direct[0]["betti"], serde_json::json!([1, 0, 0]), "{out}");
    let mapped: Vec<_> = rows.iter().filter(|r| r["route"] == "cellular" || r["route"] == "simplicial").collect();
    assert_eq!(mapped.len(), 2, "{out}");
    for r in mapped {
        let e = r["error"].as_str().unwrap_or_default();
        assert!(e.contains("the G-map of this complex is another space"), "{out}");
        assert!(e.contains("the vertex 0 becomes 2 cells"), "{out}");
    }
    assert!(rows.iter().all(|r| r["agree"] == true), "{out}");
}
