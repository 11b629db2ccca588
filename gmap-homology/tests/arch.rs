//! Architectural complexes: the numbers of the AC paper, G-map → complex → `.json` → back,
//! and the reader's refusals.

use gmap_core::examples;
use gmap_homology::arch::{ArchComplex, ArchError, Region, RegionId, Step, ZeroWeightRule};
use gmap_homology::dot::write_dot;
use gmap_homology::ep::EpVector;
use gmap_homology::json::{read_json, write_json, JsonError};

fn regions(v: &[(u64, usize)]) -> Vec<Region> {
    v.iter().map(|&(id, dim)| Region { id: RegionId(id), dim }).collect()
}

fn betti(x: &ArchComplex) -> Vec<usize> {
    x.homology_z().unwrap().betti
}

// Table 1: P, Q, R = 0, 1, 2; a, b, c = 3, 4, 5.
const PQR_ABC: [(u64, usize); 6] = [(0, 0), (1, 0), (2, 0), (3, 1), (4, 1), (5, 1)];

#[test]
fn table_1_two_graphs_one_chain_complex() {
    // δ: the loop c hangs at Q (left graph of Figure 2); δ': at R (right graph). Our copy of
    // Table 1 shows a stray "1" in column c of δ'; the text says each partial matrix keeps
    // exactly one zero and both complete to the same ∂, which fixes δ'(R, c) = 0 alone.
    let common = [(3, 0, -1), (3, 1, 1), (4, 1, -1), (4, 2, 1)];
    let mut e1 = common.to_vec();
    e1.push((5, 1, 0));
    let mut e2 = common.to_vec();
    e2.push((5, 2, 0));
    let delta = ArchComplex::try_new(1, regions(&PQR_ABC), e1).unwrap();
    let delta2 = ArchComplex::try_new(1, regions(&PQR_ABC), e2).unwrap();
    assert_ne!(delta, delta2);
    // one chain complex: both complete by zero to the full matrix ∂ of Table 1
    let full = vec![vec![-1, 0, 0], vec![1, -1, 0], vec![0, 1, 0]];
    assert_eq!(delta.chain_complex().boundary(1).to_dense(), full);
    assert_eq!(delta2.chain_complex().boundary(1).to_dense(), full);
    assert_eq!(betti(&delta), vec![1, 1]);
    assert_eq!(betti(&delta2), vec![1, 1]);
    // the partial matrices keep one zero each, in different places
    let zeros = |x: &ArchComplex| {
        x.entries()
            .iter()
            .filter(|e| e.weight == 0)
            .map(|e| (x.region(e.from).id.0, x.region(e.to).id.0))
            .collect::<Vec<_>>()
    };
    assert_eq!(zeros(&delta), vec![(5, 1)]);
    assert_eq!(zeros(&delta2), vec![(5, 2)]);
    // 5 defined entries of 9: the other zeros are dropped
    assert_eq!(delta.entries().len(), 5);
    // the topology tells the graphs apart: c's closure holds Q in δ, and R in δ'
    let ids = |x: &ArchComplex, v: Vec<usize>| v.iter().map(|&r| x.region(r).id.0).collect::<Vec<_>>();
    assert_eq!(ids(&delta, delta.closure(delta.index_of(RegionId(5)).unwrap())), vec![1, 5]);
    assert_eq!(ids(&delta2, delta2.closure(delta2.index_of(RegionId(5)).unwrap())), vec![2, 5]);
    // and so does the star of Q: in δ it holds the three edges, in δ' two
    assert_eq!(ids(&delta, delta.star(delta.index_of(RegionId(1)).unwrap())), vec![1, 3, 4, 5]);
    assert_eq!(ids(&delta2, delta2.star(delta2.index_of(RegionId(1)).unwrap())), vec![1, 3, 4]);
}

