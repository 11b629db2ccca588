//! Persistence of grey images: the cubical filtration of a d-dimensional array.
//!
//! ## The grid
//!
//! Cells live on a doubled grid ([`crate::cubical::grid`]), last axis fastest (numpy's C
//! order): a point with `k` odd coordinates is a `k`-cell. The two constructions place the
//! array differently:
//!
//! * **T-construction** (`Construction::T`, GUDHI's `CubicalComplex(top_dimensional_cells=…)`):
//!   pixel `(i, j, …)` is the top cell `(2i+1, 2j+1, …)` of a grid of `2n+1` points per axis;
//!   a lower cell takes the minimum of the top cells around it.
//! * **V-construction** (`Construction::V`, CubicalRipser's default, GUDHI's `vertices=`):
//!   pixel `(i, j, …)` is the vertex `(2i, 2j, …)` of a grid of `2n-1` points per axis; a
//!   higher cell takes the maximum of its vertices.
//!
//! With `periodic` every axis has `2n` points and wraps (a d-torus). Superlevel filtrations
//! negate the values, run, and negate back (births then lie above deaths; an essential class
//! dies at `-inf`).
//!
//! Cells are ordered by (value, dimension, grid index), a total order refining the
//! filtration.
//!
//! ## The computation
//!
//! * Dimension 0 by union-find over the edges in order (elder rule): `O(E α(E))`.
//! * Dimension `d-1` by union-find over the top cells in reverse order: the anti-transpose
//!   of `∂_d` is a graph's incidence matrix (every (d-1)-cell has two cofaces; in a box
//!   the outside is one more node, present from the start) and has the same pairs
//!   (de Silva, Morozov and Vejdemo-Johansson, docs/REFERENCES.md). This also tells which
//!   (d-1)-cells are negative, so the matrix reduction below skips the others (clearing).
//!   On a torus each dual component left at the end is an essential d-class, and the
//!   positive (d-1)-cells no d-cell kills are essential (d-1)-classes.
//! * Dimensions 1 to d-2 by column reduction over `Z/p` with clearing (`pairing`, private),
//!   the boundary computed from the grid as columns are asked for.
//! * With representative cycles asked for, every dimension down to 1 goes through the
//!   reduction (it gives the reduced columns and `V`).
//!
//! Memory: the value of every grid cell (`8 · 2^d · N` bytes for `N` pixels), the sorted
//! cells of the dimensions in use (4 bytes each, 16 while sorted), and for the reduction a
//! rank per grid cell (4 bytes) and an owner per row (4 bytes).

pub(crate) use super::options::{check_field, key, unkey};
pub use super::options::{Construction, CubicalOptions};
use super::pairing::{reduce_dim, Entry};
use super::{CellName, Diagram, PersistenceError};
use crate::complex::cubical::grid::{self, Grid, Order, Placement};

/// Where the pixels sit on the doubled grid.
fn placement(opts: &CubicalOptions) -> Placement {
    match (opts.periodic, opts.construction) {
        (true, _) => Placement::Periodic,
        (false, Construction::T) => Placement::Cubes,
        (false, Construction::V) => Placement::Vertices,
    }
}

/// The cubical filtration of an image: the grid, every cell's value, the cells of each
/// dimension in filtration order.
pub struct CubicalFiltration {
    grid: Grid,
    /// the image's shape and values (times `sign`)
    shape: Vec<usize>,
    pixels: Vec<f64>,
    construction: Construction,
    /// every grid cell's value (times `sign`), made when the general route needs it
    vals: std::sync::OnceLock<Vec<f64>>,
    /// per dimension, the cells in filtration order with their keys
    order: Vec<Option<Vec<(u64, u32)>>>,
    rank: Vec<u32>,
    sign: f64,
}

