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
//! of the current one is finished and counted. Memory: about 20 bytes per cube of a layer,
//! whatever the number of layers; time O(cubes · α).
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

use gmap_core::union_find::UnionFind;

use super::cubical::CubicalError;

/// What [`betti_one_pass`] found.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct OnePass {
    /// `b_0 … b_d` (the groups are free: `H_k = Z^{b_k}`)
    pub betti: Vec<u64>,
    /// the cells of the closure, alternating (computed in 3-D; `b_0 - b_1 + …` otherwise)
    pub euler_characteristic: i64,
    /// cubes of the set
    pub cubes: u64,
    /// components of the complement in `R^d`, the unbounded one included (d ≥ 2)
    pub complement_components: u64,
}

/// The largest number of cubes in one layer (two layers of labels are numbered by `u32`).
pub const MAX_LAYER: usize = (u32::MAX as usize - 2) / 2;

/// The Betti numbers of the set of a box of `shape` cubes (axis 0 fastest, `1 ≤ d ≤ 3`),
/// whose presence bytes (non-zero: the cube is in the set) `fill(start, out)` writes for the
/// cubes `start .. start + out.len()` in that order. `fill` is called once per layer of the
/// slowest axis, in order. See the [module docs](self). Refuses a dimension outside 1–3, an
/// empty box, or a layer over [`MAX_LAYER`] cubes.
pub fn betti_one_pass(shape: &[usize], mut fill: impl FnMut(usize, &mut [u8])) -> Result<OnePass, CubicalError> {
    let d = shape.len();
    if !(1..=3).contains(&d) || shape.contains(&0) {
        return Err(CubicalError::BadShape(format!("the one-pass route takes dimensions 1 to 3, not the shape {shape:?}")));
    }
    if d == 1 {
        let mut row = vec![0u8; shape[0]];
        fill(0, &mut row);
        let mut runs = 0u64;
        let mut cubes = 0u64;
        let mut last = false;
        for &b in &row {
            let p = b != 0;
            runs += (p && !last) as u64;
            cubes += p as u64;
            last = p;
        }
        return Ok(OnePass { betti: vec![runs, 0], euler_characteristic: runs as i64, cubes, complement_components: 0 });
    }
    let (n0, n1) = (shape[0], shape[1]);
    let n2 = if d == 3 { shape[2] } else { 1 };
    let (w, h) = (n0 + 2, n1 + 2);
    let pp = w.checked_mul(h).filter(|&p| p <= MAX_LAYER).ok_or_else(|| CubicalError::TooLarge {
        points: format!("{} × {}", n0, n1),
        limit: MAX_LAYER as u64,
    })?;
    // two layers of padded presence, a raw layer, two union-finds of 2 pp + 1 items, marks
    let bytes = (pp as u64) * (2 + 1 + 2 * 4 * 2 + 2 * 4 + 2 * 4);
    gmap_core::resources::check_memory("the one-pass cubical homology's layers", Some(bytes))?;
    let mut pass = Pass::new(n0, n1, d == 3);
    let mut raw = vec![0u8; n0 * n1];
    for z in 0..=n2 {
        if z < n2 {
            fill(z * n0 * n1, &mut raw);
            pass.load(&raw);
        } else {
            pass.load_border();
        }
        pass.step(z == n2);
    }
    let complement_components = pass.complement_finished + 1;
    let b0 = pass.set_finished;
    let bounded = pass.complement_finished;
    let (betti, chi) = if d == 2 {
        (vec![b0, bounded, 0], b0 as i64 - bounded as i64)
    } else {
        // b1 = b0 + b2 - χ ≥ 0
        let b1 = b0 as i64 + bounded as i64 - pass.euler;
        (vec![b0, b1.max(0) as u64, bounded, 0], pass.euler)
    };
    if b0 == 0 {
        return Ok(OnePass { betti: vec![0; d + 1], euler_characteristic: 0, cubes: 0, complement_components: 1 });
    }
    Ok(OnePass { betti, euler_characteristic: chi, cubes: pass.cubes, complement_components })
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

/// The state between two layers. Items of each union-find: 0 the outside (complement only),
/// `1 + p` the cube at padded position p of the previous layer, `1 + pp + p` of the current
/// one; a root is the smallest item of its class, so the outside is always a root.
struct Pass {
    w: usize,
    h: usize,
    pp: usize,
    /// 3-D: layers before the first and after the last are outside; 2-D: there are none
    three: bool,
    prev: Vec<u8>,
    cur: Vec<u8>,
    set: UnionFind,
    comp: UnionFind,
    /// label (an item of the previous layer, or 0) of each padded cube of the previous layer
    set_label: Vec<u32>,
    comp_label: Vec<u32>,
    mark: Vec<bool>,
    first: Vec<u32>,
    set_finished: u64,
    complement_finished: u64,
    euler: i64,
    cubes: u64,
    table: [i8; 256],
}

const NONE: u32 = u32::MAX;

impl Pass {
    fn new(n0: usize, n1: usize, three: bool) -> Pass {
        let (w, h) = (n0 + 2, n1 + 2);
        let pp = w * h;
        Pass {
            w,
            h,
            pp,
            three,
            prev: vec![0; pp],
            cur: vec![0; pp],
            set: UnionFind::new(2 * pp + 1),
            comp: UnionFind::new(2 * pp + 1),
            set_label: vec![NONE; pp],
            // before the first layer: the outside in 3-D, nothing in 2-D
            comp_label: vec![if three { 0 } else { NONE }; pp],
            mark: vec![false; 2 * pp + 1],
            first: vec![NONE; 2 * pp + 1],
            set_finished: 0,
            complement_finished: 0,
            euler: 0,
            cubes: 0,
            table: euler_table(),
        }
    }

    /// The next layer: the previous one moves back, `raw` (n0 × n1, x fastest) is padded.
    fn load(&mut self, raw: &[u8]) {
        std::mem::swap(&mut self.prev, &mut self.cur);
        let n0 = self.w - 2;
        for (y, row) in raw.chunks_exact(n0).enumerate() {
            let dst = &mut self.cur[(y + 1) * self.w + 1..(y + 1) * self.w + 1 + n0];
            for (o, &b) in dst.iter_mut().zip(row) {
                *o = (b != 0) as u8;
            }
        }
    }

    /// The layer after the last: empty (the outside in 3-D, nothing in 2-D).
    fn load_border(&mut self) {
        std::mem::swap(&mut self.prev, &mut self.cur);
        self.cur.fill(0);
    }

    /// Links the current layer to the previous one, counts the classes that end, labels
    /// the current layer. `last`: the current layer is the one after the box.
    fn step(&mut self, last: bool) {
        let (w, h, pp) = (self.w, self.h, self.pp);
        let cur_exists = !last || self.three;
        // seed the previous layer's items from its labels, the current ones as singletons
        for p in 0..pp {
            let l = self.set_label[p];
            self.set.set_parent(1 + p as u32, if l == NONE { 1 + p as u32 } else { l });
            let l = self.comp_label[p];
            self.comp.set_parent(1 + p as u32, if l == NONE { 1 + p as u32 } else { l });
        }
        let cur_item = |p: usize| (1 + pp + p) as u32;
        for y in 0..h {
            for x in 0..w {
                let p = y * w + x;
                let border = x == 0 || y == 0 || x + 1 == w || y + 1 == h;
                // padding cubes and an after-last 3-D layer are the outside
                let outside = cur_exists && (border || last);
                self.set.set_parent(cur_item(p), cur_item(p));
                self.comp.set_parent(cur_item(p), if outside { 0 } else { cur_item(p) });
            }
        }
        if !last {
            self.link_set();
            self.link_complement();
        } else if self.three {
            // the previous layer's absent cubes join the outside layer after it
            for p in 0..pp {
                if self.prev[p] == 0 && self.comp_label[p] != NONE {
                    self.comp.union(1 + p as u32, cur_item(p));
                }
            }
        }
        if self.three {
            self.add_euler();
        }
        // finished classes: roots of previous labels that reach no current cube
        self.set_finished += Self::finish(&mut self.set, &self.set_label, &self.cur, 1, pp, &mut self.mark, true);
        self.complement_finished +=
            Self::finish(&mut self.comp, &self.comp_label, &self.cur, 0, pp, &mut self.mark, cur_exists);
        // the current layer's labels, for the next step
        self.first.fill(NONE);
        for p in 0..pp {
            let present = self.cur[p] == 1;
            self.set_label[p] = if present && !last {
                let r = self.set.find(cur_item(p)) as usize;
                if self.first[r] == NONE {
                    self.first[r] = 1 + p as u32;
                }
                self.first[r]
            } else {
                NONE
            };
            self.cubes += (present && !last) as u64;
        }
        self.first.fill(NONE);
        for p in 0..pp {
            self.comp_label[p] = if self.cur[p] == 0 && cur_exists {
                let r = self.comp.find(cur_item(p)) as usize;
                if r == 0 {
                    0
                } else {
                    if self.first[r] == NONE {
                        self.first[r] = 1 + p as u32;
                    }
                    self.first[r]
                }
            } else {
                NONE
            };
        }
    }

    /// Counts the classes of previous-layer labels none of whose items is in the current
    /// layer (with `want` the current layer's cubes of value `want`: 1 for the set, 0 for
    /// the complement), the outside excepted.
    fn finish(
        uf: &mut UnionFind,
        labels: &[u32],
        cur: &[u8],
        want: u8,
        pp: usize,
        mark: &mut [bool],
        cur_exists: bool,
    ) -> u64 {
        mark.fill(false);
        if cur_exists {
            for (p, &b) in cur.iter().enumerate() {
                if b == want {
                    let r = uf.find((1 + pp + p) as u32) as usize;
                    mark[r] = true;
                }
            }
        }
        let mut n = 0;
        for (p, &l) in labels.iter().enumerate() {
            // one count per class: at its label's owner
            if l == 1 + p as u32 {
                let r = uf.find(l) as usize;
                if r != 0 && !mark[r] {
                    mark[r] = true;
                    n += 1;
                }
            }
        }
        n
    }

    /// 26-connectivity of the set's cubes: each cube of the current layer with the cubes
    /// before it in the layer and the 9 below.
    fn link_set(&mut self) {
        let (w, pp) = (self.w, self.pp);
        let (prev, cur) = (&self.prev, &self.cur);
        let mut uf = self.set.view();
        let c = |p: usize| (1 + pp + p) as u32;
        let b = |p: usize| (1 + p) as u32;
        for y in 1..self.h - 1 {
            for x in 1..w - 1 {
                let p = y * w + x;
                if cur[p] == 0 {
                    continue;
                }
                if cur[p - 1] != 0 {
                    // the left cube already joined the columns x - 1 and x
                    uf.union(c(p), c(p - 1));
                    if cur[p - w + 1] != 0 {
                        uf.union(c(p), c(p - w + 1));
                    }
                    for q in [p - w + 1, p + 1, p + w + 1] {
                        if prev[q] != 0 {
                            uf.union(c(p), b(q));
                        }
                    }
                    continue;
                }
                for q in [p - w - 1, p - w, p - w + 1] {
                    if cur[q] != 0 {
                        uf.union(c(p), c(q));
                    }
                }
                for q in [p - w - 1, p - w, p - w + 1, p - 1, p, p + 1, p + w - 1, p + w, p + w + 1] {
                    if prev[q] != 0 {
                        uf.union(c(p), b(q));
                    }
                }
            }
        }
    }

    /// Facet connectivity of the absent cubes (padding included, already the outside).
    fn link_complement(&mut self) {
        let (w, pp) = (self.w, self.pp);
        let (prev, cur) = (&self.prev, &self.cur);
        let prev_exists = &self.comp_label;
        let mut uf = self.comp.view();
        let c = |p: usize| (1 + pp + p) as u32;
        // the border after the box too: its cubes are the outside, linked backwards only
        for y in 1..self.h {
            for x in 1..w {
                let p = y * w + x;
                if cur[p] != 0 {
                    continue;
                }
                if cur[p - 1] == 0 {
                    uf.union(c(p), c(p - 1));
                }
                if cur[p - w] == 0 {
                    uf.union(c(p), c(p - w));
                }
                if prev[p] == 0 && prev_exists[p] != NONE {
                    uf.union(c(p), (1 + p) as u32);
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
