//! The metrical edit of complexes with points (TM §X–XI): a T-junction and a point given
//! twice are refused naming their cells, snapping welds and splits them into the building
//! meant, and a room missing a face is named with the room it opens into.

use gmap_homology::arch::{ArchError, MetricDefect, Shape};
use gmap_homology::json::{json_metric_defects, read_json, read_json_with, JsonError, JsonOptions};

fn data(name: &str) -> String {
    std::fs::read_to_string(format!("{}/../tests/data/arch/{name}", env!("CARGO_MANIFEST_DIR"))).unwrap()
}

/// Names of the metrical defects of a file (read without orienting it).
fn defects(text: &str) -> Vec<String> {
    let (d, names, _) = json_metric_defects(text).unwrap();
    d.iter().map(|d| d.named(&names).to_string()).collect()
}

#[test]
fn a_t_junction_is_refused_naming_the_walls() {
    let text = data("t_junction.json");
    match read_json(&text) {
        Err(JsonError::NotConforming { defects, names, tolerance }) => {
            assert_eq!(tolerance, 8e-8);
            let msgs: Vec<String> = defects.iter().map(|d| d.named(&names).to_string()).collect();
            for want in [
                "point p400 lies inside edge p000-p800 (a T-junction)",
                "point p403 lies inside edge p003-p803 (a T-junction)",
                "point p460 lies inside edge p060-p860 (a T-junction)",
                "edge p400-p403 lies inside face south wall (a T-junction)",
                "edge p460-p463 lies inside face north wall (a T-junction)",
            ] {
                assert!(msgs.iter().any(|m| m == want), "{want} not in {msgs:?}");
            }
            assert!(defects
                .iter()
                .all(|d| matches!(d, MetricDefect::VertexOnEdge { .. } | MetricDefect::EdgeInFace { .. })));
            assert_eq!(defects.len(), 6, "{msgs:?}");
        }
        other => panic!("{other:?}"),
    }
    let m = read_json(&text).unwrap_err().to_string();
    assert!(m.starts_with("the points do not make a conforming complex (tolerance 8e-8): point p4"), "{m}");
    assert!(m.contains("--snap EPS"), "{m}");
}

#[test]
fn snapping_a_t_junction_gives_the_two_rooms() {
    let (x, report) = read_json_with(&data("t_junction.json"), &JsonOptions::snap(Some(1e-6))).unwrap();
    // 12 points; 20 edges (the 4 long ones cut in two, merged with the floors' and
    // ceilings' edges); 11 faces (south and north walls cut); 2 rooms
    assert_eq!(x.region_counts(), vec![12, 20, 11, 2], "{report:#?}");
    assert_eq!(x.homology_z().unwrap().betti, vec![1, 0, 0, 0]);
    assert!(Shape::of(&x).defects().is_empty());
    assert!(report.iter().any(|l| l == "split edge p000-p800 at p400 into p000-p800, p000-p800.2"), "{report:?}");
    assert!(
        report.iter().any(|l| l.starts_with("split face south wall along p400-p403 into south wall, south wall.2")),
        "{report:?}"
    );
    // each room is closed by its own half of the south and north walls
    let room = |n: &str| (0..x.regions().len()).find(|&k| x.region_name(k) == n).unwrap();
    for r in ["room 1 (kitchen)", "room 2 (living)"] {
        assert_eq!(x.down(room(r)).len(), 6, "{r}");
    }
    // the rooms share the party wall only
    let faces = |r: usize| x.down(r).iter().map(|e| e.to).collect::<std::collections::BTreeSet<_>>();
    let common: Vec<String> = faces(room("room 1 (kitchen)"))
        .intersection(&faces(room("room 2 (living)")))
        .map(|&f| x.region_name(f))
        .collect();
    assert_eq!(common, vec!["party wall"]);
}

#[test]
fn a_point_given_twice_is_refused_and_welded() {
    let text = data("near_points.json");
    let m = read_json(&text).unwrap_err().to_string();
    assert!(m.contains(": points p400 and p400 copy are 1.00e-9 apart: the same point twice ("), "{m}");
    let (x, report) = read_json_with(&text, &JsonOptions::snap(Some(1e-6))).unwrap();
    assert_eq!(report, vec!["welded point p400 copy into p400 (1.00e-9 apart)"]);
    assert_eq!(x.region_counts(), vec![12, 20, 11, 2]);
    assert_eq!(x.homology_z().unwrap().betti, vec![1, 0, 0, 0]);
    assert!(Shape::of(&x).defects().is_empty());
    // the same copy used by the kitchen's floor: refused for the point, not for the open room
    let text = data("near_points_floor.json");
    let m = read_json(&text).unwrap_err().to_string();
    assert!(m.contains(": points p400 and p400 copy are 1.00e-9 apart: the same point twice ("), "{m}");
    let (x, report) = read_json_with(&text, &JsonOptions::snap(Some(1e-6))).unwrap();
    assert_eq!(report[0], "welded point p400 copy into p400 (1.00e-9 apart)");
    assert_eq!(report[1], "merged edge p000-p400 copy into p000-p400: the same ends");
    assert_eq!(x.region_counts(), vec![12, 20, 11, 2]);
    assert_eq!(x.homology_z().unwrap().betti, vec![1, 0, 0, 0]);
}

#[test]
fn the_metrical_edit_names_both_defects() {
    let t = defects(&data("t_junction.json"));
    assert_eq!(t.len(), 6);
    let n = defects(&data("near_points.json"));
    assert_eq!(n, vec!["points p400 and p400 copy are 1.00e-9 apart: the same point twice"]);
}

#[test]
fn every_conforming_example_passes_the_metrical_edit() {
    for f in [
        "two_rooms.json",
        "court.json",
        "floor_court.json",
        "rooms_door_window.json",
        "window.json",
        "tetrahedron.json",
    ] {
        let text = data(f);
        assert!(defects(&text).is_empty(), "{f}: {:?}", defects(&text));
        read_json(&text).unwrap();
    }
}

#[test]
fn a_missing_party_wall_names_both_rooms() {
    // the party wall left out of both rooms: each is open along its edges
    let text = data("two_rooms.json");
    assert_eq!(read_json(&text).unwrap().homology_z().unwrap().betti, vec![1, 0, 0, 0]);
    let text = text
        .replace(r#"{"from": "room 1", "to": "party wall"},"#, "")
        .replace(r#"{"from": "room 2", "to": "party wall"},"#, "");
    match read_json(&text) {
        Err(e @ JsonError::Arch(ArchError::BoundaryOpen { dim: 3, with: Some(_), .. }, _)) => assert_eq!(
            e.to_string(),
            "3-region room 1 (kitchen) is not closed: its faces leave the edges p400-p460, p403-p463, p460-p463, p400-p403 on one of them only, so a face is missing; room 2 (living) is open at the same place: the face between room 1 (kitchen) and room 2 (living) is missing (a party wall)"
        ),
        other => panic!("{other:?}"),
    }
}
