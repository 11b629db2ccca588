//! Property tests of attributes and vertex points through the Euler operators.
//!
//! Maps of dimension 2 and 3 made of builder objects (cubes, simplices, polygons) carry an
//! attribute on every cell of every dimension and a point on every vertex. Random steps
//! follow: sews, unsews, every Euler operator of [`gmap_ops::euler::ops`] under our names
//! and CGAL's, and `close`. After each step, against a snapshot taken before it:
//!
//! * the map is valid and every cell has exactly one attribute ([`GMap::validate`]);
//! * the merge and split hooks of each dimension ran exactly as many times as cells merged
//!   and split, counted independently on the darts that survive the step: a cell after the
//!   step meeting k cells from before is k - 1 merges, a cell from before meeting k cells
//!   after is k - 1 splits;
//! * every surviving dart's cell value, and its vertex's point, is one of those its new cell
//!   had before the step (the counting hooks keep the first value), and its own when its
//!   cell merged with no other;
//! * a vertex made by the step holds the point the operator was given (or the middle of
//!   the split edge, or none for `close(0)`);
//! * CGAL's removals and contractions (of any cell, which may cut cells, leave a boundary
//!   or empty the map) delete the darts they say.
//!
//! Then every cell without an attribute (made of new darts) gets a fresh one and every
//! vertex without a point a fresh point, so that the next step starts from a full map.

#[path = "../../gmap-core/tests/attr_common/mod.rs"]
mod attr_common;

use std::collections::{BTreeSet, HashMap};

use attr_common::{attr as value, cells_by_dart as cells_of, count, fill, merges_and_splits, Full, Hooks};
use gmap_core::{DartId, Point};
use gmap_ops::build;
use gmap_ops::euler::ops::{self, EulerError};
use gmap_ops::euler::random::{attempt, Operator};
use proptest::prelude::*;

/// One random step; the numbers pick darts among the live ones.
#[derive(Clone, Debug)]
enum Step {
    Sew(usize, usize, usize),
    Unsew(usize, usize),
    /// an operator through [`attempt`] (which checks that its predicate agrees)
    Op(usize, usize, usize, usize),
    /// [`ops::try_insert_vertex_at`] with a given point
    VertexAt(usize),
    /// [`ops::insert_cell_0_in_cell_1`]: the middle of the edge
    Cgal0In1(usize),
    /// [`ops::try_insert_dangling_edge_at`] with a given point
    DanglingAt(usize),
    /// [`ops::insert_cell_1_between_two_cells_2`]
    Bridge(usize, usize),
    Close(usize),
    /// CGAL's [`ops::try_remove_cell`] of any i-cell
    CgalRemove(usize, usize),
    /// CGAL's [`ops::try_contract_cell`] of any i-cell
    CgalContract(usize, usize),
}

fn step_strategy() -> impl Strategy<Value = Step> {
    let p = any::<usize>();
    prop_oneof![
        2 => (p, p, 0usize..4).prop_map(|(a, b, i)| Step::Sew(a, b, i)),
        1 => (p, 0usize..4).prop_map(|(a, i)| Step::Unsew(a, i)),
        6 => (0usize..6, p, p, 0usize..4).prop_map(|(o, a, b, i)| Step::Op(o, a, b, i)),
        1 => p.prop_map(Step::VertexAt),
        1 => p.prop_map(Step::Cgal0In1),
        1 => p.prop_map(Step::DanglingAt),
        2 => (p, p).prop_map(|(a, b)| Step::Bridge(a, b)),
        1 => (0usize..4).prop_map(Step::Close),
        2 => (p, 0usize..4).prop_map(|(a, i)| Step::CgalRemove(a, i)),
        2 => (p, 0usize..4).prop_map(|(a, i)| Step::CgalContract(a, i)),
    ]
}

fn middle(g: &Full, d: DartId) -> Option<Point> {
    let e = g.alpha(d, 0);
    let (p, q) = (g.point(d)?, g.point(e)?);
    (e != d).then(|| [0.5 * (p[0] + q[0]), 0.5 * (p[1] + q[1]), 0.5 * (p[2] + q[2])])
}

