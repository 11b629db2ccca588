//! Persistence of 1- to 3-D images straight from the pixels, with no cell grid.
//!
//! Both constructions are driven by one order on the pixels, (value, index), found by a
//! radix sort of the values' order-preserving bit patterns (passes whose byte is the same
//! for every pixel are skipped, so an 8-bit image costs one pass):
//!
//! * **V-construction**: a cell's value is its latest vertex's; cells are ordered by (rank
//!   of their latest vertex, dimension, id), a total order refining the filtration (the
//!   lower star of each pixel, pixel after pixel).
//! * **T-construction**: a cell's value is its earliest top cell's; cells are ordered by
//!   (rank of that top cell, dimension, id).
//!
//! The diagram does not depend on how ties of value are broken, so these orders give
//! GUDHI's pairs. Then:
//!
//! * **dimension 0** by union-find on the pixels in rank order (V: 2d neighbours; T in 1-D
//!   and 2-D: the 3^d - 1 pixels sharing a vertex; T in 3-D: the vertices and edges each
//!   voxel brings, vertices first, edges in the order of their ids), each component
//!   rooted at its oldest pixel (elder rule), paths halved; the nodes are indexed by pixel
//!   (or point), so the first step of every find is a neighbour of the pixel at hand
//!   (cache-local), and a node is 8 bytes (parent, birth rank). In 3-D the edges that join
//!   two components (the negative edges) are marked, a bit per edge;
//! * **dimension d-1** by union-find on the dual in reverse rank order (Alexander
//!   duality, CubicalRipser's `JoinPairs`): top cells and the outside are the nodes, a
//!   (d-1)-cell joins its one or two cofaces, and a join of two components is a pair whose
//!   death is the younger component's latest top cell;
//! * **dimension 1 of a 3-D image** (V and T) by column reduction of the 2-cells over
//!   `Z/p` ([`Middle`]), skipping the 2-cells the dual pass found positive (clearing):
//!   columns of four entries computed from the ranks, keys `(rank << 32) | id`, an owner
//!   per edge (a `u32` that also says where the owner's column is: no hash map), only the
//!   columns changed by a reduction stored (one after the other in one array), over Z/2 an
//!   entry its key alone, a short column added into a long one in place. The negative
//!   edges are left out of every column (the compression of Bauer, Kerber and
//!   Reininghaus, "Clear and compress", 2014): such an edge is never the latest of a
//!   column being reduced (it would be that column's pivot, and a pivot of the 2-cells
//!   is never negative), so dropping its row changes no step of the reduction; columns
//!   are a third shorter, and on random 128³ arrays the pass takes 20–25% less time.
//!   (Cohomology,
//!   CubicalRipser's choice for this dimension, made columns 25 times longer on random
//!   128³ arrays.)
//!
//! In 3-D the pixels are the points of a grid padded by one on every side whose border is
//! never early ([`Padded`]): the neighbours of a pixel, the voxels of an edge (T) and the
//! 3 × 3 × 3 block around a pixel (V: read into two bit masks, early and inside, that
//! precomputed templates test for the cubes and 2-cells at the pixel) are read with no test
//! of the bounds and no division. The dual pass writes, for each rank, which 2-cells of
//! its pixel are left for the middle pass (a bit per template), which then reads that
//! array in order instead of finding the 2-cells again; in V a 2-cell whose latest edge
//! (known from its template) has no owner yet is paired without building its column (84%
//! of them on random 128³).
//!
//! The sweeps visit pixels in value order, all over the image: each step prefetches the
//! rows the step twelve pixels ahead will read (in 3-D only those it reads, and in the
//! middle pass only for pixels with columns), and the union-find nodes, the ranks (3-D)
//! and the owners are asked for 2 MB pages (`crate::prefetch::filled`: with 4 KB pages
//! nearly every such read also misses the TLB).
//!
//! Cost: the sort `O(N)` passes, then `O(N α(N))` for the union-finds; the reduction is
//! near-linear on images. Memory: the values in rank order (8 bytes per pixel); in 1-D
//! and 2-D the union-find (8; the dual pass reuses its nodes) and, in the dual pass, the
//! ranks (4); in 3-D, per point of the padded grid of `(s + 2)^3`, the union-find (8) and
//! the ranks (4), then an owner per edge (12) and a bit per edge, per pixel its point (4)
//! and its 2-cells left to reduce (1 or 2), and the stored columns (8 bytes an entry over
//! Z/2, 16 otherwise).
//!
//! Periodic images, cycles and images of dimension 4 or more go through the general route
//! of [`super::cubical`].

use bitvec::vec::BitVec;
use gmap_core::fastdiv::Divider;

use super::options::{check_field, key, unkey, Construction, CubicalOptions};
use super::reduce::Zp;
use super::{Diagram, PersistenceError};
use crate::complex::cubical::grid::{face_sign, Grid, Order};
use crate::prefetch::{filled, prefetch};

/// Whether the pixel route takes an image of this shape with these options: no cycles, not
/// periodic, 1 to 3 axes, and every edge and 2-cell of the padded grid numbered in a `u32`.
pub(crate) fn applies(shape: &[usize], opts: &CubicalOptions) -> bool {
    let d = shape.len();
    if opts.periodic || opts.cycles || d == 0 || d > 3 {
        return false;
    }
    // edges and 2-cells are named `3 · point + axis` (T: on a grid of (s + 2)^d points)
    let vertices = shape.iter().try_fold(1usize, |v, &s| v.checked_mul(s + 2));
    // (and 4 + the largest edge is a u32: see `Middle`'s owners)
    vertices.and_then(|v| v.checked_mul(3)).is_some_and(|m| m < u32::MAX as usize - 4)
}

