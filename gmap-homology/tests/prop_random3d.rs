//! Property tests on random 3- and 4-dimensional G-maps.
//!
//! The theorem under test (docs/DESIGN.md, "When cellular homology is right"): where
//! every cell is orientable as a compacted cell (C1) and bounded by a homology sphere (C2),
//! the cellular border operator (BO Def. 10) has the homology of the simplicial counterpart
//! (BO §6) — over Z, Z/2 and Z/3. Where C1 or C2 fails, the cellular method refuses and names
//! a cell that really fails (checked here by an independent 2-colouring or an independent
//! computation of the compacted cell, BO Def. 3), while the simplicial method still answers,
//! with the right groups wherever they are known.
//!
//! Families (each run by a proptest runner that also tallies what it saw, so that no
//! property can pass vacuously):
//!
//! * voxel sets: random subsets of the cubes of a `k_1 × k_2 × k_3` grid (`k ≤ 5`, any axes
//!   periodic), shared faces sewn — holes, cavities and tunnels included; 4-cube grids too;
//! * random gluings: tetrahedra and cubes (4-simplices and 4-cubes) with random facet
//!   pairings by random rotations and reflections; the pieces are balls, so a refusal must
//!   name a folded edge or face (C1), and an acceptance must agree;
//! * random Euler operators (gmap_ops::euler::random) on the solid torus, the 3-torus,
//!   torus × I, lens spaces L(p, q) with p ≥ 3 and the 4-torus: both methods must give the
//!   known groups;
//! * violations: a volume bounded by a closed surface of genus ≥ 1 (C2) or a non-orientable
//!   one (C1) beside a good voxel set, dart numbers shuffled; a volume bounded by a torus
//!   glued to a voxel set along a square (C2; the groups are the voxel set's); 4-cells
//!   bounded by lens spaces, by the 3-torus, by a 3-sphere pinched at two points (the
//!   suspension of a torus: C2 in dimension 4) and by the suspension of the projective plane
//!   (C1 in dimension 4); a boundary facet (a square, or a cube of a 4D voxel set) folded
//!   onto itself by a symmetry: an odd one reverses a cell (C1), an even one keeps every
//!   orientation and is refused as self-bending (BO Def. 6), the facet named; either way
//!   the simplicial groups stay the voxel set's; darts made k-free inside a cell (C1,
//!   incomplete boundary).
//!
//! Every map the cellular method accepts is also checked against BO §6: the chain map τ from
//! cellular to simplicial chains commutes with the border operators (`c∂ᶜτ = cτ∂ˢ`).
//!
//! Run with `--nocapture` to see the tallies (acceptance rates, groups met).

use std::cell::RefCell;
use std::collections::{BTreeMap, HashMap};

use gmap_core::{AlphaSet, BoundaryDefect, CellDefect, Dart, DenseMap, GMap};
use gmap_homology::border::border_from_oriented;
use gmap_homology::{
    cellular_complex, chain_map_tau, check_by_dimension, check_preconditions, homology_z, homology_zp,
    simplicial_complex, ChainComplex, Homology, PreconditionError,
};
use gmap_ops::build;
use gmap_ops::euler::ops;
use gmap_ops::euler::random::{random_steps, Operator};
use gmap_ops::import::SimplicialComplex;
use gmap_ops::rng::SplitMix64;
use proptest::prelude::*;
use proptest::test_runner::{Config, RngAlgorithm, TestCaseError, TestRng, TestRunner};

// ---------------------------------------------------------------------------------------
// small tools

/// Counters of what a family generated, shared by the cases of one runner.
#[derive(Default)]
struct Tally(RefCell<BTreeMap<String, usize>>);

impl Tally {
    fn add(&self, key: impl Into<String>) {
        *self.0.borrow_mut().entry(key.into()).or_default() += 1;
    }

    fn get(&self, key: &str) -> usize {
        self.0.borrow().get(key).copied().unwrap_or(0)
    }

    fn report(&self, family: &str) {
        eprintln!("{family}: {:?}", self.0.borrow());
    }
}

/// Runs `test` on `cases` values of `strategy`; panics with proptest's (shrunk) failure.
/// Runs `test` on `cases` values of `strategy` drawn from a fixed seed: the tests below also
/// assert how many cases reached each verdict, which must not depend on the luck of a run.
fn run<S: Strategy>(cases: u32, strategy: S, test: impl Fn(S::Value) -> Result<(), TestCaseError>) {
    let config = Config { cases, failure_persistence: None, ..Config::default() };
    let mut runner = TestRunner::new_with_rng(config, TestRng::deterministic_rng(RngAlgorithm::ChaCha));
    if let Err(e) = runner.run(&strategy, test) {
        panic!("{e}");
    }
}

fn fail(e: impl std::fmt::Display) -> TestCaseError {
    TestCaseError::fail(e.to_string())
}

/// The darts with `keep[d]`, renumbered in order; links to dropped darts become free.
fn restrict(m: &DenseMap, keep: &[bool]) -> DenseMap {
    let n = m.dim();
    let mut new = vec![u32::MAX; m.dart_count()];
    let mut count = 0u32;
    for d in 0..m.dart_count() {
        if keep[d] {
            new[d] = count;
            count += 1;
        }
    }
    let mut flat = Vec::with_capacity(count as usize * (n + 1));
    for d in m.darts() {
        if !keep[d.index()] {
            continue;
        }
        for i in 0..=n {
            let y = m.alpha(d, i);
            flat.push(if keep[y.index()] { new[y.index()] } else { new[d.index()] });
        }
    }
    DenseMap::try_from_flat(n, flat).expect("dropping whole n-cells keeps a G-map")
}

/// The disjoint union of two maps of one dimension: the darts of `b` follow those of `a`.
fn union(a: &DenseMap, b: &DenseMap) -> DenseMap {
    assert_eq!(a.dim(), b.dim());
    let off = a.dart_count() as u32;
    let mut flat = a.flat().to_vec();
    flat.extend(b.flat().iter().map(|&x| x + off));
    DenseMap::try_from_flat(a.dim(), flat).expect("a union of G-maps is a G-map")
}

