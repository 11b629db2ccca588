//! Representative cycles of a cubical set of dimension 1 or 2 in time linear in the cells,
//! read off the structures of the one-pass route rather than off a reduced chain complex.
//!
//! A set X of closed unit squares in the plane has torsion-free homology, and a basis of each
//! group comes from two union-finds:
//!
//! * **`H_0`**: one vertex per component of X (the smallest in the grid's order), the roots of
//!   a union-find over the vertices and edges of X.
//! * **`H_1`** (2-D): the boundary of each bounded component C of the complement (absent
//!   squares joined across shared edges; those on the box's border join the unbounded
//!   outside): `∂(Σ_{v ∈ C} v)`, the edges between a square of C and a square of X, with the
//!   signs of `∂v`. It is a cycle of X (each of its edges lies on a square of X), and by
//!   Alexander duality (`H̃_1(X) ≅ H̃^0(S^2 \ X)`, the winding number of the boundary of `C_i`
//!   around a point of `C_j` being `δ_ij`) these cycles are a basis over Z: each is a hole's
//!   own outline, as short as the hole's perimeter.
//!
//! The Betti numbers so found are checked against the Euler characteristic counted on the
//! cells. Time O(cells · α); memory a byte per point of the doubled grid and a `u32` per
//! vertex, or two `u32` per square while the complement is labelled.
//!
//! In 3-D, `H_0` and `H_2` (the boundaries of the cavities) would come the same way, but a
//! basis of `H_1` needs loops that no union-find gives: a fixed spanning forest contracted
//! first leaves sweeps stuck on random sets (every edge on two squares, every square with two
//! edges), so 3-D sets take the cubical complex ([`crate::cubical`]) and
//! [`crate::generators`].
//!
//! ```
//! use gmap_homology::cubical_gens::cubical_generators;
//! // a ring of 8 squares around a hole: one component, one loop
//! let bits = [1, 1, 1, 1, 0, 1, 1, 1, 1];
//! let g = cubical_generators(&[3, 3], &bits).unwrap();
//! assert_eq!(g.betti, vec![1, 1, 0]);
//! // the loop is the boundary of the hole: its four edges, in the doubled grid (7 × 7 points)
//! let loop1 = &g.generators[1];
//! assert_eq!((loop1.dim, loop1.chain.len()), (1, 4));
//! ```

use super::cubical::CubicalError;

/// A representative cycle of one free summand of `H_dim`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CubeCycle {
    /// the dimension k of the group
    pub dim: usize,
    /// `(point, coefficient)`: the cells as points of the doubled grid (`2L + 1` per axis, axis
    /// 0 fastest, a cell odd along the axes it spans), increasing, coefficients ±1 for the
    /// boundaries and the fundamental cycles
    pub chain: Vec<(u64, i64)>,
}

/// What [`cubical_generators`] found.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CubicalGenerators {
    /// `b_0 … b_d` (the groups are free)
    pub betti: Vec<u64>,
    /// the alternating count of the cells of X
    pub euler_characteristic: i64,
    /// a cycle per free summand, dimension by dimension
    pub generators: Vec<CubeCycle>,
    /// points of the doubled grid per axis (`2L + 1`)
    pub grid: Vec<usize>,
}

/// The bytes [`cubical_generators`] holds for a box of `shape` squares besides its input and
/// its output (`None` past `u64`).
pub fn bytes_needed(shape: &[usize]) -> Option<u64> {
    let prod = |f: &dyn Fn(usize) -> u64| shape.iter().try_fold(1u64, |v, &l| v.checked_mul(f(l)));
    let grid = prod(&|l| 2 * l as u64 + 1)?;
    let vertices = prod(&|l| l as u64 + 1)?;
    let squares = prod(&|l| l as u64)?;
    // the doubled grid and a u32 per vertex, or two u32 per square while the complement is
    // labelled
    Some(grid.checked_add(vertices.checked_mul(4)?)?.max(squares.checked_mul(8)?))
}

/// A cell of the closure, in the doubled grid's bytes.
const PRESENT: u8 = 1;

/// The box: cubes, vertices and the doubled grid, with their strides (axis 0 fastest).
struct Box {
    d: usize,
    n: [usize; 3],
    /// doubled grid points per axis and strides
    g: [usize; 3],
    gs: [usize; 3],
    /// vertex strides
    vs: [usize; 3],
    /// cube strides
    cs: [usize; 3],
}