/// The diagram by the pixel route, or `None` where it does not apply.
pub(crate) fn diagram(
    shape: &[usize],
    pixels: &[f64],
    construction: Construction,
    sign: f64,
    opts: &CubicalOptions,
) -> Option<Result<Diagram, PersistenceError>> {
    let d = shape.len();
    let n = pixels.len();
    if !applies(shape, opts) {
        return None;
    }
    let field = match check_field(opts.field) {
        Ok(f) => f,
        Err(e) => return Some(Err(e)),
    };
    let (order, keys) = sort_order(pixels);
    // the values in rank order, from the sorted keys in their place (no gather)
    let sv: Vec<f64> = keys.into_iter().map(unkey).collect();
    let mut out = Out::new(Diagram::new(opts.field), &sv, sign);
    if d == 3 {
        let (grid, pix) = Padded::new([shape[0], shape[1], shape[2]], &order);
        drop(order);
        let done = match construction {
            // over Z/2 a column entry is its key alone (coefficient 1)
            Construction::V if opts.field == 2 => v3::<u64>(grid, pix, field, &mut out),
            Construction::V => v3::<(u64, u32)>(grid, pix, field, &mut out),
            Construction::T if opts.field == 2 => t3::<u64>(grid, pix, field, &mut out),
            Construction::T => t3::<(u64, u32)>(grid, pix, field, &mut out),
        };
        if done.is_err() {
            return None;
        }
    } else {
        // one node per pixel, [parent, rank]: the rank of a neighbour is read from the
        // cache line its node is on; one more for the dual pass's outside, which reuses the
        // nodes
        let mut pix = Forest::new(n + 1);
        for (r, &p) in order.iter().enumerate() {
            pix.nodes[p as usize] = [p, r as u32];
        }
        let (rows, cols) = if d == 1 { (1, shape[0]) } else { (shape[0], shape[1]) };
        match construction {
            Construction::V => v2(rows, cols, &order, pix, &mut out),
            Construction::T => t2(rows, cols, &order, pix, &mut out),
        }
    }
    out.push(0, 0, None);
    let mut diagram = out.finish();
    diagram.finish();
    Some(Ok(diagram))
}

/// The diagram being filled, with the values in rank order. A pair's values are read
/// [`LAG`] pairs after it is pushed, their cache lines asked for at the push: a birth
/// is a rank from anywhere in the image, and reading its value at once would stall the
/// sweep on a cache miss per pair.
struct Out<'a> {
    diagram: Diagram,
    sv: &'a [f64],
    sign: f64,
    /// the pairs pushed and not yet read: `(dim, birth, death)`, `u32::MAX` for no death
    /// (no rank is `u32::MAX`: `diagram` takes images of fewer pixels)
    pending: [(u8, u32, u32); LAG],
    next: usize,
}

/// How many pairs [`Out`] holds before reading their values.
const LAG: usize = 16;

impl<'a> Out<'a> {
    fn new(diagram: Diagram, sv: &'a [f64], sign: f64) -> Self {
        Out { diagram, sv, sign, pending: [(0, 0, 0); LAG], next: 0 }
    }

    /// A pair between ranks (`None`: essential).
    #[inline]
    fn push(&mut self, dim: usize, birth: u32, death: Option<u32>) {
        if death == Some(birth) {
            return; // one rank, one value: most pairs, found without reading the values
        }
        prefetch(self.sv, birth as usize);
        let slot = self.next % LAG;
        if self.next >= LAG {
            self.read(self.pending[slot]);
        }
        // dimensions are at most 3
        self.pending[slot] = (dim as u8, birth, death.unwrap_or(u32::MAX));
        self.next += 1;
    }

    /// Enters a pending pair in the diagram, unless its values are equal.
    #[inline]
    fn read(&mut self, (dim, birth, death): (u8, u32, u32)) {
        let b = self.sv[birth as usize];
        let e = if death == u32::MAX { f64::INFINITY } else { self.sv[death as usize] };
        if b != e {
            self.diagram.push(dim as usize, b, e, self.sign, None);
        }
    }

    /// The diagram, every pending pair read.
    fn finish(mut self) -> Diagram {
        let first = self.next.saturating_sub(LAG);
        for k in first..self.next {
            self.read(self.pending[k % LAG]);
        }
        self.diagram
    }
}

/// The pixels in order of (value, index), and their keys in that order: a stable LSD radix
/// sort of the values' keys, 11 bits a pass.
fn sort_order(values: &[f64]) -> (Vec<u32>, Vec<u64>) {
    let n = values.len();
    let mut keys: Vec<u64> = values.iter().map(|&v| key(v)).collect();
    let mut idx: Vec<u32> = (0..n as u32).collect();
    const BITS: usize = 11;
    const MASK: u64 = (1 << BITS) - 1;
    let mut counts = vec![[0usize; 1 << BITS]; 64usize.div_ceil(BITS)];
    for &k in &keys {
        for (b, c) in counts.iter_mut().enumerate() {
            c[((k >> (BITS * b)) & MASK) as usize] += 1;
        }
    }
    let (mut keys2, mut idx2) = (vec![0u64; n], vec![0u32; n]);
    for (b, c) in counts.iter().enumerate() {
        if c.contains(&n) {
            continue; // every key has these bits
        }
        let mut pos = [0usize; 1 << BITS];
        let mut s = 0;
        for (p, &x) in pos.iter_mut().zip(c) {
            *p = s;
            s += x;
        }
        for (&k, &i) in keys.iter().zip(&idx) {
            let slot = &mut pos[((k >> (BITS * b)) & MASK) as usize];
            keys2[*slot] = k;
            idx2[*slot] = i;
            *slot += 1;
        }
        std::mem::swap(&mut keys, &mut keys2);
        std::mem::swap(&mut idx, &mut idx2);
    }
    (idx, keys)
}

/// Union-find nodes `[parent, time]`: the root's time names its component (the elder rule
/// compares times), paths are halved.
struct Forest {
    nodes: Vec<[u32; 2]>,
}

impl Forest {
    fn new(n: usize) -> Self {
        Forest { nodes: filled(n, [0, 0]) }
    }

    /// The times of the first `n` nodes (for the ranks once the nodes are reused), on huge
    /// pages like the nodes.
    fn times(&self, n: usize) -> Vec<u32> {
        let mut t = filled(n, 0u32);
        for (t, node) in t.iter_mut().zip(&self.nodes) {
            *t = node[1];
        }
        t
    }

    #[inline]
    fn make(&mut self, x: u32, time: u32) {
        self.nodes[x as usize] = [x, time];
    }

    #[inline]
    fn find(&mut self, mut x: u32) -> u32 {
        loop {
            let p = self.nodes[x as usize][0];
            if p == x {
                return x;
            }
            let g = self.nodes[p as usize][0];
            if g == p {
                return p;
            }
            self.nodes[x as usize][0] = g;
            x = g;
        }
    }

    /// Joins the components of `x` and `y`; the one whose root time is `keep`-er (smaller
    /// with `keep_small`) stays root. Returns the lost root's time, `None` if already one.
    #[inline]
    fn union(&mut self, x: u32, y: u32, keep_small: bool) -> Option<u32> {
        let (a, b) = (self.find(x), self.find(y));
        if a == b {
            return None;
        }
        let (ta, tb) = (self.nodes[a as usize][1], self.nodes[b as usize][1]);
        let a_stays = if keep_small { ta < tb } else { ta > tb };
        let (stay, lose, t) = if a_stays { (a, b, tb) } else { (b, a, ta) };
        self.nodes[lose as usize][0] = stay;
        Some(t)
    }
}

