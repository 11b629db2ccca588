//! The integer homology of a cubical set of dimension ≤ 3 in one streaming pass, without a
//! chain complex: the components of the set, the components of its complement and the Euler
//! characteristic.
//!
//! A set X of closed unit cubes in `R^d`, `d ≤ 3`, has torsion-free homology, and:
//!
//! * `b_0` is the number of components of X: two cubes are joined when they share any face,
//!   a vertex included (26-connectivity in 3-D, 8 in 2-D);
//! * `b_{d-1}` (d ≥ 2) is, by Alexander duality (`H̃_{d-1}(X) ≅ H̃^0(S^d \ X)`), the number
//!   of bounded components of the complement: two absent cubes of the box are joined when
//!   they share a facet (6-connectivity in 3-D, 4 in 2-D) and the absent cubes on the box's
//!   border join the unbounded outside;
//! * in 3-D, `b_1 = b_0 + b_2 - χ`, with χ the alternating count of the cells of the closure,
//!   summed over the grid's vertices from a table of the 256 patterns of the 8 cubes around
//!   each.
//!
//! A 2-D set is computed as the same set in a box one cube thick (`n0 × 1 × n1`): its rows
//! are the layers.
//!
//! The box is read one layer of cubes (across its slowest axis) at a time from a `fill`
//! callback, and each of the two union-finds holds two layers: the labels of the previous
//! layer and the cubes of the current one. A class of the previous layer that reaches no cube
//! of the current one is finished and counted. Memory: about 40 bytes per cube of a layer
//! and per thread, whatever the number of layers; time O(cubes · α).
//!
//! **Blocks.** The layers are cut into blocks of consecutive layers, one per thread, that
//! share their boundary layer: block `i > 0` starts with the last layer of block `i - 1`.
//! A block keeps the cubes of its first layer as anchors (never finished, with their class
//! at the end of the block) and leaves the classes of its last layer open, with their labels;
//! [`block_pass`] computes one block from its layers alone and [`merge_blocks`] glues the
//! summaries along the shared layers. A process or a machine per block (the MPI route)
//! sends only its [`BlockSummary`]: O(layer) numbers, whatever the block's size.
//!
//! Periodic boxes (a torus, where Alexander duality in the sphere does not hold) have their
//! own one-pass route ([`super::torus`]: duality in the torus, with the winding
//! lattice of the complement); dimensions ≥ 4 take the chain-complex route
//! ([`super`]).
//!
//! ```
//! use gmap_homology::cubical::pass::betti_one_pass;
//! // a 3 × 3 × 3 block with its centre removed: a sphere
//! let mut bits = vec![1u8; 27];
//! bits[13] = 0;
//! let r = betti_one_pass(&[3, 3, 3], |start, out| out.copy_from_slice(&bits[start..start + out.len()])).unwrap();
//! assert_eq!((r.betti.clone(), r.euler_characteristic), (vec![1, 0, 1, 0], 2));
//! ```

use std::ops::Range;

use gmap_core::union_find::UnionFind;

use super::CubicalError;
use crate::complex::wire::{Reader, Writer};

/// What [`betti_one_pass`] found.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct OnePass {
    /// `b_0 … b_d` (the groups are free: `H_k = Z^{b_k}`)
    pub betti: Vec<u64>,
    /// the cells of the closure, alternating (counted in 3-D; `b_0 - b_1` in 2-D, `b_0` in 1-D)
    pub euler_characteristic: i64,
    /// cubes of the set
    pub cubes: u64,
    /// components of the complement in `R^d`, the unbounded one included (d ≥ 2)
    pub complement_components: u64,
    /// the blocks the layers were cut into (threads)
    pub blocks: usize,
}

/// The largest number of cubes in one padded layer (three layers of items are numbered by
/// `u32`).
pub const MAX_LAYER: usize = (u32::MAX as usize - 2) / 3;

