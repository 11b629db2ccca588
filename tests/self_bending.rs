//! Self-bending (BO Def. 6, part 2): each kind of cell folded onto itself is found by
//! `check_no_self_bending`, makes `gmap info` report `complete_boundaries: false`, and is
//! refused by the cellular method with the folded cell named, while `--method simplicial`
//! still gives the groups.
//!
//! The kinds: an edge of a polygon sewn to itself reversed (a 1-cell, 2D); a free square face
//! of a cube sewn to itself by a half-turn (a 2-cell whose orientation is kept: C1 and C2
//! hold, only Def. 6 refuses it); the same face sewn by the mirror through a diagonal (a
//! 2-cell reversed: C1 refuses it too); and by the mirror through two edge midpoints (two
//! edges reversed, the lowest cell named).

mod common;

use std::collections::HashMap;

use common::{gmap, p, stderr, stdout};
use gmap_core::{AlphaSet, BoundaryDefect, CellDefect, Dart, DenseMap};
use gmap_homology::{cellular_complex, homology_z, simplicial_complex, PreconditionError};
use gmap_ops::build;

/// The automorphism of the `set`-orbit of `d` that sends `d` to `e` (`alpha_k` commuting
/// with it for `k` in `set`), as pairs `(x, image of x)`.
fn orbit_map(m: &DenseMap, d: Dart, e: Dart, set: AlphaSet) -> Vec<(Dart, Dart)> {
    let mut phi: HashMap<Dart, Dart> = HashMap::from([(d, e)]);
    let mut stack = vec![d];
    while let Some(x) = stack.pop() {
        for k in set.iter() {
            let (y, fy) = (m.alpha(x, k), m.alpha(phi[&x], k));
            match phi.get(&y) {
                Some(&got) => assert_eq!(got, fy, "not a symmetry of the orbit"),
                None => {
                    phi.insert(y, fy);
                    stack.push(y);
                }
            }
        }
    }
    let mut pairs: Vec<(Dart, Dart)> = phi.into_iter().collect();
    pairs.sort_unstable();
    pairs
}

/// A solid cube whose face at dart 0 (free along `alpha_3`) is sewn to itself by the
/// symmetry of the square that sends dart 0 to `image(cube, dart 0)`.
fn folded_cube(image: impl Fn(&DenseMap, Dart) -> Dart) -> DenseMap {
    let mut m = build::cube(3).unwrap();
    let d = Dart::new(0);
    assert!(m.is_free(d, 3));
    let e = image(&m, d);
    for (x, y) in orbit_map(&m, d, e, AlphaSet::below(2)) {
        assert_ne!(x, y, "the fold has no fixed dart");
        m.link(x, y, 3);
    }
    m.validate().unwrap();
    m
}

/// The four kinds, with the dimension of the lowest folded cell and whether the fold keeps
/// that cell's orientation.
fn kinds() -> Vec<(&'static str, DenseMap, usize, bool)> {
    let mut edge = build::polygon(4).unwrap();
    let a0 = edge.alpha(Dart::new(0), 0);
    edge.link(Dart::new(0), a0, 2);
    edge.validate().unwrap();
    let half_turn = folded_cube(|m, d| {
        let a10 = |x: Dart| m.alpha(m.alpha(x, 0), 1);
        a10(a10(d))
    });
    let diagonal = folded_cube(|m, d| m.alpha(d, 1));
    let midpoints = folded_cube(|m, d| m.alpha(d, 0));
    vec![
        ("edge of a square sewn to itself reversed", edge, 1, false),
        ("face of a cube sewn to itself by a half-turn", half_turn, 2, true),
        ("face of a cube sewn to itself by a diagonal mirror", diagonal, 2, false),
        ("face of a cube sewn to itself by a mirror through edge midpoints", midpoints, 1, false),
    ]
}

/// The smallest dart of the i-cell of `d`.
fn cell_rep(m: &DenseMap, d: Dart, i: usize) -> Dart {
    m.orbit(d, AlphaSet::cell(i, m.dim())).into_iter().min().unwrap()
}

