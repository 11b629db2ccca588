//! Representative cycles of a cubical set of dimension ≤ 3 in time linear in the cells (plus
//! the length of the cycles), read off union-finds and a sweep over the grid rather than off
//! a chain complex built first.
//!
//! A set X of closed unit cubes in `R^d`, `d ≤ 3`, has torsion-free homology, and a basis of
//! each group comes from:
//!
//! * **`H_0`**: one vertex per component of X (the smallest in the grid's order), the roots of
//!   a union-find over the vertices and edges of X.
//! * **`H_{d-1}`** (d ≥ 2): the boundary of each bounded component C of the complement (absent
//!   cubes joined across shared facets; those on the box's border join the unbounded
//!   outside): `∂(Σ_{v ∈ C} v)`, the facets between a cube of C and a cube of X, with the
//!   signs of `∂v`. It is a cycle of X (each of its facets lies on a cube of X), and by
//!   Alexander duality (`H̃_{d-1}(X) ≅ H̃^0(S^d \ X)`, the linking number of the boundary of
//!   `C_i` with a point of `C_j` being `δ_ij`) these cycles are a basis over Z: in 2-D each
//!   hole's outline, in 3-D each cavity's skin.
//! * **`H_1` of a 3-D set, from the complement**, where that is the sparser side (the
//!   complement's loops off a spanning forest at most one per two cubes): X lies in the box K,
//!   which is contractible, so `∂: H_2(K, X) → H_1(X)` is an isomorphism, and the boundaries
//!   of a basis of the relative 2-cycles (chains of squares not in X whose boundary lies in X)
//!   are a basis. A spanning forest of the absent cubes and the outside, joined across the
//!   squares not in X, leaves one such square per independent loop of the complement: one
//!   whose four edges are in X is a relative cycle on its own, the loop of those four edges
//!   around its tunnel; the others, tied together by the edges not in X, are reduced with
//!   unit pivots ([`tunnel_loops`]). No sweep runs, and the loops are short (four edges around
//!   a tunnel one cube thick).
//! * **`H_1` of a 3-D set, otherwise**: collapses and coreductions over the cells on the grid itself
//!   (the sweep of [`crate::generators`], without building the complex), which pair each
//!   vertex but one per component with an edge, in a forest grown inside small aligned blocks
//!   first. The edges the sweep leaves are a basis, each lifted to its fundamental cycle: the
//!   edge and the path of the forest between its ends. Where the sweep stalls, a cell is
//!   made critical; the critical edges are finished by elimination with unit pivots (their
//!   `H_1` is the cokernel of `∂_2`), or by [`crate::generators`] where a unit is missing.
//!   Cavities whose cubes and shared facets make a tree are filled before the sweep, which
//!   leaves `H_1` and the 1-skeleton as they are, so that their skins collapse instead of
//!   stalling it.
//!
//! The Betti numbers so found are checked against the Euler characteristic counted on the
//! cells. Memory: a byte per point of the doubled grid and a `u32` per vertex (3-D: the
//! sweep's waiting cells, up to 6 bytes more per point, and a bit per cube; or the columns of
//! the complement's reduction, at most 4 bytes per point), or two `u32` per cube while the
//! complement is labelled and a `u32` per link off its forest (at most one per two cubes);
//! plus the cycles given.
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

#![allow(clippy::needless_range_loop)] // axes index several arrays at once

use std::collections::VecDeque;

use gmap_core::fastdiv::Divider;
use gmap_core::union_find::UnionFind;

use super::cubical::CubicalError;
use crate::engine::chain::ChainComplex;
use crate::engine::sparse::SparseMatrix;
use crate::prefetch::prefetch;

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

/// The bytes [`cubical_generators`] holds for a box of `shape` cubes besides its input and
/// its output (`None` past `u64`).
pub fn bytes_needed(shape: &[usize]) -> Option<u64> {
    let prod = |f: &dyn Fn(usize) -> u64| shape.iter().try_fold(1u64, |v, &l| v.checked_mul(f(l)));
    let grid = prod(&|l| 2 * l as u64 + 1)?;
    let vertices = prod(&|l| l as u64 + 1)?;
    let cubes = prod(&|l| l as u64)?;
    // the doubled grid and a u32 per vertex, in 3-D the sweep's waiting cells: two bits per
    // grid point (vertices, cubes) and queues of u32 that hold each edge and square at most
    // twice (3/4 of the points: 6 bytes per point at worst), and a bit per cube (the cavities
    // filled), or the complement's reduction (at most a quarter of the points in entries of
    // 16 bytes, fewer than the sweep's); or two u32 per cube while the complement is labelled,
    // and in 3-D a u32 per link off its forest (at most one per two cubes)
    let sweep = if shape.len() == 3 {
        grid.div_ceil(4).checked_add(grid.checked_mul(6)?)?.checked_add(cubes.div_ceil(8))?
    } else {
        0
    };
    let labelled = cubes.checked_mul(if shape.len() == 3 { 10 } else { 8 })?;
    Some(grid.checked_add(vertices.checked_mul(4)?)?.checked_add(sweep)?.max(labelled))
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
    /// `g[0]` and `gs[1]`, `gs[2]` as dividers (the grid's points fit in `u32`)
    div: [Divider; 3],
}

