//! TM on 3-cell models: two rooms sharing a wall with a door, built as a model (with the
//! paper's orientation conventions, TM §III) and as a G-map carved by Euler operators.
//! Views, sections and their near/far, from/to annotations ((7:1)–(7:4)), the structure
//! (6:1), closing by an exterior cell, and the edit check ((7:5), (7:6)) per defect kind.

use gmap_homology::tm::{Ends, Sides, SignedSet, TmDefect, TmError, TmModel, TmSet};

type P = [i64; 3];

/// A model with named cells (id = index), and the lists it was built from, to edit.
struct Fixture {
    names: Vec<String>,
    cells: Vec<(u64, usize)>,
    inc: Vec<(usize, usize, u64, u64)>,
    model: TmModel,
}

impl Fixture {
    fn ix(&self, name: &str) -> usize {
        self.names.iter().position(|n| n == name).unwrap_or_else(|| panic!("no cell {name}"))
    }
    fn id(&self, name: &str) -> u64 {
        self.ix(name) as u64
    }
    fn name(&self, id: u64) -> &str {
        &self.names[id as usize]
    }
    fn set(&self, items: &[(&str, u64, u64)]) -> SignedSet {
        items.iter().map(|&(n, p, m)| (self.ix(n), p, m)).collect()
    }
    /// The model rebuilt after `edit` changed the incidence list.
    fn edited(&self, edit: impl FnOnce(&mut Vec<(usize, usize, u64, u64)>)) -> TmModel {
        let mut inc = self.inc.clone();
        edit(&mut inc);
        TmModel::try_new(3, self.cells.clone(), &inc).unwrap()
    }
    /// Defects as (condition, cell, at, +, -), by name.
    fn named(&self, defects: &[TmDefect]) -> Vec<(&'static str, String, String, u64, u64)> {
        let mut v: Vec<_> = defects
            .iter()
            .map(|d| {
                let (at, p, m) = match *d {
                    TmDefect::BoundaryNotCircuit { at, plus, minus, .. }
                    | TmDefect::CoboundaryNotCocircuit { at, plus, minus, .. } => (at, plus, minus),
                    ref other => panic!("a defect this test does not know: {other:?}"),
                };
                (d.condition(), self.name(d.cell()).to_string(), self.name(at).to_string(), p, m)
            })
            .collect();
        v.sort();
        v
    }
}