/// The bytes [`betti_one_pass`] holds per padded layer cube and block.
pub const BYTES_PER_LAYER_CUBE: u64 = 72;

/// The Betti numbers of the set of a box of `shape` cubes (axis 0 fastest, `1 ≤ d ≤ 3`),
/// whose presence bytes (non-zero: the cube is in the set) `fill(start, out)` writes for the
/// cubes `start .. start + out.len()` in that order. `fill` is called once per layer of the
/// slowest axis and block, from the block's thread ([`gmap_core::parallel`] decides how
/// many). See the [module docs](self). Refuses a dimension outside 1–3, an empty box, a
/// layer over [`MAX_LAYER`] cubes, or layers over the memory limit.
pub fn betti_one_pass(shape: &[usize], fill: impl Fn(usize, &mut [u8]) + Sync) -> Result<OnePass, CubicalError> {
    let d = shape.len();
    if !(1..=3).contains(&d) || shape.contains(&0) {
        return Err(CubicalError::BadShape(format!(
            "the one-pass route takes dimensions 1 to 3, not the shape {shape:?}"
        )));
    }
    if d == 1 {
        let mut row = vec![0u8; shape[0]];
        fill(0, &mut row);
        let (mut runs, mut cubes, mut last) = (0u64, 0u64, false);
        for &b in &row {
            let p = b != 0;
            runs += (p && !last) as u64;
            cubes += p as u64;
            last = p;
        }
        return Ok(OnePass {
            betti: vec![runs, 0],
            euler_characteristic: runs as i64,
            cubes,
            complement_components: 0,
            blocks: 1,
        });
    }
    if d == 2 {
        // the same space as the set of the n0 × 1 × n1 box (the cubes in the same order):
        // its rows become layers, streamed in blocks, one per thread, O(row) memory, where
        // the plane as one layer would hold the whole image; its b2 is 0, and its holes
        // (the bounded components of the complement in the plane) are b1
        let r = betti_one_pass(&[shape[0], 1, shape[1]], fill)?;
        let holes = if r.cubes == 0 { 0 } else { r.betti[1] };
        return Ok(OnePass { betti: vec![r.betti[0], r.betti[1], 0], complement_components: holes + 1, ..r });
    }
    let layers = shape[2];
    let pp = padded_layer(shape)?;
    let volume = shape.iter().product::<usize>();
    // blocks of at least 8 layers
    let blocks = gmap_core::parallel::threads_for(volume, layers / 8).max(1);
    gmap_core::resources::check_memory(
        "the layers of the one-pass cubical homology",
        (pp as u64).checked_mul(BYTES_PER_LAYER_CUBE * blocks as u64),
    )?;
    let ranges = gmap_core::parallel::split_ranges(layers, blocks);
    let summaries = gmap_core::parallel::map_tasks(blocks, volume, |i| {
        let r = &ranges[i];
        // block i > 0 starts with the last layer of block i - 1
        let start = if i == 0 { 0 } else { r.start - 1 };
        block_pass(shape, start..r.end, i > 0, &fill)
    });
    let summaries = summaries.into_iter().collect::<Result<Vec<_>, _>>()?;
    Ok(merge_blocks(shape, &summaries))
}

fn padded_layer(shape: &[usize]) -> Result<usize, CubicalError> {
    (shape[0] + 2).checked_mul(shape[1] + 2).filter(|&p| p <= MAX_LAYER).ok_or_else(|| CubicalError::TooLarge {
        points: format!("{} × {} (a layer)", shape[0], shape[1]),
        limit: MAX_LAYER as u64,
    })
}

