//! EO's catalogue, operator by operator: each operator the paper names is applied where
//! its precondition holds, and its effect is asserted on the paper's own counts (the
//! letters of its name: `mvC` adds a vertex `v` and a component `C`, `kffhmCCh` removes a
//! face `f` with its hole `fh` and adds a component `C` and a global hole `Ch`, …), on the
//! Euler characteristic (its `euler_effect`, the same by EO Theorems 1 and 2), and its
//! inverse brings the counts back. Refusals name the reason and leave the object unchanged.

use gmap_ops::euler::strata::{EoArgs, EoOperator, EoStep, Family, StrataError, StratifiedObject};

fn run(o: &mut StratifiedObject, name: &str, a: EoArgs) -> EoStep {
    o.apply_named(name, &a).unwrap_or_else(|e| panic!("{name}: {e}"))
}

/// Applies `name` and checks its effect on the paper's counts and on χ; returns the step.
fn check(o: &mut StratifiedObject, name: &str, a: EoArgs, expected: &[(&str, i64)]) -> EoStep {
    let before = o.counts();
    let chi = o.euler_by_strata();
    let step = run(o, name, a);
    assert_eq!(step.counts.delta(&before), expected, "{name}: change of the counts");
    let op = EoOperator::from_name(name).unwrap();
    assert_eq!(step.euler - chi, op.euler_effect(), "{name}: Euler characteristic");
    assert_eq!(step.counts.theorem_1(), step.euler, "{name}: Theorem 1 by the paper's formula");
    assert_eq!(step.counts.theorem_2(), step.euler, "{name}: Theorem 2 by the paper's formula");
    step
}

/// Applies `name` (an inverse) and checks that the counts are back to `before`.
fn undo(o: &mut StratifiedObject, name: &str, a: EoArgs, before: &StratifiedObject) {
    let step = run(o, name, a);
    assert_eq!(step.counts, before.counts(), "{name} undoes");
    assert_eq!(step.euler, before.euler_by_strata());
}

/// A triangle's boundary: three vertices, three edges, one component with a 1-hole.
/// Returns the object, the vertices, the edges and the component.
fn circle() -> (StratifiedObject, [usize; 3], [usize; 3], usize) {
    let mut o = StratifiedObject::new();
    let v0 = run(&mut o, "mvC", EoArgs::new()).new[0];
    let v1 = run(&mut o, "mvC", EoArgs::new()).new[0];
    let c = o.strata[v0].component;
    let c1 = o.strata[v1].component;
    let e01 = run(&mut o, "mekC", EoArgs::new().c(c).c2(c1).on(&[v0, v1])).new[0];
    let v2 = run(&mut o, "mvC", EoArgs::new()).new[0];
    let c2 = o.strata[v2].component;
    let e12 = run(&mut o, "mekC", EoArgs::new().c(c).c2(c2).on(&[v1, v2])).new[0];
    let e20 = run(&mut o, "meCh", EoArgs::new().c(c).on(&[v2, v0])).new[0];
    (o, [v0, v1, v2], [e01, e12, e20], c)
}

/// A disc: the circle and a face filling it. Returns the object, vertices, edges, the face
/// and the component.
fn disc() -> (StratifiedObject, [usize; 3], [usize; 3], usize, usize) {
    let (mut o, v, e, c) = circle();
    let f = run(&mut o, "mfkCh", EoArgs::new().c(c).on(&[e[0], e[1], e[2], v[0], v[1], v[2]])).new[0];
    (o, v, e, f, c)
}

/// A ball: the disc, a second face closing a sphere, a solid filling it. Returns the
/// object, vertices, the solid and the component.
fn ball() -> (StratifiedObject, [usize; 3], usize, usize) {
    let (mut o, v, e, f, c) = disc();
    let all = [e[0], e[1], e[2], v[0], v[1], v[2]];
    let f2 = run(&mut o, "mfCc", EoArgs::new().c(c).on(&all)).new[0];
    let mut below = all.to_vec();
    below.extend([f, f2]);
    let s = run(&mut o, "mskCc", EoArgs::new().c(c).on(&below)).new[0];
    (o, v, s, c)
}

