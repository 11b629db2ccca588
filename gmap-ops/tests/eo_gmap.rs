//! EO's operators that have a G-map counterpart, applied by name to a G-map and to the
//! stratified object it carries ([`StratifiedObject::from_map`]): both give the same
//! complete and incomplete cells per dimension ([`incomplete_cells`]) and the same Euler
//! characteristic, and both theorems agree on the object.

mod euler_common;

use std::collections::HashMap;

use euler_common::{cube_grid, find_cut, polygon, thaw};
use gmap_core::{DartId, GMap};
use gmap_ops::euler::ops::{can_insert_edge, try_insert_edge, try_insert_vertex};
use gmap_ops::euler::strata::{apply_on_gmap, map_counts, EoArgs, EoOperator, StratifiedObject};

/// The stratum of the i-cell of every dart of `g` in the object `from_map` reads.
fn read(g: &GMap) -> (StratifiedObject, impl Fn(DartId, usize) -> usize) {
    let (m, ids) = g.to_dense_with_ids();
    let (o, strata) = StratifiedObject::from_map(&m);
    assert_eq!(o.validate(), Ok(()));
    let parts: Vec<Vec<u32>> = (0..=m.dim()).map(|i| m.cells(i).of).collect();
    let index: HashMap<DartId, usize> = ids.iter().enumerate().map(|(k, &d)| (d, k)).collect();
    let at = move |d: DartId, i: usize| strata[i][parts[i][index[&d]] as usize];
    (o, at)
}

/// Applies `name` to `g` at `darts` and to `o` at `args`; asserts the same counts. Returns
/// the counts `(complete, incomplete, χ)`.
fn both(
    g: &mut GMap,
    o: &mut StratifiedObject,
    name: &str,
    darts: &[DartId],
    args: EoArgs,
) -> (Vec<i64>, Vec<i64>, i64) {
    let op = EoOperator::from_name(name).unwrap();
    let r = apply_on_gmap(op, g, darts).expect("a G-map counterpart");
    let eop = r.unwrap_or_else(|e| panic!("{name} on the G-map: {e}"));
    assert_eq!(eop.name, name.trim_end_matches('∞'));
    let step = o.apply(op, &args).unwrap_or_else(|e| panic!("{name} on the object: {e}"));
    let (m, _) = g.to_dense_with_ids();
    assert!(m.validate().is_ok());
    let counts = map_counts(&m);
    assert_eq!((step.complete.clone(), step.incomplete.clone(), step.euler), counts, "{name}");
    assert_eq!(step.counts.theorem_1(), step.counts.theorem_2());
    counts
}

/// A 1-map path `u — w` with an edge missing its far end at `w`: darts `a b` (the
/// complete edge) and `c` (the open one, 0-free), `b c` forming the vertex `w`.
fn open_path() -> (GMap, [DartId; 3]) {
    let mut g = GMap::new(1);
    let (a, b, c) = (g.create_dart(), g.create_dart(), g.create_dart());
    g.sew(a, b, 0);
    g.sew(b, c, 1);
    (g, [a, b, c])
}

#[test]
fn mve_on_an_edge_with_a_missing_end() {
    // a lone dart: a vertex and an edge missing its far end (χ = 0)
    let mut g = GMap::new(1);
    let a = g.create_dart();
    let (mut o, at) = read(&g);
    assert_eq!(map_counts(&g.to_dense_map()), (vec![1, 0], vec![0, 1], 0));
    let e = at(a, 1);
    // mve∞ (EO Fig. 5(b)): a complete edge from the vertex to the new one, an open edge
    // beyond; the same counts on both sides
    let counts = both(&mut g, &mut o, "mve∞", &[a], EoArgs::new().s(e));
    assert_eq!(counts, (vec![2, 1], vec![0, 1], 0));
    // mve refuses an open edge, and mve∞ a complete one
    let mve = EoOperator::from_name("mve").unwrap();
    let b = g.alpha(g.alpha(a, 0), 1);
    assert!(apply_on_gmap(mve, &mut g, &[b]).unwrap().is_err());
    assert!(o.apply(mve, &EoArgs::new().s(o.strata.len() - 1)).is_err());
    // kve∞ takes the new vertex away again
    let (mut o, at) = read(&g);
    let v = g.alpha(a, 0);
    let args = EoArgs::new().s(at(v, 1)).t(at(v, 0)).u(at(g.alpha(v, 1), 1));
    let counts = both(&mut g, &mut o, "kve∞", &[v], args);
    assert_eq!(counts, (vec![1, 0], vec![0, 1], 0));
}

#[test]
fn subdividers_on_a_path_with_an_open_end() {
    let (mut g, [a, b, c]) = open_path();
    let (mut o, at) = read(&g);
    assert_eq!(map_counts(&g.to_dense_map()), (vec![2, 1], vec![0, 1], 0));
    // mve on the complete edge; the new part takes the end w
    let args = EoArgs::new().s(at(a, 1)).moved(&[at(b, 0)]);
    assert_eq!(both(&mut g, &mut o, "mve", &[a], args), (vec![3, 2], vec![0, 1], 0));
    // mve∞ on the open edge
    let (mut o, at) = read(&g);
    assert_eq!(both(&mut g, &mut o, "mve∞", &[c], EoArgs::new().s(at(c, 1))), (vec![4, 3], vec![0, 1], 0));
    // kve on the vertex w (between two complete edges), kve∞ on the one next to the open edge
    let (mut o, at) = read(&g);
    let v = g.alpha(c, 0); // a dart of the vertex made by mve∞
    let args = EoArgs::new().s(at(b, 1)).t(at(b, 0)).u(at(c, 1));
    assert_eq!(both(&mut g, &mut o, "kve", &[b], args), (vec![3, 2], vec![0, 1], 0));
    let (mut o, at) = read(&g);
    let args = EoArgs::new().s(at(v, 1)).t(at(v, 0)).u(at(g.alpha(v, 1), 1));
    assert_eq!(both(&mut g, &mut o, "kve∞", &[v], args), (vec![2, 1], vec![0, 1], 0));
}