impl CubicalFiltration {
    /// Filters the array `values` of shape `shape` (C order). Refuses an empty shape, a
    /// size mismatch, a NaN (naming its index) and a grid past `u32` indices.
    pub fn new(shape: &[usize], values: &[f64], opts: &CubicalOptions) -> Result<Self, PersistenceError> {
        if shape.is_empty() || shape.contains(&0) {
            return Err(PersistenceError::BadInput(format!("shape {shape:?} has no cells")));
        }
        let n: Option<usize> = shape.iter().try_fold(1usize, |p, &s| p.checked_mul(s));
        if n != Some(values.len()) {
            return Err(PersistenceError::BadInput(format!("shape {shape:?} does not hold {} values", values.len())));
        }
        if let Some(i) = values.iter().position(|v| v.is_nan()) {
            return Err(PersistenceError::BadInput(format!("value {i} is NaN")));
        }
        let grid = Grid::of_box(shape, placement(opts), Order::LastFastest)
            .filter(|g| g.len() < u32::MAX as usize)
            .ok_or_else(|| PersistenceError::TooLarge(format!("a grid of shape {shape:?}")))?;
        let sign = if opts.superlevel { -1.0 } else { 1.0 };
        let d = grid.axes();
        Ok(CubicalFiltration {
            grid,
            shape: shape.to_vec(),
            pixels: values.iter().map(|&v| sign * v).collect(),
            construction: opts.construction,
            vals: std::sync::OnceLock::new(),
            order: vec![None; d + 1],
            rank: Vec::new(),
            sign,
        })
    }

    /// Points of the doubled grid per axis.
    pub fn grid_shape(&self) -> &[usize] {
        self.grid.points()
    }

    /// The value of a grid cell in the input's sign.
    pub fn value(&self, g: usize) -> f64 {
        self.sign * self.vals()[g]
    }

    /// Every grid cell's value (times `sign`).
    fn vals(&self) -> &[f64] {
        self.vals.get_or_init(|| cell_values(&self.grid, &self.pixels, self.construction, 1.0))
    }

    /// Builds the sorted list of k-cells (and their ranks).
    fn ensure(&mut self, k: usize, with_rank: bool) {
        if self.order[k].is_none() {
            let mut keys: Vec<(u64, u32)> = (0..self.grid.len())
                .filter(|&g| self.grid.dim(g) == k)
                .map(|g| (key(self.vals()[g]), g as u32))
                .collect();
            keys.sort_unstable();
            self.order[k] = Some(keys);
        }
        if with_rank {
            if self.rank.is_empty() {
                self.rank = vec![u32::MAX; self.grid.len()];
            }
            let list = self.order[k].as_ref().expect("built above");
            if list.first().is_some_and(|&(_, g)| self.rank[g as usize] == u32::MAX) {
                for (i, &(_, g)) in list.iter().enumerate() {
                    self.rank[g as usize] = i as u32;
                }
            }
        }
    }

    fn list(&self, k: usize) -> &[(u64, u32)] {
        self.order[k].as_deref().unwrap_or(&[])
    }

    fn name(&self, g: usize) -> CellName {
        CellName::Grid(self.grid.coords(g))
    }

