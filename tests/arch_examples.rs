//! The architect's examples (`examples/arch_rooms_door_window.rs`,
//! `examples/arch_floor_court.rs`) print exactly their known homology, TM check and views;
//! `gmap tm check` and `gmap tm views` print the same through the command line, name cells
//! as the file does, and exit 1 on a model that fails the check.

mod common;
use common::{gmap, p, stderr, stdout};

#[allow(dead_code)]
#[path = "../examples/arch_floor_court.rs"]
mod floor;
use floor::rooms;

/// An example's `run`.
type Run = fn(&mut dyn std::io::Write) -> Result<(), Box<dyn std::error::Error>>;

const ROOMS: &str = r#"homology of the region complex: (Z^2, 0, 0, 0)
homology of the space (--topological): (Z, 0, 0, 0)
TM model of dimension 3, cells (0..n) 20 29 13 2
defects: 10
  (7:6) the coboundary of 2-cell floor 1 is not a cocircuit: it lies on one 3-cell only (taken -1), a free face
  (7:6) the coboundary of 2-cell ceiling 1 is not a cocircuit: it lies on one 3-cell only (taken +1), a free face
  (7:6) the coboundary of 2-cell south 1 is not a cocircuit: it lies on one 3-cell only (taken +1), a free face
  (7:6) the coboundary of 2-cell north 1 is not a cocircuit: it lies on one 3-cell only (taken -1), a free face
  (7:6) the coboundary of 2-cell west wall is not a cocircuit: it lies on one 3-cell only (taken -1), a free face
  (7:6) the coboundary of 2-cell floor 2 is not a cocircuit: it lies on one 3-cell only (taken -1), a free face
  (7:6) the coboundary of 2-cell ceiling 2 is not a cocircuit: it lies on one 3-cell only (taken +1), a free face
  (7:6) the coboundary of 2-cell south 2 is not a cocircuit: it lies on one 3-cell only (taken +1), a free face
  (7:6) the coboundary of 2-cell north 2 is not a cocircuit: it lies on one 3-cell only (taken -1), a free face
  (7:6) the coboundary of 2-cell east wall is not a cocircuit: it lies on one 3-cell only (taken +1), a free face
closed by the exterior 3-cell: no defect (the defects above are its free faces)
metrical edit (TM X, tolerance 8e-8): no defect
passes the edit check
views of the 2-cells (TM 7:1) and the 3-cells on their sides (TM 7:3):
  floor 1: near room 1 (kitchen), far nothing; boundary 6 1-cells, 6 0-cells
  ceiling 1: near nothing, far room 1 (kitchen); boundary 4 1-cells, 4 0-cells
  south 1: near nothing, far room 1 (kitchen); boundary 4 1-cells, 4 0-cells
  north 1: near room 1 (kitchen), far nothing; boundary 4 1-cells, 4 0-cells
  west wall: near room 1 (kitchen), far nothing; boundary 4 1-cells, 4 0-cells
  floor 2: near room 2 (living), far nothing; boundary 6 1-cells, 6 0-cells
  ceiling 2: near nothing, far room 2 (living); boundary 4 1-cells, 4 0-cells
  south 2: near nothing, far room 2 (living); boundary 4 1-cells, 4 0-cells
  north 2: near room 2 (living), far nothing; boundary 4 1-cells, 4 0-cells
  east wall: near nothing, far room 2 (living); boundary 4 1-cells, 4 0-cells
  wall: near room 2 (living), far room 1 (kitchen); boundary 12 1-cells, 12 0-cells
  door: near room 2 (living), far room 1 (kitchen); boundary 4 1-cells, 4 0-cells
  window: near room 2 (living), far room 1 (kitchen); boundary 4 1-cells, 4 0-cells
"#;

const FLOOR: &str = r#"homology of the region complex: (Z^2, Z, 0)
homology of the space (--topological): (Z, Z, 0)
TM model of dimension 2, cells (0..n) 8 8 1
defects: 8
  (7:6) the coboundary of 1-cell e0 is not a cocircuit: it lies on one 2-cell only (taken +1), a free face
  (7:6) the coboundary of 1-cell e1 is not a cocircuit: it lies on one 2-cell only (taken +1), a free face
  (7:6) the coboundary of 1-cell e2 is not a cocircuit: it lies on one 2-cell only (taken -1), a free face
  (7:6) the coboundary of 1-cell e3 is not a cocircuit: it lies on one 2-cell only (taken -1), a free face
  (7:6) the coboundary of 1-cell e4 is not a cocircuit: it lies on one 2-cell only (taken -1), a free face
  (7:6) the coboundary of 1-cell e5 is not a cocircuit: it lies on one 2-cell only (taken -1), a free face
  (7:6) the coboundary of 1-cell e6 is not a cocircuit: it lies on one 2-cell only (taken +1), a free face
  (7:6) the coboundary of 1-cell e7 is not a cocircuit: it lies on one 2-cell only (taken +1), a free face
closed by the exterior 2-cell: no defect (the defects above are its free faces)
metrical edit (TM X, tolerance 8e-8): no defect
passes the edit check
views of the 1-cells (TM 7:1) and the 2-cells on their sides (TM 7:3):
  e0: near nothing, far floor (ground floor); boundary 2 0-cells
  e1: near nothing, far floor (ground floor); boundary 2 0-cells
  e2: near floor (ground floor), far nothing; boundary 2 0-cells
  e3: near floor (ground floor), far nothing; boundary 2 0-cells
  e4: near floor (ground floor), far nothing; boundary 2 0-cells
  e5: near floor (ground floor), far nothing; boundary 2 0-cells
  e6: near nothing, far floor (ground floor); boundary 2 0-cells
  e7: near nothing, far floor (ground floor); boundary 2 0-cells