/// A random renumbering of the darts.
fn shuffled(m: &DenseMap, rng: &mut SplitMix64) -> (DenseMap, Vec<u32>) {
    let mut perm: Vec<u32> = (0..m.dart_count() as u32).collect();
    rng.shuffle(&mut perm);
    (m.permuted(&perm), perm)
}

/// The isomorphism of the `set`-orbit of `d0` onto that of `e0` sending `d0` to `e0`
/// (pairs `(x, image)`), if the two orbits are isomorphic that way.
fn orbit_iso(m: &DenseMap, d0: Dart, e0: Dart, set: &[usize]) -> Option<Vec<(u32, u32)>> {
    let mut img: HashMap<u32, u32> = HashMap::new();
    img.insert(d0.get(), e0.get());
    let mut stack = vec![d0.get()];
    while let Some(x) = stack.pop() {
        let fx = img[&x];
        for &k in set {
            let y = m.alpha(Dart::new(x), k).get();
            let z = m.alpha(Dart::new(fx), k).get();
            match img.get(&y) {
                Some(&w) if w != z => return None,
                Some(_) => {}
                None => {
                    img.insert(y, z);
                    stack.push(y);
                }
            }
        }
    }
    let mut pairs: Vec<(u32, u32)> = img.into_iter().collect();
    pairs.sort_unstable();
    let mut images: Vec<u32> = pairs.iter().map(|p| p.1).collect();
    images.sort_unstable();
    images.dedup();
    (images.len() == pairs.len()).then_some(pairs)
}

// ---------------------------------------------------------------------------------------
// independent checks of a refusal

/// C1 for the i-cell of `dart`, by a breadth-first 2-colouring written here (not the
/// kernel's): `Err("free")` for a dart k-free with k < i, `Err("conflict")` for a colouring
/// conflict.
fn own_c1(m: &DenseMap, i: usize, dart: u32) -> Result<(), &'static str> {
    let n = m.dim();
    let mut colour: HashMap<u32, bool> = HashMap::new();
    colour.insert(dart, true);
    let mut queue = std::collections::VecDeque::from([dart]);
    while let Some(x) = queue.pop_front() {
        let c = colour[&x];
        for k in (0..=n).filter(|&k| k != i) {
            let y = m.alpha(Dart::new(x), k).get();
            if k < i && y == x {
                return Err("free");
            }
            let want = if k < i { !c } else { c };
            match colour.get(&y) {
                Some(&got) if got != want => return Err("conflict"),
                Some(_) => {}
                None => {
                    colour.insert(y, want);
                    queue.push_back(y);
                }
            }
        }
    }
    Ok(())
}

/// The compacted i-cell of `dart` (BO Def. 3), built here: its elements are the
/// `<alpha_{i+1}..alpha_n>`-orbits inside the cell, `alpha_k` (k < i) acting on them.
fn own_compacted(m: &DenseMap, i: usize, dart: u32) -> DenseMap {
    let n = m.dim();
    let cell = m.orbit(Dart::new(dart), AlphaSet::cell(i, n));
    let b = m.partition(AlphaSet::above(i, n));
    let mut local: HashMap<u32, u32> = HashMap::new();
    let mut reps = Vec::new();
    for d in &cell {
        let e = b.of[d.index()];
        if let std::collections::hash_map::Entry::Vacant(v) = local.entry(e) {
            v.insert(reps.len() as u32);
            reps.push(*d);
        }
    }
    let mut flat = Vec::with_capacity(reps.len() * i);
    for &r in &reps {
        for k in 0..i {
            flat.push(local[&b.of[m.alpha(r, k).index()]]);
        }
    }
    DenseMap::try_from_flat(i - 1, flat).expect("alpha_k, k < i, is well defined on the orbits")
}

/// `(Z, 0, …, 0, Z)`: the integer homology of the m-sphere, as printed.
fn sphere_string(m: usize) -> String {
    let mut parts = vec!["Z".to_string()];
    parts.extend((1..m).map(|_| "0".to_string()));
    parts.push("Z".to_string());
    format!("({})", parts.join(", "))
}

/// Checks that the cell a refusal names really fails the condition it is refused for.
/// Returns the dimension and smallest dart of the cell named.
fn check_refusal(m: &DenseMap, e: &PreconditionError) -> Result<(usize, u32), TestCaseError> {
    match e {
        PreconditionError::C1(CellDefect::IncompleteBoundary { dim, dart, alpha }) => {
            prop_assert!(alpha < dim, "{e}");
            let cell = m.orbit(*dart, AlphaSet::cell(*dim, m.dim()));
            prop_assert!(cell.iter().any(|&x| m.is_free(x, *alpha)), "no {alpha}-free dart in the cell named: {e}");
            prop_assert_eq!(own_c1(m, *dim, dart.get()), Err("free"));
            Ok((*dim, dart.get()))
        }
        PreconditionError::C1(CellDefect::NotOrientable { dim, dart, .. }) => {
            prop_assert_eq!(own_c1(m, *dim, dart.get()), Err("conflict"), "{}", e);
            Ok((*dim, dart.get()))
        }
        PreconditionError::C2 { dim, dart, .. } => {
            prop_assert!(*dim >= 3, "{e}");
            prop_assert_eq!(own_c1(m, *dim, dart.get()), Ok(()), "C2 is checked after C1: {}", e);
            let b = own_compacted(m, *dim, dart.get());
            let h = homology_z(&simplicial_complex(&b)).map_err(fail)?;
            prop_assert_ne!(h.to_string(), sphere_string(dim - 1), "the cell named is bounded by a sphere: {}", e);
            Ok((*dim, dart.get()))
        }
        PreconditionError::SelfBending(BoundaryDefect::SelfBending { dart, i, other, cell }) => {
            // BO Def. 6, walked here: both orbits of `dart` hold `other`, and the cell named
            // is the i-cell of both darts, with C1 holding on it (self-bending is checked last)
            let n = m.dim();
            prop_assert_ne!(dart, other);
            let up = m.orbit(*dart, AlphaSet::above(*i, n));
            let down = m.orbit(*dart, AlphaSet::below(*i));
            prop_assert!(up.contains(other) && down.contains(other), "{}", e);
            let c = m.orbit(*cell, AlphaSet::cell(*i, n));
            prop_assert!(c.contains(dart) && c.iter().min() == Some(cell), "{}", e);
            prop_assert_eq!(own_c1(m, *i, cell.get()), Ok(()), "self-bending is checked after C1: {}", e);
            Ok((*i, cell.get()))
        }
        PreconditionError::SelfBending(other) => Err(fail(format!("not a self-bending: {other}"))),
        other => Err(fail(format!("a refusal this test does not know: {other}"))),
    }
}

