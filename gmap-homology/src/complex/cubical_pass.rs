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
//! Periodic boxes (a torus, where Alexander duality does not hold) and dimensions ≥ 4 take
//! the chain-complex route ([`super::cubical`]).
//!
//! ```
//! use gmap_homology::cubical_pass::betti_one_pass;
//! // a 3 × 3 × 3 block with its centre removed: a sphere
//! let mut bits = vec![1u8; 27];
//! bits[13] = 0;
//! let r = betti_one_pass(&[3, 3, 3], |start, out| out.copy_from_slice(&bits[start..start + out.len()])).unwrap();
//! assert_eq!((r.betti.clone(), r.euler_characteristic), (vec![1, 0, 1, 0], 2));
//! ```

use std::ops::Range;

use gmap_core::union_find::UnionFind;

use super::cubical::CubicalError;

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
pub fn betti_one_pass(
    shape: &[usize],
    fill: impl Fn(usize, &mut [u8]) + Sync,
) -> Result<OnePass, CubicalError> {
    let d = shape.len();
    if !(1..=3).contains(&d) || shape.contains(&0) {
        return Err(CubicalError::BadShape(format!("the one-pass route takes dimensions 1 to 3, not the shape {shape:?}")));
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
    let layers = if d == 3 { shape[2] } else { 1 };
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
        return Err(CubicalError::BadShape(format!("a block of the one-pass route in dimension 2 or 3, not {shape:?}")));
    }
    let n2 = if d == 3 { shape[2] } else { 1 };
    if layers.start >= layers.end || layers.end > n2 {
        return Err(CubicalError::BadShape(format!("layers {layers:?} of a box of {n2}")));
    }
    padded_layer(shape)?;
    let (n0, n1) = (shape[0], shape[1]);
    if !shared && layers.start > 0 {
        return Err(CubicalError::BadShape(format!("block 0 starts at layer 0, not {}", layers.start)));
    }
    let anchored = shared;
    let open_end = layers.end < n2;
    let mut pass = Pass::new(n0, n1, d == 3, anchored);
    let mut raw = vec![0u8; n0 * n1];
    let mut cubes = 0u64;
    let mut first_layer = Vec::new();
    for z in layers.clone() {
        fill(z * n0 * n1, &mut raw);
        if !(anchored && z == layers.start) {
            cubes += raw.iter().filter(|&&b| b != 0).count() as u64;
        }
        pass.load(Some(&raw));
        if anchored && z == layers.start {
            first_layer = pass.cur.clone();
        }
        pass.step(z == layers.start, false);
    }
    let (set_last, complement_last) = if open_end {
        (pass.set_label.clone(), pass.comp_label.clone())
    } else {
        pass.load(None);
        pass.step(false, true);
        (Vec::new(), Vec::new())
    };
    let (set_first, complement_first) = if anchored { pass.anchors(&first_layer) } else { (Vec::new(), Vec::new()) };
    Ok(BlockSummary {
        layers,
        set_finished: pass.set_finished,
        complement_finished: pass.complement_finished,
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
    // the ids of block i: 0 the outside, i (2 pp + 1) + x for its item x
    let span = 2 * pp as u64 + 1;
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

/// The state between two layers. Items of each union-find: 0 the outside (complement only),
/// `1 + p` the anchor of the padded cube p of the block's first layer, `1 + pp + p` the
/// cube p of the previous layer, `1 + 2 pp + p` of the current one. A root is the smallest
/// item of its class, so the outside and the anchors are roots of the classes they are in.
struct Pass {
    w: usize,
    h: usize,
    pp: usize,
    /// 3-D: the layers before the box and after it are the outside; 2-D: there are none
    three: bool,
    anchored: bool,
    prev: Vec<u8>,
    cur: Vec<u8>,
    set: UnionFind,
    comp: UnionFind,
    /// the label (an item ≤ 1 + 2 pp, or NONE) of each padded cube of the previous layer
    set_label: Vec<u32>,
    comp_label: Vec<u32>,
    /// per item: the stamp of its last use and what it held then (mark, first label)
    stamp: Vec<u32>,
    first: Vec<u32>,
    clock: u32,
    roots: Vec<u32>,
    set_finished: u64,
    complement_finished: u64,
    euler: i64,
    table: [i8; 256],
}

impl Pass {
    fn new(n0: usize, n1: usize, three: bool, anchored: bool) -> Pass {
        let (w, h) = (n0 + 2, n1 + 2);
        let pp = w * h;
        Pass {
            w,
            h,
            pp,
            three,
            anchored,
            prev: vec![0; pp],
            cur: vec![0; pp],
            set: UnionFind::new(3 * pp + 1),
            comp: UnionFind::new(3 * pp + 1),
            set_label: vec![NONE; pp],
            // before the box: the outside in 3-D; nothing in 2-D or before a block's first layer
            comp_label: vec![if three && !anchored { 0 } else { NONE }; pp],
            stamp: vec![0; 3 * pp + 1],
            first: vec![NONE; 3 * pp + 1],
            clock: 0,
            roots: vec![0; pp],
            set_finished: 0,
            complement_finished: 0,
            euler: 0,
            table: euler_table(),
        }
    }

    /// The next layer: the previous one moves back, `raw` (n0 × n1, x fastest) is padded;
    /// `None`: the layer after the box, empty.
    fn load(&mut self, raw: Option<&[u8]>) {
        std::mem::swap(&mut self.prev, &mut self.cur);
        let Some(raw) = raw else {
            self.cur.fill(0);
            return;
        };
        let n0 = self.w - 2;
        for (y, row) in raw.chunks_exact(n0).enumerate() {
            let dst = &mut self.cur[(y + 1) * self.w + 1..(y + 1) * self.w + 1 + n0];
            for (o, &b) in dst.iter_mut().zip(row) {
                *o = (b != 0) as u8;
            }
        }
    }

    fn tick(&mut self) -> u32 {
        self.clock += 1;
        self.clock
    }

    /// Links the current layer to the previous one, counts the classes that end, labels the
    /// current layer. `first`: the block's first layer (anchors in a block past the first);
    /// `after`: the current layer is the empty one after the box.
    fn step(&mut self, first: bool, after: bool) {
        let (w, h, pp) = (self.w, self.h, self.pp);
        let anchor_layer = first && self.anchored;
        // where the current layer's items are
        let cur_base = if anchor_layer { 1 } else { 1 + 2 * pp };
        let prev_base = 1 + pp;
        // the current layer's absent cubes exist (as the outside after a 3-D box)
        let cur_exists = !after || self.three;
        for p in 0..pp {
            let l = self.set_label[p];
            let it = (prev_base + p) as u32;
            self.set.set_parent(it, if l == NONE { it } else { l });
            let l = self.comp_label[p];
            self.comp.set_parent(it, if l == NONE { it } else { l });
        }
        for y in 0..h {
            for x in 0..w {
                let p = y * w + x;
                let border = x == 0 || y == 0 || x + 1 == w || y + 1 == h;
                let it = (cur_base + p) as u32;
                self.set.set_parent(it, it);
                self.comp.set_parent(it, if cur_exists && (border || after) { 0 } else { it });
            }
        }
        if !after {
            self.link_set(cur_base);
            self.link_complement(cur_base);
        } else if self.three {
            // the previous layer's absent cubes join the outside after the box
            for p in 0..pp {
                if self.prev[p] == 0 && self.comp_label[p] != NONE {
                    self.comp.union((prev_base + p) as u32, 0);
                }
            }
        }
        if self.three && !anchor_layer {
            self.add_euler();
        }
        let (sf, sl) = self.finish_and_label(true, cur_base, !after);
        self.set_finished += sf;
        self.set_label = sl;
        let (cf, cl) = self.finish_and_label(false, cur_base, cur_exists);
        self.complement_finished += cf;
        self.comp_label = cl;
    }

    /// Counts the classes of the previous layer's labels that reach no cube of the current
    /// layer (the outside and anchored classes excepted), and labels the current layer: its
    /// class's root when that is the outside or an anchor, else its first cube's item as an
    /// item of the previous layer of the next step.
    fn finish_and_label(&mut self, is_set: bool, cur_base: usize, cur_exists: bool) -> (u64, Vec<u32>) {
        let pp = self.pp;
        let want = is_set as u8;
        let mark = self.tick();
        let mut roots = std::mem::take(&mut self.roots);
        {
            let uf = if is_set { &mut self.set } else { &mut self.comp };
            for p in 0..pp {
                roots[p] = if cur_exists && self.cur[p] == want { uf.find((cur_base + p) as u32) } else { NONE };
                if roots[p] != NONE {
                    self.stamp[roots[p] as usize] = mark;
                }
            }
        }
        let labels = if is_set { &self.set_label } else { &self.comp_label };
        let uf = if is_set { &mut self.set } else { &mut self.comp };
        let mut n = 0;
        for (p, &l) in labels.iter().enumerate() {
            // one count per class, at the cube that owns its label
            if l == (1 + pp + p) as u32 {
                let r = uf.find(l) as usize;
                if r > pp && self.stamp[r] != mark {
                    self.stamp[r] = mark;
                    n += 1;
                }
            }
        }
        let label = self.tick();
        let mut out = vec![NONE; pp];
        for p in 0..pp {
            let r = roots[p];
            if r == NONE {
                continue;
            }
            out[p] = if r as usize <= pp {
                r
            } else {
                if self.stamp[r as usize] != label {
                    self.stamp[r as usize] = label;
                    self.first[r as usize] = (1 + pp + p) as u32;
                }
                self.first[r as usize]
            };
        }
        self.roots = roots;
        (n, out)
    }

    /// The classes of the first layer's cubes at the end of the block (`first_layer`: that
    /// layer's padded presence).
    fn anchors(&mut self, first_layer: &[u8]) -> (Vec<u32>, Vec<u32>) {
        let pp = self.pp;
        let mut s = vec![NONE; pp];
        let mut c = vec![NONE; pp];
        for p in 0..pp {
            let it = (1 + p) as u32;
            if first_layer[p] != 0 {
                s[p] = self.set.find(it);
            } else {
                c[p] = self.comp.find(it);
            }
        }
        (s, c)
    }

    /// 26-connectivity of the set's cubes: each cube of the current layer with the cubes
    /// before it in the layer and the 9 below.
    fn link_set(&mut self, cur_base: usize) {
        let w = self.w;
        let (prev, cur, label) = (&self.prev, &self.cur, &self.set_label);
        let mut uf = self.set.view();
        let c = |p: usize| (cur_base + p) as u32;
        for y in 1..self.h - 1 {
            for x in 1..w - 1 {
                let p = y * w + x;
                if cur[p] == 0 {
                    continue;
                }
                let mut rc = c(p);
                let mut last = NONE;
                let join = |uf: &mut gmap_core::union_find::Sets<'_>, q: u32, rc: &mut u32| {
                    let rq = uf.find(q);
                    if rq != *rc {
                        *rc = uf.link_roots(*rc, rq);
                    }
                };
                // the prev layer's cubes, by label (neighbours of one class share it)
                let mut below = |uf: &mut gmap_core::union_find::Sets<'_>, q: usize, rc: &mut u32| {
                    if prev[q] != 0 {
                        let l = label[q];
                        if l != last {
                            last = l;
                            join(uf, l, rc);
                        }
                    }
                };
                if cur[p - 1] != 0 {
                    // the left cube already joined the columns x - 1 and x
                    join(&mut uf, c(p - 1), &mut rc);
                    if cur[p - w + 1] != 0 {
                        join(&mut uf, c(p - w + 1), &mut rc);
                    }
                    for q in [p - w + 1, p + 1, p + w + 1] {
                        below(&mut uf, q, &mut rc);
                    }
                    continue;
                }
                for q in [p - w - 1, p - w, p - w + 1] {
                    if cur[q] != 0 {
                        join(&mut uf, c(q), &mut rc);
                    }
                }
                for q in [p - w - 1, p - 1, p + w - 1, p - w, p, p + w, p - w + 1, p + 1, p + w + 1] {
                    below(&mut uf, q, &mut rc);
                }
            }
        }
    }

    /// Facet connectivity of the absent cubes (the padding is the outside already).
    fn link_complement(&mut self, cur_base: usize) {
        let w = self.w;
        let (prev, cur, label) = (&self.prev, &self.cur, &self.comp_label);
        let mut uf = self.comp.view();
        let c = |p: usize| (cur_base + p) as u32;
        // the border after the box too: its cubes are the outside, linked backwards only
        for y in 1..self.h {
            for x in 1..w {
                let p = y * w + x;
                if cur[p] != 0 {
                    continue;
                }
                let mut rc = uf.find(c(p));
                for q in [p - 1, p - w] {
                    if cur[q] == 0 {
                        let rq = uf.find(c(q));
                        if rq != rc {
                            rc = uf.link_roots(rc, rq);
                        }
                    }
                }
                if prev[p] == 0 && label[p] != NONE {
                    let rq = uf.find(label[p]);
                    if rq != rc {
                        uf.link_roots(rc, rq);
                    }
                }
            }
        }
    }

    /// The vertices between the previous and the current layer.
    fn add_euler(&mut self) {
        let w = self.w;
        let (prev, cur) = (&self.prev, &self.cur);
        let mut sum = 0i64;
        // vertex (v, r) is the corner of padded columns v, v + 1 and rows r, r + 1
        for r in 0..self.h - 1 {
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
