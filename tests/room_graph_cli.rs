//! `gmap graph FILE --dual faces|apertures|exterior`: the room graphs of the six buildings
//! of issue 45 (`tests/data/arch/buildings`, made by `scripts/arch_buildings.py`) equal
//! TopologicPy's `Graph.ByTopology` answers (`direct`, `viaSharedApertures`,
//! `toExteriorTopologies`) recorded by `scripts/topologicpy_room_graphs.py` in
//! `tests/data/arch/buildings/topologicpy/room_graphs.json`; the GraphML, DOT and JSON outputs keep the
//! file's ids and names; bad kinds and formats are refused.

mod common;
use common::{gmap, p, stderr, stdout};

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use serde_json::Value;

fn arch(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/arch").join(name)
}

/// `gmap graph FILE --dual VIA` as JSON.
fn graph(file: &Path, via: &str) -> Value {
    let o = gmap(&["graph", p(file), "--dual", via]);
    assert!(o.status.success(), "{}", stderr(&o));
    serde_json::from_str(&stdout(&o)).unwrap()
}

fn pair(e: &Value) -> (String, String) {
    let (a, b) = (e["source"].as_str().unwrap().to_string(), e["target"].as_str().unwrap().to_string());
    if a < b {
        (a, b)
    } else {
        (b, a)
    }
}

fn round(x: f64) -> f64 {
    (x * 1e6).round() / 1e6
}

/// gmap's answers in the recorded form (scripts/topologicpy_room_graphs.py's comment).
fn answers(file: &Path) -> Value {
    let faces: Vec<Value> = {
        let mut v: Vec<(String, String, f64)> = graph(file, "faces")["edges"]
            .as_array()
            .unwrap()
            .iter()
            .map(|e| {
                let (a, b) = pair(e);
                (a, b, round(e["area"].as_f64().unwrap()))
            })
            .collect();
        v.sort_by(|x, y| x.partial_cmp(y).unwrap());
        v.into_iter().map(|(a, b, s)| serde_json::json!([a, b, s])).collect()
    };
    let mut apertures: Vec<(String, String, Vec<String>)> = graph(file, "apertures")["edges"]
        .as_array()
        .unwrap()
        .iter()
        .map(|e| {
            let (a, b) = pair(e);
            let mut f: Vec<String> =
                e["faces"].as_array().unwrap().iter().map(|f| f.as_str().unwrap().into()).collect();
            f.sort();
            (a, b, f)
        })
        .collect();
    apertures.sort();
    let mut exterior = BTreeMap::new();
    let g = graph(file, "exterior");
    for e in g["edges"].as_array().unwrap() {
        assert_eq!(e["target"], "exterior");
        let walls = e["kinds"]
            .as_array()
            .unwrap()
            .iter()
            .filter(|k| !["door", "window", "opening"].contains(&k.as_str().unwrap()))
            .count();
        exterior.insert(
            e["source"].as_str().unwrap().to_string(),
            serde_json::json!([walls, round(e["area"].as_f64().unwrap())]),
        );
    }
    serde_json::json!({"faces": faces, "apertures": apertures, "exterior": exterior})
}

#[test]
fn the_six_buildings_give_topologicpys_room_graphs() {
    let recorded: Value =
        serde_json::from_str(&std::fs::read_to_string(arch("buildings/topologicpy/room_graphs.json")).unwrap())
            .unwrap();
    assert_eq!(recorded["topologicpy"], "0.9.87");
    let buildings = recorded["buildings"].as_object().unwrap();
    let names: Vec<&str> = buildings.keys().map(String::as_str).collect();
    assert_eq!(names, ["courtyard", "door_window", "grid_2x2", "l_flat", "shaft", "stair_two_storeys"]);
    for (name, want) in buildings {
        let got = answers(&arch(&format!("buildings/{name}.json")));
        assert_eq!(&got, want, "{name}");
    }
}