/// Applies a step; returns whether it changed the map and the point a vertex it makes must
/// have.
fn apply(g: &mut Full, step: &Step, fresh: Point) -> Result<(bool, Option<Point>), TestCaseError> {
    let darts: Vec<DartId> = g.darts().collect();
    if darts.is_empty() {
        // CGAL's removals may empty the map
        return Ok((false, None));
    }
    let n = g.dim();
    let pick = |k: usize| darts[k % darts.len()];
    let agree = |allowed: bool, done: bool| -> Result<bool, TestCaseError> {
        prop_assert_eq!(allowed, done, "predicate and operator disagree on {:?}", step);
        Ok(done)
    };
    Ok(match *step {
        Step::Sew(a, b, i) => (g.try_sew(pick(a), pick(b), i % (n + 1)).is_ok(), None),
        Step::Unsew(a, i) => {
            let (d, i) = (pick(a), i % (n + 1));
            (!g.is_free(d, i) && g.try_unsew(d, i).is_ok(), None)
        }
        Step::Op(o, a, b, i) => {
            let op = Operator::ALL[o];
            let (d, e, i) = (pick(a), pick(b), i % (n + 1));
            let point = match op {
                Operator::InsertVertex => middle(g, d),
                Operator::SplitCell if i == 1 => middle(g, d),
                _ => None,
            };
            let tried = attempt(g, op, d, e, i);
            (agree(tried.allowed, tried.result.is_ok())?, point)
        }
        Step::VertexAt(a) => {
            let d = pick(a);
            let allowed = ops::can_insert_vertex(g, d);
            (agree(allowed, ops::try_insert_vertex_at(g, d, Some(fresh)).is_ok())?, Some(fresh))
        }
        Step::Cgal0In1(a) => {
            let d = pick(a);
            let (allowed, point) = (ops::is_insertable_cell_0_in_cell_1(g, d), middle(g, d));
            let made = ops::insert_cell_0_in_cell_1(g, d);
            if let Ok(v) = made {
                prop_assert_eq!(g.point(v), point, "the new vertex is not at the middle");
            }
            (agree(allowed, made.is_ok())?, point)
        }
        Step::DanglingAt(a) => {
            let d = pick(a);
            let allowed = ops::can_insert_dangling_edge(g, d);
            (agree(allowed, ops::try_insert_dangling_edge_at(g, d, Some(fresh)).is_ok())?, Some(fresh))
        }
        Step::Bridge(a, b) => {
            let (d1, d2) = (pick(a), pick(b));
            let allowed = ops::is_insertable_cell_1_between_two_cells_2(g, d1, d2);
            let made = ops::insert_cell_1_between_two_cells_2(g, d1, d2);
            if let Ok(e) = made {
                prop_assert_eq!(g.alpha(e, 1), d1);
            }
            (agree(allowed, made.is_ok())?, None)
        }
        Step::CgalRemove(a, i) | Step::CgalContract(a, i) => {
            let (d, i) = (pick(a), i % (n + 1));
            let before = g.dart_count();
            let remove = matches!(step, Step::CgalRemove(..));
            let allowed = if remove { ops::is_removable(g, d, i) } else { ops::is_contractible(g, d, i) };
            let done = if remove { ops::try_remove_cell(g, d, i) } else { ops::try_contract_cell(g, d, i) };
            if let Ok(k) = done {
                prop_assert_eq!(before - g.dart_count(), k, "the darts deleted");
            }
            (agree(allowed, done.is_ok())?, None)
        }
        Step::Close(i) => {
            let i = i % (n + 1);
            let allowed = ops::can_close(g, i);
            (agree(allowed, ops::try_close(g, i).is_ok())?, None)
        }
    })
}