/// Defect rows (condition, cell, at, +, -), sorted as [`Fixture::named`] sorts them.
fn rows(v: &[(&'static str, &str, &str, u64, u64)]) -> Vec<(&'static str, String, String, u64, u64)> {
    let mut out: Vec<_> = v.iter().map(|&(c, a, b, p, m)| (c, a.to_string(), b.to_string(), p, m)).collect();
    out.sort();
    out
}

/// The ten outer faces: floors, ceilings, the walls at y = 0, y = 3, x = 0 and x = 6.
const OUTER: [&str; 10] = ["F1", "C1", "S1", "N1", "X0", "F2", "C2", "S2", "N2", "X6"];

fn vname(p: P) -> String {
    match p {
        [3, 1, 0] => "d1".into(),
        [3, 2, 0] => "d2".into(),
        [3, 2, 2] => "d3".into(),
        [3, 1, 2] => "d4".into(),
        [x, y, z] => format!("x{x}y{y}z{z}"),
    }
}

/// Newell's normal of a planar polygon (right-hand rule of the cycle).
fn normal(cycle: &[P]) -> P {
    let mut n = [0i64; 3];
    for (i, a) in cycle.iter().enumerate() {
        let b = cycle[(i + 1) % cycle.len()];
        n[0] += (a[1] - b[1]) * (a[2] + b[2]);
        n[1] += (a[2] - b[2]) * (a[0] + b[0]);
        n[2] += (a[0] - b[0]) * (a[1] + b[1]);
    }
    n
}

fn dot(a: P, b: P) -> i64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// Two rooms R1 = [0,3]×[0,3]×[0,3] and R2 = [3,6]×[0,3]×[0,3] sharing the wall x = 3, in
/// which a door D = y ∈ [1,2], z ∈ [0,2] stands on the floor (door corners d1 = (3,1,0),
/// d2 = (3,2,0), d3 = (3,2,2), d4 = (3,1,2)); the wall W around the door is a U-shaped
/// octagon. Orientations follow TM §III: an edge goes from its lower to its higher end
/// along its axis (`B e = {-from, +to}`); a face is oriented so that its near side (the
/// side from which its boundary runs anticlockwise) faces `dir`: the outer faces face
/// outwards, W and D face room 1; a room takes a face positively when it lies on the face's
/// far side. Cells are numbered vertices, edges, faces, rooms, in order of appearance.
fn two_rooms() -> Fixture {
    let (a, b) = (3i64, 6i64);
    let faces: Vec<(&str, P, Vec<P>)> = vec![
        ("F1", [0, 0, -1], vec![[0, 0, 0], [3, 0, 0], [3, 1, 0], [3, 2, 0], [3, 3, 0], [0, 3, 0]]),
        ("C1", [0, 0, 1], vec![[0, 0, a], [a, 0, a], [a, a, a], [0, a, a]]),
        ("S1", [0, -1, 0], vec![[0, 0, 0], [a, 0, 0], [a, 0, a], [0, 0, a]]),
        ("N1", [0, 1, 0], vec![[0, a, 0], [a, a, 0], [a, a, a], [0, a, a]]),
        ("X0", [-1, 0, 0], vec![[0, 0, 0], [0, a, 0], [0, a, a], [0, 0, a]]),
        ("F2", [0, 0, -1], vec![[3, 0, 0], [6, 0, 0], [6, 3, 0], [3, 3, 0], [3, 2, 0], [3, 1, 0]]),
        ("C2", [0, 0, 1], vec![[a, 0, a], [b, 0, a], [b, a, a], [a, a, a]]),
        ("S2", [0, -1, 0], vec![[a, 0, 0], [b, 0, 0], [b, 0, a], [a, 0, a]]),
        ("N2", [0, 1, 0], vec![[a, a, 0], [b, a, 0], [b, a, a], [a, a, a]]),
        ("X6", [1, 0, 0], vec![[b, 0, 0], [b, a, 0], [b, a, a], [b, 0, a]]),
        ("W", [-1, 0, 0], vec![[3, 0, 0], [3, 1, 0], [3, 1, 2], [3, 2, 2], [3, 2, 0], [3, 3, 0], [3, 3, 3], [3, 0, 3]]),
        ("D", [-1, 0, 0], vec![[3, 1, 0], [3, 2, 0], [3, 2, 2], [3, 1, 2]]),
    ];
    // rooms: name, doubled centre, faces
    let rooms: Vec<(&str, P, Vec<&str>)> = vec![
        ("R1", [3, 3, 3], vec!["F1", "C1", "S1", "N1", "X0", "W", "D"]),
        ("R2", [9, 3, 3], vec!["F2", "C2", "S2", "N2", "X6", "W", "D"]),
    ];
    let mut verts: Vec<P> = Vec::new();
    let mut edges: Vec<(usize, usize)> = Vec::new();
    let mut face_edges: Vec<Vec<(usize, bool)>> = Vec::new();
    let vindex = |p: P, verts: &mut Vec<P>| match verts.iter().position(|&q| q == p) {
        Some(i) => i,
        None => {
            verts.push(p);
            verts.len() - 1
        }
    };
    let mut oriented = Vec::new();
    for (_, dir, cycle) in &faces {
        let mut cycle = cycle.clone();
        if dot(normal(&cycle), *dir) < 0 {
            cycle.reverse();
        }
        let mut fe = Vec::new();
        for i in 0..cycle.len() {
            let (u, v) = (cycle[i], cycle[(i + 1) % cycle.len()]);
            let (iu, iv) = (vindex(u, &mut verts), vindex(v, &mut verts));
            let forward = u < v; // along the axis, lower end first
            let key = if forward { (iu, iv) } else { (iv, iu) };
            let e = match edges.iter().position(|&x| x == key) {
                Some(e) => e,
                None => {
                    edges.push(key);
                    edges.len() - 1
                }
            };
            fe.push((e, forward));
        }
        face_edges.push(fe);
        oriented.push(cycle);
    }
    let (nv, ne, nf) = (verts.len(), edges.len(), faces.len());
    let mut names: Vec<String> = verts.iter().map(|&p| vname(p)).collect();
    names.extend(edges.iter().map(|&(u, v)| format!("{}-{}", vname(verts[u]), vname(verts[v]))));
    names.extend(faces.iter().map(|f| f.0.to_string()));
    names.extend(rooms.iter().map(|r| r.0.to_string()));
    let mut cells: Vec<(u64, usize)> = Vec::new();
    for (k, count) in [nv, ne, nf, rooms.len()].into_iter().enumerate() {
        for _ in 0..count {
            cells.push((cells.len() as u64, k));
        }
    }
    let mut inc = Vec::new();
    for (e, &(u, v)) in edges.iter().enumerate() {
        inc.push((nv + e, u, 0, 1));
        inc.push((nv + e, v, 1, 0));
    }
    for (f, fe) in face_edges.iter().enumerate() {
        for &(e, forward) in fe {
            inc.push((nv + ne + f, nv + e, u64::from(forward), u64::from(!forward)));
        }
    }
    for (r, (_, centre, list)) in rooms.iter().enumerate() {
        for name in list {
            let f = faces.iter().position(|x| x.0 == *name).unwrap();
            let cyc = &oriented[f];
            // doubled centroid of the face minus the doubled room centre
            let mut off = [0i64; 3];
            for (j, o) in off.iter_mut().enumerate() {
                *o = 2 * cyc.iter().map(|p| p[j]).sum::<i64>() / cyc.len() as i64 - centre[j];
            }
            let far = dot(normal(cyc), off) > 0; // the normal points away: the room is behind
            inc.push((nv + ne + nf + r, nv + ne + f, u64::from(far), u64::from(!far)));
        }
    }
    let model = TmModel::try_new(3, cells.clone(), &inc).unwrap();
    Fixture { names, cells, inc, model }
}

/// [`two_rooms`] closed by the exterior cell `E` (the next id), built by
/// [`TmModel::try_close_with_exterior`].
fn two_rooms_closed() -> Fixture {
    let mut f = two_rooms();
    let id = f.cells.len() as u64;
    let (closed, e) = f.model.try_close_with_exterior(id).unwrap();
    f.names.push("E".into());
    f.cells.push((id, 3));
    f.inc.extend(closed.bounding(e).iter().map(|(c, p, m)| (e, c, p, m)));
    f.model = TmModel::try_new(3, f.cells.clone(), &f.inc).unwrap();
    assert_eq!(f.model, closed);
    f
}

#[test]
fn two_rooms_counts_and_open_defects() {
    let f = two_rooms();
    let t = &f.model;
    let counts: Vec<usize> = (0..=3).map(|k| t.regions_of_dim(k).len()).collect();
    assert_eq!(counts, vec![16, 25, 12, 2]);
    // χ = 16 - 25 + 12 - 2 = 1: the two rooms together are a ball
    // every boundary is a circuit (7:5); the ten outer faces have one room each (7:6)
    let defects = t.edit_defects();
    assert_eq!(defects.len(), 10);
    let expected: Vec<_> = OUTER.iter().map(|&n| ("(7:6)", n, n, 1, 0)).collect();
    assert_eq!(f.named(&defects), rows(&expected));
    assert!(defects.iter().all(|d| d.dim() == 2));
    assert_eq!(
        t.edit_check().unwrap_err().to_string(),
        format!(
            "TM (7:6): the coboundary of 2-cell {id} is not a cocircuit: cell {id} occurs +1/-0 times in its coboundary",
            id = f.id("F1")
        )
    );
}

#[test]
fn door_view_near_and_far_7_3() {
    let f = two_rooms();
    let t = &f.model;
    let d = f.ix("D");
    // Fig. 2: the view of a 2-cell, near side c1^3 (room 1), far side c2^3 (room 2)
    assert_eq!(t.try_sides(d), Ok(Sides { near: Some(f.ix("R1")), far: Some(f.ix("R2")) }));
    let v = t.try_annotated_view(d).unwrap();
    assert_eq!(v.sides, Sides { near: Some(f.ix("R1")), far: Some(f.ix("R2")) });
    // (7:1): the door, its four edges (anticlockwise seen from room 1: the threshold and
    // the jamb at y = 2 run against their direction), each corner once with each sign
    let expected = f.set(&[
        ("D", 1, 0),
        ("d1-d2", 0, 1),
        ("d1-d4", 1, 0),
        ("d4-d3", 1, 0),
        ("d2-d3", 0, 1),
        ("d1", 1, 1),
        ("d2", 1, 1),
        ("d3", 1, 1),
        ("d4", 1, 1),
    ]);
    assert_eq!(v.cells, expected);
    // the wall around the door: same sides, an octagon
    let w = t.try_annotated_view(f.ix("W")).unwrap();
    assert_eq!(w.sides, Sides { near: Some(f.ix("R1")), far: Some(f.ix("R2")) });
    assert_eq!(w.cells.len(), 17);
    // an outer wall of the open model: the room on the far side, nothing near
    assert_eq!(t.try_sides(f.ix("X0")), Ok(Sides { near: None, far: Some(f.ix("R1")) }));
    // (7:3) is G c^2, a 3-cocircuit: the pair of opposite rooms
    assert!(t.is_cocircuit(t.cobounding(d), 3));
    assert_eq!(*t.cobounding(d), f.set(&[("R1", 0, 1), ("R2", 1, 0)]));
}

#[test]
fn threshold_section_from_and_to_7_4() {
    let f = two_rooms();
    let t = &f.model;
    let thr = f.ix("d1-d2");
    // Fig. 1: the section through a 1-cell, looking from c1^0 (d1) to c2^0 (d2)
    let s = t.try_annotated_section(thr).unwrap();
    assert_eq!(s.ends, Ends { from: Some(f.ix("d1")), to: Some(f.ix("d2")) });
    assert_eq!(*t.bounding(thr), f.set(&[("d1", 0, 1), ("d2", 1, 0)]));
    // (7:2): the threshold, the door and both floors, both rooms once with each sign
    let expected = f.set(&[("d1-d2", 1, 0), ("D", 0, 1), ("F1", 0, 1), ("F2", 1, 0), ("R1", 1, 1), ("R2", 1, 1)]);
    assert_eq!(s.cells, expected);
    // a jamb lies inside the wall plane: the door and the wall only, then both rooms
    let jamb = t.try_annotated_section(f.ix("d1-d4")).unwrap();
    assert_eq!(jamb.ends, Ends { from: Some(f.ix("d1")), to: Some(f.ix("d4")) });
    assert_eq!(jamb.cells, f.set(&[("d1-d4", 1, 0), ("D", 1, 0), ("W", 0, 1), ("R1", 1, 1), ("R2", 1, 1)]));
}

#[test]
fn closing_with_an_exterior_cell_passes_the_edit_check() {
    let f = two_rooms();
    let (closed, e) = f.model.try_close_with_exterior(99).unwrap();
    assert_eq!(closed.id(e), 99);
    assert_eq!(closed.edit_check(), Ok(()));
    let counts: Vec<usize> = (0..=3).map(|k| closed.regions_of_dim(k).len()).collect();
    assert_eq!(counts, vec![16, 25, 12, 3]); // χ = 0, the 3-sphere
                                             // the outside is on the near side of every outer face
    assert_eq!(closed.try_sides(f.ix("X0")), Ok(Sides { near: Some(e), far: Some(f.ix("R1")) }));
    assert_eq!(closed.try_sides(f.ix("D")), Ok(Sides { near: Some(f.ix("R1")), far: Some(f.ix("R2")) }));
    assert_eq!(closed.bounding(e).len(), 10);
    assert_eq!(closed.bounding(e).totals(), (0, 10));
    // the section through the threshold now reaches the outside under the floors
    let s = closed.section(&SignedSet::cell(f.ix("d1-d2")));
    assert_eq!(s.get(e), (1, 1));
    assert_eq!(s.len(), 7);
    // closing again: nothing left
    assert_eq!(closed.try_close_with_exterior(100), Err(TmError::AlreadyClosed { dim: 2 }));
    assert_eq!(f.model.try_close_with_exterior(f.id("D")), Err(TmError::IdInUse { id: f.id("D") }));
}

#[test]
fn structure_6_1_stores_bounding_circuits_and_cobounding_cocircuits() {
    let f = two_rooms();
    let (t, e) = f.model.try_close_with_exterior(99).unwrap();
    // Fig. 4: four entry keys, C^0..C^3 holding Y^1, Y^2, Z^1, Z^2
    let layout = t.file_layout();
    let shown: Vec<String> = layout
        .iter()
        .map(|(k, sets)| format!("{k}: {}", sets.iter().map(|s| s.to_string()).collect::<Vec<_>>().join(", ")))
        .collect();
    assert_eq!(shown, vec!["C^0: Y^1", "C^1: Y^2", "C^2: Z^1", "C^3: Z^2"]);
    // dual keys hold dual sets (C^0 with Y^1 against C^3 with Z^2)
    for (key, sets) in &layout {
        let TmSet::C(k) = *key else { panic!("key {key}") };
        let (dkey, dsets) = &layout[3 - k];
        assert_eq!(key.dual(3), *dkey);
        assert_eq!(sets.iter().map(|s| s.dual(3)).collect::<Vec<_>>(), *dsets);
    }
    // Z_B^k: one stored circuit per (k+1)-cell, each a k-circuit; Y_G^k dually
    let z: Vec<usize> = (0..3).map(|k| t.bounding_circuits(k).count()).collect();
    let y: Vec<usize> = (1..=3).map(|k| t.cobounding_cocircuits(k).count()).collect();
    assert_eq!(z, vec![25, 12, 3]);
    assert_eq!(y, vec![16, 25, 12]);
    for k in 0..3 {
        assert!(t.bounding_circuits(k).all(|(_, s)| t.is_circuit(s, k)));
        assert!(t.cobounding_cocircuits(k + 1).all(|(_, s)| t.is_cocircuit(s, k + 1)));
    }
    // the door's record: its bounding 1-circuit under C^2
    let d = f.ix("D");
    let rec = t.record(d);
    assert_eq!(rec.len(), 1);
    assert_eq!(rec[0].0, TmSet::Z(1));
    assert_eq!(*rec[0].1, f.set(&[("d1-d2", 0, 1), ("d1-d4", 1, 0), ("d4-d3", 1, 0), ("d2-d3", 0, 1)]));
    // a room's record: its 2-circuit of seven faces; the exterior's: ten
    assert_eq!(t.record(f.ix("R1"))[0].1.len(), 7);
    assert_eq!(t.record(e)[0].1.len(), 10);
    // the dual model stores the same sets under the dual names
    let du = t.dual();
    for k in 0..3 {
        let a: Vec<_> = t.bounding_circuits(k).map(|(c, s)| (c, s.clone())).collect();
        let b: Vec<_> = du.cobounding_cocircuits(3 - k).map(|(c, s)| (c, s.clone())).collect();
        assert_eq!(a, b);
    }
    assert_eq!(du.edit_check(), Ok(()));
}

#[test]
fn defect_missing_end_7_5_on_edges_faces_and_7_6_on_vertices() {
    let f = two_rooms_closed();
    let (thr, d2) = (f.ix("d1-d2"), f.ix("d2"));
    let t = f.edited(|inc| inc.retain(|&(u, l, _, _)| !(u == thr && l == d2)));
    assert_eq!(t.try_ends(thr), Ok(Ends { from: Some(f.ix("d1")), to: None }));
    let defects = t.edit_defects();
    let expected = rows(&[
        // (7:5), k = 1: the threshold has no "to" vertex
        ("(7:5)", "d1-d2", "d1-d2", 0, 1),
        // (7:5), k = 2: the faces on the threshold do not close up at d2
        ("(7:5)", "D", "d2", 1, 0),
        ("(7:5)", "F1", "d2", 1, 0),
        ("(7:5)", "F2", "d2", 0, 1),
        // (7:6), k = 0: the same pairs seen from d2, first at F1
        ("(7:6)", "d2", "F1", 1, 0),
    ]);
    assert_eq!(f.named(&defects), expected);
    // the first defect in check order: the threshold, (7:5)
    let first = t.edit_check().unwrap_err();
    assert_eq!(first, defects[0]);
    assert_eq!((first.condition(), first.cell(), first.dim()), ("(7:5)", f.id("d1-d2"), 1));
}

#[test]
fn defect_missing_ceiling_7_5_on_a_room_and_7_6_on_edges_and_faces() {
    let f = two_rooms_closed();
    let (r1, c1) = (f.ix("R1"), f.ix("C1"));
    let t = f.edited(|inc| inc.retain(|&(u, l, _, _)| !(u == r1 && l == c1)));
    // the ceiling is anticlockwise seen from above: its edges at y = 0 and x = 3 run
    // forwards, those at y = 3 and x = 0 backwards; without it, R1 meets each ceiling
    // edge once, through the wall below it, with the opposite sign
    let expected = rows(&[
        // (7:5), k = 3: room 1 is not closed (first at the first ceiling edge)
        ("(7:5)", "R1", "x0y0z3-x3y0z3", 0, 1),
        // (7:6), k = 1: each ceiling edge sees room 1 once
        ("(7:6)", "x0y0z3-x3y0z3", "R1", 0, 1),
        ("(7:6)", "x3y0z3-x3y3z3", "R1", 0, 1),
        ("(7:6)", "x0y3z3-x3y3z3", "R1", 1, 0),
        ("(7:6)", "x0y0z3-x0y3z3", "R1", 1, 0),
        // (7:6), k = 2: the ceiling has the outside on its near side and nothing beyond
        ("(7:6)", "C1", "C1", 0, 1),
    ]);
    assert_eq!(f.named(&t.edit_defects()), expected);
    assert_eq!(t.try_sides(c1), Ok(Sides { near: Some(f.ix("E")), far: None }));
}

#[test]
fn defect_door_twisted_7_6_on_the_door_and_closing_refused() {
    let f = two_rooms();
    let (r2, d) = (f.ix("R2"), f.ix("D"));
    // room 2 takes the door with the wrong sign: both rooms on the near side
    let t = f.edited(|inc| {
        for x in inc.iter_mut().filter(|x| x.0 == r2 && x.1 == d) {
            std::mem::swap(&mut x.2, &mut x.3);
        }
    });
    assert_eq!(t.try_sides(d), Err(TmError::NotAPair { id: f.id("D"), dim: 2, plus: 0, minus: 2 }));
    // closing refuses: the door is not an opening
    assert_eq!(t.try_close_with_exterior(99), Err(TmError::NotFree { id: f.id("D"), dim: 2, plus: 0, minus: 2 }));
    let mut expected = vec![
        // (7:5), k = 3: room 2 meets each door edge twice with one sign, first the threshold
        ("(7:5)", "R2", "d1-d2", 2, 0),
        // (7:6), k = 2: both rooms on the near side of the door
        ("(7:6)", "D", "D", 0, 2),
        // (7:6), k = 1: each door edge sees room 2 twice with one sign
        ("(7:6)", "d1-d2", "R2", 2, 0),
        ("(7:6)", "d1-d4", "R2", 0, 2),
        ("(7:6)", "d2-d3", "R2", 2, 0),
        ("(7:6)", "d4-d3", "R2", 0, 2),
    ];
    // and the ten free faces of the open model, as before
    expected.extend(OUTER.iter().map(|&n| ("(7:6)", n, n, 1, 0)));
    assert_eq!(f.named(&t.edit_defects()), rows(&expected));
}

#[test]
fn model_errors_are_typed() {
    let f = two_rooms();
    let t = &f.model;
    assert_eq!(t.try_sides(f.ix("d1-d2")), Err(TmError::WrongDimension { id: f.id("d1-d2"), dim: 1, expected: 2 }));
    assert_eq!(t.try_ends(f.ix("D")), Err(TmError::WrongDimension { id: f.id("D"), dim: 2, expected: 1 }));
    assert_eq!(t.try_ends(1000), Err(TmError::NoSuchCell { index: 1000, len: 55 }));
    let cells = vec![(7, 0), (8, 1), (9, 2)];
    assert_eq!(
        TmModel::try_new(2, cells.clone(), &[(2, 0, 1, 0)]),
        Err(TmError::NotAdjacent { upper: 9, upper_dim: 2, lower: 7, lower_dim: 0 })
    );
    assert_eq!(TmModel::try_new(2, cells.clone(), &[(1, 3, 1, 0)]), Err(TmError::NoSuchCell { index: 3, len: 3 }));
    assert_eq!(TmModel::try_new(1, cells.clone(), &[]), Err(TmError::DimensionAbove { id: 9, dim: 2, max: 1 }));
    assert_eq!(
        TmModel::try_new(2, vec![(7, 0), (7, 1)], &[]),
        Err(TmError::DuplicateId { id: 7, first: 0, second: 1 })
    );
    let point = TmModel::try_new(0, vec![(1, 0)], &[]).unwrap();
    assert_eq!(point.try_close_with_exterior(2), Err(TmError::Pointless { what: "exterior cell" }));
    assert_eq!(point.try_sides(0), Err(TmError::Pointless { what: "sides of a cell" }));
}

/// The same two rooms as a 3-map: two unit cubes side by side (`build::grid`), the door
/// carved into their common face by Euler operators: two vertices on its bottom edge
/// (`mve` twice), an edge across the face between them (`mef`, the door becomes a digon),
/// and two vertices on that edge (the door's upper corners).
fn two_rooms_gmap() -> gmap_core::DenseMap {
    use gmap_core::GMap;
    use gmap_ops::euler::ops::{try_insert_edge, try_insert_vertex};
    let grid = gmap_ops::build::grid(&[2, 1, 1], &[false, false, false]).unwrap();
    let (mut g, _) = GMap::from_dense(&grid);
    let d = g.darts().find(|&d| g.alpha(d, 3) != d).expect("a dart of the common face");
    try_insert_vertex(&mut g, d).unwrap();
    let x1 = g.alpha(d, 0);
    let y = g.alpha(x1, 1);
    try_insert_vertex(&mut g, y).unwrap();
    let x2 = g.alpha(y, 0);
    try_insert_edge(&mut g, x1, x2).unwrap();
    let z = g.alpha(x1, 1);
    try_insert_vertex(&mut g, z).unwrap();
    let z2 = g.alpha(g.alpha(z, 0), 1);
    try_insert_vertex(&mut g, z2).unwrap();
    g.to_dense().0
}

#[test]
fn two_rooms_from_a_gmap() {
    let m = two_rooms_gmap();
    assert_eq!(m.cell_counts(), vec![16, 25, 12, 2]);
    let t = TmModel::from_map(&m).unwrap();
    // the same defects as the model: the ten outer faces, one room each
    let defects = t.edit_defects();
    assert_eq!(defects.len(), 10);
    for d in &defects {
        let TmDefect::CoboundaryNotCocircuit { dim: 2, plus, minus, .. } = *d else { panic!("{d}") };
        assert_eq!(plus + minus, 1);
    }
    let (closed, e) = t.try_close_with_exterior(1000).unwrap();
    assert_eq!(closed.edit_check(), Ok(()));
    assert_eq!(closed.bounding(e).len(), 10);
    // the two inner faces: the wall (8 edges) and the door (4), each between the two rooms
    let rooms = t.regions_of_dim(3).to_vec();
    let mut inner: Vec<(usize, Sides)> = t
        .regions_of_dim(2)
        .iter()
        .filter_map(|&f| t.try_sides(f).ok().filter(|s| s.near.is_some() && s.far.is_some()).map(|s| (f, s)))
        .collect();
    inner.sort_by_key(|&(f, _)| t.bounding(f).len());
    assert_eq!(inner.iter().map(|&(f, _)| t.bounding(f).len()).collect::<Vec<_>>(), vec![4, 8]);
    for (_, s) in &inner {
        let mut pair = vec![s.near.unwrap(), s.far.unwrap()];
        pair.sort();
        assert_eq!(pair, rooms);
    }
    // the door's view: the door, 4 edges, 4 corners once with each sign
    let door = inner[0].0;
    let v = t.try_annotated_view(door).unwrap();
    assert_eq!(v.cells.len(), 9);
    assert_eq!(v.cells.iter().filter(|&(c, p, m)| t.cell_dim(c) == 0 && (p, m) == (1, 1)).count(), 4);
    // its edges: the threshold on three faces (door and both floors), the jambs and the
    // head on two (door and wall); every section has both rooms once with each sign
    let mut cobounded: Vec<usize> = t.bounding(door).iter().map(|(e, _, _)| t.cobounding(e).len()).collect();
    cobounded.sort();
    assert_eq!(cobounded, vec![2, 2, 2, 3]);
    for (edge, _, _) in t.bounding(door).iter() {
        let s = t.try_annotated_section(edge).unwrap();
        assert!(s.ends.from.is_some() && s.ends.to.is_some() && s.ends.from != s.ends.to);
        for &r in &rooms {
            assert_eq!(s.cells.get(r), (1, 1));
        }
    }
}
#[test]
fn gmap_rooms_are_oriented_coherently_whatever_the_dart_numbering() {
    // reversed dart numbering: each cell's smallest dart, which fixes its own orientation,
    // changes; the model still orients both rooms by the map's orientation classes
    let m = two_rooms_gmap();
    let n = m.dart_count() as u32;
    assert_ne!(n % 7, 0);
    for perm in [(0..n).rev().collect::<Vec<u32>>(), (0..n).map(|k| (k * 7 + 3) % n).collect()] {
        let p = m.permuted(&perm);
        assert_eq!(p.cell_counts(), vec![16, 25, 12, 2]);
        let t = TmModel::from_map(&p).unwrap();
        assert_eq!(t.edit_defects().len(), 10);
        let (closed, _) = t.try_close_with_exterior(1000).unwrap();
        assert_eq!(closed.edit_check(), Ok(()));
        let raw = TmModel::from_arch(&gmap_homology::arch::ArchComplex::from_map(&p).unwrap());
        // with each room's own orientation (smallest dart positive) the two rooms land on
        // the same side of the wall and of the door: two more defects, (7:6) on both
        let extra: Vec<TmDefect> = raw
            .edit_defects()
            .into_iter()
            .filter(|d| raw.cobounding(raw.index_of(d.cell()).unwrap()).len() == 2)
            .collect();
        assert_eq!(extra.len(), 2);
        for d in extra {
            let TmDefect::CoboundaryNotCocircuit { dim: 2, plus, minus, .. } = d else { panic!("{d}") };
            assert!((plus, minus) == (2, 0) || (plus, minus) == (0, 2));
        }
        assert_eq!(raw.edit_defects().len(), 12);
    }
}
