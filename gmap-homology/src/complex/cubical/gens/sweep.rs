//! `H_1` of a 3-D set by collapses and coreductions on the grid itself, and the fundamental
//! cycles of the forest they grow.

#![allow(clippy::needless_range_loop)] // axes index several arrays at once

use std::collections::VecDeque;

use super::cells::{
    dim_of, for_cofaces, for_each_point, for_faces, merged, moved, square_sign, try_vec, Box, CubeCycle, PRESENT,
};
use super::cokernel::{cokernel_by_unit_pivots, minus_multiple, subtract_in_place};
use crate::complex::cubical::CubicalError;
use crate::engine::chain::ChainComplex;
use crate::engine::sparse::SparseMatrix;
use crate::prefetch::prefetch;

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
pub(super) fn loops(
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