/// Builds the map of `pieces`, runs `steps`, checks every property after each; returns the
/// number of steps that changed the map.
fn run(n: usize, pieces: &[usize], steps: &[Step]) -> Result<usize, TestCaseError> {
    let mut g = Full::with_attributes(n);
    for &k in pieces {
        let piece = match k % 5 {
            0 => build::simplex(n),
            1 => build::cube(n),
            2 => build::polygon(3),
            3 => build::polygon(4),
            _ => build::simplex(1),
        };
        g.try_append(&piece.expect("a small builder object")).expect("pieces fit in the map");
    }
    let mut next = 0;
    fill(&mut g, &mut next);
    let hooks = Hooks::default();
    hooks.install(&mut g);
    let mut changed = 0;
    for step in steps {
        let before = cells_of(&g);
        let values: HashMap<DartId, Vec<Option<u64>>> =
            g.darts().map(|x| (x, (0..=n).map(|j| value(&g, x, j)).collect())).collect();
        let points: HashMap<DartId, Option<Point>> = g.darts().map(|x| (x, g.point(x))).collect();
        let (m0, s0) = hooks.counts();
        next += 1;
        let (done, made_point) = apply(&mut g, step, [next as f64, -1.0, 0.5])?;
        changed += done as usize;
        g.validate().map_err(|e| TestCaseError::fail(format!("{step:?}: {e}")))?;
        let after = cells_of(&g);
        let (m1, s1) = hooks.counts();
        let survivors: Vec<DartId> = g.darts().filter(|x| values.contains_key(x)).collect();
        if !done {
            prop_assert_eq!(survivors.len(), values.len(), "{:?} failed but removed darts", step);
            prop_assert_eq!(g.dart_count(), values.len(), "{:?} failed but made darts", step);
        }
        for j in 0..=n {
            let old: Vec<u32> = survivors.iter().map(|x| before[j][x]).collect();
            let new: Vec<u32> = survivors.iter().map(|x| after[j][x]).collect();
            let (merges, splits) = merges_and_splits(&old, &new);
            prop_assert_eq!(m1[j] - m0[j], merges, "merges of {}-cells in {:?}", j, step);
            prop_assert_eq!(s1[j] - s0[j], splits, "splits of {}-cells in {:?}", j, step);
            // one value per cell that holds a dart from before; none on cells of new darts
            let kept: BTreeSet<u32> = survivors.iter().map(|x| after[j][x]).collect();
            prop_assert_eq!(count(&g, j), kept.len(), "{}-values after {:?}", j, step);
            // the value of a surviving cell is one its darts had before
            let mut had: HashMap<u32, BTreeSet<Option<u64>>> = HashMap::new();
            for x in &survivors {
                had.entry(after[j][x]).or_default().insert(values[x][j]);
            }
            for x in &survivors {
                let v = value(&g, *x, j);
                prop_assert!(v.is_some(), "a {}-cell lost its value in {:?}", j, step);
                prop_assert!(had[&after[j][x]].contains(&v), "a {}-value from nowhere in {:?}", j, step);
                if merges == 0 {
                    prop_assert_eq!(v, values[x][j], "a {}-value changed in {:?}", j, step);
                }
            }
            if j == 0 {
                let mut had: HashMap<u32, Vec<Option<Point>>> = HashMap::new();
                for x in &survivors {
                    had.entry(after[0][x]).or_default().push(points[x]);
                }
                for x in &survivors {
                    let p = g.point(*x);
                    prop_assert!(p.is_some(), "a vertex lost its point in {:?}", step);
                    prop_assert!(had[&after[0][x]].contains(&p), "a point from nowhere in {:?}", step);
                    if merges == 0 {
                        prop_assert_eq!(p, points[x], "a vertex moved in {:?}", step);
                    }
                }
                // vertices of new darts only: the operator's point
                let old_vertices: BTreeSet<u32> = survivors.iter().map(|x| after[0][x]).collect();
                for x in g.darts().filter(|x| !old_vertices.contains(&after[0][x])) {
                    prop_assert_eq!(g.point(x), made_point, "the point of a new vertex in {:?}", step);
                }
            }
        }
        fill(&mut g, &mut next);
    }
    Ok(changed)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, ..ProptestConfig::default() })]

    #[test]
    fn attributes_and_points_follow_euler_operators_in_2d(
        pieces in prop::collection::vec(0usize..5, 1..4),
        steps in prop::collection::vec(step_strategy(), 1..30),
    ) {
        run(2, &pieces, &steps)?;
    }

    #[test]
    fn attributes_and_points_follow_euler_operators_in_3d(
        pieces in prop::collection::vec(0usize..5, 1..4),
        steps in prop::collection::vec(step_strategy(), 1..30),
    ) {
        run(3, &pieces, &steps)?;
    }
}