// ---------------------------------------------------------------------------------------
// the theorem

/// Homology of one complex over Z, Z/2 and Z/3, checked against Euler–Poincaré and the
/// universal coefficient theorem (dim H_k(Z/p) = b_k + #p-torsion of H_k and of H_{k-1}).
#[derive(Clone, Debug, PartialEq, Eq)]
struct Groups {
    z: Homology,
    z2: Homology,
    z3: Homology,
}

fn groups(c: &ChainComplex) -> Result<Groups, TestCaseError> {
    let z = homology_z(c).map_err(fail)?;
    let z2 = homology_zp(c, 2).map_err(fail)?;
    let z3 = homology_zp(c, 3).map_err(fail)?;
    prop_assert_eq!(z.euler_characteristic(), c.euler_characteristic(), "Euler–Poincaré over Z");
    for (p, h) in [(2u64, &z2), (3, &z3)] {
        prop_assert_eq!(h.euler_characteristic(), c.euler_characteristic(), "Euler–Poincaré over Z/{}", p);
        let tors = |k: usize| z.torsion[k].iter().filter(|t| t.is_multiple_of(p)).count();
        for k in 0..z.betti.len() {
            let want = z.betti[k] + tors(k) + if k > 0 { tors(k - 1) } else { 0 };
            prop_assert_eq!(h.betti[k], want, "universal coefficients, H_{} over Z/{}: Z gives {}", k, p, z);
        }
    }
    Ok(Groups { z, z2, z3 })
}

/// The groups with one more component (a contractible one).
fn plus_point(g: &Groups) -> Groups {
    let mut g = g.clone();
    for h in [&mut g.z, &mut g.z2, &mut g.z3] {
        h.betti[0] += 1;
    }
    g
}

/// What the cellular method said about a map, and the simplicial groups.
enum Verdict {
    Accepted(Groups),
    Refused { error: PreconditionError, dim: usize, dart: u32, simplicial: Groups },
}

/// The simplicial groups (∂∂ = 0, H_0 = components); if the cellular method accepts, ∂∂ = 0,
/// its χ is the map's and its groups are the simplicial ones over Z, Z/2, Z/3; if it
/// refuses, the cell it names really fails.
fn judge(m: &DenseMap) -> Result<Verdict, TestCaseError> {
    prop_assert_eq!(m.validate(), Ok(()));
    let s = simplicial_complex(m);
    prop_assert_eq!(s.check_dd(), Ok(()));
    let hs = groups(&s)?;
    prop_assert_eq!(hs.z.betti[0], m.component_count());
    // the ring walks of 3-maps give the cells, colours and error of the per-dimension check
    prop_assert_eq!(check_preconditions(m), check_by_dimension(m));
    // the two phases of 3-maps give the complex (or the error) of all dimensions at once
    let whole = check_by_dimension(m).map(|o| border_from_oriented(m, &o));
    let staged = cellular_complex(m);
    prop_assert_eq!(staged.as_ref().map(|c| (&c.chain, &c.reps)), whole.as_ref().map(|c| (&c.chain, &c.reps)));
    match staged {
        Ok(c) => {
            prop_assert_eq!(c.chain.check_dd(), Ok(()));
            prop_assert_eq!(c.chain.euler_characteristic(), m.euler_characteristic());
            let hc = groups(&c.chain)?;
            prop_assert_eq!(&hc, &hs, "cellular (left) and simplicial (right) differ");
            // BO §6: the chain map τ commutes with the border operators
            let tau = chain_map_tau(m).map_err(fail)?;
            prop_assert_eq!(tau.check_commutes(), Ok(()));
            Ok(Verdict::Accepted(hs))
        }
        Err(error) => {
            let (dim, dart) = check_refusal(m, &error)?;
            Ok(Verdict::Refused { error, dim, dart, simplicial: hs })
        }
    }
}

// ---------------------------------------------------------------------------------------
// family (a): voxel sets

/// The cubes of a grid with `keep[c]` (cube `c` numbered as [`build::grid`] does, axis 0
/// fastest), shared facets sewn.
fn voxels(sizes: &[usize], periodic: &[bool], keep: &[bool]) -> DenseMap {
    let g = build::grid(sizes, periodic).expect("small grid");
    let cubes: usize = sizes.iter().product();
    let per = g.dart_count() / cubes;
    let keep_dart: Vec<bool> = (0..g.dart_count()).map(|d| keep[d / per]).collect();
    restrict(&g, &keep_dart)
}

/// Grid sizes in `1..=max`, periodicity flags and a mask of cubes of density 0.5, 0.8 or
/// 0.95 (so that cavities and tunnels show up), never empty.
fn voxel_params(dim: usize, max: usize) -> impl Strategy<Value = (Vec<usize>, Vec<bool>, Vec<bool>)> {
    (prop::collection::vec(1..=max, dim), prop::collection::vec(any::<bool>(), dim), 0usize..3).prop_flat_map(
        |(sizes, periodic, density)| {
            let cubes: usize = sizes.iter().product();
            let p = [0.5, 0.8, 0.95][density];
            (Just(sizes), Just(periodic), prop::collection::vec(prop::bool::weighted(p), cubes)).prop_map(
                |(s, per, mut keep)| {
                    if !keep.contains(&true) {
                        keep[0] = true;
                    }
                    (s, per, keep)
                },
            )
        },
    )
}