impl Box {
    fn new(shape: &[usize]) -> Self {
        let d = shape.len();
        let mut n = [1usize; 3];
        let mut g = [1usize; 3];
        n[..d].copy_from_slice(shape);
        for a in 0..d {
            g[a] = 2 * n[a] + 1;
        }
        let (mut gs, mut vs, mut cs) = ([0usize; 3], [0usize; 3], [0usize; 3]);
        let (mut s, mut v, mut c) = (1, 1, 1);
        for a in 0..3 {
            gs[a] = s;
            vs[a] = v;
            cs[a] = c;
            s *= g[a];
            v *= if a < d { n[a] + 1 } else { 1 };
            c *= n[a];
        }
        Box { d, n, g, gs, vs, cs }
    }

    fn grid_len(&self) -> usize {
        self.g.iter().product()
    }

    fn vertex_count(&self) -> usize {
        (0..self.d).map(|a| self.n[a] + 1).product()
    }

    fn cube_count(&self) -> usize {
        self.n.iter().product()
    }
}

/// Visits every point of a product of arithmetic ranges `start[a], start[a] + step[a], … <
/// end[a]`, axis 0 fastest, with the point's coordinates.
fn for_each_point(start: [usize; 3], step: [usize; 3], end: [usize; 3], mut f: impl FnMut([usize; 3])) {
    if (0..3).any(|a| start[a] >= end[a]) {
        return;
    }
    let mut c = start;
    loop {
        f(c);
        let mut a = 0;
        loop {
            c[a] += step[a];
            if c[a] < end[a] {
                break;
            }
            c[a] = start[a];
            a += 1;
            if a == 3 {
                return;
            }
        }
    }
}

/// Union-find over `u32` numbers linking the larger root under the smaller, paths halved:
/// every root is the smallest member of its class, and `parent[x] ≤ x`.
fn find(parent: &mut [u32], mut x: u32) -> u32 {
    while parent[x as usize] != x {
        let p = parent[x as usize];
        parent[x as usize] = parent[p as usize];
        x = p;
    }
    x
}

fn union(parent: &mut [u32], a: u32, b: u32) -> bool {
    let (ra, rb) = (find(parent, a), find(parent, b));
    if ra == rb {
        return false;
    }
    let (lo, hi) = if ra < rb { (ra, rb) } else { (rb, ra) };
    parent[hi as usize] = lo;
    true
}

fn try_vec<T: Clone>(len: usize, value: T, what: &'static str) -> Result<Vec<T>, CubicalError> {
    let mut v = Vec::new();
    v.try_reserve_exact(len).map_err(|_| CubicalError::OutOfMemory {
        what,
        bytes: (len as u64).saturating_mul(std::mem::size_of::<T>() as u64),
    })?;
    v.resize(len, value);
    Ok(v)
}

/// A basis of the homology of the set of a box of `shape` squares (axis 0 fastest, d = 1 or
/// 2, not periodic) whose presence bytes are `bits` (non-zero: in the set): a cycle per free
/// summand, in the cells of the doubled grid. See the [module docs](self). Refuses another
/// dimension, a shape not matching `bits`, a doubled grid past `u32` numbers, and memory over
/// the limit. O(cells · α).
pub fn cubical_generators(shape: &[usize], bits: &[u8]) -> Result<CubicalGenerators, CubicalError> {
    let d = shape.len();
    if !(1..=2).contains(&d) || shape.contains(&0) {
        return Err(CubicalError::BadShape(format!(
            "the one-pass generators take dimensions 1 and 2, not the shape {shape:?}"
        )));
    }
    let cubes = shape.iter().try_fold(1usize, |v, &l| v.checked_mul(l));
    if cubes != Some(bits.len()) {
        return Err(CubicalError::BadShape(format!("{} bytes for a box of {shape:?} cubes", bits.len())));
    }
    let grid_points = shape.iter().try_fold(1u64, |v, &l| v.checked_mul(2 * l as u64 + 1));
    match grid_points {
        Some(p) if p < u32::MAX as u64 && usize::try_from(p).is_ok() => {}
        _ => {
            return Err(CubicalError::TooLarge {
                points: grid_points.map_or("more than 2^64".to_string(), |p| p.to_string()),
                limit: u32::MAX as u64 - 1,
            })
        }
    }
    gmap_core::resources::check_memory("the generators of a cubical set", bytes_needed(shape))?;
    let bx = Box::new(shape);
    let mut betti = vec![0u64; d + 1];
    // H_1 first: its union-find over the squares is freed before the grid is built
    let holes = if d == 2 { complement_boundaries(&bx, bits)? } else { Vec::new() };
    let mut st = try_vec(bx.grid_len(), 0u8, "the cells of the doubled grid")?;
    let cells = mark_closure(&bx, bits, &mut st);
    let euler_characteristic: i64 = cells.iter().enumerate().map(|(k, &c)| if k % 2 == 0 { c } else { -c }).sum();
    let mut forest = try_vec(bx.vertex_count(), 0u32, "the components of the vertices")?;
    let roots = components(&bx, &st, &mut forest);
    betti[0] = roots.len() as u64;
    betti[1] = holes.len() as u64;
    let mut generators: Vec<CubeCycle> =
        roots.iter().map(|&p| CubeCycle { dim: 0, chain: vec![(p as u64, 1)] }).collect();
    generators.extend(holes);
    if betti[0] as i64 - betti[1] as i64 != euler_characteristic {
        return Err(CubicalError::Internal(format!(
            "the Betti numbers {betti:?} do not sum to the Euler characteristic {euler_characteristic}"
        )));
    }
    Ok(CubicalGenerators { betti, euler_characteristic, generators, grid: bx.g[..d].to_vec() })
}