#[test]
fn global_hole_shapers() {
    // mvC / kvC
    let mut o = StratifiedObject::new();
    let before = o.clone();
    let v = check(&mut o, "mvC", EoArgs::new(), &[("v", 1), ("C", 1)]).new[0];
    undo(&mut o, "kvC", EoArgs::new().s(v), &before);
    // meCh / keCh: an edge closing a path into a loop
    let (mut o, v, _, c) = circle();
    let before = o.clone();
    let e = check(&mut o, "meCh", EoArgs::new().c(c).on(&[v[0], v[1]]), &[("e", 1), ("Ch", 1)]).new[0];
    undo(&mut o, "keCh", EoArgs::new().s(e), &before);
    // mfCc / kfCc: a second face on a disc's boundary makes a void
    let (mut o, v, e, _, c) = disc();
    let before = o.clone();
    let f = check(&mut o, "mfCc", EoArgs::new().c(c).on(&[e[0], e[1], e[2], v[0]]), &[("f", 1), ("Cc", 1)]).new[0];
    undo(&mut o, "kfCc", EoArgs::new().s(f), &before);
    // meehCCh / keehCCh, mffcCCc / kffcCCc: a circle, a sphere, each a new component
    let mut o = StratifiedObject::new();
    let before = o.clone();
    let e = check(&mut o, "meehCCh", EoArgs::new(), &[("e", 1), ("eh", 1), ("C", 1), ("Ch", 1)]).new[0];
    undo(&mut o, "keehCCh", EoArgs::new().s(e), &before);
    let f = check(&mut o, "mffcCCc", EoArgs::new(), &[("f", 1), ("fc", 1), ("C", 1), ("Cc", 1)]).new[0];
    undo(&mut o, "kffcCCc", EoArgs::new().s(f), &before);
}

#[test]
fn detachments_that_make_holes_and_components() {
    // kemC / mekC (dimension 1): detaching the edge of a path leaves two components
    let mut o = StratifiedObject::new();
    let v0 = run(&mut o, "mvC", EoArgs::new()).new[0];
    let v1 = run(&mut o, "mvC", EoArgs::new()).new[0];
    let (c0, c1) = (o.strata[v0].component, o.strata[v1].component);
    let e = run(&mut o, "mekC", EoArgs::new().c(c0).c2(c1).on(&[v0, v1])).new[0];
    let before = o.clone();
    let s = check(&mut o, "kemC", EoArgs::new().s(e).moved(&[v1]), &[("e", -1), ("C", 1)]);
    undo(&mut o, "mekC", EoArgs::new().c(c0).c2(s.new_components[0]).on(&[v0, v1]), &before);
    // kfmCh / mfkCh: detaching a disc's face leaves its boundary circle
    let (mut o, v, e, f, c) = disc();
    let before = o.clone();
    check(&mut o, "kfmCh", EoArgs::new().s(f), &[("f", -1), ("Ch", 1)]);
    undo(&mut o, "mfkCh", EoArgs::new().c(c).on(&[e[0], e[1], e[2], v[0], v[1], v[2]]), &before);
    // ksmCc / mskCc: detaching a ball's solid leaves its boundary sphere
    let (mut o, v, s, c) = ball();
    let before = o.clone();
    let below = before.strata[s].frontier.clone();
    check(&mut o, "ksmCc", EoArgs::new().s(s), &[("s", -1), ("Cc", 1)]);
    undo(&mut o, "mskCc", EoArgs::new().c(c).on(&below), &before);
    let _ = v;
    // kffhmCCh / mffhkCCh: a tube (an annulus between two circles); detaching the annulus
    // leaves two circles: a new component and a new global 1-hole
    let mut o = StratifiedObject::new();
    let s1 = run(&mut o, "meehCCh", EoArgs::new());
    let s2 = run(&mut o, "meehCCh", EoArgs::new());
    let (e1, e2, c1, c2) = (s1.new[0], s2.new[0], s1.new_components[0], s2.new_components[0]);
    let before = o.clone();
    let f = check(
        &mut o,
        "mffhkCCh",
        EoArgs::new().c(c1).c2(c2).on(&[e1, e2]),
        &[("f", 1), ("fh", 1), ("C", -1), ("Ch", -1)],
    )
    .new[0];
    let tube = o.clone();
    check(&mut o, "kffhmCCh", EoArgs::new().s(f).moved(&[e2]), &[("f", -1), ("fh", -1), ("C", 1), ("Ch", 1)]);
    assert_eq!(o.counts(), before.counts());
    assert_eq!(o.euler_by_strata(), tube.euler_by_strata()); // χ: 0 before and after
                                                             // ksscmCCc / mssckCCc: a shell between two spheres
    let mut o = StratifiedObject::new();
    let s1 = run(&mut o, "mffcCCc", EoArgs::new());
    let s2 = run(&mut o, "mffcCCc", EoArgs::new());
    let (f1, f2, c1, c2) = (s1.new[0], s2.new[0], s1.new_components[0], s2.new_components[0]);
    let before = o.clone();
    let s = check(
        &mut o,
        "mssckCCc",
        EoArgs::new().c(c1).c2(c2).on(&[f1, f2]),
        &[("s", 1), ("sc", 1), ("C", -1), ("Cc", -1)],
    )
    .new[0];
    check(&mut o, "ksscmCCc", EoArgs::new().s(s).moved(&[f2]), &[("s", -1), ("sc", -1), ("C", 1), ("Cc", 1)]);
    assert_eq!(o.counts(), before.counts());
}