impl Box {
    fn new(shape: &[usize]) -> Result<Self, CubicalError> {
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
        // the caller checked that the grid's points fit in u32: so do its strides
        let div = [g[0], gs[1], gs[2]]
            .map(|x| Divider::new(x).ok_or(CubicalError::TooLarge { points: x.to_string(), limit: u32::MAX as u64 }));
        let [a, b, c] = div;
        Ok(Box { d, n, g, gs, vs, cs, div: [a?, b?, c?] })
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

    /// The number of the cube at cube coordinates `c`.
    #[inline]
    fn cube(&self, c: &[usize; 3]) -> usize {
        c[0] * self.cs[0] + c[1] * self.cs[1] + c[2] * self.cs[2]
    }

    /// The cube coordinates of cube number `v`.
    fn cube_coords(&self, v: usize) -> [usize; 3] {
        [v % self.n[0], v / self.cs[1] % self.n[1], v / self.cs[2]]
    }

    /// The grid point of the cube at cube coordinates `c` (odd along every axis).
    #[inline]
    fn centre(&self, c: &[usize; 3]) -> usize {
        (0..self.d).map(|a| (2 * c[a] + 1) * self.gs[a]).sum()
    }

    /// The grid point at doubled coordinates `c`.
    #[inline]
    fn point(&self, c: &[usize; 3]) -> usize {
        c[0] * self.gs[0] + c[1] * self.gs[1] + c[2] * self.gs[2]
    }

    /// The doubled coordinates of grid point `p`.
    #[inline]
    fn coords(&self, p: usize) -> [usize; 3] {
        let z = self.div[2].quotient(p);
        let r = p - z * self.gs[2];
        let y = self.div[1].quotient(r);
        [r - y * self.gs[1], y, z]
    }

    /// The vertex number of grid point `p` (even coordinates).
    #[inline]
    fn vertex_of(&self, p: usize) -> usize {
        let c = self.coords(p);
        (c[0] / 2) * self.vs[0] + (c[1] / 2) * self.vs[1] + (c[2] / 2) * self.vs[2]
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

fn try_vec<T: Clone>(len: usize, value: T, what: &'static str) -> Result<Vec<T>, CubicalError> {
    let mut v = Vec::new();
    v.try_reserve_exact(len).map_err(|_| CubicalError::OutOfMemory {
        what,
        bytes: (len as u64).saturating_mul(std::mem::size_of::<T>() as u64),
    })?;
    v.resize(len, value);
    Ok(v)
}

/// A basis of the homology of the set of a box of `shape` cubes (axis 0 fastest,
/// `1 ≤ d ≤ 3`, not periodic) whose presence bytes are `bits` (non-zero: in the set): a cycle
/// per free summand, dimension by dimension, in the cells of the doubled grid. See the
/// [module docs](self). Refuses another dimension, a shape not matching `bits`, a doubled
/// grid past `u32` numbers, memory over the limit, and in 3-D a set whose sweep stops at a
/// vertex ([`CubicalError::NotReduced`]: the cubical complex's route then applies) or leaves
/// critical edges that unit pivots do not clear and that are more than
/// [`crate::generators`] takes ([`CubicalError::Generators`]). In 3-D the loops come from
/// the complement where its loops off a spanning forest are at most one per two cubes and
/// their reduction stays within a quarter of the grid's points in entries, else from the
/// sweep. O(cells · α + the length of the cycles).
pub fn cubical_generators(shape: &[usize], bits: &[u8]) -> Result<CubicalGenerators, CubicalError> {
    generators_by(shape, bits, Route::Auto)
}

/// [`cubical_generators`] with at most `pairs` eliminations between cells of dimension ≥ 1
/// in the 3-D sweep, the rest made critical (for the tests of that part; any `pairs` gives a
/// basis).
#[doc(hidden)]
pub fn cubical_generators_pairing(
    shape: &[usize],
    bits: &[u8],
    pairs: usize,
) -> Result<CubicalGenerators, CubicalError> {
    generators_by(shape, bits, Route::Sweep { pairs })
}

/// [`cubical_generators`] with the 3-D `H_1` from the complement whatever its size
/// ([`CubicalError::Internal`] where its reduction needs a pivot that is not a unit), for the
/// tests of that route.
#[doc(hidden)]
pub fn cubical_generators_tunnels(shape: &[usize], bits: &[u8]) -> Result<CubicalGenerators, CubicalError> {
    generators_by(shape, bits, Route::Tunnels)
}

/// How the 3-D `H_1` is found.
#[derive(Clone, Copy)]
enum Route {
    /// from the complement where its loops off the forest are few, else by the sweep
    Auto,
    /// by the sweep, with at most `pairs` eliminations above the vertices
    Sweep { pairs: usize },
    /// from the complement
    Tunnels,
}

fn generators_by(shape: &[usize], bits: &[u8], route: Route) -> Result<CubicalGenerators, CubicalError> {
    let d = shape.len();
    if !(1..=3).contains(&d) || shape.contains(&0) {
        return Err(CubicalError::BadShape(format!(
            "the one-pass generators take dimensions 1 to 3, not the shape {shape:?}"
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
    let bx = Box::new(shape)?;
    let mut betti = vec![0u64; d + 1];
    // H_{d-1} first: its union-find over the cubes is freed before the grid is built
    let cubes = bits.len();
    let (links, budget) = match route {
        _ if d != 3 => (None, 0),
        Route::Auto => (Some(cubes / 2), bx.grid_len() / 4),
        Route::Sweep { .. } => (None, 0),
        Route::Tunnels => (Some(usize::MAX), usize::MAX),
    };
    let Complement { boundaries: top, tree_cubes, cotree } = if d >= 2 {
        complement_boundaries(&bx, bits, links)?
    } else {
        Complement { boundaries: Vec::new(), tree_cubes: Vec::new(), cotree: None }
    };
    let mut st = try_vec(bx.grid_len(), 0u8, "the cells of the doubled grid")?;
    let cells = mark_closure(&bx, bits, &mut st);
    let euler_characteristic: i64 = cells.iter().enumerate().map(|(k, &c)| if k % 2 == 0 { c } else { -c }).sum();
    let (forest, roots) = components(&bx, &st);
    betti[0] = roots.len() as u64;
    let mut generators: Vec<CubeCycle> =
        roots.iter().map(|&p| CubeCycle { dim: 0, chain: vec![(p as u64, 1)] }).collect();
    if d == 3 {
        let from_complement = cotree.and_then(|links| tunnel_loops(&bx, &mut st, &links, budget));
        let loops = match (from_complement, route) {
            (Some(loops), _) => loops,
            (None, Route::Tunnels) => {
                return Err(CubicalError::Internal(
                    "the loops from the complement need a pivot that is not a unit".to_string(),
                ))
            }
            (None, _) => {
                // the marks of an attempt from the complement go
                for x in st.iter_mut() {
                    *x &= PRESENT;
                }
                let pairs = if let Route::Sweep { pairs } = route { pairs } else { usize::MAX };
                // the union-find's memory becomes the depths in the forest
                let mut depth = forest.into_parents();
                fill_tree_cavities(&bx, &tree_cubes, &mut st);
                loops(&bx, &mut st, &mut depth, &roots, pairs)?
            }
        };
        betti[1] = loops.len() as u64;
        generators.extend(loops);
    }
    if d >= 2 {
        betti[d - 1] = top.len() as u64;
        generators.extend(top);
    }
    let alternating: i64 =
        betti.iter().enumerate().map(|(k, &b)| if k % 2 == 0 { b as i64 } else { -(b as i64) }).sum();
    if alternating != euler_characteristic {
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
        let v = bx.cube(&c);
        if bits[v] == 0 {
            return;
        }
        let centre = bx.centre(&c) as isize;
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

/// The union-find of the present vertices over the present edges, and the grid points of
/// its roots, increasing (the smallest vertex of each component).
fn components(bx: &Box, st: &[u8]) -> (UnionFind, Vec<usize>) {
    let d = bx.d;
    let mut uf = UnionFind::new(bx.vertex_count());
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
                uf.union(v as u32, (v + bx.vs[a]) as u32);
            }
        });
    }
    let mut roots = Vec::new();
    for_each_point([0; 3], [2, 2, 2], bx.g, |c| {
        let p = bx.point(&c);
        if st[p] & PRESENT != 0 {
            let v = (c[0] / 2) * bx.vs[0] + (c[1] / 2) * bx.vs[1] + (c[2] / 2) * bx.vs[2];
            if uf.find(v as u32) == v as u32 {
                roots.push(p);
            }
        }
    });
    (uf, roots)
}

/// `H_{d-1}`: the boundaries of the bounded components of the complement (absent cubes joined
/// across shared facets), ordered by their smallest cube; and, a bit per cube, the cubes of
/// the components whose cubes and shared facets make a tree (see [`fill_tree_cavities`]).
/// With `links` (3-D), the absent cubes on the border are joined to the outside as well, and
/// the squares that joined two cubes already joined are kept for [`tunnel_loops`] while there
/// are at most `links` of them.
fn complement_boundaries(bx: &Box, bits: &[u8], links: Option<usize>) -> Result<Complement, CubicalError> {
    let d = bx.d;
    let m = bx.cube_count();
    let mut uf = UnionFind::new(m);
    // the outside, joined to the absent cubes across the box's border (for the links)
    let outside_node = uf.push();
    let mut cotree: Option<Vec<u32>> = links.map(|_| Vec::new());
    let cap = links.unwrap_or(0);
    for_each_point([0; 3], [1; 3], bx.n, |c| {
        let v = bx.cube(&c);
        if bits[v] != 0 {
            return;
        }
        let Some(list) = &mut cotree else {
            for a in 0..d {
                if c[a] + 1 < bx.n[a] && bits[v + bx.cs[a]] == 0 {
                    uf.union(v as u32, (v + bx.cs[a]) as u32);
                }
            }
            return;
        };
        let centre = bx.centre(&c);
        for a in 0..d {
            // the facet below on the border, the facet above to the next cube or the border
            let mut link = |other: u32, facet: usize| {
                if !uf.union(v as u32, other) {
                    list.push(facet as u32);
                }
            };
            if c[a] == 0 {
                link(outside_node, centre - bx.gs[a]);
            }
            if c[a] + 1 < bx.n[a] {
                if bits[v + bx.cs[a]] == 0 {
                    link((v + bx.cs[a]) as u32, centre + bx.gs[a]);
                }
            } else {
                link(outside_node, centre + bx.gs[a]);
            }
        }
        if list.len() > cap {
            cotree = None;
        }
    });
    // the classes labelled in order of their smallest cube; a class with a cube on the box's
    // border is unbounded
    let (label, classes) = uf.labels();
    drop(uf);
    let label = &label[..m];
    let mut outside = vec![0u64; classes.div_ceil(64)];
    let on_border = |c: &[usize; 3]| (0..d).any(|a| c[a] == 0 || c[a] + 1 == bx.n[a]);
    for_each_point([0; 3], [1; 3], bx.n, |c| {
        let v = bx.cube(&c);
        if bits[v] == 0 && on_border(&c) {
            let l = label[v] as usize;
            outside[l / 64] |= 1 << (l % 64);
        }
    });
    // the bounded classes numbered in the same order
    let mut number = vec![u32::MAX; classes];
    let mut sizes: Vec<usize> = Vec::new();
    // per bounded class: its cubes minus the facets they share (1 for a tree)
    let mut excess: Vec<i64> = Vec::new();
    // the facets of an absent cube v on a present neighbour, with the signs of ∂v
    let facets = |c: &[usize; 3], v: usize, f: &mut dyn FnMut(usize, i64)| {
        let p = bx.centre(c);
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
    for_each_point([0; 3], [1; 3], bx.n, |c| {
        let v = bx.cube(&c);
        if bits[v] != 0 || on_border(&c) {
            return;
        }
        let l = label[v] as usize;
        if outside[l / 64] >> (l % 64) & 1 != 0 {
            return;
        }
        if number[l] == u32::MAX {
            number[l] = sizes.len() as u32;
            sizes.push(0);
            excess.push(0);
        }
        let id = number[l] as usize;
        facets(&c, v, &mut |_, _| sizes[id] += 1);
        // the facets shared with the next cube along each axis (absent: the same class)
        excess[id] += 1 - (0..d).filter(|&a| bits[v + bx.cs[a]] == 0).count() as i64;
    });
    let mut chains: Vec<Vec<(u64, i64)>> = Vec::new();
    chains.try_reserve_exact(sizes.len()).map_err(|_| CubicalError::OutOfMemory {
        what: "the boundaries of the complement's components",
        bytes: sizes.len() as u64 * 24,
    })?;
    chains.extend(sizes.iter().map(|&n| Vec::with_capacity(n)));
    let mut tree_cubes =
        if d == 3 { try_vec(m.div_ceil(64), 0u64, "the cubes of the cavities to fill")? } else { Vec::new() };
    for_each_point([0; 3], [1; 3], bx.n, |c| {
        let v = bx.cube(&c);
        if bits[v] != 0 || on_border(&c) {
            return;
        }
        let id = number[label[v] as usize];
        if id == u32::MAX {
            return;
        }
        facets(&c, v, &mut |p, s| chains[id as usize].push((p as u64, s)));
        if d == 3 && excess[id as usize] == 1 {
            tree_cubes[v / 64] |= 1 << (v % 64);
        }
    });
    let chains = chains
        .into_iter()
        .map(|mut chain| {
            chain.sort_unstable();
            CubeCycle { dim: d - 1, chain }
        })
        .collect();
    Ok(Complement { boundaries: chains, tree_cubes, cotree })
}

/// What [`complement_boundaries`] found.
struct Complement {
    /// a basis of `H_{d-1}`
    boundaries: Vec<CubeCycle>,
    /// in 3-D, a bit per cube: the cavities to fill before the sweep
    tree_cubes: Vec<u64>,
    /// if asked and not past the cap: the facets not in X that joined two cubes (or a cube
    /// and the outside) already joined, as grid points (see [`tunnel_loops`])
    cotree: Option<Vec<u32>>,
}

/// Cell states of the doubled grid during the 3-D sweep, besides [`PRESENT`]: eliminated
/// (paired or frozen), and two 3-bit counts: the faces and the cofaces still alive (for an
/// eliminated vertex the faces' bits hold the direction of its parent in the forest).
const DEAD: u8 = 2;
const FACES_SHIFT: u8 = 2;
const COFACES_SHIFT: u8 = 5;
/// the parent direction of a root
const ROOT: u8 = 7;

#[inline]
fn faces(s: u8) -> u8 {
    (s >> FACES_SHIFT) & 7
}

#[inline]
fn cofaces(s: u8) -> u8 {
    s >> COFACES_SHIFT
}

#[inline]
fn with_faces(s: u8, c: u8) -> u8 {
    (s & !(7 << FACES_SHIFT)) | (c << FACES_SHIFT)
}

#[inline]
fn with_cofaces(s: u8, c: u8) -> u8 {
    (s & !(7 << COFACES_SHIFT)) | (c << COFACES_SHIFT)
}

#[inline]
fn alive(s: u8) -> bool {
    s & (PRESENT | DEAD) == PRESENT
}

/// The faces of grid point `p` (coordinates `c`): its two neighbours along each odd axis,
/// `f(q, a, x)` with the face's point, the axis it lies along from `p` and its coordinate
/// there.
#[inline]
fn for_faces(bx: &Box, c: &[usize; 3], p: usize, mut f: impl FnMut(usize, usize, usize)) {
    for a in 0..bx.d {
        if c[a] % 2 == 1 {
            f(p - bx.gs[a], a, c[a] - 1);
            f(p + bx.gs[a], a, c[a] + 1);
        }
    }
}

/// The cofaces of grid point `p` within the grid: its neighbours along each even axis,
/// `f(q, a, x)` as for [`for_faces`].
#[inline]
fn for_cofaces(bx: &Box, c: &[usize; 3], p: usize, mut f: impl FnMut(usize, usize, usize)) {
    for a in 0..bx.d {
        if c[a].is_multiple_of(2) {
            if c[a] > 0 {
                f(p - bx.gs[a], a, c[a] - 1);
            }
            if c[a] + 1 < bx.g[a] {
                f(p + bx.gs[a], a, c[a] + 1);
            }
        }
    }
}

/// The coordinates `c` with `x` along axis `a`.
#[inline]
fn moved(c: &[usize; 3], a: usize, x: usize) -> [usize; 3] {
    let mut n = *c;
    n[a] = x;
    n
}

#[inline]
fn dim_of(c: &[usize; 3]) -> usize {
    c.iter().filter(|&&x| x % 2 == 1).count()
}

/// The level of the cell at coordinates `c`: the largest over its odd axes of
/// `trailing_zeros(x + 1)`, x its lower end along the axis (an edge of level l lies inside an
/// aligned block of `2^(l+1)` vertices per axis, in none smaller).
#[inline]
fn level(c: &[usize; 3]) -> usize {
    axis_level(c[0]).max(axis_level(c[1])).max(axis_level(c[2]))
}

/// A coordinate's share of [`level`]: `trailing_zeros(x / 2 + 1)` if odd, else 0.
#[inline]
fn axis_level(x: usize) -> usize {
    if x % 2 == 1 {
        (x / 2 + 1).trailing_zeros() as usize
    } else {
        0
    }
}

/// `∂[e, q]`: the coefficient of edge `e` in the boundary of the square at `q` (coordinates
/// `cq`): along its first odd axis the upper face +1, along its second −1, the lower ones the
/// opposite.
#[inline]
fn square_sign(bx: &Box, cq: &[usize; 3], q: usize, e: usize) -> i64 {
    let first = (0..bx.d).find(|&a| cq[a] % 2 == 1).unwrap_or(0);
    let upper = e > q;
    let along_first = e.abs_diff(q) == bx.gs[first];
    match (along_first, upper) {
        (true, true) | (false, false) => 1,
        _ => -1,
    }
}

/// The cells waiting for the sweep, in this order: vertices (lowest point first); edges with
/// one alive face (their coreductions grow the forest), lowest level first, so that the
/// forest grows inside small blocks before it crosses larger ones and its paths stay short;
/// edges with one alive coface, then squares, highest level first (an edge left over is a
/// cycle of its own, lifted through the forest: those paired away first are the ones whose
/// paths would be long); cubes (lowest point first). Within a level, first come first.
struct Waiting {
    /// vertices and cubes, a bit per grid point
    bits: [Vec<u64>; 2],
    cursor: [usize; 2],
    pending: [usize; 2],
    /// per level: edges to coreduce, edges to collapse, squares
    grow: Vec<VecDeque<u32>>,
    collapse: Vec<VecDeque<u32>>,
    squares: Vec<VecDeque<u32>>,
    /// per kind (grow, collapse, squares): a bit per level whose queue is not empty, so that
    /// a pop finds its level in one instruction instead of a scan of the 64 queues
    nonempty: [u64; 3],
    /// the cell a few pops after the last one in its queue, if any: its state is read in
    /// ahead of time (the queues jump all over the grid)
    ahead: usize,
}

impl Waiting {
    fn new(len: usize) -> Result<Self, CubicalError> {
        let w = len.div_ceil(64);
        let v = || try_vec(w, 0u64, "the sweep's waiting cells");
        let levels = || (0..usize::BITS).map(|_| VecDeque::new()).collect::<Vec<_>>();
        Ok(Waiting {
            bits: [v()?, v()?],
            cursor: [0; 2],
            pending: [0; 2],
            grow: levels(),
            collapse: levels(),
            squares: levels(),
            nonempty: [0; 3],
            ahead: usize::MAX,
        })
    }

    /// Queues the cell at `p` (coordinates `c`), ready `by_faces` (one alive face) or by its
    /// cofaces.
    #[inline]
    /// The cell at `p`, of dimension `k` and [`level`] `l`.
    fn push(&mut self, k: usize, l: usize, p: usize, by_faces: bool) {
        let queue = |me: &mut Self, kind: usize| {
            me.nonempty[kind] |= 1 << l;
            let q = match kind {
                0 => &mut me.grow[l],
                1 => &mut me.collapse[l],
                _ => &mut me.squares[l],
            };
            q.push_back(p as u32);
        };
        match k {
            1 if by_faces => queue(self, 0),
            1 => queue(self, 1),
            2 => queue(self, 2),
            _ => {
                let i = usize::from(k == 3);
                let (w, b) = (p / 64, 1u64 << (p % 64));
                if self.bits[i][w] & b == 0 {
                    self.bits[i][w] |= b;
                    self.pending[i] += 1;
                    self.cursor[i] = self.cursor[i].min(w);
                }
            }
        }
    }

    fn pop(&mut self) -> Option<usize> {
        if self.pending[0] > 0 {
            return Some(self.pop_bit(0));
        }
        // grow: the lowest level first; collapse and squares: the highest
        for kind in 0..3 {
            let m = self.nonempty[kind];
            if m == 0 {
                continue;
            }
            let l = if kind == 0 { m.trailing_zeros() } else { 63 - m.leading_zeros() } as usize;
            let q = match kind {
                0 => &mut self.grow[l],
                1 => &mut self.collapse[l],
                _ => &mut self.squares[l],
            };
            let p = q.pop_front().map(|p| p as usize);
            self.ahead = q.get(AHEAD).map_or(usize::MAX, |&a| a as usize);
            if q.is_empty() {
                self.nonempty[kind] &= !(1 << l);
            }
            return p;
        }
        (self.pending[1] > 0).then(|| self.pop_bit(1))
    }

    /// The lowest waiting point of `bits[i]` (one is waiting).
    fn pop_bit(&mut self, i: usize) -> usize {
        let bits = &mut self.bits[i];
        let mut w = self.cursor[i];
        while bits[w] == 0 {
            w += 1;
        }
        let b = bits[w].trailing_zeros() as usize;
        bits[w] &= bits[w] - 1;
        self.cursor[i] = w;
        self.pending[i] -= 1;
        w * 64 + b
    }
}

/// How many cells ahead of the sweep's pops their states are read in.
const AHEAD: usize = 8;

/// What the 3-D sweep keeps of the edges it had to make critical: their rows of `∂_2` on the
/// squares still standing (the fill of later coreductions included).
#[derive(Default)]
struct Frozen {
    /// the frozen edges, as grid points
    edges: Vec<usize>,
    /// per square with an entry in a frozen row: `(frozen edge number, coefficient)`
    rows: rustc_hash::FxHashMap<usize, Vec<(u32, i64)>>,
}

impl Frozen {
    /// `rows[target] -= lambda · source` (sorted by frozen edge, zeros dropped).
    fn subtract(&mut self, target: usize, lambda: i64, source: &[(u32, i64)]) -> Result<(), CubicalError> {
        let overflow = || CubicalError::Internal("a coefficient of the sweep's fill overflows".to_string());
        let row = self.rows.entry(target).or_default();
        if source.len() * 8 < row.len() {
            subtract_in_place(row, lambda, source, &mut |_| {}).ok_or_else(overflow)?;
        } else {
            *row = minus_multiple(row, lambda, source).ok_or_else(overflow)?.0;
        }
        if row.is_empty() {
            self.rows.remove(&target);
        }
        Ok(())
    }
}

/// Marks present, for the sweep of `H_1`, the cubes and shared facets of the cavities whose
/// cubes and shared facets make a tree (`tree_cubes`, from [`complement_boundaries`]): a
/// single cube among six of the set, two cubes in a row, an L, … Such a cavity C has no edge
/// with its four cubes in C (they would close a cycle of four cubes), hence no vertex with its
/// eight: every edge and vertex of its closure is already in X, so X ∪ C̄ has the same
/// 1-skeleton and its cycles of edges are chains of X. The open C retracts onto its tree, so
/// `H^1(C) = 0`, and by Alexander duality (natural in the inclusion) `H_1(X) → H_1(X ∪ C̄)`
/// is an isomorphism: a basis found in X ∪ C̄ is one of X. The filled cavity collapses
/// through its cubes instead of stalling the sweep on its skin. (`H_2` is read before, from
/// the complement.)
fn fill_tree_cavities(bx: &Box, tree_cubes: &[u64], st: &mut [u8]) {
    let marked = |v: usize| tree_cubes[v / 64] >> (v % 64) & 1 != 0;
    for (w, &word) in tree_cubes.iter().enumerate() {
        let mut rest = word;
        while rest != 0 {
            let v = w * 64 + rest.trailing_zeros() as usize;
            rest &= rest - 1;
            let c = bx.cube_coords(v);
            let p = bx.centre(&c);
            st[p] |= PRESENT;
            // a facet shared with the next cube along an axis, when that cube is marked (both
            // absent and face to face: the same cavity)
            for a in 0..3 {
                if marked(v + bx.cs[a]) {
                    st[p + bx.gs[a]] |= PRESENT;
                }
            }
        }
    }
}

/// `H_1` of a 3-D set from its complement, when the complement is the sparser side: the loops
/// around the tunnels and rings of absent cubes. K, the box's cubes, is contractible, so
/// `∂: H_2(K, X) → H_1(X)` is an isomorphism, and a basis of `H_1(X)` is the boundaries of a
/// basis of the relative 2-cycles: chains of squares not in X whose boundary has no edge
/// outside X. In the relative chains the boundaries of the absent cubes are the stars of the
/// graph whose nodes are the absent cubes and the outside, and whose links are the squares not
/// in X (between two absent cubes, or on the box's border); a spanning forest of that graph
/// (`cotree`: the links that joined nothing, from [`complement_boundaries`]) makes every class
/// modulo those stars a unique chain of the links off the forest, so the relative cycles
/// modulo boundaries are the kernel of M, the boundary of those links on the edges not in X.
/// A link with all four edges in X is a basis element on its own, its boundary a loop of four
/// edges around the tunnel. The others are reduced: a row of M with one entry left forces its
/// column out of the kernel (peeled, repeatedly); the rest by column reduction with unit
/// pivots, each column that reaches zero giving the combination of squares it took. `None`
/// where a pivot is not a unit or the reduction outgrows `budget` entries (the sweep then
/// decides). O(links + the reduction).
fn tunnel_loops(bx: &Box, st: &mut [u8], cotree: &[u32], budget: usize) -> Option<Vec<CubeCycle>> {
    // the four edges of the square at q, with their coefficients in ∂q
    let edges_of = |q: usize| {
        let c = bx.coords(q);
        let mut out = [(0usize, 0i64); 4];
        let mut i = 0;
        for_faces(bx, &c, q, |e, _, _| {
            out[i] = (e, square_sign(bx, &c, q, e));
            i += 1;
        });
        out
    };
    let outside_x = |s: u8| s & PRESENT == 0;
    let mut out = Vec::new();
    // the links with an edge outside X are the columns of M, marked LIVE on the grid; each
    // edge outside X counts its live columns (cells outside X have their bytes free)
    let mut columns = 0usize;
    for &q in cotree {
        let q = q as usize;
        let edges = edges_of(q);
        if edges.iter().all(|&(e, _)| !outside_x(st[e])) {
            let mut chain: Vec<(u64, i64)> = edges.iter().map(|&(e, k)| (e as u64, k)).collect();
            chain.sort_unstable();
            out.push(CubeCycle { dim: 1, chain });
            continue;
        }
        st[q] |= LIVE;
        columns += 1;
        for (e, _) in edges {
            if outside_x(st[e]) {
                st[e] += ROW_ONE;
            }
        }
    }
    if columns == 0 {
        return Some(out);
    }
    // peeling: a row with one live column puts that column out of the kernel
    let row_count = |s: u8| s >> ROW_SHIFT;
    let mut single: Vec<usize> = Vec::new();
    for &q in cotree {
        let q = q as usize;
        if st[q] & LIVE != 0 {
            single.extend(edges_of(q).iter().map(|x| x.0).filter(|&e| outside_x(st[e]) && row_count(st[e]) == 1));
        }
    }
    while let Some(e) = single.pop() {
        if row_count(st[e]) != 1 {
            continue;
        }
        let mut square = usize::MAX;
        for_cofaces(bx, &bx.coords(e), e, |q, _, _| {
            if st[q] & LIVE != 0 {
                square = q;
            }
        });
        if square == usize::MAX {
            return None;
        }
        st[square] &= !LIVE;
        for (e2, _) in edges_of(square) {
            if outside_x(st[e2]) {
                st[e2] -= ROW_ONE;
                if row_count(st[e2]) == 1 {
                    single.push(e2);
                }
            }
        }
    }
    // the core: column reduction with unit pivots, the pivots' columns and combinations kept
    // end to end
    let mut pivot_of: rustc_hash::FxHashMap<u32, u32> = rustc_hash::FxHashMap::default();
    let (mut kept_r, mut kept_v): (Column, Column) = (Vec::new(), Vec::new());
    let (mut ends_r, mut ends_v): (Vec<usize>, Vec<usize>) = (vec![0], vec![0]);
    let mut spent = 0usize;
    for &q in cotree {
        let q = q as usize;
        if st[q] & LIVE == 0 {
            continue;
        }
        st[q] &= !LIVE;
        let mut r: Column =
            edges_of(q).iter().filter(|&&(e, _)| outside_x(st[e])).map(|&(e, k)| (e as u32, k)).collect();
        r.sort_unstable();
        let mut v: Column = vec![(q as u32, 1)];
        while let Some(&(low, value)) = r.last() {
            let Some(&i) = pivot_of.get(&low) else { break };
            let i = i as usize;
            let ri = &kept_r[ends_r[i]..ends_r[i + 1]];
            let factor = value.checked_mul(ri.last()?.1)?;
            r = minus_multiple(&r, factor, ri)?.0;
            v = minus_multiple(&v, factor, &kept_v[ends_v[i]..ends_v[i + 1]])?.0;
            spent = spent.checked_add(r.len() + v.len())?;
            if spent + kept_r.len() + kept_v.len() > budget {
                return None;
            }
        }
        match r.last() {
            None => {
                // a relative cycle: its boundary is a loop of X
                let mut chain = Vec::new();
                for &(q, k) in &v {
                    for (e, s) in edges_of(q as usize) {
                        chain.push((e as u64, s.checked_mul(k)?));
                    }
                }
                let chain = merged(chain);
                if chain.iter().any(|&(e, _)| outside_x(st[e as usize])) {
                    return None;
                }
                out.push(CubeCycle { dim: 1, chain });
            }
            Some(&(low, value)) => {
                if value.abs() != 1 {
                    return None;
                }
                pivot_of.insert(low, (ends_r.len() - 1) as u32);
                kept_r.extend_from_slice(&r);
                kept_v.extend_from_slice(&v);
                ends_r.push(kept_r.len());
                ends_v.push(kept_v.len());
                if spent + kept_r.len() + kept_v.len() > budget {
                    return None;
                }
            }
        }
    }
    Some(out)
}

/// [`tunnel_loops`]' marks on the cells outside X: a square whose column is live, and per
/// edge the count of its live columns (at most 4).
const LIVE: u8 = 2;
const ROW_SHIFT: u8 = 2;
const ROW_ONE: u8 = 1 << ROW_SHIFT;

/// `H_1` of a 3-D set: collapses and coreductions over all the cells, from one vertex set
/// aside per component (Mrozek and Batko's coreductions with collapses, as the sweep of
/// [`crate::generators`] does on a chain complex, here on the grid itself). A cell with one
/// alive face is paired with it, a cell with one alive coface with that, in the order of
/// [`Waiting`]. A vertex paired with an edge by a
/// coreduction records the edge's other end as its parent (already eliminated: set aside,
/// or paired the same way), so those pairs make a forest rooted at the set-aside vertices.
///
/// When no cell is ready the lowest cell of the lowest dimension with an alive face or
/// coface is made critical (frozen): an edge keeps its row of `∂_2` on the squares still
/// standing, updated by the later coreductions of edges into squares (the fill); squares
/// and cubes need nothing for `H_1`. At the end the edges never paired are cycles on no
/// square, a basis element each; the frozen edges and the squares with entries in their rows
/// make a small complex whose `H_1` comes from [`frozen_loops`]. Every cycle is lifted
/// to X through the forest: an edge becomes its fundamental cycle. A vertex that would have
/// to be frozen is refused ([`CubicalError::NotReduced`]). `pairs` bounds the eliminations
/// between cells of dimension ≥ 1 (tests of the frozen part).
fn loops(
    bx: &Box,
    st: &mut [u8],
    depth: &mut [u32],
    roots: &[usize],
    mut pairs: usize,
) -> Result<Vec<CubeCycle>, CubicalError> {
    let mut waiting = Waiting::new(bx.grid_len())?;
    for_each_point([0; 3], [1; 3], bx.g, |c| {
        let p = bx.point(&c);
        if st[p] & PRESENT == 0 {
            return;
        }
        let mut k = 0u8;
        for_cofaces(bx, &c, p, |q, _, _| k += st[q] & PRESENT);
        st[p] = with_cofaces(with_faces(st[p], 2 * dim_of(&c) as u8), k);
        if k == 1 {
            waiting.push(dim_of(&c), level(&c), p, false);
        }
    });
    // a cell no longer alive: its alive faces lose a coface, its alive cofaces a face
    let release = |st: &mut [u8], waiting: &mut Waiting, y: usize| {
        let c = bx.coords(y);
        let k = dim_of(&c);
        let la = [axis_level(c[0]), axis_level(c[1]), axis_level(c[2])];
        // the level of the neighbour at x along axis a
        let level_with = |a: usize, x: usize| {
            let others = match a {
                0 => la[1].max(la[2]),
                1 => la[0].max(la[2]),
                _ => la[0].max(la[1]),
            };
            others.max(axis_level(x))
        };
        for_faces(bx, &c, y, |x, a, v| {
            if alive(st[x]) {
                let n = cofaces(st[x]) - 1;
                st[x] = with_cofaces(st[x], n);
                if n == 1 {
                    waiting.push(k - 1, level_with(a, v), x, false);
                }
            }
        });
        for_cofaces(bx, &c, y, |z, a, v| {
            if alive(st[z]) {
                let n = faces(st[z]) - 1;
                st[z] = with_faces(st[z], n);
                if n == 1 {
                    waiting.push(k + 1, level_with(a, v), z, true);
                }
            }
        });
    };
    for &r in roots {
        st[r] = with_faces(st[r] | DEAD, ROOT);
        depth[bx.vertex_of(r)] = 0;
        release(st, &mut waiting, r);
    }
    let mut frozen = Frozen::default();
    // where the search for a cell to freeze goes on, per dimension (cells only lose entries)
    let mut scan = [0usize; 4];
    loop {
        let p = match waiting.pop() {
            Some(p) => p,
            None => {
                // nothing ready: freeze the lowest cell with entries of the lowest dimension
                let Some((k, p)) = next_with_entries(bx, st, &mut scan) else { break };
                match k {
                    0 => {
                        return Err(CubicalError::NotReduced(format!(
                            "the sweep of the cells stopped at the vertex at grid point {p}"
                        )))
                    }
                    1 => {
                        let c = bx.coords(p);
                        let id = frozen.edges.len() as u32;
                        for_cofaces(bx, &c, p, |q, a, v| {
                            if alive(st[q]) {
                                let sign = square_sign(bx, &moved(&c, a, v), q, p);
                                frozen.rows.entry(q).or_default().push((id, sign));
                            }
                        });
                        frozen.edges.push(p);
                    }
                    _ => {}
                }
                st[p] |= DEAD;
                release(st, &mut waiting, p);
                continue;
            }
        };
        let a = waiting.ahead;
        if a != usize::MAX {
            prefetch(st, a);
            prefetch(st, a.wrapping_sub(bx.gs[1]));
            prefetch(st, a + bx.gs[1]);
            prefetch(st, a.wrapping_sub(bx.gs[2]));
            prefetch(st, a + bx.gs[2]);
        }
        let s = st[p];
        if !alive(s) || (faces(s) != 1 && cofaces(s) != 1) {
            continue;
        }
        let c = bx.coords(p);
        let k = dim_of(&c);
        let coreduction = faces(s) == 1;
        if (k >= 2 || (k == 1 && !coreduction)) && pairs == 0 {
            continue;
        }
        let (lower, upper) = if coreduction {
            let mut a = p;
            for_faces(bx, &c, p, |x, _, _| {
                if alive(st[x]) {
                    a = x;
                }
            });
            (a, p)
        } else {
            let mut b = p;
            for_cofaces(bx, &c, p, |z, _, _| {
                if alive(st[z]) {
                    b = z;
                }
            });
            (p, b)
        };
        if dim_of(&bx.coords(lower)) >= 1 {
            pairs -= 1;
        }
        match (k, coreduction) {
            (1, true) => {
                // a vertex paired with its edge: its parent is the edge's other end
                let u = 2 * p - lower;
                let axis = (0..bx.d).find(|&b| c[b] % 2 == 1).unwrap_or(0);
                depth[bx.vertex_of(lower)] = depth[bx.vertex_of(u)] + 1;
                st[lower] = with_faces(st[lower], 2 * axis as u8 + u8::from(u > lower));
            }
            (2, true) => {
                // an edge into a square: the squares on the edge take the square's entries
                // in the frozen rows
                if let Some(source) = frozen.rows.remove(&upper) {
                    let eps = square_sign(bx, &c, upper, lower);
                    let ce = bx.coords(lower);
                    let mut others = Vec::new();
                    for_cofaces(bx, &ce, lower, |q, a, v| {
                        if q != upper && alive(st[q]) {
                            others.push((q, moved(&ce, a, v)));
                        }
                    });
                    for (q, cq) in others {
                        let alpha = square_sign(bx, &cq, q, lower);
                        frozen.subtract(q, alpha * eps, &source)?;
                    }
                }
            }
            _ => {}
        }
        // a square paired away takes its column with it
        if !frozen.rows.is_empty() {
            for y in [lower, upper] {
                if dim_of(&bx.coords(y)) == 2 {
                    frozen.rows.remove(&y);
                }
            }
        }
        st[lower] |= DEAD;
        st[upper] |= DEAD;
        release(st, &mut waiting, lower);
        release(st, &mut waiting, upper);
    }
    // the edges never paired nor frozen: a basis element each, their cycles walked
    // `WALKS` at a time
    let mut out = Vec::new();
    let mut batch = Vec::with_capacity(WALKS);
    let mut start = [0usize; 3];
    for a in 0..bx.d {
        start[a] = 1;
        for_each_point(start, [2; 3], bx.g, |c| {
            let e = bx.point(&c);
            if alive(st[e]) {
                batch.push(e);
                if batch.len() == WALKS {
                    fundamental_cycles(bx, st, depth, &batch, &mut out);
                    batch.clear();
                }
            }
        });
        start[a] = 0;
    }
    fundamental_cycles(bx, st, depth, &batch, &mut out);
    if !frozen.edges.is_empty() {
        out.extend(frozen_loops(bx, st, depth, &frozen)?);
    }
    Ok(out)
}

/// The lowest alive cell of the lowest dimension with an alive face or coface, from the
/// scan's positions on.
fn next_with_entries(bx: &Box, st: &[u8], scan: &mut [usize; 4]) -> Option<(usize, usize)> {
    for k in 0..4 {
        while scan[k] < st.len() {
            let p = scan[k];
            let s = st[p];
            if alive(s) && (faces(s) > 0 || cofaces(s) > 0) && dim_of(&bx.coords(p)) == k {
                return Some((k, p));
            }
            scan[k] += 1;
        }
    }
    None
}

/// The cycles of the frozen part: the complex `C_2 → C_1 → 0` of the squares with entries in
/// the frozen rows and the frozen edges. Its `H_1` is the cokernel of `∂_2`: where
/// [`cokernel_by_unit_pivots`] clears every column, the edges it leaves are a basis;
/// otherwise the complex goes to [`crate::generators::generators`] (dense past its cells with
/// entries: limited). Each cycle found, a sum of frozen edges, is lifted to the sum of their
/// fundamental cycles.
fn frozen_loops(bx: &Box, st: &[u8], depth: &[u32], frozen: &Frozen) -> Result<Vec<CubeCycle>, CubicalError> {
    let mut squares: Vec<&usize> = frozen.rows.keys().collect();
    squares.sort_unstable();
    let columns: Vec<Vec<(u32, i64)>> = squares.iter().map(|q| frozen.rows[*q].clone()).collect();
    let bad = |what: String| CubicalError::Internal(what);
    let n = frozen.edges.len();
    // most often unit pivots clear every column: the edges left are a basis, no dense stage
    if let Some(free) = cokernel_by_unit_pivots(n, columns.clone()) {
        return Ok(free
            .into_iter()
            .map(|i| {
                let mut chain = Vec::new();
                fundamental_cycle(bx, st, depth, frozen.edges[i as usize], 1, &mut chain);
                CubeCycle { dim: 1, chain: merged(chain) }
            })
            .collect());
    }
    let d2 = SparseMatrix::try_from_columns(n, &columns).map_err(|e| bad(e.to_string()))?;
    let complex = ChainComplex::try_new_unchecked_dd(vec![0, n, squares.len()], vec![SparseMatrix::zeros(0, n), d2])
        .map_err(|e| bad(e.to_string()))?;
    // past its limits the reduced complex's route would stop the same way, after building
    // the whole complex: refused here, with the reason
    let found = crate::generators::generators(&complex, None).map_err(|e| match e {
        crate::HomologyError::Internal(what) => bad(format!("the part of the sweep made critical: {what}")),
        e => CubicalError::Generators(e),
    })?;
    let mut out = Vec::new();
    for g in found.into_iter().filter(|g| g.dim == 1) {
        if g.order != 0 {
            return Err(bad("torsion in H_1 of a cubical set of dimension 3".to_string()));
        }
        let mut chain = Vec::new();
        for &(i, coef) in &g.chain {
            fundamental_cycle(bx, st, depth, frozen.edges[i as usize], coef, &mut chain);
        }
        out.push(CubeCycle { dim: 1, chain: merged(chain) });
    }
    Ok(out)
}

/// A basis of `Z^n / ⟨columns⟩` made of unit vectors, when elimination with pivots ±1 clears
/// every column: the rows never chosen as a pivot. A pivot `(e, u)` of a column c, `u = ±1`,
/// says `e ≡ −u·(c − u·e)` modulo the columns, so `e` is dropped from the generators and
/// from every other column (`c' −= u·c'[e]·c`: unimodular, the quotient unchanged); a
/// column left without a unit entry, or a coefficient past `i64`, gives `None` (the dense
/// stage of [`crate::generators`] then decides). The pivot of a column is its unit entry in
/// the fewest other columns, which keeps the fill small. `columns`: `(row, coefficient)`,
/// rows below `n`, increasing.
fn cokernel_by_unit_pivots(n: usize, mut columns: Vec<Column>) -> Option<Vec<u32>> {
    // the columns each row has an entry in (some no longer: checked when used)
    let mut rows: Vec<Vec<u32>> = vec![Vec::new(); n];
    for (j, c) in columns.iter().enumerate() {
        for &(e, _) in c {
            rows[e as usize].push(j as u32);
        }
    }
    let mut pivot = vec![false; n];
    // first the columns of one entry, and those that come down to one: each drops its row
    // from the other columns and lengthens none (on the 52,632 critical edges of 256³ at
    // density 0.7: 2.2–2.3 s against 2.4–2.6 s without; taking the columns of two entries
    // early as well was slower)
    let mut single: Vec<usize> = (0..columns.len()).filter(|&j| columns[j].len() == 1).collect();
    while let Some(j) = single.pop() {
        if columns[j].len() == 1 {
            pivot_out(j, &mut columns, &mut rows, &mut pivot, &mut |k, len| {
                if len == 1 {
                    single.push(k)
                }
            })?;
        }
    }
    let mut waiting: Vec<usize> = (0..columns.len()).rev().collect();
    let mut deferred = Vec::new();
    let mut progress = true;
    while progress {
        progress = false;
        while let Some(j) = waiting.pop() {
            if columns[j].is_empty() {
                continue;
            }
            if pivot_out(j, &mut columns, &mut rows, &mut pivot, &mut |_, _| {})? {
                progress = true;
            } else {
                deferred.push(j);
            }
        }
        waiting.append(&mut deferred);
    }
    waiting.iter().all(|&j| columns[j].is_empty()).then(|| (0..n as u32).filter(|&e| !pivot[e as usize]).collect())
}

/// One step of [`cokernel_by_unit_pivots`]: column `j` on its unit entry `(e, u)` in the
/// fewest other columns (`rows[e]`, some no longer: checked here) is taken out, and `e` from
/// every other column; `changed(k, length)` hears of each column changed. `Some(false)`: no
/// unit entry, nothing done; `None` past `i64`.
fn pivot_out(
    j: usize,
    columns: &mut [Column],
    rows: &mut [Vec<u32>],
    pivot: &mut [bool],
    changed: &mut dyn FnMut(usize, usize),
) -> Option<bool> {
    let unit = columns[j].iter().filter(|x| x.1.abs() == 1).min_by_key(|x| rows[x.0 as usize].len());
    let Some(&(e, u)) = unit else { return Some(false) };
    let source = std::mem::take(&mut columns[j]);
    pivot[e as usize] = true;
    for k in std::mem::take(&mut rows[e as usize]) {
        let k = k as usize;
        let Ok(at) = columns[k].binary_search_by_key(&e, |x| x.0) else { continue };
        let factor = columns[k][at].1.checked_mul(u)?;
        if source.len() * 8 < columns[k].len() {
            // a short source into a long column: edited in place, entry by entry
            subtract_in_place(&mut columns[k], factor, &source, &mut |r| rows[r as usize].push(k as u32))?;
        } else {
            let (sum, new_rows) = minus_multiple(&columns[k], factor, &source)?;
            for r in new_rows {
                rows[r as usize].push(k as u32);
            }
            columns[k] = sum;
        }
        changed(k, columns[k].len());
    }
    Some(true)
}

/// A sparse column: `(row, coefficient)`, rows increasing.
type Column = Vec<(u32, i64)>;

/// `target −= factor·source` (both sorted by row), zeros dropped, by a binary search and an
/// insertion or removal per entry of `source` (for a source much shorter than the target);
/// `new_row(r)` hears of each row the target had not. `None` past `i64`.
fn subtract_in_place(
    target: &mut Column,
    factor: i64,
    source: &[(u32, i64)],
    new_row: &mut dyn FnMut(u32),
) -> Option<()> {
    let mut from = 0;
    for &(r, v) in source {
        let delta = factor.checked_mul(v)?;
        match target[from..].binary_search_by_key(&r, |x| x.0) {
            Ok(i) => {
                let at = from + i;
                let value = target[at].1.checked_sub(delta)?;
                if value == 0 {
                    target.remove(at);
                    from = at;
                } else {
                    target[at].1 = value;
                    from = at + 1;
                }
            }
            Err(i) => {
                let at = from + i;
                target.insert(at, (r, delta.checked_neg()?));
                new_row(r);
                from = at + 1;
            }
        }
    }
    Some(())
}

/// `target − factor·source` (both sorted by row) without its zeros, and the rows it has that
/// `target` had not; `None` past `i64`.
fn minus_multiple(target: &[(u32, i64)], factor: i64, source: &[(u32, i64)]) -> Option<(Column, Vec<u32>)> {
    let mut out = Vec::with_capacity(target.len() + source.len());
    let mut new_rows = Vec::new();
    let (mut i, mut j) = (0, 0);
    while i < target.len() || j < source.len() {
        if j == source.len() || (i < target.len() && target[i].0 < source[j].0) {
            out.push(target[i]);
            i += 1;
        } else if i == target.len() || source[j].0 < target[i].0 {
            new_rows.push(source[j].0);
            out.push((source[j].0, factor.checked_mul(source[j].1)?.checked_neg()?));
            j += 1;
        } else {
            let v = target[i].1.checked_sub(factor.checked_mul(source[j].1)?)?;
            if v != 0 {
                out.push((target[i].0, v));
            }
            i += 1;
            j += 1;
        }
    }
    Some((out, new_rows))
}

/// The vertex one step up the forest from vertex `x`, the edge between them, and the edge's
/// coefficient when walked that way.
#[inline]
fn step_up(bx: &Box, st: &[u8], x: usize) -> (usize, usize, i64) {
    let dir = faces(st[x]) as usize;
    let (a, up) = (dir / 2, dir % 2 == 1);
    let s = bx.gs[a];
    if up {
        (x + 2 * s, x + s, 1)
    } else {
        (x - 2 * s, x - s, -1)
    }
}

/// `sign` times the edge at grid point `e` plus the path of the forest between its ends: a
/// cycle of X, added to `out`.
fn fundamental_cycle(bx: &Box, st: &[u8], depth: &[u32], e: usize, sign: i64, out: &mut Vec<(u64, i64)>) {
    let mut walk = Walk::new(bx, depth, e, sign, out);
    while walk.step(bx, st, out) {}
}

/// The walk of a fundamental cycle up the forest: the two ends of its edge and their depths.
struct Walk {
    x: usize,
    y: usize,
    dx: u32,
    dy: u32,
    sign: i64,
}

/// The ends of the edge at grid point `e`: `(upper, lower)`, so that `∂e = upper − lower`.
fn edge_ends(bx: &Box, e: usize) -> (usize, usize) {
    let c = bx.coords(e);
    let a = (0..bx.d).find(|&a| c[a] % 2 == 1).unwrap_or(0);
    (e + bx.gs[a], e - bx.gs[a])
}

impl Walk {
    /// Starts the cycle of `sign` times edge `e`, pushed to `out`.
    fn new(bx: &Box, depth: &[u32], e: usize, sign: i64, out: &mut Vec<(u64, i64)>) -> Self {
        Walk::from_ends(bx, depth, e, edge_ends(bx, e), sign, out)
    }

    /// [`Walk::new`] with the edge's ends already found.
    fn from_ends(
        bx: &Box,
        depth: &[u32],
        e: usize,
        (x, y): (usize, usize),
        sign: i64,
        out: &mut Vec<(u64, i64)>,
    ) -> Self {
        out.push((e as u64, sign));
        // the path from the upper end to the lower one closes the cycle
        Walk { x, y, dx: depth[bx.vertex_of(x)], dy: depth[bx.vertex_of(y)], sign }
    }

    /// One step: the deeper end up, or both until they meet, their edges pushed to `out`, the
    /// next states read in ahead; `false` once the ends have met.
    #[inline]
    fn step(&mut self, bx: &Box, st: &[u8], out: &mut Vec<(u64, i64)>) -> bool {
        let (up_x, up_y) = match self.dx.cmp(&self.dy) {
            std::cmp::Ordering::Greater => (true, false),
            std::cmp::Ordering::Less => (false, true),
            std::cmp::Ordering::Equal if self.x != self.y => (true, true),
            std::cmp::Ordering::Equal => return false,
        };
        if up_x {
            let (nx, edge, k) = step_up(bx, st, self.x);
            out.push((edge as u64, self.sign * k));
            prefetch(st, nx);
            self.x = nx;
            self.dx -= 1;
        }
        if up_y {
            let (ny, edge, k) = step_up(bx, st, self.y);
            out.push((edge as u64, -self.sign * k));
            prefetch(st, ny);
            self.y = ny;
            self.dy -= 1;
        }
        true
    }
}

/// How many fundamental cycles [`fundamental_cycles`] walks in step.
const WALKS: usize = 16;

/// The fundamental cycles of `edges` (each as [`fundamental_cycle`] with sign 1, its cells
/// sorted), added to `out` in that order. The walks up the forest jump across the grid, a
/// cache miss per step on a large one: taken in step, one step of each in turn with the next
/// vertex's state read in ahead, their misses overlap.
fn fundamental_cycles(bx: &Box, st: &[u8], depth: &[u32], edges: &[usize], out: &mut Vec<CubeCycle>) {
    let ends: Vec<(usize, usize)> = edges.iter().map(|&e| edge_ends(bx, e)).collect();
    for &(x, y) in &ends {
        prefetch(depth, bx.vertex_of(x));
        prefetch(depth, bx.vertex_of(y));
    }
    let mut walks: Vec<(Walk, Vec<(u64, i64)>)> = edges
        .iter()
        .zip(&ends)
        .map(|(&e, &xy)| {
            let mut chain = Vec::new();
            (Walk::from_ends(bx, depth, e, xy, 1, &mut chain), chain)
        })
        .collect();
    let mut stepped = true;
    while stepped {
        stepped = false;
        for (walk, chain) in &mut walks {
            stepped |= walk.step(bx, st, chain);
        }
    }
    out.extend(walks.into_iter().map(|(_, mut chain)| {
        chain.sort_unstable();
        CubeCycle { dim: 1, chain }
    }));
}

/// The chain with its cells sorted, their coefficients summed and the zeros dropped.
fn merged(mut chain: Vec<(u64, i64)>) -> Vec<(u64, i64)> {
    chain.sort_unstable_by_key(|x| x.0);
    let mut out: Vec<(u64, i64)> = Vec::with_capacity(chain.len());
    for (p, c) in chain {
        match out.last_mut() {
            Some(last) if last.0 == p => last.1 += c,
            _ => out.push((p, c)),
        }
    }
    out.retain(|x| x.1 != 0);
    out
}

#[cfg(test)]
mod tests {
    use super::{cokernel_by_unit_pivots, minus_multiple, subtract_in_place};
    use proptest::prelude::*;

    /// A sorted sparse column: rows below 40, coefficients ±1 or ±2.
    fn column(len: usize) -> impl Strategy<Value = Vec<(u32, i64)>> {
        prop::collection::btree_map(0u32..40, prop::sample::select(vec![1i64, -1, 2, -2]), 0..len)
            .prop_map(|m| m.into_iter().collect())
    }

    proptest! {
        #[test]
        fn editing_a_column_in_place_equals_the_merge(
            target in column(30),
            source in column(5),
            factor in prop::sample::select(vec![1i64, -1, 2]),
        ) {
            let (merged, mut new_rows) = minus_multiple(&target, factor, &source).unwrap();
            let mut edited = target.clone();
            let mut heard = Vec::new();
            subtract_in_place(&mut edited, factor, &source, &mut |r| heard.push(r)).unwrap();
            prop_assert_eq!(edited, merged);
            new_rows.sort_unstable();
            heard.sort_unstable();
            prop_assert_eq!(heard, new_rows);
        }
    }

    #[test]
    fn editing_in_place_refuses_past_i64() {
        assert!(subtract_in_place(&mut vec![(0, i64::MIN)], 1, &[(0, 1)], &mut |_| {}).is_none());
    }

    #[test]
    fn unit_pivots_give_a_basis_of_the_cokernel() {
        // Z³ / ⟨e0 + e1, e1 − e2⟩ ≅ Z, generated by e1 (e0 and e2 are pivots: each in fewer
        // columns than e1)
        assert_eq!(cokernel_by_unit_pivots(3, vec![vec![(0, 1), (1, 1)], vec![(1, 1), (2, -1)]]), Some(vec![1]));
        // a column equal to an earlier one is cleared by it
        assert_eq!(cokernel_by_unit_pivots(2, vec![vec![(0, 1), (1, 1)], vec![(0, 1), (1, 1)]]), Some(vec![1]));
        // the fill of one pivot gives the next its unit: ⟨e0 + 2e1, e0 + 3e1⟩ is all of Z²
        assert_eq!(cokernel_by_unit_pivots(2, vec![vec![(0, 1), (1, 2)], vec![(0, 1), (1, 3)]]), Some(vec![]));
        // no relation: every row is free
        assert_eq!(cokernel_by_unit_pivots(2, vec![]), Some(vec![0, 1]));
        // Z / 2Z has torsion: no unit pivot, the dense stage decides
        assert_eq!(cokernel_by_unit_pivots(1, vec![vec![(0, 2)]]), None);
        // a column left with 2e1 after e0 is pivoted: refused the same way
        assert_eq!(cokernel_by_unit_pivots(2, vec![vec![(0, 1), (1, 1)], vec![(0, 1), (1, 3)]]), None);
        // coefficients past i64 refuse instead of wrapping
        assert_eq!(cokernel_by_unit_pivots(2, vec![vec![(0, 1), (1, i64::MAX)], vec![(0, -1), (1, i64::MAX)]]), None);
    }
}
