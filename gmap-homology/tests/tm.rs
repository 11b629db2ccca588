//! TM's boundary/coboundary model on G-maps: signed sets, view and section, circuits,
//! the edit check, Poincaré duality through the dual map.

use gmap_core::examples;
use gmap_homology::arch::ArchComplex;
use gmap_homology::tm::{SignedSet, TmDefect, TmModel, TmSet};

#[test]
fn cylinder_seam_occurs_with_both_signs() {
    let cyl = examples::cylinder();
    let t = TmModel::from_map(&cyl).unwrap();
    let face = t.regions_of_dim(2)[0];
    let b = t.boundary(&SignedSet::cell(face));
    // three edges: two boundary circles once each (opposite signs), the seam +1 and -1
    let mut occ: Vec<(u64, u64)> = b.iter().map(|(_, p, m)| (p, m)).collect();
    occ.sort();
    // (both circles come out positive with the smallest-dart orientation of each edge)
    assert_eq!(occ, vec![(1, 0), (1, 0), (1, 1)]);
    // the boundary of the face is a circuit
    assert!(t.is_circuit(&b, 1));
    // the view of the face holds everything: 1 face, 3 edges, 2 vertices
    assert_eq!(t.view(&SignedSet::cell(face)).len(), 6);
    // the section of a vertex: the vertex, the edges on it, the face
    let v0 = t.regions_of_dim(0)[0];
    assert_eq!(t.section(&SignedSet::cell(v0)).len(), 4);
    // a cylinder has free edges: their coboundary (one face, once) is not a cocircuit
    match t.edit_check() {
        Err(TmDefect::CoboundaryNotCocircuit { dim: 1, plus: 1, minus: 0, .. }) => {}
        other => panic!("unexpected {other:?}"),
    }
}

#[test]
fn closed_surfaces_and_the_edit_check() {
    // the Klein bottle: the face is glued to one edge twice with the same orientation
    let k = TmModel::from_map(&examples::klein_bottle()).unwrap();
    match k.edit_check() {
        Err(TmDefect::CoboundaryNotCocircuit { dim: 1, plus: 2, minus: 0, .. }) => {}
        other => panic!("unexpected {other:?}"),
    }
    for m in [examples::torus(), examples::klein_bottle()] {
        let t = TmModel::from_map(&m).unwrap();
        let face = t.regions_of_dim(2)[0];
        assert!(t.is_circuit(&t.boundary(&SignedSet::cell(face)), 1));
        let v = t.regions_of_dim(0)[0];
        assert!(t.is_cocircuit(&t.coboundary(&SignedSet::cell(v)), 1));
    }
    assert_eq!(TmModel::from_map(&examples::torus()).unwrap().edit_check(), Ok(()));
}

#[test]
fn dangling_edge_is_named() {
    // an edge with only one end vertex: its boundary is not a 0-circuit
    let t = TmModel::new(1, vec![(10, 0), (11, 1)], &[(1, 0, 1, 0)]);
    assert_eq!(t.edit_check(), Err(TmDefect::BoundaryNotCircuit { cell: 11, dim: 1, at: 11, plus: 1, minus: 0 }));
    assert_eq!(
        t.edit_check().unwrap_err().to_string(),
        "TM (7:5): the boundary of 1-cell 11 is not a circuit: cell 11 occurs +1/-0 times in its boundary"
    );
}

#[test]
fn poincare_duality_transposes_the_incidence_graph() {
    // (a map with boundary has no dual with complete cells: closed maps only)
    for m in [examples::torus(), examples::klein_bottle()] {
        // weights are dual up to sign only on orientable maps; the Klein bottle keeps the pairs
        let orientable = m.is_orientable();
        let x = ArchComplex::from_map(&m).unwrap();
        let d = ArchComplex::from_map(&m.dual()).unwrap();
        let xt = x.transpose().unwrap();
        // same regions and pairs; weights agree up to the orientation of the cells
        let n = m.dim();
        let counts = m.cell_counts();
        let off = |k: usize| counts[..k].iter().sum::<usize>() as u64;
        // dual id of primal region (k, j) is off_dual(n-k) + j
        let dcounts = m.dual().cell_counts();
        let doff = |k: usize| dcounts[..k].iter().sum::<usize>() as u64;
        let map_id = |id: u64| {
            let k = (0..=n).rev().find(|&k| off(k) <= id && counts[k] > 0 && id < off(k) + counts[k] as u64).unwrap();
            doff(n - k) + (id - off(k))
        };
        let mut a: Vec<(u64, u64, i64)> = xt
            .entry_ids()
            .into_iter()
            .map(|(f, t, w)| (map_id(f.0), map_id(t.0), if orientable { w.abs() } else { 0 }))
            .collect();
        let mut b: Vec<(u64, u64, i64)> =
            d.entry_ids().into_iter().map(|(f, t, w)| (f.0, t.0, if orientable { w.abs() } else { 0 })).collect();
        a.sort();
        b.sort();
        assert_eq!(a, b);
        // the TM model of the dual is the dual of the model (boundary and coboundary swap)
        let t = TmModel::from_map(&m).unwrap();
        let td = t.dual();
        assert_eq!(td.regions_of_dim(0).len(), counts[n]);
        let f = t.regions_of_dim(n)[0];
        assert_eq!(td.coboundary(&SignedSet::cell(f)), t.boundary(&SignedSet::cell(f)));
    }
}

