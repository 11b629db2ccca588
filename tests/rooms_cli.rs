//! Rooms from walls (`gmap rooms`, `gmap::rooms_of`): the two-storey building of
//! `examples/building.rs` given only as its faces (`tests/data/arch/building_walls.off`, its
//! 2-skeleton) gives back its 8 rooms, the outer cell and the rooms' adjacency; random
//! boxes in a grid give one 3-cell per box.

mod common;
use common::{gmap, p, stderr, stdout};

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

use gmap::algebra::lar::Faces;
use proptest::prelude::*;

#[allow(dead_code)]
#[path = "../examples/building.rs"]
mod building;

fn soup() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/arch/building_walls.off")
}

#[test]
fn the_soup_is_the_buildings_faces() {
    let g = building::building().unwrap();
    let text = gmap::ops::export::gmap_two_skeleton_off_string(&g).unwrap();
    if std::env::var_os("GMAP_BLESS").is_some() {
        std::fs::write(soup(), &text).unwrap();
    }
    assert_eq!(std::fs::read_to_string(soup()).unwrap(), text, "GMAP_BLESS=1 rewrites it");
    assert_eq!(text.lines().nth(1), Some("27 36 0"));
}

/// The grid cell (x, y, storey) of a room of the building by its volume's centre.
fn grid_cell(x: &gmap::algebra::arch::ArchComplex, room: usize) -> [usize; 3] {
    let mut pts = BTreeSet::new();
    for f in x.down(room) {
        for e in x.down(f.to) {
            for v in x.down(e.to) {
                pts.insert(v.to);
            }
        }
    }
    let n = pts.len() as f64;
    let c = pts.iter().fold([0.0; 3], |c, &v| {
        let p = x.region_point(v).unwrap();
        [c[0] + p[0] / n, c[1] + p[1] / n, c[2] + p[2] / n]
    });
    [usize::from(c[0] > 4.0), usize::from(c[1] > 3.5), usize::from(c[2] > 3.0)]
}

#[test]
fn the_building_from_its_walls() {
    let rooms = gmap::rooms_of(&soup()).unwrap();
    assert_eq!(rooms.counts, [27, 54, 36]);
    assert_eq!(rooms.rooms.len(), 8);
    let x = &rooms.complex;
    assert_eq!(x.region_counts(), vec![27, 54, 36, 8]);
    assert_eq!(x.homology_z().unwrap().betti, vec![1, 0, 0, 0]);
    // every room is one of the grid's cubes, once; volumes 4 × 3.5 × 3 m
    let cells: BTreeSet<[usize; 3]> = x.regions_of_dim(3).iter().map(|&r| grid_cell(x, r as usize)).collect();
    assert_eq!(cells.len(), 8);
    assert!(rooms.rooms.iter().all(|r| r.1 == 6 && (r.2 - 42.0).abs() < 1e-9), "{:?}", rooms.rooms);
    // the adjacency: rooms sharing a face are the grid's neighbours, 12 pairs, as in the
    // building's own incidence graph
    let mut pairs = BTreeSet::new();
    for (name, _, _, next) in &rooms.rooms {
        for other in next {
            let k = |n: &str| x.regions_of_dim(3).iter().map(|&r| r as usize).find(|&r| x.region_name(r) == n).unwrap();
            let (a, b) = (grid_cell(x, k(name)), grid_cell(x, k(other)));
            pairs.insert((a.min(b), a.max(b)));
        }
    }
    assert_eq!(pairs.len(), 12);
    assert!(pairs.iter().all(|(a, b)| (0..3).filter(|&i| a[i] != b[i]).count() == 1));
    let g = building::building().unwrap();
    let arch = gmap::algebra::arch::ArchComplex::from_labelled_map(&g).unwrap();
    let mut theirs = 0;
    for &a in arch.regions_of_dim(3) {
        for &b in arch.regions_of_dim(3) {
            let fa: BTreeSet<usize> = arch.down(a as usize).iter().map(|e| e.to).collect();
            if a < b && arch.down(b as usize).iter().any(|e| fa.contains(&e.to)) {
                theirs += 1;
            }
        }
    }
    assert_eq!(theirs, 12);
}