/// How many pixels ahead of the sweep their rows are read in (see [`touch_ahead`]).
const AHEAD: usize = 12;

/// Reads the entry (node or rank) of the pixel `AHEAD` steps after `r` in the sweep's
/// direction (`dir` 1: forward, 0: `r` is that pixel's step already) and the entries of the
/// rows above and below:
/// the loads start early and overlap with the current step's work, so the step that needs
/// them finds them in cache (the sweep visits pixels in value order, all over the image).
#[inline]
fn touch_ahead<T>(nodes: &[T], order: &[u32], r: usize, cols: usize, dir: usize) {
    let Some(&q) = order.get(r + dir * AHEAD) else { return };
    let q = q as usize;
    prefetch(nodes, q);
    prefetch(nodes, q.wrapping_sub(cols));
    prefetch(nodes, q + cols);
}

/// Reads `data` at `at + i · steps[0] + j · steps[1]` for the `(i, j)` of `rows` (rows of
/// a 3-D array around a point) so that their cache lines load while the current step
/// works: the sweeps visit the voxels in value order, all over the array. Only the rows the
/// step will read: more hints than the processor has loads in flight hold it up.
#[inline]
fn touch_rows<T>(data: &[T], at: usize, steps: [usize; 2], rows: &[(isize, isize)]) {
    for &(i, j) in rows {
        prefetch(data, at.wrapping_add_signed(i * steps[0] as isize + j * steps[1] as isize));
    }
}

/// The nine rows around a point.
const BLOCK: [(isize, isize); 9] = [(-1, -1), (-1, 0), (-1, 1), (0, -1), (0, 0), (0, 1), (1, -1), (1, 0), (1, 1)];
/// A point's row and the four next to it (its six neighbours).
const CROSS: [(isize, isize); 5] = [(0, 0), (-1, 0), (1, 0), (0, -1), (0, 1)];
/// The rows of the points below a point along the first two axes (V: lower corners of the
/// cubes and 2-cells at a point).
const LOWER: [(isize, isize); 4] = [(-1, -1), (-1, 0), (0, -1), (0, 0)];
/// The rows of the points above (T: the corners of a voxel of lower corner the point).
const UPPER: [(isize, isize); 4] = [(0, 0), (0, 1), (1, 0), (1, 1)];

/// 2-D V-construction (a 1-D image is one row).
fn v2(rows: usize, cols: usize, order: &[u32], mut pix: Forest, out: &mut Out) {
    let n = rows * cols;
    // (pixels are fewer than 2^32: `diagram`'s test)
    let Some(by_cols) = Divider::new(cols) else { return };
    // dimension 0: each pixel's edges to earlier neighbours
    for (r, &p) in order.iter().enumerate() {
        touch_ahead(&pix.nodes, order, r, cols, 1);
        let r = r as u32;
        let i = by_cols.quotient(p as usize);
        let j = p as usize - i * cols;
        let mut link = |q: usize| {
            if pix.nodes[q][1] < r {
                if let Some(young) = pix.union(p, q as u32, true) {
                    out.push(0, young, Some(r));
                }
            }
        };
        if j > 0 {
            link(p as usize - 1);
        }
        if j + 1 < cols {
            link(p as usize + 1);
        }
        if i > 0 {
            link(p as usize - cols);
        }
        if i + 1 < rows {
            link(p as usize + cols);
        }
    }
    if rows < 2 || cols < 2 {
        return;
    }
    // dimension 1 on the dual: squares by their lower-left pixel, the outside node `n`; the
    // nodes are the pixels' again (a square's is made before it is read), the ranks copied
    // out first (half the bytes to read)
    let ranks = pix.times(n);
    let rank = |q: usize| ranks[q];
    let mut f = pix;
    let outside = n as u32;
    f.make(outside, u32::MAX);
    let square = |a: usize, b: usize| -> u32 {
        if a < rows - 1 && b < cols - 1 {
            (a * cols + b) as u32
        } else {
            outside
        }
    };
    for (r, &p) in order.iter().enumerate().rev() {
        if r >= AHEAD {
            touch_ahead(&ranks, order, r - AHEAD, cols, 0);
            // the squares at that pixel: rows i - 1 and i of the dual's nodes
            let q = order[r - AHEAD] as usize;
            prefetch(&f.nodes, q.wrapping_sub(cols));
            prefetch(&f.nodes, q);
        }
        let r = r as u32;
        let i = by_cols.quotient(p as usize);
        let j = p as usize - i * cols;
        let early = |a: usize, b: usize| rank(a * cols + b) <= r;
        // the squares whose latest corner is p
        for (a, b) in [(i.wrapping_sub(1), j.wrapping_sub(1)), (i.wrapping_sub(1), j), (i, j.wrapping_sub(1)), (i, j)] {
            if a < rows - 1 && b < cols - 1 && early(a, b) && early(a + 1, b) && early(a, b + 1) && early(a + 1, b + 1)
            {
                f.make((a * cols + b) as u32, r);
            }
        }
        // the edges whose latest end is p join their two cofaces
        let mut edge = |x: u32, y: u32| {
            if let Some(young) = f.union(x, y, false) {
                out.push(1, r, Some(young));
            }
        };
        if j > 0 && rank(p as usize - 1) < r {
            edge(square(i.wrapping_sub(1), j - 1), square(i, j - 1));
        }
        if j + 1 < cols && rank(p as usize + 1) < r {
            edge(square(i.wrapping_sub(1), j), square(i, j));
        }
        if i > 0 && rank(p as usize - cols) < r {
            edge(square(i - 1, j.wrapping_sub(1)), square(i - 1, j));
        }
        if i + 1 < rows && rank(p as usize + cols) < r {
            edge(square(i, j.wrapping_sub(1)), square(i, j));
        }
    }
}