#[test]
fn voxel_sets_3d_cellular_equals_simplicial() {
    let tally = Tally::default();
    run(64, voxel_params(3, 5), |(sizes, periodic, keep)| {
        let m = voxels(&sizes, &periodic, &keep);
        match judge(&m)? {
            Verdict::Accepted(h) => {
                tally.add("accepted");
                if h.z.betti[1] > 0 {
                    tally.add("H1 != 0");
                }
                if h.z.betti[2] > 0 {
                    tally.add("H2 != 0");
                }
                if h.z.betti[0] > 1 {
                    tally.add("H0 > Z");
                }
            }
            Verdict::Refused { error, .. } => return Err(fail(format!("a voxel set meets C1 and C2: {error}"))),
        }
        Ok(())
    });
    tally.report("voxels 3D");
    assert_eq!(tally.get("accepted"), 64);
    assert!(tally.get("H1 != 0") >= 8, "too few tunnels");
    assert!(tally.get("H2 != 0") >= 4, "too few cavities");
}

#[test]
fn voxel_sets_4d_cellular_equals_simplicial() {
    let tally = Tally::default();
    run(12, voxel_params(4, 2), |(sizes, periodic, keep)| {
        let m = voxels(&sizes, &periodic, &keep);
        match judge(&m)? {
            Verdict::Accepted(h) => {
                tally.add("accepted");
                if h.z.betti.iter().skip(1).any(|&b| b > 0) {
                    tally.add("H_k != 0 for some k > 0");
                }
            }
            Verdict::Refused { error, .. } => return Err(fail(format!("a voxel set meets C1 and C2: {error}"))),
        }
        Ok(())
    });
    tally.report("voxels 4D");
    assert_eq!(tally.get("accepted"), 12);
}

// ---------------------------------------------------------------------------------------
// family (b): random gluings

/// Pieces (`true`: an n-cube, `false`: an n-simplex) whose facets are paired at random
/// (a facet with one of the same shape) by a random isomorphism of the facets (a rotation
/// or a reflection), sewn with `alpha_n`; about one facet in `free_one_in` stays free.
fn glued(n: usize, cubes: &[bool], free_one_in: usize, seed: u64) -> DenseMap {
    let mut rng = SplitMix64::new(seed);
    let mut m = DenseMap::new(n, 0);
    for &c in cubes {
        let piece = if c { build::cube(n) } else { build::simplex(n) }.expect("small piece");
        m = union(&m, &piece);
    }
    let p = m.partition(AlphaSet::below(n - 1));
    let mut darts_of: Vec<Vec<u32>> = vec![Vec::new(); p.len()];
    for d in 0..m.dart_count() {
        darts_of[p.of[d] as usize].push(d as u32);
    }
    let mut order: Vec<usize> = (0..p.len()).collect();
    rng.shuffle(&mut order);
    let mut used = vec![false; p.len()];
    let facet_alphas: Vec<usize> = (0..n - 1).collect();
    for a in 0..order.len() {
        let f = order[a];
        if used[f] || rng.below(free_one_in) == 0 {
            continue;
        }
        let Some(&g) = order[a + 1..].iter().find(|&&g| !used[g] && darts_of[g].len() == darts_of[f].len()) else {
            continue;
        };
        let e0 = darts_of[g][rng.below(darts_of[g].len())];
        let Some(pairs) = orbit_iso(&m, Dart::new(darts_of[f][0]), Dart::new(e0), &facet_alphas) else {
            continue; // a square onto a triangle's flags cannot happen (same size), but stay safe
        };
        for (x, y) in pairs {
            m.link(Dart::new(x), Dart::new(y), n);
        }
        used[f] = true;
        used[g] = true;
    }
    m
}

fn gluing_family(
    n: usize,
    cases: u32,
    pieces: std::ops::RangeInclusive<usize>,
    cube_weight: f64,
    free_one_in: std::ops::Range<usize>,
) -> Tally {
    let tally = Tally::default();
    let strategy = (prop::collection::vec(prop::bool::weighted(cube_weight), pieces), free_one_in, any::<u64>());
    run(cases, strategy, |(cubes, free_one_in, seed)| {
        let m = glued(n, &cubes, free_one_in, seed);
        match judge(&m)? {
            Verdict::Accepted(h) => {
                tally.add("accepted");
                if h.z.torsion.iter().any(|t| !t.is_empty()) {
                    tally.add("torsion");
                }
                if h.z.betti.iter().skip(1).any(|&b| b > 0) {
                    tally.add("H_k != 0 for some k > 0");
                }
            }
            Verdict::Refused { error, dim, .. } => {
                // the pieces' own cells are balls: only folded or open lower cells can fail
                prop_assert!(
                    matches!(error, PreconditionError::C1(_) | PreconditionError::SelfBending(_)),
                    "{}",
                    error
                );
                prop_assert!(dim < n, "{}", error);
                tally.add(if dim == 1 { "refused: folded edge" } else { "refused: folded face" });
            }
        }
        Ok(())
    });
    tally
}

#[test]
fn random_gluings_of_tetrahedra_and_cubes() {
    let tally = gluing_family(3, 128, 1..=6, 0.4, 3..10);
    tally.report("gluings 3D");
    let acc = tally.get("accepted");
    assert!(acc >= 24, "too few accepted gluings: {acc} of 128");
    assert!(acc <= 120, "too few refused gluings: {} of 128", 128 - acc);
}

#[test]
fn random_gluings_of_4_simplices() {
    let tally = gluing_family(4, 48, 1..=3, 0.3, 2..3);
    tally.report("gluings 4D");
    assert!(tally.get("accepted") >= 2, "too few accepted gluings");
}

// ---------------------------------------------------------------------------------------
// family (c): Euler operators on classic objects

/// The operators of the classic-object family, removals drawn twice as often as the others.
const CLASSIC_OPERATORS: [Operator; 6] = [
    Operator::InsertVertex,
    Operator::InsertEdge,
    Operator::InsertDanglingEdge,
    Operator::RemoveCell,
    Operator::RemoveCell,
    Operator::ContractCell,
];