#[test]
fn stratum_subdividers() {
    // mve / kve on an edge of the circle; the new part takes the end v1
    let (mut o, v, e, _) = circle();
    let before = o.clone();
    let s = check(&mut o, "mve", EoArgs::new().s(e[0]).moved(&[v[1]]), &[("v", 1), ("e", 1)]);
    undo(&mut o, "kve", EoArgs::new().s(e[0]).t(s.new[0]).u(s.new[1]), &before);
    // mve∞ / kve∞: an edge with a missing end splits into a complete edge and an open one
    let mut o = StratifiedObject::new();
    let w = run(&mut o, "mvC", EoArgs::new()).new[0];
    let eo = run(&mut o, "me∞E∞", EoArgs::new().on(&[w])).new[0];
    let before = o.clone();
    let s = check(&mut o, "mve∞", EoArgs::new().s(eo), &[("v", 1), ("e", 1)]);
    assert!(o.strata[eo].complete && !o.strata[s.new[1]].complete);
    undo(&mut o, "kve∞", EoArgs::new().s(eo).t(s.new[0]).u(s.new[1]), &before);
    // a lone open edge splits into two open edges
    let mut o = StratifiedObject::new();
    let lone = run(&mut o, "me∞E∞", EoArgs::new()).new[0];
    check(&mut o, "mve∞", EoArgs::new().s(lone), &[("v", 1), ("e∞", 1)]);
    // mef / kef across the disc, from v0 to v1; the new part takes e01
    let (mut o, v, e, f, _) = disc();
    let before = o.clone();
    let s = check(&mut o, "mef", EoArgs::new().s(f).on(&[v[0], v[1]]).moved(&[e[0]]), &[("e", 1), ("f", 1)]);
    undo(&mut o, "kef", EoArgs::new().s(f).t(s.new[0]).u(s.new[1]), &before);
    // mef∞ / kef∞: an open sheet cut by an open edge from its vertex
    let mut o = StratifiedObject::new();
    let w = run(&mut o, "mvC", EoArgs::new()).new[0];
    let fo = run(&mut o, "mf∞F∞", EoArgs::new().on(&[w])).new[0];
    let before = o.clone();
    let s = check(&mut o, "mef∞", EoArgs::new().s(fo).on(&[w]).cut_complete(false), &[("e∞", 1), ("f∞", 1)]);
    undo(&mut o, "kef∞", EoArgs::new().s(fo).t(s.new[0]).u(s.new[1]), &before);
    // mfs / kfs: a ball cut by a face through v0
    let (mut o, v, sol, _) = ball();
    let before = o.clone();
    let s = check(&mut o, "mfs", EoArgs::new().s(sol).on(&[v[0]]), &[("f", 1), ("s", 1)]);
    undo(&mut o, "kfs", EoArgs::new().s(sol).t(s.new[0]).u(s.new[1]), &before);
    // mfs∞ / kfs∞: a lone open solid cut by an open face
    let mut o = StratifiedObject::new();
    let so = run(&mut o, "ms∞S∞", EoArgs::new()).new[0];
    let before = o.clone();
    let s = check(&mut o, "mfs∞", EoArgs::new().s(so).cut_complete(false), &[("f∞", 1), ("s∞", 1)]);
    undo(&mut o, "kfs∞", EoArgs::new().s(so).t(s.new[0]).u(s.new[1]), &before);
    // meehffh / keehffh: a circle inside the disc's face, bounding a new disc
    let (mut o, _, _, f, _) = disc();
    let before = o.clone();
    let s = check(&mut o, "meehffh", EoArgs::new().s(f), &[("e", 1), ("f", 1), ("eh", 1), ("fh", 1)]);
    undo(&mut o, "keehffh", EoArgs::new().s(f).t(s.new[0]).u(s.new[1]), &before);
    // mffcssc / kffcssc: a sphere inside the ball's solid, bounding a new ball
    let (mut o, _, sol, _) = ball();
    let before = o.clone();
    let s = check(&mut o, "mffcssc", EoArgs::new().s(sol), &[("f", 1), ("s", 1), ("fc", 1), ("sc", 1)]);
    undo(&mut o, "kffcssc", EoArgs::new().s(sol).t(s.new[0]).u(s.new[1]), &before);
    // meehfkfc / keehfkfc: a sphere face cut in two discs by a circle
    let mut o = StratifiedObject::new();
    let sp = run(&mut o, "mffcCCc", EoArgs::new()).new[0];
    let before = o.clone();
    let s = check(&mut o, "meehfkfc", EoArgs::new().s(sp), &[("e", 1), ("f", 1), ("eh", 1), ("fc", -1)]);
    undo(&mut o, "keehfkfc", EoArgs::new().s(sp).t(s.new[0]).u(s.new[1]), &before);
}

