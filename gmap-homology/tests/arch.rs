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

/// The wall cycles of AC Example 8.22, as the paper writes ∂A: `(line, weight in ∂A)`,
/// one group per boundary component (the outer wall, court 1, court 2).
const WALLS: [[(u64, i64); 4]; 3] =
    [[(1, -1), (2, 1), (3, -1), (12, 1)], [(4, 1), (5, -1), (6, 1), (10, -1)], [(7, 1), (8, -1), (9, 1), (11, -1)]];

/// AC Example 8.22 (Fig. 11) as a floor plan with two inner courts: the 2-region A (id 100),
/// the lines l1..l12 (ids 1..12) with the paper's ∂A, each boundary component a wall of four
/// lines closed by four corner points (ids 21..32). The paper counts 8 points, which no
/// floor plan with two courts has: three disjoint closed walls of 4 lines each need 12
/// corners (with 8, χ of the space would be 8 - 12 + 1 = -3 instead of a two-holed disk's
/// -1), so the corners here are ours. Each line runs from one corner to the next one in the
/// direction that its sign in ∂A asks for, so that ∂∂A = 0.
fn floor_plan() -> ArchComplex {
    let mut regs = vec![(100u64, 2usize)];
    regs.extend((1..=12).map(|l| (l, 1)));
    regs.extend((21..=32).map(|p| (p, 0)));
    let mut e: Vec<(u64, u64, i64)> = Vec::new();
    for (w, wall) in WALLS.iter().enumerate() {
        let corner = |k: usize| 21 + 4 * w as u64 + (k % 4) as u64;
        for (k, &(l, sign)) in wall.iter().enumerate() {
            // walking the wall, line l goes from corner k to corner k + 1 when its sign is +1
            let (from, to) = if sign > 0 { (corner(k), corner(k + 1)) } else { (corner(k + 1), corner(k)) };
            e.push((l, from, -1));
            e.push((l, to, 1));
            e.push((100, l, sign));
        }
    }
    ArchComplex::try_new(2, regions(&regs), e).unwrap()
}

#[test]
fn example_8_22_floor_plan() {
    let x = floor_plan();
    // the paper's counts: one 2-region, twelve lines, ∂A as printed, three boundary components
    assert_eq!(x.region_counts(), vec![12, 12, 1]);
    let a = x.index_of(RegionId(100)).unwrap();
    let mut boundary: Vec<(u64, i64)> = x.down(a).iter().map(|en| (x.region(en.to).id.0, en.weight)).collect();
    boundary.sort_unstable();
    let mut want: Vec<(u64, i64)> = WALLS.iter().flatten().copied().collect();
    want.sort_unstable();
    assert_eq!(boundary, want);
    assert_eq!(x.components_of(&x.boundary_regions(a)).len(), 3);
    assert_eq!(x.boundary_component_count(a), 3);
    // A is a disk with two courts: the sphere with three holes, by default and as given
    assert_eq!(x.region_betti(a), vec![1, 2, 0]);
    // the complex itself: three separate walls, A bounding their sum
    assert_eq!(betti(&x), vec![3, 2, 0]);
    for y in [x.clone(), x.clone().with_region_betti(RegionId(100), vec![1, 2, 0]).unwrap()] {
        let t = y.topological(ZeroWeightRule::Closed).unwrap();
        // two connecting edges from the outer wall, each joining two parts (X_1 - Y_0)
        assert_eq!(t.operators.len(), 2);
        assert!(t.operators.iter().all(|o| o.step == Step::ConnectBoundary && o.vector == EpVector::a(2, 1)));
        assert!(t.operators.iter().all(|o| o.region == RegionId(100)));
        assert_eq!(t.operators[0].created, vec![RegionId(101)]);
        assert_eq!(t.operators[1].created, vec![RegionId(102)]);
        // the floor with two courts: one component, two loops, no cavity
        assert_eq!(betti(&t.complex), vec![1, 2, 0]);
        assert_eq!(t.complex.homology_z().unwrap().to_string(), "(Z, Z^2, 0)");
        assert_eq!(t.complex.region_counts(), vec![12, 14, 1]);
        assert_eq!(t.complex.euler_characteristic(), -1);
        assert_eq!(t.total().unwrap(), EpVector::a(2, 1).try_add(&EpVector::a(2, 1)).unwrap());
        let b = t.complex.index_of(RegionId(100)).unwrap();
        assert_eq!(t.complex.components_of(&t.complex.boundary_regions(b)).len(), 1);
    }
    // numbers that contradict three boundary circles are refused, the region named
    let e = x.clone().with_region_betti(RegionId(100), vec![1, 1, 0]).unwrap().topological(ZeroWeightRule::Closed);
    assert!(matches!(e, Err(ArchError::RegionTopologyUnknown { id: RegionId(100), dim: 2, boundary: 3, .. })), "{e:?}");
    // a floor of genus 1 with the same three walls: b_1 = 2g + r - 1 = 4, two more loops
    let t = x.with_region_betti(RegionId(100), vec![1, 4, 0]).unwrap().topological(ZeroWeightRule::Closed).unwrap();
    assert_eq!(betti(&t.complex), vec![1, 4, 0]);
    let steps: Vec<Step> = t.operators.iter().map(|o| o.step).collect();
    assert_eq!(steps, [Step::ConnectBoundary, Step::ConnectBoundary, Step::HandleLoop, Step::HandleLoop]);
}

