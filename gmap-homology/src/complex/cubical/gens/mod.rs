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
//!   unit pivots (`complement::tunnel_loops`). No sweep runs, and the loops are short (four edges around
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
//! use gmap_homology::cubical::gens::cubical_generators;
//! // a ring of 8 squares around a hole: one component, one loop
//! let bits = [1, 1, 1, 1, 0, 1, 1, 1, 1];
//! let g = cubical_generators(&[3, 3], &bits).unwrap();
//! assert_eq!(g.betti, vec![1, 1, 0]);
//! // the loop is the boundary of the hole: its four edges, in the doubled grid (7 × 7 points)
//! let loop1 = &g.generators[1];
//! assert_eq!((loop1.dim, loop1.chain.len()), (1, 4));
//! ```

#![allow(clippy::needless_range_loop)] // axes index several arrays at once

mod cells;
mod cokernel;
mod complement;
mod components;
mod sweep;

pub use cells::CubeCycle;

use crate::complex::cubical::grid::{self, Placement};
use crate::complex::cubical::CubicalError;
use cells::{try_vec, Box, PRESENT};
use complement::{complement_boundaries, fill_tree_cavities, tunnel_loops, Complement};
use components::{components, mark_closure};
use sweep::loops;

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
    let grid = grid::point_count(shape, Placement::Cubes)?;
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
    let grid_points = grid::point_count(shape, Placement::Cubes);
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
