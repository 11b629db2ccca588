//! What the complement of the set gives: `H_{d-1}` as the boundaries of its bounded
//! components, the cavities filled before the sweep, and in 3-D `H_1` from its tunnels.

#![allow(clippy::needless_range_loop)] // axes index several arrays at once

use gmap_core::union_find::UnionFind;

use super::cells::{for_cofaces, for_each_point, for_faces, merged, square_sign, try_vec, Box, CubeCycle, PRESENT};
use super::cokernel::{minus_multiple, Column};
use crate::complex::cubical::CubicalError;

/// `H_{d-1}`: the boundaries of the bounded components of the complement (absent cubes joined
/// across shared facets), ordered by their smallest cube; and, a bit per cube, the cubes of
/// the components whose cubes and shared facets make a tree (see [`fill_tree_cavities`]).
/// With `links` (3-D), the absent cubes on the border are joined to the outside as well, and
/// the squares that joined two cubes already joined are kept for [`tunnel_loops`] while there
/// are at most `links` of them.
pub(super) fn complement_boundaries(bx: &Box, bits: &[u8], links: Option<usize>) -> Result<Complement, CubicalError> {
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
pub(super) struct Complement {
    /// a basis of `H_{d-1}`
    pub(super) boundaries: Vec<CubeCycle>,
    /// in 3-D, a bit per cube: the cavities to fill before the sweep
    pub(super) tree_cubes: Vec<u64>,
    /// if asked and not past the cap: the facets not in X that joined two cubes (or a cube
    /// and the outside) already joined, as grid points (see [`tunnel_loops`])
    pub(super) cotree: Option<Vec<u32>>,
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
pub(super) fn fill_tree_cavities(bx: &Box, tree_cubes: &[u64], st: &mut [u8]) {
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
pub(super) fn tunnel_loops(bx: &Box, st: &mut [u8], cotree: &[u32], budget: usize) -> Option<Vec<CubeCycle>> {
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
