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
//!   `Z/p` ([`middle`]), skipping the 2-cells the dual pass found positive (clearing):
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
//! of [`super::image`].

mod middle;
mod plane;
mod sweep;
mod volume;

use super::options::{check_field, key, unkey, Construction, CubicalOptions};
use super::{Diagram, PersistenceError};
use plane::{t2, v2};
use sweep::{Forest, Out};
use volume::{t3, v3, Padded};

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

#[cfg(test)]
mod tests;