#[test]
fn mef_kef_on_a_square() {
    let mut g = polygon(4);
    let (mut o, at) = read(&g);
    assert_eq!(map_counts(&g.to_dense_map()), (vec![4, 4, 1], vec![0, 0, 0], 1));
    let d1 = g.darts().next().unwrap();
    let d2 = g.darts().find(|&x| can_insert_edge(&g, d1, x)).unwrap();
    let args = EoArgs::new().s(at(d1, 2)).on(&[at(d1, 0), at(d2, 0)]);
    assert_eq!(both(&mut g, &mut o, "mef", &[d1, d2], args), (vec![4, 5, 2], vec![0, 0, 0], 1));
    // mve on the new edge, then kve and kef back
    let (mut o, at) = read(&g);
    let e = g.alpha(d1, 1);
    let args = EoArgs::new().s(at(e, 1));
    assert_eq!(both(&mut g, &mut o, "mve", &[e], args), (vec![5, 6, 2], vec![0, 0, 0], 1));
    let (mut o, at) = read(&g);
    let v = g.alpha(e, 0);
    let args = EoArgs::new().s(at(v, 1)).t(at(v, 0)).u(at(g.alpha(v, 1), 1));
    assert_eq!(both(&mut g, &mut o, "kve", &[v], args), (vec![4, 5, 2], vec![0, 0, 0], 1));
    let (mut o, at) = read(&g);
    let e = g.alpha(d1, 1);
    let args = EoArgs::new().s(at(e, 2)).t(at(e, 1)).u(at(g.alpha(e, 2), 2));
    assert_eq!(both(&mut g, &mut o, "kef", &[e], args), (vec![4, 4, 1], vec![0, 0, 0], 1));
}

#[test]
fn mfs_kfs_in_a_cube() {
    // a solid cube with a square drawn around its middle (as in euler_ops)
    let (mut g, _) = thaw(&cube_grid(3, 1, false));
    let d = g.darts().next().unwrap();
    let mut cut = vec![d];
    let mut x = d;
    for _ in 0..3 {
        x = g.alpha(g.alpha(g.alpha(x, 1), 0), 1);
        x = g.alpha(x, 2);
        cut.push(x);
    }
    for &e in &cut {
        try_insert_vertex(&mut g, e).unwrap();
    }
    for k in 0..4 {
        let a = g.alpha(cut[k], 0);
        let b = g.alpha(cut[(k + 1) % 4], 0);
        let t = g.darts().find(|&y| can_insert_edge(&g, a, y) && g.cell_darts(y, 0).contains(&b)).unwrap();
        try_insert_edge(&mut g, a, t).unwrap();
    }
    // the boundary of the solid is free for alpha_3, not below: every cell is complete
    let (mut o, at) = read(&g);
    assert_eq!(map_counts(&g.to_dense_map()), (vec![12, 20, 10, 1], vec![0, 0, 0, 0], 1));
    let seeds = find_cut(&g);
    let args = EoArgs::new().s(at(seeds[0], 3)).on(&[at(seeds[0], 0)]);
    assert_eq!(both(&mut g, &mut o, "mfs", &seeds, args), (vec![12, 20, 11, 2], vec![0, 0, 0, 0], 1));
    let (mut o, at) = read(&g);
    let f = g.alpha(seeds[0], 2);
    let args = EoArgs::new().s(at(f, 3)).t(at(f, 2)).u(at(g.alpha(f, 3), 3));
    assert_eq!(both(&mut g, &mut o, "kfs", &[f], args), (vec![12, 20, 10, 1], vec![0, 0, 0, 0], 1));
}

#[test]
fn counterparts_are_the_ball_subdividers() {
    let with: Vec<&str> = EoOperator::ALL.iter().filter(|o| o.gmap_counterpart().is_some()).map(|o| o.name()).collect();
    assert_eq!(with, ["mve", "kve", "mve∞", "kve∞", "mef", "kef", "mfs", "kfs"]);
    // and the others have none
    let mut g = GMap::new(1);
    let a = g.create_dart();
    assert!(apply_on_gmap(EoOperator::from_name("mvC").unwrap(), &mut g, &[a]).is_none());
}

#[test]
fn a_map_read_as_an_object_satisfies_both_theorems() {
    // a square with one side's far end cut away: an edge missing an end at a corner
    let mut g = polygon(4);
    let d = g.darts().next().unwrap();
    let far = g.alpha(d, 0);
    let far_corner = g.alpha(far, 1);
    g.remove_dart(far);
    g.remove_dart(far_corner);
    let (m, _) = g.to_dense_with_ids();
    let (o, _) = StratifiedObject::from_map(&m);
    assert_eq!(o.validate(), Ok(()));
    let (complete, incomplete, chi) = map_counts(&m);
    let step = o.step("read");
    assert_eq!((step.complete, step.incomplete, step.euler), (complete, incomplete, chi));
}