/// 2-D T-construction (a 1-D image is one row): the pixels are the top cells.
fn t2(rows: usize, cols: usize, order: &[u32], mut pix: Forest, out: &mut Out) {
    let n = rows * cols;
    let Some(by_cols) = Divider::new(cols) else { return };
    // dimension 0: pixels sharing a vertex
    for (r, &p) in order.iter().enumerate() {
        touch_ahead(&pix.nodes, order, r, cols, 1);
        let r = r as u32;
        let i = by_cols.quotient(p as usize);
        let j = p as usize - i * cols;
        for a in i.saturating_sub(1)..(i + 2).min(rows) {
            for b in j.saturating_sub(1)..(j + 2).min(cols) {
                let q = a * cols + b;
                if pix.nodes[q][1] < r {
                    if let Some(young) = pix.union(p, q as u32, true) {
                        out.push(0, young, Some(r));
                    }
                }
            }
        }
    }
    // dimension 1 on the dual: pixels sharing an edge, the border's edges to the outside;
    // the nodes are the pixels' again, the ranks copied out first
    let ranks = pix.times(n);
    let rank = |q: usize| ranks[q];
    let mut f = pix;
    let outside = n as u32;
    f.make(outside, u32::MAX);
    for (r, &p) in order.iter().enumerate().rev() {
        if r >= AHEAD {
            touch_ahead(&ranks, order, r - AHEAD, cols, 0);
            touch_ahead(&f.nodes, order, r - AHEAD, cols, 0);
        }
        let r = r as u32;
        f.make(p, r);
        let i = by_cols.quotient(p as usize);
        let j = p as usize - i * cols;
        let mut edge = |y: u32| {
            if let Some(young) = f.union(p, y, false) {
                out.push(1, r, Some(young));
            }
        };
        if i == 0 || j == 0 || i + 1 == rows || j + 1 == cols {
            edge(outside);
        }
        for q in [
            (j > 0).then(|| p as usize - 1),
            (j + 1 < cols).then(|| p as usize + 1),
            (i > 0).then(|| p as usize - cols),
            (i + 1 < rows).then(|| p as usize + cols),
        ]
        .into_iter()
        .flatten()
        {
            if rank(q) > r {
                edge(q as u32);
            }
        }
    }
}

/// 3-D V-construction on the padded grid ([`Padded`]). Edges and 2-cells are named
/// `3 · point + axis`: an edge by its lower end and its axis, a 2-cell by its lower corner
/// and the axis it is normal to.
fn v3<E: Entry>(grid: Padded, mut pix: Forest, field: Zp, out: &mut Out) -> Result<(), TooLarge> {
    let Padded { g, gstride, at } = grid;
    let points = g[0] * gstride[0];
    // dimension 0: the six neighbours, the edges to them in the order of their ids (lower
    // end, axis), as the filtration orders the edges of one rank; `negative_edges` marks
    // the edges that join two components (a bit per edge id)
    let mut negative_edges: BitVec = BitVec::repeat(false, 3 * points);
    for (r, &v) in at.iter().enumerate() {
        if let Some(&q) = at.get(r + AHEAD) {
            touch_rows(&pix.nodes, q as usize, [gstride[0], gstride[1]], &CROSS);
        }
        let r = r as u32;
        let v = v as usize;
        for (axis, q, low) in [
            (0, v - gstride[0], v - gstride[0]),
            (1, v - gstride[1], v - gstride[1]),
            (2, v - 1, v - 1),
            (0, v + gstride[0], v),
            (1, v + gstride[1], v),
            (2, v + 1, v),
        ] {
            if pix.nodes[q][1] < r {
                if let Some(young) = pix.union(v as u32, q as u32, true) {
                    out.push(0, young, Some(r));
                    negative_edges.set(3 * low + axis, true);
                }
            }
        }
    }
    let rank = pix.times(pix.nodes.len());
    drop(pix);
    let block = block_offsets(gstride);
    let (cubes, faces) = (cube_templates(gstride), face_templates(gstride));
    // the 3 × 3 × 3 block around the point `v` (bit `9(dz+1) + 3(dy+1) + (dx+1)`): the
    // pixels no later than rank `r`, and the pixels
    let masks = |v: usize, r: u32| -> (u32, u32) {
        let (mut early, mut real) = (0u32, 0u32);
        for (k, &o) in block.iter().enumerate() {
            let t = rank[v.wrapping_add_signed(o)];
            early |= u32::from(t <= r) << k;
            real |= u32::from(t != u32::MAX) << k;
        }
        (early, real)
    };

    // dimension 2 on the dual: cubes by their lower corner, the outside node; `negative[r]`
    // says which 2-cells of the pixel of rank r (bit k: `faces[k]`) join no two components
    let mut f = Forest::new(points + 1);
    let outside = points as u32;
    f.make(outside, u32::MAX);
    let mut negative = vec![0u16; at.len()];
    for r in (0..at.len()).rev() {
        if let Some(&q) = r.checked_sub(AHEAD).and_then(|a| at.get(a)) {
            touch_rows(&rank, q as usize, [gstride[0], gstride[1]], &BLOCK);
            touch_rows(&f.nodes, q as usize, [gstride[0], gstride[1]], &LOWER);
        }
        let v = at[r] as usize;
        let r = r as u32;
        let (early, real) = masks(v, r);
        for cube in &cubes {
            if early & cube.corners == cube.corners {
                f.make(v.wrapping_add_signed(cube.at) as u32, r);
            }
        }
        let node = |c: &Template| {
            if real & c.corners == c.corners {
                v.wrapping_add_signed(c.at) as u32
            } else {
                outside
            }
        };
        let mut neg = 0u16;
        for (k, face) in faces.iter().enumerate().rev() {
            if early & face.corners != face.corners {
                continue;
            }
            if let Some(young) = f.union(node(&face.cofaces[0]), node(&face.cofaces[1]), false) {
                out.push(2, r, Some(young));
            } else {
                neg |= 1 << k;
            }
        }
        negative[r as usize] = neg;
    }
    drop(f);

    // dimension 1: the negative 2-cells' columns, reduced, without their negative edges
    // (Bauer, Kerber and Reininghaus's compression: an edge that joins two components is
    // never the latest edge of a column being reduced, so its row changes no pivot)
    let edge_key = |v: usize, axis: usize| -> Option<u64> {
        let e = 3 * v + axis;
        if negative_edges[e] {
            return None;
        }
        let t = rank[v].max(rank[v + gstride[axis]]);
        Some(((t as u64) << 32) | e as u64)
    };
    let mut middle = Middle::<E>::new(3 * points, gstride, field);
    for (r, &neg) in negative.iter().enumerate() {
        if let Some(&q) = at.get(r + AHEAD).filter(|_| negative[r + AHEAD] != 0) {
            touch_rows(&rank, q as usize, [gstride[0], gstride[1]], &BLOCK);
            touch_rows(&middle.owner, 3 * q as usize, [3 * gstride[0], 3 * gstride[1]], &LOWER);
        }
        let (v, r) = (at[r] as usize, r as u32);
        let mut neg = neg;
        while neg != 0 {
            let face = &faces[neg.trailing_zeros() as usize];
            neg &= neg - 1;
            let id = (3 * v).wrapping_add_signed(face.id) as u32;
            // most 2-cells pair with their latest edge at once (its first coface): no column
            // to build, and a pair of one rank to leave out
            if !middle.take((3 * v).wrapping_add_signed(face.pivot) as u32, id) {
                middle.column(id, r, out, |id, col| square_boundary(id, gstride, field, edge_key, col))?;
            }
        }
    }
    Ok(())
}

