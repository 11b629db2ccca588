//! `.json` complexes named as an architect writes them: string ids, `name` labels, points,
//! incidence weights left out (chosen from the points or by propagation), and every
//! message naming regions by the file's ids and names.

use gmap_homology::arch::{ArchError, RegionId, ZeroWeightRule};
use gmap_homology::json::{read_json, write_json, JsonError};

fn data(name: &str) -> String {
    std::fs::read_to_string(format!("{}/../tests/data/arch/{name}", env!("CARGO_MANIFEST_DIR"))).unwrap()
}

/// The tetrahedron's surface with its weights removed.
fn unsigned_tetrahedron() -> String {
    let t = data("tetrahedron.json");
    let re = [", \"weight\": 1}", ", \"weight\": -1}"];
    re.iter().fold(t, |t, r| t.replace(r, "}"))
}

#[test]
fn weights_left_out_are_chosen_so_that_boundaries_are_cycles() {
    let x = read_json(&unsigned_tetrahedron()).unwrap();
    assert_eq!(x.homology_z().unwrap().betti, vec![1, 0, 1]);
    // the chosen signs are written and read back as they are
    let text = write_json(&x);
    assert!(!text.contains("\"weight\": 0"), "{text}");
    assert_eq!(read_json(&text).unwrap(), x);
    // the faces of a closed surface are oriented coherently: each edge cancels
    let ch = x.chain_complex();
    let m = ch.boundary(2).to_dense();
    for row in m {
        assert_eq!(row.iter().sum::<i64>(), 0, "an edge of the sphere is taken once each way");
    }
}

#[test]
fn two_rooms_with_a_door_and_a_window_oriented_from_their_points() {
    let x = read_json(&data("rooms_door_window.json")).unwrap();
    assert_eq!(x.region_counts(), vec![20, 29, 13, 2]);
    // the wall around the window is not a cell: the region complex has two components
    assert_eq!(x.homology_z().unwrap().betti, vec![2, 0, 0, 0]);
    let t = x.topological(ZeroWeightRule::Closed).unwrap();
    assert_eq!(t.complex.homology_z().unwrap().betti, vec![1, 0, 0, 0]);
    // both rooms have outward normals: the door, the window and the wall between them are
    // taken once with each sign
    let room = |key: &str| (0..x.regions().len()).find(|&k| x.region_key(k) == Some(key)).unwrap();
    for face in ["door", "window", "wall"] {
        let f = room(face);
        let (a, b) = (x.weight(room("room 1"), f).unwrap(), x.weight(room("room 2"), f).unwrap());
        assert_eq!(a, -b, "{face}");
    }
    // the window's edges and the wall's inner circle: opposite senses in the wall and the window
    let (wall, window) = (room("wall"), room("window"));
    for e in x.down(window) {
        assert_eq!(x.weight(wall, e.to), Some(-e.weight));
    }
    assert_eq!(x.region_name(room("room 1")), "room 1 (kitchen)");
    assert_eq!(x.region_point(room("v0")), Some([0.0, 0.0, 0.0]));
}