/// A block of layers, computed alone: what [`merge_blocks`] needs of it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct BlockSummary {
    /// the layers of the block
    pub layers: Range<usize>,
    /// classes of the set that touch neither the first layer (past block 0) nor the last one
    /// (before the last block)
    pub set_finished: u64,
    /// bounded classes of the complement, likewise
    pub complement_finished: u64,
    /// χ of the vertex layers the block owns (all between its layers, and the one after
    /// its last layer in the last block; in 3-D)
    pub euler: i64,
    /// cubes of the set in the block's own layers (the first one excluded past block 0)
    pub cubes: u64,
    /// per padded cube of the first layer (past block 0): its class of the set at the end
    /// of the block, an anchor `1 ..= pp`, or `u32::MAX` for an absent cube
    pub set_first: Vec<u32>,
    /// the same for the complement, 0 for the outside, `u32::MAX` for a cube of the set
    pub complement_first: Vec<u32>,
    /// per padded cube of the last layer (before the last block): its class, an anchor
    /// (`1 ..= pp`) or a class of the block's own (`> pp`), `u32::MAX` for an absent cube
    pub set_last: Vec<u32>,
    /// the same for the complement
    pub complement_last: Vec<u32>,
}

impl BlockSummary {
    /// The message a process sends of it: the label arrays as runs of equal labels (a
    /// label holds along a run of cubes), so O(runs of the shared layers) bytes.
    pub fn to_bytes(&self) -> Vec<u8> {
        let mut w = Writer::default();
        w.u64(self.layers.start as u64);
        w.u64(self.layers.end as u64);
        w.u64(self.set_finished);
        w.u64(self.complement_finished);
        w.i64(self.euler);
        w.u64(self.cubes);
        for v in [&self.set_first, &self.complement_first, &self.set_last, &self.complement_last] {
            w.runs(v);
        }
        w.bytes
    }

    /// Reads back what [`BlockSummary::to_bytes`] wrote, for a box of `shape`; a malformed
    /// message is an error ([`CubicalError::BadMessage`]), never a panic.
    pub fn from_bytes(shape: &[usize], bytes: &[u8]) -> Result<BlockSummary, CubicalError> {
        let pp = padded_layer(shape)?;
        let mut r = Reader::new(bytes, "a block summary");
        let start = r.usize(usize::MAX)?;
        let end = r.usize(usize::MAX)?;
        let (set_finished, complement_finished, euler, cubes) = (r.u64()?, r.u64()?, r.i64()?, r.u64()?);
        let mut labels = Vec::with_capacity(4);
        for _ in 0..4 {
            let v = r.runs(pp)?;
            if !v.is_empty() && v.len() != pp {
                return Err(r.error(&format!("{} labels for a padded layer of {pp} cubes", v.len())));
            }
            labels.push(v);
        }
        r.finish()?;
        let n2 = if shape.len() == 3 { shape[2] } else { 1 };
        if start >= end || end > n2 {
            return Err(r.error(&format!("layers {start}..{end} of a box of {n2}")));
        }
        // a block past the first has its first layer's labels, one before the last its last's
        for (i, need) in [start > 0, start > 0, end < n2, end < n2].into_iter().enumerate() {
            if labels[i].is_empty() == need {
                return Err(r.error(&format!(
                    "label array {i} is {} for layers {start}..{end}",
                    if need { "missing" } else { "unexpected" }
                )));
            }
        }
        let [set_first, complement_first, set_last, complement_last]: [Vec<u32>; 4] =
            labels.try_into().map_err(|_| r.error("four label arrays"))?;
        Ok(BlockSummary {
            layers: start..end,
            set_finished,
            complement_finished,
            euler,
            cubes,
            set_first,
            complement_first,
            set_last,
            complement_last,
        })
    }
}

