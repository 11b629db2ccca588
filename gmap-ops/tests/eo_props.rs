//! Property tests of EO's operators: random sequences of named operators at random places
//! keep EO Theorems 1 and 2 equal (and equal to the paper's formulas term by term), change
//! χ by the operator's `euler_effect`, and leave the object unchanged when refused; on
//! 1-maps, random subdivisions and coalescences (`mve`, `mve∞`, `kve`, `kve∞`) applied to
//! a G-map and to the object it carries give the same counts throughout.

use std::collections::HashMap;

use gmap_core::{DartId, GMap};
use gmap_ops::euler::strata::{apply_on_gmap, map_counts, EoArgs, EoOperator, Family, Scheme, StratifiedObject};
use gmap_ops::rng::SplitMix64;
use proptest::prelude::*;

fn pick(r: &mut SplitMix64, v: &[usize]) -> Option<usize> {
    (!v.is_empty()).then(|| v[r.below(v.len())])
}

fn subset(r: &mut SplitMix64, v: &[usize]) -> Vec<usize> {
    v.iter().copied().filter(|_| r.below(2) == 0).collect()
}

/// Arguments for `op` drawn from the strata and components that could fit it (and now and
/// then from ones that cannot), so that both acceptances and refusals occur.
fn args_for(o: &StratifiedObject, op: EoOperator, r: &mut SplitMix64) -> EoArgs {
    let live: Vec<usize> = o.live_strata().collect();
    let comps: Vec<usize> = o.live_components().collect();
    let of_dim = |d: usize| -> Vec<usize> { live.iter().copied().filter(|&s| o.strata[s].dim == d).collect() };
    let mut a = EoArgs::new();
    let s = if r.below(8) == 0 { pick(r, &live) } else { pick(r, &of_dim(op.n)) };
    a.s = s;
    let frontier = s.map(|s| o.strata[s].frontier.clone()).unwrap_or_default();
    let td = match op.scheme {
        Scheme::MergeFill | Scheme::MergeClose => op.d,
        _ => op.n.saturating_sub(1),
    };
    let tcand: Vec<usize> = frontier.iter().copied().filter(|&t| o.strata[t].dim == td).collect();
    a.t = pick(r, &tcand);
    if let (Some(s), Some(t)) = (a.s, a.t) {
        let ucand: Vec<usize> = o.bounded_by(t).into_iter().filter(|&u| u != s && o.strata[u].dim == op.n).collect();
        a.u = pick(r, &ucand);
    }
    a.c = match (op.scheme, a.s) {
        (Scheme::CompactComponent | Scheme::CompactComponentHole | Scheme::FillComponentHole, _) => pick(r, &comps),
        (_, Some(s)) if r.below(4) != 0 => Some(o.strata[s].component),
        _ => pick(r, &comps),
    };
    a.c2 = pick(r, &comps);
    a.c3 = pick(r, &comps);
    let below: Vec<usize> = live.iter().copied().filter(|&x| o.strata[x].dim < op.n).collect();
    a.on = match op.scheme {
        Scheme::Subdivide | Scheme::MergeFill | Scheme::MergeClose => subset(r, &frontier),
        Scheme::AttachHole | Scheme::DetachHole | Scheme::DetachHoled => {
            let cs: Vec<usize> = [a.c, a.c2].into_iter().flatten().collect();
            let pool: Vec<usize> = below.iter().copied().filter(|&x| cs.contains(&o.strata[x].component)).collect();
            subset(r, &pool)
        }
        _ => subset(r, &below),
    };
    let pool = match (op.scheme, a.s, a.c) {
        (Scheme::Subdivide, _, _) => frontier.clone(),
        (_, Some(s), _) if matches!(op.scheme, Scheme::DetachHole | Scheme::DetachHoled) => {
            o.strata_of(o.strata[s].component).into_iter().filter(|&x| x != s).collect()
        }
        (Scheme::CompactStratum | Scheme::CompactHole, _, _) => frontier.clone(),
        (_, _, Some(c)) => o.strata_of(c),
        _ => vec![],
    };
    a.moved = subset(r, &pool);
    a.moved2 = pool.iter().copied().filter(|x| !a.moved.contains(x)).filter(|_| r.below(2) == 0).collect();
    if r.below(6) == 0 {
        a.holes = vec![(1 + r.below(2), 1)];
    }
    if r.below(4) == 0 {
        a.parts_complete = Some((r.below(2) == 0, r.below(2) == 0));
    }
    if r.below(3) == 0 {
        a.cut_complete = Some(r.below(2) == 0);
    }
    a
}