#[test]
fn local_hole_shapers_filled() {
    // mvfh / kvfh: a vertex inside the disc's face (EO Example 2's fourth step)
    let (mut o, v, _, f, _) = disc();
    let before = o.clone();
    let t = check(&mut o, "mvfh", EoArgs::new().s(f), &[("v", 1), ("fh", 1)]).new[0];
    // mekfh / kemfh: an edge from v0 to that vertex makes the punctured face a disc again
    let mid = o.clone();
    let e = check(&mut o, "mekfh", EoArgs::new().s(f).on(&[v[0], t]), &[("e", 1), ("fh", -1)]).new[0];
    undo(&mut o, "kemfh", EoArgs::new().s(f).t(e), &mid);
    undo(&mut o, "kvfh", EoArgs::new().s(f).t(t), &before);
    // mvsc / kvsc, mesh / kesh in the ball's solid
    let (mut o, v, sol, _) = ball();
    let before = o.clone();
    let t = check(&mut o, "mvsc", EoArgs::new().s(sol), &[("v", 1), ("sc", 1)]).new[0];
    // meksc / kemsc: an edge from v0 to the inner vertex
    let mid = o.clone();
    let e = check(&mut o, "meksc", EoArgs::new().s(sol).on(&[v[0], t]), &[("e", 1), ("sc", -1)]).new[0];
    undo(&mut o, "kemsc", EoArgs::new().s(sol).t(e), &mid);
    undo(&mut o, "kvsc", EoArgs::new().s(sol).t(t), &before);
    let e = check(&mut o, "mesh", EoArgs::new().s(sol).on(&[v[0], v[1]]), &[("e", 1), ("sh", 1)]).new[0];
    // mfksh / kfmsh: a face spanning the tunnel
    let mid = o.clone();
    let f = check(&mut o, "mfksh", EoArgs::new().s(sol).on(&[e, v[0], v[1]]), &[("f", 1), ("sh", -1)]).new[0];
    undo(&mut o, "kfmsh", EoArgs::new().s(sol).t(f), &mid);
    undo(&mut o, "kesh", EoArgs::new().s(sol).t(e), &before);
    // me∞s∞h / ke∞s∞h: an open edge through an open solid
    let mut o = StratifiedObject::new();
    let so = run(&mut o, "ms∞S∞", EoArgs::new()).new[0];
    let before = o.clone();
    let e = check(&mut o, "me∞s∞h", EoArgs::new().s(so), &[("e∞", 1), ("s∞h", 1)]).new[0];
    undo(&mut o, "ke∞s∞h", EoArgs::new().s(so).t(e), &before);
    // mvkeh / kvmeh: a vertex on a circle edge
    let mut o = StratifiedObject::new();
    let r = run(&mut o, "meehCCh", EoArgs::new()).new[0];
    let before = o.clone();
    let t = check(&mut o, "mvkeh", EoArgs::new().s(r), &[("v", 1), ("eh", -1)]).new[0];
    undo(&mut o, "kvmeh", EoArgs::new().s(r).t(t), &before);
    // mvkfc / kvmfc: a vertex on a sphere face
    let mut o = StratifiedObject::new();
    let sp = run(&mut o, "mffcCCc", EoArgs::new()).new[0];
    let before = o.clone();
    let t = check(&mut o, "mvkfc", EoArgs::new().s(sp), &[("v", 1), ("fc", -1)]).new[0];
    undo(&mut o, "kvmfc", EoArgs::new().s(sp).t(t), &before);
}