    /// The persistence diagram (and cycles, if `opts.cycles`) of this filtration.
    pub fn diagram(mut self, opts: &CubicalOptions) -> Result<Diagram, PersistenceError> {
        if let Some(d) = super::lower_star::diagram(&self.shape, &self.pixels, self.construction, self.sign, opts) {
            return d;
        }
        let field = check_field(opts.field)?;
        let d = self.grid.axes();
        let mut diagram = Diagram::new(opts.field);
        // with cycles every dimension is reduced as a matrix; without, dimension d-1 comes
        // from a union-find on the dual (periodic or not)
        let full = opts.cycles;
        // the (d-1)-cells that are born (positive): skipped as columns
        let mut skip: Vec<bool> = Vec::new();
        let mut top = d + 1; // the highest column dimension the reduction handles
        if !full && d >= 2 {
            self.ensure(d - 1, d >= 3);
            skip = self.dual_union_find(&mut diagram);
            top = d - 1;
        } else if full {
            top = d;
        }
        let low = if opts.cycles { 1 } else { 2 };
        let mut claimed_below: Option<Vec<bool>> = None;
        if top <= d {
            for k in (low..=top).rev() {
                self.ensure(k, true);
                self.ensure(k - 1, true);
                let rows = self.list(k - 1).len();
                let cleared = claimed_below.take();
                let ncols = self.list(k).len() as u32;
                let grid = &self.grid;
                let rank = &self.rank;
                let list = self.order[k].as_deref().expect("ensured");
                let skip_k = if k == d - 1 && !full { Some(&skip) } else { None };
                let cols = (0..ncols).filter(|&j| {
                    !cleared.as_ref().is_some_and(|c| c[j as usize]) && !skip_k.is_some_and(|s| s[j as usize])
                });
                let mut faces = Vec::new();
                let minus = field.of(-1);
                let r = reduce_dim(
                    field,
                    rows,
                    cols,
                    |j, out: &mut Vec<Entry>| {
                        grid.faces(list[j as usize].1 as usize, &mut faces);
                        out.extend(faces.iter().map(|&(f, s)| (rank[f], if s > 0 { 1 } else { minus })));
                    },
                    opts.cycles,
                    opts.cycles,
                );
                let (lo, hi) = (self.list(k - 1), self.list(k));
                for &(row, col) in &r.pairs {
                    let (b, e) = (lo[row as usize].1 as usize, hi[col as usize].1 as usize);
                    let cycle = opts.cycles.then(|| {
                        let chain = r.reduced[&col].iter().map(|&(x, c)| (self.name(lo[x as usize].1 as usize), c));
                        (chain.collect(), self.name(b), Some(self.name(e)))
                    });
                    diagram.push(k - 1, self.vals()[b], self.vals()[e], self.sign, cycle);
                }
                for &col in &r.zero {
                    let g = hi[col as usize].1 as usize;
                    let cycle = opts.cycles.then(|| {
                        let chain = r.v[&col].iter().map(|&(x, c)| (self.name(hi[x as usize].1 as usize), c));
                        (chain.collect(), self.name(g), None)
                    });
                    diagram.push(k, self.vals()[g], f64::INFINITY, self.sign, cycle);
                }
                claimed_below = Some(r.claimed);
            }
        }
        if opts.cycles {
            // dimension 0's columns are zero; those not claimed by edges are essential
            let claimed = claimed_below.unwrap_or_default();
            self.ensure(0, false);
            for (i, &(_, g)) in self.list(0).iter().enumerate() {
                if !claimed.get(i).copied().unwrap_or(false) {
                    let cycle = Some((vec![(self.name(g as usize), 1)], self.name(g as usize), None));
                    diagram.push(0, self.vals()[g as usize], f64::INFINITY, self.sign, cycle);
                }
            }
        } else {
            self.ensure(1.min(d), false);
            let positive = self.union_find_0(&mut diagram);
            if d >= 1 && self.grid.is_periodic() {
                // positive edges no 2-cell kills are essential 1-classes (in 2-D the dual
                // union-find found the killed ones)
                let claimed = claimed_below.unwrap_or_default();
                let killed = |i: usize| claimed.get(i).copied().unwrap_or(false) || (d == 2 && skip[i]);
                for (i, &(_, g)) in self.list(1).iter().enumerate() {
                    if positive[i] && !killed(i) {
                        diagram.push(1, self.vals()[g as usize], f64::INFINITY, self.sign, None);
                    }
                }
            }
        }
        diagram.finish();
        Ok(diagram)
    }