/// A square disc as a 2-map: 4 vertices, 4 edges, 1 face.
fn square() -> TmModel {
    let mut m = gmap_core::DenseMap::new(2, 8);
    for k in 0..4u32 {
        m.link(gmap_core::Dart::new(2 * k), gmap_core::Dart::new(2 * k + 1), 0);
        m.link(gmap_core::Dart::new(2 * k + 1), gmap_core::Dart::new((2 * k + 2) % 8), 1);
    }
    TmModel::from_map(&m).unwrap()
}

#[test]
fn two_dimensional_file_layout_fig_3() {
    let t = square();
    // Fig. 3: three entry points; C^0 holds Y^1, C^2 holds Z^1, the self-dual C^1 both pairs
    let shown: Vec<String> = t
        .file_layout()
        .iter()
        .map(|(k, sets)| format!("{k}: {}", sets.iter().map(|s| s.to_string()).collect::<Vec<_>>().join(", ")))
        .collect();
    assert_eq!(shown, vec!["C^0: Y^1", "C^1: Z^0, Y^2", "C^2: Z^1"]);
    assert_eq!(TmSet::C(0).dual(2), TmSet::C(2));
    assert_eq!(TmSet::Y(1).dual(2), TmSet::Z(1));
    assert_eq!(TmSet::Z(0).dual(2), TmSet::Y(2));
    let e = t.regions_of_dim(1)[0];
    let rec = t.record(e);
    assert_eq!(rec.iter().map(|r| r.0).collect::<Vec<_>>(), vec![TmSet::Z(0), TmSet::Y(2)]);
    assert_eq!(rec[0].1.totals(), (1, 1)); // from and to
    assert_eq!(rec[1].1.totals().0 + rec[1].1.totals().1, 1); // one face: a free edge
                                                              // Z_B^0: 4 pairs of end vertices, Z_B^1: the face's boundary; Y_G^1: 4, Y_G^2: 4
    assert_eq!((t.bounding_circuits(0).count(), t.bounding_circuits(1).count()), (4, 1));
    assert_eq!((t.cobounding_cocircuits(1).count(), t.cobounding_cocircuits(2).count()), (4, 4));
    assert_eq!(t.bounding_circuits(2).count() + t.cobounding_cocircuits(0).count(), 0);
}

#[test]
fn closing_a_disc_gives_a_sphere_that_passes() {
    let t = square();
    let defects = t.edit_defects();
    assert_eq!(defects.len(), 4); // the four free edges, (7:6)
    assert!(defects.iter().all(|d| d.condition() == "(7:6)" && d.dim() == 1));
    let (closed, e) = t.try_close_with_exterior(99).unwrap();
    assert_eq!(closed.edit_check(), Ok(()));
    assert_eq!((closed.regions_of_dim(2).len(), closed.bounding(e).len()), (2, 4)); // χ = 4 - 4 + 2
    let face = t.regions_of_dim(2)[0];
    for &edge in closed.regions_of_dim(1) {
        // the face and the outside on the two sides of every edge
        let s = closed.try_sides(edge).unwrap();
        let mut pair = vec![s.near.unwrap(), s.far.unwrap()];
        pair.sort();
        assert_eq!(pair, vec![face, e]);
        // the face lies left of (far side in TM's sign) the edges it takes positively
        assert_eq!(s.far == Some(face), t.bounding(face).get(edge) == (1, 0));
        let ends = closed.try_ends(edge).unwrap();
        assert!(ends.from.is_some() && ends.to.is_some() && ends.from != ends.to);
    }
}