#[test]
fn string_ids_and_points_are_written_back() {
    let x = read_json(&data("floor_court.json")).unwrap();
    let text = write_json(&x);
    assert!(text.contains(r#"{"id": "v4", "dim": 0, "point": [3.0, 3.0, 0.0]}"#), "{text}");
    assert!(text.contains(r#"{"id": "floor", "dim": 2, "labels": {"name": "ground floor"}}"#), "{text}");
    assert!(text.contains(r#"{"from": "floor", "to": "e0", "weight": 1}"#), "{text}");
    assert_eq!(read_json(&text).unwrap(), x);
    // the floor runs anticlockwise seen from above, its court clockwise
    assert_eq!(x.homology_z().unwrap().betti, vec![2, 1, 0]);
    let t = x.topological(ZeroWeightRule::Closed).unwrap();
    assert_eq!(t.complex.homology_z().unwrap().betti, vec![1, 1, 0]);
}

#[test]
fn messages_name_regions_as_the_file_does() {
    let msg = |text: &str| read_json(text).unwrap_err().to_string();
    let cyc = r#"{"regions": [{"id": "beam", "dim": 1}, {"id": "post", "dim": 1, "labels": {"name": "main post"}}],
                  "incidence": [{"from": "beam", "to": "post", "weight": 0}, {"from": "post", "to": "beam", "weight": 0}]}"#;
    assert_eq!(msg(cyc), "the incidence graph has a cycle: beam -> post (main post) -> beam");
    let unknown = r#"{"regions": [{"id": "a", "dim": 0}, {"id": 3, "dim": 1, "labels": {"name": "beam"}}],
                      "incidence": [{"from": 3, "to": "b", "weight": 1}]}"#;
    assert_eq!(msg(unknown), "incidence entry 3 (beam) -> b names the unknown region b");
    let dup = r#"{"regions": [{"id": "a", "dim": 0}, {"id": "a", "dim": 1}], "incidence": []}"#;
    assert_eq!(msg(dup), "duplicate region id a");
    // signs left out where the faces cannot cancel: a triangle missing an edge, refused for
    // what it misses (not for its signs)
    let open = r#"{"regions": [{"id": "a", "dim": 0}, {"id": "b", "dim": 0}, {"id": "c", "dim": 0},
                    {"id": "ab", "dim": 1}, {"id": "bc", "dim": 1}, {"id": "room", "dim": 2}],
                   "incidence": [{"from": "ab", "to": "a"}, {"from": "ab", "to": "b"}, {"from": "bc", "to": "b"},
                    {"from": "bc", "to": "c"}, {"from": "room", "to": "ab"}, {"from": "room", "to": "bc"}]}"#;
    assert_eq!(
        msg(open),
        "2-region room is not closed: its edges leave the vertices a, c on one of them only, so an edge is missing"
    );
    match read_json(open) {
        Err(JsonError::Arch(ArchError::BoundaryOpen { id, dim: 2, .. }, names)) => assert_eq!(names.get(id), "room"),
        other => panic!("{other:?}"),
    }
    // some weights given and some left out
    let mixed = r#"{"regions": [{"id": "a", "dim": 0}, {"id": "b", "dim": 0}, {"id": "ab", "dim": 1}],
                    "incidence": [{"from": "ab", "to": "a", "weight": -1}, {"from": "ab", "to": "b"}]}"#;
    assert_eq!(msg(mixed), "1-region ab cannot be oriented: some of its incidence weights are given and some left out; give the incidence weights");
    // string ids are numbered after the largest number used
    let x = read_json(r#"{"regions": [{"id": 7, "dim": 0}, {"id": "p", "dim": 0}], "incidence": []}"#).unwrap();
    assert_eq!(x.region(1).id, RegionId(8));
    assert_eq!(x.region_name(1), "p");
    assert_eq!(x.region_name(0), "7");
}

#[test]
fn unsigned_non_orientable_complexes_are_refused_with_a_region_name() {
    // three squares in a ring: without a twist an annulus, read with its groups
    let annulus = read_json(&data("annulus_unsigned.json")).unwrap();
    assert_eq!(annulus.homology_z().unwrap().betti, vec![1, 1, 0]);
    // the faces of neighbours cancel: every edge between two squares has weights ±1 summing to 0
    let ch = annulus.chain_complex();
    for row in ch.boundary(2).to_dense() {
        let s: i64 = row.iter().sum();
        assert!(s == 0 || row.iter().filter(|&&w| w != 0).count() == 1, "{row:?}");
    }
    // with a twist, a Möbius band: no orientation agrees all the way round
    let text = data("moebius_unsigned.json");
    match read_json(&text) {
        Err(e @ JsonError::Arch(ArchError::CannotOrient { dim: 2, at: Some(_), .. }, _)) => {
            let m = e.to_string();
            assert!(m.contains("2-region square ") && m.contains("(panel "), "{m}");
            assert!(m.contains("the complex is not orientable"), "{m}");
            assert!(m.contains("at region rung "), "{m}");
            assert!(m.ends_with("give the incidence weights"), "{m}");
        }
        other => panic!("{other:?}"),
    }
}
