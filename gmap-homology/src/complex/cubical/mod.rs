//! The cubical chain complex of a full cubical set, built directly on flat arrays.
//!
//! A set of `L_0 × … × L_{d-1}` box cubes (a bitmap) is the union of closed unit cubes; its
//! cells are the elementary cubes of the closure, named by the points of its doubled grid
//! ([`grid`]: `2L + 1` points per axis, `2L` on a periodic axis whose ends are identified, a
//! cell odd along the axes it spans, the cube with minimal vertex `x` at `2x + 1`). The
//! boundary of a cell sums its two faces along each odd axis with the signs of
//! [`grid::face_sign`].
//!
//! The routes that need no complex, or build it piece by piece, are the modules below:
//! [`pass`] and [`torus`] (the groups of a set of dimension ≤ 3 in one pass, in a box or a
//! torus), [`gens`] (their generators), [`slabs`] (the complex reduced slab by slab) and
//! [`blocks`] (slabs reduced apart, for several processes).
//!
//! Before any matrix is built, free faces are collapsed on the grid itself (an elementary
//! collapse removes a cell with a single coface together with that coface, which keeps the
//! homology): on solid regions this removes nearly everything, so the matrices hold only the
//! cells that got stuck. [`cubical_complex_with`] can skip it (the plain complex, for checks).
//!
//! ```
//! use gmap_homology::{cubical::cubical_complex, homology_z};
//! // a ring of 8 squares around a hole
//! let bits = [1, 1, 1, 1, 0, 1, 1, 1, 1];
//! let c = cubical_complex(&[3, 3], &bits, false).unwrap();
//! assert_eq!(homology_z(&c.chain).unwrap().betti, vec![1, 1, 0]);
//! ```

#![allow(clippy::needless_range_loop)] // axes index several arrays at once

pub mod blocks;
pub mod gens;
pub mod grid;
pub mod pass;
pub mod slabs;
pub mod torus;

use thiserror::Error;

use crate::{ChainComplex, SparseMatrix};
use grid::{Grid, Order, Placement};

/// Why the cubical complex of a set could not be built.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
#[non_exhaustive]
pub enum CubicalError {
    /// The shape and the bitmap do not match, or the dimension is 0.
    #[error("bad cubical set: {0}")]
    BadShape(String),
    /// The doubled grid has too many points.
    #[error("the cubical grid of {points} cells is over the limit of {limit} cells")]
    TooLarge {
        /// points of the doubled grid (`None` past `u64`)
        points: String,
        /// the limit
        limit: u64,
    },
    /// The estimated memory is over the limit (`--max-memory`).
    #[error(transparent)]
    MemoryLimit(#[from] gmap_core::resources::MemoryLimit),
    /// A block's message (between processes) is malformed.
    #[error("bad block message: {0}")]
    BadMessage(String),
    /// A route could not reduce the set and hands it on (the generators of a 3-D set whose
    /// sweep stops at a vertex: the cubical complex's route takes it).
    #[error("{0}")]
    NotReduced(String),
    /// The generators of the part a sweep made critical could not be computed (over the
    /// limits of [`crate::generators`]).
    #[error("the edges the sweep of the cells made critical: {0}")]
    Generators(crate::HomologyError),
    /// A check of a result failed (a bug, reported rather than a wrong answer).
    #[error("internal error: {0}")]
    Internal(String),
    /// Memory could not be had.
    #[error("cannot allocate {bytes} bytes for {what}")]
    OutOfMemory {
        /// what the memory was for
        what: &'static str,
        /// the estimate
        bytes: u64,
    },
}

/// A cubical chain complex with the cells its generators stand for.
#[derive(Clone, Debug)]
pub struct CubicalComplex {
    /// the chain complex
    pub chain: ChainComplex,
    /// `cells[k][i]`: the doubled-grid point of the i-th k-cell
    pub cells: Vec<Vec<u64>>,
    /// points of the doubled grid per axis (`2L + 1`, or `2L` on periodic axes)
    pub grid: Vec<usize>,
}

impl CubicalComplex {
    /// The doubled coordinates of the i-th k-cell (odd along the axes it spans).
    pub fn coordinates(&self, k: usize, i: usize) -> Vec<usize> {
        grid::coordinates(&self.grid, Order::FirstFastest, self.cells[k][i] as usize)
    }

