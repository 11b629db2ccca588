//! Properties of image persistence on random 1-D to 4-D arrays: the diagram equals that of
//! a plain reduction written here (every cell in one matrix, no clearing, no union-find),
//! and every returned cycle is a cycle, present at its pair's birth, not a boundary before
//! its death (and one at it).

use std::collections::BTreeMap;

use gmap_homology::persistence::{
    cubical_persistence, morse_persistence, CellName, Construction, CubicalOptions, Diagram, PersistenceError,
};
use proptest::prelude::*;

/// The doubled grid of an image, built independently of the library.
struct Cells {
    m: Vec<usize>,
    periodic: bool,
    /// every grid point: (coordinates, value)
    cells: Vec<(Vec<usize>, f64)>,
}

fn linear(m: &[usize], c: &[usize]) -> usize {
    c.iter().zip(m).fold(0, |r, (&x, &n)| r * n + x)
}

impl Cells {
    fn new(shape: &[usize], values: &[f64], t: bool, periodic: bool, sign: f64) -> Self {
        let m: Vec<usize> = shape
            .iter()
            .map(|&s| {
                if periodic {
                    2 * s
                } else if t {
                    2 * s + 1
                } else {
                    2 * s - 1
                }
            })
            .collect();
        let pixel = |p: &[usize]| values[linear(shape, p)] * sign;
        let mut cells = Vec::new();
        let total: usize = m.iter().product();
        for g in 0..total {
            let mut c = vec![0; m.len()];
            let mut r = g;
            for a in (0..m.len()).rev() {
                c[a] = r % m[a];
                r /= m[a];
            }
            // the pixels around (T: top cells containing it) or in (V: its vertices)
            let mut around: Vec<Vec<usize>> = vec![vec![]];
            for a in 0..m.len() {
                let want_odd = t;
                let opts: Vec<usize> = if (c[a] % 2 == 1) == want_odd {
                    vec![c[a]]
                } else {
                    let mut o = vec![];
                    if c[a] > 0 {
                        o.push(c[a] - 1);
                    } else if periodic {
                        o.push(m[a] - 1);
                    }
                    if c[a] + 1 < m[a] {
                        o.push(c[a] + 1);
                    } else if periodic {
                        o.push(0);
                    }
                    o
                };
                around =
                    around.into_iter().flat_map(|p| opts.iter().map(move |&x| [p.clone(), vec![x]].concat())).collect();
            }
            let px = around.iter().map(|p| pixel(&p.iter().map(|&x| x / 2).collect::<Vec<_>>()));
            let v = if t { px.fold(f64::INFINITY, f64::min) } else { px.fold(f64::NEG_INFINITY, f64::max) };
            cells.push((c, v));
        }
        Cells { m, periodic, cells }
    }

    fn dim(c: &[usize]) -> usize {
        c.iter().filter(|&&x| x % 2 == 1).count()
    }

    /// Signed faces by grid index.
    fn boundary(&self, c: &[usize], p: i64) -> BTreeMap<usize, i64> {
        let mut out = BTreeMap::new();
        let mut j = 0;
        for a in 0..c.len() {
            if c[a] % 2 == 1 {
                let s: i64 = if j % 2 == 0 { 1 } else { -1 };
                let mut lo = c.to_vec();
                lo[a] -= 1;
                let mut hi = c.to_vec();
                hi[a] = if c[a] + 1 == self.m[a] { 0 } else { c[a] + 1 };
                for (f, x) in [(lo, -s), (hi, s)] {
                    let e = out.entry(linear(&self.m, &f)).or_insert(0);
                    *e = (*e + x).rem_euclid(p);
                }
                j += 1;
            }
        }
        out.retain(|_, x| *x != 0);
        out
    }
}

fn inv(a: i64, p: i64) -> i64 {
    (1..p).find(|x| a * x % p == 1).unwrap()
}

/// `a += f * b` over Z/p.
fn axpy(a: &mut BTreeMap<usize, i64>, f: i64, b: &BTreeMap<usize, i64>, p: i64) {
    for (&r, &x) in b {
        let e = a.entry(r).or_insert(0);
        *e = (*e + f * x).rem_euclid(p);
        if *e == 0 {
            a.remove(&r);
        }
    }
}