/// One operator at random; checks the result. Returns the family when it was applied.
fn step(o: &mut StratifiedObject, op_pick: usize, seed: u64) -> Result<Option<Family>, String> {
    let op = EoOperator::ALL[op_pick % EoOperator::ALL.len()];
    let mut r = SplitMix64::new(seed);
    let args = args_for(o, op, &mut r);
    let before = o.clone();
    let chi = o.euler_by_strata();
    match o.apply(op, &args) {
        Ok(s) => {
            let name = op.name();
            o.validate().map_err(|e| format!("{name} left an invalid object: {e}"))?;
            if s.euler != o.euler_by_components() || s.euler != s.counts.theorem_1() || s.euler != s.counts.theorem_2()
            {
                return Err(format!("{name}: the theorems disagree: {s:?}"));
            }
            if s.euler - chi != op.euler_effect() {
                return Err(format!("{name}: χ changed by {}, not {}", s.euler - chi, op.euler_effect()));
            }
            Ok(Some(op.family()))
        }
        Err(e) => {
            if *o != before {
                return Err(format!("{} refused ({e}) but changed the object", op.name()));
            }
            Ok(None)
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn random_operator_sequences(seq in proptest::collection::vec((0usize..1000, any::<u64>()), 1..80)) {
        let mut o = StratifiedObject::new();
        for (op, seed) in seq {
            if let Err(e) = step(&mut o, op, seed) {
                prop_assert!(false, "{}", e);
            }
        }
    }
}

#[test]
fn random_sequences_reach_every_family() {
    let mut seen: HashMap<Family, usize> = HashMap::new();
    let mut r = SplitMix64::new(7);
    for _ in 0..200 {
        let mut o = StratifiedObject::new();
        for _ in 0..120 {
            let (op, seed) = (r.below(EoOperator::ALL.len()), r.next_u64());
            if let Some(f) = step(&mut o, op, seed).unwrap() {
                *seen.entry(f).or_default() += 1;
            }
        }
    }
    for f in Family::ALL {
        assert!(seen.get(&f).copied().unwrap_or(0) > 0, "no {f:?} applied: {seen:?}");
    }
}

// ---------- a 1-map and the object it carries ----------

/// A 1-map: a cycle of k edges (`kind` 0), a path of k edges (1), the path with an edge
/// missing its far end at each end (2).
fn base(kind: u8, k: usize) -> GMap {
    let mut g = GMap::new(1);
    let d: Vec<DartId> = (0..2 * k).map(|_| g.create_dart()).collect();
    for j in 0..k {
        g.sew(d[2 * j], d[2 * j + 1], 0);
        if kind == 0 || j + 1 < k {
            g.sew(d[2 * j + 1], d[(2 * j + 2) % (2 * k)], 1);
        }
    }
    if kind == 2 {
        let (p, q) = (g.create_dart(), g.create_dart());
        g.sew(p, d[0], 1);
        g.sew(q, d[2 * k - 1], 1);
    }
    g
}

/// The object the map carries and, for every dart, the strata of its vertex and its edge.
fn read(g: &GMap) -> (StratifiedObject, HashMap<DartId, usize>, HashMap<DartId, usize>) {
    let (m, ids) = g.to_dense_with_ids();
    let (o, strata) = StratifiedObject::from_map(&m);
    let (p0, p1) = (m.cells(0), m.cells(1));
    let mut vert = HashMap::new();
    let mut edge = HashMap::new();
    for (k, &d) in ids.iter().enumerate() {
        vert.insert(d, strata[0][p0.of[k] as usize]);
        edge.insert(d, strata[1][p1.of[k] as usize]);
    }
    (o, vert, edge)
}

fn counts(o: &StratifiedObject) -> (Vec<i64>, Vec<i64>, i64) {
    let s = o.step("");
    let mut c = s.complete;
    let mut i = s.incomplete;
    c.resize(2, 0);
    i.resize(2, 0);
    (c, i, s.euler)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn a_one_map_and_its_object_keep_the_same_counts(
        kind in 0u8..3,
        k in 1usize..6,
        seq in proptest::collection::vec((0u8..4, 0usize..200), 1..40),
    ) {
        let mut g = base(kind, k);
        let (mut o, mut vert, mut edge) = read(&g);
        prop_assert_eq!(counts(&o), map_counts(&g.to_dense_map()));
        for (which, pick) in seq {
            let darts: Vec<DartId> = g.darts().collect();
            let d = darts[pick % darts.len()];
            let name = ["mve", "mve∞", "kve", "kve∞"][which as usize];
            let op = EoOperator::from_name(name).unwrap();
            let args = if which < 2 {
                let mut a = EoArgs::new().s(edge[&d]);
                // the far end goes with the new part; on a loop it bounds both
                if !g.is_free(d, 0) {
                    let far = vert[&g.alpha(d, 0)];
                    a = if far == vert[&d] { a.on(&[far]) } else { a.moved(&[far]) };
                }
                a
            } else {
                EoArgs::new().s(edge[&d]).t(vert[&d]).u(edge[&g.alpha(d, 1)])
            };
            let w = g.alpha(d, 0);
            let other = g.alpha(d, 1);
            match apply_on_gmap(op, &mut g, &[d]).unwrap() {
                Ok(_) => {
                    let s = o.apply(op, &args);
                    prop_assert!(s.is_ok(), "{} accepted by the G-map, refused by the object: {:?}", name, s);
                    let s = s.unwrap();
                    if which < 2 {
                        // the new darts: a = alpha_0(d) on d's side, b = alpha_1(a) beyond
                        let a = g.alpha(d, 0);
                        let b = g.alpha(a, 1);
                        let (cut, part) = (s.new[0], s.new[1]);
                        vert.insert(a, cut);
                        vert.insert(b, cut);
                        edge.insert(a, edge[&d]);
                        edge.insert(b, part);
                        if w != d {
                            edge.insert(w, part);
                        }
                    } else {
                        let (keep, gone) = (edge[&d], edge[&other]);
                        for v in edge.values_mut() {
                            if *v == gone {
                                *v = keep;
                            }
                        }
                        vert.remove(&d);
                        vert.remove(&other);
                        edge.remove(&d);
                        edge.remove(&other);
                    }
                    let (m, _) = g.to_dense_with_ids();
                    prop_assert_eq!(counts(&o), map_counts(&m), "after {}", name);
                    prop_assert_eq!(o.validate(), Ok(()));
                }
                Err(e) => {
                    // the G-map refuses: so does the object, except where the result is a
                    // lone open edge, which EO has and a G-map cannot carry
                    let mut copy = o.clone();
                    let lone = format!("{e}").contains("without darts");
                    prop_assert!(lone || copy.apply(op, &args).is_err(), "{} refused by the G-map ({}) only", name, e);
                }
            }
        }
    }
}