#[test]
fn local_hole_shapers_on_open_strata() {
    // me∞kf∞h / ke∞mf∞h: an open sheet with an open hole, cut open by an open edge
    let mut o = StratifiedObject::new();
    let fo = run(&mut o, "mf∞F∞", EoArgs::new()).new[0];
    run(&mut o, "mf∞hF∞h", EoArgs::new().s(fo));
    let before = o.clone();
    let e = check(&mut o, "me∞kf∞h", EoArgs::new().s(fo), &[("e∞", 1), ("f∞h", -1)]).new[0];
    undo(&mut o, "ke∞mf∞h", EoArgs::new().s(fo).t(e), &before);
    // me∞ks∞c / ke∞ms∞c and mf∞ks∞h / kf∞ms∞h in an open solid
    let mut o = StratifiedObject::new();
    let so = run(&mut o, "ms∞S∞", EoArgs::new()).new[0];
    run(&mut o, "ms∞cS∞c", EoArgs::new().s(so));
    run(&mut o, "ms∞hS∞h", EoArgs::new().s(so));
    let before = o.clone();
    let e = check(&mut o, "me∞ks∞c", EoArgs::new().s(so), &[("e∞", 1), ("s∞c", -1)]).new[0];
    undo(&mut o, "ke∞ms∞c", EoArgs::new().s(so).t(e), &before);
    let f = check(&mut o, "mf∞ks∞h", EoArgs::new().s(so), &[("f∞", 1), ("s∞h", -1)]).new[0];
    undo(&mut o, "kf∞ms∞h", EoArgs::new().s(so).t(f), &before);
}

#[test]
fn attachers_and_unfilled_holes() {
    let mut o = StratifiedObject::new();
    let v = run(&mut o, "mvC", EoArgs::new()).new[0];
    let before = o.clone();
    let e = check(&mut o, "me∞E∞", EoArgs::new().on(&[v]), &[("e∞", 1), ("E∞", 1)]).new[0];
    let f = check(&mut o, "mf∞F∞", EoArgs::new().on(&[v, e]), &[("f∞", 1), ("F∞", 1)]).new[0];
    let s = check(&mut o, "ms∞S∞", EoArgs::new().on(&[v, e, f]), &[("s∞", 1), ("S∞", 1)]).new[0];
    // unfilled hole shapers
    let mid = o.clone();
    check(&mut o, "mf∞hF∞h", EoArgs::new().s(f), &[("f∞h", 1), ("F∞h", 1)]);
    check(&mut o, "ms∞hS∞h", EoArgs::new().s(s), &[("s∞h", 1), ("S∞h", 1)]);
    check(&mut o, "ms∞cS∞c", EoArgs::new().s(s), &[("s∞c", 1), ("S∞c", 1)]);
    check(&mut o, "ks∞cS∞c", EoArgs::new().s(s), &[("s∞c", -1), ("S∞c", -1)]);
    check(&mut o, "ks∞hS∞h", EoArgs::new().s(s), &[("s∞h", -1), ("S∞h", -1)]);
    undo(&mut o, "kf∞hF∞h", EoArgs::new().s(f), &mid);
    // detachers, highest first (a stratum bounding another cannot go)
    check(&mut o, "ks∞S∞", EoArgs::new().s(s), &[("s∞", -1), ("S∞", -1)]);
    check(&mut o, "kf∞F∞", EoArgs::new().s(f), &[("f∞", -1), ("F∞", -1)]);
    undo(&mut o, "ke∞E∞", EoArgs::new().s(e), &before);
}

