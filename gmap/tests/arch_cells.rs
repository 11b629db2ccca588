//! No conversion of an architectural complex changes the space: regions that are not cells
//! (a wall with a window, a floor around a court) are cut into cells, so every format
//! written through a G-map reads back with the groups of `gmap homology --topological`;
//! what cannot be cut is refused with the region's name.

use std::collections::HashMap;
use std::path::Path;

use proptest::prelude::*;

/// A complex built from coordinates: vertices, edges and faces oriented from them, so the
/// incidence signs satisfy δ² = 0 (the model generator of tests/data/arch/window.json).
#[derive(Default)]
struct Model {
    regions: Vec<String>,
    incidence: Vec<String>,
    vertices: HashMap<[i64; 3], usize>,
    edges: HashMap<(usize, usize), usize>,
}

impl Model {
    fn region(&mut self, dim: usize, name: Option<&str>) -> usize {
        let id = self.regions.len();
        let labels = name.map(|n| format!(r#", "labels": {{"name": "{n}"}}"#)).unwrap_or_default();
        self.regions.push(format!(r#"{{"id": {id}, "dim": {dim}{labels}}}"#));
        id
    }

    fn entry(&mut self, from: usize, to: usize, weight: i64) {
        self.incidence.push(format!(r#"{{"from": {from}, "to": {to}, "weight": {weight}}}"#));
    }

    fn vertex(&mut self, p: [i64; 3]) -> usize {
        if let Some(&v) = self.vertices.get(&p) {
            return v;
        }
        let v = self.region(0, None);
        self.vertices.insert(p, v);
        v
    }

    /// The edge between two vertices (from the smaller id to the larger) and the sign of
    /// the direction a → b along it.
    fn edge(&mut self, a: usize, b: usize) -> (usize, i64) {
        let key = (a.min(b), a.max(b));
        let e = match self.edges.get(&key) {
            Some(&e) => e,
            None => {
                let e = self.region(1, None);
                self.entry(e, key.1, 1);
                self.entry(e, key.0, -1);
                self.edges.insert(key, e);
                e
            }
        };
        (e, if a < b { 1 } else { -1 })
    }

    /// A 2-region over circles of points, each traversed in the face's orientation (holes
    /// the other way round).
    fn face(&mut self, circles: &[Vec<[i64; 3]>], name: Option<&str>) -> usize {
        let f = self.region(2, name);
        for c in circles {
            let ids: Vec<usize> = c.iter().map(|&p| self.vertex(p)).collect();
            for k in 0..ids.len() {
                let (e, sign) = self.edge(ids[k], ids[(k + 1) % ids.len()]);
                self.entry(f, e, sign);
            }
        }
        f
    }

    fn json(&self, dim: usize) -> String {
        format!(
            "{{\"dimension\": {dim},\n\"regions\": [{}],\n\"incidence\": [{}]}}\n",
            self.regions.join(",\n"),
            self.incidence.join(",\n")
        )
    }
}

/// The rectangle `[u0, u1] × [v0, v1]` in the plane `x_axis = c`, counter-clockwise about
/// `+axis` (in the basis `(axis + 1, axis + 2)`), or clockwise.
fn rect(axis: usize, c: i64, [u0, u1, v0, v1]: [i64; 4], clockwise: bool) -> Vec<[i64; 3]> {
    let mut pts: Vec<[i64; 3]> = [(u0, v0), (u1, v0), (u1, v1), (u0, v1)]
        .iter()
        .map(|&(u, v)| {
            let mut p = [0; 3];
            (p[axis], p[(axis + 1) % 3], p[(axis + 2) % 3]) = (c, u, v);
            p
        })
        .collect();
    if clockwise {
        pts.reverse();
    }
    pts
}

/// The window slots of a 10 × 10 wall or floor square: `[u0, u1, v0, v1]` offsets.
const SLOTS: [[i64; 4]; 2] = [[2, 4, 3, 7], [6, 8, 3, 7]];

/// A floor of `holes.len()` squares in a row; square i has the holes `holes[i]` (slot, with
/// a pane or left open as a court).
fn floor(holes: &[Vec<(usize, bool)>]) -> String {
    let mut m = Model::default();
    for (i, hs) in holes.iter().enumerate() {
        let x = 10 * i as i64;
        let mut circles = vec![rect(2, 0, [x, x + 10, 0, 10], false)];
        let mut panes = Vec::new();
        for &(slot, pane) in hs {
            let [u0, u1, v0, v1] = SLOTS[slot];
            let r = [x + u0, x + u1, v0, v1];
            circles.push(rect(2, 0, r, true));
            if pane {
                panes.push(r);
            }
        }
        m.face(&circles, Some(&format!("floor {i}")));
        for r in panes {
            m.face(&[rect(2, 0, r, false)], Some("pane"));
        }
    }
    m.json(2)
}

/// `windows.len() + 1` rooms of 10³ in a row along x; the wall between rooms i and i + 1
/// has the windows `windows[i]` (slots), each closed by a pane.
fn rooms(windows: &[Vec<usize>]) -> String {
    let mut m = Model::default();
    let n = windows.len() + 1;
    let mut walls: Vec<Vec<usize>> = Vec::new(); // the faces at x = 10 i
    for i in 0..=n {
        let c = 10 * i as i64;
        let slots = if i == 0 || i == n { &[][..] } else { &windows[i - 1][..] };
        let mut circles = vec![rect(0, c, [0, 10, 0, 10], false)];
        circles.extend(slots.iter().map(|&s| rect(0, c, SLOTS[s], true)));
        let mut faces = vec![m.face(&circles, Some(&format!("wall {i}")))];
        faces.extend(slots.iter().map(|&s| m.face(&[rect(0, c, SLOTS[s], false)], Some("window"))));
        walls.push(faces);
    }
    for i in 0..n {
        let (x0, x1) = (10 * i as i64, 10 * i as i64 + 10);
        let mut sides = Vec::new();
        for (axis, r) in [(1, [0, 10, x0, x1]), (2, [x0, x1, 0, 10])] {
            sides.push((m.face(&[rect(axis, 0, r, false)], None), -1));
            sides.push((m.face(&[rect(axis, 10, r, false)], None), 1));
        }
        let room = m.region(3, Some(&format!("room {i}")));
        for (f, s) in sides {
            m.entry(room, f, s);
        }
        for &f in &walls[i] {
            m.entry(room, f, -1);
        }
        for &f in &walls[i + 1] {
            m.entry(room, f, 1);
        }
    }
    m.json(3)
}

fn groups(path: &Path, topological: bool) -> (Vec<usize>, Vec<Vec<gmap::algebra::Natural>>) {
    let mut o = gmap::HomologyOptions::default();
    o.topological = topological;
    let r = gmap::homology_file(path, &o).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    (r.groups.betti, r.groups.torsion)
}

/// Every format written through a G-map reads back with the topological groups of `json`;
/// `.json` and `.dot` are written as they are. Returns the topological Betti numbers.
fn every_format_keeps_the_space(json: &str, dir: &Path) -> Vec<usize> {
    let src = dir.join("model.json");
    std::fs::write(&src, json).unwrap();
    let space = groups(&src, true);
    for ext in ["gmap", "moka", "facets"] {
        let out = dir.join(format!("model.{ext}"));
        gmap::save_file(&src, &out, &gmap::SaveOptions::default()).unwrap_or_else(|e| panic!("{ext}: {e}\n{json}"));
        assert_eq!(groups(&out, false), space, "{ext}\n{json}");
    }
    for ext in ["lar.json", "dot"] {
        gmap::save_file(&src, dir.join(format!("model.{ext}")), &gmap::SaveOptions::default()).unwrap();
    }
    let again = dir.join("again.json");
    gmap::save_file(&src, &again, &gmap::SaveOptions::default()).unwrap();
    assert_eq!(groups(&again, true), space);
    space.0
}

fn data(name: &str) -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../tests/data/arch").join(name)
}

#[test]
fn the_wall_with_a_window_and_the_floor_with_a_court_keep_their_space() {
    let dir = tempfile::tempdir().unwrap();
    for (name, betti) in [("window.json", vec![1, 0, 0, 0]), ("court.json", vec![1, 1, 0])] {
        let text = std::fs::read_to_string(data(name)).unwrap();
        assert_eq!(every_format_keeps_the_space(&text, dir.path()), betti, "{name}");
    }
    // the generator here writes the same two rooms as the test data
    assert_eq!(every_format_keeps_the_space(&rooms(&[vec![0]]), dir.path()), vec![1, 0, 0, 0]);
    assert_eq!(every_format_keeps_the_space(&floor(&[vec![(0, false)]]), dir.path()), vec![1, 1, 0]);
}

#[test]
fn the_cut_regions_are_two_disks_on_a_ring_of_edges() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("court.gmap");
    gmap::save_file(data("court.json"), &out, &gmap::SaveOptions::default()).unwrap();
    let gmap::Input::Map(m) = gmap::open(&out).unwrap() else { panic!("a map") };
    // 8 vertices, 8 edges of the two squares and 2 of the ring, the annulus as 2 faces
    assert_eq!(m.map().cell_counts(), vec![8, 10, 2]);
    let out = dir.path().join("window.gmap");
    gmap::save_file(data("window.json"), &out, &gmap::SaveOptions::default()).unwrap();
    let gmap::Input::Map(m) = gmap::open(&out).unwrap() else { panic!("a map") };
    // 16 vertices; 24 edges + 2 of the ring; 12 faces + 1 for the cut wall; 2 rooms
    assert_eq!(m.map().cell_counts(), vec![16, 26, 13, 2]);
}

#[test]
fn homology_of_json_says_which_space() {
    let o = gmap::HomologyOptions::default();
    let r = gmap::homology_file(data("court.json"), &o).unwrap();
    assert_eq!(r.groups.betti, vec![2, 1, 0]);
    let text = r.to_text();
    assert!(text.contains("space: the region complex"), "{text}");
    assert!(
        text.contains(
            "hint: region 0 (floor with court) (Betti numbers (1, 1, 0)) is not a ball; gmap homology --topological"
        ),
        "{text}"
    );
    let v = r.to_json();
    assert_eq!(v["space"], "region complex");
    assert_eq!(v["not_balls"][0]["betti"], serde_json::json!([1, 1, 0]));
    let mut o = gmap::HomologyOptions::default();
    o.topological = true;
    let r = gmap::homology_file(data("court.json"), &o).unwrap();
    assert_eq!(r.groups.betti, vec![1, 1, 0]);
    assert_eq!(r.to_json()["space"], "topological");
    assert!(r.to_json().get("hint").is_none());
    // a complex of cells: the statement and no hint
    let r = gmap::homology_file(data("tetrahedron.json"), &gmap::HomologyOptions::default()).unwrap();
    assert!(!r.to_text().contains("hint"), "{}", r.to_text());
}

fn refusal(json: &str) -> String {
    let dir = tempfile::tempdir().unwrap();
    let src = dir.path().join("bad.json");
    std::fs::write(&src, json).unwrap();
    let out = dir.path().join("bad.gmap");
    let e = gmap::save_file(&src, &out, &gmap::SaveOptions::default()).unwrap_err().to_string();
    assert!(!out.exists());
    assert!(e.starts_with(&src.display().to_string()), "the input is named first: {e}");
    assert!(e.contains(&format!("nothing written to {}", out.display())), "{e}");
    e
}

#[test]
fn what_cannot_be_cut_is_refused_with_the_region_and_why() {
    // a torus with a hole given as a region: genus 1
    let text = std::fs::read_to_string(data("court.json")).unwrap();
    let torus = text.replacen(r#""dim": 2, "labels""#, r#""dim": 2, "betti": [1, 2, 0], "labels""#, 1);
    let e = refusal(&torus);
    assert!(e.contains("region 0 (floor with court): a 2-region with Betti numbers (1, 2, 0)"), "{e}");
    // a figure-eight boundary: two squares sharing a vertex as the boundary of one face
    let mut m = Model::default();
    m.face(&[rect(2, 0, [0, 10, 0, 10], false), rect(2, 0, [10, 20, 10, 20], false)], Some("eight"));
    let e = refusal(&m.json(2));
    assert!(e.contains("region 0 (eight): its boundary is not a union of circles: region"), "{e}");
    assert!(e.contains("lies on 4 of its boundary edges"), "{e}");
    // a weight 2: another space
    // weights 2 on the boundary of a square (δ² is still 0): another space than a disk
    let mut m = Model::default();
    let f = m.face(&[rect(2, 0, [0, 10, 0, 10], false)], Some("twice"));
    let from = format!(r#"{{"from": {f}, "#);
    for entry in m.incidence.iter_mut().filter(|e| e.starts_with(&from)) {
        *entry = entry.replace(r#""weight": 1}"#, r#""weight": 2}"#).replace(r#""weight": -1}"#, r#""weight": -2}"#);
    }
    let e = refusal(&m.json(2));
    assert!(e.contains("region 0 (twice): its entry to region"), "{e}");
    assert!(e.contains("has weight 2: a cell of a regular complex meets each face of its boundary once"), "{e}");
    // a room with a cavity: the boundary of an inner box is part of its boundary too
    let mut m = Model::default();
    let mut faces = Vec::new();
    for (lo, hi, sign) in [(0, 30, 1), (10, 20, -1)] {
        for axis in 0..3 {
            faces.push((m.face(&[rect(axis, lo, [lo, hi, lo, hi], false)], None), -sign));
            faces.push((m.face(&[rect(axis, hi, [lo, hi, lo, hi], false)], None), sign));
        }
    }
    let room = m.region(3, Some("hollow"));
    for (f, s) in faces {
        m.entry(room, f, s);
    }
    let e = refusal(&m.json(3));
    assert!(
        e.contains(&format!("region {room} (hollow): a 3-region with Betti numbers (1, 0, 1, 0) is not a ball")),
        "{e}"
    );
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 24, ..ProptestConfig::default() })]

    /// Random floors with courts and panes, random rows of rooms with windows: every format
    /// keeps the topological groups.
    #[test]
    fn random_complexes_with_holes_keep_their_space(
        holes in prop::collection::vec(prop::sample::subsequence(vec![(0usize, false), (1, true)], 0..=2), 1..4),
        panes in prop::collection::vec(any::<bool>(), 4),
        windows in prop::collection::vec(prop::sample::subsequence(vec![0usize, 1], 0..=2), 0..3),
    ) {
        let dir = tempfile::tempdir().unwrap();
        // the first slot is a court or a pane at random
        let holes: Vec<Vec<(usize, bool)>> = holes
            .iter()
            .zip(panes.iter().cycle())
            .map(|(hs, &p)| hs.iter().map(|&(s, pane)| (s, if s == 0 { p } else { pane })).collect())
            .collect();
        let courts: usize = holes.iter().flatten().filter(|h| !h.1).count();
        let betti = every_format_keeps_the_space(&floor(&holes), dir.path());
        prop_assert_eq!(betti, vec![1, courts, 0]);
        let betti = every_format_keeps_the_space(&rooms(&windows), dir.path());
        prop_assert_eq!(betti, vec![1, 0, 0, 0]);
    }
}

#[test]
fn what_each_format_drops_of_an_architects_file() {
    let x = gmap::open(data("rooms_door_window.json")).unwrap();
    let o = gmap::SaveOptions::default();
    let drops = |out: &str| gmap::save::dropped(&x, std::path::Path::new(out), &o);
    // the incidence graph's .json and the .gmap of the cut map keep labels and points
    assert!(drops("x.json").is_empty());
    assert!(drops("x.gmap").is_empty());
    assert_eq!(drops("x.dot"), vec!["the points"]);
    assert_eq!(drops("x.moka"), vec!["the labels", "the points"]);
    assert_eq!(drops("x.lar.json"), vec!["the labels", "the points"]);
}