/// Marks the cells of the closure of the set present, and counts them by dimension.
fn mark_closure(bx: &Box, bits: &[u8], st: &mut [u8]) -> [i64; 4] {
    let d = bx.d;
    // the 3^d cells of a cube, as offsets from its centre, with their dimensions
    let mut offsets: Vec<(isize, usize)> = vec![(0, d)];
    for a in 0..d {
        let s = bx.gs[a] as isize;
        offsets = offsets.iter().flat_map(|&(o, k)| [(o, k), (o - s, k - 1), (o + s, k - 1)]).collect();
    }
    let mut cells = [0i64; 4];
    for_each_point([0; 3], [1; 3], bx.n, |c| {
        let v = c[0] * bx.cs[0] + c[1] * bx.cs[1] + c[2] * bx.cs[2];
        if bits[v] == 0 {
            return;
        }
        let centre = (0..3).map(|a| if a < d { (2 * c[a] + 1) * bx.gs[a] } else { 0 }).sum::<usize>() as isize;
        for &(o, k) in &offsets {
            let p = (centre + o) as usize;
            if st[p] & PRESENT == 0 {
                st[p] |= PRESENT;
                cells[k] += 1;
            }
        }
    });
    cells
}

/// The union-find of the present vertices over the present edges: the grid points of the
/// roots, increasing (the smallest vertex of each component).
fn components(bx: &Box, st: &[u8], forest: &mut [u32]) -> Vec<usize> {
    let d = bx.d;
    for (i, x) in forest.iter_mut().enumerate() {
        *x = i as u32;
    }
    for a in 0..d {
        let mut end = [1usize; 3];
        for (e, &n) in end.iter_mut().zip(&bx.n).take(d) {
            *e = n + 1;
        }
        end[a] = bx.n[a];
        for_each_point([0; 3], [1; 3], end, |c| {
            let p = (0..d).map(|b| 2 * c[b] * bx.gs[b]).sum::<usize>() + bx.gs[a];
            if st[p] & PRESENT != 0 {
                let v = (0..d).map(|b| c[b] * bx.vs[b]).sum::<usize>();
                union(forest, v as u32, (v + bx.vs[a]) as u32);
            }
        });
    }
    let mut roots = Vec::new();
    for_each_point([0; 3], [2, 2, 2], bx.g, |c| {
        let p = c[0] * bx.gs[0] + c[1] * bx.gs[1] + c[2] * bx.gs[2];
        if st[p] & PRESENT != 0 {
            let v = (c[0] / 2) * bx.vs[0] + (c[1] / 2) * bx.vs[1] + (c[2] / 2) * bx.vs[2];
            if forest[v] == v as u32 {
                roots.push(p);
            }
        }
    });
    roots
}