#[test]
fn stratum_and_hole_compacters() {
    // ke∞me / me∞ke, kf∞mf / mf∞kf, ks∞ms / ms∞ks: strata with a vertex in their frontier
    let mut o = StratifiedObject::new();
    let v = run(&mut o, "mvC", EoArgs::new()).new[0];
    let e = run(&mut o, "me∞E∞", EoArgs::new().on(&[v])).new[0];
    let f = run(&mut o, "mf∞F∞", EoArgs::new().on(&[v])).new[0];
    let s = run(&mut o, "ms∞S∞", EoArgs::new().on(&[v])).new[0];
    let before = o.clone();
    check(&mut o, "ke∞me", EoArgs::new().s(e), &[("e", 1), ("e∞", -1)]);
    check(&mut o, "kf∞mf", EoArgs::new().s(f), &[("f", 1), ("f∞", -1)]);
    check(&mut o, "ks∞ms", EoArgs::new().s(s), &[("s", 1), ("s∞", -1)]);
    check(&mut o, "ms∞ks", EoArgs::new().s(s), &[("s", -1), ("s∞", 1)]);
    check(&mut o, "mf∞kf", EoArgs::new().s(f), &[("f", -1), ("f∞", 1)]);
    undo(&mut o, "me∞ke", EoArgs::new().s(e), &before);
    // kf∞hmfh / mf∞hkfh: a vertex w fills the open hole of an open sheet
    let mut o = StratifiedObject::new();
    let f = run(&mut o, "mf∞F∞", EoArgs::new()).new[0];
    run(&mut o, "mf∞hF∞h", EoArgs::new().s(f));
    let w = run(&mut o, "mvC", EoArgs::new()).new[0];
    let before = o.clone();
    check(&mut o, "kf∞hmfh", EoArgs::new().s(f).on(&[w]), &[("fh", 1), ("f∞h", -1)]);
    undo(&mut o, "mf∞hkfh", EoArgs::new().s(f).moved(&[w]), &before);
    // ks∞hmsh / ms∞hksh, ks∞cmsc / ms∞cksc
    let mut o = StratifiedObject::new();
    let s = run(&mut o, "ms∞S∞", EoArgs::new()).new[0];
    run(&mut o, "ms∞hS∞h", EoArgs::new().s(s));
    run(&mut o, "ms∞cS∞c", EoArgs::new().s(s));
    let w = run(&mut o, "mvC", EoArgs::new()).new[0];
    let before = o.clone();
    check(&mut o, "ks∞hmsh", EoArgs::new().s(s).on(&[w]), &[("sh", 1), ("s∞h", -1)]);
    check(&mut o, "ks∞cmsc", EoArgs::new().s(s).on(&[w]), &[("sc", 1), ("s∞c", -1)]);
    check(&mut o, "ms∞cksc", EoArgs::new().s(s), &[("sc", -1), ("s∞c", 1)]);
    undo(&mut o, "ms∞hksh", EoArgs::new().s(s).moved(&[w]), &before);
}