#[test]
fn gmap_rooms_writes_a_three_map_whose_volumes_are_the_rooms() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("rooms.gmap");
    let o = gmap(&["rooms", p(&soup()), p(&out)]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = stdout(&o);
    assert!(text.starts_with("faces 36, edges 54, vertices 27\n3-cells 9: 8 rooms and the outer cell\n"), "{text}");
    assert_eq!(text.lines().filter(|l| l.starts_with("room ")).count(), 8);
    let info = gmap(&["info", p(&out)]);
    assert!(stdout(&info).contains("cells (0..n)          27 54 36 8\n"), "{}", stdout(&info));
    let h = gmap(&["homology", p(&out)]);
    assert!(stdout(&h).contains("H_0 = Z\nH_1 = 0\nH_2 = 0\nH_3 = 0\n"), "{}", stdout(&h));
    // from a .json the faces keep their ids and labels
    let json = dir.path().join("rooms.json");
    let from = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/arch/rooms_door_window.json");
    let o = gmap(&["rooms", p(&from), p(&json)]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(stdout(&o), "faces 13, edges 29, vertices 20\n3-cells 3: 2 rooms and the outer cell\nroom 1 (kitchen): 8 faces, volume 72; next to room 2 (living)\nroom 2 (living): 8 faces, volume 72; next to room 1 (kitchen)\n");
    let written = std::fs::read_to_string(&json).unwrap();
    assert!(written.contains(r#"{"id": "window", "dim": 2, "labels": {"kind": "window"}}"#), "{written}");
    // .gmap: the faces' labels and ids on the 2-cells (the wall with the window cut in two
    // pieces, both the wall's), the rooms' ids on the volumes, the vertices' points
    let map = dir.path().join("rooms.gmap");
    let o = gmap(&["rooms", p(&from), p(&map)]);
    assert!(o.status.success(), "{}", stderr(&o));
    let g = gmap::core::io::read_labelled_gmap(&map).unwrap();
    let (dense, labels, _) = gmap::core::to_dense_labels(&g);
    assert_eq!(dense.cell_counts(), vec![20, 31, 14, 2]);
    let text = |l: &gmap::core::Labels, k: &str| match l.get(k) {
        Some(gmap::core::LabelValue::Text(t)) => t.clone(),
        other => panic!("{k}: {other:?}"),
    };
    let mut faces: Vec<(String, String)> = labels.of[2].iter().map(|l| (text(l, "id"), text(l, "kind"))).collect();
    faces.sort();
    let want: Vec<(String, String)> = [
        ("ceiling 1", "ceiling"),
        ("ceiling 2", "ceiling"),
        ("door", "door"),
        ("east wall", "wall"),
        ("floor 1", "floor"),
        ("floor 2", "floor"),
        ("north 1", "wall"),
        ("north 2", "wall"),
        ("south 1", "wall"),
        ("south 2", "wall"),
        ("wall", "wall"),
        ("wall", "wall"),
        ("west wall", "wall"),
        ("window", "window"),
    ]
    .iter()
    .map(|(a, b)| (a.to_string(), b.to_string()))
    .collect();
    assert_eq!(faces, want);
    let mut rooms: Vec<String> = labels.of[3].iter().map(|l| text(l, "id")).collect();
    rooms.sort();
    assert_eq!(rooms, ["room 1", "room 2"]);
    assert!(g.has_points());
    // and gmap convert keeps them: nothing dropped, no --lossy needed
    let converted = dir.path().join("converted.gmap");
    let o = gmap(&["convert", p(&json), p(&converted)]);
    assert!(o.status.success(), "{}", stderr(&o));
    let again = gmap::core::io::read_labelled_gmap(&converted).unwrap();
    assert_eq!(gmap::core::to_dense_labels(&again).1, labels);
    // a free-standing wall is refused with its name
    let free = dir.path().join("free.off");
    std::fs::write(&free, "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n").unwrap();
    let o = gmap(&["rooms", p(&free), p(&json)]);
    assert_eq!(o.status.code(), Some(1));
    assert!(stderr(&o).contains("rooms from walls: face 0 has the same 3-cell on both sides"), "{}", stderr(&o));
}

/// The faces of the boxes `chosen` of an nx × ny × nz grid with lines at `xs`, `ys`, `zs`.
fn boxes(lines: &[Vec<f64>; 3], chosen: &BTreeSet<[usize; 3]>) -> Faces {
    let [nx, ny, _] = [lines[0].len(), lines[1].len(), lines[2].len()];
    let vid = |i: usize, j: usize, k: usize| (i + nx * (j + ny * k)) as u32;
    let mut points = Vec::new();
    for k in 0..lines[2].len() {
        for j in 0..ny {
            for i in 0..nx {
                points.push([lines[0][i], lines[1][j], lines[2][k]]);
            }
        }
    }
    let mut faces: BTreeSet<Vec<u32>> = BTreeSet::new();
    for &[i, j, k] in chosen {
        let c = |a: usize, b: usize, d: usize| vid(i + a, j + b, k + d);
        let quads = [
            [c(0, 0, 0), c(1, 0, 0), c(1, 1, 0), c(0, 1, 0)],
            [c(0, 0, 1), c(1, 0, 1), c(1, 1, 1), c(0, 1, 1)],
            [c(0, 0, 0), c(1, 0, 0), c(1, 0, 1), c(0, 0, 1)],
            [c(0, 1, 0), c(1, 1, 0), c(1, 1, 1), c(0, 1, 1)],
            [c(0, 0, 0), c(0, 1, 0), c(0, 1, 1), c(0, 0, 1)],
            [c(1, 0, 0), c(1, 1, 0), c(1, 1, 1), c(1, 0, 1)],
        ];
        for q in quads {
            faces.insert(q.to_vec());
        }
    }
    Faces::try_new(points, faces.into_iter().map(|q| vec![q]).collect()).unwrap()
}

/// The boxes face-connected to the first one.
fn component(chosen: &BTreeSet<[usize; 3]>) -> BTreeSet<[usize; 3]> {
    let mut out = BTreeSet::new();
    let mut stack: Vec<[usize; 3]> = chosen.iter().next().copied().into_iter().collect();
    while let Some(b) = stack.pop() {
        if !out.insert(b) {
            continue;
        }
        for i in 0..3 {
            for d in [-1i64, 1] {
                let mut n = b;
                let v = n[i] as i64 + d;
                if v < 0 {
                    continue;
                }
                n[i] = v as usize;
                if chosen.contains(&n) && !out.contains(&n) {
                    stack.push(n);
                }
            }
        }
    }
    out
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// Random face-connected boxes of a 3 × 3 × 2 grid with random spacings (no box can
    /// enclose a void): one 3-cell per box and the outer cell; each box's cell is its six
    /// faces, with volume the box's.
    #[test]
    fn boxes_in_a_grid_give_one_cell_per_box(
        picks in proptest::collection::btree_set((0usize..3, 0usize..3, 0usize..2), 1..18),
        steps in proptest::collection::vec(1u32..5, 10),
    ) {
        let chosen: BTreeSet<[usize; 3]> = picks.into_iter().map(|(a, b, c)| [a, b, c]).collect();
        let chosen = component(&chosen);
        let line = |from: usize, n: usize| -> Vec<f64> {
            let mut v = vec![0.0];
            for s in &steps[from..from + n] {
                v.push(v.last().unwrap() + f64::from(*s));
            }
            v
        };
        let lines = [line(0, 3), line(3, 3), line(6, 2)];
        let faces = boxes(&lines, &chosen);
        let cells = faces.cells().unwrap();
        prop_assert_eq!(cells.cells.len(), chosen.len() + 1);
        prop_assert!(cells.rooms().all(|c| c.len() == 6));
        let mut volumes: Vec<f64> =
            (0..cells.cells.len()).filter(|&k| k != cells.outer).map(|k| cells.volumes6[k] / 6.0).collect();
        let mut expected: Vec<f64> = chosen.iter().map(|&[i, j, k]| {
            (lines[0][i + 1] - lines[0][i]) * (lines[1][j + 1] - lines[1][j]) * (lines[2][k + 1] - lines[2][k])
        }).collect();
        volumes.sort_by(f64::total_cmp);
        expected.sort_by(f64::total_cmp);
        prop_assert_eq!(volumes, expected);
        let total: f64 = cells.volumes6.iter().sum();
        prop_assert!(total.abs() < 1e-9, "the outer cell's volume is minus the rooms'");
    }
}