/// The plain reduction of the whole boundary matrix in filtration order.
fn reference(cells: &Cells, p: i64, sign: f64) -> Vec<(usize, u64, u64)> {
    let n = cells.cells.len();
    let mut order: Vec<usize> = (0..n).collect();
    let key = |g: usize| (cells.cells[g].1, Cells::dim(&cells.cells[g].0), g);
    order.sort_by(|&a, &b| key(a).partial_cmp(&key(b)).unwrap());
    let mut pos = vec![0; n];
    for (i, &g) in order.iter().enumerate() {
        pos[g] = i;
    }
    let mut cols: Vec<BTreeMap<usize, i64>> = order
        .iter()
        .map(|&g| cells.boundary(&cells.cells[g].0, p).into_iter().map(|(f, x)| (pos[f], x)).collect())
        .collect();
    let mut owner: BTreeMap<usize, usize> = BTreeMap::new();
    let mut born = vec![true; n];
    let mut out = Vec::new();
    let v = |i: usize| cells.cells[order[i]].1;
    let bits = |x: f64| (sign * x + 0.0).to_bits();
    for j in 0..n {
        while let Some((&low, &c)) = cols[j].iter().next_back() {
            match owner.get(&low) {
                Some(&o) => {
                    let oc = cols[o][&low];
                    let f = (p - c * inv(oc, p) % p) % p;
                    let other = cols[o].clone();
                    axpy(&mut cols[j], f, &other, p);
                }
                None => {
                    owner.insert(low, j);
                    born[low] = false;
                    born[j] = false;
                    if v(low) != v(j) {
                        out.push((Cells::dim(&cells.cells[order[low]].0), bits(v(low)), bits(v(j))));
                    }
                    break;
                }
            }
        }
    }
    for j in 0..n {
        if born[j] && cols[j].is_empty() {
            out.push((Cells::dim(&cells.cells[order[j]].0), bits(v(j)), (sign * f64::INFINITY).to_bits()));
        }
    }
    out.sort_unstable();
    out
}

fn ours(d: &Diagram) -> Vec<(usize, u64, u64)> {
    let b = |x: f64| (x + 0.0).to_bits();
    let mut v: Vec<_> = d.pairs.iter().map(|p| (p.dim, b(p.birth), b(p.death))).collect();
    v.sort_unstable();
    v
}

/// Rank over Z/p of a set of sparse vectors (Gaussian elimination on a copy).
fn rank(vectors: &[BTreeMap<usize, i64>], p: i64) -> usize {
    let mut pivots: BTreeMap<usize, BTreeMap<usize, i64>> = BTreeMap::new();
    let mut r = 0;
    for v in vectors {
        let mut v = v.clone();
        while let Some((&low, &c)) = v.iter().next_back() {
            match pivots.get(&low) {
                Some(o) => {
                    let f = (p - c * inv(o[&low], p) % p) % p;
                    axpy(&mut v, f, o, p);
                }
                None => {
                    pivots.insert(low, v);
                    r += 1;
                    break;
                }
            }
        }
    }
    r
}

/// Is `chain` a boundary of the (k+1)-cells whose value passes `keep`?
fn is_boundary(cells: &Cells, chain: &BTreeMap<usize, i64>, k: usize, keep: impl Fn(f64) -> bool, p: i64) -> bool {
    let cols: Vec<BTreeMap<usize, i64>> = cells
        .cells
        .iter()
        .filter(|(c, v)| Cells::dim(c) == k + 1 && keep(*v))
        .map(|(c, _)| cells.boundary(c, p))
        .collect();
    let r = rank(&cols, p);
    let mut with = cols;
    with.push(chain.clone());
    rank(&with, p) == r
}

fn arrays() -> impl Strategy<Value = (Vec<usize>, Vec<f64>)> {
    (1usize..=4)
        .prop_flat_map(|d| {
            let max: usize = [0, 9, 5, 3, 2][d];
            proptest::collection::vec(1..=max, d)
        })
        .prop_flat_map(|shape| {
            let n: usize = shape.iter().product();
            (Just(shape), proptest::collection::vec((0..5u8).prop_map(f64::from), n))
        })
}

/// Larger arrays than [`arrays`], with few values (plateaus) or distinct ones.
fn larger_arrays() -> impl Strategy<Value = (Vec<usize>, Vec<f64>)> {
    (1usize..=4, any::<bool>())
        .prop_flat_map(|(d, ties)| {
            let max: usize = [0, 40, 14, 7, 4][d];
            (proptest::collection::vec(1..=max, d), Just(ties))
        })
        .prop_flat_map(|(shape, ties)| {
            let n: usize = shape.iter().product();
            let value = if ties { (0..4u8).prop_map(f64::from).boxed() } else { (-1e3..1e3f64).boxed() };
            (Just(shape), proptest::collection::vec(value, n))
        })
}