    /// Dimension 0 by union-find over the edges in order; returns which edges are positive.
    fn union_find_0(&self, diagram: &mut Diagram) -> Vec<bool> {
        let grid = &self.grid;
        let d = grid.axes();
        // the oldest vertex of a component is the smallest (value, index): kept as the
        // largest complemented key
        let mut uf = Elder::new(
            (0..grid.len())
                .filter(|&g| (0..d).all(|a| grid.coord(g, a) & 1 == 0))
                .map(|g| (!key(self.vals()[g]), !(g as u32))),
        );
        let edges = if d >= 1 { self.list(1) } else { &[] };
        let mut positive = vec![false; edges.len()];
        for (i, &(ke, e)) in edges.iter().enumerate() {
            let e = e as usize;
            let a = (0..d).find(|&a| grid.coord(e, a) & 1 == 1).expect("an edge has an odd axis");
            let (lo, up) = grid.faces_along(e, a, grid.coord(e, a));
            let (u, v) = (grid.compact(lo, false), grid.compact(up, false));
            match uf.union(u as u32, v as u32) {
                None => positive[i] = true,
                Some((_, young)) => diagram.push(0, unkey(!young.0), unkey(ke), self.sign, None),
            }
        }
        for c in 0..uf.nodes.len() as u32 {
            if uf.find(c) == c {
                diagram.push(0, unkey(!uf.nodes[c as usize].best.0), f64::INFINITY, self.sign, None);
            }
        }
        positive
    }

    /// Dimension d-1 by union-find on the dual (the top cells joined across their shared
    /// (d-1)-cells, latest first: the anti-transpose of `∂_d`, a graph's incidence matrix,
    /// whose pairs union-find gives over any field); returns which (d-1)-cells are
    /// positive (join two dual components). Outside a periodic box the outside is one
    /// more node, later than every cell; a periodic box has none, and each dual component
    /// left at the end is an essential d-class, born at its latest top cell.
    fn dual_union_find(&self, diagram: &mut Diagram) -> Vec<bool> {
        let grid = &self.grid;
        let d = grid.axes();
        // a component's representative is its latest top cell; the outside, last node, is
        // later than all
        let mut uf = Elder::new(
            (0..grid.len())
                .filter(|&g| (0..d).all(|a| grid.coord(g, a) & 1 == 1))
                .map(|g| (key(self.vals()[g]), g as u32))
                .chain(std::iter::once((u64::MAX, u32::MAX))),
        );
        let outside = (uf.nodes.len() - 1) as u32;
        let list = self.list(d - 1);
        let mut positive = vec![false; list.len()];
        for (i, &(ks, s)) in list.iter().enumerate().rev() {
            let s = s as usize;
            let a = (0..d).find(|&a| grid.coord(s, a) & 1 == 0).expect("a (d-1)-cell has an even axis");
            let [lo, hi] = grid.cofaces_along(s, a, grid.coord(s, a));
            let node = |t: Option<usize>| t.map_or(outside, |t| grid.compact(t, true) as u32);
            if let Some((_, young)) = uf.union(node(lo), node(hi)) {
                positive[i] = true;
                diagram.push(d - 1, unkey(ks), unkey(young.0), self.sign, None);
            }
        }
        if grid.is_periodic() {
            for c in 0..outside {
                if uf.find(c) == c {
                    diagram.push(d, unkey(uf.nodes[c as usize].best.0), f64::INFINITY, self.sign, None);
                }
            }
        }
        positive
    }
}

/// A node of [`Elder`]: its parent, rank, and (at a root) the component's best member.
#[derive(Clone, Copy)]
struct Node {
    parent: u32,
    rank: u32,
    best: (u64, u32),
}

/// Union-find whose components remember their best member by a key (the largest wins):
/// union by rank, paths halved, one record per node (one cache line per visit).
struct Elder {
    nodes: Vec<Node>,
}

impl Elder {
    /// One node per key, in order.
    fn new(keys: impl Iterator<Item = (u64, u32)>) -> Self {
        Elder { nodes: keys.enumerate().map(|(i, best)| Node { parent: i as u32, rank: 0, best }).collect() }
    }

    #[inline]
    fn find(&mut self, mut x: u32) -> u32 {
        while self.nodes[x as usize].parent != x {
            let p = self.nodes[self.nodes[x as usize].parent as usize].parent;
            self.nodes[x as usize].parent = p;
            x = p;
        }
        x
    }