/// `H_1` of a 2-D set: the boundaries of the bounded components of the complement (absent
/// squares joined across shared edges), ordered by their smallest square.
fn complement_boundaries(bx: &Box, bits: &[u8]) -> Result<Vec<CubeCycle>, CubicalError> {
    let d = bx.d;
    let m = bx.cube_count();
    let mut uf = try_vec(m, 0u32, "the components of the complement")?;
    for (i, x) in uf.iter_mut().enumerate() {
        *x = i as u32;
    }
    for_each_point([0; 3], [1; 3], bx.n, |c| {
        let v = c[0] * bx.cs[0] + c[1] * bx.cs[1] + c[2] * bx.cs[2];
        if bits[v] != 0 {
            return;
        }
        for a in 0..d {
            if c[a] + 1 < bx.n[a] && bits[v + bx.cs[a]] == 0 {
                union(&mut uf, v as u32, (v + bx.cs[a]) as u32);
            }
        }
    });
    // every class to its root (parents are smaller: one forward pass), then the outside's
    // roots: a component with a cube on the box's border is unbounded
    for v in 0..m {
        let p = uf[v] as usize;
        uf[v] = uf[p];
    }
    let mut outside = vec![0u64; m.div_ceil(64)];
    let on_border = |c: &[usize; 3]| (0..d).any(|a| c[a] == 0 || c[a] + 1 == bx.n[a]);
    for_each_point([0; 3], [1; 3], bx.n, |c| {
        let v = c[0] * bx.cs[0] + c[1] * bx.cs[1] + c[2] * bx.cs[2];
        if bits[v] == 0 && on_border(&c) {
            let r = uf[v] as usize;
            outside[r / 64] |= 1 << (r % 64);
        }
    });
    // the bounded roots numbered in the order of their smallest cube (a root comes first in
    // its class): `uf[root] = number | NUMBERED`, the other members keep their root
    const NUMBERED: u32 = 1 << 31;
    let mut sizes: Vec<usize> = Vec::new();
    let centre = |c: &[usize; 3]| (0..d).map(|a| (2 * c[a] + 1) * bx.gs[a]).sum::<usize>();
    // the facets of an absent cube v on a present neighbour, with the signs of ∂v
    let facets = |c: &[usize; 3], v: usize, f: &mut dyn FnMut(usize, i64)| {
        let p = centre(c);
        for a in 0..d {
            let sign = if a % 2 == 0 { 1 } else { -1 };
            if bits[v + bx.cs[a]] != 0 {
                f(p + bx.gs[a], sign);
            }
            if bits[v - bx.cs[a]] != 0 {
                f(p - bx.gs[a], -sign);
            }
        }
    };
    // the number of the bounded component of absent cube v, once its root is numbered
    let number_of = |uf: &[u32], v: usize| -> Option<usize> {
        let r = if uf[v] & NUMBERED != 0 { v } else { uf[v] as usize };
        (uf[r] & NUMBERED != 0).then_some((uf[r] & !NUMBERED) as usize)
    };
    for_each_point([0; 3], [1; 3], bx.n, |c| {
        let v = c[0] * bx.cs[0] + c[1] * bx.cs[1] + c[2] * bx.cs[2];
        if bits[v] != 0 || on_border(&c) {
            return;
        }
        if uf[v] as usize == v && outside[v / 64] >> (v % 64) & 1 == 0 {
            uf[v] = sizes.len() as u32 | NUMBERED;
            sizes.push(0);
        }
        if let Some(id) = number_of(&uf, v) {
            facets(&c, v, &mut |_, _| sizes[id] += 1);
        }
    });
    let mut chains: Vec<Vec<(u64, i64)>> = Vec::new();
    chains.try_reserve_exact(sizes.len()).map_err(|_| CubicalError::OutOfMemory {
        what: "the boundaries of the complement's components",
        bytes: sizes.len() as u64 * 24,
    })?;
    chains.extend(sizes.iter().map(|&n| Vec::with_capacity(n)));
    for_each_point([0; 3], [1; 3], bx.n, |c| {
        let v = c[0] * bx.cs[0] + c[1] * bx.cs[1] + c[2] * bx.cs[2];
        if bits[v] != 0 || on_border(&c) {
            return;
        }
        let Some(id) = number_of(&uf, v) else { return };
        facets(&c, v, &mut |p, s| chains[id].push((p as u64, s)));
    });
    drop(uf);
    Ok(chains
        .into_iter()
        .map(|mut chain| {
            chain.sort_unstable();
            CubeCycle { dim: d - 1, chain }
        })
        .collect())
}
