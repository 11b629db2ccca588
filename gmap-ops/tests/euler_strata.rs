//! EO on G-maps: detaching a vertex from a circle leaves two boundary-incomplete edges
//! (darts free for alpha_0); the cell counts then follow EO Theorem 1, and the abstract
//! stratified model gives the same Euler characteristic. EO Example 2 step by step.

use gmap_core::GMap;
use gmap_ops::euler::strata::{example_2, incomplete_cells, EoArgs, StratifiedObject};

#[test]
fn detach_and_reattach_a_vertex() {
    // a triangle as a 1-map
    let mut g = GMap::new(1);
    let d: Vec<_> = (0..6).map(|_| g.create_dart()).collect();
    for k in 0..3 {
        g.sew(d[2 * k], d[2 * k + 1], 0);
        g.sew(d[2 * k + 1], d[(2 * k + 2) % 6], 1);
    }
    assert_eq!(incomplete_cells(&g.to_dense_map()), (vec![3, 3], vec![0, 0]));
    // detach the vertex {d1, d2} (EO's kvC-like detachment): its darts go, the two edges
    // at it lose an end
    g.remove_dart(d[1]);
    g.remove_dart(d[2]);
    let m = g.to_dense_map();
    assert!(m.validate().is_ok());
    let (complete, incomplete) = incomplete_cells(&m);
    assert_eq!((complete.clone(), incomplete.clone()), (vec![2, 1], vec![0, 2]));
    // EO Theorem 1 with ball strata: v - e - e∞ = 2 - 1 - 2
    let chi = m.euler_characteristic();
    assert_eq!(chi, -1);
    // the same object by EO's operators: two vertices joined by an edge, and an open edge
    // at each of them
    let mut o = StratifiedObject::new();
    let run = |o: &mut StratifiedObject, name: &str, a: EoArgs| o.apply_named(name, &a).unwrap();
    let v1 = run(&mut o, "mvC", EoArgs::new()).new[0];
    let v2 = run(&mut o, "mvC", EoArgs::new()).new[0];
    let (c1, c2) = (o.strata[v1].component, o.strata[v2].component);
    run(&mut o, "mekC", EoArgs::new().c(c1).c2(c2).on(&[v1, v2]));
    let ea = run(&mut o, "me∞E∞", EoArgs::new().on(&[v1])).new[0];
    let s = run(&mut o, "me∞E∞", EoArgs::new().on(&[v2]));
    let eb = s.new[0];
    assert_eq!((s.complete, s.incomplete), (vec![2, 1], vec![0, 2]));
    assert_eq!(o.euler_by_strata(), chi);
    // compact it: a new vertex v3 closes both open ends (kE∞C joins v3's component,
    // kE∞mCh closes the loop)
    let v3 = run(&mut o, "mvC", EoArgs::new()).new[0];
    run(&mut o, "ke∞me", EoArgs::new().s(ea).on(&[v3]));
    run(&mut o, "ke∞me", EoArgs::new().s(eb).on(&[v3]));
    let (ca, cb, c3) = (o.strata[ea].component, o.strata[eb].component, o.strata[v3].component);
    run(&mut o, "kE∞C", EoArgs::new().c(ca).c2(c1).c3(c3));
    let s = run(&mut o, "kE∞mCh", EoArgs::new().c(cb).c2(c1));
    assert_eq!((s.complete, s.incomplete, s.euler), (vec![3, 3], vec![0, 0], 0));
    assert_eq!((s.counts.big_c, s.counts.big_ch), (1, 1));
    // compact: a new vertex closes both open ends again
    let a = g.create_dart();
    let b = g.create_dart();
    g.sew(d[0], a, 0);
    g.sew(d[3], b, 0);
    g.sew(a, b, 1);
    let m = g.to_dense_map();
    assert_eq!(incomplete_cells(&m), (vec![3, 3], vec![0, 0]));
    assert_eq!(m.euler_characteristic(), 0);
}

#[test]
fn example_2_step_by_step() {
    let steps = example_2();
    let table: Vec<(&str, i64, i64, i64, i64)> =
        steps.iter().map(|s| (s.name.as_str(), s.components, s.global_holes[1], s.global_holes[2], s.euler)).collect();
    assert_eq!(
        table,
        vec![
            ("meehCCh", 1, 1, 0, 0), // a circle edge: C = 1, Ch = 1
            ("mfkCh", 1, 0, 0, 1),   // a disc fills the hole
            ("mfCc", 1, 0, 1, 2),    // a second disc makes a void: a sphere
            ("mvfh", 1, 0, 1, 2),    // a vertex in f1: f1 gets a 1-hole, global shape unchanged
            ("meCh", 1, 1, 1, 1),    // a loop edge at the vertex: a global 1-hole
        ]
    );
    // local holes at the end: e1's hole and f1's hole; strata v1; e1, e2; f1, f2
    let last = steps.last().unwrap();
    assert_eq!(last.complete, vec![1, 2, 2]);
    assert_eq!(last.local_holes[1], 2);
}