/// A 3-D image on the grid of its points padded by one on every side: the pixel c at the
/// point c + (1, 1, 1). The border's rank is u32::MAX (never early), so that the
/// neighbours of a pixel are read with no test of the bounds.
struct Padded {
    /// the padded grid's shape and strides
    g: [usize; 3],
    gstride: [usize; 3],
    /// the point of the pixel of each rank
    at: Vec<u32>,
}

impl Padded {
    /// The grid, and one union-find node per point, `[point, rank]` (the rank of a
    /// neighbour is read from the cache line its node is on).
    fn new(shape: [usize; 3], order: &[u32]) -> (Self, Forest) {
        let g = [shape[0] + 2, shape[1] + 2, shape[2] + 2];
        // C order, the last axis fastest ([`applies`] checked that the points fit a u32)
        let points = Grid::new(g.to_vec(), false, Order::LastFastest).expect("the padded grid fits a u32");
        let gstride = [points.strides()[0], points.strides()[1], points.strides()[2]];
        let inner = gstride[0] + gstride[1] + 1;
        let mut pix = Forest::new(g[0] * gstride[0]);
        for (v, node) in pix.nodes.iter_mut().enumerate() {
            *node = [v as u32, u32::MAX];
        }
        let at = order
            .iter()
            .enumerate()
            .map(|(r, &p)| {
                let p = p as usize;
                let (z, y, x) = (p / (shape[1] * shape[2]), (p / shape[2]) % shape[1], p % shape[2]);
                let v = z * gstride[0] + y * gstride[1] + x + inner;
                pix.nodes[v][1] = r as u32;
                v as u32
            })
            .collect();
        (Padded { g, gstride, at }, pix)
    }
}

/// A vertex or an edge of a voxel (T-construction, on [`Padded`]'s grid): its point's
/// offset from the voxel's point, its axis (an edge's), and the mask of the other voxels
/// around the voxel that contain it (in [`block_offsets`]' bits).
struct VoxelCell {
    at: isize,
    axis: usize,
    voxels: u32,
}

/// The voxel's cell whose point is its lower corner plus `delta` and that spans the axes
/// `spans` (none: a vertex; one: an edge along it).
fn voxel_cell(delta: [isize; 3], spans: Option<usize>, gstride: [usize; 3]) -> VoxelCell {
    let at = (0..3).map(|a| (delta[a] - 1) * gstride[a] as isize).sum();
    // along an axis the cell does not span, the voxels at delta - 1 and delta (relative to
    // the voxel) contain it; along the one it spans, only the voxel's own layer
    let mut voxels = 0;
    for k in 0..8 {
        let d: [isize; 3] = std::array::from_fn(|a| if Some(a) == spans { 0 } else { delta[a] - ((k >> a) & 1) });
        if d != [0, 0, 0] {
            voxels |= block_bit(d);
        }
    }
    VoxelCell { at, axis: spans.unwrap_or(0), voxels }
}

/// The eight vertices of a voxel.
fn corner_templates(gstride: [usize; 3]) -> [VoxelCell; 8] {
    std::array::from_fn(|k| voxel_cell([k >> 2 & 1, k >> 1 & 1, k & 1].map(|x| x as isize), None, gstride))
}

/// The twelve edges of a voxel, in the order of their ids `3 · point + axis`.
fn edge_templates(gstride: [usize; 3]) -> Vec<VoxelCell> {
    let mut edges: Vec<VoxelCell> = (0..3)
        .flat_map(|axis| {
            (0..4).map(move |k| {
                let [b, c] = OTHERS[axis];
                let mut delta = [0isize; 3];
                delta[b] = k & 1;
                delta[c] = k >> 1;
                voxel_cell(delta, Some(axis), gstride)
            })
        })
        .collect();
    edges.sort_unstable_by_key(|e| 3 * e.at + e.axis as isize);
    edges
}

/// The offsets of the 3 × 3 × 3 block around a point of a grid of strides `gstride`, in
/// the order of the block's bits `9(dz+1) + 3(dy+1) + (dx+1)`.
fn block_offsets(gstride: [usize; 3]) -> [isize; 27] {
    std::array::from_fn(|k| {
        let d = [k / 9, (k / 3) % 3, k % 3].map(|x| x as isize - 1);
        (0..3).map(|a| d[a] * gstride[a] as isize).sum()
    })
}

/// The bit of the offset `d` (each coordinate in -1, 0, 1) in a 3 × 3 × 3 block mask.
fn block_bit(d: [isize; 3]) -> u32 {
    1 << (9 * (d[0] + 1) + 3 * (d[1] + 1) + d[2] + 1)
}

/// A cube near a point: its eight corners as block bits, and the offset of its lower corner.
struct Template {
    corners: u32,
    at: isize,
}

/// The cube of lower corner `low` (offsets from a point), as a [`Template`].
fn cube_at(low: [isize; 3], gstride: [usize; 3]) -> Template {
    let corners = (0..8).fold(0, |m, k| m | block_bit([low[0] + (k >> 2), low[1] + ((k >> 1) & 1), low[2] + (k & 1)]));
    Template { corners, at: (0..3).map(|a| low[a] * gstride[a] as isize).sum() }
}

/// The eight cubes that have a point as a corner.
fn cube_templates(gstride: [usize; 3]) -> [Template; 8] {
    std::array::from_fn(|d| cube_at([-((d as isize >> 2) & 1), -((d as isize >> 1) & 1), -(d as isize & 1)], gstride))
}

/// A 2-cell that has a point as a corner: its four corners as block bits, the offset of its
/// id (`3 · lower corner + normal`) from three times the point, and its two cofaces.
struct FaceTemplate {
    corners: u32,
    id: isize,
    /// the offset of its latest edge from three times the point (V: of its two edges
    /// at the point, the one of larger id)
    pivot: isize,
    cofaces: [Template; 2],
}