/// A torus as a region (legal under AC Def. 8.1): by default a region without boundary is a
/// sphere, and Algorithm 8.16 says (1, 0, 1); given the torus's Betti numbers it says
/// (1, 2, 1) — never (1, 0, 1) for a region known to be a torus.
#[test]
fn a_torus_region_gets_its_own_betti_numbers() {
    let x = ArchComplex::try_from_ids(2, &[(7, 2)], &[]).unwrap();
    assert_eq!(x.region_betti(0), vec![1, 0, 1]);
    assert!(!x.has_region_betti(0));
    assert_eq!(betti(&x.topological(ZeroWeightRule::Closed).unwrap().complex), vec![1, 0, 1]);
    let torus = x.with_region_betti(RegionId(7), vec![1, 2, 1]).unwrap();
    assert!(torus.has_region_betti(0));
    for rule in [ZeroWeightRule::Closed, ZeroWeightRule::Seam] {
        let t = torus.topological(rule).unwrap();
        assert_eq!(betti(&t.complex), vec![1, 2, 1], "{rule:?}");
        assert_eq!(t.complex.region_counts(), vec![1, 2, 1]);
        let steps: Vec<Step> = t.operators.iter().map(|o| o.step).collect();
        assert_eq!(steps, [Step::BaseVertex, Step::HandleLoop, Step::HandleLoop]);
        // X_0 + Y_0, then X_1 + Y_1 twice: from (0, 0, 1; 0, 0, 1) to (1, 2, 1; 1, 2, 1)
        let before = EpVector::try_new(vec![0, 0, 1], vec![0, 0, 1]).unwrap();
        assert_eq!(
            before.try_add(&t.total().unwrap()).unwrap(),
            EpVector::try_new(vec![1, 2, 1], vec![1, 2, 1]).unwrap()
        );
        // Theorem 8.11: the complex's homology lies in the topological one (b_i ≤ b_i^top)
        assert!(betti(&torus).iter().zip(betti(&t.complex)).all(|(a, b)| *a <= b));
        // the output is a cw-complex: it carries no region topology
        assert!((0..t.complex.regions().len()).all(|r| !t.complex.has_region_betti(r)));
    }
    // genus 2, and a torus touching a point with a zero entry: the loops sit at that point
    let g2 = ArchComplex::try_from_ids(2, &[(7, 2)], &[]).unwrap().with_region_betti(RegionId(7), vec![1, 4, 1]);
    assert_eq!(betti(&g2.unwrap().topological(ZeroWeightRule::Closed).unwrap().complex), vec![1, 4, 1]);
    let touching = ArchComplex::try_from_ids(2, &[(1, 0), (7, 2)], &[(7, 1, 0)]).unwrap();
    let t =
        touching.with_region_betti(RegionId(7), vec![1, 2, 1]).unwrap().topological(ZeroWeightRule::Closed).unwrap();
    assert_eq!(betti(&t.complex), vec![1, 2, 1]);
    assert_eq!(t.complex.region_counts(), vec![1, 2, 1]);
    // a torus with one hole, its boundary a loop wall at a point: (1, 2, 0)
    let holed = ArchComplex::try_from_ids(2, &[(1, 0), (2, 1), (7, 2)], &[(2, 1, 0), (7, 2, 1)]).unwrap();
    assert_eq!(betti(&holed.topological(ZeroWeightRule::Closed).unwrap().complex), vec![1, 0, 0]);
    let t = holed.with_region_betti(RegionId(7), vec![1, 2, 0]).unwrap().topological(ZeroWeightRule::Closed).unwrap();
    assert_eq!(betti(&t.complex), vec![1, 2, 0]);
}