#[test]
fn global_compacters() {
    // kE∞C / mE∞C (EO Fig. 14(b)): an open edge at v1 gets a compacting vertex v2 at its
    // other end; its component and v2's join v1's
    let mut o = StratifiedObject::new();
    let v1 = run(&mut o, "mvC", EoArgs::new()).new[0];
    let e = run(&mut o, "me∞E∞", EoArgs::new().on(&[v1])).new[0];
    let v2 = run(&mut o, "mvC", EoArgs::new()).new[0];
    run(&mut o, "ke∞me", EoArgs::new().s(e).on(&[v2]));
    let (c1, ce, c2) = (o.strata[v1].component, o.strata[e].component, o.strata[v2].component);
    let before = o.clone();
    check(&mut o, "kE∞C", EoArgs::new().c(ce).c2(c1).c3(c2), &[("C", -1), ("E∞", -1)]);
    undo(&mut o, "mE∞C", EoArgs::new().c(c1).moved(&[e]).moved2(&[v2]), &before);
    // kE∞mCh / mE∞kCh (EO Fig. 15(b)): the open edge closes at v1 itself: a loop
    let mut o = StratifiedObject::new();
    let v1 = run(&mut o, "mvC", EoArgs::new()).new[0];
    let e = run(&mut o, "me∞E∞", EoArgs::new().on(&[v1])).new[0];
    run(&mut o, "ke∞me", EoArgs::new().s(e));
    let (c1, ce) = (o.strata[v1].component, o.strata[e].component);
    let before = o.clone();
    check(&mut o, "kE∞mCh", EoArgs::new().c(ce).c2(c1), &[("Ch", 1), ("E∞", -1)]);
    undo(&mut o, "mE∞kCh", EoArgs::new().c(c1).moved(&[e]), &before);
    // kF∞Ch / mF∞Ch: an open disc whose rim is a circle edge closes onto it
    let mut o = StratifiedObject::new();
    let r = run(&mut o, "meehCCh", EoArgs::new()).new[0];
    let f = run(&mut o, "mf∞F∞", EoArgs::new().on(&[r])).new[0];
    run(&mut o, "kf∞mf", EoArgs::new().s(f));
    let (cr, cf) = (o.strata[r].component, o.strata[f].component);
    let before = o.clone();
    check(&mut o, "kF∞Ch", EoArgs::new().c(cf).c2(cr), &[("Ch", -1), ("F∞", -1)]);
    undo(&mut o, "mF∞Ch", EoArgs::new().c(cr).moved(&[f]), &before);
    // kS∞Cc / mS∞Cc: an open ball closes onto a sphere face
    let mut o = StratifiedObject::new();
    let sp = run(&mut o, "mffcCCc", EoArgs::new()).new[0];
    let s = run(&mut o, "ms∞S∞", EoArgs::new().on(&[sp])).new[0];
    run(&mut o, "ks∞ms", EoArgs::new().s(s));
    let (cp, cs) = (o.strata[sp].component, o.strata[s].component);
    let before = o.clone();
    check(&mut o, "kS∞Cc", EoArgs::new().c(cs).c2(cp), &[("Cc", -1), ("S∞", -1)]);
    undo(&mut o, "mS∞Cc", EoArgs::new().c(cp).moved(&[s]), &before);
    // kF∞mCc / mF∞kCc: an open disc compacted by one vertex is a sphere
    let mut o = StratifiedObject::new();
    let v = run(&mut o, "mvC", EoArgs::new()).new[0];
    let f = run(&mut o, "mf∞F∞", EoArgs::new().on(&[v])).new[0];
    run(&mut o, "kf∞mf", EoArgs::new().s(f));
    let (cv, cf) = (o.strata[v].component, o.strata[f].component);
    let before = o.clone();
    check(&mut o, "kF∞mCc", EoArgs::new().c(cf).c2(cv), &[("Cc", 1), ("F∞", -1)]);
    undo(&mut o, "mF∞kCc", EoArgs::new().c(cv).moved(&[f]), &before);
    // kF∞hC / mF∞hC (EO Fig. 16): a vertex fills the open hole of a punctured sheet; the
    // hole goes locally (kf∞hmfh) and globally, and the vertex's component merges
    let mut o = StratifiedObject::new();
    let f = run(&mut o, "mf∞F∞", EoArgs::new()).new[0];
    run(&mut o, "mf∞hF∞h", EoArgs::new().s(f));
    let w = run(&mut o, "mvC", EoArgs::new()).new[0];
    run(&mut o, "kf∞hmfh", EoArgs::new().s(f).on(&[w]));
    let (cf, cw) = (o.strata[f].component, o.strata[w].component);
    let before = o.clone();
    check(&mut o, "kF∞hC", EoArgs::new().c(cf).c2(cw), &[("C", -1), ("F∞h", -1)]);
    undo(&mut o, "mF∞hC", EoArgs::new().c(cf).moved(&[w]), &before);
    // kS∞cC / mS∞cC
    let mut o = StratifiedObject::new();
    let s = run(&mut o, "ms∞S∞", EoArgs::new()).new[0];
    run(&mut o, "ms∞cS∞c", EoArgs::new().s(s));
    let w = run(&mut o, "mvC", EoArgs::new()).new[0];
    run(&mut o, "ks∞cmsc", EoArgs::new().s(s).on(&[w]));
    let (cs, cw) = (o.strata[s].component, o.strata[w].component);
    let before = o.clone();
    check(&mut o, "kS∞cC", EoArgs::new().c(cs).c2(cw), &[("C", -1), ("S∞c", -1)]);
    undo(&mut o, "mS∞cC", EoArgs::new().c(cs).moved(&[w]), &before);
}

#[test]
fn catalogue_lists_every_family() {
    let fams: Vec<Family> = EoOperator::ALL.iter().map(|o| o.family()).collect();
    for f in Family::ALL {
        assert!(fams.contains(&f), "{f:?}");
    }
    assert_eq!(EoOperator::ALL.len(), 100);
    for op in EoOperator::ALL {
        assert!(!op.precondition().is_empty());
    }
    // the operators that change the number of components, and by how much χ
    let effect = |n: &str| EoOperator::from_name(n).unwrap().euler_effect();
    assert_eq!([effect("mekC"), effect("kemC"), effect("kffhmCCh"), effect("ksscmCCc")], [-1, 1, 0, 2]);
    assert_eq!([effect("kE∞C"), effect("kE∞mCh"), effect("kF∞hC"), effect("mvC"), effect("meehCCh")], [0, 0, 0, 1, 0]);
}