/// One block of layers `layers`: block 0 starts at layer 0; a later block (`shared`) starts
/// with the last layer of the block before it, whose cubes it keeps as anchors. Reads only
/// its layers through `fill`.
pub fn block_pass(
    shape: &[usize],
    layers: Range<usize>,
    shared: bool,
    fill: &(impl Fn(usize, &mut [u8]) + Sync),
) -> Result<BlockSummary, CubicalError> {
    let d = shape.len();
    if !(2..=3).contains(&d) || shape.contains(&0) {
        return Err(CubicalError::BadShape(format!(
            "a block of the one-pass route in dimension 2 or 3, not {shape:?}"
        )));
    }
    let n2 = if d == 3 { shape[2] } else { 1 };
    if layers.start >= layers.end || layers.end > n2 {
        return Err(CubicalError::BadShape(format!("layers {layers:?} of a box of {n2}")));
    }
    if !shared && layers.start > 0 {
        return Err(CubicalError::BadShape(format!("block 0 starts at layer 0, not {}", layers.start)));
    }
    padded_layer(shape)?;
    let (n0, n1) = (shape[0], shape[1]);
    let open_end = layers.end < n2;
    let mut pass = Pass::new(n0, n1, d == 3, shared);
    let mut raw = vec![0u8; n0 * n1];
    let mut cubes = 0u64;
    let mut firsts = None;
    for z in layers.clone() {
        fill(z * n0 * n1, &mut raw);
        let anchor_layer = shared && z == layers.start;
        if !anchor_layer {
            cubes += raw.iter().filter(|&&b| b != 0).count() as u64;
        }
        pass.load(Some(&raw));
        pass.step(z == layers.start, false);
        if anchor_layer {
            firsts = Some((pass.set.cur.clone(), pass.comp.cur.clone()));
        }
    }
    let (set_last, complement_last) = if open_end {
        (pass.set.cube_labels(&pass.set.cur, &pass.set.label), pass.comp.cube_labels(&pass.comp.cur, &pass.comp.label))
    } else {
        pass.load(None);
        pass.step(false, true);
        (Vec::new(), Vec::new())
    };
    let (set_first, complement_first) = match firsts {
        Some((s, c)) => (pass.set.anchor_labels(&s), pass.comp.anchor_labels(&c)),
        None => (Vec::new(), Vec::new()),
    };
    Ok(BlockSummary {
        layers,
        set_finished: pass.set.finished,
        complement_finished: pass.comp.finished,
        euler: pass.euler,
        cubes,
        set_first,
        complement_first,
        set_last,
        complement_last,
    })
}

/// Glues the summaries of consecutive blocks (block 0 first) along their shared layers: the
/// classes open at a cut are joined through the cubes of the shared layer, and each class
/// made of them counts once. O(blocks × layer).
pub fn merge_blocks(shape: &[usize], blocks: &[BlockSummary]) -> OnePass {
    let d = shape.len();
    let pp = (shape[0] + 2) * (shape[1] + 2);
    let (mut set_finished, mut comp_finished, mut euler, mut cubes) = (0u64, 0u64, 0i64, 0u64);
    for b in blocks {
        set_finished += b.set_finished;
        comp_finished += b.complement_finished;
        euler += b.euler;
        cubes += b.cubes;
    }
    // the ids of block i: 0 the outside, (i, x) for its item x
    let span = 1u64 << 32;
    for (is_set, finished) in [(true, &mut set_finished), (false, &mut comp_finished)] {
        if blocks.len() < 2 {
            break;
        }
        let mut uf = UnionFind::new(1);
        let mut index: rustc_hash::FxHashMap<u64, u32> = Default::default();
        let mut id = |uf: &mut UnionFind, block: usize, x: u32| -> u32 {
            if x == 0 {
                return 0;
            }
            *index.entry(block as u64 * span + x as u64).or_insert_with(|| uf.push())
        };
        for i in 0..blocks.len() - 1 {
            let (a, b) = (&blocks[i], &blocks[i + 1]);
            let (last, first) =
                if is_set { (&a.set_last, &b.set_first) } else { (&a.complement_last, &b.complement_first) };
            for p in 0..pp {
                let (x, y) = (last[p], first[p]);
                if x == NONE || y == NONE {
                    continue;
                }
                // an anchor of block i is an item of the block before it: the same class
                let (ia, ib) = (id(&mut uf, i, x), id(&mut uf, i + 1, y));
                uf.union(ia, ib);
            }
        }
        // a last-layer label of block i that is an anchor names the same class as that
        // anchor in block i's first layer (both are `block i, x`): chains cross whole blocks
        let roots: std::collections::HashSet<u32> = (1..uf.len() as u32).map(|x| uf.find(x)).collect();
        *finished += roots.iter().filter(|&&r| r != 0).count() as u64;
    }
    let bounded = comp_finished;
    let b0 = set_finished;
    let (betti, chi) = if d == 2 {
        (vec![b0, bounded, 0], b0 as i64 - bounded as i64)
    } else {
        let b1 = b0 as i64 + bounded as i64 - euler;
        (vec![b0, b1.max(0) as u64, bounded, 0], euler)
    };
    if cubes == 0 {
        return OnePass {
            betti: vec![0; d + 1],
            euler_characteristic: 0,
            cubes: 0,
            complement_components: 1,
            blocks: blocks.len(),
        };
    }
    OnePass { betti, euler_characteristic: chi, cubes, complement_components: bounded + 1, blocks: blocks.len() }
}