/// The twelve 2-cells that have a point as a corner, by id.
fn face_templates(gstride: [usize; 3]) -> Vec<FaceTemplate> {
    let mut faces = Vec::with_capacity(12);
    for normal in 0..3 {
        let [a, b] = OTHERS[normal];
        for (da, db) in [(0isize, 0isize), (1, 0), (0, 1), (1, 1)] {
            let mut low = [0isize; 3];
            low[a] = -da;
            low[b] = -db;
            let mut corners = 0;
            for (ea, eb) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
                let mut c = low;
                c[a] += ea;
                c[b] += eb;
                corners |= block_bit(c);
            }
            let mut below = low;
            below[normal] -= 1;
            let at: isize = (0..3).map(|x| low[x] * gstride[x] as isize).sum();
            // the edges at the point: along a from low + db e_b, along b from low + da e_a
            let pivot = (-3 * da * gstride[a] as isize + a as isize).max(-3 * db * gstride[b] as isize + b as isize);
            faces.push(FaceTemplate {
                corners,
                id: 3 * at + normal as isize,
                pivot,
                cofaces: [cube_at(low, gstride), cube_at(below, gstride)],
            });
        }
    }
    faces.sort_unstable_by_key(|f| f.id);
    faces
}

/// The boundary of the 2-cell `id = 3 · corner + normal` of a 3-D grid of strides `stride`
/// (the corner's point grid): `+e(c, a) + e(c + e_a, b) - e(c + e_b, a) - e(c, b)` for
/// the other axes `a < b` (the signs of [`face_sign`]: along `a`, its first axis, the faces
/// are the edges along `b`), edges keyed by `edge_key(corner, axis)` (`None`: left out),
/// sorted by key.
#[inline]
fn square_boundary<E: Entry>(
    id: u32,
    stride: [usize; 3],
    field: Zp,
    edge_key: impl Fn(usize, usize) -> Option<u64>,
    col: &mut Vec<E>,
) {
    let (low, normal) = (id as usize / 3, id as usize % 3);
    let [a, b] = OTHERS[normal];
    let coef = |j: usize, upper: bool| if face_sign(j, upper) > 0 { 1 } else { field.of(-1) };
    col.clear();
    for (v, axis, coef) in [
        (low, a, coef(1, false)),
        (low + stride[a], b, coef(0, true)),
        (low + stride[b], a, coef(1, true)),
        (low, b, coef(0, false)),
    ] {
        if let Some(k) = edge_key(v, axis) {
            col.push(E::new(k, coef));
        }
    }
    col.sort_unstable_by_key(|e| e.key());
}

/// An entry of a column of the middle dimension: a key `(rank << 32) | edge` and a
/// coefficient, or over Z/2 the key alone (8 bytes instead of 16: the merges and the
/// stored columns read half as much).
trait Entry: Copy + Default {
    fn new(key: u64, coef: u32) -> Self;
    fn key(self) -> u64;
    fn coef(self) -> u32;

    /// `out = a + f · b` for entries sorted by key, zeros dropped.
    #[inline]
    fn merge(field: Zp, a: &[Self], f: u32, b: &[Self], out: &mut Vec<Self>) {
        out.clear();
        let (mut i, mut j) = (0, 0);
        while i < a.len() && j < b.len() {
            let (ka, kb) = (a[i].key(), b[j].key());
            if ka < kb {
                out.push(a[i]);
                i += 1;
            } else if kb < ka {
                out.push(Self::new(kb, field.mul(f, b[j].coef())));
                j += 1;
            } else {
                let c = field.add(a[i].coef(), field.mul(f, b[j].coef()));
                if c != 0 {
                    out.push(Self::new(ka, c));
                }
                i += 1;
                j += 1;
            }
        }
        out.extend_from_slice(&a[i..]);
        out.extend(b[j..].iter().map(|x| Self::new(x.key(), field.mul(f, x.coef()))));
    }
}

impl Entry for u64 {
    #[inline(always)]
    fn new(key: u64, _: u32) -> Self {
        key
    }
    #[inline(always)]
    fn key(self) -> u64 {
        self
    }
    #[inline(always)]
    fn coef(self) -> u32 {
        1
    }

    /// Over Z/2 the sum is the symmetric difference.
    #[inline]
    fn merge(_: Zp, a: &[u64], _: u32, b: &[u64], out: &mut Vec<u64>) {
        out.clear();
        let (mut i, mut j) = (0, 0);
        while i < a.len() && j < b.len() {
            let (x, y) = (a[i], b[j]);
            if x < y {
                out.push(x);
                i += 1;
            } else if y < x {
                out.push(y);
                j += 1;
            } else {
                i += 1;
                j += 1;
            }
        }
        out.extend_from_slice(&a[i..]);
        out.extend_from_slice(&b[j..]);
    }
}

impl Entry for (u64, u32) {
    #[inline(always)]
    fn new(key: u64, coef: u32) -> Self {
        (key, coef)
    }
    #[inline(always)]
    fn key(self) -> u64 {
        self.0
    }
    #[inline(always)]
    fn coef(self) -> u32 {
        self.1
    }
}

/// Columns of at most this many entries are added into a long column in place.
const SHORT: usize = 8;

/// The column reduction of the middle dimension of a 3-D image: the negative 2-cells in
/// filtration order, each column reduced until its pivot (latest edge, the largest key
/// `(rank << 32) | edge`) has no owner. Only the columns changed by a reduction are stored
/// (one after the other in one array); the others are recomputed from the boundary when
/// needed. An edge's owner is one `u32`: [`Middle::FREE`], the place `k < 4` of an
/// unchanged column's 2-cell among the edge's four cofaces ([`coface`]), or `4 + i` for
/// the stored column whose header (its length) is `entries[i]`, so that finding the column
/// to add reads no table and one cache line. A short column (at most [`SHORT`] entries)
/// added into a long one goes in place, each entry found by bisection and moved in (on
/// 128³ random T, 990,597 such additions meet working columns of 716 entries on average);
/// otherwise the part of the working column from the added column's first key up is
/// merged with it, the rest staying in place.
struct Middle<E> {
    field: Zp,
    /// the point strides of the grid the edges and 2-cells are named on
    stride: [usize; 3],
    owner: Vec<u32>,
    /// the stored columns one after the other, each a header entry (its key the column's
    /// length) followed by the column: finding a stored column reads one cache line
    entries: Vec<E>,
    col: Vec<E>,
    other: Vec<E>,
    scratch: Vec<E>,
}

/// The `k`-th of the four 2-cells containing the edge `e = 3 · point + axis` on a grid of
/// point strides `stride`: spanned by the edge's axis and the other axis `o` (the first of
/// the two others for `k < 2`), lower corner the edge's point minus `(k & 1) · e_o`.
#[inline]
fn coface(e: u32, k: u32, stride: [usize; 3]) -> u32 {
    let (v, axis) = (e as usize / 3, e as usize % 3);
    let others = OTHERS[axis];
    let (o, normal) = if k < 2 { (others[0], others[1]) } else { (others[1], others[0]) };
    (3 * (v - (k as usize & 1) * stride[o]) + normal) as u32
}