/// AC Figure 4 as described in Example 3.4 / 3.13.
/// A: one line without boundary (1-region, no vertex).
/// B: two vertices, two lines with zero boundary, a surface bounded by both lines.
/// C: two lines without boundary and a surface bounded by both.
fn figure_4() -> (ArchComplex, ArchComplex, ArchComplex) {
    let a = ArchComplex::try_new(1, regions(&[(0, 1)]), Vec::<(u64, u64, i64)>::new()).unwrap();
    let b = ArchComplex::try_new(
        2,
        regions(&[(0, 0), (1, 0), (2, 1), (3, 1), (4, 2)]),
        vec![(2, 0, 0), (3, 1, 0), (4, 2, 1), (4, 3, -1)],
    )
    .unwrap();
    let c = ArchComplex::try_new(2, regions(&[(0, 1), (1, 1), (2, 2)]), vec![(2, 0, 1), (2, 1, 1)]).unwrap();
    (a, b, c)
}

#[test]
fn example_3_13_betti_numbers() {
    let (a, b, c) = figure_4();
    assert_eq!(betti(&a), vec![0, 1]);
    assert_eq!(betti(&b), vec![2, 1, 0]);
    assert_eq!(betti(&c), vec![0, 1, 0]);
    // Euler–Poincaré formula (Cor. 3.11)
    for x in [&a, &b, &c] {
        let h = x.homology_z().unwrap();
        assert_eq!(x.euler_characteristic(), h.euler_characteristic());
    }
}

#[test]
fn stars_closures_and_t0() {
    let (_, b, _) = figure_4();
    let idx = |id: u64| b.index_of(RegionId(id)).unwrap();
    assert_eq!(b.star(idx(0)), vec![idx(0), idx(2), idx(4)]);
    assert_eq!(b.closure(idx(4)), vec![0, 1, 2, 3, 4]);
    assert!(b.is_open(&b.star(idx(1))));
    assert!(!b.is_open(&[idx(0)]));
    assert!(b.is_closed(&[idx(0), idx(2)]));
    assert!(!b.is_closed(&[idx(2)]));
    // T0: every pair of distinct regions is separated by an open set
    for x in 0..5 {
        for y in 0..5 {
            if x != y {
                let u = b.separating_open_set(x, y);
                assert!(b.is_open(&u));
                assert_ne!(u.contains(&x), u.contains(&y));
            }
        }
    }
    assert_eq!(b.boundary_regions(idx(4)).len(), 4);
    assert_eq!(b.component_count(), 1);
    assert_eq!(figure_4().0.component_count(), 1);
    assert_eq!(ring().component_count(), 1);
    assert_eq!(b.components_of(&b.boundary_regions(idx(4))).len(), 2);
}

/// The ring of AC Example 8.21: a 2-region Area with ∂(Area) = 1·Circle + 0·Line.
fn ring() -> ArchComplex {
    ArchComplex::try_new(2, regions(&[(0, 1), (1, 1), (2, 2)]), vec![(2, 0, 1), (2, 1, 0)]).unwrap()
}

#[test]
fn example_8_21_ring() {
    let r = ring();
    assert_eq!(betti(&r), vec![0, 1, 0]);
    let t = r.topological(ZeroWeightRule::Closed).unwrap();
    assert_eq!(betti(&t.complex), vec![1, 1, 0]);
    assert_eq!(t.complex.region_counts(), vec![2, 3, 1]);
    let steps: Vec<Step> = t.operators.iter().map(|o| o.step).collect();
    assert_eq!(steps, vec![Step::BaseVertex, Step::BaseVertex, Step::ConnectBoundary]);
    assert_eq!(t.operators[2].vector, EpVector::a(2, 1)); // X_1 - Y_0
                                                          // configuration before + operators = configuration after
    let before = EpVector::try_new(vec![0, 2, 1], vec![0, 1, 0]).unwrap();
    let after = before.try_add(&t.total().unwrap()).unwrap();
    assert_eq!(after, EpVector::try_new(vec![2, 3, 1], vec![1, 1, 0]).unwrap());
    assert!(after.is_configuration());
    // the paper's literal case α = 0 reproduces its printed first operator
    let s = r.topological(ZeroWeightRule::Seam).unwrap();
    let mut first = EpVector::zero(2);
    for o in s.operators.iter().filter(|o| o.step != Step::ConnectBoundary) {
        first = first.try_add(&o.vector).unwrap();
    }
    assert_eq!(first.to_string(), "3X_0 + 2Y_0 - Y_1");
    // ... but lowers b_1, so it does not reach the ring's topological Betti numbers
    assert_eq!(betti(&s.complex), vec![1, 0, 0]);
}