/// The contribution to χ of the cells whose minimal vertex is a grid vertex, for each pattern
/// of the 8 cubes around it: bit `4 dx + dy + 2 dz` for the cube on the upper side of the
/// vertex along x (`dx = 1`), y, z.
fn euler_table() -> [i8; 256] {
    let mut t = [0i8; 256];
    for (code, slot) in t.iter_mut().enumerate() {
        let cube = |dx: usize, dy: usize, dz: usize| code >> (4 * dx + dy + 2 * dz) & 1 == 1;
        let mut chi = 0i8;
        // the cell spanning the axes in `span` from the vertex: present iff a cube around the
        // vertex on the upper side along each spanned axis is present
        for span in 0..8usize {
            let mut present = false;
            for c in 0..8usize {
                let (dx, dy, dz) = (c & 1, c >> 1 & 1, c >> 2 & 1);
                let ok = (0..3).all(|a| span >> a & 1 == 0 || [dx, dy, dz][a] == 1);
                present |= ok && cube(dx, dy, dz);
            }
            if present {
                chi += if span.count_ones() % 2 == 0 { 1 } else { -1 };
            }
        }
        *slot = chi;
    }
    t
}

const NONE: u32 = u32::MAX;

/// The runs of one layer: maximal intervals `[x0, x1)` of cubes of one kind (in the set, or
/// not) along axis 0, row after row.
#[derive(Clone, Debug, Default)]
struct Runs {
    /// `start[y] .. start[y + 1]`: the runs of row y
    start: Vec<u32>,
    x0: Vec<u32>,
    x1: Vec<u32>,
}

impl Runs {
    fn clear(&mut self) {
        self.start.clear();
        self.x0.clear();
        self.x1.clear();
    }

    fn row(&self, y: usize) -> Range<usize> {
        self.start[y] as usize..self.start[y + 1] as usize
    }

    fn len(&self) -> usize {
        self.x0.len()
    }
}

/// One of the two union-finds of a block (the set's or the complement's) over runs. Items:
/// 0 the outside (complement only), `1 + i` the i-th run of the block's first layer (an
/// anchor, in a block past the first), `1 + r + i` the i-th run of the previous layer,
/// `1 + 2r + i` of the current one, r the most runs a layer can have. A root is the smallest
/// item of its class, so the outside and the anchors are roots of the classes they are in.
struct Kind {
    /// the kind of cube: 1 the set, 0 the complement
    want: u8,
    /// 1 for the set's connectivity (any shared face), 0 for the complement's (facets)
    reach: u32,
    r: usize,
    /// padded row length (n0 + 2)
    width: usize,
    uf: UnionFind,
    prev: Runs,
    cur: Runs,
    /// the label of each run of the previous layer: the outside, an anchor or an item of
    /// the previous layer
    label: Vec<u32>,
    /// per item: the stamp of its last use and the first label given to its class then
    stamp: Vec<u32>,
    first: Vec<u32>,
    clock: u32,
    roots: Vec<u32>,
    finished: u64,
}