/// The place of the 2-cell `id` among the cofaces of its edge `e` ([`coface`]).
#[inline]
fn coface_place(e: u32, id: u32) -> u32 {
    let (v, axis) = (e as usize / 3, e as usize % 3);
    let (low, normal) = (id as usize / 3, id as usize % 3);
    let first = OTHERS[axis][1] == normal;
    2 * u32::from(!first) + u32::from(low != v)
}

/// The two axes other than each axis, in increasing order.
const OTHERS: [[usize; 2]; 3] = [[1, 2], [0, 2], [0, 1]];

impl<E: Entry> Middle<E> {
    const FREE: u32 = u32::MAX;

    fn new(edges: usize, stride: [usize; 3], field: Zp) -> Self {
        Middle {
            field,
            stride,
            owner: filled(edges, Self::FREE),
            entries: Vec::new(),
            col: Vec::new(),
            other: Vec::new(),
            scratch: Vec::new(),
        }
    }

    /// Makes the 2-cell `id` the owner of its pivot `e` if `e` has none yet (its column is
    /// then reduced as it is: its boundary) and says whether it did.
    #[inline]
    fn take(&mut self, e: u32, id: u32) -> bool {
        let free = self.owner[e as usize] == Self::FREE;
        if free {
            self.owner[e as usize] = coface_place(e, id);
        }
        free
    }

    /// Reduces the column of the 2-cell `id` at rank `death`; `boundary(id, col)` fills
    /// `col` with a 2-cell's boundary, sorted by key. Records the pair it makes. Fails
    /// only if the stored columns would outgrow what an owner can address (`u32::MAX - 4`
    /// entries: 32 GB of them over Z/2).
    #[inline]
    fn column(
        &mut self,
        id: u32,
        death: u32,
        out: &mut Out,
        boundary: impl Fn(u32, &mut Vec<E>),
    ) -> Result<(), TooLarge> {
        let field = self.field;
        boundary(id, &mut self.col);
        let mut changed = false;
        while let Some(&top) = self.col.last() {
            let pivot = top.key();
            let e = (pivot & 0xffff_ffff) as u32;
            let o = self.owner[e as usize];
            if o == Self::FREE {
                self.owner[e as usize] = if changed {
                    let at = self.entries.len();
                    if at > (u32::MAX - 4) as usize {
                        return Err(TooLarge);
                    }
                    self.entries.push(E::new(self.col.len() as u64, 0));
                    self.entries.extend_from_slice(&self.col);
                    4 + at as u32
                } else {
                    coface_place(e, id)
                };
                out.push(1, (pivot >> 32) as u32, Some(death));
                return Ok(());
            }
            let pcol: &[E] = if o < 4 {
                boundary(coface(e, o, self.stride), &mut self.other);
                &self.other
            } else {
                let at = (o - 4) as usize + 1;
                &self.entries[at..at + self.entries[at - 1].key() as usize]
            };
            // the next pivot is most likely the working column's or the added column's
            // second latest edge: their owners load while the column is added
            let n = self.col.len();
            for x in [self.col.get(n.wrapping_sub(2)), pcol.get(pcol.len().wrapping_sub(2))].into_iter().flatten() {
                prefetch(&self.owner, (x.key() & 0xffff_ffff) as usize);
            }
            let pc = pcol.last().expect("a pivot column is not zero").coef();
            let fac = field.neg(field.mul(top.coef(), field.inv(pc)));
            if pcol.len() <= SHORT && self.col.len() > 4 * SHORT {
                // a short column into a long one: in place, each entry found by bisection
                for &x in pcol.iter().rev() {
                    let (k, c) = (x.key(), field.mul(fac, x.coef()));
                    match self.col.binary_search_by_key(&k, |e| e.key()) {
                        Ok(i) => match field.add(self.col[i].coef(), c) {
                            0 => {
                                self.col.remove(i);
                            }
                            s => self.col[i] = E::new(k, s),
                        },
                        Err(i) => self.col.insert(i, E::new(k, c)),
                    }
                }
            } else {
                // the entries below the added column's first key stay
                let first = pcol[0].key();
                let lo = self.col.partition_point(|x| x.key() < first);
                E::merge(field, &self.col[lo..], fac, pcol, &mut self.scratch);
                self.col.truncate(lo);
                self.col.extend_from_slice(&self.scratch);
            }
            changed = true;
        }
        unreachable!("a negative 2-cell's column does not reduce to zero");
    }
}

/// The stored columns of [`Middle`] outgrew what an owner can address: the image is left
/// to the general route.
struct TooLarge;