#[test]
fn the_outputs_keep_the_files_ids_names_and_areas() {
    let dir = tempfile::tempdir().unwrap();
    let file = arch("buildings/door_window.json");
    let out = dir.path().join("doors.graphml");
    let o = gmap(&["graph", p(&file), "--dual", "apertures", "-o", p(&out)]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stdout(&o).starts_with("wrote ") && stdout(&o).ends_with(": 2 nodes, 1 edges\n"), "{}", stdout(&o));
    let g = std::fs::read_to_string(&out).unwrap();
    assert!(g.contains("<data key=\"id\">kitchen</data><data key=\"name\">kitchen</data>"), "{g}");
    assert!(g.contains("<data key=\"id\">living</data><data key=\"name\">living (living room)</data>"), "{g}");
    assert!(g.contains("<data key=\"faces\">door; window</data><data key=\"face_names\">door; window</data><data key=\"count\">2</data><data key=\"area\">4.0</data>"), "{g}");
    assert_eq!(g.matches("<node ").count(), 2);
    let o = gmap(&["graph", p(&file), "--dual", "faces", "--format", "dot"]);
    let d = stdout(&o);
    assert!(d.starts_with("graph faces {\n"), "{d}");
    assert!(d.contains("  \"kitchen\" -- \"living\" [label=\"wall kitchen/living, door, window\\n18\", \"faces\"=\"wall kitchen/living; door; window\", \"area\"=\"18\"];\n"), "{d}");
    let j = graph(&arch("buildings/stair_two_storeys.json"), "exterior");
    let nodes: Vec<&str> = j["nodes"].as_array().unwrap().iter().map(|n| n["id"].as_str().unwrap()).collect();
    assert_eq!(nodes, ["hall", "stair 0", "office", "stair 1", "exterior"]);
    assert_eq!(j["nodes"][1]["labels"]["storey"], "ground");
    assert_eq!(j["nodes"][1]["name"], "stair 0 (stair, ground)");
}

#[test]
fn the_rooms_found_in_walls_have_their_graph() {
    // the two-storey building of examples/building.rs given as its faces: 8 rooms, each next
    // to the ones `gmap rooms` lists
    let dir = tempfile::tempdir().unwrap();
    let rooms = dir.path().join("rooms.json");
    let o = gmap(&["rooms", p(&arch("building_walls.off")), p(&rooms)]);
    assert!(o.status.success(), "{}", stderr(&o));
    let listed: usize = stdout(&o)
        .lines()
        .filter(|l| l.contains("; next to "))
        .map(|l| l.split("; next to ").nth(1).unwrap().split(", ").count())
        .sum();
    let j = graph(&rooms, "faces");
    assert_eq!(j["nodes"].as_array().unwrap().len(), 8);
    assert_eq!(2 * j["edges"].as_array().unwrap().len(), listed);
    let j = graph(&rooms, "exterior");
    assert_eq!(j["edges"].as_array().unwrap().len(), 8, "every room of the building has an outside face");
}

#[test]
fn bad_kinds_and_formats_are_refused() {
    let file = arch("buildings/grid_2x2.json");
    let o = gmap(&["graph", p(&file), "--dual", "stairs"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("faces, apertures, exterior"), "{}", stderr(&o));
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("g.off");
    let o = gmap(&["graph", p(&file), "--dual", "faces", "-o", p(&out)]);
    assert_eq!(o.status.code(), Some(1));
    assert!(stderr(&o).contains("a room graph is written as .graphml, .dot or .json, not '.off'"), "{}", stderr(&o));
    assert!(!out.exists());
}

#[test]
fn an_ifc_file_is_pointed_to_the_python_package() {
    let dir = tempfile::tempdir().unwrap();
    let ifc = dir.path().join("house.ifc");
    std::fs::write(&ifc, "ISO-10303-21;\nEND-ISO-10303-21;\n").unwrap();
    for args in [vec!["info", p(&ifc)], vec!["graph", p(&ifc), "--dual", "faces"]] {
        let o = gmap(&args);
        assert_eq!(o.status.code(), Some(1));
        let e = stderr(&o);
        assert!(
            e.contains("IFC is read through the Python package and IfcOpenShell: pip install './python[ifc]'"),
            "{e}"
        );
        assert!(e.contains("gmap.ifc.open(path)"), "{e}");
        assert!(!e.contains("unsupported input format"), "{e}");
    }
}