impl Kind {
    fn new(want: u8, n0: usize, n1: usize) -> Kind {
        let r = n1 * n0.div_ceil(2) + 1;
        Kind {
            want,
            reach: want as u32,
            r,
            width: n0 + 2,
            uf: UnionFind::new(3 * r + 1),
            prev: Runs::default(),
            cur: Runs::default(),
            label: Vec::new(),
            stamp: vec![0; 3 * r + 1],
            first: vec![NONE; 3 * r + 1],
            clock: 0,
            roots: Vec::new(),
            finished: 0,
        }
    }

    /// The runs of `layer` (n0 × n1 presence bytes, 0 or 1) become the current ones.
    fn load(&mut self, layer: Option<&[u8]>, n0: usize, n1: usize) {
        std::mem::swap(&mut self.prev, &mut self.cur);
        self.cur.clear();
        self.cur.start.push(0);
        for y in 0..n1 {
            if let Some(layer) = layer {
                let row = &layer[y * n0..(y + 1) * n0];
                let mut x = 0;
                while x < n0 {
                    // the next cube of the kind, then the end of its run
                    match row[x..].iter().position(|&b| b == self.want) {
                        None => break,
                        Some(k) => x += k,
                    }
                    let end = row[x..].iter().position(|&b| b != self.want).map_or(n0, |k| x + k);
                    self.cur.x0.push(x as u32);
                    self.cur.x1.push(end as u32);
                    x = end;
                }
            }
            self.cur.start.push(self.cur.x0.len() as u32);
        }
    }

    fn tick(&mut self) -> u32 {
        self.clock += 1;
        self.clock
    }

    /// Seeds the items of the previous layer from their labels and the current ones as
    /// singletons.
    fn seed(&mut self, cur_base: u32) {
        let prev_base = (1 + self.r) as u32;
        for (i, &l) in self.label.iter().enumerate() {
            let it = prev_base + i as u32;
            self.uf.set_parent(it, if l == NONE { it } else { l });
        }
        for i in 0..self.cur.len() as u32 {
            self.uf.set_parent(cur_base + i, cur_base + i);
        }
    }

    /// Joins the runs of rows `a` (items from `base_a`) and `b` (items from `base_b`) that
    /// meet: their intervals widened by `reach` overlap. Both lists are sorted: one walk.
    fn join_rows(&mut self, a: Range<usize>, base_a: u32, b_prev: bool, b: Range<usize>, base_b: u32) {
        let (mut i, mut j) = (a.start, b.start);
        let e = self.reach;
        let (ax0, ax1) = (&self.cur.x0, &self.cur.x1);
        let (bx0, bx1) = if b_prev { (&self.prev.x0, &self.prev.x1) } else { (&self.cur.x0, &self.cur.x1) };
        let mut uf = self.uf.view();
        let mut last = NONE;
        while i < a.end && j < b.end {
            let (a0, a1, b0, b1) = (ax0[i], ax1[i], bx0[j], bx1[j]);
            if a0 < b1 + e && b0 < a1 + e {
                let x = base_a + i as u32;
                let y = if b_prev { self.label[j] } else { base_b + j as u32 };
                if y != last {
                    last = y;
                    let (rx, ry) = (uf.find(x), uf.find(y));
                    if rx != ry {
                        uf.link_roots(rx, ry);
                    }
                }
            }
            if a1 <= b1 {
                i += 1;
                last = NONE;
            }
            if b1 <= a1 {
                j += 1;
            }
        }
    }