/// 3-D T-construction: the voxels are the top cells. Voxels, vertices, edges and 2-cells
/// live on the padded grid ([`Padded`]: the voxel c at the point c + (1, 1, 1), its lower
/// corner at the point c); edges and 2-cells are named `3 · point + axis` (a 2-cell by its
/// lower corner and its normal axis). A cell's time is the rank of its earliest voxel.
fn t3<E: Entry>(grid: Padded, pix: Forest, field: Zp, out: &mut Out) -> Result<(), TooLarge> {
    let Padded { g, gstride, at } = grid;
    let block = block_offsets(gstride);
    let rank = pix.times(pix.nodes.len());
    let points = g[0] * gstride[0];
    let inner = gstride[0] + gstride[1] + 1;

    // dimension 0 on the vertices and edges themselves (their nodes reuse the voxels'):
    // each voxel brings the vertices and edges none of its neighbours brought before it
    // (a cell's time is its earliest voxel's), the vertices first, then the edges in the
    // order of their ids, as the filtration orders the cells of one rank. `negative_edges`
    // marks the edges that join two components (a bit per edge id).
    let mut vert = pix;
    let (corners, edges) = (corner_templates(gstride), edge_templates(gstride));
    let mut negative_edges: BitVec = BitVec::repeat(false, 3 * points);
    for (r, &v) in at.iter().enumerate() {
        if let Some(&q) = at.get(r + AHEAD) {
            touch_rows(&rank, q as usize, [gstride[0], gstride[1]], &BLOCK);
            touch_rows(&vert.nodes, q as usize - inner, [gstride[0], gstride[1]], &UPPER);
        }
        let (v, r) = (v as usize, r as u32);
        let mut early = 0u32;
        for (k, &o) in block.iter().enumerate() {
            early |= u32::from(rank[v.wrapping_add_signed(o)] < r) << k;
        }
        for c in &corners {
            if early & c.voxels == 0 {
                vert.make(v.wrapping_add_signed(c.at) as u32, r);
            }
        }
        for e in &edges {
            if early & e.voxels == 0 {
                let low = v.wrapping_add_signed(e.at);
                if let Some(young) = vert.union(low as u32, (low + gstride[e.axis]) as u32, true) {
                    out.push(0, young, Some(r));
                    negative_edges.set(3 * low + e.axis, true);
                }
            }
        }
    }
    drop(vert);
    // the six faces of a voxel by id, as (offset of the id from 3 · its lower corner,
    // offset of the other voxel): below along z, y, x, then above along x, y, z
    let faces: [(usize, isize); 6] = std::array::from_fn(|k| {
        let a = if k < 3 { k } else { 5 - k };
        let s = gstride[a] as isize;
        if k < 3 {
            (a, -s)
        } else {
            (3 * gstride[a] + a, s)
        }
    });

    // dimension 2 on the dual: voxels and the outside; `negative[r]` says which faces of
    // the voxel of rank r (bit k: `faces[k]`) are its own (the other voxel later or
    // absent) and join no two components
    let mut f = Forest::new(points + 1);
    let outside = points as u32;
    f.make(outside, u32::MAX);
    let mut negative = vec![0u8; at.len()];
    for r in (0..at.len()).rev() {
        if let Some(&q) = r.checked_sub(AHEAD).and_then(|a| at.get(a)) {
            touch_rows(&rank, q as usize, [gstride[0], gstride[1]], &CROSS);
            touch_rows(&f.nodes, q as usize, [gstride[0], gstride[1]], &CROSS);
        }
        let v = at[r] as usize;
        let r = r as u32;
        f.make(v as u32, r);
        let mut neg = 0u8;
        for (k, &(_, o)) in faces.iter().enumerate().rev() {
            let q = v.wrapping_add_signed(o);
            let t = rank[q];
            if t <= r {
                continue; // the face is the other voxel's
            }
            let other = if t == u32::MAX { outside } else { q as u32 };
            if let Some(young) = f.union(v as u32, other, false) {
                out.push(2, r, Some(young));
            } else {
                neg |= 1 << k;
            }
        }
        negative[r as usize] = neg;
    }
    drop(f);

    // dimension 1: an edge's time is its earliest voxel's; the negative edges are left out
    // (see `v3`)
    let edge_key = |v: usize, axis: usize| -> Option<u64> {
        let e = 3 * v + axis;
        if negative_edges[e] {
            return None;
        }
        let [b, c] = OTHERS[axis];
        let at = v + inner;
        let t = rank[at].min(rank[at - gstride[b]]).min(rank[at - gstride[c]]).min(rank[at - gstride[b] - gstride[c]]);
        Some(((t as u64) << 32) | e as u64)
    };
    let mut middle = Middle::<E>::new(3 * points, gstride, field);
    for (r, &neg) in negative.iter().enumerate() {
        if let Some(&q) = at.get(r + AHEAD).filter(|_| negative[r + AHEAD] != 0) {
            let v = q as usize - inner;
            touch_rows(&rank, q as usize, [gstride[0], gstride[1]], &BLOCK);
            touch_rows(&middle.owner, 3 * v, [3 * gstride[0], 3 * gstride[1]], &UPPER);
        }
        let (low, r) = (at[r] as usize - inner, r as u32);
        let mut neg = neg;
        while neg != 0 {
            let id = (3 * low + faces[neg.trailing_zeros() as usize].0) as u32;
            neg &= neg - 1;
            middle.column(id, r, out, |id, col| square_boundary(id, gstride, field, edge_key, col))?;
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::super::{cubical_persistence, Construction, CubicalOptions, Diagram};

    /// Values from a xorshift generator: `levels` distinct values (ties), or all distinct
    /// (`levels` 0).
    fn values(n: usize, seed: u64, levels: u64) -> Vec<f64> {
        let mut x = seed;
        (0..n)
            .map(|_| {
                x ^= x << 13;
                x ^= x >> 7;
                x ^= x << 17;
                if levels == 0 {
                    (x >> 11) as f64 / (1u64 << 53) as f64
                } else {
                    (x % levels) as f64
                }
            })
            .collect()
    }

    fn pairs(d: &Diagram) -> Vec<(usize, u64, u64)> {
        let mut v: Vec<_> = d.pairs.iter().map(|p| (p.dim, p.birth.to_bits(), p.death.to_bits())).collect();
        v.sort_unstable();
        v
    }

    /// The pixel route's 3-D diagrams equal the general route's (the one that gives
    /// cycles) on arrays large enough for long columns, stored columns and every kind of
    /// addition in the middle dimension, and on arrays one or two pixels thick (the padded
    /// border on both sides of a pixel).
    #[test]
    fn pixel_route_equals_general_route_in_3d() {
        for (shape, seed, levels) in [
            ([20, 18, 16], 7, 0),
            ([17, 19, 13], 11, 0),
            ([12, 14, 15], 5, 4),
            ([9, 10, 11], 3, 2),
            ([1, 9, 8], 13, 0),
            ([7, 2, 1], 17, 3),
            ([2, 11, 2], 19, 0),
        ] {
            let vals = values(shape.iter().product(), seed, levels);
            for construction in [Construction::V, Construction::T] {
                for (field, superlevel) in [(2, false), (3, false), (2, true)] {
                    let mut opts = CubicalOptions { construction, superlevel, periodic: false, field, cycles: false };
                    let fast = cubical_persistence(&shape, &vals, &opts).unwrap();
                    opts.cycles = true;
                    let general = cubical_persistence(&shape, &vals, &opts).unwrap();
                    assert_eq!(pairs(&fast), pairs(&general), "{shape:?} {construction:?} Z/{field} {superlevel}");
                }
            }
        }
    }

    /// The same on many small random arrays, few of them with distinct values: ties make
    /// the order of the cells of one rank matter (which edges join two components, and
    /// so which rows the middle pass leaves out).
    #[test]
    fn pixel_route_equals_general_route_on_small_3d_arrays() {
        for seed in 1..=60u64 {
            let shape = [2 + seed as usize % 5, 2 + (seed as usize / 5) % 4, 3 + (seed as usize / 3) % 5];
            let vals = values(shape.iter().product(), seed * 7919, seed % 4);
            for construction in [Construction::V, Construction::T] {
                for field in [2, 3] {
                    let mut opts =
                        CubicalOptions { construction, superlevel: false, periodic: false, field, cycles: false };
                    let fast = cubical_persistence(&shape, &vals, &opts).unwrap();
                    opts.cycles = true;
                    let general = cubical_persistence(&shape, &vals, &opts).unwrap();
                    assert_eq!(pairs(&fast), pairs(&general), "{shape:?} seed {seed} {construction:?} Z/{field}");
                }
            }
        }
    }
}