/// A classic closed or bounded object and its integer homology.
fn classic(kind: usize, a: usize, b: usize, c: usize) -> (DenseMap, String, &'static str) {
    match kind {
        0 => (build::solid_torus(a).unwrap(), "(Z, Z, 0, 0)".into(), "solid torus"),
        1 => (build::grid(&[a, b, c], &[true; 3]).unwrap(), "(Z, Z^3, Z^3, Z)".into(), "3-torus"),
        2 => {
            let p = a + b + c; // 3..=6
            let q = (1..p).filter(|q| gcd(*q, p) == 1).nth(c % 2).unwrap_or(1);
            (build::lens_space(p, q).unwrap(), format!("(Z, Z/{p}, 0, Z)"), "lens space")
        }
        // L(1, 0) and L(2, 1): see `removing_the_loop_edge_of_l1_and_l2_keeps_the_space`
        3 => (build::grid(&[a, b, c], &[true, true, false]).unwrap(), "(Z, Z^2, Z, 0)".into(), "torus × I"),
        _ => {
            let sizes = [1, 1, a.min(2), b.min(2)];
            (build::grid(&sizes, &[true; 4]).unwrap(), "(Z, Z^4, Z^6, Z^4, Z)".into(), "4-torus")
        }
    }
}

fn gcd(a: usize, b: usize) -> usize {
    if b == 0 {
        a
    } else {
        gcd(b, a % b)
    }
}

#[test]
fn euler_operators_on_classic_objects_keep_the_groups() {
    let tally = Tally::default();
    let strategy = ((0usize..5), 1usize..=2, 1usize..=2, 1usize..=2, 0usize..24, any::<u64>());
    run(64, strategy, |(kind, a, b, c, steps, seed)| {
        let (base, want, name) = classic(kind, a, b, c);
        match judge(&base)? {
            Verdict::Accepted(h) => prop_assert_eq!(h.z.to_string(), want.clone(), "{}", name),
            Verdict::Refused { error, .. } => return Err(fail(format!("{name}: base object refused: {error}"))),
        }
        let (mut g, _) = GMap::from_dense(&base);
        let mut rng = SplitMix64::new(seed);
        let applied = random_steps(&mut g, steps, &CLASSIC_OPERATORS, &mut rng);
        let (m, _) = g.to_dense_with_ids();
        match judge(&m)? {
            Verdict::Accepted(h) => {
                prop_assert_eq!(h.z.to_string(), want.clone(), "{} after {:?}", name, applied);
                tally.add("accepted");
            }
            Verdict::Refused { error, simplicial, .. } => {
                prop_assert_eq!(simplicial.z.to_string(), want.clone(), "{} after {:?}", name, applied);
                eprintln!("{name} after {applied:?}: refused: {error}");
                tally.add("refused");
            }
        }
        for op in &applied {
            tally.add(format!("op {op}"));
        }
        if !applied.is_empty() {
            tally.add("changed");
        }
        if m.cell_counts() != base.cell_counts() {
            tally.add("cells changed");
        }
        Ok(())
    });
    tally.report("Euler operators");
    assert!(tally.get("changed") >= 32, "too few operators applied");
    assert!(tally.get("accepted") >= 48, "Euler operators should keep C1 and C2");
}

// ---------------------------------------------------------------------------------------
// violations

/// A closed surface from a schema word (orientable of genus `g`, or the connected sum of
/// `g` projective planes), subdivided by random edge and face splits, as a 3-map with
/// `alpha_3` the identity: one volume bounded by the surface — the cone on it, contractible.
fn coned_surface(orientable: bool, g: usize, steps: usize, rng: &mut SplitMix64) -> DenseMap {
    let word = if orientable { build::orientable_surface_word(g) } else { build::nonorientable_surface_word(g) };
    let s = build::schema(&word).unwrap();
    let (mut gm, _) = GMap::from_dense(&s);
    random_steps(&mut gm, steps, &[Operator::InsertVertex, Operator::InsertEdge], rng);
    gm.to_dense_map().embedded(3).unwrap()
}

#[test]
fn volumes_bounded_by_surfaces_of_genus_at_least_one_are_refused() {
    let tally = Tally::default();
    let strategy = (any::<bool>(), 0usize..=3, 0usize..8, voxel_params(3, 3), any::<u64>());
    run(64, strategy, |(orientable, g, steps, (sizes, periodic, keep), seed)| {
        let mut rng = SplitMix64::new(seed);
        let good = voxels(&sizes, &periodic, &keep);
        let hgood = groups(&simplicial_complex(&good))?;
        let cone = coned_surface(orientable, g, steps, &mut rng);
        let cone_first = rng.below(2) == 0;
        let joined = if cone_first { union(&cone, &good) } else { union(&good, &cone) };
        let cone_start = if cone_first { 0 } else { good.dart_count() };
        let (m, perm) = shuffled(&joined, &mut rng);
        let cone_darts: Vec<u32> = (cone_start..cone_start + cone.dart_count()).map(|d| perm[d]).collect();
        let cone_min = *cone_darts.iter().min().unwrap();
        let want = plus_point(&hgood);
        match judge(&m)? {
            Verdict::Accepted(h) => {
                prop_assert_eq!(g, 0, "a volume bounded by a surface of genus {} was accepted", g);
                prop_assert_eq!(&h, &want);
                tally.add("accepted: ball");
            }
            Verdict::Refused { error, dim, dart, simplicial } => {
                prop_assert!(g > 0, "a ball was refused: {}", error);
                prop_assert_eq!(dim, 3);
                prop_assert_eq!(dart, cone_min, "the cell named is not the cone: {}", error);
                if orientable {
                    let chi = 2 - 2 * g as i64;
                    match &error {
                        PreconditionError::C2 { found, .. } => {
                            prop_assert!(found.contains(&chi.to_string()), "χ = {} not in {}", chi, found)
                        }
                        other => return Err(fail(format!("expected C2, got {other}"))),
                    }
                    tally.add("refused: C2");
                } else {
                    prop_assert!(matches!(error, PreconditionError::C1(CellDefect::NotOrientable { .. })), "{}", error);
                    tally.add("refused: C1 non-orientable");
                }
                prop_assert_eq!(&simplicial, &want, "the cone is contractible");
            }
        }
        Ok(())
    });
    tally.report("coned surfaces");
    assert!(tally.get("refused: C2") >= 8);
    assert!(tally.get("refused: C1 non-orientable") >= 8);
    assert!(tally.get("accepted: ball") >= 3);
}