/// Each operator applied by Algorithm 8.16 changes the configuration exactly as it says.
#[test]
fn algorithm_8_16_operators_are_exact() {
    let (a, b, c) = figure_4();
    for x in [a, b, c, ring()] {
        for rule in [ZeroWeightRule::Closed, ZeroWeightRule::Seam] {
            let t = x.topological(rule).unwrap();
            let conf = |y: &ArchComplex| {
                let v: Vec<i64> = y.region_counts().iter().map(|&c| c as i64).collect();
                let mut b: Vec<i64> = betti(y).iter().map(|&c| c as i64).collect();
                b.resize(v.len(), 0);
                EpVector::try_new(v, b).unwrap()
            };
            let start = conf(&x);
            assert_eq!(start.try_add(&t.total().unwrap()).unwrap(), conf(&t.complex), "{rule:?}");
            for o in &t.operators {
                assert!(o.vector.is_operator());
            }
            if rule == ZeroWeightRule::Closed {
                // only the connecting step lowers a Betti number (b_0, joining parts)
                for o in &t.operators {
                    let lowered: Vec<usize> = (0..o.vector.dy().len()).filter(|&j| o.vector.dy()[j] < 0).collect();
                    match o.step {
                        Step::ConnectBoundary => assert!(lowered.is_empty() || lowered == vec![0]),
                        _ => assert!(lowered.is_empty()),
                    }
                }
            }
        }
    }
    // Figure 4 topologically: A is a circle, B an annulus, C an annulus
    let (a, b, c) = figure_4();
    assert_eq!(betti(&a.topological(ZeroWeightRule::Closed).unwrap().complex), vec![1, 1]);
    assert_eq!(betti(&b.topological(ZeroWeightRule::Closed).unwrap().complex), vec![1, 1, 0]);
    assert_eq!(betti(&c.topological(ZeroWeightRule::Closed).unwrap().complex), vec![1, 1, 0]);
}

/// AC Example 8.22: one 2-region A, lines l1..l12 (ids 1..12), 8 points (ids 21..28), with
/// ∂A = -l1 + l2 - l3 + l12 + l4 - l5 + l6 - l10 + l7 - l8 + l9 - l11: the outer wall
/// (4 corners) and two inner courts (2 points each; the figure is not in our copy, so the
/// ends of the lines are ours), three boundary components.
fn floor_plan() -> ArchComplex {
    let mut regs = vec![(100u64, 2usize)];
    regs.extend((1..=12).map(|l| (l, 1)));
    regs.extend((21..=28).map(|p| (p, 0)));
    let line = |l: u64, from: u64, to: u64| [(l, from, -1i64), (l, to, 1)];
    let mut e: Vec<(u64, u64, i64)> = Vec::new();
    // outer: P21 -> P22 -> P23 -> P24 -> P21, traversed as -l1, l2, -l3, l12
    e.extend(line(1, 22, 21));
    e.extend(line(2, 22, 23));
    e.extend(line(3, 24, 23));
    e.extend(line(12, 24, 21));
    // court 1 between P25 and P26: l4, -l5, l6, -l10
    for l in [4, 5, 6, 10] {
        e.extend(line(l, 25, 26));
    }
    // court 2 between P27 and P28: l7, -l8, l9, -l11
    for l in [7, 8, 9, 11] {
        e.extend(line(l, 27, 28));
    }
    for (l, w) in
        [(1, -1), (2, 1), (3, -1), (12, 1), (4, 1), (5, -1), (6, 1), (10, -1), (7, 1), (8, -1), (9, 1), (11, -1)]
    {
        e.push((100, l, w));
    }
    ArchComplex::try_new(2, regions(&regs), e).unwrap()
}