/// What Algorithm 8.16 cannot know it refuses, naming the region; what no region can be
/// is refused when it is given.
#[test]
fn region_topology_refusals_name_the_region() {
    // a solid torus whose boundary is not recorded, and one bounded by a recorded sphere
    let x = ArchComplex::try_from_ids(3, &[(9, 3)], &[]).unwrap().with_region_betti(RegionId(9), vec![1, 1, 0, 0]);
    let e = x.unwrap().topological(ZeroWeightRule::Closed).unwrap_err();
    assert!(matches!(e, ArchError::RegionTopologyUnknown { id: RegionId(9), dim: 3, boundary: 0, .. }), "{e}");
    assert!(
        e.to_string().starts_with("region 9 (3-region with Betti numbers (1, 1, 0, 0) and 0 boundary component(s))"),
        "{e}"
    );
    assert!(e.to_string().contains("Algorithm 8.16 cannot cellulate it"), "{e}");
    let s = ArchComplex::try_from_ids(3, &[(1, 2), (9, 3)], &[(9, 1, 1)]).unwrap();
    assert_eq!(betti(&s.topological(ZeroWeightRule::Closed).unwrap().complex), vec![1, 0, 0, 0]);
    let e = s.with_region_betti(RegionId(9), vec![1, 1, 0, 0]).unwrap().topological(ZeroWeightRule::Closed);
    assert!(matches!(e, Err(ArchError::RegionTopologyUnknown { id: RegionId(9), boundary: 1, .. })), "{e:?}");
    // a closed 3-manifold other than the sphere: not determined by its Betti numbers
    let t3 = ArchComplex::try_from_ids(3, &[(9, 3)], &[]).unwrap().with_region_betti(RegionId(9), vec![1, 3, 3, 1]);
    assert!(t3.unwrap().topological(ZeroWeightRule::Closed).is_err());
    // but a closed 3-sphere or a 3-ball without recorded boundary is fine
    let s3 = ArchComplex::try_from_ids(3, &[(9, 3)], &[]).unwrap();
    let t =
        s3.clone().with_region_betti(RegionId(9), vec![1, 0, 0, 1]).unwrap().topological(ZeroWeightRule::Seam).unwrap();
    assert_eq!(betti(&t.complex), vec![1, 0, 0, 1]);
    let t = s3.with_region_betti(RegionId(9), vec![1, 0, 0, 0]).unwrap().topological(ZeroWeightRule::Closed).unwrap();
    assert_eq!(betti(&t.complex), vec![1, 0, 0, 0]);
    assert_eq!(t.operators[0].step, Step::CompleteSeam);
    // a closed torus glued with a non-zero weight
    let glued = ArchComplex::try_from_ids(2, &[(1, 0), (2, 1), (7, 2)], &[(2, 1, 0), (7, 2, 1)]).unwrap();
    let e = glued.with_region_betti(RegionId(7), vec![1, 2, 1]).unwrap().topological(ZeroWeightRule::Closed);
    assert!(matches!(e, Err(ArchError::RegionTopologyUnknown { id: RegionId(7), .. })), "{e:?}");
    // numbers no region has
    let x = ArchComplex::try_from_ids(2, &[(7, 2)], &[]).unwrap();
    for (b, why) in [
        (vec![1, 2], "one Betti number per dimension"),
        (vec![2, 0, 0], "connected"),
        (vec![1, 0, 2], "b_dim = 1 when closed"),
        (vec![1, 1, 1], "b_1 = 2g"),
    ] {
        let e = x.clone().with_region_betti(RegionId(7), b.clone()).unwrap_err();
        assert!(matches!(&e, ArchError::RegionBetti { id: RegionId(7), dim: 2, betti, .. } if *betti == b), "{e}");
        assert!(e.to_string().contains(why) && e.to_string().ends_with("(AC Def. 8.1)"), "{e}");
    }
    let y = ArchComplex::try_from_ids(3, &[(9, 3)], &[]).unwrap();
    let e = y.with_region_betti(RegionId(9), vec![1, 1, 0, 1]).unwrap_err();
    assert!(e.to_string().contains("Poincaré duality"), "{e}");
    assert!(matches!(x.with_region_betti(RegionId(8), vec![1, 0, 1]), Err(ArchError::UnknownRegion { .. })));
}