#[test]
fn volume_bounded_by_a_torus_glued_to_a_voxel_set_is_refused() {
    let tally = Tally::default();
    let strategy = (2usize..=3, 2usize..=3, voxel_params(3, 3), any::<u64>());
    run(48, strategy, |(k1, k2, (sizes, mut periodic, keep), seed)| {
        periodic[0] = false; // a boundary face always exists
        let mut rng = SplitMix64::new(seed);
        let good = voxels(&sizes, &periodic, &keep);
        let hgood = groups(&simplicial_complex(&good))?;
        // one volume bounded by a torus of k1 × k2 squares: the cone on the torus
        let cone = build::grid(&[k1, k2], &[true, true]).unwrap().embedded(3).unwrap();
        let m = union(&good, &cone);
        let off = good.dart_count() as u32;
        let free: Vec<Dart> = good.darts().filter(|&d| good.is_free(d, 3)).collect();
        let q = free[rng.below(free.len())];
        let f = Dart::new(off + rng.below(cone.dart_count()) as u32);
        let q_face = m.orbit(q, AlphaSet::of(&[0, 1]));
        let f_face = m.orbit(f, AlphaSet::of(&[0, 1]));
        prop_assert_eq!((q_face.len(), f_face.len()), (8, 8));
        // glue a square of the torus onto the boundary square by any of its 8 symmetries
        let e0 = f_face[rng.below(8)];
        let pairs = orbit_iso(&m, q, e0, &[0, 1]).expect("two squares");
        let mut m = m;
        for (x, y) in pairs {
            m.link(Dart::new(x), Dart::new(y), 3);
        }
        let embedded = facet_embedded(&good, &q_face)
            && facet_embedded(&cone, &cone.orbit(Dart::new(f.get() - off), AlphaSet::of(&[0, 1])));
        let (m, perm) = shuffled(&m, &mut rng);
        let cone_min = (off..off + cone.dart_count() as u32).map(|d| perm[d as usize]).min().unwrap();
        match judge(&m)? {
            Verdict::Accepted(_) => return Err(fail("a volume bounded by a torus was accepted")),
            Verdict::Refused { error, dim, dart, simplicial } => {
                match &error {
                    PreconditionError::C2 { found, .. } => prop_assert!(found.contains('0'), "χ = 0 not in {}", found),
                    other => return Err(fail(format!("expected C2, got {other}"))),
                }
                prop_assert_eq!((dim, dart), (3, cone_min), "{}", error);
                if embedded {
                    // M ∪ cone(T) along an embedded disc: the cone is contractible
                    prop_assert_eq!(&simplicial, &hgood);
                    tally.add("known groups");
                }
                tally.add("refused: C2");
            }
        }
        Ok(())
    });
    tally.report("torus-bounded volume glued");
    assert_eq!(tally.get("refused: C2"), 48);
    assert!(tally.get("known groups") >= 16);
}

#[test]
fn four_cells_bounded_by_lens_spaces_and_3_tori_are_refused() {
    let tally = Tally::default();
    let strategy = (1usize..=5, 1usize..5, any::<bool>(), 1usize..=2, any::<u64>());
    run(24, strategy, |(p, q, torus, a, seed)| {
        let mut rng = SplitMix64::new(seed);
        let (boundary, is_sphere) = if torus {
            (build::grid(&[a, 1, 1], &[true; 3]).unwrap(), false)
        } else {
            let q = if gcd(q % p, p) == 1 { q % p } else { 1 };
            (build::lens_space(p, q).unwrap(), p == 1)
        };
        let (m, _) = shuffled(&boundary.embedded(4).unwrap(), &mut rng);
        let ball = "(Z, 0, 0, 0, 0)";
        match judge(&m)? {
            Verdict::Accepted(h) => {
                prop_assert!(is_sphere, "a 4-cell with a non-sphere boundary was accepted");
                prop_assert_eq!(h.z.to_string(), ball);
                tally.add("accepted: bounded by S^3");
            }
            Verdict::Refused { error, dim, dart, simplicial } => {
                prop_assert!(!is_sphere, "{}", error);
                prop_assert!(matches!(error, PreconditionError::C2 { dim: 4, .. }), "{}", error);
                prop_assert_eq!((dim, dart), (4, 0));
                prop_assert_eq!(simplicial.z.to_string(), ball);
                tally.add("refused: C2 in dimension 4");
            }
        }
        Ok(())
    });
    tally.report("4-cells");
    assert!(tally.get("refused: C2 in dimension 4") >= 10);
}

/// Triangles of three closed surfaces: the boundary of a tetrahedron (S²), the 7-vertex
/// torus and the 6-vertex projective plane, with their integer homology.
fn surface_triangles(which: usize) -> (Vec<[u64; 3]>, &'static str) {
    match which {
        0 => (vec![[0, 1, 2], [0, 1, 3], [0, 2, 3], [1, 2, 3]], "(Z, 0, Z)"),
        1 => {
            let t = (0..7u64).flat_map(|i| [[i, (i + 1) % 7, (i + 3) % 7], [i, (i + 2) % 7, (i + 3) % 7]]).collect();
            (t, "(Z, Z^2, Z)")
        }
        _ => {
            let t = vec![
                [1, 2, 3],
                [1, 3, 4],
                [1, 4, 5],
                [1, 5, 6],
                [1, 6, 2],
                [2, 3, 5],
                [3, 4, 6],
                [4, 5, 2],
                [5, 6, 3],
                [6, 2, 4],
            ];
            (t, "(Z, Z/2, 0)")
        }
    }
}