    /// Links the current layer: each row with the row before it and with the rows of the
    /// previous layer it touches; `outside_rows`: the runs on the box's sides join the
    /// outside (complement); `prev_items`: whether the previous layer has items.
    fn link(&mut self, cur_base: u32, n0: usize, n1: usize, prev_items: bool) {
        let cur_rows = |k: &Kind, y: usize| k.cur.row(y);
        for y in 0..n1 {
            let row = cur_rows(self, y);
            if row.is_empty() {
                continue;
            }
            // the row before, in this layer
            if y > 0 {
                let before = cur_rows(self, y - 1);
                self.join_rows(row.clone(), cur_base, false, before, cur_base);
            }
            if prev_items {
                let lo = if self.reach == 1 { y.saturating_sub(1) } else { y };
                let hi = if self.reach == 1 { (y + 1).min(n1 - 1) } else { y };
                for yy in lo..=hi {
                    let below = self.prev.row(yy);
                    self.join_rows(row.clone(), cur_base, true, below, 0);
                }
            }
            if self.want == 0 {
                // the complement's runs on the sides of the box are the outside
                let mut uf = self.uf.view();
                for i in row {
                    if y == 0 || y + 1 == n1 || self.cur.x0[i] == 0 || self.cur.x1[i] as usize == n0 {
                        let r = uf.find(cur_base + i as u32);
                        if r != 0 {
                            uf.link_roots(r, 0);
                        }
                    }
                }
            }
        }
    }

    /// Every current run (or every run of the previous layer, `prev`) joins the outside.
    fn all_outside(&mut self, cur_base: u32, prev: bool) {
        let n = if prev { self.label.len() } else { self.cur.len() };
        let mut uf = self.uf.view();
        for i in 0..n {
            let x = if prev { self.label[i] } else { cur_base + i as u32 };
            let r = uf.find(x);
            if r != 0 {
                uf.link_roots(r, 0);
            }
        }
    }

    /// Counts the classes of the previous layer's labels that reach no run of the current
    /// layer (the outside and anchored classes excepted), and labels the current runs: the
    /// root when it is the outside or an anchor, else the item its class's first run will
    /// have as a run of the previous layer.
    fn finish_and_label(&mut self, cur_base: u32) {
        let r = self.r as u32;
        let mark = self.tick();
        let n = self.cur.len();
        self.roots.clear();
        for i in 0..n as u32 {
            let root = self.uf.find(cur_base + i);
            self.roots.push(root);
            self.stamp[root as usize] = mark;
        }
        let prev_base = 1 + r;
        for i in 0..self.label.len() {
            let l = self.label[i];
            // one count per class, at the run that owns its label
            if l == prev_base + i as u32 {
                let root = self.uf.find(l);
                if root > r && self.stamp[root as usize] != mark {
                    self.stamp[root as usize] = mark;
                    self.finished += 1;
                }
            }
        }
        let label = self.tick();
        self.label.clear();
        for i in 0..n {
            let root = self.roots[i];
            self.label.push(if root <= r {
                root
            } else {
                if self.stamp[root as usize] != label {
                    self.stamp[root as usize] = label;
                    self.first[root as usize] = prev_base + i as u32;
                }
                self.first[root as usize]
            });
        }
    }

    /// Per padded cube of a layer with `runs` (`labels[i]` for the cubes of run i), NONE
    /// elsewhere.
    fn cube_labels(&self, runs: &Runs, labels: &[u32]) -> Vec<u32> {
        let n1 = runs.start.len() - 1;
        let w = self.width;
        let mut out = vec![NONE; w * (n1 + 2)];
        for y in 0..n1 {
            for i in runs.row(y) {
                let base = (y + 1) * w + 1;
                out[base + runs.x0[i] as usize..base + runs.x1[i] as usize].fill(labels[i]);
            }
        }
        out
    }

    /// The classes at the end of the block of the anchored runs of the first layer, per
    /// padded cube.
    fn anchor_labels(&mut self, runs: &Runs) -> Vec<u32> {
        let roots: Vec<u32> = (0..runs.len() as u32).map(|i| self.uf.find(1 + i)).collect();
        self.cube_labels(runs, &roots)
    }
}