    /// The i-th k-cell as a product of intervals and points of the input's coordinates
    /// (`min` is the box's minimal vertex): `[0,1]x[2,3]x5`.
    pub fn cell_name(&self, k: usize, i: usize, min: &[i64]) -> String {
        let coords = self.coordinates(k, i);
        let parts: Vec<String> = coords
            .iter()
            .enumerate()
            .map(|(a, &c)| {
                let lo = min.get(a).copied().unwrap_or(0) + (c / 2) as i64;
                if c % 2 == 1 {
                    format!("[{},{}]", lo, lo + 1)
                } else {
                    lo.to_string()
                }
            })
            .collect();
        parts.join("x")
    }
}

/// The largest doubled grid (cells of the closed box) accepted.
pub const MAX_GRID_POINTS: u64 = u32::MAX as u64 - 1;

const PRESENT: u8 = 1;
const QUEUED: u8 = 2;
/// a present cell that is never collapsed (shared with another slab)
const FROZEN: u8 = 4;

/// The cubical chain complex of a set of box cubes, after collapses of free faces. `shape` is
/// the box's number of cubes per axis, `bits` one byte a cube (non-zero: in the set), axis 0
/// fastest. With `periodic` the box's opposite faces are identified (a d-torus of cubes).
pub fn cubical_complex(shape: &[usize], bits: &[u8], periodic: bool) -> Result<CubicalComplex, CubicalError> {
    cubical_complex_with(shape, bits, periodic, true)
}

/// [`cubical_complex`], with the collapses of free faces or without them (the complex of all
/// the cells of the closure).
pub fn cubical_complex_with(
    shape: &[usize],
    bits: &[u8],
    periodic: bool,
    collapse: bool,
) -> Result<CubicalComplex, CubicalError> {
    cubical_cell_complex_with(shape, bits, &[], periodic, collapse)
}

/// The cubical complex of a cubical cell complex: the closure of the cubes of `bits` (as in
/// [`cubical_complex_with`]) and of the lower cells `cells`, each given by its doubled
/// coordinates relative to the box (`2 (x_a - min_a) + e_a` along axis `a`, `e_a` 1 where the
/// cell spans the axis, 0 where it is a point), `d` coordinates a cell, each at most `2 L_a`.
/// On a periodic box the coordinate `2 L_a` is the coordinate 0 (the box's opposite faces
/// are one). O(grid points × d + cells × d).
///
/// ```
/// use gmap_homology::{cubical::cubical_cell_complex_with, homology_z};
/// // the four edges of the unit square, no square: [0,1]x0, [0,1]x1, 0x[0,1], 1x[0,1]
/// let edges = [1, 0, 1, 2, 0, 1, 2, 1];
/// let c = cubical_cell_complex_with(&[1, 1], &[0], &edges, false, false).unwrap();
/// assert_eq!(c.chain.counts(), &[4, 4, 0]);
/// assert_eq!(homology_z(&c.chain).unwrap().betti, vec![1, 1, 0]);
/// ```
pub fn cubical_cell_complex_with(
    shape: &[usize],
    bits: &[u8],
    cells: &[usize],
    periodic: bool,
    collapse: bool,
) -> Result<CubicalComplex, CubicalError> {
    let (g, mut state) = closed_grid(shape, bits, cells, periodic)?;
    if collapse {
        collapse_free_faces(&g, &mut state);
    }
    build(&g, &state)
}

/// The cubical complex of a slab of a larger box (`shape`: the slab's cubes, the last axis
/// across the cut), after collapses of the free faces that are not on a shared side: the
/// cells on the first hyperplane of the last axis (`shared_first`) and on its last one
/// (`shared_last`) are shared with the slabs beside it and never collapsed, whatever their
/// cofaces here. Not periodic.
pub(crate) fn slab_complex(
    shape: &[usize],
    bits: &[u8],
    shared_first: bool,
    shared_last: bool,
) -> Result<CubicalComplex, CubicalError> {
    let (g, mut state) = closed_grid(shape, bits, &[], false)?;
    let d = shape.len();
    let (s, last) = (g.strides()[d - 1], g.points()[d - 1] - 1);
    for (shared, c) in [(shared_first, 0), (shared_last, last)] {
        if shared {
            for x in &mut state[c * s..(c + 1) * s] {
                if *x & PRESENT != 0 {
                    *x |= FROZEN;
                }
            }
        }
    }
    collapse_free_faces(&g, &mut state);
    build(&g, &state)
}

/// The doubled grid of a box and the closure of its set and of the lower `cells` (doubled
/// coordinates relative to the box, `d` a cell): [`PRESENT`] on every cell of it.
fn closed_grid(shape: &[usize], bits: &[u8], cells: &[usize], periodic: bool) -> Result<(Grid, Vec<u8>), CubicalError> {
    let d = shape.len();
    if d == 0 || shape.contains(&0) {
        return Err(CubicalError::BadShape(format!("shape {shape:?}")));
    }
    let volume = shape.iter().try_fold(1usize, |v, &s| v.checked_mul(s));
    if volume != Some(bits.len()) {
        return Err(CubicalError::BadShape(format!("{} bytes for the shape {shape:?}", bits.len())));
    }
    let placement = if periodic { Placement::Periodic } else { Placement::Cubes };
    let g = grid::point_count(shape, placement)
        .filter(|&v| v <= MAX_GRID_POINTS)
        .and_then(|_| Grid::of_box(shape, placement, Order::FirstFastest));
    let Some(g) = g else {
        return Err(CubicalError::TooLarge { points: grid::shown(shape, placement), limit: MAX_GRID_POINTS });
    };
    // the grid, its collapse stack and its cell numbers, before any of them is allocated
    gmap_core::resources::check_memory(
        &format!("the cubical grid of {} points", grid::shown(shape, placement)),
        grid::bytes(shape, placement, gmap_core::resources::CUBICAL_BYTES_PER_POINT),
    )?;
    let len = g.len();
    let mut state: Vec<u8> = Vec::new();
    state.try_reserve_exact(len).map_err(|_| CubicalError::OutOfMemory { what: "the grid", bytes: len as u64 })?;
    state.resize(len, 0);

    if !cells.len().is_multiple_of(d) {
        return Err(CubicalError::BadShape(format!("{} cell coordinates for dimension {d}", cells.len())));
    }
    mark_cubes(shape, &g, bits, &mut state);
    let (n, stride) = (g.points(), g.strides());
    for cell in cells.chunks_exact(d) {
        let mut p = 0usize;
        for a in 0..d {
            // the closed box's last hyperplane is the first one of a periodic box
            let c = if periodic && cell[a] == n[a] { 0 } else { cell[a] };
            if c >= n[a] {
                return Err(CubicalError::BadShape(format!("the cell {cell:?} is outside the box {shape:?}")));
            }
            p += c * stride[a];
        }
        state[p] = PRESENT;
    }
    close_marked(&g, &mut state);
    Ok((g, state))
}

/// Marks [`PRESENT`] in `out` (a byte per point of the doubled grid `g` of a box of `shape`
/// cubes, axis 0 fastest) the cubes of `bits` (doubled point 2x + 1 of cube x) and every
/// face of them: their closure. A last odd coordinate of a periodic grid has its upper face
/// at 0. O(points × dimension).
pub(crate) fn mark_closure(shape: &[usize], g: &Grid, bits: &[u8], out: &mut [u8]) {
    mark_cubes(shape, g, bits, out);
    close_marked(g, out);
}

/// Marks [`PRESENT`] the cubes of `bits` (doubled point 2x + 1 of cube x). O(cubes × d).
fn mark_cubes(shape: &[usize], g: &Grid, bits: &[u8], out: &mut [u8]) {
    let d = shape.len();
    let stride = g.strides();
    let mut x = vec![0usize; d];
    for &b in bits {
        if b != 0 {
            let p: usize = (0..d).map(|a| (2 * x[a] + 1) * stride[a]).sum();
            out[p] = PRESENT;
        }
        for a in 0..d {
            x[a] += 1;
            if x[a] < shape[a] {
                break;
            }
            x[a] = 0;
        }
    }
}

/// Marks [`PRESENT`] every face of the marked cells of `out`: along each axis in turn, a
/// point with an odd coordinate marks its two faces ([`Grid::faces_along`], a row of the
/// axis's stride at a time). O(points × d).
fn close_marked(g: &Grid, out: &mut [u8]) {
    let (d, len) = (g.axes(), out.len());
    for a in 0..d {
        let (s, na) = (g.strides()[a], g.points()[a]);
        let block = s * na;
        for base in (0..len).step_by(block) {
            for c in (1..na).step_by(2) {
                let row = base + c * s;
                let up = if c + 1 == na { base } else { row + s };
                for lo in 0..s {
                    if out[row + lo] != 0 {
                        out[row - s + lo] = PRESENT;
                        out[up + lo] = PRESENT;
                    }
                }
            }
        }
    }
}

/// Elementary collapses of free faces (a present cell with exactly one present coface),
/// until none is left, on the grid itself; [`FROZEN`] cells are never collapsed. Each removal
/// queues the faces of the two cells removed, whose cofaces changed.
fn collapse_free_faces(g: &Grid, state: &mut [u8]) {
    let d = g.axes();
    let mut stack: Vec<u32> = Vec::new();
    for p in (0..g.len()).rev() {
        if state[p] & (PRESENT | FROZEN) == PRESENT {
            state[p] |= QUEUED;
            stack.push(p as u32);
        }
    }
    let mut coord = vec![0usize; d];
    while let Some(p) = stack.pop() {
        let p = p as usize;
        state[p] &= !QUEUED;
        if state[p] & (PRESENT | FROZEN) != PRESENT {
            continue;
        }
        let mut found = None;
        let mut count = 0;
        for (a, c) in coord.iter_mut().enumerate() {
            *c = g.coord(p, a);
            if c.is_multiple_of(2) {
                for q in g.cofaces_along(p, a, *c).into_iter().flatten() {
                    if state[q] & PRESENT != 0 {
                        count += 1;
                        found = Some(q);
                    }
                }
            }
        }
        if count != 1 {
            continue;
        }
        let t = found.unwrap();
        state[p] &= !PRESENT;
        state[t] &= !PRESENT;
        // faces of p and of t
        for cell in [p, t] {
            for a in 0..d {
                let c = g.coord(cell, a);
                if c % 2 == 1 {
                    let (lo, up) = g.faces_along(cell, a, c);
                    for q in [lo, up] {
                        if state[q] == PRESENT {
                            state[q] |= QUEUED;
                            stack.push(q as u32);
                        }
                    }
                }
            }
        }
    }
}

/// Numbers the present cells per dimension in grid order and builds the boundaries.
fn build(g: &Grid, state: &[u8]) -> Result<CubicalComplex, CubicalError> {
    let (d, n) = (g.axes(), g.points());
    let mut idx: Vec<u32> = Vec::new();
    idx.try_reserve_exact(g.len())
        .map_err(|_| CubicalError::OutOfMemory { what: "the cell numbers", bytes: 4 * g.len() as u64 })?;
    idx.resize(g.len(), u32::MAX);
    let mut counts = vec![0usize; d + 1];
    let mut coord = vec![0usize; d];
    let mut odd = 0usize;
    let mut cells: Vec<Vec<u64>> = vec![Vec::new(); d + 1];
    for (p, slot) in idx.iter_mut().enumerate() {
        if state[p] & PRESENT != 0 {
            *slot = counts[odd] as u32;
            counts[odd] += 1;
            cells[odd].push(p as u64);
        }
        for a in 0..d {
            coord[a] += 1;
            if coord[a] < n[a] {
                // the coordinate's parity flipped
                if coord[a] & 1 == 1 {
                    odd += 1;
                } else {
                    odd -= 1;
                }
                break;
            }
            // wrapped from n_a - 1 to 0: that coordinate was odd iff n_a is even
            if n[a].is_multiple_of(2) {
                odd -= 1;
            }
            coord[a] = 0;
        }
    }
    // the matrices: per k-cell its grid point, its column pointer and 2k entries
    let matrix_bytes = counts.iter().enumerate().try_fold(0u64, |sum, (k, &c)| {
        let per = 16u64.checked_add((2 * k as u64).checked_mul(12)?)?;
        sum.checked_add((c as u64).checked_mul(per)?)
    });
    gmap_core::resources::check_memory("the boundary matrices of the cubical complex", matrix_bytes)?;
    let mut col_ptr: Vec<Vec<usize>> = (0..=d).map(|k| Vec::with_capacity(counts[k] + 1)).collect();
    let mut rows: Vec<Vec<u32>> = (0..=d).map(|k| Vec::with_capacity(2 * k * counts[k])).collect();
    let mut vals: Vec<Vec<i64>> = (0..=d).map(|k| Vec::with_capacity(2 * k * counts[k])).collect();
    for c in col_ptr.iter_mut() {
        c.push(0);
    }
    let mut entries: Vec<(u32, i64)> = Vec::with_capacity(2 * d);
    for p in 0..g.len() {
        if state[p] & PRESENT == 0 {
            continue;
        }
        entries.clear();
        let mut k = 0usize;
        g.for_each_face(p, |lo, up, sign| {
            k += 1;
            // a periodic axis of one cube: the two faces are one, their entries cancel
            if lo != up {
                entries.push((idx[lo], -sign));
                entries.push((idx[up], sign));
            }
        });
        if k == 0 {
            continue;
        }
        entries.sort_unstable_by_key(|e| e.0);
        for &(r, v) in &entries {
            rows[k].push(r);
            vals[k].push(v);
        }
        col_ptr[k].push(rows[k].len());
    }
    let mut boundaries = Vec::with_capacity(d);
    for k in 1..=d {
        let m = SparseMatrix::try_from_csc(
            counts[k - 1],
            counts[k],
            std::mem::take(&mut col_ptr[k]),
            std::mem::take(&mut rows[k]),
            std::mem::take(&mut vals[k]),
        )
        .map_err(|e| CubicalError::BadShape(format!("internal: {e}")))?;
        boundaries.push(m);
    }
    let chain = ChainComplex::try_new_unchecked_dd(counts, boundaries)
        .map_err(|e| CubicalError::BadShape(format!("internal: {e}")))?;
    Ok(CubicalComplex { chain, cells, grid: g.points().to_vec() })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::homology_z;

    fn betti(shape: &[usize], bits: &[u8], periodic: bool) -> Vec<usize> {
        let a = cubical_complex_with(shape, bits, periodic, false).unwrap().chain;
        a.check_dd().unwrap();
        let b = cubical_complex(shape, bits, periodic).unwrap().chain;
        b.check_dd().unwrap();
        let (ha, hb) = (homology_z(&a).unwrap(), homology_z(&b).unwrap());
        assert_eq!(ha, hb);
        assert!(ha.torsion.iter().all(|t| t.is_empty()));
        ha.betti
    }

    #[test]
    fn small_sets() {
        assert_eq!(betti(&[1, 1], &[1], false), vec![1, 0, 0]);
        assert_eq!(betti(&[3, 3], &[1, 1, 1, 1, 0, 1, 1, 1, 1], false), vec![1, 1, 0]);
        assert_eq!(betti(&[2, 2], &[1, 0, 0, 1], false), vec![1, 0, 0]);
        let mut shell = vec![1u8; 27];
        shell[13] = 0;
        assert_eq!(betti(&[3, 3, 3], &shell, false), vec![1, 0, 1, 0]);
        assert_eq!(betti(&[4, 4], &[1; 16], true), vec![1, 2, 1]);
        assert_eq!(betti(&[1, 1], &[1], true), vec![1, 2, 1]);
        assert_eq!(betti(&[2, 1, 3], &[1; 6], true), vec![1, 3, 3, 1]);
        assert_eq!(betti(&[3, 2], &[0; 6], false), vec![0, 0, 0]);
    }

    #[test]
    fn random_sets_agree_with_the_plain_complex() {
        let mut s = 12345u64;
        for t in 0..40 {
            let shape = if t % 2 == 0 { vec![5, 4, 3] } else { vec![7, 6] };
            let bits: Vec<u8> = (0..shape.iter().product::<usize>())
                .map(|_| {
                    s = s.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
                    ((s >> 33) % 100 < 55) as u8
                })
                .collect();
            betti(&shape, &bits, t % 3 == 0);
        }
    }
}
