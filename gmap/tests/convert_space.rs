//! A write keeps the space or refuses (issue 47): the G-map of a simplicial complex pinched
//! at a face (two triangles sharing only a vertex) pulls the face apart, so every map format
//! refuses it naming the face and the formats that keep the complex, and `lossy` writes it
//! saying what changes; an unpinched complex is written as the same space.

use std::path::Path;

use gmap::save::{save_checked, write_checked};
use gmap::{ErrorKind, HomologyOptions, Item, SaveOptions};
use proptest::prelude::*;

fn write(dir: &Path, name: &str, text: &str) -> std::path::PathBuf {
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

fn betti(path: &Path) -> Vec<usize> {
    gmap::homology_file(path, &HomologyOptions::default()).unwrap().groups.betti
}

const HINT: &str = "convert with --lossy to write it anyway";

#[test]
fn a_bowtie_is_refused_by_every_map_format_naming_its_vertex() {
    let dir = tempfile::tempdir().unwrap();
    let bowtie = write(dir.path(), "bowtie.facets", "0 1 2\n0 3 4\n");
    assert_eq!(betti(&bowtie), vec![1, 0, 0]);
    for ext in ["gmap", "moka", "off", "vtk", "lar.json"] {
        let out = dir.path().join(format!("b.{ext}"));
        let e = save_checked(&bowtie, &out, &SaveOptions::default(), HINT).unwrap_err();
        let msg = e.to_string();
        assert_eq!(e.kind(), ErrorKind::Unsupported, "{ext}: {msg}");
        assert!(
            msg.contains("the facets around the vertex 0 fall into 2 groups that share no ridge there"),
            "{ext}: {msg}"
        );
        assert!(msg.contains("so the vertex 0 becomes 2 cells (nothing written)"), "{ext}: {msg}");
        assert!(msg.contains(".facets, .json, .dot, .graphml keep it; convert with --lossy"), "{ext}: {msg}");
        assert_eq!(e.item(), Some(&Item::Simplex(vec![0])));
        assert_eq!(e.path(), Some(out.as_path()));
        assert!(!out.exists(), "{ext} written");
    }
    // the formats that keep it write it as the same space
    for ext in ["facets", "json"] {
        let out = dir.path().join(format!("kept.{ext}"));
        assert_eq!(save_checked(&bowtie, &out, &SaveOptions::default(), HINT).unwrap(), Vec::<String>::new());
        assert_eq!(betti(&out), vec![1, 0, 0], "{ext}");
    }
}

#[test]
fn lossy_writes_the_bowtie_and_says_the_vertex_splits() {
    let dir = tempfile::tempdir().unwrap();
    let bowtie = write(dir.path(), "bowtie.facets", "0 1 2\n0 3 4\n");
    let out = dir.path().join("b.gmap");
    let mut o = SaveOptions::default();
    o.lossy = true;
    let said = save_checked(&bowtie, &out, &o, HINT).unwrap();
    assert_eq!(said.len(), 1, "{said:?}");
    assert!(said[0].starts_with(&format!("{} is another space than {}", out.display(), bowtie.display())), "{said:?}");
    assert!(said[0].ends_with("so the vertex 0 becomes 2 cells"), "{said:?}");
    // what it says is what changed: two components
    assert_eq!(betti(&out), vec![2, 0, 0]);
}

#[test]
fn a_pinched_edge_and_a_pinched_vertex_of_solids_are_named() {
    let dir = tempfile::tempdir().unwrap();
    // two tetrahedra sharing an edge only
    let edge = write(dir.path(), "edge.facets", "0 1 2 3\n0 1 4 5\n");
    let e = save_checked(&edge, dir.path().join("e.gmap"), &SaveOptions::default(), HINT).unwrap_err();
    assert!(e.to_string().contains("around the edge {0, 1} fall into 2 groups"), "{e}");
    assert_eq!(e.item(), Some(&Item::Simplex(vec![0, 1])));
    // two tetrahedra sharing a vertex only: the vertex first
    let vertex = write(dir.path(), "vertex.facets", "0 1 2 3\n3 4 5 6\n");
    let e = save_checked(&vertex, dir.path().join("v.gmap"), &SaveOptions::default(), HINT).unwrap_err();
    assert!(e.to_string().contains("around the vertex 3 fall into 2 groups"), "{e}");
    // three triangles around a vertex that share no edge there: three groups
    let three = write(dir.path(), "three.facets", "0 1 2\n0 3 4\n0 5 6\n");
    let e = save_checked(&three, dir.path().join("t.gmap"), &SaveOptions::default(), HINT).unwrap_err();
    assert!(e.to_string().contains("fall into 3 groups"), "{e}");
}

#[test]
fn a_pinched_torus_made_from_a_cylinder_is_refused() {
    // a cylinder of six triangles whose two boundary circles are coned to one apex 9: the
    // apex's triangles form two cones that meet at the apex only
    let dir = tempfile::tempdir().unwrap();
    let text = "0 1 3\n1 3 4\n1 2 4\n2 4 5\n2 0 5\n0 5 3\n0 1 9\n1 2 9\n2 0 9\n3 4 9\n4 5 9\n5 3 9\n";
    let pinched = write(dir.path(), "pinched_torus.facets", text);
    // the pinched torus: H_1 = Z, H_2 = Z
    assert_eq!(betti(&pinched), vec![1, 1, 1]);
    let e = save_checked(&pinched, dir.path().join("p.gmap"), &SaveOptions::default(), HINT).unwrap_err();
    assert!(e.to_string().contains("around the vertex 9 fall into 2 groups"), "{e}");
    // written anyway, the apex splits: a sphere
    let mut o = SaveOptions::default();
    o.lossy = true;
    let out = dir.path().join("p.gmap");
    save_checked(&pinched, &out, &o, HINT).unwrap();
    assert_eq!(betti(&out), vec![1, 0, 1]);
}

#[test]
fn closed_manifolds_convert_to_every_map_format_as_the_same_space() {
    let dir = tempfile::tempdir().unwrap();
    let data = Path::new(env!("CARGO_MANIFEST_DIR")).join("../tests/data");
    for name in ["rp2.facets", "tetrahedron.facets"] {
        let src = data.join(name);
        let want = gmap::homology_file(&src, &HomologyOptions::default()).unwrap().groups;
        let out = dir.path().join(format!("{name}.gmap"));
        assert!(save_checked(&src, &out, &SaveOptions::default(), HINT).unwrap().is_empty());
        assert_eq!(gmap::homology_file(&out, &HomologyOptions::default()).unwrap().groups, want, "{name}");
    }
}

#[test]
fn a_cubical_set_pinched_at_a_corner_is_written_with_lossy_only() {
    let dir = tempfile::tempdir().unwrap();
    let corner = write(dir.path(), "corner.cub", "(0,0)\n(1,1)\n");
    let out = dir.path().join("c.gmap");
    let e = save_checked(&corner, &out, &SaveOptions::default(), HINT).unwrap_err();
    let msg = e.to_string();
    assert!(msg.contains("the cubes around the cell 1x1 fall into 2 groups that share no facet there"), "{msg}");
    assert!(msg.contains(".vtk, .json, .cub, .dot, .graphml keep it"), "{msg}");
    assert!(!out.exists());
    let mut o = SaveOptions::default();
    o.lossy = true;
    let said = save_checked(&corner, &out, &o, HINT).unwrap();
    assert!(said[0].ends_with("so the cell 1x1 becomes 2 cells"), "{said:?}");
    assert_eq!(betti(&out), vec![2, 0, 0]);
}

#[test]
fn the_rule_is_the_same_for_an_input_made_in_memory() {
    // the Python package's objects have no file: the message names the kind
    let sc = gmap::ops::import::SimplicialComplex::from_facets(vec![vec![0, 1, 2], vec![2, 3, 4]]).unwrap();
    let input = gmap::Input::Simplicial(gmap::Sourced::new(sc));
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("m.gmap");
    let e = write_checked(&input, &out, &SaveOptions::default(), "save with lossy=True").unwrap_err();
    assert!(e.to_string().contains("m.gmap is another space than the simplicial complex"), "{e}");
    assert!(e.to_string().ends_with("keep it; save with lossy=True"), "{e}");
    // save itself, the writer, refuses it too
    assert!(gmap::save(&input, &out, &SaveOptions::default()).is_err());
    assert!(!out.exists());
}

/// Pure 2-complexes on few vertices: each facet three distinct labels below 7.
fn complexes() -> impl Strategy<Value = Vec<[u64; 3]>> {
    prop::collection::vec((0u64..7, 0u64..7, 0u64..7), 1..9).prop_map(|v| {
        let mut out: Vec<[u64; 3]> = v
            .into_iter()
            .filter(|(a, b, c)| a != b && b != c && a != c)
            .map(|(a, b, c)| {
                let mut f = [a, b, c];
                f.sort_unstable();
                f
            })
            .collect();
        out.sort_unstable();
        out.dedup();
        out
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]
    /// Converting to `.gmap` either refuses naming a pinched face, or writes a map with
    /// the complex's own groups; with lossy it always writes and says so when pinched.
    #[test]
    fn convert_keeps_the_groups_or_refuses(facets in complexes()) {
        prop_assume!(!facets.is_empty());
        let dir = tempfile::tempdir().unwrap();
        let text: String = facets.iter().map(|f| format!("{} {} {}\n", f[0], f[1], f[2])).collect();
        let src = write(dir.path(), "x.facets", &text);
        let want = gmap::homology_file(&src, &HomologyOptions::default()).unwrap().groups;
        let out = dir.path().join("x.gmap");
        match save_checked(&src, &out, &SaveOptions::default(), HINT) {
            Ok(said) => {
                prop_assert!(said.is_empty());
                let got = gmap::homology_file(&out, &HomologyOptions::default()).unwrap().groups;
                prop_assert_eq!(got, want, "{}", text);
            }
            Err(e) => {
                prop_assert!(!out.exists());
                let msg = e.to_string();
                // a ridge in three facets has no G-map at all; anything else is a pinch
                if !msg.contains("facets") || !msg.contains("another space") {
                    prop_assert!(msg.contains("in 3 facets") || msg.contains("ridge"), "{}", msg);
                } else {
                    prop_assert!(matches!(e.item(), Some(Item::Simplex(s)) if s.len() == 1), "{}", msg);
                    let mut o = SaveOptions::default();
                    o.lossy = true;
                    let said = save_checked(&src, &out, &o, HINT).unwrap();
                    prop_assert_eq!(said.len(), 1);
                }
            }
        }
    }
}
