//! `gmap convert` of any complex to its incidence graph (`.json`, `.dot`, `.graphml`): the
//! face poset of simplicial complexes that have no G-map (a book of three triangles, mixed
//! dimensions) and of cubical sets, which also write `.gmap` and `.vtk` voxels. networkx
//! reads the GraphML with its labels (skipped when python3 or networkx is missing).

mod common;
use common::{gmap, p, stderr, stdout};

const BOOK: &str = "1 2 3\n1 2 4\n1 2 5\n";
const MIXED: &str = "1 2 3 4\n4 5\n6\n";
const ELL: &str = "(0,0)\n(1,0)\n(1,1)\n";

fn convert(dir: &std::path::Path, name: &str, text: &str, ext: &str) -> std::path::PathBuf {
    let src = dir.join(name);
    std::fs::write(&src, text).unwrap();
    let out = dir.join(format!("{name}.{ext}"));
    let o = gmap(&["convert", p(&src), p(&out)]);
    assert!(o.status.success(), "{name} → .{ext}: {}", stderr(&o));
    out
}

#[test]
fn the_book_and_a_mixed_complex_have_incidence_graphs() {
    let dir = tempfile::tempdir().unwrap();
    // (file, regions per dimension, incidences)
    for (name, text, counts, entries) in
        [("book.facets", BOOK, "5 7 3", 23), ("mixed.facets", MIXED, "6 7 4 1", 30), ("ell.cub", ELL, "8 10 3", 32)]
    {
        let json = convert(dir.path(), name, text, "json");
        let o = gmap(&["info", p(&json)]);
        let info = stdout(&o);
        assert!(info.contains(&format!("regions (0..n)        {counts}\n")), "{name}: {info}");
        assert!(info.contains(&format!("incidences            {entries}\n")), "{name}: {info}");
        // the face poset has the homology of the complex
        let h = |f: &std::path::Path| {
            let o = gmap(&["homology", "--json", p(f)]);
            assert!(o.status.success(), "{}", stderr(&o));
            let v: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
            (v["betti"].clone(), v["torsion"].clone())
        };
        assert_eq!(h(&json), h(&dir.path().join(name)), "{name}");
        let dot = std::fs::read_to_string(convert(dir.path(), name, text, "dot")).unwrap();
        assert_eq!(dot.matches(" -> ").count(), entries, "{name}");
        let graphml = std::fs::read_to_string(convert(dir.path(), name, text, "graphml")).unwrap();
        assert_eq!(graphml.matches("<edge ").count(), entries, "{name}");
    }
    let book = std::fs::read_to_string(dir.path().join("book.facets.json")).unwrap();
    assert!(book.contains(r#""labels": {"name": "[1,2,3]"}"#), "{book}");
    let ell = std::fs::read_to_string(dir.path().join("ell.cub.json")).unwrap();
    assert!(ell.contains(r#""labels": {"name": "[0,1]x[0,1]"}"#), "{ell}");
}

#[test]
fn cubical_sets_write_gmap_and_voxels() {
    let dir = tempfile::tempdir().unwrap();
    let m = convert(dir.path(), "ell.cub", ELL, "gmap");
    let o = gmap(&["homology", p(&m)]);
    assert_eq!(
        stdout(&o),
        "dimension 2, method cellular, coefficients Z\nH_0 = Z\nH_1 = 0\nH_2 = 0\neuler characteristic 1\n"
    );
    let vtk = std::fs::read_to_string(convert(dir.path(), "ell.cub", ELL, "vtk")).unwrap();
    assert!(vtk.contains("POINTS 8 double\n") && vtk.contains("CELL_TYPES 3\n9\n9\n9\n"), "{vtk}");
    // the voxels read back as a 2-map of the same space
    let o = gmap(&["homology", p(&dir.path().join("ell.cub.vtk"))]);
    assert!(stdout(&o).contains("H_0 = Z\nH_1 = 0\n"), "{}{}", stdout(&o), stderr(&o));
}

#[test]
fn networkx_reads_the_graphml_with_its_labels() {
    let dir = tempfile::tempdir().unwrap();
    let book = convert(dir.path(), "book.facets", BOOK, "graphml");
    let window = dir.path().join("window.graphml");
    let data = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/arch/window.json");
    let o = gmap(&["convert", p(&data), p(&window)]);
    assert!(o.status.success(), "{}", stderr(&o));
    let script = r#"
import sys
try:
    import networkx as nx
except ImportError:
    print("skip"); sys.exit(0)
g = nx.read_graphml(sys.argv[1])
spine = [n for n, d in g.nodes(data=True) if d["name"] == "[1,2]"][0]
ends = sorted((g.nodes[t]["name"], d["weight"]) for _, t, d in g.out_edges(spine, data=True))
pages = sorted(g.nodes[s]["name"] for s, _ in g.in_edges(spine))
print(g.number_of_nodes(), g.number_of_edges(), g.is_directed(), g.nodes[spine]["dim"], ends, pages)
w = nx.read_graphml(sys.argv[2])
print(sorted(d["name"] for _, d in w.nodes(data=True) if "name" in d))
"#;
    let run = std::process::Command::new("python3").arg("-c").arg(script).arg(&book).arg(&window).output();
    let Ok(run) = run else {
        eprintln!("python3 missing: skipped");
        return;
    };
    let out = String::from_utf8_lossy(&run.stdout).to_string();
    assert!(run.status.success(), "{}", String::from_utf8_lossy(&run.stderr));
    if out.trim() == "skip" {
        eprintln!("networkx missing: skipped");
        return;
    }
    let mut lines = out.lines();
    let first = lines.next().unwrap();
    // the spine of the book: an edge on two vertices, in three triangles
    assert_eq!(first, "15 23 True 1 [('[1]', -1), ('[2]', 1)] ['[1,2,3]', '[1,2,4]', '[1,2,5]']");
    assert_eq!(lines.next().unwrap(), "['room 1', 'room 2', 'wall with window', 'window']");
}