"#;

fn run(f: Run) -> String {
    let mut out = Vec::new();
    f(&mut out).unwrap();
    String::from_utf8(out).unwrap()
}

#[test]
fn two_rooms_with_a_door_and_a_window() {
    assert_eq!(run(rooms::run), ROOMS);
}

#[test]
fn a_floor_with_a_court() {
    assert_eq!(run(floor::run), FLOOR);
}

#[test]
fn tm_commands_print_what_the_examples_print() {
    let file = rooms::model();
    let check = gmap(&["tm", "check", p(&file)]);
    assert!(check.status.success(), "{}", stderr(&check));
    let views = gmap(&["tm", "views", p(&file)]);
    assert!(ROOMS.ends_with(&format!("{}{}", stdout(&check), stdout(&views))));
    let door = gmap(&["tm", "views", p(&file), "--cell", "door"]);
    assert_eq!(
        stdout(&door),
        "view (TM 7:1) of 2-cell door: 9 cells\nnear room 2 (living), far room 1 (kitchen) (TM 7:3)\n  2-cell door +1\n  1-cell e2 +1\n  1-cell e22 -1\n  1-cell e23 -1\n  1-cell e24 +1\n  0-cell v14 +1/-1\n  0-cell v15 +1/-1\n  0-cell v2 +1/-1\n  0-cell v3 +1/-1\n"
    );
    // a room by its name label; a 1-cell's section with its ends
    let kitchen = gmap(&["tm", "views", p(&file), "--cell", "kitchen"]);
    assert!(
        stdout(&kitchen).starts_with("view (TM 7:1) of 3-cell room 1 (kitchen): 46 cells\n"),
        "{}",
        stdout(&kitchen)
    );
    let e2 = gmap(&["tm", "views", p(&file), "--cell", "e2"]);
    assert!(stdout(&e2).starts_with("section (TM 7:2) of 1-cell e2: "), "{}", stdout(&e2));
    assert!(stdout(&e2).contains("from v2 to v3 (TM 7:4)\n"), "{}", stdout(&e2));
    let none = gmap(&["tm", "views", p(&file), "--cell", "attic"]);
    assert_eq!(none.status.code(), Some(1));
    assert!(stderr(&none).contains("no cell is called 'attic'"), "{}", stderr(&none));
}

#[test]
fn tm_check_fails_with_the_cells_named() {
    // room 2 turned inside out (every weight of its faces negated): still a complex, but
    // both rooms take the door, the window and the wall with the same sign
    let text = std::fs::read_to_string(rooms::model()).unwrap();
    let dir = tempfile::tempdir().unwrap();
    let signed = dir.path().join("signed.json");
    let x = gmap::algebra::json::read_json(&text).unwrap();
    let mut out = String::new();
    for line in gmap::algebra::json::write_json(&x).lines() {
        let flipped = match line.find(r#""from": "room 2","#) {
            Some(_) if line.contains("\"weight\": -1") => line.replace("\"weight\": -1", "\"weight\": 1"),
            Some(_) => line.replace("\"weight\": 1", "\"weight\": -1"),
            None => line.to_string(),
        };
        out.push_str(&flipped);
        out.push('\n');
    }
    std::fs::write(&signed, out).unwrap();
    let check = gmap(&["tm", "check", p(&signed)]);
    assert_eq!(check.status.code(), Some(1), "{}", stdout(&check));
    let text = stdout(&check);
    assert!(text.contains("defects: 13\n"), "{text}");
    assert!(
        text.contains("(7:6) the coboundary of 2-cell door is not a cocircuit: the 3-cells on it take it "),
        "{text}"
    );
    assert!(text.ends_with("fails the edit check\n"), "{text}");
    // a cubical set has no TM model
    let cub = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/cubical");
    let any = std::fs::read_dir(cub)
        .unwrap()
        .map(|e| e.unwrap().path())
        .find(|p| p.extension().is_some_and(|e| e == "cub"))
        .unwrap();
    let refused = gmap(&["tm", "check", p(&any)]);
    assert_eq!(refused.status.code(), Some(1));
    assert!(
        stderr(&refused).contains("a TM model is made from an architectural complex (.json) or a G-map"),
        "{}",
        stderr(&refused)
    );
}

#[test]
fn generators_name_regions_by_the_files_ids_and_names() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("named.json");
    let tet = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/arch/tetrahedron.json");
    let text = std::fs::read_to_string(tet).unwrap();
    std::fs::write(
        &file,
        text.replace(r#"{"id": 10, "dim": 2}"#, r#"{"id": 10, "dim": 2, "labels": {"name": "roof"}}"#),
    )
    .unwrap();
    let o = gmap(&["homology", p(&file), "--generators"]);
    assert!(
        stdout(&o).ends_with("generator of H_2 (Z): -1 region 10 (roof) +1 region 11 -1 region 12 +1 region 13\n"),
        "{}",
        stdout(&o)
    );
    let o = gmap(&["homology", p(&file), "--generators", "--json"]);
    assert!(stdout(&o).contains(r#"{"cell":{"name":"roof","region":10},"coefficient":-1}"#), "{}", stdout(&o));
    // string ids: the file's id in the JSON
    let floor = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/arch/floor_court.json");
    let o = gmap(&["homology", p(&floor), "--generators", "--json"]);
    assert!(stdout(&o).contains(r#"{"cell":{"region":"e4"},"coefficient":-1}"#), "{}", stdout(&o));
}
