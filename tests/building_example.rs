//! `examples/building.rs`: the labelled two-storey building, its exact counts and homology,
//! and the names it keeps in the `.json` and `.dot` incidence graphs and the `.vtk` cell
//! data, also when `gmap convert` writes them from the `.gmap` it writes.

mod common;
use common::{gmap, p, stderr, stdout};

use std::collections::BTreeSet;

use gmap_core::{AlphaSet, LabelValue};

#[allow(dead_code)]
#[path = "../examples/building.rs"]
mod building;

const ROOMS: [&str; 8] = ["bathroom", "bedroom", "hall", "kitchen", "landing", "living", "office", "study"];

fn text(v: Option<&LabelValue>) -> &str {
    match v {
        Some(LabelValue::Text(t)) => t,
        other => panic!("expected a text, found {other:?}"),
    }
}

#[test]
fn the_building_prints_its_counts_and_homology() {
    let dir = tempfile::tempdir().unwrap();
    let mut out = Vec::new();
    building::run(dir.path(), &mut out).unwrap();
    let out = String::from_utf8(out).unwrap();
    let expected = "\
#Darts=384, #0-cells=27, #1-cells=54, #2-cells=36, #3-cells=8, #ccs=1, orientable=true, valid=1
homology of the map: (Z, 0, 0, 0)
incidence graph: 125 regions (27, 54, 36, 8), 300 entries
homology of the incidence graph: (Z, 0, 0, 0)
rooms: 8
  hall (name=\"hall\" storey=0 area=14.0)
  kitchen (name=\"kitchen\" storey=0 area=14.0)
  living (name=\"living\" storey=0 area=14.0)
  study (name=\"study\" storey=0 area=14.0)
  landing (name=\"landing\" storey=1 area=14.0)
  bathroom (name=\"bathroom\" storey=1 area=14.0)
  bedroom (name=\"bedroom\" storey=1 area=14.0)
  office (name=\"office\" storey=1 area=14.0)
openings: door bedroom/office, door hall/kitchen, door hall/living, door landing/bathroom, \
door landing/bedroom, door living/study, stair hall/landing
wrote building.gmap, building.json, building.dot, building.vtk
";
    assert_eq!(out, expected);
    for ext in ["gmap", "json", "dot", "vtk"] {
        assert!(dir.path().join(format!("building.{ext}")).is_file(), "building.{ext}");
    }
}

#[test]
fn every_vertex_has_one_point_and_every_edge_runs_along_an_axis() {
    let g = building::building().unwrap();
    let (m, _) = g.to_dense_with_ids();
    assert_eq!(m.cell_counts(), vec![27, 54, 36, 8]);
    let vertices = m.cells(0);
    let mut points = BTreeSet::new();
    for d in m.darts() {
        let p = m.point(d).expect("every dart has its vertex's point");
        assert_eq!(Some(p), m.point(vertices.reps[vertices.of[d.index()] as usize]));
        points.insert(p.map(f64::to_bits));
        let q = m.point(m.alpha(d, 0)).unwrap();
        let moved: Vec<f64> = (0..3).map(|a| (q[a] - p[a]).abs()).filter(|&x| x != 0.0).collect();
        assert!(moved == [4.0] || moved == [3.5] || moved == [3.0], "{p:?} -> {q:?}");
    }
    assert_eq!(points.len(), 27);
    // each room is a box of 4 x 3.5 x 3 m: its darts span exactly that
    for &r in &m.cells(3).reps {
        let orbit = m.orbit(r, AlphaSet::of(&[0, 1, 2]));
        let span: Vec<f64> = (0..3)
            .map(|a| {
                let xs = orbit.iter().map(|&d| m.point(d).unwrap()[a]);
                xs.clone().fold(f64::MIN, f64::max) - xs.fold(f64::MAX, f64::min)
            })
            .collect();
        assert_eq!(span, [4.0, 3.5, 3.0]);
    }
}

#[test]
fn the_files_keep_the_names() {
    let dir = tempfile::tempdir().unwrap();
    building::run(dir.path(), &mut Vec::new()).unwrap();
    let file = |ext: &str| dir.path().join(format!("building.{ext}"));

    // .json: the rooms are the 3-regions, each door a 2-region between the two rooms it names
    let x = gmap_homology::json::read_json_file(&file("json")).unwrap();
    assert_eq!(x.region_counts(), vec![27, 54, 36, 8]);
    assert_eq!(x.homology_z().unwrap().betti, vec![1, 0, 0, 0]);
    let rooms: BTreeSet<&str> =
        x.regions_of_dim(3).iter().map(|&r| text(x.region_labels(r as usize).get("name"))).collect();
    assert_eq!(rooms, ROOMS.into_iter().collect());
    let mut kinds = std::collections::BTreeMap::new();
    for &f in x.regions_of_dim(2) {
        let l = x.region_labels(f as usize);
        *kinds.entry(text(l.get("kind")).to_string()).or_insert(0) += 1;
        let sides: BTreeSet<&str> = x.up_of(f as usize).map(|e| text(x.region_labels(e.from).get("name"))).collect();
        match l.get("between") {
            Some(LabelValue::Text(b)) => {
                assert_eq!(sides, b.split('/').collect(), "face {f}");
            }
            None => assert_eq!(sides.len(), 1, "an outer face bounds one room"),
            other => panic!("{other:?}"),
        }
    }
    let kinds: Vec<(String, i32)> = kinds.into_iter().collect();
    let want = [("door", 6), ("floor", 3), ("roof", 4), ("slab", 4), ("stair", 1), ("wall", 18)];
    assert_eq!(kinds, want.map(|(k, n)| (k.to_string(), n)));

    // .dot: a node per room shown by its name, the doors as attributes
    let dot = std::fs::read_to_string(file("dot")).unwrap();
    for r in ROOMS {
        assert_eq!(dot.matches(&format!("[label=\"{r}\\n3\", \"storey\"=")).count(), 1, "{r}");
    }
    assert_eq!(dot.matches("\"kind\"=\"door\", \"material\"=\"oak\"").count(), 6);

    // .vtk: 8 hexahedra and the 36 labelled faces (quadrangles), with their labels as cell data
    let vtk = std::fs::read_to_string(file("vtk")).unwrap();
    assert!(vtk.contains("\nCELLS 44 252\n"), "{vtk}");
    let types: Vec<&str> = vtk.split("CELL_TYPES 44\n").nth(1).unwrap().lines().take(44).collect();
    assert_eq!(types, [["12"; 8].as_slice(), ["9"; 36].as_slice()].concat());
    assert!(vtk.contains("\nCELL_DATA 44\nSCALARS dim int 1\n"));
    // name, storey, area, kind, material, between; the four text columns with their tables
    assert!(vtk.contains("\nFIELD labels 6\n"));
    assert!(vtk.contains("\nFIELD FieldData 4\n"));
    let array = |name: &str| -> Vec<&str> {
        vtk.split(&format!("\n{name} 1 44 ")).nth(1).unwrap().lines().skip(1).take(44).collect()
    };
    // a text column: ranks in the table of texts of the dataset's field data (NUL-ended bytes)
    let texts = |name: &str| -> Vec<String> {
        let head = format!("\ngmap:texts:{name} 1 ");
        let bytes: Vec<u8> = vtk
            .split(&head)
            .nth(1)
            .unwrap()
            .lines()
            .skip(1)
            .take_while(|l| l.starts_with(|c: char| c.is_ascii_digit()))
            .flat_map(|l| l.split(' ').map(|b| b.parse::<u8>().unwrap()).collect::<Vec<_>>())
            .collect();
        bytes[..bytes.len() - 1].split(|&b| b == 0).map(|t| String::from_utf8(t.to_vec()).unwrap()).collect()
    };
    let of = |name: &str| -> Vec<String> {
        let t = texts(name);
        array(name)
            .iter()
            .map(|r| r.parse::<i64>().unwrap())
            .map(|r| if r < 0 { String::new() } else { t[r as usize].clone() })
            .collect()
    };
    let names = of("name");
    assert_eq!(names[..8].iter().map(String::as_str).collect::<BTreeSet<_>>(), ROOMS.into_iter().collect());
    assert!(names[8..].iter().all(|n| n.is_empty()));
    assert_eq!(array("name")[8..], ["-1"; 36]);
    assert_eq!(of("kind").iter().filter(|k| *k == "door").count(), 6);
    assert_eq!(array("area")[..8], ["14.0"; 8]);
    assert!(vtk.contains("\nstorey 1 44 int\n") && vtk.contains("\narea 1 44 double\n"));

    // gmap convert from the .gmap writes the same .vtk and .json, and the .json reads back as it is
    for ext in ["vtk", "json", "dot"] {
        let again = dir.path().join(format!("again.{ext}"));
        // the incidence graphs drop the points: refused without --lossy, said on stderr with it
        let o = gmap(&["convert", p(&file("gmap")), p(&again)]);
        assert_eq!(o.status.success(), ext == "vtk", "{}", stderr(&o));
        let o = gmap(&["convert", "--lossy", p(&file("gmap")), p(&again)]);
        assert!(o.status.success(), "{}", stderr(&o));
        assert_eq!(stderr(&o).contains("drops the points"), ext != "vtk", "{}", stderr(&o));
        assert_eq!(std::fs::read(&again).unwrap(), std::fs::read(file(ext)).unwrap(), "{ext}");
    }
    let back = dir.path().join("back.json");
    assert!(gmap(&["convert", p(&file("json")), p(&back)]).status.success());
    assert_eq!(std::fs::read(&back).unwrap(), std::fs::read(file("json")).unwrap());
    let o = gmap(&["homology", p(&file("gmap"))]);
    assert!(stdout(&o).contains("H_0 = Z\nH_1 = 0\nH_2 = 0\nH_3 = 0\n"), "{}", stdout(&o));
}