#[test]
fn example_8_22_floor_plan() {
    let x = floor_plan();
    assert_eq!(x.region_counts(), vec![8, 12, 1]);
    let a = x.index_of(RegionId(100)).unwrap();
    assert_eq!(x.components_of(&x.boundary_regions(a)).len(), 3);
    let t = x.topological(ZeroWeightRule::Closed).unwrap();
    // two connecting edges, each joining two parts
    assert_eq!(t.operators.len(), 2);
    assert!(t.operators.iter().all(|o| o.step == Step::ConnectBoundary && o.vector == EpVector::a(2, 1)));
    assert_eq!(betti(&x)[0], 3);
    assert_eq!(betti(&t.complex)[0], 1);
    let y = &t.complex;
    assert_eq!(y.components_of(&y.boundary_regions(y.index_of(RegionId(100)).unwrap())).len(), 1);
}

#[test]
fn gmap_to_complex_keeps_the_cylinder_zeros() {
    let cyl = examples::cylinder();
    let x = ArchComplex::from_map(&cyl).unwrap();
    assert_eq!(x.region_counts(), vec![2, 3, 1]);
    // entries: each of the 3 edges on its vertices, the face on its 3 edges
    let w: Vec<(RegionId, RegionId, i64)> = x.entry_ids();
    let zeros = w.iter().filter(|e| e.2 == 0).count();
    // the two boundary loops on their vertices, and the face on the seam edge
    assert_eq!(zeros, 3);
    assert_eq!(w.len(), 7);
    assert_eq!(betti(&x), vec![1, 1, 0]);
    let back = read_json(&write_json(&x)).unwrap();
    assert_eq!(back, x);
    assert_eq!(betti(&back), vec![1, 1, 0]);
}

#[test]
fn gmap_examples_round_trip_through_json() {
    for (m, b) in [
        (examples::torus(), vec![1, 2, 1]),
        (examples::fig1_curve(), vec![1, 1]),
        (examples::fig1_surface(), vec![1, 0, 0]),
    ] {
        let x = ArchComplex::from_map(&m).unwrap();
        assert_eq!(betti(&x), b);
        let back = read_json(&write_json(&x)).unwrap();
        assert_eq!(betti(&back), b);
        assert_eq!(back.entry_ids(), x.entry_ids());
    }
    // the Klein bottle: H_1 = Z + Z/2 survives the round trip
    let k = ArchComplex::from_map(&examples::klein_bottle()).unwrap();
    let h = read_json(&write_json(&k)).unwrap().homology_z().unwrap();
    assert_eq!(h.betti, vec![1, 1, 0]);
    assert_eq!(h.torsion, vec![vec![], vec![2], vec![]]);
}

#[test]
fn dot_output() {
    let x = ArchComplex::from_map(&examples::cylinder()).unwrap();
    let d = write_dot(&x);
    assert_eq!(d.lines().filter(|l| l.contains("->")).count(), 7);
    assert_eq!(d.lines().filter(|l| l.contains("[label=") && !l.contains("->")).count(), 6);
    assert!(d.starts_with("digraph incidence {"));
}

fn arch_err(text: &str) -> ArchError {
    match read_json(text) {
        Err(JsonError::Arch(e)) => e,
        other => panic!("expected an AC error, got {other:?}"),
    }
}