    /// Joins the components of `u` and `v`; `None` if they were one, else the two best
    /// members `(kept, lost)`: the lost one's class dies.
    #[inline]
    fn union(&mut self, u: u32, v: u32) -> Option<((u64, u32), (u64, u32))> {
        let (ru, rv) = (self.find(u), self.find(v));
        if ru == rv {
            return None;
        }
        let (nu, nv) = (self.nodes[ru as usize], self.nodes[rv as usize]);
        let (keep, lose) = if nu.best > nv.best { (nu.best, nv.best) } else { (nv.best, nu.best) };
        let (hi, lo) = if nu.rank >= nv.rank { (ru, rv) } else { (rv, ru) };
        self.nodes[lo as usize].parent = hi;
        if nu.rank == nv.rank {
            self.nodes[hi as usize].rank += 1;
        }
        self.nodes[hi as usize].best = keep;
        Some((keep, lose))
    }
}

/// Every grid cell's value (times `sign`), by one pass per axis: the V-construction takes
/// the maximum of the two neighbours along an odd axis, the T-construction the minimum of
/// those along an even axis that exist. A cell's value is final after the pass of its last
/// odd (V) or even (T) axis, whose neighbours are final by then.
fn cell_values(grid: &Grid, values: &[f64], construction: Construction, sign: f64) -> Vec<f64> {
    let (d, m, stride) = (grid.axes(), grid.points(), grid.strides());
    let mut vals = vec![f64::INFINITY; grid.len()];
    let pixel_parity = match construction {
        Construction::V => 0,
        Construction::T => 1,
    };
    // place the pixels
    let shape: Vec<usize> = m.iter().map(|&m| if pixel_parity == 1 { m / 2 } else { m.div_ceil(2) }).collect();
    let mut idx = vec![0usize; d];
    for &v in values {
        let g: usize = (0..d).map(|a| (2 * idx[a] + pixel_parity) * stride[a]).sum();
        vals[g] = sign * v;
        for a in (0..d).rev() {
            idx[a] += 1;
            if idx[a] < shape[a] {
                break;
            }
            idx[a] = 0;
        }
    }
    for a in 0..d {
        let (s, m) = (stride[a], m[a]);
        let block = s * m;
        for base in (0..grid.len()).step_by(block) {
            for c in 0..m {
                let along = c & 1 == 1;
                let row = base + c * s;
                match construction {
                    Construction::V if along => {
                        let lo = row - s;
                        let hi = if c + 1 == m { base } else { row + s };
                        for t in 0..s {
                            vals[row + t] = vals[lo + t].max(vals[hi + t]);
                        }
                    }
                    Construction::T if !along => {
                        let lo = if c > 0 {
                            Some(row - s)
                        } else if grid.is_periodic() {
                            Some(base + (m - 1) * s)
                        } else {
                            None
                        };
                        let hi = if c + 1 < m { Some(row + s) } else { None };
                        for t in 0..s {
                            let x = lo.map_or(f64::INFINITY, |l| vals[l + t]);
                            let y = hi.map_or(f64::INFINITY, |h| vals[h + t]);
                            vals[row + t] = x.min(y);
                        }
                    }
                    _ => {}
                }
            }
        }
    }
    vals
}

/// The peak memory, in bytes, of a whole process that reads an image of `shape` from a file
/// as `f64` values and computes its diagram with `opts` (`None` past `u64`): what the
/// memory policy compares with its limit before any work.
///
/// [`PROCESS_BYTES`] plus, per pixel, figures from peak resident memory on uniform random
/// values (the most pairs and the longest columns we know; smooth images take less), with
/// about 10% to spare:
///
/// | route | bytes |
/// | --- | ---: |
/// | pixel route, 1-D and 2-D | 64 per pixel |
/// | pixel route, 3-D, per point of the padded grid: V over Z/2, V over Z/p or T over Z/2, T over Z/p | 88, 108, 160 |
/// | general route (periodic, dimension 4 or more), per cell of the grid | 64 |
/// | general route with cycles, per cell of the grid | 256 |
///
/// The figure with cycles is a floor rather than a bound: the cycles' total length grows
/// with the image (on random 3-D arrays in V, 1,063 bytes per pixel at 48³, 1,216 at 64³).
pub fn memory_estimate(shape: &[usize], opts: &CubicalOptions) -> Option<u64> {
    data_estimate(shape, opts)?.checked_add(PROCESS_BYTES)
}