#[test]
fn every_kind_is_found_and_refused_with_its_cell() {
    for (name, m, dim, keeps) in kinds() {
        // Def. 6 through gmap-core: the fold, at the lowest dimension, at dart 0's cell
        let defect = m.check_no_self_bending().unwrap_err();
        let BoundaryDefect::SelfBending { dart, i, other, cell } = defect else { panic!("{name}: {defect}") };
        assert_eq!(i, dim, "{name}");
        assert_eq!(dart, Dart::new(0), "{name}");
        assert_eq!(cell, cell_rep(&m, Dart::new(0), dim), "{name}");
        assert!(m.orbit(dart, AlphaSet::above(i, m.dim())).contains(&other), "{name}");
        assert!(m.orbit(dart, AlphaSet::below(i)).contains(&other), "{name}");
        assert_eq!(m.check_complete_boundaries(), Err(defect.clone()), "{name}");
        assert!(!m.has_complete_boundaries() && !m.has_no_self_bending(), "{name}");
        // the cellular method refuses, naming the folded cell
        match cellular_complex(&m) {
            Err(PreconditionError::SelfBending(e)) => {
                assert!(keeps, "{name}: a fold that keeps the orientation is Def. 6's alone");
                assert_eq!(e, defect, "{name}");
            }
            Err(PreconditionError::C1(CellDefect::NotOrientable { dim: d, dart, .. })) => {
                assert!(!keeps, "{name}: a reversing fold fails C1 first");
                assert_eq!((d, dart), (dim, cell), "{name}");
            }
            other => panic!("{name}: expected a refusal, got {:?}", other.map(|c| c.chain.counts().to_vec())),
        }
        // the simplicial counterpart: a ball (or a square) with a boundary cell folded is
        // still contractible
        let want = if m.dim() == 2 { "(Z, 0, 0)" } else { "(Z, 0, 0, 0)" };
        assert_eq!(homology_z(&simplicial_complex(&m)).unwrap().to_string(), want, "{name}");
    }
}

#[test]
fn the_half_turn_cube_passes_c1_and_c2() {
    // what made the fold slip through before Def. 6 was checked: every cell orientable as a
    // compacted cell, and the volume bounded by a sphere
    let (_, m, _, _) = kinds().into_iter().nth(1).unwrap();
    for i in 0..=3 {
        assert!(m.cell_orientation(i).is_ok(), "C1 on the {i}-cells");
    }
    assert_eq!(m.cell_counts(), vec![6, 10, 6, 1]);
    let msg = cellular_complex(&m).unwrap_err().to_string();
    assert!(msg.starts_with("the 2-cell of dart 0 is folded onto itself: darts 0 and "), "{msg}");
    assert!(msg.ends_with("(Def. 6 of BO: no self-bending)"), "{msg}");
    // the unfolded cube has complete boundaries (alpha_3 may be free)
    assert!(build::cube(3).unwrap().has_complete_boundaries());
}

#[test]
fn the_command_line_refuses_each_kind_and_simplicial_answers() {
    let dir = tempfile::tempdir().unwrap();
    for (k, (name, m, dim, _)) in kinds().into_iter().enumerate() {
        let path = dir.path().join(format!("fold{k}.gmap"));
        std::fs::write(&path, gmap_core::io::format_gmap(&m)).unwrap();
        let cell = cell_rep(&m, Dart::new(0), dim);
        let o = gmap(&["homology", p(&path), "--method", "cellular"]);
        assert_eq!(o.status.code(), Some(1), "{name}: {}", stderr(&o));
        let err = stderr(&o);
        assert!(err.contains("the cellular method does not apply (use --method simplicial)"), "{name}: {err}");
        assert!(err.contains(&format!("the {dim}-cell of dart {}", cell.get())), "{name}: {err}");
        let o = gmap(&["homology", p(&path), "--method", "simplicial", "--json"]);
        assert_eq!(o.status.code(), Some(0), "{name}: {}", stderr(&o));
        let v: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
        let want = if m.dim() == 2 { serde_json::json!([1, 0, 0]) } else { serde_json::json!([1, 0, 0, 0]) };
        assert_eq!(v["betti"], want, "{name}");
        let o = gmap(&["info", p(&path), "--json"]);
        let v: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
        assert_eq!(v["complete_boundaries"], false, "{name}");
    }
    // the half-turn: refused for Def. 6 in the contract's words
    let path = dir.path().join("fold1.gmap");
    let err = stderr(&gmap(&["homology", p(&path)]));
    assert!(err.contains("is folded onto itself") && err.contains("(Def. 6 of BO: no self-bending)"), "{err}");
}