#[test]
fn reader_rejects_each_violation() {
    let head = r#"{"dimension": 2, "regions": [{"id": 0, "dim": 0}, {"id": 1, "dim": 1}, {"id": 2, "dim": 1}, {"id": 3, "dim": 2}], "incidence": "#;
    let cyc = format!("{head}[{{\"from\": 1, \"to\": 2, \"weight\": 0}}, {{\"from\": 2, \"to\": 1, \"weight\": 0}}]}}");
    assert_eq!(arch_err(&cyc), ArchError::Cycle { cycle: vec![RegionId(1), RegionId(2), RegionId(1)] });
    let up = format!("{head}[{{\"from\": 0, \"to\": 1, \"weight\": 1}}]}}");
    assert_eq!(
        arch_err(&up),
        ArchError::DimensionNotDecreasing { from: RegionId(0), to: RegionId(1), from_dim: 0, to_dim: 1 }
    );
    let same = format!("{head}[{{\"from\": 1, \"to\": 2, \"weight\": 1}}]}}");
    assert!(matches!(arch_err(&same), ArchError::DimensionNotDecreasing { from: RegionId(1), to: RegionId(2), .. }));
    let gap = format!("{head}[{{\"from\": 3, \"to\": 0, \"weight\": 2}}]}}");
    assert_eq!(
        arch_err(&gap),
        ArchError::WeightAcrossGap { from: RegionId(3), to: RegionId(0), from_dim: 2, to_dim: 0, weight: 2 }
    );
    let dup_e =
        format!("{head}[{{\"from\": 1, \"to\": 0, \"weight\": 1}}, {{\"from\": 1, \"to\": 0, \"weight\": 1}}]}}");
    assert_eq!(arch_err(&dup_e), ArchError::DuplicateEntry { from: RegionId(1), to: RegionId(0) });
    let dup_r = r#"{"regions": [{"id": 4, "dim": 0}, {"id": 4, "dim": 1}], "incidence": []}"#;
    assert_eq!(arch_err(dup_r), ArchError::DuplicateRegion { id: RegionId(4) });
    let sq = format!("{head}[{{\"from\": 1, \"to\": 0, \"weight\": 1}}, {{\"from\": 3, \"to\": 1, \"weight\": 1}}]}}");
    assert_eq!(arch_err(&sq), ArchError::SquareNotZero { from: RegionId(3), to: RegionId(0), value: 1 });
    let unknown = format!("{head}[{{\"from\": 9, \"to\": 0, \"weight\": 1}}]}}");
    assert_eq!(
        arch_err(&unknown),
        ArchError::UnknownRegion { from: RegionId(9), to: RegionId(0), missing: RegionId(9) }
    );
    // the message names the reason
    assert!(read_json(&cyc).unwrap_err().to_string().contains("cycle: 1 -> 2 -> 1"));
    // not JSON, or JSON of the wrong shape
    assert!(matches!(read_json("{\"regions\": [}"), Err(JsonError::Syntax { line: 1, .. })));
    let e = read_json(r#"{"regions": [{"id": -1, "dim": 0}], "incidence": []}"#).unwrap_err();
    assert_eq!(e.to_string(), "regions[0].id: expected a non-negative integer, found -1");
    let e = read_json(r#"{"regions": [{"id": 1, "dim": 0}]}"#).unwrap_err();
    assert_eq!(e.to_string(), "incidence: missing");
}

#[test]
fn algorithm_8_16_refuses_when_ids_run_out() {
    // a line without boundary whose id is the largest u64: a base vertex needs a new id
    let x = ArchComplex::try_from_ids(1, &[(u64::MAX, 1)], &[]).unwrap();
    assert_eq!(x.topological(ZeroWeightRule::Closed).unwrap_err(), ArchError::IdsExhausted);
    // one below leaves exactly one id: the vertex gets u64::MAX
    let y = ArchComplex::try_from_ids(1, &[(u64::MAX - 1, 1)], &[]).unwrap();
    let t = y.topological(ZeroWeightRule::Closed).unwrap();
    assert!(t.complex.index_of(RegionId(u64::MAX)).is_some());
}