/// What [`memory_estimate`] counts for the program itself, whatever the image: its code,
/// libraries and the allocator's own (16 MiB; a process computing the diagram of a
/// 64 × 64 × 64 image peaks at 29–37 MB).
pub const PROCESS_BYTES: u64 = 16 << 20;

fn data_estimate(shape: &[usize], opts: &CubicalOptions) -> Option<u64> {
    let product = |f: &dyn Fn(usize) -> Option<usize>| {
        shape.iter().try_fold(1u64, |acc, &s| f(s).and_then(|x| acc.checked_mul(x as u64)))
    };
    if super::lower_star::applies(shape, opts) {
        if shape.len() < 3 {
            return product(&Some)?.checked_mul(64);
        }
        let per = match (opts.construction, opts.field == 2) {
            (Construction::V, true) => 88,
            (Construction::V, false) | (Construction::T, true) => 108,
            (Construction::T, false) => 160,
        };
        return product(&|s| s.checked_add(2))?.checked_mul(per);
    }
    // the general route's grid: 2s + 1 points per axis (T), 2s - 1 (V), 2s (periodic)
    grid::bytes(shape, placement(opts), if opts.cycles { 256 } else { 64 })
}

/// The persistence diagram of an image: [`CubicalFiltration::new`] then
/// [`CubicalFiltration::diagram`].
pub fn cubical_persistence(
    shape: &[usize],
    values: &[f64],
    opts: &CubicalOptions,
) -> Result<Diagram, PersistenceError> {
    CubicalFiltration::new(shape, values, opts)?.diagram(opts)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn memory_estimate_follows_the_route() {
        let o = |construction, field, periodic, cycles| CubicalOptions {
            construction,
            superlevel: false,
            periodic,
            field,
            cycles,
        };
        let t2 = o(Construction::T, 2, false, false);
        const P: u64 = PROCESS_BYTES;
        // pixel route: 64 bytes a pixel in 1-D and 2-D
        assert_eq!(memory_estimate(&[1000], &t2), Some(P + 64_000));
        assert_eq!(memory_estimate(&[4000, 4000], &t2), Some(P + 1_024_000_000));
        // 3-D: per point of the padded grid
        let padded = 258u64 * 258 * 258;
        assert_eq!(memory_estimate(&[256; 3], &o(Construction::V, 2, false, false)), Some(P + 88 * padded));
        assert_eq!(memory_estimate(&[256; 3], &o(Construction::V, 3, false, false)), Some(P + 108 * padded));
        assert_eq!(memory_estimate(&[256; 3], &t2), Some(P + 108 * padded));
        assert_eq!(memory_estimate(&[256; 3], &o(Construction::T, 3, false, false)), Some(P + 160 * padded));
        // general route: per cell of the grid
        assert_eq!(memory_estimate(&[10; 4], &t2), Some(P + 64 * 21u64.pow(4)));
        assert_eq!(memory_estimate(&[10; 4], &o(Construction::V, 2, false, false)), Some(P + 64 * 19u64.pow(4)));
        assert_eq!(memory_estimate(&[100, 100], &o(Construction::T, 2, true, false)), Some(P + 64 * 200 * 200));
        assert_eq!(memory_estimate(&[100, 100], &o(Construction::T, 2, false, true)), Some(P + 256 * 201 * 201));
        // past u64
        assert_eq!(memory_estimate(&[1 << 40, 1 << 40], &t2), None);
        assert_eq!(memory_estimate(&[usize::MAX, 2, 2, 2], &t2), None);
    }
}