#[test]
fn four_cells_bounded_by_suspensions_are_refused() {
    // The suspension of a surface, triangulated (two cone points, 10 and 11), is a 3-sphere
    // only for S²: for the torus it is a 3-sphere pinched at two points whose links are
    // tori, homology (Z, 0, Z^2, Z), so a 4-cell bounded by it fails C2; for the projective
    // plane it is not orientable, so the 4-cell fails C1. (A 2-map cannot pinch a sphere: a
    // vertex of a 2-map is one cycle of corners, so such a vertex splits in two.)
    let tally = Tally::default();
    let strategy = (0usize..3, any::<bool>(), any::<u64>());
    run(24, strategy, |(which, with_good, seed)| {
        let mut rng = SplitMix64::new(seed);
        let (triangles, h_surface) = surface_triangles(which);
        let surface = SimplicialComplex::from_facets(triangles.iter().map(|t| t.to_vec())).unwrap();
        let surface = surface.to_gmap(10_000).unwrap();
        prop_assert_eq!(homology_z(&simplicial_complex(&surface)).unwrap().to_string(), h_surface);
        let facets = triangles.iter().flat_map(|t| [10, 11].map(|apex| vec![apex, t[0], t[1], t[2]]));
        let suspension = SimplicialComplex::from_facets(facets).unwrap().to_gmap(100_000).unwrap();
        let cell = suspension.embedded(4).unwrap();
        let good = voxels(&[1, 1, 1, 2], &[false, false, false, true], &[true, true]);
        let (joined, cell_start, want_h0) =
            if with_good { (union(&good, &cell), good.dart_count(), 2) } else { (cell.clone(), 0, 1) };
        let (m, perm) = shuffled(&joined, &mut rng);
        let cell_min = (cell_start..cell_start + cell.dart_count()).map(|d| perm[d]).min().unwrap();
        match judge(&m)? {
            Verdict::Accepted(h) => {
                prop_assert_eq!(which, 0, "a 4-cell bounded by a suspension of {} was accepted", h_surface);
                prop_assert_eq!(h.z.betti[0], want_h0);
                tally.add("accepted: bounded by S^3");
            }
            Verdict::Refused { error, dim, dart, simplicial } => {
                prop_assert_eq!((dim, dart), (4, cell_min), "{}", error);
                match which {
                    1 => {
                        prop_assert!(matches!(error, PreconditionError::C2 { .. }), "{}", error);
                        tally.add("refused: C2, pinched");
                    }
                    2 => {
                        prop_assert!(
                            matches!(error, PreconditionError::C1(CellDefect::NotOrientable { .. })),
                            "{}",
                            error
                        );
                        tally.add("refused: C1, non-orientable boundary");
                    }
                    _ => return Err(fail(format!("a 4-ball was refused: {error}"))),
                }
                // the cone on anything is contractible; the good part is a torus S^1 × I^3
                let want = if with_good { "(Z^2, Z, 0, 0, 0)" } else { "(Z, 0, 0, 0, 0)" };
                prop_assert_eq!(simplicial.z.to_string(), want);
            }
        }
        Ok(())
    });
    tally.report("suspensions");
    assert!(tally.get("refused: C2, pinched") >= 3);
    assert!(tally.get("refused: C1, non-orientable boundary") >= 3);
}

/// Whether the closed (n-1)-cell made of the darts `facet` (one side of it, the orbit of
/// `alpha_0..alpha_{n-2}`) is embedded in `m`: for every k < n - 1, its k-cells as a
/// cell of its own are distinct k-cells of `m`.
fn facet_embedded(m: &DenseMap, facet: &[Dart]) -> bool {
    let n = m.dim();
    (0..n - 1).all(|k| {
        let cells = m.cells(k);
        let mut global: Vec<u32> = facet.iter().map(|d| cells.of[d.index()]).collect();
        global.sort_unstable();
        global.dedup();
        let own = AlphaSet::below(n - 1).without(k);
        let mut seen: Vec<Dart> = Vec::new();
        let mut local = 0;
        for &d in facet {
            if !seen.contains(&d) {
                local += 1;
                seen.extend(m.orbit(d, own));
            }
        }
        global.len() == local
    })
}

/// The flag parity of each dart of the `set`-orbit of `d` (`alpha_k` flips it), as a map;
/// `None` if the orbit is not 2-colourable.
fn flag_parity(m: &DenseMap, d: Dart, set: AlphaSet) -> Option<HashMap<u32, bool>> {
    let mut parity = HashMap::from([(d.get(), false)]);
    let mut stack = vec![d];
    while let Some(x) = stack.pop() {
        let c = parity[&x.get()];
        for k in set.iter() {
            let y = m.alpha(x, k);
            match parity.get(&y.get()) {
                Some(&got) if got == c => return None,
                Some(_) => {}
                None => {
                    parity.insert(y.get(), !c);
                    stack.push(y);
                }
            }
        }
    }
    Some(parity)
}