#[test]
fn refusals_name_the_reason_and_change_nothing() {
    let refuse = |o: &mut StratifiedObject, name: &str, a: EoArgs| -> StrataError {
        let before = o.clone();
        let e = o.apply_named(name, &a).expect_err(name);
        assert_eq!(*o, before, "{name} refused but changed the object");
        e
    };
    // a lone open edge is never marked complete
    let mut o = StratifiedObject::new();
    let e = run(&mut o, "me∞E∞", EoArgs::new()).new[0];
    assert_eq!(refuse(&mut o, "ke∞me", EoArgs::new().s(e)), StrataError::LoneOpenStratum(e));
    // a complete edge cannot be attached with nothing at its ends
    let (mut o, _, _, c) = circle();
    assert!(matches!(refuse(&mut o, "meCh", EoArgs::new().c(c)), StrataError::LoneOpenStratum(_)));
    // hole ranges: a boundary-incomplete edge has no 1-hole (mf∞hF∞h is for faces), a
    // vertex none, an open face no 2-hole
    let mut o = StratifiedObject::new();
    let e = run(&mut o, "me∞E∞", EoArgs::new()).new[0];
    assert!(matches!(refuse(&mut o, "mf∞hF∞h", EoArgs::new().s(e)), StrataError::Precondition { .. }));
    let f = run(&mut o, "mf∞F∞", EoArgs::new()).new[0];
    run(&mut o, "mf∞hF∞h", EoArgs::new().s(f));
    assert!(matches!(refuse(&mut o, "kf∞hF∞h", EoArgs::new().s(e)), StrataError::Precondition { .. }));
    // mve on a circle edge would leave a closed edge with a vertex: refused (that is mvkeh)
    let mut o = StratifiedObject::new();
    let r = run(&mut o, "meehCCh", EoArgs::new()).new[0];
    assert_eq!(refuse(&mut o, "mve", EoArgs::new().s(r)), StrataError::ClosedWithFrontier(r));
    // kvmfc on an open face (with a vertex inside) would give it a 2-hole
    let mut o = StratifiedObject::new();
    let f = run(&mut o, "mf∞F∞", EoArgs::new()).new[0];
    let v = run(&mut o, "mvfh", EoArgs::new().s(f)).new[0];
    assert_eq!(
        refuse(&mut o, "kvmfc", EoArgs::new().s(f).t(v)),
        StrataError::HoleOutOfRange { stratum: f, dim: 2, state: "boundary-incomplete", k: 2 }
    );
    // detaching a vertex that bounds an edge
    let (mut o, v, _, _) = circle();
    assert!(matches!(refuse(&mut o, "kvC", EoArgs::new().s(v[0])), StrataError::Precondition { .. }));
    // kemC on an edge of a circle: the rest does not fall apart, so the split the caller
    // asks for crosses a frontier
    let (mut o, v, e, _) = circle();
    assert!(matches!(refuse(&mut o, "kemC", EoArgs::new().s(e[0]).moved(&[v[1]])), StrataError::Precondition { .. }));
    // the theorems would disagree: keCh on a circle edge whose component has no 1-hole
    // left (after mfkCh filled it)
    let (mut o, _, e, _, _) = disc();
    refuse(&mut o, "keCh", EoArgs::new().s(e[0]));
    // unknown names
    assert!(StratifiedObject::new().apply_named("mxyz", &EoArgs::new()).is_err());
}

#[test]
fn invariants_catch_hand_made_objects() {
    // the fields are public: validate() names what a hand-made object breaks
    let (good, v, e, f, _) = disc();
    assert_eq!(good.validate(), Ok(()));
    // a vertex has no holes
    let mut o = good.clone();
    o.strata[v[0]].holes = vec![0, 1];
    assert_eq!(o.validate(), Err(StrataError::VertexHole(v[0])));
    // an edge has no 2-hole
    let mut o = good.clone();
    o.strata[e[0]].holes = vec![0, 0, 1];
    assert!(matches!(o.validate(), Err(StrataError::HoleOutOfRange { k: 2, dim: 1, .. })));
    // a face has at most one 2-hole
    let mut o = good.clone();
    o.strata[f].holes[2] = 2;
    assert!(matches!(o.validate(), Err(StrataError::HoleCount { k: 2, .. })));
    // a lone open edge is never complete
    let mut o = StratifiedObject::new();
    let x = run(&mut o, "me∞E∞", EoArgs::new()).new[0];
    o.strata[x].complete = true;
    o.components[o.strata[x].component].complete = true;
    assert_eq!(o.validate(), Err(StrataError::LoneOpenStratum(x)));
    // the theorems must agree
    let mut o = good.clone();
    let c = o.strata[f].component;
    o.components[c].holes = vec![0, 1];
    assert_eq!(o.validate(), Err(StrataError::TheoremsDisagree { by_strata: 1, by_components: 0 }));
    // an incomplete stratum in a complete component
    let mut o = good;
    o.strata[e[1]].complete = false;
    assert!(matches!(o.validate(), Err(StrataError::IncompleteInComplete { .. })));
}
