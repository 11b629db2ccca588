//! The architect's defects through the command line: a T-junction and a point given twice
//! are refused naming the place, `--snap EPS` welds and splits them into the building meant
//! and says what it did, `gmap tm check` lists them as metrical defects (TM §X), and every
//! node of a GraphML export carries the id the file gave it.

mod common;
use common::{gmap, p, stderr, stdout};

fn arch(name: &str) -> std::path::PathBuf {
    std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/arch").join(name)
}

#[test]
fn a_t_junction_is_refused_and_snapped() {
    let f = arch("t_junction.json");
    let o = gmap(&["homology", p(&f)]);
    assert!(!o.status.success());
    let e = stderr(&o);
    assert!(e.contains("the points do not make a conforming complex (tolerance 8e-8): point p400 lies inside edge p000-p800 (a T-junction)"), "{e}");
    let o = gmap(&["homology", "--snap", "1e-6", p(&f)]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stdout(&o).contains("H_0 = Z\nH_1 = 0\nH_2 = 0\nH_3 = 0\n"), "{}", stdout(&o));
    let e = stderr(&o);
    assert!(e.contains("snap: split edge p000-p800 at p400 into p000-p800, p000-p800.2\n"), "{e}");
    assert!(e.contains("snap: split face south wall along p400-p403 into south wall, south wall.2\n"), "{e}");
    assert!(e.contains("snap: room 1 (kitchen) takes south wall, north wall\n"), "{e}");
    let o = gmap(&["info", "--snap", "1e-6", p(&f)]);
    assert!(o.status.success(), "{}", stderr(&o));
}

#[test]
fn a_point_given_twice_is_refused_and_welded() {
    let f = arch("near_points.json");
    let o = gmap(&["info", p(&f)]);
    assert!(!o.status.success());
    assert!(stderr(&o).contains("points p400 and p400 copy are 1.00e-9 apart: the same point twice"), "{}", stderr(&o));
    let o = gmap(&["homology", "--snap", "1e-6", p(&f)]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stdout(&o).contains("H_0 = Z\nH_1 = 0\nH_2 = 0\nH_3 = 0\n"), "{}", stdout(&o));
    assert_eq!(stderr(&o), "snap: welded point p400 copy into p400 (1.00e-9 apart)\n");
}

#[test]
fn tm_check_names_the_metrical_defects() {
    let o = gmap(&["tm", "check", p(&arch("near_points.json"))]);
    assert_eq!(o.status.code(), Some(1));
    let out = stdout(&o);
    assert!(
        out.contains("metrical edit (TM X, tolerance 8e-8): 1 defect\n  points p400 and p400 copy are 1.00e-9 apart: the same point twice\nfails the edit check\n"),
        "{out}"
    );
    let o = gmap(&["tm", "check", p(&arch("t_junction.json"))]);
    assert_eq!(o.status.code(), Some(1));
    let out = stdout(&o);
    assert!(out.contains("metrical edit (TM X, tolerance 8e-8): 6 defects\n"), "{out}");
    assert!(out.contains("  edge p400-p403 lies inside face south wall (a T-junction)\n"), "{out}");
    // snapped, the model passes both edits
    let o = gmap(&["tm", "check", "--snap", "1e-6", p(&arch("t_junction.json"))]);
    assert!(o.status.success(), "{}{}", stdout(&o), stderr(&o));
    assert!(
        stdout(&o).contains("metrical edit (TM X, tolerance 8e-8): no defect\npasses the edit check\n"),
        "{}",
        stdout(&o)
    );
    let o = gmap(&["tm", "check", p(&arch("two_rooms.json"))]);
    assert!(o.status.success(), "{}", stdout(&o));
}

#[test]
fn every_graphml_node_carries_the_files_id() {
    let dir = tempfile::tempdir().unwrap();
    let mut checked = 0;
    for entry in std::fs::read_dir(arch("")).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().and_then(|e| e.to_str()) != Some("json") {
            continue;
        }
        let text = std::fs::read_to_string(&path).unwrap();
        let v: serde_json::Value = serde_json::from_str(&text).unwrap();
        let ids: std::collections::BTreeSet<String> = v["regions"]
            .as_array()
            .unwrap()
            .iter()
            .map(|r| match &r["id"] {
                serde_json::Value::String(s) => s.clone(),
                other => other.to_string(),
            })
            .collect();
        let out = dir.path().join("g.graphml");
        let o = gmap(&["convert", "--lossy", p(&path), p(&out)]);
        if !o.status.success() {
            // refused inputs (a Möbius band of regions, a T-junction) have no graph to check
            assert!(stderr(&o).contains("error: "), "{}", stderr(&o));
            continue;
        }
        let g = std::fs::read_to_string(&out).unwrap();
        let nodes: Vec<&str> = g.lines().filter(|l| l.trim_start().starts_with("<node ")).collect();
        assert_eq!(nodes.len(), ids.len(), "{}", path.display());
        let found: std::collections::BTreeSet<String> = nodes
            .iter()
            .map(|n| n.split("<data key=\"id\">").nth(1).and_then(|r| r.split("</data>").next()).unwrap().to_string())
            .collect();
        assert_eq!(found, ids, "{}", path.display());
        checked += 1;
    }
    assert!(checked >= 7, "{checked}");
    // the refused ones are the Möbius band, the T-junction and the points given twice
    assert_eq!(
        checked,
        std::fs::read_dir(arch(""))
            .unwrap()
            .filter(|e| e.as_ref().unwrap().path().extension().is_some_and(|x| x == "json"))
            .count()
            - 4
    );
}