#[test]
fn boundary_facets_folded_onto_themselves() {
    let tally = Tally::default();
    let strategy = (prop_oneof![3 => Just(3usize), 1 => Just(4usize)], 0usize..4, any::<u64>());
    run(64, strategy, |(n, odd_one_in, seed)| {
        let mut rng = SplitMix64::new(seed);
        let sizes: Vec<usize> = (0..n).map(|_| 1 + rng.below(if n == 3 { 4 } else { 2 })).collect();
        let periodic: Vec<bool> = (0..n).map(|a| a > 0 && rng.below(2) == 0).collect(); // axis 0 has a boundary
        let cubes: usize = sizes.iter().product();
        let keep: Vec<bool> = (0..cubes).map(|c| c == 0 || rng.below(5) != 0).collect();
        let good = voxels(&sizes, &periodic, &keep);
        let hgood = groups(&simplicial_complex(&good))?;
        let free: Vec<Dart> = good.darts().filter(|&d| good.is_free(d, n)).collect();
        prop_assert!(!free.is_empty());
        let d = free[rng.below(free.len())];
        let facet_set = AlphaSet::below(n - 1);
        let facet = good.orbit(d, facet_set);
        let embedded = facet_embedded(&good, &facet);
        let parity = flag_parity(&good, d, facet_set).expect("a cube's facet is orientable");
        // a symmetry of the facet that is a fixed-point-free involution, of the parity asked
        // for: odd ones (reflections, the antipodal map of a cube) reverse the facet
        let odd = odd_one_in != 0;
        let mut candidates = facet.clone();
        rng.shuffle(&mut candidates);
        let alphas: Vec<usize> = facet_set.iter().collect();
        let phi: HashMap<u32, u32> = candidates
            .iter()
            .filter(|e| parity[&e.get()] == odd)
            .filter_map(|&e| orbit_iso(&good, d, e, &alphas))
            .map(|pairs| pairs.into_iter().collect::<HashMap<u32, u32>>())
            .find(|phi| phi.iter().all(|(&x, &y)| x != y && phi[&y] == x))
            .expect("a square and a cube have fixed-point-free involutions of both parities");
        let mut m = good.clone();
        for (&x, &y) in &phi {
            m.link(Dart::new(x), Dart::new(y), n);
        }
        let facet_darts: Vec<u32> = facet.iter().map(|x| x.get()).collect();
        let kind = if odd { "odd" } else { "even" };
        match judge(&m)? {
            Verdict::Accepted(_) => return Err(fail(format!("a facet folded by an {kind} symmetry was accepted"))),
            Verdict::Refused { error, dim, dart, simplicial } => {
                // an odd fold reverses the facet (C1); an even one keeps its orientation and is
                // refused as self-bending, unless it reverses an edge on its way (C1)
                match &error {
                    PreconditionError::C1(_) => tally.add(format!("{n}D {kind}: C1")),
                    PreconditionError::SelfBending(_) if !odd => tally.add(format!("{n}D {kind}: self-bending")),
                    _ => return Err(fail(format!("a facet folded by an {kind} symmetry: {error}"))),
                }
                prop_assert!(dim < n, "{}", error);
                let cell = m.orbit(Dart::new(dart), AlphaSet::cell(dim, n));
                prop_assert!(
                    cell.iter().any(|x| facet_darts.contains(&x.get())),
                    "the cell named misses the fold: {}",
                    error
                );
                if embedded {
                    // the closed facet is a ball, its quotient by a linear involution too
                    prop_assert_eq!(&simplicial, &hgood, "folding an embedded facet keeps the groups");
                    tally.add("known groups");
                }
                tally.add(format!("{n}D {kind}: refused, {dim}-cell"));
            }
        }
        Ok(())
    });
    tally.report("folded facets");
    let count = |prefix: &str| -> usize {
        tally.0.borrow().iter().filter(|(k, _)| k.starts_with(prefix)).map(|(_, v)| v).sum()
    };
    assert!(count("3D odd: refused") >= 16);
    assert!(count("4D odd: refused") >= 4);
    assert!(tally.get("3D even: self-bending") + tally.get("4D even: self-bending") >= 2);
    assert!(tally.get("known groups") >= 20);
}

#[test]
fn cells_opened_inside_are_refused() {
    let tally = Tally::default();
    let strategy = (prop_oneof![4 => Just(3usize), 1 => Just(4usize)], any::<u64>(), any::<u64>());
    run(64, strategy, |(n, pick, seed)| {
        let mut rng = SplitMix64::new(seed);
        let sizes: Vec<usize> = (0..n).map(|_| 1 + rng.below(if n == 3 { 3 } else { 2 })).collect();
        let periodic: Vec<bool> = (0..n).map(|_| rng.below(2) == 0).collect();
        let cubes: usize = sizes.iter().product();
        let keep: Vec<bool> = (0..cubes).map(|c| c == 0 || rng.below(4) != 0).collect();
        let good = voxels(&sizes, &periodic, &keep);
        let d = Dart::new((pick % good.dart_count() as u64) as u32);
        let k = rng.below(n);
        let far: Vec<usize> = (0..=n).filter(|&j| j + 2 <= k || j >= k + 2).collect();
        let opened = good.orbit(d, AlphaSet::of(&far));
        let mut m = good.clone();
        let mut freed: Vec<u32> = Vec::new();
        for &x in &opened {
            let y = m.alpha(x, k);
            if y != x {
                freed.extend([x.get(), y.get()]);
                m.unlink(x, k);
            }
        }
        prop_assert!(!freed.is_empty(), "only alpha_n is free in a voxel set");
        match judge(&m)? {
            Verdict::Accepted(_) => return Err(fail(format!("darts {freed:?} are {k}-free and it was accepted"))),
            Verdict::Refused { error, dim, dart, .. } => {
                match &error {
                    PreconditionError::C1(CellDefect::IncompleteBoundary { alpha, .. }) => prop_assert_eq!(*alpha, k),
                    other => return Err(fail(format!("expected an incomplete boundary, got {other}"))),
                }
                prop_assert_eq!(dim, k + 1, "{}", error);
                let cell = m.orbit(Dart::new(dart), AlphaSet::cell(dim, n));
                prop_assert!(cell.iter().any(|x| freed.contains(&x.get())), "the cell named misses the cut: {}", error);
                tally.add(if n == 3 { "refused 3D" } else { "refused 4D" });
            }
        }
        Ok(())
    });
    tally.report("opened cells");
    assert_eq!(tally.get("refused 3D") + tally.get("refused 4D"), 64);
}

/// L(1, 0) (the 3-sphere) and L(2, 1) (projective 3-space) have one edge, a loop whose
/// vertex is made of its own darts only, with `alpha_2 alpha_3` an involution on it.
/// Taken for a dangling edge, its removal would delete every dart and leave the empty map;
/// a dangling edge needs a vertex of degree one, so the loop is not removable and the
/// space keeps its homology.
#[test]
fn removing_the_loop_edge_of_l1_and_l2_keeps_the_space() {
    for (p, q, want) in [(1, 0, "(Z, 0, 0, Z)"), (2, 1, "(Z, Z/2, 0, Z)")] {
        let base = build::lens_space(p, q).unwrap();
        assert_eq!(base.cell_counts(), vec![1, 1, 1, 1]);
        let (mut g, ids) = GMap::from_dense(&base);
        assert!(!ops::is_removable_keeping_homology(&g, ids[0], 1), "L({p}, {q})");
        if ops::is_removable_keeping_homology(&g, ids[0], 1) {
            ops::try_remove_cell_keeping_homology(&mut g, ids[0], 1).unwrap();
        }
        let (m, _) = g.to_dense_with_ids();
        let h = homology_z(&simplicial_complex(&m)).unwrap();
        assert_eq!(h.to_string(), want, "L({p}, {q})");
    }
}