/// The options of a test case: the T-construction if `t`, else V.
fn options(t: bool, superlevel: bool, periodic: bool, field: u32, cycles: bool) -> CubicalOptions {
    let construction = if t { Construction::T } else { Construction::V };
    CubicalOptions { construction, superlevel, periodic, field, cycles }
}

/// The Morse route's diagram with no memory limit to speak of.
fn morse(shape: &[usize], values: &[f64], opts: &CubicalOptions) -> Result<Diagram, PersistenceError> {
    morse_persistence(shape, &|i| values[i], opts, u64::MAX)
}

proptest! {
    // cheap cases (under a millisecond each); a sign lost on the gradient's paths over Z/3
    // shows only on some arrays
    #![proptest_config(ProptestConfig::with_cases(1024))]

    #[test]
    fn the_morse_route_equals_a_plain_reduction(
        (shape, values) in arrays(), t in any::<bool>(), superlevel in any::<bool>(),
        p in prop::sample::select(vec![2u32, 3, 5]),
    ) {
        let opts = options(t, superlevel, false, p, false);
        let sign = if superlevel { -1.0 } else { 1.0 };
        let cells = Cells::new(&shape, &values, t, false, sign);
        prop_assert_eq!(ours(&morse(&shape, &values, &opts).unwrap()), reference(&cells, p as i64, sign));
    }

    #[test]
    fn the_morse_route_equals_the_whole_grid_on_larger_arrays(
        (shape, values) in larger_arrays(), t in any::<bool>(), superlevel in any::<bool>(),
        p in prop::sample::select(vec![2u32, 3, 5]),
    ) {
        let opts = options(t, superlevel, false, p, false);
        let whole = cubical_persistence(&shape, &values, &opts).unwrap();
        prop_assert_eq!(ours(&morse(&shape, &values, &opts).unwrap()), ours(&whole));
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]

    #[test]
    fn diagrams_equal_a_plain_reduction(
        (shape, values) in arrays(), t in any::<bool>(), superlevel in any::<bool>(),
        periodic in any::<bool>(), p in prop::sample::select(vec![2u32, 3, 5]), cycles in any::<bool>(),
    ) {
        let opts = options(t, superlevel, periodic, p, cycles);
        let sign = if superlevel { -1.0 } else { 1.0 };
        let cells = Cells::new(&shape, &values, t, periodic, sign);
        let d = cubical_persistence(&shape, &values, &opts).unwrap();
        prop_assert_eq!(ours(&d), reference(&cells, p as i64, sign));
    }

    #[test]
    fn cycles_are_cycles_born_at_birth_and_alive_until_death(
        (shape, values) in arrays(), t in any::<bool>(), superlevel in any::<bool>(),
        periodic in any::<bool>(), p in prop::sample::select(vec![2u32, 3]),
    ) {
        let opts = options(t, superlevel, periodic, p, true);
        let sign = if superlevel { -1.0 } else { 1.0 };
        let cells = Cells::new(&shape, &values, t, periodic, sign);
        let d = cubical_persistence(&shape, &values, &opts).unwrap();
        prop_assert_eq!(d.cycles.len(), d.pairs.len());
        let pi = p as i64;
        for (pair, chain) in d.pairs.iter().zip(&d.cycles) {
            let (birth, death) = (sign * pair.birth, sign * pair.death);
            let mut c: BTreeMap<usize, i64> = BTreeMap::new();
            for (name, x) in chain {
                let CellName::Grid(g) = name else { panic!("a grid cell") };
                prop_assert_eq!(Cells::dim(g), pair.dim);
                let g = linear(&cells.m, g);
                // present at birth
                prop_assert!(cells.cells[g].1 <= birth, "cell {:?} after the birth {}", cells.cells[g], birth);
                c.insert(g, *x as i64);
            }
            prop_assert!(!c.is_empty());
            // a cycle (vertices: every 0-chain is)
            let mut bd: BTreeMap<usize, i64> = BTreeMap::new();
            for (&g, &x) in &c {
                axpy(&mut bd, x, &cells.boundary(&cells.cells[g].0, pi), pi);
            }
            prop_assert!(bd.is_empty(), "boundary {:?} of {:?}", bd, chain);
            // not a boundary before death; one at death if it dies
            prop_assert!(!is_boundary(&cells, &c, pair.dim, |v| v < death, pi), "a boundary before {}", death);
            if death.is_finite() {
                prop_assert!(is_boundary(&cells, &c, pair.dim, |v| v <= death, pi), "not a boundary at {}", death);
            }
        }
        let _ = cells.periodic;
    }
}