/// The state of a block between two layers: the two kinds and the Euler characteristic of
/// the vertices seen.
struct Pass {
    n0: usize,
    n1: usize,
    /// 3-D: the layers before the box and after it are the outside; 2-D: there are none
    three: bool,
    anchored: bool,
    set: Kind,
    comp: Kind,
    /// padded presence of the previous and the current layer, for χ
    prev: Vec<u8>,
    cur: Vec<u8>,
    euler: i64,
    table: [i8; 256],
}

impl Pass {
    fn new(n0: usize, n1: usize, three: bool, anchored: bool) -> Pass {
        let pp = (n0 + 2) * (n1 + 2);
        let mut set = Kind::new(1, n0, n1);
        let mut comp = Kind::new(0, n0, n1);
        set.cur.start = vec![0; n1 + 1];
        comp.cur.start = vec![0; n1 + 1];
        Pass { n0, n1, three, anchored, set, comp, prev: vec![0; pp], cur: vec![0; pp], euler: 0, table: euler_table() }
    }

    /// The next layer (n0 × n1, x fastest; `None`: the empty layer after the box).
    fn load(&mut self, raw: Option<&[u8]>) {
        let (n0, n1) = (self.n0, self.n1);
        std::mem::swap(&mut self.prev, &mut self.cur);
        let w = n0 + 2;
        match raw {
            None => self.cur.fill(0),
            Some(raw) => {
                for (y, row) in raw.chunks_exact(n0).enumerate() {
                    let dst = &mut self.cur[(y + 1) * w + 1..(y + 1) * w + 1 + n0];
                    for (o, &b) in dst.iter_mut().zip(row) {
                        *o = (b != 0) as u8;
                    }
                }
            }
        }
        // the runs read the padded rows' inner parts
        let inner: Option<Vec<u8>> = raw.map(|_| {
            let mut v = Vec::with_capacity(n0 * n1);
            for y in 0..n1 {
                v.extend_from_slice(&self.cur[(y + 1) * w + 1..(y + 1) * w + 1 + n0]);
            }
            v
        });
        self.set.load(inner.as_deref(), n0, n1);
        self.comp.load(inner.as_deref(), n0, n1);
    }

    /// Links the current layer to the previous one, counts the classes that end, labels the
    /// current runs. `first`: the block's first layer (anchors in a block past the first);
    /// `after`: the current layer is the empty one after the box.
    fn step(&mut self, first: bool, after: bool) {
        let (n0, n1) = (self.n0, self.n1);
        let anchor_layer = first && self.anchored;
        for k in [&mut self.set, &mut self.comp] {
            let cur_base = if anchor_layer { 1 } else { (1 + 2 * k.r) as u32 };
            k.seed(cur_base);
            if !after {
                // previous items: none before an anchored first layer or a 2-D layer
                let prev_items = !first;
                k.link(cur_base, n0, n1, prev_items);
                if k.want == 0 && first && self.three && !self.anchored {
                    // the layer before a 3-D box is the outside
                    k.all_outside(cur_base, false);
                }
            } else if k.want == 0 && self.three {
                // the previous layer's absent cubes meet the outside after the box
                k.all_outside(cur_base, true);
            }
            k.finish_and_label(cur_base);
        }
        if self.three && !anchor_layer {
            self.add_euler();
        }
    }

    /// The vertices between the previous and the current layer.
    fn add_euler(&mut self) {
        let w = self.n0 + 2;
        let (prev, cur) = (&self.prev, &self.cur);
        let mut sum = 0i64;
        // vertex (v, r) is the corner of padded columns v, v + 1 and rows r, r + 1
        for r in 0..self.n1 + 1 {
            let (p0, p1) = (r * w, (r + 1) * w);
            let col = |x: usize| -> usize {
                (prev[p0 + x] | prev[p1 + x] << 1 | cur[p0 + x] << 2 | cur[p1 + x] << 3) as usize
            };
            let mut lo = col(0);
            for x in 1..w {
                let hi = col(x);
                sum += self.table[lo | hi << 4] as i64;
                lo = hi;
            }
        }
        self.euler += sum;
    }
}