#[test]
fn region_betti_numbers_in_json() {
    let text = r#"{"dimension": 2, "regions": [{"id": 7, "dim": 2, "betti": [1, 2, 1]}], "incidence": []}"#;
    let x = read_json(text).unwrap();
    assert_eq!(x.region_betti(0), vec![1, 2, 1]);
    assert_eq!(betti(&x.topological(ZeroWeightRule::Closed).unwrap().complex), vec![1, 2, 1]);
    // written back with its numbers; a region without them is written as before
    let back = write_json(&x);
    assert!(back.contains(r#"{"id": 7, "dim": 2, "betti": [1, 2, 1]}"#), "{back}");
    assert_eq!(read_json(&back).unwrap(), x);
    assert!(!write_json(&floor_plan()).contains("betti"));
    // refusals: numbers no region has, and a malformed field, each with the region or path
    let e = read_json(r#"{"regions": [{"id": 7, "dim": 2, "betti": [1, 1, 1]}], "incidence": []}"#).unwrap_err();
    assert!(matches!(e, JsonError::Arch(ArchError::RegionBetti { id: RegionId(7), .. }, _)), "{e}");
    let e = read_json(r#"{"regions": [{"id": 7, "dim": 2, "betti": "torus"}], "incidence": []}"#).unwrap_err();
    assert_eq!(e.to_string(), r#"regions[0].betti: expected an array of non-negative integers, found "torus""#);
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
        Err(JsonError::Arch(e, _)) => e,
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
    assert_eq!(e.to_string(), "regions[0].id: expected a non-negative integer or a string, found -1");
    let e = read_json(r#"{"regions": [{"id": 18446744073709551616, "dim": 0}], "incidence": []}"#).unwrap_err();
    assert_eq!(e.to_string(), "regions[0].id: 18446744073709551616 does not fit a 64-bit integer");
    let e = read_json(r#"{"regions": [{"id": 0, "dim": 1.5}], "incidence": []}"#).unwrap_err();
    assert_eq!(e.to_string(), "regions[0].dim: expected a non-negative integer, found 1.5");
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

/// AC Example 8.13 (n = 1): `-1 - X^2 = -X_0 - Y_0` removes the vertex of a circle's
/// cw-complex; the Betti numbers change from (1, 1) to (0, 1), the topological ones stay
/// (1, 1), which Algorithm 8.16 recovers.
#[test]
fn example_8_13_removing_the_vertex_of_a_circle() {
    let circle = ArchComplex::try_from_ids(1, &[(1, 0), (2, 1)], &[(2, 1, 0)]).unwrap();
    let line = ArchComplex::try_from_ids(1, &[(2, 1)], &[]).unwrap();
    assert_eq!(betti(&circle), vec![1, 1]);
    assert_eq!(betti(&line), vec![0, 1]);
    let op = EpVector::try_new(vec![-1, 0], vec![-1, 0]).unwrap();
    assert!(op.is_operator());
    assert_eq!(gmap_homology::ep::EpPolynomial::to_poly(&op).coeffs(), &[-1, 0, -1]);
    let conf = |x: &ArchComplex| {
        let c: Vec<i64> = x.region_counts().iter().map(|&c| c as i64).collect();
        EpVector::try_new(c, betti(x).iter().map(|&b| b as i64).collect()).unwrap()
    };
    assert_eq!(conf(&circle).try_add(&op).unwrap(), conf(&line));
    for x in [&circle, &line] {
        assert_eq!(betti(&x.topological(ZeroWeightRule::Closed).unwrap().complex), vec![1, 1]);
    }
    // Remark 8.2: a 1-region is a loop or a segment, nothing else
    assert!(ArchComplex::check_region_betti(1, &[1, 1]).is_ok());
    assert!(ArchComplex::check_region_betti(1, &[1, 0]).is_ok());
    assert!(ArchComplex::check_region_betti(1, &[1, 2]).is_err());
}

/// AC Remark 8.20: `X_{i-1} - Y_i = X^{i-1} (1 - X^{n+2})` is an Euler–Poincaré operator.
#[test]
fn remark_8_20_the_seam_operator() {
    use gmap_homology::ep::{EpPolynomial, Poly};
    for n in 2..=4 {
        for i in 2..=n {
            let v = EpVector::x_unit(n, i - 1).try_add_scaled(-1, &EpVector::y_unit(n, i)).unwrap();
            assert!(v.is_operator(), "n = {n}, i = {i}");
            let mut one_minus = vec![0i64; n + 3];
            one_minus[0] = 1;
            one_minus[n + 2] = -1;
            let want = Poly::monomial(i - 1).try_mul(&Poly::new(one_minus)).unwrap();
            assert_eq!(v.to_poly(), want, "n = {n}, i = {i}");
        }
    }
}

/// AC Lemma 8.14: on the complex of a cw-complex (here the cells of a G-map, AC Remark 3.3)
/// the homology is the topological one: Algorithm 8.16 has nothing to do.
#[test]
fn lemma_8_14_cw_complexes_are_left_alone() {
    for (m, want) in [
        (examples::torus(), vec![1, 2, 1]),
        (examples::cylinder(), vec![1, 1, 0]),
        (examples::klein_bottle(), vec![1, 1, 0]),
    ] {
        let x = ArchComplex::from_map(&m).unwrap();
        let t = x.topological(ZeroWeightRule::Closed).unwrap();
        assert!(t.operators.is_empty());
        assert_eq!(t.complex, x);
        assert_eq!(betti(&x), want);
    }
}