/// The random steps above do change maps: a fixed sequence on a cube with a square counts
/// its applied steps and the hooks it calls.
#[test]
fn a_fixed_sequence_changes_the_map_and_calls_the_hooks() {
    let steps = [
        Step::Bridge(0, 48),
        Step::Op(0, 5, 0, 0),
        Step::Op(1, 7, 9, 0),
        Step::VertexAt(11),
        Step::DanglingAt(3),
        Step::Op(3, 0, 0, 1),
        Step::Close(3),
    ];
    let changed = run(3, &[1, 3], &steps).unwrap();
    assert!(changed >= 4, "only {changed} steps applied");
}

/// Each operator's effect on attributes, on a pillow (two squares sewn along their four
/// edges: a sphere) with a value on every cell.
#[test]
fn a_pillow_cut_and_merged_back() {
    let mut g = Full::with_attributes(2);
    let d = g.try_append(&build::polygon(4).unwrap()).unwrap();
    let e = g.try_append(&build::polygon(4).unwrap()).unwrap();
    for k in 0..4 {
        g.sew(d[2 * k], e[2 * k], 2);
    }
    let mut next = 0;
    fill(&mut g, &mut next);
    let c = Hooks::default();
    c.install(&mut g);
    let face = *g.attribute::<2>(d[0]).unwrap();
    // the diagonal from corner 0 to corner 2: the face splits once, the copy keeps the value
    let far = g.alpha(g.alpha(g.alpha(d[0], 0), 1), 0);
    ops::try_insert_edge(&mut g, d[0], far).unwrap();
    assert_eq!((c.counts().0[2], c.counts().1[2]), (0, 1));
    assert_eq!(g.attribute_count::<2>(), 3);
    assert_eq!(g.attribute::<2>(d[0]), Some(&face));
    // the new edge has no value; removing it merges the faces back
    let diagonal = g.alpha(d[0], 1);
    assert_eq!(g.attribute::<1>(diagonal), None);
    ops::try_remove_cell_keeping_homology(&mut g, diagonal, 1).unwrap();
    assert_eq!((c.counts().0[2], c.counts().1[2]), (1, 1));
    assert_eq!(g.attribute_count::<2>(), 2);
    // a vertex in an edge at a given point; the edge's value is copied to both halves
    let edge = *g.attribute::<1>(d[0]).unwrap();
    ops::try_insert_vertex_at(&mut g, d[0], Some([9.0, 9.0, 9.0])).unwrap();
    assert_eq!(g.point(g.alpha(d[0], 0)), Some([9.0, 9.0, 9.0]));
    assert_eq!((c.counts().0[1], c.counts().1[1]), (0, 1));
    let b = g.alpha(d[1], 0);
    assert_eq!(g.attribute::<1>(b), Some(&edge));
    assert_eq!(g.point(b), Some([9.0, 9.0, 9.0]));
    fill(&mut g, &mut next);
    // contracting the half edge at d[0] merges its two vertices: the one of d[0] is kept,
    // with its point, and the merge hook of 0-cells runs once
    let (p, v) = (g.point(d[0]), *g.attribute::<0>(d[0]).unwrap());
    ops::try_contract_cell_keeping_homology(&mut g, d[0], 1).unwrap_or_else(|e: EulerError| panic!("{e}"));
    assert_eq!((c.counts().0[0], c.counts().1[0]), (1, 0));
    assert_eq!((g.point(b), g.attribute::<0>(b)), (p, Some(&v)));
    assert_eq!(g.point(d[7]), p);
    assert_eq!((g.dart_count(), g.attribute_count::<0>(), g.point_count()), (16, 4, 4));
    g.validate().unwrap();
}
